//! The RLS section: λ and α (P0 = α·I), Run / Pause / Step / Reset, the current sample's e_k
//! and θ_k beside the batch solution; the plot: each parameter's trajectory against k, the
//! batch solution dashed in the same colour.

use eframe::egui::{self, Color32, Ui};
use egui_plot::{HLine, Line, LineStyle, Plot};

use crate::field::{Limits, NumberField};
use crate::look::{Look, Palette};
use crate::words::lsq_app::Phrase;
use degrau_ident::words::lsq::{LsqPhrase as L, parameter_name};
use degrau_words::Localize;

use super::animation::Animation;
use super::commands::Command;
use super::session::Session;
use super::{arx_view, heading, note, warn, words};

pub fn panel(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    heading(ui, L::RlsHeading.get(lang));
    note(ui, look, Phrase::RlsEquations.get(lang));
    arx_view::orders(ui, session.orders, look, out);
    arx_view::offset(ui, session.offset, look, out);
    let o = &session.rls_options;
    let lambda = NumberField::new(L::Forgetting.get(lang), o.lambda)
        .limits(Limits {
            min: 1e-3,
            max: 1.0,
            why: None,
        })
        .show(ui, lang);
    if let Some(l) = lambda {
        out.push(Command::SetLambda(l));
    }
    let alpha = NumberField::new(L::InitialCovariance.get(lang), o.alpha)
        .limits(Limits {
            min: 1e-9,
            max: 1e12,
            why: None,
        })
        .show(ui, lang);
    if let Some(a) = alpha {
        out.push(Command::SetAlpha(a));
    }
    buttons(ui, session, look, out);
    match &session.animation {
        None => note(ui, look, Phrase::RlsPress.get(lang)),
        Some(Err(e)) => warn(ui, look, &e.text(lang)),
        Some(Ok(a)) => state(ui, a, look),
    }
}

fn buttons(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let has = session.samples.is_some();
    let running = session.is_running();
    ui.horizontal(|ui| {
        let mut button = |ui: &mut Ui, enabled: bool, p: Phrase, c: Command| {
            if ui
                .add_enabled(enabled, egui::Button::new(p.get(lang)))
                .clicked()
            {
                out.push(c);
            }
        };
        button(ui, has && !running, Phrase::Run, Command::RlsRun);
        button(ui, running, Phrase::Pause, Command::RlsPause);
        button(ui, has, Phrase::Step, Command::RlsStep);
        button(ui, has, Phrase::Reset, Command::RlsReset);
    });
}

/// Where the run is: k, e_k, θ_k and the batch θ.
fn state(ui: &mut Ui, a: &Animation, look: &Look) {
    let lang = look.lang;
    ui.label(Phrase::RlsProgress.with(lang, &[a.taken().to_string(), a.rows().to_string()]));
    if let (Some(k), Some(e)) = (a.last_sample(), a.errors.last()) {
        ui.label(format!("k = {k}, e_k = {}", words::num(*e, lang)));
    }
    let batch = a.batch.as_ref().ok();
    egui::Grid::new("rls theta")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            ui.label(L::Parameter.get(lang));
            ui.label("θ_k");
            ui.label(Phrase::Batch.get(lang));
            ui.end_row();
            for (i, r) in a.regression.regressors.iter().enumerate() {
                ui.label(parameter_name(*r, a.orders.nk));
                ui.label(words::num(a.theta()[i], lang));
                ui.label(batch.map_or("—".into(), |b| words::num(b.theta[i], lang)));
                ui.end_row();
            }
        });
    if let Err(e) = &a.batch {
        warn(ui, look, &e.text(lang));
    }
    if a.finished() {
        note(ui, look, Phrase::RlsDone.get(lang));
    }
}

/// The colour of parameter `i`.
fn colour(palette: &Palette, i: usize) -> Color32 {
    let cycle = [
        palette.main,
        palette.model,
        palette.compare,
        palette.marker,
        palette.pole,
        palette.damping,
    ];
    cycle[i % cycle.len()]
}

/// θ_k against k, the batch solution dashed.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    ui.label(Phrase::RlsPlot.get(lang));
    let Some(Ok(a)) = &session.animation else {
        note(ui, look, Phrase::RlsPress.get(lang));
        return;
    };
    let first = a.regression.first;
    let shown = crate::grid::app_axes(Plot::new("rls plot"), lang)
        .height(ui.available_height().max(160.0))
        .x_axis_label("k")
        .legend(egui_plot::Legend::default().position(egui_plot::Corner::RightBottom))
        .include_x(first as f64)
        .include_x((first + a.rows()) as f64)
        .show(ui, |plot| {
            for (i, r) in a.regression.regressors.iter().enumerate() {
                let name = parameter_name(*r, a.orders.nk);
                let c = colour(palette, i);
                let points: Vec<[f64; 2]> = a
                    .trajectory
                    .iter()
                    .enumerate()
                    .map(|(row, t)| [(first + row) as f64, t[i]])
                    .collect();
                plot.line(Line::new(name.clone(), points).color(c).width(2.0));
                if let Ok(b) = &a.batch {
                    plot.hline(
                        HLine::new(Phrase::BatchOf.with(lang, &[name]), b.theta[i])
                            .color(c)
                            .style(LineStyle::dashed_loose()),
                    );
                }
            }
        });
    crate::look::name_canvas(&shown.response, Phrase::RlsPlot.get(lang));
}
