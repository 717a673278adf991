//! The exact step response y(t) of A·G(s)/s, evaluated from its closed form.
//!
//! Y(s) = A·k·Π(s − zᵢ) / (s·Π(s − pⱼ)) is split into partial fractions over *clusters* of
//! poles (the step's own pole at the origin included). The contribution of a cluster with
//! nodes x₁…x_m (its poles, distinct, repeated or both) is the divided difference
//! (R(s)·e^{sτ})[x₁…x_m], R = everything else in Y(s); by Leibniz's rule it is
//! Σ_k R[x₁…x_k]·e^{sτ}[x_k…x_m]. Both factors are computed stably through the Opitz
//! matrix of the nodes (see [`super::divided`]): no residue 1/δ^{m−1} of two poles δ apart
//! is ever formed, so nearly equal poles cost no accuracy. For a single pole this is the
//! residue formula; for an exactly repeated pole of multiplicity m at c it is the classical
//! e^{cτ}·Σ_{j<m} q_j·τ^j with q_j = R[c…c]_{m−j}/j!, kept in that polynomial form.
//!
//! Which poles form a cluster: those within [`MERGE_RELATIVE`] of each other (single
//! linkage, relative to their modulus), then, while the partial fractions of some cluster
//! would still amplify rounding by more than [`AMPLIFICATION_LIMIT`] (many poles a few
//! percent apart), the closest clusters are merged too, up to [`MAX_MERGE_GAP`]. The poles'
//! moduli and distances are computed once for all the tolerances tried.
//!
//! No ODE is integrated: every sample is the closed form at that instant. Uniform grids use
//! the recurrence e^{c(t+h)} = e^{ct}·e^{ch} (and exp((τ+h)N) = exp(τN)·exp(hN) for a
//! cluster), re-anchored every [`REANCHOR`] steps.
//!
//! What is exact costs only where it is needed: a cluster of distinct poles (the Opitz
//! matrix, its exponential scaled and squared) is evaluated as such, every other pole by
//! its residue; a real pole in real arithmetic (the same products: its imaginary parts are
//! all zero); and the distance of the closed-form text's repeated-pole form from the exact
//! y ([`StepResponse::repeated_form_error`]) is walked on its grid by the same recurrences,
//! once per response.

use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use super::divided;
use super::poly::C64;
use super::tf::TransferFunction;
use super::{LtiError, Quantity};

mod fractions;
mod walk;

use fractions::*;
use walk::*;

/// Poles this close (relative to the larger modulus) always form one cluster.
pub const MERGE_RELATIVE: f64 = 1e-2;
/// Clusters further apart than this (relative) are never merged: their partial fractions
/// are well conditioned, and a wider cluster only costs squarings.
pub const MAX_MERGE_GAP: f64 = 0.5;
/// The largest Π|p|/|c − p| (over the poles p outside a cluster with centre c) accepted
/// before clusters are merged further: how much larger than the final value a cluster's
/// terms may be, so how much rounding the sum of the partial fractions may amplify.
pub const AMPLIFICATION_LIMIT: f64 = 1e4;
/// Poles on the imaginary axis this close are one repeated pair (classification only: the
/// roots of (s² + 1)² come out as j(1 ± 1e-9)).
pub const REPEATED_AXIS_RELATIVE: f64 = 1e-6;
/// Steps of the exponential recurrence between exact re-evaluations.
const REANCHOR: usize = 64;
/// Intervals of the grid on which [`StepResponse::repeated_form_error`] compares the forms.
const FORM_GRID: usize = 4000;

/// What a step response does as t → ∞ (its words: `crate::words::step`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Behaviour {
    /// Converges to a finite final value A·G(0).
    Settles,
    /// Ramps (or grows as a polynomial) without bound: a pole at the origin.
    Integrating,
    /// Oscillates forever with bounded amplitude: simple poles on the imaginary axis.
    Oscillating,
    /// Grows exponentially: a pole in the right half plane (or a repeated one on the axis).
    Unstable,
}

