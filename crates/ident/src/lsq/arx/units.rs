//! The units least squares solves in, so that ARX and RLS give the same answers at any scale
//! of the record (a record at 1e300 or 1e-300 as at 1): what this module owns is the change
//! of units and the sums that must not overflow or underflow.
//!
//! - **Equilibration** ([`Equilibrated`]): column c of Φ is divided by its largest magnitude
//!   s_c, Y by its largest magnitude s_Y (an all-zero one by 1). Then Ỹ = Φ̃θ̃ with
//!   θ̃_c = θ_c·s_c/s_Y: the a's (columns of −y) come out as they are, a b by s_u/s_y, the
//!   constant by 1/s_y. The sizes are maxima, which scale with the data exactly
//!   (max|k·x| = k·max|x|), so a record scaled by 10^k solves the same problem to rounding:
//!   QR's norms and RLS's P never over- or underflow, and the collinearity threshold, the α of
//!   RLS's P0 = α·I and the exact-fit rule mean the same at every scale.
//! - **Mapping back**: θ_c = θ̃_c·s_Y/s_c, se_c likewise, E = s_Y·Ẽ. A parameter beyond
//!   double precision in the record's units (a gain of 1e600 output units per input unit) is
//!   refused with its order of magnitude.
//! - **The cost** ([`Cost`]): J = s_Y²·J̃ lies beyond double precision for a record near
//!   1e±300 (J ≈ 1e±600), so it is kept as J̃ and s_Y: its value when a double holds it, its
//!   log10 always, the AIC from ln J̃ + 2 ln s_Y, and J relative to Σ(y − ȳ)², which decides
//!   whether a fit is exact to rounding ([`ROUNDING_LEVEL`]).
//! - **Sums** ([`mean`], [`fit_percent`]): taken on the values divided by a power of two near
//!   their magnitude, which is exact (a record of ordinary size gives the same bits as the
//!   plain sums), so they neither overflow at 1e300 nor underflow at 1e-300.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::{LeastSquares, LsqError, Regression, Regressor};
use crate::stats::{binary_unit, mean};

/// J below this share of Σ(y − ȳ)² is at rounding level: the fit is exact.
pub const ROUNDING_LEVEL: f64 = 1e-20;

/// The Euclidean norm of `terms`, without overflow or underflow at any scale.
fn norm(terms: &[f64]) -> f64 {
    let unit = binary_unit(terms.iter().copied());
    unit * terms
        .iter()
        .map(|x| (x / unit) * (x / unit))
        .sum::<f64>()
        .sqrt()
}

/// The project's fit %: 100·(1 − ‖y − ŷ‖/‖y − ȳ‖); NaN for a constant (or empty) y, −∞ when
/// ŷ is not finite (a simulation that diverges).
pub fn fit_percent(y: &[f64], yhat: &[f64]) -> f64 {
    let n = y.len().min(yhat.len());
    if yhat[..n].iter().any(|v| !v.is_finite()) {
        return f64::NEG_INFINITY;
    }
    let ybar = mean(&y[..n]);
    let spread: Vec<f64> = y[..n].iter().map(|v| v - ybar).collect();
    let miss: Vec<f64> = y[..n].iter().zip(&yhat[..n]).map(|(a, b)| a - b).collect();
    let spread = norm(&spread);
    if spread > 0.0 {
        100.0 * (1.0 - norm(&miss) / spread)
    } else {
        f64::NAN
    }
}

/// J = EᵀE in the record's units, kept as J̃ in the solving units and the output's unit
/// (J = J̃·s_Y²), since J itself may lie beyond double precision.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Cost {
    /// J̃ = ẼᵀẼ in the solving units.
    pub solved: f64,
    /// s_Y, the output's unit (record units per solving unit).
    pub output_unit: f64,
    /// Σ(Ỹ − mean Ỹ)² over the same rows, in the solving units (0 for a constant output).
    pub output_spread: f64,
}

