//! Estimation and validation, the notes' sixth step ("utilizar uma parte dos dados para
//! validar o modelo"): fit on one part of a record, score on the other.
//!
//! - **The split** ([`Split`]): a fraction of the samples or a time; the estimation part is
//!   the samples before it, the validation part the samples from it on. A second record is
//!   validated by scoring the model on it directly ([`score_arx`] with split 0).
//! - **ARX and RLS** ([`validate_arx`], [`validate_rls`]): the model estimated on the first
//!   part; its one-step prediction (measured past outputs) and its free simulation, run over
//!   the whole record from the start (the simulation's state carried across the split), scored
//!   on the validation part; the residual checks ([`crate::diagnose::residuals::analyse`]) on
//!   the validation part's one-step prediction errors (white for a right ARX model).
//! - **The continuous fit** ([`validate_continuous`]): fitted on the estimation part, simulated
//!   exactly over the whole record (the state is carried across the split), scored on the
//!   validation part, its residuals (output errors) checked there.

use serde::{Deserialize, Serialize};

use crate::diagnose::residuals::{self, Boundaries, ResidualAnalysis};
use crate::experiment::{Experiment, ExperimentError};
use crate::fit::{FitData, FitOptions, FitReport};
use crate::lsq::arx::{ArxFit, ArxModel, ArxOrders, LsqError, Offset, Scores, arx};
use crate::lsq::rls::{RlsFit, RlsOptions, rls_arx};

/// Where a record is split.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Split {
    /// This share of the samples (0 < f < 1) estimates.
    Fraction(f64),
    /// The samples before this time (s) estimate.
    Time(f64),
}

/// Fewest samples on either side of a split.
pub const MIN_PART: usize = 3;

/// The index of the first validation sample, refusing a split that leaves fewer than
/// [`MIN_PART`] samples on either side.
pub fn split_index(time: &[f64], split: Split) -> Result<usize, LsqError> {
    let n = time.len();
    let index = match split {
        Split::Fraction(f) if f.is_finite() && f > 0.0 && f < 1.0 => {
            (f * n as f64).round() as usize
        }
        Split::Time(t) if t.is_finite() => time.partition_point(|&s| s < t),
        _ => return Err(LsqError::BadSplit),
    };
    if index < MIN_PART || n.saturating_sub(index) < MIN_PART {
        return Err(LsqError::BadSplit);
    }
    Ok(index)
}

/// A model scored on the validation part.
#[derive(Debug, Clone, PartialEq)]
pub struct ArxValidation {
    /// The first validation sample.
    pub split: usize,
    /// Fit % of the prediction and the simulation on the estimation part.
    pub estimation: Scores,
    /// The same over the whole record, scored on the validation part.
    pub validation: Scores,
    /// The checks of the validation part's one-step prediction errors.
    pub residuals: ResidualAnalysis,
}

/// Scores `model` on the record, the prediction and simulation starting at the model's
/// longest lag and scored from `split` on, with the residual checks there.
pub fn score_arx(
    model: &ArxModel,
    time: &[f64],
    u: &[f64],
    y: &[f64],
    split: usize,
) -> ArxValidation {
    let first = model.orders.max_lag();
    let estimation = model.score(&u[..split], &y[..split], first, first);
    let validation = model.score(u, y, first, split.max(first));
    let from = validation.from;
    let errors: Vec<f64> = y[from..]
        .iter()
        .zip(&validation.prediction[from..])
        .map(|(a, b)| a - b)
        .collect();
    let residuals = check(&time[from..], &errors, Some(&u[from..]));
    ArxValidation {
        split,
        estimation,
        validation,
        residuals,
    }
}

/// The residual checks over a whole part (no step regions: it is all one region).
fn check(time: &[f64], errors: &[f64], input: Option<&[f64]>) -> ResidualAnalysis {
    let (start, end) = (
        time.first().copied().unwrap_or(0.0),
        time.last().copied().unwrap_or(0.0),
    );
    residuals::analyse(
        time,
        errors,
        input,
        Boundaries {
            response_start: start,
            settled: end,
        },
    )
}

