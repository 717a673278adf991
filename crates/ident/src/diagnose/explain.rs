//! The evidence of a named cause, read off the current residuals (which statistic, over
//! which time interval), and the verdict on the model the chain ends with.

use super::cause::Cause;
use super::judge::{analyse, whiteness};
use super::report::{Artefacts, Bias, Ending, Evidence, Verdict, Whiteness};
use crate::diagnose::drift_evidence::read_drift;
use crate::diagnose::residuals::{self};
use crate::diagnose::staircase::Staircase;
use crate::fit::guess::features;
use crate::fit::{FitData, FitReport};
use crate::model::Param;

/// The model's main time constant (Tw for an underdamped pair, else Tp1), at least one
/// sampling period.
pub(super) fn characteristic_time(report: &FitReport, data: &FitData) -> f64 {
    let m = &report.model;
    let t = if m.structure.underdamped {
        m.get(Param::Tw)
    } else {
        m.get(Param::Tp1)
    };
    t.max(data.sampling_period())
}

/// Mean of the residuals over [a, b], their count and the fraction sharing the mean's sign.
pub(super) fn interval_stats(data: &FitData, r: &[f64], (a, b): (f64, f64)) -> Bias {
    let inside: Vec<f64> = data
        .times
        .iter()
        .zip(r)
        .filter(|(t, _)| **t >= a && **t <= b)
        .map(|(_, e)| *e)
        .collect();
    bias_of(&inside, (a, b))
}

/// The mean of the residuals `inside` and the share of them of its sign, said of (a, b).
pub(super) fn bias_of(inside: &[f64], (start, end): (f64, f64)) -> Bias {
    let n = inside.len();
    let none = Bias {
        start,
        end,
        n: 0,
        mean: 0.0,
        same_sign: 0.0,
    };
    if n == 0 {
        return none;
    }
    let mean = inside.iter().sum::<f64>() / n as f64;
    let same = inside
        .iter()
        .filter(|e| e.signum() == mean.signum())
        .count() as f64
        / n as f64;
    Bias {
        n,
        mean,
        same_sign: same,
        ..none
    }
}

/// The residuals `r` just after every input change, each signed by its change's direction
/// (the dead time's misfit turns with the change), gathered into one [`Bias`] from the first
/// change to the last window's end. A change's window runs from the sample after it to the
/// first sample `td` or more after it: where the model has moved and the data has not yet
/// (or less), however short the dead time against the sampling.
pub(super) fn after_each_change(data: &FitData, r: &[f64], td: f64) -> Bias {
    let changes = &data.input.changes;
    let t = &data.times;
    let mut end = f64::NAN;
    let mut oriented = Vec::new();
    for c in changes {
        let first = t.partition_point(|&s| s <= c.t);
        let last = t
            .partition_point(|&s| s < c.t + td)
            .min(t.len().saturating_sub(1));
        if first <= last && first < t.len() {
            oriented.extend(r[first..=last].iter().map(|e| c.du.signum() * e));
            end = t[last];
        }
    }
    let start = changes.first().map_or(0.0, |c| c.t);
    bias_of(&oriented, (start, if end.is_nan() { start } else { end }))
}

