//! `nonlinearity`: on a record with several input changes, each change's own fit
//! ([`per_step_fits`](crate::diagnose::per_step::per_step_fits)) gives a static gain; a linear
//! process gives the same one every time. Named when two changes' gains differ beyond both
//! 95 % intervals (widened for the colour of each window's residuals,
//! [`widen_steps_for_colour`](crate::diagnose::per_step::widen_steps_for_colour)) and by more
//! than the record resolves ([`RESOLVED_SHARE`]): up against down, small against large, one
//! operating point against another. The evidence lists every change's gain with its
//! interval. Only the changes held long enough to show their gain ([`HELD_LAGS`] time
//! constants beyond the dead time, [`fit_held`]): a change made while the output still
//! moves is no evidence on its own, its gain resting on the extrapolated tail of the
//! response before it.
//! Cost: nothing beyond the per-step fits the diagnosis already has.

use crate::diagnose::per_step::{RESOLVED_SHARE, StepFit};
use crate::fit::FitData;
use crate::model::{Model, Param};

use super::{Handling, StepGain, TestCause, TestCauseKind, TestEvidence, TimeScales};

/// A change must be held this many of the model's slowest time constants (beyond its dead
/// time) for its own gain to be read: after three the response has reached 95 % of its
/// level, and the window's level is the change's, not an extrapolation of a tail.
pub const HELD_LAGS: f64 = 3.0;

/// The least hold (s) for `model`'s response to show its gain: its dead time plus
/// [`HELD_LAGS`] of its slowest time constant; `None` for a model without a time constant.
fn needed_hold(model: &Model) -> Option<f64> {
    let scales = TimeScales::of(model);
    let slowest = scales.time_constants.first().copied()?;
    Some(scales.dead_time + HELD_LAGS * slowest)
}

/// Whether change `k` of `data` was held long enough for its own gain to be read: until the
/// next change (or the record's end) at least [`needed_hold`]. A shorter hold is an
/// actuator's overshoot settling, a wobble's swing, a busy input, or a change made while
/// the output still moved: cut into such windows, each piece's "gain" rests on how the
/// previous response's tail is extrapolated, not on a level the process reached.
pub fn change_held(data: &FitData, model: &Model, k: usize) -> bool {
    let (Some(needed), Some(c)) = (needed_hold(model), data.input.changes.get(k)) else {
        return false;
    };
    let end = data.times.last().copied().unwrap_or(f64::NEG_INFINITY);
    let until = data.input.changes.get(k + 1).map_or(end, |next| next.t);
    until - c.t >= needed
}

/// Whether at least two changes of `data` were held long enough ([`change_held`]) for
/// their gains to be compared.
pub fn steps_held(data: &FitData, model: &Model) -> bool {
    (0..data.input.changes.len())
        .filter(|&k| change_held(data, model, k))
        .count()
        >= 2
}

/// Whether a change's own fit was held long enough by its own model ([`needed_hold`];
/// `joint`'s when the change's own fit failed): its window, from the change to the last
/// sample before the next one, shows its gain. The change's own lags, not the joint fit's:
/// a nonlinearity bends the joint fit's lags too.
pub fn fit_held(f: &StepFit, joint: &Model) -> bool {
    let own = f.fit.as_ref().ok().and_then(|r| needed_hold(&r.model));
    own.or_else(|| needed_hold(joint))
        .is_some_and(|needed| f.window.1 - f.change.t >= needed)
}

/// The time scales that set how long a change must be held, as slow as `report`'s 95 %
/// intervals allow: each lag and the dead time at its interval's upper end; `None` when one
/// of them has no interval (the window did not determine it).
fn slowest_allowed(report: &crate::fit::FitReport) -> Option<Model> {
    let mut model = report.model;
    let s = model.structure;
    let mut scales = vec![Param::Tp1, Param::Tp2, Param::Tp3];
    scales.truncate(s.poles as usize);
    if s.underdamped {
        scales = vec![Param::Tw];
        if s.poles == 3 {
            scales.push(Param::Tp3);
        }
    }
    if s.delay {
        scales.push(Param::Td);
    }
    for p in scales {
        let (_, high) = report.interval(p)?;
        model.values.set(p, high);
    }
    Some(model)
}

/// Whether a change's own fit shows, by itself, that the change was held through its
/// response: its window lasts the [`needed_hold`] of the slowest lags and dead time its own
/// 95 % intervals allow ([`slowest_allowed`]). A window cut before the response settled
/// leaves its lag undetermined (the level it heads for trades with how slowly it gets
/// there), and its interval reaches past the window; one that shows the level pins the lag
/// down. This needs no joint fit: when the changes' gains differ, a joint linear fit bends
/// its lags to reach levels it cannot (a P1 through an up step of gain 2.8 and a down step
/// of 1.5 ends with a lag four times the steps' own), and would say that changes held
/// through four of their own time constants were not.
pub fn own_fit_held(f: &StepFit) -> bool {
    let Ok(report) = &f.fit else {
        return false;
    };
    slowest_allowed(report)
        .and_then(|m| needed_hold(&m))
        .is_some_and(|needed| f.window.1 - f.change.t >= needed)
}

