//! The multi-start search of a fit: the starts run (on a long record's reduction, on every
//! core when nobody watches), screened after a few iterations, the best run that is not an
//! alias chosen, then refined on every sample and polished, and reported.

use super::problem::Problem;
use super::report::FitReport;
use super::setup::{FitData, FitError, FitObserver, FitOptions, Method, Progress};
use super::solver::{LeastSquaresProblem, Run, Termination, lm, nelder_mead};
use crate::fit::reduce;
use crate::model::{Structure, Values};

/// Fits `structure` to `data` starting from `guess`.
///
/// On a long record the starts run on its reduction ([`reduce`]: every sample after each
/// input change, fewer as the response settles, each weighted by the samples it stands
/// for); the best of them is then refined on every sample, which the report, its
/// statistics and its intervals use.
pub fn fit(
    data: &FitData,
    structure: Structure,
    guess: Values,
    options: &FitOptions,
    observer: &mut dyn FitObserver,
) -> Result<FitReport, FitError> {
    let every = Samples::Every;
    fit_on(data, structure, guess, options, observer, every, None)
}

/// [`fit`] minimising Σ wᵢ(yᵢ − ŷᵢ)², each sample weighted by `weights` (one per sample,
/// ≥ 0): a step of iteratively reweighted least squares ([`crate::fit::robust`]). It runs on every
/// sample (the weights belong to the samples, not to a reduction's blocks); its n, MSE and
/// intervals count a sample by its weight.
pub fn fit_weighted(
    data: &FitData,
    structure: Structure,
    guess: Values,
    options: &FitOptions,
    weights: &[f64],
) -> Result<FitReport, FitError> {
    if weights.len() != data.y.len() || weights.iter().any(|w| !(w.is_finite() && *w >= 0.0)) {
        return Err(FitError::NonFiniteData);
    }
    fit_on(
        data,
        structure,
        guess,
        options,
        &mut (),
        Samples::Every,
        Some(weights),
    )
}

/// [`fit`] without its last stage on a long record: the best of the starts on the reduced
/// record, its statistics (n, MSE, fit %, AIC, intervals) estimated from the weighted
/// samples, which stand for the whole record's. For comparing many candidate fits of one
/// record (the diagnosis's extension search) before fitting the chosen one on every
/// sample; on a record [`reduce`] leaves as it is, the same as [`fit`]. Nobody watches it:
/// its starts are screened on every core.
pub fn search_fit(
    data: &FitData,
    structure: Structure,
    guess: Values,
    options: &FitOptions,
) -> Result<FitReport, FitError> {
    let reduced = Samples::Reduced;
    fit_on(data, structure, guess, options, &mut (), reduced, None)
}

/// Which samples a fit ends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Samples {
    Every,
    Reduced,
}

