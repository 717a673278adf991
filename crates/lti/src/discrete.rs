//! Discrete transfer functions H(z) = B(z)/A(z)·z^−nk with their sampling period h, as MATLAB's
//! `idpoly`/`arx` write them: A(z) = 1 + a1·z⁻¹ + … + a_na·z⁻ⁿᵃ, B(z) = b1 + b2·z⁻¹ + … +
//! b_nb·z^−(nb−1), so that y(k) + a1·y(k−1) + … = b1·u(k−nk) + … + b_nb·u(k−nk−nb+1); nk = 1
//! is the plain delay of a zero-order hold.
//!
//! - **c2d** ([`c2d`]): the exact zero-order-hold discretisation of a
//!   [`TransferFunction`] with its dead time θ, fractional part included: θ = d·h + L with
//!   d whole samples and 0 ≤ L < h, split exactly (L = θ mod h; d up to
//!   [`MAX_DELAY_SAMPLES`], beyond which θ's own rounding is a good part of a sample). Poles and zeros
//!   that are exactly equal cancel first (s/s is the gain 1, whose image is B = [1]). The
//!   denominator has the poles e^{pᵢh}; the numerator comes from the pulse response
//!   g(k) = s(kh) − s((k−1)h) of the step response s(t) of G·e^{−Ls}, through B = A·G
//!   (polynomial product, truncated at n + 1 terms). s(t) is the closed form
//!   ([`crate::StepResponse`]) except near t = 0, where its Taylor series from the
//!   Markov parameters keeps its relative precision ([`crate::markov`]): at h = 1e-9
//!   the samples are 1e-19 where the closed form holds 1e-16. This matches the matrix
//!   exponential of the augmented state matrix (the tests check it) without building a
//!   state-space model, and it handles repeated poles and integrators as the step response
//!   does. The model keeps what c2d knows exactly: its poles e^{pᵢh} and its static gain
//!   G(0) (rounded coefficients near 1 cannot give them back: at h = 1e-9 the sum of A's
//!   coefficients is 1e-19 below their rounding).
//! - **The notes' closed FOPTD formulas** ([`foptd_zoh`]): a1 = −e^{−h/τ},
//!   b0 = K(1 − e^{−(h−L)/τ}), b1 = K·e^{−h/τ}(e^{L/τ} − 1), with nk = d + 1 (the notes'
//!   "θ < h ⇒ d = 1" counts the hold's sample; MATLAB's nk).
//! - **d2c** ([`DiscreteTf::d2c`]): back to G(s)·e^{−θs} for distinct poles: s = ln(z)/h; the
//!   continuous residues rᵢ from the discrete ones cᵢ (matching the step response at the
//!   samples: cᵢ = rᵢ(zᵢ − 1)/pᵢ, or rᵢ = cᵢ/h at z = 1); the dead time (nk − 1)·h, plus, for a
//!   first-order model with two b's, L from the notes' formulas (e^{L/τ} = 1 + b2/(K·e^{−h/τ})).
//!   With nk = 0, or one b more than the order otherwise, H is biproper: G = b1 + the
//!   strictly proper G of (B − b1·A)/A, delayed nk·h. The answer is checked by its defining
//!   equation, c2d(G) = H, and refused when it fails ([`DiscreteError::NoZohEquivalent`]);
//!   a B and an A sharing a root are refused first ([`DiscreteError::CommonFactor`]).
//!
//! Pure math: nothing here knows about the GUI or the command line.

use serde::{Deserialize, Serialize};

use super::markov::EarlyStep;
use super::poly::{self, C64};
use super::root_error;
use super::{LtiError, TransferFunction};

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
    /// What [`c2d`] knows exactly about the model, beyond its rounded coefficients.
    #[serde(skip)]
    sampled: Option<Sampled>,
}

/// The exact poles and static gain of a model built by [`c2d`].
#[derive(Debug, Clone, PartialEq)]
struct Sampled {
    /// e^{pᵢh}.
    poles: Vec<C64>,
    /// G(0) (±∞ with an integrator).
    dc_gain: f64,
}

