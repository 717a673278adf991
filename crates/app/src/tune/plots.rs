//! The Tune mode's centre: the setpoint step response (with the setpoint) and the load
//! disturbance response side by side, each with its metrics under it, the dead time exact.

use eframe::egui::{self, RichText, Ui};
use egui_plot::{HLine, Line, LineStyle, Plot};

use degrau_lti::words::control::ControlWord as W;
use degrau_words::Localize;

use super::derived::{LoopTrouble, Response};
use super::session::Session;
use crate::look::Look;
use crate::words::tune::Tune as T;

/// The width kept beside each plot for its metrics (points).
const METRICS_WIDTH: f32 = 250.0;

/// Which of the two plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Which {
    Setpoint,
    Load,
}

impl Which {
    pub fn title(self) -> W {
        match self {
            Which::Setpoint => W::SetpointResponse,
            Which::Load => W::LoadResponse,
        }
    }
}

pub fn show(ui: &mut Ui, session: &Session, look: &Look) {
    let lang = look.lang;
    let view = match &session.view {
        Some(Ok(view)) => view,
        Some(Err(trouble)) => {
            let why = match trouble {
                LoopTrouble::Model(p) => p.text(lang),
                LoopTrouble::Controller(e) => e.text(lang),
                LoopTrouble::Loop(e) => e.text(lang),
            };
            ui.add(
                egui::Label::new(
                    RichText::new(format!("{} {why}", T::NoLoop.get(lang)))
                        .color(look.palette.error),
                )
                .wrap(),
            );
            return;
        }
        None => return,
    };
    ui.add(egui::Label::new(RichText::new(W::ExactDelay.get(lang)).weak()).wrap());
    // One above the other, each with its metrics beside it: both plots keep their width
    // in a 1000-point window.
    let half = (ui.available_height() - ui.spacing().item_spacing.y) / 2.0;
    let width = ui.available_width();
    for (which, r) in [(Which::Setpoint, &view.setpoint), (Which::Load, &view.load)] {
        ui.allocate_ui(egui::vec2(width, half), |ui| one(ui, which, r, look, half));
    }
}

fn one(ui: &mut Ui, which: Which, r: &Response, look: &Look, height: f32) {
    let lang = look.lang;
    let title = which.title().get(lang);
    let top = ui.cursor().top();
    ui.add(egui::Label::new(RichText::new(title).strong()).wrap());
    let used = ui.cursor().top() - top;
    let plot_height = (height - used - ui.spacing().item_spacing.y).max(crate::design::PLOT_MIN);
    let plot_width = (ui.available_width() - METRICS_WIDTH).max(crate::design::PLOT_MIN);
    let reference = match which {
        Which::Setpoint => (1.0, T::SetpointLine),
        Which::Load => (0.0, T::Undisturbed),
    };
    // The legend where the curve is not: below the setpoint's line; for a load, on the side
    // away from its peak deviation (the curve returns to 0 along the other side).
    let corner = match which {
        Which::Load if r.metrics.peak.is_some_and(|p| p.value > 0.0) => egui_plot::Corner::RightTop,
        _ => egui_plot::Corner::RightBottom,
    };
    ui.horizontal_top(|ui| {
        let shown = crate::grid::app_axes(Plot::new(("tune plot", which as u8)), lang)
            .x_grid_spacer(crate::grid::one_two_five())
            .x_axis_label("t (s)")
            .y_axis_label("y(t)")
            .height(plot_height)
            .width(plot_width)
            .min_size(egui::vec2(crate::design::PLOT_MIN, crate::design::PLOT_MIN))
            .legend(
                egui_plot::Legend::default()
                    .position(corner)
                    .background_alpha(0.75),
            )
            .show(ui, |plot| {
                plot.hline(
                    HLine::new(reference.1.get(lang), reference.0)
                        .color(look.palette.marker)
                        .style(LineStyle::dashed_dense())
                        .width(1.2),
                );
                plot.line(
                    Line::new(T::Output.get(lang), r.curve.clone())
                        .color(look.palette.main)
                        .width(2.2),
                );
            });
        crate::look::name_canvas(&shown.response, title);
        ui.vertical(|ui| super::metrics::show(ui, which, r, look));
    });
}
