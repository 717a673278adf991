//! The τc field: a number of seconds, or empty for τc = θ. Its text is kept in egui's
//! widget memory while typed and committed on Enter or when focus leaves.

use eframe::egui::{self, RichText, Ui};

use degrau_words::Localize;

use super::commands::Command;
use super::session::{Refusal, Saved, Session};
use crate::field::parse_number;
use crate::look::Look;
use crate::words::tune::Tune as T;

/// The typing state of the field.
#[derive(Debug, Clone, Default)]
struct Buffer {
    text: String,
    editing: bool,
    /// The value the text was made from.
    source: Option<Option<f64>>,
    error: Option<String>,
}

pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let id = ui.make_persistent_id("tune tc");
    let mut b: Buffer = ui.data(|d| d.get_temp(id)).unwrap_or_default();
    if !b.editing && b.source != Some(kept.tc) && b.error.is_none() {
        b.text = kept.tc.map_or_else(String::new, |t| lang.num(t, 6));
        b.source = Some(kept.tc);
    }
    ui.horizontal_wrapped(|ui| {
        let name = ui.label(T::Tc.get(lang));
        let response = ui
            .add(
                egui::TextEdit::singleline(&mut b.text)
                    .id(id.with("text"))
                    .hint_text(T::TcEmpty.get(lang))
                    .desired_width(80.0),
            )
            .labelled_by(name.id);
        if response.has_focus() {
            b.editing = true;
        }
        if response.lost_focus() && b.editing {
            b.editing = false;
            if b.text.trim().is_empty() {
                b.error = None;
                out.push(Command::SetTc(None));
            } else {
                match parse_number(&b.text) {
                    Ok(v) => {
                        b.error = None;
                        out.push(Command::SetTc(Some(v)));
                    }
                    Err(e) => b.error = Some(e.text(lang)),
                }
            }
        }
    });
    ui.weak(T::TcEmpty.get(lang));
    if let Some(e) = &b.error {
        ui.add(egui::Label::new(RichText::new(e).color(look.palette.error)).wrap());
    }
    if let Some(r) = session
        .refusal
        .as_ref()
        .filter(|r| matches!(r, Refusal::Tc(_)))
    {
        ui.add(egui::Label::new(RichText::new(r.text(lang)).color(look.palette.error)).wrap());
    }
    ui.data_mut(|d| d.insert_temp(id, b));
}
