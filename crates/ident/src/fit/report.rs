//! The report of a fit's optimum: MSE, RMSE, fit %, AIC, the warnings (a parameter at a
//! bound, an overdamped underdamped model, an alias, no convergence, an undetermined gain)
//! and the 95 % intervals from s²(JᵀJ)⁻¹, two lags the record cannot tell apart read through
//! their mean and squared half-difference ([`lag_pair`]).

use std::ops::Add;

use serde::{Deserialize, Serialize};

use nalgebra::DMatrix;

use super::problem::{Column, Direction, Problem};
use super::setup::{CHUNK, FitData, FitError, FitOptions, Method};
use super::solver::{LeastSquaresProblem, Normal, Run, Termination};
use crate::fit::lag_pair;
use crate::model::Param;
use crate::model::scale::Scale;
use crate::model::{Model, ModelError, Values};
use crate::stats::student_t_quantile;

/// Something a student should know about a fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FitWarning {
    AtBound {
        param: String,
        bound: f64,
    },
    OverdampedUnderdamped {
        zeta: f64,
    },
    Alias {
        omega_d: f64,
        nyquist: f64,
        between_samples: f64,
    },
    NotIdentifiable {
        param: String,
    },
    /// A combination of the parameters is not identifiable (no one parameter alone).
    CombinationNotIdentifiable,
    /// Two real lags the record cannot tell apart (equal lags explain it as well): their
    /// intervals are read together ([`lag_pair`]).
    LagsNotResolved {
        larger: String,
        smaller: String,
    },
    NotConverged,
    /// No step lowered the cost from the start.
    NoImprovement,
    /// A statistic beyond double precision in the record's units (shown as inf or 0).
    Unrepresentable {
        statistic: String,
        log10: f64,
    },
    /// The 95 % interval of Kp, [low, high], contains 0: the record does not determine the
    /// gain, not even its sign.
    GainUndetermined {
        low: f64,
        high: f64,
    },
}

/// One estimated parameter with its 95 % confidence interval, when it exists.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Estimate {
    pub param: Param,
    pub value: f64,
    /// The Wald interval, cut to the parameter's feasible range (a step-instant lead Ta in
    /// [0, Ts), a lag above zero): what lies outside it is no value the model can take.
    pub ci95: Option<(f64, f64)>,
    /// The feasible range the fit searched (record units); not written out.
    #[serde(skip)]
    pub bounds: Option<(f64, f64)>,
}

impl Estimate {
    /// `(lo, hi)` cut to the feasible range, when known.
    fn within_bounds(&self, (lo, hi): (f64, f64)) -> (f64, f64) {
        match self.bounds {
            Some((a, b)) => (lo.max(a), hi.min(b)),
            None => (lo, hi),
        }
    }
}

/// The result of a fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FitReport {
    pub model: Model,
    pub method: Method,
    /// Estimated parameters in order, with their 95 % intervals when they exist.
    pub params: Vec<Estimate>,
    pub n: usize,
    /// Mean squared error in (output units)²; inf or 0 where beyond double precision (then a
    /// [`FitWarning::Unrepresentable`] says so, and `ln_mse` holds it).
    pub mse: f64,
    /// ln of the MSE in (output units)², finite at any scale (floored for an exact fit).
    #[serde(default)]
    pub ln_mse: f64,
    pub rmse: f64,
    pub fit_percent: f64,
    pub aic: f64,
    pub iterations: usize,
    pub termination: Termination,
    pub warnings: Vec<FitWarning>,
    pub starts: usize,
    /// Every accepted point of the winning start, for the landscape's path.
    pub path: Vec<Values>,
    /// The internal units the fit ran in.
    #[serde(default)]
    pub units: Scale,
    /// The correlation of Kp's estimate with every other parameter's, from the same
    /// covariance as the intervals (−1 to 1; empty when there is none): how far the record
    /// lets the gain trade with a drift, a slow lag, a transient or Y0.
    #[serde(default)]
    pub kp_correlations: Vec<(Param, f64)>,
}

impl FitReport {
    /// The 95 % interval of a parameter, if estimated and identifiable.
    pub fn interval(&self, p: Param) -> Option<(f64, f64)> {
        self.params
            .iter()
            .find(|e| e.param == p)
            .and_then(|e| e.ci95)
    }

