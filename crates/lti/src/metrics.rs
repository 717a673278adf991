//! Step-response characteristics with MATLAB `stepinfo` definitions, computed on the
//! continuous response rather than read off samples.
//!
//! A response is described by *monotone pieces*: breakpoints (t, y) between which y is
//! monotone, and a way to find where a piece crosses a level. For an LTI response the
//! breakpoints are the step instant and every zero of y'(t) (found on a grid dense enough
//! for the fastest oscillation and, just after the step, for the fastest pole or zero,
//! refined by safeguarded Newton with y''), so every level crossing lies in exactly one
//! piece and is refined to machine precision. The search stops where the transients'
//! envelope shows that the tail can no longer change any metric (see
//! [`LtiPieces::for_metrics`]). Measured data (straight lines between samples) fit the same
//! description, so both share one definition.
//!
//! Newton starts close to its answer: a critical point from the zero of the chord of y'
//! across its cell, a level crossing from y at the piece's start plus the trapezoid rule
//! on the grid of y' (a long monotone rise otherwise costs bisections first); and it stops
//! as soon as two steps show quadratic convergence leaving the next one below rounding
//! (about three evaluations of the closed form per point).
//!
//! All levels are measured from y_init (the output before the step: 0 for a system at rest)
//! towards y_final, with Δ = y_final − y_init:
//! - **rise time**: from the first time y reaches y_init + 10 % Δ to the first time it
//!   reaches y_init + 90 % Δ (limits settable, e.g. 5–95 %; with 0–100 % it is the time of
//!   the first arrival at y_final after the dead time, as MATLAB's `stepinfo` gives it);
//! - **settling time**: the first time after which |y − y_final| ≤ 2 % |Δ| forever
//!   (threshold settable, e.g. 5 %), counted from the step (a dead time is included);
//! - **overshoot**: 100·(largest excursion beyond y_final)/|Δ| in %, 0 when there is none;
//! - **undershoot**: 100·(largest excursion from y_init opposite to Δ)/|Δ| in %, 0 when none
//!   (with y_init = 0 both are "% of |y_final|", as MATLAB and python-control report them);
//! - **peak**: the largest |y − y_init| (MATLAB's peak absolute value when y_init = 0) and
//!   **peak time** when it is reached; a response that never exceeds |Δ| approaches its
//!   peak only as t → ∞, so peak = |Δ| and peak time is *none*;
//! - **settling min / max**: the smallest and largest y once the response has risen (from
//!   the end of the rise on), the final value included as the limit it approaches;
//! - **steady state**: y_final.
//!
//! A response that does not settle (integrator, unstable, undamped) has no final value, so
//! none of these exist and all are `None`; for a bounded undamped oscillation the peak and
//! its time are still reported. Excursions smaller than [`NEGLIGIBLE`]·|Δ| are not counted
//! as overshoot or undershoot (they are below the accuracy of the closed form).

use serde::{Deserialize, Serialize};

use super::LtiError;
use super::response::{Behaviour, Derivative, StepResponse};

/// Excursions below this fraction of |Δ| are numerical noise, not overshoot.
pub const NEGLIGIBLE: f64 = 1e-10;

/// The narrowest settling band accepted (a fraction of the step's effect): the response is
/// computed to about 1e-12 of its final value, so a band below 1e-9 could not be judged.
pub const MIN_SETTLING_THRESHOLD: f64 = 1e-9;

/// Thresholds of the metrics, as MATLAB's `stepinfo` options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepInfoOptions {
    /// Settling band as a fraction of |Δ| (MATLAB's SettlingTimeThreshold, default 0.02).
    pub settling_threshold: f64,
    /// Rise-time limits as fractions of Δ (MATLAB's RiseTimeLimits, default (0.1, 0.9)).
    pub rise_limits: (f64, f64),
}

impl Default for StepInfoOptions {
    fn default() -> Self {
        Self {
            settling_threshold: 0.02,
            rise_limits: (0.1, 0.9),
        }
    }
}