pub(super) fn fit_on(
    data: &FitData,
    structure: Structure,
    guess: Values,
    options: &FitOptions,
    observer: &mut dyn FitObserver,
    end_on: Samples,
    weights: Option<&[f64]>,
) -> Result<FitReport, FitError> {
    validate(data, &structure)?;
    let mut problem = Problem::new(data, structure, guess)?;
    problem.root_weights = weights.map(|w| w.iter().map(|w| w.sqrt()).collect());
    let x0 = problem.clamp(problem.fixed.vector(&problem.params));
    // A screen's start is checked by its own first evaluation (a start that cannot be
    // evaluated ends with no finite cost, which a screen drops); any other fit says why.
    if !options.screen && !problem.sse(&x0, None).is_ok_and(f64::is_finite) {
        return Err(match problem.model(&x0).transfer_function() {
            Err(e) => FitError::BadGuess(e),
            Ok(_) => FitError::NonFiniteCost,
        });
    }
    let reduction =
        reduce::reduce(&problem.data.times, &problem.data.input).filter(|_| weights.is_none());
    if reduction.is_some() {
        problem.alias_span = Some(reduce::MIN_SAMPLES);
    }
    let search = reduction.as_ref().map(|r| problem.restricted(r));
    let searched = search.as_ref().unwrap_or(&problem);
    let starts = searched.starts(&x0, options.starts.max(1), options.seed);
    let n = data.y.len() as f64;
    let screens = options.method == Method::LevenbergMarquardt
        && starts.len() > START_SCREEN_KEPT
        && options.max_iterations > START_SCREEN_ITERATIONS;
    let first_pass = FitOptions {
        max_iterations: if screens {
            START_SCREEN_ITERATIONS
        } else {
            options.max_iterations
        },
        ..*options
    };
    let mut runs: Vec<Option<Run>> = Vec::new();
    if observer.watches() {
        for (k, start) in starts.iter().enumerate() {
            if observer.cancelled() {
                break;
            }
            let best_cost = lowest_cost(&runs) / n;
            let mut report = progress(&problem, observer, (k, starts.len()), best_cost);
            runs.push(searched.run(options.method, start, &first_pass, &mut report));
        }
    } else {
        // Independent starts: the same runs, in the same order, on every core.
        runs = crate::parallel::map(&starts, |start| {
            searched.run(options.method, start, &first_pass, &mut |_, _, _| false)
        });
    }
    // A screen: only the lowest unfinished runs go on; the others are dropped.
    let continued = if screens {
        leading_unfinished(&runs, START_SCREEN_KEPT)
    } else {
        Vec::new()
    };
    for &k in &continued {
        if observer.cancelled() {
            break;
        }
        let best_cost = lowest_cost(&runs) / n;
        let mut report = progress(&problem, observer, (k, starts.len()), best_cost);
        if let Some(run) = runs[k].as_mut() {
            searched.go_on(run, options, &mut report);
        }
    }
    let runs: Vec<Run> = runs
        .into_iter()
        .enumerate()
        .filter(|(k, r)| {
            let unfinished = r
                .as_ref()
                .is_some_and(|r| r.termination == Termination::IterationLimit);
            !screens || !unfinished || continued.contains(k)
        })
        .filter_map(|(_, r)| r)
        .collect();
    let cancelled = observer.cancelled();
    let mut run = best_run(runs, &problem).unwrap_or_else(|| Run {
        x: x0.clone(),
        sse: problem.sse(&x0, None).unwrap_or(f64::INFINITY),
        iterations: 0,
        termination: Termination::Cancelled,
        path: vec![x0.clone()],
    });
    let ending = match end_on {
        Samples::Reduced => searched,
        Samples::Every => &problem,
    };
    let refined =
        search.is_some() && end_on == Samples::Every && run.termination != Termination::Cancelled;
    if refined {
        let best_cost = run.sse / n;
        let last = starts.len().saturating_sub(1);
        let mut report = progress(&problem, observer, (last, starts.len()), best_cost);
        problem.refine(&mut run, options, &mut report);
    }
    if cancelled || observer.cancelled() {
        run.termination = Termination::Cancelled;
    } else if options.method == Method::LevenbergMarquardt && !refined && !options.screen {
        ending.polish(&mut run);
    }
    ending.report(run, options, starts.len(), &problem)
}

/// Iterations each start of a multi-start fit runs before the screen ranks them.
const START_SCREEN_ITERATIONS: usize = 5;
/// Unfinished starts that go on to convergence after the screen (the lowest-cost ones).
/// Starts in the same basin agree long before they converge, and one far behind after the
/// screen does not overtake the leaders; the finished ones are all kept.
const START_SCREEN_KEPT: usize = 3;

/// The lowest cost (SSE) among `runs`, infinite when there is none.
fn lowest_cost(runs: &[Option<Run>]) -> f64 {
    runs.iter()
        .flatten()
        .map(|r| r.sse)
        .fold(f64::INFINITY, f64::min)
}

/// The indices of the `kept` runs of lowest cost among those the iteration limit stopped.
fn leading_unfinished(runs: &[Option<Run>], kept: usize) -> Vec<usize> {
    let mut unfinished: Vec<(usize, f64)> = runs
        .iter()
        .enumerate()
        .filter_map(|(k, r)| r.as_ref().map(|r| (k, r)))
        .filter(|(_, r)| r.termination == Termination::IterationLimit)
        .map(|(k, r)| (k, r.sse))
        .collect();
    unfinished.sort_by(|a, b| a.1.total_cmp(&b.1));
    unfinished.into_iter().take(kept).map(|(k, _)| k).collect()
}

/// The run of lowest cost that is not an alias, else the lowest: a run without alias beats
/// any aliased one, since an alias can match the samples better than the true optimum (it
/// does on the LECI data) while being wrong between them. The (costly) alias check runs on
/// the runs in order of cost until one passes, and not at all when there is one run (the
/// report checks the run it ends with).
fn best_run(mut runs: Vec<Run>, problem: &Problem) -> Option<Run> {
    runs.sort_by(|a, b| a.sse.total_cmp(&b.sse));
    let chosen = match runs.len() {
        0 | 1 => 0,
        _ => runs
            .iter()
            .position(|r| problem.alias(&r.x).is_none())
            .unwrap_or(0),
    };
    (chosen < runs.len()).then(|| runs.swap_remove(chosen))
}

