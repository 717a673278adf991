//! The test's causes handled before the model's are judged (the order of reasoning of
//! [`crate::diagnose`], in [`super::TestCauseKind::ALL`]'s order): a test not at rest
//! gets an initial transient and a free Y0; outliers are left out of the structural search
//! (and the final fit weighs them with a robust loss, [`outliers::LOSS`]); a clipped span
//! and a disturbance's window are left out of every fit. Each exclusion is followed by a
//! refit from the current optimum, so the next check sees the handled problem. When the
//! changes' own gains differ (`nonlinearity`), the model is sought on the first change's
//! window ([`on_first_step_when_nonlinear`]).
//!
//! Two judgements here do not trust the joint fit alone. Whether the changes were held
//! long enough to compare their gains is read from the changes' own fits too
//! ([`held_for_comparison`]): a linear fit through gains that differ bends its lag, and
//! would hide the nonlinearity behind it. And a motion before the first change that is
//! significant but small against the record's range is still a test not at rest when the
//! initial transient explains it, on the whole record and on the samples before the change
//! alone, having been seen over the transient's half-life ([`small_motion_that_matters`]).

use super::{
    FittedRecord, TestCause, closed_loop::closed_loop, coloured_noise, disturbance, fit_held,
    imperfect_step, nonlinearity, not_at_rest, not_at_rest_with, outliers, own_fit_held,
    quantisation, read_within_quanta, sampling, saturation, small_step, steps_held, time_constants,
};
use crate::diagnose::drift_evidence::{read_drift, read_drift_after};
use crate::diagnose::extension::{Extensions, StartExtensions};
use crate::diagnose::judge::{BIC_THRESHOLD, bic};
use crate::diagnose::per_step::{
    MAX_PER_STEP, StepFit, per_step_fits, widen_steps_for_colour, window_data,
};
use crate::fit::guess::auto_guess;
use crate::fit::rest::{Motion, motion_within_range};
use crate::fit::robust::{RobustFit, robust_fit};
use crate::fit::{FitData, FitOptions, FitReport, fit, within_span};
use crate::model::{Param, Structure};

/// A record with its test's artefacts handled.
#[derive(Debug, Clone)]
pub struct Handled {
    /// The samples the structural search fits (outliers, clipped spans and disturbance
    /// windows left out).
    pub data: FitData,
    /// The samples the final robust fit uses (clipped spans and disturbance windows left
    /// out, outliers kept and down-weighted); `None` without outliers.
    pub robust_data: Option<FitData>,
    /// The start model refitted on `data` (with an initial transient when not at rest).
    pub start: FitReport,
    /// The causes found, in the order found.
    pub causes: Vec<TestCause>,
    /// The single extensions of `start` on `data`, when a test fitted them ([`StartExtensions`]).
    pub start_extensions: Option<Extensions>,
}

/// The samples of the record still in, as indices into the original record.
struct Kept {
    keep: Vec<bool>,
}

impl Kept {
    fn indices(&self) -> Vec<usize> {
        (0..self.keep.len()).filter(|&i| self.keep[i]).collect()
    }

    /// Leaves out `local` (indices into the kept samples).
    fn drop(&mut self, local: &[usize]) {
        let map = self.indices();
        for &i in local {
            self.keep[map[i]] = false;
        }
    }
}

