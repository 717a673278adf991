//! Discrete transfer functions H(z) = B(z)/A(z)·z^−nk with their sampling period h, as MATLAB's
//! `idpoly`/`arx` write them: A(z) = 1 + a1·z⁻¹ + … + a_na·z⁻ⁿᵃ, B(z) = b1 + b2·z⁻¹ + … +
//! b_nb·z^−(nb−1), so that y(k) + a1·y(k−1) + … = b1·u(k−nk) + … + b_nb·u(k−nk−nb+1); nk = 1
//! is the plain delay of a zero-order hold.
//!
//! - **c2d** ([`c2d`]): the exact zero-order-hold discretisation of a
//!   [`TransferFunction`] with its dead time θ, fractional part included: θ = d·h + L with
//!   d = ⌊θ/h⌋ whole samples and 0 ≤ L < h. The denominator has the poles e^{pᵢh}; the
//!   numerator comes from the exact pulse response g(k) = s(kh) − s((k−1)h) of the closed-form
//!   step response s(t) of G·e^{−Ls} ([`crate::lti::StepResponse`]), through B = A·G
//!   (polynomial product, truncated at n + 1 terms). This matches the matrix exponential of
//!   the augmented state matrix (the tests check it) without building a state-space model,
//!   and it handles repeated poles and integrators as the step response does.
//! - **The notes' closed FOPTD formulas** ([`foptd_zoh`]): a1 = −e^{−h/τ},
//!   b0 = K(1 − e^{−(h−L)/τ}), b1 = K·e^{−h/τ}(e^{L/τ} − 1), with nk = d + 1 (the notes'
//!   "θ < h ⇒ d = 1" counts the hold's sample; MATLAB's nk).
//! - **d2c** ([`DiscreteTf::d2c`]): back to G(s)·e^{−θs} for distinct poles: s = ln(z)/h; the
//!   continuous residues rᵢ from the discrete ones cᵢ (matching the step response at the
//!   samples: cᵢ = rᵢ(zᵢ − 1)/pᵢ, or rᵢ = cᵢ/h at z = 1); the dead time (nk − 1)·h, plus, for a
//!   first-order model with two b's, L from the notes' formulas (e^{L/τ} = 1 + b2/(K·e^{−h/τ})).
//!
//! Pure math: nothing here knows about the GUI or the command line.

use serde::{Deserialize, Serialize};

use super::poly::{self, C64};
use super::{LtiError, StepResponse, TransferFunction};

/// A discrete transfer function B(z)/A(z)·z^−nk sampled every `ts` seconds (see the module
/// docs for the convention).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DiscreteTf {
    /// [1, a1, …, a_na].
    a: Vec<f64>,
    /// [b1, …, b_nb].
    b: Vec<f64>,
    /// Delay in samples of b1.
    nk: usize,
    /// Sampling period h (s).
    ts: f64,
}

/// What can go wrong with a discrete transfer function (`crate::text::lsq` says it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum DiscreteError {
    /// The sampling period is not a positive finite number.
    BadSamplingPeriod(f64),
    /// A coefficient is NaN or infinite, or A's first coefficient is not 1.
    BadCoefficients,
    /// B has no coefficient, or every coefficient is 0.
    NoNumerator,
    /// A has no pole (only its leading 1).
    NoPoles,
    /// A pole on the negative real axis or at 0: no continuous system samples to it.
    NoContinuousPole { pole: C64 },
    /// Two poles within 1e-8 of each other: d2c needs distinct poles.
    RepeatedPoles { pole: C64 },
    /// A numerator longer than the denominator's order + 1, or a fractional delay
    /// (nb = na + 1) on a model of order above 1: not the ZOH image of a G(s)·e^{−θs} that
    /// d2c can invert.
    NumeratorTooLong { na: usize, nb: usize },
    /// The continuous system could not be built.
    Lti(LtiError),
}

impl From<LtiError> for DiscreteError {
    fn from(e: LtiError) -> Self {
        DiscreteError::Lti(e)
    }
}

/// Coefficients this close to 0 (relative to the largest) at B's ends are dropped by
/// [`c2d`]: the rounding left where the exact coefficient is 0.
const NEGLIGIBLE: f64 = 1e-13;