impl StepInfoOptions {
    /// Checks that the thresholds make sense: 1e-9 ≤ band < 1 and 0 ≤ low < high ≤ 1.
    pub fn check(&self) -> Result<(), LtiError> {
        let (low, high) = self.rise_limits;
        if !(self.settling_threshold >= MIN_SETTLING_THRESHOLD && self.settling_threshold < 1.0) {
            return Err(LtiError::BadSettlingBand(self.settling_threshold));
        }
        if !((0.0..1.0).contains(&low) && low < high && high <= 1.0) {
            return Err(LtiError::BadRiseLimits { low, high });
        }
        Ok(())
    }

    /// [`StepInfoOptions::check`] with the refusal in English words.
    pub fn validate(&self) -> Result<(), String> {
        self.check().map_err(|e| e.to_string())
    }
}

/// The characteristics of one step response; times in seconds from the step, values in the
/// output's units, percentages in %. `None` means the metric does not exist (see module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StepInfo {
    pub rise_time: Option<f64>,
    pub settling_time: Option<f64>,
    pub overshoot: Option<f64>,
    pub undershoot: Option<f64>,
    pub peak: Option<f64>,
    pub peak_time: Option<f64>,
    pub steady_state: Option<f64>,
    pub settling_min: Option<f64>,
    pub settling_max: Option<f64>,
    /// When the response first reaches the low rise limit (start of the rise span).
    pub rise_start: Option<f64>,
    /// When the response first reaches the high rise limit (end of the rise span).
    pub rise_end: Option<f64>,
    /// When the undershoot is deepest.
    pub undershoot_time: Option<f64>,
    /// The output before the step.
    pub initial_value: f64,
    /// What the response does in the long run.
    pub behaviour: Behaviour,
}

/// A response made of monotone pieces between breakpoints.
pub trait MonotonePieces {
    /// Breakpoints (t, y), in time order; y is monotone between consecutive ones. Two
    /// breakpoints at the same instant describe a jump.
    fn breakpoints(&self) -> &[(f64, f64)];
    /// The instant in piece `i` (between breakpoints i and i+1) where y equals `level`;
    /// the caller guarantees that the level lies between the two breakpoint values.
    fn crossing(&self, i: usize, level: f64) -> f64;
}

impl StepInfo {
    /// Metrics of the exact step response of a system.
    pub fn of_response(response: &StepResponse, options: &StepInfoOptions) -> Self {
        Self::of_rational(response, options).delayed(response.delay())
    }

    /// The metrics with every instant in τ = t − θ, from the end of the dead time.
    pub(crate) fn of_rational(response: &StepResponse, options: &StepInfoOptions) -> Self {
        match response.behaviour() {
            Behaviour::Settles => {
                let y_final = response.final_value().unwrap_or(0.0);
                let pieces = LtiPieces::for_metrics(response, options);
                Self::from_pieces(&pieces, 0.0, y_final, options)
            }
            Behaviour::Oscillating => {
                let pieces = LtiPieces::new(response, Some(response.rational_horizon(0.0)));
                let mut info = Self::not_settling(0.0, Behaviour::Oscillating);
                if let Some((tau, y)) = largest_deviation(pieces.breakpoints(), 0.0) {
                    info.peak = Some(y.abs());
                    info.peak_time = Some(tau);
                }
                info
            }
            other => Self::not_settling(0.0, other),
        }
    }

    /// The same metrics for the response delayed by θ seconds: every instant moves by θ,
    /// the durations (rise time) stay. Metrics are found in τ = t − θ and only shifted
    /// here, so a dead time of 1e16 s leaves the rise time exact.
    pub fn delayed(mut self, delay: f64) -> Self {
        for t in [
            &mut self.rise_start,
            &mut self.rise_end,
            &mut self.settling_time,
            &mut self.peak_time,
            &mut self.undershoot_time,
        ] {
            *t = t.map(|t| t + delay);
        }
        self
    }

    /// Every metric absent: the response has no final value.
    pub fn not_settling(initial_value: f64, behaviour: Behaviour) -> Self {
        Self {
            rise_time: None,
            settling_time: None,
            overshoot: None,
            undershoot: None,
            peak: None,
            peak_time: None,
            steady_state: None,
            settling_min: None,
            settling_max: None,
            rise_start: None,
            rise_end: None,
            undershoot_time: None,
            initial_value,
            behaviour,
        }
    }

