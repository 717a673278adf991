//! Recursive least squares as the course notes write it ("Implementação recursiva"), one new
//! input/output pair per sample:
//!
//! e_k = y(k) − φᵀθ_{k−1},
//! P_k = (P_{k−1} − P_{k−1}φφᵀP_{k−1}/(λ + φᵀP_{k−1}φ))/λ,
//! θ_k = θ_{k−1} + P_kφ·e_k,
//!
//! with P₀ = α·I (α large: little trust in the initial θ₀), and a forgetting factor
//! 0 < λ ≤ 1 (λ = 1 is the notes' form; λ < 1 weighs a sample n steps old by λⁿ, to follow a
//! process that changes). P_k is kept symmetric. At λ = 1, θ_N minimises
//! J + (θ − θ₀)ᵀP₀⁻¹(θ − θ₀), so with a large α it ends at the batch solution
//! ([`crate::lsq::arx::least_squares`]) on the same rows.
//!
//! [`Rls`] steps one sample at a time (the app animates it); [`run`] goes through the rows of a
//! [`Regression`] and keeps the trajectory; [`rls_arx`] does it for an ARX model of a record.
//!
//! [`run`] steps in the solving units of [`crate::lsq::arx`] (each column of Φ and Y
//! divided by its largest magnitude) and maps θ_k, e_k and the last estimate's figures back,
//! so a record at 1e300 or 1e-300 gives what it gives at 1: α of P₀ = α·I is in those units
//! (the same trust at any scale), and θ₀ is given in the record's units.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use crate::lsq::arx::{
    ArxModel, ArxOrders, Equilibrated, LeastSquares, LsqError, Offset, Regression, Scores,
    arx_regression, sampling_period,
};

/// The settings of a recursive estimate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RlsOptions {
    /// P₀ = α·I.
    pub alpha: f64,
    /// Forgetting factor λ in (0, 1].
    pub lambda: f64,
    /// θ₀; zeros when `None`.
    pub theta0: Option<Vec<f64>>,
}

impl Default for RlsOptions {
    fn default() -> Self {
        Self {
            alpha: 1e6,
            lambda: 1.0,
            theta0: None,
        }
    }
}

/// The state of a recursive least-squares estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct Rls {
    theta: DVector<f64>,
    p: DMatrix<f64>,
    lambda: f64,
    samples: usize,
}

impl Rls {
    /// A fresh estimate of `n` parameters.
    pub fn new(n: usize, options: &RlsOptions) -> Result<Self, LsqError> {
        if !(options.lambda > 0.0 && options.lambda <= 1.0) {
            return Err(LsqError::BadForgetting(options.lambda));
        }
        if !(options.alpha.is_finite() && options.alpha > 0.0) {
            return Err(LsqError::BadCovariance(options.alpha));
        }
        let theta = match &options.theta0 {
            Some(t) if t.len() != n => {
                return Err(LsqError::BadInitialTheta {
                    expected: n,
                    got: t.len(),
                });
            }
            Some(t) if t.iter().any(|v| !v.is_finite()) => return Err(LsqError::NonFinite),
            Some(t) => DVector::from_column_slice(t),
            None => DVector::zeros(n),
        };
        Ok(Self {
            theta,
            p: DMatrix::identity(n, n) * options.alpha,
            lambda: options.lambda,
            samples: 0,
        })
    }

    /// One sample: the regressor φ (as many entries as parameters) and the measured y.
    /// Returns the a-priori error e_k = y − φᵀθ_{k−1}.
    pub fn update(&mut self, phi: &[f64], y: f64) -> f64 {
        let phi = DVector::from_column_slice(phi);
        let e = y - phi.dot(&self.theta);
        let p_phi = &self.p * &phi;
        let denominator = self.lambda + phi.dot(&p_phi);
        self.p -= &p_phi * p_phi.transpose() / denominator;
        self.p /= self.lambda;
        self.p = (&self.p + self.p.transpose()) * 0.5;
        self.theta += &self.p * &phi * e;
        self.samples += 1;
        e
    }

    /// θ_k.
    pub fn theta(&self) -> &[f64] {
        self.theta.as_slice()
    }

    /// P_k.
    pub fn covariance(&self) -> &DMatrix<f64> {
        &self.p
    }

    /// The number of samples taken in.
    pub fn samples(&self) -> usize {
        self.samples
    }
}

