//! The initial transient of a test not at rest: x(τ) = Σ Xᵢ·φᵢ(τ), the free response of G's
//! own poles in the Newton basis of their exponentials (see [`crate::model`]'s docs), and its
//! evaluation along a record.
//!
//! One or two real poles, and three whose two farthest are apart, are evaluated in closed
//! form at each instant: the divided differences of the poles' exponentials, a difference
//! taken as it stands where its poles are far apart for the instant and by `expm1` where
//! they are close, the second over the farthest pair. Three poles all close are walked along the record: φ(τ + h) =
//! e^{ch}·φ(τ)·exp(hN) (N the Opitz matrix of the offsets, so the walk is the same divided
//! differences, only advanced: [`RowAdvance`] keeps the matrices of the clock's spacings),
//! with a fresh exact evaluation every [`RESEED`] instants, so that rounding cannot build up.
//! An underdamped pair is cheap in closed form at each instant.

use crate::model::{Model, Param};
use degrau_lti::C64;
use degrau_lti::divided::{self, RowAdvance};

/// Instants walked between two exact evaluations of the basis.
const RESEED: usize = 256;

/// The initial transient x(τ) = Σ Xᵢ·φᵢ(τ), τ from the record's first instant (see the
/// module docs).
#[derive(Debug, Clone)]
pub(crate) struct Transient {
    /// The coefficients X1… (output units).
    coefficients: Vec<f64>,
    modes: Modes,
}

/// The free-response basis of G's poles (no integrator).
#[derive(Debug, Clone)]
enum Modes {
    /// Real poles: themselves (for the closed form: a slow pole read back as c + (p − c)
    /// beside fast ones would lose the digits of c), and their centre c and offsets pᵢ − c,
    /// for the divided differences.
    Real {
        poles: Vec<f64>,
        /// The order a, b, c of three poles with a and c the two farthest apart, when the
        /// basis is in closed form ([`closed_form_holds`]; always for one or two poles).
        closed: Option<[usize; 3]>,
        center: f64,
        offsets: Vec<C64>,
        radius: f64,
    },
    /// An underdamped pair σ ± jω (ω² < 0 for real poles from ζ > 1), and a third real
    /// pole if any.
    Pair {
        sigma: f64,
        omega_squared: f64,
        third: Option<f64>,
    },
}

impl Transient {
    pub(crate) fn of(model: &Model) -> Option<Transient> {
        let s = &model.structure;
        if !s.transient {
            return None;
        }
        let v = &model.values;
        let count = s.poles as usize;
        let coefficients = [Param::X1, Param::X2, Param::X3][..count]
            .iter()
            .map(|&p| v.get(p))
            .collect();
        let modes = if s.underdamped {
            let (tw, zeta) = (v.get(Param::Tw), v.get(Param::Zeta));
            Modes::Pair {
                sigma: -zeta / tw,
                omega_squared: (1.0 - zeta * zeta) / (tw * tw),
                third: (s.poles == 3).then(|| -1.0 / v.get(Param::Tp3)),
            }
        } else {
            let poles: Vec<f64> = [Param::Tp1, Param::Tp2, Param::Tp3][..count]
                .iter()
                .map(|&p| -1.0 / v.get(p))
                .collect();
            let center = poles.iter().sum::<f64>() / count as f64;
            let offsets: Vec<C64> = poles.iter().map(|p| C64::new(p - center, 0.0)).collect();
            let radius = offsets.iter().map(|d| d.norm()).fold(0.0, f64::max);
            let closed = closed_form_holds(&poles).then(|| match poles.len() {
                3 => {
                    let (a, c, _) = farthest(&poles);
                    [a, 3 - a - c, c]
                }
                _ => [0, 1, 2],
            });
            Modes::Real {
                poles,
                closed,
                center,
                offsets,
                radius,
            }
        };
        Some(Transient {
            coefficients,
            modes,
        })
    }

    /// The coefficients X1… (output units).
    pub(crate) fn coefficients(&self) -> &[f64] {
        &self.coefficients
    }

    /// x(τ), from a fresh evaluation of the basis.
    #[cfg(test)]
    fn value(&self, tau: f64) -> f64 {
        combine(padded(&self.coefficients), self.basis(tau))
    }

