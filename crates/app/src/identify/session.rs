//! The identification session: what the Identify mode holds and does, with no egui in it.
//! It owns the settings, the loaded step test and the choices made on it (the
//! [`Experiment`]), the guess, the background jobs (fit, diagnosis, cost landscape), the fit
//! report and the diagnosis chain, the status, and the data the plots draw (measured
//! samples, model curve, residuals), recomputed only when one of their inputs changed.
//!
//! Views read a `&Session` and return [`Command`]s; [`Session::apply`] carries them out
//! once per frame before anything is drawn. Whatever a change makes stale is dropped at
//! once: a new test, a new structure or a new choice on the test clears the fit, the
//! diagnosis and the status that belonged to the old one.
//!
//! By job: [`settings`] (what is kept between runs), [`loading`] (a test from a file, pasted
//! text or the example), [`jobs`] (the fit, the diagnosis, the per-step fits, the landscape)
//! and [`plots`] (the plots' data and the guess handles); this module keeps the session, what
//! it shows and [`Session::apply`].

mod jobs;
mod loading;
mod plots;
mod settings;
#[cfg(test)]
mod tests;

pub use jobs::{DiagnoseNote, Status};
pub use loading::{LoadError, LoadMessage, Loaded, Source};
pub use plots::{HandleFrame, Plots, Segment};
pub(crate) use plots::{nearest_point, padded_by};
pub use settings::{CODES, Saved};

use jobs::{DiagnoseOutcome, FitJob};
use loading::unit_in;

use std::sync::Arc;

use super::commands::{Choice, Command, Frozen, Gesture, MeasuredMarkers, OffsetChoice, Outcome};
use super::cost::LandscapeState;
use super::steps::{InputPlot, PerStepState, input_plot};
use crate::dialog::Pick;
use crate::job::{Job, Waker};
use degrau_ident::diagnose::tracker::DiagnoseProgress;
use degrau_ident::diagnose::{DiagnoseReport, Step};
use degrau_ident::experiment::{Drive, Experiment, Offset, OperatingPoint};
use degrau_ident::fit::handles::Handle;
use degrau_ident::fit::{FitData, FitReport};
use degrau_ident::model::excitation::{Excitation, Hold};
use degrau_ident::model::{Model, Param, Structure};

/// What the model curve shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    Guess,
    Fitting,
    Fitted,
    /// A row of the diagnosis chain (0: its start).
    ChainRow(usize),
}

/// The identification mode's state.
#[derive(Default)]
pub struct Session {
    pub settings: Saved,
    pub loaded: Option<Loaded>,
    /// The last message about loading.
    pub message: Option<LoadMessage>,
    job: Option<FitJob>,
    pub report: Option<FitReport>,
    /// The structure and data the report belongs to.
    pub fitted: Option<(Structure, FitData)>,
    pub status: Status,
    pub landscape: LandscapeState,
    /// Each input change fitted on its own window (after a fit of a multi-step record).
    pub per_step: PerStepState,
    pub markers: MeasuredMarkers,
    /// The chain of the diagnosis: start fit, then one step per extension.
    pub diagnosis: Option<DiagnoseReport>,
    diagnose_job: Option<Job<DiagnoseProgress, DiagnoseOutcome>>,
    /// Which model of the chain is shown (0: the start).
    pub selected_step: Option<usize>,
    pub diagnose_note: DiagnoseNote,
    /// The hand methods drawn on the measured curve.
    pub hand: super::hand_state::HandState,
    /// The axes held while a handle is dragged.
    pub frozen: Option<Frozen>,
    /// The file the reading choices were last used on (none: typed for the next load).
    choices_used_on: Option<Source>,
    /// Bumped whenever the fit data are rebuilt.
    data_revision: u64,
    plots: Plots,
    /// The input plot, rebuilt with the fit data.
    input_plot: InputPlot,
    plots_key: Option<(u64, Option<Model>, Option<f64>)>,
    waker: Option<Waker>,
}

impl Session {
    /// A session with the given settings, with the test they name loaded again (the example
    /// or the file, with the choices made on it), as it was when the app was closed.
    pub fn with_settings(settings: Saved) -> Self {
        let mut session = Self {
            settings: settings.clone(),
            ..Default::default()
        };
        if settings.example {
            session.load_example();
        } else if !settings.path.is_empty() {
            session.load_path(&settings.path);
        }
        if let (Some(e), Some(l)) = (settings.experiment, session.loaded.as_mut()) {
            l.experiment = e;
            session.rebuild(true);
        }
        session
    }

    /// The settings to keep between runs, with the loaded test's choices.
    pub fn settings_to_save(&self) -> Saved {
        Saved {
            experiment: self.loaded.as_ref().map(|l| l.experiment.clone()),
            ..self.settings.clone()
        }
    }

