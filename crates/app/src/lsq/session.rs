//! The least-squares session: what the mode holds and does, with no egui in it. It reads the
//! Identify mode's record (the samples its fit sees: window and filter applied, the input as
//! the model sees it, as [`Samples`]) and its continuous fit, and owns the ARX orders and fit with its AIC
//! grid and d2c, the notes' three-sample example, the RLS animation, the PRBS designer, and
//! the estimation/validation split with its results (the continuous model's in the
//! background).
//!
//! Views read a `&Session` and return [`Command`]s; [`Session::apply`] carries them out once
//! per frame. A new record, new orders or a new split drop whatever described the old ones.

use crate::dialog::Pick;
use crate::identify;
use crate::identify::session::Shown;
use crate::job::{Job, Waker};
use degrau_ident::fit::{FitData, FitOptions};
use degrau_ident::lsq::arx::{
    self, ArxFit, ArxOrders, Candidate, LeastSquares, LsqError, Offset, Regression, Regressor,
    Start,
};
use degrau_ident::lsq::rls::RlsOptions;
use degrau_ident::lsq::validation::{
    self, ArxValidation, ContinuousValidation, Split, ValidationError,
};
use degrau_ident::model::Model;
use degrau_lti::TransferFunction;
use degrau_lti::discrete::DiscreteError;

use super::advisor::Advice;
use super::animation::Animation;
use super::commands::{Command, ExampleModel, Outcome, Section};
use super::designer::{DesignError, Designed, ModelSource, PrbsSettings};
use super::samples::Samples;

/// The notes' three samples (u, y).
pub const EXAMPLE_U: [f64; 3] = [0.0, 1.0, 2.0];
pub const EXAMPLE_Y: [f64; 3] = [0.0, 0.9, 2.1];

/// An ARX fit with what is derived from it.
#[derive(Debug, Clone)]
pub struct ArxResult {
    pub fit: ArxFit,
    /// The AIC grid around the orders, best first.
    pub grid: Result<Vec<Candidate>, LsqError>,
    /// The continuous G(s)·e^{−θs} of the ARX model.
    pub d2c: Result<TransferFunction, DiscreteError>,
}

/// One of the notes' example models, solved.
#[derive(Debug, Clone)]
pub struct ExampleFit {
    pub model: ExampleModel,
    pub regression: Result<Regression, LsqError>,
    pub lsq: Result<LeastSquares, LsqError>,
}

/// The regressors of an example model.
pub fn example_regressors(model: ExampleModel) -> Vec<Regressor> {
    match model {
        ExampleModel::Constant => vec![Regressor::Constant],
        ExampleModel::Line => vec![Regressor::Constant, Regressor::Input(0)],
        ExampleModel::TwoInputs => vec![
            Regressor::Constant,
            Regressor::Input(0),
            Regressor::Input(1),
        ],
    }
}

/// The notes' example model solved on the three samples (signals 0 before them, as the
/// notes take them).
pub fn solve_example(model: ExampleModel) -> ExampleFit {
    let regression = arx::regression(
        &EXAMPLE_U,
        &EXAMPLE_Y,
        &example_regressors(model),
        Start::Zeros,
    );
    let lsq = regression
        .as_ref()
        .map_err(Clone::clone)
        .and_then(arx::least_squares);
    ExampleFit {
        model,
        regression,
        lsq,
    }
}

/// ARX and RLS estimated on the first part, scored on the rest.
#[derive(Debug, Clone)]
pub struct Validation {
    pub arx: Result<ArxValidation, LsqError>,
    pub rls: Result<ArxValidation, LsqError>,
    /// The first validation sample.
    pub split: Result<usize, LsqError>,
}

/// What the last export said.
#[derive(Debug, Clone, PartialEq)]
pub enum ExportNote {
    Saved(String),
    Failed {
        path: String,
        reason: String,
    },
    /// The record was handed to the Identify mode.
    Used,
}

type ContinuousJob = Job<(), Result<ContinuousValidation, ValidationError>>;

