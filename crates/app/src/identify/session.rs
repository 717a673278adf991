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

use degrau_ident::excitation::Excitation;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::commands::{Choice, Command, Gesture, LandscapeCommand, OffsetChoice, Outcome};
use super::cost::LandscapeState;
use super::steps::{InputPlot, PerStepState, input_plot};
use crate::field::{FieldError, parse_number};
use crate::job::{self, Job, Waker};
use degrau_ident::data::{self, DataError, LoadOptions, StepTest};
use degrau_ident::diagnose::{self, Cause, DiagnoseOptions, DiagnoseReport, Step};
use degrau_ident::excitation::{Hold, InputChange};
use degrau_ident::experiment::{Drive, Experiment, ExperimentError, Offset, OperatingPoint};
use degrau_ident::fit::{
    FitData, FitError, FitObserver, FitOptions, FitReport, Method, Progress, Termination, fit,
};
use degrau_ident::handles::{self, Handle};
use degrau_ident::models::{Model, ModelError, Param, Structure, Values};
use degrau_ident::tracker::{DiagnoseProgress, Tracker};
use degrau_lti::{StepInfo, StepInfoOptions};

/// The LECI step test of the course notes (`t, y`), shipped with the app.
const LECI_EXAMPLE: &str = include_str!("../../../../assets/leci_step.csv");

/// Points of the model curve drawn over the record.
const CURVE_POINTS: usize = 800;

/// The model codes offered, in the order of the notes.
pub const CODES: [&str; 13] = [
    "P1", "P1D", "P2", "P2D", "P2U", "P2DU", "P2Z", "P2DZ", "P2DUZ", "P3", "P3D", "P1I", "P1DI",
];

/// Choices kept between runs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub path: String,
    /// The shipped example is what is loaded (it has no path).
    pub example: bool,
    /// The step, operating point, window and filter chosen on the loaded test, restored
    /// with it after a restart.
    pub experiment: Option<Experiment>,
    pub time_col: String,
    pub y_col: String,
    pub u_col: String,
    /// Sampling period (s) for files without a time column (empty: none).
    pub sampling_period: String,
    /// The input before the record started, for a test whose step came at the first sample
    /// (empty: none).
    pub initial_input: String,
    /// A second file that holds the input, joined on time (empty: the input is a column of
    /// the test's own file).
    pub u_path: String,
    pub code: String,
    pub drift: bool,
    pub method: Method,
    pub multistart: bool,
    pub starts: usize,
}

impl Default for Saved {
    fn default() -> Self {
        Self {
            path: String::new(),
            example: false,
            experiment: None,
            time_col: String::new(),
            y_col: String::new(),
            u_col: String::new(),
            sampling_period: String::new(),
            initial_input: String::new(),
            u_path: String::new(),
            code: "P2DU".into(),
            drift: false,
            method: Method::LevenbergMarquardt,
            multistart: true,
            starts: 16,
        }
    }
}

impl Saved {
    /// The reading choices that are not automatic, as typed.
    fn reading_choices(&self) -> Vec<(Choice, String)> {
        [
            (Choice::TimeColumn, &self.time_col),
            (Choice::OutputColumn, &self.y_col),
            (Choice::InputColumn, &self.u_col),
            (Choice::SamplingPeriod, &self.sampling_period),
            (Choice::InitialInput, &self.initial_input),
        ]
        .into_iter()
        .filter(|(_, text)| !text.trim().is_empty())
        .map(|(c, text)| (c, text.trim().to_string()))
        .collect()
    }

    fn clear_reading_choices(&mut self) {
        for text in [
            &mut self.time_col,
            &mut self.y_col,
            &mut self.u_col,
            &mut self.sampling_period,
            &mut self.initial_input,
        ] {
            text.clear();
        }
    }
}

/// Where a test came from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    File(String),
    Example,
    Pasted,
}

/// Why a test did not load.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadError {
    /// A reading choice that is not a number.
    Choice { choice: Choice, error: FieldError },
    /// The loader's refusal.
    Data(DataError),
    /// The model code cannot be read.
    Model(ModelError),
}

/// What the last load said.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadMessage {
    Loaded {
        samples: usize,
        source: Source,
        /// The loader's notes.
        notes: Vec<degrau_ident::data::DataNote>,
        /// The step could not be read off the input: what was used instead.
        step_missing: Option<(ExperimentError, f64)>,
        /// Reading choices typed for this load and used for it.
        kept: Vec<(Choice, String)>,
        /// Reading choices made on the previous file, cleared for this one.
        cleared: Vec<(Choice, String)>,
    },
    /// The shipped example, set up as the notes set it up.
    Example {
        samples: usize,
        du: f64,
        t0: f64,
        y0: f64,
    },
    Failed {
        source: Source,
        error: LoadError,
        /// A test loaded before is still there.
        kept: bool,
    },
}

