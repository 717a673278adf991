//! Reading the measured step curve the way a hand construction does, robustly: the record
//! from t0 on, its noise, a lightly smoothed copy for the level crossings, and the local line
//! fits the steepest rise is read from.
//!
//! - **Noise** σ: the median absolute second difference over the samples after t0, divided
//!   by 0.6745·√6 (white noise gives second differences of variance 6σ²; the median ignores
//!   the curve's own curvature and single spikes), floored at the resolution q/√12 of a
//!   quantised record (q the smallest step between distinct values). Coloured noise is
//!   underestimated by this; the student can move the tangent's point.
//! - **Window** n: the fewest samples (at least 2) whose least-squares line has a slope
//!   standard error σ·√(12/(n³ − n))/h at most 2 % of the rough slope 0.8·Δy/(t90 − t10),
//!   and at most the samples in a quarter of t90 − t10. Noise-free records get n = 2 (the
//!   steepest segment between two samples).
//! - **Smoothed curve**: a running median of 3 (harmless on a monotone curve, removes
//!   single-sample spikes) then, for n ≥ 3, a centred running mean of n samples. Level
//!   crossings are read on it as on [`crate::record::prepare::SampledPieces`]: straight lines
//!   between samples, the crossing time interpolated.

use super::HandError;

/// The share of the rough slope the steepest slope's standard error may reach.
const SLOPE_PRECISION: f64 = 0.02;

/// A least-squares line through points: its value at the points' mean abscissa, that mean,
/// and its slope. `None` with fewer than two distinct abscissae.
pub(crate) fn line_fit(xs: &[f64], ys: &[f64]) -> Option<Line> {
    let n = xs.len().min(ys.len());
    if n < 2 {
        return None;
    }
    let x_mean = xs[..n].iter().sum::<f64>() / n as f64;
    let y_mean = ys[..n].iter().sum::<f64>() / n as f64;
    let (mut sxx, mut sxy) = (0.0, 0.0);
    for (x, y) in xs.iter().zip(ys) {
        sxx += (x - x_mean) * (x - x_mean);
        sxy += (x - x_mean) * (y - y_mean);
    }
    (sxx > 0.0).then(|| Line {
        x: x_mean,
        y: y_mean,
        slope: sxy / sxx,
    })
}

/// A straight line through (x, y) with a slope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Line {
    pub x: f64,
    pub y: f64,
    pub slope: f64,
}

impl Line {
    /// The abscissa where the line reaches `level`.
    pub fn at_level(&self, level: f64) -> f64 {
        self.x + (level - self.y) / self.slope
    }

    /// The intercept at x = 0.
    pub fn at_zero(&self) -> f64 {
        self.y - self.slope * self.x
    }
}

/// The record after t0 as the constructions read it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Curve {
    /// Times of the samples with t ≥ t0 (s, absolute).
    pub times: Vec<f64>,
    /// The outputs after a running median of 3 (spikes removed).
    pub despiked: Vec<f64>,
    /// The smoothed outputs the levels are read on.
    pub smooth: Vec<f64>,
    /// The noise σ (output units).
    pub noise: f64,
    /// Samples in each local line fit (and in the running mean, when 3 or more).
    pub window: usize,
    /// Whether the curve goes up from its start level.
    pub rising: bool,
}

impl Curve {
    /// The curve of the samples of `times`, `y` from `t0` on, rising from `y0` to `y_final`.
    pub fn new(times: &[f64], y: &[f64], t0: f64, y0: f64, y_final: f64) -> Self {
        let start = times.partition_point(|&t| t < t0);
        let times = times[start..].to_vec();
        let despiked = crate::stats::running_median3(&y[start..times.len() + start]);
        let noise = noise_level(&despiked, y);
        let mut curve = Curve {
            smooth: despiked.clone(),
            times,
            despiked,
            noise,
            window: 2,
            rising: y_final >= y0,
        };
        curve.window = curve.choose_window(y0, y_final);
        if curve.window >= 3 {
            curve.smooth = running_mean(&curve.despiked, curve.window);
        }
        curve
    }

    /// The median sampling period after t0 (s).
    fn period(&self) -> f64 {
        crate::record::timebase::sampling_period(&self.times).unwrap_or(1.0)
    }

    fn choose_window(&self, y0: f64, y_final: f64) -> usize {
        let rise = y_final - y0;
        let (Ok(t10), Ok(t90)) = (
            self.crossing_in(&self.despiked, y0 + 0.1 * rise, 10.0),
            self.crossing_in(&self.despiked, y0 + 0.9 * rise, 90.0),
        ) else {
            return 2;
        };
        let span = (t90 - t10).max(self.period());
        let rough = 0.8 * rise.abs() / span;
        let h = self.period();
        let most = ((0.25 * span / h).floor() as usize).max(2);
        (2..=most)
            .find(|&n| {
                let n = n as f64;
                self.noise * (12.0 / (n * n * n - n)).sqrt() / h <= SLOPE_PRECISION * rough
            })
            .unwrap_or(most)
    }

    /// The first time (s, absolute) the smoothed curve reaches `level` going from its start
    /// level towards it; `percent` names the level in the error.
    pub fn crossing(&self, level: f64, percent: f64) -> Result<f64, HandError> {
        self.crossing_in(&self.smooth, level, percent)
    }