    /// Metrics of any response given as monotone pieces, from y_init towards y_final.
    pub fn from_pieces(
        pieces: &impl MonotonePieces,
        y_init: f64,
        y_final: f64,
        options: &StepInfoOptions,
    ) -> Self {
        let points = pieces.breakpoints();
        let mut info = Self::not_settling(y_init, Behaviour::Settles);
        info.steady_state = Some(y_final);
        let delta = y_final - y_init;
        if points.is_empty() {
            return info;
        }
        if delta == 0.0 {
            // No change to measure against: only the peak deviation is meaningful.
            if let Some((t, y)) = largest_deviation(points, y_init) {
                info.peak = Some(y.abs());
                info.peak_time = Some(t);
            }
            return info;
        }
        let sign = delta.signum();
        let span = delta.abs();
        // Normalised progress: 0 before the step, 1 at the final value.
        let e = |y: f64| sign * (y - y_init) / span;
        let level = |fraction: f64| y_init + fraction * delta;
        // The first piece that reaches `fraction`, and the instant it does.
        // A response already at the level when the step comes (a low limit of 0 %) reaches
        // it at the step instant.
        let first_crossing = |fraction: f64| -> Option<(usize, f64)> {
            if e(points[0].1) >= fraction {
                return Some((0, points[0].0));
            }
            points.windows(2).enumerate().find_map(|(i, w)| {
                let (a, b) = (e(w[0].1), e(w[1].1));
                (a < fraction && b >= fraction).then(|| (i, pieces.crossing(i, level(fraction))))
            })
        };

        let (lo, hi) = options.rise_limits;
        info.rise_start = first_crossing(lo).map(|(_, t)| t);
        let rise_end = first_crossing(hi);
        info.rise_end = rise_end.map(|(_, t)| t);
        if let (Some(a), Some(b)) = (info.rise_start, info.rise_end) {
            info.rise_time = Some(b - a);
        }

        let band = options.settling_threshold;
        info.settling_time = points
            .iter()
            .rposition(|&(_, y)| (e(y) - 1.0).abs() > band)
            .and_then(|i| {
                (i + 1 < points.len()).then(|| {
                    let above = e(points[i].1) > 1.0;
                    pieces.crossing(i, level(if above { 1.0 + band } else { 1.0 - band }))
                })
            });

        let (max_i, max_e) = extreme(points, e);
        let (min_i, min_e) = extreme(points, |y| -e(y));
        let min_e = -min_e;
        let overshoot = max_e - 1.0;
        info.overshoot = Some(if overshoot > NEGLIGIBLE {
            100.0 * overshoot
        } else {
            0.0
        });
        let undershoot = -min_e;
        info.undershoot = Some(if undershoot > NEGLIGIBLE {
            100.0 * undershoot
        } else {
            0.0
        });
        if undershoot > NEGLIGIBLE {
            info.undershoot_time = Some(points[min_i].0);
        }
        let (peak_i, peak_e) = if max_e >= undershoot {
            (max_i, max_e)
        } else {
            (min_i, undershoot)
        };
        if peak_e > 1.0 + NEGLIGIBLE {
            // From y itself, not peak_e·span: e overflows when |Δ| is tiny next to y.
            info.peak = Some((points[peak_i].1 - y_init).abs());
            info.peak_time = Some(points[peak_i].0);
        } else {
            info.peak = Some(span);
        }

        if let Some((piece, _)) = rise_end {
            // Every breakpoint after the piece where the rise ends: those after the crossing,
            // and y(θ⁺) when the rise ends inside the jump of a biproper system (the values
            // just after the jump count, the 0 before it does not).
            let after = points[piece + 1..].iter().map(|p| p.1);
            let candidates = after.chain([level(hi), y_final]);
            let (lo_y, hi_y) = candidates.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
                (a.min(y), b.max(y))
            });
            info.settling_min = Some(lo_y);
            info.settling_max = Some(hi_y);
        }
        info
    }
}

/// The breakpoint index and value where `score(y)` is largest.
fn extreme(points: &[(f64, f64)], score: impl Fn(f64) -> f64) -> (usize, f64) {
    points
        .iter()
        .enumerate()
        .map(|(i, p)| (i, score(p.1)))
        .fold((0, f64::NEG_INFINITY), |best, cur| {
            if cur.1 > best.1 { cur } else { best }
        })
}

