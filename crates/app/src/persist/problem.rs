//! What could not be restored or saved, as typed facts: which part of a saved session
//! ([`Field`]) and why ([`Reason`]), why the state file could not be read or written
//! ([`StateError`]) and why a session could not be saved ([`SaveFailure`]). Their English and
//! Portuguese are in [`crate::words::persist`]; a system's own refusal is said by the system
//! (its OS text of an io error is carried as it is).

use std::path::PathBuf;

use crate::design::closed_loop::LoopProblem;
use crate::design::plane::View;
use crate::design::state::SystemProblem;
use crate::field::LimitReason;
use degrau_lti::LtiError;

/// What was being done with a file when the system refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileAction {
    LookAt,
    Read,
    Create,
    Write,
    Replace,
}

/// Why the state file could not be read or written.
#[derive(Debug, Clone, PartialEq)]
pub enum StateError {
    /// The system refused; `os` is its own text of why.
    Io {
        action: FileAction,
        path: PathBuf,
        os: String,
    },
    NotAFile(PathBuf),
    /// The file's size in bytes, past what a saved session can be.
    TooLarge(PathBuf, u64),
}

impl StateError {
    /// The system's refusal to `action` the file at `path`.
    pub fn io(action: FileAction, path: &std::path::Path, error: &std::io::Error) -> Self {
        StateError::Io {
            action,
            path: path.to_path_buf(),
            os: error.to_string(),
        }
    }
}

/// Which part of a saved session a problem is about.
#[derive(Debug, Clone, PartialEq)]
pub enum Field {
    /// The whole file: it could not be read, or is not a saved session.
    WholeFile,
    /// The whole session handed to the app: it could not be written as JSON.
    WholeSession,
    /// A field, by its path in the file (`splane.view`, `system.poles`).
    Path(String),
}

/// A number chosen on a step test, as a problem with it names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TestValue {
    StepTime,
    StepSize,
    OperatingPoint,
    WindowStart,
    WindowEnd,
}

/// Why the choices saved on a step test cannot be restored.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExperimentProblem {
    NotFinite {
        what: TestValue,
        value: f64,
    },
    ZeroStep,
    /// A window whose start is not before its end.
    EmptyWindow(f64, f64),
    /// A filter cut-off (Hz) that is not a positive number.
    Filter(f64),
}

/// Why a part of a saved session could not be restored (it was reset to its default).
#[derive(Debug, Clone, PartialEq)]
pub enum Reason {
    File(StateError),
    /// Not JSON: where the reading stopped.
    NotJson {
        line: usize,
        column: usize,
    },
    /// JSON, but not an object.
    NotAnObject,
    /// A field that holds an object held this (its JSON, shortened).
    ExpectedObject {
        found: String,
    },
    /// A value (its JSON, shortened) that is not of the kind the field holds.
    Unreadable {
        found: String,
    },
    /// The session could not be written as JSON.
    NotWritable,
    System(SystemProblem),
    Placement(LimitReason),
    /// The step characteristics' thresholds.
    Options(LtiError),
    Loop(LoopProblem),
    /// A view of the s-plane out of range (it is fitted to the roots again).
    View(View),
    Experiment(ExperimentProblem),
    /// A model code that cannot be read.
    Code(String),
    /// A number of starts out of range (the largest is [`degrau_ident::fit::MAX_STARTS`]).
    Starts(usize),
    /// A presentation size out of range.
    Scale(f32),
    /// The Tune mode's model (or τc) makes no model.
    TuneModel(crate::tune::model::ModelProblem),
    /// The Tune mode's controller numbers make no controller.
    Controller(degrau_lti::control::ControllerError),
    /// The Frequency mode's sampling period is not a positive number of seconds.
    SamplingPeriod(f64),
}

/// A part of a saved session that could not be restored and was reset to its default.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldProblem {
    pub field: Field,
    pub reason: Reason,
}

/// Why the session could not be saved.
#[derive(Debug, Clone, PartialEq)]
pub enum SaveFailure {
    /// The saver thread has stopped (or could not start).
    Stopped,
    /// The session could not be written as JSON.
    NotWritable,
    File(StateError),
}

/// A value's JSON as a problem quotes it: at most [`QUOTED_CHARS`] characters.
pub fn quoted(value: &serde_json::Value) -> String {
    let text = value.to_string();
    match text.char_indices().nth(QUOTED_CHARS) {
        Some((end, _)) => format!("{}…", &text[..end]),
        None => text,
    }
}

/// The most characters of a value a problem quotes.
const QUOTED_CHARS: usize = 60;
