//! `imperfect_step`: the measured input ramps, overshoots or wobbles instead of stepping
//! (the notes: "o degrau não é perfeito (constante de tempo de válvulas, rampa na
//! aceleração de motores etc)"). Read from the input as [`Excitation`] holds it (its
//! `steps`/`ramps` evaluated at the samples, its `changes`); a typed ideal step has nothing
//! to read.
//!
//! For each measured change, over the samples up to the next change of the test (a
//! wobbling actuator jumps several times for one change: see [`windows`]): the settled
//! level is the median of the window's last half, and a band of ± max(5 % of Δu, 3σ) about
//! it (σ the input's own noise from its first differences) says what counts as a departure.
//! - **wobble**: after first reaching the band, the input leaves it on alternate sides at
//!   least twice (up, down, up): an ideal-step model would take the output's answer for an
//!   **oscillation**;
//! - **overshoot**: it goes past the band in the change's direction: an overshooting input
//!   makes the output overshoot as a **zero** would;
//! - **ramp**: from the first sample that shows the change to the first in the band takes
//!   D ≥ two sampling periods (a step between two samples is in the band at once, however
//!   long the gap a stretch left out made before it). A ramp of
//!   duration D is the step through a moving average of length D: it delays the response
//!   by D/2 on average and spreads it by D/√12. An ideal-step model takes it for a **dead
//!   time** of about D/2 while that spread is under a sampling period (D < √12·h), for an
//!   **extra pole** (a lag) beyond.
//!
//! The first change that departs is reported. The fit already uses the measured input, so
//! nothing is mistaken. A change's samples are found from its instant, not from the index
//! it had in the record the input was measured on: the record read here may have samples
//! left out (outliers, a clipped span, a window), and a window read past the next change
//! took a staircase's next level for an overshoot. Cost: O(n + input steps).

use crate::diagnose::cause::Cause;
use crate::fit::FitData;
use crate::fit::rest::difference_noise;
use crate::model::excitation::{Excitation, InputChange};

use crate::stats::median;

use super::{Handling, StepShape, TestCause, TestCauseKind, TestEvidence};

/// Share of a change's size the input must depart from its settled level by.
const BAND_SHARE: f64 = 0.05;
/// Multiple of the input's own noise it must depart by.
const BAND_NOISE: f64 = 3.0;
/// The fewest samples in a change's window worth reading.
const MIN_WINDOW: usize = 6;
/// Samples the input must hold still for before a later change starts a window of its own.
const MIN_HOLD: usize = 5;
/// A later change at least this share of an earlier one's size is a change of the test.
const SAME_SIZE: f64 = 0.9;
/// Sampling periods between the samples about a change beyond which samples were left out
/// there (outliers, a clipped span): the change's shape is not in the record, and it is
/// not judged.
const GAP: f64 = 1.5;

/// The input's level u(t) at each of `times` (ascending), as `input` holds it: u0 plus its
/// steps and ramps up to each instant. O(n + steps + ramps).
pub fn input_at(input: &Excitation, times: &[f64]) -> Vec<f64> {
    let (mut si, mut level) = (0, input.u0);
    let (mut ri, mut slope, mut ramped, mut t_knot) = (0, 0.0, 0.0, None::<f64>);
    times
        .iter()
        .map(|&t| {
            while let Some(s) = input.steps.get(si).filter(|s| s.t <= t) {
                level += s.du;
                si += 1;
            }
            while let Some(r) = input.ramps.get(ri).filter(|r| r.t <= t) {
                ramped += t_knot.map_or(0.0, |k| slope * (r.t - k));
                slope += r.du;
                t_knot = Some(r.t);
                ri += 1;
            }
            level + t_knot.map_or(0.0, |k| ramped + slope * (t - k))
        })
        .collect()
}

/// `imperfect_step` on a record's measured input (see the module docs).
pub fn imperfect_step(data: &FitData) -> Option<TestCause> {
    let u = input_at(&data.input, &data.times);
    let h = data.sampling_period();
    let noise = difference_noise(&u);
    windows(&data.times, &u, &data.input.changes, noise)
        .into_iter()
        .find_map(|(c, end)| departure(&data.times, &u, c, end, noise, h))
}

