//! The PRBS designer: length, clock period, levels, periods and sampling period; the model
//! (a procest code and its values, or the Design mode's G(s)), noise and seed; the register
//! it gives; Export CSV (time, u, y) and Use as record. The plots: u and y against time.

use eframe::egui::{self, Ui};
use egui_plot::Line;

use crate::field::{LimitReason, Limits, NumberField};
use crate::identify::CODES;
use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_ident::words::lsq::LsqPhrase as L;
use degrau_lti::TransferFunction;
use degrau_words::Localize;

use super::commands::Command;
use super::designer::{ModelSource, PrbsSettings};
use super::session::{ExportNote, Session};
use super::{heading, note, warn, words};

/// The most samples a designed test may have.
const MAX_SAMPLES: f64 = 1_000_000.0;

pub fn panel(
    ui: &mut Ui,
    session: &Session,
    design: Option<&TransferFunction>,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    heading(ui, L::PrbsHeading.get(lang));
    note(ui, look, Phrase::PrbsNote.get(lang));
    let before = &session.prbs;
    let mut s = before.clone();
    signal_fields(ui, &mut s, look);
    heading(ui, Phrase::PrbsModel.get(lang));
    model_fields(ui, &mut s, design, look);
    if s != *before {
        out.push(Command::SetPrbs(s));
    }
    match &session.designed {
        None => {}
        Some(Err(e)) => warn(ui, look, &e.text(lang)),
        Some(Ok(d)) => {
            let p = d.prbs;
            ui.label(Phrase::Register.with(
                lang,
                &[
                    p.order.to_string(),
                    p.bits_per_period().to_string(),
                    p.clock.to_string(),
                    p.period().to_string(),
                    d.record.time.len().to_string(),
                ],
            ));
            ui.label(Phrase::NoiseStd.with(lang, &[words::num(d.noise_std, lang)]));
            ui.horizontal(|ui| {
                if ui.button(Phrase::ExportCsv.get(lang)).clicked() {
                    out.push(Command::BrowsePrbsExport);
                }
                if ui.button(Phrase::UseAsRecord.get(lang)).clicked() {
                    out.push(Command::UsePrbs);
                }
            });
        }
    }
    match &session.export_note {
        Some(ExportNote::Saved(path)) => note(
            ui,
            look,
            &Phrase::Saved.with(lang, std::slice::from_ref(path)),
        ),
        Some(ExportNote::Failed { path, reason }) => warn(
            ui,
            look,
            &Phrase::NotSaved.with(lang, &[path.clone(), reason.clone()]),
        ),
        Some(ExportNote::Used) => note(ui, look, Phrase::Used.get(lang)),
        None => {}
    }
}

/// A count field (at least `min`).
fn count(ui: &mut Ui, label: &str, value: usize, min: f64, max: f64, look: &Look) -> Option<usize> {
    NumberField::new(label, value as f64)
        .limits(Limits::new(min, max, LimitReason::Count))
        .show(ui, look.lang)
        .map(|v| v.round() as usize)
}

/// A number field within `limits`.
fn number(ui: &mut Ui, label: &str, value: f64, limits: Limits, look: &Look) -> Option<f64> {
    NumberField::new(label, value)
        .limits(limits)
        .show(ui, look.lang)
}

fn signal_fields(ui: &mut Ui, s: &mut PrbsSettings, look: &Look) {
    let lang = look.lang;
    if let Some(v) = count(
        ui,
        Phrase::Length.get(lang),
        s.samples,
        3.0,
        MAX_SAMPLES,
        look,
    ) {
        s.samples = v;
    }
    if let Some(v) = count(ui, L::Clock.get(lang), s.clock, 1.0, 10_000.0, look) {
        s.clock = v;
    }
    let any = Limits::default();
    if let Some(v) = number(ui, Phrase::Low.get(lang), s.low, any, look) {
        s.low = v;
    }
    if let Some(v) = number(ui, Phrase::High.get(lang), s.high, any, look) {
        s.high = v;
    }
    if let Some(v) = count(ui, Phrase::Periods.get(lang), s.periods, 1.0, 1000.0, look) {
        s.periods = v;
    }
    let positive = Limits {
        min: 1e-9,
        max: 1e9,
        why: None,
    };
    if let Some(v) = number(ui, L::SamplingPeriod.get(lang), s.ts, positive, look) {
        s.ts = v;
    }
}

fn model_fields(ui: &mut Ui, s: &mut PrbsSettings, design: Option<&TransferFunction>, look: &Look) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        ui.selectable_value(
            &mut s.source,
            ModelSource::Procest,
            Phrase::FromCode.get(lang),
        );
        ui.selectable_value(
            &mut s.source,
            ModelSource::Design,
            Phrase::FromDesign.get(lang),
        );
    });
    match s.source {
        ModelSource::Procest => {
            egui::ComboBox::from_label(Phrase::ModelCode.get(lang))
                .selected_text(s.code.clone())
                .show_ui(ui, |ui| {
                    for code in CODES {
                        ui.selectable_value(&mut s.code, code.to_string(), code);
                    }
                });
            for p in s.params() {
                let label = format!("{} {}", p.name(), p.unit()).trim().to_string();
                let field = NumberField::new(&label, s.values.get(p)).id_salt(("prbs", p.name()));
                if let Some(v) = field.show(ui, lang) {
                    s.values.set(p, v);
                }
            }
        }
        ModelSource::Design => match design {
            Some(tf) => {
                ui.label(format!(
                    "G(s) = {}",
                    degrau_lti::words::approx::formula(tf, lang)
                ));
            }
            None => warn(ui, look, Phrase::NoDesign.get(lang)),
        },
    }
    let percent = Limits {
        min: 0.0,
        max: 100.0,
        why: None,
    };
    if let Some(v) = number(
        ui,
        Phrase::NoisePercent.get(lang),
        s.noise_percent,
        percent,
        look,
    ) {
        s.noise_percent = v;
    }
    if let Some(v) = count(ui, Phrase::Seed.get(lang), s.seed as usize, 0.0, 1e12, look) {
        s.seed = v as u64;
    }
}

/// u and y against time.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    let Some(Ok(d)) = &session.designed else {
        ui.label(Phrase::NoDesignedTest.get(lang));
        return;
    };
    let r = &d.record;
    let height = (ui.available_height() - 60.0) / 2.0;
    ui.label(Phrase::PrbsInput.get(lang));
    words::time_plot("prbs input", height * 0.7, lang).show(ui, |plot| {
        plot.line(
            Line::new("u", words::pairs(&r.time, &r.u))
                .color(palette.main)
                .width(1.5),
        );
    });
    ui.label(Phrase::PrbsOutput.get(lang));
    words::time_plot("prbs output", height * 1.3, lang).show(ui, |plot| {
        plot.line(
            Line::new("y", words::pairs(&r.time, &r.y))
                .color(palette.data)
                .width(1.2),
        );
    });
}