/// Finds and handles the artefacts of the test on `data`, starting from the fit `start`.
pub fn handle(data: &FitData, start: FitReport, fit_options: &FitOptions) -> Handled {
    let mut causes = Vec::new();
    let mut current = start;
    if let Some(cause) = not_at_rest(data) {
        let transient = with_transient(data, &current, fit_options);
        if !drift_explains_motion(data, &current, transient.as_ref(), fit_options) {
            causes.push(cause);
            if let Some(r) = transient {
                current = r;
            }
        }
    } else if let Some((cause, transient)) = small_motion_that_matters(data, &current, fit_options)
    {
        causes.push(cause);
        current = transient;
    }
    causes.extend(FittedRecord::new(data, &current).and_then(|r| closed_loop(&r)));
    let mut kept = Kept {
        keep: vec![true; data.y.len()],
    };
    if let Some((cause, samples)) = saturation::detect(data, &current) {
        causes.push(cause);
        kept.drop(&samples);
        current = refit(&data.keeping(&kept.keep), &current).unwrap_or(current);
    }
    let mut handled = data.keeping(&kept.keep);
    let mut outlier_samples = Vec::new();
    if let Ok(r) = current.residuals(&handled)
        && let Some((cause, samples)) = outliers::detect(&handled, &r)
    {
        causes.push(cause);
        let map = kept.indices();
        outlier_samples = samples.iter().map(|&i| map[i]).collect();
        kept.drop(&samples);
        handled = data.keeping(&kept.keep);
        current = refit(&handled, &current).unwrap_or(current);
    }
    let mut start_extensions = None;
    if let Ok(r) = current.residuals(&handled) {
        let extensions = StartExtensions::new(&handled, &current);
        let found = disturbance::detect_with(&handled, &current, &r, &extensions);
        let fitted = extensions.fitted();
        match found {
            Some((cause, samples)) => {
                causes.push(cause);
                kept.drop(&samples);
                handled = data.keeping(&kept.keep);
                current = refit(&handled, &current).unwrap_or(current);
            }
            // The record and the start are the loop's: its first step chooses among the
            // extensions the test fitted.
            None => start_extensions = fitted,
        }
    }
    let robust_data = (!outlier_samples.is_empty()).then(|| {
        let mut keep = kept.keep.clone();
        outlier_samples.iter().for_each(|&i| keep[i] = true);
        data.keeping(&keep)
    });
    within_record(&mut causes, &data.times);
    let mut handled = Handled {
        data: handled,
        robust_data,
        start: current,
        causes,
        start_extensions,
    };
    on_first_step_when_nonlinear(&mut handled);
    handled
}

/// Each cause's interval cut to the record's span, [first sample, last sample]: the
/// evidence points into the record, never past its ends (an interval set by a model's time
/// constant may reach beyond); an interval wholly outside it is dropped.
fn within_record(causes: &mut [TestCause], times: &[f64]) {
    for c in causes {
        c.interval = c.interval.and_then(|i| within_span(times, i));
    }
}

/// `not_at_rest` for a motion before the first change beyond the noise but small against
/// the record's range ([`motion_within_range`]), when it matters to the fit: the start
/// structure with the initial transient pays for its parameters by the BIC threshold
/// ([`BIC_THRESHOLD`]) on the whole record and on the samples before the change alone
/// ([`explains_before`]), and a drift does not explain the motion instead
/// ([`drift_explains_motion`]). Without it, the earlier response's tail is left for the
/// model's loop, which bends a zero or a dead time to the start of the response; with it,
/// the transient models it as the free response of the same poles. A motion that changes
/// nothing in the fit is not worth the words.
fn small_motion_that_matters(
    data: &FitData,
    current: &FitReport,
    options: &FitOptions,
) -> Option<(TestCause, FitReport)> {
    let motion = motion_within_range(data)?;
    let transient = with_transient(data, current, options)?;
    let pays = bic(&transient) < bic(current) - BIC_THRESHOLD;
    (pays
        && seen_over_half_life(&motion, &transient)
        && explains_before(data, current, &transient, motion.samples)
        && !drift_explains_motion(data, current, Some(&transient), options))
    .then(|| (not_at_rest_with(motion), transient))
}

/// Whether the motion before the change was seen for at least the half-life of the
/// transient's slowest pole (ln 2 of its time constant): most of what the transient
/// attributes to the earlier response is then in the record, not extrapolated from it. On
/// a stretch short against the lag, the free response is a straight line whose slope
/// alone fixes a transient many times the motion seen (ten samples of a heater moving by
/// 0.4 before its step, read with its two-minute lag, made a transient of 5.5 that traded
/// with the gain): a line there is as much a drift, or the noise's wander.
fn seen_over_half_life(motion: &Motion, transient: &FitReport) -> bool {
    let span = motion.span.1 - motion.span.0;
    time_constants(&transient.model)
        .first()
        .is_some_and(|&slowest| span >= std::f64::consts::LN_2 * slowest)
}

/// Whether `transient` explains the first `samples` samples (those before the first
/// change) better than `current` by the BIC threshold, n·ln(SSE ratio) > [`BIC_THRESHOLD`]
/// on them alone. The initial transient is the free response of the model's poles over
/// the whole record, and with Y0 free it can also bend the response after the change (and
/// trade with the gain: a record of ten samples before its step, read as a transient of the
/// heater's two-minute lag, lost a third of its gain); only the samples before the change
/// are what a test not at rest, and nothing else, explains.
fn explains_before(
    data: &FitData,
    current: &FitReport,
    transient: &FitReport,
    samples: usize,
) -> bool {
    let sse = |r: &FitReport| {
        r.residuals(data)
            .ok()
            .map(|e| e.iter().take(samples).map(|v| v * v).sum::<f64>())
    };
    match (sse(current), sse(transient)) {
        (Some(before), Some(after)) if after > 0.0 => {
            samples as f64 * (before / after).ln() > BIC_THRESHOLD
        }
        _ => false,
    }
}

