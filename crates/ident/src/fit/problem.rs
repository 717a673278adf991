//! The least-squares problem of a process model on a record, in the record's internal units
//! ([`Scale`]): the free parameters, their bounds and typical sizes, the residuals y − ŷ a
//! piece of [`CHUNK`] samples at a time (weighted on a reduced record), and the normal
//! equations from a Jacobian whose columns are exact where the model is linear in a
//! parameter (offset, gain, drift, the initial transient's coefficients) and forward
//! differences of simulations elsewhere.

use nalgebra::{DMatrix, DVector};

use super::setup::{CHUNK, FitData, FitError, bounds_with};
use super::solver::{LeastSquaresProblem, Normal};
use crate::fit::reduce::Reduction;
use crate::model::scale::{Scale, Unrepresentable};
use crate::model::{Model, ModelError, Param, Simulator, Structure, Values};
use crate::random::Lcg;

/// One column of a finite-difference Jacobian: the point moved along it, and the step's
/// length in the column's parameter.
pub(super) struct Direction {
    pub(super) moved: Vec<f64>,
    pub(super) h: f64,
    pub(super) column: Column,
}

/// How a Jacobian column is had.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Column {
    /// The difference of the residuals at the moved point, over its step.
    Difference,
    /// The operating point Y0: ŷ moves one for one with it, so the residuals' column is
    /// −1 (−√w with weights), without a simulation.
    Offset,
    /// The gain Kp (≠ 0): the forced response is proportional to it and nothing else is,
    /// so the column is −(ŷ − Y0 − drift − transient)/Kp, read off the residuals.
    Gain(f64),
    /// The drift: ŷ moves by (t − t₀) per unit.
    Drift,
    /// A coefficient of the initial transient (X1 at 0…): ŷ is linear in it, and its column
    /// is the transient's basis function ([`Simulator::transient_basis`]).
    Transient(usize),
}

