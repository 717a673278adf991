//! The s-plane's geometry and kept state, with nothing painted: which part of the plane is
//! shown ([`View`], its sane ranges, [`fit_view`]), the canvas's state kept between frames
//! and runs ([`SPlaneState`]), the mapping between screen and plane for one frame
//! ([`Transform`]) and the readout of a point ([`readout`]). The canvas that draws with them
//! is [`super::splane`]; the closed loop's overlay on it is [`super::locus_view`].

use eframe::egui::{self, Pos2, Rect, Ui, Vec2};
use serde::{Deserialize, Serialize};

use degrau_words::Lang;

use super::state::{ROOT_LIMIT, Root, RootId, RootRole, System};

/// Target pixels between grid lines.
const GRID_PIXELS: f64 = 70.0;

/// Fewest pixels per unit (1/s) of a view: ±[`ROOT_LIMIT`] fits in a few hundred pixels.
pub const MIN_PIXELS_PER_UNIT: f64 = 1e-8;
/// Most pixels per unit of a view (a pixel is 0.1 µ(1/s)).
pub const MAX_PIXELS_PER_UNIT: f64 = 1e7;
/// Farthest a view's centre may be from the origin (1/s): ten times [`ROOT_LIMIT`].
pub const CENTER_LIMIT: f64 = 10.0 * ROOT_LIMIT;

/// Which part of the s-plane is shown: the point at the centre and pixels per unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct View {
    pub center_re: f64,
    pub center_im: f64,
    pub pixels_per_unit: f64,
}

impl View {
    /// The view clamped to finite, sane ranges (centre within ±[`CENTER_LIMIT`], scale in
    /// [[`MIN_PIXELS_PER_UNIT`], [`MAX_PIXELS_PER_UNIT`]]); `None` when a number is NaN,
    /// so the view is fitted to the roots again.
    pub fn sane(self) -> Option<View> {
        let View {
            center_re,
            center_im,
            pixels_per_unit,
        } = self;
        if center_re.is_nan() || center_im.is_nan() || pixels_per_unit.is_nan() {
            return None;
        }
        Some(View {
            center_re: center_re.clamp(-CENTER_LIMIT, CENTER_LIMIT),
            center_im: center_im.clamp(-CENTER_LIMIT, CENTER_LIMIT),
            pixels_per_unit: pixels_per_unit.clamp(MIN_PIXELS_PER_UNIT, MAX_PIXELS_PER_UNIT),
        })
    }

    /// True when the view is already within its sane ranges.
    pub fn is_sane(&self) -> bool {
        self.sane() == Some(*self)
    }
}

/// The canvas's own state (kept between frames and runs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SPlaneState {
    /// `None` fits the view to the roots on the next frame.
    pub view: Option<View>,
    pub damping_grid: bool,
    pub snap: bool,
    pub selected: Option<RootId>,
}

impl Default for SPlaneState {
    fn default() -> Self {
        Self {
            view: None,
            damping_grid: true,
            snap: false,
            selected: None,
        }
    }
}

/// Mapping between screen and s-plane for one frame.
#[derive(Debug, Clone, Copy)]
pub struct Transform {
    pub(super) rect: Rect,
    pub(super) view: View,
}

impl Transform {
    /// Whether a handle at `at` is on the canvas (one off it is neither drawn nor offered
    /// to a screen reader), or is being dragged as `id` (the drag follows the pointer out).
    pub fn holds_handle(&self, ui: &Ui, at: Pos2, id: egui::Id) -> bool {
        self.rect.contains(at) || ui.ctx().is_being_dragged(id)
    }

    /// The canvas's rect on screen.
    pub fn rect(&self) -> Rect {
        self.rect
    }

    /// Pixels per unit (1/s) of the view.
    pub fn pixels_per_unit(&self) -> f64 {
        self.view.pixels_per_unit
    }

    pub fn to_screen(&self, re: f64, im: f64) -> Pos2 {
        let c = self.rect.center();
        Pos2::new(
            c.x + ((re - self.view.center_re) * self.view.pixels_per_unit) as f32,
            c.y - ((im - self.view.center_im) * self.view.pixels_per_unit) as f32,
        )
    }

    pub fn to_plane(&self, p: Pos2) -> (f64, f64) {
        let c = self.rect.center();
        (
            self.view.center_re + (p.x - c.x) as f64 / self.view.pixels_per_unit,
            self.view.center_im - (p.y - c.y) as f64 / self.view.pixels_per_unit,
        )
    }

