//! Fitting a process model to a measured step test by least squares on the output:
//! minimise the mean squared error (1/N)·Σ(yᵢ − ŷᵢ)² over the free parameters, within bounds.
//!
//! Two methods, chosen by the student:
//! - **Levenberg–Marquardt**, bounded: the projected variant (steps clipped to the box,
//!   parameters held at an active bound removed from the step). Written here because the
//!   `levenberg-marquardt` crate has no bounds, and the usual workaround, a change of
//!   variables, can never reach a bound (a dead time of exactly 0) and distorts the
//!   Jacobian the confidence intervals come from.
//! - **Nelder–Mead** (MATLAB's `fminsearch`, the notes' method) with the same bounds by
//!   clamping, fminsearch's initial simplex and coefficients. Written here for the same
//!   bounds, and to report its path like LM's; `argmin` would add its trait machinery for
//!   sixty lines of algorithm.
//!
//! A multi-start option (on by default) runs LM from the guess and from spread-out starts
//! and keeps the best: the LECI notes show a single start landing on a spurious alias.
//!
//! The report follows MATLAB: MSE, RMSE, NRMSE fit % as `compare` (100·(1 − ‖y − ŷ‖/‖y − ȳ‖)),
//! AIC as `aic` (N·ln MSE + 2p + N·(ln 2π + 1)), and 95 % intervals from the Jacobian at the
//! optimum (s² (JᵀJ)⁻¹ with s² = SSE/(N − p), Student-t quantile), with warnings for a
//! parameter at a bound, Zeta ≥ 1 in an underdamped model, and an alias.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::models::{Model, ModelError, Param, StepSetup, Structure, Values};
use super::stats::student_t_quantile;

/// The measured test as the fit sees it (already windowed and filtered).
#[derive(Debug, Clone, PartialEq)]
pub struct FitData {
    pub times: Vec<f64>,
    pub y: Vec<f64>,
    pub setup: StepSetup,
}

impl FitData {
    /// The median sampling period (s).
    pub fn sampling_period(&self) -> f64 {
        super::prepare::sampling_period(&self.times).unwrap_or(1.0)
    }

    /// Duration of the record after the step (s).
    pub fn duration(&self) -> f64 {
        let last = self.times.last().copied().unwrap_or(self.setup.t0);
        (last - self.setup.t0).max(self.sampling_period())
    }
}

/// The optimiser.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Method {
    LevenbergMarquardt,
    NelderMead,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::LevenbergMarquardt => "lm",
            Method::NelderMead => "nelder-mead",
        }
    }
}

/// How to fit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FitOptions {
    pub method: Method,
    /// Number of starts (1 = the guess only).
    pub starts: usize,
    /// Iteration limit per start.
    pub max_iterations: usize,
    /// Seed of the spread-out starts (fits are reproducible).
    pub seed: u64,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            method: Method::LevenbergMarquardt,
            starts: 16,
            max_iterations: 200,
            seed: 1,
        }
    }
}

/// Why the optimiser stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    /// The gradient (projected onto the bounds) vanished.
    Gradient,
    /// Steps became negligible.
    SmallStep,
    /// The cost stopped decreasing.
    SmallCostChange,
    /// The iteration limit was reached.
    IterationLimit,
    /// The student cancelled.
    Cancelled,
}

impl Termination {
    pub fn describe(self) -> &'static str {
        match self {
            Termination::Gradient => "converged: the gradient vanished",
            Termination::SmallStep => "converged: the steps became negligible",
            Termination::SmallCostChange => "converged: the cost stopped decreasing",
            Termination::IterationLimit => "stopped at the iteration limit (not converged)",
            Termination::Cancelled => "cancelled",
        }
    }
}

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
    NotConverged,
}

impl FitWarning {
    pub fn message(&self) -> String {
        match self {
            FitWarning::AtBound { param, bound } => format!(
                "{param} stopped at its bound {bound}: the optimum may lie beyond it, or the model \
                 does not need this parameter"
            ),
            FitWarning::OverdampedUnderdamped { zeta } => format!(
                "Zeta = {zeta:.4} ≥ 1 in an underdamped model: the pair is not oscillatory; an \
                 overdamped structure (two real poles) says the same with a clearer meaning"
            ),
            FitWarning::Alias {
                omega_d,
                nyquist,
                between_samples,
            } => format!(
                "alias: the model oscillates at ωd = {omega_d:.4} rad/s, but samples every Ts can only \
                 show up to π/Ts = {nyquist:.4} rad/s; between the samples the model swings by \
                 {:.0} % of the step's effect. Its samples may match the data while the model is \
                 wrong: start from a better guess (the oscillation period of the data) or use \
                 several starts",
                100.0 * between_samples
            ),
            FitWarning::NotIdentifiable { param } => format!(
                "{param} is not identifiable from this data (the fit does not depend on it): no \
                 interval can be given"
            ),
            FitWarning::NotConverged => {
                "the optimiser did not converge: the values are not an optimum".into()
            }
        }
    }
}

