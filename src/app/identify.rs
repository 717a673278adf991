//! The identification view: load a measured step test (path, file dialog, drop, paste),
//! say how to read it (columns, sampling period, step, operating point, window, filter),
//! drag a model's guesses on the plot, fit it off the UI thread with progress and a cancel
//! button, then read the parameters with their intervals and the residuals.
//! Everything computed here comes from [`crate::ident`].

use eframe::egui::{self, Color32, DragValue, RichText, Ui};
use serde::{Deserialize, Serialize};

use crate::app::job::Job;
use crate::app::system_panel::finite_number;
use crate::ident::data::{self, LoadOptions, StepTest};
use crate::ident::diagnose::{self, DiagnoseOptions, DiagnoseReport, Step};
use crate::ident::experiment::{Experiment, Offset};
use crate::ident::fit::{FitData, FitError, FitOptions, FitReport, Method, Progress, fit};
use crate::ident::models::{Model, Param, Structure, Values, pair_poles};
use crate::lti::number::sig;
use crate::text::{Lang, Localize};

/// The LECI step test of the course notes (`t, y`), shipped with the app.
const LECI_EXAMPLE: &str = include_str!("../../assets/leci_step.csv");

/// A number typed in a field (a decimal comma is accepted); empty is `None`.
fn optional_number(text: &str, what: &str) -> Result<Option<f64>, String> {
    let text = text.trim();
    if text.is_empty() {
        return Ok(None);
    }
    text.replace(',', ".")
        .parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .map(Some)
        .ok_or_else(|| format!("{what}: \"{text}\" is not a number"))
}

/// The model codes offered, in the order of the notes.
pub const CODES: [&str; 13] = [
    "P1", "P1D", "P2", "P2D", "P2U", "P2DU", "P2Z", "P2DZ", "P2DUZ", "P3", "P3D", "P1I", "P1DI",
];

/// Choices kept between runs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct IdentSettings {
    pub path: String,
    /// The shipped example is what is loaded (it has no path).
    pub example: bool,
    /// The step, operating point, window and filter chosen on the loaded test, restored
    /// with it after a restart.
    pub experiment: Option<Experiment>,
    pub time_col: String,
    pub y_col: String,
    pub u_col: String,
    /// Sampling period for files without a time column (text as typed).
    pub sampling_period: String,
    /// The input before the record started, for a test whose step came at the first sample
    /// (text as typed; empty: none).
    pub initial_input: String,
    pub code: String,
    pub drift: bool,
    pub method: Method,
    pub multistart: bool,
    pub starts: usize,
}

impl Default for IdentSettings {
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
            code: "P2DU".into(),
            drift: false,
            method: Method::LevenbergMarquardt,
            multistart: true,
            starts: 16,
        }
    }
}

/// A loaded test and what was chosen on it.
pub struct Loaded {
    pub test: StepTest,
    pub experiment: Experiment,
    /// The samples the fit sees (window and filter applied).
    pub data: Result<FitData, String>,
    pub structure: Structure,
    /// The model shown before a fit: the guess the student drags.
    pub guess: Values,
}

/// The view's state.
#[derive(Default)]
pub struct IdentView {
    pub settings: IdentSettings,
    pub loaded: Option<Loaded>,
    /// The last message about loading: (is an error, text).
    pub message: Option<(bool, String)>,
    job: Option<Job<Progress, Result<FitReport, FitError>>>,
    pub report: Option<FitReport>,
    /// The structure and data the report belongs to.
    pub fitted: Option<(Structure, FitData)>,
    pub status: String,
    pub landscape: crate::app::landscape_view::LandscapeView,
    pub markers: crate::app::step_plot::Markers,
    /// The chain of the diagnosis: start fit, then one step per extension.
    pub diagnosis: Option<DiagnoseReport>,
    diagnose_job: Option<Job<(), DiagnoseOutcome>>,
    /// Which model of the chain is shown (0: the start).
    pub selected_step: Option<usize>,
    pub diagnose_note: String,
}