/// What can go wrong with a discrete transfer function (`crate::words::discrete` says it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
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
    /// More than na + 1 b's: not the ZOH image of a proper G(s)·e^{−θs}.
    NumeratorTooLong { na: usize, nb: usize },
    /// A dead time of more samples than [`MAX_DELAY_SAMPLES`] (θ/h here).
    DelayTooLong { samples: f64 },
    /// A sampling period so short against this continuous pole that e^{p·h} differs from 1
    /// by less than [`MIN_POLE_STEP`]: A(z)'s coefficients could not tell it from an
    /// integrator.
    PeriodTooShort { ts: f64, pole: C64 },
    /// B(z)'s coefficients at this period fall outside double precision's normal range
    /// (they scale as h^r for a relative degree r).
    NumeratorOutOfRange { ts: f64 },
    /// B(z) and A(z) share this root: a pole cancelled by a zero, so H is of lower order
    /// than A says.
    CommonFactor { root: C64 },
    /// The continuous system found does not discretise back to H(z) (c2d(d2c(H)) ≠ H): no
    /// G(s)·e^{−θs} of the forms d2c knows has H's samples.
    NoZohEquivalent,
    /// The continuous system could not be built.
    Lti(#[from] LtiError),
}

/// Coefficients this close to 0 (relative to the largest) at B's ends are dropped by
/// [`c2d`]: the rounding left where the exact coefficient is 0.
const NEGLIGIBLE: f64 = 1e-13;

/// The most samples a dead time may span: up to 2⁴⁰, θ = d·h + L in double precision places
/// θ within 2⁻¹² of a sample, so d is exact and L is known (at θ/h = 1e20, θ's own rounding
/// is 16384 samples).
pub const MAX_DELAY_SAMPLES: usize = 1 << 40;

/// The least |p·h| of a pole p ≠ 0 that [`c2d`] samples: A(z)'s coefficients then hold
/// 1 − e^{p·h} to three digits (at 1e-16 they would hold none, and say z = 1).
pub const MIN_POLE_STEP: f64 = 1e-13;

/// c2d(d2c(H)) must give H's coefficients back to this, relative to the largest of A's and
/// of B's.
const ROUND_TRIP: f64 = 1e-8;