/// One line of progress, for a live display.
#[derive(Debug, Clone, PartialEq)]
pub struct Progress {
    pub start: usize,
    pub starts: usize,
    pub iteration: usize,
    pub cost: f64,
    pub best_cost: f64,
    pub model: Model,
}

/// Receives progress and may cancel. `()` ignores everything.
pub trait FitObserver {
    fn progress(&mut self, _progress: &Progress) {}
    fn cancelled(&self) -> bool {
        false
    }
}

impl FitObserver for () {}

/// One estimated parameter with its 95 % confidence interval, when it exists.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Estimate {
    pub param: Param,
    pub value: f64,
    pub ci95: Option<(f64, f64)>,
}

/// The result of a fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FitReport {
    pub model: Model,
    pub method: Method,
    /// Estimated parameters in order, with their 95 % intervals when they exist.
    pub params: Vec<Estimate>,
    pub n: usize,
    pub mse: f64,
    pub rmse: f64,
    pub fit_percent: f64,
    pub aic: f64,
    pub iterations: usize,
    pub termination: Termination,
    pub warnings: Vec<FitWarning>,
    pub starts: usize,
    /// Every accepted point of the winning start, for the landscape's path.
    pub path: Vec<Values>,
}

impl FitReport {
    /// The 95 % interval of a parameter, if estimated and identifiable.
    pub fn interval(&self, p: Param) -> Option<(f64, f64)> {
        self.params
            .iter()
            .find(|e| e.param == p)
            .and_then(|e| e.ci95)
    }

    /// The residuals y − ŷ of this fit on `data`.
    pub fn residuals(&self, data: &FitData) -> Result<Vec<f64>, ModelError> {
        let yhat = self.model.simulate(&data.setup, &data.times)?;
        Ok(data.y.iter().zip(yhat).map(|(y, m)| y - m).collect())
    }
}

/// Errors that stop a fit before it starts.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error("{n} samples after the step are too few to estimate {p} parameters")]
    TooFewSamples { n: usize, p: usize },
    #[error("the step size Δu is {0}: it must be a finite number other than zero")]
    BadStep(f64),
    #[error("the initial guess is not a valid model: {0}")]
    BadGuess(ModelError),
    #[error("the data contain a value that is not a finite number")]
    NonFiniteData,
}

/// Lower and upper bound of each parameter for this data.
pub fn bounds(p: Param, data: &FitData) -> (f64, f64) {
    let ts = data.sampling_period();
    let duration = data.duration();
    match p {
        Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw => (1e-3 * ts, 100.0 * duration),
        Param::Zeta => (0.0, 10.0),
        Param::Td => (0.0, 0.95 * duration),
        Param::Tz => (-100.0 * duration, 100.0 * duration),
        Param::Kp | Param::Y0 | Param::Drift => (f64::NEG_INFINITY, f64::INFINITY),
    }
}

