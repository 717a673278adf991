//! What a fitted model gets wrong, why, how to extend it, and how much the extension gains.
//!
//! The loop, as the ball-and-tube notes walk it by hand:
//! 1. fit the start model (the student's, or `P1`);
//! 2. for every extension the structure can still take (a dead time, a free offset, an
//!    underdamped pair, one more pole, a zero, an integrator, a drift term) refit the
//!    extended model, warm-started from the current fit (and from the extended structure's
//!    automatic guess);
//! 3. the extension that lowers the Bayesian information criterion most names the cause,
//!    provided it pays for its extra parameter: BIC = N·ln(MSE) + p·ln(N) must drop by more
//!    than [`BIC_THRESHOLD`] (10: "very strong" evidence on Kass & Raftery's scale; for one
//!    extra parameter the MSE must fall by a factor e^{(10 + ln N)/N}, i.e. 2.1 % at N = 800);
//! 4. the cause is explained with evidence from the current residuals (which statistic, over
//!    which time interval), the gain is measured (RMSE before and after and their ratio, fit %
//!    before and after, the BIC change), and the loop repeats until nothing pays: `none`.
//!
//! Trying the extensions, rather than reading the cause off residual patterns alone, makes the
//! naming robust when several patterns overlap (a missing dead time and a missing pole both
//! make the model rise too early); the residual statistics then say *where* and *how*.
//! A zero and an inverse response are the same extension (Tz): its fitted sign names the cause.

pub(crate) mod cause;
pub mod drift_evidence;
mod explain;
pub(crate) mod extension;
pub mod holdout;
pub(crate) mod judge;
pub mod offset_evidence;
pub mod per_step;
mod report;
pub mod residuals;
mod search;
pub mod staircase;
mod step;
pub mod test_causes;
#[cfg(test)]
mod tests;
pub mod tracker;

pub use cause::Cause;
pub use extension::{Extensions, StartExtensions};
pub use judge::{BIC_THRESHOLD, analyse, bic, judged_change};
pub use report::{
    Artefacts, Bias, DiagnoseOptions, DiagnoseReport, Ending, Evidence, Gain, GainTrade, Step,
    TRADE_CORRELATION, TRADE_WIDTH, Verdict, Whiteness,
};
pub use step::next_step;

use crate::diagnose::test_causes::handling;
use crate::diagnose::tracker::Tracker;
use crate::fit::guess::auto_guess;
use crate::fit::{FitData, FitError, FitReport, fit};
use crate::model::{Model, Param, Structure, Values};
use explain::verdict;
use extension::{EXTENSIONS, Extension, oscillates, real_poles};
use report::gain_trade;
use step::{backward_step, next_step_with};

/// Runs the loop from `start`, fitted from its automatic guess; Y0 is held at
/// `start_values`' Y0 when the structure holds it (e.g. 0 for a model that starts at zero).
pub fn diagnose(
    data: &FitData,
    start: Structure,
    start_values: Option<Values>,
    options: &DiagnoseOptions,
) -> Result<DiagnoseReport, FitError> {
    let held_y0 = start_values.map(|v| v.get(Param::Y0));
    let mut guess = auto_guess(data, start, held_y0);
    if let Some(y0) = held_y0 {
        guess.set(Param::Y0, y0);
    }
    let first = fit(data, start, guess, &options.fit, &mut ())?;
    Ok(diagnose_from(data, first, options))
}

/// Runs the loop from a fit the student already has.
///
/// The order of reasoning: the test's causes first ([`handling::handle`]: not at rest,
/// outliers, a clipped span, a disturbance), each handled so that the loop sees the handled
/// problem (the fits of the chain are on the samples left in); then the model's causes, one
/// extension at a time (or two at once, [`next_step`]); then the robust loss on the
/// outliers and the intervals widened for coloured noise ([`handling::finish`]).
pub fn diagnose_from(
    data: &FitData,
    start: FitReport,
    options: &DiagnoseOptions,
) -> DiagnoseReport {
    diagnose_tracked(data, start, options, &Tracker::none())
}

