//! The answer fields of a part: one text field per question, named by the question's label
//! and unit, and under it the verdict of the last Check (● or × and the exercise crate's
//! message, which says Degrau's value, the formula's and where the sheet differs).

use eframe::egui::{self, RichText, Ui};

use degrau_exercise::{Lang, Part, Question, Verdict};

use super::Command;
use super::session::{Progress, Saved, Session};
use crate::look::Look;

/// The field's label: the question's, with its unit (`"Compensator pole a (s⁻¹)"`).
pub fn field_label(q: &Question, lang: Lang) -> String {
    let unit = match &q.expected {
        degrau_exercise::Expected::Number { unit, .. } => unit.symbol(),
        _ => "",
    };
    if unit.is_empty() {
        q.label.get(lang).to_string()
    } else {
        format!("{} ({unit})", q.label.get(lang))
    }
}

/// The line under a field after a Check: the mark and the message.
pub fn verdict_line(v: &Verdict, lang: Lang) -> String {
    let mark = if v.right {
        Progress::Right
    } else {
        Progress::Wrong
    };
    format!("{} {}", mark.symbol(), v.message.get(lang))
}

/// Draws the fields of `part`.
pub fn show(
    ui: &mut Ui,
    session: &Session,
    part: &Part,
    kept: &Saved,
    look: &Look,
    out: &mut Vec<Command>,
) {
    ui.label(RichText::new(crate::words::exercises::Exercises::Answers.get(look.lang)).strong());
    for q in &part.questions {
        field(ui, q, kept, look, out);
        if let Some(v) = session.verdict(&q.id) {
            let colour = if v.right {
                look.palette.main
            } else {
                look.palette.error
            };
            ui.add(
                egui::Label::new(RichText::new(verdict_line(v, look.lang)).color(colour)).wrap(),
            );
        }
        ui.add_space(4.0);
    }
}

/// One question's label and field; a change is a [`Command::Type`].
fn field(ui: &mut Ui, q: &Question, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let name = ui.add(egui::Label::new(field_label(q, look.lang)).wrap());
    let mut text = kept
        .answers
        .get(&q.id)
        .map(|a| a.text.clone())
        .unwrap_or_default();
    let edit = egui::TextEdit::singleline(&mut text)
        .id_salt(("exercise answer", &q.id))
        .desired_width(f32::INFINITY);
    if ui.add(edit).labelled_by(name.id).changed() {
        out.push(Command::Type {
            question: q.id.clone(),
            text,
        });
    }
}
