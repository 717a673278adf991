//! The Identify mode's side panel: the test (path, example, file dialog, how to read it), the
//! step and operating point, window and filter, the model structure and its guesses, the fit
//! and its result, and the diagnosis chain. It reads the session and returns commands.

use eframe::egui::{self, DragValue, RichText, Ui};

use crate::field::{Limits, NumberField};
use crate::look::Look;
use crate::words::identify::Phrase;
use degrau_ident::experiment::{Drive, Offset, OperatingPoint};
use degrau_ident::fit::{MAX_STARTS, Method, bounds};
use degrau_ident::model::Param;
use degrau_ident::model::excitation::Hold;
use degrau_words::Localize;

use super::commands::{Choice, CodeKind, Command, LandscapeCommand, OffsetChoice};
use super::session::{CODES, DiagnoseNote, Session};
use super::words;

/// Draws the panel's sections into `ui`, adding what the student asks to `out`.
pub fn show(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    ui.heading(Phrase::StepTest.get(look.lang));
    data_section(ui, session, look, out);
    if session.loaded.is_none() {
        return;
    }
    ui.separator();
    step_section(ui, session, look, out);
    ui.separator();
    model_section(ui, session, look, out);
    ui.separator();
    fit_section(ui, session, look, out);
    ui.separator();
    super::hand::section(ui, session, look, out);
    if session.report.is_some() {
        results(ui, session, look, out);
        per_step_section(ui, session, look, out);
        ui.separator();
        diagnose_section(ui, session, look, out);
        if session.diagnosis.is_some() {
            ui.separator();
            super::test_causes::section(ui, session, look);
        }
    }
}

fn data_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        let label = ui.label(Phrase::FileField.get(lang));
        let mut path = session.settings.path.clone();
        let response = ui
            .add(egui::TextEdit::singleline(&mut path).desired_width(190.0))
            .labelled_by(label.id);
        if response.changed() {
            out.push(Command::SetPath(path));
        }
        let entered = response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if ui.button(Phrase::Load.get(lang)).clicked() || entered {
            out.push(Command::LoadPath);
        }
        if ui
            .button(Phrase::Example.get(lang))
            .on_hover_text(Phrase::ExampleHelp.get(lang))
            .clicked()
        {
            out.push(Command::LoadExample);
        }
        if ui.button(Phrase::Open.get(lang)).clicked() {
            out.push(Command::BrowseTest);
        }
    });
    egui::CollapsingHeader::new(Phrase::HowToRead.get(lang))
        .id_salt("how to read")
        .show(ui, |ui| reading_choices(ui, session, look, out));
    if let Some(message) = &session.message {
        let (error, text) = words::load_message(message, lang);
        let color = if error {
            look.palette.error
        } else {
            look.palette.weak_text
        };
        ui.label(RichText::new(text).color(color));
    }
}

/// The columns (the detected ones as hints), the sampling period and the input before the
/// record, for the next load.
fn reading_choices(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let s = &session.settings;
    let test = session.loaded.as_ref().map(|l| &l.test);
    egui::Grid::new("columns").num_columns(2).show(ui, |ui| {
        for (choice, text, detected) in [
            (
                Choice::TimeColumn,
                &s.time_col,
                test.map(|t| t.time_name.clone()),
            ),
            (
                Choice::OutputColumn,
                &s.y_col,
                test.map(|t| t.output_name.clone()),
            ),
            (
                Choice::InputColumn,
                &s.u_col,
                test.and_then(|t| t.input_name.clone()),
            ),
        ] {
            let label = ui.label(words::choice_name(choice, lang));
            let hint = match detected {
                Some(name) => Phrase::DetectedColumn.with(lang, &[name]),
                None => Phrase::ColumnHint.get(lang).to_string(),
            };
            let mut edited = text.clone();
            if ui
                .add(
                    egui::TextEdit::singleline(&mut edited)
                        .hint_text(hint)
                        .desired_width(150.0),
                )
                .labelled_by(label.id)
                .changed()
            {
                out.push(Command::SetChoice(choice, edited));
            }
            ui.end_row();
        }
    });
    input_file(ui, &s.u_path, look, out);
    optional_choice(
        ui,
        Choice::SamplingPeriod,
        &s.sampling_period,
        (Phrase::GiveSamplingPeriod, 1.0),
        Limits {
            min: 1e-9,
            max: 1e9,
            why: None,
        },
        look,
        out,
    );
    optional_choice(
        ui,
        Choice::InitialInput,
        &s.initial_input,
        (Phrase::GiveInitialInput, 0.0),
        Limits::default(),
        look,
        out,
    );
    ui.weak(Phrase::DropOrPaste.get(lang));
}

