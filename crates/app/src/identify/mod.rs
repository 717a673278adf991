//! The Identify mode: load a measured step test, say how to read it (columns, sampling
//! period, step, operating point, window, filter), drag a model's guesses on the plot, fit it
//! off the UI thread with progress and a cancel button, read the parameters with their
//! intervals and the residuals, ask what the model gets wrong, and look at the cost
//! landscape. Everything computed comes from [`degrau_ident`].
//!
//! The mode is a [`Session`] (its state, jobs and derived data; no egui) and views that read
//! it and return [`Command`]s: [`panel`] (the right side), [`plot`] (the centre),
//! [`test_causes`] (what the test got wrong, in both) and [`landscape`] (a window). The
//! app, each frame, calls [`Session::poll`], then [`show`]; it applies each command with
//! [`Session::apply`] in its own `apply` (as `Command::Identify`), and an [`Outcome`] (open
//! the fitted model in Design, open a file dialog) becomes the app's next command.

pub mod commands;
pub mod cost;
pub mod grab;
pub mod hand;
pub mod hand_state;
pub mod landscape;
pub mod panel;
pub mod plot;
pub mod session;
pub mod steps;
pub mod test_causes;
pub mod words;

use eframe::egui;

use crate::look::Look;

pub use commands::{Command, Outcome};
pub use session::{CODES, Saved, Session};

/// The width the right panel starts with (px).
const PANEL_WIDTH: f32 = 380.0;

/// Draws the identification mode in `ui` (the area below the menu bar and notices): its
/// right panel, its central plots and its landscape window. Returns what the student asked.
pub fn show(ui: &mut egui::Ui, session: &Session, look: &Look) -> Vec<Command> {
    let mut commands = Vec::new();
    egui::Panel::right("identification")
        .resizable(true)
        .default_size(PANEL_WIDTH)
        .show(ui, |ui| {
            egui::ScrollArea::vertical()
                .show(ui, |ui| panel::show(ui, session, look, &mut commands));
        });
    egui::CentralPanel::default().show(ui, |ui| plot::show(ui, session, look, &mut commands));
    landscape::show(ui.ctx(), session, look, &mut commands);
    commands
}