/// The least-squares problem in the free parameters, on the record in internal units.
pub(super) struct Problem {
    /// The record in internal units.
    pub(super) data: FitData,
    pub(super) units: Scale,
    /// Median sampling period (internal units).
    pub(super) ts: f64,
    pub(super) structure: Structure,
    pub(super) params: Vec<Param>,
    pub(super) lower: Vec<f64>,
    pub(super) upper: Vec<f64>,
    /// Typical magnitudes, for finite-difference steps (internal units).
    pub(super) typical: Vec<f64>,
    /// The guess, with the values of the parameters that are not estimated (e.g. a fixed Y0),
    /// in internal units.
    pub(super) fixed: Values,
    /// √weight of each sample on a reduced record (a block mean: see [`reduce`](crate::fit::reduce)); `None`:
    /// every sample counts once.
    pub(super) root_weights: Option<Vec<f64>>,
    /// The record's scatter within the blocks of a reduced record ([`Reduction::within`]),
    /// added to every sum of squares so that it is the record's; 0 otherwise.
    pub(super) within: f64,
    /// On a long record, the alias check looks at this many samples after each input
    /// change reaches the output (see [`alias_spans`](super::alias)); `None`: the whole record.
    pub(super) alias_span: Option<usize>,
}
impl Problem {
    pub(super) fn new(
        data: &FitData,
        structure: Structure,
        guess: Values,
    ) -> Result<Self, FitError> {
        let ts = data.sampling_period();
        let units = Scale::of(data, ts).ok_or(FitError::BadStep(data.input.du_scale()))?;
        units.check(structure)?;
        let data = units.data_in(data);
        let ts = ts / units.t_unit;
        let duration = data.duration_with(ts);
        let params = structure.params();
        let lead = if structure.lead {
            data.input.lead_range
        } else {
            0.0
        };
        let (lower, upper): (Vec<f64>, Vec<f64>) = params
            .iter()
            .map(|&p| bounds_with(p, ts, duration, lead))
            .unzip();
        let y_span = data.y.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b))
            - data.y.iter().fold(f64::INFINITY, |a, &b| a.min(b));
        let y_scale = y_span.abs().max(1e-12);
        let typical = params
            .iter()
            .map(|&p| match p {
                Param::Kp | Param::Y0 | Param::X1 | Param::X2 | Param::X3 => y_scale,
                Param::Drift => y_scale / duration,
                Param::Zeta => 1.0,
                _ => ts,
            })
            .collect();
        Ok(Self {
            fixed: units.values_in(structure, &guess),
            data,
            units,
            ts,
            structure,
            params,
            lower,
            upper,
            typical,
            root_weights: None,
            within: 0.0,
            alias_span: None,
        })
    }

    /// The same problem (units, bounds, fixed values) on the block means of `r`, each
    /// weighted by the samples it stands for, its sums of squares the record's.
    pub(super) fn restricted(&self, r: &Reduction) -> Problem {
        Problem {
            data: r.apply(&self.data),
            units: self.units,
            ts: self.ts,
            structure: self.structure,
            params: self.params.clone(),
            lower: self.lower.clone(),
            upper: self.upper.clone(),
            typical: self.typical.clone(),
            fixed: self.fixed,
            root_weights: Some(r.weights().iter().map(|w| w.sqrt()).collect()),
            within: r.within(&self.data.times, &self.data.y),
            alias_span: None,
        }
    }

    /// The model at `x` (internal units).
    pub(super) fn model(&self, x: &[f64]) -> Model {
        Model::new(self.structure, self.fixed.with_vector(&self.params, x))
    }

    /// The model at `x` in the data's units.
    pub(super) fn model_out(&self, x: &[f64]) -> Result<Model, Unrepresentable> {
        self.units.model_out(&self.model(x))
    }

    pub(super) fn simulator(&self, x: &[f64]) -> Result<Simulator, ModelError> {
        self.model(x).simulator(&self.data.input)
    }

    /// Residuals y − ŷ of one piece of the record (`range`) into `out`.
    pub(super) fn piece(&self, s: &Simulator, range: std::ops::Range<usize>, out: &mut [f64]) {
        let out = &mut out[..range.len()];
        s.fill(&self.data.times[range.clone()], out);
        for (r, y) in out.iter_mut().zip(&self.data.y[range.clone()]) {
            *r = y - *r;
        }
        if let Some(w) = &self.root_weights {
            out.iter_mut().zip(&w[range]).for_each(|(r, w)| *r *= w);
        }
    }

    /// The residuals' derivative on one piece (`range`) into `out` along a parameter whose
    /// column is known without a simulation (see [`Column`]): r = (y − ŷ)·√w, `residuals`
    /// the piece's residuals at the point, `base` its simulator and `basis` its initial
    /// transient's basis on the piece (empty without one).
    pub(super) fn exact_column(
        &self,
        column: Column,
        (base, basis): (&Simulator, &[Vec<f64>]),
        range: std::ops::Range<usize>,
        residuals: &[f64],
        out: &mut [f64],
    ) {
        let out = &mut out[..range.len()];
        let times = &self.data.times[range.clone()];
        match column {
            Column::Offset => out.iter_mut().for_each(|c| *c = 1.0),
            // Never asked for: its column is a difference of simulations.
            Column::Difference => out.iter_mut().for_each(|c| *c = 0.0),
            Column::Drift => {
                let t0 = base.drift_origin();
                out.iter_mut().zip(times).for_each(|(c, t)| *c = t - t0);
            }
            Column::Transient(i) => match basis.get(i) {
                Some(phi) => out.copy_from_slice(&phi[..out.len()]),
                None => out.iter_mut().for_each(|c| *c = 0.0),
            },
            Column::Gain(kp) => {
                // ŷ = y − r/√w, then its forced part.
                let y = &self.data.y[range.clone()];
                match &self.root_weights {
                    Some(w) => {
                        for (((c, y), r), w) in
                            out.iter_mut().zip(y).zip(residuals).zip(&w[range.clone()])
                        {
                            *c = if *w > 0.0 { y - r / w } else { 0.0 };
                        }
                    }
                    None => {
                        for ((c, y), r) in out.iter_mut().zip(y).zip(residuals) {
                            *c = y - r;
                        }
                    }
                }
                base.forced_from(times, out, Some(basis));
                out.iter_mut().for_each(|c| *c /= kp);
            }
        }
        // ∂r/∂p = −√w·∂ŷ/∂p.
        match &self.root_weights {
            Some(w) => out.iter_mut().zip(&w[range]).for_each(|(c, w)| *c *= -w),
            None => out.iter_mut().for_each(|c| *c = -*c),
        }
    }

    /// The record's length: the samples, or on a reduced record the samples they stand for.
    pub(super) fn samples(&self) -> usize {
        match &self.root_weights {
            Some(w) => w.iter().map(|w| w * w).sum::<f64>().round() as usize,
            None => self.data.y.len(),
        }
    }

    /// The pieces of the record.
    pub(super) fn pieces(&self) -> impl Iterator<Item = std::ops::Range<usize>> + use<> {
        let n = self.data.y.len();
        (0..n.div_ceil(CHUNK)).map(move |k| k * CHUNK..(k * CHUNK + CHUNK).min(n))
    }

    /// Sum of squared residuals at `x`, keeping the residuals in `keep` when given (a slice
    /// of the record's length); an error when the model is invalid or a residual is not
    /// finite.
    pub(super) fn sse(&self, x: &[f64], mut keep: Option<&mut [f64]>) -> Result<f64, ModelError> {
        let s = self.simulator(x)?;
        let mut buffer = if keep.is_some() {
            Vec::new()
        } else {
            vec![0.0; CHUNK.min(self.data.y.len())]
        };
        let mut sum = 0.0;
        for range in self.pieces() {
            let out = match keep.as_deref_mut() {
                Some(k) => &mut k[range.clone()],
                None => &mut buffer[..],
            };
            self.piece(&s, range.clone(), out);
            let piece = &out[..range.len()];
            sum += dot(piece, piece);
        }
        sum += self.within;
        if sum.is_finite() {
            Ok(sum)
        } else {
            Err(ModelError::Overflow)
        }
    }

    /// The Jacobian's columns of the parameters themselves: each moved by h, a relative
    /// √ε of its size (backward at an upper bound).
    pub(super) fn coordinate_directions(&self, x: &[f64]) -> Vec<Direction> {
        (0..x.len())
            .map(|i| {
                let h = self.difference_step(i, x[i]);
                let mut moved = x.to_vec();
                moved[i] = x[i] + h;
                let column = match self.params[i] {
                    Param::Y0 => Column::Offset,
                    Param::Drift => Column::Drift,
                    Param::Kp if x[i] != 0.0 && x[i].is_finite() => Column::Gain(x[i]),
                    Param::X1 => Column::Transient(0),
                    Param::X2 => Column::Transient(1),
                    Param::X3 => Column::Transient(2),
                    _ => Column::Difference,
                };
                Direction { moved, h, column }
            })
            .collect()
    }

    /// The finite-difference step of parameter `i` at `value`: √ε of its size (or of its
    /// typical magnitude), backward when forward would pass its upper bound.
    pub(super) fn difference_step(&self, i: usize, value: f64) -> f64 {
        let h = f64::EPSILON.sqrt() * value.abs().max(self.typical[i]);
        if value + h > self.upper[i] { -h } else { h }
    }

    /// [`Problem::normal_equations`] with the Jacobian's columns along `directions` (the
    /// difference of the residuals at each moved point, over its step).
    pub(super) fn normal_along(
        &self,
        x: &[f64],
        known: Option<&[f64]>,
        directions: &[Direction],
    ) -> Option<Normal> {
        let p = directions.len();
        let base = self.simulator(x).ok()?;
        let shifted_models = directions
            .iter()
            .map(|d| match d.column {
                Column::Difference => self.simulator(&d.moved).ok().map(Some),
                _ => Some(None),
            })
            .collect::<Option<Vec<_>>>()?;
        let steps: Vec<f64> = directions.iter().map(|d| d.h).collect();
        let width = CHUNK.min(self.data.y.len());
        let mut r = vec![0.0; width];
        let mut columns = vec![vec![0.0; width]; p];
        let mut a = DMatrix::<f64>::zeros(p, p);
        let mut g = DVector::<f64>::zeros(p);
        for range in self.pieces() {
            let len = range.len();
            let r = match known {
                Some(k) => &k[range.clone()],
                None => {
                    self.piece(&base, range.clone(), &mut r);
                    &r[..len]
                }
            };
            // The transient's basis, once per piece: the columns of its coefficients, and
            // the transient the gain's column takes out.
            let basis = if directions
                .iter()
                .any(|d| matches!(d.column, Column::Gain(_) | Column::Transient(_)))
            {
                base.transient_basis(&self.data.times[range.clone()])
            } else {
                Vec::new()
            };
            for (((column, s), h), d) in columns
                .iter_mut()
                .zip(&shifted_models)
                .zip(&steps)
                .zip(directions)
            {
                let Some(s) = s else {
                    self.exact_column(d.column, (&base, &basis), range.clone(), r, column);
                    continue;
                };
                self.piece(s, range.clone(), column);
                for (c, base) in column[..len].iter_mut().zip(r) {
                    *c = (*c - base) / h;
                }
            }
            for i in 0..p {
                let ci = &columns[i][..len];
                g[i] += dot(ci, r);
                for k in 0..=i {
                    a[(i, k)] += dot(ci, &columns[k][..len]);
                }
            }
        }
        for i in 0..p {
            for k in 0..i {
                a[(k, i)] = a[(i, k)];
            }
        }
        a.iter()
            .chain(g.iter())
            .all(|v| v.is_finite())
            .then_some(Normal { a, g })
    }

    /// Start points: the guess, then spread-out points around it (reproducible).
    pub(super) fn starts(&self, x0: &[f64], count: usize, seed: u64) -> Vec<Vec<f64>> {
        let mut rng = Lcg(seed.wrapping_mul(2654435761).wrapping_add(1));
        let duration = self.data.duration_with(self.ts);
        let mut out = vec![x0.to_vec()];
        while out.len() < count {
            let x: Vec<f64> = self
                .params
                .iter()
                .zip(x0)
                .map(|(&p, &v)| match p {
                    Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw => {
                        v * (3.0 * rng.symmetric()).exp()
                    }
                    Param::Zeta => 0.05 + 0.9 * rng.unit(),
                    Param::Td => v * (0.3 + 1.4 * rng.unit()),
                    Param::Tz => v + rng.symmetric() * duration * 0.3,
                    Param::Kp => v * (0.5 * rng.symmetric()).exp(),
                    Param::Ta => v,
                    Param::Y0 | Param::Drift | Param::X1 | Param::X2 | Param::X3 => v,
                })
                .collect();
            out.push(self.clamp(x));
        }
        out
    }
}