/// The sample of `times` that first shows change `c`: the first at or after its instant
/// (`times.len()` when it comes after the last). Read from the instant, not from the
/// change's `index`, which counts the samples of the record the input was measured on:
/// the samples left out since (outliers, a clipped span, a disturbance's window) shift it.
/// `None` for a typed step, which has no measured samples to read.
fn first_sample(times: &[f64], c: &InputChange) -> Option<usize> {
    c.index?;
    Some(times.partition_point(|&t| t < c.t))
}

/// Each change with the end of its window (exclusive sample index). A wobbling or
/// overshooting actuator makes several significant jumps for one change: a later change
/// belongs to the earlier one's window while the input has not held still for
/// [`MIN_HOLD`] samples before it and it is smaller than the earlier change (a PRBS, whose
/// changes are all of one size, keeps one window per change).
fn windows<'c>(
    times: &[f64],
    u: &[f64],
    changes: &'c [InputChange],
    noise: f64,
) -> Vec<(&'c InputChange, usize)> {
    let mut out = Vec::new();
    let mut k = 0;
    while let Some(c) = changes.get(k) {
        let band = band(c, noise);
        let mut j = k + 1;
        while let Some(next) = changes.get(j) {
            let Some(i) = first_sample(times, next).map(|i| i.min(u.len())) else {
                break;
            };
            let held = i >= MIN_HOLD && {
                let before = &u[i - MIN_HOLD..i];
                let level = median(before);
                before.iter().all(|v| (v - level).abs() <= band)
            };
            if held || next.du.abs() >= SAME_SIZE * c.du.abs() {
                break;
            }
            j += 1;
        }
        let end = changes
            .get(j)
            .and_then(|n| first_sample(times, n))
            .map_or(u.len(), |i| i.min(u.len()));
        out.push((c, end));
        k = j;
    }
    out
}

/// What counts as a departure from a change's settled level (input units).
fn band(c: &InputChange, noise: f64) -> f64 {
    (BAND_SHARE * c.du.abs()).max(BAND_NOISE * noise)
}

/// How change `c` (window up to sample `end`) departed from a step, if it did.
fn departure(
    times: &[f64],
    u: &[f64],
    c: &InputChange,
    end: usize,
    noise: f64,
    h: f64,
) -> Option<TestCause> {
    let first = first_sample(times, c).filter(|&i| i >= 1)?;
    let end = end.min(u.len()).min(times.len());
    if end < first + MIN_WINDOW || times[first] - times[first - 1] > GAP * h {
        return None;
    }
    let window = &u[first..end];
    let settled = median(&window[window.len() / 2..]);
    let band = band(c, noise);
    // Signed departure from the settled level, positive beyond it in the change's direction.
    let beyond = |v: f64| (v - settled) * c.du.signum();
    let reach = window.iter().position(|&v| beyond(v).abs() <= band)?;
    let (alternations, last_out, widest) = excursions(&window[reach..], band, &beyond);
    let t_start = times[first - 1];
    let t_at = |i: usize| times[first + i];
    let overshoot = window.iter().map(|&v| beyond(v)).fold(0.0, f64::max);
    let (shape, mistaken_for, t_end) = if alternations >= 2 {
        let t_end = t_at(reach + last_out.unwrap_or(0));
        (
            StepShape::Wobble { amplitude: widest },
            Cause::Oscillation,
            t_end,
        )
    } else if overshoot > band {
        let last = window.iter().rposition(|&v| beyond(v) > band).unwrap_or(0);
        let fraction = overshoot / c.du.abs();
        (StepShape::Overshoot { fraction }, Cause::Zero, t_at(last))
    } else {
        // From the first sample that shows the change (a step between two samples takes
        // the period between them, however long a stretch left out made it).
        let duration = t_at(reach) - t_at(0);
        if duration < 2.0 * h {
            return None;
        }
        let lag = duration / 12f64.sqrt() >= h;
        let cause = if lag {
            Cause::ExtraPole
        } else {
            Cause::DeadTime
        };
        (StepShape::Ramp { duration }, cause, t_at(reach))
    };
    Some(TestCause {
        kind: TestCauseKind::ImperfectStep,
        evidence: TestEvidence::ImperfectStep {
            shape,
            mistaken_for: Some(mistaken_for),
        },
        interval: Some((t_start, t_end)),
        handling: Handling::MeasuredInput,
    })
}

