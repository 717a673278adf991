//! Preparing a loaded step test for fitting: where and how large the step is, the operating
//! point before it, the window of samples kept, the course notes' low-pass filter, and the
//! measured curve's own step characteristics.
//!
//! - **Step**: [`detect_step`] takes the largest jump of the input column; the instant is the
//!   time of the first sample at the new level. A record that starts with the step (a heater
//!   on from the first row) has no jump inside it: the caller says what the input was before
//!   the record (`initial_input`), and then that initial step is the one reported.
//! - **Operating point**: [`operating_point`] is the mean output before t0, `None` when no
//!   sample is before it. A sample *at* t0 counts as before when the next sample has the same
//!   time (the pre-step row of a log that writes the step instant twice, as TCLab's).
//! - **Window**: [`Window::Samples`] counts samples from 1 and includes both ends, as
//!   MATLAB's `dados(37:313)` in the notes; [`Window::Time`] keeps start ≤ t ≤ end. Times are
//!   not shifted.
//! - **Filter**: [`Ewma`] is the notes' `lowpass(x, Ts, RC)` (Passold, appendix D): RC =
//!   1/(2π fc), α = Ts/(RC + Ts), y[k] = y[k−1] + α(x[k] − y[k−1]) from y[0] = x[0]. It
//!   warns when Ts > RC/5, as the notes do. It delays slow signals by exactly RC: its DC
//!   group delay is (1 − α)/α samples = RC/Ts · Ts.
//! - **Measured characteristics**: [`SampledPieces`] is the measured curve as straight lines
//!   between samples, which are monotone pieces, so [`measured_step_info`] applies the very
//!   definitions of [`degrau_lti::metrics`] (rise, settling, overshoot, peak…), interpolating
//!   crossings between samples; times are relative to t0. [`final_level`] gives a final value.

use serde::{Deserialize, Serialize};

use crate::record::data::{DataNote, MIN_SAMPLES, StepTest};
use crate::stats::mean;
use degrau_lti::metrics::{MonotonePieces, StepInfo, StepInfoOptions};

/// The step found in the input column.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepEdge {
    /// Step instant (s): the time of the first sample at the new level.
    pub t0: f64,
    /// Step size u_after − u_before.
    pub du: f64,
    pub u_before: f64,
    pub u_after: f64,
    /// Index (0-based) of the first sample at the new level.
    pub index: usize,
}

/// Problems with the preparation choices (`crate::words` says them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum PrepareError {
    /// Samples `first` to `last` (1-based, both included) are not within 1 to `count`.
    BadRange {
        first: usize,
        last: usize,
        count: usize,
    },
    TooFewInWindow {
        kept: usize,
        needed: usize,
    },
    /// The window's start (s) is after its end, or one is not a number.
    BadTimeRange {
        start: f64,
        end: f64,
    },
    /// The filter cut-off (Hz) is not a positive number.
    BadCutoff(f64),
    /// The sampling period (s) is not a positive number.
    BadSamplingPeriod(f64),
}

/// The step in the input column: the largest jump between consecutive samples (the earliest
/// of equal ones), or, when `initial_input` (the input before the record) is given and
/// differs from the first sample, the step at the first sample. `None` without an input
/// column or when the input never changes.
pub fn detect_step(test: &StepTest, initial_input: Option<f64>) -> Option<StepEdge> {
    let u = test.input.as_deref()?;
    let (&t_first, &u_first) = (test.time.first()?, u.first()?);
    if let Some(u0) = initial_input.filter(|u0| u0.is_finite() && *u0 != u_first) {
        return Some(StepEdge {
            t0: t_first,
            du: u_first - u0,
            u_before: u0,
            u_after: u_first,
            index: 0,
        });
    }
    let jumps = u
        .windows(2)
        .zip(&test.time[1..])
        .enumerate()
        .map(|(k, (w, &t))| StepEdge {
            t0: t,
            du: w[1] - w[0],
            u_before: w[0],
            u_after: w[1],
            index: k + 1,
        });
    jumps
        .filter(|e| e.du != 0.0)
        .fold(None, |best: Option<StepEdge>, e| match best {
            Some(b) if b.du.abs() >= e.du.abs() => Some(b),
            _ => Some(e),
        })
}