impl DiscreteTf {
    /// H(z) from A = [1, a1, …], B = [b1, …], the delay nk (samples) and the period h (s).
    pub fn new(a: Vec<f64>, b: Vec<f64>, nk: usize, ts: f64) -> Result<Self, DiscreteError> {
        if !(ts.is_finite() && ts > 0.0) {
            return Err(DiscreteError::BadSamplingPeriod(ts));
        }
        if a.first() != Some(&1.0) || a.iter().chain(&b).any(|c| !c.is_finite()) {
            return Err(DiscreteError::BadCoefficients);
        }
        if b.iter().all(|&c| c == 0.0) {
            return Err(DiscreteError::NoNumerator);
        }
        Ok(Self { a, b, nk, ts })
    }

    /// [1, a1, …, a_na].
    pub fn a(&self) -> &[f64] {
        &self.a
    }

    /// [b1, …, b_nb].
    pub fn b(&self) -> &[f64] {
        &self.b
    }

    /// The delay of b1 in samples.
    pub fn nk(&self) -> usize {
        self.nk
    }

    /// The sampling period h (s).
    pub fn ts(&self) -> f64 {
        self.ts
    }

    /// The order na of A.
    pub fn na(&self) -> usize {
        self.a.len() - 1
    }

    /// The poles: the roots of z^na + a1·z^(na−1) + … + a_na.
    pub fn poles(&self) -> Result<Vec<C64>, DiscreteError> {
        if self.na() == 0 {
            return Ok(Vec::new());
        }
        Ok(poly::roots(&self.a)?)
    }

    /// The static gain H(1) = ΣB/ΣA (±∞ with a pole at z = 1).
    pub fn dc_gain(&self) -> f64 {
        self.b.iter().sum::<f64>() / self.a.iter().sum::<f64>()
    }

    /// The response to `u` (u(k) at sample k) from rest (zero before the first sample):
    /// y(k) = −a1·y(k−1) − … + b1·u(k−nk) + ….
    pub fn simulate(&self, u: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; u.len()];
        for k in 0..u.len() {
            let mut v = 0.0;
            for (i, &ai) in self.a.iter().enumerate().skip(1) {
                if k >= i {
                    v -= ai * y[k - i];
                }
            }
            for (j, &bj) in self.b.iter().enumerate() {
                if k >= self.nk + j {
                    v += bj * u[k - self.nk - j];
                }
            }
            y[k] = v;
        }
        y
    }

    /// The response to a unit step applied at sample 0, at samples 0..n.
    pub fn step(&self, n: usize) -> Vec<f64> {
        self.simulate(&vec![1.0; n])
    }

    /// The continuous G(s)·e^{−θs} whose ZOH discretisation at h is this H(z) (see the module
    /// docs): distinct poles off the negative real axis, nb ≤ na, or nb = 2 for na = 1.
    pub fn d2c(&self) -> Result<TransferFunction, DiscreteError> {
        let (na, nb) = (self.na(), self.b.len());
        if na == 0 {
            return Err(DiscreteError::NoPoles);
        }
        if nb > na + 1 || (nb == na + 1 && na > 1) {
            return Err(DiscreteError::NumeratorTooLong { na, nb });
        }
        if nb == na + 1 {
            return self.first_order_with_fraction();
        }
        let zp = self.poles()?;
        check_poles(&zp)?;
        // The bracket z^(1−nk)·H(z) = (b1·z^(na−1) + … + b_nb·z^(na−nb))/A(z), in powers of z.
        let mut num_z = self.b.clone();
        num_z.resize(na, 0.0);
        let h = self.ts;
        let sp: Vec<C64> = zp.iter().map(|&z| continuous_pole(z, h)).collect();
        let residues: Vec<C64> = zp
            .iter()
            .zip(&sp)
            .enumerate()
            .map(|(i, (&z, &s))| {
                let others = zp
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .fold(C64::new(1.0, 0.0), |acc, (_, &w)| acc * (z - w));
                let c = poly::eval_complex(&num_z, z) / others;
                if s.norm() == 0.0 {
                    c / h
                } else {
                    c * s / (z - 1.0)
                }
            })
            .collect();
        let num = trim_rounding(&numerator_from_residues(&sp, &residues), &sp, h);
        let den = poly::poly_from_roots(&sp);
        let tf = TransferFunction::from_coeffs(&num, &den)?;
        Ok(tf.with_delay((self.nk.saturating_sub(1)) as f64 * h)?)
    }

    /// The notes' FOPTD inverted: τ from a1, K from the static gain, L from b2.
    fn first_order_with_fraction(&self) -> Result<TransferFunction, DiscreteError> {
        let h = self.ts;
        let pole = -self.a[1];
        check_poles(&[C64::new(pole, 0.0)])?;
        let k = self.dc_gain();
        let s = continuous_pole(C64::new(pole, 0.0), h).re;
        let (b1, b2) = (self.b[0], self.b[1]);
        let tf = if s == 0.0 {
            // An integrator K/s: b1 = K(h − L), b2 = K·L.
            TransferFunction::from_zpk(&[], &[C64::new(0.0, 0.0)], (b1 + b2) / h)?
        } else {
            TransferFunction::from_zpk(&[], &[C64::new(s, 0.0)], -k * s)?
        };
        let fraction = if s == 0.0 {
            h * b2 / (b1 + b2)
        } else {
            // e^{L/τ} = 1 + b2/(K·e^{−h/τ}), with −1/τ = s.
            -(1.0 + b2 / (k * pole)).ln() / s
        };
        let whole = self.nk.saturating_sub(1) as f64 * h;
        Ok(tf.with_delay(whole + fraction.clamp(0.0, h))?)
    }
}