/// One group of equal or nearly equal poles and its contribution to y.
#[derive(Debug, Clone)]
pub struct Cluster {
    /// Centre of the cluster (mean of its poles), rad/s. Only Im ≥ 0 is kept.
    pub center: C64,
    /// How many poles of Y(s) the cluster holds (the step's pole counts).
    pub multiplicity: usize,
    /// 1 for a real cluster, 2 for a complex one standing for itself and its mirror.
    pub weight: f64,
    /// q_j of e^{cτ}·Σ q_j τ^j, lowest power of τ first: the exact contribution for an
    /// exactly repeated pole; for a cluster of distinct poles, that of the repeated pole
    /// at its centre it approaches (q_j = a_{m−1−j}/j!, a_n the Taylor coefficients of R
    /// at c), an approximation (see [`Cluster::approximation`]).
    pub coeffs: Vec<C64>,
    /// b_j with |contribution(τ)| ≤ weight·e^{στ}·Σ b_j τ^j, σ = [`Cluster::decay_rate`]:
    /// |q_j| for a repeated pole, |R[x₁…x_{m−j}]|/j! for a spread cluster.
    bound: Vec<f64>,
    /// Coefficients of the first derivative's polynomial factor: c·P + P'.
    d1: Vec<C64>,
    /// Coefficients of the second derivative's polynomial factor.
    d2: Vec<C64>,
    /// The largest |Im| of its poles (rad/s).
    frequency: f64,
    /// The exact form of a cluster of distinct poles.
    spread: Option<Spread>,
}

/// A cluster whose poles are not all equal: its divided-difference form.
#[derive(Debug, Clone)]
struct Spread {
    /// The poles (both halves for a self-conjugate cluster), rad/s.
    nodes: Vec<C64>,
    /// x_i − c.
    offsets: Vec<C64>,
    /// max |x_i − c| (rad/s).
    radius: f64,
    /// max Re(x_i − c) (rad/s): |e^{sτ}[x_k…x_m]| ≤ e^{(Re c + growth)τ}·τ^{m−k}/(m−k)!.
    growth: f64,
    /// R[x₁…x_k], (R·s)[x₁…x_k], (R·s²)[x₁…x_k] for y, y', y''.
    differences: [Vec<C64>; 3],
}

/// Which derivative of y to evaluate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Derivative {
    Value,
    First,
    Second,
}

impl Derivative {
    fn index(self) -> usize {
        match self {
            Derivative::Value => 0,
            Derivative::First => 1,
            Derivative::Second => 2,
        }
    }
}

/// What a cluster's y, y' and y'' at one τ are built from.
struct Basis {
    /// e^{cτ}.
    exp_ct: C64,
    /// e^{(s − c)τ}[x_k…x_m], k = 1…m, for a spread cluster (empty otherwise).
    row: Vec<C64>,
}

impl Cluster {
    fn poly(&self, which: Derivative) -> &[C64] {
        match which {
            Derivative::Value => &self.coeffs,
            Derivative::First => &self.d1,
            Derivative::Second => &self.d2,
        }
    }

    /// The poles of the cluster (for a complex one, those above the axis), rad/s.
    pub fn poles(&self) -> Vec<C64> {
        match &self.spread {
            Some(s) => s.nodes.clone(),
            None => vec![self.center; self.multiplicity],
        }
    }

    /// True when the poles are exactly equal, so [`Cluster::coeffs`] is the exact form.
    pub fn is_repeated(&self) -> bool {
        self.spread.is_none()
    }

    /// The largest distance of a pole from the centre (rad/s); 0 for a repeated pole.
    pub fn radius(&self) -> f64 {
        self.spread.as_ref().map_or(0.0, |s| s.radius)
    }

    /// The exponential rate that bounds the cluster's decay (1/s): the largest real part
    /// among its poles.
    pub fn decay_rate(&self) -> f64 {
        self.center.re + self.spread.as_ref().map_or(0.0, |s| s.growth)
    }

    /// The largest oscillation frequency among its poles (rad/s).
    pub fn frequency(&self) -> f64 {
        self.frequency
    }

    fn basis(&self, tau: f64) -> Basis {
        let exp_ct = exp(self.center * tau);
        let row = match &self.spread {
            Some(s) if exp_ct != C64::new(0.0, 0.0) => {
                divided::exp_last_row(&s.offsets, s.radius, tau)
            }
            _ => Vec::new(),
        };
        Basis { exp_ct, row }
    }

