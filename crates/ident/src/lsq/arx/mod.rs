//! Least squares on a sampled record as the course notes teach it: the regressor vector
//! φ(k), the matrix Φ of N measurements stacked row by row, θ̂ minimising J = EᵀE with
//! E = Y − Φθ̂, and the ARX model y(k) + a1·y(k−1) + … + a_na·y(k−na) = b1·u(k−nk) + … +
//! b_nb·u(k−nk−nb+1) (MATLAB `arx`'s convention: nk the delay in samples, nk = 1 the plain
//! zero-order-hold delay), φ(k)ᵀ = [−y(k−1) … −y(k−na) u(k−nk) … u(k−nk−nb+1)].
//!
//! - **The solve**: θ̂ by nalgebra's Householder QR of Φ (Φ = QR, Rθ̂ = QᵀY), never the
//!   notes' normal equations (ΦᵀΦ squares Φ's condition number). Φ is refused as singular
//!   when a column's component orthogonal to the columns before it (|Rᵢᵢ|) is below 1e-10 of
//!   the column's norm (the regressors are collinear to that precision).
//! - **Standard errors**: σ̂² = J/(N − p), cov(θ̂) = σ̂²(ΦᵀΦ)⁻¹ = σ̂²·R⁻¹R⁻ᵀ, so seᵢ is σ̂ times
//!   the norm of row i of R⁻¹ (none when N = p).
//! - **Prediction and simulation**: the one-step-ahead prediction ŷ(k) = φ(k)ᵀθ̂ uses the
//!   measured past outputs; the free simulation feeds its own past outputs back. Both start
//!   from the measured samples before the first full row and are scored on the rows of Φ,
//!   with the project's fit % = 100·(1 − ‖y − ŷ‖/‖y − ȳ‖).
//! - **Any scale**: Φ and Y are solved in their own units (each column and Y divided by its
//!   largest magnitude, [`units`]) and θ̂, its standard errors and J mapped back, so a record
//!   at 1e300 or 1e-300 gives the same a's, the b's scaled exactly, and the same fit %; J,
//!   which may then lie beyond double precision, is a [`Cost`].
//! - **AIC** (MATLAB's raw `aic` and [`crate::fit`]'s): N·ln(J/N) + 2p + N·(ln 2π + 1),
//!   p the number of estimated parameters; [`select_orders`] compares a grid on the same rows,
//!   best AIC first, except that orders fitting exactly (J at rounding level, below
//!   [`ROUNDING_LEVEL`] of Σ(y − ȳ)², where AIC is decided by roundoff) come first, fewest
//!   parameters first. A grid or an order whose longest lag the record cannot hold is refused
//!   before anything is fitted.
//! - **The operating point** ([`Offset`]): a record far from zero is worked in deviations,
//!   either u − u0, y − y0 with u0, y0 the means of the samples before the input's first
//!   significant change ([`crate::model::excitation`]'s rule; the first sample when it
//!   changes at once), or with a constant regressor estimated with the others.
//! - **Named regressors** ([`Regressor`], [`regression`]): the same machinery for any list of
//!   regressors (a constant, u(k − j), −y(k − i)), so the notes' three-sample example is
//!   reproducible; [`Start::Zeros`] takes the signals as 0 before the record, as the notes do.
//!
//! The sampling period h is the record's median interval; ARX assumes it is uniform.

mod units;

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use crate::model::excitation::{Excitation, Hold};
use crate::stats::mean;
use degrau_lti::discrete::{DiscreteError, DiscreteTf};
pub(crate) use units::Equilibrated;
pub use units::{Cost, ROUNDING_LEVEL, fit_percent};

/// One column of Φ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Regressor {
    /// The constant 1.
    Constant,
    /// −y(k − i), i ≥ 1 (the notes' sign: its parameter is aᵢ).
    Output(usize),
    /// u(k − j), j ≥ 0.
    Input(usize),
}

/// Where Φ's first row is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Start {
    /// At the first sample whose regressors are all inside the record (MATLAB `arx`).
    #[default]
    FirstFullRow,
    /// At the first sample, the signals taken as 0 before the record (the notes' example).
    Zeros,
}

