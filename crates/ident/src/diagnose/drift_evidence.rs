//! Whether a record shows a drift by what only a drift explains (issue 21).
//!
//! A drift, a slow pole the model lacks, a response that has not settled, a test not at rest
//! and a nonlinearity can all leave the same slow residual; bought on that residual, a drift
//! trades one for one with the gain. So a drift is kept only where no input change can
//! explain the trend:
//! - it is read on the *settled stretches* alone: before the first change's response, and
//!   from each change plus the 2 % settling time (dead time included) of both the extended
//!   model and the one it extends, whichever is longer, to the next change
//!   ([`settled_stretches`]); elsewhere the process is still answering;
//! - on them, the residuals of the extended model *without* its drift are regressed on one
//!   level per stretch, a common slope d (the drift: the same whatever the change), and, on
//!   the stretches after changes, a slope c·Δu that scales with the last change's size and
//!   sign (a slow process part, which a drift is not) when the record's changes differ
//!   enough to tell the two apart (kept only where it is significant, [`Z_SCALED`]), and a
//!   curvature q·Δu (a slow part decelerates; a drift is a straight line);
//! - the drift is shown when d is significant (|z| ≥ [`Z_DRIFT`], the standard errors
//!   widened for the residuals' lag-one correlation), has the sign and the size of the
//!   fitted drift ([`DriftReading::shows`]), and the curvature is not significant. With no
//!   settled stretch, or a design that cannot tell d from c (no stretch before the first
//!   change, and the changes after which the stretches are read all of one size), the
//!   record does not show a drift;
//! - [`settled_slope_before`] reads the same common slope on a model's own residuals, on
//!   the settled stretches before an instant: what a trend said to begin there (a load's
//!   ramp, [`crate::diagnose::test_causes::disturbance`]) already had before it.
//!
//! Least squares through the normal equations of a handful of columns, accumulated sample
//! by sample (nalgebra's Cholesky), so a record of 10⁶ samples costs one pass.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use crate::fit::{FitData, FitReport};
use crate::model::Model;
use crate::stats::lag_one;

/// The least |z| of the common slope for a drift to be shown.
pub const Z_DRIFT: f64 = 3.0;

/// A curvature with |z| at or above this says the settled stretches still bend: a slow
/// part of the process, not a drift.
pub const Z_CURVATURE: f64 = 3.0;

/// The reading and a fit's drift agree in size when neither is more than this many times
/// the other ([`DriftReading::shows`]): a trend several times the fitted drift is not that
/// drift.
pub const DRIFT_AGREEMENT: f64 = 2.0;

/// The slope scaling with the changes is kept in the reading only when its |z| reaches
/// this (the usual two-sided 95 % level): a slow part of the process the settled stretches
/// do not show is no reason to widen the drift's standard error.
pub const Z_SCALED: f64 = 2.0;

/// Two changes' sizes differ enough to tell a slope that scales with Δu from a drift when
/// they differ by this share of the larger.
const DISTINCT_CHANGES: f64 = 0.2;

/// The fewest samples a stretch needs to count.
const MIN_STRETCH: usize = 3;

/// What the settled stretches say of a drift.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DriftReading {
    /// The common slope of the residuals on the settled stretches (output units per second).
    pub slope: f64,
    /// Its t statistic, widened for correlated residuals.
    pub z: f64,
    /// Its standard error (output units per second), widened likewise.
    pub se: f64,
    /// The curvature's t statistic on the stretches after changes (0 when not read).
    pub curvature_z: f64,
    /// Samples and stretches read.
    pub samples: usize,
    pub stretches: usize,
    /// Whether a slope scaling with the changes was read beside the drift.
    pub scaled_slope: bool,
}

impl DriftReading {
    /// Whether the reading shows the drift `drift` (units per second) a fit found: a slope
    /// significant, of its sign and of its size (the trend of a few samples before the first
    /// change, several times the fitted drift, is a test not quite at rest, not the drift the
    /// whole record is charged with), in a straight line.
    ///
    /// Of its size: within [`Z_DRIFT`] standard errors of it, or within a factor of
    /// [`DRIFT_AGREEMENT`] of it. The fit's drift carries what the rest of its model gets
    /// wrong (a Y0 held at the mean before the change, which a drift lifts or lowers, is
    /// matched by tilting the drift), while the reading gives each stretch its own level; on
    /// a quiet record the standard error is far smaller than that bias, and the same drift
    /// read two ways would not agree to within it.
    pub fn shows(&self, drift: f64) -> bool {
        self.z.abs() >= Z_DRIFT
            && self.slope.signum() == drift.signum()
            && self.agrees(drift)
            && self.curvature_z.abs() < Z_CURVATURE
    }

