//! Fitting a process model to a measured step test by least squares on the output:
//! minimise the mean squared error (1/N)·Σ(yᵢ − ŷᵢ)² over the free parameters, within bounds.
//!
//! Two methods, chosen by the student, both in [`solver`] (which knows nothing of models):
//! **Levenberg–Marquardt**, bounded, and **Nelder–Mead** (MATLAB's `fminsearch`, the notes'
//! method) with the same bounds.
//!
//! Every fit runs on the record in its internal units ([`Scale`](crate::model::scale::Scale): the output about its level
//! in half-ranges, the step ±1, time from t0 in record lengths) and scales its results back,
//! so a record at 1e-300 or 1e300, a step of 1e-200, time in nanoseconds or years, fits as a
//! unit-sized one does. The sums run over pieces of [`CHUNK`] samples: no N × p Jacobian and no
//! residual vector per start or iteration, so a record of millions of samples fits in little
//! more memory than the record itself.
//!
//! A multi-start option (on by default) runs LM from the guess and from spread-out starts
//! and keeps the best: the LECI notes show a single start landing on a spurious alias. A fit
//! nobody watches ([`FitObserver::watches`]) screens its starts on every core.
//!
//! On a long record (more than [`reduce::MIN_SAMPLES`](crate::fit::reduce::MIN_SAMPLES) samples) the starts run on its
//! reduction ([`reduce`](crate::fit::reduce): every sample just after each input change, block means of doubling
//! length as the response settles, weighted by the samples they stand for), and the best of
//! them is refined on every sample, which the report and its intervals use: an 80,000-sample
//! P1D costs about one local fit on the whole record. [`search_fit`] stops before that last
//! stage, for comparing many candidates of one record (the diagnosis's extension search).
//!
//! The report follows MATLAB: MSE, RMSE, NRMSE fit % as `compare` (100·(1 − ‖y − ŷ‖/‖y − ȳ‖)),
//! AIC as `aic` (N·ln MSE + 2p + N·(ln 2π + 1)), and 95 % intervals from the Jacobian at the
//! optimum (s² (JᵀJ)⁻¹ with s² = SSE/(N − p), Student-t quantile), with warnings for a
//! parameter at a bound, Zeta ≥ 1 in an underdamped model, and an alias.
//!
//! The module, by job: [`problem`] (the least-squares problem of a model on a record, in
//! internal units), [`solver`] (LM and Nelder–Mead on any such problem), `search` (the
//! multi-start search, its screen and the refinement on every sample), `report` (the
//! statistics, warnings and intervals of the optimum) and `alias` (the check that the model
//! does not swing between the samples).

mod alias;
pub mod censored;
pub mod guess;
pub mod handles;
pub mod lag_pair;
pub mod landscape;
mod problem;
pub mod reduce;
mod report;
pub mod rest;
pub mod robust;
mod search;
mod setup;
mod solver;
#[cfg(test)]
mod tests;

pub use alias::alias_warning;
pub use report::{Estimate, FitReport, FitWarning};
pub use search::{fit, fit_weighted, search_fit};
pub use setup::{
    CHUNK, FitData, FitError, FitObserver, FitOptions, MAX_STARTS, Method, Progress, bounds,
    within_span,
};
pub use solver::Termination;