/// ARX of `orders` estimated before `split`, validated after it.
pub fn validate_arx(
    time: &[f64],
    u: &[f64],
    y: &[f64],
    orders: ArxOrders,
    offset: Offset,
    split: Split,
) -> Result<(ArxFit, ArxValidation), LsqError> {
    same_length(time, u, y)?;
    let s = split_index(time, split)?;
    let fit = arx(&time[..s], &u[..s], &y[..s], orders, offset)?;
    let v = score_arx(&fit.model, time, u, y, s);
    Ok((fit, v))
}

/// RLS's last model, run on the samples before `split` of the record (time in s, u, y),
/// validated after it.
pub fn validate_rls(
    [time, u, y]: [&[f64]; 3],
    orders: ArxOrders,
    offset: Offset,
    options: &RlsOptions,
    split: Split,
) -> Result<(RlsFit, ArxValidation), LsqError> {
    same_length(time, u, y)?;
    let s = split_index(time, split)?;
    let fit = rls_arx(&time[..s], &u[..s], &y[..s], orders, offset, options)?;
    let v = score_arx(&fit.model, time, u, y, s);
    Ok((fit, v))
}

/// Refuses columns that differ in length.
fn same_length(time: &[f64], u: &[f64], y: &[f64]) -> Result<(), LsqError> {
    if u.len() != y.len() || time.len() != y.len() {
        return Err(LsqError::LengthMismatch {
            u: u.len(),
            y: y.len(),
        });
    }
    Ok(())
}

/// The continuous fit estimated before the split and scored after it.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuousValidation {
    pub split: usize,
    /// The fit on the estimation part.
    pub report: FitReport,
    /// y − ŷ over the whole record, ŷ simulated from the start.
    pub residuals: Vec<f64>,
    pub estimation_fit_percent: f64,
    pub validation_fit_percent: f64,
    /// The checks of the validation part's residuals.
    pub checks: ResidualAnalysis,
}

/// What stops a continuous validation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum ValidationError {
    Lsq(LsqError),
    Fit(ExperimentError),
}

/// Fits `code` on the samples of `data` before `split` (the experiment's guess and
/// operating point), and scores the exact simulation over the whole record on the rest.
pub fn validate_continuous(
    experiment: &Experiment,
    data: &FitData,
    code: &str,
    split: Split,
    options: &FitOptions,
) -> Result<ContinuousValidation, ValidationError> {
    let s = split_index(&data.times, split).map_err(ValidationError::Lsq)?;
    let estimation = FitData {
        times: data.times[..s].to_vec(),
        y: data.y[..s].to_vec(),
        input: data.input.clone(),
    };
    let report = experiment
        .fit_prepared(&estimation, code, false, &[], options, &mut ())
        .map_err(ValidationError::Fit)?;
    let residuals = report.residuals(data).map_err(|e| {
        ValidationError::Fit(ExperimentError::from(crate::fit::FitError::BadGuess(e)))
    })?;
    let score = |range: std::ops::Range<usize>| {
        let yhat: Vec<f64> = data.y[range.clone()]
            .iter()
            .zip(&residuals[range.clone()])
            .map(|(y, e)| y - e)
            .collect();
        crate::lsq::arx::fit_percent(&data.y[range], &yhat)
    };
    let input: Vec<f64> = data.times[s..]
        .iter()
        .map(|&t| data.input.deviation_at(t))
        .collect();
    Ok(ContinuousValidation {
        estimation_fit_percent: score(0..s),
        validation_fit_percent: score(s..data.y.len()),
        checks: check(&data.times[s..], &residuals[s..], Some(&input)),
        split: s,
        report,
        residuals,
    })
}
