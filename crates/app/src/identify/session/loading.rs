//! Loading a step test into the session: from a file (with the input's own file joined on
//! time), from pasted columns or the shipped example; where it came from ([`Source`]), what
//! the loader said ([`LoadMessage`], [`LoadError`]) and what a loaded test holds
//! ([`Loaded`]). A new file starts from its own columns: reading choices made on another
//! file are cleared and named.

use degrau_ident::experiment::{Experiment, ExperimentError, Offset};
use degrau_ident::fit::FitData;
use degrau_ident::model::{ModelError, Structure, Values};
use degrau_ident::record::data::{self, DataError, LoadOptions, StepTest};

use super::super::commands::Choice;
use super::Session;
use crate::field::{FieldError, parse_number};

/// The LECI step test of the course notes (`t, y`), shipped with the app.
const LECI_EXAMPLE: &str = include_str!("../../../../../assets/leci_step.csv");

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
        notes: Vec<degrau_ident::record::data::DataNote>,
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

/// A number typed in a reading field; empty is `None`.
fn optional_number(text: &str, choice: Choice) -> Result<Option<f64>, LoadError> {
    if text.trim().is_empty() {
        return Ok(None);
    }
    parse_number(text)
        .map(Some)
        .map_err(|error| LoadError::Choice { choice, error })
}

/// The structure `test`'s shape suggests ([`degrau_ident::fit::guess::suggested_structure`]):
/// what a record starts with when no structure was asked for; the notes' P1D when its data
/// cannot be read yet.
fn suggested_code(test: &StepTest, experiment: &Experiment) -> String {
    experiment.fit_data(test).map_or_else(
        |_| "P1D".into(),
        |d| degrau_ident::fit::guess::suggested_structure(&d).code(),
    )
}

impl Session {
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
    /// [`degrau_ident::record::join`]); the failure names that file.
    pub(super) fn with_input_file(&self, test: StepTest) -> Result<StepTest, (Source, LoadError)> {
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
            .and_then(|input| degrau_ident::record::join::join_on_time(test, &input))
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
    pub(super) fn start_reading(&mut self, source: &Source) -> Vec<(Choice, String)> {
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

    pub(super) fn refuse(&mut self, source: Source, error: LoadError) {
        self.message = Some(LoadMessage::Failed {
            source,
            error,
            kept: self.loaded.is_some(),
        });
    }

    pub(super) fn load_options(&self) -> Result<LoadOptions, LoadError> {
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

    pub(super) fn accept(
        &mut self,
        test: StepTest,
        source: Source,
        cleared: Vec<(Choice, String)>,
    ) {
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

/// The unit a column header names in parentheses or brackets at its end.
pub(super) fn unit_in(name: &str) -> Option<String> {
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
