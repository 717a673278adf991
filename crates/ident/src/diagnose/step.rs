//! One step of the chain: the extension that pays most (a pole preferred to a dead time
//! that only stands in for it, an integrator to a pole whose lag the record cannot show
//! settling, a pair where no single extension pays, a look ahead past a
//! stand-in), checked on held-out data and against the output's rounding; and the backward
//! step that drops a parameter that no longer pays.

use super::cause::Cause;
use super::explain::explain;
use super::extension::{
    EXTENSIONS, Extension, Extensions, best_pair, candidates, full_fit, on_every_sample,
};
use super::judge::{
    BIC_THRESHOLD, bic, far_from_white, gain, judged_change, no_longer_pays, pays, plainly_pays,
    slowest_lag,
};
use super::report::{Evidence, Step};
use crate::diagnose::holdout::Validation;
use crate::diagnose::staircase::Staircase;
use crate::diagnose::tracker::Tracker;
use crate::fit::{FitData, FitOptions, FitReport, search_fit};
use crate::model::{Model, Param, Structure};

/// The terms of `current` the backward look may take out, but not `added`, the one just
/// paid for: the first whose term no longer pays ([`no_longer_pays`]), with the step that
/// removes it.
pub(super) fn backward_step(
    data: &FitData,
    current: &FitReport,
    added: Extension,
) -> Option<(Extension, Step)> {
    // The refits without each term are independent: spread over the cores, the first in
    // EXTENSIONS' order that no longer pays is taken.
    let removable: Vec<(Extension, Structure, Param)> = EXTENSIONS
        .into_iter()
        .filter(|e| *e != added)
        .filter_map(|e| {
            let (s, param) = e.removed(current.model.structure)?;
            Some((e, s, param))
        })
        .collect();
    let refits = crate::parallel::map(&removable, |&(_, s, _)| refit_without(data, current, s));
    removable
        .into_iter()
        .zip(refits)
        .find_map(|((e, _, param), without)| {
            let without = without?;
            let delta = judged_change(data, &without, current);
            no_longer_pays(current, param, delta).then(|| {
                let step = Step {
                    cause: e.cause(&current.model.values),
                    paired: None,
                    evidence: Evidence::NoLongerPays {
                        param,
                        value: current.model.get(param),
                        ci95: current.interval(param),
                        criterion_delta: delta,
                    },
                    interval: None,
                    gain: gain(current, &without),
                    fit: without,
                    removed: true,
                };
                (e, step)
            })
        })
}

/// `current` refitted without a term (structure `s`), from its own values (one start).
pub(super) fn refit_without(
    data: &FitData,
    current: &FitReport,
    s: Structure,
) -> Option<FitReport> {
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let r = search_fit(data, s, current.model.values, &options).ok()?;
    let full = full_fit(data, r)?;
    full.ln_mse.is_finite().then_some(full)
}

/// The leading cause of what `current` gets wrong and the extended fit, or `None` when no
/// extension pays for itself. An extension is judged by the BIC corrected for its own fit's
/// residual correlation ([`judged_change`]), so that coloured noise buys no structure; when
/// no single extension pays but the residuals are far from white, pairs of extensions are
/// tried ([`best_pair`]: P1 → P2Z, P1 → P2D, …), and a pair that pays is one step naming
/// both causes.
pub fn next_step(data: &FitData, current: &FitReport) -> Option<Step> {
    next_step_with(data, current, &EXTENSIONS, None, None, &Tracker::none()).map(|c| c.step)
}

/// A step of the loop with the extension it made.
pub(super) struct Chosen {
    pub(super) extension: Extension,
    pub(super) step: Step,
}

