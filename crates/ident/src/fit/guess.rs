//! Automatic initial guesses read off the measured curve, the way the notes teach them:
//! the static gain from the final level, time constants from the 28.3 % and 63.2 % times
//! (two-point method), ζ from the overshoot, ωd from the oscillation period between
//! crossings of the final level (or π over the peak time), an integrator's gain from the
//! final slope. The dead time is the data's 5 % time minus the 5 % time of the guessed model
//! without delay, which works for every structure alike.
//!
//! Both the features and the guess are read in the record's internal units ([`Scale`]) and
//! scaled back, so they do not depend on the record's scale (a 1e300 output, time in years).

use crate::fit::FitData;
use crate::model::excitation::Excitation;
use crate::model::scale::Scale;
use crate::model::{Model, Param, Structure, Values};
use crate::record::timebase::rest_samples;
use crate::stats::{OUTLIER_THRESHOLD as THRESHOLD, mean, tame};

/// What the curve shows, relative to the operating point y0 and the final level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveFeatures {
    pub y0: f64,
    pub y_final: f64,
    /// Final slope (units per second) over the last fifth of the record.
    pub final_slope: f64,
    /// First times (from t0) at which the normalised response reaches 5 %, 28.3 %, 63.2 %.
    pub t5: Option<f64>,
    pub t28: Option<f64>,
    pub t63: Option<f64>,
    /// Largest normalised excursion beyond 1 and when (from t0).
    pub overshoot: f64,
    pub t_peak: Option<f64>,
    /// Time from the peak until the excess over the final level has fallen to 1/e of itself:
    /// the slow time constant of an overshoot made by a zero.
    pub overshoot_decay: Option<f64>,
    /// Deepest normalised excursion below 0 (inverse response) and when.
    pub undershoot: f64,
    pub t_dip: Option<f64>,
    /// Period of the oscillation about the final level, from successive upward crossings.
    pub period: Option<f64>,
}

/// The output measured at rest, before the step changes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestLevel {
    /// The mean of the samples at rest (output units).
    pub y0: f64,
    /// How many samples were before the step.
    pub samples: usize,
    /// How many of them were wild (a spike, a dropout) and left out of the mean.
    pub wild: usize,
    /// True when the only sample is the one at the step instant t0 itself: the record
    /// starts with the step, so none is before it.
    pub at_step: bool,
}

/// The output at rest: the mean of the samples before t0 that are not wild (beyond the
/// outliers' [`THRESHOLD`] robust standard deviations of their median: a spike before the
/// step would otherwise shift the held Y0 and make the whole record look offset), counted as
/// [`crate::record::timebase::samples_before`] counts them (a sample at t0 counts when the next one
/// has the same time, the pre-step row of a log that writes the step instant twice), so the
/// fit holds Y0 where the data panel says it is. When none is before t0 but the first sample
/// is at t0 (a record that starts with the step, e.g. a heater switched on at the first
/// row), that sample: t0 is the time of the first sample at the new input level, and at t0
/// itself no process model's output has moved yet (y(t0) = Y0 for every structure, with or
/// without dead time, all strictly proper). A sample at t0 is not used when samples before
/// it exist: a step that came between two samples has already moved a fast output there.
/// `None` when the data start after t0.
pub fn rest_level(data: &FitData) -> Option<RestLevel> {
    let (samples, at_step) = rest_samples(&data.times, data.input.t0(), data.y.len())?;
    let kept = tame(&data.y[..samples], THRESHOLD);
    Some(RestLevel {
        y0: mean(&kept),
        samples,
        wild: samples - kept.len(),
        at_step,
    })
}

/// The level of [`rest_level`], if the data show one.
pub fn level_before(data: &FitData) -> Option<f64> {
    rest_level(data).map(|r| r.y0)
}

/// The record's internal units and the record in them, `None` when it has none (no step).
fn internal(data: &FitData) -> Option<(Scale, FitData)> {
    let units = Scale::of(data, data.sampling_period())?;
    let inside = units.data_in(data);
    Some((units, inside))
}