    /// weight·Re(contribution) at τ from its basis there.
    fn contribution(&self, which: Derivative, basis: &Basis, tau: f64) -> f64 {
        let value = match &self.spread {
            // A real pole: the imaginary parts would only multiply e^{cτ}'s zero one.
            None if self.center.im == 0.0 => {
                return self.weight * (basis.exp_ct.re * horner_re(self.poly(which), tau));
            }
            None => horner(self.poly(which), tau),
            Some(_) if basis.row.is_empty() => return 0.0,
            Some(s) => dot(&s.differences[which.index()], &basis.row),
        };
        self.weight * (basis.exp_ct * value).re
    }

    /// An upper bound of |contribution| at τ ≥ 0.
    pub fn envelope(&self, tau: f64) -> f64 {
        let poly: f64 = self.bound.iter().rev().fold(0.0, |acc, b| acc * tau + b);
        self.weight * poly * (self.decay_rate() * tau).exp()
    }

    fn is_step_constant(&self) -> bool {
        self.center == C64::new(0.0, 0.0) && self.multiplicity == 1
    }
}

fn dot(a: &[C64], b: &[C64]) -> C64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn horner(coeffs: &[C64], tau: f64) -> C64 {
    coeffs
        .iter()
        .rev()
        .fold(C64::new(0.0, 0.0), |acc, &q| acc * tau + q)
}

/// Re [`horner`]: the real parts alone (τ is real, so they never meet the imaginary ones).
fn horner_re(coeffs: &[C64], tau: f64) -> f64 {
    coeffs.iter().rev().fold(0.0, |acc, q| acc * tau + q.re)
}

/// The closed-form step response of a transfer function to a step of amplitude A at t = 0.
#[derive(Debug, Clone)]
pub struct StepResponse {
    amplitude: f64,
    delay: f64,
    clusters: Vec<Cluster>,
    behaviour: Behaviour,
    final_value: Option<f64>,
    /// The sign of y' just after the step when y'(θ⁺) = 0 exactly (relative degree r ≥ 2:
    /// y ≈ A·k·τ^r/r!, so y' has the sign of A·k), where the computed y'(θ⁺) is rounding
    /// noise of either sign; 0 when y'(θ⁺) itself is meaningful.
    initial_slope_sign: f64,
    /// Σ|pⱼ| + Σ|zᵢ| (rad/s): bounds the growth rate of y's derivatives at the step, so
    /// 1/it is the shortest time scale on which y can turn right after the step (fast zeros
    /// make early wiggles even when every pole is slow).
    initial_rate: f64,
    /// [`StepResponse::repeated_form_error`], once measured.
    form_error: OnceLock<f64>,
}

impl StepResponse {
    /// The response of `tf` to a step of amplitude `amplitude` applied at t = 0.
    pub fn new(tf: &TransferFunction, amplitude: f64) -> Result<Self, LtiError> {
        if !amplitude.is_finite() || amplitude == 0.0 {
            return Err(LtiError::BadAmplitude(amplitude));
        }
        let mut poles: Vec<C64> = tf.poles().to_vec();
        poles.push(C64::new(0.0, 0.0));
        let clusters = partial_fractions(&poles, tf.zeros(), amplitude * tf.gain());
        if amplitude.is_subnormal() {
            return Err(LtiError::Subnormal {
                what: Quantity::StepAmplitude,
                value: amplitude,
            });
        }
        let behaviour = classify(tf);
        let final_value = (behaviour == Behaviour::Settles).then(|| amplitude * tf.dc_gain());
        check_representable(final_value, tf, amplitude)?;
        if let Some(expected) = final_value {
            check_final_value(&clusters, expected)?;
        }
        let initial_slope_sign = if tf.relative_degree() >= 2 {
            (amplitude * tf.gain()).signum()
        } else {
            0.0
        };
        let initial_rate = tf.poles().iter().chain(tf.zeros()).map(|r| r.norm()).sum();
        Ok(Self {
            amplitude,
            delay: tf.delay(),
            clusters,
            behaviour,
            final_value,
            initial_slope_sign,
            initial_rate,
            form_error: OnceLock::new(),
        })
    }

