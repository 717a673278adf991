//! What the identification views ask of the session ([`Command`]), and what the session asks
//! of the app in return ([`Outcome`]). A view never changes the session while it draws: it
//! returns commands, applied once per frame before the next is drawn. The plain data a
//! command carries lives here too: the axes held while a handle is dragged ([`Frozen`]) and
//! which characteristics of the measured curve are marked ([`MeasuredMarkers`]).

use degrau_ident::fit::Method;
use degrau_ident::fit::handles::Handle;
use degrau_ident::fit::landscape::Axis;
use degrau_ident::model::Param;

/// A reading choice for the next load (typed as text; empty: automatic or none).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Choice {
    TimeColumn,
    OutputColumn,
    InputColumn,
    /// Seconds between samples, for a file without a time column.
    SamplingPeriod,
    /// The input before the record started.
    InitialInput,
    /// A second file that holds the input (its own time and input columns), joined on time.
    InputFile,
}

impl Choice {
    pub const ALL: [Choice; 6] = [
        Choice::TimeColumn,
        Choice::OutputColumn,
        Choice::InputColumn,
        Choice::SamplingPeriod,
        Choice::InitialInput,
        Choice::InputFile,
    ];
}

/// How the operating point Y0 is treated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OffsetChoice {
    /// Held at the level before the step.
    Before,
    /// Estimated with the other parameters.
    Estimate,
    /// Held at a typed value (`None`: start from the current Y0).
    Typed(Option<f64>),
}

/// A gesture on a guess handle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Gesture {
    /// A handle was grabbed: the plot's axes are held as they are.
    Grab(Frozen),
    /// The handle is at (t, y) on the held axes.
    Move { handle: Handle, to: (f64, f64) },
    /// The handle was let go: the axes follow the curves again.
    Release,
}

/// The code a fitted model is copied as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CodeKind {
    Matlab,
    PythonControl,
}

/// What the cost-landscape window asks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LandscapeCommand {
    Open,
    Close,
    Axes(Axis, Axis),
    /// How far around the fit the axes reach (a factor ≥ 1.2).
    Spread(f64),
    Compute,
    Cancel,
}

/// The plot's axes at the moment a handle was grabbed: held until it is let go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frozen {
    pub t: (f64, f64),
    pub y: (f64, f64),
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

/// What a view asks of the identification session.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// The path field's text.
    SetPath(String),
    /// Load the file the path field names.
    LoadPath,
    /// Load a file picked in the file dialog (or dropped on the window).
    Open(String),
    /// Choose the test's file with the file dialog.
    BrowseTest,
    /// Load columns pasted as text (or a record made in another mode).
    LoadText(String),
    LoadExample,
    SetChoice(Choice, String),
    /// Choose the input's own file with the file dialog.
    BrowseInputFile,
    /// The step time t0 (s).
    SetStepTime(f64),
    /// The step size Δu.
    SetStepSize(f64),
    SetOffset(OffsetChoice),
    /// What drove the test: the measured input (with its hold) or one ideal step.
    SetDrive(degrau_ident::experiment::Drive),
    /// The time window kept (s), none for the whole record.
    SetWindow(Option<(f64, f64)>),
    /// The low-pass filter's cut-off (Hz), none for no filter.
    SetFilter(Option<f64>),
    SetCode(String),
    SetDrift(bool),
    /// Read the guesses off the curve again.
    AutoGuess,
    SetGuess(Param, f64),
    Handle(Gesture),
    SetMethod(Method),
    SetMultistart(bool),
    SetStarts(usize),
    Fit,
    CancelFit,
    /// Fit each input change on its own window again.
    FitEachStep,
    CancelPerStep,
    /// Stop waiting for the running diagnosis.
    CancelDiagnosis,
    /// The whole loop (`whole`) or one step of the diagnosis.
    Diagnose {
        whole: bool,
    },
    /// Show a row of the chain (0: its start).
    SelectStep(usize),
    SetMarkers(MeasuredMarkers),
    Landscape(LandscapeCommand),
    /// Open the fitted model in the Design mode.
    ShowOnSPlane,
    /// Open the fitted model in the Tune mode.
    TuneController,
    /// The hand methods' section.
    Hand(super::hand_state::HandCommand),
}

/// What the session asks of the app after a command.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// Show this transfer function on the s-plane, stepped by `du`.
    ShowOnSPlane {
        tf: degrau_lti::TransferFunction,
        du: f64,
    },
    /// Tune a controller for the fitted model (`code`: its structure), or say why it cannot.
    Tune {
        model: Result<crate::tune::model::ProcessSettings, crate::tune::model::ModelProblem>,
        code: String,
    },
    /// Choose a file with the file dialog (the app opens it).
    Pick(crate::dialog::Pick),
}