    /// The basis φ₁(τ)… (X1's first; zero past the poles' count), evaluated afresh.
    fn basis(&self, tau: f64) -> Basis {
        match &self.modes {
            Modes::Real {
                poles,
                closed: Some(order),
                ..
            } => closed_basis(poles, *order, exponentials(poles, tau), tau),
            Modes::Real {
                center,
                offsets,
                radius,
                ..
            } => newton_basis(&real_basis(*center, offsets, *radius, tau)),
            Modes::Pair {
                sigma,
                omega_squared,
                third,
            } => {
                let e = (sigma * tau).exp();
                let (cos, sinc) = oscillation(*omega_squared, tau);
                [e * cos, e * sinc, third.map_or(0.0, |p| (p * tau).exp())]
            }
        }
    }
}

/// The basis of a transient at one instant: φᵢ for Xᵢ₊₁, zero past the poles' count.
type Basis = [f64; 3];

/// Σ Xᵢ·φᵢ, the coefficients `x` padded with zeros ([`padded`]).
#[inline(always)]
fn combine(x: Basis, basis: Basis) -> f64 {
    x[0] * basis[0] + x[1] * basis[1] + x[2] * basis[2]
}

/// The coefficients X1… in a basis's shape, zero past their count.
fn padded(coefficients: &[f64]) -> Basis {
    let mut x = [0.0; 3];
    x.iter_mut().zip(coefficients).for_each(|(x, c)| *x = *c);
    x
}

/// e^{pτ} of each real pole (up to three), zero past their count.
#[inline(always)]
fn exponentials(poles: &[f64], tau: f64) -> [f64; 3] {
    let mut e = [0.0; 3];
    for (e, p) in e.iter_mut().zip(poles) {
        *e = (p * tau).exp();
    }
    e
}

/// The basis from e^{cτ}·(last row of exp(τN)), whose last entry is e^{p_m τ} (X1's).
fn newton_basis(row: &[C64]) -> Basis {
    let mut basis = [0.0; 3];
    basis
        .iter_mut()
        .zip(row.iter().rev())
        .for_each(|(b, r)| *b = r.re);
    basis
}

/// The least gap between the two farthest of three poles, as a share of the largest's
/// size, for the second divided difference in closed form: taken over that pair (it is
/// symmetric in its poles), its subtraction then loses at most a few digits at any instant.
/// Three poles all closer are walked ([`Walk`]).
const APART: f64 = 0.05;

/// Whether the real poles are evaluated in closed form: one or two always, three when the
/// two farthest are [`APART`].
fn closed_form_holds(poles: &[f64]) -> bool {
    let size = poles.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
    match poles.len() {
        0..=2 => true,
        3 => farthest(poles).2 >= APART * size,
        _ => false,
    }
}

/// Of three poles, the indices of the two farthest apart, and their gap.
fn farthest(poles: &[f64]) -> (usize, usize, f64) {
    [(0, 1), (0, 2), (1, 2)]
        .into_iter()
        .map(|(i, j)| (i, j, (poles[i] - poles[j]).abs()))
        .fold((0, 2, f64::NEG_INFINITY), |best, c| {
            if c.2 > best.2 { c } else { best }
        })
}

/// The first divided difference f[p, q] = (e^{qτ} − e^{pτ})/(q − p) from the two
/// exponentials `ep` = e^{pτ} and `eq` = e^{qτ}: their difference as it stands where the
/// poles are 1/|τ| or more apart (it then loses under two bits), else without cancellation
/// however close the poles, anchored on the larger exponent: e^{hτ}·(1 − e^{(l − h)τ})/(h − l)
/// by `expm1` (τ·e^{pτ} for equal poles).
#[inline(always)]
fn divided(p: f64, q: f64, (ep, eq): (f64, f64), tau: f64) -> f64 {
    if ((q - p) * tau).abs() >= 1.0 {
        return (eq - ep) / (q - p);
    }
    let (hi, lo, top) = if q >= p { (q, p, eq) } else { (p, q, ep) };
    if hi == lo {
        tau * top
    } else {
        -top * ((lo - hi) * tau).exp_m1() / (hi - lo)
    }
}