/// The least-squares mode's state.
pub struct Session {
    pub section: Section,
    /// The fit data the samples were built from.
    source: Option<FitData>,
    pub samples: Option<Samples>,
    /// The Identify mode's fitted model and its output at the samples.
    pub continuous: Option<(Model, Vec<f64>)>,
    pub orders: ArxOrders,
    pub offset: Offset,
    pub arx: Option<Result<ArxResult, LsqError>>,
    pub example: ExampleModel,
    /// The three example models, solved.
    pub examples: Vec<ExampleFit>,
    pub rls_options: RlsOptions,
    pub animation: Option<Result<Animation, LsqError>>,
    pub prbs: PrbsSettings,
    pub designed: Option<Result<Designed, DesignError>>,
    /// The Design mode's G(s) the test was designed with.
    design_used: Option<TransferFunction>,
    pub export_note: Option<ExportNote>,
    pub split: Split,
    pub validation: Option<Validation>,
    continuous_job: Option<ContinuousJob>,
    pub continuous_validation: Option<Result<ContinuousValidation, ValidationError>>,
    /// The sampling and amplitude rules on the record with the Identify mode's model.
    pub advice: Option<Advice>,
    waker: Option<Waker>,
}

impl Default for Session {
    fn default() -> Self {
        Self {
            section: Section::default(),
            source: None,
            samples: None,
            continuous: None,
            orders: ArxOrders::new(1, 1, 1),
            offset: Offset::Initial,
            arx: None,
            example: ExampleModel::default(),
            examples: ExampleModel::ALL.into_iter().map(solve_example).collect(),
            rls_options: RlsOptions::default(),
            animation: None,
            prbs: PrbsSettings::default(),
            designed: None,
            design_used: None,
            export_note: None,
            split: Split::Fraction(0.5),
            validation: None,
            continuous_job: None,
            continuous_validation: None,
            advice: None,
            waker: None,
        }
    }
}

impl Session {
    /// Hands in what wakes the UI when the background validation ends.
    pub fn set_waker(&mut self, waker: Waker) {
        self.waker = Some(waker);
    }

    pub fn has_waker(&self) -> bool {
        self.waker.is_some()
    }

    /// Takes in the Identify mode's record and fit when they changed: a new record drops
    /// everything fitted on the old one and fits the ARX orders on it.
    pub fn sync(&mut self, ident: &identify::Session, design: Option<&TransferFunction>) {
        let loaded = ident.loaded.as_ref();
        let data = loaded.and_then(|l| l.data.as_ref().ok());
        if data != self.source.as_ref() {
            self.source = data.cloned();
            self.advice = None;
            self.samples = loaded.zip(data).map(|(l, d)| Samples::of(&l.test, d));
            self.continuous = None;
            self.record_changed();
        }
        // The fit shown in the Identify mode: its own, or a row of its diagnosis chain.
        let fitted = match ident.shown() {
            Some((m, Shown::Fitted | Shown::ChainRow(_))) => Some(m),
            _ => None,
        };
        if fitted != self.continuous.as_ref().map(|c| c.0) {
            self.continuous = match (fitted, &self.source) {
                (Some(m), Some(d)) => m.simulate(&d.input, &d.times).ok().map(|y| (m, y)),
                _ => None,
            };
        }
        self.advise(ident);
        let design_changed =
            self.prbs.source == ModelSource::Design && design != self.design_used.as_ref();
        if self.designed.is_none() || design_changed {
            self.redesign(design);
        }
    }

    /// The rules on the record with the Identify mode's model (its fit, or the guess), when
    /// either changed.
    fn advise(&mut self, ident: &identify::Session) {
        let shown = match ident.shown() {
            Some((m, Shown::Fitted | Shown::ChainRow(_))) => Some((m, true)),
            Some((m, Shown::Guess)) => Some((m, false)),
            _ => None,
        };
        let current = self.advice.as_ref().map(|a| (a.model, a.fitted));
        if shown != current || self.advice.is_some() != self.source.is_some() {
            self.advice = match (shown, &self.source) {
                (Some((m, fitted)), Some(d)) => Some(Advice::new(d, m, fitted)),
                _ => None,
            };
        }
    }

    /// The record changed: what described the old one goes, the ARX orders are fitted.
    fn record_changed(&mut self) {
        self.animation = None;
        self.forget_continuous_validation();
        self.fit();
        self.revalidate();
    }

