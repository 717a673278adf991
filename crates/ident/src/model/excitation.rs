//! The input of a test as the model sees it: its level before the first change (the
//! operating point u0) and how it moves from there, as a sum of steps (and, with a
//! first-order hold, of ramps), so that the exact response of G(s) to it is a sum of exact
//! step responses ([`degrau_lti::StepResponse::superpose`]).
//!
//! - **The ideal step** ([`Excitation::step`]): Δu at t0, typed by the student (the LECI
//!   case): one step at an exact instant.
//! - **A measured input** ([`Excitation::measured`]): the input column, held between
//!   samples. With a zero-order hold (a logged actuator command) u(t) = u_k on
//!   [t_k, t_{k+1}), so every change between two samples is a step at the sample that first
//!   shows it; with a first-order hold (an analog input that was sampled) u(t) is the
//!   straight line between samples, a sum of ramps whose slope changes at each sample.
//! - **The step instant**: a change first seen at sample k happened in (t_{k−1}, t_k] (a
//!   switch or an actuator not synchronised with the logger). With a zero-order hold the
//!   model may move every change earlier by up to one sampling period ([`Excitation::lead_range`],
//!   the range of the fit's step-instant parameter `Ta`, or of a negative `Td`); a typed step
//!   and a first-order hold have exact instants.
//! - **The changes** ([`InputChange`]): the input's significant jumps, for the plot, the
//!   per-step table and the JSON. A jump is a move of the input when it exceeds eight
//!   times the input's own sample-to-sample noise (the median absolute first difference,
//!   robust to the jumps themselves; at most half the range, for inputs that change at most
//!   samples, as a PRBS); consecutive moves of one sign (a ramped step, a slow actuator
//!   that moves a little at every sample) are one change, at the first sample that shows
//!   it, of their total size, when that total exceeds both 5 % of the input's range and
//!   the noise term.

use serde::{Deserialize, Serialize};

/// How the input moves between its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Hold {
    /// Held at each sample's value until the next (a logged actuator command).
    #[default]
    Zoh,
    /// A straight line from each sample to the next (an analog input that was sampled).
    Foh,
}

/// One component of the input: a step of size `du` at `t` (input units), or, among
/// [`Excitation::ramps`], a change of slope of `du` input units per second at `t`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct InputStep {
    pub t: f64,
    pub du: f64,
}

/// A significant change of the input (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct InputChange {
    /// The instant the model puts it at (s): the first sample that shows the new level (or
    /// the typed t0).
    pub t: f64,
    /// Its size, level after − level before (input units).
    pub du: f64,
    /// The input level before it (input units).
    pub u_before: f64,
    /// The earliest instant it may have happened (s): the previous sample's time; equal to
    /// `t` when the instant is exact.
    pub earliest: f64,
    /// Index (0-based) of the first sample that shows it; `None` for a typed step.
    pub index: Option<usize>,
}

/// The input as the model sees it, relative to its level before the first change.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Excitation {
    /// The input level before the first change (input units); 0 when only Δu is known.
    pub u0: f64,
    pub hold: Hold,
    /// Steps of the input, sorted by instant (input units).
    pub steps: Vec<InputStep>,
    /// Changes of slope (first-order hold), sorted by instant (input units per second).
    pub ramps: Vec<InputStep>,
    /// The significant changes, in order; at least one.
    pub changes: Vec<InputChange>,
    /// How long before its instant each change may have happened (s): 0 for exact instants.
    pub lead_range: f64,
    /// The record's first instant (s), the origin of an initial transient's coefficients;
    /// `None` for a typed step (the first change is the origin).
    #[serde(default)]
    pub start: Option<f64>,
}

/// Share of the input's range a jump must exceed to be a change.
pub const CHANGE_SHARE: f64 = 0.05;
/// Multiple of the input's sample-to-sample noise a jump must exceed to be a change.
pub const CHANGE_NOISE: f64 = 8.0;

impl Excitation {
    /// The ideal step: Δu at t0, an exact instant.
    pub fn step(t0: f64, du: f64) -> Self {
        Self {
            u0: 0.0,
            hold: Hold::Zoh,
            steps: vec![InputStep { t: t0, du }],
            ramps: Vec::new(),
            changes: vec![InputChange {
                t: t0,
                du,
                u_before: 0.0,
                earliest: t0,
                index: None,
            }],
            lead_range: 0.0,
            start: None,
        }
    }