/// Reads the features of the curve; `y0` overrides the level before the step.
pub fn features(data: &FitData, y0: Option<f64>) -> CurveFeatures {
    let Some((u, inside)) = internal(data) else {
        return features_as_given(data, y0);
    };
    let f = features_as_given(&inside, y0.map(|y| u.output_in(y)));
    let time = |t: Option<f64>| t.map(|t| t * u.t_unit);
    CurveFeatures {
        y0: u.y_level + f.y0 * u.y_unit,
        y_final: u.y_level + f.y_final * u.y_unit,
        final_slope: f.final_slope * u.y_unit / u.t_unit,
        t5: time(f.t5),
        t28: time(f.t28),
        t63: time(f.t63),
        t_peak: time(f.t_peak),
        overshoot_decay: time(f.overshoot_decay),
        t_dip: time(f.t_dip),
        period: time(f.period),
        ..f
    }
}

/// [`features`] read in the record's units as they are.
fn features_as_given(data: &FitData, y0: Option<f64>) -> CurveFeatures {
    let n = data.y.len();
    let y0 = y0
        .or_else(|| level_before(data))
        .unwrap_or_else(|| data.y.first().copied().unwrap_or(0.0));
    let tail = (n / 10).max(3).min(n);
    // NaN for a record without samples (nothing to read; the fit refuses it).
    let y_final = data.y[n - tail..].iter().sum::<f64>() / tail as f64;
    let fifth = (n / 5).max(2).min(n);
    let final_slope = slope(&data.times[n - fifth..], &data.y[n - fifth..]);
    let span = y_final - y0;
    let e: Vec<(f64, f64)> = data
        .times
        .iter()
        .zip(&data.y)
        .filter(|(t, _)| **t >= data.input.t0())
        .map(|(t, y)| {
            (
                t - data.input.t0(),
                if span != 0.0 { (y - y0) / span } else { 0.0 },
            )
        })
        .collect();
    let crossing = |level: f64| first_crossing(&e, level);
    let (peak_i, peak) =
        e.iter().enumerate().fold(
            (0, f64::NEG_INFINITY),
            |b, (i, p)| if p.1 > b.1 { (i, p.1) } else { b },
        );
    let (dip_i, dip) =
        e.iter().enumerate().fold(
            (0, f64::INFINITY),
            |b, (i, p)| if p.1 < b.1 { (i, p.1) } else { b },
        );
    let t63 = crossing(0.632);
    let undershoot = (-dip).max(0.0);
    CurveFeatures {
        y0,
        y_final,
        final_slope,
        t5: crossing(0.05),
        t28: crossing(0.283),
        t63,
        overshoot: (peak - 1.0).max(0.0),
        t_peak: (peak > 1.0).then(|| e[peak_i].0),
        overshoot_decay: (peak > 1.0)
            .then(|| first_fall(&e[peak_i..], 1.0 + (peak - 1.0) / std::f64::consts::E))
            .flatten()
            .map(|t| t - e[peak_i].0),
        undershoot,
        t_dip: (undershoot > 0.0 && dip_i < peak_i).then(|| e[dip_i].0),
        period: upward_period(&e, hysteresis(&e, (peak - 1.0).max(0.0))),
    }
}

/// The least normalised overshoot or dip the shape must show, beyond the noise, to suggest
/// a structure that makes one.
const SHAPE_SHARE: f64 = 0.03;

/// The final slope, over the mean slope since the first change, above which the output is
/// taken to ramp (an integrator): a lag slows down towards its level, an integrator does not
/// (a first-order response cut at half its time constant still ends at 0.77 of its mean).
const RAMP_RATIO: f64 = 0.9;

/// The structure the record's shape suggests, for the first guess a student starts from:
/// the notes' first order plus dead time (P1D) unless the curve shows more. An overshoot
/// beyond the noise that falls back before the record's end (not the end of a rise still
/// under way) suggests an underdamped pair with its dead time (P2DU); a dip the wrong
/// way before the rise, a zero (P2Z); an output still climbing at the end as fast as on
/// average, an integrator (P1DI). "Beyond the noise" is beyond the largest of N Gaussian
/// samples, √(2 ln N)·σ (σ from the first differences), and at least [`SHAPE_SHARE`] of
/// the change. A record of several changes is read on its first change's stretch.
pub fn suggested_structure(data: &FitData) -> Structure {
    let code = suggested_code(data);
    Structure::parse(code).unwrap_or_else(|_| Structure::parse("P1D").expect("P1D is a code"))
}