/// The evidence for a cause: which statistic over which interval.
pub(super) fn explain(
    cause: Cause,
    data: &FitData,
    current: &FitReport,
    extended: &FitReport,
) -> (Evidence, Option<(f64, f64)>) {
    let r = current.residuals(data).unwrap_or_default();
    // The residual analysis (correlations at every lag: the costliest statistic here) only
    // for the causes whose evidence reads it.
    let analysis = std::cell::OnceCell::new();
    let analysis = || analysis.get_or_init(|| analyse(current, data));
    let v = extended.model.values;
    let t0 = data.input.t0();
    let t_first = data.times.first().copied().unwrap_or(t0);
    let t_last = data.times.last().copied().unwrap_or(t0);
    // The effect of the input's largest excursion from u0 (the step's, for one step).
    let effect = (extended.model.get(Param::Kp) * data.input.du_scale()).abs();
    let region = |kind: residuals::RegionKind| {
        analysis()
            .as_ref()
            .and_then(|a| a.regions.iter().find(|g| g.kind == kind).cloned())
    };
    match cause {
        Cause::DeadTime => {
            let td = v.get(Param::Td);
            let changes = data.input.changes.len();
            let bias = match changes {
                0 | 1 => interval_stats(data, &r, (t0, t0 + td)),
                _ => after_each_change(data, &r, td),
            };
            let interval = (bias.start, bias.end);
            (Evidence::DeadTime { bias, td, changes }, Some(interval))
        }
        Cause::Offset => {
            let bias = interval_stats(data, &r, (t_first, t_last));
            (
                Evidence::Offset {
                    bias,
                    y0_held: current.model.get(Param::Y0),
                    y0_estimated: v.get(Param::Y0),
                },
                Some((t_first, t_last)),
            )
        }
        Cause::Oscillation => {
            let period = analysis().as_ref().and_then(|a| a.dominant_period);
            let transient = region(residuals::RegionKind::Transient).map(|g| (g.start, g.end));
            (
                Evidence::Oscillation {
                    period,
                    omega_d: extended.model.damped_frequency(),
                    zeta: v.get(Param::Zeta),
                },
                transient,
            )
        }
        Cause::ExtraPole => {
            let start = t0
                + if current.model.structure.delay {
                    current.model.get(Param::Td)
                } else {
                    0.0
                };
            let interval = (start, start + characteristic_time(current, data));
            let bias = interval_stats(data, &r, interval);
            let added = [Param::Tp3, Param::Tp2]
                .into_iter()
                .find(|p| extended.model.structure.params().contains(p))
                .map(|p| (p, v.get(p)));
            (Evidence::ExtraPole { bias, added }, Some(interval))
        }
        Cause::Zero => {
            let f = features(data, Some(current.model.get(Param::Y0)));
            let tp = f.t_peak.map(|t| t + t0);
            (
                Evidence::Zero {
                    overshoot: f.overshoot,
                    peak_time: tp,
                    underdamped: current.model.structure.underdamped,
                    tz: v.get(Param::Tz),
                },
                tp.map(|t| (t0, t + (t - t0))),
            )
        }
        Cause::InverseResponse => {
            let f = features(data, Some(current.model.get(Param::Y0)));
            let dip = f.t_dip.map(|t| t + t0);
            (
                Evidence::InverseResponse {
                    undershoot: f.undershoot,
                    dip_time: dip,
                    tz: v.get(Param::Tz),
                },
                dip.map(|t| (t0, t + (t - t0))),
            )
        }
        Cause::Integrator => {
            let tail = region(residuals::RegionKind::Tail);
            let slope = features(data, None).final_slope;
            (
                Evidence::Integrator {
                    slope,
                    per_time_constant: slope.abs() * current.model.get(Param::Tp1)
                        / effect.max(f64::MIN_POSITIVE),
                    trend_z: tail.map(|g| g.slope_z),
                },
                tail.map(|g| (g.start, g.end)),
            )
        }
        Cause::Drift => {
            let reading = read_drift(data, &current.model, extended);
            let models = [&current.model, &extended.model];
            let stretches = crate::diagnose::drift_evidence::settled_stretches(&models, data);
            let span = stretches
                .iter()
                .map(|s| (s.start.max(t_first), s.end.min(t_last)))
                .filter(|(a, b)| a < b)
                .fold(None, |acc: Option<(f64, f64)>, (a, b)| match acc {
                    None => Some((a, b)),
                    Some((lo, hi)) => Some((lo.min(a), hi.max(b))),
                });
            (
                Evidence::Drift {
                    tail: reading.map(|d| (d.slope, d.z)),
                    drift: v.get(Param::Drift),
                },
                span,
            )
        }
        Cause::None => (Evidence::None, None),
    }
}

/// Why the final model is adequate (or why the loop stopped), with the whiteness statistics.
pub(super) fn verdict(data: &FitData, report: &FitReport, adequate: bool) -> Verdict {
    let analysis = whiteness(report, data);
    let white = analysis.as_ref().is_some_and(|a| a.white);
    Verdict {
        structure: None,
        artefacts: Artefacts::default(),
        ending: match (adequate, white) {
            (true, _) if Staircase::of(data, report).is_some() => Ending::WithinRounding,
            (true, true) => Ending::Adequate,
            (true, false) => Ending::NotWhite,
            (false, _) => Ending::StepLimit,
        },
        whiteness: analysis.map(|a| Whiteness {
            outside: a.outside_band.len(),
            lags: a.autocorrelation.len().saturating_sub(1),
            runs_z: a.runs.z,
        }),
    }
}
