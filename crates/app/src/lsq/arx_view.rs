//! The ARX section: the orders and the operating point, Fit; θ with standard errors, J, AIC,
//! the fit % of the one-step prediction and of the free simulation side by side, the ARX
//! model's d2c G(s) beside the Identify mode's continuous fit, the AIC grid, and Φ and Y as the
//! notes write them. The plot: the measured output, the prediction, the simulation and the
//! continuous fit.

use eframe::egui::{self, Ui};
use egui_plot::{Line, Points};

use crate::field::{LimitReason, Limits, NumberField};
use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_ident::lsq::arx::{ArxOrders, Offset, Regression, fit_percent};
use degrau_ident::words::lsq::{LsqPhrase as L, parameter_name, regressor_symbol};
use degrau_words::Localize;

use super::commands::Command;
use super::session::{ArxResult, Session};
use super::{heading, note, warn, words};

/// Rows of Φ shown (the rest is counted).
const PHI_ROWS: usize = 200;

/// The largest order or delay typed.
const MAX_ORDER: f64 = 20.0;

pub fn panel(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, L::ArxHeading.get(lang));
    note(ui, look, Phrase::ArxEquation.get(lang));
    orders(ui, session.orders, look, out);
    offset(ui, session.offset, look, out);
    if ui
        .add_enabled(
            session.samples.is_some(),
            egui::Button::new(Phrase::Fit.get(lang)),
        )
        .clicked()
    {
        out.push(Command::Fit);
    }
    match &session.arx {
        None if session.samples.is_some() => note(ui, look, Phrase::PressFit.get(lang)),
        None => note(ui, look, Phrase::NoRecord.get(lang)),
        Some(Err(e)) => warn(ui, look, &e.text(lang)),
        Some(Ok(r)) => results(ui, session, r, look, out),
    }
}

/// The na, nb, nk fields.
pub fn orders(ui: &mut Ui, orders: ArxOrders, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let count = |min: f64| Limits::new(min, MAX_ORDER, LimitReason::Count);
    let field = |ui: &mut Ui, label: &str, value: usize, min: f64| {
        NumberField::new(label, value as f64)
            .limits(count(min))
            .width(50.0)
            .show(ui, lang)
            .map(|v| v.round() as usize)
    };
    ui.horizontal_wrapped(|ui| {
        let mut o = orders;
        if let Some(v) = field(ui, "na", o.na, 0.0) {
            o.na = v;
        }
        if let Some(v) = field(ui, "nb", o.nb, 0.0) {
            o.nb = v;
        }
        if let Some(v) = field(ui, "nk", o.nk, 0.0) {
            o.nk = v;
        }
        if o != orders {
            out.push(Command::SetOrders(o));
        }
    });
}

/// How the operating point is handled.
pub fn offset(ui: &mut Ui, offset: Offset, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        ui.label(L::OperatingPoint.get(lang));
        for (o, p) in [
            (Offset::Initial, Phrase::OffsetInitial),
            (Offset::Constant, Phrase::OffsetConstant),
            (Offset::None, Phrase::OffsetNone),
        ] {
            if ui.selectable_label(offset == o, p.get(lang)).clicked() && offset != o {
                out.push(Command::SetOffset(o));
            }
        }
    });
}

fn results(ui: &mut Ui, session: &Session, r: &ArxResult, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let fit = &r.fit;
    heading(ui, Phrase::Estimate.get(lang));
    parameter_table(
        ui,
        &fit.regression,
        &fit.lsq.theta,
        &fit.lsq.se,
        fit.model.orders.nk,
        look,
    );
    egui::Grid::new("arx figures")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label(Phrase::Cost.get(lang));
            ui.label(words::num(fit.lsq.j, lang));
            ui.end_row();
            ui.label(L::Rows.get(lang));
            ui.label(fit.regression.y.len().to_string());
            ui.end_row();
            ui.label(L::Aic.get(lang));
            ui.label(words::num(fit.aic, lang));
            ui.end_row();
            ui.label(L::SamplingPeriod.get(lang));
            ui.label(words::num(fit.model.ts, lang));
            ui.end_row();
            if fit.offset == Offset::Initial {
                ui.label(L::OperatingPoint.get(lang));
                ui.label(format!(
                    "({}, {})",
                    words::num(fit.model.u0, lang),
                    words::num(fit.model.y0, lang)
                ));
                ui.end_row();
            }
        });
    heading(ui, Phrase::TwoFits.get(lang));
    egui::Grid::new("arx fit percent")
        .striped(true)
        .num_columns(2)
        .show(ui, |ui| {
            ui.label(L::FitPrediction.get(lang));
            ui.label(L::FitSimulation.get(lang));
            ui.end_row();
            ui.label(words::percent(fit.scores.fit_percent_prediction, lang));
            ui.label(words::percent(fit.scores.fit_percent_simulation, lang));
            ui.end_row();
        });
    note(ui, look, Phrase::WhichIsWhich.get(lang));
    heading(ui, Phrase::D2c.get(lang));
    match &r.d2c {
        Ok(tf) => {
            ui.label(format!(
                "G(s) = {}",
                degrau_lti::words::approx::formula(tf, lang)
            ));
        }
        Err(e) => warn(ui, look, &e.text(lang)),
    }
    continuous(ui, session, look);
    grid(ui, r, look, out);
    regressors(ui, &fit.regression, look);
}