/// The operating point y0: the output at rest before the step, by the rule of
/// [`crate::fit::guess::rest_level`] (the mean of the samples before t0, or the sample at t0 when
/// the record starts with the step); `None` when there is none (the caller then estimates it
/// or types it).
pub fn operating_point(test: &StepTest, t0: f64) -> Option<f64> {
    let (samples, _) = crate::record::timebase::rest_samples(&test.time, t0, test.output.len())?;
    Some(mean(&test.output[..samples]))
}

/// The final level: the mean output over the last `fraction` of the record's duration (at
/// least the last sample), e.g. 0.1 for the last 10 %. `None` for an empty test or a
/// fraction outside (0, 1].
pub fn final_level(test: &StepTest, fraction: f64) -> Option<f64> {
    if !(fraction > 0.0 && fraction <= 1.0) {
        return None;
    }
    let (&first, &last) = (test.time.first()?, test.time.last()?);
    let from = last - fraction * (last - first);
    let start = test
        .time
        .partition_point(|&t| t < from)
        .min(test.time.len() - 1);
    let tail = test.output.get(start..).filter(|v| !v.is_empty())?;
    Some(mean(tail))
}

/// The samples kept for fitting.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Window {
    /// Samples `first` to `last`, counted from 1, both included (MATLAB's `first:last`).
    Samples { first: usize, last: usize },
    /// Samples with start ≤ t ≤ end (s).
    Time { start: f64, end: f64 },
}

/// The test restricted to a window (at least [`MIN_SAMPLES`] samples), with a note.
pub fn apply_window(test: &StepTest, window: Window) -> Result<StepTest, PrepareError> {
    let input_len = test.input.as_ref().map_or(usize::MAX, Vec::len);
    let count = test.time.len().min(test.output.len()).min(input_len);
    let time = &test.time[..count];
    let range = match window {
        Window::Samples { first, last } => {
            if first == 0 || first > last || last > count {
                return Err(PrepareError::BadRange { first, last, count });
            }
            first - 1..last
        }
        Window::Time { start, end } => {
            if start.is_nan() || end.is_nan() || start > end {
                return Err(PrepareError::BadTimeRange { start, end });
            }
            time.partition_point(|&t| t < start)..time.partition_point(|&t| t <= end)
        }
    };
    if range.len() < MIN_SAMPLES {
        return Err(PrepareError::TooFewInWindow {
            kept: range.len(),
            needed: MIN_SAMPLES,
        });
    }
    let mut notes = test.notes.clone();
    notes.push(DataNote::Window {
        first: range.start + 1,
        last: range.end,
        count,
        start: time[range.start],
        end: time[range.end - 1],
    });
    Ok(StepTest {
        time: time[range.clone()].to_vec(),
        output: test.output[range.clone()].to_vec(),
        input: test.input.as_ref().map(|u| u[range.clone()].to_vec()),
        time_name: test.time_name.clone(),
        output_name: test.output_name.clone(),
        input_name: test.input_name.clone(),
        sampling_period: test.sampling_period,
        notes,
    })
}

/// The notes' first-order low-pass (exponentially weighted moving average).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ewma {
    /// Time constant RC = 1/(2π fc) (s).
    pub rc: f64,
    /// Sampling period Ts (s).
    pub ts: f64,
    /// α = Ts/(RC + Ts).
    pub alpha: f64,
}

impl Ewma {
    /// The filter of cut-off `cutoff_hz` for samples `ts` seconds apart, unchecked: see
    /// [`Ewma::try_new`] for values typed by a user.
    pub fn new(cutoff_hz: f64, ts: f64) -> Self {
        Self::from_rc(1.0 / (std::f64::consts::TAU * cutoff_hz), ts)
    }

    /// [`Ewma::new`] with a positive, finite cut-off and sampling period.
    pub fn try_new(cutoff_hz: f64, ts: f64) -> Result<Self, PrepareError> {
        if !(cutoff_hz.is_finite() && cutoff_hz > 0.0) {
            return Err(PrepareError::BadCutoff(cutoff_hz));
        }
        if !(ts.is_finite() && ts > 0.0) {
            return Err(PrepareError::BadSamplingPeriod(ts));
        }
        Ok(Self::new(cutoff_hz, ts))
    }

