//! The stability margins of the loop L(s) = C(s)·G0(s)·e^{−θs} around a plant with a true
//! dead time, the delay exact (never a Padé approximant): every gain crossover (|L(jω)| = 1)
//! and every phase crossover (∠L(jω) = −180° mod 360°) on ω ≥ 0 (ω = 0 when L(0) is finite
//! and negative), the gain and phase margins
//! chosen as MATLAB's `margin` chooses them (the smallest), the delay margin, the peak of
//! the sensitivity Ms and the closed loop's bandwidth ([`margins`]).
//!
//! The crossings are found on a logarithmic grid (200 points a
//! decade, never more than 0.1/θ apart so that the delay's phase ωθ moves at most 0.1 rad
//! between samples, with points added around lightly damped roots) and refined by
//! bisection to the last bit. A missing margin is infinite: no phase crossover gives
//! GM = ∞ (the gain can be raised without bound), no gain crossover gives PM = ∞ and an
//! infinite delay margin.

use std::f64::consts::PI;

use serde::Serialize;

use crate::TransferFunction;
use crate::control::Controller;
use crate::control::frequency::{
    bisect, frequency_grid, last_crossing, loop_at, max_sensitivity, resonances, root_scales,
};
use crate::poly::{self, C64};

/// A phase crossover: ω ≥ 0 where L(jω) is real and negative.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PhaseCrossing {
    /// ω (rad/s).
    pub w: f64,
    /// The gain margin there, 1/|L(jω)|.
    pub gm: f64,
    /// The same in dB, 20·log10(gm).
    pub gm_db: f64,
}

/// A gain crossover: ω > 0 where |L(jω)| = 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GainCrossing {
    /// ω (rad/s).
    pub w: f64,
    /// The phase margin there (degrees), 180° + ∠L(jω) wrapped to (−180°, 180°].
    pub pm: f64,
    /// The extra dead time (s) that brings this crossing to −180°: the phase margin taken
    /// in [0°, 360°), in radians, over ω.
    pub delay_margin: f64,
}

/// The stability margins of a loop ([`margins`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Margins {
    /// The gain margin (a ratio): 1/|L| at the phase crossover whose |log| is smallest;
    /// `f64::INFINITY` when there is no phase crossover.
    pub gm: f64,
    /// The gain margin in dB (`f64::INFINITY` when there is no phase crossover).
    pub gm_db: f64,
    /// The phase crossover of [`Self::gm`] (rad/s); None when there is none.
    pub w_pc: Option<f64>,
    /// The phase margin (degrees, in (−180°, 180°]): the smallest in magnitude over the gain
    /// crossovers; `f64::INFINITY` when there is no gain crossover.
    pub pm: f64,
    /// The gain crossover of [`Self::pm`] (rad/s); None when there is none.
    pub w_gc: Option<f64>,
    /// The smallest extra dead time (s) that destabilises (over the gain crossovers, each
    /// phase margin taken in [0°, 360°)); `f64::INFINITY` when there is no gain crossover.
    pub delay_margin: f64,
    /// Ms, the peak of |1/(1 + L(jω))|; None unless the closed loop is stable.
    pub ms: Option<f64>,
    /// The closed loop's bandwidth (rad/s): the first ω where |T(jω)| = |L/(1 + L)| falls
    /// 3 dB below |T(0)|; `f64::INFINITY` when it does not within the frequencies scanned,
    /// None when |T(0)| is 0 or infinite (no level to fall from).
    pub bandwidth: Option<f64>,
    /// Every phase crossover found, by increasing ω.
    pub phase_crossings: Vec<PhaseCrossing>,
    /// Every gain crossover found, by increasing ω.
    pub gain_crossings: Vec<GainCrossing>,
}

/// −3 dB as a ratio.
fn minus_3db() -> f64 {
    10f64.powf(-3.0 / 20.0)
}