    /// Step amplitude A.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Transport delay θ in seconds: y(t) = 0 for t < θ.
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// What the response does as t → ∞.
    pub fn behaviour(&self) -> Behaviour {
        self.behaviour
    }

    /// The final value A·G(0) when the response settles.
    pub fn final_value(&self) -> Option<f64> {
        self.final_value
    }

    /// The partial-fraction clusters (for the closed-form text).
    pub fn clusters(&self) -> &[Cluster] {
        &self.clusters
    }

    /// y(t); the right limit at t = θ (y(θ⁺) = A·D for a biproper system), 0 before.
    pub fn value(&self, t: f64) -> f64 {
        self.eval(Derivative::Value, t)
    }

    /// y'(t) for t > θ (the impulse response times A), 0 before.
    pub fn derivative(&self, t: f64) -> f64 {
        self.eval(Derivative::First, t)
    }

    /// Any derivative of y at time t (seconds from the step).
    pub fn eval(&self, which: Derivative, t: f64) -> f64 {
        let tau = t - self.delay;
        if tau < 0.0 {
            return 0.0;
        }
        self.eval_rational(which, tau)
    }

    /// The sign of y' just after the step when the computed y'(θ⁺) is only rounding noise
    /// (relative degree ≥ 2, where y'(θ⁺) = 0 exactly); 0 otherwise.
    pub(crate) fn initial_slope_sign(&self) -> f64 {
        self.initial_slope_sign
    }

    /// Σ|pⱼ| + Σ|zᵢ| (rad/s): 1/it is the shortest time scale of y just after the step.
    pub(crate) fn initial_rate(&self) -> f64 {
        self.initial_rate
    }

    /// The rational part (no delay) at τ ≥ 0.
    pub(crate) fn eval_rational(&self, which: Derivative, tau: f64) -> f64 {
        self.clusters
            .iter()
            .map(|c| c.contribution(which, &c.basis(tau), tau))
            .sum()
    }

    /// Several derivatives of the rational part at τ ≥ 0, sharing the exponentials (what a
    /// Newton step needs, and the value where it lands).
    pub(crate) fn eval_rational_set<const K: usize>(
        &self,
        which: [Derivative; K],
        tau: f64,
    ) -> [f64; K] {
        self.clusters.iter().fold([0.0; K], |mut sums, c| {
            let basis = c.basis(tau);
            for (sum, &w) in sums.iter_mut().zip(&which) {
                *sum += c.contribution(w, &basis, tau);
            }
            sums
        })
    }

    /// Σₖ aₖ·y(t − sₖ)/A at each instant of `times` into `out` (both cut to the shorter):
    /// the exact response to a sum of steps of sizes aₖ at instants sₖ (`steps`, sorted by
    /// instant), each delayed by this response's dead time. `times` must be ascending.
    ///
    /// One pass over the instants with a running state per cluster, so the cost is
    /// O(len(times) + len(steps)) whatever the number of steps (a PRBS of thousands of
    /// changes costs as much as one step): each cluster's contribution is
    /// weight·Re(e^{cτ}·d·b(τ)) with a basis b that advances linearly, b(τ + h) = M(h)·b(τ)
    /// (the powers τʲ of a repeated pole by the binomial rule, the last row of exp(τN) of a
    /// spread cluster by a product with exp(hN)), so the sum over the steps advances as one
    /// vector. No ODE is integrated and nothing is discretised: each term is the closed
    /// form, only summed in another order.
    pub fn superpose(&self, steps: &[(f64, f64)], times: &[f64], out: &mut [f64]) {
        let n = times.len().min(out.len());
        let (times, out) = (&times[..n], &mut out[..n]);
        out.iter_mut().for_each(|v| *v = 0.0);
        if n == 0 || steps.is_empty() {
            return;
        }
        let scale = 1.0 / self.amplitude;
        for c in &self.clusters {
            if c.spread.is_none() && c.coeffs.len() == 1 {
                superpose_simple(c, self.delay, scale, steps, times, out);
                continue;
            }
            let mut state = Superposition::new(c, self.delay, scale);
            for (o, &t) in out.iter_mut().zip(times) {
                state.advance_to(t, steps);
                *o += state.value();
            }
        }
    }

