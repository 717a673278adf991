//! The session's background jobs: the fit (with its progress and cancel), the diagnosis
//! (the whole loop or one step), the per-step fits and the cost landscape, what each said
//! last ([`Status`], [`DiagnoseNote`]), and [`Session::poll`], which takes in what they sent.

use degrau_ident::diagnose::tracker::{DiagnoseProgress, Tracker};
use degrau_ident::diagnose::{self, Cause, DiagnoseOptions, DiagnoseReport, Step};
use degrau_ident::experiment::ExperimentError;
use degrau_ident::fit::{FitError, FitObserver, FitOptions, FitReport, Progress, Termination, fit};
use degrau_ident::model::Param;

use super::super::commands::LandscapeCommand;
use super::Session;
use crate::job::{self, Job};

/// What the fit said last, beside the Fit button.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Status {
    #[default]
    Idle,
    Fitting,
    Progress {
        start: usize,
        starts: usize,
        iteration: usize,
        cost: f64,
        best_cost: f64,
    },
    Cancelling,
    Fitted {
        termination: Termination,
        starts: usize,
        iterations: usize,
    },
    FromDiagnosis {
        termination: Termination,
        iterations: usize,
    },
    FitFailed(FitError),
    /// The structure cannot be built on these data.
    Structure(ExperimentError),
}

/// What the diagnosis said last.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum DiagnoseNote {
    #[default]
    None,
    RunningLoop,
    LookingForCause,
    /// The loop's verdict.
    Verdict(Option<degrau_ident::diagnose::Verdict>),
    Cause(Cause),
    /// No extension pays for itself.
    Adequate,
    /// The student cancelled it.
    Cancelled,
}

/// What a background diagnosis returns.
pub(super) enum DiagnoseOutcome {
    /// The whole loop ran.
    Loop(Box<DiagnoseReport>),
    /// One step was asked for: the leading cause (or none).
    Step(Option<Box<Step>>),
}

pub(super) type FitJob = Job<Progress, Result<FitReport, FitError>>;

impl Session {
    /// Takes what the jobs sent; true while one of them runs.
    pub fn poll(&mut self) -> bool {
        self.poll_fit();
        self.poll_diagnosis();
        self.landscape.poll();
        self.per_step.poll();
        self.refresh_plots();
        let hand_fitting = self.hand.poll();
        hand_fitting
            || self.job.is_some()
            || self.diagnose_job.is_some()
            || self.landscape.is_computing()
            || self.per_step.is_running()
    }

    /// Starts the per-step fits of the current fit's data and structure (nothing for a
    /// record with one change).
    pub(super) fn start_per_step(&mut self) {
        let (Some(report), Some((_, data))) = (&self.report, &self.fitted) else {
            return;
        };
        let options = FitOptions {
            method: self.settings.method,
            ..FitOptions::default()
        };
        self.per_step.start(
            data.clone(),
            report.model.structure,
            options,
            self.waker.clone(),
        );
    }

    /// Stops a diagnosis (it ends at its next fit; what it found is not used).
    pub(super) fn cancel_diagnosis(&mut self) {
        if let Some(job) = self.diagnose_job.take() {
            job.cancel();
            self.diagnose_note = DiagnoseNote::Cancelled;
        }
    }

    /// Starts the whole loop (`whole`) or one step from the current fit, off the UI thread.
    pub(super) fn start_diagnosis(&mut self, whole: bool) {
        if self.is_diagnosing() || self.is_fitting() {
            return;
        }
        let (Some(report), Some((_, data))) = (self.current_fit(), self.fitted.clone()) else {
            return;
        };
        self.diagnose_note = if whole {
            DiagnoseNote::RunningLoop
        } else {
            DiagnoseNote::LookingForCause
        };
        self.diagnose_job = Some(Job::spawn(self.waker.clone(), move |ctx| {
            if whole {
                let options = DiagnoseOptions::default();
                let send = |p: DiagnoseProgress| ctx.report(p);
                let stop = || ctx.cancelled();
                let tracker = Tracker::new(Some(&send), Some(&stop), options.max_steps);
                let chain = diagnose::diagnose_tracked(&data, report, &options, &tracker);
                DiagnoseOutcome::Loop(Box::new(chain))
            } else {
                DiagnoseOutcome::Step(diagnose::next_step(&data, &report).map(Box::new))
            }
        }));
    }

    /// The last fit of the chain, or the fit.
    pub(super) fn current_fit(&self) -> Option<FitReport> {
        match &self.diagnosis {
            Some(d) => Some(d.final_fit.clone()),
            None => self.report.clone(),
        }
    }