/// Over `after` (the samples from the first in the band on): how many times the input
/// left the band on the other side from its previous exit, the index of the last sample
/// outside it, and the widest departure (input units).
fn excursions(
    after: &[f64],
    band: f64,
    beyond: &dyn Fn(f64) -> f64,
) -> (usize, Option<usize>, f64) {
    let mut side = 0.0;
    let mut alternations = 0;
    let mut last_out = None;
    let mut widest: f64 = 0.0;
    for (i, &v) in after.iter().enumerate() {
        let d = beyond(v);
        widest = widest.max(d.abs());
        if d.abs() > band {
            last_out = Some(i);
            if side != 0.0 && d.signum() != side {
                alternations += 1;
            }
            side = d.signum();
        }
    }
    (alternations, last_out, widest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::test_causes::testing::{Messy, Shape, messy};

    fn found(shape: Shape) -> Option<TestCause> {
        let m = messy(Messy {
            shape,
            ..Messy::default()
        });
        imperfect_step(&m.data)
    }

    #[test]
    fn the_input_is_read_back_at_the_samples() {
        let m = messy(Messy {
            shape: Shape::Ramp(6.0),
            ..Messy::default()
        });
        let read = input_at(&m.data.input, &m.data.times);
        assert_eq!(read.len(), m.u.len());
        assert!(read.iter().zip(&m.u).all(|(a, b)| (a - b).abs() < 1e-12));
    }

    #[test]
    fn an_ideal_step_between_samples_is_quiet() {
        assert_eq!(found(Shape::Ideal), None);
        // A typed step has no measured input to read.
        let mut m = messy(Messy::default());
        m.data.input = Excitation::step(40.37, 10.0);
        assert_eq!(imperfect_step(&m.data), None);
    }

    #[test]
    fn a_ramp_is_a_dead_time_when_short_and_a_lag_when_long() {
        for (d, expected) in [(3.0, Cause::DeadTime), (12.0, Cause::ExtraPole)] {
            let cause = found(Shape::Ramp(d)).expect("a ramp is named");
            let TestEvidence::ImperfectStep {
                shape: StepShape::Ramp { duration },
                mistaken_for,
            } = cause.evidence
            else {
                panic!("{cause:?}")
            };
            // Read from the samples: within a sampling period of the truth.
            assert!((duration - d).abs() <= 1.05, "{duration} for {d}");
            assert_eq!(mistaken_for, Some(expected));
            let (a, b) = cause.interval.unwrap();
            assert!(a < 40.37 && b > 40.37 + d - 1.05, "{a} {b}");
        }
    }

    /// A staircase (0 → 10 → 15 about u0) read on the samples left after outliers or a
    /// clipped span were left out: the changes' `index` counts the whole record's samples,
    /// so the first change's window ran past the second into the next level and read it as
    /// an overshoot of 50 % (issue 21, on a clean 10⁶-sample record); with the last samples
    /// left out it ran past the record's end (the panic of a 200-sample PRBS).
    #[test]
    fn a_staircase_with_samples_left_out_is_no_overshoot_and_no_panic() {
        let m = messy(Messy {
            steps: vec![(40.37, 10.0, 1.2), (160.6, 5.0, 1.2)],
            ..Messy::default()
        });
        assert_eq!(imperfect_step(&m.data), None);
        for left_out in [5..30, 60..90, 100..150, 270..300, 150..161, 10..158] {
            let keep: Vec<bool> = (0..m.data.y.len())
                .map(|i| !left_out.contains(&i))
                .collect();
            let kept = m.data.keeping(&keep);
            assert_eq!(imperfect_step(&kept), None, "{left_out:?}");
        }
    }

    #[test]
    fn an_overshoot_is_a_zero_and_a_wobble_an_oscillation() {
        let over = found(Shape::Overshoot {
            fraction: 0.4,
            decay: 5.0,
        })
        .expect("an overshoot is named");
        let TestEvidence::ImperfectStep {
            shape: StepShape::Overshoot { fraction },
            mistaken_for,
        } = over.evidence
        else {
            panic!("{over:?}")
        };
        assert!((0.25..=0.4).contains(&fraction), "{fraction}");
        assert_eq!(mistaken_for, Some(Cause::Zero));
        let wobble = found(Shape::Wobble {
            amplitude: 0.2,
            period: 8.0,
        })
        .expect("a wobble is named");
        let TestEvidence::ImperfectStep {
            shape: StepShape::Wobble { amplitude },
            mistaken_for,
        } = wobble.evidence
        else {
            panic!("{wobble:?}")
        };
        assert!((1.5..=2.0).contains(&amplitude), "{amplitude}");
        assert_eq!(mistaken_for, Some(Cause::Oscillation));
    }
}
