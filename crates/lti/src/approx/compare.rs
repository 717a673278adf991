//! What an approximation costs: the largest gap between two exact step responses relative
//! to the step's effect, their integral of squared error (ISE), and each step metric's
//! difference, with which metrics stay within 5 %.
//!
//! Both responses are the exact ones ([`StepResponse`]), read over one window [0, T]: T is
//! the larger of the two automatic windows ([`analyse`]). The window is cut at t = 0 and at
//! each dead time (where a response may start or jump), each piece into small intervals;
//! the ISE is their 3-point Gauss–Legendre sum, the largest gap the best sample refined by
//! a golden-section search. The ISE is summed in units of the step's effect squared, so that
//! a response near 1e±160 (whose ISE a double cannot hold) still has its order of magnitude.
//!
//! A metric is within 5 % when its difference is at most 5 % of the original's value: the
//! overshoot and undershoot too (2.12 % against 4.32 % is a change of 104 %, not "within"),
//! where an original under [`NEGLIGIBLE_PERCENT`] % allows that many points (a response
//! that barely overshoots is not told from one that does not); two absent metrics agree, a
//! metric present in one only does not.

use serde::Serialize;

use crate::golden::golden_max;
use crate::words::step::Metric;
use crate::{StepInfo, StepInfoOptions, StepResponse, analyse};

/// The tolerance of "within 5 %", relative to the original's value.
pub const WITHIN: f64 = 0.05;
/// An overshoot or undershoot below this (percent of the change) is negligible: a
/// difference of this many points is within.
pub const NEGLIGIBLE_PERCENT: f64 = 0.1;

/// Small intervals the window is cut into (shared by the pieces, by length).
const INTERVALS: usize = 1200;

/// One step metric, original and approximate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MetricDifference {
    #[serde(skip)]
    pub metric: Metric,
    pub original: Option<f64>,
    pub approx: Option<f64>,
    /// approx − original, in the metric's unit.
    pub difference: Option<f64>,
    /// The difference over |original| (a fraction), when the original is not 0.
    pub relative: Option<f64>,
    /// Within [`WITHIN`] (see the module docs).
    pub within: bool,
}

/// The cost of replacing one response by another.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    pub original: StepInfo,
    pub approx: StepInfo,
    /// max |y − ŷ| over the window, over the step's effect (a fraction).
    pub max_error: f64,
    /// When that largest gap happens (s).
    pub max_error_time: f64,
    /// ∫₀ᵀ (y − ŷ)² dt, in the output's units squared times seconds: 0 or ∞ where a double
    /// cannot hold it (responses near 1e±160), see [`Comparison::ise_value`].
    pub ise: f64,
    /// ∫₀ᵀ ((y − ŷ)/effect)² dt (s): the ISE in units of the step's effect squared, which a
    /// double holds at any scale of the output.
    pub ise_relative: f64,
    /// The window's end T (s).
    pub horizon: f64,
    /// The step's effect the gaps are measured against: |A·G(0)| for a response that
    /// settles (else the largest |y| of the original over the window).
    pub effect: f64,
    /// Every metric of [`Metric::ALL`], in that order.
    pub metrics: Vec<MetricDifference>,
}

impl Comparison {
    /// The metrics within 5 %.
    pub fn kept(&self) -> Vec<Metric> {
        self.metrics
            .iter()
            .filter(|d| d.within)
            .map(|d| d.metric)
            .collect()
    }

    /// The ISE when a double holds it; `None` beyond double precision (then
    /// [`Comparison::ise_log10`] gives its order of magnitude).
    pub fn ise_value(&self) -> Option<f64> {
        (self.ise_relative == 0.0 || self.ise.is_normal()).then_some(self.ise)
    }

    /// log₁₀ of the ISE, at any scale (−∞ for an exact 0).
    pub fn ise_log10(&self) -> f64 {
        self.ise_relative.log10() + 2.0 * self.effect.log10()
    }
}

/// Compares the exact step response `approx` with `original` (same step).
pub fn compare(
    original: &StepResponse,
    approx: &StepResponse,
    options: &StepInfoOptions,
) -> Comparison {
    let a = analyse(original, options);
    let b = analyse(approx, options);
    let horizon = a.horizon.max(b.horizon);
    let gap = |t: f64| original.value(t) - approx.value(t);
    let pieces = pieces(horizon, &[original.delay(), approx.delay()]);
    let effect = step_effect(original, horizon);
    let mut ise_relative = 0.0;
    let mut best = (0.0f64, 0.0f64);
    let mut best_piece = (0.0, 0.0, 0.0);
    for &(start, end, count) in &pieces {
        let h = (end - start) / count as f64;
        for i in 0..count {
            let (lo, hi) = (start + i as f64 * h, start + (i + 1) as f64 * h);
            ise_relative += gauss3(&|t| (gap(t) / effect).powi(2), lo, hi);
            for t in [lo, hi] {
                let e = gap(t).abs();
                // A gap that is not a number is kept too: the comparison then has none.
                if e.is_nan() || e > best.1 {
                    best = (t, e);
                    best_piece = (start, end, h);
                }
            }
        }
    }
    let (start, end, h) = best_piece;
    let (lo, hi) = ((best.0 - h).max(start), (best.0 + h).min(end));
    let refined = golden_max(|t| gap(t).abs(), lo, hi, 0.0);
    if refined.1 > best.1 {
        best = refined;
    }
    Comparison {
        metrics: differences(&a.info, &b.info),
        original: a.info,
        approx: b.info,
        max_error: best.1 / effect,
        max_error_time: best.0,
        ise: ise_relative * effect * effect,
        ise_relative,
        horizon,
        effect,
    }
}

