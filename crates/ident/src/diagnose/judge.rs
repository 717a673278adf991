//! The rules every step of a diagnosis is judged by, a structural cause's as a test cause's:
//! the BIC and when its drop pays for a parameter, how far residuals are from white, and the
//! candidates no record can back (an alias, a lag beyond the record).

use super::report::Gain;
use crate::diagnose::residuals::{self, ResidualAnalysis};
use crate::diagnose::test_causes::time_constants;
use crate::fit::{FitData, FitReport};
use crate::model::{Model, Param};
use crate::stats::lag_one;

/// An extension must lower BIC by more than this to be kept.
pub const BIC_THRESHOLD: f64 = 10.0;

/// BIC of a fit: N·ln(MSE) + p·ln(N), from the fit's ln MSE (finite at any scale).
pub fn bic(r: &FitReport) -> f64 {
    let n = r.n as f64;
    n * r.ln_mse + r.params.len() as f64 * n.ln()
}

/// The residual analysis of a fit on its data.
pub fn analyse(report: &FitReport, data: &FitData) -> Option<ResidualAnalysis> {
    let r = report.residuals(data).ok()?;
    let bounds = residuals::boundaries(&report.model, data);
    Some(residuals::analyse(&data.times, &r, None, bounds))
}

/// The whiteness test of a fit's residuals on its data ([`residuals::whiteness`]).
pub(super) fn whiteness(report: &FitReport, data: &FitData) -> Option<residuals::Whiteness> {
    report
        .residuals(data)
        .ok()
        .map(|r| residuals::whiteness(&r))
}

/// Whether the term of `param` no longer pays in `current`: the corrected BIC change of
/// adding it back (`delta`, from the model without it) is not below −[`BIC_THRESHOLD`], or
/// a dead time ended at or below zero (no dead time: a step-instant lead's share at most).
pub(super) fn no_longer_pays(current: &FitReport, param: Param, delta: f64) -> bool {
    let null_dead_time = param == Param::Td && current.model.get(Param::Td) <= 0.0;
    null_dead_time || !(delta.is_finite() && delta < -BIC_THRESHOLD)
}

/// The residuals' RMSE must exceed the white noise read from the output's first differences
/// ([`crate::fit::rest::difference_noise`]) this many times for pairs to be tried: strongly
/// coloured noise (AR(1) up to ρ = 0.97) stays below it, a missing pair of effects leaves
/// tens of times the noise.
pub(super) const FAR_FROM_WHITE: f64 = 8.0;

/// Whether what `current` leaves is far from white: not white by the residual analysis, and
/// its RMSE above [`FAR_FROM_WHITE`] times the output's white noise.
pub(super) fn far_from_white(data: &FitData, current: &FitReport) -> bool {
    let noise = crate::fit::rest::difference_noise(&data.y);
    current.rmse > FAR_FROM_WHITE * noise && whiteness(current, data).is_some_and(|w| !w.white)
}

/// Whether `candidate` pays by the plain BIC: kept when what `current` leaves is far from
/// white (tens of times the noise is structure, not coloured noise, whatever the
/// correlation of a first extension's residuals).
pub(super) fn plainly_pays(current: &FitReport, candidate: &FitReport) -> bool {
    let change = bic(candidate) - bic(current);
    change.is_finite() && change < -BIC_THRESHOLD
}

/// Whether `candidate` pays for its extra parameters over `current`: its corrected BIC
/// change is a finite number below −[`BIC_THRESHOLD`].
pub(super) fn pays(data: &FitData, current: &FitReport, candidate: &FitReport) -> bool {
    let change = judged_change(data, current, candidate);
    change.is_finite() && change < -BIC_THRESHOLD
}

/// The BIC change of `candidate` over `current` with the likelihood term counted on the
/// candidate's effective number of independent residuals: N·(1 − ρ)/(1 + ρ), ρ the lag-one
/// autocorrelation of its residuals (clamped to [0, 0.99]; 0 leaves the plain BIC). A right
/// extension leaves white residuals and keeps its full gain; one that only absorbs coloured
/// noise leaves them correlated and must gain that much more.
pub fn judged_change(data: &FitData, current: &FitReport, candidate: &FitReport) -> f64 {
    let rho = candidate
        .residuals(data)
        .map_or(0.0, |r| lag_one(&r))
        .clamp(0.0, 0.99);
    let n = candidate.n as f64;
    let n_eff = n * (1.0 - rho) / (1.0 + rho);
    let extra = candidate.params.len() as f64 - current.params.len() as f64;
    n_eff * (candidate.ln_mse - current.ln_mse) + extra * n.ln()
}

pub(super) fn aliased(r: &FitReport) -> bool {
    r.warnings
        .iter()
        .any(|w| matches!(w, crate::fit::FitWarning::Alias { .. }))
}

pub(super) fn gain(before: &FitReport, after: &FitReport) -> Gain {
    Gain {
        rmse_before: before.rmse,
        rmse_after: after.rmse,
        rmse_ratio: if after.rmse > 0.0 {
            before.rmse / after.rmse
        } else {
            f64::INFINITY
        },
        fit_percent_before: before.fit_percent,
        fit_percent_after: after.fit_percent,
        criterion_delta: bic(after) - bic(before),
    }
}

/// The slowest time constant of `model` (s): its poles' ([`time_constants`]: a pair's Tw,
/// not its envelope Tw/ζ, for a lightly damped ringing shows its period however slowly it
/// decays) and a zero's |Tz|; 0 for a model without any.
pub(super) fn slowest_lag(model: &Model) -> f64 {
    let zero = if model.structure.zero {
        model.get(Param::Tz).abs()
    } else {
        0.0
    };
    time_constants(model)
        .first()
        .copied()
        .unwrap_or(0.0)
        .max(zero)
}

/// Whether `candidate` leans on a time constant slower than the record can show: longer
/// than the record after its first change, and more than twice `current`'s slowest. Such a
/// lag (a pole or zero of thousands of seconds on a record of minutes) is not identifiable:
/// it only bends the tail, as a drift would, and its static gain is an extrapolation. It is
/// the mirror of [`aliased`], a lag too fast for the sampling.
pub(super) fn beyond_record(data: &FitData, current: &Model, candidate: &Model) -> bool {
    let slowest = slowest_lag(candidate);
    slowest > data.duration() && slowest > 2.0 * slowest_lag(current)
}
