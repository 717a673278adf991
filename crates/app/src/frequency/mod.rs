//! The Frequency mode: the source's loop in frequency. A Bode diagram (magnitude over phase
//! on one log-ω axis, the notes' asymptotes, the crossovers marked, a hover readout of the
//! exact values), the stability margins, the Nyquist diagram with its encirclement count
//! beside the closed loop's direct count, and the plant sampled with a zero-order hold on
//! the z-plane with the notes' sampling rules.
//!
//! The mode is a [`Session`] (the derived data; no egui) over its settings ([`Saved`], kept
//! in the app's state file), and views that read them and return [`Command`]s: the left
//! panel ([`source`], [`margins`]) and one view per tab ([`bode`], [`nyquist`], [`zplane`]).
//! The source's transfer function comes from the other modes ([`Sources`]), handed over by
//! the app before the mode draws; the app applies each command with [`Session::apply`]
//! once per frame, after the views.

pub mod bode;
pub mod commands;
pub mod derived;
pub mod margins;
pub mod nyquist;
pub mod nyquist_window;
pub mod rules;
pub mod session;
pub mod source;
pub mod zplane;

use eframe::egui::{self, Ui};

pub use commands::Command;
pub use commands::{SourceKind, Tab};
pub use session::{Saved, Session, Source, Sources};

use crate::look::Look;
use crate::words::frequency::Frequency as T;
use degrau_words::Localize;

/// The width the left panel starts with (points).
const PANEL_WIDTH: f32 = 330.0;
/// The narrowest the left panel goes (points).
const PANEL_MIN: f32 = 240.0;
/// Room kept beside the left panel (points): the z-plane's two plots side by side.
const CENTRE_MIN: f32 = 2.0 * crate::design::PLOT_MIN + 60.0;

/// Draws the Frequency mode in `ui` (the area below the menu and notices). Returns what
/// the student asked.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let mut commands = Vec::new();
    let full = ui.available_rect_before_wrap().width();
    let side_max = (full - CENTRE_MIN).max(PANEL_MIN);
    egui::Panel::left("frequency")
        .resizable(true)
        .default_size(PANEL_WIDTH.min(side_max))
        .size_range(PANEL_MIN..=side_max)
        .show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| {
                source::show(ui, session, kept, look, &mut commands);
                ui.separator();
                margins::show(ui, session, look);
            });
        });
    egui::CentralPanel::default().show(ui, |ui| {
        tabs(ui, kept, look, &mut commands);
        let Some(data) = &session.loop_data else {
            ui.add(egui::Label::new(T::NoSource.get(look.lang)).wrap());
            return;
        };
        let data = match data {
            Ok(d) => d,
            Err(e) => {
                let why = format!("{} {}", T::NoLoop.get(look.lang), e.text(look.lang));
                ui.colored_label(look.palette.error, why);
                return;
            }
        };
        match kept.tab {
            Tab::Bode => bode::show(ui, session, data, look),
            Tab::Nyquist => nyquist::show(ui, session, data, kept, look, &mut commands),
            Tab::ZPlane => zplane::show(ui, session, kept, look, &mut commands),
        }
    });
    commands
}

/// The tabs: Bode, Nyquist, z-plane.
fn tabs(ui: &mut Ui, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        for (tab, name) in [
            (Tab::Bode, T::TabBode),
            (Tab::Nyquist, T::TabNyquist),
            (Tab::ZPlane, T::TabZPlane),
        ] {
            if ui
                .selectable_label(kept.tab == tab, name.get(look.lang))
                .clicked()
                && kept.tab != tab
            {
                out.push(Command::SetTab(tab));
            }
        }
    });
    ui.separator();
}

/// A value written for the student: ∞ for an infinite one, else `digits` significant
/// digits in the language's numbers.
pub fn value(x: f64, digits: i32, lang: degrau_words::Lang) -> String {
    if x.is_infinite() {
        crate::words::frequency::INFINITE.to_string()
    } else {
        lang.num(x, digits)
    }
}