/// θ with its standard errors, one row per regressor.
pub fn parameter_table(
    ui: &mut Ui,
    regression: &Regression,
    theta: &[f64],
    se: &[Option<f64>],
    nk: usize,
    look: &Look,
) {
    let lang = look.lang;
    egui::Grid::new(("theta", regression.regressors.len()))
        .striped(true)
        .num_columns(4)
        .show(ui, |ui| {
            ui.label(L::Parameter.get(lang));
            ui.label(L::Regressors.get(lang));
            ui.label(L::Value.get(lang));
            ui.label(L::StandardError.get(lang));
            ui.end_row();
            for (i, r) in regression.regressors.iter().enumerate() {
                ui.label(parameter_name(*r, nk));
                ui.label(regressor_symbol(*r));
                ui.label(words::num(theta[i], lang));
                ui.label(se[i].map_or("—".into(), |s| words::num(s, lang)));
                ui.end_row();
            }
        });
}

/// The Identify mode's continuous fit, written out with its fit % on the same samples.
fn continuous(ui: &mut Ui, session: &Session, look: &Look) {
    let lang = look.lang;
    heading(ui, Phrase::ContinuousFit.get(lang));
    match (&session.continuous, &session.samples) {
        (Some((model, yhat)), Some(s)) => {
            if let Ok(tf) = model.transfer_function() {
                ui.label(format!(
                    "{}: G(s) = {}",
                    model.structure.code(),
                    degrau_lti::words::approx::formula(&tf, lang)
                ));
            }
            ui.label(
                Phrase::ContinuousFitPercent
                    .with(lang, &[words::percent(fit_percent(&s.y, yhat), lang)]),
            );
        }
        _ => note(ui, look, Phrase::NoContinuousFit.get(lang)),
    }
}

/// The AIC grid, best first; a row's button fits its orders.
fn grid(ui: &mut Ui, r: &ArxResult, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, L::Candidates.get(lang));
    let candidates = match &r.grid {
        Ok(c) => c,
        Err(e) => {
            warn(ui, look, &e.text(lang));
            return;
        }
    };
    note(ui, look, Phrase::AicNote.get(lang));
    egui::ScrollArea::vertical()
        .id_salt("aic grid")
        .max_height(220.0)
        .show(ui, |ui| {
            egui::Grid::new("aic")
                .striped(true)
                .num_columns(7)
                .show(ui, |ui| {
                    for h in ["na", "nb", "nk"] {
                        ui.label(h);
                    }
                    ui.label(L::Aic.get(lang));
                    ui.label(Phrase::PredictionShort.get(lang));
                    ui.label(Phrase::SimulationShort.get(lang));
                    ui.label("");
                    ui.end_row();
                    for c in candidates {
                        let o = c.orders;
                        for v in [o.na, o.nb, o.nk] {
                            ui.label(v.to_string());
                        }
                        ui.label(words::num(c.aic, lang));
                        ui.label(words::percent(c.fit_percent_prediction, lang));
                        ui.label(words::percent(c.fit_percent_simulation, lang));
                        let label = Phrase::FitThese.with(
                            lang,
                            &[o.na.to_string(), o.nb.to_string(), o.nk.to_string()],
                        );
                        if o == r.fit.model.orders {
                            ui.label(Phrase::Current.get(lang));
                        } else if ui.small_button(label).clicked() {
                            out.push(Command::FitOrders(o));
                        }
                        ui.end_row();
                    }
                });
        });
}

/// Φ and Y, the first rows, scrollable.
pub fn regressors(ui: &mut Ui, regression: &Regression, look: &Look) {
    let lang = look.lang;
    heading(ui, Phrase::PhiAndY.get(lang));
    let rows = regression.y.len();
    if rows > PHI_ROWS {
        note(
            ui,
            look,
            &Phrase::FirstRows.with(lang, &[PHI_ROWS.to_string(), rows.to_string()]),
        );
    }
    egui::ScrollArea::both()
        .id_salt(("phi", regression.regressors.len()))
        .max_height(240.0)
        .show(ui, |ui| {
            egui::Grid::new(("phi grid", regression.regressors.len()))
                .striped(true)
                .show(ui, |ui| {
                    ui.label("k");
                    for r in &regression.regressors {
                        ui.label(regressor_symbol(*r));
                    }
                    ui.label("y(k)");
                    ui.end_row();
                    for row in 0..rows.min(PHI_ROWS) {
                        ui.label((regression.first + row).to_string());
                        for c in 0..regression.phi.ncols() {
                            ui.label(words::num(regression.phi[(row, c)], lang));
                        }
                        ui.label(words::num(regression.y[row], lang));
                        ui.end_row();
                    }
                });
        });
}

/// The measured output, the ARX prediction and simulation, and the continuous fit.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    let Some(s) = &session.samples else { return };
    ui.label(Phrase::ArxPlot.get(lang));
    let fit = session.arx_fit().map(|r| &r.fit);
    let shown = words::time_plot("arx plot", ui.available_height(), lang).show(ui, |plot| {
        plot.points(
            Points::new(Phrase::Measured.get(lang), words::pairs(&s.time, &s.y))
                .color(palette.data)
                .radius(2.0),
        );
        if let Some(f) = fit {
            let from = f.scores.from;
            plot.line(
                Line::new(
                    Phrase::Prediction.get(lang),
                    words::pairs(&s.time[from..], &f.scores.prediction[from..]),
                )
                .color(palette.main)
                .width(1.5),
            );
            plot.line(
                Line::new(
                    Phrase::Simulation.get(lang),
                    words::pairs(&s.time[from..], &f.scores.simulation[from..]),
                )
                .color(palette.model)
                .width(2.0),
            );
        }
        if let Some((_, yhat)) = &session.continuous {
            plot.line(
                Line::new(
                    Phrase::ContinuousCurve.get(lang),
                    words::pairs(&s.time, yhat),
                )
                .color(palette.compare)
                .width(1.5)
                .style(egui_plot::LineStyle::dashed_loose()),
            );
        }
    });
    crate::look::name_canvas(&shown.response, Phrase::ArxPlot.get(lang));
}
