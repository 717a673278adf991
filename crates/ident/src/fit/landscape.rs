//! The cost landscape: the mean squared error over a grid of two parameters, the others held
//! at a model's values (e.g. ζ and ωn with Kp and Td at the fit, as the LECI notes' Figure 4
//! shows it, with its several local minima). Computed in rows so a caller can show progress
//! and cancel, in the record's internal units ([`Scale`]) like a fit, and scaled back.

use serde::{Deserialize, Serialize};

use crate::fit::FitData;
use crate::model::scale::Scale;
use crate::model::{Model, Param, Values};

/// One axis of the landscape: a parameter, or ωn = 1/Tw for an underdamped pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Axis {
    Param(Param),
    /// ωn = 1/Tw (rad/s).
    NaturalFrequency,
}

impl Axis {
    pub fn name(self) -> String {
        match self {
            Axis::Param(p) => p.name().to_string(),
            Axis::NaturalFrequency => "ωn (rad/s)".to_string(),
        }
    }

    /// The axis value of a model.
    pub fn value(self, v: &Values) -> f64 {
        match self {
            Axis::Param(p) => v.get(p),
            Axis::NaturalFrequency => 1.0 / v.get(Param::Tw),
        }
    }

    /// Sets the axis value in `v`.
    pub fn set(self, v: &mut Values, x: f64) {
        match self {
            Axis::Param(p) => v.set(p, x),
            Axis::NaturalFrequency => v.set(Param::Tw, 1.0 / x),
        }
    }

    /// Whether the grid is spaced logarithmically (positive scale parameters).
    pub fn logarithmic(self) -> bool {
        matches!(
            self,
            Axis::NaturalFrequency | Axis::Param(Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw)
        )
    }
}

/// The grid and its costs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Landscape {
    pub x_axis: Axis,
    pub y_axis: Axis,
    pub xs: Vec<f64>,
    pub ys: Vec<f64>,
    /// MSE, row-major: `cost[j * xs.len() + i]` at (xs[i], ys[j]); infinite where the model
    /// is invalid. In (output units)² when `cost_log10_unit` is 0, else in units of
    /// 10^cost_log10_unit (output units)² (a 1e300 record's MSE, 1e596, is beyond doubles).
    pub cost: Vec<f64>,
    /// log₁₀ of the unit of `cost` in (output units)²: 0 unless the MSE itself is beyond
    /// double precision.
    #[serde(default)]
    pub cost_log10_unit: f64,
}

impl Landscape {
    /// The grid point of lowest cost: (x, y, cost).
    pub fn minimum(&self) -> Option<(f64, f64, f64)> {
        let (k, c) = self
            .cost
            .iter()
            .enumerate()
            .filter(|(_, c)| c.is_finite())
            .min_by(|a, b| a.1.total_cmp(b.1))?;
        Some((self.xs[k % self.xs.len()], self.ys[k / self.xs.len()], *c))
    }

    /// Grid points lower than their 8 neighbours: the local minima a start can fall into.
    pub fn local_minima(&self) -> Vec<(f64, f64, f64)> {
        let (nx, ny) = (self.xs.len(), self.ys.len());
        let at = |i: usize, j: usize| self.cost[j * nx + i];
        let mut out = Vec::new();
        for j in 1..ny.saturating_sub(1) {
            for i in 1..nx.saturating_sub(1) {
                let c = at(i, j);
                let lower = (j - 1..=j + 1)
                    .all(|b| (i - 1..=i + 1).all(|a| (a, b) == (i, j) || c < at(a, b)));
                if c.is_finite() && lower {
                    out.push((self.xs[i], self.ys[j], c));
                }
            }
        }
        out
    }
}

/// `n` points from `lo` to `hi`, logarithmic when asked (and both positive).
pub fn grid(lo: f64, hi: f64, n: usize, log: bool) -> Vec<f64> {
    let n = n.max(2);
    let t = |k: usize| k as f64 / (n - 1) as f64;
    if log && lo > 0.0 && hi > 0.0 {
        (0..n)
            .map(|k| (lo.ln() + (hi.ln() - lo.ln()) * t(k)).exp())
            .collect()
    } else {
        (0..n).map(|k| lo + (hi - lo) * t(k)).collect()
    }
}

/// Computes the landscape row by row; `on_row(done, total)` returning true cancels (then
/// `None` is returned).
pub fn compute(
    data: &FitData,
    model: &Model,
    (x_axis, xs): (Axis, Vec<f64>),
    (y_axis, ys): (Axis, Vec<f64>),
    on_row: &mut dyn FnMut(usize, usize) -> bool,
) -> Option<Landscape> {
    let units = Scale::of(data, data.sampling_period()).unwrap_or_default();
    let unit_square = units.mse_out(1.0);
    let physical = unit_square.is_normal();
    let inside = units.data_in(data);
    let mut cost = Vec::with_capacity(xs.len() * ys.len());
    let mut buffer = vec![0.0; data.times.len()];
    for (j, &y) in ys.iter().enumerate() {
        for &x in &xs {
            let mut v = model.values;
            x_axis.set(&mut v, x);
            y_axis.set(&mut v, y);
            let m = units.model_in(&Model::new(model.structure, v));
            let c = match m.simulate_into(&inside.input, &inside.times, &mut buffer) {
                Ok(()) => {
                    buffer
                        .iter()
                        .zip(&inside.y)
                        .map(|(m, y)| (y - m).powi(2))
                        .sum::<f64>()
                        / inside.y.len() as f64
                }
                Err(_) => f64::INFINITY,
            };
            let c = if physical { c * unit_square } else { c };
            cost.push(if c.is_finite() { c } else { f64::INFINITY });
        }
        if on_row(j + 1, ys.len()) {
            return None;
        }
    }
    Some(Landscape {
        x_axis,
        y_axis,
        xs,
        ys,
        cost,
        cost_log10_unit: if physical {
            0.0
        } else {
            2.0 * units.y_unit.log10()
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Structure;
    use crate::model::excitation::Excitation;

    #[test]
    fn the_minimum_is_at_the_truth_and_cancel_works() {
        let s = Structure::parse("P2U").unwrap();
        let mut truth = Values::default();
        truth.set(Param::Kp, 1.0);
        truth.set(Param::Tw, 1.0);
        truth.set(Param::Zeta, 0.3);
        truth.set(Param::Y0, 0.0);
        let setup = Excitation::step(0.0, 1.0);
        let times: Vec<f64> = (0..200).map(|k| 0.1 * k as f64).collect();
        let model = Model::new(s, truth);
        let y = model.simulate(&setup, &times).unwrap();
        let data = FitData {
            times,
            y,
            input: setup,
        };
        let xs = grid(0.1, 0.9, 9, false);
        let ys = grid(0.25, 4.0, 17, true);
        let l = compute(
            &data,
            &model,
            (Axis::Param(Param::Zeta), xs),
            (Axis::NaturalFrequency, ys.clone()),
            &mut |_, _| false,
        )
        .unwrap();
        let (x, y, c) = l.minimum().unwrap();
        assert!(
            (x - 0.3).abs() < 1e-12 && (y - 1.0).abs() < 1e-12 && c < 1e-25,
            "{x} {y} {c}"
        );
        let cancelled = compute(
            &data,
            &model,
            (Axis::Param(Param::Zeta), grid(0.1, 0.9, 9, false)),
            (Axis::NaturalFrequency, ys),
            &mut |done, _| done >= 2,
        );
        assert!(cancelled.is_none());
    }
}