/// [`next_step`] with only the extensions `allowed`, choosing among the extensions `known`
/// when they were fitted already (of `current` on `data`). `reached` is a model the record
/// is known to reach (a chain made again without the oscillation: the first chain's model,
/// its overdamped pair as two real poles): pairs are tried whatever the single extensions
/// leave, since that chain paid for its pair, and an extension whose structure is the
/// model's starts from it too.
pub(super) fn next_step_with(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    known: Option<&Extensions>,
    reached: Option<&Model>,
    tracker: &Tracker,
) -> Option<Chosen> {
    let candidates = match known {
        Some(Extensions(all)) => all
            .iter()
            .filter(|(e, _)| allowed.contains(e))
            .cloned()
            .collect(),
        None => candidates(data, current, allowed, reached, tracker),
    };
    let lowest = |list: Vec<&(Extension, FitReport)>| {
        list.into_iter()
            .min_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)))
            .cloned()
    };
    let leader = lowest(candidates.iter().collect());
    let far = far_from_white(data, current);
    // Every candidate of the step is validated against the same current model.
    let validation = Validation::new(data, current);
    // The corrected BIC judges first: of the extensions that pay by it, the lowest BIC; only
    // when none does, and what is left is far from white, the lowest BIC by the plain one.
    // Of those, the lowest BIC that also predicts the part of the record it was not
    // fitted to ([`validates`]): a drift or a zero bought on the fitted part extrapolates
    // badly, a real pole does not.
    let mut paying: Vec<&(Extension, FitReport)> = candidates
        .iter()
        .filter(|(_, c)| pays(data, current, c))
        .collect();
    paying.sort_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)));
    prefer_pole_to_dead_time(&mut paying);
    prefer_integrator_to_lag_beyond_record(data, &mut paying);
    let paying = paying
        .into_iter()
        .find(|(_, c)| validation.keeps(c))
        .cloned();
    let leader_extension = leader.as_ref().map(|(e, _)| *e);
    // The leader pays by the plain BIC but not by the corrected one: its residuals are
    // correlated, which coloured noise does, and so does a second effect still missing
    // (P2U without its dead time on the LECI test); pairs may tell, judged by the corrected
    // BIC, which coloured noise does not pass.
    let leader_plainly = leader
        .as_ref()
        .is_some_and(|(_, c)| plainly_pays(current, c));
    // A free Y0 pays by the corrected BIC only: one constant absorbs a share of any misfit
    // that is far from white (an actuator's motion the held input does not show, a model
    // still short of a pole), and an operating point that is really off leaves residuals
    // biased everywhere, which pay by both.
    let single = paying
        .or_else(|| leader.clone().filter(|(_, c)| far && validation.keeps(c)))
        .and_then(|w| on_every_sample(data, w))
        .filter(|(e, c)| {
            pays(data, current, c)
                || (far && *e != Extension::FreeOffset && plainly_pays(current, c))
        });
    let single = single.map(|w| look_ahead(data, current, allowed, w, &validation, tracker));
    let (extension, paired, candidate) = match single {
        Some(chosen) => chosen,
        None => {
            if !far && !leader_plainly && reached.is_none() {
                return None;
            }
            let ((mut e1, mut e2), c) = best_pair(data, current, allowed, reached, tracker)?;
            if !pays(data, current, &c) || !validation.keeps(&c) {
                return None;
            }
            // The pair's member that did best alone is named first.
            if leader_extension == Some(e2) {
                std::mem::swap(&mut e1, &mut e2);
            }
            (e1, Some(e2.cause(&c.model.values)), c)
        }
    };
    // On a staircase, an extension must gain more than rounding alone lets it.
    if Staircase::of(data, current).is_some_and(|s| !s.beyond_rounding(data, current, &candidate)) {
        return None;
    }
    let cause = extension.cause(&candidate.model.values);
    let (evidence, interval) = explain(cause, data, current, &candidate);
    // The evidence points into the record, never past its ends (an interval set by a time
    // constant stuck at its bound may reach far beyond).
    let interval = interval.and_then(|i| data.within_record(i));
    Some(Chosen {
        extension,
        step: Step {
            cause,
            paired,
            evidence,
            interval,
            gain: gain(current, &candidate),
            fit: candidate,
            removed: false,
        },
    })
}