/// What a background diagnosis returns.
enum DiagnoseOutcome {
    /// The whole loop ran.
    Loop(Box<DiagnoseReport>),
    /// One step was asked for: the leading cause (or none).
    Step(Option<Box<Step>>),
}

/// What the view asks of the app.
pub enum IdentAction {
    None,
    /// Show this model's transfer function on the s-plane.
    ShowOnSPlane(Model),
}

impl IdentView {
    /// A view with nothing loaded and the given settings.
    /// A view with the given settings, with the test they name loaded again (the example or
    /// the file, with the choices made on it), as it was when the app was closed.
    pub fn with_settings(settings: IdentSettings) -> Self {
        let mut view = Self {
            settings: settings.clone(),
            ..Default::default()
        };
        if settings.example {
            view.load_example();
        } else if !settings.path.is_empty() {
            view.load_path(&settings.path);
        }
        if let (Some(e), Some(l)) = (settings.experiment, view.loaded.as_mut()) {
            l.experiment = e;
            view.rebuild(true);
        }
        view
    }

    /// The settings to keep between runs, with the loaded test's choices.
    pub fn settings_to_save(&self) -> IdentSettings {
        IdentSettings {
            experiment: self.loaded.as_ref().map(|l| l.experiment.clone()),
            ..self.settings.clone()
        }
    }

    /// Loads a file by path; a failure keeps what was loaded before.
    pub fn load_path(&mut self, path: &str) {
        self.settings.path = path.to_string();
        let options = self.load_options();
        match options.and_then(|o| {
            data::load_file(std::path::Path::new(path), &o).map_err(|e| e.to_string())
        }) {
            Ok(test) => {
                self.settings.example = false;
                self.accept(test, path);
            }
            Err(e) => {
                let kept = if self.loaded.is_some() {
                    " What was loaded before is kept."
                } else {
                    ""
                };
                self.message = Some((true, format!("Not loaded ({path}): {e}.{kept}")))
            }
        }
    }

    /// Loads the example that ships with the app: the LECI step test of the course notes
    /// (35 samples; Δu = 10 at t0 = 5 s from the operating point y0 = 50), set up as the
    /// notes set it up.
    pub fn load_example(&mut self) {
        match data::load_str(LECI_EXAMPLE, &LoadOptions::default()) {
            Ok(test) => {
                self.settings.path.clear();
                self.settings.example = true;
                self.accept(test, "the LECI example of the course notes");
                if let Some(l) = self.loaded.as_mut() {
                    l.experiment.t0 = 5.0;
                    l.experiment.du = 10.0;
                    l.experiment.offset = Offset::Fixed(50.0);
                }
                self.message = Some((
                    false,
                    "Loaded the LECI example of the course notes: 35 samples, a step of \
                     Δu = 10 at t0 = 5 s from y0 = 50."
                        .into(),
                ));
                self.rebuild(true);
            }
            Err(e) => self.message = Some((true, format!("The example did not load: {e}."))),
        }
    }

    /// Loads columns pasted as text.
    pub fn load_text(&mut self, text: &str) {
        match data::from_columns(text) {
            Ok(test) => {
                self.settings.example = false;
                self.settings.path.clear();
                self.accept(test, "pasted data");
            }
            Err(e) => {
                self.message = Some((
                    true,
                    format!(
                        "The pasted text is not a step test: {e}. What was loaded before is kept."
                    ),
                ))
            }
        }
    }

    fn load_options(&self) -> Result<LoadOptions, String> {
        let sampling_period =
            optional_number(&self.settings.sampling_period, "the sampling period (s)")?;
        optional_number(&self.settings.initial_input, "the input before the record")?;
        let s = &self.settings;
        Ok(LoadOptions::from_text(
            &s.time_col,
            &s.y_col,
            &s.u_col,
            sampling_period,
            0,
        ))
    }