/// Fits `structure` to `data` starting from `guess`.
pub fn fit(
    data: &FitData,
    structure: Structure,
    guess: Values,
    options: &FitOptions,
    observer: &mut dyn FitObserver,
) -> Result<FitReport, FitError> {
    validate(data, &structure)?;
    let problem = Problem::new(data, structure, guess);
    let x0 = problem.clamp(guess.vector(&problem.params));
    problem.cost(&x0).map_err(FitError::BadGuess)?;
    let starts = problem.starts(&x0, options.starts.max(1), options.seed);
    let mut best: Option<Run> = None;
    for (k, start) in starts.iter().enumerate() {
        if observer.cancelled() {
            break;
        }
        let best_cost = best.as_ref().map_or(f64::INFINITY, |b| b.cost);
        let mut report = |iteration: usize, cost: f64, x: &[f64]| {
            observer.progress(&Progress {
                start: k,
                starts: starts.len(),
                iteration,
                cost,
                best_cost: best_cost.min(cost),
                model: problem.model(x),
            });
            observer.cancelled()
        };
        let run = match options.method {
            Method::LevenbergMarquardt => {
                problem.levenberg_marquardt(start, options.max_iterations, &mut report)
            }
            Method::NelderMead => {
                problem.nelder_mead(start, options.max_iterations * 10, &mut report)
            }
        };
        let Some(mut run) = run else { continue };
        run.aliased = alias_warning(&problem.model(&run.x), data).is_some();
        if best.as_ref().is_none_or(|b| run.better_than(b)) {
            best = Some(run);
        }
    }
    let cancelled = observer.cancelled();
    let mut run = best.unwrap_or_else(|| Run {
        x: x0.clone(),
        cost: problem.cost(&x0).unwrap_or(f64::INFINITY),
        iterations: 0,
        termination: Termination::Cancelled,
        path: vec![x0.clone()],
        aliased: false,
    });
    if cancelled {
        run.termination = Termination::Cancelled;
    }
    Ok(problem.report(run, options, starts.len()))
}

fn validate(data: &FitData, structure: &Structure) -> Result<(), FitError> {
    if !data.setup.du.is_finite() || data.setup.du == 0.0 {
        return Err(FitError::BadStep(data.setup.du));
    }
    if data.times.iter().chain(&data.y).any(|v| !v.is_finite()) {
        return Err(FitError::NonFiniteData);
    }
    let after = data.times.iter().filter(|&&t| t >= data.setup.t0).count();
    let p = structure.len();
    if after <= p || data.times.len() <= p + 1 {
        return Err(FitError::TooFewSamples { n: after, p });
    }
    Ok(())
}

/// One optimiser run.
struct Run {
    x: Vec<f64>,
    cost: f64,
    iterations: usize,
    termination: Termination,
    path: Vec<Vec<f64>>,
    /// Whether the result oscillates faster than the sampling shows (see [`alias_warning`]).
    aliased: bool,
}

impl Run {
    /// A run without alias beats any aliased one: an alias can match the samples better
    /// than the true optimum (it does on the LECI data) while being wrong between them.
    fn better_than(&self, other: &Run) -> bool {
        match (self.aliased, other.aliased) {
            (false, true) => true,
            (true, false) => false,
            _ => self.cost < other.cost,
        }
    }
}

/// The least-squares problem in the free parameters.
struct Problem<'a> {
    data: &'a FitData,
    structure: Structure,
    params: Vec<Param>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// Typical magnitudes, for finite-difference steps.
    scale: Vec<f64>,
    /// Values of the parameters that are not estimated (e.g. a fixed Y0).
    fixed: Values,
}