/// The earliest breakpoint with the largest |y − y_init| (ties within rounding go to the
/// first, so a periodic response reports its first peak): (time, deviation).
fn largest_deviation(points: &[(f64, f64)], y_init: f64) -> Option<(f64, f64)> {
    let largest = points
        .iter()
        .map(|p| (p.1 - y_init).abs())
        .fold(0.0, f64::max);
    points
        .iter()
        .map(|&(t, y)| (t, y - y_init))
        .find(|d| d.1.abs() >= largest * (1.0 - 1e-12))
}

/// Monotone pieces of an exact LTI step response over [0, horizon], in τ = t − θ (time
/// from the end of the dead time): [`StepInfo::delayed`] turns metrics found on them into
/// times from the step.
pub struct LtiPieces<'a> {
    response: &'a StepResponse,
    /// Breakpoints (τ, y).
    points: Vec<(f64, f64)>,
    /// The grid of y' the critical points were bracketed on, (τ, y') ascending: where
    /// Newton starts for a level crossing ([`LtiPieces::first_guess`]).
    slopes: Vec<(f64, f64)>,
}

/// Samples per period of the fastest live oscillation when bracketing critical points.
const SAMPLES_PER_PERIOD: f64 = 12.0;
/// Minimum samples per grid segment.
const MIN_SEGMENT_SAMPLES: usize = 24;
/// Maximum samples per grid segment.
const MAX_SEGMENT_SAMPLES: usize = 20_000;
/// The grid covers the response until its transients are below this fraction of its size
/// (and below a tenth of a [`NEGLIGIBLE`] excursion from the final value, see
/// [`LtiPieces::new`]).
const TAIL_FRACTION: f64 = 1e-9;

impl<'a> LtiPieces<'a> {
    /// Breakpoints: the step instant (a jump for a biproper system), every zero of y' on
    /// [0, horizon] (horizon: until the transients are negligible when `None`), and the end.
    pub fn new(response: &'a StepResponse, horizon: Option<f64>) -> Self {
        Self::build(response, horizon, None)
    }

    /// The pieces [`StepInfo::of_response`] needs for a settling response: those of
    /// [`LtiPieces::new`], stopped early once the tail can no longer change a metric.
    ///
    /// After τ, |y − y∞| ≤ E(τ), the sum of the transients' envelopes. Once E is below the
    /// settling band, below 1 − the high rise limit and below the overshoot found so far
    /// (in units of |Δ|), no value in the tail can be a band exit, a first crossing, an
    /// extreme or a settling min/max, so its critical points need not be refined. For a
    /// lightly damped mode that rings on long after the response has settled, that skips
    /// most of them (order 8 of the benchmark: 200 Newton refinements down to 13).
    /// Everything up to that point is found and refined as before (the metrics agree with
    /// those of the full search to rounding); the last piece, in the tail, is then not
    /// monotone, but no level the metrics look for is crossed inside it.
    pub fn for_metrics(response: &'a StepResponse, options: &StepInfoOptions) -> Self {
        let pruning = response
            .final_value()
            .filter(|&y| y != 0.0)
            .map(|y_final| Pruning {
                y_final,
                fixed_margin: options.settling_threshold.min(1.0 - options.rise_limits.1),
            });
        Self::build(response, None, pruning)
    }

    fn build(response: &'a StepResponse, horizon: Option<f64>, pruning: Option<Pruning>) -> Self {
        let scale = response.magnitude_scale().max(f64::MIN_POSITIVE);
        // Beyond the end nothing may count any more: no overshoot above NEGLIGIBLE·|Δ|, no
        // exit from the settling band. When zeros make the final value small next to the
        // transient terms (|Δ| ≪ scale), 1e-9·scale alone is not enough: the response of
        // 0.0185(s² + 4.9s + 84.9)(s² + 9.4s + 85)(s + 16.2)/(7 poles) rose by 1e-8·|Δ|
        // above its final value after the grid had stopped, and the overshoot read 0.
        let tail = match response.final_value() {
            Some(y_final) if y_final != 0.0 => {
                (TAIL_FRACTION * scale).min(0.1 * NEGLIGIBLE * y_final.abs())
            }
            _ => TAIL_FRACTION * scale,
        }
        .max(f64::MIN_POSITIVE);
        let end = horizon.unwrap_or_else(|| response.envelope_time(tail, |_| true));
        let end = if end.is_finite() && end > 0.0 {
            end
        } else {
            response.fastest_rate().map_or(1.0, |r| 10.0 / r)
        };
        let y0 = response.eval_rational(Derivative::Value, 0.0);
        let mut points = vec![(0.0, 0.0), (0.0, y0)];
        let critical = critical_points(response, end, tail, pruning, y0);
        points.extend(critical.found);
        let end = critical.end;
        points.push((end, response.eval_rational(Derivative::Value, end)));
        Self {
            response,
            points,
            slopes: critical.slopes,
        }
    }

