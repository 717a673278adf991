//! How the app looks: the one palette every colour comes from (light and dark), the
//! presentation size and the language, handed to every view as one [`Look`].
//!
//! Views never write a `Color32` of their own: a colour they need is a named field here,
//! chosen for both themes, so a curve, its marker and its legend agree everywhere.

use eframe::egui::{Color32, Visuals};

use degrau_words::Lang;

/// The smallest and largest presentation size (a factor on text, markers and lines).
pub const SCALE_RANGE: std::ops::RangeInclusive<f32> = 1.0..=2.0;

/// The smallest window (points at the presentation size) every mode is laid out for: the
/// presentation size is capped so the window keeps at least this much, its menu and its
/// plots (a 1000×650 window stays at 1×; 1600×900 goes up to 1.38×).
pub const LAYOUT_MIN: [f32; 2] = [1000.0, 650.0];

/// The zoom to draw at: the presentation size asked for, capped so a window of
/// `window` points at 1× keeps [`LAYOUT_MIN`] (never below 1×).
pub fn fitted_zoom(scale: f32, window: [f32; 2]) -> f32 {
    let room = (window[0] / LAYOUT_MIN[0]).min(window[1] / LAYOUT_MIN[1]);
    let room = if room.is_finite() { room } else { 1.0 };
    clamp_scale(scale.min(room))
}

/// Every colour the app draws with, for one theme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Palette {
    /// The system's (or the data's model's) main curve.
    pub main: Color32,
    /// A system kept for comparison, and its markers.
    pub compare: Color32,
    /// Step metric markers (rise, settling, peak, dead time).
    pub marker: Color32,
    /// The response before the last edit.
    pub ghost: Color32,
    /// Something wrong said on the canvas ("does not settle", an unstable system).
    pub error: Color32,
    /// A warning (a fit warning, a kept choice).
    pub warning: Color32,
    /// The s-plane's stable half.
    pub stable_region: Color32,
    /// Grid lines of the s-plane.
    pub grid: Color32,
    /// Axes and their labels.
    pub axis: Color32,
    /// Constant-ζ and constant-ωn lines.
    pub damping: Color32,
    /// Poles (×).
    pub pole: Color32,
    /// Zeros (o).
    pub zero: Color32,
    /// The selected root, an active handle.
    pub selected: Color32,
    /// Quiet text on a canvas.
    pub weak_text: Color32,
    /// Measured data.
    pub data: Color32,
    /// A fitted or guessed model over the data.
    pub model: Color32,
    /// A draggable guess handle at rest.
    pub handle: Color32,
    /// The window of the data that a piece of evidence is about.
    pub evidence: Color32,
    /// The optimiser's path on the cost landscape.
    pub path: Color32,
    /// Local minima on the cost landscape.
    pub minimum: Color32,
    /// The fit's point on the cost landscape.
    pub fit_point: Color32,
}

impl Palette {
    /// The palette of a theme.
    pub fn new(dark: bool) -> Self {
        let visuals = if dark {
            Visuals::dark()
        } else {
            Visuals::light()
        };
        let pick = |d: Color32, l: Color32| if dark { d } else { l };
        let rgb = Color32::from_rgb;
        Self {
            main: pick(rgb(120, 190, 255), rgb(20, 90, 200)),
            // Purple: the fitted model's and the closed loop's orange is another curve on
            // the same plots (the notes' example drew two models in one orange).
            compare: pick(rgb(205, 140, 255), rgb(130, 50, 190)),
            marker: pick(rgb(240, 200, 80), rgb(170, 110, 0)),
            ghost: visuals.weak_text_color().gamma_multiply(0.6),
            error: pick(rgb(255, 110, 90), rgb(200, 40, 30)),
            warning: pick(rgb(240, 170, 60), rgb(190, 100, 0)),
            stable_region: pick(
                Color32::from_rgba_unmultiplied(40, 90, 50, 50),
                Color32::from_rgba_unmultiplied(120, 200, 130, 45),
            ),
            grid: visuals.widgets.noninteractive.bg_stroke.color,
            axis: visuals.text_color(),
            damping: pick(rgb(90, 110, 160), rgb(130, 150, 200)),
            pole: pick(rgb(255, 120, 100), rgb(200, 40, 30)),
            zero: pick(rgb(110, 170, 255), rgb(20, 80, 200)),
            selected: rgb(240, 170, 0),
            weak_text: visuals.weak_text_color(),
            data: pick(rgb(200, 200, 200), rgb(60, 60, 60)),
            model: pick(rgb(255, 150, 80), rgb(210, 80, 0)),
            handle: pick(rgb(255, 150, 80), rgb(210, 80, 0)),
            evidence: Color32::from_rgba_unmultiplied(230, 60, 60, 40),
            path: pick(Color32::WHITE, rgb(30, 30, 30)),
            minimum: pick(Color32::LIGHT_RED, rgb(200, 30, 30)),
            fit_point: pick(Color32::YELLOW, rgb(230, 160, 0)),
        }
    }
}

