//! The metrics of one response, as a student reads them: final value, overshoot, peak (or
//! peak deviation) and its time, settling time, IAE and ITAE; "none" with the reason where a
//! metric is undefined, and "did not settle" for a loop that does not.

use eframe::egui::{self, RichText, Ui};

use degrau_lti::words::control::ControlWord as W;
use degrau_words::Lang;

use super::derived::Response;
use super::plots::Which;
use crate::look::Look;
use crate::words::tune::{NO_VALUE, Tune as T};

/// The rows (name, value) of a response's metrics.
pub fn rows(which: Which, r: &Response, lang: Lang) -> Vec<(&'static str, String)> {
    let m = &r.metrics;
    let num = |x: Option<f64>| match x {
        Some(x) => lang.num(x, 4),
        None if r.settled => T::NoneValue.get(lang).to_string(),
        None => NO_VALUE.to_string(),
    };
    let peak_name = match which {
        Which::Setpoint => W::Peak,
        Which::Load => W::PeakDeviation,
    };
    vec![
        (W::FinalValue.get(lang), num(m.final_value)),
        (W::Overshoot.get(lang), num(m.overshoot)),
        (peak_name.get(lang), num(m.peak.map(|p| p.value))),
        (W::PeakTime.get(lang), num(m.peak.map(|p| p.time))),
        (W::SettlingTime.get(lang), num(m.settling_time)),
        (W::Iae.get(lang), num(m.iae)),
        (W::Itae.get(lang), num(m.itae)),
    ]
}

pub fn show(ui: &mut Ui, which: Which, r: &Response, look: &Look) {
    let lang = look.lang;
    egui::Grid::new(("tune metrics", which as u8))
        .striped(true)
        .num_columns(2)
        .show(ui, |ui| {
            for (name, value) in rows(which, r, lang) {
                ui.label(name);
                ui.label(value);
                ui.end_row();
            }
        });
    let note = if !r.settled {
        Some((W::NotSettled.get(lang), look.palette.error))
    } else if r.metrics.iae.is_none() {
        Some((W::NoIntegralAction.get(lang), look.palette.warning))
    } else {
        None
    };
    if let Some((text, colour)) = note {
        ui.add(egui::Label::new(RichText::new(text).color(colour)).wrap());
    }
}