    /// Widens every 95 % interval about its estimate by `factor` (≥ 1): the correction for
    /// residuals correlated as an AR(1) with coefficient ρ, √((1 + ρ)/(1 − ρ)).
    /// The gain's warning follows the widened interval.
    pub fn widen_intervals(&mut self, factor: f64) {
        for e in &mut self.params {
            if let Some((lo, hi)) = e.ci95 {
                e.ci95 = Some(e.within_bounds((
                    e.value - factor * (e.value - lo),
                    e.value + factor * (hi - e.value),
                )));
            }
        }
        self.warnings
            .retain(|w| !matches!(w, FitWarning::GainUndetermined { .. }));
        self.warnings.extend(gain_warning(&self.params));
    }

    /// The residuals y − ŷ of this fit on `data` (output units), simulated in the fit's
    /// internal units, so that they are right at any scale.
    pub fn residuals(&self, data: &FitData) -> Result<Vec<f64>, ModelError> {
        let units = &self.units;
        let simulator = units
            .model_in(&self.model)
            .simulator(&units.input_in(&data.input))?;
        let mut r = vec![0.0; data.y.len()];
        let mut times = Vec::with_capacity(CHUNK);
        for (k, out) in r.chunks_mut(CHUNK).enumerate() {
            let range = k * CHUNK..k * CHUNK + out.len();
            times.clear();
            times.extend(data.times[range.clone()].iter().map(|&t| units.time_in(t)));
            simulator.fill(&times, out);
            for (o, &y) in out.iter_mut().zip(&data.y[range]) {
                *o = units.output_difference_out(units.output_in(y) - *o);
            }
        }
        Ok(r)
    }
}

/// [`FitWarning::GainUndetermined`] when the 95 % interval of Kp among `params` contains 0.
fn gain_warning(params: &[Estimate]) -> Option<FitWarning> {
    let (low, high) = params
        .iter()
        .find(|e| e.param == Param::Kp)
        .and_then(|e| e.ci95)?;
    (low <= 0.0 && 0.0 <= high).then_some(FitWarning::GainUndetermined { low, high })
}
/// Each estimated parameter's 95 % interval, in order (`None` where none can be given).
type Intervals = Vec<Option<(f64, f64)>>;
impl Problem {
    /// The report of `run` (on this problem's samples; the alias check on `checked`'s).
    pub(super) fn report(
        &self,
        run: Run,
        options: &FitOptions,
        starts: usize,
        checked: &Problem,
    ) -> Result<FitReport, FitError> {
        let units = &self.units;
        let model = self.model_out(&run.x)?;
        let n = self.samples();
        let p = self.params.len();
        let mse = run.sse / n as f64;
        let weight = |i: usize| self.root_weights.as_ref().map_or(1.0, |w| w[i] * w[i]);
        let mean = self
            .data
            .y
            .iter()
            .enumerate()
            .map(|(i, y)| weight(i) * y)
            .sum::<f64>()
            / n as f64;
        let spread = self
            .data
            .y
            .iter()
            .enumerate()
            .map(|(i, y)| weight(i) * (y - mean) * (y - mean))
            .sum::<f64>()
            .add(self.within)
            .sqrt();
        let fit_percent = if spread > 0.0 {
            100.0 * (1.0 - run.sse.sqrt() / spread)
        } else {
            f64::NAN
        };
        let ln_mse = units.ln_mse_out(mse);
        let aic = n as f64 * ln_mse
            + 2.0 * p as f64
            + n as f64 * ((2.0 * std::f64::consts::PI).ln() + 1.0);
        let mut warnings = Vec::new();
        let mse_out = units.mse_out(mse);
        if mse > 0.0 && !mse_out.is_normal() {
            warnings.push(FitWarning::Unrepresentable {
                statistic: "MSE".into(),
                log10: ln_mse / std::f64::consts::LN_10,
            });
        }
        let mut kp_correlations = Vec::new();
        let intervals = if options.screen {
            vec![None; p]
        } else {
            self.intervals(&run.x, run.sse, &mut warnings, &mut kp_correlations)
        };
        for (i, &param) in self.params.iter().enumerate() {
            for bound in [self.lower[i], self.upper[i]] {
                let tolerance = 1e-6 * (bound.abs() + self.typical[i]);
                if bound.is_finite()
                    && (run.x[i] - bound).abs() <= tolerance
                    && !(param == Param::Td && bound <= 0.0)
                    && param != Param::Ta
                {
                    warnings.push(FitWarning::AtBound {
                        param: param.name().into(),
                        bound: units.value_out(param, self.structure, bound),
                    });
                }
            }
        }
        if self.structure.underdamped && model.get(Param::Zeta) >= 1.0 {
            warnings.push(FitWarning::OverdampedUnderdamped {
                zeta: model.get(Param::Zeta),
            });
        }
        if !options.screen
            && let Some(alias) = checked.alias(&run.x)
        {
            warnings.push(alias);
        }
        match run.termination {
            Termination::IterationLimit => warnings.push(FitWarning::NotConverged),
            Termination::NoImprovement => warnings.push(FitWarning::NoImprovement),
            _ => {}
        }
        let out = |param: Param, x: f64| units.value_out(param, self.structure, x);
        let params: Vec<Estimate> = self
            .params
            .iter()
            .zip(&run.x)
            .zip(intervals)
            .enumerate()
            .map(|(i, ((&param, &value), ci95))| {
                let estimate = Estimate {
                    param,
                    value: out(param, value),
                    ci95: None,
                    bounds: Some((out(param, self.lower[i]), out(param, self.upper[i]))),
                };
                Estimate {
                    ci95: ci95
                        .map(|(lo, hi)| estimate.within_bounds((out(param, lo), out(param, hi))))
                        .filter(|(lo, hi)| lo.is_finite() && hi.is_finite()),
                    ..estimate
                }
            })
            .collect();
        warnings.extend(gain_warning(&params));
        Ok(FitReport {
            params,
            model,
            method: options.method,
            n,
            mse: mse_out,
            ln_mse,
            rmse: units.output_difference_out(mse.sqrt()),
            fit_percent,
            aic,
            iterations: run.iterations,
            termination: run.termination,
            warnings,
            starts,
            path: run
                .path
                .iter()
                .filter_map(|x| self.model_out(x).ok().map(|m| m.values))
                .collect(),
            units: *units,
            kp_correlations,
        })
    }

