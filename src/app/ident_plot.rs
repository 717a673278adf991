//! The identification plots: the measured samples, the model (the guess being dragged, the
//! fit animating towards the data, or the result), the measured curve's own step
//! characteristics, draggable handles for the guesses, and the residuals y − ŷ beneath on
//! the same time axis.

use eframe::egui::{self, Color32, Id, Rect, Sense, Stroke, Ui, Vec2};
use egui_plot::{HLine, Legend, Line, Plot, PlotPoint, Points, VLine};

use crate::app::identify::IdentView;
use crate::app::step_plot::{Markers, draw_step_markers};
use crate::ident::handles::{self, Handle};
use crate::ident::models::Model;
use crate::lti::StepInfoOptions;
use crate::lti::number::sig;

/// Pixels around a handle that grab it.
const GRAB: f32 = 9.0;

/// Draws both plots into `ui`.
pub fn show(ui: &mut Ui, view: &mut IdentView) {
    let Some(loaded) = view.loaded.as_ref() else {
        ui.centered_and_justified(|ui| {
            ui.label("Load a step test: File → Open a step test…, type its path on the right, drop it here, paste columns, or press Example for the LECI test of the course notes.");
        });
        return;
    };
    let Ok(data) = loaded.data.clone() else {
        ui.label("The chosen window and filter leave nothing to show.");
        return;
    };
    let model = view.shown_model();
    let setup = data.setup;
    let t_end = data.times.last().copied().unwrap_or(setup.t0);
    let t_start = data.times.first().copied().unwrap_or(0.0);
    let measured: Vec<[f64; 2]> = data
        .times
        .iter()
        .zip(&data.y)
        .map(|(t, y)| [*t, *y])
        .collect();
    let fine: Vec<f64> = (0..=800)
        .map(|k| t_start + (t_end - t_start) * k as f64 / 800.0)
        .collect();
    let curve = model.and_then(|m| m.simulate(&setup, &fine).ok());
    let info = measured_info(view, &data);
    let dark = ui.visuals().dark_mode;
    let (data_color, model_color, marker_color) = if dark {
        (
            Color32::from_rgb(200, 200, 200),
            Color32::from_rgb(255, 150, 80),
            Color32::from_rgb(120, 190, 255),
        )
    } else {
        (
            Color32::from_rgb(60, 60, 60),
            Color32::from_rgb(210, 80, 0),
            Color32::from_rgb(20, 90, 200),
        )
    };
    let link = Id::unique("identification time axis");
    let height = ui.available_height();
    ui.label("Measured output and model");
    let markers = view.markers;
    let evidence = view.evidence_interval();
    let response = Plot::new("identification")
        .height(height * 0.62)
        .legend(
            Legend::default()
                .position(egui_plot::Corner::RightBottom)
                .text_style(egui::TextStyle::Small),
        )
        .x_axis_label("t (s)")
        .y_axis_label("y")
        .y_grid_spacer(super::grid::one_two_five())
        .y_axis_formatter(super::grid::tick_label)
        .allow_drag(false)
        .link_axis(link, [true, false])
        .show(ui, |plot| {
            plot.points(
                Points::new("measured", measured.clone())
                    .color(data_color)
                    .radius(2.0),
            );
            plot.vline(
                VLine::new(format!("step at t0 = {} s", sig(setup.t0, 4)), setup.t0)
                    .color(data_color.gamma_multiply(0.5)),
            );
            if let Some((a, b)) = evidence {
                plot.span(
                    egui_plot::Span::new("evidence", a..=b)
                        .fill(Color32::from_rgba_unmultiplied(230, 60, 60, 40)),
                );
            }
            if let Some(info) = &info {
                let value_at = |t: f64| interpolate(&measured, t);
                draw_step_markers(
                    plot,
                    info,
                    &StepInfoOptions::default(),
                    &value_at,
                    setup.t0,
                    &markers,
                    marker_color,
                );
            }
            if let Some(c) = &curve {
                let name = if view.is_fitting() {
                    "model (fitting…)"
                } else if view.report.is_some() {
                    "fitted model"
                } else {
                    "model (guess)"
                };
                let points: Vec<[f64; 2]> = fine.iter().zip(c).map(|(t, y)| [*t, *y]).collect();
                plot.line(Line::new(name, points).color(model_color).width(2.0));
            }
        });
    if !view.is_fitting() {
        // The line first, so that a model handle on top of it wins the pointer.
        drag_step_line(ui, view, &response.transform);
        if let Some(m) = model {
            drag_handles(ui, view, &response.transform, m, t_end);
        }
    }
    ui.label("Residuals y − ŷ");
    let residuals: Vec<[f64; 2]> = match model.and_then(|m| m.simulate(&setup, &data.times).ok()) {
        Some(yhat) => data
            .times
            .iter()
            .zip(&data.y)
            .zip(yhat)
            .map(|((t, y), m)| [*t, y - m])
            .collect(),
        None => Vec::new(),
    };
    Plot::new("residuals")
        .height(ui.available_height())
        .x_axis_label("t (s)")
        .y_axis_label("y − ŷ")
        .y_grid_spacer(super::grid::one_two_five())
        .y_axis_formatter(super::grid::tick_label)
        .link_axis(link, [true, false])
        .show(ui, |plot| {
            plot.hline(HLine::new("zero", 0.0).color(data_color.gamma_multiply(0.5)));
            plot.line(
                Line::new("residual", residuals.clone())
                    .color(model_color)
                    .width(1.2),
            );
            plot.points(
                Points::new("residual", residuals)
                    .color(model_color)
                    .radius(1.5),
            );
        });
}

