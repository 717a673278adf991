//! The one place where the Identify mode turns its session's facts into words: the load
//! message, the fit's status, the diagnosis note. The library's own facts (data notes,
//! errors, warnings, evidence, the fit text and the chain table) are said by the text layer
//! ([`degrau_ident::words::ident`], [`degrau_ident::words::report`]), the same words the CLI prints; this
//! file only picks them.

use crate::words::identify::Phrase;
use degrau_ident::diagnose::Cause;
use degrau_ident::diagnose::tracker::DiagnoseProgress;
use degrau_ident::diagnose::{DiagnoseReport, Step};
use degrau_ident::experiment::ExperimentError;
use degrau_ident::fit::handles::Handle;
use degrau_ident::fit::{FitReport, FitWarning, Method, Termination};
use degrau_ident::model::{Model, Param};
use degrau_words::{Lang, Localize};

use super::commands::Choice;
use super::session::{DiagnoseNote, LoadError, LoadMessage, Source, Status};
use super::steps::{Agreement, agreement, compared_params};
use degrau_ident::diagnose::per_step::StepFit;
use degrau_ident::diagnose::test_causes::fit_held;
use degrau_ident::model::excitation::InputChange;

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
        Choice::InputFile => Phrase::InputFile,
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

/// `text` as a sentence of its own: its first letter upper-case and a full stop at its end
/// (a fact said mid-sentence elsewhere, here alone; sentences side by side ran together).
pub fn sentence(text: &str) -> String {
    let text = text.trim();
    let mut chars = text.chars();
    let Some(first) = chars.next() else {
        return String::new();
    };
    let mut out: String = first.to_uppercase().chain(chars).collect();
    if !out.ends_with(['.', '!', '?', ':']) {
        out.push('.');
    }
    out
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
            let out: Vec<String> = out.iter().map(|s| sentence(s)).collect();
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
/// A cause named in the student's words.
fn named(c: Cause, lang: Lang) -> &'static str {
    degrau_ident::words::ident::cause_name(c, degrau_ident::words::ident::Naming::Words, lang)
}

pub fn diagnose_note(note: &DiagnoseNote, lang: Lang) -> String {
    match note {
        DiagnoseNote::None => String::new(),
        DiagnoseNote::RunningLoop => Phrase::RunningLoop.get(lang).to_string(),
        DiagnoseNote::LookingForCause => Phrase::LookingForCause.get(lang).to_string(),
        DiagnoseNote::Verdict(v) => v.map_or(String::new(), |v| v.text(lang)),
        DiagnoseNote::Cause(c) => format!("{}: {}", named(*c, lang), c.text(lang)),
        DiagnoseNote::Adequate => {
            format!("{}: {}", named(Cause::None, lang), Cause::None.text(lang))
        }
        DiagnoseNote::Cancelled => Phrase::DiagnosisCancelled.get(lang).to_string(),
    }
}

/// How far a running diagnosis has gone: the extension it looks for and the fits made.
pub fn diagnose_progress(p: &DiagnoseProgress, lang: Lang) -> String {
    Phrase::DiagnoseProgress.with(
        lang,
        &[
            p.extension.to_string(),
            p.max_steps.to_string(),
            p.fits.to_string(),
        ],
    )
}

/// The static gain line of a diagnosis, with what the record does not separate it from.
pub fn static_gain_line(d: &DiagnoseReport, lang: Lang) -> String {
    degrau_ident::words::report::static_gain_line(d, lang)
}

/// A selected step of the chain: its cause, its evidence, its remedy and what it gained.
pub fn step_lines(step: &Step, lang: Lang) -> [String; 3] {
    degrau_ident::words::report::step_lines(step, degrau_ident::words::ident::Naming::Words, lang)
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
    degrau_ident::words::ident::experiment_error(e, lang, degrau_ident::words::ident::Where::App)
}

/// A fit warning.
pub fn warning(w: &FitWarning, lang: Lang) -> String {
    degrau_ident::words::report::warning_line(w, lang)
}

/// A parameter's meaning, for a tooltip.
pub fn param_help(p: Param, lang: Lang) -> &'static str {
    degrau_ident::words::ident::param_meaning(p, lang)
}

/// The fit's parameter table (header and rows: parameter, value with unit, interval).
pub fn param_rows(report: &FitReport, lang: Lang) -> ([String; 3], Vec<[String; 3]>) {
    degrau_ident::words::report::param_rows(report, lang)
}