/// The start structure with an initial transient and a free Y0, fitted from its guess.
fn with_transient(data: &FitData, current: &FitReport, options: &FitOptions) -> Option<FitReport> {
    let mut s: Structure = current.model.structure;
    s.transient = true;
    s.free_offset = true;
    let guess = auto_guess(data, s, None);
    fit(data, s, guess, options, &mut ()).ok()
}

/// The current structure refitted on `data` from its optimum (one start).
fn refit(data: &FitData, current: &FitReport) -> Option<FitReport> {
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    fit(
        data,
        current.model.structure,
        current.model.values,
        &options,
        &mut (),
    )
    .ok()
}

/// The loop's final fit with the handling that comes after it: the robust loss on the
/// outliers ([`outliers::LOSS`]), and, when the loop ended because no extension paid
/// (`adequate`), the intervals widened for correlated residuals, which names
/// `coloured_noise`; the causes found are appended to `causes`, then all are put in
/// [`super::TestCauseKind::ALL`]'s order.
pub fn finish(
    handled: &Handled,
    last: FitReport,
    adequate: bool,
    causes: &mut Vec<TestCause>,
) -> FitReport {
    let found_before = causes.len();
    let mut last = match &handled.robust_data {
        Some(d) => robust(d, &last).map_or(last, |r| r.report),
        None => last,
    };
    if adequate
        && let Ok(r) = last.residuals(&handled.data)
        && let Some(cause) = coloured_noise::detect(&handled.data.times, &r)
    {
        if let super::Handling::IntervalsWidened { factor } = cause.handling {
            last.widen_intervals(factor);
        }
        causes.push(cause);
    }
    causes.extend(reported(&handled.data, &last));
    within_record(&mut causes[found_before..], &handled.data.times);
    causes.sort_by_key(|c| super::TestCauseKind::ALL.iter().position(|k| *k == c.kind));
    last
}

/// The causes that change nothing in the fit, read off the final model and the record:
/// an imperfect step, the output's resolution, the sampling period against the notes'
/// rules, a step small against the noise, and each change's own gain against the others
/// (on a record [`on_first_step_when_nonlinear`] did not already cut to its first step).
fn reported(data: &FitData, last: &FitReport) -> Vec<TestCause> {
    let mut found: Vec<TestCause> = imperfect_step(data).into_iter().collect();
    if let Some(record) = FittedRecord::new(data, last) {
        found.extend(quantisation(&record).map(|c| read_within_quanta(c, &record)));
        found.extend(sampling(&record));
        found.extend(small_step(&record));
    }
    found.extend(step_gains_differ(data, last).map(|(cause, _)| cause));
    found
}

/// `nonlinearity` on a record of 2 to [`MAX_PER_STEP`] changes, each held long enough to
/// show its response ([`steps_held`]): each change fitted on its own window with
/// `fitted`'s process model, against `fitted` itself; the cause with the per-step fits.
fn step_gains_differ(data: &FitData, fitted: &FitReport) -> Option<(TestCause, Vec<StepFit>)> {
    let changes = data.input.changes.len();
    if !(2..=MAX_PER_STEP).contains(&changes) {
        return None;
    }
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let fits = own_fits(data, fitted, &options);
    if !held_for_comparison(data, fitted, &fits) {
        return None;
    }
    // Judged on intervals as honest as the model's fit: a structure about to be extended
    // leaves correlated residuals, and its white-noise intervals would call a linear
    // record's steps different. The fits returned keep their own intervals (a model started
    // from one is widened once, at the end, for what its own residuals show).
    let mut judged = fits.clone();
    widen_steps_for_colour(data, &mut judged);
    // Only changes held through their response are evidence (the others' gains rest on an
    // extrapolated tail): at least two of them must differ.
    let held: Vec<StepFit> = judged
        .iter()
        .filter(|f| fit_held(f, &fitted.model))
        .cloned()
        .collect();
    if held.len() < 2 {
        return None;
    }
    let cause = nonlinearity(&held)?;
    if drift_explains_gains(data, fitted, &options) {
        return None;
    }
    Some((cause, fits))
}

