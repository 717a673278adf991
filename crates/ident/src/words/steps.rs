//! The words of a record's input as the model saw it and of its per-step fits: which
//! changes drove the fit, and the table of each change fitted on its own window beside the
//! joint fit (CLI text; the app draws its own table from the same facts).

use crate::diagnose::per_step::StepFit;
use crate::fit::FitReport;
use crate::model::Param;
use crate::model::excitation::{Excitation, Hold};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// Words of the input and of the per-step table.
    pub enum StepsPhrase {
        Joint => ("all steps", "todos os degraus"),
        Step => ("step", "degrau"),
        Failed => ("no fit", "sem ajuste"),
        NotAtRest => ("not at rest before", "fora do repouso antes"),
        NotHeld => (
            "held under 3 τ: not compared",
            "mantido menos de 3 τ: não comparado"
        ),
        PerStepHeading => (
            "Each change fitted on its own window (a linear process gives the same values within their intervals):",
            "Cada mudança ajustada na sua própria janela (um processo linear dá os mesmos valores dentro dos seus intervalos):"
        ),
        Skipped => (
            "Per-step fits skipped: more than {0} changes (a PRBS-like input has no step windows to compare).",
            "Ajustes por degrau omitidos: mais de {0} mudanças (uma entrada do tipo PRBS não tem janelas de degrau a comparar)."
        ),
    }
}

/// How the input moves between samples, in words.
impl Localize for Hold {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Hold::Zoh => (
                "held between samples (zero-order hold)",
                "mantida entre amostras (segurador de ordem zero)",
            ),
            Hold::Foh => (
                "a straight line between samples (first-order hold)",
                "uma reta entre amostras (segurador de ordem um)",
            ),
        };
        lang.pick(en, pt).into()
    }
}

/// One line on the input that drove the fit: the ideal step, or the measured input's
/// changes (`0 → 100 at 63 s, …`).
pub fn input_line(input: &Excitation, lang: Lang) -> String {
    let typed = input.changes.len() == 1 && input.changes[0].index.is_none();
    if typed {
        let c = input.changes[0];
        return lang.pick(
            format!(
                "Input: one ideal step Δu = {} at t0 = {} s",
                lang.num(c.du, 6),
                lang.num(c.t, 6)
            ),
            format!(
                "Entrada: um degrau ideal Δu = {} em t0 = {} s",
                lang.num(c.du, 6),
                lang.num(c.t, 6)
            ),
        );
    }
    let changes: Vec<String> = input
        .changes
        .iter()
        .map(|c| {
            let (from, to, t) = (
                lang.num(c.u_before, 6),
                lang.num(c.u_before + c.du, 6),
                lang.num(c.t, 6),
            );
            lang.pick(
                format!("{from} → {to} at {t} s"),
                format!("{from} → {to} em {t} s"),
            )
        })
        .collect();
    let n = input.changes.len();
    let hold = input.hold.text(lang);
    let lead = if input.lead_range > 0.0 {
        let ts = lang.num(input.lead_range, 4);
        lang.pick(
            format!(
                "; each change estimated within the {ts} s before the sample that first shows it"
            ),
            format!(
                "; cada mudança estimada dentro dos {ts} s antes da amostra que primeiro a mostra"
            ),
        )
    } else {
        String::new()
    };
    lang.pick(
        format!(
            "Input: the measured input, {hold}, {n} change(s) used: {}{lead}",
            changes.join(", ")
        ),
        format!(
            "Entrada: a entrada medida, {hold}, {n} mudança(s) usada(s): {}{lead}",
            changes.join(", ")
        ),
    )
}

/// `value [lo; hi]` of `p` in `report`.
fn cell(report: &FitReport, p: Param, lang: Lang) -> String {
    let value = lang.num(report.model.get(p), 4);
    match report.interval(p) {
        Some((a, b)) => format!(
            "{value} [{}{}{}]",
            lang.num(a, 3),
            lang.pick(", ", "; "),
            lang.num(b, 3)
        ),
        None => value,
    }
}

/// The per-step table as text lines: a heading, a header row, one row per change and the
/// joint fit's row, columns aligned.
pub fn per_step_lines(fits: &[StepFit], joint: &FitReport, lang: Lang) -> Vec<String> {
    let params = crate::diagnose::per_step::compared_params(&joint.model.structure);
    let mut header = vec![
        StepsPhrase::Step.get(lang).to_string(),
        "t (s)".into(),
        "Δu".into(),
    ];
    header.extend(params.iter().map(|p| {
        let unit = p.unit();
        if unit.is_empty() {
            p.name().to_string()
        } else {
            format!("{} ({unit})", p.name())
        }
    }));
    header.push(lang.pick("fit %", "ajuste %").into());
    let mut rows = vec![header];
    for (k, f) in fits.iter().enumerate() {
        let mut row = vec![
            format!("{}", k + 1),
            lang.num(f.change.t, 6),
            lang.num(f.change.du, 6),
        ];
        match &f.fit {
            Ok(r) => {
                row.extend(params.iter().map(|&p| {
                    let q = crate::diagnose::per_step::same_lag(&joint.model, &r.model, p);
                    cell(r, q, lang)
                }));
                let mut figure = lang.num(r.fit_percent, 4);
                if f.not_at_rest {
                    figure = format!("{figure} ({})", StepsPhrase::NotAtRest.get(lang));
                }
                if !crate::diagnose::test_causes::fit_held(f, &joint.model) {
                    figure = format!("{figure} ({})", StepsPhrase::NotHeld.get(lang));
                }
                row.push(figure);
            }
            Err(e) => {
                row.push(format!(
                    "{}: {}",
                    StepsPhrase::Failed.get(lang),
                    e.text(lang)
                ));
            }
        }
        rows.push(row);
    }
    let mut last = vec![
        StepsPhrase::Joint.get(lang).to_string(),
        String::new(),
        String::new(),
    ];
    last.extend(params.iter().map(|&p| cell(joint, p, lang)));
    last.push(lang.num(joint.fit_percent, 4));
    rows.push(last);
    let widths: Vec<usize> = (0..rows[0].len())
        .map(|c| {
            rows.iter()
                .filter_map(|r| r.get(c))
                .map(|s| s.chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut lines = vec![StepsPhrase::PerStepHeading.get(lang).to_string()];
    lines.extend(rows.iter().map(|r| {
        r.iter()
            .enumerate()
            .map(|(c, s)| format!("{s:<w$}", w = widths[c]))
            .collect::<Vec<_>>()
            .join("  ")
            .trim_end()
            .to_string()
    }));
    lines
}

/// An input said by [`input_line`], as a fact for the test of every message.
#[cfg(test)]
struct InputWords(Excitation);

#[cfg(test)]
impl Localize for InputWords {
    fn text(&self, lang: Lang) -> String {
        input_line(&self.0, lang)
    }
}

/// Every message of this module, for the test of every message.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = StepsPhrase::messages();
    for hold in [Hold::Zoh, Hold::Foh] {
        all.push(Message::of(format!("steps::Hold::{hold:?}"), &hold));
    }
    all.push(Message::of(
        "steps::input::typed",
        &InputWords(Excitation::step(5.0, 10.0)),
    ));
    let time = [0.0, 1.0, 2.0, 3.0];
    if let Some(measured) = Excitation::measured(&time, &[0.0, 0.0, 2.0, 2.0], None, Hold::Zoh) {
        all.push(Message::of("steps::input::measured", &InputWords(measured)));
    }
    all
}