    pub(super) fn poll_diagnosis(&mut self) {
        let Some(result) = self.diagnose_job.as_mut().and_then(|j| j.poll()) else {
            return;
        };
        self.diagnose_job = None;
        match result {
            DiagnoseOutcome::Loop(d) => {
                self.diagnose_note = DiagnoseNote::Verdict(d.verdict);
                self.selected_step = Some(d.steps.len());
                self.adopt(&d.final_fit);
                self.diagnosis = Some(*d);
            }
            DiagnoseOutcome::Step(Some(step)) => {
                let start = self.report.clone();
                let d = self.diagnosis.get_or_insert_with(|| DiagnoseReport {
                    start: start.unwrap_or_else(|| step.fit.clone()),
                    steps: Vec::new(),
                    final_fit: step.fit.clone(),
                    adequate: false,
                    verdict: None,
                    static_gain: (0.0, None),
                    gain_trade: None,
                    test_causes: Vec::new(),
                });
                d.final_fit = step.fit.clone();
                d.static_gain = (step.fit.model.get(Param::Kp), step.fit.interval(Param::Kp));
                d.steps.push(*step.clone());
                self.selected_step = Some(d.steps.len());
                self.diagnose_note = DiagnoseNote::Cause(step.cause);
                self.adopt(&step.fit);
            }
            DiagnoseOutcome::Step(None) => {
                self.diagnose_note = DiagnoseNote::Adequate;
                if let Some(d) = &mut self.diagnosis {
                    d.adequate = true;
                }
            }
        }
    }

    /// Makes a fit of the chain the current one (its structure, values and code).
    pub(super) fn adopt(&mut self, fit: &FitReport) {
        self.settings.code = fit.model.structure.code();
        self.settings.drift = fit.model.structure.drift;
        if let Some(l) = self.loaded.as_mut() {
            l.structure = fit.model.structure;
            l.guess = fit.model.values;
        }
        if let Some((s, _)) = &mut self.fitted {
            *s = fit.model.structure;
        }
        self.status = Status::FromDiagnosis {
            termination: fit.termination,
            iterations: fit.iterations,
        };
        self.report = Some(fit.clone());
        self.landscape.forget();
        self.start_per_step();
    }

    /// Starts a fit from the current guess.
    pub(super) fn start_fit(&mut self) {
        if self.is_fitting() {
            return;
        }
        let Some(l) = self.loaded.as_ref() else {
            return;
        };
        let Ok(data) = l.data.clone() else { return };
        let (structure, guess) = (l.structure, l.guess);
        let options = FitOptions {
            method: self.settings.method,
            starts: if self.settings.multistart {
                self.settings.starts.max(1)
            } else {
                1
            },
            ..FitOptions::default()
        };
        self.forget_fit();
        self.fitted = Some((structure, data.clone()));
        self.status = Status::Fitting;
        self.job = Some(Job::spawn(self.waker.clone(), move |job| {
            fit(&data, structure, guess, &options, &mut Relay(job, 0))
        }));
    }

    pub(super) fn cancel_fit(&mut self) {
        if let Some(j) = &self.job {
            j.cancel();
            self.status = Status::Cancelling;
        }
    }

    /// Collects a finished fit, or its progress.
    pub(super) fn poll_fit(&mut self) {
        let Some(job) = self.job.as_mut() else { return };
        match job.poll() {
            Some(Ok(report)) => {
                self.status = Status::Fitted {
                    termination: report.termination,
                    starts: report.starts,
                    iterations: report.iterations,
                };
                if let Some(l) = self.loaded.as_mut() {
                    l.guess = report.model.values;
                }
                self.report = Some(report);
                self.job = None;
                self.clear_diagnosis();
                self.start_per_step();
            }
            Some(Err(e)) => {
                self.status = Status::FitFailed(e);
                self.fitted = None;
                self.job = None;
            }
            None => {
                if let Some(p) = &job.progress
                    && self.status != Status::Cancelling
                {
                    self.status = Status::Progress {
                        start: p.start,
                        starts: p.starts,
                        iteration: p.iteration,
                        cost: p.cost,
                        best_cost: p.best_cost,
                    };
                }
            }
        }
    }

    pub(super) fn landscape_command(&mut self, command: LandscapeCommand) {
        let fit = match (&self.report, &self.fitted) {
            (Some(r), Some((_, d))) => Some((r, d)),
            _ => None,
        };
        self.landscape.apply(command, fit, self.waker.clone());
    }

    pub fn is_diagnosing(&self) -> bool {
        self.diagnose_job.is_some()
    }

    /// How far the running diagnosis has gone, once it has said.
    pub fn diagnose_progress(&self) -> Option<DiagnoseProgress> {
        self.diagnose_job.as_ref().and_then(|j| j.progress)
    }

    pub fn is_fitting(&self) -> bool {
        self.job.is_some()
    }

    /// The fit's progress, while it runs.
    pub fn fit_progress(&self) -> Option<&Progress> {
        self.job.as_ref()?.progress.as_ref()
    }
}

/// Passes a fit's progress to the UI.
struct Relay<'a>(
    &'a job::Context<Progress, Result<FitReport, FitError>>,
    usize,
);

impl FitObserver for Relay<'_> {
    fn progress(&mut self, p: &Progress) {
        // Every 4th iteration is enough for a smooth animation.
        self.1 += 1;
        if self.1 % 4 == 1 {
            self.0.report(p.clone());
        }
    }
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}
