//! The Nyquist tab: L(jω) for ω > 0 (solid, arrows of increasing ω) and its mirror for
//! ω < 0 (dashed), the −1 point and the unit circle, in a window that keeps −1 readable or
//! the whole curve; beside it the criterion's verdict (N, P, Z = N + P) and the closed
//! loop's count from its characteristic equation, which must agree (both are shown as
//! computed if they ever do not).

use eframe::egui::{self, RichText, Ui};
use egui_plot::{
    Arrows, Legend, Line, LineStyle, MarkerShape, Plot, PlotBounds, PlotPoints, Points,
};

use degrau_lti::control::StabilityError;
use degrau_words::{Lang, Localize};

use super::commands::Command;
use super::derived::LoopData;
use super::nyquist_window::{pieces, whole, window};
use super::session::{Saved, Session};
use crate::look::Look;
use crate::words::frequency::{self as words, Frequency as T};

/// The arrows of increasing ω drawn on the ω > 0 branch.
const ARROWS: usize = 6;

pub fn show(
    ui: &mut Ui,
    _session: &Session,
    data: &LoopData,
    kept: &Saved,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    verdict(ui, data, look);
    let mut on = kept.whole_curve;
    if ui
        .checkbox(&mut on, T::WholeCurve.get(lang))
        .on_hover_text(T::WholeCurveHelp.get(lang))
        .changed()
    {
        out.push(Command::SetWholeCurve(on));
    }
    let Ok(n) = &data.nyquist else {
        return;
    };
    let curve: Vec<[f64; 2]> = n.curve.iter().map(|p| [p.l.re, p.l.im]).collect();
    let side = ui
        .available_height()
        .min(ui.available_width())
        .max(crate::design::PLOT_MIN);
    let bounds = if kept.whole_curve {
        whole(&curve)
    } else {
        window(&curve)
    };
    let shown = crate::grid::app_axes(Plot::new("nyquist"), lang)
        .x_grid_spacer(crate::grid::one_two_five())
        .data_aspect(1.0)
        .width(ui.available_width().max(crate::design::PLOT_MIN))
        .height(side)
        .show_x(false)
        .show_y(false)
        .x_axis_label("Re L(jω)")
        .y_axis_label("Im L(jω)")
        .legend(Legend::default().background_alpha(0.75))
        .show(ui, |plot| {
            // The window is set when it changes (a new curve, the toggle), so the student
            // can zoom and pan in between.
            if fresh_window(plot.ctx(), bounds) {
                plot.set_plot_bounds(PlotBounds::from_min_max(bounds.0, bounds.1));
            }
            let b = plot.plot_bounds();
            draw(plot, &curve, (b.min(), b.max()), look);
        });
    crate::look::name_canvas(&shown.response, T::NyquistPlot.get(lang));
}

/// Whether the default window differs from the one set last (kept in egui's memory: a view
/// matter, not the session's).
fn fresh_window(ctx: &egui::Context, bounds: ([f64; 2], [f64; 2])) -> bool {
    let key = [bounds.0[0], bounds.0[1], bounds.1[0], bounds.1[1]].map(f64::to_bits);
    let id = egui::Id::unique("nyquist-window");
    ctx.data_mut(|d| {
        let old = d.get_temp::<[u64; 4]>(id);
        d.insert_temp(id, key);
        old != Some(key)
    })
}

/// The curve, its mirror, the arrows (in the `shown` window), −1 and the unit circle.
fn draw(plot: &mut egui_plot::PlotUi<'_>, curve: &[[f64; 2]], shown: Window, look: &Look) {
    let lang = look.lang;
    let circle = PlotPoints::from_parametric_callback(
        |t| (t.cos(), t.sin()),
        0.0..=std::f64::consts::TAU,
        200,
    );
    plot.line(
        Line::new(T::UnitCircle.get(lang), circle)
            .color(look.palette.grid)
            .style(LineStyle::dashed_dense()),
    );
    for piece in pieces(curve) {
        let mirror: Vec<[f64; 2]> = piece.iter().map(|p| [p[0], -p[1]]).collect();
        plot.line(
            Line::new(T::NegativeW.get(lang), mirror)
                .color(look.palette.main)
                .style(LineStyle::dashed_loose())
                .width(1.4),
        );
        plot.line(
            Line::new(words::POSITIVE_W, piece)
                .color(look.palette.main)
                .width(2.2),
        );
    }
    let (tails, tips) = arrows(curve, shown);
    if !tails.is_empty() {
        plot.arrows(
            Arrows::new(words::POSITIVE_W, tails, tips)
                .tip_length(12.0)
                .color(look.palette.main),
        );
    }
    plot.points(
        Points::new(words::MINUS_ONE, vec![[-1.0, 0.0]])
            .shape(MarkerShape::Plus)
            .radius(8.0)
            .color(look.palette.error),
    );
}