impl<'a> Problem<'a> {
    fn new(data: &'a FitData, structure: Structure, held: Values) -> Self {
        let params = structure.params();
        let (lower, upper): (Vec<f64>, Vec<f64>) = params.iter().map(|&p| bounds(p, data)).unzip();
        let y_span = data.y.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b))
            - data.y.iter().fold(f64::INFINITY, |a, &b| a.min(b));
        let y_scale = y_span.abs().max(1e-12);
        let scale = params
            .iter()
            .map(|&p| match p {
                Param::Kp => y_scale / data.setup.du.abs(),
                Param::Y0 => y_scale,
                Param::Drift => y_scale / data.duration(),
                Param::Zeta => 1.0,
                _ => data.sampling_period(),
            })
            .collect();
        Self {
            data,
            structure,
            params,
            lower,
            upper,
            scale,
            fixed: held,
        }
    }

    fn model(&self, x: &[f64]) -> Model {
        Model::new(self.structure, self.fixed.with_vector(&self.params, x))
    }

    fn clamp(&self, mut x: Vec<f64>) -> Vec<f64> {
        for (i, v) in x.iter_mut().enumerate() {
            *v = v.clamp(self.lower[i], self.upper[i]);
        }
        x
    }

    fn residuals(&self, x: &[f64], out: &mut [f64]) -> Result<(), ModelError> {
        self.model(x)
            .simulate_into(&self.data.setup, &self.data.times, out)?;
        for (r, y) in out.iter_mut().zip(&self.data.y) {
            *r = y - *r;
        }
        if out.iter().any(|r| !r.is_finite()) {
            return Err(ModelError::BadValue {
                name: "model",
                value: f64::NAN,
                why: "its response overflowed",
            });
        }
        Ok(())
    }

    /// Mean squared error.
    fn cost(&self, x: &[f64]) -> Result<f64, ModelError> {
        let mut r = vec![0.0; self.data.y.len()];
        self.residuals(x, &mut r)?;
        Ok(r.iter().map(|v| v * v).sum::<f64>() / r.len() as f64)
    }

    /// Forward-difference Jacobian of the residuals (backward at an upper bound).
    fn jacobian(&self, x: &[f64], r: &[f64]) -> Option<DMatrix<f64>> {
        let n = r.len();
        let mut j = DMatrix::zeros(n, x.len());
        let mut shifted = x.to_vec();
        let mut r2 = vec![0.0; n];
        for i in 0..x.len() {
            let mut h = f64::EPSILON.sqrt() * x[i].abs().max(self.scale[i]);
            if x[i] + h > self.upper[i] {
                h = -h;
            }
            shifted[i] = x[i] + h;
            self.residuals(&shifted, &mut r2).ok()?;
            for k in 0..n {
                j[(k, i)] = (r2[k] - r[k]) / h;
            }
            shifted[i] = x[i];
        }
        Some(j)
    }

    /// Start points: the guess, then spread-out points around it (reproducible).
    fn starts(&self, x0: &[f64], count: usize, seed: u64) -> Vec<Vec<f64>> {
        let mut rng = Lcg(seed.wrapping_mul(2654435761).wrapping_add(1));
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
                    Param::Tz => {
                        v + self.scale[0].max(1.0) * 0.0
                            + rng.symmetric() * self.data.duration() * 0.3
                    }
                    Param::Kp => v * (0.5 * rng.symmetric()).exp(),
                    Param::Y0 | Param::Drift => v,
                })
                .collect();
            out.push(self.clamp(x));
        }
        out
    }

    /// Projected Levenberg–Marquardt from `x`.
    fn levenberg_marquardt(
        &self,
        x: &[f64],
        max_iterations: usize,
        report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
    ) -> Option<Run> {
        let n = self.data.y.len();
        let m = x.len();
        let mut x = x.to_vec();
        let mut r = vec![0.0; n];
        self.residuals(&x, &mut r).ok()?;
        let mut sse: f64 = r.iter().map(|v| v * v).sum();
        let mut lambda = 1e-3;
        let mut path = vec![x.clone()];
        let mut termination = Termination::IterationLimit;
        let mut iterations = 0;
        let mut trial = vec![0.0; n];
        for iteration in 1..=max_iterations {
            iterations = iteration;
            if report(iteration, sse / n as f64, &x) {
                termination = Termination::Cancelled;
                break;
            }
            let j = self.jacobian(&x, &r)?;
            // With r = y − ŷ and J = ∂r/∂x the cost gradient is 2Jᵀr: descent is −Jᵀr.
            let g = j.tr_mul(&DVector::from_column_slice(&r));
            let a = j.tr_mul(&j);
            // Active set: at a bound with the descent direction pointing out of the box.
            let free: Vec<usize> = (0..m)
                .filter(|&i| {
                    !((x[i] <= self.lower[i] && g[i] > 0.0)
                        || (x[i] >= self.upper[i] && g[i] < 0.0))
                })
                .collect();
            let gradient_norm = free
                .iter()
                .map(|&i| (g[i] * self.scale[i]).abs())
                .fold(0.0, f64::max);
            if gradient_norm <= 1e-12 * sse.max(f64::MIN_POSITIVE) || free.is_empty() {
                termination = Termination::Gradient;
                break;
            }
            let mut accepted = false;
            let mut step_small = false;
            for _ in 0..30 {
                let k = free.len();
                let mut lhs = DMatrix::zeros(k, k);
                let mut rhs = DVector::zeros(k);
                for (a_i, &i) in free.iter().enumerate() {
                    rhs[a_i] = -g[i];
                    for (a_j, &jj) in free.iter().enumerate() {
                        lhs[(a_i, a_j)] = a[(i, jj)];
                    }
                    lhs[(a_i, a_i)] +=
                        lambda * a[(i, i)].max(1e-12 / (self.scale[i] * self.scale[i]));
                }
                let Some(delta) = lhs.cholesky().map(|c| c.solve(&rhs)) else {
                    lambda *= 10.0;
                    continue;
                };
                let mut candidate = x.clone();
                for (a_i, &i) in free.iter().enumerate() {
                    candidate[i] = (x[i] + delta[a_i]).clamp(self.lower[i], self.upper[i]);
                }
                step_small = free
                    .iter()
                    .all(|&i| (candidate[i] - x[i]).abs() <= 1e-10 * (x[i].abs() + self.scale[i]));
                if self.residuals(&candidate, &mut trial).is_ok() {
                    let new_sse: f64 = trial.iter().map(|v| v * v).sum();
                    if new_sse < sse {
                        let relative = (sse - new_sse) / sse.max(f64::MIN_POSITIVE);
                        let rho = (sse - new_sse) / predicted_reduction(&g, &a, &x, &candidate);
                        x = candidate;
                        std::mem::swap(&mut r, &mut trial);
                        sse = new_sse;
                        lambda = damping_after_success(lambda, rho);
                        accepted = true;
                        path.push(x.clone());
                        if relative < 1e-10 {
                            termination = Termination::SmallCostChange;
                        }
                        break;
                    }
                }
                if step_small {
                    break;
                }
                lambda *= 4.0;
            }
            if termination == Termination::SmallCostChange {
                break;
            }
            if !accepted {
                termination = if step_small {
                    Termination::SmallStep
                } else {
                    Termination::SmallCostChange
                };
                break;
            }
        }
        Some(Run {
            x,
            cost: sse / n as f64,
            iterations,
            termination,
            path,
            aliased: false,
        })
    }

    /// Bounded Nelder–Mead on the MSE from `x` (fminsearch's simplex and coefficients).
    fn nelder_mead(
        &self,
        x: &[f64],
        max_iterations: usize,
        report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
    ) -> Option<Run> {
        let m = x.len();
        let f = |p: &[f64]| self.cost(p).unwrap_or(f64::INFINITY);
        let mut simplex: Vec<(Vec<f64>, f64)> = Vec::with_capacity(m + 1);
        simplex.push((x.to_vec(), f(x)));
        for i in 0..m {
            let mut p = x.to_vec();
            p[i] = if p[i] != 0.0 { 1.05 * p[i] } else { 0.00025 };
            let p = self.clamp(p);
            let v = f(&p);
            simplex.push((p, v));
        }
        let mut path = vec![x.to_vec()];
        let mut termination = Termination::IterationLimit;
        let mut iterations = 0;
        for iteration in 1..=max_iterations {
            iterations = iteration;
            simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
            if report(iteration, simplex[0].1, &simplex[0].0) {
                termination = Termination::Cancelled;
                break;
            }
            if path.last() != Some(&simplex[0].0) {
                path.push(simplex[0].0.clone());
            }
            let spread_f = (simplex[m].1 - simplex[0].1).abs();
            let spread_x = simplex[1..]
                .iter()
                .flat_map(|(p, _)| {
                    p.iter()
                        .zip(&simplex[0].0)
                        .enumerate()
                        .map(|(i, (a, b))| (a - b).abs() / (b.abs() + self.scale[i]))
                })
                .fold(0.0, f64::max);
            if spread_f <= 1e-12 * simplex[0].1.abs().max(f64::MIN_POSITIVE) && spread_x <= 1e-9 {
                termination = Termination::SmallStep;
                break;
            }
            let centroid: Vec<f64> = (0..m)
                .map(|i| simplex[..m].iter().map(|s| s.0[i]).sum::<f64>() / m as f64)
                .collect();
            let along = |t: f64| {
                self.clamp(
                    centroid
                        .iter()
                        .zip(&simplex[m].0)
                        .map(|(c, w)| c + t * (w - c))
                        .collect(),
                )
            };
            let reflected = along(-1.0);
            let fr = f(&reflected);
            if fr < simplex[0].1 {
                let expanded = along(-2.0);
                let fe = f(&expanded);
                simplex[m] = if fe < fr {
                    (expanded, fe)
                } else {
                    (reflected, fr)
                };
            } else if fr < simplex[m - 1].1 {
                simplex[m] = (reflected, fr);
            } else {
                let (contracted, fc) = if fr < simplex[m].1 {
                    let c = along(-0.5);
                    let v = f(&c);
                    (c, v)
                } else {
                    let c = along(0.5);
                    let v = f(&c);
                    (c, v)
                };
                if fc < simplex[m].1.min(fr) {
                    simplex[m] = (contracted, fc);
                } else {
                    let best = simplex[0].0.clone();
                    for s in simplex.iter_mut().skip(1) {
                        let p = self.clamp(
                            best.iter()
                                .zip(&s.0)
                                .map(|(b, v)| b + 0.5 * (v - b))
                                .collect(),
                        );
                        let v = f(&p);
                        *s = (p, v);
                    }
                }
            }
        }
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        let (x, cost) = simplex.swap_remove(0);
        cost.is_finite().then_some(Run {
            x,
            cost,
            iterations,
            termination,
            path,
            aliased: false,
        })
    }

    fn report(&self, run: Run, options: &FitOptions, starts: usize) -> FitReport {
        let model = self.model(&run.x);
        let n = self.data.y.len();
        let p = self.params.len();
        let mut r = vec![0.0; n];
        let ok = self.residuals(&run.x, &mut r).is_ok();
        let sse: f64 = r.iter().map(|v| v * v).sum();
        let mse = sse / n as f64;
        let mean = self.data.y.iter().sum::<f64>() / n as f64;
        let spread = self
            .data
            .y
            .iter()
            .map(|y| (y - mean).powi(2))
            .sum::<f64>()
            .sqrt();
        let fit_percent = if spread > 0.0 {
            100.0 * (1.0 - sse.sqrt() / spread)
        } else {
            f64::NAN
        };
        let aic = n as f64 * mse.max(f64::MIN_POSITIVE).ln()
            + 2.0 * p as f64
            + n as f64 * ((2.0 * std::f64::consts::PI).ln() + 1.0);
        let mut warnings = Vec::new();
        let intervals = if ok {
            self.intervals(&run.x, &r, sse, &mut warnings)
        } else {
            vec![None; p]
        };
        for (i, &param) in self.params.iter().enumerate() {
            for bound in [self.lower[i], self.upper[i]] {
                let tolerance = 1e-6 * (bound.abs() + self.scale[i]);
                if bound.is_finite()
                    && (run.x[i] - bound).abs() <= tolerance
                    && !(param == Param::Td && bound == 0.0)
                {
                    warnings.push(FitWarning::AtBound {
                        param: param.name().into(),
                        bound,
                    });
                }
            }
        }
        if self.structure.underdamped && model.get(Param::Zeta) >= 1.0 {
            warnings.push(FitWarning::OverdampedUnderdamped {
                zeta: model.get(Param::Zeta),
            });
        }
        if let Some(alias) = alias_warning(&model, self.data) {
            warnings.push(alias);
        }
        if run.termination == Termination::IterationLimit {
            warnings.push(FitWarning::NotConverged);
        }
        FitReport {
            params: self
                .params
                .iter()
                .zip(&run.x)
                .zip(intervals)
                .map(|((&param, &value), ci95)| Estimate { param, value, ci95 })
                .collect(),
            model,
            method: options.method,
            n,
            mse,
            rmse: mse.sqrt(),
            fit_percent,
            aic,
            iterations: run.iterations,
            termination: run.termination,
            warnings,
            starts,
            path: run
                .path
                .iter()
                .map(|x| self.fixed.with_vector(&self.params, x))
                .collect(),
        }
    }

    /// 95 % intervals from s²(JᵀJ)⁻¹.
    fn intervals(
        &self,
        x: &[f64],
        r: &[f64],
        sse: f64,
        warnings: &mut Vec<FitWarning>,
    ) -> Vec<Option<(f64, f64)>> {
        let (n, p) = (r.len(), x.len());
        let none = vec![None; p];
        if n <= p {
            return none;
        }
        let Some(j) = self.jacobian(x, r) else {
            return none;
        };
        let a = j.tr_mul(&j);
        let dof = (n - p) as f64;
        let s2 = sse / dof;
        let t = student_t_quantile(0.975, dof);
        // Scale columns so the conditioning reflects the model, not the units.
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
        if singular {
            for (i, param) in self.params.iter().enumerate() {
                if !is_positive(d[i]) {
                    warnings.push(FitWarning::NotIdentifiable {
                        param: param.name().into(),
                    });
                }
            }
            if d.iter().all(|v| *v > 0.0) {
                warnings.push(FitWarning::NotIdentifiable {
                    param: "a combination of the parameters".into(),
                });
            }
            return none;
        }
        let Some(inverse) = scaled.try_inverse() else {
            return none;
        };
        (0..p)
            .map(|i| {
                let variance = s2 * inverse[(i, i)] / (d[i] * d[i]);
                let half = t * variance.max(0.0).sqrt();
                Some((x[i] - half, x[i] + half))
            })
            .collect()
    }
}