    /// 95 % intervals from s²(JᵀJ)⁻¹ (internal units); two real lags the record cannot
    /// tell apart read through their mean and squared half-difference ([`lag_pair`]).
    pub(super) fn intervals(
        &self,
        x: &[f64],
        sse: f64,
        warnings: &mut Vec<FitWarning>,
        correlations: &mut Vec<(Param, f64)>,
    ) -> Intervals {
        let (n, p) = (self.samples(), x.len());
        let none = vec![None; p];
        if n <= p {
            return none;
        }
        let Some(Normal { a, .. }) = self.normal_equations(x, None) else {
            return none;
        };
        let dof = (n - p) as f64;
        let s2 = sse / dof;
        let t = student_t_quantile(0.975, dof);
        let inverse = inverse_scaled(&a);
        if let Some((intervals, larger, smaller)) =
            self.lag_pair_intervals(x, s2, t, inverse.is_err())
        {
            warnings.push(FitWarning::LagsNotResolved {
                larger: larger.name().into(),
                smaller: smaller.name().into(),
            });
            return intervals;
        }
        let inverse = match inverse {
            Ok(inverse) => inverse,
            Err(diagonal) => {
                for (param, d) in self.params.iter().zip(&diagonal) {
                    if !is_positive(*d) {
                        warnings.push(FitWarning::NotIdentifiable {
                            param: param.name().into(),
                        });
                    }
                }
                if diagonal.iter().all(|v| *v > 0.0) {
                    warnings.push(FitWarning::CombinationNotIdentifiable);
                }
                return none;
            }
        };
        if let Some(k) = self.params.iter().position(|q| *q == Param::Kp) {
            correlations.extend(self.params.iter().enumerate().filter_map(|(j, &q)| {
                let d = inverse[(k, k)] * inverse[(j, j)];
                (j != k && d > 0.0).then(|| (q, (inverse[(k, j)] / d.sqrt()).clamp(-1.0, 1.0)))
            }));
        }
        (0..p)
            .map(|i| {
                let half = t * (s2 * inverse[(i, i)]).max(0.0).sqrt();
                Some((x[i] - half, x[i] + half))
            })
            .collect()
    }

