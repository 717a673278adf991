//! The validation section, the notes' sixth step: a split of the record (a fraction of the
//! samples or a time, drawn as a vertical line); ARX (prediction and simulation), RLS's final
//! model and the Identify mode's continuous model estimated before it, each with its fit % on
//! the estimation part and on the validation part side by side, and the residual checks on
//! the validation part.

use eframe::egui::{self, Ui};
use egui_plot::{Line, LineStyle, Points, VLine};

use crate::field::{Limits, NumberField};
use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_ident::diagnose::residuals::ResidualAnalysis;
use degrau_ident::lsq::validation::{ArxValidation, Split};
use degrau_ident::words::lsq::LsqPhrase as L;
use degrau_words::Localize;

use super::commands::Command;
use super::session::Session;
use super::{heading, note, warn, words};

pub fn panel(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, L::Validation.get(lang));
    note(ui, look, Phrase::ValidationNote.get(lang));
    split(ui, session, look, out);
    let Some(v) = &session.validation else {
        note(ui, look, Phrase::NoRecord.get(lang));
        return;
    };
    if let Err(e) = &v.split {
        warn(ui, look, &e.text(lang));
        return;
    }
    ui.label(Phrase::ArxOrders.with(
        lang,
        &[
            session.orders.na.to_string(),
            session.orders.nb.to_string(),
            session.orders.nk.to_string(),
        ],
    ));
    egui::Grid::new("validation")
        .striped(true)
        .num_columns(7)
        .show(ui, |ui| {
            ui.label(Phrase::Model.get(lang));
            ui.label(L::Estimation.get(lang));
            ui.label(L::Validation.get(lang));
            ui.label(L::ResidualsWhite.get(lang));
            ui.label(Phrase::LagsOutside.get(lang));
            ui.label(Phrase::RunsZ.get(lang));
            ui.label(Phrase::ResidualStd.get(lang));
            ui.end_row();
            arx_rows(ui, Phrase::ArxName, &v.arx, look);
            arx_rows(ui, Phrase::RlsName, &v.rls, look);
            if let Some(Ok(c)) = &session.continuous_validation {
                ui.label(Phrase::ContinuousName.with(lang, &[c.report.model.structure.code()]));
                ui.label(words::percent(c.estimation_fit_percent, lang));
                ui.label(words::percent(c.validation_fit_percent, lang));
                checks(ui, &c.checks, look);
                ui.end_row();
            }
        });
    note(ui, look, Phrase::ChecksNote.get(lang));
    continuous(ui, session, look, out);
}

/// The split's kind and value.
fn split(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let current = session.split;
    let end = session
        .samples
        .as_ref()
        .and_then(|s| s.time.last().copied())
        .unwrap_or(1.0);
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::SplitAt.get(lang));
        let fraction = matches!(current, Split::Fraction(_));
        if ui
            .selectable_label(fraction, Phrase::SplitFraction.get(lang))
            .clicked()
            && !fraction
        {
            out.push(Command::SetSplit(Split::Fraction(0.5)));
        }
        if ui
            .selectable_label(!fraction, Phrase::SplitTime.get(lang))
            .clicked()
            && fraction
        {
            let t = session.split_time().unwrap_or(end / 2.0);
            out.push(Command::SetSplit(Split::Time(t)));
        }
    });
    match current {
        Split::Fraction(f) => {
            let field = NumberField::new(Phrase::EstimationShare.get(lang), f).limits(Limits {
                min: 0.01,
                max: 0.99,
                why: None,
            });
            if let Some(v) = field.show(ui, lang) {
                out.push(Command::SetSplit(Split::Fraction(v)));
            }
        }
        Split::Time(t) => {
            if let Some(v) = NumberField::new(Phrase::SplitTimeField.get(lang), t)
                .suffix("s")
                .show(ui, lang)
            {
                out.push(Command::SetSplit(Split::Time(v)));
            }
        }
    }
}

