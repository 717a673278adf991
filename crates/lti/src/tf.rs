//! Transfer functions G(s) = k·Π(s − zᵢ)/Π(s − pⱼ)·e^{−θs}, kept in zero-pole-gain form.
//!
//! `gain` is the k of the zero-pole-gain form, as in MATLAB's and python-control's `zpk`
//! (not the static gain: that is [`TransferFunction::dc_gain`], the notes' "ganho estático").
//! The transport delay θ (seconds) is carried exactly, never replaced by a Padé approximant.
//! Coefficient input follows MATLAB's `tf(num, den)`: descending powers of s.

use serde::{Deserialize, Serialize};

use super::poly::{self, C64};
use super::root_error;
use super::{LtiError, Polynomial, Quantity, RootRole};

/// The largest order accepted: far above anything taught, and it keeps every computation
/// (roots, partial fractions, metrics) inside its accuracy and time budget.
pub const MAX_ORDER: usize = 30;

/// Two roots of a real system are taken as one conjugate pair when they mirror each other
/// to this relative tolerance.
const PAIR_TOLERANCE: f64 = 1e-9;

/// A SISO continuous-time transfer function with an optional transport delay.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TransferFunction {
    zeros: Vec<C64>,
    poles: Vec<C64>,
    gain: f64,
    delay: f64,
}

/// Where the poles lie, the classical classification of a step response's fate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Stability {
    /// Every pole strictly in the left half plane.
    Stable,
    /// No pole in the right half plane, but some on the imaginary axis (integrators or
    /// undamped oscillators).
    MarginallyStable,
    /// At least one pole in the right half plane.
    Unstable,
}

impl TransferFunction {
    /// Builds G(s) = k·Π(s − zᵢ)/Π(s − pⱼ) from its zeros, poles and gain k.
    ///
    /// Complex roots must come in conjugate pairs (they are made exactly conjugate); the
    /// system must be proper (no more zeros than poles) and have at least one pole.
    pub fn from_zpk(zeros: &[C64], poles: &[C64], gain: f64) -> Result<Self, LtiError> {
        if poles.is_empty() {
            return Err(LtiError::NoPoles);
        }
        if poles.len() > MAX_ORDER {
            return Err(LtiError::OrderTooHigh(poles.len()));
        }
        if zeros.len() > poles.len() {
            return Err(LtiError::Improper {
                num_degree: zeros.len(),
                den_degree: poles.len(),
            });
        }
        if gain.is_nan() || gain.is_infinite() {
            // Typed gains are finite: this one was computed and overflowed.
            return Err(LtiError::GainOutOfRange);
        }
        if gain == 0.0 {
            return Err(LtiError::BadGain(gain));
        }
        if gain.is_subnormal() {
            return Err(LtiError::Subnormal {
                what: Quantity::Gain,
                value: gain,
            });
        }
        Ok(Self {
            zeros: paired(zeros, RootRole::Zero)?,
            poles: paired(poles, RootRole::Pole)?,
            gain,
            delay: 0.0,
        })
    }

    /// Builds G(s) = num(s)/den(s) from coefficients in descending powers, as MATLAB's
    /// `tf(num, den)`. Leading zero coefficients are dropped, as MATLAB does.
    pub fn from_coeffs(num: &[f64], den: &[f64]) -> Result<Self, LtiError> {
        let num = poly::strip_leading_zeros(num, Polynomial::Numerator)?;
        let den = poly::strip_leading_zeros(den, Polynomial::Denominator)?;
        if num.len() > den.len() {
            return Err(LtiError::Improper {
                num_degree: num.len() - 1,
                den_degree: den.len() - 1,
            });
        }
        if den.len() == 1 {
            return Err(LtiError::NoPoles);
        }
        if den.len() - 1 > MAX_ORDER {
            return Err(LtiError::OrderTooHigh(den.len() - 1));
        }
        let gain = num[0] / den[0];
        if !gain.is_normal() {
            return Err(LtiError::GainOutOfRange);
        }
        let zeros = poly::roots(&num)?;
        let poles = poly::roots(&den)?;
        Self::from_zpk(&zeros, &poles, gain)
    }

    /// The same system with a transport delay θ ≥ 0 seconds.
    pub fn with_delay(mut self, delay: f64) -> Result<Self, LtiError> {
        if !delay.is_finite() || delay < 0.0 {
            return Err(LtiError::BadDelay(delay));
        }
        self.delay = delay;
        Ok(self)
    }