/// The fall of the sum of squares that the linearised model predicts for the step from `x`
/// to `candidate`: S − |r + Jd|² = −(2gᵀd + dᵀAd), with g = Jᵀr and A = JᵀJ.
fn predicted_reduction(g: &DVector<f64>, a: &DMatrix<f64>, x: &[f64], candidate: &[f64]) -> f64 {
    let d = DVector::from_iterator(x.len(), x.iter().zip(candidate).map(|(x, c)| c - x));
    -(2.0 * g.dot(&d) + d.dot(&(a * &d)))
}

/// The damping after an accepted step, from the gain ratio ρ = actual / predicted fall
/// (Moré's rule): a step the linear model overrated (ρ < 1/4, as on a poor fit with large
/// residuals, where Gauss–Newton steps overshoot and zigzag along the valley) doubles λ; a
/// step it predicted well (ρ > 3/4) divides λ by three.
fn damping_after_success(lambda: f64, rho: f64) -> f64 {
    if rho.is_nan() || rho < 0.25 {
        (lambda * 2.0).max(1e-6)
    } else if rho > 0.75 {
        (lambda / 3.0).max(1e-12)
    } else {
        lambda
    }
}

/// True for a number above zero (false for NaN).
fn is_positive(x: f64) -> bool {
    x > 0.0
}

