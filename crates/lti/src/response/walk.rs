//! The walk along a record: the running state of each cluster's partial fractions advanced
//! from instant to instant (one exponential per distinct spacing, reused within rounding
//! and jitter), superposing the input's steps as they come.

use super::*;

/// The running sum V(t) = Σ_{sₖ+θ ≤ t} aₖ·e^{c(t−sₖ−θ)}·b(t − sₖ − θ) of one cluster over
/// the steps seen so far (see [`StepResponse::superpose`]). It walks forward through the
/// steps' instants and the requested instants in order: each step is added where it
/// starts (τ = 0, no exponential), and the state advances between consecutive instants by
/// e^{ch}·M(h), with e^{ch} and M(h) kept for the last distinct h, so a uniform grid or a
/// clocked input costs a few multiplications per instant.
pub(super) struct Superposition<'a> {
    cluster: &'a Cluster,
    delay: f64,
    /// 1/A: the clusters hold A·y; the steps give their own sizes.
    scale: f64,
    state: Vec<C64>,
    /// b(0): what a unit step adds where it starts.
    start_row: Vec<C64>,
    /// The instant the state is at (−∞ before the first step).
    t: f64,
    /// Steps already added.
    added: usize,
    /// e^{ch} over `cached_h`.
    cached_h: f64,
    cached_exp: C64,
    /// A spread cluster's exp(hN) over the spacings walked.
    advance: Option<divided::RowAdvance>,
}

/// The largest |cδ| (|re| + |im|) by which an advance reuses the cached e^{ch}, times the
/// correction e^{cδ} by its cubic ([`small_exp`], the rest under 5e-18): instants on a grid,
/// whose spacings differ by rounding, and a logger's jittered instants share one exponential.
/// A spacing further off (the part of a sampling interval after a step between samples, a
/// gap) is a new exponential, and the cache moves to it: a wider reuse would chain every
/// later spacing to that one's series (on a slow pole every spacing is "near" any other).
pub(super) const NEAR_ADVANCE: f64 = 1e-4;

impl<'a> Superposition<'a> {
    pub(super) fn new(cluster: &'a Cluster, delay: f64, scale: f64) -> Self {
        let start_row = match &cluster.spread {
            Some(_) => {
                let row = cluster.basis(0.0).row;
                if row.is_empty() {
                    let m = cluster.spread.as_ref().map_or(0, |s| s.offsets.len());
                    vec![C64::new(0.0, 0.0); m]
                } else {
                    row
                }
            }
            None => {
                let mut row = vec![C64::new(0.0, 0.0); cluster.coeffs.len()];
                if let Some(first) = row.first_mut() {
                    *first = C64::new(1.0, 0.0);
                }
                row
            }
        };
        let m = start_row.len();
        Self {
            cluster,
            delay,
            scale,
            state: vec![C64::new(0.0, 0.0); m],
            start_row,
            t: f64::NEG_INFINITY,
            added: 0,
            cached_h: f64::NAN,
            cached_exp: C64::new(1.0, 0.0),
            advance: cluster
                .spread
                .as_ref()
                .map(|s| divided::RowAdvance::new(&s.offsets, s.radius)),
        }
    }

    /// Moves the state to instant `t` (≥ the last one), adding on the way each step that
    /// starts by then, at its own instant.
    pub(super) fn advance_to(&mut self, t: f64, steps: &[(f64, f64)]) {
        while let Some(&(s, a)) = steps.get(self.added) {
            let start = s + self.delay;
            if start > t {
                break;
            }
            self.move_to(start);
            let a = a * self.scale;
            for (v, r) in self.state.iter_mut().zip(&self.start_row) {
                *v += r * a;
            }
            self.added += 1;
        }
        self.move_to(t);
    }

    /// V ← V(t): propagates from the current instant (nothing to do before the first step).
    pub(super) fn move_to(&mut self, t: f64) {
        if self.added > 0 && t > self.t {
            self.propagate(t - self.t);
        }
        self.t = self.t.max(t);
    }

    /// e^{ch}, from the cached advance when h is within [`NEAR_ADVANCE`] of it.
    pub(super) fn exponential(&mut self, h: f64) -> C64 {
        let c = self.cluster;
        let z = c.center * (h - self.cached_h);
        if z.re.abs() + z.im.abs() <= NEAR_ADVANCE {
            return self.cached_exp * small_exp(z);
        }
        self.cached_h = h;
        self.cached_exp = exp(c.center * h);
        self.cached_exp
    }