    /// y at arbitrary instants (seconds from the step).
    pub fn sample(&self, times: &[f64]) -> Vec<f64> {
        times.iter().map(|&t| self.value(t)).collect()
    }

    /// y at `n` evenly spaced instants from `t_start` to `t_end` inclusive: (times, values).
    pub fn sample_uniform(&self, t_start: f64, t_end: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
        let dt = if n > 1 {
            (t_end - t_start) / (n - 1) as f64
        } else {
            0.0
        };
        let times: Vec<f64> = (0..n).map(|i| t_start + dt * i as f64).collect();
        let mut values = vec![0.0; n];
        let first = times.iter().position(|&t| t >= self.delay).unwrap_or(n);
        if first < n {
            self.eval_uniform_rational(
                Derivative::Value,
                times[first] - self.delay,
                dt,
                &mut values[first..],
            );
        }
        (times, values)
    }

    /// Fills `out[i]` with the rational part's derivative at τ₀ + i·h (τ₀ ≥ 0).
    pub(crate) fn eval_uniform_rational(
        &self,
        which: Derivative,
        tau0: f64,
        h: f64,
        out: &mut [f64],
    ) {
        out.iter_mut().for_each(|v| *v = 0.0);
        for c in &self.clusters {
            match &c.spread {
                // The step's constant has no derivative: nothing to add.
                None if c.poly(which).iter().all(|q| *q == C64::new(0.0, 0.0)) => {}
                None => uniform_repeated(c, c.poly(which), tau0, h, out),
                Some(s) => uniform_spread(c, s, &s.differences[which.index()], tau0, h, out),
            }
        }
    }

    /// The earliest τ (from the delay) after which every transient cluster's envelope stays
    /// below `eps`; clusters for which `keep` is false are ignored. Infinite when a kept
    /// cluster does not decay.
    pub(crate) fn envelope_time(&self, eps: f64, keep: impl Fn(&Cluster) -> bool) -> f64 {
        let kept: Vec<&Cluster> = self
            .clusters
            .iter()
            .filter(|c| !c.is_step_constant() && keep(c))
            .collect();
        let terms: usize = kept.iter().map(|c| c.bound.len()).sum();
        let share = eps / terms.max(1) as f64;
        kept.iter()
            .flat_map(|c| {
                c.bound
                    .iter()
                    .enumerate()
                    .map(move |(j, &b)| term_decay_time(c.weight * b, j, c.decay_rate(), share))
            })
            .fold(0.0, f64::max)
    }

    /// A scale of the response's magnitude: |final value| plus the sizes of the transients.
    pub fn magnitude_scale(&self) -> f64 {
        self.clusters
            .iter()
            .map(|c| c.weight * c.bound.iter().sum::<f64>())
            .sum()
    }

    /// The fastest pole modulus of Y(s) other than the origin (rad/s), if any.
    pub(crate) fn fastest_rate(&self) -> Option<f64> {
        self.clusters
            .iter()
            .map(|c| c.center.norm() + c.radius())
            .filter(|&r| r > 0.0)
            .reduce(f64::max)
    }

    /// The largest oscillation frequency (rad/s) among clusters with `keep` true.
    pub(crate) fn max_frequency(&self, keep: impl Fn(&Cluster) -> bool) -> f64 {
        self.clusters
            .iter()
            .filter(|c| keep(c))
            .map(|c| c.frequency())
            .fold(0.0, f64::max)
    }

    /// How far the repeated-pole form of the clusters of distinct poles (what
    /// [`Cluster::coeffs`] write, the closed-form text) is from the exact y: the largest
    /// difference on a 4000-point grid over each such cluster's transient, 0 when every
    /// cluster is an exactly repeated pole, infinite when such a cluster does not decay.
    ///
    /// Measured once (both closed-form texts ask) and kept; each cluster's grid is walked by
    /// the uniform recurrences of [`StepResponse::eval_uniform_rational`], one exp(hN) for
    /// the whole grid, not a scaled and squared exp(τN) at each of its 4001 instants.
    pub fn repeated_form_error(&self) -> f64 {
        *self.form_error.get_or_init(|| {
            let scale = self.magnitude_scale().max(f64::MIN_POSITIVE);
            self.clusters
                .iter()
                .filter_map(|c| c.spread.as_ref().map(|s| (c, s)))
                .map(|(c, s)| self.cluster_form_error(c, s, scale))
                .sum()
        })
    }