    /// The intervals with the two closest real lags read as (m, q) ([`lag_pair`]), when
    /// the record cannot tell them apart: the lags' own covariance is singular (`singular`,
    /// a fit on the fold) or the 95 % interval of q reaches 0 (equal lags explain the
    /// record as well). `None` otherwise (and for fewer than two real lags), with the lags'
    /// names (larger, smaller) when given.
    pub(super) fn lag_pair_intervals(
        &self,
        x: &[f64],
        s2: f64,
        t: f64,
        singular: bool,
    ) -> Option<(Intervals, Param, Param)> {
        let (i, j) = self.closest_lags(x)?;
        let (m, q) = lag_pair::mean_and_square(x[i], x[j]);
        let mut directions = self.coordinate_directions(x);
        // Both lags move by the larger's step (backward when it would pass its bound).
        let h = self.difference_step(i, x[i]);
        let mut moved = x.to_vec();
        (moved[i], moved[j]) = (x[i] + h, x[j] + h);
        directions[i] = Direction {
            moved,
            h,
            column: Column::Difference,
        };
        let dq = lag_pair::Q_STEP * m * m + f64::EPSILON.sqrt() * q;
        let (a, b) = lag_pair::lags_of(m, q + dq);
        if b < self.lower[j] || a > self.upper[i] {
            return None;
        }
        let mut moved = x.to_vec();
        (moved[i], moved[j]) = (a, b);
        directions[j] = Direction {
            moved,
            h: dq,
            column: Column::Difference,
        };
        let Normal { a, .. } = self.normal_along(x, None, &directions)?;
        let inverse = inverse_scaled(&a).ok()?;
        let c = |k: usize, l: usize| s2 * inverse[(k, l)];
        if !singular && q - t * c(j, j).max(0.0).sqrt() > 0.0 {
            return None;
        }
        let pair = [[c(i, i), c(i, j)], [c(j, i), c(j, j)]];
        let (larger, smaller) = lag_pair::lag_ranges((m, q), pair, t)?;
        let intervals = (0..x.len())
            .map(|k| match k {
                _ if k == i => Some(larger),
                _ if k == j => Some(smaller),
                _ => {
                    let half = t * c(k, k).max(0.0).sqrt();
                    Some((x[k] - half, x[k] + half))
                }
            })
            .collect();
        Some((intervals, self.params[i], self.params[j]))
    }

    /// The indices (larger first) of the two real lags closest in ratio, if the structure
    /// has two or more.
    pub(super) fn closest_lags(&self, x: &[f64]) -> Option<(usize, usize)> {
        let lags: Vec<usize> = (0..x.len())
            .filter(|&k| matches!(self.params[k], Param::Tp1 | Param::Tp2 | Param::Tp3))
            .collect();
        let separation = |&(k, l): &(usize, usize)| (x[k] - x[l]).abs() / (x[k] + x[l]).abs();
        lags.iter()
            .enumerate()
            .flat_map(|(n, &k)| lags[n + 1..].iter().map(move |&l| (k, l)))
            .min_by(|p, q| separation(p).total_cmp(&separation(q)))
            .map(|(k, l)| if x[k] >= x[l] { (k, l) } else { (l, k) })
    }
}

/// (JᵀJ)⁻¹ from A = JᵀJ, inverted with its columns scaled so that the conditioning
/// reflects the model, not the units; its diagonal's roots when A is singular (an
/// eigenvalue under 1e-13 of the largest of the scaled A, or a column of zeros).
fn inverse_scaled(a: &DMatrix<f64>) -> Result<DMatrix<f64>, Vec<f64>> {
    let p = a.nrows();
    let d: Vec<f64> = (0..p).map(|i| a[(i, i)].sqrt()).collect();
    let mut scaled = a.clone();
    for i in 0..p {
        for k in 0..p {
            scaled[(i, k)] /= d[i] * d[k];
        }
    }
    let singular = d.iter().any(|&v| !is_positive(v)) || {
        let eig = scaled.clone().symmetric_eigenvalues();
        let max = eig.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        eig.iter().any(|v| *v <= 1e-13 * max)
    };
    let inverse = if singular { None } else { scaled.try_inverse() };
    let Some(mut inverse) = inverse else {
        return Err(d);
    };
    for i in 0..p {
        for k in 0..p {
            inverse[(i, k)] /= d[i] * d[k];
        }
    }
    Ok(inverse)
}

/// True for a number above zero (false for NaN).
fn is_positive(x: f64) -> bool {
    x > 0.0
}