/// The input's own file, for the next load: a path field and a file dialog.
fn input_file(ui: &mut Ui, path: &str, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        let label = ui.label(words::choice_name(Choice::InputFile, lang));
        let mut edited = path.to_string();
        if ui
            .add(
                egui::TextEdit::singleline(&mut edited)
                    .hint_text(Phrase::InputFileHint.get(lang))
                    .desired_width(190.0),
            )
            .labelled_by(label.id)
            .changed()
        {
            out.push(Command::SetChoice(Choice::InputFile, edited));
        }
        if ui.button(Phrase::Open.get(lang)).clicked() {
            out.push(Command::BrowseInputFile);
        }
    });
}

/// A reading choice that is either not given or a number: a checkbox and a number field.
fn optional_choice(
    ui: &mut Ui,
    choice: Choice,
    text: &str,
    (give, start): (Phrase, f64),
    limits: Limits,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    let given = !text.trim().is_empty();
    ui.horizontal_wrapped(|ui| {
        let mut on = given;
        if ui.checkbox(&mut on, give.get(lang)).changed() {
            let text = if on { start.to_string() } else { String::new() };
            out.push(Command::SetChoice(choice, text));
        }
    });
    if given {
        let value = crate::field::parse_number(text).unwrap_or(start);
        if let Some(v) = NumberField::new(words::choice_name(choice, lang), value)
            .limits(limits)
            .show(ui, lang)
        {
            out.push(Command::SetChoice(choice, v.to_string()));
        }
    }
}

fn step_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(loaded) = session.loaded.as_ref() else {
        return;
    };
    let e = &loaded.experiment;
    let lang = look.lang;
    let (first, last) = (
        loaded.test.time.first().copied().unwrap_or(0.0),
        loaded.test.time.last().copied().unwrap_or(0.0),
    );
    let within = Limits {
        min: first,
        max: last,
        why: None,
    };
    drive_choices(ui, session, look, out);
    if e.drive == Drive::Step {
        if let Some(t0) = NumberField::new(Phrase::StepTime.get(lang), e.t0)
            .limits(within)
            .show(ui, lang)
        {
            out.push(Command::SetStepTime(t0));
        }
        if let Some(du) = NumberField::new(Phrase::StepSize.get(lang), e.du).show(ui, lang) {
            out.push(Command::SetStepSize(du));
        }
    }
    operating_point(ui, session, look, out);
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::Window.get(lang));
        let mut on = e.window.is_some();
        if ui.checkbox(&mut on, Phrase::KeepOnly.get(lang)).changed() {
            out.push(Command::SetWindow(on.then_some((first, last))));
        }
    });
    if let Some((a, b)) = e.window {
        ui.horizontal_wrapped(|ui| {
            if let Some(a) = NumberField::new(Phrase::WindowFrom.get(lang), a)
                .limits(within)
                .show(ui, lang)
            {
                out.push(Command::SetWindow(Some((a, b))));
            }
            if let Some(b) = NumberField::new(Phrase::WindowTo.get(lang), b)
                .limits(within)
                .show(ui, lang)
            {
                out.push(Command::SetWindow(Some((a, b))));
            }
        });
    }
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::Filter.get(lang));
        let mut on = e.filter_hz.is_some();
        if ui.checkbox(&mut on, Phrase::FilterOn.get(lang)).changed() {
            out.push(Command::SetFilter(on.then_some(1.0)));
        }
    });
    if let Some(fc) = e.filter_hz {
        if let Some(fc) = NumberField::new(Phrase::CutOff.get(lang), fc)
            .limits(Limits {
                min: 1e-6,
                max: 1e6,
                why: None,
            })
            .show(ui, lang)
        {
            out.push(Command::SetFilter(Some(fc)));
        }
        if let Ok(d) = &loaded.data {
            ui.weak(words::filter_description(fc, d.sampling_period(), lang));
        }
    }
    if let Err(e) = &loaded.data {
        ui.colored_label(look.palette.error, words::experiment_error(e, lang));
    }
}

