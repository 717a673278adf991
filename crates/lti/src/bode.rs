//! The Bode diagram of G(s) = k·Π(s − zᵢ)/Π(s − pⱼ)·e^{−θs}: |G(jω)| in dB and ∠G(jω) in
//! degrees, exact with the dead time, and the straight-line asymptotes the course notes draw
//! by hand.
//!
//! The magnitude is a sum of logarithms (one per factor), so it neither overflows nor
//! underflows where the product would. The phase is a sum of per-factor angles, each
//! continuous in ω for its root, plus 180° for a negative k and exactly −ωθ·180/π for the
//! delay: it is continuous for increasing ω by construction, never unwrapped from samples.
//! Each root's angle starts (at ω = 0) on the principal branch, so a stable system starts at
//! the phase MATLAB shows (0°, or −90° per pole at the origin); the only jumps left are the
//! true ±180° jumps at an undamped root on the imaginary axis.

use serde::{Deserialize, Serialize};

use crate::poly::C64;
use crate::tf::TransferFunction;

/// Samples of the Bode diagram.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bode {
    /// Frequencies ω (rad/s).
    pub w: Vec<f64>,
    /// |G(jω)| in dB.
    pub mag_db: Vec<f64>,
    /// ∠G(jω) in degrees, continuous in ω.
    pub phase_deg: Vec<f64>,
}

/// A corner frequency of the asymptotes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Corner {
    /// The corner ω (rad/s): |r| of a real root or ωn of a complex pair.
    pub w: f64,
    /// How the slope changes there (dB/decade): −20 per real pole, −40 per complex pair of
    /// poles, +20 and +40 for zeros (summed when roots share a corner).
    pub slope_change_db_per_decade: f64,
}

/// The notes' straight-line magnitude asymptotes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Asymptotes {
    /// 20·log10|K_bode|: the low-frequency line's value at ω = 1, K_bode the gain of the
    /// time-constant (Bode) form.
    pub low_db_at_1: f64,
    /// The system type: the net number of poles at the origin.
    pub system_type: i32,
    /// The corners, in increasing ω.
    pub corners: Vec<Corner>,
}

impl Asymptotes {
    /// The low-frequency slope, −20·type dB/decade.
    pub fn low_slope(&self) -> f64 {
        -20.0 * f64::from(self.system_type)
    }

    /// The slope in each interval (dB/decade): before the first corner, then after each one.
    pub fn slopes(&self) -> Vec<f64> {
        let mut slope = self.low_slope();
        let mut out = vec![slope];
        for c in &self.corners {
            slope += c.slope_change_db_per_decade;
            out.push(slope);
        }
        out
    }

    /// The asymptotes as the notes say them, line by line: the low-frequency line, then each
    /// corner where the slope changes (a pole and a zero sharing a corner change nothing and
    /// are not said), or that there is none ([`AsymptoteLine`]; its words are in
    /// `crate::words::bode`).
    pub fn lines(&self) -> Vec<AsymptoteLine> {
        let mut out = vec![AsymptoteLine::Low {
            db: self.low_db_at_1,
            slope: self.low_slope(),
            system_type: self.system_type,
        }];
        let corners: Vec<AsymptoteLine> = self
            .corners
            .iter()
            .zip(self.slopes().into_iter().skip(1))
            .filter(|(c, _)| c.slope_change_db_per_decade != 0.0)
            .map(|(c, slope)| AsymptoteLine::Corner {
                w: c.w,
                change: c.slope_change_db_per_decade,
                slope,
            })
            .collect();
        if corners.is_empty() {
            out.push(AsymptoteLine::NoCorner);
        }
        out.extend(corners);
        out
    }

    /// The piecewise line at ω (dB): the low-frequency line plus each passed corner's change.
    pub fn value_db(&self, w: f64) -> f64 {
        let lw = w.log10();
        let mut value = self.low_db_at_1 + self.low_slope() * lw;
        for c in self.corners.iter().filter(|c| c.w < w) {
            value += c.slope_change_db_per_decade * (lw - c.w.log10());
        }
        value
    }
}

/// A line of the asymptotes in words ([`Asymptotes::lines`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AsymptoteLine {
    /// The low-frequency line: `db` at ω = 1 rad/s, its `slope` (dB/decade), the type.
    Low {
        db: f64,
        slope: f64,
        system_type: i32,
    },
    /// No corner changes the slope: the asymptote is the low-frequency line everywhere.
    NoCorner,
    /// A corner at `w` (rad/s) where the slope changes by `change` to `slope` (dB/decade).
    Corner { w: f64, change: f64, slope: f64 },
}