/// The regression problem Y = Φθ + E, built row by row.
#[derive(Debug, Clone, PartialEq)]
pub struct Regression {
    /// Φ's columns, in order.
    pub regressors: Vec<Regressor>,
    /// N × p: row r is φ(first + r)ᵀ.
    pub phi: DMatrix<f64>,
    /// Y: the measured output of each row.
    pub y: DVector<f64>,
    /// The index (0-based) of the sample of Φ's first row.
    pub first: usize,
}

/// θ̂ and what comes with it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LeastSquares {
    /// θ̂, in the order of the regressors.
    pub theta: Vec<f64>,
    /// Standard error of each parameter, √(σ̂²·[(ΦᵀΦ)⁻¹]ᵢᵢ); `None` when N = p.
    pub se: Vec<Option<f64>>,
    /// E = Y − Φθ̂, one per row.
    pub residuals: Vec<f64>,
    /// J = EᵀE as a double: 0 or ∞ where J lies beyond double precision (see `cost`).
    pub j: f64,
    /// J, kept at any scale.
    pub cost: Cost,
}

/// What stops a least-squares estimate (`crate::words::lsq` says it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum LsqError {
    /// The input and output columns differ in length.
    LengthMismatch { u: usize, y: usize },
    /// A sample is NaN or infinite.
    NonFinite,
    /// No regressor, or an output regressor at lag 0 (y(k) explaining itself).
    BadRegressors,
    /// `rows` rows of Φ for `parameters` parameters.
    TooFewSamples { rows: usize, parameters: usize },
    /// Regressor `index` (0-based) is collinear with the ones before it.
    Singular { index: usize },
    /// The output never changes: nothing to identify, and no fit % to give.
    ConstantOutput,
    /// The longest lag, `lag` samples, leaves no row of Φ in a record of `samples`.
    LagBeyondRecord { lag: usize, samples: usize },
    /// The parameter of `regressor` (or its standard error) is about 10^`log10` in the
    /// record's units, beyond double precision.
    Unrepresentable { regressor: Regressor, log10: f64 },
    /// The forgetting factor λ is outside (0, 1].
    BadForgetting(f64),
    /// The initial covariance α is not a positive finite number.
    BadCovariance(f64),
    /// RLS's covariance P (P₀ = α·I, divided by λ at every row) left double precision's
    /// range at row `row` (from 1) of Φ.
    CovarianceOverflow { alpha: f64, lambda: f64, row: usize },
    /// The initial θ has the wrong length.
    BadInitialTheta { expected: usize, got: usize },
    /// The validation split leaves too few samples on one side.
    BadSplit,
    /// The discrete model could not be formed.
    Discrete(#[from] DiscreteError),
}

/// |Rᵢᵢ| below this share of column i's norm: collinear.
const COLLINEAR: f64 = 1e-10;

/// Builds Y = Φθ from the samples `u`, `y` (same length) for `regressors`.
pub fn regression(
    u: &[f64],
    y: &[f64],
    regressors: &[Regressor],
    start: Start,
) -> Result<Regression, LsqError> {
    if u.len() != y.len() {
        return Err(LsqError::LengthMismatch {
            u: u.len(),
            y: y.len(),
        });
    }
    if u.iter().chain(y).any(|v| !v.is_finite()) {
        return Err(LsqError::NonFinite);
    }
    if regressors.is_empty() || regressors.contains(&Regressor::Output(0)) {
        return Err(LsqError::BadRegressors);
    }
    let lag = regressors
        .iter()
        .map(|r| match r {
            Regressor::Constant => 0,
            Regressor::Output(i) | Regressor::Input(i) => *i,
        })
        .max()
        .unwrap_or(0);
    let first = match start {
        Start::FirstFullRow => lag.min(y.len()),
        Start::Zeros => 0,
    };
    let rows = y.len() - first;
    let at = |v: &[f64], k: usize, back: usize| k.checked_sub(back).map_or(0.0, |i| v[i]);
    let phi = DMatrix::from_fn(rows, regressors.len(), |r, c| {
        let k = first + r;
        match regressors[c] {
            Regressor::Constant => 1.0,
            Regressor::Output(i) => -at(y, k, i),
            Regressor::Input(j) => at(u, k, j),
        }
    });
    Ok(Regression {
        regressors: regressors.to_vec(),
        phi,
        y: DVector::from_column_slice(&y[first..]),
        first,
    })
}

