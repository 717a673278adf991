//! The Bode tab: |L(jω)| in dB over ∠L(jω) in degrees, one log-ω axis (the plots' x is
//! log10 ω, its ticks written as ω), the notes' asymptotes dashed with their corners, the
//! crossovers marked on the 0 dB and −180° lines, and a readout of the exact values at the
//! hovered ω (from [`degrau_lti::bode::bode`] there, not read off the samples).

use eframe::egui::{self, Id, RichText, Ui};
use egui_plot::{GridInput, GridMark, HLine, Legend, Line, LineStyle, MarkerShape, Plot, Points};

use degrau_lti::bode::bode;
use degrau_words::Lang;

use super::derived::LoopData;
use super::session::Session;
use crate::look::Look;
use crate::words::frequency::Frequency as T;

/// The most decades the axis labels one by one.
const DECADES_LABELLED: f64 = 12.0;

/// Draws the two plots and the readout under them.
pub fn show(ui: &mut Ui, session: &Session, data: &LoopData, look: &Look) {
    let lang = look.lang;
    let name = symbol(session);
    let row = ui.text_style_height(&egui::TextStyle::Body) + 2.0 * ui.spacing().item_spacing.y;
    let each = ((ui.available_height() - 2.0 * row) / 2.0).max(crate::design::PLOT_MIN);
    let width = ui.available_width().max(crate::design::PLOT_MIN);
    let x: Vec<f64> = data.bode.w.iter().map(|w| w.log10()).collect();
    let at = |w: f64| {
        let b = bode(&data.l, &[w]);
        (b.mag_db[0], b.phase_deg[0])
    };
    let mag = base("bode magnitude", lang, each, width)
        .y_axis_label(format!("|{name}| (dB)"))
        .show(ui, |plot| {
            plot.hline(HLine::new("0 dB", 0.0).color(look.palette.axis).width(1.0));
            let pts = zip(&x, &data.asymptote_db);
            plot.line(
                Line::new(T::Asymptotes.get(lang), pts)
                    .color(look.palette.marker)
                    .style(LineStyle::dashed_loose())
                    .width(1.4),
            );
            let corners: Vec<[f64; 2]> = data
                .asymptotes
                .corners
                .iter()
                .filter(|c| c.slope_change_db_per_decade != 0.0)
                .map(|c| [c.w.log10(), data.asymptotes.value_db(c.w)])
                .collect();
            plot.points(
                Points::new(T::Corners.get(lang), corners)
                    .shape(MarkerShape::Diamond)
                    .radius(5.0)
                    .color(look.palette.marker),
            );
            plot.line(
                Line::new(T::Curve.get(lang), zip(&x, &data.bode.mag_db))
                    .color(look.palette.main)
                    .width(2.2),
            );
            crossovers(plot, data, look, |w| at(w).0);
        });
    crate::look::name_canvas(&mag.response, T::Magnitude.get(lang));
    // The phase falls to the right: its legend goes where it starts, bottom left.
    let phase = base("bode phase", lang, each, width)
        .legend(
            Legend::default()
                .background_alpha(0.75)
                .position(egui_plot::Corner::LeftBottom),
        )
        .y_axis_label(format!("∠{name} (°)"))
        .x_axis_label("ω (rad/s)")
        .show(ui, |plot| {
            plot.hline(
                HLine::new("−180°", -180.0)
                    .color(look.palette.axis)
                    .width(1.0),
            );
            plot.line(
                Line::new(T::Curve.get(lang), zip(&x, &data.bode.phase_deg))
                    .color(look.palette.main)
                    .width(2.2),
            );
            crossovers(plot, data, look, |w| at(w).1);
        });
    crate::look::name_canvas(&phase.response, T::Phase.get(lang));
    let hovered = [&mag, &phase].into_iter().find_map(|p| {
        let pos = p.response.hover_pos()?;
        Some(10f64.powf(p.transform.value_from_position(pos).x))
    });
    let text = match hovered.filter(|w| w.is_finite() && *w > 0.0) {
        Some(w) => {
            let (db, deg) = at(w);
            readout(w, db, deg, name, lang)
        }
        None => T::HoverHint.get(lang).to_string(),
    };
    ui.label(RichText::new(text).monospace());
}

/// G for a system alone, L for a loop.
fn symbol(session: &Session) -> &'static str {
    match session.source.as_ref().and_then(|s| s.controller.as_ref()) {
        Some(_) => "L",
        None => "G",
    }
}

/// The readout line: ω, the magnitude in dB and as a ratio, the phase.
pub fn readout(w: f64, db: f64, deg: f64, name: &str, lang: Lang) -> String {
    let n = |x: f64| lang.num(x, 4);
    format!(
        "ω = {} rad/s   |{name}| = {} dB ({})   ∠{name} = {}°",
        n(w),
        n(db),
        n(10f64.powf(db / 20.0)),
        n(deg)
    )
}

