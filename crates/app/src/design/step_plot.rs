//! The live step-response plot: the exact curve, a faint ghost of the previous response, an
//! optional second system to compare, and the markers a student reads (10 %/90 % crossings
//! and the rise span, peak with overshoot, the settling band and time, steady state,
//! undershoot). Every marker can be switched off; its value shows on hover and its
//! definition is one hover away on the toggle.
//!
//! The y range comes from the current curves only (the ghost never sets it), and hovering
//! reads the curve's exact value at the cursor's t, or a marker's own value near a marker.
//! The view reads the session and returns commands; it changes nothing itself.

use eframe::egui::{self, Color32, FontId, Ui};
use egui_plot::{
    HLine, HoverPosition, Legend, Line, LineStyle, MarkerShape, Plot, PlotPoint, Points, Text,
    VLine,
};

use crate::look::Look;
use crate::words::design::Design as P;
use degrau_lti::words::feedback::Loop;
use degrau_lti::words::step::Metric;
use degrau_lti::{StepInfoOptions, StepResponse};
use degrau_words::Lang;

use super::analysis::Analysis;
use super::commands::{Command, Markers};
use super::session::{Saved, Session};

/// Size of the plot's tick labels, legend and hover text (points, before the presentation
/// size): larger than egui_plot's default so a projector shows them.
pub const PLOT_TEXT: f32 = 14.0;

/// The legend name of the system's curve (notation, the same in every language).
pub const CURVE_NAME: &str = "y(t)";

/// A percentage of a fraction, as the thresholds are written.
fn pct(f: f64, lang: Lang) -> String {
    lang.num(100.0 * f, 6)
}

/// The toggles and thresholds above the plot; the commands they ask for.
pub fn controls(ui: &mut Ui, kept: &Saved, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let (markers, options) = (kept.markers, kept.options);
    let mut out = Vec::new();
    let bar = |ui: &mut Ui| {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        ui.label(P::MarkersLabel.get(lang));
        let mut m = markers;
        let toggles: [(&mut bool, P, Metric); 5] = [
            (&mut m.rise, P::Rise, Metric::RiseTime),
            (&mut m.peak, P::Peak, Metric::Overshoot),
            (&mut m.settling, P::Settling, Metric::SettlingTime),
            (&mut m.steady_state, P::SteadyState, Metric::SteadyState),
            (&mut m.undershoot, P::Undershoot, Metric::Undershoot),
        ];
        for (flag, name, metric) in toggles {
            ui.checkbox(flag, name.get(lang))
                .on_hover_text(metric.definition(&options, lang));
        }
        ui.checkbox(&mut m.ghost, P::Previous.get(lang))
            .on_hover_text(P::PreviousHelp.get(lang));
        if m != markers {
            out.push(Command::SetMarkers(m));
        }
        ui.separator();
        let mut o = options;
        let band = |t: f64| format!("{} ±{} %", P::Band.get(lang), pct(t, lang));
        egui::ComboBox::from_id_salt("settling band")
            .selected_text(band(o.settling_threshold))
            .show_ui(ui, |ui| {
                for t in [0.02, 0.05] {
                    ui.selectable_value(&mut o.settling_threshold, t, band(t));
                }
            })
            .response
            .on_hover_text(P::BandHelp.get(lang));
        let rise = |(a, b): (f64, f64)| {
            format!("{} {}–{} %", P::Rise.get(lang), pct(a, lang), pct(b, lang))
        };
        egui::ComboBox::from_id_salt("rise limits")
            .selected_text(rise(o.rise_limits))
            .show_ui(ui, |ui| {
                for limits in [(0.1, 0.9), (0.05, 0.95)] {
                    ui.selectable_value(&mut o.rise_limits, limits, rise(limits));
                }
            })
            .response
            .on_hover_text(P::RiseHelp.get(lang));
        if o != options {
            out.push(Command::SetOptions(o));
        }
    };
    // Wrapped when the plot has height to spare; else one line scrolled sideways (wrapped
    // in a short window, it took the plot's height).
    if ui.available_height() > super::PLOT_MIN + WRAPPED_ROOM {
        ui.horizontal_wrapped(bar);
    } else {
        crate::look::one_line(ui, "step plot controls", bar);
    }
    out
}

/// Height the wrapped controls may take above the plot (its title and x axis included).
const WRAPPED_ROOM: f32 = 160.0;

/// The y range the current curves span (the step's start, 0, included), with a margin; the
/// ghost is not a current curve and never widens it.
pub fn y_range(curves: &[&[[f64; 2]]]) -> (f64, f64) {
    let (lo, hi) = curves
        .iter()
        .flat_map(|c| c.iter())
        .map(|p| p[1])
        .filter(|y| y.is_finite())
        .fold((0.0f64, 0.0f64), |(lo, hi), y| (lo.min(y), hi.max(y)));
    let span = hi - lo;
    let margin = if span > 0.0 { 0.05 * span } else { 1.0 };
    (lo - margin, hi + margin)
}