impl Cost {
    /// J in the record's units, 0 or ∞ where a double cannot hold it (see [`Cost::value`]).
    pub fn raw(&self) -> f64 {
        self.solved * self.output_unit * self.output_unit
    }

    /// J when a double holds it (0, or a normal number), `None` beyond double precision.
    pub fn value(&self) -> Option<f64> {
        let j = self.raw();
        (self.solved == 0.0 || j.is_normal()).then_some(j)
    }

    /// log₁₀ J (−∞ for an exact zero).
    pub fn log10(&self) -> f64 {
        self.solved.log10() + 2.0 * self.output_unit.log10()
    }

    /// J/Σ(y − ȳ)²: the share of the output's variation left unexplained (scale-free).
    pub fn relative(&self) -> f64 {
        self.solved / self.output_spread
    }

    /// Whether J is at rounding level: 0, or below [`ROUNDING_LEVEL`] of Σ(y − ȳ)².
    pub fn exact(&self) -> bool {
        self.solved == 0.0 || self.solved <= ROUNDING_LEVEL * self.output_spread
    }

    /// AIC = N·ln(J/N) + 2p + N·(ln 2π + 1) (MATLAB's raw `aic`), from ln J̃ + 2 ln s_Y; J̃/N
    /// is floored at the smallest normal number, so an exact fit stays finite.
    pub fn aic(&self, rows: usize, parameters: usize) -> f64 {
        let n = rows as f64;
        let ln_mse = (self.solved / n).max(f64::MIN_POSITIVE).ln() + 2.0 * self.output_unit.ln();
        n * ln_mse + 2.0 * parameters as f64 + n * ((2.0 * std::f64::consts::PI).ln() + 1.0)
    }
}

/// `x·num/den`, in whichever order keeps it finite and nonzero when it can be.
fn rescaled(x: f64, num: f64, den: f64) -> f64 {
    // The first order that neither overflows nor underflows: num/den last, for subnormal
    // units (a record near 5e-324, where x·num underflows and x/den overflows).
    let tries = [x * num / den, x / den * num, x * (num / den)];
    tries
        .into_iter()
        .find(|v| v.is_finite() && (*v != 0.0 || x == 0.0))
        .unwrap_or(tries[1])
}

/// Φ and Y in the solving units (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Equilibrated {
    pub phi: DMatrix<f64>,
    pub y: DVector<f64>,
    regressors: Vec<Regressor>,
    /// s_c of each column.
    columns: Vec<f64>,
    /// s_Y.
    output: f64,
}

/// The largest magnitude of `v`, 1 when it is 0.
fn largest(v: impl Iterator<Item = f64>) -> f64 {
    let m = v.fold(0.0f64, |m, x| m.max(x.abs()));
    if m > 0.0 { m } else { 1.0 }
}

impl Equilibrated {
    /// `reg` in the solving units.
    pub fn of(reg: &Regression) -> Self {
        let columns: Vec<f64> = reg
            .phi
            .column_iter()
            .map(|c| largest(c.iter().copied()))
            .collect();
        let output = largest(reg.y.iter().copied());
        let mut phi = reg.phi.clone();
        for (mut c, s) in phi.column_iter_mut().zip(&columns) {
            c /= *s;
        }
        Self {
            phi,
            y: &reg.y / output,
            regressors: reg.regressors.clone(),
            columns,
            output,
        }
    }

    /// θ of the record's units in the solving units (entries past the columns kept).
    pub fn theta_in(&self, theta: &[f64]) -> Vec<f64> {
        theta
            .iter()
            .enumerate()
            .map(|(c, &t)| {
                self.columns
                    .get(c)
                    .map_or(t, |&s| rescaled(t, s, self.output))
            })
            .collect()
    }

    /// A value of column c's parameter (θ_c or its standard error) in the record's units.
    fn parameter_out(&self, c: usize, solved: f64) -> Result<f64, LsqError> {
        let value = rescaled(solved, self.output, self.columns[c]);
        if value.is_finite() && (value != 0.0 || solved == 0.0) {
            return Ok(value);
        }
        Err(LsqError::Unrepresentable {
            regressor: self.regressors[c],
            log10: solved.abs().log10() + self.output.log10() - self.columns[c].log10(),
        })
    }