/// The prediction and simulation rows of an ARX-shaped model.
fn arx_rows(
    ui: &mut Ui,
    name: Phrase,
    v: &Result<ArxValidation, degrau_ident::lsq::arx::LsqError>,
    look: &Look,
) {
    let lang = look.lang;
    match v {
        Err(e) => {
            ui.label(name.get(lang));
            ui.label(e.text(lang));
            ui.end_row();
        }
        Ok(v) => {
            let fits = |ui: &mut Ui, how: Phrase, (estimation, validation): (f64, f64)| {
                ui.label(format!("{} — {}", name.get(lang), how.get(lang)));
                ui.label(words::percent(estimation, lang));
                ui.label(words::percent(validation, lang));
            };
            let (e, va) = (&v.estimation, &v.validation);
            let prediction = (e.fit_percent_prediction, va.fit_percent_prediction);
            fits(ui, Phrase::PredictionShort, prediction);
            checks(ui, &v.residuals, look);
            ui.end_row();
            let simulation = (e.fit_percent_simulation, va.fit_percent_simulation);
            fits(ui, Phrase::SimulationShort, simulation);
            for _ in 0..4 {
                ui.label("");
            }
            ui.end_row();
        }
    }
}

/// The residual checks' four cells.
fn checks(ui: &mut Ui, r: &ResidualAnalysis, look: &Look) {
    let lang = look.lang;
    ui.label(if r.white { L::Yes } else { L::No }.get(lang));
    ui.label(format!(
        "{} / {}",
        r.outside_band.len(),
        r.autocorrelation.len().saturating_sub(1)
    ));
    ui.label(lang.num(r.runs.z, 3));
    ui.label(words::num(r.std, lang));
}

/// The continuous model's validation: its button, its progress, its refusal.
fn continuous(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, Phrase::ContinuousValidation.get(lang));
    if session.is_validating() {
        ui.horizontal(|ui| {
            ui.spinner();
            ui.label(Phrase::Validating.get(lang));
            if ui.button(Phrase::Cancel.get(lang)).clicked() {
                out.push(Command::CancelContinuous);
            }
        });
        return;
    }
    if ui.button(Phrase::ValidateContinuous.get(lang)).clicked() {
        out.push(Command::ValidateContinuous);
    }
    if let Some(Err(e)) = &session.continuous_validation {
        warn(ui, look, &e.text(lang));
    }
}

/// The record, the models over it from the start, and the split.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    let Some(s) = &session.samples else { return };
    ui.label(Phrase::ValidationPlot.get(lang));
    let v = session.validation.as_ref();
    let shown = words::time_plot("validation plot", ui.available_height(), lang).show(ui, |plot| {
        plot.points(
            Points::new(Phrase::Measured.get(lang), words::pairs(&s.time, &s.y))
                .color(palette.data)
                .radius(2.0),
        );
        let sims = v.into_iter().flat_map(|v| {
            [
                (Phrase::ArxName, v.arx.as_ref().ok(), palette.model),
                (Phrase::RlsName, v.rls.as_ref().ok(), palette.main),
            ]
        });
        for (name, a, colour) in sims {
            if let Some(a) = a {
                let from = session.orders.max_lag().min(s.time.len());
                plot.line(
                    Line::new(
                        Phrase::SimulationOf.with(lang, &[name.get(lang).to_string()]),
                        words::pairs(&s.time[from..], &a.validation.simulation[from..]),
                    )
                    .color(colour)
                    .width(1.5),
                );
            }
        }
        if let Some(Ok(c)) = &session.continuous_validation {
            let yhat: Vec<f64> = s.y.iter().zip(&c.residuals).map(|(y, e)| y - e).collect();
            plot.line(
                Line::new(
                    Phrase::ContinuousName.with(lang, &[c.report.model.structure.code()]),
                    words::pairs(&s.time, &yhat),
                )
                .color(palette.compare)
                .width(1.5)
                .style(LineStyle::dashed_loose()),
            );
        }
        if let Some(t) = session.split_time() {
            plot.vline(
                VLine::new(Phrase::SplitLine.get(lang), t)
                    .color(palette.marker)
                    .width(2.0),
            );
        }
    });
    crate::look::name_canvas(&shown.response, Phrase::ValidationPlot.get(lang));
}