/// The alias check: an oscillation faster than the sampling can show (ωd ≥ π/Ts), or a
/// model that swings between samples by more than 10 % of the step's effect beyond what
/// straight lines through its own samples show.
pub fn alias_warning(model: &Model, data: &FitData) -> Option<FitWarning> {
    let ts = data.sampling_period();
    let nyquist = std::f64::consts::PI / ts;
    let omega_d = model.damped_frequency().unwrap_or(0.0);
    let effect = (model.get(Param::Kp) * data.setup.du)
        .abs()
        .max(f64::MIN_POSITIVE);
    let between = between_sample_swing(model, data) / effect;
    (omega_d >= nyquist || between > 0.1).then_some(FitWarning::Alias {
        omega_d,
        nyquist,
        between_samples: between,
    })
}

/// The largest distance between the model on a 16× finer grid and the straight lines
/// through the model's values at the sample instants.
fn between_sample_swing(model: &Model, data: &FitData) -> f64 {
    const REFINE: usize = 16;
    let t = &data.times;
    if t.len() < 2 {
        return 0.0;
    }
    let Ok(at_samples) = model.simulate(&data.setup, t) else {
        return 0.0;
    };
    let fine: Vec<f64> = t
        .windows(2)
        .flat_map(|w| (1..REFINE).map(move |k| w[0] + (w[1] - w[0]) * k as f64 / REFINE as f64))
        .collect();
    let Ok(values) = model.simulate(&data.setup, &fine) else {
        return 0.0;
    };
    let mut worst: f64 = 0.0;
    for (i, w) in t.windows(2).enumerate() {
        for k in 1..REFINE {
            let s = k as f64 / REFINE as f64;
            let line = at_samples[i] + s * (at_samples[i + 1] - at_samples[i]);
            let v = values[i * (REFINE - 1) + k - 1];
            if w[1] > data.setup.t0 {
                worst = worst.max((v - line).abs());
            }
        }
    }
    worst
}