    fn accept(&mut self, test: StepTest, source: &str) {
        let initial_input = optional_number(&self.settings.initial_input, "").unwrap_or(None);
        let (experiment, step_note) = match Experiment::new(&test, None, None, initial_input) {
            Ok(e) => (e, None),
            Err(e) => {
                let t0 = test.time.first().copied().unwrap_or(0.0);
                let fallback = Experiment {
                    t0,
                    du: 1.0,
                    offset: Offset::Auto,
                    window: None,
                    filter_hz: None,
                };
                (
                    fallback,
                    Some(format!("{e}. Set t0 and Δu below (now t0 = {t0}, Δu = 1).")),
                )
            }
        };
        let mut notes = vec![format!("Loaded {} samples from {source}.", test.time.len())];
        notes.extend(test.notes.iter().map(|n| n.text(Lang::En)));
        notes.extend(step_note);
        self.message = Some((false, notes.join(" ")));
        let structure = Structure::parse(&self.settings.code)
            .unwrap_or_else(|_| Structure::parse("P1D").expect("a valid code"));
        self.report = None;
        self.fitted = None;
        self.loaded = Some(Loaded {
            test,
            experiment,
            data: Err(String::new()),
            structure,
            guess: Values::default(),
        });
        self.rebuild(true);
    }