/// The fit's figures of merit in one line.
pub fn fit_summary(report: &FitReport, lang: Lang) -> String {
    degrau_ident::words::report::figures_line(report, lang)
}

/// A filter's description.
pub fn filter_description(fc: f64, ts: f64, lang: Lang) -> String {
    degrau_ident::record::prepare::Ewma::new(fc, ts).text(lang)
}

/// A handle's accessible label.
pub fn handle_label(h: Handle, lang: Lang) -> &'static str {
    degrau_ident::words::ident::handle_label(h, lang)
}

/// What dragging a handle does.
pub fn handle_help(h: Handle, lang: Lang) -> &'static str {
    degrau_ident::words::ident::handle_help(h, lang)
}

/// The chain table: its header and one row per model.
pub fn chain_rows(d: &DiagnoseReport, lang: Lang) -> ([String; 5], Vec<[String; 5]>) {
    degrau_ident::words::report::chain_rows(d, lang)
}

/// The chain table as tab-separated text, for a spreadsheet or a report.
pub fn chain_text(d: &DiagnoseReport, lang: Lang) -> String {
    degrau_ident::words::report::chain_text(d, lang)
}

/// ωn, σ, ωd and the poles of a model, in words.
pub fn derived(model: &Model, lang: Lang) -> Vec<String> {
    degrau_ident::words::report::derived(model, lang)
}

/// "N input changes used."
pub fn changes_used(n: usize, lang: Lang) -> String {
    match n {
        1 => Phrase::OneChangeUsed.get(lang).to_string(),
        n => Phrase::ChangesUsed.with(lang, &[n.to_string()]),
    }
}

/// How early each change may have come (the step-instant lead), when it is not exact.
pub fn change_lead(lead: f64, lang: Lang) -> Option<String> {
    (lead > 0.0).then(|| {
        let s = num(lang, lead, 4);
        Phrase::ChangeLead.with(lang, &[s.clone(), s])
    })
}

/// A signed number (+2, −1,5).
fn signed(lang: Lang, x: f64, digits: i32) -> String {
    let n = num(lang, x.abs(), digits);
    if x < 0.0 {
        format!("−{n}")
    } else {
        format!("+{n}")
    }
}

/// A change mark's accessible label: "change 2 at t = 201 s (Δu = +20)".
pub fn change_mark(k: usize, c: &InputChange, lang: Lang) -> String {
    Phrase::ChangeMark.with(
        lang,
        &[
            (k + 1).to_string(),
            num(lang, c.t, 5),
            signed(lang, c.du, 4),
        ],
    )
}

/// A change's short label on the input plot: "1: +20".
pub fn change_short(k: usize, c: &InputChange, lang: Lang) -> String {
    format!("{}: {}", k + 1, signed(lang, c.du, 3))
}

/// The interval a change may have happened in, or that its instant is exact.
pub fn change_span(k: usize, c: &InputChange, lang: Lang) -> String {
    if c.earliest < c.t {
        Phrase::ChangeSpan.with(
            lang,
            &[
                (k + 1).to_string(),
                num(lang, c.earliest, 5),
                num(lang, c.t, 5),
            ],
        )
    } else {
        Phrase::ChangeInstantExact.with(lang, &[(k + 1).to_string(), num(lang, c.t, 5)])
    }
}

/// A step window's label on the output plot: "step 2".
pub fn step_window(k: usize, lang: Lang) -> String {
    Phrase::StepWindow.with(lang, &[(k + 1).to_string()])
}

/// A step window's accessible label: "step 2 window, 201 s to 350 s".
pub fn step_window_label(k: usize, (a, b): (f64, f64), lang: Lang) -> String {
    Phrase::StepWindowLabel.with(
        lang,
        &[(k + 1).to_string(), num(lang, a, 5), num(lang, b, 5)],
    )
}

/// An interval as the parameter table writes it: "[0,79; 0,81]" (a semicolon between the
/// ends where the decimal mark is a comma).
fn interval(lang: Lang, (lo, hi): (f64, f64)) -> String {
    let sep = lang.pick(", ", "; ");
    format!("[{}{sep}{}]", num(lang, lo, 4), num(lang, hi, 4))
}

