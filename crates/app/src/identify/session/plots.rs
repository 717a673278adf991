//! The data the Identify mode's plots draw, derived from the session: the measured samples,
//! the model curve and the residuals with their ranges ([`Plots`], recomputed only when the
//! data or the shown model changed), the plot's frame (the axes held while a handle is
//! dragged, or the curves' own), what the guess handles act on ([`HandleFrame`],
//! [`Segment`]) and the nearest sample to a time.

use degrau_ident::fit::FitData;
use degrau_ident::fit::handles::{self, Handle};
use degrau_ident::model::excitation::{Excitation, InputChange};
use degrau_ident::model::{Model, Param};
use degrau_lti::{StepInfo, StepInfoOptions};

use super::super::commands::Frozen;
use super::super::steps::InputPlot;
use super::Session;

/// Points of the model curve drawn over the record.
const CURVE_POINTS: usize = 800;

/// The plots' data, derived from the session.
#[derive(Debug, Clone, Default)]
pub struct Plots {
    /// The samples the fit sees, (t, y).
    pub measured: Vec<[f64; 2]>,
    /// The model shown over the record, (t, ŷ).
    pub model: Vec<[f64; 2]>,
    /// y − ŷ at each sample.
    pub residuals: Vec<[f64; 2]>,
    /// The measured curve's step characteristics.
    pub info: Option<StepInfo>,
    /// What the noise explains of a sample's excursion: √(2 ln N)·σ, the largest of N
    /// Gaussian samples, σ read from the first differences (robust; output units). A
    /// measured overshoot within it is noise.
    pub noise_band: f64,
    /// The time the record spans.
    pub t_range: (f64, f64),
    /// The y range of the current curves (measured and model) only.
    pub y_range: (f64, f64),
    /// The residuals' range (with zero).
    pub residual_range: (f64, f64),
}

impl Plots {
    /// Whether the measured overshoot is within what the noise explains ([`Plots::noise_band`]):
    /// read off raw samples, a heater that does not overshoot read 13.7 % or 16.9 % as the
    /// model changed.
    pub fn overshoot_is_noise(&self) -> bool {
        let Some(info) = &self.info else { return false };
        let (Some(os), Some(y_final)) = (info.overshoot, info.steady_state) else {
            return false;
        };
        os / 100.0 * (y_final - info.initial_value).abs() <= self.noise_band
    }
}

impl Session {
    /// Recomputes the plots' data when the data or the shown model changed.
    pub(super) fn refresh_plots(&mut self) {
        let data = self.loaded.as_ref().and_then(|l| match &l.data {
            Ok(d) => Some((d, &l.experiment)),
            Err(_) => None,
        });
        self.hand
            .refresh(data, self.data_revision, self.waker.clone());
        let shown = self.shown_model();
        let y0 = self.held_operating_point();
        let key = (self.data_revision, shown, y0);
        if self.plots_key.is_some_and(|k| same_key(&k, &key)) {
            return;
        }
        self.plots_key = Some(key);
        self.plots = match self.loaded.as_ref().map(|l| (&l.data, l)) {
            Some((Ok(data), l)) => plots_for(data, shown, y0.unwrap_or(l.guess.get(Param::Y0))),
            _ => Plots::default(),
        };
    }

    /// The measured sample nearest in time to `t`, (t, y).
    pub fn nearest_sample(&self, t: f64) -> Option<[f64; 2]> {
        nearest(&self.plots.measured, t)
    }

    /// The shown model's exact value at `t`.
    pub fn model_value(&self, t: f64) -> Option<f64> {
        let model = self.shown_model()?;
        let setup = self.setup()?;
        model.simulate(&setup, &[t]).ok()?.first().copied()
    }

    /// The residual at the sample nearest in time to `t`, (t, y − ŷ).
    pub fn nearest_residual(&self, t: f64) -> Option<[f64; 2]> {
        nearest(&self.plots.residuals, t)
    }

    /// The input plot's data (rebuilt with the fit data).
    pub fn input_plot(&self) -> &InputPlot {
        &self.input_plot
    }

    /// The plots' data (recomputed by [`Session::apply`] and [`Session::poll`] when an input
    /// changed).
    pub fn plots(&self) -> &Plots {
        &self.plots
    }