    /// Recomputes the fit data and structure after a change; `reguess` resets the guess.
    pub fn rebuild(&mut self, reguess: bool) {
        let Some(l) = self.loaded.as_mut() else {
            return;
        };
        l.data = l.experiment.fit_data(&l.test).map_err(|e| e.to_string());
        if let Ok(d) = &l.data {
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
                    if changed {
                        // The last fit's outcome was about another structure.
                        self.status.clear();
                    }
                }
                Err(e) => self.status = e.to_string(),
            }
        }
    }

    /// Moves the step time t0 (dragged on the plot), keeping the guesses.
    pub fn set_step_time(&mut self, t0: f64) {
        if let Some(l) = self.loaded.as_mut()
            && t0.is_finite()
        {
            l.experiment.t0 = t0;
            self.rebuild(false);
        }
    }

    /// The model shown: the running fit's latest, the fit's, or the guess.
    pub fn shown_model(&self) -> Option<Model> {
        if let Some(p) = self.job.as_ref().and_then(|j| j.progress.as_ref()) {
            return Some(p.model);
        }
        if let (Some(k), Some(d)) = (self.selected_step, &self.diagnosis) {
            return chain(d).get(k).map(|f| f.model);
        }
        let l = self.loaded.as_ref()?;
        match (&self.report, &self.fitted) {
            (Some(r), Some((s, _))) if *s == l.structure => Some(r.model),
            _ => Some(Model::new(l.structure, l.guess)),
        }
    }

    /// Sets the guess (a drag on the plot); a previous fit no longer describes what is shown.
    pub fn set_guess(&mut self, model: Model) {
        if let Some(l) = self.loaded.as_mut() {
            l.guess = model.values;
            l.structure = model.structure;
            self.report = None;
            self.fitted = None;
            self.clear_diagnosis();
        }
    }

    fn clear_diagnosis(&mut self) {
        self.diagnosis = None;
        self.selected_step = None;
        self.diagnose_note.clear();
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

    pub fn is_diagnosing(&self) -> bool {
        self.diagnose_job.is_some()
    }

    /// Starts the whole loop (`whole`) or one step from the current fit, off the UI thread.
    pub fn start_diagnosis(&mut self, ctx: Option<egui::Context>, whole: bool) {
        let (Some(report), Some((_, data))) = (self.current_fit(), self.fitted.clone()) else {
            return;
        };
        self.diagnose_note = if whole {
            "Running the loop…".into()
        } else {
            "Looking for the leading cause…".into()
        };
        self.diagnose_job = Some(Job::spawn(ctx, move |_| {
            if whole {
                let chain = diagnose::diagnose_from(&data, report, &DiagnoseOptions::default());
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
                self.diagnose_note = d.verdict.map(|v| v.text(Lang::En)).unwrap_or_default();
                self.selected_step = Some(d.steps.len());
                self.adopt(&d.final_fit);
                self.diagnosis = Some(*d);
            }
            DiagnoseOutcome::Step(Some(step)) => {
                let start = self.report.clone();
                let d = self.diagnosis.get_or_insert_with(|| DiagnoseReport {
                    start: start.clone().unwrap_or_else(|| step.fit.clone()),
                    steps: Vec::new(),
                    final_fit: step.fit.clone(),
                    adequate: false,
                    verdict: None,
                    static_gain: (0.0, None),
                });
                d.final_fit = step.fit.clone();
                d.static_gain = (step.fit.model.get(Param::Kp), step.fit.interval(Param::Kp));
                d.steps.push(*step.clone());
                self.selected_step = Some(d.steps.len());
                self.diagnose_note = format!("{}: {}", step.cause.id(), step.cause.text(Lang::En));
                self.adopt(&step.fit);
            }
            DiagnoseOutcome::Step(None) => {
                self.diagnose_note =
                    "none: no extension lowers BIC by 10; the model is adequate.".into();
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
        self.status = format!(
            "from the diagnosis: {} · {} iterations",
            fit.termination.text(Lang::En),
            fit.iterations
        );
        self.report = Some(fit.clone());
    }

    pub fn is_fitting(&self) -> bool {
        self.job.is_some()
    }

    /// Starts a fit from the current guess.
    pub fn start_fit(&mut self, ctx: Option<egui::Context>) {
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
        self.fitted = Some((structure, data.clone()));
        self.status = "Fitting…".into();
        self.job = Some(Job::spawn(ctx, move |job| {
            struct Relay<'a>(
                &'a crate::app::job::Context<Progress, Result<FitReport, FitError>>,
                usize,
            );
            impl crate::ident::fit::FitObserver for Relay<'_> {
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
            fit(&data, structure, guess, &options, &mut Relay(job, 0))
        }));
    }

    pub fn cancel_fit(&mut self) {
        if let Some(j) = &self.job {
            j.cancel();
            self.status = "Cancelling…".into();
        }
    }

    /// Collects a finished fit.
    pub fn poll(&mut self) {
        let Some(job) = self.job.as_mut() else { return };
        match job.poll() {
            Some(Ok(report)) => {
                self.status = format!(
                    "{} · {} start(s), {} iterations",
                    report.termination.text(Lang::En),
                    report.starts,
                    report.iterations
                );
                if let Some(l) = self.loaded.as_mut() {
                    l.guess = report.model.values;
                }
                self.report = Some(report);
                self.job = None;
                self.clear_diagnosis();
            }
            Some(Err(e)) => {
                self.status = format!("The fit did not run: {e}");
                self.fitted = None;
                self.job = None;
            }
            None => {
                if let Some(p) = &job.progress {
                    self.status = format!(
                        "start {}/{} · iteration {} · MSE {} (best {})",
                        p.start + 1,
                        p.starts,
                        p.iteration,
                        sig(p.cost, 5),
                        sig(p.best_cost, 5)
                    );
                }
            }
        }
    }

    /// Draws the side panel; returns a request for the app.
    pub fn panel(&mut self, ui: &mut Ui) -> IdentAction {
        let mut action = IdentAction::None;
        self.poll();
        self.poll_diagnosis();
        ui.heading("Step test");
        self.data_section(ui);
        if self.loaded.is_some() {
            ui.separator();
            self.step_section(ui);
            ui.separator();
            self.model_section(ui);
            ui.separator();
            self.fit_section(ui);
            if let Some(a) = self.results(ui) {
                action = a;
            }
            if self.report.is_some() {
                ui.separator();
                self.diagnose_section(ui);
            }
        }
        action
    }

    fn data_section(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            let label = ui.label("Step test file");
            ui.add(egui::TextEdit::singleline(&mut self.settings.path).desired_width(190.0))
                .labelled_by(label.id);
            if ui.button("Load").clicked() {
                let path = self.settings.path.clone();
                self.load_path(&path);
            }
            if ui
                .button("Example")
                .on_hover_text("The LECI step test of the course notes")
                .clicked()
            {
                self.load_example();
            }
            if ui.button("Open…").clicked()
                && let Some(p) = rfd::FileDialog::new()
                    .add_filter("step tests", &["csv", "tsv", "txt", "dat"])
                    .pick_file()
            {
                self.load_path(&p.display().to_string());
            }
        });
        egui::CollapsingHeader::new("How to read the file").show(ui, |ui| {
            egui::Grid::new("columns").num_columns(2).show(ui, |ui| {
                for (name, field, hint) in [
                    (
                        "Time column",
                        &mut self.settings.time_col,
                        "name or number; empty: automatic",
                    ),
                    (
                        "Output column",
                        &mut self.settings.y_col,
                        "name or number; empty: automatic",
                    ),
                    (
                        "Input column",
                        &mut self.settings.u_col,
                        "name or number; empty: automatic",
                    ),
                    (
                        "Sampling period (s)",
                        &mut self.settings.sampling_period,
                        "only for files without time",
                    ),
                    (
                        "Input before the record",
                        &mut self.settings.initial_input,
                        "only if the step is at the first sample",
                    ),
                ] {
                    let l = ui.label(name);
                    ui.add(
                        egui::TextEdit::singleline(field)
                            .hint_text(hint)
                            .desired_width(150.0),
                    )
                    .labelled_by(l.id);
                    ui.end_row();
                }
            });
            ui.weak("Drop a file on the window, or paste two or three columns (Ctrl+V).");
        });
        if let Some((error, text)) = &self.message {
            let color = if *error {
                ui.visuals().error_fg_color
            } else {
                ui.visuals().weak_text_color()
            };
            ui.label(RichText::new(text).color(color));
        }
    }

    fn step_section(&mut self, ui: &mut Ui) {
        let Some(l) = self.loaded.as_mut() else {
            return;
        };
        let mut changed = false;
        let e = &mut l.experiment;
        egui::Grid::new("step").num_columns(2).show(ui, |ui| {
            let label = ui.label("Step time t0 (s)");
            changed |= ui
                .add(
                    DragValue::new(&mut e.t0)
                        .speed(0.01)
                        .max_decimals(6)
                        .custom_parser(finite_number),
                )
                .labelled_by(label.id)
                .changed();
            ui.end_row();
            let label = ui.label("Step size Δu");
            changed |= ui
                .add(
                    DragValue::new(&mut e.du)
                        .speed(0.01)
                        .max_decimals(6)
                        .custom_parser(finite_number),
                )
                .labelled_by(label.id)
                .changed();
            ui.end_row();
            ui.label("Operating point y0");
            ui.horizontal(|ui| {
                let mut mode = match e.offset {
                    Offset::Auto => 0,
                    Offset::Free => 1,
                    Offset::Fixed(_) => 2,
                };
                let before = mode;
                ui.radio_value(&mut mode, 0, "mean before the step");
                ui.radio_value(&mut mode, 1, "estimate");
                ui.radio_value(&mut mode, 2, "typed");
                if mode != before {
                    let y0 = l.guess.get(Param::Y0);
                    e.offset = [Offset::Auto, Offset::Free, Offset::Fixed(y0)][mode];
                    changed = true;
                }
                if let Offset::Fixed(v) = &mut e.offset {
                    changed |= ui
                        .add(
                            DragValue::new(v)
                                .speed(0.01)
                                .max_decimals(6)
                                .custom_parser(finite_number),
                        )
                        .changed();
                }
            });
            ui.end_row();
            ui.label("Window (s)");
            ui.horizontal(|ui| {
                let (first, last) = (
                    l.test.time.first().copied().unwrap_or(0.0),
                    l.test.time.last().copied().unwrap_or(0.0),
                );
                let mut on = e.window.is_some();
                changed |= ui.checkbox(&mut on, "keep only").changed();
                if on {
                    let w = e.window.get_or_insert((first, last));
                    changed |= ui
                        .add(
                            DragValue::new(&mut w.0)
                                .speed(0.05)
                                .range(first..=last)
                                .prefix("from "),
                        )
                        .changed();
                    changed |= ui
                        .add(
                            DragValue::new(&mut w.1)
                                .speed(0.05)
                                .range(first..=last)
                                .prefix("to "),
                        )
                        .changed();
                } else {
                    e.window = None;
                }
            });
            ui.end_row();
            ui.label("Low-pass filter");
            ui.horizontal(|ui| {
                let mut on = e.filter_hz.is_some();
                changed |= ui.checkbox(&mut on, "EWMA").changed();
                if on {
                    let fc = e.filter_hz.get_or_insert(1.0);
                    changed |= ui
                        .add(
                            DragValue::new(fc)
                                .speed(0.01)
                                .range(1e-6..=1e6)
                                .suffix(" Hz"),
                        )
                        .changed();
                } else {
                    e.filter_hz = None;
                }
            });
            ui.end_row();
        });
        if let (Some(fc), Ok(d)) = (l.experiment.filter_hz, &l.data) {
            let filter = crate::ident::prepare::Ewma::new(fc, d.sampling_period());
            ui.weak(filter.text(Lang::En));
        }
        if let Err(e) = &l.data {
            ui.colored_label(ui.visuals().error_fg_color, e);
        }
        if changed {
            self.rebuild(false);
        }
    }

    fn model_section(&mut self, ui: &mut Ui) {
        let mut changed = false;
        ui.horizontal(|ui| {
            ui.strong("Model structure");
            egui::ComboBox::from_id_salt("model code")
                .selected_text(&self.settings.code)
                .show_ui(ui, |ui| {
                    for code in CODES {
                        changed |= ui
                            .selectable_value(&mut self.settings.code, code.to_string(), code)
                            .changed();
                    }
                });
            changed |= ui
                .checkbox(&mut self.settings.drift, "drift")
                .on_hover_text("Add a linear drift term Drift·(t − t0)")
                .changed();
            if ui
                .button("Automatic guess")
                .on_hover_text("Read the guesses off the curve again")
                .clicked()
            {
                self.rebuild(true);
                self.report = None;
            }
        });
        if changed {
            self.rebuild(true);
            self.report = None;
        }
        let Some(l) = self.loaded.as_mut() else {
            return;
        };
        let mut edited = false;
        egui::Grid::new("guess").num_columns(2).show(ui, |ui| {
            for p in l.structure.params() {
                let label = ui
                    .label(format!("{} guess", p.name()))
                    .on_hover_text(crate::text::ident::param_meaning(p, Lang::En));
                let mut v = l.guess.get(p);
                let speed = 0.01 * v.abs().max(0.01);
                if ui
                    .add(
                        DragValue::new(&mut v)
                            .speed(speed)
                            .max_decimals(6)
                            .custom_parser(finite_number),
                    )
                    .labelled_by(label.id)
                    .changed()
                {
                    l.guess.set(p, v);
                    edited = true;
                }
                ui.end_row();
            }
        });
        if edited {
            self.report = None;
        }
    }

    fn fit_section(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            ui.radio_value(
                &mut self.settings.method,
                Method::LevenbergMarquardt,
                "Levenberg–Marquardt",
            );
            ui.radio_value(&mut self.settings.method, Method::NelderMead, "Nelder–Mead");
        });
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.settings.multistart, "multi-start").on_hover_text(
                "Run from the guess and from spread-out starts, keep the best result that is not an alias",
            );
            if self.settings.multistart {
                ui.add(DragValue::new(&mut self.settings.starts).range(2..=crate::ident::fit::MAX_STARTS).suffix(" starts"));
            }
        });
        ui.horizontal(|ui| {
            let can_fit = self.loaded.as_ref().is_some_and(|l| l.data.is_ok());
            if self.is_fitting() {
                if ui.button("Cancel").clicked() {
                    self.cancel_fit();
                }
                ui.spinner();
            } else if ui.add_enabled(can_fit, egui::Button::new("Fit")).clicked() {
                self.start_fit(Some(ui.ctx().clone()));
            }
            if !self.status.is_empty() {
                ui.label(&self.status);
            }
        });
    }

    fn results(&mut self, ui: &mut Ui) -> Option<IdentAction> {
        let report = self.report.as_ref()?;
        let mut action = None;
        ui.separator();
        ui.strong(format!("Fitted {}", report.model.structure.code()));
        egui::Grid::new("parameters")
            .striped(true)
            .num_columns(3)
            .show(ui, |ui| {
                ui.strong("Parameter");
                ui.strong("Value");
                ui.strong("95 % interval");
                ui.end_row();
                for e in &report.params {
                    let unit = if e.param.unit().is_empty() {
                        String::new()
                    } else {
                        format!(" {}", e.param.unit())
                    };
                    ui.label(e.param.name())
                        .on_hover_text(crate::text::ident::param_meaning(e.param, Lang::En));
                    ui.label(format!("{}{unit}", sig(e.value, 5)));
                    ui.label(match e.ci95 {
                        Some((lo, hi)) => format!("[{}, {}]", sig(lo, 4), sig(hi, 4)),
                        None => "none".into(),
                    });
                    ui.end_row();
                }
            });
        for line in derived(&report.model) {
            ui.label(line);
        }
        ui.label(format!(
            "MSE {} · RMSE {} · fit {} % · AIC {} · N = {}",
            sig(report.mse, 4),
            sig(report.rmse, 4),
            sig(report.fit_percent, 4),
            sig(report.aic, 5),
            report.n
        ));
        for w in &report.warnings {
            ui.label(
                RichText::new(format!("Warning: {}", w.text(Lang::En)))
                    .color(Color32::from_rgb(210, 120, 0)),
            );
        }
        ui.horizontal(|ui| {
            if ui.button("Show on the s-plane").clicked() {
                action = Some(IdentAction::ShowOnSPlane(report.model));
            }
            if ui.button("Cost landscape…").clicked() {
                self.landscape.open = true;
            }
        });
        action
    }
}