    /// Where y first reaches `level` between the breakpoints `a` and `b`, estimated from
    /// y(a) and the trapezoid rule on the grid of y' (the last stretch by the chord to
    /// y(b)): where Newton starts, the bracket [a, b] keeping it safe. Over a long first
    /// piece (a monotone rise spans the whole transient) it saves the bisections a start
    /// at the midpoint needs; the midpoint when the estimate does not reach the level.
    fn first_guess(&self, a: (f64, f64), b: (f64, f64), level: f64) -> f64 {
        let from = self.slopes.partition_point(|s| s.0 <= a.0);
        // y' at a: its grid sample at τ = 0, else 0 (a critical point).
        let slope_a = match from.checked_sub(1).map(|k| self.slopes[k]) {
            Some((t, s)) if t == a.0 => s,
            _ => 0.0,
        };
        let (mut t, mut y, mut slope) = (a.0, a.1, slope_a);
        let below = a.1 < level;
        for &(tk, sk) in self.slopes[from..].iter().take_while(|s| s.0 < b.0) {
            let yk = y + 0.5 * (tk - t) * (slope + sk);
            if (yk >= level) == below {
                return t + (tk - t) * (level - y) / (yk - y);
            }
            (t, y, slope) = (tk, yk, sk);
        }
        if (b.1 >= level) == below && b.1 != y {
            t + (b.0 - t) * (level - y) / (b.1 - y)
        } else {
            0.5 * (a.0 + b.0)
        }
    }
}

/// What the search for critical points leaves.
struct Critical {
    /// The critical points (τ, y), ascending.
    found: Vec<(f64, f64)>,
    /// The end actually used (earlier than asked once the tail cannot change a metric).
    end: f64,
    /// The grid of y' searched, (τ, y') ascending.
    slopes: Vec<(f64, f64)>,
}

/// What the metrics can still see in the tail of a settling response.
#[derive(Debug, Clone, Copy)]
struct Pruning {
    y_final: f64,
    /// min(settling band, 1 − high rise limit), in units of |Δ|.
    fixed_margin: f64,
}

impl Pruning {
    /// The time after which no metric can change, given the largest e = y/y∞ seen so far.
    fn cut(&self, response: &StepResponse, max_e: f64, tail: f64) -> f64 {
        let overshoot = (max_e - 1.0).max(0.0);
        // Half the margin: the end point itself must be strictly inside, not on the edge.
        let margin = 0.5 * self.fixed_margin.min(overshoot) * self.y_final.abs();
        response.envelope_time(margin.max(tail), |_| true)
    }
}

impl MonotonePieces for LtiPieces<'_> {
    fn breakpoints(&self) -> &[(f64, f64)] {
        &self.points
    }

    fn crossing(&self, i: usize, level: f64) -> f64 {
        let (a, b) = (self.points[i], self.points[i + 1]);
        if a.0 == b.0 {
            return a.0; // inside the jump at the step
        }
        let f = |tau: f64| {
            let [y, slope] = self
                .response
                .eval_rational_set([Derivative::Value, Derivative::First], tau);
            (y - level, slope)
        };
        let start = self.first_guess(a, b, level);
        safe_newton(f, (a.0, a.1 - level), (b.0, b.1 - level), start)
    }
}