/// The t range of the current curves, from 0.
fn t_range(curves: &[&[[f64; 2]]]) -> f64 {
    curves
        .iter()
        .filter_map(|c| c.last())
        .map(|p| p[0])
        .filter(|t| t.is_finite() && *t > 0.0)
        .fold(0.0, f64::max)
        .max(1e-9)
}

/// The hover text: near a marker its own value; anywhere else the value of each current
/// curve at the cursor's t, exact (from its [`StepResponse`]), not the cursor's y.
pub fn hover_text(
    position: &HoverPosition<'_>,
    main: Option<&StepResponse>,
    compare: Option<(&str, &StepResponse)>,
    lang: Lang,
) -> String {
    let (name, at) = match position {
        HoverPosition::NearDataPoint {
            plot_name,
            position,
            ..
        } => (*plot_name, *position),
        HoverPosition::Elsewhere { position } => ("", *position),
    };
    let is_curve = name.is_empty()
        || name == CURVE_NAME
        || name == P::Previous.get(lang)
        || name.starts_with("B:");
    let t = at.x;
    if !is_curve {
        return format!(
            "{name}\nt = {} s\ny = {}",
            lang.num(t, 5),
            lang.num(at.y, 5)
        );
    }
    let mut text = format!("t = {} s", lang.num(t, 5));
    if let Some(r) = main {
        text.push_str(&format!("\ny(t) = {}", lang.num(r.value(t.max(0.0)), 5)));
    }
    if let Some((b, r)) = compare {
        text.push_str(&format!("\nB {b}: {}", lang.num(r.value(t.max(0.0)), 5)));
    }
    text
}

/// The smallest plot (points) that shows its legend.
const LEGEND_MIN: egui::Vec2 = egui::vec2(520.0, 380.0);

/// Draws the plot; returns the rect it took (for the PNG export).
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> egui::Rect {
    let lang = look.lang;
    let palette = &look.palette;
    let analysis = &session.analysis;
    let compare = session.compare(kept);
    let compare_name = compare.map(|(n, _)| super::presets::compare_name(n, lang));
    let mut current: Vec<&[[f64; 2]]> = vec![&analysis.curve];
    if let Some((_, b)) = compare {
        current.push(&b.curve);
    }
    let closed = session
        .feedback
        .closed
        .as_ref()
        .filter(|_| kept.feedback.closed);
    if let Some(c) = closed {
        current.push(&c.curve);
    }
    let input = session.feedback.input_curve.as_ref();
    if let Some((curve, reference)) = input {
        current.push(curve);
        current.push(reference);
    }
    let (y_lo, y_hi) = y_range(&current);
    let t_hi = t_range(&current);
    let main_response = analysis.response.as_ref();
    let compare_response = compare
        .zip(compare_name.as_deref())
        .and_then(|((_, b), name)| b.response.as_ref().map(|r| (name, r)));
    let hover =
        move |pos: &HoverPosition<'_>| Some(hover_text(pos, main_response, compare_response, lang));
    // Until the student zooms or pans the plot (a double-click returns), its range is the
    // current curves' own, frame after frame; kept with the plot as egui_plot keeps its own.
    let navigated_id = ui.scope_id().with("step plot navigated");
    let navigated: bool = ui.data(|d| d.get_temp(navigated_id)).unwrap_or(false);
    // The plot's scope holds its title, its axes and ticks: what "Save step plot as PNG"
    // crops to (the plot frame alone had no axes, ticks or title).
    let scoped = ui.scope(|ui| {
        ui.label(egui::RichText::new(plot_title(analysis, lang)).strong());
        let font = FontId::proportional(PLOT_TEXT);
        ui.style_mut()
            .text_styles
            .insert(egui::TextStyle::Body, font.clone());
        ui.style_mut()
            .text_styles
            .insert(egui::TextStyle::Small, font.clone());
        // A legend on a small plot would hide the curve: the markers' values are in the
        // metrics table and on hover, so a small plot goes without it.
        let room = ui.available_size();
        let legend = (room.x >= LEGEND_MIN.x && room.y >= LEGEND_MIN.y).then(|| {
            Legend::default()
                .position(egui_plot::Corner::RightBottom)
                .background_alpha(0.75)
                .text_style(egui::TextStyle::Body)
        });
        let mut plot = crate::grid::app_axes(Plot::new("step response"), lang)
            .x_grid_spacer(crate::grid::one_two_five());
        if let Some(legend) = legend {
            plot = plot.legend(legend);
        }
        let response = plot
            .x_axis_label("t (s)")
            .y_axis_label("y(t)")
            .label_formatter(hover)
            .default_x_bounds(0.0, t_hi)
            .default_y_bounds(y_lo, y_hi)
            .min_size(egui::vec2(200.0, 200.0))
            .show(ui, |plot| {
                if !navigated {
                    plot.set_auto_bounds(true);
                }
                if kept.markers.ghost
                    && let Some(g) = &session.ghost
                {
                    plot.line(
                        Line::new(P::Previous.get(lang), g.clone())
                            .color(palette.ghost)
                            .width(1.5),
                    );
                }
                if let (Some((_, b)), Some(name)) = (compare, &compare_name) {
                    plot.line(
                        Line::new(format!("B: {name}"), b.curve.clone())
                            .color(palette.compare)
                            .width(1.8),
                    );
                }
                plot.line(
                    Line::new(CURVE_NAME, analysis.curve.clone())
                        .color(palette.main)
                        .width(2.2),
                );
                // With the loop closed, only the closed loop's markers carry text: the open
                // loop's labels printed over the closed loop's.
                draw_markers(plot, analysis, &kept.markers, look, closed.is_none());
                if let Some(c) = closed {
                    plot.line(
                        Line::new(
                            Loop::closed_loop_curve(session.feedback.approximant.is_some())
                                .get(lang),
                            c.curve.clone(),
                        )
                        .color(palette.model)
                        .width(2.2),
                    );
                    draw_markers(plot, c, &kept.markers, look, true);
                }
                if let Some((curve, reference)) = input {
                    let which = Loop::input_name(kept.feedback.input).get(lang);
                    plot.line(
                        Line::new(
                            format!("{} {which}", Loop::InputCurve.get(lang)),
                            curve.clone(),
                        )
                        .color(palette.path)
                        .width(2.0),
                    );
                    plot.line(
                        Line::new(
                            format!("{} {which}", Loop::InputItself.get(lang)),
                            reference.clone(),
                        )
                        .color(palette.path.gamma_multiply(0.5))
                        .style(LineStyle::dashed_dense())
                        .width(1.2),
                    );
                }
            });
        let r = &response.response;
        let moved = r.dragged()
            || (r.hovered()
                && ui
                    .input(|i| i.smooth_scroll_delta != egui::Vec2::ZERO || i.zoom_delta() != 1.0));
        let now = if r.double_clicked() {
            false
        } else {
            navigated || moved
        };
        if now != navigated {
            ui.data_mut(|d| d.insert_temp(navigated_id, now));
        }
        let name = P::PlotName.get(lang);
        crate::look::name_canvas(&response.response, name);
    });
    scoped.response.rect
}