/// What drove the test (the measured input, with its hold, or one ideal step), and the facts
/// of the input used: how many changes, how early each may have come, which change the
/// handles act on.
fn drive_choices(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(loaded) = session.loaded.as_ref() else {
        return;
    };
    let lang = look.lang;
    let drive = loaded.experiment.drive;
    let measurable = session.has_measured_input();
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::Drive.get(lang))
            .on_hover_text(Phrase::DriveHelp.get(lang));
        let hold = match drive {
            Drive::Measured { hold } => hold,
            Drive::Step => Hold::Zoh,
        };
        let measured = matches!(drive, Drive::Measured { .. });
        if ui
            .add_enabled(
                measurable,
                egui::RadioButton::new(measured, Phrase::DriveMeasured.get(lang)),
            )
            .clicked()
            && !measured
        {
            out.push(Command::SetDrive(Drive::Measured { hold }));
        }
        if ui.radio(!measured, Phrase::DriveStep.get(lang)).clicked() && measured {
            out.push(Command::SetDrive(Drive::Step));
        }
    });
    if !measurable {
        ui.weak(Phrase::NoInputToUse.get(lang));
    }
    if let Drive::Measured { hold } = drive {
        ui.horizontal_wrapped(|ui| {
            ui.label(Phrase::BetweenSamples.get(lang))
                .on_hover_text(Phrase::HoldHelp.get(lang));
            for (h, phrase) in [(Hold::Zoh, Phrase::HoldZoh), (Hold::Foh, Phrase::HoldFoh)] {
                if ui.radio(hold == h, phrase.get(lang)).clicked() && hold != h {
                    out.push(Command::SetDrive(Drive::Measured { hold: h }));
                }
            }
        });
    }
    let Ok(data) = &loaded.data else { return };
    ui.label(words::changes_used(data.input.changes.len(), lang));
    if let Some(lead) = words::change_lead(data.input.lead_range, lang) {
        ui.weak(lead);
    }
    if let Some(s) = session.handle_frame().and_then(|f| f.segment) {
        ui.weak(words::handles_on_largest(s.index, s.change.t, lang));
    }
}