    /// Hands in what wakes the UI when a job has news.
    pub fn set_waker(&mut self, waker: Arc<dyn Fn() + Send + Sync>) {
        self.waker = Some(waker);
    }

    /// Whether a waker was handed in.
    pub fn has_waker(&self) -> bool {
        self.waker.is_some()
    }

    /// Drops the fit, its diagnosis, its landscape and the status: they describe something
    /// that is no longer shown. A running fit or diagnosis is cancelled and forgotten.
    fn forget_fit(&mut self) {
        if let Some(j) = self.job.take() {
            j.cancel();
        }
        self.diagnose_job = None;
        self.report = None;
        self.fitted = None;
        self.status = Status::Idle;
        self.clear_diagnosis();
        self.landscape.forget();
        self.per_step.forget();
    }

    fn clear_diagnosis(&mut self) {
        self.diagnosis = None;
        self.selected_step = None;
        self.diagnose_note = DiagnoseNote::None;
    }

    /// Recomputes the fit data and structure after a change; `reguess` resets the guess.
    fn rebuild(&mut self, reguess: bool) {
        let Some(l) = self.loaded.as_mut() else {
            return;
        };
        l.data = l.experiment.fit_data(&l.test);
        self.data_revision += 1;
        self.input_plot = l.data.as_ref().map(input_plot).unwrap_or_default();
        let Ok(d) = &l.data else {
            return;
        };
        match l
            .experiment
            .structure(&self.settings.code, self.settings.drift, d)
        {
            Ok(s) => {
                let changed = s != l.structure;
                l.structure = s;
                if reguess || changed {
                    l.guess = l.experiment.guess(s, d);
                }
                if let Status::Structure(_) = self.status {
                    self.status = Status::Idle;
                }
            }
            Err(e) => self.status = Status::Structure(e),
        }
    }

    /// A choice on the test changed: the fit no longer describes these data.
    fn experiment_changed(&mut self, reguess: bool) {
        self.forget_fit();
        self.rebuild(reguess);
    }

    /// Moves the step time t0 (dragged on the plot), keeping the guesses.
    pub fn set_step_time(&mut self, t0: f64) {
        if let Some(l) = self.loaded.as_mut()
            && t0.is_finite()
            && t0 != l.experiment.t0
        {
            l.experiment.t0 = t0;
            l.experiment.drive = Drive::Step;
            self.experiment_changed(false);
        }
    }

    /// The model shown: the running fit's latest, a selected chain row's, the fit's, or the
    /// guess.
    pub fn shown_model(&self) -> Option<Model> {
        self.shown().map(|(m, _)| m)
    }

    /// The model shown and what it is.
    pub fn shown(&self) -> Option<(Model, Shown)> {
        if let Some(job) = &self.job {
            return job
                .progress
                .as_ref()
                .map(|p| (p.model, Shown::Fitting))
                .or_else(|| self.guess_model().map(|m| (m, Shown::Fitting)));
        }
        if let (Some(k), Some(d)) = (self.selected_step, &self.diagnosis) {
            return d.rows().get(k).map(|f| (f.model, Shown::ChainRow(k)));
        }
        let l = self.loaded.as_ref()?;
        match (&self.report, &self.fitted) {
            (Some(r), Some((s, _))) if *s == l.structure => Some((r.model, Shown::Fitted)),
            _ => self.guess_model().map(|m| (m, Shown::Guess)),
        }
    }

    /// The fit whose model is shown: the row of the diagnosis chain chosen, else the last
    /// fit while it still describes what is shown.
    pub fn shown_report(&self) -> Option<&FitReport> {
        match (self.shown(), &self.diagnosis) {
            (Some((_, Shown::ChainRow(k))), Some(d)) => d.rows().get(k).copied(),
            (Some((_, Shown::Fitted)), _) => self.report.as_ref(),
            _ => None,
        }
    }

    /// Whether the values in the model's fields are a fit's (the next fit starts from them).
    pub fn guess_is_fitted(&self) -> bool {
        let Some(l) = self.loaded.as_ref() else {
            return false;
        };
        self.shown_report()
            .is_some_and(|r| r.model.values == l.guess && r.model.structure == l.structure)
    }

    fn guess_model(&self) -> Option<Model> {
        let l = self.loaded.as_ref()?;
        Some(Model::new(l.structure, l.guess))
    }

    /// Sets the guess (a drag on the plot); a previous fit no longer describes what is shown.
    pub fn set_guess(&mut self, model: Model) {
        if let Some(l) = self.loaded.as_mut() {
            l.guess = model.values;
            l.structure = model.structure;
            self.forget_fit();
        }
    }

