//! A part's worked solution, step by step (the exercise crate's
//! [`degrau_exercise::solution`]), and, for each question whose printed answer on the sheet
//! differs from Degrau's, what the sheet prints and why it differs.

use eframe::egui::{self, RichText, Ui};

use degrau_exercise::{Part, solution};

use crate::look::Look;
use crate::words::exercises::Exercises as T;

/// Draws the solution of `part`.
pub fn show(ui: &mut Ui, part: &Part, look: &Look) {
    let lang = look.lang;
    ui.label(RichText::new(T::Solution.get(lang)).strong());
    for step in solution(part, lang) {
        ui.add(egui::Label::new(step.line).wrap());
        ui.add_space(2.0);
    }
    let differing: Vec<_> = part
        .questions
        .iter()
        .filter_map(|q| Some((q, q.sheet.as_ref()?, q.difference.as_ref()?)))
        .collect();
    if differing.is_empty() {
        return;
    }
    ui.add_space(4.0);
    ui.label(RichText::new(T::SheetDiffers.get(lang)).strong());
    for (q, printed, why) in differing {
        let line = format!(
            "{}: {} {}. {}",
            q.label.get(lang),
            T::SheetPrints.get(lang),
            printed,
            why.get(lang)
        );
        ui.add(egui::Label::new(RichText::new(line).color(look.palette.warning)).wrap());
    }
}