    /// The measured input `u` at instants `time` (ascending, same length), held as `hold`
    /// says. `initial_input` is the input before the record started, when it differs from
    /// the first sample (a heater switched on at the first row): a step at the first sample.
    /// `None` when the input has no significant change (see the module docs).
    pub fn measured(
        time: &[f64],
        u: &[f64],
        initial_input: Option<f64>,
        hold: Hold,
    ) -> Option<Self> {
        let n = time.len().min(u.len());
        let (time, u) = (&time[..n], &u[..n]);
        let (&t_first, &u_first) = (time.first()?, u.first()?);
        let initial = initial_input.filter(|v| v.is_finite() && *v != u_first);
        let u0 = initial.unwrap_or(u_first);
        let mut steps = Vec::new();
        let mut ramps = Vec::new();
        if let Some(before) = initial {
            steps.push(InputStep {
                t: t_first,
                du: u_first - before,
            });
        }
        match hold {
            Hold::Zoh => steps.extend((1..n).filter(|&k| u[k] != u[k - 1]).map(|k| InputStep {
                t: time[k],
                du: u[k] - u[k - 1],
            })),
            Hold::Foh => {
                let mut slope = 0.0;
                for k in 0..n.saturating_sub(1) {
                    let dt = time[k + 1] - time[k];
                    let next = if dt > 0.0 {
                        (u[k + 1] - u[k]) / dt
                    } else {
                        slope
                    };
                    if next != slope {
                        ramps.push(InputStep {
                            t: time[k],
                            du: next - slope,
                        });
                    }
                    slope = next;
                }
                if slope != 0.0 {
                    ramps.push(InputStep {
                        t: time[n - 1],
                        du: -slope,
                    });
                }
            }
        }
        let changes = significant_changes(time, u, initial);
        if changes.is_empty() {
            return None;
        }
        let lead_range = match hold {
            Hold::Zoh => crate::record::timebase::sampling_period(time).unwrap_or(0.0),
            Hold::Foh => 0.0,
        };
        Some(Self {
            u0,
            hold,
            steps,
            ramps,
            changes,
            lead_range,
            start: time.first().copied(),
        })
    }

    /// The instant of the first change (s).
    pub fn t0(&self) -> f64 {
        self.changes.first().map_or(0.0, |c| c.t)
    }

    /// The size of the first change (input units): the step Δu of a single-step test.
    pub fn du(&self) -> f64 {
        self.changes.first().map_or(0.0, |c| c.du)
    }

    /// The largest change by size (the first of equal ones).
    pub fn largest_change(&self) -> Option<&InputChange> {
        self.changes
            .iter()
            .fold(None, |best: Option<&InputChange>, c| match best {
                Some(b) if b.du.abs() >= c.du.abs() => Some(b),
                _ => Some(c),
            })
    }

    /// Whether the input changes more than once.
    pub fn is_multi_step(&self) -> bool {
        self.changes.len() > 1
    }

    /// The input's deviation from u0 at instant `t` (input units), as the model sees it
    /// (no step-instant lead).
    pub fn deviation_at(&self, t: f64) -> f64 {
        let steps: f64 = self
            .steps
            .iter()
            .take_while(|s| s.t <= t)
            .map(|s| s.du)
            .sum();
        let ramps: f64 = self
            .ramps
            .iter()
            .take_while(|s| s.t <= t)
            .map(|s| s.du * (t - s.t))
            .sum();
        steps + ramps
    }

    /// The largest |u(t) − u0| over the record (input units): the input's scale. At least
    /// the size of the largest change; the step's size for an ideal step.
    pub fn du_scale(&self) -> f64 {
        let mut level: f64 = 0.0;
        let mut largest: f64 = 0.0;
        for s in &self.steps {
            level += s.du;
            largest = largest.max(level.abs());
        }
        if !self.ramps.is_empty() {
            let mut slope = 0.0;
            let mut value = 0.0;
            let mut t_last = self.ramps[0].t;
            for r in &self.ramps {
                value += slope * (r.t - t_last);
                largest = largest.max(value.abs());
                slope += r.du;
                t_last = r.t;
            }
        }
        self.changes
            .iter()
            .map(|c| c.du.abs())
            .fold(largest, f64::max)
    }