    /// Whether the reading goes on with the drift `drift` without showing it on its own: a
    /// slope of its sign within a factor of [`DRIFT_AGREEMENT`] of its size (nearer the
    /// drift than no slope at all), in a straight line, whatever its significance (a few
    /// short stretches after the changes, coloured noise).
    pub fn continues(&self, drift: f64) -> bool {
        (1.0 / DRIFT_AGREEMENT..=DRIFT_AGREEMENT).contains(&(self.slope / drift))
            && self.curvature_z.abs() < Z_CURVATURE
    }

    /// The slope within [`Z_DRIFT`] standard errors of `drift`, or within a factor of
    /// [`DRIFT_AGREEMENT`] of it.
    fn agrees(&self, drift: f64) -> bool {
        let ratio = self.slope / drift;
        (self.slope - drift).abs() <= Z_DRIFT * self.se
            || (1.0 / DRIFT_AGREEMENT..=DRIFT_AGREEMENT).contains(&ratio)
    }
}

/// A stretch of the record where `model`'s response has settled (or not yet begun): its
/// time span and the size of the change before it (0 before the first change).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretch {
    pub start: f64,
    pub end: f64,
    pub du: f64,
}

/// The stretches of `data` where none of `models` moves: before the first change plus the
/// longest dead time, and from each change plus the longest 2 % settling time (dead time
/// included) to the next change (the record's end for the last one). Only the first when a
/// model does not settle.
pub fn settled_stretches(models: &[&Model], data: &FitData) -> Vec<Stretch> {
    let (Some(&first), Some(&last)) = (data.times.first(), data.times.last()) else {
        return Vec::new();
    };
    let changes = &data.input.changes;
    let dead = models.iter().map(|m| m.dead_time()).fold(0.0, f64::max);
    let mut out = Vec::new();
    if let Some(c) = changes.first() {
        out.push(Stretch {
            start: first,
            end: c.earliest.min(c.t) + dead,
            du: 0.0,
        });
    }
    let settle = models
        .iter()
        .map(|m| m.settling().filter(|s| s.is_finite()))
        .try_fold(0.0f64, |acc, s| s.map(|s| acc.max(s)));
    let Some(settle) = settle else {
        return out;
    };
    for (k, c) in changes.iter().enumerate() {
        let end = changes
            .get(k + 1)
            .map_or(f64::INFINITY, |n| n.earliest.min(n.t));
        let start = c.t + settle;
        if start < end.min(last) {
            out.push(Stretch {
                start,
                end,
                du: c.du,
            });
        }
    }
    out
}

/// Reads the drift of `extended` (a fit with a drift term, extending `current`) from the
/// stretches where neither model moves ([`settled_stretches`]: a model that bought the
/// drift with a faster lag must not call the slow approach it left "settled"): `None` when
/// they hold too few samples to tell.
pub fn read_drift(data: &FitData, current: &Model, extended: &FitReport) -> Option<DriftReading> {
    read(data, current, extended, true)
}

/// [`read_drift`] on the stretches after the changes alone: what shows a drift apart from
/// the motion before the first change (an earlier response dying out moves there too, and
/// is gone once the test's own responses settle).
pub fn read_drift_after(
    data: &FitData,
    current: &Model,
    extended: &FitReport,
) -> Option<DriftReading> {
    read(data, current, extended, false)
}