/// The progress callback of start `k` of `starts`: reports each iteration to `observer`
/// (costs as MSE over the record's samples) and says whether to cancel.
fn progress<'a>(
    problem: &'a Problem,
    observer: &'a mut dyn FitObserver,
    (k, starts): (usize, usize),
    best_cost: f64,
) -> impl FnMut(usize, f64, &[f64]) -> bool + 'a {
    let n = problem.data.y.len() as f64;
    let watched = observer.watches();
    move |iteration: usize, sse: f64, x: &[f64]| {
        if watched && let Ok(model) = problem.model_out(x) {
            observer.progress(&Progress {
                start: k,
                starts,
                iteration,
                cost: problem.units.mse_out(sse / n),
                best_cost: problem.units.mse_out(best_cost.min(sse / n)),
                model,
            });
        }
        observer.cancelled()
    }
}

fn validate(data: &FitData, structure: &Structure) -> Result<(), FitError> {
    let du = data.input.du_scale();
    if !du.is_finite() || du == 0.0 {
        return Err(FitError::BadStep(du));
    }
    if let Some(t) = data
        .input
        .steps
        .iter()
        .chain(&data.input.ramps)
        .map(|s| s.t)
        .chain([data.input.t0()])
        .find(|t| !t.is_finite())
    {
        return Err(FitError::BadStepTime(t));
    }
    if data.times.iter().chain(&data.y).any(|v| !v.is_finite()) {
        return Err(FitError::NonFiniteData);
    }
    let after = data.times.iter().filter(|&&t| t >= data.input.t0()).count();
    let p = structure.len();
    if after <= p || data.times.len() <= p + 1 || data.y.len() != data.times.len() {
        return Err(FitError::TooFewSamples { n: after, p });
    }
    Ok(())
}

impl Problem {
    /// One local search from `start` by `method`.
    pub(super) fn run(
        &self,
        method: Method,
        start: &[f64],
        options: &FitOptions,
        report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
    ) -> Option<Run> {
        match method {
            Method::LevenbergMarquardt => lm::levenberg_marquardt(
                self,
                start,
                options.max_iterations,
                lm::Stop::CostSettles,
                report,
            ),
            Method::NelderMead => {
                nelder_mead::nelder_mead(self, start, options.max_iterations * 10, report)
            }
        }
    }

    /// Continues a run a screen stopped, from where it stopped, to the whole iteration limit
    /// (the test that stops it is the one the first pass used).
    pub(super) fn go_on(
        &self,
        run: &mut Run,
        options: &FitOptions,
        report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
    ) {
        let left = options.max_iterations.saturating_sub(run.iterations);
        let Some(more) = lm::levenberg_marquardt(self, &run.x, left, lm::Stop::CostSettles, report)
        else {
            return;
        };
        if more.sse <= run.sse {
            run.iterations += more.iterations;
            run.path.extend(more.path.into_iter().skip(1));
            run.x = more.x;
            run.sse = more.sse;
            run.termination = match more.termination {
                Termination::NoImprovement => Termination::SmallCostChange,
                other => other,
            };
        }
    }

    /// Continues `run` (found on a reduced record) on this problem's samples until its steps
    /// are negligible (Levenberg–Marquardt: the polish included): its cost, termination and
    /// path become this record's.
    pub(super) fn refine(
        &self,
        run: &mut Run,
        options: &FitOptions,
        report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
    ) {
        let fine = match options.method {
            Method::LevenbergMarquardt => lm::levenberg_marquardt(
                self,
                &run.x,
                options.max_iterations,
                lm::Stop::StepsSettle,
                report,
            ),
            Method::NelderMead => self.run(options.method, &run.x, options, report),
        };
        match fine {
            Some(fine) => {
                run.iterations += fine.iterations;
                run.path.extend(fine.path.into_iter().skip(1));
                run.x = fine.x;
                run.sse = fine.sse;
                run.termination = match fine.termination {
                    // The reduced record's optimum is already this record's.
                    Termination::NoImprovement => run.termination,
                    other => other,
                };
            }
            None => run.sse = self.sse(&run.x, None).unwrap_or(f64::INFINITY),
        }
    }

    /// Refines a converged run until its steps are negligible, so that the optimum does not
    /// depend on where the cost test happened to stop it (a few iterations at most).
    pub(super) fn polish(&self, run: &mut Run) {
        if matches!(
            run.termination,
            Termination::IterationLimit | Termination::NoImprovement | Termination::Cancelled
        ) {
            return;
        }
        let Some(fine) =
            lm::levenberg_marquardt(self, &run.x, 10, lm::Stop::StepsSettle, &mut |_, _, _| {
                false
            })
        else {
            return;
        };
        if fine.sse < run.sse {
            run.iterations += fine.iterations;
            run.path.extend(fine.path.into_iter().skip(1));
            run.x = fine.x;
            run.sse = fine.sse;
        }
    }
}