    /// The filter of time constant `rc` (s).
    pub fn from_rc(rc: f64, ts: f64) -> Self {
        Self {
            rc,
            ts,
            alpha: ts / (rc + ts),
        }
    }

    /// RC/Ts, which the notes expect to be at least 5.
    pub fn ratio(&self) -> f64 {
        self.rc / self.ts
    }

    /// Whether Ts > RC/5: the notes warn that the digital filter then behaves quite
    /// differently from the RC filter it imitates.
    pub fn too_coarse(&self) -> bool {
        self.ts > self.rc / 5.0
    }

    /// The delay the filter adds to slow signals (its group delay at DC), in seconds: RC.
    pub fn lag(&self) -> f64 {
        (1.0 - self.alpha) / self.alpha * self.ts
    }

    /// The filtered signal, started at the first sample.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        let mut y = Vec::with_capacity(x.len());
        let mut last = match x.first() {
            Some(&x0) => x0,
            None => return y,
        };
        for &xk in x {
            last += self.alpha * (xk - last);
            y.push(last);
        }
        y
    }
}

/// A measured curve as straight lines between its samples, from t0 on, times relative to t0.
/// Each segment is monotone, so the samples are the breakpoints of monotone pieces.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledPieces {
    points: Vec<(f64, f64)>,
}

impl SampledPieces {
    /// The samples with t ≥ t0 (both slices cut to the shorter), as (t − t0, y).
    pub fn new(time: &[f64], y: &[f64], t0: f64) -> Self {
        let points = time
            .iter()
            .zip(y)
            .filter(|(t, _)| **t >= t0)
            .map(|(&t, &y)| (t - t0, y))
            .collect();
        Self { points }
    }
}