/// [`diagnose_from`] reporting its progress to `tracker`, and ending early (with the chain
/// made so far) when the tracker says it was cancelled.
pub fn diagnose_tracked(
    data: &FitData,
    start: FitReport,
    options: &DiagnoseOptions,
    tracker: &Tracker,
) -> DiagnoseReport {
    let handled = handling::handle(data, start, &options.fit);
    let mut allowed = EXTENSIONS.to_vec();
    let (mut current, mut steps, mut adequate) =
        run_loop(&handled, options, &allowed, None, tracker);
    // The chain is made again while it ends on a term that was not what the record needs,
    // each time without that term, guided by the model reached ([`next_step_with`]: a pair
    // of extensions that paid there is tried here too, and starts from it).
    loop {
        let reached = real_poles(&current.model);
        let overdamped = current.model.structure.underdamped && !oscillates(&current);
        if overdamped && allowed.contains(&Extension::Underdamped) {
            // The pair ended overdamped (ζ ≥ 1 within its interval, once the other
            // extensions took their part): it is two real poles, and the chain is made
            // again without the oscillation, so that its steps name the extra pole (the
            // pole and the zero of an overshoot, each alone no better than coloured noise,
            // are tried as the pair that paid).
            allowed.retain(|e| *e != Extension::Underdamped);
            (current, steps, adequate) =
                run_loop(&handled, options, &allowed, Some(&reached), tracker);
            continue;
        }
        let Some(stand_in) = first_taken_out(&steps).filter(|e| allowed.contains(e)) else {
            break;
        };
        // The first term named was taken out again once the later terms were in: it stood
        // in for them (a dead time for an inverse response's dip, which the zero and its
        // pole then explain, so that the dead time ends at or below zero). The chain is
        // made again without it, so that its first step names what the record needs; it
        // replaces the first chain when it ends about as well (its BIC at most
        // [`BIC_THRESHOLD`] above), else the first chain stands.
        allowed.retain(|e| *e != stand_in);
        let again = run_loop(&handled, options, &allowed, Some(&reached), tracker);
        if bic(&again.0) > bic(&current) + BIC_THRESHOLD {
            break;
        }
        (current, steps, adequate) = again;
    }
    let mut test_causes = handled.causes.clone();
    let current = handling::finish(&handled, current, adequate, &mut test_causes);
    let mut verdict = verdict(&handled.data, &current, adequate);
    verdict.structure = Some(current.model.structure);
    verdict.artefacts = Artefacts::of(&test_causes);
    let kp = current.model.get(Param::Kp);
    DiagnoseReport {
        start: handled.start,
        static_gain: (kp, current.interval(Param::Kp)),
        gain_trade: gain_trade(&current),
        final_fit: current,
        steps,
        adequate,
        verdict: Some(verdict),
        test_causes,
    }
}

/// The extension of the chain's first step when it is a stand-in ([`step::STAND_INS`]) that
/// a later step took out again ([`backward_step`]).
fn first_taken_out(steps: &[Step]) -> Option<Extension> {
    let first = steps.first().filter(|s| !s.removed)?;
    let extension = match first.cause {
        Cause::DeadTime => Extension::Delay,
        Cause::Drift => Extension::Drift,
        _ => return None,
    };
    steps[1..]
        .iter()
        .any(|s| s.removed && s.cause == first.cause)
        .then_some(extension)
}

/// The loop on the handled record from its start, with the extensions `allowed`: the last
/// fit, the steps, and whether it ended because no extension paid.
fn run_loop(
    handled: &handling::Handled,
    options: &DiagnoseOptions,
    allowed: &[Extension],
    reached: Option<&Model>,
    tracker: &Tracker,
) -> (FitReport, Vec<Step>, bool) {
    let mut current = handled.start.clone();
    let mut steps = Vec::new();
    let mut allowed = allowed.to_vec();
    for k in 0..options.max_steps {
        if tracker.cancelled() {
            break;
        }
        tracker.extension(k + 1);
        // The first step's extensions may have been fitted by the test causes' handling.
        let known = handled.start_extensions.as_ref().filter(|_| k == 0);
        let Some(step) = next_step_with(&handled.data, &current, &allowed, known, reached, tracker)
        else {
            return (current, steps, true);
        };
        current = step.step.fit.clone();
        let added = step.extension;
        steps.push(step.step);
        // The backward look: a term added earlier that the later ones made useless is
        // taken out, and not tried again (the chain would go round).
        while let Some((extension, removal)) = backward_step(&handled.data, &current, added) {
            allowed.retain(|e| *e != extension);
            current = removal.fit.clone();
            steps.push(removal);
        }
    }
    (current, steps, false)
}