    /// The same poles and zeros with k scaled so that the static gain G(0) equals `dc_gain`.
    pub fn with_dc_gain(mut self, dc_gain: f64) -> Result<Self, LtiError> {
        if !dc_gain.is_finite() || dc_gain == 0.0 {
            return Err(LtiError::BadGain(dc_gain));
        }
        let current = self.dc_gain();
        if !current.is_finite() || current == 0.0 {
            return Err(LtiError::DcGainNotScalable(current));
        }
        self.gain *= dc_gain / current;
        if !self.gain.is_normal() {
            return Err(LtiError::GainOutOfRange);
        }
        Ok(self)
    }

    /// Zeros, conjugate pairs adjacent (upper member first).
    pub fn zeros(&self) -> &[C64] {
        &self.zeros
    }

    /// Poles, conjugate pairs adjacent (upper member first).
    pub fn poles(&self) -> &[C64] {
        &self.poles
    }

    /// The k of the zero-pole-gain form.
    pub fn gain(&self) -> f64 {
        self.gain
    }

    /// Transport delay θ in seconds.
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// Numerator coefficients, descending powers.
    pub fn num(&self) -> Vec<f64> {
        poly::poly_from_roots(&self.zeros)
            .into_iter()
            .map(|c| c * self.gain)
            .collect()
    }

    /// Denominator coefficients, descending powers, monic.
    pub fn den(&self) -> Vec<f64> {
        poly::poly_from_roots(&self.poles)
    }

    /// Order: the number of poles.
    pub fn order(&self) -> usize {
        self.poles.len()
    }

    /// Relative degree: poles minus zeros (0 means direct feedthrough, a biproper system).
    pub fn relative_degree(&self) -> usize {
        self.poles.len() - self.zeros.len()
    }

    /// System type: the net number of poles at the origin (integrators), after exact
    /// cancellation against zeros at the origin; negative means net differentiators.
    pub fn system_type(&self) -> i32 {
        count_origin(&self.poles) as i32 - count_origin(&self.zeros) as i32
    }

    /// The static gain G(0) = lim_{s→0} G(s): ±∞ for a system with an integrator, 0 for one
    /// with a zero at the origin. Roots at the origin cancel exactly first, so s/s gives 1.
    pub fn dc_gain(&self) -> f64 {
        let net = self.system_type();
        let (zeros, poles) = (
            product_neg_nonzero(&self.zeros),
            product_neg_nonzero(&self.poles),
        );
        // k·Πz first, unless it leaves the normal range (k = 2.2e-308 times a zero of 2e-10
        // lost 8 digits as a subnormal before the division brought it back).
        let first = self.gain * zeros;
        let value = if first.is_normal() {
            first / poles
        } else {
            self.gain * (zeros / poles)
        };
        match net {
            0 => value,
            n if n > 0 => value.signum() * f64::INFINITY,
            _ => 0.0,
        }
    }

    /// Where the poles lie. A pole exactly cancelled by an equal zero does not count.
    pub fn stability(&self) -> Stability {
        let poles = self.uncancelled_poles();
        if poles.iter().any(|p| p.re > 0.0) {
            Stability::Unstable
        } else if poles.iter().any(|p| p.re == 0.0) {
            Stability::MarginallyStable
        } else {
            Stability::Stable
        }
    }

    /// True when every (uncancelled) pole lies strictly in the left half plane.
    pub fn is_stable(&self) -> bool {
        self.stability() == Stability::Stable
    }

    /// Poles left after removing those exactly equal to a zero.
    pub fn uncancelled_poles(&self) -> Vec<C64> {
        self.cancelled_roots().1
    }

    /// The zeros and the poles left after each pole exactly equal to a zero cancels with it
    /// (s/s is 1): the same G(s), of the lowest order its roots show.
    pub fn cancelled_roots(&self) -> (Vec<C64>, Vec<C64>) {
        let mut zeros = self.zeros.clone();
        let mut poles = Vec::with_capacity(self.poles.len());
        for &p in &self.poles {
            match zeros.iter().position(|&z| z == p) {
                Some(i) => {
                    zeros.remove(i);
                }
                None => poles.push(p),
            }
        }
        (zeros, poles)
    }

    /// G evaluated at a complex frequency s (delay included).
    pub fn eval(&self, s: C64) -> C64 {
        let num: C64 = self.zeros.iter().map(|&z| s - z).product();
        let den: C64 = self.poles.iter().map(|&p| s - p).product();
        num / den * self.gain * (-s * self.delay).exp()
    }

