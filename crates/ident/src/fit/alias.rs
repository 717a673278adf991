//! The alias check of a fitted model: an oscillation faster than the sampling can show, or a
//! swing between the samples that straight lines through them do not show (the LECI notes'
//! spurious optimum).

use super::problem::Problem;
use super::report::FitWarning;
use super::setup::{CHUNK, FitData};
use crate::fit::reduce;
use crate::model::scale::Scale;
use crate::model::{Model, Param};

impl Problem {
    /// The alias check of the model at `x`, its frequencies in the data's units.
    pub(super) fn alias(&self, x: &[f64]) -> Option<FitWarning> {
        alias_in(&self.model(x), &self.data, self.ts, self.alias_span)
            .map(|w| frequencies_out(w, &self.units))
    }
}

/// The alias check: an oscillation faster than the sampling can show (ωd ≥ π/Ts), or a
/// model that swings between samples by more than 10 % of the step's effect beyond what
/// straight lines through its own samples show. Computed in the record's internal units;
/// on a long record (one [`reduce`] shrinks) the swing is looked for in the
/// [`reduce::MIN_SAMPLES`] samples after each change reaches the output, where a stable
/// model's response moves fastest.
pub fn alias_warning(model: &Model, data: &FitData) -> Option<FitWarning> {
    let ts = data.sampling_period();
    let units = Scale::of(data, ts)?;
    let span = reduce::reduce(&data.times, &data.input).map(|_| reduce::MIN_SAMPLES);
    alias_in(
        &units.model_in(model),
        &units.data_in(data),
        ts / units.t_unit,
        span,
    )
    .map(|w| frequencies_out(w, &units))
}

/// [`alias_warning`] on a record and model in the same units, sampled every `ts`, the swing
/// looked for in `span` samples after each change (`None`: everywhere).
pub(super) fn alias_in(
    model: &Model,
    data: &FitData,
    ts: f64,
    span: Option<usize>,
) -> Option<FitWarning> {
    let nyquist = std::f64::consts::PI / ts;
    let omega_d = model.damped_frequency().unwrap_or(0.0);
    let effect = (model.get(Param::Kp) * data.input.du_scale())
        .abs()
        .max(f64::MIN_POSITIVE);
    let n = data.times.len();
    let spans = match span {
        Some(len) => alias_spans(data, model.input_shift(), settled_within(model, ts, len)),
        None => vec![(0, n.saturating_sub(1))],
    };
    let between = spans
        .iter()
        .map(|&span| between_sample_swing(model, data, ts, span))
        .fold(0.0, f64::max)
        / effect;
    (omega_d >= nyquist || between > 0.1).then_some(FitWarning::Alias {
        omega_d,
        nyquist,
        between_samples: between,
    })
}

/// The samples after a change the swing is looked for in: at most `len`, and no further
/// than the model's 2 % settling time (sampled every `ts`), after which each change's part
/// of the response stays within 2 % of its effect, so that it swings between samples by at
/// most 4 % of it, under the check's 10 %.
pub(super) fn settled_within(model: &Model, ts: f64, len: usize) -> usize {
    let settled = model
        .settling()
        .filter(|t| t.is_finite() && *t > 0.0)
        .map(|t| (t / ts).ceil() + 2.0);
    match settled {
        Some(samples) if samples < len as f64 => samples as usize,
        _ => len,
    }
}

/// The spans of sample indices (first, last) from the sample before each change reaches
/// the output (its instant moved by `shift`) to `len` samples after, overlapping ones merged.
fn alias_spans(data: &FitData, shift: f64, len: usize) -> Vec<(usize, usize)> {
    let t = &data.times;
    let last = t.len().saturating_sub(1);
    let mut spans: Vec<(usize, usize)> = Vec::new();
    for c in &data.input.changes {
        let a = t.partition_point(|&s| s < c.t + shift).saturating_sub(1);
        let b = (a + len).min(last);
        match spans.last_mut() {
            Some(prev) if a <= prev.1 => prev.1 = prev.1.max(b),
            _ => spans.push((a, b)),
        }
    }
    spans
}

/// An alias warning's frequencies (rad per internal time unit) in rad/s.
fn frequencies_out(w: FitWarning, units: &Scale) -> FitWarning {
    match w {
        FitWarning::Alias {
            omega_d,
            nyquist,
            between_samples,
        } => FitWarning::Alias {
            omega_d: omega_d / units.t_unit,
            nyquist: nyquist / units.t_unit,
            between_samples,
        },
        other => other,
    }
}

/// An interval between kept samples longer than this many sampling periods is a gap where
/// samples were left out, not a sampling interval.
const GAP: f64 = 1.5;

/// The largest distance between the model on a 16× finer grid and the straight lines
/// through the model's values at the sample instants, over the windows between samples
/// `first` and `last` that end after the step; evaluated a piece of the record at a time.
pub(super) fn between_sample_swing(
    model: &Model,
    data: &FitData,
    ts: f64,
    (first, last): (usize, usize),
) -> f64 {
    const REFINE: usize = 16;
    let t = &data.times;
    let Ok(simulator) = model.simulator(&data.input) else {
        return 0.0;
    };
    let windows = last.min(t.len().saturating_sub(1));
    let per_piece = CHUNK / REFINE;
    let (mut fine, mut values) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for start in (first..windows).step_by(per_piece) {
        let end = (start + per_piece).min(windows);
        fine.clear();
        if let Some((a, b)) = crate::model::uniform_grid(&t[start..=end]) {
            // Evenly spaced by construction, so the fast recurrence evaluates it.
            let m = REFINE * (end - start);
            fine.extend((0..=m).map(|j| a + (b - a) * j as f64 / m as f64));
        } else {
            for i in start..end {
                let (a, b) = (t[i], t[i + 1]);
                fine.extend((0..REFINE).map(|k| a + (b - a) * k as f64 / REFINE as f64));
            }
            fine.push(t[end]);
        }
        values.resize(fine.len(), 0.0);
        simulator.fill(&fine, &mut values);
        for (w, i) in (start..end).enumerate() {
            // Before the response, or across a gap where samples were left out (outliers,
            // a clipped span): not a sampling interval.
            if t[i + 1] <= data.input.t0() || t[i + 1] - t[i] > GAP * ts {
                continue;
            }
            let (ya, yb) = (values[w * REFINE], values[(w + 1) * REFINE]);
            for k in 1..REFINE {
                let line = ya + k as f64 / REFINE as f64 * (yb - ya);
                worst = worst.max((values[w * REFINE + k] - line).abs());
            }
        }
    }
    worst
}