/// Each change of `data` fitted on its own window with `fitted`'s process model
/// ([`per_step_fits`]), the first with an initial transient when `fitted` has one. A
/// record found not at rest was moving before its first change, but the first window
/// holds only the last third of that stretch, where the motion may be too small for the
/// window's own rest test: fitted from rest, its gain would take the earlier response's
/// tail for its own, and differ from the others' as a nonlinearity's would.
fn own_fits(data: &FitData, fitted: &FitReport, options: &FitOptions) -> Vec<StepFit> {
    let mut structure = fitted.model.structure;
    let moving = structure.transient;
    structure.transient = false;
    let mut fits = per_step_fits(data, structure, options);
    if moving && let Some(first) = fits.first_mut().filter(|f| !f.not_at_rest) {
        structure.transient = true;
        if let Some(refit) = first_from_motion(data, structure, options) {
            *first = refit;
        }
    }
    fits
}

/// The first change of `data` fitted on its own window ([`window_data`]) with an initial
/// transient, as [`per_step_fits`] fits a window found not at rest: Y0 free, the step
/// instant's lead when the record has one.
fn first_from_motion(
    data: &FitData,
    structure: Structure,
    options: &FitOptions,
) -> Option<StepFit> {
    let window = window_data(data, 0)?;
    let s = Structure {
        free_offset: true,
        drift: false,
        lead: window.input.lead_range > 0.0,
        transient: true,
        ..structure
    };
    let guess = auto_guess(&window, s, None);
    let span = (*window.times.first()?, *window.times.last()?);
    Some(StepFit {
        change: *data.input.changes.first()?,
        window: span,
        not_at_rest: true,
        fit: fit(&window, s, guess, options, &mut ()),
    })
}

/// Whether at least two changes of `data` were held long enough for their gains to be
/// compared: by the joint fit's time scales ([`steps_held`]), or, when the joint fit says
/// not, by the changes' own fits, each window showing its level within its own intervals
/// ([`own_fit_held`]). The joint fit alone cannot decide it: a linear model through
/// changes whose gains differ bends its lags to compromise between their levels, and the
/// very nonlinearity to be named would hide itself behind a lag no change shows.
fn held_for_comparison(data: &FitData, fitted: &FitReport, fits: &[StepFit]) -> bool {
    steps_held(data, &fitted.model) || fits.iter().filter(|f| own_fit_held(f)).count() >= 2
}

/// Whether the motion before the first change is a drift rather than a test not at rest.
///
/// A drift is a straight line across the whole record: its slope before the change goes on,
/// the same, on the stretches where the test's own responses have settled. A test not at
/// rest is an earlier response dying out, the free response of the process's own poles: a
/// curve that bends towards rest, gone by the time the test's responses settle. So the
/// drift explains the motion when the current model with a drift term shows its drift
/// ([`read_drift`], over the stretch before the change and the settled ones), and the
/// settled stretches after the changes alone ([`read_drift_after`]) either show it too, or
/// go on with its slope (its sign and size, not significant on their own: short stretches,
/// coloured noise) while the drift explains the record better than the initial transient
/// does (`transient`, the same model with the transient; BIC, each with its own parameters).
fn drift_explains_motion(
    data: &FitData,
    current: &FitReport,
    transient: Option<&FitReport>,
    options: &FitOptions,
) -> bool {
    let Some(with_drift) = with_drift(data, current, options) else {
        return false;
    };
    let drift = with_drift.model.get(Param::Drift);
    if !read_drift(data, &current.model, &with_drift).is_some_and(|d| d.shows(drift)) {
        return false;
    }
    let Some(after) = read_drift_after(data, &current.model, &with_drift) else {
        return false;
    };
    after.shows(drift)
        || (after.continues(drift) && transient.is_none_or(|t| bic(&with_drift) < bic(t)))
}

/// `current`'s structure with a drift term, fitted from its values (the drift from 0);
/// `None` for a structure that has one, or an initial transient, or a fit that fails.
fn with_drift(data: &FitData, current: &FitReport, options: &FitOptions) -> Option<FitReport> {
    let mut s = current.model.structure;
    if s.drift || s.transient {
        return None;
    }
    s.drift = true;
    let mut guess = current.model.values;
    guess.set(Param::Drift, 0.0);
    fit(data, s, guess, options, &mut ()).ok()
}