    /// The same input in other units: instants t ↦ (t − origin)/t_unit, steps divided by
    /// `du_unit`, slopes by du_unit/t_unit.
    pub fn rescaled(&self, origin: f64, t_unit: f64, du_unit: f64) -> Self {
        let time = |t: f64| (t - origin) / t_unit;
        let scaled = |list: &[InputStep], factor: f64| -> Vec<InputStep> {
            list.iter()
                .map(|s| InputStep {
                    t: time(s.t),
                    du: s.du * factor,
                })
                .collect()
        };
        Self {
            u0: self.u0 / du_unit,
            hold: self.hold,
            steps: scaled(&self.steps, 1.0 / du_unit),
            ramps: scaled(&self.ramps, t_unit / du_unit),
            changes: self
                .changes
                .iter()
                .map(|c| InputChange {
                    t: time(c.t),
                    du: c.du / du_unit,
                    u_before: c.u_before / du_unit,
                    earliest: time(c.earliest),
                    index: c.index,
                })
                .collect(),
            lead_range: self.lead_range / t_unit,
            start: self.start.map(time),
        }
    }

    /// The instants of the steps and slope changes, moved by `shift` seconds (the dead time,
    /// less the step-instant lead), as (instant, size) pairs for
    /// [`degrau_lti::StepResponse::superpose`].
    pub fn shifted_steps(&self, shift: f64) -> Vec<(f64, f64)> {
        self.steps.iter().map(|s| (s.t + shift, s.du)).collect()
    }

    /// [`Excitation::shifted_steps`] for the slope changes.
    pub fn shifted_ramps(&self, shift: f64) -> Vec<(f64, f64)> {
        self.ramps.iter().map(|s| (s.t + shift, s.du)).collect()
    }
}

/// The median of |u_k − u_{k−1}| over the samples: the input's own sample-to-sample noise
/// (0 for a clean, piecewise-constant input).
fn difference_noise(u: &[f64]) -> f64 {
    let mut d: Vec<f64> = u.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    if d.is_empty() {
        return 0.0;
    }
    let mid = d.len() / 2;
    *d.select_nth_unstable_by(mid, f64::total_cmp).1
}

