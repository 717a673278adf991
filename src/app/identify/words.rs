//! The one place where the Identify mode turns the library's facts into words: the notes on
//! the data, the fit's status and text, its warnings, the diagnosis's evidence and the chain
//! table. The library still hands some of these over as English sentences; they are rendered
//! here and nowhere else, so that this file can be swapped for the text layer's renderers
//! (`crate::text::report`) without touching a view.

use crate::format::sig;
use crate::ident::diagnose::{DiagnoseReport, Step};
use crate::ident::experiment::ExperimentError;
use crate::ident::fit::{FitReport, FitWarning, Method, Termination};
use crate::ident::handles::Handle;
use crate::ident::models::{Model, Param, pair_poles};
use crate::text::identify::Phrase;
use crate::text::{Lang, Localize};

use super::commands::Choice;
use super::session::{DiagnoseNote, LoadError, LoadMessage, Source, Status};

/// A number for running text in `lang`.
fn num(lang: Lang, x: f64, digits: i32) -> String {
    lang.num(x, digits)
}

/// The label of a reading choice.
pub fn choice_name(choice: Choice, lang: Lang) -> &'static str {
    match choice {
        Choice::TimeColumn => Phrase::TimeColumn,
        Choice::OutputColumn => Phrase::OutputColumn,
        Choice::InputColumn => Phrase::InputColumn,
        Choice::SamplingPeriod => Phrase::SamplingPeriod,
        Choice::InitialInput => Phrase::InitialInput,
    }
    .get(lang)
}

fn choices(list: &[(Choice, String)], lang: Lang) -> String {
    list.iter()
        .map(|(c, text)| format!("{} {text}", choice_name(*c, lang).to_lowercase()))
        .collect::<Vec<_>>()
        .join(", ")
}

fn source_name(source: &Source, lang: Lang) -> String {
    match source {
        Source::File(path) => path.clone(),
        Source::Example => Phrase::TheExample.get(lang).to_string(),
        Source::Pasted => Phrase::PastedData.get(lang).to_string(),
    }
}

/// The last load's message: (is an error, text).
pub fn load_message(message: &LoadMessage, lang: Lang) -> (bool, String) {
    match message {
        LoadMessage::Loaded {
            samples,
            source,
            notes,
            step_missing,
            kept,
            cleared,
        } => {
            let mut out = vec![
                Phrase::LoadedFrom.with(lang, &[samples.to_string(), source_name(source, lang)]),
            ];
            out.extend(notes.iter().cloned());
            if let Some((error, t0)) = step_missing {
                out.push(
                    Phrase::StepMissing
                        .with(lang, &[experiment_error(error, lang), num(lang, *t0, 6)]),
                );
            }
            if !cleared.is_empty() {
                out.push(Phrase::ClearedChoices.with(lang, &[choices(cleared, lang)]));
            }
            if !kept.is_empty() {
                out.push(Phrase::KeptChoices.with(lang, &[choices(kept, lang)]));
            }
            (false, out.join(" "))
        }
        LoadMessage::Example {
            samples,
            du,
            t0,
            y0,
        } => (false, example_message(*samples, *du, *t0, *y0, lang)),
        LoadMessage::Failed {
            source,
            error,
            kept,
        } => {
            let reason = match error {
                LoadError::Choice { choice, error } => {
                    format!("{}: {}", choice_name(*choice, lang), error.text(lang))
                }
                LoadError::Data(e) => e.to_string(),
                LoadError::Model(e) => e.to_string(),
            };
            let mut text = match source {
                Source::File(path) => Phrase::NotLoaded.with(lang, &[path.clone(), reason]),
                Source::Pasted => Phrase::PasteRefused.with(lang, &[reason]),
                Source::Example => Phrase::ExampleRefused.with(lang, &[reason]),
            };
            if *kept {
                text.push(' ');
                text.push_str(Phrase::KeptBefore.get(lang));
            }
            (true, text)
        }
    }
}

/// The example's own message, with its step and operating point.
pub fn example_message(samples: usize, du: f64, t0: f64, y0: f64, lang: Lang) -> String {
    Phrase::LoadedExample.with(
        lang,
        &[
            samples.to_string(),
            num(lang, du, 4),
            num(lang, t0, 4),
            num(lang, y0, 4),
        ],
    )
}

