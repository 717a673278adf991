//! The left panel's source: which system the mode shows (the Design mode's G(s), the Tune
//! mode's loop C·G, or the Identify mode's fitted model when there is one), written out.

use eframe::egui::{self, RichText, Ui};

use degrau_lti::TransferFunction;
use degrau_lti::poly::format_poly;
use degrau_words::Lang;

use super::commands::Command;
use super::commands::SourceKind;
use super::session::{Saved, Session};
use crate::design::system_panel::fraction_text;
use crate::look::Look;
use crate::words::frequency::Frequency as T;

/// Draws the source's choice and its transfer functions.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.heading(T::SourceHeading.get(lang));
    for kind in SourceKind::ALL {
        let name = match kind {
            SourceKind::Design => T::SourceDesign,
            SourceKind::Tune => T::SourceTune,
            SourceKind::Fitted => T::SourceFitted,
        };
        let available = session.sources.get(kind).is_some();
        let text = if available || kind != SourceKind::Fitted {
            name.get(lang).to_string()
        } else {
            format!("{} {}", name.get(lang), T::NoFit.get(lang))
        };
        let radio = ui.add_enabled(available, egui::RadioButton::new(kept.source == kind, text));
        if radio.clicked() && kept.source != kind {
            out.push(Command::SetSource(kind));
        }
    }
    let Some(source) = &session.source else {
        ui.add(
            egui::Label::new(RichText::new(T::NoSource.get(lang)).color(look.palette.warning))
                .wrap(),
        );
        return;
    };
    ui.add_space(4.0);
    ui.label("G(s) =");
    written(ui, &source.plant, lang);
    if let Some(c) = &source.controller {
        ui.label(format!("{} C(s) =", T::Controller.get(lang)));
        let (num, den) = c.feedback_coeffs();
        // Written with a monic denominator, as a transfer function is.
        let lead = den.first().copied().filter(|d| *d != 0.0).unwrap_or(1.0);
        let monic = |p: &[f64]| p.iter().map(|x| x / lead).collect::<Vec<_>>();
        let text = fraction(&monic(&num), &monic(&den), 0.0, lang);
        ui.add(egui::Label::new(RichText::new(text).monospace()).wrap());
    }
}

/// `tf` as a fraction of polynomials, its dead time after the bar.
pub fn written(ui: &mut Ui, tf: &TransferFunction, lang: Lang) {
    ui.add(egui::Label::new(RichText::new(tf_text(tf, lang)).monospace()).wrap());
}

/// `tf` as three lines: numerator, bar (with e^(−θs)), denominator.
pub fn tf_text(tf: &TransferFunction, lang: Lang) -> String {
    fraction(&tf.num(), &tf.den(), tf.delay(), lang)
}

/// num/den as three lines, e^(−θs) after the bar (a P controller's den is 1: no
/// transfer function of its own, still written as a fraction).
fn fraction(num: &[f64], den: &[f64], delay: f64, lang: Lang) -> String {
    let num = lang.localize_number(&format_poly(num));
    let den = lang.localize_number(&format_poly(den));
    let delay = if delay > 0.0 {
        format!(" · e^(−{} s)", lang.num(delay, 6))
    } else {
        String::new()
    };
    fraction_text(&num, &den, &delay)
}