/// A small reproducible generator for the spread-out starts (and the tests' noise).
pub(crate) struct Lcg(pub(crate) u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 11
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        self.next() as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [−1, 1).
    pub(crate) fn symmetric(&mut self) -> f64 {
        2.0 * self.unit() - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn synthetic(code: &str, truth: &[(Param, f64)], noise: f64) -> (FitData, Structure, Values) {
        let structure = Structure::parse(code).unwrap();
        let mut v = Values::default();
        for &(p, x) in truth {
            v.set(p, x);
        }
        let setup = StepSetup { t0: 2.0, du: 2.0 };
        let times: Vec<f64> = (0..400).map(|k| 0.1 * k as f64).collect();
        let mut y = Model::new(structure, v).simulate(&setup, &times).unwrap();
        let mut rng = Lcg(9);
        for v in y.iter_mut() {
            *v += noise * rng.symmetric();
        }
        (FitData { times, y, setup }, structure, v)
    }

    #[test]
    fn recovers_a_p1d_from_a_rough_guess() {
        let truth = [
            (Param::Kp, 1.5),
            (Param::Tp1, 4.0),
            (Param::Td, 1.2),
            (Param::Y0, 3.0),
        ];
        let (data, s, _) = synthetic("P1D", &truth, 0.0);
        let mut guess = Values::default();
        guess.set(Param::Kp, 1.0);
        guess.set(Param::Tp1, 1.0);
        guess.set(Param::Td, 0.3);
        guess.set(Param::Y0, 2.0);
        let options = FitOptions {
            starts: 1,
            ..Default::default()
        };
        let r = fit(&data, s, guess, &options, &mut ()).unwrap();
        eprintln!("{:?} {} {:?}", r.termination, r.iterations, r.warnings);
        for (p, x) in truth {
            assert!(
                (r.model.get(p) - x).abs() < 1e-6 * x.abs().max(1.0),
                "{p:?}: {}",
                r.model.get(p)
            );
        }
        assert!(r.mse < 1e-20, "{}", r.mse);
        assert!(r.fit_percent > 99.999);
    }

    #[test]
    fn intervals_cover_the_truth_with_noise() {
        let truth = [
            (Param::Kp, 0.7),
            (Param::Tp1, 20.0),
            (Param::Tp2, 5.0),
            (Param::Y0, 20.0),
        ];
        let (data, s, v) = synthetic("P2", &truth, 0.01);
        let r = fit(&data, s, v, &FitOptions::default(), &mut ()).unwrap();
        let (lo, hi) = r.interval(Param::Kp).unwrap();
        assert!(lo < 0.7 && 0.7 < hi, "[{lo}, {hi}]");
        assert!(hi - lo < 0.05);
        // Noise uniform ±0.01 has standard deviation 0.01/√3.
        assert!((r.rmse - 0.01 / 3f64.sqrt()).abs() < 0.002, "{}", r.rmse);
    }

    #[test]
    fn nelder_mead_converges_too() {
        let truth = [(Param::Kp, 2.0), (Param::Tp1, 3.0), (Param::Y0, 1.0)];
        let (data, s, _) = synthetic("P1", &truth, 0.0);
        let mut guess = Values::default();
        guess.set(Param::Kp, 1.0);
        guess.set(Param::Tp1, 1.0);
        guess.set(Param::Y0, 0.0);
        let options = FitOptions {
            method: Method::NelderMead,
            starts: 1,
            ..Default::default()
        };
        let r = fit(&data, s, guess, &options, &mut ()).unwrap();
        assert!((r.model.get(Param::Kp) - 2.0).abs() < 1e-4, "{:?}", r.model);
        assert!((r.model.get(Param::Tp1) - 3.0).abs() < 1e-3);
    }

    #[test]
    fn cancelling_stops_and_says_so() {
        struct CancelAfter(usize);
        impl FitObserver for CancelAfter {
            fn progress(&mut self, _: &Progress) {
                self.0 = self.0.saturating_sub(1);
            }
            fn cancelled(&self) -> bool {
                self.0 == 0
            }
        }
        let (data, s, v) = synthetic(
            "P2",
            &[(Param::Kp, 1.0), (Param::Tp1, 3.0), (Param::Tp2, 1.0)],
            0.01,
        );
        let r = fit(&data, s, v, &FitOptions::default(), &mut CancelAfter(3)).unwrap();
        assert_eq!(r.termination, Termination::Cancelled);
    }

    #[test]
    fn too_few_samples_and_bad_steps_are_refused() {
        let data = FitData {
            times: vec![0.0, 1.0],
            y: vec![0.0, 1.0],
            setup: StepSetup { t0: 0.0, du: 1.0 },
        };
        let s = Structure::parse("P2DU").unwrap();
        assert!(matches!(
            fit(&data, s, Values::default(), &FitOptions::default(), &mut ()),
            Err(FitError::TooFewSamples { .. })
        ));
        let data = FitData {
            setup: StepSetup { t0: 0.0, du: 0.0 },
            ..data
        };
        assert!(matches!(
            fit(&data, s, Values::default(), &FitOptions::default(), &mut ()),
            Err(FitError::BadStep(_))
        ));
    }
}