/// The measured curve's step characteristics relative to y0 and its final level.
fn measured_info(
    view: &IdentView,
    data: &crate::ident::fit::FitData,
) -> Option<crate::lti::StepInfo> {
    let l = view.loaded.as_ref()?;
    let y0 = l
        .experiment
        .operating_point(data)
        .unwrap_or_else(|| l.guess.get(crate::ident::models::Param::Y0));
    let y_final = crate::ident::guess::features(data, Some(y0)).y_final;
    let pieces = crate::ident::prepare::SampledPieces::new(&data.times, &data.y, data.setup.t0);
    Some(crate::lti::StepInfo::from_pieces(
        &pieces,
        y0,
        y_final,
        &StepInfoOptions::default(),
    ))
}

/// Linear interpolation of sorted (t, y) points.
fn interpolate(points: &[[f64; 2]], t: f64) -> f64 {
    match points.iter().position(|p| p[0] >= t) {
        Some(0) => points[0][1],
        Some(k) => {
            let (a, b) = (points[k - 1], points[k]);
            if b[0] == a[0] {
                b[1]
            } else {
                a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
            }
        }
        None => points.last().map_or(0.0, |p| p[1]),
    }
}

/// The guess handles over the plot: accessible widgets a student (or a test) drags.
fn drag_handles(
    ui: &mut Ui,
    view: &mut IdentView,
    transform: &egui_plot::PlotTransform,
    model: Model,
    t_end: f64,
) {
    let Some(setup) = view
        .loaded
        .as_ref()
        .and_then(|l| l.data.as_ref().ok())
        .map(|d| d.setup)
    else {
        return;
    };
    let frame: Rect = *transform.frame();
    for handle in handles::handles(&model) {
        let Some((t, y)) = handles::position(&model, &setup, t_end, handle) else {
            continue;
        };
        let at = transform.position_from_point(&PlotPoint::new(t, y));
        if !frame.expand(GRAB).contains(at) {
            continue;
        }
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * GRAB));
        let response = ui.interact(
            rect,
            Id::unique(("ident handle", handle_key(handle))),
            Sense::drag(),
        );
        response
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, handle.label()));
        let response = response.on_hover_text(handle.help());
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let value = transform.value_from_position(p);
            view.set_guess(handles::drag(
                &model,
                &setup,
                t_end,
                handle,
                (value.x, value.y),
            ));
        }
        let active = response.hovered() || response.dragged();
        let painter = ui.painter_at(frame.expand(GRAB));
        let color = if active {
            Color32::from_rgb(240, 170, 0)
        } else {
            Color32::from_rgb(210, 80, 0)
        };
        painter.circle(at, 5.5, color.gamma_multiply(0.35), Stroke::new(2.0, color));
    }
}

/// The step time t0 as a vertical line dragged left or right, within the record.
fn drag_step_line(ui: &mut Ui, view: &mut IdentView, transform: &egui_plot::PlotTransform) {
    let Some(l) = view.loaded.as_ref() else {
        return;
    };
    let (Some(&first), Some(&last)) = (l.test.time.first(), l.test.time.last()) else {
        return;
    };
    let frame: Rect = *transform.frame();
    let x = transform
        .position_from_point(&PlotPoint::new(l.experiment.t0, 0.0))
        .x;
    if !(frame.left()..=frame.right()).contains(&x) {
        return;
    }
    let rect = Rect::from_x_y_ranges(x - 4.0..=x + 4.0, frame.y_range());
    let response = ui.interact(rect, Id::unique("step time line"), Sense::drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, "step time line"));
    let response = response
        .on_hover_text("Drag left or right: the step time t0.")
        .on_hover_cursor(egui::CursorIcon::ResizeHorizontal);
    if response.dragged()
        && let Some(p) = ui.ctx().pointer_interact_pos()
    {
        view.set_step_time(transform.value_from_position(p).x.clamp(first, last));
    }
    if response.hovered() || response.dragged() {
        ui.painter_at(frame).vline(
            x,
            frame.y_range(),
            Stroke::new(2.0, Color32::from_rgb(240, 170, 0)),
        );
    }
}

fn handle_key(h: Handle) -> u8 {
    match h {
        Handle::FinalValue => 0,
        Handle::DeadTime => 1,
        Handle::TimeConstant => 2,
        Handle::FirstPeak => 3,
    }
}

/// Markers toggles for the measured curve (same as the step plot's).
pub fn marker_controls(ui: &mut Ui, markers: &mut Markers) {
    ui.horizontal(|ui| {
        ui.label("Measured characteristics:");
        ui.checkbox(&mut markers.rise, "Rise");
        ui.checkbox(&mut markers.peak, "Peak");
        ui.checkbox(&mut markers.settling, "Settling");
        ui.checkbox(&mut markers.steady_state, "Final level");
    });
}