    /// Carries out one command; `ident` is the Identify mode (its experiment and model code
    /// for the continuous validation), `design` the Design mode's G(s) if valid.
    pub fn apply(
        &mut self,
        command: Command,
        ident: &identify::Session,
        design: Option<&TransferFunction>,
    ) -> Option<Outcome> {
        match command {
            Command::SetSection(s) => self.section = s,
            Command::SetOrders(o) => {
                if o != self.orders {
                    self.orders = o;
                    self.settings_changed();
                }
            }
            Command::SetOffset(o) => {
                if o != self.offset {
                    self.offset = o;
                    self.settings_changed();
                }
            }
            Command::Fit => self.fit(),
            Command::FitOrders(o) => {
                self.orders = o;
                self.settings_changed();
                self.fit();
            }
            Command::SetExample(m) => self.example = m,
            Command::SetLambda(l) => self.set_rls(RlsOptions {
                lambda: l,
                ..self.rls_options.clone()
            }),
            Command::SetAlpha(a) => self.set_rls(RlsOptions {
                alpha: a,
                ..self.rls_options.clone()
            }),
            Command::RlsRun => {
                if let Some(a) = self.animation_ready() {
                    if a.finished() {
                        self.rls_reset();
                    }
                    if let Some(Ok(a)) = self.animation.as_mut() {
                        a.running = true;
                    }
                }
            }
            Command::RlsPause => {
                if let Some(Ok(a)) = self.animation.as_mut() {
                    a.running = false;
                }
            }
            Command::RlsStep => {
                if let Some(a) = self.animation_ready() {
                    a.running = false;
                    a.step();
                }
            }
            Command::RlsReset => self.rls_reset(),
            Command::SetPrbs(s) => {
                self.prbs = s;
                self.redesign(design);
                self.export_note = None;
            }
            Command::BrowsePrbsExport => return Some(Outcome::Pick(Pick::PrbsCsv)),
            Command::ExportPrbs(path) => self.export(&path),
            Command::UsePrbs => {
                if let Some(Ok(d)) = &self.designed {
                    self.export_note = Some(ExportNote::Used);
                    self.section = Section::Arx;
                    return Some(Outcome::UseRecord(degrau_ident::lsq::prbs::to_csv(
                        &d.record,
                    )));
                }
            }
            Command::SetSplit(s) => {
                if s != self.split {
                    self.split = s;
                    self.forget_continuous_validation();
                    self.revalidate();
                }
            }
            Command::ValidateContinuous => self.start_continuous_validation(ident),
            Command::CancelContinuous => self.forget_continuous_validation(),
        }
        None
    }

    /// The PRBS test designed again (`design`: the Design mode's G(s) it may use).
    fn redesign(&mut self, design: Option<&TransferFunction>) {
        self.design_used = design.cloned();
        self.designed = Some(self.prbs.design(design));
    }

    /// The orders or the offset changed: the fit, the animation and the validation go.
    fn settings_changed(&mut self) {
        self.arx = None;
        self.animation = None;
        self.revalidate();
    }

    fn set_rls(&mut self, options: RlsOptions) {
        if options != self.rls_options {
            self.rls_options = options;
            self.animation = None;
            self.revalidate();
        }
    }

    /// Fits the ARX orders on the record, with the AIC grid around them and the d2c.
    fn fit(&mut self) {
        let Some(s) = &self.samples else {
            self.arx = None;
            return;
        };
        let (o, offset) = (self.orders, self.offset);
        self.arx = Some(
            arx::arx(&s.time, &s.u, &s.y, o, offset).map(|fit| ArxResult {
                grid: arx::select_orders(&s.time, &s.u, &s.y, &aic_grid(o), offset),
                d2c: fit.model.discrete().and_then(|d| d.d2c()),
                fit,
            }),
        );
    }

    /// The animation, made fresh if there is none; `None` without a record or with a
    /// refusal (kept to be shown).
    fn animation_ready(&mut self) -> Option<&mut Animation> {
        if self.animation.is_none() {
            self.rls_reset();
        }
        self.animation.as_mut()?.as_mut().ok()
    }

    fn rls_reset(&mut self) {
        self.animation = self
            .samples
            .as_ref()
            .map(|s| Animation::new(s, self.orders, self.offset, &self.rls_options));
    }

    /// One frame of the RLS animation; whether it wants another frame.
    pub fn tick(&mut self) -> bool {
        match self.animation.as_mut() {
            Some(Ok(a)) => a.tick(),
            _ => false,
        }
    }

    /// Whether the RLS animation is running.
    pub fn is_running(&self) -> bool {
        matches!(&self.animation, Some(Ok(a)) if a.running)
    }

