//! Each input change of a multi-step record fitted on its own window, beside the joint fit:
//! if the process is linear, every step gives the same gain, time constants and dead time
//! within their intervals; up against down, small against large, one operating point
//! against another differing beyond them is a nonlinearity (the notes' "repetir o teste
//! várias vezes (subida e descida)").
//!
//! Change k's window runs from the last third of the stretch since the previous change (or
//! the record's start) to the last sample before the next change, so it holds the level the
//! change left from, where the previous response had most nearly settled, and the response
//! it caused. On it the change
//! is one step from that level: Y0 estimated (the level before it is not the record's
//! operating point), an initial transient estimated after the first change (the previous
//! response's tail, exactly the free response of the same poles) and on the first when the
//! output moved before it ([`crate::fit::rest`]), the same step-instant lead as the joint fit
//! (none for a change at the record's first sample from the input before the record).

use crate::fit::guess::auto_guess;
use crate::fit::{FitData, FitError, FitObserver, FitOptions, FitReport, fit};
use crate::model::excitation::{Excitation, InputChange};
use crate::model::{Model, Param, Structure};
use crate::stats::{ar1_widening, lag_one};

/// One change's own fit.
#[derive(Debug, Clone, PartialEq)]
pub struct StepFit {
    pub change: InputChange,
    /// The window fitted (s, both ends included).
    pub window: (f64, f64),
    /// Whether the output still moved before this change (an initial transient estimated).
    pub not_at_rest: bool,
    pub fit: Result<FitReport, FitError>,
}

/// The most changes a record may have for its per-step fits (each is a whole fit; a
/// PRBS-like input has no step windows to compare).
pub const MAX_PER_STEP: usize = 12;

/// The fewest samples a change's window needs for a fit of its own.
pub const MIN_WINDOW: usize = 3;

/// The share of the stretch since the previous change a window keeps before its change.
pub const BEFORE_SHARE: f64 = 1.0 / 3.0;

/// The data of change `k`'s window, as one step from the level before it.
pub fn window_data(data: &FitData, k: usize) -> Option<FitData> {
    let changes = &data.input.changes;
    let change = *changes.get(k)?;
    let first = data.times.first().copied()?;
    let since = if k == 0 { first } else { changes[k - 1].t };
    let start = change.t - BEFORE_SHARE * (change.t - since).max(0.0);
    let end = changes.get(k + 1).map_or(f64::INFINITY, |next| next.t);
    let keep: Vec<usize> = (0..data.times.len())
        .filter(|&i| data.times[i] >= start && data.times[i] < end)
        .collect();
    // A window without samples to fit (a change at the record's last sample, or with its
    // samples left out) has no fit of its own.
    if keep.len() < MIN_WINDOW {
        return None;
    }
    let mut input = Excitation::step(change.t, change.du);
    input.changes[0] = change;
    input.u0 = change.u_before;
    // The change's own uncertainty about its instant: none for the change at the record's
    // first sample from the input before it (nothing earlier is in the record, and its Y0
    // and a lead would be one unknown).
    input.lead_range = data.input.lead_range.min(change.t - change.earliest);
    Some(FitData {
        times: keep.iter().map(|&i| data.times[i]).collect(),
        y: keep.iter().map(|&i| data.y[i]).collect(),
        input,
    })
}

/// Change `k` of `data` fitted on its own window with `structure`'s process model (see the
/// module docs), reporting to `observer` (which may cancel it); `None` when there is no
/// change `k`.
pub fn fit_change(
    data: &FitData,
    k: usize,
    structure: Structure,
    options: &FitOptions,
    observer: &mut dyn FitObserver,
) -> Option<StepFit> {
    let window = window_data(data, k)?;
    let not_at_rest = crate::fit::rest::rest_before(&window).is_not_at_rest();
    // After the first change the window starts on the previous response's tail, which is
    // the free response of the same poles: the initial transient models it exactly, however
    // small (the rest test only says whether it is worth a word).
    let s = Structure {
        free_offset: true,
        drift: false,
        lead: window.input.lead_range > 0.0,
        transient: k > 0 || not_at_rest,
        ..structure
    };
    let guess = auto_guess(&window, s, None);
    let span = (
        window.times.first().copied().unwrap_or(f64::NAN),
        window.times.last().copied().unwrap_or(f64::NAN),
    );
    Some(StepFit {
        change: *data.input.changes.get(k)?,
        window: span,
        not_at_rest,
        fit: fit(&window, s, guess, options, observer),
    })
}

/// Every change of `data` fitted on its own window with `structure`'s process model (see
/// the module docs), the changes spread over the cores; empty for a record with one change
/// (the joint fit is that change's).
pub fn per_step_fits(data: &FitData, structure: Structure, options: &FitOptions) -> Vec<StepFit> {
    if !data.input.is_multi_step() {
        return Vec::new();
    }
    let changes: Vec<usize> = (0..data.input.changes.len()).collect();
    crate::parallel::map(&changes, |&k| {
        fit_change(data, k, structure, options, &mut ())
    })
    .into_iter()
    .flatten()
    .collect()
}