/// θ̂ = argmin ‖Y − Φθ‖² by QR in the solving units, with J and the standard errors in
/// the record's (see the module docs).
pub fn least_squares(reg: &Regression) -> Result<LeastSquares, LsqError> {
    let (rows, p) = reg.phi.shape();
    if rows < p || p == 0 {
        return Err(LsqError::TooFewSamples {
            rows,
            parameters: p,
        });
    }
    let solving = Equilibrated::of(reg);
    let qr = solving.phi.clone().qr();
    let r = qr.r();
    for i in 0..p {
        let norm = solving.phi.column(i).norm();
        if norm == 0.0 || r[(i, i)].abs() <= COLLINEAR * norm {
            return Err(LsqError::Singular { index: i });
        }
    }
    let qty = qr.q().transpose() * &solving.y;
    let theta = r
        .solve_upper_triangular(&qty)
        .ok_or(LsqError::Singular { index: 0 })?;
    let variances = if rows > p {
        let r_inv = r
            .solve_upper_triangular(&DMatrix::identity(p, p))
            .ok_or(LsqError::Singular { index: 0 })?;
        Some((0..p).map(|i| r_inv.row(i).norm_squared()).collect())
    } else {
        None
    };
    solving.estimate(&theta, variances)
}

/// The orders of an ARX model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct ArxOrders {
    /// Number of a's (poles).
    pub na: usize,
    /// Number of b's.
    pub nb: usize,
    /// Delay of b1 in samples.
    pub nk: usize,
}

impl ArxOrders {
    pub fn new(na: usize, nb: usize, nk: usize) -> Self {
        Self { na, nb, nk }
    }

    /// The regressors −y(k−1) … −y(k−na), u(k−nk) … u(k−nk−nb+1).
    pub fn regressors(&self) -> Vec<Regressor> {
        (1..=self.na)
            .map(Regressor::Output)
            .chain((0..self.nb).map(|j| Regressor::Input(self.nk + j)))
            .collect()
    }

    /// The longest lag: max(na, nk + nb − 1).
    pub fn max_lag(&self) -> usize {
        self.na
            .max(self.nk.saturating_add(self.nb).saturating_sub(1))
    }

    /// The parameters to estimate: na + nb, and the constant with [`Offset::Constant`].
    pub fn parameters(&self, offset: Offset) -> usize {
        self.na
            .saturating_add(self.nb)
            .saturating_add(usize::from(offset == Offset::Constant))
    }

    /// Refuses, before anything is built, orders a record of `samples` cannot hold: no
    /// regressor, a longest lag leaving no row of Φ, or fewer rows than parameters.
    pub fn check(&self, samples: usize, offset: Offset) -> Result<(), LsqError> {
        if self.na.saturating_add(self.nb) == 0 {
            return Err(LsqError::BadRegressors);
        }
        let lag = self.max_lag();
        if lag >= samples {
            return Err(LsqError::LagBeyondRecord { lag, samples });
        }
        let (rows, parameters) = (samples - lag, self.parameters(offset));
        if rows < parameters {
            return Err(LsqError::TooFewSamples { rows, parameters });
        }
        Ok(())
    }
}

/// How the operating point is handled (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Offset {
    /// The samples as they are (a record already in deviations).
    None,
    /// u − u0, y − y0 with the means before the input's first change.
    #[default]
    Initial,
    /// A constant regressor, estimated with the others.
    Constant,
}

/// An estimated ARX model, with its operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ArxModel {
    pub orders: ArxOrders,
    /// [1, a1, …, a_na].
    pub a: Vec<f64>,
    /// [b1, …, b_nb].
    pub b: Vec<f64>,
    /// The constant term (0 unless [`Offset::Constant`]).
    pub constant: f64,
    /// The operating point subtracted from u and y (0 unless [`Offset::Initial`]).
    pub u0: f64,
    pub y0: f64,
    /// The sampling period h (s).
    pub ts: f64,
}

