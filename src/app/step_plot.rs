//! The live step-response plot: the exact curve, a faint ghost of the previous response, an
//! optional second system to compare, and the markers a student reads (10 %/90 % crossings
//! and the rise span, peak with overshoot, the settling band and time, steady state,
//! undershoot). Every marker can be switched off; its value shows on hover and its
//! definition is one hover away on the toggle.

use eframe::egui::{self, Color32, Ui};
use egui_plot::{
    HLine, HoverPosition, Legend, Line, LineStyle, MarkerShape, Plot, PlotPoint, Points, Span,
    Text, VLine,
};
use serde::{Deserialize, Serialize};

use crate::app::analysis::Analysis;
use crate::lti::StepInfoOptions;
use crate::lti::number::format_number;
use crate::lti::number::sig;

/// Which markers are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Markers {
    pub rise: bool,
    pub peak: bool,
    pub settling: bool,
    pub steady_state: bool,
    pub undershoot: bool,
    pub ghost: bool,
}

impl Default for Markers {
    fn default() -> Self {
        Self {
            rise: true,
            peak: true,
            settling: true,
            steady_state: true,
            undershoot: true,
            ghost: true,
        }
    }
}

/// The definitions shown on hover, with the current thresholds.
pub fn definitions(options: &StepInfoOptions) -> [(&'static str, String); 5] {
    let (lo, hi) = options.rise_limits;
    let band = options.settling_threshold;
    [
        (
            "Rise",
            format!(
                "Rise time: from the first time y reaches {} % of the way from its initial to its final \
                 value to the first time it reaches {} %.",
                pct(lo),
                pct(hi)
            ),
        ),
        (
            "Peak",
            "Peak: the largest |y − y_init| and when it happens. Overshoot: how far the peak goes beyond \
             the final value, in % of the change |y_final − y_init|. A response that never passes its \
             final value has no peak time: it approaches its peak as t tends to ∞."
                .to_string(),
        ),
        (
            "Settling",
            format!(
                "Settling time: the first time after which |y − y_final| stays within {} % of \
                 |y_final − y_init| for ever (the shaded band), counted from the step.",
                pct(band)
            ),
        ),
        ("Steady state", "Steady state: the final value y_final = A·G(0), when the response settles.".to_string()),
        (
            "Undershoot",
            "Undershoot: how far y first moves the wrong way (opposite to its final change), in % of \
             |y_final − y_init|: the mark of a right-half-plane zero."
                .to_string(),
        ),
    ]
}

fn pct(f: f64) -> String {
    format_number(100.0 * f)
}

/// The toggles and thresholds above the plot.
pub fn controls(ui: &mut Ui, markers: &mut Markers, options: &mut StepInfoOptions) {
    let defs = definitions(options);
    ui.horizontal_wrapped(|ui| {
        ui.label("Markers:");
        let toggles: [(&mut bool, &str); 5] = [
            (&mut markers.rise, defs[0].0),
            (&mut markers.peak, defs[1].0),
            (&mut markers.settling, defs[2].0),
            (&mut markers.steady_state, defs[3].0),
            (&mut markers.undershoot, defs[4].0),
        ];
        for ((flag, name), (_, definition)) in toggles.into_iter().zip(defs.iter()) {
            ui.checkbox(flag, name).on_hover_text(definition);
        }
        ui.checkbox(&mut markers.ghost, "Previous")
            .on_hover_text("Show the response before the last edit as a faint ghost.");
        ui.separator();
        egui::ComboBox::from_id_salt("settling band")
            .selected_text(format!("Band ±{} %", pct(options.settling_threshold)))
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut options.settling_threshold, 0.02, "Band ±2 %");
                ui.selectable_value(&mut options.settling_threshold, 0.05, "Band ±5 %");
            })
            .response
            .on_hover_text("Settling band, as a fraction of the change |y_final − y_init|.");
        egui::ComboBox::from_id_salt("rise limits")
            .selected_text(format!(
                "Rise {}–{} %",
                pct(options.rise_limits.0),
                pct(options.rise_limits.1)
            ))
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut options.rise_limits, (0.1, 0.9), "Rise 10–90 %");
                ui.selectable_value(&mut options.rise_limits, (0.05, 0.95), "Rise 5–95 %");
            })
            .response
            .on_hover_text("Rise-time limits, as fractions of the way from y_init to y_final.");
    });
}

/// Colours of the plot.
fn colors(ui: &Ui) -> (Color32, Color32, Color32, Color32) {
    let dark = ui.visuals().dark_mode;
    let main = if dark {
        Color32::from_rgb(120, 190, 255)
    } else {
        Color32::from_rgb(20, 90, 200)
    };
    let compare = if dark {
        Color32::from_rgb(255, 170, 90)
    } else {
        Color32::from_rgb(210, 100, 0)
    };
    let marker = if dark {
        Color32::from_rgb(240, 200, 80)
    } else {
        Color32::from_rgb(170, 110, 0)
    };
    let ghost = ui.visuals().weak_text_color().gamma_multiply(0.6);
    (main, compare, marker, ghost)
}