    /// The largest |exact − repeated form| of one spread cluster on [`FORM_GRID`] + 1
    /// instants over its transient (until its envelope is below 1e-12·`scale`).
    fn cluster_form_error(&self, c: &Cluster, s: &Spread, scale: f64) -> f64 {
        if c.decay_rate() >= 0.0 {
            return f64::INFINITY;
        }
        let end = self.envelope_time(1e-12 * scale, |k| std::ptr::eq(k, c));
        let h = end / FORM_GRID as f64;
        let mut exact = vec![0.0; FORM_GRID + 1];
        let mut form = vec![0.0; FORM_GRID + 1];
        uniform_spread(c, s, &s.differences[0], 0.0, h, &mut exact);
        uniform_repeated(c, &c.coeffs, 0.0, h, &mut form);
        exact
            .iter()
            .zip(&form)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    }

    /// The plotting window counted from the end of the dead time (seconds): the transient of
    /// the stable part (1.5 × the time its envelope needs to fall below 2 % of the response's
    /// size), for a settling response at least `landmarks`, the latest instant its metrics
    /// need shown (τ, from the end of the dead time; [`super::analysis`] takes it from the
    /// metrics already computed), and for one that does not settle a few periods of the
    /// sustained oscillation or e-foldings of the growth (`landmarks` is ignored).
    pub(crate) fn rational_horizon(&self, landmarks: f64) -> f64 {
        let scale = self.magnitude_scale().max(f64::MIN_POSITIVE);
        let stable = |c: &Cluster| c.decay_rate() < 0.0;
        let transient = 1.5 * self.envelope_time(0.02 * scale, stable);
        let rational = match self.behaviour {
            Behaviour::Settles => landmarks.max(transient),
            Behaviour::Unstable => {
                let growth = self
                    .clusters
                    .iter()
                    .map(|c| c.decay_rate())
                    .fold(0.0, f64::max);
                let repeated_axis =
                    self.max_frequency(|c| c.center.re == 0.0 && c.multiplicity > 1);
                let by_growth = if growth > 0.0 { 4.0 / growth } else { 0.0 };
                let by_period = if repeated_axis > 0.0 {
                    5.0 * std::f64::consts::TAU / repeated_axis
                } else {
                    0.0
                };
                transient.max(by_growth).max(by_period)
            }
            Behaviour::Oscillating | Behaviour::Integrating => {
                let w = self.max_frequency(|c| c.center.re == 0.0);
                let slowest_w = self
                    .clusters
                    .iter()
                    .filter(|c| c.center.re == 0.0 && c.frequency() > 0.0)
                    .map(|c| c.frequency())
                    .fold(w, f64::min);
                let by_period = if slowest_w > 0.0 {
                    4.0 * std::f64::consts::TAU / slowest_w
                } else {
                    0.0
                };
                transient.max(by_period)
            }
        };
        if rational > 0.0 && rational.is_finite() {
            rational
        } else {
            self.fastest_rate().map_or(10.0, |r| 10.0 / r)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    fn zpk(zeros: &[C64], poles: &[C64], k: f64) -> TransferFunction {
        TransferFunction::from_zpk(zeros, poles, k).unwrap()
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * b.abs().max(1e-300) || (a - b).abs() <= tol
    }

    #[test]
    fn first_order_closed_form() {
        let r = StepResponse::new(&zpk(&[], &[c(-5.0, 0.0)], 5.0), 1.0).unwrap();
        for t in [0.0f64, 0.01, 0.3, 1.0, 4.0] {
            let exact = 1.0 - (-5.0 * t).exp();
            assert!(close(r.value(t), exact, 1e-14), "t={t}");
        }
        assert_eq!(r.final_value(), Some(1.0));
    }

    #[test]
    fn the_notes_third_order_example() {
        // y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100, A = 2.
        let g = zpk(&[], &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)], 0.5);
        let r = StepResponse::new(&g, 2.0).unwrap();
        for t in [0.0f64, 0.1, 0.7, 1.3, 2.9, 6.0] {
            let e = (-t).exp();
            let exact = 1.0 / 25.0
                - 0.03 * e * ((2.0 * t).cos() + 4.0 / 3.0 * (2.0 * t).sin())
                - (-5.0 * t).exp() / 100.0;
            assert!(
                (r.value(t) - exact).abs() < 1e-16 + 1e-14 * exact.abs(),
                "t={t}"
            );
        }
    }