fn suggested_code(data: &FitData) -> &'static str {
    // A staircase is judged on its first change's stretch (the later levels are no
    // overshoot of the first), with single wild samples taken out (a dropout is no dip).
    let keep: Vec<bool> = match data.input.changes.get(1) {
        Some(next) => data.times.iter().map(|&t| t < next.t).collect(),
        None => vec![true; data.times.len()],
    };
    let mut data = data.keeping(&keep);
    let noise = noise_scale(&data);
    data.y = crate::stats::running_median3(&data.y);
    let data = &data;
    let f = features(data, None);
    let span = (f.y_final - f.y0).abs();
    let band = noise * crate::stats::largest_of_gaussians(data.y.len());
    let beyond = |share: f64| span > 0.0 && share > SHAPE_SHARE.max(band / span);
    if ramps(data, &f) {
        "P1DI"
    } else if f.t_dip.is_some()
        && beyond(f.undershoot)
        && !crate::fit::rest::rest_before(data).is_not_at_rest()
    {
        "P2Z"
    } else if f
        .t_peak
        .is_some_and(|t| t < 0.9 * (data.times.last().copied().unwrap_or(0.0) - data.input.t0()))
        && f.overshoot_decay.is_some()
        && beyond(f.overshoot)
    {
        "P2DU"
    } else {
        "P1D"
    }
}

/// The output noise's standard deviation for judging a shape: the larger of the white
/// noise read from the first differences and the robust scale of the last fifth about its
/// straight line (where coloured noise, which the differences under-read, wanders as far as
/// it goes).
fn noise_scale(data: &FitData) -> f64 {
    let n = data.y.len();
    let from = n - n / 5;
    let (t, y) = (&data.times[from..], &data.y[from..]);
    let tail = if t.len() >= 5 {
        let b = slope(t, y);
        let (mt, my) = (mean(t), mean(y));
        let about: Vec<f64> = t
            .iter()
            .zip(y)
            .map(|(t, y)| y - my - b * (t - mt))
            .collect();
        crate::stats::robust_scale(&about)
    } else {
        0.0
    };
    crate::fit::rest::difference_noise(&data.y).max(tail)
}

/// Whether the curve ramps as an integrator does: over the last fifth of the stretch since
/// the change it still climbs at least [`RAMP_RATIO`] of its mean slope, and as fast as
/// over the fifth before (within [`RAMP_STEADY`]). A lag cut before it
/// settles (a heater stepped again after a fraction of its time constant) still slows down
/// from one fifth to the next, e^{−T/(5τ)}.
fn ramps(data: &FitData, f: &CurveFeatures) -> bool {
    let t0 = data.input.t0();
    let after = data.times.last().copied().unwrap_or(t0) - t0;
    let from = |share: f64| data.times.partition_point(|&t| t < t0 + share * after);
    let (a, b) = (from(0.6), from(0.8));
    let n = data.times.len();
    if !(after > 0.0 && b - a >= 3 && n - b >= 3) {
        return false;
    }
    let (before, last) = (
        slope(&data.times[a..b], &data.y[a..b]),
        slope(&data.times[b..], &data.y[b..]),
    );
    let mean_slope = (f.y_final - f.y0) / after;
    last * mean_slope > 0.0
        && last.abs() >= RAMP_RATIO * mean_slope.abs()
        && (before - last).abs() <= RAMP_STEADY * last.abs()
}

/// How far the last fifth's slope may differ from the fifth's before for a ramp.
const RAMP_STEADY: f64 = 0.05;

/// First instant at which the normalised curve reaches `level`, interpolated.
fn first_crossing(e: &[(f64, f64)], level: f64) -> Option<f64> {
    e.windows(2).find_map(|w| {
        let ((ta, a), (tb, b)) = (w[0], w[1]);
        (a < level && b >= level).then(|| ta + (tb - ta) * (level - a) / (b - a))
    })
}