/// The markers of the crossovers on one plot, on its curve (a phase crossover may be at
/// −540° as well as −180°).
fn crossovers(
    plot: &mut egui_plot::PlotUi<'_>,
    data: &LoopData,
    look: &Look,
    curve: impl Fn(f64) -> f64,
) {
    let lang = look.lang;
    let m = &data.margins;
    if let Some(w) = m.w_gc {
        let y = curve(w);
        plot.points(
            Points::new(T::GainCrossover.get(lang), vec![[w.log10(), y]])
                .shape(MarkerShape::Circle)
                .radius(6.0)
                .filled(false)
                .color(look.palette.selected),
        );
    }
    if let Some(w) = m.w_pc {
        let y = curve(w);
        plot.points(
            Points::new(T::PhaseCrossover.get(lang), vec![[w.log10(), y]])
                .shape(MarkerShape::Square)
                .radius(6.0)
                .filled(false)
                .color(look.palette.error),
        );
    }
}

/// (x, y) pairs of the finite points.
fn zip(x: &[f64], y: &[f64]) -> Vec<[f64; 2]> {
    x.iter()
        .zip(y)
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .map(|(&x, &y)| [x, y])
        .collect()
}

/// The y axes' width (points): room for "−1000" and the axis label.
const Y_AXIS_WIDTH: f32 = 64.0;

/// A plot of the Bode tab: log-ω ticks, the app's y axis, x linked with the other plot.
fn base(id: &'static str, lang: Lang, height: f32, width: f32) -> Plot<'static> {
    let group = Id::unique("bode axes");
    crate::grid::app_axes(Plot::new(id), lang)
        .x_grid_spacer(decades)
        .x_axis_formatter(move |m, _| decade_label(m, lang))
        .link_axis(group, [true, false])
        .link_cursor(group, [true, false])
        // One y-axis width for both, so their ω axes line up (−1200° is wider than 50 dB).
        .y_axis_min_width(Y_AXIS_WIDTH)
        .show_x(false)
        .show_y(false)
        .height(height)
        .width(width)
        .min_size(egui::vec2(crate::design::PLOT_MIN, crate::design::PLOT_MIN))
        .legend(Legend::default().background_alpha(0.75))
}

/// Grid marks on log10 ω: every decade, and 2…9 within each when few decades are shown.
fn decades(input: GridInput) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo {
        return Vec::new();
    }
    let span = hi - lo;
    let every = (span / DECADES_LABELLED).ceil().max(1.0);
    let first = (lo / every).floor() as i64;
    let last = (hi / every).ceil() as i64;
    let mut out = Vec::new();
    for k in first..=last {
        let d = k as f64 * every;
        out.push(GridMark {
            value: d,
            step_size: every,
        });
        if every == 1.0 && span <= 6.0 {
            out.extend((2..10).map(|m| GridMark {
                value: d + (m as f64).log10(),
                step_size: 0.1,
            }));
        }
    }
    out.retain(|m| m.value >= lo && m.value <= hi);
    out
}

/// A decade's tick written as ω (0.1, 1, 10); the marks within a decade are unlabelled.
fn decade_label(mark: GridMark, lang: Lang) -> String {
    if mark.step_size < 1.0 || (mark.value - mark.value.round()).abs() > 1e-9 {
        return String::new();
    }
    lang.num(10f64.powf(mark.value.round()), 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decades_are_written_as_omega() {
        let mark = |value: f64, step_size: f64| GridMark { value, step_size };
        assert_eq!(decade_label(mark(-1.0, 1.0), Lang::En), "0.1");
        assert_eq!(decade_label(mark(-1.0, 1.0), Lang::Pt), "0,1");
        assert_eq!(decade_label(mark(2.0, 1.0), Lang::En), "100");
        assert_eq!(decade_label(mark(0.3, 0.1), Lang::En), "");
        let marks = decades(GridInput {
            bounds: (-1.5, 1.5),
            base_step_size: 0.01,
        });
        assert!(marks.iter().any(|m| m.value == 0.0 && m.step_size == 1.0));
        assert_eq!(marks.iter().filter(|m| m.step_size == 1.0).count(), 3);
    }

    #[test]
    fn the_readout_writes_db_ratio_and_degrees() {
        let text = readout(1.2346, -6.0206, -95.25, "G", Lang::En);
        assert_eq!(
            text,
            "ω = 1.235 rad/s   |G| = -6.021 dB (0.5)   ∠G = -95.25°"
        );
    }
}