/// Within this of z = 1 a pole is the integrator's, s = 0 (1e-12·h is rounding, not a time
/// constant of 10¹² samples).
const AT_ONE: f64 = 1e-12;

/// s = ln(z)/h, exactly 0 for z within [`AT_ONE`] of 1.
fn continuous_pole(z: C64, h: f64) -> C64 {
    if (z - 1.0).norm() <= AT_ONE {
        C64::new(0.0, 0.0)
    } else {
        z.ln() / h
    }
}

/// Leading coefficients of N(s) (descending powers) that are rounding: |nⱼ|·ωʲ below 1e-9
/// of the largest such term, ω the largest |pole| (1/h without one), so that a
/// relative degree above 1 does not come back with a zero at 10¹⁵.
fn trim_rounding(num: &[f64], poles: &[C64], h: f64) -> Vec<f64> {
    let omega = poles.iter().map(|p| p.norm()).fold(0.0f64, f64::max);
    let omega = if omega > 0.0 { omega } else { 1.0 / h };
    let degree = num.len().saturating_sub(1);
    let weighted: Vec<f64> = num
        .iter()
        .enumerate()
        .map(|(j, c)| c.abs() * omega.powi((degree - j) as i32))
        .collect();
    let largest = weighted.iter().fold(0.0f64, |m, &x| m.max(x));
    let first = weighted
        .iter()
        .position(|&w| w > 1e-9 * largest)
        .unwrap_or(degree);
    num[first..].to_vec()
}

/// Refuses poles with no continuous image, or repeated ones.
fn check_poles(zp: &[C64]) -> Result<(), DiscreteError> {
    for (i, &z) in zp.iter().enumerate() {
        if z.norm() == 0.0 || (z.im == 0.0 && z.re < 0.0) {
            return Err(DiscreteError::NoContinuousPole { pole: z });
        }
        if zp[..i]
            .iter()
            .any(|&w| (z - w).norm() <= 1e-8 * z.norm().max(1.0))
        {
            return Err(DiscreteError::RepeatedPoles { pole: z });
        }
    }
    Ok(())
}

/// N(s) = Σᵢ rᵢ·Π_{j≠i}(s − pⱼ) (descending powers, real parts: the residues of conjugate
/// poles are conjugate).
fn numerator_from_residues(poles: &[C64], residues: &[C64]) -> Vec<f64> {
    let n = poles.len();
    let mut sum = vec![C64::new(0.0, 0.0); n];
    for (i, &r) in residues.iter().enumerate() {
        let mut acc = vec![r];
        for (_, &p) in poles.iter().enumerate().filter(|&(j, _)| j != i) {
            let mut next = vec![C64::new(0.0, 0.0); acc.len() + 1];
            for (m, &c) in acc.iter().enumerate() {
                next[m] += c;
                next[m + 1] -= c * p;
            }
            acc = next;
        }
        for (m, c) in acc.iter().enumerate() {
            sum[m] += *c;
        }
    }
    sum.iter().map(|c| c.re).collect()
}