/// The operating point: held at the level before the step, estimated, or typed; the value
/// held is said beside the choice.
fn operating_point(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(loaded) = session.loaded.as_ref() else {
        return;
    };
    let offset = loaded.experiment.offset;
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::OperatingPoint.get(lang));
        let choices = [
            (
                Phrase::MeanBefore,
                matches!(offset, Offset::Auto),
                OffsetChoice::Before,
            ),
            (
                Phrase::Estimate,
                matches!(offset, Offset::Free),
                OffsetChoice::Estimate,
            ),
            (
                Phrase::Typed,
                matches!(offset, Offset::Fixed(_)),
                OffsetChoice::Typed(None),
            ),
        ];
        for (phrase, selected, choice) in choices {
            if ui.radio(selected, phrase.get(lang)).clicked() && !selected {
                out.push(Command::SetOffset(choice));
            }
        }
    });
    let unit = session
        .output_unit()
        .map_or(String::new(), |u| format!(" {u}"));
    match offset {
        Offset::Auto => match session.held_operating_point() {
            Some(y0) => {
                let held = format!("{}{unit}", lang.num(y0, 4));
                ui.label(Phrase::HeldAt.with(lang, &[held]));
            }
            None => {
                // Why it is estimated: no sample before the step, too few before the first
                // of several changes, or the output still moved.
                let text = match session.operating_point_fact() {
                    Some(fact @ OperatingPoint::Estimated { .. }) => {
                        words::sentence(&fact.text(lang))
                    }
                    _ => Phrase::NoSampleBefore.get(lang).to_string(),
                };
                ui.label(RichText::new(text).color(look.palette.warning));
            }
        },
        Offset::Free => {
            ui.weak(Phrase::EstimatedY0.get(lang));
        }
        Offset::Fixed(v) => {
            let suffix = unit.clone();
            if let Some(v) = NumberField::new(Phrase::TypedY0.get(lang), v)
                .suffix(&suffix)
                .show(ui, lang)
            {
                out.push(Command::SetOffset(OffsetChoice::Typed(Some(v))));
            }
        }
    }
}

fn model_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(loaded) = session.loaded.as_ref() else {
        return;
    };
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        let label = ui.strong(Phrase::ModelStructure.get(lang));
        let current = session.settings.code.clone();
        egui::ComboBox::from_id_salt("model code")
            .selected_text(&current)
            .show_ui(ui, |ui| {
                for code in CODES {
                    if ui.selectable_label(current == code, code).clicked() && current != code {
                        out.push(Command::SetCode(code.to_string()));
                    }
                }
            })
            .response
            .labelled_by(label.id);
        let mut drift = session.settings.drift;
        if ui
            .checkbox(&mut drift, Phrase::Drift.get(lang))
            .on_hover_text(Phrase::DriftHelp.get(lang))
            .changed()
        {
            out.push(Command::SetDrift(drift));
        }
        if ui
            .button(Phrase::AutoGuess.get(lang))
            .on_hover_text(Phrase::AutoGuessHelp.get(lang))
            .clicked()
        {
            out.push(Command::AutoGuess);
        }
    });
    let data = loaded.data.as_ref().ok();
    // After a fit the fields hold its values, where the next fit starts: not a "guess".
    let named = if session.guess_is_fitted() {
        Phrase::FittedStartOf
    } else {
        Phrase::GuessOf
    };
    for p in loaded.structure.params() {
        let (min, max) = data.map_or((f64::NEG_INFINITY, f64::INFINITY), |d| bounds(p, d));
        let label = named.with(lang, &[p.name().to_string()]);
        let field = NumberField::new(&label, loaded.guess.get(p))
            .limits(Limits {
                min,
                max,
                why: None,
            })
            .suffix(p.unit());
        let response = ui.scope(|ui| field.show(ui, lang));
        response.response.on_hover_text(words::param_help(p, lang));
        if let Some(v) = response.inner {
            out.push(Command::SetGuess(p, v));
        }
    }
}

fn fit_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(loaded) = session.loaded.as_ref() else {
        return;
    };
    let s = &session.settings;
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        for m in [Method::LevenbergMarquardt, Method::NelderMead] {
            if ui.radio(s.method == m, words::method_name(m)).clicked() {
                out.push(Command::SetMethod(m));
            }
        }
    });
    ui.horizontal_wrapped(|ui| {
        let mut multistart = s.multistart;
        if ui
            .checkbox(&mut multistart, Phrase::Multistart.get(lang))
            .on_hover_text(Phrase::MultistartHelp.get(lang))
            .changed()
        {
            out.push(Command::SetMultistart(multistart));
        }
        if s.multistart {
            let mut starts = s.starts;
            let suffix = format!(" {}", Phrase::Starts.get(lang));
            if ui
                .add(
                    DragValue::new(&mut starts)
                        .range(2..=MAX_STARTS)
                        .suffix(suffix),
                )
                .changed()
            {
                out.push(Command::SetStarts(starts));
            }
        }
    });
    ui.horizontal_wrapped(|ui| {
        if session.is_fitting() {
            if ui.button(Phrase::Cancel.get(lang)).clicked() {
                out.push(Command::CancelFit);
            }
            ui.spinner();
        } else if ui
            .add_enabled(
                loaded.data.is_ok(),
                egui::Button::new(Phrase::Fit.get(lang)),
            )
            .clicked()
        {
            out.push(Command::Fit);
        }
        let status = words::status(&session.status, lang);
        if !status.is_empty() {
            ui.label(status);
        }
    });
}