    fn crossing_in(&self, values: &[f64], level: f64, percent: f64) -> Result<f64, HandError> {
        let reached = |v: f64| if self.rising { v >= level } else { v <= level };
        let k = values
            .iter()
            .position(|&v| reached(v))
            .ok_or(HandError::LevelNotReached { percent })?;
        if k == 0 {
            return Ok(self.times[0]);
        }
        let (ta, tb, ya, yb) = (self.times[k - 1], self.times[k], values[k - 1], values[k]);
        Ok(if yb == ya {
            ta
        } else {
            ta + (level - ya) / (yb - ya) * (tb - ta)
        })
    }

    /// The local line fit of the window of samples starting at `start`.
    fn local_line(&self, start: usize) -> Option<Line> {
        let end = (start + self.window).min(self.times.len());
        line_fit(&self.times[start..end], &self.despiked[start..end])
    }

    /// The local line fit with the steepest slope towards `sign` (+1 rising, −1 falling).
    pub fn steepest(&self, sign: f64) -> Option<Line> {
        let last = self.times.len().checked_sub(self.window)?;
        (0..=last)
            .filter_map(|k| self.local_line(k))
            .filter(|l| l.slope * sign > 0.0)
            .max_by(|a, b| (a.slope * sign).total_cmp(&(b.slope * sign)))
    }

    /// The local line fit of the window centred nearest the time `t` (s, absolute).
    pub fn line_at(&self, t: f64) -> Option<Line> {
        let centre = self.times.partition_point(|&x| x < t);
        let half = self.window / 2;
        let last = self.times.len().checked_sub(self.window)?;
        self.local_line(centre.saturating_sub(half).min(last))
    }

    /// The samples (t, smoothed y).
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.times.iter().copied().zip(self.smooth.iter().copied())
    }
}

/// The record too short, without a rise, or not settled: the checks every method shares.
pub(crate) fn check_rise(curve: &Curve, y0: f64, y_final: f64) -> Result<(), HandError> {
    let change = y_final - y0;
    let scale = y0.abs().max(y_final.abs()).max(f64::MIN_POSITIVE);
    if !(change.abs() > 5.0 * curve.noise && change.abs() > 1e-9 * scale) {
        return Err(HandError::NoRise {
            change,
            noise: curve.noise,
        });
    }
    Ok(())
}

/// How far the last fifth of the record (by time) still moves, as a share of `change`:
/// the slope of its least-squares line times its duration.
pub(crate) fn final_drift(curve: &Curve, change: f64) -> Option<f64> {
    let (first, last) = (*curve.times.first()?, *curve.times.last()?);
    let from = curve
        .times
        .partition_point(|&t| t < last - 0.2 * (last - first));
    let line = line_fit(&curve.times[from..], &curve.despiked[from..])?;
    Some(line.slope * (last - curve.times[from]) / change)
}

/// The centred running mean of `n` samples, narrower near the ends (symmetric).
fn running_mean(y: &[f64], n: usize) -> Vec<f64> {
    let half = n / 2;
    let mut prefix = Vec::with_capacity(y.len() + 1);
    prefix.push(0.0);
    for v in y {
        prefix.push(prefix.last().copied().unwrap_or(0.0) + v);
    }
    (0..y.len())
        .map(|k| {
            let h = half.min(k).min(y.len() - 1 - k);
            (prefix[k + h + 1] - prefix[k - h]) / (2 * h + 1) as f64
        })
        .collect()
}

/// σ of the noise of `despiked` (see the module docs), at least the resolution of `raw`.
fn noise_level(despiked: &[f64], raw: &[f64]) -> f64 {
    let mut second: Vec<f64> = despiked
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs())
        .collect();
    let mad = if second.is_empty() {
        0.0
    } else {
        let middle = second.len() / 2;
        *second.select_nth_unstable_by(middle, f64::total_cmp).1
    };
    (mad / (0.6745 * 6f64.sqrt())).max(resolution(raw) / 12f64.sqrt())
}

/// The smallest step between distinct values (0 with fewer than two).
fn resolution(y: &[f64]) -> f64 {
    let mut sorted: Vec<f64> = y.iter().copied().filter(|v| v.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let step = sorted
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if step.is_finite() { step } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_fit_is_exact_on_a_line() {
        let l = line_fit(&[1.0, 2.0, 3.0], &[5.0, 7.0, 9.0]).unwrap();
        assert_eq!((l.x, l.y, l.slope), (2.0, 7.0, 2.0));
        assert_eq!(l.at_level(5.0), 1.0);
        assert_eq!(l.at_zero(), 3.0);
        assert!(line_fit(&[1.0, 1.0], &[0.0, 1.0]).is_none());
    }

    #[test]
    fn the_running_mean_narrows_at_the_ends() {
        assert_eq!(
            running_mean(&[1.0, 2.0, 3.0, 10.0], 3),
            [1.0, 2.0, 5.0, 10.0]
        );
    }

    #[test]
    fn resolution_and_noise_of_a_quantised_record() {
        let y: Vec<f64> = (0..50).map(|k| (k / 5) as f64 * 0.25).collect();
        assert_eq!(resolution(&y), 0.25);
        assert!((noise_level(&y, &y) - 0.25 / 12f64.sqrt()).abs() < 1e-12);
        assert_eq!(resolution(&[1.0]), 0.0);
    }
}