/// A loaded test and what was chosen on it.
pub struct Loaded {
    pub test: StepTest,
    pub experiment: Experiment,
    /// The samples the fit sees (window and filter applied).
    pub data: Result<FitData, ExperimentError>,
    pub structure: Structure,
    /// The model shown before a fit: the guess the student drags.
    pub guess: Values,
}

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

/// What the model curve shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    Guess,
    Fitting,
    Fitted,
    /// A row of the diagnosis chain (0: its start).
    ChainRow(usize),
}

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

/// The plot's axes at the moment a handle was grabbed: held until it is let go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frozen {
    pub t: (f64, f64),
    pub y: (f64, f64),
}

/// What a background diagnosis returns.
enum DiagnoseOutcome {
    /// The whole loop ran.
    Loop(Box<DiagnoseReport>),
    /// One step was asked for: the leading cause (or none).
    Step(Option<Box<Step>>),
}

type FitJob = Job<Progress, Result<FitReport, FitError>>;

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

/// Which characteristics of the measured curve are marked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeasuredMarkers {
    pub rise: bool,
    pub peak: bool,
    pub settling: bool,
    pub steady_state: bool,
}

impl MeasuredMarkers {
    /// Every marker on (`true`) or off.
    pub const fn all(on: bool) -> Self {
        Self {
            rise: on,
            peak: on,
            settling: on,
            steady_state: on,
        }
    }
}

impl Default for MeasuredMarkers {
    fn default() -> Self {
        Self::all(true)
    }
}

/// A number typed in a reading field; empty is `None`.
fn optional_number(text: &str, choice: Choice) -> Result<Option<f64>, LoadError> {
    if text.trim().is_empty() {
        return Ok(None);
    }
    parse_number(text)
        .map(Some)
        .map_err(|error| LoadError::Choice { choice, error })
}