impl ArxModel {
    /// The model from θ = [a1 … a_na b1 … b_nb (c)].
    pub fn from_theta(orders: ArxOrders, theta: &[f64], offset: (f64, f64), ts: f64) -> Self {
        let (na, nb) = (orders.na, orders.nb);
        let mut a = vec![1.0];
        a.extend_from_slice(&theta[..na]);
        Self {
            orders,
            a,
            b: theta[na..na + nb].to_vec(),
            constant: theta.get(na + nb).copied().unwrap_or(0.0),
            u0: offset.0,
            y0: offset.1,
            ts,
        }
    }

    /// θ = [a1 … a_na b1 … b_nb], with the constant last when there is one.
    pub fn theta(&self) -> Vec<f64> {
        let mut t: Vec<f64> = self.a[1..].iter().chain(&self.b).copied().collect();
        if self.constant != 0.0 {
            t.push(self.constant);
        }
        t
    }

    /// H(z) = B(z)/A(z)·z^−nk at the model's period.
    pub fn discrete(&self) -> Result<DiscreteTf, DiscreteError> {
        DiscreteTf::new(self.a.clone(), self.b.clone(), self.orders.nk, self.ts)
    }

    /// ŷ(k) from the past outputs `past` (deviations) and the measured input.
    fn next(&self, k: usize, u: &[f64], past: &[f64]) -> f64 {
        let mut v = self.constant;
        for (i, &ai) in self.a.iter().enumerate().skip(1) {
            v -= ai * (past[k - i] - self.y0);
        }
        for (j, &bj) in self.b.iter().enumerate() {
            v += bj * (u[k - self.orders.nk - j] - self.u0);
        }
        self.y0 + v
    }

    /// The one-step-ahead prediction at every sample: the measured y before sample `first`
    /// (at least the longest lag), φ(k)ᵀθ̂ from the measured past after.
    pub fn predict(&self, u: &[f64], y: &[f64], first: usize) -> Vec<f64> {
        let n = u.len().min(y.len());
        let first = first.max(self.orders.max_lag()).min(n);
        let mut out = y[..n].to_vec();
        for (k, o) in out.iter_mut().enumerate().skip(first) {
            *o = self.next(k, u, y);
        }
        out
    }

    /// The free simulation: the measured y before sample `first` (at least the longest
    /// lag), then the model's own past outputs.
    pub fn simulate(&self, u: &[f64], y: &[f64], first: usize) -> Vec<f64> {
        let n = u.len().min(y.len());
        let first = first.max(self.orders.max_lag()).min(n);
        let mut out = y[..n].to_vec();
        for k in first..n {
            out[k] = self.next(k, u, &out);
        }
        out
    }

    /// The prediction and the simulation from sample `first` (at least the longest lag) on,
    /// scored from sample `from` on.
    pub fn score(&self, u: &[f64], y: &[f64], first: usize, from: usize) -> Scores {
        let prediction = self.predict(u, y, first);
        let simulation = self.simulate(u, y, first);
        let from = from.min(prediction.len());
        let scored = &y[from..prediction.len()];
        Scores {
            fit_percent_prediction: fit_percent(scored, &prediction[from..]),
            fit_percent_simulation: fit_percent(scored, &simulation[from..]),
            prediction,
            simulation,
            from,
        }
    }
}

/// A model's one-step prediction and free simulation over a record, each with its fit % on
/// the samples from `from` on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scores {
    /// The one-step-ahead prediction at every sample (output units).
    pub prediction: Vec<f64>,
    /// The free simulation at every sample (output units).
    pub simulation: Vec<f64>,
    /// The first sample scored.
    pub from: usize,
    pub fit_percent_prediction: f64,
    pub fit_percent_simulation: f64,
}

/// An ARX fit: the model, the problem it solved and its figures.
#[derive(Debug, Clone, PartialEq)]
pub struct ArxFit {
    pub model: ArxModel,
    pub offset: Offset,
    /// Φ and Y, in deviations from the operating point.
    pub regression: Regression,
    pub lsq: LeastSquares,
    /// The prediction and simulation, scored on the rows of Φ.
    pub scores: Scores,
    pub aic: f64,
}

