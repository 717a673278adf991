//! The Tune mode: from a process model (typed, or the Identify mode's fit) to a controller.
//! The student picks P, PI, PD or PID, types or drags Kc, Ti, Td (and N, b), or takes a
//! tuning rule's, and watches the loop's setpoint and load responses, computed with the
//! dead time exact (no Padé), and their metrics.
//!
//! The mode is a [`Session`] (the derived data; no egui) over its settings ([`Saved`], kept
//! in the app's state file), and views that read them and return [`Command`]s: [`panel`]
//! (the left side: the model, the controller, τc and the rules' [`table`]) and [`plots`] (the centre:
//! both responses with their [`metrics`]). The app applies each command with
//! [`Session::apply`] once per frame, after the views.

pub mod commands;
pub mod derived;
pub mod metrics;
pub mod model;
pub mod panel;
pub mod plots;
pub mod session;
pub mod table;
mod tc_field;

use eframe::egui::{self, Ui};

pub use commands::Command;
pub use session::{Saved, Session};

use crate::look::Look;

/// The width the left panel starts with (points).
const PANEL_WIDTH: f32 = 360.0;
/// The widest the left panel starts (points): the rule table's ten columns whole.
const PANEL_WIDE: f32 = 680.0;
/// The share of the window the left panel starts with, between the two widths above.
const PANEL_SHARE: f32 = 0.42;
/// The narrowest the left panel goes (points).
const PANEL_MIN: f32 = 240.0;
/// Room kept beside the left panel (points): a plot at its narrowest and the metrics'
/// column beside it.
const CENTRE_MIN: f32 = crate::design::PLOT_MIN + METRICS_WIDTH;
/// The metrics' column beside each plot, with the margins (points).
const METRICS_WIDTH: f32 = 360.0;

/// Draws the Tune mode in `ui` (the area below the menu and notices). Returns what the
/// student asked.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let mut commands = Vec::new();
    let full = ui.available_rect_before_wrap().width();
    let side_max = (full - CENTRE_MIN).max(PANEL_MIN);
    egui::Panel::left("tune")
        .resizable(true)
        .default_size(
            (PANEL_SHARE * full)
                .clamp(PANEL_WIDTH, PANEL_WIDE)
                .min(side_max),
        )
        .size_range(PANEL_MIN..=side_max)
        .show(ui, |ui| {
            egui::ScrollArea::vertical()
                .show(ui, |ui| panel::show(ui, session, kept, look, &mut commands));
        });
    egui::CentralPanel::default().show(ui, |ui| plots::show(ui, session, look));
    commands
}