    /// The axes the main plot shows: held while a handle is dragged, else the curves'.
    pub fn plot_frame(&self) -> Frozen {
        self.frozen.unwrap_or(Frozen {
            t: self.plots.t_range,
            y: self.plots.y_range,
        })
    }

    /// What the guess handles act on: the shown model on the whole input, or, on a
    /// multi-step record, on the largest change's segment (see [`HandleFrame`]).
    pub fn handle_frame(&self) -> Option<HandleFrame> {
        let (model, input, t_end) = (self.shown_model()?, self.setup()?, self.t_end()?);
        let segment = largest_segment(&model, &input, &self.input_plot);
        Some(HandleFrame {
            model,
            input,
            t_end,
            segment,
        })
    }
}

/// What the guess handles act on. On a record with one change, the shown model on the whole
/// input. On a multi-step record, the handles apply to the largest change's segment (from
/// it to the next change): the final-value handle sits at the segment's end on the whole
/// model (Kp scales every change alike, so it is exact), the dead-time, time-constant and
/// peak handles read and set the model as one step of that change from the level the model
/// stands at when it comes (exact when the earlier changes have settled by then).
#[derive(Debug, Clone)]
pub struct HandleFrame {
    pub model: Model,
    pub input: Excitation,
    pub t_end: f64,
    pub segment: Option<Segment>,
}

/// The largest change's segment, as one step.
#[derive(Debug, Clone)]
pub struct Segment {
    /// Index (0-based) of the change.
    pub index: usize,
    pub change: InputChange,
    /// The shown model as one step of the change: Y0 at the model's level at the change,
    /// no drift or initial transient.
    pub model: Model,
    pub input: Excitation,
    /// The segment's end (s).
    pub t_end: f64,
}

/// Parameters that belong to the whole record, not to one change's step.
const RECORD_PARAMS: [Param; 5] = [Param::Y0, Param::Drift, Param::X1, Param::X2, Param::X3];

impl HandleFrame {
    /// The handles offered.
    pub fn handles(&self) -> Vec<Handle> {
        handles::handles(&self.model)
    }

    /// Where `handle` sits (t, y).
    pub fn position(&self, handle: Handle) -> Option<(f64, f64)> {
        match (&self.segment, handle) {
            (None, _) => handles::position(&self.model, &self.input, self.t_end, handle),
            (Some(s), Handle::FinalValue) => {
                handles::position(&self.model, &self.input, s.t_end, handle)
            }
            (Some(s), _) => handles::position(&s.model, &s.input, s.t_end, handle),
        }
    }

    /// The shown model after dragging `handle` to `to`.
    pub fn drag(&self, handle: Handle, to: (f64, f64)) -> Model {
        match (&self.segment, handle) {
            (None, _) => handles::drag(&self.model, &self.input, self.t_end, handle, to),
            (Some(s), Handle::FinalValue) => {
                handles::drag(&self.model, &self.input, s.t_end, handle, to)
            }
            (Some(s), _) => {
                let moved = handles::drag(&s.model, &s.input, s.t_end, handle, to);
                let mut m = self.model;
                for p in m.structure.params() {
                    if !RECORD_PARAMS.contains(&p) {
                        m.values.set(p, moved.get(p));
                    }
                }
                m
            }
        }
    }
}

/// The largest change's segment of a multi-step input (none for one change).
fn largest_segment(model: &Model, input: &Excitation, plot: &InputPlot) -> Option<Segment> {
    if !input.is_multi_step() {
        return None;
    }
    let change = *input.largest_change()?;
    let index = input.changes.iter().position(|c| *c == change)?;
    let t_end = plot.spans.get(index)?.1;
    let level = *model.simulate(input, &[change.t]).ok()?.first()?;
    let mut one = *model;
    for p in RECORD_PARAMS {
        one.values.set(p, 0.0);
    }
    one.values.set(Param::Y0, level);
    let mut step = Excitation::step(change.t, change.du);
    step.u0 = change.u_before;
    Some(Segment {
        index,
        change,
        model: one,
        input: step,
        t_end,
    })
}

/// Keys compared bit for bit (a NaN in a model is still "the same model").
fn same_key(a: &(u64, Option<Model>, Option<f64>), b: &(u64, Option<Model>, Option<f64>)) -> bool {
    let bits = |x: Option<f64>| x.map(f64::to_bits);
    a.0 == b.0 && a.1 == b.1 && bits(a.2) == bits(b.2)
}

