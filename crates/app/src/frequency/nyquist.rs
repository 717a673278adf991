//! The Nyquist tab: the closed loop's count of right half-plane roots, from its
//! characteristic equation.

use eframe::egui::{self, Ui};

use degrau_words::Localize;

use super::commands::Command;
use super::derived::LoopData;
use super::session::{Saved, Session};
use crate::look::Look;
use crate::words::frequency::{self as words, Frequency as T};

pub fn show(
    ui: &mut Ui,
    _session: &Session,
    data: &LoopData,
    _kept: &Saved,
    look: &Look,
    _out: &mut Vec<Command>,
) {
    let lang = look.lang;
    let direct = match &data.closed_loop {
        Ok(z) => words::direct_count(*z, lang),
        Err(e) => e.text(lang),
    };
    ui.add(egui::Label::new(format!("{} {direct}", T::Direct.get(lang))).wrap());
}
