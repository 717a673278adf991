//! Draws a part's figure (the [`figure::scene`](super::figure::scene) of exercises 2, 4 and
//! 9) above its readings: the curve, the dashed guides from the axes to each reading and
//! their labels, with the app's axes, palette and plot text size. A figure on paper: it
//! does not zoom, pan or take the page's scrolling; hovering reads the coordinates.

use eframe::egui::{self, Align2, FontId, RichText, Ui};
use egui_plot::{
    Arrows, HoverPosition, Line, LineStyle, Plot, PlotBounds, PlotPoint, Points, Text,
};

use degrau_exercise::Part;

use super::figure::{self, Label, Mark, Scene, Side};
use crate::design::step_plot::PLOT_TEXT;
use crate::look::Look;
use crate::words::exercises::Exercises as T;

/// The figure's height, its axes included (points): the plot's frame keeps the 220 points
/// every plot of the app keeps.
pub const HEIGHT: f32 = 270.0;
/// How far a label keeps from its point (points).
const PAD: f32 = 5.0;

/// Draws `part`'s figure, if it is read off one.
pub fn show(ui: &mut Ui, part: &Part, look: &Look) {
    let Some(scene) = figure::scene(part, look.lang) else {
        return;
    };
    ui.label(RichText::new(T::FigureTitle.get(look.lang)).strong());
    ui.scope(|ui| {
        let font = FontId::proportional(PLOT_TEXT);
        for style in [egui::TextStyle::Body, egui::TextStyle::Small] {
            ui.style_mut().text_styles.insert(style, font.clone());
        }
        plot(ui, &part.id, &scene, look);
    });
    ui.add_space(4.0);
}

/// The plot itself.
fn plot(ui: &mut Ui, id: &str, scene: &Scene, look: &Look) {
    let lang = look.lang;
    let (lo, hi) = scene.y_range;
    let output = scene.output;
    let hover = move |pos: &HoverPosition<'_>| {
        let at = match pos {
            HoverPosition::NearDataPoint { position, .. } => *position,
            HoverPosition::Elsewhere { position } => *position,
        };
        Some(format!(
            "t = {} s\n{output} = {}",
            lang.num(at.x, 4),
            lang.num(at.y, 4)
        ))
    };
    let response = crate::grid::app_axes(Plot::new(("exercise figure", id)), lang)
        .x_grid_spacer(crate::grid::one_two_five())
        .x_axis_label(figure::T_AXIS)
        .y_axis_label(scene.y_axis.clone())
        .width(ui.available_width())
        .height(HEIGHT)
        .allow_zoom(false)
        .allow_drag(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .default_x_bounds(0.0, scene.t_end)
        .default_y_bounds(lo, hi)
        .label_formatter(hover)
        .show(ui, |plot| {
            plot.set_plot_bounds(PlotBounds::from_min_max([0.0, lo], [scene.t_end, hi]));
            let palette = &look.palette;
            plot.line(
                Line::new(output, scene.curve.clone())
                    .color(palette.main)
                    .width(2.2)
                    .allow_band(false),
            );
            for mark in &scene.marks {
                draw_mark(plot, mark, scene, look);
            }
        });
    crate::look::name_canvas(&response.response, T::FigureName.get(lang));
}

/// A dashed guide from `from` to `to` in the markers' colour.
fn guide(
    plot: &mut egui_plot::PlotUi<'_>,
    name: String,
    from: [f64; 2],
    to: [f64; 2],
    look: &Look,
) {
    plot.line(
        Line::new(name, vec![from, to])
            .color(look.palette.marker)
            .width(1.4)
            .style(LineStyle::dashed_loose())
            .allow_band(false),
    );
}

fn draw_mark(plot: &mut egui_plot::PlotUi<'_>, mark: &Mark, scene: &Scene, look: &Look) {
    let color = look.palette.marker;
    let label = mark.label();
    let name = label.text.clone();
    match *mark {
        Mark::Instant { t, y, .. } => {
            guide(
                plot,
                format!("{name} |"),
                [t, scene.y_range.0],
                [t, y],
                look,
            );
            plot.points(
                Points::new(format!("{name} •"), vec![[t, y]])
                    .color(color)
                    .radius(4.0)
                    .filled(true),
            );
        }
        Mark::Value { t, y, .. } => {
            guide(plot, format!("{name} —"), [0.0, y], [t, y], look);
        }
        Mark::Level { y, .. } => {
            guide(plot, format!("{name} —"), [0.0, y], [scene.t_end, y], look);
        }
        Mark::Gap { t, from, to, .. } => {
            plot.arrows(
                Arrows::new(
                    format!("{name} ↕"),
                    vec![[t, from], [t, to]],
                    vec![[t, to], [t, from]],
                )
                .color(color)
                .tip_length(6.0),
            );
        }
    }
    write(plot, label, look);
}

/// A label beside its point, a few points away on its side.
fn write(plot: &mut egui_plot::PlotUi<'_>, label: &Label, look: &Look) {
    let (anchor, dx, dy) = match label.side {
        Side::AboveRight => (Align2::LEFT_BOTTOM, PAD, -PAD),
        Side::BelowRight => (Align2::LEFT_TOP, PAD, PAD),
        Side::AboveLeft => (Align2::RIGHT_BOTTOM, -PAD, -PAD),
    };
    let point = PlotPoint::new(label.at[0], label.at[1]);
    let screen = plot.screen_from_plot(point) + egui::vec2(dx, dy);
    let at = plot.plot_from_screen(screen);
    let at = if at.x.is_finite() && at.y.is_finite() {
        at
    } else {
        point
    };
    plot.text(
        Text::new(label.text.clone(), at, label.text.clone())
            .anchor(anchor)
            .color(look.palette.marker),
    );
}