    #[test]
    fn double_pole_is_exact() {
        // (s+5)/(s+10)^2: y = 1/20 − e^{−10t}/20 + (1/2)t e^{−10t}.
        let r = StepResponse::new(
            &zpk(&[c(-5.0, 0.0)], &[c(-10.0, 0.0), c(-10.0, 0.0)], 1.0),
            1.0,
        )
        .unwrap();
        for t in [0.0f64, 0.05, 0.1, 0.3, 1.0] {
            let e = (-10.0 * t).exp();
            let exact = 0.05 - e / 20.0 + 0.5 * t * e;
            assert!((r.value(t) - exact).abs() < 1e-15, "t={t}");
        }
    }

    #[test]
    fn nearly_repeated_poles_match_the_exact_formula() {
        // 1/((s+1)(s+1+d)): y = 1/(1+d) − e^{−t}/d + e^{−(1+d)t}/(d(1+d)); for small d use the
        // series: = 1 − e^{−t}(1 + t) + d·(t²/2·e^{−t} + … ) computed in extended form.
        let d = 1e-6;
        let r = StepResponse::new(&zpk(&[], &[c(-1.0, 0.0), c(-1.0 - d, 0.0)], 1.0), 1.0).unwrap();
        for t in [0.1f64, 1.0, 3.0, 10.0] {
            // Divided-difference expansion to second order in d, exact to ~1e-18 here.
            let e = (-t).exp();
            let y0 = 1.0 - e * (1.0 + t);
            let y1 = -(1.0 - e * (1.0 + t + t * t / 2.0)); // d/dd of 1/(1+d)·… at d = 0
            let exact = y0 + d * y1;
            assert!(
                (r.value(t) - exact).abs() < 1e-11,
                "t={t}: {} vs {exact}",
                r.value(t)
            );
        }
    }

    #[test]
    fn integrator_ramps() {
        // 1/(s(s+1)): y = t − 1 + e^{−t}.
        let r = StepResponse::new(&zpk(&[], &[c(0.0, 0.0), c(-1.0, 0.0)], 1.0), 1.0).unwrap();
        assert_eq!(r.behaviour(), Behaviour::Integrating);
        for t in [0.0, 0.5, 2.0, 20.0] {
            assert!((r.value(t) - (t - 1.0 + (-t).exp())).abs() < 1e-13);
        }
        assert_eq!(r.final_value(), None);
    }

    #[test]
    fn unstable_pole_grows() {
        // 1/(s−1): y = e^{t} − 1.
        let r = StepResponse::new(&zpk(&[], &[c(1.0, 0.0)], 1.0), 1.0).unwrap();
        assert_eq!(r.behaviour(), Behaviour::Unstable);
        assert!((r.value(3.0) - (3f64.exp() - 1.0)).abs() < 1e-12);
    }

    #[test]
    fn biproper_system_has_direct_feedthrough() {
        // (s+2)/(s+1): y = 2 − e^{−t}, y(0+) = 1.
        let r = StepResponse::new(&zpk(&[c(-2.0, 0.0)], &[c(-1.0, 0.0)], 1.0), 3.0).unwrap();
        assert!((r.value(0.0) - 3.0).abs() < 1e-15);
        assert!((r.value(1.0) - 3.0 * (2.0 - (-1f64).exp())).abs() < 1e-14);
    }

