//! Whether a record shows an operating point off the one held, by what only an offset
//! explains. The held Y0 is the mean of the samples before the step ([`rest_level`]), an
//! estimate with its own noise: σ/√n, widened for their lag-one correlation, and up to half
//! a quantum off on a staircase. A free Y0 fitted on the whole record, where the samples at
//! rest after a return outnumber those before the step several times, moves away from it
//! by that noise alone, and on a long record the BIC pays for the move (a challenge of
//! spikes alone, whose 133 samples before the step read 2.7 standard errors high, ended
//! with `offset` named). So the free Y0 is kept only when it differs from the held one by
//! more than [`Z_OFFSET`] standard errors of the difference and, on a staircase, by more
//! than half a quantum. A Y0 the student gave (not the mean before the step) has no noise
//! of its own: only the free Y0's counts.

use crate::diagnose::test_causes::resolution;
use crate::fit::guess::rest_level;
use crate::fit::{FitData, FitReport};
use crate::model::{Model, Param};
use crate::stats::{OUTLIER_THRESHOLD, ar1_widening, lag_one, robust_scale, tame};

/// Standard errors of the difference a free Y0 must stand off the held one (a two-sided
/// probability of 6e-5 for white noise).
pub const Z_OFFSET: f64 = 4.0;

/// Whether `free`'s Y0 differs from `held`'s by more than the held one's own noise and the
/// free one's can make (see the module docs).
pub fn offset_shown(data: &FitData, held: &Model, free: &FitReport) -> bool {
    let (y_held, y_free) = (held.get(Param::Y0), free.model.get(Param::Y0));
    let apart = (y_free - y_held).abs();
    let se_free = free.interval(Param::Y0).map_or_else(
        || free.rmse / (free.n.max(1) as f64).sqrt(),
        |(lo, hi)| (hi - lo) / (2.0 * 1.96),
    );
    let (se_held, rounding) = held_noise(data, y_held, free).unwrap_or((0.0, 0.0));
    apart > Z_OFFSET * se_held.hypot(se_free) && apart > rounding
}

/// The standard error of the mean before the step when `y_held` is that mean, and half the
/// output's quantum (0 for a continuous output); `None` when Y0 was not read there. The
/// noise is read on `free`'s residuals there (its wild ones left out), not on the samples:
/// a trend the model carries (a drift, a test not at rest) is no noise of the mean.
fn held_noise(data: &FitData, y_held: f64, free: &FitReport) -> Option<(f64, f64)> {
    let rest = rest_level(data)?;
    let same = (rest.y0 - y_held).abs() <= 1e-9 * y_held.abs().max(1e-300);
    if rest.at_step || !same {
        return None;
    }
    let residuals = free.residuals(data).ok()?;
    let kept = tame(residuals.get(..rest.samples)?, OUTLIER_THRESHOLD);
    let n = kept.len() as f64;
    let se = robust_scale(&kept) * ar1_widening(lag_one(&kept)) / n.sqrt();
    let half_quantum = resolution(&data.y).map_or(0.0, |q| 0.5 * q);
    Some((if se.is_finite() { se } else { 0.0 }, half_quantum))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{FitOptions, fit};
    use crate::model::excitation::{Excitation, Hold};
    use crate::model::{Structure, Values};
    use crate::random::Lcg;

    /// A P1 (Kp 2, τ 5 s) from y0 40, its input stepped by 3 at 10 s and back at 60 s,
    /// sampled every 0.1 s for 150 s, white noise `noise`, the samples before the step
    /// lifted by `lift` (a held Y0 that far off), a drift of `drift` units/s on all of it.
    fn record(lift: f64, drift: f64, noise: f64) -> FitData {
        let s = Structure::parse("P1").unwrap();
        let v = Values::from_pairs(&[(Param::Kp, 2.0), (Param::Tp1, 5.0), (Param::Y0, 40.0)]);
        let times: Vec<f64> = (0..1500).map(|k| 0.1 * k as f64).collect();
        let u: Vec<f64> = (0..1500)
            .map(|k| if (100..600).contains(&k) { 13.0 } else { 10.0 })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        let clean = Model::new(s, v).simulate(&input, &times).unwrap();
        let mut rng = Lcg(41);
        let y = clean
            .iter()
            .enumerate()
            .map(|(k, c)| {
                let before = if k < 100 { lift } else { 0.0 };
                c + noise * rng.gaussian() + before + drift * 0.1 * k as f64
            })
            .collect();
        FitData { times, y, input }
    }

    /// The held P1 (Y0 the mean before the step) and the free one, with a drift term when
    /// `drift`.
    fn fits(data: &FitData, drift: bool) -> (FitReport, FitReport) {
        let y0 = rest_level(data).unwrap().y0;
        let mut free = Structure::parse("P1").unwrap();
        free.drift = drift;
        let mut held = free;
        held.free_offset = false;
        let mut v = Values::from_pairs(&[(Param::Kp, 2.0), (Param::Tp1, 5.0)]);
        v.set(Param::Y0, y0);
        let o = FitOptions::default();
        let h = fit(data, held, v, &o, &mut ()).unwrap();
        let f = fit(data, free, h.model.values, &o, &mut ()).unwrap();
        (h, f)
    }

    #[test]
    fn a_held_level_off_by_its_own_noise_is_no_offset_and_a_real_one_is() {
        // The mean of 100 samples of σ 0.05 has a standard error of 0.005: lifted by two of
        // them it is within its noise, by ten it is off.
        for (lift, shown) in [(0.0, false), (0.01, false), (0.05, true)] {
            let data = record(lift, 0.0, 0.05);
            let (held, free) = fits(&data, false);
            assert_eq!(
                offset_shown(&data, &held.model, &free),
                shown,
                "lift {lift}"
            );
        }
    }

    #[test]
    fn beside_a_drift_the_mean_before_the_step_is_off_by_its_motion() {
        // A drift of 0.02 units/s moves the output 0.2 over the 10 s before the step, under
        // noise of 0.01: their mean is 0.1 off the level at the step, a hundred standard
        // errors. The noise of that mean is read on the residuals of the model with its
        // drift; read on the samples, the trend would pass for noise correlated near 1, and
        // the offset for its own noise.
        let data = record(0.0, 0.02, 0.01);
        let (held, free) = fits(&data, true);
        assert!(offset_shown(&data, &held.model, &free), "{:?}", free.model);
    }
}