/// What every view is drawn with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    pub lang: Lang,
    pub palette: Palette,
    /// The presentation size, within [`SCALE_RANGE`].
    pub scale: f32,
}

impl Look {
    pub fn new(lang: Lang, dark: bool, scale: f32) -> Self {
        Self {
            lang,
            palette: Palette::new(dark),
            scale: clamp_scale(scale),
        }
    }
}

/// A presentation size within [`SCALE_RANGE`] (a non-number is 1).
pub fn clamp_scale(scale: f32) -> f32 {
    if scale.is_finite() {
        scale.clamp(*SCALE_RANGE.start(), *SCALE_RANGE.end())
    } else {
        1.0
    }
}

/// Names a plot or canvas for a screen reader (and the layout tests): a canvas `name`.
pub fn name_canvas(response: &eframe::egui::Response, name: &str) {
    response.widget_info(|| {
        eframe::egui::WidgetInfo::labeled(eframe::egui::accesskit::Role::Canvas, true, name)
    });
}

/// One line of widgets scrolled sideways when it does not fit, with room under it for the
/// scroll bar (a floating bar over the line took the clicks on its lower half).
pub fn one_line<R>(
    ui: &mut eframe::egui::Ui,
    id: &str,
    add: impl FnOnce(&mut eframe::egui::Ui) -> R,
) -> R {
    eframe::egui::ScrollArea::horizontal()
        .id_salt(id)
        .show(ui, |ui| {
            let inner = ui.horizontal(add).inner;
            // The line's middle (where a click lands) is kept clear of the bar.
            let bar = ui.spacing().scroll;
            let zone = bar.bar_width + bar.bar_inner_margin + bar.bar_outer_margin;
            ui.add_space((zone - 0.5 * ui.spacing().interact_size.y + 1.0).max(0.0));
            inner
        })
        .inner
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curves_differ_from_each_other_in_both_themes() {
        for dark in [false, true] {
            let p = Palette::new(dark);
            let curves = [p.main, p.compare, p.marker, p.data, p.model];
            for (i, a) in curves.iter().enumerate() {
                for b in &curves[i + 1..] {
                    // Told apart at a glance: the "redmean" colour distance (0 to ~765),
                    // not merely unequal ((255, 170, 90) and (255, 150, 80) were both orange).
                    assert!(distance(*a, *b) > 80.0, "{a:?} {b:?}, dark = {dark}");
                }
            }
        }
    }

    /// The "redmean" approximation of perceived colour difference.
    fn distance(a: Color32, b: Color32) -> f64 {
        let (r1, g1, b1) = (a.r() as f64, a.g() as f64, a.b() as f64);
        let (r2, g2, b2) = (b.r() as f64, b.g() as f64, b.b() as f64);
        let mean = (r1 + r2) / 2.0;
        let (dr, dg, db) = (r1 - r2, g1 - g2, b1 - b2);
        ((2.0 + mean / 256.0) * dr * dr + 4.0 * dg * dg + (2.0 + (255.0 - mean) / 256.0) * db * db)
            .sqrt()
    }

    #[test]
    fn the_zoom_keeps_the_smallest_layout() {
        assert_eq!(fitted_zoom(1.6, [1000.0, 650.0]), 1.0);
        assert!((fitted_zoom(1.6, [1600.0, 900.0]) - 900.0 / 650.0).abs() < 1e-6);
        assert_eq!(fitted_zoom(1.2, [1600.0, 900.0]), 1.2);
        assert_eq!(fitted_zoom(2.0, [2400.0, 1300.0]), 2.0);
        assert_eq!(fitted_zoom(1.6, [0.0, 0.0]), 1.0);
    }

    #[test]
    fn scale_is_clamped() {
        assert_eq!(clamp_scale(0.2), 1.0);
        assert_eq!(clamp_scale(3.0), 2.0);
        assert_eq!(clamp_scale(f32::NAN), 1.0);
        assert_eq!(clamp_scale(1.6), 1.6);
    }
}