/// The operating point (u0, y0) of `offset` (see the module docs).
pub fn operating_point(time: &[f64], u: &[f64], y: &[f64], offset: Offset) -> (f64, f64) {
    if offset != Offset::Initial || u.is_empty() || y.is_empty() {
        return (0.0, 0.0);
    }
    let n = u.len().min(y.len()).min(time.len());
    let before = Excitation::measured(&time[..n], &u[..n], None, Hold::Zoh)
        .and_then(|e| e.changes.first().and_then(|c| c.index))
        .unwrap_or(1)
        .clamp(1, n.max(1));
    (mean(&u[..before]), mean(&y[..before]))
}

/// The median sampling period of `time` (s), 1 when it has fewer than two samples.
pub fn sampling_period(time: &[f64]) -> f64 {
    crate::record::timebase::sampling_period(time).unwrap_or(1.0)
}

/// Φ and Y of an ARX model of `orders` on the record, in deviations from the operating point
/// (u0, y0) of `offset` (returned with them), from the first full row.
pub fn arx_regression(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    orders: ArxOrders,
    offset: Offset,
) -> Result<(Regression, (f64, f64)), LsqError> {
    if u.len() != y.len() {
        return Err(LsqError::LengthMismatch {
            u: u.len(),
            y: y.len(),
        });
    }
    orders.check(y.len(), offset)?;
    if y.iter().all(|&v| v == y[0]) {
        return Err(LsqError::ConstantOutput);
    }
    let (u0, y0) = operating_point(time, u, y, offset);
    let du: Vec<f64> = u.iter().map(|v| v - u0).collect();
    let dy: Vec<f64> = y.iter().map(|v| v - y0).collect();
    let mut regressors = orders.regressors();
    if offset == Offset::Constant {
        regressors.push(Regressor::Constant);
    }
    Ok((
        regression(&du, &dy, &regressors, Start::FirstFullRow)?,
        (u0, y0),
    ))
}

/// Fits an ARX model of `orders` to the record (`time` in s, `u`, `y`), Φ starting at the
/// first full row.
pub fn arx(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    orders: ArxOrders,
    offset: Offset,
) -> Result<ArxFit, LsqError> {
    arx_from(time, u, y, orders, offset, orders.max_lag())
}

/// [`arx`] with Φ's first row at sample `first` (at least the longest lag): the rows a grid
/// of orders shares.
pub fn arx_from(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    orders: ArxOrders,
    offset: Offset,
    first: usize,
) -> Result<ArxFit, LsqError> {
    let (mut regression, (u0, y0)) = arx_regression(time, u, y, orders, offset)?;
    let first = first.max(regression.first).min(y.len());
    if first > regression.first {
        let skip = first - regression.first;
        regression.phi = regression.phi.rows_range(skip..).into_owned();
        regression.y = regression.y.rows_range(skip..).into_owned();
        regression.first = first;
    }
    let lsq = least_squares(&regression)?;
    let model = ArxModel::from_theta(orders, &lsq.theta, (u0, y0), sampling_period(time));
    Ok(ArxFit {
        scores: model.score(u, y, first, first),
        aic: lsq
            .cost
            .aic(regression.y.len(), regression.regressors.len()),
        model,
        offset,
        regression,
        lsq,
    })
}

/// One candidate of an order search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    pub orders: ArxOrders,
    pub aic: f64,
    /// J, `None` beyond double precision (then `j_log10` gives its order of magnitude).
    pub j: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub j_log10: Option<f64>,
    /// J at rounding level ([`ROUNDING_LEVEL`]): the order reproduces the rows exactly.
    pub exact: bool,
    pub fit_percent_prediction: f64,
    pub fit_percent_simulation: f64,
}

impl Candidate {
    fn of(orders: ArxOrders, fit: &ArxFit) -> Self {
        let cost = fit.lsq.cost;
        Self {
            orders,
            aic: fit.aic,
            j: cost.value(),
            j_log10: cost.value().is_none().then(|| cost.log10()),
            exact: cost.exact(),
            fit_percent_prediction: fit.scores.fit_percent_prediction,
            fit_percent_simulation: fit.scores.fit_percent_simulation,
        }
    }

    /// The search's order: exact fits first, fewest parameters first (their AIC is decided
    /// by roundoff), then best AIC.
    fn ranking(&self, other: &Self) -> std::cmp::Ordering {
        let size = |c: &Self| c.orders.na + c.orders.nb;
        other
            .exact
            .cmp(&self.exact)
            .then_with(|| match self.exact {
                true => size(self).cmp(&size(other)),
                false => std::cmp::Ordering::Equal,
            })
            .then_with(|| self.aic.total_cmp(&other.aic))
    }
}