/// First instant at which the normalised curve falls to `level`, interpolated.
fn first_fall(e: &[(f64, f64)], level: f64) -> Option<f64> {
    e.windows(2).find_map(|w| {
        let ((ta, a), (tb, b)) = (w[0], w[1]);
        (a > level && b <= level).then(|| ta + (tb - ta) * (a - level) / (a - b))
    })
}

/// The half-width of the band about the final level a swing must cross to count as an
/// oscillation: a quarter of the overshoot, and at least three noise standard deviations, so
/// that noise about a settled level does not make a period. The noise is estimated from
/// second differences, robustly (σ ≈ median|Δ²e| / (0.6745·√6)): a smooth curve adds little
/// to them, and the few large ones of a coarsely sampled rise do not move the median.
fn hysteresis(e: &[(f64, f64)], overshoot: f64) -> f64 {
    let mut d2: Vec<f64> = e
        .windows(3)
        .map(|w| (w[2].1 - 2.0 * w[1].1 + w[0].1).abs())
        .collect();
    let noise = if d2.is_empty() {
        0.0
    } else {
        let mid = d2.len() / 2;
        let (_, median, _) = d2.select_nth_unstable_by(mid, f64::total_cmp);
        *median / (0.6745 * 6f64.sqrt())
    };
    (0.25 * overshoot).max(3.0 * noise)
}

/// Mean time between successive upward crossings of the final level (1), if at least two;
/// a crossing counts when the curve came from below 1 − `band` and goes on above 1 + `band`.
fn upward_period(e: &[(f64, f64)], band: f64) -> Option<f64> {
    let mut ups = Vec::new();
    let (mut armed, mut candidate) = (false, None);
    for w in e.windows(2) {
        let ((ta, a), (tb, b)) = (w[0], w[1]);
        if b < 1.0 - band {
            armed = true;
            candidate = None;
        }
        if armed && a < 1.0 && b >= 1.0 {
            candidate = Some(ta + (tb - ta) * (1.0 - a) / (b - a));
        }
        if b > 1.0 + band
            && let Some(t) = candidate.take()
        {
            ups.push(t);
            armed = false;
        }
    }
    (ups.len() >= 2).then(|| (ups[ups.len() - 1] - ups[0]) / (ups.len() - 1) as f64)
}