impl IdentView {
    /// "What does the model get wrong?": the cause in words, the buttons, the chain table.
    fn diagnose_section(&mut self, ui: &mut Ui) {
        ui.heading("What does the model get wrong?");
        ui.horizontal(|ui| {
            if self.is_diagnosing() {
                ui.spinner();
            } else {
                if ui
                    .button("Extend with the leading cause")
                    .on_hover_text("Name what the model gets wrong and extend it once")
                    .clicked()
                {
                    self.start_diagnosis(Some(ui.ctx().clone()), false);
                }
                if ui
                    .button("Run the whole loop")
                    .on_hover_text("Extend until no extension pays for itself")
                    .clicked()
                {
                    self.start_diagnosis(Some(ui.ctx().clone()), true);
                }
            }
        });
        if !self.diagnose_note.is_empty() {
            ui.label(&self.diagnose_note);
        }
        let Some(d) = &self.diagnosis else { return };
        let rows = chain_rows(d);
        let mut selected = self.selected_step;
        egui::Grid::new("chain")
            .striped(true)
            .num_columns(5)
            .show(ui, |ui| {
                for head in ["Model", "RMSE", "Fit %", "BIC change", "Kp ± 95 %"] {
                    ui.strong(head);
                }
                ui.end_row();
                for (k, row) in rows.iter().enumerate() {
                    if ui
                        .selectable_label(selected == Some(k), &row[0])
                        .on_hover_text("Show this model's curve and residuals")
                        .clicked()
                    {
                        selected = Some(k);
                    }
                    for cell in &row[1..] {
                        ui.label(cell);
                    }
                    ui.end_row();
                }
            });
        self.selected_step = selected;
        if ui.button("Copy the table").clicked() {
            ui.ctx().copy_text(chain_text(d));
        }
        if let Some(step) = selected
            .and_then(|k| k.checked_sub(1))
            .and_then(|k| d.steps.get(k))
        {
            ui.strong(format!(
                "{}: {}",
                step.cause.id(),
                step.cause.text(Lang::En)
            ));
            ui.label(step.evidence.text(Lang::En));
            ui.label(format!(
                "Remedy: {}. RMSE {} → {} ({}× lower); fit {} % → {} %.",
                crate::text::ident::remedy(step.cause, Lang::En),
                sig(step.gain.rmse_before, 4),
                sig(step.gain.rmse_after, 4),
                sig(step.gain.rmse_ratio, 3),
                sig(step.gain.fit_percent_before, 4),
                sig(step.gain.fit_percent_after, 4)
            ));
        }
        if let Some(v) = &d.verdict {
            ui.weak(v.text(Lang::En));
        }
    }
}