/// "Step response y(t), A = 2": what the plot shows, above it.
fn plot_title(analysis: &Analysis, lang: degrau_words::Lang) -> String {
    let name = P::PlotName.get(lang);
    let mut chars = name.chars();
    let name: String = chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default();
    format!(
        "{name} y(t), A = {}",
        lang.num(analysis.system.amplitude, 6)
    )
}

/// `text` laid out in lines no wider than most of the plot (one line ran out of both
/// sides of a small plot).
fn wrapped(plot: &egui_plot::PlotUi<'_>, text: String, color: egui::Color32) -> egui::WidgetText {
    let width = 0.9 * plot.transform().frame().width();
    let job = egui::text::LayoutJob::simple(text, FontId::proportional(PLOT_TEXT), color, width);
    let galley = plot.ctx().fonts_mut(|f| f.layout_job(job));
    egui::WidgetText::Galley(galley)
}

fn draw_markers(
    plot: &mut egui_plot::PlotUi<'_>,
    analysis: &Analysis,
    markers: &Markers,
    look: &Look,
    labelled: bool,
) {
    let (Some(info), Some(response)) = (&analysis.info, &analysis.response) else {
        return;
    };
    let (lang, color) = (look.lang, look.palette.marker);
    if info.steady_state.is_none() {
        let y_end = analysis.curve.last().map_or(0.0, |p| p[1]);
        let status = degrau_words::Localize::text(&response.behaviour(), lang);
        let status = wrapped(plot, status, look.palette.error);
        plot.text(
            Text::new(
                P::DoesNotSettle.get(lang),
                PlotPoint::new(0.5 * analysis.horizon, 0.5 * y_end),
                status,
            )
            .color(look.palette.error),
        );
        if let (Some(peak), Some(tp)) = (info.peak, info.peak_time) {
            let y = response.value(tp);
            let name = format!("{} {}", P::PeakName.get(lang), lang.num(peak, 4));
            plot.points(point(&name, tp, y, color));
        }
        return;
    }
    let value_at = |t: f64| response.value(t);
    draw_step_markers_in(
        plot,
        info,
        &analysis.options,
        &value_at,
        (0.0, labelled),
        markers,
        color,
        lang,
    );
}