/// Least-squares slope of y over t.
fn slope(t: &[f64], y: &[f64]) -> f64 {
    let n = t.len() as f64;
    let (mt, my) = (t.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (num, den) = t.iter().zip(y).fold((0.0, 0.0), |(a, b), (t, y)| {
        (a + (t - mt) * (y - my), b + (t - mt).powi(2))
    });
    if den > 0.0 { num / den } else { 0.0 }
}

/// An initial guess for `structure`; `y0` is the operating point when known. A structure
/// that holds Y0 (not `free_offset`) holds it at the level at rest ([`rest_level`]) when
/// none is given, as the app and the CLI do: the least-squares guess of a record with
/// several changes (an actuator's motion, a second step) would otherwise fix it where the
/// regression put it, off the samples before the step by several times their noise.
pub fn auto_guess(data: &FitData, structure: Structure, y0: Option<f64>) -> Values {
    let y0 = y0.or_else(|| {
        (!structure.free_offset)
            .then(|| level_before(data))
            .flatten()
    });
    internal(data)
        .and_then(|(u, inside)| {
            let guess = guess_as_given(&inside, structure, y0.map(|y| u.output_in(y)));
            u.values_out(structure, &guess).ok()
        })
        .unwrap_or_else(|| guess_as_given(data, structure, y0))
}

/// `guess` with its real lags in ascending order when the structure has an initial
/// transient (before [`linear_part`] solves the transient's coefficients for them). The transient's basis is Newton's (see [`crate::model::transient`]): its k-th function
/// is dominated, once the faster modes have died, by the k-th pole's mode only when the
/// faster poles come first; with the slow pole first every function decays like it, the
/// coefficients are nearly collinear on a window that starts on a previous response's late
/// tail, and a fit crawls along them for hundreds of iterations (the RC ladder's per-step P2
/// windows hit the 200-iteration limit; in this order they converge in about twenty). The step
/// response does not depend on the order.
fn fastest_pole_first(mut guess: Values, s: Structure) -> Values {
    if !s.transient || s.underdamped || s.poles < 2 {
        return guess;
    }
    let lags = [Param::Tp1, Param::Tp2, Param::Tp3];
    let lags = &lags[..s.poles as usize];
    let mut values: Vec<f64> = lags.iter().map(|&p| guess.get(p)).collect();
    values.sort_by(f64::total_cmp);
    for (&p, v) in lags.iter().zip(values) {
        guess.set(p, v);
    }
    guess
}

/// [`auto_guess`] in the record's units as they are: read off the curve for one step
/// from rest, by least squares on the whole record otherwise ([`regression_guess`]).
///
/// On a long record the regression runs on its reduction ([`crate::fit::reduce`]: block means,
/// every sample kept where the response moves): a guess needs the curve's shape, not every
/// sample's noise, and the fit that follows uses every sample.
fn guess_as_given(data: &FitData, structure: Structure, y0: Option<f64>) -> Values {
    if needs_regression(data, structure) {
        let start = curve_guess(data, structure, y0);
        let guess = match crate::fit::reduce::reduce(&data.times, &data.input) {
            Some(r) => regression_guess(&r.apply(data), structure, y0, start),
            None => regression_guess(data, structure, y0, start),
        };
        return guess.unwrap_or(start);
    }
    curve_guess(data, structure, y0)
}

/// Whether the curve's features cannot be read as one step's response from rest: the input
/// moves more than once (several changes, a ramped step, a first-order hold) or the output
/// was not at rest (an initial transient to start).
fn needs_regression(data: &FitData, structure: Structure) -> bool {
    let input = &data.input;
    input.is_multi_step() || input.steps.len() > 1 || !input.ramps.is_empty() || structure.transient
}

/// The guess read off the curve of the first change (the notes' methods).
fn curve_guess(data: &FitData, structure: Structure, y0: Option<f64>) -> Values {
    let f = features_as_given(data, y0);
    let duration = data.duration();
    let ts = data.sampling_period();
    let du = data.input.du();
    let mut v = Values::default();
    v.set(Param::Y0, f.y0);
    v.set(Param::Drift, 0.0);
    let positive = |x: f64| lag_in_range(x, ts, duration);
    // Total lag (sum of time constants plus dead time) from the 63.2 % time.
    let t63 = f.t63.unwrap_or(duration / 3.0);
    let two_point = f.t28.map(|t28| 1.5 * (t63 - t28)).filter(|tau| *tau > 0.0);
    let lag = if structure.delay {
        two_point.unwrap_or(t63)
    } else {
        t63
    };
    if structure.integrator {
        v.set(Param::Kp, f.final_slope / du);
        // The ramp's asymptote y = y0 + Kp·du·(t − t0 − Td − Tp) crosses y0 at the total lag.
        let last_t = data.times.last().copied().unwrap_or(data.input.t0()) - data.input.t0();
        let last_y = data.y.last().copied().unwrap_or(f.y0);
        let intercept = if f.final_slope != 0.0 {
            last_t - (last_y - f.y0) / f.final_slope
        } else {
            duration / 5.0
        };
        set_lags(&mut v, structure, positive(intercept));
    } else {
        v.set(Param::Kp, (f.y_final - f.y0) / du);
        set_lags(&mut v, structure, positive(lag));
    }
    if structure.underdamped {
        let zeta = if f.overshoot > 1e-3 {
            let l = f.overshoot.ln();
            (-l / (std::f64::consts::PI.powi(2) + l * l).sqrt()).clamp(0.02, 0.95)
        } else {
            0.8
        };
        let omega_d = f.period.map(|p| std::f64::consts::TAU / p);
        let wn = match omega_d {
            Some(wd) => wd / (1.0 - zeta * zeta).sqrt(),
            None => 1.8 / positive(lag),
        };
        v.set(Param::Zeta, zeta);
        v.set(Param::Tw, natural_period(1.0 / wn, ts, duration));
    }
    if structure.zero {
        set_zero(&mut v, structure, &f, ts, duration);
    }
    if structure.delay {
        let own = own_five_percent_time(structure, v, data).unwrap_or(0.0);
        let td = f.t5.map_or(0.0, |t5| (t5 - own).max(0.0));
        v.set(Param::Td, td.min(0.9 * duration));
        if structure.underdamped
            && f.period.is_none()
            && let Some(tp) = f.t_peak
        {
            let wd = std::f64::consts::PI / (tp - td).max(2.0 * ts);
            let zeta = v.get(Param::Zeta);
            v.set(
                Param::Tw,
                natural_period((1.0 - zeta * zeta).sqrt() / wd, ts, duration),
            );
        }
    }
    v
}

/// Lags tried by [`regression_guess`], as multiples of the sampling period up to half the
/// record (log-spaced).
const REGRESSION_LAGS: usize = 12;
/// Dead time's share of the total lag tried by [`regression_guess`].
const DELAY_SHARES: [f64; 4] = [0.05, 0.2, 0.4, 0.7];
/// Damping ratios tried by [`regression_guess`] for an underdamped pair.
const ZETAS: [f64; 3] = [0.2, 0.45, 0.75];
/// Tz over the slowest lag the curve's guess implies (a small zero on the side the curve
/// points at).
const SMALL_ZERO: f64 = 0.3;
/// Tz over the slowest lag tried by [`regression_guess`] for a zero: small ones on either
/// side, an inverse response's, and lead zeros above the lags (an overshoot that decays
/// with the slow lag: its peak is about Tz/Tp1 of the final level).
const ZERO_SHARES: [f64; 6] = [SMALL_ZERO, -SMALL_ZERO, -1.0, 1.5, 2.5, 4.0];

/// A least-squares guess from the whole record, driven by the measured input: the output is
/// linear in Kp, Y0, the initial transient's X1… and the drift once the lags are chosen, so
/// a small grid over the total lag (and the dead time's share of it, and ζ) solves those by
/// linear least squares at each point and keeps the point of least squared error, then
/// refines the lag about it. Cheap (a few dozen simulations) and robust on any input: multi-
/// step, pulse, doublet, PRBS, ramped steps. `start` gives the values the grid does not
/// choose (Tz's sign, a third pole's share). `None` when no point can be solved.
fn regression_guess(
    data: &FitData,
    structure: Structure,
    y0: Option<f64>,
    start: Values,
) -> Option<Values> {
    let ts = data.sampling_period();
    let duration = data.duration();
    if !(ts > 0.0 && duration > ts) {
        return None;
    }
    let mut base = start;
    base.set(Param::Ta, 0.5 * data.input.lead_range);
    let shape = |lag: f64, share: f64, zeta: f64, zero: f64| {
        let mut v = base;
        let td = if structure.delay { share * lag } else { 0.0 };
        let own = lag - td;
        set_lags(&mut v, structure, own);
        if structure.underdamped {
            v.set(Param::Zeta, zeta);
            v.set(
                Param::Tw,
                natural_period(own / (2.0 * zeta.max(0.3)), ts, duration),
            );
        }
        if structure.zero {
            let tp = v.get(Param::Tp1).max(v.get(Param::Tw));
            v.set(Param::Tz, zero * tp);
        }
        v.set(Param::Td, td);
        v
    };
    // The zero's place: the curve's side first (a dip: Tz < 0), then the others the grid
    // tries, so that a zero is guessed where the whole record puts it (a lead zero's
    // overshoot on a record of several changes, which the first change's features do not
    // read).
    let curve_side = if start.get(Param::Tz) < 0.0 {
        -SMALL_ZERO
    } else {
        SMALL_ZERO
    };
    let zeros: Vec<f64> = if structure.zero {
        std::iter::once(curve_side)
            .chain(ZERO_SHARES.into_iter().filter(|z| *z != curve_side))
            .collect()
    } else {
        vec![curve_side]
    };
    let lo = (2.0 * ts).ln();
    let hi = (0.5 * duration).ln().max(lo);
    let step = (hi - lo) / (REGRESSION_LAGS - 1) as f64;
    let mid_share = if structure.delay {
        DELAY_SHARES[1]
    } else {
        0.0
    };
    let mid_zeta = ZETAS[1];
    let solve = |v: Values| linear_part(data, structure, y0, v);
    // 1. The total lag, at middle shapes, with each place of a zero.
    let mut best = (0..REGRESSION_LAGS)
        .flat_map(|i| zeros.iter().map(move |&z| (i, z)))
        .filter_map(|(i, z)| {
            let lag = (lo + step * i as f64).exp();
            solve(shape(lag, mid_share, mid_zeta, z))
                .map(|(v, e)| (lag, mid_share, mid_zeta, z, v, e))
        })
        .min_by(|a, b| a.5.total_cmp(&b.5))?;
    // 2. The shape at that lag.
    let shares: &[f64] = if structure.delay {
        &DELAY_SHARES
    } else {
        &[0.0]
    };
    let zetas: &[f64] = if structure.underdamped {
        &ZETAS
    } else {
        &[ZETAS[1]]
    };
    for &share in shares {
        for &zeta in zetas {
            if let Some((v, e)) = solve(shape(best.0, share, zeta, best.3))
                && e < best.5
            {
                best = (best.0, share, zeta, best.3, v, e);
            }
        }
    }
    // 3. The lag again, on a finer grid about the best.
    for k in [-3.0, -2.0, -1.0, 1.0, 2.0, 3.0] {
        let lag = best.0 * (k * step / 4.0).exp();
        if let Some((v, e)) = solve(shape(lag, best.1, best.2, best.3))
            && e < best.5
        {
            best = (lag, best.1, best.2, best.3, v, e);
        }
    }
    Some(best.4)
}

/// The parameters the output is linear in, for the lags of `v`: Kp always, Y0 when not
/// held (`y0`), X1… with an initial transient, the drift; solved by least squares on every
/// sample. The values with them set and the sum of squared errors, or `None` when the
/// model cannot be simulated or the regressors are degenerate.
fn linear_part(
    data: &FitData,
    structure: Structure,
    y0: Option<f64>,
    v: Values,
) -> Option<(Values, f64)> {
    let v = fastest_pole_first(v, structure);
    let mut linear = vec![Param::Kp];
    linear.extend(structure.transient_params());
    if structure.drift {
        linear.push(Param::Drift);
    }
    let mut base = v;
    for &p in &linear {
        base.set(p, 0.0);
    }
    base.set(Param::Kp, 1.0);
    base.set(Param::Y0, 0.0);
    let simulate = |values: Values| {
        Model::new(structure, values)
            .simulate(&data.input, &data.times)
            .ok()
    };
    let kp_response = simulate(base)?;
    let mut columns = vec![kp_response.clone()];
    for &p in &linear[1..] {
        let mut with = base;
        with.set(p, 1.0);
        let r = simulate(with)?;
        columns.push(r.iter().zip(&kp_response).map(|(a, b)| a - b).collect());
    }
    let target: Vec<f64> = match y0 {
        Some(level) => data.y.iter().map(|y| y - level).collect(),
        None => {
            columns.push(vec![1.0; data.y.len()]);
            linear.push(Param::Y0);
            data.y.clone()
        }
    };
    let coefficients = least_squares(&columns, &target)?;
    let mut out = v;
    for (&p, &c) in linear.iter().zip(&coefficients) {
        out.set(p, c);
    }
    if let Some(level) = y0 {
        out.set(Param::Y0, level);
    }
    let sse = target
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let fit: f64 = columns
                .iter()
                .zip(&coefficients)
                .map(|(c, a)| c[i] * a)
                .sum();
            (t - fit).powi(2)
        })
        .sum::<f64>();
    sse.is_finite().then_some((out, sse))
}

