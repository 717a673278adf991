//! The least-squares mode: the second half of the course notes on the Identify mode's record.
//! ARX least squares as the notes write it (Φ, Y, θ with standard errors, J, AIC over a small
//! grid, one-step prediction against free simulation, the model's d2c G(s) beside the
//! continuous fit), the notes' three-sample example with its regressors, recursive least
//! squares animated sample by sample, a PRBS test designed on a model and exported or used
//! as the record, estimation on one part of the record with validation on the other, and the
//! notes' sampling and amplitude rules with the record's own numbers.
//! Everything computed comes from [`degrau_ident::lsq::arx`], [`degrau_ident::lsq::rls`],
//! [`degrau_ident::lsq::prbs`], [`degrau_ident::lsq::validation`] and [`degrau_lti::discrete`].
//!
//! The mode is a [`Session`] (state and derived data; no egui) and views that read it and
//! return [`Command`]s: the right panel (the section's controls and tables) and the central
//! plot of the section. The top level calls, each frame, [`Session::sync`] (the Identify
//! mode's record and fit), [`Session::poll`] and [`Session::tick`] (the RLS animation), then
//! [`show`]; it applies each command with [`Session::apply`] in its own `apply` (as
//! `Command::Lsq`), and an [`Outcome`] (use a designed record, open a file dialog) becomes
//! the app's next command.

pub mod advisor;
pub mod advisor_view;
pub mod animation;
pub mod arx_view;
pub mod commands;
pub mod designer;
pub mod example_view;
pub mod prbs_view;
pub mod rls_view;
pub mod samples;
pub mod session;
pub mod validation_view;
pub mod words;

use eframe::egui::{self, RichText};

use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_lti::TransferFunction;

pub use commands::{Command, Outcome, Section};
pub use session::Session;

/// The width the right panel starts with (px).
const PANEL_WIDTH: f32 = 440.0;

/// Draws the least-squares mode in `ui`: the section tabs and controls on the right, the
/// section's plot in the centre. Returns what the student asked.
pub fn show(
    ui: &mut egui::Ui,
    session: &Session,
    design: Option<&TransferFunction>,
    look: &Look,
) -> Vec<Command> {
    let mut out = Vec::new();
    egui::Panel::right("least squares")
        .resizable(true)
        .default_size(PANEL_WIDTH)
        .show(ui, |ui| {
            tabs(ui, session, look, &mut out);
            ui.separator();
            egui::ScrollArea::vertical().show(ui, |ui| match session.section {
                Section::Arx => arx_view::panel(ui, session, look, &mut out),
                Section::Example => example_view::panel(ui, session, look, &mut out),
                Section::Rls => rls_view::panel(ui, session, look, &mut out),
                Section::Prbs => prbs_view::panel(ui, session, design, look, &mut out),
                Section::Validation => validation_view::panel(ui, session, look, &mut out),
                Section::Advisor => advisor_view::panel(ui, session, look),
            });
        });
    egui::CentralPanel::default().show(ui, |ui| {
        let needs_record = !matches!(session.section, Section::Example | Section::Prbs);
        if needs_record && session.samples.is_none() {
            ui.centered_and_justified(|ui| {
                ui.label(Phrase::NoRecord.get(look.lang));
            });
            return;
        }
        match session.section {
            Section::Arx => arx_view::plot(ui, session, look),
            Section::Example => example_view::plot(ui, session, look),
            Section::Rls => rls_view::plot(ui, session, look),
            Section::Prbs => prbs_view::plot(ui, session, look),
            Section::Validation => validation_view::plot(ui, session, look),
            Section::Advisor => advisor_view::plot(ui, session, look),
        }
    });
    out
}

/// The sections as tabs.
fn tabs(ui: &mut egui::Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        for s in Section::ALL {
            if ui
                .selectable_label(session.section == s, words::section(s, look.lang))
                .clicked()
                && session.section != s
            {
                out.push(Command::SetSection(s));
            }
        }
    });
}

/// A heading in the panel.
pub(crate) fn heading(ui: &mut egui::Ui, text: &str) {
    ui.add_space(6.0);
    ui.label(RichText::new(text).strong());
}

/// A refusal or a failure, in the warning colour, wrapped.
pub(crate) fn warn(ui: &mut egui::Ui, look: &Look, text: &str) {
    ui.add(egui::Label::new(RichText::new(text).color(look.palette.warning)).wrap());
}

/// A quiet explanation, wrapped.
pub(crate) fn note(ui: &mut egui::Ui, look: &Look, text: &str) {
    ui.add(egui::Label::new(RichText::new(text).color(look.palette.weak_text)).wrap());
}
