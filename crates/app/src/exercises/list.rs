//! The left side of the Exercises mode: each exercise with its lettered parts, each part
//! marked with the student's progress (not tried, started, right, wrong); a click opens it.

use eframe::egui::{RichText, Ui};

use degrau_exercise::{Exercise, Part};

use super::Command;
use super::session::{Progress, Saved, progress};
use crate::look::Look;
use crate::words::exercises::Exercises as T;

/// The text of a part's entry in the list: its mark and id (`"● 8b"`).
pub fn entry(part: &Part, kept: &Saved) -> String {
    format!("{} {}", progress(part, kept).symbol(), part.id)
}

/// Draws the list.
pub fn show(ui: &mut Ui, sheet: &[Exercise], kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.heading(T::SheetHeading.get(lang));
    super::weak(ui, T::SheetSource.get(lang), look);
    ui.separator();
    for exercise in sheet {
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(format!("{} {}", T::Exercise.get(lang), exercise.id)).strong());
            for part in &exercise.parts {
                let mark = progress(part, kept);
                let text = RichText::new(entry(part, kept)).color(colour(mark, look));
                let open = part.id == kept.part;
                if ui
                    .selectable_label(open, text)
                    .on_hover_text(mark.word(lang))
                    .clicked()
                    && !open
                {
                    out.push(Command::Select(part.id.clone()));
                }
            }
        });
    }
}

/// The colour of a mark.
fn colour(mark: Progress, look: &Look) -> eframe::egui::Color32 {
    match mark {
        Progress::Right => look.palette.main,
        Progress::Wrong => look.palette.error,
        Progress::Started | Progress::NotTried => look.palette.weak_text,
    }
}