/// A window of the plot: (min, max) corners.
type Window = ([f64; 2], [f64; 2]);

/// A few short arrows along the part of the curve inside the `shown` window, pointing the way
/// ω grows, spread evenly along its length; none when that part is too short to carry them.
fn arrows(curve: &[[f64; 2]], shown: Window) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let (lo, hi) = shown;
    let inside = |p: &[f64; 2]| p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1];
    let drawn: Vec<[f64; 2]> = pieces(curve).into_iter().flatten().collect();
    // The segments with both ends in the window, and their lengths.
    let segments: Vec<(usize, f64)> = (1..drawn.len())
        .filter(|&i| inside(&drawn[i - 1]) && inside(&drawn[i]))
        .map(|i| {
            (
                i,
                (drawn[i][0] - drawn[i - 1][0]).hypot(drawn[i][1] - drawn[i - 1][1]),
            )
        })
        .collect();
    let length: f64 = segments.iter().map(|s| s.1).sum();
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if segments.len() < 2 * ARROWS || length.is_nan() || length < 0.3 * span {
        return (Vec::new(), Vec::new());
    }
    let (mut tails, mut tips) = (Vec::new(), Vec::new());
    let (mut walked, mut next) = (0.0, 1);
    for &(i, step) in &segments {
        walked += step;
        if next <= ARROWS && walked >= length * next as f64 / (ARROWS + 1) as f64 {
            if step > 0.0 {
                tails.push(drawn[i - 1]);
                tips.push(drawn[i]);
            }
            next += 1;
        }
    }
    (tails, tips)
}

/// The criterion's verdict and the direct count, beside each other.
fn verdict(ui: &mut Ui, data: &LoopData, look: &Look) {
    let lang = look.lang;
    let criterion = match &data.nyquist {
        Ok(n) => words::nyquist_verdict(
            n.encirclements,
            n.open_loop_unstable,
            n.closed_loop_unstable,
            lang,
        ),
        Err(e) => e.text(lang),
    };
    let stable = matches!(&data.nyquist, Ok(n) if n.closed_loop_unstable == 0);
    let colour = if stable {
        look.palette.main
    } else {
        look.palette.error
    };
    ui.add(egui::Label::new(RichText::new(criterion).color(colour)).wrap());
    if let Ok(n) = &data.nyquist
        && n.imaginary_poles > 0
    {
        let note = words::indented(n.imaginary_poles, lang);
        ui.add(egui::Label::new(RichText::new(note).weak()).wrap());
    }
    let direct = direct_text(&data.closed_loop, lang);
    ui.add(egui::Label::new(format!("{} {direct}", T::Direct.get(lang))).wrap());
    if let (Ok(n), Ok(z)) = (&data.nyquist, &data.closed_loop)
        && n.closed_loop_unstable != *z as i64
    {
        ui.colored_label(look.palette.warning, T::Disagree.get(lang));
    }
}

fn direct_text(count: &Result<usize, StabilityError>, lang: Lang) -> String {
    match count {
        Ok(z) => words::direct_count(*z, lang),
        Err(e) => e.text(lang),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A half circle of radius `r` round the origin, in `n` points.
    fn arc(r: f64, n: usize) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| {
                let t = std::f64::consts::PI * i as f64 / (n - 1) as f64;
                [r * t.cos(), -r * t.sin()]
            })
            .collect()
    }

    #[test]
    fn arrows_spread_along_the_length_and_skip_a_curve_too_small_to_carry_them() {
        // Points bunched at one end: the arrows still spread evenly along the length.
        let mut curve = arc(1.0, 40);
        let end = curve[39];
        curve.extend((1..200).map(|i| [end[0] + 1e-6 * i as f64, end[1]]));
        let window = ([-2.0, -1.5], [1.5, 1.5]);
        let (tails, tips) = arrows(&curve, window);
        assert_eq!(tails.len(), ARROWS);
        for (k, tip) in tips.iter().enumerate() {
            let angle = (-tip[1]).atan2(tip[0]);
            let want = std::f64::consts::PI * (k + 1) as f64 / (ARROWS + 1) as f64;
            assert!(
                (angle - want).abs() < 0.1,
                "arrow {k} at {angle}, not {want}"
            );
        }
        // A curve of length 0.03 in a window 3 wide: no arrows.
        assert!(arrows(&arc(0.01, 100), window).0.is_empty());
        // Only the part inside the window carries them: a long branch outside adds none.
        let mut long = arc(1.0, 40);
        long.extend((1..400).map(|i| [-1.0, -1.0 - i as f64]));
        let (_, tips) = arrows(&long, window);
        assert_eq!(tips.len(), ARROWS);
        assert!(tips.iter().all(|t| t[1] >= -1.5), "{tips:?}");
    }
}