/// (cos ωτ, sin(ωτ)/ω) for ω² > 0, (cosh, sinh(|ω|τ)/|ω|) for ω² < 0, (1, τ) at ω = 0.
fn oscillation(omega_squared: f64, tau: f64) -> (f64, f64) {
    let w = omega_squared.abs().sqrt();
    let x = w * tau;
    if x.abs() < 1e-4 {
        let x2 = omega_squared * tau * tau;
        return (1.0 - x2 / 2.0, tau * (1.0 - x2 / 6.0));
    }
    if omega_squared > 0.0 {
        (x.cos(), x.sin() / w)
    } else {
        (x.cosh(), x.sinh() / w)
    }
}

impl Transient {
    /// Adds x(t − origin) to `out` at each instant of `times` (ascending; both cut to the
    /// shorter).
    pub(crate) fn add_to(&self, times: &[f64], origin: f64, out: &mut [f64]) {
        let n = times.len().min(out.len());
        let x = padded(&self.coefficients);
        let out = &mut out[..n];
        self.for_each_basis(&times[..n], origin, |k, basis| {
            out[k] += combine(x, basis);
        });
    }

    /// The basis φᵢ(t − origin) at each instant of `times` (ascending) into `columns[i]`,
    /// the derivative of x along Xᵢ₊₁: as many columns as given, each cut to the instants.
    pub(crate) fn basis_into(&self, times: &[f64], origin: f64, columns: &mut [Vec<f64>]) {
        let n = columns.iter().fold(times.len(), |n, c| n.min(c.len()));
        self.for_each_basis(&times[..n], origin, |k, basis| {
            columns
                .iter_mut()
                .zip(basis)
                .for_each(|(column, phi)| column[k] = phi);
        });
    }

    /// Calls `each(k, φ(t_k − origin))` at each instant of `times` (ascending).
    fn for_each_basis(&self, times: &[f64], origin: f64, mut each: impl FnMut(usize, Basis)) {
        match &self.modes {
            // One or two poles, or three well apart: the basis in closed form at each
            // instant (see [`closed_basis`]): a few exponentials cost less than a walk's
            // matrices.
            Modes::Real {
                poles,
                closed: Some(order),
                ..
            } => {
                for (k, &t) in times.iter().enumerate() {
                    let tau = t - origin;
                    each(
                        k,
                        closed_basis(poles, *order, exponentials(poles, tau), tau),
                    );
                }
            }
            Modes::Real {
                center,
                offsets,
                radius,
                ..
            } => {
                let mut walk = Walk::new(*center, offsets, *radius);
                for (k, &t) in times.iter().enumerate() {
                    each(k, newton_basis(walk.at(t - origin)));
                }
            }
            Modes::Pair { .. } => {
                for (k, &t) in times.iter().enumerate() {
                    each(k, self.basis(t - origin));
                }
            }
        }
    }
}

/// The basis f[p_m], f[p_{m−1}, p_m], f[p1, p2, p3] at τ from the poles' exponentials `e`:
/// the divided differences of f(p) = e^{pτ} over the poles as listed (X1's on the last), the
/// first by [`divided`], the second, symmetric in its poles, as f[a, b, c] = (f[b, c] −
/// f[a, b])/(c − a) in the `order` a, b, c that puts the two farthest apart at its ends
/// ([`closed_form_holds`]).
#[inline(always)]
fn closed_basis(poles: &[f64], order: [usize; 3], e: [f64; 3], tau: f64) -> Basis {
    let first = |i: usize, j: usize| divided(poles[i], poles[j], (e[i], e[j]), tau);
    match poles.len() {
        1 => [e[0], 0.0, 0.0],
        2 => [e[1], first(0, 1), 0.0],
        3 => {
            let [a, b, c] = order;
            let second = (first(b, c) - first(a, b)) / (poles[c] - poles[a]);
            [e[2], first(1, 2), second]
        }
        _ => [f64::NAN; 3],
    }
}