/// A dead time and one more pole the record cannot tell apart (their BICs within
/// [`BIC_THRESHOLD`]): the classic first-order-plus-dead-time reading of a slow second lag,
/// whose dead time trades with the slow lag and the gain on a record that has not settled.
/// The pole is put first: it is the process's own structure, and its gain the settled one.
pub(super) fn prefer_pole_to_dead_time(paying: &mut [&(Extension, FitReport)]) {
    let Some(first) = paying.first() else { return };
    if first.0 != Extension::Delay {
        return;
    }
    let lead = bic(&first.1);
    if let Some(k) = paying
        .iter()
        .position(|(e, c)| *e == Extension::Pole && bic(c) - lead < BIC_THRESHOLD)
    {
        paying[..=k].rotate_right(1);
    }
}

/// An integrator and one more pole whose slow lag is longer than the record (its slowest
/// time constant beyond [`FitData::duration`]) that the record cannot tell apart (their BICs
/// within [`BIC_THRESHOLD`]; on a staircase, where rounding sways least squares, their BICs
/// on the censored likelihood of [`Staircase::censored_change`]): such a lag never shows
/// its level, it only bends a ramp, and its static gain is an extrapolation (tens or
/// hundreds of times the ramp's slope over a lag). What the record shows is the ramp,
/// which only the integrator explains with a gain it measures (the slope): the integrator
/// is put first.
pub(super) fn prefer_integrator_to_lag_beyond_record(
    data: &FitData,
    paying: &mut [&(Extension, FitReport)],
) {
    let Some(first) = paying.first() else { return };
    if first.0 != Extension::Pole || slowest_lag(&first.1.model) <= data.duration() {
        return;
    }
    let lead = bic(&first.1);
    // The pole's residuals tell whether the record is a staircase (the start's residuals
    // still hold the ramp it misses).
    let staircase = Staircase::of(data, &first.1);
    let within = |c: &FitReport| {
        bic(c) - lead < BIC_THRESHOLD
            || staircase.is_some_and(|s| {
                s.censored_change(data, &first.1, c)
                    .is_some_and(|change| change < BIC_THRESHOLD)
            })
    };
    if let Some(k) = paying
        .iter()
        .position(|(e, c)| *e == Extension::Integrator && within(c))
    {
        paying[..=k].rotate_right(1);
    }
}

/// Extensions that mimic a missing part of the dynamics from the first step: a dead time
/// takes an inverse response's dip or a fast lag's slow start, a drift a slow approach, a
/// free Y0 a share of any misfit. When one of them leads, the pairs are looked at too.
pub(super) const STAND_INS: [Extension; 3] =
    [Extension::Delay, Extension::Drift, Extension::FreeOffset];

/// The one-step look-ahead, so that a first wrong turn does not trap the loop: when the
/// single extension chosen is a stand-in ([`STAND_INS`]) and what `current` leaves is far
/// from white, the best pair of dynamic extensions ([`best_pair`]) is taken instead if it
/// pays over the single one by the corrected BIC and predicts the held-out part as well
/// (P1 → P2Z for an inverse response, which a dead time first only approximates). The
/// chosen extension, a second one named with it, and the fit.
pub(super) fn look_ahead(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    (e, c): (Extension, FitReport),
    validation: &Validation,
    tracker: &Tracker,
) -> (Extension, Option<Cause>, FitReport) {
    if !STAND_INS.contains(&e) || !far_from_white(data, current) {
        return (e, None, c);
    }
    let Some(((mut e1, mut e2), pair)) = best_pair(data, current, allowed, None, tracker) else {
        return (e, None, c);
    };
    let better = judged_change(data, &c, &pair) < -BIC_THRESHOLD;
    if !better || !validation.keeps(&pair) {
        return (e, None, c);
    }
    if e == e2 {
        std::mem::swap(&mut e1, &mut e2);
    }
    (e1, Some(e2.cause(&pair.model.values)), pair)
}