/// Zeros of y' on (0, end) and y there, from sign changes on segmented uniform grids,
/// refined (Newton from the chord's zero in the cell); with `pruning`, only until the tail
/// cannot change a metric any more (the end actually used is returned too, and the grid).
fn critical_points(
    response: &StepResponse,
    end: f64,
    tail: f64,
    pruning: Option<Pruning>,
    y0: f64,
) -> Critical {
    // The first segment spans 10/rate or less; rate includes the zeros (see initial_rate):
    // 0.14(s² − 30s + 319)(s + 1.3)·…/(two near-double pairs at −1.13 ± 1.1j) rises, dips
    // below zero and turns back within 0.15 s, all inside one cell of a grid sized for
    // the poles alone, and its undershoot read 0.
    let fastest = response
        .fastest_rate()
        .unwrap_or(1.0 / end)
        .max(response.initial_rate());
    let decades = ((end * fastest).log10().ceil() as i64 - 1).clamp(0, 12) as i32;
    let mut bounds = vec![0.0];
    bounds.extend((0..=decades).rev().map(|k| end * 10f64.powi(-k)));
    let mut found = Vec::new();
    let mut slope = Vec::new();
    let mut slopes = Vec::new();
    let mut max_e = pruning.map_or(0.0, |p| y0 / p.y_final);
    let mut end = end;
    if let Some(p) = pruning {
        end = end.min(p.cut(response, max_e, tail));
    }
    'segments: for w in bounds.windows(2) {
        let a = w[0];
        if a >= end {
            break;
        }
        let b = w[1].min(end);
        let live_frequency = response.max_frequency(|c| c.envelope(a) > tail);
        let periods = (b - a) * live_frequency / std::f64::consts::TAU;
        let n = ((periods * SAMPLES_PER_PERIOD).ceil() as usize)
            .clamp(MIN_SEGMENT_SAMPLES, MAX_SEGMENT_SAMPLES);
        let h = (b - a) / n as f64;
        slope.resize(n + 1, 0.0);
        response.eval_uniform_rational(Derivative::First, a, h, &mut slope);
        slopes.extend((0..=n).map(|i| (a + h * i as f64, slope[i])));
        if a == 0.0 && response.initial_slope_sign() != 0.0 {
            // y'(0) = 0 exactly here, computed as noise of either sign: with the wrong one, a
            // critical point in the first cell went unseen (the 0.0016 % undershoot of
            // 0.19·1.91(s − 20)/((s² + 3s + 2.9)(s + 0.075)) read 0). Use the true sign of
            // y' just after the step instead.
            slope[0] = response.initial_slope_sign();
        }
        for i in turning_cells(&slope) {
            let (ta, tb) = (a + h * i as f64, a + h * (i + 1) as f64);
            if ta >= end {
                break 'segments;
            }
            let (fa, fb) = (slope[i], slope[i + 1]);
            let (tau, y) = if fa * fb < 0.0 {
                refine_critical(response, (ta, fa), (tb, fb))
            } else {
                (tb, response.eval_rational(Derivative::Value, tb))
            };
            if let Some(p) = pruning {
                // The cut only moves earlier as the overshoot found grows.
                if y / p.y_final > max_e {
                    max_e = y / p.y_final;
                    end = end.min(p.cut(response, max_e, tail));
                }
            }
            found.push((tau, y));
        }
    }
    found.retain(|&(tau, _)| tau < end);
    Critical { found, end, slopes }
}

/// The cells i (from sample i to i + 1) of a grid of y' where it changes sign, or reaches
/// 0 exactly at the cell's end (not at the grid's last sample), in order.
fn turning_cells(slope: &[f64]) -> impl Iterator<Item = usize> + '_ {
    let n = slope.len() - 1;
    (0..n).filter(move |&i| {
        let (fa, fb) = (slope[i], slope[i + 1]);
        fa * fb < 0.0 || (fb == 0.0 && i + 1 < n && fa != 0.0)
    })
}