    /// The series connection G·H (MATLAB's `G*H`): the zeros, poles and delays of both, the
    /// gains multiplied. Nothing cancels (a pole of one equal to a zero of the other stays,
    /// as in MATLAB; [`Self::cancelled_roots`] shows it).
    pub fn series(&self, other: &Self) -> Result<Self, LtiError> {
        let zeros: Vec<C64> = self.zeros.iter().chain(&other.zeros).copied().collect();
        let poles: Vec<C64> = self.poles.iter().chain(&other.poles).copied().collect();
        Self::from_zpk(&zeros, &poles, self.gain * other.gain)?.with_delay(self.delay + other.delay)
    }

    /// The unity-feedback closed loop Kp·G/(1 + Kp·G), MATLAB's `feedback(Kp*G, 1)`: its
    /// poles are the roots of den + Kp·num, refused ([`LtiError::LoopPolesUnresolved`]) when
    /// double precision cannot give them right (a root that is not one to
    /// [`root_error::BACKWARD_LIMIT`], or whose side of the imaginary axis rounding hides).
    pub fn closed_loop(&self, kp: f64) -> Result<Self, LtiError> {
        let (num, den) = self.closed_loop_coeffs(kp)?;
        let cl = Self::from_coeffs(&num, &den)?;
        if root_error::resolved(&den, cl.poles()) {
            Ok(cl)
        } else {
            Err(LtiError::LoopPolesUnresolved { kp })
        }
    }

    /// The closed loop's Kp·num and den + Kp·num (descending powers), both divided by the
    /// leading coefficient of den + Kp·num (1 unless G is biproper): the closed loop as
    /// computed from the coefficients, not rebuilt from its roots. A coefficient beyond
    /// double precision's range is [`LtiError::LoopPolesUnresolved`].
    pub fn closed_loop_coeffs(&self, kp: f64) -> Result<(Vec<f64>, Vec<f64>), LtiError> {
        if !kp.is_finite() {
            return Err(LtiError::BadLoopGain(kp));
        }
        if self.delay != 0.0 {
            return Err(LtiError::DelayInLoop);
        }
        // Kp·k first: k·Π(s − zᵢ) alone may underflow where Kp·k·Π(s − zᵢ) does not (k =
        // 1e-295 around a Padé numerator whose constant term is 1.2e-37 lost it, and the
        // closed loop gained a zero and a pole at 0).
        let k = self.gain * kp;
        let num: Vec<f64> = if k.is_finite() && k != 0.0 {
            poly::poly_from_roots(&self.zeros)
                .into_iter()
                .map(|c| c * k)
                .collect()
        } else {
            self.num().iter().map(|c| c * kp).collect()
        };
        let mut den = self.den();
        let offset = den.len() - num.len();
        for (i, c) in num.iter().enumerate() {
            den[offset + i] += c;
        }
        if num.iter().chain(&den).any(|c| !c.is_finite()) {
            return Err(LtiError::LoopPolesUnresolved { kp });
        }
        let den = poly::strip_leading_zeros(&den, Polynomial::Denominator)?;
        let lead = den[0];
        Ok((
            num.iter().map(|c| c / lead).collect(),
            den.iter().map(|c| c / lead).collect(),
        ))
    }

    /// A one-line description in factored form with every digit, e.g.
    /// `0.5 (s+10) / ((s+1-2j)(s+1+2j)(s+5))` (the shortest text that reads back as each
    /// number: for code, logs and messages about one system).
    pub fn describe(&self) -> String {
        self.describe_with(super::exact)
    }

    /// The factored form for people: six significant digits
    /// ([`super::number::format_number`]), so a root computed as 1.0000000000000002 reads 1.
    pub fn describe_rounded(&self) -> String {
        self.describe_with(super::number::format_number)
    }

    /// The factored form with each number written by `number`.
    fn describe_with(&self, number: fn(f64) -> String) -> String {
        let factors = |roots: &[C64]| {
            roots
                .iter()
                .map(|&r| linear_factor(r, number))
                .collect::<String>()
        };
        let num = if self.zeros.is_empty() {
            String::new()
        } else {
            format!(" {}", factors(&self.zeros))
        };
        let delay = if self.delay > 0.0 {
            format!(" e^(-{} s)", number(self.delay))
        } else {
            String::new()
        };
        // One factor carries its own parentheses; a product needs them around it.
        let den = match self.poles.len() {
            1 => factors(&self.poles),
            _ => format!("({})", factors(&self.poles)),
        };
        format!("{}{num} / {den}{delay}", number(self.gain))
    }
}