fn read(
    data: &FitData,
    current: &Model,
    extended: &FitReport,
    before: bool,
) -> Option<DriftReading> {
    let mut without = extended.clone();
    without.model.structure.drift = false;
    let r = without.residuals(data).ok()?;
    let mut stretches = settled_stretches(&[current, &extended.model], data);
    if !before {
        stretches.retain(|s| s.du != 0.0);
    }
    let members = members(data, &stretches);
    let used: Vec<usize> = (0..stretches.len())
        .filter(|&s| members.iter().filter(|m| m.1 == s).count() >= MIN_STRETCH)
        .collect();
    if used.is_empty() {
        return None;
    }
    let scaled = distinct_changes(&stretches, &used);
    if before && !scaled && used.iter().all(|&s| stretches[s].du != 0.0) {
        // Only stretches after changes of one size: a common slope there is as well a slope
        // that scales with that change (a slow part still answering it), and nothing tells
        // the two apart.
        return None;
    }
    let after: usize = members
        .iter()
        .filter(|m| used.contains(&m.1) && stretches[m.1].du != 0.0)
        .count();
    let curved = after >= 2 * MIN_STRETCH;
    let design = Design::new(data, &stretches, &used, scaled, curved);
    let (reading, scaled_z) = design.solve(&data.times, &members, &r, &stretches)?;
    if scaled_z.is_some_and(|z| z.abs() < Z_SCALED) {
        // No slope scaling with the changes is shown: the stretches' slopes are read as the
        // common one alone, which the nuisance column would only blur.
        let design = Design::new(data, &stretches, &used, false, curved);
        return design
            .solve(&data.times, &members, &r, &stretches)
            .map(|(reading, _)| reading);
    }
    Some(reading)
}

/// The common slope of `residuals` (of `model` on `data`) on the stretches where `model`
/// does not move ([`settled_stretches`]) before the instant `until`, each stretch with its
/// own level: what was already there before a trend said to start at `until` (a load's
/// ramp begins where the output was steady; a drift's line was there all along). `None`
/// when those stretches hold too few samples to tell.
pub fn settled_slope_before(
    data: &FitData,
    model: &Model,
    residuals: &[f64],
    until: f64,
) -> Option<DriftReading> {
    let stretches: Vec<Stretch> = settled_stretches(&[model], data)
        .into_iter()
        .filter(|s| s.start < until)
        .map(|s| Stretch {
            end: s.end.min(until),
            ..s
        })
        .collect();
    let members = members(data, &stretches);
    let used: Vec<usize> = (0..stretches.len())
        .filter(|&s| members.iter().filter(|m| m.1 == s).count() >= MIN_STRETCH)
        .collect();
    if used.is_empty() || residuals.len() != data.times.len() {
        return None;
    }
    let design = Design::new(data, &stretches, &used, false, false);
    design
        .solve(&data.times, &members, residuals, &stretches)
        .map(|(reading, _)| reading)
}

/// Each sample inside a stretch: (sample index, stretch index).
fn members(data: &FitData, stretches: &[Stretch]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (s, st) in stretches.iter().enumerate() {
        let from = data.times.partition_point(|&t| t < st.start);
        let to = data.times.partition_point(|&t| t < st.end);
        out.extend((from..to).map(|i| (i, s)));
    }
    out
}

/// Whether the used stretches after changes hold two changes of sizes distinct enough.
fn distinct_changes(stretches: &[Stretch], used: &[usize]) -> bool {
    let sizes: Vec<f64> = used
        .iter()
        .map(|&s| stretches[s].du)
        .filter(|du| *du != 0.0)
        .collect();
    let largest = sizes.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    sizes.iter().enumerate().any(|(i, a)| {
        sizes[i + 1..]
            .iter()
            .any(|b| (a - b).abs() > DISTINCT_CHANGES * largest)
    })
}

/// The regression's columns: one level per used stretch, the common slope, then the
/// slope and curvature scaled by each stretch's change when asked for.
struct Design {
    /// The used stretches' centres (s), by stretch index (NaN for stretches not used).
    centre: Vec<f64>,
    /// Column of each stretch's level, by stretch index.
    level: Vec<Option<usize>>,
    levels: usize,
    scaled: bool,
    curved: bool,
    /// The time unit the slopes are computed in (s), for conditioning.
    unit: f64,
}

impl Design {
    fn new(
        data: &FitData,
        stretches: &[Stretch],
        used: &[usize],
        scaled: bool,
        curved: bool,
    ) -> Self {
        let mut level = vec![None; stretches.len()];
        let mut centre = vec![f64::NAN; stretches.len()];
        let last = data.times.last().copied().unwrap_or(0.0);
        for (k, &s) in used.iter().enumerate() {
            level[s] = Some(k);
            let st = stretches[s];
            centre[s] = 0.5 * (st.start + st.end.min(last));
        }
        Design {
            centre,
            level,
            levels: used.len(),
            scaled,
            curved,
            unit: data.duration().max(f64::MIN_POSITIVE),
        }
    }