/// The zero of y' in the cell [a, b] of the grid (`a` = (a, y'(a)), `b` likewise, of
/// opposite signs) and y there: Newton from the chord's zero, y evaluated with y' and y''
/// at each step. Newton's last step δ is tiny (|δ| ≤ 1e-6·τ, where y'(τ) = 0), so y at the
/// zero is y + δ·(y' + δ·y''/2) from the point it stepped from, to O(δ³·y''') (far below
/// rounding): y costs no evaluation of its own.
fn refine_critical(response: &StepResponse, a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    use Derivative::{First, Second, Value};
    let last = std::cell::Cell::new((f64::NAN, [0.0; 3]));
    let f = |tau: f64| {
        let values = response.eval_rational_set([Value, First, Second], tau);
        last.set((tau, values));
        (values[1], values[2])
    };
    let tau = safe_newton(f, a, b, a.0 + (b.0 - a.0) * a.1 / (a.1 - b.1));
    let (at, [y, slope, curvature]) = last.get();
    let step = tau - at;
    if step.abs() <= 1e-6 * tau.abs() {
        (tau, y + step * (slope + 0.5 * curvature * step))
    } else {
        (tau, response.eval_rational(Value, tau))
    }
}

/// Whether two Newton steps in a row (`previous`, then `last`) show quadratic convergence
/// that leaves the next step below `rounding`: |dₖ₊₁| ≈ |dₖ|³/|dₖ₋₁|² (dₖ = K·dₖ₋₁²), so
/// the point `last` stepped to is the root to rounding and needs no evaluation to confirm
/// it. A double root converges only linearly (dₖ ≈ dₖ₋₁/2) and never passes.
fn converged(previous: Option<f64>, last: Option<f64>, rounding: f64) -> bool {
    match (previous, last) {
        (Some(p), Some(d)) => d.abs() <= 0.1 * p.abs() && (d / p).powi(2) * d.abs() <= rounding,
        _ => false,
    }
}