/// How the optimiser stopped (the library's words).
pub fn termination(t: Termination, _lang: Lang) -> String {
    t.describe().to_string()
}

/// The status beside the Fit button (empty when there is nothing to say).
pub fn status(status: &Status, lang: Lang) -> String {
    match status {
        Status::Idle => String::new(),
        Status::Fitting => Phrase::Fitting.get(lang).to_string(),
        Status::Cancelling => Phrase::Cancelling.get(lang).to_string(),
        Status::Progress {
            start,
            starts,
            iteration,
            cost,
            best_cost,
        } => Phrase::FitProgress.with(
            lang,
            &[
                (start + 1).to_string(),
                starts.to_string(),
                iteration.to_string(),
                num(lang, *cost, 5),
                num(lang, *best_cost, 5),
            ],
        ),
        Status::Fitted {
            termination: t,
            starts,
            iterations,
        } => Phrase::FitDone.with(
            lang,
            &[
                termination(*t, lang),
                starts.to_string(),
                iterations.to_string(),
            ],
        ),
        Status::FromDiagnosis {
            termination: t,
            iterations,
        } => Phrase::FromDiagnosis.with(lang, &[termination(*t, lang), iterations.to_string()]),
        Status::FitFailed(e) => Phrase::FitFailed.with(lang, &[e.to_string()]),
        Status::Structure(e) => experiment_error(e, lang),
    }
}

/// What the diagnosis said last (empty: nothing).
pub fn diagnose_note(note: &DiagnoseNote, lang: Lang) -> String {
    match note {
        DiagnoseNote::None => String::new(),
        DiagnoseNote::RunningLoop => Phrase::RunningLoop.get(lang).to_string(),
        DiagnoseNote::LookingForCause => Phrase::LookingForCause.get(lang).to_string(),
        DiagnoseNote::Verdict(v) => v.clone(),
        DiagnoseNote::Cause(c) => format!("{}: {}", c.id(), c.explanation()),
        DiagnoseNote::Adequate => {
            "none: no extension lowers BIC by 10; the model is adequate.".into()
        }
    }
}

/// A selected step of the chain: its cause, its evidence, its remedy and what it gained.
pub fn step_lines(step: &Step) -> [String; 3] {
    [
        format!("{}: {}", step.cause.id(), step.cause.explanation()),
        step.evidence.clone(),
        format!(
            "Remedy: {}. RMSE {} → {} ({}× lower); fit {} % → {} %.",
            step.cause.remedy(),
            sig(step.gain.rmse_before, 4),
            sig(step.gain.rmse_after, 4),
            sig(step.gain.rmse_ratio, 3),
            sig(step.gain.fit_percent_before, 4),
            sig(step.gain.fit_percent_after, 4)
        ),
    ]
}

/// An optimiser's name (a proper name, the same in every language).
pub fn method_name(m: Method) -> &'static str {
    match m {
        Method::LevenbergMarquardt => "Levenberg–Marquardt",
        Method::NelderMead => "Nelder–Mead",
    }
}

/// Why the choices on a test cannot be used (the library's words).
pub fn experiment_error(e: &ExperimentError, _lang: Lang) -> String {
    e.to_string()
}

/// A fit warning.
pub fn warning(w: &FitWarning, lang: Lang) -> String {
    Phrase::Warning.with(lang, &[w.message()])
}

/// A parameter's meaning, for a tooltip.
pub fn param_help(p: Param) -> &'static str {
    p.describe()
}

/// A parameter's value with its unit.
pub fn value_with_unit(p: Param, value: f64) -> String {
    if p.unit().is_empty() {
        sig(value, 5)
    } else {
        format!("{} {}", sig(value, 5), p.unit())
    }
}

/// An interval, or its absence.
pub fn interval(ci: Option<(f64, f64)>, lang: Lang) -> String {
    match ci {
        Some((lo, hi)) => format!("[{}, {}]", sig(lo, 4), sig(hi, 4)),
        None => Phrase::NoInterval.get(lang).to_string(),
    }
}

/// The fit's figures of merit in one line.
pub fn fit_summary(report: &FitReport) -> String {
    format!(
        "MSE {} · RMSE {} · fit {} % · AIC {} · N = {}",
        sig(report.mse, 4),
        sig(report.rmse, 4),
        sig(report.fit_percent, 4),
        sig(report.aic, 5),
        report.n
    )
}