/// The real-pole basis at τ, e^{cτ}·(last row of exp(τN)), evaluated afresh: its last entry
/// is e^{p_m τ}, the earlier ones the higher divided differences.
fn real_basis(center: f64, offsets: &[C64], radius: f64, tau: f64) -> Vec<C64> {
    let e = (center * tau).exp();
    if e == 0.0 {
        // Poles all close (farther ones are in closed form, [`closed_form_holds`]): every
        // mode has decayed with e^{cτ}, and exp(τN) may overflow, 0·∞.
        return vec![C64::new(0.0, 0.0); offsets.len()];
    }
    let mut row = divided::exp_last_row(offsets, radius, tau);
    row.iter_mut().for_each(|r| *r *= e);
    row
}

/// The real-pole basis e^{cτ}·(last row of exp(τN)) advanced from instant to instant.
struct Walk<'a> {
    center: f64,
    offsets: &'a [C64],
    radius: f64,
    tau: f64,
    row: Vec<C64>,
    /// Instants walked since the last exact evaluation.
    walked: usize,
    advance: RowAdvance,
}

impl<'a> Walk<'a> {
    fn new(center: f64, offsets: &'a [C64], radius: f64) -> Self {
        Self {
            center,
            offsets,
            radius,
            tau: f64::NAN,
            row: Vec::new(),
            walked: 0,
            advance: RowAdvance::new(offsets, radius),
        }
    }

    /// The basis at τ (not before the previous instant).
    fn at(&mut self, tau: f64) -> &[C64] {
        let h = tau - self.tau;
        if !(h > 0.0 && h.is_finite() && self.walked < RESEED) {
            self.exact(tau);
            return &self.row;
        }
        self.advance.advance(&mut self.row, h);
        let e = (self.center * h).exp();
        self.row.iter_mut().for_each(|r| *r *= e);
        self.tau = tau;
        self.walked += 1;
        &self.row
    }

    fn exact(&mut self, tau: f64) {
        self.row = real_basis(self.center, self.offsets, self.radius, tau);
        self.tau = tau;
        self.walked = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Structure, Values};

    fn transient(code: &str, params: &[(Param, f64)]) -> Transient {
        let mut s = Structure::parse(code).expect("a code");
        s.transient = true;
        Transient::of(&Model::new(s, Values::from_pairs(params))).expect("a transient")
    }

    /// The walk against the exact value at every instant, on a grid made as a logger makes
    /// it (k·Ts, with its rounding), with a gap, and on jittered instants.
    fn walk_matches_exact(x: &Transient) {
        let mut grids: Vec<Vec<f64>> = vec![(0..3000).map(|k| 0.1 * k as f64).collect()];
        // A logger's instants read back from text with six decimals.
        grids.push(
            (0..5000)
                .map(|k| {
                    format!("{:.6}", 0.002 * k as f64 + 100.0)
                        .parse()
                        .unwrap_or(0.0)
                })
                .collect(),
        );
        let mut gap: Vec<f64> = (0..400).map(|k| 0.37 * k as f64).collect();
        gap.extend((900..1500).map(|k| 0.37 * k as f64));
        grids.push(gap);
        grids.push(
            (0..700)
                .map(|k| 0.5 * k as f64 + 0.2 * ((k * 7919) % 13) as f64 / 13.0)
                .collect(),
        );
        for times in grids {
            let mut walked = vec![0.0; times.len()];
            x.add_to(&times, -1.5, &mut walked);
            let scale = x.coefficients.iter().map(|c| c.abs()).sum::<f64>();
            for (k, (&t, w)) in times.iter().zip(&walked).enumerate() {
                assert!(w.is_finite(), "k {k}: {w}");
                let value = x.value(t + 1.5);
                assert!((w - value).abs() <= 1e-12 * scale, "k {k}: {w} vs {value}");
                // The Newton evaluation multiplies e^{cτ} by exp(τN): past radius·τ ≈ 709 the
                // product is 0·∞ for poles far apart, where the closed form still holds.
                let exact = newton(x, t + 1.5);
                if exact.is_finite() {
                    assert!((w - exact).abs() <= 1e-12 * scale, "k {k}: {w} vs {exact}");
                }
            }
        }
    }