/// A whole recursive run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RlsRun {
    /// θ_k after each row of Φ (row r of the regression is sample first + r).
    pub trajectory: Vec<Vec<f64>>,
    /// The a-priori error e_k of each row.
    pub errors: Vec<f64>,
    /// θ_N.
    pub last: Vec<f64>,
    /// θ_N's residuals, J and standard errors σ̂·√(P_N)ᵢᵢ, σ̂² = J/(N − p) (at λ = 1 and a
    /// large α, P_N is (ΦᵀΦ)⁻¹ and σ̂²·P_N the covariance of θ̂).
    pub estimate: LeastSquares,
}

/// Runs RLS through the rows of `reg` in order, in the solving units (module docs).
pub fn run(reg: &Regression, options: &RlsOptions) -> Result<RlsRun, LsqError> {
    let solving = Equilibrated::of(reg);
    let in_solving_units = RlsOptions {
        theta0: options.theta0.as_deref().map(|t| solving.theta_in(t)),
        ..options.clone()
    };
    let mut rls = Rls::new(reg.phi.ncols(), &in_solving_units)?;
    let (rows, p) = solving.phi.shape();
    let mut trajectory = Vec::with_capacity(rows);
    let mut errors = Vec::with_capacity(rows);
    let mut phi = vec![0.0; p];
    for r in 0..rows {
        for (c, v) in phi.iter_mut().enumerate() {
            *v = solving.phi[(r, c)];
        }
        errors.push(solving.error_out(rls.update(&phi, solving.y[r])));
        if !rls.p.iter().chain(&rls.theta).all(|v| v.is_finite()) {
            return Err(LsqError::CovarianceOverflow {
                alpha: options.alpha,
                lambda: options.lambda,
                row: r + 1,
            });
        }
        trajectory.push(solving.theta_out(rls.theta())?);
    }
    let variances = (rows > p).then(|| rls.p.diagonal().iter().copied().collect());
    Ok(RlsRun {
        last: solving.theta_out(rls.theta())?,
        estimate: solving.estimate(&rls.theta, variances)?,
        trajectory,
        errors,
    })
}

/// RLS on an ARX model of a record: the run and the model its last θ gives.
#[derive(Debug, Clone, PartialEq)]
pub struct RlsFit {
    pub run: RlsRun,
    pub model: ArxModel,
    pub regression: Regression,
    /// The last model's prediction and simulation, scored on the rows of Φ.
    pub scores: Scores,
    /// The last model's AIC on the rows of Φ.
    pub aic: f64,
}

/// RLS for an ARX model of `orders` on the record (`time` in s, `u`, `y`), the operating
/// point handled as [`crate::lsq::arx::arx`] does.
pub fn rls_arx(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    orders: ArxOrders,
    offset: Offset,
    options: &RlsOptions,
) -> Result<RlsFit, LsqError> {
    let (reg, (u0, y0)) = arx_regression(time, u, y, orders, offset)?;
    let run = run(&reg, options)?;
    let model = ArxModel::from_theta(orders, &run.last, (u0, y0), sampling_period(time));
    Ok(RlsFit {
        scores: model.score(u, y, reg.first, reg.first),
        aic: run.estimate.cost.aic(reg.phi.nrows(), reg.phi.ncols()),
        run,
        model,
        regression: reg,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lsq::arx::{Start, least_squares, regression};

    #[test]
    fn at_lambda_one_it_ends_at_the_batch_solution() {
        let n = 200;
        let u: Vec<f64> = (0..n).map(|k| ((k * 7919) % 13) as f64 - 6.0).collect();
        let mut y = vec![0.0; n];
        for k in 2..n {
            y[k] = 1.2 * y[k - 1] - 0.4 * y[k - 2]
                + 0.3 * u[k - 1]
                + 0.1 * u[k - 2]
                + 0.01 * (((k * 31) % 7) as f64 - 3.0);
        }
        let orders = ArxOrders::new(2, 2, 1);
        let reg = regression(&u, &y, &orders.regressors(), Start::FirstFullRow).unwrap();
        let batch = least_squares(&reg).unwrap();
        let r = run(&reg, &RlsOptions::default()).unwrap();
        for (a, b) in r.last.iter().zip(&batch.theta) {
            assert!((a - b).abs() < 1e-6, "{a} vs {b}");
        }
    }

    #[test]
    fn bad_settings_are_refused() {
        let bad = RlsOptions {
            lambda: 1.5,
            ..RlsOptions::default()
        };
        assert_eq!(Rls::new(2, &bad), Err(LsqError::BadForgetting(1.5)));
    }
}