/// `(s+1-2j)` for the root −1+2j, `s` for the origin, each number written by `number`.
fn linear_factor(root: C64, number: fn(f64) -> String) -> String {
    let signed = |v: f64| {
        if v < 0.0 {
            format!("-{}", number(-v))
        } else {
            format!("+{}", number(v))
        }
    };
    match (root.re == 0.0, root.im == 0.0) {
        (true, true) => "s".into(),
        (_, true) => format!("(s{})", signed(-root.re)),
        (true, false) => format!("(s{}j)", signed(-root.im)),
        (false, false) => format!("(s{}{}j)", signed(-root.re), signed(-root.im)),
    }
}

/// Number of roots exactly at the origin.
fn count_origin(roots: &[C64]) -> usize {
    roots.iter().filter(|r| r.re == 0.0 && r.im == 0.0).count()
}

/// Π(−r) over the roots that are not at the origin (real for a conjugate-closed set).
pub(crate) fn product_neg_nonzero(roots: &[C64]) -> f64 {
    roots
        .iter()
        .filter(|r| !(r.re == 0.0 && r.im == 0.0))
        .map(|&r| -r)
        .product::<C64>()
        .re
}

/// Validates user roots: finite, complex ones in conjugate pairs; returns them exactly
/// conjugate-closed and sorted.
fn paired(roots: &[C64], what: RootRole) -> Result<Vec<C64>, LtiError> {
    if let Some(index) = roots
        .iter()
        .position(|r| !r.re.is_finite() || !r.im.is_finite())
    {
        return Err(LtiError::NonFiniteRoot {
            what,
            index: index + 1,
        });
    }
    if let Some((index, value)) = roots.iter().enumerate().find_map(|(i, r)| {
        [r.re, r.im]
            .into_iter()
            .find(|x| x.is_subnormal())
            .map(|x| (i, x))
    }) {
        return Err(LtiError::Subnormal {
            what: Quantity::Root {
                role: what,
                index: index + 1,
            },
            value,
        });
    }
    let mut lower: Vec<C64> = roots.iter().copied().filter(|r| r.im < 0.0).collect();
    for upper in roots.iter().filter(|r| r.im > 0.0) {
        // The nearest partner within the tolerance: in a cluster of pairs the first one
        // within it may be another pair's, which would leave a root unpaired.
        let tol = PAIR_TOLERANCE * upper.norm();
        let nearest = lower
            .iter()
            .enumerate()
            .map(|(i, l)| (i, (l.conj() - upper).norm()))
            .filter(|&(_, d)| d <= tol)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match nearest.map(|(i, _)| i) {
            Some(i) => {
                lower.swap_remove(i);
            }
            None => return Err(LtiError::UnpairedComplexRoot { what, root: *upper }),
        }
    }
    if let Some(l) = lower.first() {
        return Err(LtiError::UnpairedComplexRoot { what, root: *l });
    }
    Ok(poly::conjugate_closed(roots.to_vec()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    fn notes_third_order() -> TransferFunction {
        TransferFunction::from_zpk(&[], &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)], 0.5).unwrap()
    }

    #[test]
    fn a_series_connection_evaluates_to_the_product() {
        let g = notes_third_order().with_delay(0.5).unwrap();
        let h = TransferFunction::from_coeffs(&[2.0, 1.0], &[3.0, 0.0])
            .unwrap()
            .with_delay(0.25)
            .unwrap();
        let gh = g.series(&h).unwrap();
        assert_eq!((gh.order(), gh.delay()), (4, 0.75));
        for s in [c(0.3, 1.0), c(-0.2, 4.0), c(2.0, -0.5)] {
            let (a, b) = (gh.eval(s), g.eval(s) * h.eval(s));
            assert!((a - b).norm() <= 1e-14 * b.norm(), "{a} vs {b}");
        }
    }

    #[test]
    fn describe_writes_the_factored_form_with_one_pair_of_parentheses_per_factor() {
        assert_eq!(
            notes_third_order().describe(),
            "0.5 / ((s+1-2j)(s+1+2j)(s+5))"
        );
        let first = TransferFunction::from_zpk(&[c(-10.0, 0.0)], &[c(-5.0, 0.0)], 2.0).unwrap();
        assert_eq!(first.describe(), "2 (s+10) / (s+5)");
        let integrator = TransferFunction::from_zpk(&[], &[c(0.0, 0.0)], 1.0).unwrap();
        assert_eq!(integrator.describe(), "1 / s");
        let extreme =
            TransferFunction::from_zpk(&[], &[c(-1e200, 0.0), c(-2.5e-7, 0.0)], 1.0).unwrap();
        assert_eq!(extreme.describe(), "1 / ((s+2.5e-7)(s+1e200))");
    }

    #[test]
    fn the_rounded_description_has_six_digits() {
        let g = TransferFunction::from_zpk(
            &[],
            &[c(-1.0000000000000002, 2.0), c(-1.0000000000000002, -2.0)],
            0.5,
        )
        .unwrap();
        assert_eq!(g.describe_rounded(), "0.5 / ((s+1-2j)(s+1+2j))");
        assert!(g.describe().contains("1.0000000000000002"));
    }

    #[test]
    fn zpk_to_coefficients_matches_the_notes() {
        let g = notes_third_order();
        let den = g.den();
        assert_eq!(den.len(), 4);
        for (a, b) in den.iter().zip([1.0, 7.0, 15.0, 25.0]) {
            assert!((a - b).abs() < 1e-12);
        }
        assert_eq!(g.num(), vec![0.5]);
        assert!((g.dc_gain() - 0.02).abs() < 1e-15);
        assert_eq!(g.order(), 3);
        assert_eq!(g.relative_degree(), 3);
        assert!(g.is_stable());
    }

    #[test]
    fn closed_loop_of_the_notes_example() {
        let g = TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0]).unwrap();
        let cl = g.closed_loop(1.0).unwrap();
        for (a, b) in cl.den().iter().zip([1.0, 7.0, 15.0, 25.5]) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
        // The notes' zpk(FTMF): (s+5.025)(s^2 + 1.975s + 5.075).
        assert!(
            cl.poles()
                .iter()
                .any(|p| (p.re + 5.025).abs() < 1e-3 && p.im == 0.0)
        );
    }

    #[test]
    fn improper_and_degenerate_systems_are_refused() {
        assert!(matches!(
            TransferFunction::from_coeffs(&[1.0, 0.0, 0.0], &[1.0, 1.0]),
            Err(LtiError::Improper {
                num_degree: 2,
                den_degree: 1
            })
        ));
        assert_eq!(
            TransferFunction::from_zpk(&[], &[], 1.0),
            Err(LtiError::NoPoles)
        );
        assert_eq!(
            TransferFunction::from_coeffs(&[1.0], &[3.0]),
            Err(LtiError::NoPoles)
        );
        assert!(TransferFunction::from_coeffs(&[f64::NAN], &[1.0, 1.0]).is_err());
        assert!(TransferFunction::from_coeffs(&[1.0], &[1.0, f64::INFINITY]).is_err());
        assert!(TransferFunction::from_coeffs(&[0.0], &[1.0, 1.0]).is_err());
        assert!(matches!(
            TransferFunction::from_zpk(&[], &[c(-1.0, 1.0)], 1.0),
            Err(LtiError::UnpairedComplexRoot { .. })
        ));
        assert!(TransferFunction::from_zpk(&[], &[c(f64::NAN, 0.0)], 1.0).is_err());
        assert!(TransferFunction::from_zpk(&[], &[c(-1.0, 0.0)], 0.0).is_err());
        assert!(notes_third_order().with_delay(-1.0).is_err());
    }

    #[test]
    fn leading_zero_coefficients_are_dropped() {
        let g = TransferFunction::from_coeffs(&[0.0, 0.0, 2.0], &[0.0, 1.0, 4.0]).unwrap();
        assert_eq!(g.order(), 1);
        assert!((g.dc_gain() - 0.5).abs() < 1e-15);
    }

    #[test]
    fn zero_over_zero_dc_gain_cancels_at_the_origin() {
        let g = TransferFunction::from_coeffs(&[1.0, 0.0], &[1.0, 0.0]).unwrap();
        assert_eq!(g.dc_gain(), 1.0);
        assert_eq!(g.system_type(), 0);
        let integrator = TransferFunction::from_coeffs(&[1.0], &[1.0, 2.0, 0.0]).unwrap();
        assert_eq!(integrator.dc_gain(), f64::INFINITY);
        assert_eq!(integrator.system_type(), 1);
        assert_eq!(integrator.stability(), Stability::MarginallyStable);
    }

    #[test]
    fn dc_gain_can_be_set() {
        let g = notes_third_order().with_dc_gain(2.0).unwrap();
        assert!((g.dc_gain() - 2.0).abs() < 1e-14);
        assert!((g.gain() - 50.0).abs() < 1e-12);
    }

    #[test]
    fn closed_loop_refuses_a_delay() {
        let g = notes_third_order().with_delay(0.3).unwrap();
        assert_eq!(g.closed_loop(1.0), Err(LtiError::DelayInLoop));
    }

    #[test]
    fn eval_gives_the_frequency_response() {
        let g = TransferFunction::from_coeffs(&[5.0], &[1.0, 5.0]).unwrap();
        let v = g.eval(c(0.0, 5.0));
        assert!((v - c(0.5, -0.5)).norm() < 1e-15);
    }
}
