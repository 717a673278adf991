//! The step response near t = 0, to relative precision: the Markov parameters of G (the
//! coefficients of its expansion at s = ∞, G(s) = D + Σₘ Mₘ·s^{−(m+1)}) give the Taylor
//! series y(τ) = D + Σₘ Mₘ·τ^{m+1}/(m+1)! of the unit-step response.
//!
//! The closed form sums partial fractions whose terms are of the order of the final value,
//! so where y(τ) is far smaller (τ ≪ the fastest time constant, y ~ τ^r for a relative
//! degree r) it holds only absolute precision: y(1e-9) of 2/(10s² + 11s + 1) is 1e-19 and
//! came out as −4e-16. The series' terms fall from the first one where ρτ is small (ρ the
//! largest |pole|), so [`EarlyStep`] sums it up to ρτ = [`SERIES_REACH`] and takes the
//! closed form ([`StepResponse`]) beyond.
//!
//! Pure math: nothing here knows about the GUI or the command line.

use super::{LtiError, StepResponse, TransferFunction};

/// The series is summed while ρτ ≤ this: its terms then grow at most e² times above the
/// sum before they fall.
pub const SERIES_REACH: f64 = 2.0;

/// Terms of the series summed beyond the order: at ρτ ≤ [`SERIES_REACH`], 2^60/60! is far
/// below rounding.
const EXTRA_TERMS: usize = 60;

/// The unit-step response of a rational G (no dead time) at τ ≥ 0, with relative precision
/// near τ = 0.
#[derive(Debug, Clone)]
pub struct EarlyStep {
    /// D = G(∞), the direct feedthrough.
    feedthrough: f64,
    /// d₁ … dₙ of the monic denominator sⁿ + d₁sⁿ⁻¹ + … + dₙ.
    den: Vec<f64>,
    /// r₁ … rₙ of the strictly proper part's numerator (N − D·den), descending powers.
    rest: Vec<f64>,
    /// The largest |pole| (rad/s).
    rho: f64,
    /// The closed form, for ρτ beyond [`SERIES_REACH`].
    closed: StepResponse,
}

impl EarlyStep {
    /// The step response of `g` (its dead time ignored: τ is the time after it).
    pub fn new(g: &TransferFunction) -> Result<Self, LtiError> {
        let undelayed = g.clone().with_delay(0.0)?;
        let closed = StepResponse::new(&undelayed, 1.0)?;
        let den = undelayed.den();
        let mut num = vec![0.0; den.len() - undelayed.num().len()];
        num.extend(undelayed.num());
        let feedthrough = num[0];
        let rest = num[1..]
            .iter()
            .zip(&den[1..])
            .map(|(n, d)| n - feedthrough * d)
            .collect();
        let rho = undelayed
            .poles()
            .iter()
            .map(|p| p.norm())
            .fold(0.0, f64::max);
        Ok(Self {
            feedthrough,
            den: den[1..].to_vec(),
            rest,
            rho,
            closed,
        })
    }

    /// y(τ) (0 before the step, τ < 0).
    pub fn value(&self, tau: f64) -> f64 {
        if tau < 0.0 {
            0.0
        } else if self.rho * tau <= SERIES_REACH {
            self.series(tau)
        } else {
            self.closed.value(tau)
        }
    }

    /// D + Σₘ Mₘ·τ^{m+1}/(m+1)!, with Tₘ = Mₘ·τ^{m+1} from the recurrence of the long
    /// division: Tₘ = r_{m+1}·τ^{m+1} − Σᵢ dᵢτⁱ·T_{m−i}.
    fn series(&self, tau: f64) -> f64 {
        let n = self.den.len();
        let scaled_den: Vec<f64> = (1..=n)
            .map(|i| self.den[i - 1] * tau.powi(i as i32))
            .collect();
        let mut t: Vec<f64> = Vec::with_capacity(n + EXTRA_TERMS);
        let (mut sum, mut factorial) = (self.feedthrough, 1.0);
        for m in 0..n + EXTRA_TERMS {
            let own = self.rest.get(m).map_or(0.0, |r| r * tau.powi(m as i32 + 1));
            let history: f64 = (1..=m.min(n)).map(|i| scaled_den[i - 1] * t[m - i]).sum();
            let tm = own - history;
            t.push(tm);
            factorial *= (m + 1) as f64;
            sum += tm / factorial;
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_order_at_a_nanosecond_keeps_its_digits() {
        // 2/(10s² + 11s + 1) = 0.2/((s + 1)(s + 0.1)): y(τ) = 0.1τ² − 0.0366…τ³ + …
        let g = TransferFunction::from_coeffs(&[2.0], &[10.0, 11.0, 1.0]).unwrap();
        let y = EarlyStep::new(&g).unwrap();
        let tau: f64 = 1e-9;
        let exact = 0.1 * tau * tau - 0.2 * 1.1 * tau.powi(3) / 6.0;
        assert!(
            (y.value(tau) - exact).abs() <= 1e-15 * exact,
            "{}",
            y.value(tau)
        );
    }

    #[test]
    fn the_series_meets_the_closed_form() {
        let g = TransferFunction::from_coeffs(&[1.0, 3.0], &[1.0, 2.0, 5.0, 4.0]).unwrap();
        let y = EarlyStep::new(&g).unwrap();
        let r = StepResponse::new(&g, 1.0).unwrap();
        let reach = SERIES_REACH / y.rho;
        for tau in [0.5 * reach, 0.99 * reach] {
            assert!((y.series(tau) - r.value(tau)).abs() < 1e-14, "τ = {tau}");
        }
    }

    #[test]
    fn an_integrator_and_a_feedthrough_are_exact() {
        let integrator = TransferFunction::from_coeffs(&[3.0], &[1.0, 0.0, 0.0]).unwrap();
        let y = EarlyStep::new(&integrator).unwrap();
        assert_eq!(y.value(2.0), 6.0);
        let biproper = TransferFunction::from_coeffs(&[2.0, 1.0], &[1.0, 1.0]).unwrap();
        let y = EarlyStep::new(&biproper).unwrap();
        assert_eq!(y.value(0.0), 2.0);
        assert_eq!(y.value(-1.0), 0.0);
    }
}