/// The markers of any step response: `value_at(t)` evaluates the curve, `shift` is added
/// to the metric times (the step instant of a measured test), `labelled` says whether the
/// rise and the peak carry text on the plot; names in `lang`.
#[allow(clippy::too_many_arguments)]
pub fn draw_step_markers_in(
    plot: &mut egui_plot::PlotUi<'_>,
    info: &degrau_lti::StepInfo,
    options: &StepInfoOptions,
    value_at: &dyn Fn(f64) -> f64,
    (shift, labelled): (f64, bool),
    markers: &Markers,
    color: Color32,
    lang: Lang,
) {
    let Some(y_final) = info.steady_state else {
        return;
    };
    let shifted = |t: Option<f64>| t.map(|t| t + shift);
    let delta = y_final - info.initial_value;
    let at = |fraction: f64| info.initial_value + fraction * delta;
    let num = |x: f64| lang.num(x, 4);
    if markers.steady_state {
        plot.hline(
            HLine::new(
                format!("{} {}", P::SteadyStateName.get(lang), num(y_final)),
                y_final,
            )
            .color(color)
            .style(LineStyle::dashed_loose()),
        );
    }
    if markers.settling {
        let band = options.settling_threshold * delta.abs();
        // Word order is the language's ("faixa de ±2 %", not a calque "±2 % faixa").
        let name = crate::words::identify::fill(
            P::BandName.get(lang),
            &[pct(options.settling_threshold, lang)],
        );
        for y in [y_final - band, y_final + band] {
            plot.hline(
                HLine::new(name.clone(), y)
                    .color(color.gamma_multiply(0.6))
                    .style(LineStyle::dotted_dense()),
            );
        }
        if let Some(ts) = shifted(info.settling_time) {
            let name = format!("{} {} s", P::SettlingTimeName.get(lang), num(ts));
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
        // The label starts at the end of the rise, beside the upper crossing.
        if labelled {
            crate::plot_span::labelled_span(
                plot,
                format!("  {} {} s", P::RiseTimeName.get(lang), num(tr)),
                a..=b,
                color.gamma_multiply(0.12),
                [b, at(hi)],
                egui::Align2::LEFT_TOP,
                color,
            );
        } else {
            plot.span(egui_plot::Span::new("", a..=b).fill(color.gamma_multiply(0.12)));
        }
        let crossing =
            |f: f64| crate::words::identify::fill(P::CrossingName.get(lang), &[pct(f, lang)]);
        plot.points(point(&crossing(lo), a, at(lo), color));
        plot.points(point(&crossing(hi), b, at(hi), color));
    }
    if markers.peak
        && let (Some(tp), Some(os)) = (shifted(info.peak_time), info.overshoot)
    {
        let y = value_at(tp);
        let name = format!("{} {} %", P::PeakOvershootName.get(lang), num(os));
        plot.points(
            point(&name, tp, y, color)
                .shape(MarkerShape::Diamond)
                .radius(6.0),
        );
        if labelled {
            plot.text(
                // Beside the peak, not above it: above, the plot's top edge cut it.
                Text::new(name, PlotPoint::new(tp, y), format!("   {} %", num(os)))
                    .anchor(egui::Align2::LEFT_CENTER)
                    .color(color),
            );
        }
    }
    if markers.undershoot
        && let (Some(tu), Some(us)) = (shifted(info.undershoot_time), info.undershoot)
    {
        let y = value_at(tu);
        let name = format!("{} {} %", P::UndershootName.get(lang), num(us));
        plot.points(point(&name, tu, y, color).shape(MarkerShape::Down));
    }
}

fn point<'a>(name: &str, t: f64, y: f64, color: Color32) -> Points<'a> {
    Points::new(name.to_string(), vec![[t, y]])
        .color(color)
        .radius(4.5)
        .filled(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_y_range_comes_from_the_current_curves() {
        let a = [[0.0, 0.0], [1.0, 0.002]];
        let (lo, hi) = y_range(&[&a]);
        assert!(lo < 0.0 && hi > 0.002 && hi < 0.0022, "{lo} {hi}");
    }

    #[test]
    fn hover_reads_the_curve_not_the_cursor() {
        let tf = degrau_lti::TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0]).unwrap();
        let r = StepResponse::new(&tf, 1.0).unwrap();
        let pos = HoverPosition::Elsewhere {
            position: PlotPoint::new(1.0, 0.9),
        };
        let text = hover_text(&pos, Some(&r), None, Lang::En);
        assert_eq!(
            text,
            format!("t = 1 s\ny(t) = {}", Lang::En.num(1.0 - (-1f64).exp(), 5))
        );
    }
}