/// Each fitted change's own static gain and its 95 % interval (failed fits left out).
pub fn step_gains(fits: &[StepFit]) -> Vec<StepGain> {
    fits.iter()
        .filter_map(|f| {
            let r = f.fit.as_ref().ok()?;
            Some(StepGain {
                t: f.change.t,
                u_before: f.change.u_before,
                du: f.change.du,
                kp: r.model.get(Param::Kp),
                ci95: r.interval(Param::Kp),
            })
        })
        .collect()
}

/// Whether two of `steps`' gains differ: their 95 % intervals are disjoint and they lie more
/// than [`RESOLVED_SHARE`] of the larger apart. Step against step, not against the joint
/// fit: a structure that misses the response's shape gives every window's gain the same
/// bias away from the joint one, and a linear process gives the steps one gain whatever it.
fn gains_differ(steps: &[StepGain]) -> bool {
    let differ = |a: &StepGain, b: &StepGain| match (a.ci95, b.ci95) {
        (Some(x), Some(y)) => {
            (x.1 < y.0 || y.1 < x.0)
                && (a.kp - b.kp).abs() > RESOLVED_SHARE * a.kp.abs().max(b.kp.abs())
        }
        _ => false,
    };
    steps
        .iter()
        .enumerate()
        .any(|(i, a)| steps[i + 1..].iter().any(|b| differ(a, b)))
}

/// `nonlinearity` from the per-step fits of the changes held through their response.
pub fn nonlinearity(fits: &[StepFit]) -> Option<TestCause> {
    let steps = step_gains(fits);
    if !gains_differ(&steps) {
        return None;
    }
    let start = fits
        .iter()
        .map(|f| f.window.0)
        .fold(f64::INFINITY, f64::min);
    let end = fits
        .iter()
        .map(|f| f.window.1)
        .fold(f64::NEG_INFINITY, f64::max);
    Some(TestCause {
        kind: TestCauseKind::Nonlinearity,
        evidence: TestEvidence::Nonlinearity { steps },
        interval: (start < end).then_some((start, end)),
        handling: Handling::PerStepTable,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::per_step::per_step_fits;
    use crate::diagnose::test_causes::testing::{Messy, messy};
    use crate::fit::FitOptions;

    fn up_and_down(gain_down: f64, noise: f64) -> Option<TestCause> {
        let m = messy(Messy {
            steps: vec![(30.4, 10.0, 1.2), (150.6, -10.0, gain_down)],
            n: 280,
            noise,
            ..Messy::default()
        });
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let fits = per_step_fits(&m.data, m.fit.model.structure, &options);
        assert_eq!(fits.len(), 2);
        nonlinearity(&fits)
    }

    #[test]
    fn a_gain_that_differs_up_and_down_is_named_with_both_gains() {
        let cause = up_and_down(0.9, 0.01).expect("1.2 up against 0.9 down");
        let TestEvidence::Nonlinearity { steps } = &cause.evidence else {
            panic!("{cause:?}")
        };
        assert_eq!(steps.len(), 2);
        assert!((steps[0].kp - 1.2).abs() < 0.05, "{steps:?}");
        assert!((steps[1].kp - 0.9).abs() < 0.05, "{steps:?}");
        assert!((steps[1].u_before - 40.0).abs() < 1e-9 && steps[1].du == -10.0);
        assert_eq!(cause.handling, Handling::PerStepTable);
    }

    #[test]
    fn only_steps_held_through_their_response_are_compared() {
        // τ = 20 s, θ = 3 s: a change must be held 63 s.
        let held = |second: f64| {
            let m = messy(Messy {
                steps: vec![(30.4, 10.0, 1.2), (second, -10.0, 0.9)],
                n: 280,
                ..Messy::default()
            });
            steps_held(&m.data, &m.fit.model)
        };
        assert!(held(150.6));
        // An overshoot settling 10 s after the jump is the actuator's, not a step.
        assert!(!held(40.6));
        // The last change must be held to the record's end (279 s) as well: 1.5 τ is not
        // enough, the response has reached 78 % of its level.
        assert!(!held(262.6));
        assert!(!held(230.0));
        assert!(held(180.0));
    }

    #[test]
    fn a_linear_process_is_quiet() {
        for noise in [0.002, 0.02] {
            assert_eq!(up_and_down(1.2, noise), None, "noise {noise}");
        }
    }
}