/// The exact ZOH discretisation of `tf` (its dead time included) at period `ts` (s); see the
/// module docs.
pub fn c2d(tf: &TransferFunction, ts: f64) -> Result<DiscreteTf, DiscreteError> {
    if !(ts.is_finite() && ts > 0.0) {
        return Err(DiscreteError::BadSamplingPeriod(ts));
    }
    let theta = tf.delay();
    let whole = (theta / ts).floor();
    let fraction = (theta - whole * ts).max(0.0);
    let (whole, fraction) = if fraction >= ts {
        (whole + 1.0, 0.0)
    } else {
        (whole, fraction)
    };
    let delayed = tf.clone().with_delay(fraction)?;
    let step = StepResponse::new(&delayed, 1.0)?;
    let n = tf.order();
    let zp: Vec<C64> = tf.poles().iter().map(|p| (*p * ts).exp()).collect();
    let a = poly::poly_from_roots(&zp);
    // Pulse response g(0..=n+1) of the held, fractionally delayed system.
    let s: Vec<f64> = (0..=n + 1).map(|k| step.value(k as f64 * ts)).collect();
    let g: Vec<f64> = (0..=n + 1)
        .map(|k| if k == 0 { s[0] } else { s[k] - s[k - 1] })
        .collect();
    // B = A·G truncated: coefficient of z^−j for j = 0..=n+1.
    let mut c: Vec<f64> = (0..=n + 1)
        .map(|j| (0..=j.min(n)).map(|i| a[i] * g[j - i]).sum())
        .collect();
    let strictly = tf.relative_degree() > 0 || fraction > 0.0;
    if strictly {
        c[0] = 0.0;
    }
    if fraction == 0.0 {
        c[n + 1] = 0.0;
    }
    let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for x in &mut c {
        if x.abs() <= NEGLIGIBLE * scale {
            *x = 0.0;
        }
    }
    let first = c.iter().position(|&x| x != 0.0).unwrap_or(0);
    let last = c.iter().rposition(|&x| x != 0.0).unwrap_or(first);
    DiscreteTf::new(a, c[first..=last].to_vec(), first + whole as usize, ts)
}

/// The notes' closed ZOH formulas for K·e^{−θs}/(τs + 1) at period h (s): a1 = −e^{−h/τ},
/// b0 = K(1 − e^{−(h−L)/τ}), b1 = K·e^{−h/τ}(e^{L/τ} − 1), with θ = d·h + L, nk = d + 1 and
/// B = [b0, b1] (b1 = 0 when L = 0 is kept, so B always has two terms).
pub fn foptd_zoh(k: f64, tau: f64, theta: f64, ts: f64) -> Result<DiscreteTf, DiscreteError> {
    if !(ts.is_finite() && ts > 0.0) {
        return Err(DiscreteError::BadSamplingPeriod(ts));
    }
    if !(tau.is_finite() && tau > 0.0) {
        return Err(DiscreteError::Lti(LtiError::BadGain(tau)));
    }
    if !(theta.is_finite() && theta >= 0.0) {
        return Err(DiscreteError::Lti(LtiError::BadDelay(theta)));
    }
    let d = (theta / ts).floor();
    let l = (theta - d * ts).clamp(0.0, ts);
    let a1 = -(-ts / tau).exp();
    let b0 = -k * (-(ts - l) / tau).exp_m1();
    let b1 = k * (-ts / tau).exp() * (l / tau).exp_m1();
    DiscreteTf::new(vec![1.0, a1], vec![b0, b1], d as usize + 1, ts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_order_without_delay_is_the_textbook_form() {
        let tf = TransferFunction::from_coeffs(&[2.0], &[3.0, 1.0]).unwrap();
        let h = 0.5;
        let d = c2d(&tf, h).unwrap();
        let p = (-h / 3.0f64).exp();
        assert_eq!(d.nk(), 1);
        assert_eq!(d.b().len(), 1);
        assert!((d.a()[1] + p).abs() < 1e-15);
        assert!((d.b()[0] - 2.0 * (1.0 - p)).abs() < 1e-14);
    }

    #[test]
    fn d2c_inverts_c2d_for_a_second_order_with_whole_delay() {
        let tf = TransferFunction::from_coeffs(&[1.5, 3.0], &[1.0, 3.0, 2.0])
            .unwrap()
            .with_delay(0.6)
            .unwrap();
        let d = c2d(&tf, 0.2).unwrap();
        assert_eq!(d.nk(), 4);
        let back = d.d2c().unwrap();
        assert!((back.delay() - 0.6).abs() < 1e-12);
        assert!((back.dc_gain() - tf.dc_gain()).abs() < 1e-10);
        let mut poles: Vec<f64> = back.poles().iter().map(|p| p.re).collect();
        poles.sort_by(f64::total_cmp);
        assert!((poles[0] + 2.0).abs() < 1e-9 && (poles[1] + 1.0).abs() < 1e-9);
        assert!((back.zeros()[0].re + 2.0).abs() < 1e-8);
    }

    #[test]
    fn simulate_follows_the_difference_equation() {
        let d = DiscreteTf::new(vec![1.0, -0.5], vec![1.0], 2, 1.0).unwrap();
        assert_eq!(d.step(5), vec![0.0, 0.0, 1.0, 1.5, 1.75]);
        assert!((d.dc_gain() - 2.0).abs() < 1e-15);
    }
}