/// `report`'s intervals widened for the colour of its residuals on `data` (the AR(1)
/// correction [`ar1_widening`] of their lag-one autocorrelation). Intervals computed as if
/// the residuals were white are honest only for a model that fits: a structure that misses
/// the response's shape (a P1 on a delayed response) leaves slow, correlated residuals, and
/// gains whose white-noise intervals are far too narrow to tell steps apart by.
pub fn widened_for_colour(report: &FitReport, data: &FitData) -> FitReport {
    let mut widened = report.clone();
    if let Ok(r) = report.residuals(data) {
        widened.widen_intervals(ar1_widening(lag_one(&r)));
    }
    widened
}

/// Each change's own fit in `fits` widened for the colour of its residuals on its own
/// window ([`widened_for_colour`]).
pub fn widen_steps_for_colour(data: &FitData, fits: &mut [StepFit]) {
    for f in fits.iter_mut() {
        let k = data.input.changes.iter().position(|c| c.t == f.change.t);
        let window = k.and_then(|k| window_data(data, k));
        if let (Some(window), Ok(r)) = (window, &mut f.fit) {
            *r = widened_for_colour(r, &window);
        }
    }
}

/// The process parameters compared step by step: gain, time constants, damping, zero, dead
/// time (not the operating point, drift, step-instant lead or initial transient, which
/// belong to each window).
pub fn compared_params(structure: &Structure) -> Vec<Param> {
    structure
        .params()
        .into_iter()
        .filter(|p| {
            !matches!(
                p,
                Param::Y0 | Param::Drift | Param::Ta | Param::X1 | Param::X2 | Param::X3
            )
        })
        .collect()
}

/// The parameter of `own` that stands for `joint`'s `p`: itself, except for the real lags
/// of a structure with two or three, which are matched by rank. The lags are
/// interchangeable in the step response, and a window's fit may end with them in another
/// order than the joint fit (its guess puts the fastest first, see
/// [`crate::fit::guess::auto_guess`]): Tp1 of the joint fit is compared with, and shown beside,
/// the window's lag of the same rank.
pub fn same_lag(joint: &Model, own: &Model, p: Param) -> Param {
    let s = joint.structure;
    let lags = [Param::Tp1, Param::Tp2, Param::Tp3];
    let count = s.poles as usize;
    let Some(slot) = lags[..count.min(3)].iter().position(|&l| l == p) else {
        return p;
    };
    if s.underdamped || count < 2 || own.structure.poles != s.poles || own.structure.underdamped {
        return p;
    }
    let rank = |m: &Model, k: usize| {
        let v = m.values.get(lags[k]);
        lags[..count]
            .iter()
            .filter(|&&l| m.values.get(l) > v || (m.values.get(l) == v && l < lags[k]))
            .count()
    };
    let wanted = rank(joint, slot);
    (0..count)
        .find(|&k| rank(own, k) == wanted)
        .map_or(p, |k| lags[k])
}

/// Relative difference below which a step's value is not called different from the joint
/// fit's, whatever its interval: a fit of a real record does not resolve values closer than
/// this (the issue's own tolerance for parameters), and a narrow interval on a quiet record
/// says nothing about how well the model's form fits each window.
pub const RESOLVED_SHARE: f64 = 0.05;

/// How a step's values stand against the joint fit's.
#[derive(Debug, Clone, PartialEq)]
pub enum Agreement {
    /// No value differs from the joint fit's beyond both their 95 % intervals and what the
    /// record resolves.
    Agree,
    /// A fit, a value or an interval is missing, and nothing else differs: nothing can be
    /// said.
    Unknown,
    /// These values differ (see [`agreement`]).
    Differ(Vec<Difference>),
}

/// A step's value whose interval does not overlap the joint fit's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Difference {
    /// Index (0-based) of the change.
    pub step: usize,
    /// Its instant (s).
    pub t: f64,
    pub param: Param,
    pub value: f64,
    pub joint: (f64, f64),
}

