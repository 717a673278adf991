//! `saturation`: the output held flat at a limit while the model keeps moving. A clipped
//! sensor or an actuator at its end stop writes the same value, exactly, sample after
//! sample, where a live signal's noise would scatter: the candidates are the samples at
//! the record's extreme value (its largest or smallest), in runs of at least [`MIN_RUN`],
//! [`MIN_SAMPLES`] or more in all. A quantised record also repeats its extreme level, so the
//! candidates are confirmed by the model (refitted without them, it must go beyond the
//! level over them by more than [`BEYOND`] times the refit's robust noise) or by the pile-up
//! at the level itself ([`piled_up`]: more samples at the limit than within a noise σ under
//! it, which a live signal's thin noise tail never gives). The clipped samples are then left
//! out of the fit.

use super::outliers::runs;
use super::quantisation::resolution;
use super::{Handling, Signal, TestCause, TestCauseKind, TestEvidence};
use crate::fit::{FitData, FitOptions, FitReport, fit};
use crate::stats::robust_scale;

/// The shortest run at the limit that counts.
pub const MIN_RUN: usize = 3;
/// The fewest samples at the limit in all.
pub const MIN_SAMPLES: usize = 8;
/// The fewest samples left to fit once the clipped ones are out.
const MIN_LEFT: usize = 20;
/// How far past the limit the refitted model must go over the clipped samples, in robust
/// standard deviations of its residuals.
pub const BEYOND: f64 = 3.0;
/// The noise (robust σ) must span this many output quanta for the pile-up at a level to be
/// read as a limit.
const DITHERED: f64 = 2.0;

/// The clipped samples of `data` (if any) given the current fit, and their indices.
pub fn detect(data: &FitData, current: &FitReport) -> Option<(TestCause, Vec<usize>)> {
    [1.0, -1.0]
        .into_iter()
        .filter_map(|side| clipped(data, current, side))
        .max_by_key(|(_, at)| at.len())
}

/// The samples held at the record's extreme on `side` (+1 the largest, −1 the smallest).
fn clipped(data: &FitData, current: &FitReport, side: f64) -> Option<(TestCause, Vec<usize>)> {
    let y = &data.y;
    let level = y.iter().map(|v| side * v).fold(f64::NEG_INFINITY, f64::max) * side;
    let range = y.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b))
        - y.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    let tolerance = 1e-12 * (level.abs() + range);
    let at: Vec<usize> = (0..y.len())
        .filter(|&i| (y[i] - level).abs() <= tolerance)
        .collect();
    let spans: Vec<Vec<usize>> = runs(&at)
        .into_iter()
        .filter(|r| r.len() >= MIN_RUN)
        .collect();
    let held: Vec<usize> = spans.iter().flatten().copied().collect();
    if held.len() < MIN_SAMPLES.max(y.len() / 50) || held.len() + MIN_LEFT > y.len() {
        return None;
    }
    let mut keep = vec![true; y.len()];
    held.iter().for_each(|&i| keep[i] = false);
    let rest = data.keeping(&keep);
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let refit = fit(
        &rest,
        current.model.structure,
        current.model.values,
        &options,
        &mut (),
    )
    .ok()?;
    let noise = robust_scale(&refit.residuals(&rest).ok()?);
    let model = y
        .iter()
        .zip(refit.residuals(data).ok()?)
        .map(|(y, r)| y - r)
        .collect::<Vec<f64>>();
    let beyond = held.iter().map(|&i| side * (model[i] - level)).sum::<f64>() / held.len() as f64;
    let past_limit = beyond > BEYOND * noise;
    if !past_limit && !piled_up(y, level, side, at.len(), noise) {
        return None;
    }
    let t = |i: usize| data.times[i];
    let spans: Vec<(f64, f64)> = spans.iter().map(|r| (t(r[0]), t(r[r.len() - 1]))).collect();
    let (start, end) = (spans[0].0, spans[spans.len() - 1].1);
    let cause = TestCause {
        kind: TestCauseKind::Saturation,
        evidence: TestEvidence::Saturation {
            signal: Signal::Output,
            level,
            samples: held.len(),
            spans,
        },
        interval: Some((start, end)),
        handling: Handling::Excluded { start, end },
    };
    Some((cause, held))
}