/// Draws the plot.
pub fn show(
    ui: &mut Ui,
    analysis: &Analysis,
    compare: Option<(&str, &Analysis)>,
    ghost: Option<&[[f64; 2]]>,
    markers: &Markers,
) {
    let (main, compare_color, marker, ghost_color) = colors(ui);
    let unit_hover = |pos: &HoverPosition<'_>| match pos {
        HoverPosition::NearDataPoint {
            plot_name,
            position,
            ..
        } if !plot_name.is_empty() => Some(format!(
            "{plot_name}\nt = {} s\ny = {}",
            format_number(position.x),
            format_number(position.y)
        )),
        HoverPosition::NearDataPoint { position, .. } | HoverPosition::Elsewhere { position } => {
            Some(format!(
                "t = {} s\ny = {}",
                format_number(position.x),
                format_number(position.y)
            ))
        }
    };
    Plot::new("step response")
        .legend(
            Legend::default()
                .position(egui_plot::Corner::RightBottom)
                .background_alpha(0.75)
                .text_style(egui::TextStyle::Small),
        )
        .x_axis_label("t (s)")
        .y_axis_label("y(t)")
        .y_grid_spacer(super::grid::one_two_five())
        .y_axis_formatter(super::grid::tick_label)
        .label_formatter(unit_hover)
        .include_y(0.0)
        .include_x(0.0)
        .show(ui, |plot| {
            if markers.ghost
                && let Some(g) = ghost
            {
                plot.line(
                    Line::new("previous", g.to_vec())
                        .color(ghost_color)
                        .width(1.5),
                );
            }
            if let Some((name, b)) = compare {
                plot.line(
                    Line::new(format!("B: {name}"), b.curve.clone())
                        .color(compare_color)
                        .width(1.8),
                );
            }
            plot.line(
                Line::new("y(t)", analysis.curve.clone())
                    .color(main)
                    .width(2.2),
            );
            draw_markers(plot, analysis, markers, marker);
        });
}

fn draw_markers(
    plot: &mut egui_plot::PlotUi<'_>,
    analysis: &Analysis,
    markers: &Markers,
    color: Color32,
) {
    let (Some(info), Some(response)) = (&analysis.info, &analysis.response) else {
        return;
    };
    if info.steady_state.is_none() {
        let y_end = analysis.curve.last().map_or(0.0, |p| p[1]);
        plot.text(
            Text::new(
                "does not settle",
                PlotPoint::new(0.5 * analysis.horizon, 0.5 * y_end),
                response.behaviour().describe(),
            )
            .color(Color32::from_rgb(220, 60, 40)),
        );
        if let (Some(peak), Some(tp)) = (info.peak, info.peak_time) {
            let y = response.value(tp);
            plot.points(point(&format!("peak {}", sig(peak, 4)), tp, y, color));
        }
        return;
    }
    let value_at = |t: f64| response.value(t);
    draw_step_markers(
        plot,
        info,
        &analysis.options,
        &value_at,
        0.0,
        markers,
        color,
    );
}

/// The markers of any step response: `value_at(t)` evaluates the curve, `shift` is added
/// to the metric times (the step instant of a measured test).
pub fn draw_step_markers(
    plot: &mut egui_plot::PlotUi<'_>,
    info: &crate::lti::StepInfo,
    options: &StepInfoOptions,
    value_at: &dyn Fn(f64) -> f64,
    shift: f64,
    markers: &Markers,
    color: Color32,
) {
    let Some(y_final) = info.steady_state else {
        return;
    };
    let shifted = |t: Option<f64>| t.map(|t| t + shift);
    let delta = y_final - info.initial_value;
    let at = |fraction: f64| info.initial_value + fraction * delta;
    if markers.steady_state {
        plot.hline(
            HLine::new(format!("steady state {}", sig(y_final, 4)), y_final)
                .color(color)
                .style(LineStyle::dashed_loose()),
        );
    }
    if markers.settling {
        let band = options.settling_threshold * delta.abs();
        let name = format!("±{} % band", pct(options.settling_threshold));
        for y in [y_final - band, y_final + band] {
            plot.hline(
                HLine::new(name.clone(), y)
                    .color(color.gamma_multiply(0.6))
                    .style(LineStyle::dotted_dense()),
            );
        }
        if let Some(ts) = shifted(info.settling_time) {
            let name = format!("settling time {} s", sig(ts, 4));
            plot.vline(
                VLine::new(name.clone(), ts)
                    .color(color)
                    .style(LineStyle::dashed_dense()),
            );
            plot.points(point(&name, ts, value_at(ts), color));
        }
    }
    if markers.rise
        && let (Some(a), Some(b), Some(tr)) = (
            shifted(info.rise_start),
            shifted(info.rise_end),
            info.rise_time,
        )
    {
        let (lo, hi) = options.rise_limits;
        plot.span(
            Span::new(format!("rise time {} s", sig(tr, 4)), a..=b)
                .fill(color.gamma_multiply(0.12)),
        );
        plot.points(point(&format!("{} % crossing", pct(lo)), a, at(lo), color));
        plot.points(point(&format!("{} % crossing", pct(hi)), b, at(hi), color));
    }
    if markers.peak
        && let (Some(tp), Some(os)) = (shifted(info.peak_time), info.overshoot)
    {
        let y = value_at(tp);
        let name = format!("peak, overshoot {} %", sig(os, 4));
        plot.points(
            point(&name, tp, y, color)
                .shape(MarkerShape::Diamond)
                .radius(6.0),
        );
        plot.text(
            Text::new(name, PlotPoint::new(tp, y), format!("  {} %", sig(os, 4)))
                .anchor(egui::Align2::LEFT_BOTTOM)
                .color(color),
        );
    }
    if markers.undershoot
        && let (Some(tu), Some(us)) = (shifted(info.undershoot_time), info.undershoot)
    {
        let y = value_at(tu);
        plot.points(
            point(&format!("undershoot {} %", sig(us, 4)), tu, y, color).shape(MarkerShape::Down),
        );
    }
}

fn point<'a>(name: &str, t: f64, y: f64, color: Color32) -> Points<'a> {
    Points::new(name.to_string(), vec![[t, y]])
        .color(color)
        .radius(4.5)
        .filled(true)
}