    /// θ̃ in the record's units.
    pub fn theta_out(&self, solved: &[f64]) -> Result<Vec<f64>, LsqError> {
        solved
            .iter()
            .enumerate()
            .map(|(c, &t)| self.parameter_out(c, t))
            .collect()
    }

    /// An error of the solving units (ẽ) in output units.
    pub fn error_out(&self, e: f64) -> f64 {
        e * self.output
    }

    /// θ̃'s figures in the record's units: θ, the residuals, J and the standard errors
    /// σ̂·√dᵢ, σ̂² = J/(N − p), from `variances` dᵢ (the diagonal of (Φ̃ᵀΦ̃)⁻¹, or RLS's P̃;
    /// `None` when N = p).
    pub fn estimate(
        &self,
        theta: &DVector<f64>,
        variances: Option<Vec<f64>>,
    ) -> Result<LeastSquares, LsqError> {
        let (rows, p) = self.phi.shape();
        let e = &self.y - &self.phi * theta;
        let solved = e.norm_squared();
        let ybar = self.y.mean();
        let cost = Cost {
            solved,
            output_unit: self.output,
            output_spread: self.y.iter().map(|v| (v - ybar) * (v - ybar)).sum(),
        };
        let se = match variances {
            Some(d) if rows > p => {
                let sigma = (solved / (rows - p) as f64).sqrt();
                d.iter()
                    .enumerate()
                    .map(|(c, v)| self.parameter_out(c, sigma * v.max(0.0).sqrt()).map(Some))
                    .collect::<Result<_, _>>()?
            }
            _ => vec![None; p],
        };
        Ok(LeastSquares {
            theta: self.theta_out(theta.as_slice())?,
            se,
            residuals: e.iter().map(|&v| self.error_out(v)).collect(),
            j: cost.raw(),
            cost,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_units_are_powers_of_two_in_the_normal_range() {
        assert_eq!(binary_unit([3.0, -5.0]), 4.0);
        assert_eq!(binary_unit([0.0]), 1.0);
        assert_eq!(binary_unit([1e-320]), f64::MIN_POSITIVE);
        assert_eq!(binary_unit([f64::MAX]), 2f64.powi(1023));
    }

    #[test]
    fn sums_hold_at_any_scale_and_give_the_plain_bits_at_unit_scale() {
        let y = [1.0, 2.5, 4.0, 3.0];
        let yhat = [1.1, 2.4, 3.8, 3.1];
        let plain = fit_percent(&y, &yhat);
        for k in [1e300, 1e-300] {
            let ys: Vec<f64> = y.iter().map(|v| v * k).collect();
            let hs: Vec<f64> = yhat.iter().map(|v| v * k).collect();
            assert!((fit_percent(&ys, &hs) - plain).abs() < 1e-12);
            assert!((mean(&ys) / k - 2.625).abs() < 1e-15);
        }
        assert_eq!(mean(&y), y.iter().sum::<f64>() / 4.0);
        assert_eq!(fit_percent(&y, &[f64::INFINITY; 4]), f64::NEG_INFINITY);
        assert!(fit_percent(&[2.0; 3], &[2.0; 3]).is_nan());
    }

    #[test]
    fn a_cost_beyond_double_precision_keeps_its_order_of_magnitude() {
        let c = Cost {
            solved: 4e-22,
            output_unit: 1e300,
            output_spread: 1.0,
        };
        assert_eq!(c.value(), None);
        assert!((c.log10() - (4e-22f64.log10() + 600.0)).abs() < 1e-12);
        assert!(c.exact());
        assert!(!Cost { solved: 4e-18, ..c }.exact());
        let unit = Cost {
            output_unit: 1.0,
            ..c
        };
        let shift = c.aic(10, 2) - unit.aic(10, 2);
        assert!((shift - 20.0 * 1e300f64.ln()).abs() < 1e-9);
    }
}