fn results(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    // The fit drawn: a chain row chosen replots that row, and its table follows.
    let Some(report) = session.shown_report().or(session.report.as_ref()) else {
        return;
    };
    let lang = look.lang;
    ui.separator();
    ui.strong(Phrase::Fitted.with(lang, &[report.model.structure.code()]));
    egui::Grid::new("parameters")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            let (header, rows) = words::param_rows(report, lang);
            for head in &header {
                ui.strong(head);
            }
            ui.end_row();
            for (e, row) in report.params.iter().zip(&rows) {
                ui.label(&row[0])
                    .on_hover_text(words::param_help(e.param, lang));
                ui.label(&row[1]);
                ui.label(&row[2]);
                ui.end_row();
            }
        });
    // What the parameters of a measured input mean, said where a student reads them.
    for p in report.model.structure.params() {
        if matches!(p, Param::Ta | Param::X1 | Param::X2 | Param::X3) {
            ui.weak(format!("{}: {}", p.name(), words::param_help(p, lang)));
        }
    }
    for line in words::derived(&report.model, lang) {
        ui.label(line);
    }
    ui.label(words::fit_summary(report, lang));
    for w in &report.warnings {
        ui.label(RichText::new(words::warning(w, lang)).color(look.palette.warning));
    }
    ui.horizontal_wrapped(|ui| {
        if ui.button(Phrase::ShowOnSPlane.get(lang)).clicked() {
            out.push(Command::ShowOnSPlane);
        }
        if ui
            .button(crate::words::tune::Tune::TuneButton.get(lang))
            .on_hover_text(crate::words::tune::Tune::TuneButtonHelp.get(lang))
            .clicked()
        {
            out.push(Command::TuneController);
        }
        if ui.button(Phrase::CostLandscape.get(lang)).clicked() {
            out.push(Command::Landscape(LandscapeCommand::Open));
        }
    });
    ui.horizontal_wrapped(|ui| {
        for (kind, phrase) in [
            (CodeKind::Matlab, Phrase::CopyMatlab),
            (CodeKind::PythonControl, Phrase::CopyPython),
        ] {
            if ui
                .button(phrase.get(lang))
                .on_hover_text(Phrase::CopyHelp.get(lang))
                .clicked()
                && let Some(code) = session.fitted_code(kind)
            {
                // The clipboard is the platform's, not the session's state.
                ui.ctx().copy_text(code);
            }
        }
    });
}

