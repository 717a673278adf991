//! The notes' three-sample example (u = [0, 1, 2], y = [0, 0.9, 2.1]): the three models
//! (a constant; θ0 + θ1·u(k); θ0 + θ1·u(k) + θ2·u(k−1)), each with its regressors Φ and Y on
//! screen, θ and J, and the three side by side so the student sees J fall as regressors are
//! added. The plot: y(k) and each model's Φθ against k.

use eframe::egui::{self, Ui};
use egui_plot::{Line, Plot, Points};

use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_words::Localize;

use super::commands::{Command, ExampleModel};
use super::session::{EXAMPLE_U, EXAMPLE_Y, ExampleFit, Session};
use super::{arx_view, heading, note, warn, words};

/// The model's equation as the notes write it.
fn equation(model: ExampleModel) -> &'static str {
    match model {
        ExampleModel::Constant => "y(k) = θ0",
        ExampleModel::Line => "y(k) = θ0 + θ1·u(k)",
        ExampleModel::TwoInputs => "y(k) = θ0 + θ1·u(k) + θ2·u(k−1)",
    }
}

pub fn panel(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, Phrase::ExampleHeading.get(lang));
    note(ui, look, Phrase::ExampleData.get(lang));
    for m in ExampleModel::ALL {
        if ui
            .selectable_label(session.example == m, equation(m))
            .clicked()
            && session.example != m
        {
            out.push(Command::SetExample(m));
        }
    }
    if let Some(fit) = session.example_fit() {
        chosen(ui, fit, look);
    }
    heading(ui, Phrase::ExampleAll.get(lang));
    egui::Grid::new("example models")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            ui.label(Phrase::Model.get(lang));
            ui.label("θ");
            ui.label("J");
            ui.end_row();
            for fit in &session.examples {
                ui.label(equation(fit.model));
                match &fit.lsq {
                    Ok(l) => {
                        ui.label(words::vector(&l.theta, lang));
                        ui.label(words::cost(l.j, y_scale(fit), lang));
                    }
                    Err(e) => {
                        ui.label(e.text(lang));
                        ui.label("—");
                    }
                }
                ui.end_row();
            }
        });
}

/// The chosen model: Φ and Y, θ and J.
fn chosen(ui: &mut Ui, fit: &ExampleFit, look: &Look) {
    let lang = look.lang;
    let regression = match &fit.regression {
        Ok(r) => r,
        Err(e) => {
            warn(ui, look, &e.text(lang));
            return;
        }
    };
    arx_view::regressors(ui, regression, look);
    match &fit.lsq {
        Ok(l) => {
            ui.label(format!("θ = {}", words::vector(&l.theta, lang)));
            ui.label(format!(
                "{} = {}",
                Phrase::Cost.get(lang),
                words::cost(l.j, y_scale(fit), lang)
            ));
            note(ui, look, Phrase::ExampleSolve.get(lang));
        }
        Err(e) => warn(ui, look, &e.text(lang)),
    }
}

/// YᵀY of the example's rows.
fn y_scale(fit: &ExampleFit) -> f64 {
    fit.regression.as_ref().map_or(1.0, |r| r.y.norm_squared())
}

/// y(k) and each model's fitted Φθ against k.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    ui.label(Phrase::ExamplePlot.get(lang));
    let k: Vec<f64> = (0..EXAMPLE_Y.len()).map(|k| k as f64).collect();
    let colours = [palette.compare, palette.main, palette.model];
    let shown = Plot::new("example plot")
        .height(ui.available_height().max(160.0))
        .x_axis_label("k")
        .legend(egui_plot::Legend::default().position(egui_plot::Corner::LeftTop))
        .show(ui, |plot| {
            plot.points(
                Points::new("y(k)", words::pairs(&k, &EXAMPLE_Y))
                    .color(palette.data)
                    .radius(5.0),
            );
            plot.points(
                Points::new("u(k)", words::pairs(&k, &EXAMPLE_U))
                    .color(palette.weak_text)
                    .shape(egui_plot::MarkerShape::Square)
                    .radius(3.0),
            );
            for (fit, colour) in session.examples.iter().zip(colours) {
                let (Ok(r), Ok(l)) = (&fit.regression, &fit.lsq) else {
                    continue;
                };
                let theta = nalgebra::DVector::from_column_slice(&l.theta);
                let yhat = &r.phi * theta;
                let width = if fit.model == session.example {
                    2.5
                } else {
                    1.0
                };
                plot.line(
                    Line::new(equation(fit.model), words::pairs(&k, yhat.as_slice()))
                        .color(colour)
                        .width(width),
                );
            }
        });
    crate::look::name_canvas(&shown.response, Phrase::ExamplePlot.get(lang));
}