/// A root of A at which B's backward error is below this is a root of B too.
const SHARED_ROOT: f64 = 1e-10;

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
        if nk > MAX_DELAY_SAMPLES {
            return Err(DiscreteError::DelayTooLong { samples: nk as f64 });
        }
        Ok(Self {
            a,
            b,
            nk,
            ts,
            sampled: None,
        })
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

    /// The poles: the roots of z^na + a1·z^(na−1) + … + a_na (for a model of [`c2d`], the
    /// exact e^{pᵢh}).
    pub fn poles(&self) -> Result<Vec<C64>, DiscreteError> {
        if let Some(s) = &self.sampled {
            return Ok(s.poles.clone());
        }
        if self.na() == 0 {
            return Ok(Vec::new());
        }
        Ok(poly::roots(&self.a)?)
    }

    /// The zeros: the roots of b1·z^(nb−1) + … + b_nb. The power of z that the delays leave,
    /// z^(na − nb + 1 − nk), adds zeros (or poles) at z = 0 that are not listed.
    pub fn zeros(&self) -> Result<Vec<C64>, DiscreteError> {
        let first = self.b.iter().position(|&c| c != 0.0).unwrap_or(0);
        if self.b.len() - first <= 1 {
            return Ok(Vec::new());
        }
        Ok(poly::roots(&self.b[first..])?)
    }

    /// The static gain H(1) = ΣB/ΣA (±∞ with a pole at z = 1); for a model of [`c2d`], the
    /// exact G(0).
    pub fn dc_gain(&self) -> f64 {
        match &self.sampled {
            Some(s) => s.dc_gain,
            None => self.b.iter().sum::<f64>() / self.a.iter().sum::<f64>(),
        }
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
    /// docs): distinct poles off the negative real axis, no root shared by B and A, nb ≤
    /// na + 1, and c2d of the answer giving H back.
    pub fn d2c(&self) -> Result<TransferFunction, DiscreteError> {
        let h = self.normalized();
        if h.na() == 0 {
            return Err(DiscreteError::NoPoles);
        }
        h.check_common_factor()?;
        let g = h.continuous()?;
        h.check_round_trip(&g)?;
        Ok(g)
    }

    /// The same H with B's leading zeros counted in nk and its trailing zeros dropped.
    fn normalized(&self) -> Self {
        let first = self.b.iter().position(|&c| c != 0.0).unwrap_or(0);
        let last = self.b.iter().rposition(|&c| c != 0.0).unwrap_or(first);
        Self {
            b: self.b[first..=last].to_vec(),
            nk: self.nk + first,
            ..self.clone()
        }
    }

    /// Refuses a root of A that is a root of B too.
    fn check_common_factor(&self) -> Result<(), DiscreteError> {
        match self
            .poles()?
            .into_iter()
            .find(|&z| root_error::backward_error(&self.b, z) <= SHARED_ROOT)
        {
            Some(root) => Err(DiscreteError::CommonFactor { root }),
            None => Ok(()),
        }
    }

    /// The candidate G(s)·e^{−θs}: biproper (nk = 0, or nb = na + 1 without a first-order
    /// fraction), the notes' first order with a fractional delay, or strictly proper.
    fn continuous(&self) -> Result<TransferFunction, DiscreteError> {
        let (na, nb) = (self.na(), self.b.len());
        if nb > na + 1 {
            return Err(DiscreteError::NumeratorTooLong { na, nb });
        }
        if self.nk == 0 {
            return self.biproper();
        }
        if nb == na + 1 {
            if na == 1
                && let Some(g) = self.first_order_with_fraction()?
            {
                return Ok(g);
            }
            return self.biproper();
        }
        let g = self.strictly_proper()?;
        Ok(g.with_delay((self.nk - 1) as f64 * self.ts)?)
    }

    /// G = b1 + the strictly proper G of (B − b1·A)/A·z⁻¹, delayed nk·h.
    fn biproper(&self) -> Result<TransferFunction, DiscreteError> {
        let direct = self.b[0];
        let len = self.b.len().max(self.a.len());
        let coefficient = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0);
        let rest: Vec<f64> = (1..len)
            .map(|i| coefficient(&self.b, i) - direct * coefficient(&self.a, i))
            .collect();
        let strictly = Self::new(self.a.clone(), rest, 1, self.ts)?.strictly_proper()?;
        let den = strictly.den();
        let mut num = vec![0.0; den.len() - strictly.num().len()];
        num.extend(strictly.num());
        let num: Vec<f64> = num.iter().zip(&den).map(|(n, d)| n + direct * d).collect();
        let g = TransferFunction::from_coeffs(&num, &den)?;
        Ok(g.with_delay(self.nk as f64 * self.ts)?)
    }

    /// G(s) (no delay) of the strictly proper H with nk = 1 and nb ≤ na: the continuous
    /// residues from the discrete ones.
    fn strictly_proper(&self) -> Result<TransferFunction, DiscreteError> {
        let na = self.na();
        let zp = self.poles()?;
        check_poles(&zp)?;
        // The bracket z·H(z) = (b1·z^(na−1) + … + b_nb·z^(na−nb))/A(z), in powers of z.
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
        Ok(TransferFunction::from_coeffs(&num, &den)?)
    }

    /// The notes' FOPTD inverted: τ from a1, K from the static gain, L from b2, when
    /// 0 ≤ L ≤ h (else `None`: no first order with a fractional delay has these samples).
    fn first_order_with_fraction(&self) -> Result<Option<TransferFunction>, DiscreteError> {
        let h = self.ts;
        let pole = -self.a[1];
        check_poles(&[C64::new(pole, 0.0)])?;
        let k = self.dc_gain();
        let s = continuous_pole(C64::new(pole, 0.0), h).re;
        let (b1, b2) = (self.b[0], self.b[1]);
        let (tf, fraction) = if s == 0.0 {
            // An integrator K/s: b1 = K(h − L), b2 = K·L.
            let tf = TransferFunction::from_zpk(&[], &[C64::new(0.0, 0.0)], (b1 + b2) / h)?;
            (tf, h * b2 / (b1 + b2))
        } else {
            // e^{L/τ} = 1 + b2/(K·e^{−h/τ}), with −1/τ = s.
            let tf = TransferFunction::from_zpk(&[], &[C64::new(s, 0.0)], -k * s)?;
            (tf, -(1.0 + b2 / (k * pole)).ln() / s)
        };
        // L is rounding away from [0, h] by at most this.
        let slack = 1e-9 * h;
        if !(fraction >= -slack && fraction <= h + slack) {
            return Ok(None);
        }
        let whole = (self.nk - 1) as f64 * h;
        Ok(Some(tf.with_delay(whole + fraction.clamp(0.0, h))?))
    }

    /// Refuses `g` unless c2d(g) is this H (A and B to [`ROUND_TRIP`], the same delay).
    fn check_round_trip(&self, g: &TransferFunction) -> Result<(), DiscreteError> {
        let back = c2d(g, self.ts)?.normalized();
        if self.nk.abs_diff(back.nk) > self.a.len() + self.b.len() {
            return Err(DiscreteError::NoZohEquivalent);
        }
        let base = self.nk.min(back.nk);
        let same = |x: &[f64], y: &[f64]| {
            let len = x.len().max(y.len());
            let at = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0);
            let scale = x.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            (0..len).all(|i| (at(x, i) - at(y, i)).abs() <= ROUND_TRIP * scale)
        };
        if same(&self.a, &back.a) && same(&self.numerator_from(base), &back.numerator_from(base)) {
            Ok(())
        } else {
            Err(DiscreteError::NoZohEquivalent)
        }
    }

    /// z^{−(nk − base)}·B(z) as coefficients of z⁰, z⁻¹, … (base ≤ nk).
    fn numerator_from(&self, base: usize) -> Vec<f64> {
        let mut out = vec![0.0; self.nk - base];
        out.extend(&self.b);
        out
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

/// A dead time θ = whole·h + fraction, 0 ≤ fraction < h.
#[derive(Debug, Clone, Copy, PartialEq)]
struct DelaySplit {
    whole: usize,
    fraction: f64,
}

/// θ split exactly into whole samples and a fraction (θ mod h is exact in floating point);
/// a fraction within rounding of 0 or h (θ and h typed as decimals: 0.3 = 3 × 0.1) is
/// none. More than [`MAX_DELAY_SAMPLES`] samples is refused.
fn split_delay(theta: f64, h: f64) -> Result<DelaySplit, DiscreteError> {
    let samples = theta / h;
    if samples > MAX_DELAY_SAMPLES as f64 {
        return Err(DiscreteError::DelayTooLong { samples });
    }
    let fraction = theta % h;
    let whole = ((theta - fraction) / h).round() as usize;
    let rounding = 4.0 * f64::EPSILON * theta;
    Ok(if fraction <= rounding {
        DelaySplit {
            whole,
            fraction: 0.0,
        }
    } else if h - fraction <= rounding {
        DelaySplit {
            whole: whole + 1,
            fraction: 0.0,
        }
    } else {
        DelaySplit { whole, fraction }
    })
}

/// The exact ZOH discretisation of `tf` (its dead time included) at period `ts` (s); see the
/// module docs.
pub fn c2d(tf: &TransferFunction, ts: f64) -> Result<DiscreteTf, DiscreteError> {
    if !(ts.is_finite() && ts > 0.0) {
        return Err(DiscreteError::BadSamplingPeriod(ts));
    }
    let DelaySplit { whole, fraction } = split_delay(tf.delay(), ts)?;
    let (zeros, poles) = tf.cancelled_roots();
    let sampled = |d: DiscreteTf, poles: Vec<C64>| DiscreteTf {
        sampled: Some(Sampled {
            poles,
            dc_gain: tf.dc_gain(),
        }),
        ..d
    };
    if poles.is_empty() {
        // A gain: the held input, delayed θ, is read at the samples one sample later when
        // the delay has a fraction.
        let nk = whole + usize::from(fraction > 0.0);
        let d = DiscreteTf::new(vec![1.0], vec![tf.gain()], nk, ts)?;
        return Ok(sampled(d, Vec::new()));
    }
    if let Some(&pole) = poles
        .iter()
        .find(|p| p.norm() != 0.0 && p.norm() * ts < MIN_POLE_STEP)
    {
        return Err(DiscreteError::PeriodTooShort { ts, pole });
    }
    let g = TransferFunction::from_zpk(&zeros, &poles, tf.gain())?;
    let zp: Vec<C64> = poles.iter().map(|p| (*p * ts).exp()).collect();
    let a = poly::poly_from_roots(&zp);
    let (first, b) = zoh_numerator(&g, &a, fraction, ts)?;
    let d = DiscreteTf::new(a, b, first + whole, ts)?;
    Ok(sampled(d, zp))
}

/// B of the ZOH image of G·e^{−Ls} (0 ≤ L < h) over A, as (its first non-zero power of z⁻¹,
/// its coefficients from there).
fn zoh_numerator(
    g: &TransferFunction,
    a: &[f64],
    fraction: f64,
    ts: f64,
) -> Result<(usize, Vec<f64>), DiscreteError> {
    let step = EarlyStep::new(g)?;
    let n = g.order();
    // Pulse response g(0..=n+1) of the held, fractionally delayed system.
    let s: Vec<f64> = (0..=n + 1)
        .map(|k| step.value(k as f64 * ts - fraction))
        .collect();
    let pulse: Vec<f64> = (0..=n + 1)
        .map(|k| if k == 0 { s[0] } else { s[k] - s[k - 1] })
        .collect();
    // B = A·G truncated: coefficient of z^−j for j = 0..=n+1.
    let mut c: Vec<f64> = (0..=n + 1)
        .map(|j| (0..=j.min(n)).map(|i| a[i] * pulse[j - i]).sum())
        .collect();
    if g.relative_degree() > 0 || fraction > 0.0 {
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
    if c.iter().all(|&x| x == 0.0) || c.iter().any(|x| !x.is_finite() || x.is_subnormal()) {
        return Err(DiscreteError::NumeratorOutOfRange { ts });
    }
    let first = c.iter().position(|&x| x != 0.0).unwrap_or(0);
    let last = c.iter().rposition(|&x| x != 0.0).unwrap_or(first);
    Ok((first, c[first..=last].to_vec()))
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
    let DelaySplit { whole, fraction: l } = split_delay(theta, ts)?;
    let a1 = -(-ts / tau).exp();
    let b0 = -k * (-(ts - l) / tau).exp_m1();
    let b1 = k * (-ts / tau).exp() * (l / tau).exp_m1();
    DiscreteTf::new(vec![1.0, a1], vec![b0, b1], whole + 1, ts)
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
        let tf = TransferFunction::from_coeffs(&[1.5, 4.5], &[1.0, 3.0, 2.0])
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
        assert!((back.zeros()[0].re + 3.0).abs() < 1e-8);
    }

    #[test]
    fn a_pole_equal_to_a_zero_cancels_before_sampling() {
        // 1.5(s + 2)/((s + 1)(s + 2)) is 1.5/(s + 1).
        let tf = TransferFunction::from_coeffs(&[1.5, 3.0], &[1.0, 3.0, 2.0]).unwrap();
        let d = c2d(&tf, 0.2).unwrap();
        assert_eq!(d.na(), 1);
        assert_eq!(d.poles().unwrap(), vec![C64::new((-0.2f64).exp(), 0.0)]);
        assert_eq!(d.dc_gain(), 1.5);
    }

    #[test]
    fn the_zoh_image_of_a_double_integrator_has_its_zero_at_minus_one() {
        // 1/s² → h²(z + 1)/(2(z − 1)²).
        let tf = TransferFunction::from_coeffs(&[1.0], &[1.0, 0.0, 0.0]).unwrap();
        let z = c2d(&tf, 0.1).unwrap().zeros().unwrap();
        assert_eq!(z.len(), 1);
        assert!((z[0] - C64::new(-1.0, 0.0)).norm() < 1e-12, "{z:?}");
        let d = DiscreteTf::new(vec![1.0, -1.5, 0.5], vec![0.0, 2.0, -1.0], 1, 1.0).unwrap();
        assert_eq!(d.zeros().unwrap(), vec![C64::new(0.5, 0.0)]);
        let gain = DiscreteTf::new(vec![1.0, -0.5], vec![3.0], 1, 1.0).unwrap();
        assert!(gain.zeros().unwrap().is_empty());
    }

    #[test]
    fn simulate_follows_the_difference_equation() {
        let d = DiscreteTf::new(vec![1.0, -0.5], vec![1.0], 2, 1.0).unwrap();
        assert_eq!(d.step(5), vec![0.0, 0.0, 1.0, 1.5, 1.75]);
        assert!((d.dc_gain() - 2.0).abs() < 1e-15);
    }
}