/// The angle of jω − r (radians), continuous in ω ≥ 0 and on the principal branch at ω = 0.
fn root_angle(r: C64, w: f64) -> f64 {
    let (x, y) = (-r.re, w - r.im);
    let a = y.atan2(x);
    // In the left half plane of jω − r (a root in the right half plane), jω − r crosses the
    // negative real axis upward when r.im > 0: atan2 would jump from −π to π there.
    if x < 0.0 && r.im > 0.0 && y >= 0.0 {
        a - 2.0 * std::f64::consts::PI
    } else {
        a
    }
}

/// 20·log10|G(jω)| and ∠G(jω) in degrees (continuous) at one ω.
fn point(g: &TransferFunction, w: f64) -> (f64, f64) {
    let s = C64::new(0.0, w);
    let log_mag = |roots: &[C64]| roots.iter().map(|&r| (s - r).norm().log10()).sum::<f64>();
    let angle = |roots: &[C64]| roots.iter().map(|&r| root_angle(r, w)).sum::<f64>();
    let mag_db = 20.0 * (g.gain().abs().log10() + log_mag(g.zeros()) - log_mag(g.poles()));
    let sign = if g.gain() < 0.0 { 180.0 } else { 0.0 };
    let phase = (angle(g.zeros()) - angle(g.poles())).to_degrees() + sign
        - w * g.delay() * 180.0 / std::f64::consts::PI;
    (mag_db, phase)
}

/// The Bode diagram at the frequencies `w` (rad/s, increasing for a continuous phase).
pub fn bode(g: &TransferFunction, w: &[f64]) -> Bode {
    let (mag_db, phase_deg) = w.iter().map(|&w| point(g, w)).unzip();
    Bode {
        w: w.to_vec(),
        mag_db,
        phase_deg,
    }
}

/// The notes' asymptotes of |G(jω)|: corners at |r| of each root off the origin (one per
/// complex pair, ±40 dB/decade), the low-frequency line from the type and K_bode.
pub fn asymptotes(g: &TransferFunction) -> Asymptotes {
    let mut corners: Vec<Corner> = Vec::new();
    let mut low_db_at_1 = 20.0 * g.gain().abs().log10();
    let mut add = |roots: &[C64], sign: f64| {
        for &r in roots.iter().filter(|r| r.norm() != 0.0) {
            low_db_at_1 += sign * 20.0 * r.norm().log10();
            let change = if r.im == 0.0 {
                20.0
            } else if r.im > 0.0 {
                40.0
            } else {
                continue;
            };
            corners.push(Corner {
                w: r.norm(),
                slope_change_db_per_decade: sign * change,
            });
        }
    };
    add(g.zeros(), 1.0);
    add(g.poles(), -1.0);
    corners.sort_by(|a, b| a.w.total_cmp(&b.w));
    let mut merged: Vec<Corner> = Vec::with_capacity(corners.len());
    for c in corners {
        match merged.last_mut() {
            Some(last) if last.w == c.w => {
                last.slope_change_db_per_decade += c.slope_change_db_per_decade
            }
            _ => merged.push(c),
        }
    }
    Asymptotes {
        low_db_at_1,
        system_type: g.system_type(),
        corners: merged,
    }
}

/// `points` frequencies evenly spread in log10 ω over [w_min, w_max] (both included).
pub fn log_grid(w_min: f64, w_max: f64, points: usize) -> Vec<f64> {
    let (lo, hi) = (w_min.log10(), w_max.log10());
    match points {
        0 => Vec::new(),
        1 => vec![w_min],
        n => (0..n)
            .map(|i| match i {
                0 => w_min,
                i if i == n - 1 => w_max,
                i => 10f64.powf(lo + (hi - lo) * i as f64 / (n - 1) as f64),
            })
            .collect(),
    }
}

/// The default range, as MATLAB's: whole decades from two below the lowest corner to two
/// above the highest (around 1/θ, or ω = 1, when there is no corner).
pub fn default_range(g: &TransferFunction) -> (f64, f64) {
    let corners = asymptotes(g).corners;
    let (low, high) = match (corners.first(), corners.last()) {
        (Some(a), Some(b)) => (a.w, b.w),
        _ if g.delay() > 0.0 => (1.0 / g.delay(), 1.0 / g.delay()),
        _ => (1.0, 1.0),
    };
    (
        10f64.powf((low.log10() - 2.0).floor()),
        10f64.powf((high.log10() + 2.0).ceil()),
    )
}

/// A log grid of `points` frequencies over [`default_range`].
pub fn frequency_grid(g: &TransferFunction, points: usize) -> Vec<f64> {
    let (lo, hi) = default_range(g);
    log_grid(lo, hi, points)
}