/// The margins of the unity-feedback loop L(s) = C(s)·G(s), G with its dead time
/// ([`Margins`]).
pub fn margins(plant: &TransferFunction, c: &Controller) -> Margins {
    let (nc, dc) = c.feedback_coeffs();
    let n = crate::locus::multiply(&nc, &plant.num());
    let d = crate::locus::multiply(&dc, &plant.den());
    let delay = plant.delay();
    let mut all: Vec<C64> = plant.zeros().iter().chain(plant.poles()).copied().collect();
    all.extend(poly::roots(&nc).unwrap_or_default());
    all.extend(poly::roots(&dc).unwrap_or_default());
    let grid = grid(&all, &n, &d, delay);
    let at = |w: f64| loop_at(plant, c, w);

    let mut phase_crossings: Vec<PhaseCrossing> = zero_crossing(at(0.0)).into_iter().collect();
    let mut gain_crossings = Vec::new();
    let sine = |w: f64| {
        let l = at(w);
        l.im / l.norm()
    };
    let log_mag = |w: f64| at(w).norm().ln();
    let (mut prev_w, mut prev_sin, mut prev_mag) = (grid[0], sine(grid[0]), log_mag(grid[0]));
    for &w in &grid[1..] {
        let (s, m) = (sine(w), log_mag(w));
        if prev_sin.is_finite() && s.is_finite() && (prev_sin < 0.0) != (s < 0.0) {
            let wpc = bisect(sine, prev_w, w);
            let l = at(wpc);
            let on_axis = l.im.abs() <= 1e-6 * l.norm();
            if l.re < 0.0 && on_axis && l.norm().is_finite() && l.norm() > 0.0 {
                let gm = 1.0 / l.norm();
                phase_crossings.push(PhaseCrossing {
                    w: wpc,
                    gm,
                    gm_db: 20.0 * gm.log10(),
                });
            }
        }
        if prev_mag.is_finite() && m.is_finite() && (prev_mag < 0.0) != (m < 0.0) {
            let wgc = bisect(log_mag, prev_w, w);
            let l = at(wgc);
            if (l.norm() - 1.0).abs() <= 1e-6 {
                let pm = wrap_degrees(180.0 + l.arg().to_degrees());
                let positive = if pm < 0.0 { pm + 360.0 } else { pm };
                gain_crossings.push(GainCrossing {
                    w: wgc,
                    pm,
                    delay_margin: positive.to_radians() / wgc,
                });
            }
        }
        (prev_w, prev_sin, prev_mag) = (w, s, m);
    }

    let chosen_gm = phase_crossings
        .iter()
        .min_by(|a, b| a.gm.ln().abs().total_cmp(&b.gm.ln().abs()));
    let chosen_pm = gain_crossings
        .iter()
        .min_by(|a, b| a.pm.abs().total_cmp(&b.pm.abs()));
    let delay_margin = gain_crossings
        .iter()
        .map(|g| g.delay_margin)
        .fold(f64::INFINITY, f64::min);
    Margins {
        gm: chosen_gm.map_or(f64::INFINITY, |p| p.gm),
        gm_db: chosen_gm.map_or(f64::INFINITY, |p| p.gm_db),
        w_pc: chosen_gm.map(|p| p.w),
        pm: chosen_pm.map_or(f64::INFINITY, |g| g.pm),
        w_gc: chosen_pm.map(|g| g.w),
        delay_margin,
        ms: max_sensitivity(plant, c).map(|s| s.ms),
        bandwidth: bandwidth(&grid, &n, &d, at),
        phase_crossings,
        gain_crossings,
    }
}

/// The phase crossover at ω = 0: a finite, negative L(0) is on the −180° line already, and
/// raising the gain by 1/|L(0)| puts a closed-loop root at s = 0 (MATLAB's `allmargin` and
/// python-control's `stability_margins` count it too).
fn zero_crossing(l0: C64) -> Option<PhaseCrossing> {
    let real_negative = l0.re < 0.0 && l0.im.abs() <= 1e-12 * l0.norm();
    (real_negative && l0.norm().is_finite()).then(|| {
        let gm = 1.0 / l0.norm();
        PhaseCrossing {
            w: 0.0,
            gm,
            gm_db: 20.0 * gm.log10(),
        }
    })
}

/// An angle in degrees brought to (−180°, 180°].
fn wrap_degrees(x: f64) -> f64 {
    let y = x.rem_euclid(360.0);
    if y > 180.0 { y - 360.0 } else { y }
}

/// The frequencies scanned: from 10⁻⁴ of the slowest scale (roots, 1/θ, the last gain
/// crossover of |n/d|) to 10⁴ of the fastest without a delay; with one, to past the last
/// frequency where |L| reaches 0.01, ten times the fastest scale, and where the delay has
/// turned (roots + 2)·180°.
fn grid(roots: &[C64], n: &[f64], d: &[f64], delay: f64) -> Vec<f64> {
    let mut scales = root_scales(roots.iter(), delay);
    if let Some(w) = last_crossing(n, d, 1.0).filter(|&w| w > 0.0) {
        scales.push(w);
    }
    if scales.is_empty() {
        scales.push(1.0);
    }
    let slowest = scales.iter().copied().fold(f64::INFINITY, f64::min);
    let fastest = scales.iter().copied().fold(0.0, f64::max);
    let lo = slowest * 1e-4;
    let hi = if delay > 0.0 {
        let quiet = last_crossing(n, d, 0.01).unwrap_or(0.0);
        (fastest * 10.0)
            .max(quiet)
            .max(PI * (roots.len() as f64 + 2.0) / delay)
    } else {
        fastest * 1e4
    };
    frequency_grid(lo, hi, delay, &resonances(roots.iter()))
}

/// The first ω of the grid's range where |T(jω)| falls 3 dB below |T(0)|, T = L/(1 + L).
fn bandwidth(grid: &[f64], n: &[f64], d: &[f64], at: impl Fn(f64) -> C64) -> Option<f64> {
    let (n0, d0) = (n[n.len() - 1], d[d.len() - 1]);
    let t0 = n0.abs() / (d0 + n0).abs();
    if !(t0.is_finite() && t0 > 0.0) {
        return None;
    }
    let level = (t0 * minus_3db()).ln();
    let t_at = |w: f64| {
        let l = at(w);
        (l / (1.0 + l)).norm().ln() - level
    };
    let mut prev = grid[0];
    if t_at(prev) < 0.0 {
        return Some(prev);
    }
    for &w in &grid[1..] {
        if t_at(w) < 0.0 {
            return Some(bisect(t_at, prev, w));
        }
        prev = w;
    }
    Some(f64::INFINITY)
}