/// A filter's description (the library's words).
pub fn filter_description(fc: f64, ts: f64) -> String {
    crate::ident::prepare::Ewma::new(fc, ts).describe()
}

/// A handle's accessible label.
pub fn handle_label(h: Handle, lang: Lang) -> &'static str {
    match h {
        Handle::FinalValue => Phrase::FinalValueHandle,
        Handle::DeadTime => Phrase::DeadTimeHandle,
        Handle::TimeConstant => Phrase::TimeConstantHandle,
        Handle::FirstPeak => Phrase::FirstPeakHandle,
    }
    .get(lang)
}

/// What dragging a handle does.
pub fn handle_help(h: Handle, lang: Lang) -> &'static str {
    match h {
        Handle::FinalValue => Phrase::FinalValueHelp,
        Handle::DeadTime => Phrase::DeadTimeHelp,
        Handle::TimeConstant => Phrase::TimeConstantHelp,
        Handle::FirstPeak => Phrase::FirstPeakHelp,
    }
    .get(lang)
}

/// The fits of a chain: the start, then each step's.
pub fn chain(d: &DiagnoseReport) -> Vec<&FitReport> {
    std::iter::once(&d.start)
        .chain(d.steps.iter().map(|s| &s.fit))
        .collect()
}

/// The chain table's column heads.
pub const CHAIN_HEADS: [&str; 5] = ["Model", "RMSE", "Fit %", "BIC change", "Kp ± 95 %"];

/// The chain table's cells: model, RMSE, fit %, BIC change, Kp ± half-interval.
pub fn chain_rows(d: &DiagnoseReport) -> Vec<[String; 5]> {
    chain(d)
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let kp = f.model.get(Param::Kp);
            let kp_text = match f.interval(Param::Kp) {
                Some((a, b)) => format!("{} ± {}", sig(kp, 4), sig(0.5 * (b - a), 2)),
                None => sig(kp, 4),
            };
            let delta = k
                .checked_sub(1)
                .and_then(|i| d.steps.get(i))
                .map_or(String::new(), |s| sig(s.gain.criterion_delta, 4));
            [
                f.model.structure.label(),
                sig(f.rmse, 4),
                sig(f.fit_percent, 4),
                delta,
                kp_text,
            ]
        })
        .collect()
}

/// The chain table as tab-separated text, for a spreadsheet or a report.
pub fn chain_text(d: &DiagnoseReport) -> String {
    let mut out = String::from("model\tRMSE\tfit %\tBIC change\tKp ± 95 %\n");
    for row in chain_rows(d) {
        out.push_str(&row.join("\t"));
        out.push('\n');
    }
    out
}

/// ωn, σ, ωd and the poles of a model, in words.
pub fn derived(model: &Model) -> Vec<String> {
    let s = model.structure;
    let mut out = Vec::new();
    if s.underdamped {
        let (tw, zeta) = (model.get(Param::Tw), model.get(Param::Zeta));
        let [p, q] = pair_poles(tw, zeta);
        out.push(format!(
            "ωn = 1/Tw = {} rad/s · σ = ζωn = {} 1/s",
            sig(1.0 / tw, 4),
            sig(zeta / tw, 4)
        ));
        if zeta < 1.0 {
            out.push(format!(
                "ωd = {} rad/s · poles {} ± {}j",
                sig(p.im, 4),
                sig(p.re, 4),
                sig(p.im, 4)
            ));
        } else {
            out.push(format!(
                "overdamped: poles {} and {}",
                sig(p.re, 4),
                sig(q.re, 4)
            ));
        }
    }
    let poles: Vec<String> = [Param::Tp1, Param::Tp2, Param::Tp3]
        .into_iter()
        .filter(|p| s.params().contains(p))
        .map(|p| format!("{} (from {})", sig(-1.0 / model.get(p), 4), p.name()))
        .collect();
    if !poles.is_empty() {
        out.push(format!("Real poles: {}", poles.join(", ")));
    }
    out.push(format!(
        "Static gain Kp = Δy/Δu = {}",
        sig(model.get(Param::Kp), 5)
    ));
    out
}