/// The structure `test`'s shape suggests ([`degrau_ident::guess::suggested_structure`]):
/// what a record starts with when no structure was asked for; the notes' P1D when its data
/// cannot be read yet.
fn suggested_code(test: &StepTest, experiment: &Experiment) -> String {
    experiment.fit_data(test).map_or_else(
        |_| "P1D".into(),
        |d| degrau_ident::guess::suggested_structure(&d).code(),
    )
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

    /// Loads a file by path; a failure keeps what was loaded before.
    pub fn load_path(&mut self, path: &str) {
        self.settings.path = path.to_string();
        let source = Source::File(path.to_string());
        let cleared = self.start_reading(&source);
        let loaded = self
            .load_options()
            .and_then(|o| data::load_file(std::path::Path::new(path), &o).map_err(LoadError::Data));
        match loaded.map(|test| self.with_input_file(test)) {
            Ok(Ok(test)) => {
                self.settings.example = false;
                self.accept(test, source, cleared);
            }
            Ok(Err((input_source, error))) => self.refuse(input_source, error),
            Err(error) => self.refuse(source, error),
        }
    }

    /// `test` with its input from the input's own file when one is chosen (joined on time,
    /// [`degrau_ident::join`]); the failure names that file.
    fn with_input_file(&self, test: StepTest) -> Result<StepTest, (Source, LoadError)> {
        let u_path = self.settings.u_path.trim();
        if u_path.is_empty() {
            return Ok(test);
        }
        let source = Source::File(u_path.to_string());
        let sampling_period =
            optional_number(&self.settings.sampling_period, Choice::SamplingPeriod)
                .map_err(|e| (source.clone(), e))?;
        let values = LoadOptions::from_text("", &self.settings.u_col, "none", sampling_period, 0);
        data::load_file(std::path::Path::new(u_path), &values)
            .and_then(|input| degrau_ident::join::join_on_time(test, &input))
            .map_err(|e| (source, LoadError::Data(e)))
    }

    /// Loads the example that ships with the app: the LECI step test of the course notes
    /// (35 samples; Δu = 10 at t0 = 5 s from the operating point y0 = 50), set up as the
    /// notes set it up.
    pub fn load_example(&mut self) {
        match data::load_str(LECI_EXAMPLE, &LoadOptions::default()) {
            Ok(test) => {
                self.settings.path.clear();
                self.settings.example = true;
                self.accept(test, Source::Example, Vec::new());
                if let Some(l) = self.loaded.as_mut() {
                    l.experiment.t0 = 5.0;
                    l.experiment.du = 10.0;
                    l.experiment.offset = Offset::Fixed(50.0);
                }
                self.message = Some(LoadMessage::Example {
                    samples: self.loaded.as_ref().map_or(0, |l| l.test.time.len()),
                    du: 10.0,
                    t0: 5.0,
                    y0: 50.0,
                });
                self.rebuild(true);
            }
            Err(e) => self.refuse(Source::Example, LoadError::Data(e)),
        }
    }

    /// Loads columns pasted as text.
    pub fn load_text(&mut self, text: &str) {
        match data::from_columns(text) {
            Ok(test) => {
                // Pasted columns (or a PRBS test used as the record) start from their own
                // columns: an input before another record (DaISy's 6) would invent a step.
                let cleared = self.start_reading(&Source::Pasted);
                self.settings.example = false;
                self.settings.path.clear();
                self.settings.u_path.clear();
                self.accept(test, Source::Pasted, cleared);
            }
            Err(e) => self.refuse(Source::Pasted, LoadError::Data(e)),
        }
    }

    /// Before reading a file: reading choices made on another file are cleared (a new file
    /// starts from its own columns); choices typed since the last load are used. Returns
    /// what was cleared.
    fn start_reading(&mut self, source: &Source) -> Vec<(Choice, String)> {
        match &self.choices_used_on {
            Some(used) if used != source => {
                let cleared = self.settings.reading_choices();
                self.settings.clear_reading_choices();
                // Another record: its structure is the one its own shape suggests.
                self.settings.code.clear();
                cleared
            }
            _ => Vec::new(),
        }
    }

    fn refuse(&mut self, source: Source, error: LoadError) {
        self.message = Some(LoadMessage::Failed {
            source,
            error,
            kept: self.loaded.is_some(),
        });
    }

    fn load_options(&self) -> Result<LoadOptions, LoadError> {
        let s = &self.settings;
        let sampling_period = optional_number(&s.sampling_period, Choice::SamplingPeriod)?;
        optional_number(&s.initial_input, Choice::InitialInput)?;
        // With the input in its own file, the test's file is read for its output alone.
        let input = if s.u_path.trim().is_empty() {
            s.u_col.as_str()
        } else {
            "none"
        };
        Ok(LoadOptions::from_text(
            &s.time_col,
            &s.y_col,
            input,
            sampling_period,
            0,
        ))
    }

    fn accept(&mut self, test: StepTest, source: Source, cleared: Vec<(Choice, String)>) {
        let initial_input =
            optional_number(&self.settings.initial_input, Choice::InitialInput).unwrap_or(None);
        let (experiment, step_missing) = match Experiment::new(&test, None, None, initial_input) {
            Ok(e) => (e, None),
            Err(e) => {
                let t0 = test.time.first().copied().unwrap_or(0.0);
                let fallback = Experiment {
                    t0,
                    du: 1.0,
                    drive: Default::default(),
                    initial_input,
                    offset: Offset::Auto,
                    window: None,
                    filter_hz: None,
                };
                (fallback, Some((e, t0)))
            }
        };
        let kept = match source {
            Source::File(_) => self.settings.reading_choices(),
            _ => Vec::new(),
        };
        self.choices_used_on = match &source {
            Source::File(_) => Some(source.clone()),
            _ => None,
        };
        self.message = Some(LoadMessage::Loaded {
            samples: test.time.len(),
            source,
            notes: test.notes.clone(),
            step_missing,
            kept,
            cleared,
        });
        if self.settings.code.trim().is_empty() {
            self.settings.code = suggested_code(&test, &experiment);
        }
        let structure =
            match Structure::parse(&self.settings.code).or_else(|_| Structure::parse("P1D")) {
                Ok(s) => s,
                Err(e) => {
                    self.refuse(source_of(&self.message), LoadError::Model(e));
                    return;
                }
            };
        self.forget_fit();
        self.frozen = None;
        self.loaded = Some(Loaded {
            test,
            experiment,
            data: Err(ExperimentError::NoStep),
            structure,
            guess: Values::default(),
        });
        self.rebuild(true);
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

    /// Starts the per-step fits of the current fit's data and structure (nothing for a
    /// record with one change).
    fn start_per_step(&mut self) {
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
    fn cancel_diagnosis(&mut self) {
        if let Some(job) = self.diagnose_job.take() {
            job.cancel();
            self.diagnose_note = DiagnoseNote::Cancelled;
        }
    }

    fn select_step(&mut self, k: usize) {
        if self.diagnosis.as_ref().is_some_and(|d| k < d.rows().len()) {
            self.selected_step = Some(k);
        }
    }

    /// Starts the whole loop (`whole`) or one step from the current fit, off the UI thread.
    fn start_diagnosis(&mut self, whole: bool) {
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
    fn current_fit(&self) -> Option<FitReport> {
        match &self.diagnosis {
            Some(d) => Some(d.final_fit.clone()),
            None => self.report.clone(),
        }
    }

    fn poll_diagnosis(&mut self) {
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
    fn adopt(&mut self, fit: &FitReport) {
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
    fn start_fit(&mut self) {
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

    fn cancel_fit(&mut self) {
        if let Some(j) = &self.job {
            j.cancel();
            self.status = Status::Cancelling;
        }
    }

    /// Collects a finished fit, or its progress.
    fn poll_fit(&mut self) {
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

    fn landscape_command(&mut self, command: LandscapeCommand) {
        let fit = match (&self.report, &self.fitted) {
            (Some(r), Some((_, d))) => Some((r, d)),
            _ => None,
        };
        self.landscape.apply(command, fit, self.waker.clone());
    }

    /// Recomputes the plots' data when the data or the shown model changed.
    fn refresh_plots(&mut self) {
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

/// The source named by a load message (the example when there is none).
fn source_of(message: &Option<LoadMessage>) -> Source {
    match message {
        Some(LoadMessage::Loaded { source, .. } | LoadMessage::Failed { source, .. }) => {
            source.clone()
        }
        Some(LoadMessage::Example { .. }) | None => Source::Example,
    }
}

/// Keys compared bit for bit (a NaN in a model is still "the same model").
fn same_key(a: &(u64, Option<Model>, Option<f64>), b: &(u64, Option<Model>, Option<f64>)) -> bool {
    let bits = |x: Option<f64>| x.map(f64::to_bits);
    a.0 == b.0 && a.1 == b.1 && bits(a.2) == bits(b.2)
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
    let y_final = degrau_ident::guess::features(data, Some(y0)).y_final;
    let pieces = degrau_ident::prepare::SampledPieces::new(&data.times, &data.y, setup.t0());
    let info = StepInfo::from_pieces(&pieces, y0, y_final, &StepInfoOptions::default());
    // The markers are drawn on a single step, where the first differences read the noise
    // (robust to the step itself) whatever the model shown: a poor guess's residuals would
    // call a real overshoot noise.
    let sigma = degrau_ident::rest::difference_noise(&data.y);
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
fn range_of(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo <= hi { (lo, hi) } else { (0.0, 1.0) }
}

/// A range with 5 % room on each side (a flat range gets room of its own size).
fn padded(range: (f64, f64)) -> (f64, f64) {
    padded_by(range, 0.05)
}

/// A range with `share` of its span as room on each side (a flat range gets room of its
/// own size).
pub(super) fn padded_by((lo, hi): (f64, f64), share: f64) -> (f64, f64) {
    let span = hi - lo;
    let room = if span > 0.0 {
        share * span
    } else {
        share * lo.abs().max(1.0)
    };
    (lo - room, hi + room)
}

/// The point of sorted `points` nearest in t (of equal times, the first).
fn nearest(points: &[[f64; 2]], t: f64) -> Option<[f64; 2]> {
    nearest_from(points, t, points.partition_point(|p| p[0] < t))
}

/// The nearer to `t` of `points[k − 1]` and `points[k]`, `k` the partition point around t.
pub(super) fn nearest_from(points: &[[f64; 2]], t: f64, k: usize) -> Option<[f64; 2]> {
    [k.checked_sub(1), Some(k)]
        .into_iter()
        .flatten()
        .filter_map(|i| points.get(i))
        .min_by(|a, b| (a[0] - t).abs().total_cmp(&(b[0] - t).abs()))
        .copied()
}

/// The unit a column header names in parentheses or brackets at its end.
fn unit_in(name: &str) -> Option<String> {
    let name = name.trim();
    let (open, close) = match name.chars().last()? {
        ')' => ('(', ')'),
        ']' => ('[', ']'),
        _ => return None,
    };
    let start = name.rfind(open)?;
    let unit = name[start + 1..name.len() - close.len_utf8()].trim();
    (!unit.is_empty()).then(|| unit.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_come_from_the_header() {
        assert_eq!(unit_in("T1 (°C)").as_deref(), Some("°C"));
        assert_eq!(unit_in("level [m]").as_deref(), Some("m"));
        assert_eq!(unit_in("T1"), None);
        assert_eq!(unit_in("odd ()"), None);
    }

    #[test]
    fn nearest_sample_in_time() {
        let p = [[0.0, 1.0], [1.0, 2.0], [3.0, 5.0]];
        assert_eq!(nearest(&p, -1.0), Some([0.0, 1.0]));
        assert_eq!(nearest(&p, 0.4), Some([0.0, 1.0]));
        assert_eq!(nearest(&p, 2.2), Some([3.0, 5.0]));
        assert_eq!(nearest(&p, 9.0), Some([3.0, 5.0]));
        assert_eq!(nearest(&[], 1.0), None);
    }

    #[test]
    fn ranges_are_padded() {
        assert_eq!(padded((0.0, 10.0)), (-0.5, 10.5));
        assert_eq!(padded((2.0, 2.0)), (1.9, 2.1));
        assert_eq!(range_of([f64::NAN, 3.0, -1.0].into_iter()), (-1.0, 3.0));
    }
}