/// The problem as its solvers see it.
impl LeastSquaresProblem for Problem {
    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    fn typical(&self) -> &[f64] {
        &self.typical
    }

    fn residual_count(&self) -> usize {
        self.data.y.len()
    }

    fn cost(&self, x: &[f64], keep: Option<&mut [f64]>) -> Option<f64> {
        self.sse(x, keep).ok()
    }

    /// A = JᵀJ and g = Jᵀr at `x` from the forward-difference Jacobian of the residuals
    /// (backward at an upper bound), summed piece by piece; `known` are the residuals at `x`
    /// when the caller kept them.
    fn normal_equations(&self, x: &[f64], known: Option<&[f64]>) -> Option<Normal> {
        self.normal_along(x, known, &self.coordinate_directions(x))
    }
}

/// Σ aᵢ·bᵢ over the shorter of the two. Eight running sums, not one: a single sum is a chain
/// of dependent additions that the compiler may not reorder (floating-point addition is not
/// associative), and the Jacobian's products are most of a fit's arithmetic between
/// simulations; eight independent ones fill the vector lanes, and their rounding is a
/// pairwise sum's, no worse.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    const LANES: usize = 8;
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut sums = [0.0; LANES];
    let ((chunks_a, tail_a), (chunks_b, tail_b)) = (a.as_chunks::<LANES>(), b.as_chunks::<LANES>());
    let tail: f64 = tail_a.iter().zip(tail_b).map(|(x, y)| x * y).sum();
    for (x, y) in chunks_a.iter().zip(chunks_b) {
        for ((s, x), y) in sums.iter_mut().zip(x).zip(y) {
            *s += x * y;
        }
    }
    let [s0, s1, s2, s3, s4, s5, s6, s7] = sums;
    ((s0 + s4) + (s1 + s5)) + ((s2 + s6) + (s3 + s7)) + tail
}