/// Linear least squares by the normal equations (a handful of columns), with partial
/// pivoting; `None` when they are singular or not finite.
fn least_squares(columns: &[Vec<f64>], target: &[f64]) -> Option<Vec<f64>> {
    let m = columns.len();
    let mut a = vec![vec![0.0; m + 1]; m];
    for i in 0..m {
        for j in 0..m {
            a[i][j] = columns[i].iter().zip(&columns[j]).map(|(x, y)| x * y).sum();
        }
        a[i][m] = columns[i].iter().zip(target).map(|(x, y)| x * y).sum();
    }
    let scale = (0..m).map(|i| a[i][i].abs()).fold(0.0, f64::max);
    for col in 0..m {
        let pivot = (col..m).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        let size = a[pivot][col].abs();
        if size.is_nan() || size <= 1e-12 * scale {
            return None;
        }
        a.swap(col, pivot);
        let pivot_row = a[col].clone();
        for (row, r) in a.iter_mut().enumerate() {
            if row != col {
                let f = r[col] / pivot_row[col];
                for (x, p) in r[col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    let x: Vec<f64> = (0..m).map(|i| a[i][m] / a[i][i]).collect();
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Tz from the curve: a dip first gives a right-half-plane zero (Tz < 0); an overshoot
/// without oscillation is read as a zero above real lags: the excess decays with the slow lag
/// (`overshoot_decay`), the fast lag shows in the peak time, and the peak ≈ Tz / Tp1 of the
/// final value; otherwise a small zero.
fn set_zero(v: &mut Values, structure: Structure, f: &CurveFeatures, ts: f64, duration: f64) {
    let tp = if structure.underdamped {
        v.get(Param::Tw)
    } else {
        v.get(Param::Tp1)
    };
    let positive = |x: f64| lag_in_range(x, ts, duration);
    let tz = match (f.t_dip, f.t_peak, f.overshoot_decay) {
        (Some(_), _, _) => -0.5 * tp,
        (None, Some(t_peak), Some(decay)) if !structure.underdamped => {
            let slow = positive(decay);
            v.set(Param::Tp1, slow);
            if structure.poles >= 2 {
                v.set(Param::Tp2, positive(t_peak / 3.0).min(slow));
            }
            if structure.poles >= 3 {
                v.set(Param::Tp3, positive(t_peak / 10.0).min(slow));
            }
            (1.0 + f.overshoot) * slow
        }
        _ => 0.3 * tp,
    };
    v.set(Param::Tz, tz);
}

/// A guessed lag kept where the record can show it: two sampling periods to ten record
/// lengths.
fn lag_in_range(lag: f64, ts: f64, duration: f64) -> f64 {
    lag.max(2.0 * ts).min(10.0 * duration)
}

/// Tw = 1/ωn kept where the sampling can show it: an oscillation is seen up to ωd = π/Ts, so
/// Tw may be well below the sampling period (the LECI test: Tw ≈ 1.04 s at Ts ≈ 1.03 s);
/// the floor is Ts/π, the ceiling ten record lengths.
fn natural_period(tw: f64, ts: f64, duration: f64) -> f64 {
    tw.max(ts / std::f64::consts::PI).min(10.0 * duration)
}

/// Splits a total lag among the structure's time constants.
fn set_lags(v: &mut Values, structure: Structure, lag: f64) {
    let shares: &[f64] = match (structure.underdamped, structure.poles) {
        (true, 3) => &[0.7, 0.3],
        (true, _) => &[1.0],
        (false, 1) => &[1.0],
        (false, 2) => &[0.75, 0.25],
        (false, _) => &[0.6, 0.25, 0.15],
    };
    if structure.underdamped {
        v.set(Param::Tw, lag * shares[0] / 2.0);
        if let Some(s) = shares.get(1) {
            v.set(Param::Tp3, lag * s);
        }
    } else {
        for (p, s) in [Param::Tp1, Param::Tp2, Param::Tp3].into_iter().zip(shares) {
            v.set(p, lag * s);
        }
    }
}

/// The guessed model's own 5 % time (no delay), from a fine simulation.
fn own_five_percent_time(structure: Structure, values: Values, data: &FitData) -> Option<f64> {
    let mut s = structure;
    s.delay = false;
    s.drift = false;
    let mut v = values;
    v.set(Param::Y0, 0.0);
    let model = Model::new(s, v);
    let horizon = data.duration();
    let times: Vec<f64> = (0..=2000).map(|k| horizon * k as f64 / 2000.0).collect();
    let y = model.simulate(&Excitation::step(0.0, 1.0), &times).ok()?;
    let kp = v.get(Param::Kp);
    if kp == 0.0 {
        return None;
    }
    let e: Vec<(f64, f64)> = times.iter().zip(&y).map(|(t, y)| (*t, y / kp)).collect();
    first_crossing(&e, 0.05)
}

#[cfg(test)]
mod tests;