    /// The interval the selected step's evidence points at.
    pub fn evidence_interval(&self) -> Option<(f64, f64)> {
        let k = self.selected_step?;
        self.diagnosis
            .as_ref()?
            .steps
            .get(k.checked_sub(1)?)?
            .interval
    }

    /// The selected chain step (not the start).
    pub fn selected_chain_step(&self) -> Option<&Step> {
        let k = self.selected_step?.checked_sub(1)?;
        self.diagnosis.as_ref()?.steps.get(k)
    }

    /// The operating point Y0 held by the choice (fixed, or the level before the step), or
    /// `None` when it is estimated with the other parameters.
    pub fn held_operating_point(&self) -> Option<f64> {
        let l = self.loaded.as_ref()?;
        l.experiment.operating_point(l.data.as_ref().ok()?)
    }

    /// The unit of the output, when the record's header names one ("T1 (°C)" → "°C").
    pub fn output_unit(&self) -> Option<String> {
        unit_in(&self.loaded.as_ref()?.test.output_name)
    }

    /// The step setup of the fit data.
    pub fn setup(&self) -> Option<Excitation> {
        Some(self.loaded.as_ref()?.data.as_ref().ok()?.input.clone())
    }

    /// The last time of the fit data (where the final-value handle sits).
    pub fn t_end(&self) -> Option<f64> {
        self.loaded
            .as_ref()?
            .data
            .as_ref()
            .ok()?
            .times
            .last()
            .copied()
    }

    /// The fitted model as a transfer function and the step it was fitted to.
    pub fn fitted_transfer_function(&self) -> Option<(degrau_lti::TransferFunction, f64)> {
        let report = self.shown_report()?;
        let du = self.fitted.as_ref().map_or(1.0, |f| f.1.input.du());
        Some((report.model.transfer_function().ok()?, du))
    }

    /// The fitted model as code for the course's tools.
    pub fn fitted_code(&self, kind: super::commands::CodeKind) -> Option<String> {
        let (tf, du) = self.fitted_transfer_function()?;
        let (num, den, delay) = (tf.num(), tf.den(), tf.delay());
        Some(match kind {
            super::commands::CodeKind::Matlab => crate::words::code::matlab(&num, &den, delay, du),
            super::commands::CodeKind::PythonControl => {
                crate::words::code::python_control(&num, &den, delay, du)
            }
        })
    }

    /// Carries out a command from a view.
    pub fn apply(&mut self, command: Command) -> Option<Outcome> {
        let outcome = self.carry_out(command);
        self.refresh_plots();
        outcome
    }

    fn carry_out(&mut self, command: Command) -> Option<Outcome> {
        match command {
            Command::SetPath(p) => self.settings.path = p,
            Command::LoadPath => {
                let path = self.settings.path.clone();
                self.load_path(&path);
            }
            Command::Open(path) => self.load_path(&path),
            Command::BrowseTest => return Some(Outcome::Pick(Pick::StepTest)),
            Command::BrowseInputFile => return Some(Outcome::Pick(Pick::InputFile)),
            Command::LoadText(text) => self.load_text(&text),
            Command::LoadExample => self.load_example(),
            Command::SetChoice(choice, text) => self.set_choice(choice, text),
            Command::SetStepTime(t0) => self.set_step_time(t0),
            Command::SetStepSize(du) => self.edit_experiment(false, |e| {
                e.du = du;
                e.drive = Drive::Step;
            }),
            Command::SetDrive(drive) => self.set_drive(drive),
            Command::FitEachStep => self.start_per_step(),
            Command::CancelPerStep => self.per_step.cancel(),
            Command::CancelDiagnosis => self.cancel_diagnosis(),
            Command::SetOffset(choice) => self.set_offset(choice),
            Command::SetWindow(window) => self.edit_experiment(false, |e| e.window = window),
            Command::SetFilter(fc) => self.edit_experiment(false, |e| e.filter_hz = fc),
            Command::SetCode(code) => {
                self.settings.code = code;
                self.experiment_changed(true);
            }
            Command::SetDrift(drift) => {
                self.settings.drift = drift;
                self.experiment_changed(true);
            }
            Command::AutoGuess => self.experiment_changed(true),
            Command::SetGuess(p, v) => {
                if let Some(mut m) = self.guess_model() {
                    m.values.set(p, v);
                    self.set_guess(m);
                }
            }
            Command::Handle(g) => self.handle_gesture(g),
            Command::SetMethod(m) => self.settings.method = m,
            Command::SetMultistart(on) => self.settings.multistart = on,
            Command::SetStarts(n) => {
                self.settings.starts = n.clamp(2, degrau_ident::fit::MAX_STARTS)
            }
            Command::Fit => self.start_fit(),
            Command::CancelFit => self.cancel_fit(),
            Command::Diagnose { whole } => self.start_diagnosis(whole),
            Command::SelectStep(k) => self.select_step(k),
            Command::SetMarkers(m) => self.markers = m,
            Command::Landscape(c) => self.landscape_command(c),
            Command::Hand(c) => self.hand.apply(c),
            Command::ShowOnSPlane => {
                return self
                    .fitted_transfer_function()
                    .map(|(tf, du)| Outcome::ShowOnSPlane { tf, du });
            }
            Command::TuneController => {
                let report = self.shown_report()?;
                return Some(Outcome::Tune {
                    model: crate::tune::model::ProcessSettings::from_fitted(&report.model),
                    code: report.model.structure.code(),
                });
            }
        }
        None
    }