impl MonotonePieces for SampledPieces {
    fn breakpoints(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// Linear interpolation on segment `i` (its start for a vertical or flat segment).
    fn crossing(&self, i: usize, level: f64) -> f64 {
        let (Some(&(ta, ya)), Some(&(tb, yb))) = (self.points.get(i), self.points.get(i + 1))
        else {
            return f64::NAN;
        };
        if ya == yb || ta == tb {
            return ta;
        }
        ta + (level - ya) / (yb - ya) * (tb - ta)
    }
}

/// The measured response's step characteristics (MATLAB `stepinfo` definitions, as for a
/// model), from y0 towards y_final, over the samples from t0 on; times relative to t0.
pub fn measured_step_info(
    test: &StepTest,
    t0: f64,
    y0: f64,
    y_final: f64,
    options: &StepInfoOptions,
) -> StepInfo {
    let pieces = SampledPieces::new(&test.time, &test.output, t0);
    StepInfo::from_pieces(&pieces, y0, y_final, options)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::timebase::{samples_before, sampling_period};

    fn test_of(time: Vec<f64>, output: Vec<f64>, input: Option<Vec<f64>>) -> StepTest {
        StepTest {
            time,
            output,
            input,
            time_name: "t".into(),
            output_name: "y".into(),
            input_name: None,
            sampling_period: None,
            notes: vec![],
        }
    }

    fn round4(x: f64) -> f64 {
        (x * 1e4).round() / 1e4
    }

    #[test]
    fn ewma_matches_the_notes_numbers() {
        // Passold: RC = 1/(2π·0.6) = 0.2653; Ts = 0.047 → alpha = 0.1505, RC/Ts = 5.6438.
        let f = Ewma::new(0.6, 0.047);
        assert_eq!(round4(f.rc), 0.2653);
        assert_eq!(round4(f.alpha), 0.1505);
        assert_eq!(round4(f.ratio()), 5.6438);
        assert!(!f.too_coarse());
        // Ts = 0.094 → alpha = 0.2617, RC/Ts = 2.8219 (esperado >= 5) and a warning.
        let f = Ewma::new(0.6, 0.094);
        assert_eq!(round4(f.alpha), 0.2617);
        assert_eq!(round4(f.ratio()), 2.8219);
        assert!(f.too_coarse());
        // The notes' other example: fc = 5 Hz, Ts = 1 ms → alpha = 0.0305, RC/Ts = 31.8310.
        let f = Ewma::new(5.0, 1e-3);
        assert_eq!((round4(f.alpha), round4(f.ratio())), (0.0305, 31.831));
    }

    #[test]
    fn ewma_recurrence_starts_at_the_first_sample() {
        let f = Ewma::from_rc(1.0, 1.0); // alpha = 1/2
        assert_eq!(f.apply(&[2.0, 4.0, 4.0, 0.0]), [2.0, 3.0, 3.5, 1.75]);
        assert!(f.apply(&[]).is_empty());
        assert!(Ewma::try_new(0.0, 0.1).is_err());
        assert!(Ewma::try_new(1.0, f64::NAN).is_err());
    }

    #[test]
    fn ewma_dc_group_delay_is_rc() {
        for (fc, ts) in [(0.6, 0.047), (0.6, 0.094), (5.0, 1e-3)] {
            let f = Ewma::new(fc, ts);
            assert!((f.lag() - f.rc).abs() < 1e-12 * f.rc);
            // Phase of H(e^{jωTs}) = α/(1 − (1−α)e^{−jωTs}), differentiated at ω → 0.
            let phase = |w: f64| {
                let (re, im) = (
                    1.0 - (1.0 - f.alpha) * (w * ts).cos(),
                    (1.0 - f.alpha) * (w * ts).sin(),
                );
                -im.atan2(re)
            };
            let h = 1e-6 / ts;
            let delay = -(phase(h) - phase(-h)) / (2.0 * h);
            assert!((delay - f.rc).abs() < 1e-6 * f.rc, "{delay} vs {}", f.rc);
            // A ramp comes out late by RC once the start-up transient has died.
            let x: Vec<f64> = (0..20_000).map(|k| k as f64 * ts).collect();
            let y = f.apply(&x);
            let lag = x[x.len() - 1] - y[y.len() - 1];
            assert!((lag - f.rc).abs() < 1e-9, "{lag} vs {}", f.rc);
        }
    }

    #[test]
    fn largest_jump_is_the_step() {
        let t: Vec<f64> = (0..8).map(f64::from).collect();
        let u = vec![0.0, 0.0, 5.0, 5.0, 2.0, 2.0, 12.0, 12.0];
        let test = test_of(t, vec![0.0; 8], Some(u));
        let e = detect_step(&test, None).unwrap();
        assert_eq!(
            (e.t0, e.du, e.u_before, e.u_after, e.index),
            (6.0, 10.0, 2.0, 12.0, 6)
        );
        // The caller's initial input makes a record that starts at a new level a step at t[0].
        let e = detect_step(&test, Some(-1.0)).unwrap();
        assert_eq!((e.t0, e.du, e.index), (0.0, 1.0, 0));
        // Equal to the first sample: no initial step, the jumps decide.
        assert_eq!(detect_step(&test, Some(0.0)).unwrap().index, 6);
    }

    #[test]
    fn constant_input_has_a_step_only_from_a_given_initial_input() {
        let test = test_of(vec![1.0, 2.0, 3.0], vec![0.0; 3], Some(vec![50.0; 3]));
        assert_eq!(detect_step(&test, None), None);
        let e = detect_step(&test, Some(0.0)).unwrap();
        assert_eq!(
            (e.t0, e.du, e.u_before, e.u_after, e.index),
            (1.0, 50.0, 0.0, 50.0, 0)
        );
        assert_eq!(
            detect_step(&test_of(vec![0.0], vec![0.0], None), Some(0.0)),
            None
        );
    }

    #[test]
    fn operating_point_uses_samples_before_t0_and_a_repeated_edge_row() {
        let test = test_of(vec![0.0, 1.0, 2.0, 3.0], vec![1.0, 3.0, 10.0, 11.0], None);
        assert_eq!(operating_point(&test, 2.0), Some(2.0));
        // A record that starts with the step: the sample at t0 is still at rest.
        assert_eq!(operating_point(&test, 0.0), Some(1.0));
        // A step before the first sample: nothing is known of the rest level.
        assert_eq!(operating_point(&test, -1.0), None);
        // TCLab: t = 0 twice, the first row before the step.
        let tclab = test_of(
            vec![0.0, 0.0, 1.0],
            vec![20.9, 20.9, 21.0],
            Some(vec![0.0, 50.0, 50.0]),
        );
        let e = detect_step(&tclab, None).unwrap();
        assert_eq!((e.t0, e.index), (0.0, 1));
        assert_eq!(samples_before(&tclab.time, e.t0), 1);
        assert_eq!(operating_point(&tclab, e.t0), Some(20.9));
    }

    #[test]
    fn sample_window_counts_from_one_inclusive() {
        // The notes keep samples 37 to 313 of 384: 277 samples, the 37th first.
        let t: Vec<f64> = (0..384).map(|k| k as f64 * 0.047).collect();
        let y: Vec<f64> = (1..=384).map(f64::from).collect();
        let test = test_of(t, y, None);
        let w = apply_window(
            &test,
            Window::Samples {
                first: 37,
                last: 313,
            },
        )
        .unwrap();
        assert_eq!(w.output.len(), 277);
        assert_eq!((w.output[0], w.output[276]), (37.0, 313.0));
        assert_eq!(w.time[0], test.time[36]);
        assert!(matches!(
            w.notes.last(),
            Some(DataNote::Window {
                first: 37,
                last: 313,
                count: 384,
                ..
            })
        ));
        assert!(apply_window(&test, Window::Samples { first: 0, last: 3 }).is_err());
        assert!(
            apply_window(
                &test,
                Window::Samples {
                    first: 10,
                    last: 385
                }
            )
            .is_err()
        );
        assert!(matches!(
            apply_window(&test, Window::Samples { first: 5, last: 6 }),
            Err(PrepareError::TooFewInWindow { kept: 2, .. })
        ));
        let w = apply_window(
            &test,
            Window::Time {
                start: 0.047,
                end: 0.188,
            },
        )
        .unwrap();
        assert_eq!(w.output, [2.0, 3.0, 4.0, 5.0]);
        assert!(
            apply_window(
                &test,
                Window::Time {
                    start: 2.0,
                    end: 1.0
                }
            )
            .is_err()
        );
    }

    #[test]
    fn final_level_averages_the_last_fraction_of_the_duration() {
        let t: Vec<f64> = (0..=10).map(f64::from).collect();
        let y: Vec<f64> = (0..=10).map(f64::from).collect();
        let test = test_of(t, y, None);
        assert_eq!(final_level(&test, 0.2), Some(9.0)); // t = 8, 9, 10
        assert_eq!(final_level(&test, 1e-9), Some(10.0));
        assert_eq!(final_level(&test, 1.0), Some(5.0));
        assert_eq!(final_level(&test, 0.0), None);
        assert_eq!(final_level(&test_of(vec![], vec![], None), 0.1), None);
    }

    #[test]
    fn sampled_pieces_interpolate_and_start_at_t0() {
        let p = SampledPieces::new(&[0.0, 1.0, 2.0, 4.0], &[5.0, 5.0, 7.0, 9.0], 1.0);
        assert_eq!(p.breakpoints(), [(0.0, 5.0), (1.0, 7.0), (3.0, 9.0)]);
        assert_eq!(p.crossing(0, 6.0), 0.5);
        assert_eq!(p.crossing(1, 8.5), 2.5);
        assert!(p.crossing(5, 1.0).is_nan());
        let i = StepInfo::from_pieces(&p, 5.0, 9.0, &StepInfoOptions::default());
        // 10 % (5.4) at 0.2, 90 % (8.6) at 1 + 1.6/2·2 = 2.6.
        assert!((i.rise_start.unwrap() - 0.2).abs() < 1e-12);
        assert!((i.rise_time.unwrap() - 2.4).abs() < 1e-12);
        assert_eq!(i.overshoot, Some(0.0));
    }

    #[test]
    fn sampling_period_is_the_median_step() {
        assert_eq!(sampling_period(&[0.0, 0.0, 1.0, 2.0, 3.5, 4.5]), Some(1.0));
        assert_eq!(sampling_period(&[1.0]), None);
    }
}
