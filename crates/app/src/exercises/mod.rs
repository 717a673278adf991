//! The Exercises mode: Barbosa's solved sheet on time responses as guided exercises. On the
//! left the exercises and their lettered parts with the student's progress; in the centre the
//! part open: its statement in the student's language, a button that loads its system into
//! the Design mode, one field per question, a Check that compares each answer with Degrau's
//! exact value (the exercise crate's [`degrau_exercise::check`]) and the worked solution,
//! with where the sheet's printed answer differs and why. Below the sheet, the
//! [`challenges`] (issue 27, item 2): a record with a hidden effect drawn off the UI thread,
//! opened in Identify, the student's cause, structure and gain checked against the hidden
//! truth, the evidence that gave it away, then Degrau's diagnosis ([`challenge_view`]).
//!
//! The mode is a [`Session`] (the sheet, the last Check's verdicts; no egui) over what it
//! keeps ([`Saved`], in the app's state file), and views that read them and return
//! [`Command`]s: [`list`] (the left side), [`part_view`] (the centre), with [`figure_view`]
//! (the figure a part is read off, laid out by the pure [`figure`]), [`answers`] (the
//! fields and their verdicts) and [`solution_view`]. The app applies each command with
//! [`Session::apply`] once per frame, after the views.

pub mod answers;
pub mod challenge_view;
pub mod challenges;
pub mod commands;
pub mod figure;
pub mod figure_view;
pub mod list;
pub mod load;
pub mod part_view;
pub mod session;
pub mod solution_view;
#[cfg(test)]
mod tests;

use eframe::egui::{self, RichText, Ui};

pub use commands::{ChallengeCommand, Command, Outcome};
pub use session::{Saved, Session};

use crate::look::Look;
use crate::words::exercises::Exercises as T;
use degrau_words::Localize;

/// The width the list starts with (points).
const LIST_WIDTH: f32 = 230.0;
/// The narrowest and widest the list goes (points).
const LIST_MIN: f32 = 170.0;
const LIST_MAX: f32 = 360.0;

/// Draws the Exercises mode in `ui` (the area below the menu and notices). Returns what the
/// student asked.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let mut commands = Vec::new();
    let sheet = match session.sheet() {
        Ok(sheet) => sheet,
        Err(e) => {
            egui::CentralPanel::default().show(ui, |ui| {
                ui.label(RichText::new(T::NoSheet.get(look.lang)).color(look.palette.error));
                ui.add(egui::Label::new(e.to_string()).wrap());
            });
            return commands;
        }
    };
    egui::Panel::left("exercises")
        .resizable(true)
        .default_size(LIST_WIDTH)
        .size_range(LIST_MIN..=LIST_MAX)
        .show(ui, |ui| {
            egui::ScrollArea::vertical()
                .id_salt("exercise list")
                .show(ui, |ui| {
                    list::show(ui, sheet, kept, look, &mut commands);
                    ui.separator();
                    challenge_view::list(ui, session, kept, look, &mut commands);
                });
        });
    egui::CentralPanel::default().show(ui, |ui| {
        egui::ScrollArea::vertical()
            .id_salt("exercise part")
            .auto_shrink([false, false])
            .show(ui, |ui| {
                if kept.challenges.open {
                    challenge_view::show(ui, session, kept, look, &mut commands);
                } else {
                    part_view::show(ui, session, sheet, kept, look, &mut commands);
                }
            });
    });
    commands
}

/// A wrapped label in the palette's weak text colour.
fn weak(ui: &mut Ui, text: impl Into<String>, look: &Look) {
    ui.add(egui::Label::new(RichText::new(text.into()).color(look.palette.weak_text)).wrap());
}

/// Something that cannot be done, said in the error colour.
fn refusal(ui: &mut Ui, what: &dyn Localize, look: &Look) {
    ui.add(egui::Label::new(RichText::new(what.text(look.lang)).color(look.palette.error)).wrap());
}