/// Each step fitted on its own beside the joint fit: the job's progress and cancel button,
/// the table, and what it says about linearity.
fn per_step_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let Some(report) = session.report.as_ref() else {
        return;
    };
    let multi = session.input_plot().changes.len() > 1;
    if !multi {
        return;
    }
    let lang = look.lang;
    ui.separator();
    ui.strong(Phrase::PerStep.get(lang))
        .on_hover_text(Phrase::PerStepHelp.get(lang));
    let state = &session.per_step;
    if let Some(progress) = state.progress() {
        ui.horizontal_wrapped(|ui| {
            if ui.button(Phrase::Cancel.get(lang)).clicked() {
                out.push(Command::CancelPerStep);
            }
            ui.spinner();
            ui.label(words::per_step_progress(progress, lang));
        });
        return;
    }
    let Some(fits) = &state.fits else {
        if state.cancelled {
            ui.weak(Phrase::PerStepCancelled.get(lang));
        }
        if ui
            .add_enabled(
                !session.is_fitting(),
                egui::Button::new(Phrase::FitEachStep.get(lang)),
            )
            .clicked()
        {
            out.push(Command::FitEachStep);
        }
        return;
    };
    let table = words::per_step_rows(report, fits, lang);
    egui::ScrollArea::horizontal()
        .id_salt("per-step table")
        .show(ui, |ui| {
            egui::Grid::new("per-step")
                .striped(true)
                .num_columns(table.header.len())
                .show(ui, |ui| {
                    for head in &table.header {
                        ui.strong(head);
                    }
                    ui.end_row();
                    for row in &table.rows {
                        for cell in row {
                            ui.label(cell);
                        }
                        ui.end_row();
                    }
                });
        });
    let instant_step = session
        .fitted
        .as_ref()
        .map_or(0.0, |(_, d)| d.sampling_period());
    for line in words::agreement_lines(report, fits, instant_step, lang) {
        ui.label(line);
    }
}

/// "What does the model get wrong?": the cause in words, the buttons, the chain table.
fn diagnose_section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.heading(Phrase::WhatIsWrong.get(lang));
    ui.horizontal_wrapped(|ui| {
        if session.is_diagnosing() {
            if ui.button(Phrase::Cancel.get(lang)).clicked() {
                out.push(Command::CancelDiagnosis);
            }
            ui.spinner();
            if let Some(p) = session.diagnose_progress() {
                ui.label(words::diagnose_progress(&p, lang));
            }
            return;
        }
        let idle = !session.is_fitting();
        if ui
            .add_enabled(idle, egui::Button::new(Phrase::ExtendOnce.get(lang)))
            .on_hover_text(Phrase::ExtendOnceHelp.get(lang))
            .clicked()
        {
            out.push(Command::Diagnose { whole: false });
        }
        if ui
            .add_enabled(idle, egui::Button::new(Phrase::WholeLoop.get(lang)))
            .on_hover_text(Phrase::WholeLoopHelp.get(lang))
            .clicked()
        {
            out.push(Command::Diagnose { whole: true });
        }
    });
    let note = words::diagnose_note(&session.diagnose_note, lang);
    if !note.is_empty() {
        ui.label(note);
    }
    let Some(d) = &session.diagnosis else { return };
    egui::ScrollArea::horizontal()
        .id_salt("chain table")
        .show(ui, |ui| {
            egui::Grid::new("chain")
                .striped(true)
                .num_columns(5)
                .show(ui, |ui| {
                    let (header, rows) = words::chain_rows(d, lang);
                    for head in &header {
                        ui.strong(head);
                    }
                    ui.end_row();
                    for (k, row) in rows.iter().enumerate() {
                        let selected = session.selected_step == Some(k);
                        if ui
                            .selectable_label(selected, &row[0])
                            .on_hover_text(Phrase::RowHelp.get(lang))
                            .clicked()
                        {
                            out.push(Command::SelectStep(k));
                        }
                        for cell in &row[1..] {
                            ui.label(cell);
                        }
                        ui.end_row();
                    }
                });
        });
    if ui.button(Phrase::CopyTable.get(lang)).clicked() {
        ui.ctx().copy_text(words::chain_text(d, lang));
    }
    if let Some(step) = session.selected_chain_step() {
        let [cause, evidence, remedy] = words::step_lines(step, lang);
        ui.strong(cause);
        ui.label(evidence);
        ui.label(remedy);
    }
    // The verdict is said once: above the table when it is the last thing the loop said.
    if let Some(verdict) = &d.verdict
        && !matches!(session.diagnose_note, DiagnoseNote::Verdict(_))
    {
        ui.weak(verdict.text(lang));
    }
    // A gain the record measures only together with another term is said under the chain.
    if d.verdict.is_some() && d.gain_trade.is_some() {
        ui.label(words::static_gain_line(d, lang));
    }
}