    fn export(&mut self, path: &std::path::Path) {
        let Some(Ok(d)) = &self.designed else { return };
        let shown = path.display().to_string();
        self.export_note = Some(
            match std::fs::write(path, degrau_ident::lsq::prbs::to_csv(&d.record)) {
                Ok(()) => ExportNote::Saved(shown),
                Err(e) => ExportNote::Failed {
                    path: shown,
                    reason: e.to_string(),
                },
            },
        );
    }

    /// ARX and RLS estimated before the split and scored after it.
    fn revalidate(&mut self) {
        let Some(s) = &self.samples else {
            self.validation = None;
            return;
        };
        let (o, offset, split) = (self.orders, self.offset, self.split);
        self.validation = Some(Validation {
            arx: validation::validate_arx(&s.time, &s.u, &s.y, o, offset, split).map(|v| v.1),
            rls: validation::validate_rls(
                [&s.time, &s.u, &s.y],
                o,
                offset,
                &self.rls_options,
                split,
            )
            .map(|v| v.1),
            split: validation::split_index(&s.time, split),
        });
    }

    /// Fits the Identify mode's model code on the estimation part in the background.
    fn start_continuous_validation(&mut self, ident: &identify::Session) {
        let Some(l) = ident.loaded.as_ref() else {
            return;
        };
        let Ok(data) = l.data.clone() else { return };
        self.forget_continuous_validation();
        let experiment = l.experiment.clone();
        let code = l.structure.code();
        let split = self.split;
        let options = FitOptions {
            method: ident.settings.method,
            starts: if ident.settings.multistart {
                ident.settings.starts.max(1)
            } else {
                1
            },
            ..FitOptions::default()
        };
        self.continuous_job = Some(Job::spawn(self.waker.clone(), move |_| {
            validation::validate_continuous(&experiment, &data, &code, split, &options)
        }));
    }

    fn forget_continuous_validation(&mut self) {
        if let Some(j) = self.continuous_job.take() {
            j.cancel();
        }
        self.continuous_validation = None;
    }

    pub fn is_validating(&self) -> bool {
        self.continuous_job.is_some()
    }

    /// Takes in a finished background validation; whether anything changed.
    pub fn poll(&mut self) -> bool {
        let Some(job) = self.continuous_job.as_mut() else {
            return false;
        };
        match job.poll() {
            Some(result) => {
                self.continuous_validation = Some(result);
                self.continuous_job = None;
                true
            }
            None => false,
        }
    }

    /// The notes' example model chosen.
    pub fn example_fit(&self) -> Option<&ExampleFit> {
        self.examples.iter().find(|e| e.model == self.example)
    }

    /// The ARX fit, if it succeeded.
    pub fn arx_fit(&self) -> Option<&ArxResult> {
        self.arx.as_ref()?.as_ref().ok()
    }

    /// The time of the first validation sample, when the split is valid.
    pub fn split_time(&self) -> Option<f64> {
        let k = *self.validation.as_ref()?.split.as_ref().ok()?;
        self.samples.as_ref()?.time.get(k).copied()
    }
}

/// The AIC grid around `orders`: na and nb from 1 to 3, nk from one below to one above.
pub fn aic_grid(orders: ArxOrders) -> Vec<ArxOrders> {
    let mut grid = Vec::new();
    for na in 1..=3 {
        for nb in 1..=3 {
            for nk in orders.nk.saturating_sub(1)..=orders.nk + 1 {
                grid.push(ArxOrders::new(na, nb, nk));
            }
        }
    }
    grid
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_notes_example_models() {
        // E = [−1, −0.1, 1.1] for the constant: J = 2.22 (the notes round it to 2.2).
        let want: [(&[f64], f64); 3] = [
            (&[1.0], 2.22),
            (&[-0.05, 1.05], 0.015),
            (&[0.0, 0.9, 0.3], 0.0),
        ];
        for (model, (theta, j)) in ExampleModel::ALL.into_iter().zip(want) {
            let fit = solve_example(model).lsq.unwrap();
            for (a, b) in fit.theta.iter().zip(theta) {
                assert!((a - b).abs() < 1e-12, "{model:?}: {a} vs {b}");
            }
            assert!((fit.j - j).abs() < 1e-12, "{model:?}: J = {}", fit.j);
        }
    }
}