/// The fits of a chain: the start, then each step's.
pub fn chain(d: &DiagnoseReport) -> Vec<&FitReport> {
    std::iter::once(&d.start)
        .chain(d.steps.iter().map(|s| &s.fit))
        .collect()
}

/// The chain table's cells: model, RMSE, fit %, BIC change, Kp ± half-interval.
pub fn chain_rows(d: &DiagnoseReport) -> Vec<[String; 5]> {
    chain(d)
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let kp = f.model.get(Param::Kp);
            let kp_text = match f.interval(Param::Kp) {
                Some((a, b)) => format!("{} ± {}", sig(kp, 4), sig(0.5 * (b - a), 2)),
                None => sig(kp, 4),
            };
            let delta = k
                .checked_sub(1)
                .and_then(|i| d.steps.get(i))
                .map_or(String::new(), |s| sig(s.gain.criterion_delta, 4));
            [
                f.model.structure.label(),
                sig(f.rmse, 4),
                sig(f.fit_percent, 4),
                delta,
                kp_text,
            ]
        })
        .collect()
}

/// The chain table as tab-separated text, for a spreadsheet or a report.
pub fn chain_text(d: &DiagnoseReport) -> String {
    let mut out = String::from("model\tRMSE\tfit %\tBIC change\tKp ± 95 %\n");
    for row in chain_rows(d) {
        out.push_str(&row.join("\t"));
        out.push('\n');
    }
    out
}