/// A root of f in [a, b] where f(a), f(b) bracket it (`a` = (a, f(a)), `b` likewise):
/// Newton steps from `start` (the midpoint when `start` is not inside) kept inside the
/// bracket, bisection otherwise (Numerical Recipes' rtsafe), to full double precision.
pub fn safe_newton(
    f: impl Fn(f64) -> (f64, f64),
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    start: f64,
) -> f64 {
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    let (mut lo, mut hi) = if fa < 0.0 { (a, b) } else { (b, a) };
    let inside = start > a.min(b) && start < a.max(b);
    let mut x = if inside { start } else { 0.5 * (a + b) };
    let mut dx_old = (b - a).abs();
    let mut dx = dx_old;
    // The previous step when it was Newton's.
    let mut newton = None;
    let (mut fx, mut dfx) = f(x);
    for _ in 0..200 {
        let newton_leaves = ((x - hi) * dfx - fx) * ((x - lo) * dfx - fx) > 0.0;
        let slow = (2.0 * fx).abs() > (dx_old * dfx).abs();
        dx_old = dx;
        let previous = newton.take();
        if newton_leaves || slow {
            dx = 0.5 * (hi - lo);
            x = lo + dx;
        } else {
            dx = fx / dfx;
            x -= dx;
            newton = Some(dx);
        }
        let rounding = f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        if dx.abs() <= 2.0 * rounding || converged(previous, newton, rounding) {
            return x;
        }
        (fx, dfx) = f(x);
        if fx == 0.0 {
            return x;
        }
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{C64, TransferFunction};

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    fn info(zeros: &[C64], poles: &[C64], k: f64) -> StepInfo {
        let g = TransferFunction::from_zpk(zeros, poles, k).unwrap();
        StepInfo::of_response(&StepResponse::new(&g, 1.0).unwrap(), &Default::default())
    }

    #[test]
    fn first_order_rise_and_settling_are_exact() {
        let i = info(&[], &[c(-5.0, 0.0)], 5.0);
        assert!((i.rise_time.unwrap() - 9f64.ln() / 5.0).abs() < 1e-14);
        assert!((i.settling_time.unwrap() - 50f64.ln() / 5.0).abs() < 1e-14);
        assert_eq!(i.overshoot, Some(0.0));
        assert_eq!(i.undershoot, Some(0.0));
        assert_eq!(i.peak, Some(1.0));
        assert_eq!(i.peak_time, None);
        assert_eq!(i.steady_state, Some(1.0));
        assert!((i.settling_min.unwrap() - 0.9).abs() < 1e-15);
        assert_eq!(i.settling_max, Some(1.0));
    }

    #[test]
    fn second_order_overshoot_and_peak_time_identities() {
        for zeta in [0.05f64, 0.2, 0.5, 0.7, 0.9] {
            let wn: f64 = 3.0;
            let wd = wn * (1.0 - zeta * zeta).sqrt();
            let p = [c(-zeta * wn, wd), c(-zeta * wn, -wd)];
            let i = info(&[], &p, wn * wn);
            let os = 100.0 * (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp();
            assert!(
                (i.overshoot.unwrap() - os).abs() < 1e-10 * os,
                "zeta {zeta}"
            );
            let tp = std::f64::consts::PI / wd;
            assert!(
                (i.peak_time.unwrap() - tp).abs() < 1e-12 * tp,
                "zeta {zeta}"
            );
            assert!((i.peak.unwrap() - (1.0 + os / 100.0)).abs() < 1e-12);
        }
    }

    #[test]
    fn real_poles_can_overshoot_with_a_zero() {
        let i = info(&[c(-7.0, 0.0)], &[c(-10.0, 0.0), c(-20.0, 0.0)], 10.0);
        assert!(i.overshoot.unwrap() > 1.0, "{:?}", i.overshoot);
        assert!(i.peak_time.is_some());
    }

    #[test]
    fn integrating_and_unstable_have_no_metrics() {
        let i = info(&[], &[c(0.0, 0.0), c(-1.0, 0.0)], 1.0);
        assert_eq!(i.behaviour, Behaviour::Integrating);
        assert_eq!(
            (i.rise_time, i.settling_time, i.steady_state),
            (None, None, None)
        );
        let u = info(&[], &[c(1.0, 0.0)], 1.0);
        assert_eq!(u.behaviour, Behaviour::Unstable);
        assert_eq!(u.peak, None);
    }

    #[test]
    fn undamped_oscillation_reports_its_peak() {
        // 1/(s²+1): y = 1 − cos t, peak 2 at π.
        let i = info(&[], &[c(0.0, 1.0), c(0.0, -1.0)], 1.0);
        assert_eq!(i.behaviour, Behaviour::Oscillating);
        assert!((i.peak.unwrap() - 2.0).abs() < 1e-12);
        assert!((i.peak_time.unwrap() - std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn inverse_response_has_undershoot() {
        // (1 − s)/(s+1)²: dips below zero first.
        let i = info(&[c(1.0, 0.0)], &[c(-1.0, 0.0), c(-1.0, 0.0)], -1.0);
        assert!(i.undershoot.unwrap() > 0.0);
        // y = 1 − e^{−t} − 2t e^{−t}; y' = e^{−t}(2t − 1)... min at t = 1/2... check value.
        let t_min = i.undershoot_time.unwrap();
        assert!((t_min - 0.5).abs() < 1e-12, "{t_min}");
        let y_min = 1.0 - (-0.5f64).exp() * 2.0;
        assert!((i.undershoot.unwrap() - (-100.0 * y_min)).abs() < 1e-10);
    }

    #[test]
    fn thresholds_can_be_changed() {
        let g = TransferFunction::from_zpk(&[], &[c(-1.0, 0.0)], 1.0).unwrap();
        let r = StepResponse::new(&g, 1.0).unwrap();
        let o = StepInfoOptions {
            settling_threshold: 0.05,
            rise_limits: (0.05, 0.95),
        };
        let i = StepInfo::of_response(&r, &o);
        assert!((i.settling_time.unwrap() - 20f64.ln()).abs() < 1e-14);
        assert!((i.rise_time.unwrap() - (0.95f64 / 0.05).ln()).abs() < 1e-14);
        assert!(
            StepInfoOptions {
                settling_threshold: 0.0,
                ..o
            }
            .validate()
            .is_err()
        );
        assert!(
            StepInfoOptions {
                rise_limits: (0.9, 0.1),
                ..o
            }
            .validate()
            .is_err()
        );
    }

    #[test]
    fn biproper_jump_counts_as_rising_at_the_step() {
        // (s+2)/(s+1) jumps to 1 then rises to 2: 10 % (0.2) is crossed inside the jump.
        let i = info(&[c(-2.0, 0.0)], &[c(-1.0, 0.0)], 1.0);
        assert_eq!(i.rise_start, Some(0.0));
        // 90 %: 2 − e^{−t} = 1.8 ⇒ t = ln 5.
        assert!((i.rise_end.unwrap() - 5f64.ln()).abs() < 1e-14);
    }
}