/// The significant changes of `u` (see the module docs); with `initial` (the input before
/// the record) differing from the first sample, a change at the first sample first.
fn significant_changes(time: &[f64], u: &[f64], initial: Option<f64>) -> Vec<InputChange> {
    let (lo, hi) = u
        .iter()
        .chain(&initial)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let range = hi - lo;
    let mut changes = Vec::new();
    if !(range > 0.0 && range.is_finite()) {
        return changes;
    }
    // The noise term is capped at half the range: on a short or busy input (a PRBS changes
    // at every other sample) the median difference is a jump itself.
    let moves = (CHANGE_NOISE * difference_noise(u)).min(0.5 * range);
    let threshold = (CHANGE_SHARE * range).max(moves);
    if let Some(before) = initial {
        changes.push(InputChange {
            t: time[0],
            du: u[0] - before,
            u_before: before,
            earliest: time[0],
            index: Some(0),
        });
    }
    let mut k = 1;
    while k < u.len() {
        let jump = u[k] - u[k - 1];
        if jump.abs() <= moves {
            k += 1;
            continue;
        }
        let start = k;
        let mut end = k;
        while end + 1 < u.len() {
            let next = u[end + 1] - u[end];
            if next.abs() > moves && next.signum() == jump.signum() {
                end += 1;
            } else {
                break;
            }
        }
        let du = u[end] - u[start - 1];
        if du.abs() > threshold {
            changes.push(InputChange {
                t: time[start],
                du,
                u_before: u[start - 1],
                earliest: time[start - 1],
                index: Some(start),
            });
        }
        k = end + 1;
    }
    changes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pulse_is_two_changes_and_two_steps() {
        let time: Vec<f64> = (0..10).map(|k| k as f64).collect();
        let u = [1.0, 1.0, 3.0, 3.0, 3.0, 3.0, 1.0, 1.0, 1.0, 1.0];
        let e = Excitation::measured(&time, &u, None, Hold::Zoh).unwrap();
        assert_eq!(e.u0, 1.0);
        assert_eq!(
            e.steps,
            vec![
                InputStep { t: 2.0, du: 2.0 },
                InputStep { t: 6.0, du: -2.0 }
            ]
        );
        assert_eq!(e.changes.len(), 2);
        assert_eq!(
            (e.changes[1].t, e.changes[1].du, e.changes[1].earliest),
            (6.0, -2.0, 5.0)
        );
        assert_eq!(e.lead_range, 1.0);
        assert_eq!(e.du_scale(), 2.0);
        assert_eq!(e.deviation_at(4.5), 2.0);
        assert_eq!(e.deviation_at(6.0), 0.0);
    }

    #[test]
    fn noise_on_the_input_is_not_a_change_and_a_ramped_step_is_one() {
        let time: Vec<f64> = (0..40).map(|k| 0.5 * k as f64).collect();
        let u: Vec<f64> = (0..40)
            .map(|k| {
                let level = match k {
                    0..10 => 2.0,
                    10 => 4.0,
                    11 => 6.0,
                    _ => 7.0,
                };
                level + 0.01 * ((k * 7919) % 13) as f64 / 13.0
            })
            .collect();
        let e = Excitation::measured(&time, &u, None, Hold::Zoh).unwrap();
        assert_eq!(e.changes.len(), 1, "{:?}", e.changes);
        let c = e.changes[0];
        assert_eq!((c.t, c.index, c.earliest), (5.0, Some(10), 4.5));
        assert!((c.du - 5.0).abs() < 0.02);
        // Every sample-to-sample change is still in the model's input.
        assert!(e.steps.len() > 10);
    }

    #[test]
    fn a_slow_ramp_is_one_change_and_jitter_is_none() {
        // 20 → 60 over 50 samples (0.8 a sample, 2 % of the range): one change of 40 at the
        // first sample that moved; a 0.1 back-and-forth on the levels is none.
        let time: Vec<f64> = (0..200).map(|k| k as f64).collect();
        let u: Vec<f64> = (0..200)
            .map(|k| {
                let ramp = (k as f64 - 30.0).clamp(0.0, 50.0) * 0.8;
                20.0 + ramp + if k % 7 == 3 { 0.1 } else { 0.0 }
            })
            .collect();
        let e = Excitation::measured(&time, &u, None, Hold::Zoh).unwrap();
        assert_eq!(e.changes.len(), 1, "{:?}", e.changes);
        let c = e.changes[0];
        assert_eq!((c.t, c.index), (31.0, Some(31)));
        assert!((c.du - 40.0).abs() < 0.2, "{c:?}");
    }

    #[test]
    fn the_input_before_the_record_makes_a_step_at_the_first_sample() {
        let time = [0.0, 1.0, 2.0];
        let u = [50.0, 50.0, 50.0];
        assert_eq!(Excitation::measured(&time, &u, None, Hold::Zoh), None);
        let e = Excitation::measured(&time, &u, Some(0.0), Hold::Zoh).unwrap();
        assert_eq!(e.u0, 0.0);
        assert_eq!(e.steps, vec![InputStep { t: 0.0, du: 50.0 }]);
        assert_eq!(e.changes[0].index, Some(0));
    }

    #[test]
    fn a_first_order_hold_is_the_line_between_samples() {
        let time = [0.0, 1.0, 2.0, 4.0, 5.0];
        let u = [0.0, 0.0, 2.0, 2.0, 1.0];
        let e = Excitation::measured(&time, &u, None, Hold::Foh).unwrap();
        assert!(e.steps.is_empty());
        assert_eq!(e.lead_range, 0.0);
        for (t, want) in [(0.5, 0.0), (1.5, 1.0), (3.0, 2.0), (4.5, 1.5), (6.0, 1.0)] {
            assert!((e.deviation_at(t) - want).abs() < 1e-12, "u({t})");
        }
    }

    #[test]
    fn rescaling_keeps_the_input() {
        let time: Vec<f64> = (0..6).map(|k| 10.0 + 2.0 * k as f64).collect();
        let u = [1.0, 1.0, 5.0, 5.0, 3.0, 3.0];
        let e = Excitation::measured(&time, &u, None, Hold::Foh).unwrap();
        let s = e.rescaled(12.0, 4.0, 2.0);
        for t in [11.0, 15.0, 19.0, 25.0] {
            let inside = s.deviation_at((t - 12.0) / 4.0) * 2.0;
            assert!((inside - e.deviation_at(t)).abs() < 1e-12);
        }
    }
}