    #[test]
    fn fast_and_slow_poles_together() {
        // 10/((s+0.01)(s+1000)) = K·… with K = 10/(10) = 1.
        let g = zpk(&[], &[c(-0.01, 0.0), c(-1000.0, 0.0)], 10.0);
        let r = StepResponse::new(&g, 1.0).unwrap();
        for t in [1e-4, 1e-2, 1.0, 100.0, 1000.0] {
            let (a, b) = (0.01_f64, 1000.0_f64);
            let exact = 10.0 / (a * b)
                + 10.0 / (a * (a - b)) * (-a * t).exp()
                + 10.0 / (b * (b - a)) * (-b * t).exp();
            assert!(
                (r.value(t) - exact).abs() < 1e-12 * exact.abs().max(1e-3),
                "t={t}"
            );
        }
    }

    #[test]
    fn delay_shifts_the_response() {
        let g = zpk(&[], &[c(-1.0, 0.0)], 1.0).with_delay(0.5).unwrap();
        let r = StepResponse::new(&g, 1.0).unwrap();
        assert_eq!(r.value(0.49), 0.0);
        assert!((r.value(1.5) - (1.0 - (-1f64).exp())).abs() < 1e-15);
    }

    #[test]
    fn uniform_sampling_matches_pointwise() {
        let g = zpk(
            &[c(-0.5, 0.0)],
            &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)],
            0.5,
        )
        .with_delay(0.2)
        .unwrap();
        let r = StepResponse::new(&g, 2.0).unwrap();
        let (t, y) = r.sample_uniform(0.0, 8.0, 2001);
        for (ti, yi) in t.iter().zip(&y) {
            assert!((r.value(*ti) - yi).abs() < 1e-14, "t={ti}");
        }
    }

    #[test]
    fn derivative_is_the_impulse_response() {
        let g = zpk(
            &[c(-3.0, 0.0)],
            &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)],
            0.5,
        );
        let r = StepResponse::new(&g, 1.0).unwrap();
        for t in [0.3, 1.0, 2.5] {
            let h = 1e-5;
            let fd = (r.value(t + h) - r.value(t - h)) / (2.0 * h);
            assert!((r.derivative(t) - fd).abs() < 1e-9);
        }
    }
    #[test]
    fn superposition_equals_the_sum_of_delayed_steps() {
        let systems = [
            zpk(&[], &[c(-0.5, 0.0)], 0.5),
            zpk(
                &[c(-3.0, 0.0)],
                &[c(-1.0, 0.0), c(-1.0, 0.0), c(-0.2, 0.0)],
                2.0,
            ),
            zpk(&[], &[c(-1.0, 0.0), c(-1.003, 0.0), c(-0.997, 0.0)], 1.0),
            zpk(
                &[c(-2.0, 0.0)],
                &[c(-0.3, 1.2), c(-0.3, -1.2), c(0.0, 0.0)],
                1.5,
            ),
            zpk(&[c(-1.0, 0.0)], &[c(-2.0, 0.0)], 3.0)
                .with_delay(0.37)
                .unwrap(),
        ];
        let steps = [
            (0.13, 1.0),
            (2.5, -2.5),
            (2.5, 0.5),
            (4.71, 3.0),
            (9.0, -1.0),
        ];
        // Uneven instants, some exactly at a step (the right limit counts).
        let mut times: Vec<f64> = (0..400)
            .map(|k| 0.031 * k as f64 + 0.002 * (k % 7) as f64)
            .collect();
        times.extend([12.87, 13.0, 20.0]);
        times.sort_by(f64::total_cmp);
        for g in &systems {
            for amplitude in [1.0, -4.0] {
                let r = StepResponse::new(g, amplitude).unwrap();
                let mut out = vec![0.0; times.len()];
                r.superpose(&steps, &times, &mut out);
                for (&t, &y) in times.iter().zip(&out) {
                    let direct: f64 = steps
                        .iter()
                        .map(|&(s, a)| a * r.value(t - s) / amplitude)
                        .sum();
                    assert!(
                        (y - direct).abs() <= 1e-11 * (1.0 + direct.abs()),
                        "{g:?} t={t}: {y} vs {direct}"
                    );
                }
            }
        }
    }
}
