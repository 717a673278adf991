//! Whether a test was at rest before its first input change: the premise of every step
//! method ("admite-se, por hipótese, que os processos estão em equilíbrio antes da variação
//! do sinal de entrada", the LECI notes). When the output still moves before the first
//! change, the model cannot start from rest: it estimates an initial transient (the free
//! response of G's poles, see [`crate::model`]) and Y0 with it.
//!
//! The test: a straight line fitted by least squares to the samples before the first change
//! (at least [`MIN_SAMPLES_BEFORE`]); the output moved when the line's change over that span
//! exceeds all of six standard errors of itself (the residuals about the line as noise, so
//! coloured noise counts against it), four times the white noise read from the first
//! differences (1.4826·MAD/√2), and 5 % of the record's output range (a movement too small
//! to matter to the fit is not worth a transient's parameters).

use serde::{Deserialize, Serialize};

use crate::fit::FitData;

/// The fewest samples before the first change the test looks at.
pub const MIN_SAMPLES_BEFORE: usize = 8;

/// How the output moved before the first change.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Motion {
    /// The line's change over the span (output units; its sign is the direction).
    pub change: f64,
    /// The span looked at (s): first sample to the last before the change.
    pub span: (f64, f64),
    pub samples: usize,
    /// The least change that counts as motion on this record (output units).
    pub threshold: f64,
}

/// What the samples before the first change say.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Rest {
    /// Too few samples before the first change to tell (rest is assumed, as the notes do).
    Unknown { samples: usize },
    /// Still within the noise.
    AtRest(Motion),
    /// The output moved.
    NotAtRest(Motion),
}

impl Rest {
    pub fn is_not_at_rest(&self) -> bool {
        matches!(self, Rest::NotAtRest(_))
    }
}

/// Whether `data` were at rest before their input's first change.
pub fn rest_before(data: &FitData) -> Rest {
    match line_before(data) {
        Err(samples) => Rest::Unknown { samples },
        Ok((motion, _)) if motion.change.abs() > motion.threshold => Rest::NotAtRest(motion),
        Ok((motion, _)) => Rest::AtRest(motion),
    }
}

/// The motion before the first change when it is significant (beyond six standard errors
/// of itself, widened for the residuals' correlation about the line as for an AR(1)) but
/// not beyond the floors [`rest_before`] also asks of it (four white-noise deviations, 5 %
/// of the record's range): too small to call the test not at rest on its own account,
/// which the caller may still do when a model shows that it matters to the fit. Its
/// `threshold` is the significance's. The widening matters here, without the floors:
/// strongly coloured noise wanders, and a stretch of it looks like a line many white-noise
/// errors long.
pub fn motion_within_range(data: &FitData) -> Option<Motion> {
    let (motion, parts) = line_before(data).ok()?;
    let noise = parts.widening * parts.significance;
    let within = motion.change.abs() <= motion.threshold;
    (within && motion.change.abs() > noise).then_some(Motion {
        threshold: noise,
        ..motion
    })
}

/// The significance part of a motion's threshold (six standard errors of the line's change,
/// output units), and the factor an AR(1) of the residuals' lag-one correlation about the
/// line widens that error by.
struct Noise {
    significance: f64,
    widening: f64,
}

/// The line through the samples before the first change: the motion (its threshold the
/// largest of the three of the module docs) and the noise's part of that threshold; the
/// number of samples when there are too few to tell.
fn line_before(data: &FitData) -> Result<(Motion, Noise), usize> {
    let t0 = data.input.t0();
    let samples = crate::record::timebase::samples_before(&data.times, t0).min(data.y.len());
    if samples < MIN_SAMPLES_BEFORE {
        return Err(samples);
    }
    let (t, y) = (&data.times[..samples], &data.y[..samples]);
    let line = Line::fit(t, y).ok_or(samples)?;
    let span = (t[0], t[samples - 1]);
    let change = line.slope * (span.1 - span.0);
    let significance = 6.0 * line.slope_error * (span.1 - span.0);
    let white = 4.0 * difference_noise(y);
    let (lo, hi) = data
        .y
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let motion = Motion {
        change,
        span,
        samples,
        threshold: significance.max(white).max(0.05 * (hi - lo)),
    };
    let noise = Noise {
        significance,
        widening: crate::stats::ar1_widening(line.lag1),
    };
    Ok((motion, noise))
}

/// A least-squares line y = a + b·(t − t̄) and the standard error of its slope.
struct Line {
    slope: f64,
    slope_error: f64,
    /// The lag-one autocorrelation of the residuals about the line.
    lag1: f64,
}

impl Line {
    fn fit(t: &[f64], y: &[f64]) -> Option<Line> {
        let n = t.len() as f64;
        let t_mean = t.iter().sum::<f64>() / n;
        let y_mean = y.iter().sum::<f64>() / n;
        let stt: f64 = t.iter().map(|t| (t - t_mean).powi(2)).sum();
        if stt.is_nan() || stt <= 0.0 {
            return None;
        }
        let sty: f64 = t
            .iter()
            .zip(y)
            .map(|(t, y)| (t - t_mean) * (y - y_mean))
            .sum();
        let slope = sty / stt;
        let residuals: Vec<f64> = t
            .iter()
            .zip(y)
            .map(|(t, y)| y - y_mean - slope * (t - t_mean))
            .collect();
        let sse: f64 = residuals.iter().map(|r| r * r).sum();
        let slope_error = (sse / (n - 2.0).max(1.0) / stt).sqrt();
        let lag1 = crate::stats::lag_one(&residuals);
        slope.is_finite().then_some(Line {
            slope,
            slope_error,
            lag1,
        })
    }
}

/// The white noise's standard deviation read from the first differences: 1.4826·MAD/√2
/// (robust to the steps, spikes and slow motion the differences also carry).
pub fn difference_noise(y: &[f64]) -> f64 {
    let d: Vec<f64> = y.windows(2).map(|w| w[1] - w[0]).collect();
    if d.is_empty() {
        return 0.0;
    }
    crate::stats::robust_scale(&d) / std::f64::consts::SQRT_2
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::excitation::Excitation;

    fn data(before: impl Fn(f64) -> f64) -> FitData {
        let times: Vec<f64> = (0..60).map(|k| k as f64).collect();
        let y = times
            .iter()
            .enumerate()
            .map(|(k, &t)| {
                let wiggle = 0.01 * (((k * 7919) % 17) as f64 / 17.0 - 0.5);
                (if t < 20.0 { before(t) } else { 12.0 }) + wiggle
            })
            .collect();
        FitData {
            times,
            y,
            input: Excitation::step(20.0, 1.0),
        }
    }

    #[test]
    fn a_flat_start_is_at_rest_and_a_rising_one_is_not() {
        assert!(matches!(rest_before(&data(|_| 10.0)), Rest::AtRest(_)));
        let rising = rest_before(&data(|t| 8.0 + 0.1 * t));
        let Rest::NotAtRest(m) = rising else {
            panic!("{rising:?}")
        };
        assert!((m.change - 1.9).abs() < 0.05, "{m:?}");
        assert_eq!((m.samples, m.span), (20, (0.0, 19.0)));
    }

    #[test]
    fn too_few_samples_say_nothing() {
        let mut d = data(|_| 10.0);
        d.input = Excitation::step(5.0, 1.0);
        assert_eq!(rest_before(&d), Rest::Unknown { samples: 5 });
    }
}
