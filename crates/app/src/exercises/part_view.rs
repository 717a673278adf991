//! The centre of the Exercises mode: the part open, its statement (the exercise's and the
//! part's, in the student's language), the figure it is read off and the readings taken off
//! it (or its specs), the button that loads its system into the Design mode, the answer
//! fields, Check and the worked solution.

use eframe::egui::{self, RichText, Ui};

use degrau_exercise::{Exercise, Part, System};

use super::session::{Saved, Session};
use super::{Command, answers, figure_view, solution_view};
use crate::look::Look;
use crate::words::exercises::Exercises as T;

/// The exercise holding the part `id`, and the part.
pub fn find<'a>(sheet: &'a [Exercise], id: &str) -> Option<(&'a Exercise, &'a Part)> {
    sheet.iter().find_map(|e| e.part(id).map(|p| (e, p)))
}

/// Draws the part open.
pub fn show(
    ui: &mut Ui,
    session: &Session,
    sheet: &[Exercise],
    kept: &Saved,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let Some((exercise, part)) = find(sheet, &kept.part) else {
        return;
    };
    statement(ui, exercise, part, look);
    figure_view::show(ui, part, look);
    readings(ui, part, look);
    open_button(ui, session, part, look, out);
    ui.separator();
    answers::show(ui, session, part, kept, look, out);
    ui.add_space(4.0);
    buttons(ui, session, part, look, out);
    if session.solution_shown(&part.id) {
        ui.separator();
        solution_view::show(ui, part, look);
    }
}

/// The exercise's statement and the part's, wrapped.
fn statement(ui: &mut Ui, exercise: &Exercise, part: &Part, look: &Look) {
    let lang = look.lang;
    ui.heading(format!("{} {}", T::Exercise.get(lang), exercise.id));
    ui.add(egui::Label::new(exercise.statement.get(lang)).wrap());
    ui.add_space(4.0);
    ui.add(egui::Label::new(RichText::new(part.statement.get(lang)).strong()).wrap());
    ui.add_space(4.0);
}

/// The numbers a part gives besides its statement: a figure's readings, or specs.
fn readings(ui: &mut Ui, part: &Part, look: &Look) {
    let lang = look.lang;
    let (heading, list) = match &part.system {
        System::Figure { readings, .. } => (T::FigureReadings, readings),
        System::Specs { specs, .. } => (T::Specs, specs),
        System::Tf { .. } | System::Loop { .. } => return,
    };
    ui.label(heading.get(lang));
    for r in list {
        let line = format!(
            "• {} = {} {}",
            r.label.get(lang),
            degrau_exercise::text::num(lang, r.value),
            r.unit.symbol()
        );
        ui.add(egui::Label::new(line.trim_end()).wrap());
    }
    ui.add_space(4.0);
}

/// "Open in Poles and zeros", and why it cannot when it cannot.
fn open_button(ui: &mut Ui, session: &Session, part: &Part, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    if ui
        .button(crate::words::exercises::open_in_design(lang))
        .on_hover_text(T::OpenHelp.get(lang))
        .clicked()
    {
        out.push(Command::OpenInDesign(part.id.clone()));
    }
    if let Some((id, problem)) = &session.load_problem
        && *id == part.id
    {
        super::refusal(ui, problem, look);
    }
}

/// Check, and the worked solution shown or hidden.
fn buttons(ui: &mut Ui, session: &Session, part: &Part, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        if ui
            .button(RichText::new(T::Check.get(lang)).strong())
            .on_hover_text(T::CheckHelp.get(lang))
            .clicked()
        {
            out.push(Command::Check(part.id.clone()));
        }
        let shown = session.solution_shown(&part.id);
        let toggle = if shown {
            T::HideSolution
        } else {
            T::ShowSolution
        };
        if ui.button(toggle.get(lang)).clicked() {
            out.push(Command::ShowSolution(part.id.clone(), !shown));
        }
    });
}