    /// x(τ) by the Newton basis e^{cτ}·(last row of exp(τN)) for real poles, whatever their
    /// gaps: the reference the closed form is checked against.
    fn newton(x: &Transient, tau: f64) -> f64 {
        match &x.modes {
            Modes::Real {
                center,
                offsets,
                radius,
                ..
            } => {
                let e = (center * tau).exp();
                let row = divided::exp_last_row(offsets, *radius, tau);
                x.coefficients
                    .iter()
                    .zip(row.iter().rev())
                    .map(|(c, r)| c * (r * e).re)
                    .sum()
            }
            Modes::Pair { .. } => x.value(tau),
        }
    }

    #[test]
    fn two_close_lags_and_a_slow_one_hold_their_slow_mode_to_the_end() {
        // Poles −5, −4.9 and −0.001 (lags 0.2 s, 0.204 s, 1000 s): the Newton basis overflows
        // once radius·τ passes ≈ 709 (0·∞ = NaN from τ ≈ 280 s); the closed form over the
        // farthest pair holds, and long after the fast modes have died x(τ) is the slow mode's
        // share alone, in partial fractions: X1·e₃ + X2·e₃/(p₃ − p₂) + X3·e₃/((p₃ − p₁)(p₃ − p₂)).
        let (p1, p2, p3) = (-5.0, -4.9, -0.001);
        let (x1, x2, x3) = (1.0, -0.7, 0.3);
        let x = transient(
            "P3",
            &[
                (Param::Tp1, -1.0 / p1),
                (Param::Tp2, -1.0 / p2),
                (Param::Tp3, -1.0 / p3),
                (Param::X1, x1),
                (Param::X2, x2),
                (Param::X3, x3),
            ],
        );
        for tau in [280.0, 400.0, 2000.0] {
            let e3 = (p3 * tau).exp();
            let slow = x1 * e3 + x2 * e3 / (p3 - p2) + x3 * e3 / ((p3 - p1) * (p3 - p2));
            let value = x.value(tau);
            assert!(
                (value - slow).abs() <= 1e-13 * slow.abs(),
                "τ {tau}: {value} vs {slow}"
            );
            let mut walked = [0.0];
            x.add_to(&[tau], 0.0, &mut walked);
            assert!((walked[0] - slow).abs() <= 1e-13 * slow.abs(), "τ {tau}");
        }
        assert!(
            newton(&x, 400.0).is_nan(),
            "the Newton basis overflows here"
        );
        // Where the Newton basis is finite, the two agree, fast modes included.
        for tau in [0.0, 0.05, 0.3, 1.0, 3.0, 20.0, 100.0] {
            let (value, exact) = (x.value(tau), newton(&x, tau));
            assert!(
                (value - exact).abs() <= 1e-13,
                "τ {tau}: {value} vs {exact}"
            );
        }
        walk_matches_exact(&x);
    }

    #[test]
    fn the_basis_is_the_newton_basis_of_the_exponentials() {
        // Two distinct lags: x(τ) = X1·e^{qτ} + X2·(e^{qτ} − e^{pτ})/(q − p), the closed form
        // of the divided difference, X1 on the last pole listed (q = −1/Tp2, p = −1/Tp1);
        // one lag: X1·e^{−τ/Tp1}.
        let (t1, t2, x1, x2) = (30.0, 5.0, 1.3, -0.4);
        let x = transient(
            "P2",
            &[
                (Param::Tp1, t1),
                (Param::Tp2, t2),
                (Param::X1, x1),
                (Param::X2, x2),
            ],
        );
        let (p1, p2) = (-1.0 / t1, -1.0 / t2);
        let one = transient("P1", &[(Param::Tp1, t1), (Param::X1, x1)]);
        for tau in [0.0, 0.7, 4.0, 25.0, 140.0] {
            let (e1, e2) = ((p1 * tau).exp(), (p2 * tau).exp());
            let closed = x1 * e2 + x2 * (e2 - e1) / (p2 - p1);
            assert!(
                (x.value(tau) - closed).abs() <= 1e-14,
                "τ {tau}: {} vs {closed}",
                x.value(tau)
            );
            assert!((one.value(tau) - x1 * e1).abs() <= 1e-15, "τ {tau}");
        }
    }

    #[test]
    fn one_lag_walks_to_its_exponential() {
        walk_matches_exact(&transient("P1D", &[(Param::Tp1, 40.0), (Param::X1, 2.5)]));
    }