/// Whether a drift the record shows where no change is answered ([`read_drift`]) makes the
/// changes' gains agree: a drift adds to the level an up step reaches and takes from a down
/// step's, so their own gains differ as a nonlinearity's would. The joint model is refitted
/// with a drift; when the drift is shown, the per-step gains are compared again on the
/// output less that drift, and if they agree there is no nonlinearity to name (the model's
/// loop names the drift).
fn drift_explains_gains(data: &FitData, fitted: &FitReport, options: &FitOptions) -> bool {
    let Some(with_drift) = with_drift(data, fitted, options) else {
        return false;
    };
    let drift = with_drift.model.get(Param::Drift);
    if !read_drift(data, &fitted.model, &with_drift).is_some_and(|d| d.shows(drift)) {
        return false;
    }
    let mut detrended = data.clone();
    let t0 = data.input.t0();
    for (y, t) in detrended.y.iter_mut().zip(&data.times) {
        *y -= drift * (t - t0);
    }
    let mut joint = with_drift;
    joint.model.structure.drift = false;
    let mut fits = own_fits(&detrended, &joint, options);
    widen_steps_for_colour(&detrended, &mut fits);
    let held: Vec<StepFit> = fits
        .into_iter()
        .filter(|f| fit_held(f, &joint.model))
        .collect();
    held.len() >= 2 && nonlinearity(&held).is_none()
}

/// `nonlinearity` checked before the model's causes. A gain that differs between the up
/// and the down step (or from one operating point to another) leaves a joint linear fit
/// levels it cannot reach, and a drift, a zero or a pole would be kept to absorb them, with
/// lags bent to suit. So when the changes' own gains differ, the cause is named and the
/// model is sought where a linear model holds: on the first change's window (the step from
/// the operating point the test started at, the notes' advice of a step about one
/// operating point), starting from that change's own fit; the samples from the second
/// change on are left out of the fit (the cause's handling says so), and the per-step
/// table in the evidence shows every change. The robust fit's data are cut the same way.
fn on_first_step_when_nonlinear(handled: &mut Handled) {
    let Some((mut cause, fits)) = step_gains_differ(&handled.data, &handled.start) else {
        return;
    };
    // The first change's window alone must show the gain: a change not held through its
    // response would leave a model whose gain the samples kept cannot determine.
    let t_first = handled.data.input.t0();
    let first = fits
        .into_iter()
        .find(|f| f.change.t == t_first)
        .filter(|f| fit_held(f, &handled.start.model))
        .and_then(|f| f.fit.ok());
    let cut = handled.data.input.changes.get(1).map(|c| c.t);
    let end = handled.data.times.last().copied();
    if let (Some(first), Some(window), Some(start), Some(end)) =
        (first, window_data(&handled.data, 0), cut, end)
    {
        handled.robust_data = handled.robust_data.take().and_then(|d| window_data(&d, 0));
        handled.data = window;
        handled.start = first;
        handled.start_extensions = None;
        cause.handling = super::Handling::Excluded { start, end };
    }
    handled.causes.push(cause);
}

fn robust(data: &FitData, last: &FitReport) -> Option<RobustFit> {
    robust_fit(
        data,
        last.model.structure,
        last.model.values,
        outliers::LOSS,
    )
    .ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::test_causes::{Handling, TestCauseKind, TestEvidence};

    #[test]
    fn an_interval_past_the_record_is_cut_to_it() {
        let cause = |interval| TestCause {
            kind: TestCauseKind::SmallStep,
            evidence: TestEvidence::SmallStep {
                effect: 1.0,
                noise: 0.5,
                ratio: 2.0,
            },
            interval,
            handling: Handling::Reported,
        };
        let times = [1342.0, 2000.0, 86_355.0];
        let mut causes = [
            cause(Some((1342.0, 8.546e6))),
            cause(Some((-5.0, 10_000.0))),
            cause(Some((9.0e4, 1.0e5))),
            cause(None),
        ];
        within_record(&mut causes, &times);
        let got: Vec<_> = causes.iter().map(|c| c.interval).collect();
        assert_eq!(
            got,
            [
                Some((1342.0, 86_355.0)),
                Some((1342.0, 10_000.0)),
                None,
                None
            ]
        );
    }
}