    /// A 1-2-5 grid step giving about [`GRID_PIXELS`] between lines.
    pub fn grid_step(&self) -> f64 {
        crate::grid::nice_step(GRID_PIXELS / self.view.pixels_per_unit)
    }
}

/// A view showing every root and the origin with a margin (roots beyond ±[`ROOT_LIMIT`],
/// or not finite, count as at the limit), within the sane ranges of [`View::sane`].
pub fn fit_view(system: &System, size: Vec2) -> View {
    let bounded = |x: f64| {
        if x.is_nan() {
            0.0
        } else {
            x.clamp(-ROOT_LIMIT, ROOT_LIMIT)
        }
    };
    let points: Vec<(f64, f64)> = [RootRole::Pole, RootRole::Zero]
        .iter()
        .flat_map(|&role| system.roots(role).iter())
        .map(|r| (bounded(r.re), bounded(r.im)))
        .flat_map(|(re, im)| [(re, im), (re, -im)])
        .chain([(0.0, 0.0)])
        .collect();
    let (min_re, max_re) = points
        .iter()
        .fold((0.0f64, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
    // Leave part of the right half plane in view so the imaginary axis is not at the edge.
    let max_re = max_re.max(0.25 * (max_re - min_re).max(1.0));
    let max_im = points.iter().fold(0.0f64, |a, p| a.max(p.1.abs()));
    let half_width = (0.5 * (max_re - min_re) * 1.25).max(1.0);
    let half_height = (max_im * 1.25).max(1.0);
    let pixels_per_unit = (size.x as f64 / 2.0 / half_width).min(size.y as f64 / 2.0 / half_height);
    let view = View {
        center_re: 0.5 * (min_re + max_re),
        center_im: 0.0,
        pixels_per_unit,
    };
    view.sane().unwrap_or(View {
        center_re: 0.0,
        center_im: 0.0,
        pixels_per_unit: 100.0,
    })
}

/// `s = −1 ± 2j · ζ = 0.447 · ωn = 2.236 rad/s · τ = 1 s` for a point of the plane, with
/// `lang`'s decimal separator.
pub fn readout(re: f64, im: f64, name: &str, lang: Lang) -> String {
    let sig = |x: f64, d: i32| lang.num(x, d);
    let root = if im.abs() > 0.0 {
        Root::pair(re, im)
    } else {
        Root::real(re)
    };
    let mut text = format!("{name} = {}", sig(re, 4));
    if im.abs() > 0.0 {
        text.push_str(&format!(" ± {}j", sig(im.abs(), 4)));
    }
    if let Some(zeta) = root.damping() {
        text.push_str(&format!(" · ζ = {}", sig(zeta, 4)));
    }
    text.push_str(&format!(
        " · ωn = {} rad/s",
        sig(root.natural_frequency(), 4)
    ));
    if re != 0.0 {
        text.push_str(&format!(" · τ = 1/|σ| = {} s", sig(1.0 / re.abs(), 4)));
    }
    if im.abs() > 0.0 {
        text.push_str(&format!(" · ωd = {} rad/s", sig(im.abs(), 4)));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transform_round_trip() {
        let t = Transform {
            rect: Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(400.0, 300.0)),
            view: View {
                center_re: -2.0,
                center_im: 0.5,
                pixels_per_unit: 40.0,
            },
        };
        let p = t.to_screen(-3.25, 1.5);
        let (re, im) = t.to_plane(p);
        assert!((re + 3.25).abs() < 1e-5 && (im - 1.5).abs() < 1e-5);
    }

    #[test]
    fn readout_names_damping_and_frequency() {
        let r = readout(-1.0, 2.0, "s", Lang::En);
        assert_eq!(
            r,
            "s = -1 ± 2j · ζ = 0.4472 · ωn = 2.236 rad/s · τ = 1/|σ| = 1 s · ωd = 2 rad/s"
        );
        assert!(readout(-1.5, 0.0, "s", Lang::Pt).starts_with("s = -1,5 ·"));
    }

    #[test]
    fn fitting_shows_every_root() {
        let system = System::default();
        let v = fit_view(&system, Vec2::new(400.0, 400.0));
        let t = Transform {
            rect: Rect::from_min_size(Pos2::ZERO, Vec2::new(400.0, 400.0)),
            view: v,
        };
        for (re, im) in [(-5.0, 0.0), (-1.0, 2.0), (-1.0, -2.0), (0.0, 0.0)] {
            assert!(t.rect.contains(t.to_screen(re, im)));
        }
    }
}