/// A value with its 95 % interval, for a cell of the per-step table: "0,8 [0,79; 0,81]".
fn value_cell(report: &FitReport, p: Param, lang: Lang) -> String {
    let value = num(lang, report.model.get(p), 4);
    match report.interval(p) {
        Some(ci) => format!("{value} {}", interval(lang, ci)),
        None => format!("{value} [{}]", Phrase::NoInterval.get(lang)),
    }
}

/// The per-step table: its header (change, t, Δu, from, then each compared parameter) and
/// one row for the joint fit and one per step.
pub fn per_step_rows(joint: &FitReport, fits: &[StepFit], lang: Lang) -> PerStepTable {
    let params = compared_params(&joint.model.structure);
    let mut header = vec![
        Phrase::ChangeHeader.get(lang).to_string(),
        // Symbols, the same in every language.
        "t (s)".to_string(),
        "Δu".to_string(),
        Phrase::FromHeader.get(lang).to_string(),
    ];
    header.extend(params.iter().map(|p| {
        let unit = p.unit().trim();
        if unit.is_empty() {
            p.name().to_string()
        } else {
            format!("{} ({unit})", p.name())
        }
    }));
    let mut joint_row = vec![
        Phrase::JointFit.get(lang).to_string(),
        String::new(),
        String::new(),
        String::new(),
    ];
    joint_row.extend(params.iter().map(|&p| value_cell(joint, p, lang)));
    let mut rows = vec![joint_row];
    for (k, f) in fits.iter().enumerate() {
        let name = if f.not_at_rest {
            Phrase::StepRowMoving
        } else {
            Phrase::StepRow
        };
        let mut row = vec![
            name.with(lang, &[(k + 1).to_string()]),
            num(lang, f.change.t, 5),
            signed(lang, f.change.du, 4),
            num(lang, f.change.u_before, 4),
        ];
        match &f.fit {
            Ok(r) => row.extend(params.iter().map(|&p| value_cell(r, p, lang))),
            Err(e) => row.push(Phrase::NoStepFit.with(lang, &[e.text(lang)])),
        }
        rows.push(row);
    }
    PerStepTable { header, rows }
}

/// The per-step table's text.
pub struct PerStepTable {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// A step's fit with its index among the record's changes.
type Numbered<'a> = (usize, &'a StepFit);

/// What a student reads under the per-step table: the steps held too briefly to compare
/// (their own values rest on the previous response's tail, as the CLI's table marks them),
/// then, of the others, which values differ beyond their intervals (a first hint of
/// nonlinearity), or that every step agrees.
pub fn agreement_lines(
    joint: &FitReport,
    fits: &[StepFit],
    instant_step: f64,
    lang: Lang,
) -> Vec<String> {
    let (held, brief): (Vec<Numbered>, Vec<Numbered>) = fits
        .iter()
        .enumerate()
        .partition(|(_, f)| f.fit.is_err() || fit_held(f, &joint.model));
    let mut lines: Vec<String> = brief
        .iter()
        .map(|(k, f)| {
            Phrase::StepNotHeld.with(lang, &[(k + 1).to_string(), num(lang, f.change.t, 5)])
        })
        .collect();
    if held.is_empty() {
        return lines;
    }
    let compared: Vec<StepFit> = held.iter().map(|(_, f)| (*f).clone()).collect();
    lines.extend(match agreement(joint, &compared, instant_step) {
        Agreement::Agree => vec![Phrase::StepsAgree.get(lang).to_string()],
        Agreement::Unknown => vec![Phrase::StepsUnknown.get(lang).to_string()],
        Agreement::Differ(list) => list
            .iter()
            .map(|d| {
                let joint = interval(lang, d.joint);
                Phrase::StepDiffers.with(
                    lang,
                    &[
                        (held[d.step].0 + 1).to_string(),
                        num(lang, d.t, 5),
                        d.param.name().to_string(),
                        num(lang, d.value, 4),
                        joint,
                    ],
                )
            })
            .collect(),
    });
    lines
}

/// The per-step job's progress: "Fitting step 2 of 4…".
pub fn per_step_progress((k, n): (usize, usize), lang: Lang) -> String {
    Phrase::PerStepRunning.with(lang, &[(k + 1).to_string(), n.max(1).to_string()])
}

/// Which change the handles act on, on a multi-step record.
pub fn handles_on_largest(index: usize, t: f64, lang: Lang) -> String {
    Phrase::HandlesOnLargest.with(lang, &[(index + 1).to_string(), num(lang, t, 5)])
}