    fn columns(&self) -> usize {
        self.levels + 1 + usize::from(self.scaled) + usize::from(self.curved)
    }

    /// The row of sample time `t` in stretch `s` (after a change `du`, in units of the
    /// largest change `du_unit`), into `row`; false for a stretch not used.
    fn row(&self, t: f64, s: usize, du: f64, du_unit: f64, row: &mut [f64]) -> bool {
        let Some(l) = self.level[s] else { return false };
        row.iter_mut().for_each(|x| *x = 0.0);
        let x = (t - self.centre[s]) / self.unit;
        row[l] = 1.0;
        row[self.levels] = x;
        let mut c = self.levels + 1;
        let scale = du / du_unit;
        if self.scaled {
            row[c] = scale * x;
            c += 1;
        }
        if self.curved {
            row[c] = scale * x * x;
        }
        true
    }

    /// The reading, and the t statistic of the slope scaled by the changes when read.
    fn solve(
        &self,
        times: &[f64],
        members: &[(usize, usize)],
        r: &[f64],
        stretches: &[Stretch],
    ) -> Option<(DriftReading, Option<f64>)> {
        let p = self.columns();
        let du_unit = stretches
            .iter()
            .fold(0.0f64, |m, s| m.max(s.du.abs()))
            .max(f64::MIN_POSITIVE);
        let r_unit = r.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if !(r_unit.is_finite() && r_unit > 0.0) {
            return None;
        }
        let mut a = DMatrix::<f64>::zeros(p, p);
        let mut b = DVector::<f64>::zeros(p);
        let mut row = vec![0.0; p];
        let mut n = 0;
        for &(i, s) in members {
            if !self.row(times[i], s, stretches[s].du, du_unit, &mut row) {
                continue;
            }
            let y = r[i] / r_unit;
            for j in 0..p {
                b[j] += row[j] * y;
                for k in 0..p {
                    a[(j, k)] += row[j] * row[k];
                }
            }
            n += 1;
        }
        if n <= p + 1 {
            return None;
        }
        let inverse = a.clone().cholesky()?.inverse();
        let beta = &inverse * &b;
        let mut fitted = Vec::with_capacity(n);
        for &(i, s) in members {
            if self.row(times[i], s, stretches[s].du, du_unit, &mut row) {
                let model: f64 = row.iter().zip(beta.iter()).map(|(x, c)| x * c).sum();
                fitted.push(r[i] / r_unit - model);
            }
        }
        let ssr: f64 = fitted.iter().map(|e| e * e).sum();
        let s2 = ssr / (n - p) as f64;
        let rho = lag_one(&fitted).clamp(0.0, 0.99);
        let widen = ((1.0 + rho) / (1.0 - rho)).sqrt();
        let se = |j: usize| (s2 * inverse[(j, j)]).max(0.0).sqrt() * widen;
        let z = |j: usize| {
            let se = se(j);
            if se > 0.0 { beta[j] / se } else { 0.0 }
        };
        let d = self.levels;
        let curvature = self.levels + 1 + usize::from(self.scaled);
        let reading = DriftReading {
            slope: beta[d] * r_unit / self.unit,
            z: z(d),
            se: se(d) * r_unit / self.unit,
            curvature_z: if self.curved { z(curvature) } else { 0.0 },
            samples: n,
            stretches: self.levels,
            scaled_slope: self.scaled,
        };
        Some((reading, self.scaled.then(|| z(d + 1))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{FitOptions, fit};
    use crate::model::excitation::{Excitation, Hold};
    use crate::model::{Param, Structure, Values};
    use crate::random::Lcg;

    /// A logged record of `truth` (input `levels` held from the given instants, 1 s
    /// sampling, `n` samples), Gaussian-ish noise of `noise` (output units).
    fn record(truth: &Model, levels: &[(f64, f64)], n: usize, noise: f64) -> FitData {
        let times: Vec<f64> = (0..n).map(|k| k as f64).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| {
                levels
                    .iter()
                    .rev()
                    .find(|(at, _)| t >= *at)
                    .map_or(30.0, |l| l.1)
            })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).expect("steps");
        let mut rng = Lcg(11);
        let y = truth
            .simulate(&input, &times)
            .expect("simulates")
            .into_iter()
            .map(|v| v + noise * (0..4).map(|_| rng.symmetric()).sum::<f64>() * 0.866)
            .collect();
        FitData { times, y, input }
    }

    fn model(code: &str, params: &[(Param, f64)]) -> Model {
        let mut v = Values::default();
        params.iter().for_each(|&(p, x)| v.set(p, x));
        Model::new(Structure::parse(code).expect("code"), v)
    }

    /// The current fit (`code`) and its extension by a drift, fitted from the truth.
    fn fits(data: &FitData, code: &str, truth: &Model) -> (FitReport, FitReport) {
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let s = Structure::parse(code).expect("code");
        let current = fit(data, s, truth.values, &options, &mut ()).expect("fits");
        let mut with = s;
        with.drift = true;
        let mut guess = current.model.values;
        guess.set(Param::Drift, 0.0);
        let extended = fit(data, with, guess, &options, &mut ()).expect("fits");
        (current, extended)
    }

    #[test]
    fn a_drift_before_the_change_and_after_up_and_down_is_shown() {
        let truth = model(
            "P1",
            &[
                (Param::Kp, 1.5),
                (Param::Tp1, 15.0),
                (Param::Y0, 200.0),
                (Param::Drift, 0.01),
            ],
        );
        let mut truth = truth;
        truth.structure.drift = true;
        let data = record(&truth, &[(60.0, 40.0), (220.0, 35.0)], 400, 0.05);
        let (current, extended) = fits(&data, "P1", &truth);
        let reading = read_drift(&data, &current.model, &extended).expect("stretches");
        assert!(
            reading.shows(extended.model.get(Param::Drift)),
            "{reading:?}"
        );
        assert!((reading.slope - 0.01).abs() < 0.002, "{reading:?}");
        assert!(reading.stretches >= 2);
    }

    #[test]
    fn a_slow_approach_that_has_not_settled_is_no_drift() {
        // A slow second lag, the record ending long before it settles: P1 + drift fits
        // the approach, but nothing before the change trends and the approach bends.
        let truth = model(
            "P2",
            &[
                (Param::Kp, 0.5),
                (Param::Tp1, 8.0),
                (Param::Tp2, 160.0),
                (Param::Y0, 40.0),
            ],
        );
        let data = record(&truth, &[(30.0, 70.0)], 330, 0.04);
        let (current, extended) = fits(&data, "P1", &truth);
        let shown = read_drift(&data, &current.model, &extended)
            .is_some_and(|d| d.shows(extended.model.get(Param::Drift)));
        assert!(!shown, "{:?}", read_drift(&data, &current.model, &extended));
    }

    #[test]
    fn a_short_rise_before_the_change_is_not_the_record_s_drift() {
        // ECAM's MV test: the output creeps 0.33 °C in the 9 s before the step, then a
        // first order answers up and down; the trend before is steep against any drift a
        // whole-record fit could charge, and one of a few samples.
        let truth = model(
            "P1",
            &[(Param::Kp, 0.56), (Param::Tp1, 166.0), (Param::Y0, 40.5)],
        );
        let mut data = record(&truth, &[(10.0, 70.0), (316.0, 30.0)], 480, 0.05);
        for (k, y) in data.y.iter_mut().take(10).enumerate() {
            *y = 40.2 + 0.04 * k as f64;
        }
        let (current, extended) = fits(&data, "P1", &truth);
        let shown = read_drift(&data, &current.model, &extended)
            .is_some_and(|d| d.shows(extended.model.get(Param::Drift)));
        assert!(!shown, "{:?}", read_drift(&data, &current.model, &extended));
    }

    #[test]
    fn stretches_start_after_the_slower_model_settles() {
        let fast = model("P1", &[(Param::Kp, 1.0), (Param::Tp1, 10.0)]);
        let slow = model("P1", &[(Param::Kp, 1.0), (Param::Tp1, 30.0)]);
        let data = record(&fast, &[(20.0, 40.0), (300.0, 30.0)], 400, 0.0);
        let st = settled_stretches(&[&fast, &slow], &data);
        // Before the change (its earliest instant 19 s), then 20 s + 4 × 30 s (2 %
        // settling 117.4 s) to the next change's earliest instant.
        assert_eq!(st.len(), 2, "{st:?}");
        assert_eq!((st[0].start, st[0].end, st[0].du), (0.0, 19.0, 0.0));
        assert!((st[1].start - (20.0 + 117.36)).abs() < 0.1, "{st:?}");
        assert_eq!(st[1].end, 299.0);
        // The second change's stretch would start at 417 s, after the record's end.
        assert!(
            settled_stretches(&[&fast, &slow], &data)
                .iter()
                .all(|s| s.start < 399.0)
        );
    }

    #[test]
    fn a_quiet_drift_the_held_y0_tilts_is_still_shown() {
        // Y0 held at the mean before the change, as the CLI holds it: with a drift that mean
        // sits half the stretch's drift above the level at the change, and the fit tilts its
        // drift to make up for it. On a quiet record the reading is many standard errors from
        // the tilted drift, yet the same size: the same drift.
        let mut truth = model(
            "P1",
            &[
                (Param::Kp, 1.5),
                (Param::Tp1, 15.0),
                (Param::Y0, 200.0),
                (Param::Drift, 0.01),
            ],
        );
        truth.structure.drift = true;
        let data = record(&truth, &[(60.0, 40.0)], 400, 0.01);
        let before = data.times.iter().filter(|t| **t < 60.0).count();
        let mut s = Structure::parse("P1").expect("code");
        s.free_offset = false;
        let mut v = truth.values;
        v.set(
            Param::Y0,
            data.y[..before].iter().sum::<f64>() / before as f64,
        );
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let current = fit(&data, s, v, &options, &mut ()).expect("fits");
        let mut with = s;
        with.drift = true;
        let mut guess = current.model.values;
        guess.set(Param::Drift, 0.0);
        let extended = fit(&data, with, guess, &options, &mut ()).expect("fits");
        let drift = extended.model.get(Param::Drift);
        let reading = read_drift(&data, &current.model, &extended).expect("stretches");
        assert!(
            (reading.slope - drift).abs() > Z_DRIFT * reading.se,
            "{reading:?} {drift}"
        );
        assert!(reading.shows(drift), "{reading:?} {drift}");
        assert!((reading.slope - 0.01).abs() < 0.001, "{reading:?}");
    }

    #[test]
    fn a_slope_scaling_with_the_changes_is_read_only_where_shown() {
        // A drift under an up-and-down pair of different sizes: nothing scales with the
        // changes, and the common slope is read alone.
        let mut truth = model(
            "P1",
            &[
                (Param::Kp, 1.5),
                (Param::Tp1, 10.0),
                (Param::Y0, 200.0),
                (Param::Drift, 0.004),
            ],
        );
        truth.structure.drift = true;
        let data = record(&truth, &[(60.0, 40.0), (200.0, 34.0)], 400, 0.05);
        let (current, extended) = fits(&data, "P1", &truth);
        let reading = read_drift(&data, &current.model, &extended).expect("stretches");
        assert!(!reading.scaled_slope, "{reading:?}");
        assert!(
            reading.shows(extended.model.get(Param::Drift)),
            "{reading:?}"
        );
    }

    #[test]
    fn the_slope_before_an_instant_is_read_on_the_settled_stretches_before_it() {
        let truth = model(
            "P1",
            &[(Param::Kp, 1.5), (Param::Tp1, 10.0), (Param::Y0, 200.0)],
        );
        let data = record(&truth, &[(60.0, 40.0)], 400, 0.02);
        // Residuals: a line of 0.003 per second everywhere, and a level step at the change.
        let r: Vec<f64> = data
            .times
            .iter()
            .map(|&t| 0.003 * t + if t >= 60.0 { 1.0 } else { 0.0 })
            .collect();
        let reading = settled_slope_before(&data, &truth, &r, 300.0).expect("stretches");
        assert_eq!(reading.stretches, 2, "{reading:?}");
        assert!((reading.slope - 0.003).abs() < 1e-9, "{reading:?}");
        // Before the change alone when the instant comes before the response settles.
        let early = settled_slope_before(&data, &truth, &r, 80.0).expect("stretches");
        assert_eq!(early.stretches, 1, "{early:?}");
    }
}