/// The plots' data for `data` and the model shown; `y0` is the measured curve's start level.
fn plots_for(data: &FitData, model: Option<Model>, y0: f64) -> Plots {
    let setup = &data.input;
    let measured: Vec<[f64; 2]> = data
        .times
        .iter()
        .zip(&data.y)
        .map(|(t, y)| [*t, *y])
        .collect();
    let t_start = data.times.first().copied().unwrap_or(0.0);
    let t_end = data.times.last().copied().unwrap_or(setup.t0());
    let fine: Vec<f64> = (0..=CURVE_POINTS)
        .map(|k| t_start + (t_end - t_start) * k as f64 / CURVE_POINTS as f64)
        .collect();
    let curve: Vec<[f64; 2]> = model
        .and_then(|m| m.simulate(setup, &fine).ok())
        .map(|c| fine.iter().zip(c).map(|(t, y)| [*t, y]).collect())
        .unwrap_or_default();
    let residuals: Vec<[f64; 2]> = model
        .and_then(|m| m.simulate(setup, &data.times).ok())
        .map(|yhat| {
            measured
                .iter()
                .zip(yhat)
                .map(|(p, m)| [p[0], p[1] - m])
                .collect()
        })
        .unwrap_or_default();
    let y_final = degrau_ident::fit::guess::features(data, Some(y0)).y_final;
    let pieces =
        degrau_ident::record::prepare::SampledPieces::new(&data.times, &data.y, setup.t0());
    let info = StepInfo::from_pieces(&pieces, y0, y_final, &StepInfoOptions::default());
    // The markers are drawn on a single step, where the first differences read the noise
    // (robust to the step itself) whatever the model shown: a poor guess's residuals would
    // call a real overshoot noise.
    let sigma = degrau_ident::fit::rest::difference_noise(&data.y);
    let noise_band = sigma * degrau_ident::stats::largest_of_gaussians(data.y.len());
    let y_range = padded(range_of(measured.iter().chain(&curve).map(|p| p[1])));
    let residual_range = padded(range_of(
        residuals.iter().map(|p| p[1]).chain(std::iter::once(0.0)),
    ));
    Plots {
        measured,
        model: curve,
        residuals,
        info: Some(info),
        noise_band,
        t_range: (t_start, t_end.max(t_start + f64::EPSILON)),
        y_range,
        residual_range,
    }
}

/// The smallest and largest finite value (0, 1 when there is none).
pub(super) fn range_of(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo <= hi { (lo, hi) } else { (0.0, 1.0) }
}

/// A range with 5 % room on each side (a flat range gets room of its own size).
pub(super) fn padded(range: (f64, f64)) -> (f64, f64) {
    padded_by(range, 0.05)
}

/// A range with `share` of its span as room on each side (a flat range gets room of its
/// own size).
pub(crate) fn padded_by((lo, hi): (f64, f64), share: f64) -> (f64, f64) {
    let span = hi - lo;
    let room = if span > 0.0 {
        share * span
    } else {
        share * lo.abs().max(1.0)
    };
    (lo - room, hi + room)
}

/// The point of sorted `points` nearest in t (of equal times, the first).
pub(super) fn nearest(points: &[[f64; 2]], t: f64) -> Option<[f64; 2]> {
    nearest_from(points, t, points.partition_point(|p| p[0] < t))
}

/// The point of a polyline nearest in time to `t` (the last of equal times: the level after
/// a jump).
pub(crate) fn nearest_point(points: &[[f64; 2]], t: f64) -> Option<[f64; 2]> {
    nearest_from(points, t, points.partition_point(|p| p[0] <= t))
}

/// The nearer to `t` of `points[k − 1]` and `points[k]`, `k` the partition point around t.
pub(crate) fn nearest_from(points: &[[f64; 2]], t: f64, k: usize) -> Option<[f64; 2]> {
    [k.checked_sub(1), Some(k)]
        .into_iter()
        .flatten()
        .filter_map(|i| points.get(i))
        .min_by(|a, b| (a[0] - t).abs().total_cmp(&(b[0] - t).abs()))
        .copied()
}