/// Whether the record piles up at `level` as only a limit makes it: more samples there
/// (`held`, in runs or not) than within one noise standard deviation (at least one quantum)
/// short of it. A live signal's extreme is the top of its noise, a thin tail: a continuous
/// record never repeats it, and a quantised one whose noise spans a few levels
/// (σ ≥ [`DITHERED`]·q) holds fewer samples at its top level than at the levels just under
/// it. A clipped record holds there every sample the limit caught, even when the limit sits
/// within the noise of the final value and the model goes past it by less than [`BEYOND`] σ.
/// A coarser record (a TCLab's 0.32 °C under σ ≈ 0.2 °C) can rest on its top level, or end
/// there still rising: it is left to the model's test.
fn piled_up(y: &[f64], level: f64, side: f64, held: usize, noise: f64) -> bool {
    let q = resolution(y);
    if q.is_some_and(|q| noise < DITHERED * q) {
        return false;
    }
    let band = noise.max(q.unwrap_or(0.0));
    let near = y
        .iter()
        .filter(|&&v| {
            let short = side * (level - v);
            short > 0.0 && short <= band
        })
        .count();
    held > near
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::excitation::Excitation;
    use crate::model::{Model, Param, Structure, Values};

    fn p1(limit: f64) -> (FitData, FitReport) {
        let s = Structure::parse("P1").unwrap();
        let mut v = Values::default();
        v.set(Param::Kp, 3.0);
        v.set(Param::Tp1, 4.0);
        v.set(Param::Y0, 20.0);
        let times: Vec<f64> = (0..200).map(|k| 0.2 * k as f64).collect();
        let input = Excitation::step(4.0, 1.0);
        let clean = Model::new(s, v).simulate(&input, &times).unwrap();
        let mut rng = crate::random::Lcg(3);
        let y = clean
            .iter()
            .map(|c| (c + 0.005 * rng.symmetric()).min(limit))
            .collect();
        let data = FitData { times, y, input };
        let r = fit(&data, s, v, &FitOptions::default(), &mut ()).unwrap();
        (data, r)
    }

    #[test]
    fn a_clipped_plateau_is_found_and_a_free_one_is_not() {
        let (data, current) = p1(22.7);
        let (cause, held) = detect(&data, &current).unwrap();
        assert!(held.len() > 50, "{cause:?}");
        let TestEvidence::Saturation { level, .. } = cause.evidence else {
            panic!()
        };
        assert_eq!(level, 22.7);
        let (data, current) = p1(f64::INFINITY);
        assert!(detect(&data, &current).is_none());
    }

    #[test]
    fn a_limit_within_the_noise_of_the_final_value_is_found_by_its_pile_up() {
        // The clean response ends at 22.9996 under noise of ± 0.005 (σ 0.0029): the model
        // goes past the limit by half a σ, but two thirds of the settled samples sit on it.
        let (data, current) = p1(22.998);
        let (cause, held) = detect(&data, &current).unwrap();
        assert!(held.len() >= MIN_SAMPLES, "{cause:?}");
        assert!(
            matches!(cause.evidence, TestEvidence::Saturation { level, .. } if level == 22.998)
        );
    }

    #[test]
    fn a_dithered_quantised_record_does_not_pile_up_at_its_top_level() {
        let mut rng = crate::random::Lcg(11);
        // Uniform noise of σ = 0.0058 on a quantum of 0.4 of that.
        let (a, q) = (0.01, 0.004 / 3f64.sqrt());
        let sd = a / 3f64.sqrt();
        let y: Vec<f64> = (0..2000)
            .map(|_| (a * rng.symmetric() / q).round() * q)
            .collect();
        let top = y.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
        let at_top = y.iter().filter(|&&v| v == top).count();
        assert!(at_top > 20, "{at_top}");
        assert!(!piled_up(&y, top, 1.0, at_top, sd));
        // The same record clipped at its middle level piles up there.
        let clipped: Vec<f64> = y.iter().map(|v| v.min(0.0)).collect();
        let at_zero = clipped.iter().filter(|&&v| v == 0.0).count();
        assert!(piled_up(&clipped, 0.0, 1.0, at_zero, sd));
    }
}