/// ωn, σ, ωd and the poles of a model, in words.
pub fn derived(model: &Model) -> Vec<String> {
    let s = model.structure;
    let mut out = Vec::new();
    if s.underdamped {
        let (tw, zeta) = (model.get(Param::Tw), model.get(Param::Zeta));
        let [p, q] = pair_poles(tw, zeta);
        out.push(format!(
            "ωn = 1/Tw = {} rad/s · σ = ζωn = {} 1/s",
            sig(1.0 / tw, 4),
            sig(zeta / tw, 4)
        ));
        if zeta < 1.0 {
            out.push(format!(
                "ωd = {} rad/s · poles {} ± {}j",
                sig(p.im, 4),
                sig(p.re, 4),
                sig(p.im, 4)
            ));
        } else {
            out.push(format!(
                "overdamped: poles {} and {}",
                sig(p.re, 4),
                sig(q.re, 4)
            ));
        }
    }
    let poles: Vec<String> = [Param::Tp1, Param::Tp2, Param::Tp3]
        .into_iter()
        .filter(|p| s.params().contains(p))
        .map(|p| format!("{} (from {})", sig(-1.0 / model.get(p), 4), p.name()))
        .collect();
    if !poles.is_empty() {
        out.push(format!("Real poles: {}", poles.join(", ")));
    }
    out.push(format!(
        "Static gain Kp = Δy/Δu = {}",
        sig(model.get(Param::Kp), 5)
    ));
    out
}