/// The na and nb of the default grid.
const GRID_ORDERS: std::ops::RangeInclusive<usize> = 1..=3;

/// The small default grid: na in 1..=3, nb in 1..=3, nk in 0..=`max_nk`, refused at once
/// when its longest lag leaves no row of Φ in a record of `samples`.
pub fn default_grid(max_nk: usize, samples: usize) -> Result<Vec<ArxOrders>, LsqError> {
    let widest = ArxOrders::new(*GRID_ORDERS.end(), *GRID_ORDERS.end(), max_nk);
    let lag = widest.max_lag();
    if lag >= samples {
        return Err(LsqError::LagBeyondRecord { lag, samples });
    }
    let mut grid = Vec::new();
    for na in GRID_ORDERS {
        for nb in GRID_ORDERS {
            for nk in 0..=max_nk {
                grid.push(ArxOrders::new(na, nb, nk));
            }
        }
    }
    Ok(grid)
}

/// Fits every order of `grid` on the same rows (from the grid's longest lag on) and ranks
/// them ([`Candidate`]'s order: exact fits by size, then AIC); orders whose Φ is singular or
/// too short are left out, and a grid whose longest lag leaves no row is refused at once.
pub fn select_orders(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    grid: &[ArxOrders],
    offset: Offset,
) -> Result<Vec<Candidate>, LsqError> {
    let first = grid.iter().map(ArxOrders::max_lag).max().unwrap_or(0);
    if first >= y.len() {
        return Err(LsqError::LagBeyondRecord {
            lag: first,
            samples: y.len(),
        });
    }
    let mut out = Vec::new();
    let mut last_error = LsqError::BadRegressors;
    for &orders in grid {
        match arx_from(time, u, y, orders, offset, first) {
            Ok(f) => out.push(Candidate::of(orders, &f)),
            Err(e) => last_error = e,
        }
    }
    if out.is_empty() {
        return Err(last_error);
    }
    out.sort_by(Candidate::ranking);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_notes_three_sample_example() {
        let (u, y) = ([0.0, 1.0, 2.0], [0.0, 0.9, 2.1]);
        let solve = |r: &[Regressor]| least_squares(&regression(&u, &y, r, Start::Zeros).unwrap());
        let c = solve(&[Regressor::Constant]).unwrap();
        // The notes print J = 2.2: 1² + 0.1² + 1.1² = 2.22, rounded to two digits.
        assert!((c.theta[0] - 1.0).abs() < 1e-14 && (c.j - 2.22).abs() < 1e-13);
        let l = solve(&[Regressor::Constant, Regressor::Input(0)]).unwrap();
        assert!((l.theta[0] + 0.05).abs() < 1e-14 && (l.theta[1] - 1.05).abs() < 1e-14);
        assert!((l.j - 0.015).abs() < 1e-14);
        let t = solve(&[
            Regressor::Constant,
            Regressor::Input(0),
            Regressor::Input(1),
        ])
        .unwrap();
        for (got, want) in t.theta.iter().zip([0.0, 0.9, 0.3]) {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
        assert!(t.j < 1e-28);
        assert_eq!(t.se, vec![None; 3]);
    }

    #[test]
    fn collinear_regressors_are_refused() {
        let u = [1.0, 2.0, 3.0, 4.0];
        let y = [0.5, 1.0, 1.5, 2.1];
        let r = regression(
            &u,
            &y,
            &[Regressor::Input(0), Regressor::Input(0)],
            Start::Zeros,
        );
        assert_eq!(
            least_squares(&r.unwrap()),
            Err(LsqError::Singular { index: 1 })
        );
    }

    #[test]
    fn fit_percent_is_100_for_a_perfect_model_and_0_for_the_mean() {
        let y = [1.0, 2.0, 4.0];
        assert_eq!(fit_percent(&y, &y), 100.0);
        let mean = [7.0 / 3.0; 3];
        assert!(fit_percent(&y, &mean).abs() < 1e-12);
    }
}