    #[test]
    fn two_lags_in_closed_form_match_the_newton_basis_even_when_they_meet() {
        for (t1, t2) in [
            (30.0, 5.0),
            (5.0, 30.0),
            (10.0, 10.0 * (1.0 + 1e-9)),
            (8.0, 8.0),
        ] {
            let x = transient(
                "P2",
                &[
                    (Param::Tp1, t1),
                    (Param::Tp2, t2),
                    (Param::X1, 1.0),
                    (Param::X2, -0.7),
                ],
            );
            walk_matches_exact(&x);
        }
    }

    #[test]
    fn three_lags_apart_in_closed_form_match_the_newton_basis() {
        let mut rng = crate::random::Lcg(5);
        let mut tried = 0;
        while tried < 40 {
            let lag = |rng: &mut crate::random::Lcg| 0.2 * 500f64.powf(rng.unit());
            let x = three_lags((lag(&mut rng), lag(&mut rng), lag(&mut rng)));
            let Modes::Real { poles, .. } = &x.modes else {
                panic!("real poles")
            };
            if closed_form_holds(poles) {
                walk_matches_exact(&x);
                tried += 1;
            }
        }
    }

    #[test]
    fn two_and_three_lags_walk_exactly_even_when_they_meet() {
        for (t1, t2, t3) in [
            (30.0, 5.0, 1.0),
            (10.0, 10.0 * (1.0 + 1e-9), 9.99),
            (8.0, 8.0, 8.0),
        ] {
            walk_matches_exact(&three_lags((t1, t2, t3)));
        }
    }

    /// A P3's transient with lags `(t1, t2, t3)` and coefficients 1, −0.7, 0.3.
    fn three_lags((t1, t2, t3): (f64, f64, f64)) -> Transient {
        transient(
            "P3",
            &[
                (Param::Tp1, t1),
                (Param::Tp2, t2),
                (Param::Tp3, t3),
                (Param::X1, 1.0),
                (Param::X2, -0.7),
                (Param::X3, 0.3),
            ],
        )
    }

    #[test]
    fn the_basis_sums_to_the_transient_it_is_the_derivative_of() {
        // x = Σ Xᵢ·φᵢ, linear in the coefficients: the basis a fit's Jacobian reads as their
        // columns, with the coefficients, gives back what add_to adds, for every kind of
        // modes (closed form, walked, a pair with a third pole).
        let pair = transient(
            "P3U",
            &[
                (Param::Tw, 3.0),
                (Param::Zeta, 0.3),
                (Param::Tp3, 2.0),
                (Param::X1, 1.0),
                (Param::X2, 0.5),
                (Param::X3, -0.4),
            ],
        );
        let times: Vec<f64> = (0..900)
            .map(|k| 0.37 * k as f64 + 0.01 * (k % 7) as f64)
            .collect();
        for x in [
            three_lags((30.0, 5.0, 1.0)),
            three_lags((8.0, 8.0, 8.0)),
            transient(
                "P2",
                &[
                    (Param::Tp1, 4.0),
                    (Param::Tp2, 4.0),
                    (Param::X1, 2.0),
                    (Param::X2, 1.0),
                ],
            ),
            pair,
        ] {
            let mut added = vec![0.0; times.len()];
            x.add_to(&times, -0.5, &mut added);
            let mut basis = vec![vec![0.0; times.len()]; x.coefficients().len()];
            x.basis_into(&times, -0.5, &mut basis);
            for (k, a) in added.iter().enumerate() {
                let sum: f64 = basis
                    .iter()
                    .zip(x.coefficients())
                    .map(|(b, c)| c * b[k])
                    .sum();
                assert!(
                    (sum - a).abs() <= 1e-13 * a.abs().max(1.0),
                    "k {k}: {sum} vs {a}"
                );
            }
        }
    }

    #[test]
    fn an_underdamped_pair_is_its_closed_form() {
        let x = transient(
            "P2U",
            &[
                (Param::Tw, 3.0),
                (Param::Zeta, 0.3),
                (Param::X1, 1.0),
                (Param::X2, 0.5),
            ],
        );
        walk_matches_exact(&x);
    }
}