    /// V ← e^{ch}·M(h)·V.
    pub(super) fn propagate(&mut self, h: f64) {
        let e = self.exponential(h);
        match &mut self.advance {
            Some(advance) => advance.advance(&mut self.state, h),
            None if self.state.len() > 1 => {
                // (τ + h)ʲ = Σᵢ C(j, i)·h^{j−i}·τⁱ, highest power first (in place).
                for j in (1..self.state.len()).rev() {
                    let mut binomial = 1.0;
                    let mut power = 1.0;
                    let mut sum = self.state[j];
                    for i in (0..j).rev() {
                        binomial *= (i + 1) as f64 / (j - i) as f64;
                        binomial = binomial.round();
                        power *= h;
                        sum += self.state[i] * (binomial * power);
                    }
                    self.state[j] = sum;
                }
            }
            None => {}
        }
        self.state.iter_mut().for_each(|v| *v *= e);
    }

    /// weight·Re(d·V).
    pub(super) fn value(&self) -> f64 {
        let d = match &self.cluster.spread {
            Some(s) => &s.differences[0],
            None => &self.cluster.coeffs,
        };
        self.cluster.weight * dot(d, &self.state).re
    }
}

/// e^z, by its series to z³ when |z| ≤ [`NEAR_ADVANCE`] (the rest under 5e-18): the
/// correction of a cached advance to a spacing that differs by rounding or jitter.
pub(super) fn small_exp(z: C64) -> C64 {
    if z.re.abs() + z.im.abs() > NEAR_ADVANCE {
        return exp(z);
    }
    C64::new(1.0, 0.0) + z * (1.0 + z * (0.5 + z / 6.0))
}

/// e^z for a real z, as [`small_exp`].
pub(super) fn small_exp_real(z: f64) -> f64 {
    if z.abs() > NEAR_ADVANCE {
        return z.exp();
    }
    1.0 + z * (1.0 + z * (0.5 + z / 6.0))
}

/// e^z, without a sine and cosine of 0 for a real z.
pub(super) fn exp(z: C64) -> C64 {
    if z.im == 0.0 {
        C64::new(z.re.exp(), 0.0)
    } else {
        z.exp()
    }
}

/// [`Superposition`] for a simple pole c (its contribution q·e^{cτ}), written out: the running
/// sum is one number, advanced by e^{ch} from the cached advance (nothing for the pole at
/// the origin of a step), so an instant costs a few multiplications. A real pole walks in
/// real arithmetic: the same products, since every imaginary part would be zero.
pub(super) fn superpose_simple(
    c: &Cluster,
    delay: f64,
    scale: f64,
    steps: &[(f64, f64)],
    times: &[f64],
    out: &mut [f64],
) {
    let d = c.coeffs[0] * c.weight;
    if c.center.im == 0.0 {
        walk_simple(c.center.re, d.re, delay, scale, steps, times, out);
    } else {
        walk_simple(c.center, d, delay, scale, steps, times, out);
    }
}

/// A pole's number: real or complex, with what the walk needs of it.
pub(super) trait PoleNumber:
    Copy + PartialEq + std::ops::Mul<Output = Self> + std::ops::MulAssign + std::ops::AddAssign<f64>
{
    const ZERO: Self;
    const ONE: Self;
    /// e^{self·h}.
    fn exp_times(self, h: f64) -> Self;
    /// e^{self·δ} for a small δ ([`small_exp`]).
    fn small_exp_times(self, delta: f64) -> Self;
    /// Whether |self·δ| is within [`NEAR_ADVANCE`].
    fn near(self, delta: f64) -> bool;
    /// Re(self·other).
    fn re_product(self, other: Self) -> f64;
}

impl PoleNumber for f64 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    fn exp_times(self, h: f64) -> Self {
        (self * h).exp()
    }
    fn small_exp_times(self, delta: f64) -> Self {
        small_exp_real(self * delta)
    }
    fn near(self, delta: f64) -> bool {
        (self * delta).abs() <= NEAR_ADVANCE
    }
    fn re_product(self, other: Self) -> f64 {
        self * other
    }
}

impl PoleNumber for C64 {
    const ZERO: Self = C64::new(0.0, 0.0);
    const ONE: Self = C64::new(1.0, 0.0);
    fn exp_times(self, h: f64) -> Self {
        exp(self * h)
    }
    fn small_exp_times(self, delta: f64) -> Self {
        small_exp(self * delta)
    }
    fn near(self, delta: f64) -> bool {
        let z = self * delta;
        z.re.abs() + z.im.abs() <= NEAR_ADVANCE
    }
    fn re_product(self, other: Self) -> f64 {
        (self * other).re
    }
}

