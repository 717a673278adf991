//! The one place where the Identify mode turns its session's facts into words: the load
//! message, the fit's status, the diagnosis note. The library's own facts (data notes,
//! errors, warnings, evidence, the fit text and the chain table) are said by the text layer
//! ([`crate::text::ident`], [`crate::text::report`]), the same words the CLI prints; this
//! file only picks them.

use crate::ident::diagnose::Cause;
use crate::ident::diagnose::{DiagnoseReport, Step};
use crate::ident::experiment::ExperimentError;
use crate::ident::fit::{FitReport, FitWarning, Method, Termination};
use crate::ident::handles::Handle;
use crate::ident::models::{Model, Param};
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
            out.extend(notes.iter().map(|n| n.text(lang)));
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
                LoadError::Data(e) => e.text(lang),
                LoadError::Model(e) => e.text(lang),
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

/// How the optimiser stopped.
pub fn termination(t: Termination, lang: Lang) -> String {
    t.text(lang)
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
        Status::FitFailed(e) => Phrase::FitFailed.with(lang, &[e.text(lang)]),
        Status::Structure(e) => experiment_error(e, lang),
    }
}

/// What the diagnosis said last (empty: nothing).
pub fn diagnose_note(note: &DiagnoseNote, lang: Lang) -> String {
    match note {
        DiagnoseNote::None => String::new(),
        DiagnoseNote::RunningLoop => Phrase::RunningLoop.get(lang).to_string(),
        DiagnoseNote::LookingForCause => Phrase::LookingForCause.get(lang).to_string(),
        DiagnoseNote::Verdict(v) => v.map_or(String::new(), |v| v.text(lang)),
        DiagnoseNote::Cause(c) => format!("{}: {}", c.id(), c.text(lang)),
        DiagnoseNote::Adequate => format!("none: {}", Cause::None.text(lang)),
    }
}

/// A selected step of the chain: its cause, its evidence, its remedy and what it gained.
pub fn step_lines(step: &Step, lang: Lang) -> [String; 3] {
    crate::text::report::step_lines(step, lang)
}

/// An optimiser's name (a proper name, the same in every language).
pub fn method_name(m: Method) -> &'static str {
    match m {
        Method::LevenbergMarquardt => "Levenberg–Marquardt",
        Method::NelderMead => "Nelder–Mead",
    }
}

/// Why the choices on a test cannot be used, naming the app's fields.
pub fn experiment_error(e: &ExperimentError, lang: Lang) -> String {
    crate::text::ident::experiment_error(e, lang, crate::text::ident::Where::App)
}

/// A fit warning.
pub fn warning(w: &FitWarning, lang: Lang) -> String {
    crate::text::report::warning_line(w, lang)
}

/// A parameter's meaning, for a tooltip.
pub fn param_help(p: Param, lang: Lang) -> &'static str {
    crate::text::ident::param_meaning(p, lang)
}

/// The fit's parameter table (header and rows: parameter, value with unit, interval).
pub fn param_rows(report: &FitReport, lang: Lang) -> ([String; 3], Vec<[String; 3]>) {
    crate::text::report::param_rows(report, lang)
}

/// The fit's figures of merit in one line.
pub fn fit_summary(report: &FitReport, lang: Lang) -> String {
    crate::text::report::figures_line(report, lang)
}

/// A filter's description.
pub fn filter_description(fc: f64, ts: f64, lang: Lang) -> String {
    crate::ident::prepare::Ewma::new(fc, ts).text(lang)
}

/// A handle's accessible label.
pub fn handle_label(h: Handle, lang: Lang) -> &'static str {
    crate::text::ident::handle_label(h, lang)
}

/// What dragging a handle does.
pub fn handle_help(h: Handle, lang: Lang) -> &'static str {
    crate::text::ident::handle_help(h, lang)
}

/// The chain table: its header and one row per model.
pub fn chain_rows(d: &DiagnoseReport, lang: Lang) -> ([String; 5], Vec<[String; 5]>) {
    crate::text::report::chain_rows(d, lang)
}

/// The chain table as tab-separated text, for a spreadsheet or a report.
pub fn chain_text(d: &DiagnoseReport, lang: Lang) -> String {
    crate::text::report::chain_text(d, lang)
}

/// ωn, σ, ωd and the poles of a model, in words.
pub fn derived(model: &Model, lang: Lang) -> Vec<String> {
    crate::text::report::derived(model, lang)
}
