//! The step report as a person reads it, in the chosen language: the system, y(t) and the
//! metrics.

use super::*;

/// The text report: the system, its poles and zeros, the metrics and y(t). Numbers in the
/// prose take the language's decimal separator; the closed forms and the samples keep points.
pub fn human_report(a: &Analysis, lang: Lang) -> String {
    let mut lines = system_lines(a, lang);
    lines.push(String::new());
    lines.extend(metric_lines(a, lang));
    lines.push(String::new());
    lines.push(Heading::ClosedForm.get(lang).to_string());
    for form in [OscillationForm::CosSin, OscillationForm::AmplitudePhase] {
        lines.push(format!("  {}", expression(&a.response, form)));
    }
    if let Some(Samples { t, y }) = &a.samples {
        lines.push(String::new());
        lines.push(format!("{}\n  t (s)\ty", Heading::Samples.get(lang)));
        lines.extend(t.iter().zip(y).map(|(t, y)| format!("  {t}\t{y}")));
    }
    lines.join("\n")
}

/// A number of the report's prose: [`format_number`] with the language's separator.
pub(super) fn prose_number(x: f64, lang: Lang) -> String {
    lang.localize_number(&format_number(x))
}

pub(super) fn system_lines(a: &Analysis, lang: Lang) -> Vec<String> {
    let tf = &a.tf;
    let roots = |r: &[C64]| {
        if r.is_empty() {
            StepPhrase::NoRoots.get(lang).to_string()
        } else {
            r.iter()
                .map(|&c| lang.localize_number(&fmt_c_rounded(c)))
                .collect::<Vec<_>>()
                .join(lang.pick(", ", "; "))
        }
    };
    let dc_gain = tf.dc_gain();
    let dc_text = static_gain_words(dc_gain, IntegratorPole::S, lang)
        .unwrap_or_else(|| prose_number(dc_gain, lang));
    let stability = crate::text::cli::stability_line(tf.stability(), a.response.behaviour(), lang);
    let step = crate::text::cli::step_line(&prose_number(a.response.amplitude(), lang), lang);
    let rows = [
        (
            StepPhrase::System.get(lang),
            format!("G(s) = {}", tf.describe_rounded()),
        ),
        ("", format!("G(s) = {}", polynomial_form(tf))),
        (StepPhrase::Poles.get(lang), roots(tf.poles())),
        (crate::text::cli::ZEROS, roots(tf.zeros())),
        (StepPhrase::DcGain.get(lang), format!("G(0) = {dc_text}")),
        (StepPhrase::Stability.get(lang), stability),
        (StepPhrase::Step.get(lang), step),
    ];
    let width = rows
        .iter()
        .map(|(label, _)| label.chars().count())
        .max()
        .unwrap_or(0);
    rows.iter()
        .map(|(label, text)| format!("{label:<width$}  {text}"))
        .collect()
}

/// `0.5 / (s^3 + 7 s^2 + 15 s + 25)`, with the delay factor when there is one.
pub(super) fn polynomial_form(tf: &TransferFunction) -> String {
    let num = format_poly(&tf.num());
    let num = if tf.zeros().is_empty() {
        num
    } else {
        format!("({num})")
    };
    let delay = if tf.delay() > 0.0 {
        format!(" · e^(-{} s)", format_number(tf.delay()))
    } else {
        String::new()
    };
    format!("{num} / ({}){delay}", format_poly(&tf.den()))
}

/// The metrics' heading with the thresholds in force, then one line per metric: its name
/// and its cell ([`Metric::cell`]: the value, or why it does not exist).
pub(super) fn metric_lines(a: &Analysis, lang: Lang) -> Vec<String> {
    let (low, high) = a.options.rise_limits;
    let pct = |f: f64| prose_number(100.0 * f, lang);
    let mut lines = vec![crate::text::cli::metrics_heading(
        &pct(low),
        &pct(high),
        &pct(a.options.settling_threshold),
        lang,
    )];
    let width = Metric::ALL
        .iter()
        .map(|m| m.name(lang).chars().count())
        .max()
        .unwrap_or(0);
    lines.extend(
        Metric::ALL
            .iter()
            .map(|m| format!("  {:<width$}  {}", m.name(lang), m.cell(&a.info, lang))),
    );
    lines
}