/// The walk of [`superpose_simple`] for a pole `center` and coefficient `d`.
pub(super) fn walk_simple<P: PoleNumber>(
    center: P,
    d: P,
    delay: f64,
    scale: f64,
    steps: &[(f64, f64)],
    times: &[f64],
    out: &mut [f64],
) {
    let constant = center == P::ZERO;
    let mut sum = P::ZERO;
    let mut at = f64::NEG_INFINITY;
    let mut added = 0;
    let mut advance = Advance::new(center);
    for (o, &t) in out.iter_mut().zip(times) {
        while let Some(&(s, a)) = steps.get(added) {
            let start = s + delay;
            if start > t {
                break;
            }
            if added > 0 && start > at && !constant {
                sum *= advance.over(start - at);
            }
            at = at.max(start);
            sum += a * scale;
            added += 1;
        }
        if added == 0 {
            continue;
        }
        if t > at && !constant {
            sum *= advance.over(t - at);
        }
        at = at.max(t);
        *o += d.re_product(sum);
    }
}

/// e^{ch} for the spacings h of a walk, kept for the last distinct one (see [`NEAR_ADVANCE`]).
pub(super) struct Advance<P> {
    center: P,
    h: f64,
    exp: P,
}

impl<P: PoleNumber> Advance<P> {
    pub(super) fn new(center: P) -> Self {
        Self {
            center,
            h: f64::NAN,
            exp: P::ONE,
        }
    }

    pub(super) fn over(&mut self, h: f64) -> P {
        let delta = h - self.h;
        if delta == 0.0 {
            return self.exp;
        }
        if self.center.near(delta) {
            return self.exp * self.center.small_exp_times(delta);
        }
        self.h = h;
        self.exp = self.center.exp_times(h);
        self.exp
    }
}

/// Adds a repeated cluster's weight·Re(e^{cτ}·P(τ)) on the grid τ₀ + i·h (a real pole in
/// real arithmetic: the same products, since every imaginary part would be zero).
pub(super) fn uniform_repeated(c: &Cluster, poly: &[C64], tau0: f64, h: f64, out: &mut [f64]) {
    let grid = (tau0, h);
    if c.center.im == 0.0 {
        walk_uniform(c.center.re, c.weight, |t| horner_re(poly, t), grid, out);
    } else {
        walk_uniform(c.center, c.weight, |t| horner(poly, t), grid, out);
    }
}

/// weight·Re(e^{cτ}·p(τ)) added on the grid τ₀ + i·h (`grid` = (τ₀, h)), e^{cτ} by the
/// recurrence e^{c(τ+h)} = e^{cτ}·e^{ch}, re-anchored every [`REANCHOR`] steps.
pub(super) fn walk_uniform<P: PoleNumber>(
    center: P,
    weight: f64,
    p: impl Fn(f64) -> P,
    (tau0, h): (f64, f64),
    out: &mut [f64],
) {
    let step = center.exp_times(h);
    let mut e = P::ZERO;
    for (i, v) in out.iter_mut().enumerate() {
        let tau = tau0 + h * i as f64;
        e = if i % REANCHOR == 0 {
            center.exp_times(tau)
        } else {
            e * step
        };
        *v += weight * e.re_product(p(tau));
    }
}

/// Adds a spread cluster's contribution on the grid τ₀ + i·h: the last row of exp(τN)
/// advances by one product with exp(hN) per step.
pub(super) fn uniform_spread(
    c: &Cluster,
    s: &Spread,
    differences: &[C64],
    tau0: f64,
    h: f64,
    out: &mut [f64],
) {
    let step = (c.center * h).exp();
    let advance = divided::exp_matrix(&s.offsets, s.radius, h);
    let mut e = C64::new(0.0, 0.0);
    let mut row = vec![C64::new(0.0, 0.0); s.offsets.len()];
    let mut next = row.clone();
    for (i, v) in out.iter_mut().enumerate() {
        let tau = tau0 + h * i as f64;
        if i % REANCHOR == 0 {
            let basis = c.basis(tau);
            e = basis.exp_ct;
            if basis.row.is_empty() {
                row.iter_mut().for_each(|r| *r = C64::new(0.0, 0.0));
            } else {
                row.copy_from_slice(&basis.row);
            }
        } else {
            e *= step;
            advance.row_times(&row, &mut next);
            std::mem::swap(&mut row, &mut next);
        }
        *v += c.weight * (e * dot(differences, &row)).re;
    }
}