/// Compares every step's own values with the joint fit's, parameter by parameter: a value
/// differs when its 95 % interval and the joint fit's do not overlap, and it is more than
/// [`RESOLVED_SHARE`] away from the joint fit's, or, for the dead time, more than
/// `instant_step` seconds (each change's instant is only known to within a sampling
/// period, and each step has its own).
pub fn agreement(joint: &FitReport, fits: &[StepFit], instant_step: f64) -> Agreement {
    let params = compared_params(&joint.model.structure);
    let mut differ = Vec::new();
    let mut unknown = false;
    for (k, f) in fits.iter().enumerate() {
        let Ok(own) = &f.fit else {
            unknown = true;
            continue;
        };
        for &p in &params {
            let q = same_lag(&joint.model, &own.model, p);
            let (value, reference) = (own.model.get(q), joint.model.get(p));
            let resolved = match p {
                Param::Td => instant_step,
                _ => RESOLVED_SHARE * reference.abs(),
            };
            match (own.interval(q), joint.interval(p)) {
                (Some(a), Some(b))
                    if (a.1 < b.0 || b.1 < a.0) && (value - reference).abs() > resolved =>
                {
                    differ.push(Difference {
                        step: k,
                        t: f.change.t,
                        param: p,
                        value,
                        joint: b,
                    })
                }
                (Some(_), Some(_)) => {}
                _ => unknown = true,
            }
        }
    }
    match (differ.is_empty(), unknown) {
        (false, _) => Agreement::Differ(differ),
        (true, true) => Agreement::Unknown,
        (true, false) => Agreement::Agree,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::Termination;
    use crate::model::excitation::Hold;
    use crate::model::{Model, Param, Values};

    /// A square wave through two lags (the RC ladder's shape: 0.13 s and 0.02 s, half
    /// period 0.8 s, an ADC's levels far from zero, noise of 1 % coloured by a first-order
    /// filter, quantised): each window starts on the previous response's late tail, where
    /// the windows' P2 fits with an initial transient crawled to the 200-iteration limit.
    /// They converge, and each window's lags, matched by rank, are the process's.
    #[test]
    fn windows_on_late_tails_converge_and_match_lags_by_rank() {
        let ts = 0.008;
        let times: Vec<f64> = (0..640).map(|k| ts * k as f64).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| {
                if t < 0.363 || ((t - 0.363) / 0.8) as i64 % 2 == 1 {
                    1241.0
                } else {
                    2482.0
                }
            })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        let mut v = Values::default();
        v.set(Param::Kp, 1.0);
        v.set(Param::Tp1, 0.13);
        v.set(Param::Tp2, 0.02);
        v.set(Param::Y0, 1241.0);
        let truth = Model::new(Structure::parse("P2").unwrap(), v);
        let clean = truth.simulate(&input, &times).unwrap();
        let (mut rng, mut coloured) = (crate::random::Lcg(12345), 0.0);
        let y: Vec<f64> = clean
            .iter()
            .map(|&c| {
                let white = (rng.unit() - 0.5) * 2.0 * 12.4;
                coloured = 0.6 * coloured + white;
                (c + coloured).round()
            })
            .collect();
        let data = FitData { times, y, input };
        let options = FitOptions {
            starts: 4,
            ..FitOptions::default()
        };
        let fits = per_step_fits(&data, truth.structure, &options);
        assert_eq!(fits.len(), 6);
        for f in &fits[1..] {
            let r = f.fit.as_ref().unwrap();
            assert_ne!(r.termination, Termination::IterationLimit, "{f:?}");
            // The fast lag rests on a few samples of each window: a third is its spread.
            for (p, want, share) in [(Param::Tp1, 0.13, 0.1), (Param::Tp2, 0.02, 0.35)] {
                let got = r.model.get(same_lag(&truth, &r.model, p));
                assert!((got - want).abs() < share * want, "{p:?} {got} {f:?}");
            }
            assert!((r.model.get(Param::Kp) - 1.0).abs() < 0.02, "{f:?}");
        }
    }

    #[test]
    fn each_step_of_a_linear_process_gives_its_gain_and_time_constant() {
        let times: Vec<f64> = (0..600).map(|k| 0.5 * k as f64).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| match t {
                t if t < 20.0 => 1.0,
                t if t < 100.0 => 3.0,
                t if t < 180.0 => 2.0,
                _ => 4.5,
            })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        assert_eq!(input.changes.len(), 3);
        let mut v = Values::default();
        v.set(Param::Kp, 1.7);
        v.set(Param::Tp1, 9.0);
        v.set(Param::Y0, 20.0);
        let truth = Model::new(Structure::parse("P1").unwrap(), v);
        let y = truth.simulate(&input, &times).unwrap();
        let data = FitData { times, y, input };
        let fits = per_step_fits(&data, truth.structure, &FitOptions::default());
        assert_eq!(fits.len(), 3);
        for f in &fits {
            let r = f.fit.as_ref().unwrap();
            assert!((r.model.get(Param::Kp) - 1.7).abs() < 1e-4, "{f:?}");
            assert!((r.model.get(Param::Tp1) - 9.0).abs() < 1e-3, "{f:?}");
        }
        // The window keeps the last third of the 80 s since the previous change: from 73.5 s.
        assert!(!fits[0].not_at_rest && fits[1].window.0 == 73.5);
    }
}