/// |A·G(0)| for a response that settles, else the largest |y| sampled over the window (1
/// when that is 0 too).
fn step_effect(r: &StepResponse, horizon: f64) -> f64 {
    let effect = match r.final_value() {
        Some(y) if y != 0.0 => y.abs(),
        _ => (0..=INTERVALS)
            .map(|i| r.value(horizon * i as f64 / INTERVALS as f64).abs())
            .fold(0.0, f64::max),
    };
    if effect > 0.0 && effect.is_finite() {
        effect
    } else {
        1.0
    }
}

/// [0, T] cut at the instants inside it: (start, end, intervals) for each piece.
fn pieces(horizon: f64, cuts: &[f64]) -> Vec<(f64, f64, usize)> {
    let mut at: Vec<f64> = cuts
        .iter()
        .copied()
        .filter(|&c| c > 0.0 && c < horizon)
        .collect();
    at.push(0.0);
    at.push(horizon);
    at.sort_by(f64::total_cmp);
    at.dedup();
    at.windows(2)
        .map(|w| {
            let share = ((w[1] - w[0]) / horizon * INTERVALS as f64).ceil() as usize;
            (w[0], w[1], share.max(8))
        })
        .collect()
}

/// ∫ f over [a, b] by 3-point Gauss–Legendre.
fn gauss3(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let x = (0.6f64).sqrt() * half;
    half * (5.0 * f(mid - x) + 8.0 * f(mid) + 5.0 * f(mid + x)) / 9.0
}

/// Each metric of [`Metric::ALL`], original against approximate.
fn differences(original: &StepInfo, approx: &StepInfo) -> Vec<MetricDifference> {
    Metric::ALL
        .iter()
        .map(|&metric| {
            let (o, a) = (metric.value(original), metric.value(approx));
            let difference = o.zip(a).map(|(o, a)| a - o);
            let relative = o
                .zip(difference)
                .filter(|(o, _)| *o != 0.0)
                .map(|(o, d)| d / o.abs());
            let within = match (o, difference) {
                (None, None) => a.is_none(),
                (Some(_), None) | (None, Some(_)) => false,
                (Some(o), Some(d)) => match metric {
                    Metric::Overshoot | Metric::Undershoot => {
                        d.abs() <= (WITHIN * o.abs()).max(NEGLIGIBLE_PERCENT)
                    }
                    _ => d.abs() <= WITHIN * o.abs(),
                },
            };
            MetricDifference {
                metric,
                original: o,
                approx: a,
                difference,
                relative,
                within,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TransferFunction;

    fn response(num: &[f64], den: &[f64]) -> StepResponse {
        StepResponse::new(&TransferFunction::from_coeffs(num, den).unwrap(), 1.0).unwrap()
    }

    #[test]
    fn two_lags_have_their_known_gap_and_ise() {
        // 1/(s+1) against 2/(s+2): e = e^{−2t} − e^{−t}, largest 1/4 at ln 2, and
        // ∫₀^∞ e² = 1/2 − 2/3 + 1/4 = 1/12 (the window holds all but ~e^{−2T}/2).
        let c = compare(
            &response(&[1.0], &[1.0, 1.0]),
            &response(&[2.0], &[1.0, 2.0]),
            &StepInfoOptions::default(),
        );
        assert!((c.max_error - 0.25).abs() < 1e-12, "{}", c.max_error);
        assert!((c.max_error_time - 2f64.ln()).abs() < 1e-6);
        let tail = (-2.0 * c.horizon).exp() / 2.0;
        assert!((c.ise - 1.0 / 12.0).abs() < tail + 1e-12, "{}", c.ise);
        assert_eq!(c.effect, 1.0);
    }

    #[test]
    fn a_model_compared_with_itself_keeps_every_metric() {
        let r = response(&[5.0], &[1.0, 2.0, 5.0]);
        let c = compare(&r, &r, &StepInfoOptions::default());
        assert_eq!((c.max_error, c.ise), (0.0, 0.0));
        assert_eq!(c.kept(), Metric::ALL.to_vec());
    }
}