    fn set_choice(&mut self, choice: Choice, text: String) {
        let s = &mut self.settings;
        let field = match choice {
            Choice::TimeColumn => &mut s.time_col,
            Choice::OutputColumn => &mut s.y_col,
            Choice::InputColumn => &mut s.u_col,
            Choice::SamplingPeriod => &mut s.sampling_period,
            Choice::InitialInput => &mut s.initial_input,
            Choice::InputFile => &mut s.u_path,
        };
        *field = text;
        // Typed for the next load, whatever file it reads.
        self.choices_used_on = None;
    }

    fn edit_experiment(&mut self, reguess: bool, edit: impl FnOnce(&mut Experiment)) {
        if let Some(l) = self.loaded.as_mut() {
            edit(&mut l.experiment);
            self.experiment_changed(reguess);
        }
    }

    fn set_offset(&mut self, choice: OffsetChoice) {
        let y0 = self.guess_model().map_or(0.0, |m| m.get(Param::Y0));
        let offset = match choice {
            OffsetChoice::Before => Offset::Auto,
            OffsetChoice::Estimate => Offset::Free,
            OffsetChoice::Typed(None) => Offset::Fixed(y0),
            OffsetChoice::Typed(Some(v)) => Offset::Fixed(v),
        };
        // Y0 held or freed changes the structure: the guess is read again.
        self.edit_experiment(true, |e| e.offset = offset);
    }

    fn handle_gesture(&mut self, gesture: Gesture) {
        match gesture {
            Gesture::Grab(frame) => self.frozen = Some(frame),
            Gesture::Release => self.frozen = None,
            Gesture::Move { handle, to } => self.drag_handle(handle, to),
        }
    }

    /// Moves a guess handle to (t, y) on the plot.
    pub fn drag_handle(&mut self, handle: Handle, to: (f64, f64)) {
        // The handle moves the model that is shown.
        let Some(frame) = self.handle_frame() else {
            return;
        };
        if self.is_fitting() || !(to.0.is_finite() && to.1.is_finite()) {
            return;
        }
        self.set_guess(frame.drag(handle, to));
    }

    /// Chooses what drove the test: the measured input (with its hold) or one ideal step
    /// (at the input's largest change, or where it was typed).
    fn set_drive(&mut self, drive: Drive) {
        let Some(l) = self.loaded.as_ref() else {
            return;
        };
        if l.experiment.drive == drive {
            return;
        }
        let (test, initial) = (&l.test, l.experiment.initial_input);
        let (t0, du) = match drive {
            Drive::Step => Experiment::single_step(test, None, None, initial)
                .map(|e| (e.t0, e.du))
                .unwrap_or((l.experiment.t0, l.experiment.du)),
            Drive::Measured { hold } => test
                .input
                .as_deref()
                .and_then(|u| Excitation::measured(&test.time, u, initial, hold))
                .map_or((l.experiment.t0, l.experiment.du), |x| (x.t0(), x.du())),
        };
        self.edit_experiment(true, |e| {
            e.drive = drive;
            e.t0 = t0;
            e.du = du;
        });
    }

    /// Whether the loaded test has an input that changes (the measured drive can be chosen).
    pub fn has_measured_input(&self) -> bool {
        self.loaded.as_ref().is_some_and(|l| {
            l.test.input.as_deref().is_some_and(|u| {
                Excitation::measured(&l.test.time, u, l.experiment.initial_input, Hold::Zoh)
                    .is_some()
            })
        })
    }

    /// What the operating-point choice does with Y0 on the data shown.
    pub fn operating_point_fact(&self) -> Option<OperatingPoint> {
        let l = self.loaded.as_ref()?;
        Some(l.experiment.operating_point_fact(l.data.as_ref().ok()?))
    }

    fn select_step(&mut self, k: usize) {
        if self.diagnosis.as_ref().is_some_and(|d| k < d.rows().len()) {
            self.selected_step = Some(k);
        }
    }
}
