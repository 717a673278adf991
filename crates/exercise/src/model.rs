//! The shape of the sheet as data: exercises, their lettered parts, the system each part loads
//! into the app, the questions with the answers Degrau computed, the sheet's printed answer
//! beside each, and the documented differences.
//!
//! Ids are stable strings (`"4"`, `"1a"`, `"1a.tau"`) so a saved state can refer to them;
//! nothing here computes (the exercises in [`crate::sheet`] fill it from `degrau-lti`).

use degrau_lti::{C64, TransferFunction};
use serde::Serialize;

use crate::text::Text;

/// One numbered exercise of the sheet.
#[derive(Debug, Clone, Serialize)]
pub struct Exercise {
    /// `"1"` … `"13"`.
    pub id: String,
    /// What the exercise says before its lettered parts (the sheet's words, and English).
    pub statement: Text,
    pub parts: Vec<Part>,
}

/// One lettered part (or the whole exercise when it has no letters).
#[derive(Debug, Clone, Serialize)]
pub struct Part {
    /// `"1a"`, `"2"`, `"13b"`.
    pub id: String,
    /// The part's statement as the sheet words it, and in English.
    pub statement: Text,
    /// What to load into the app.
    pub system: System,
    /// The mode the part belongs to.
    pub mode: Mode,
    pub questions: Vec<Question>,
    /// The worked solution, one line per step.
    pub solution: Vec<Text>,
}

/// The mode (and view) of the app a part belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Design: the s-plane and the step response of one transfer function.
    DesignStep,
    /// Design: the s-plane with a region of specs and the poles that meet it.
    DesignPlane,
    /// Design: the unity-feedback loop around a gain K, its root locus.
    DesignLoop,
    /// Identify: read the parameters off a figure of a step response.
    Identify,
}

/// What a part loads.
#[derive(Debug, Clone, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum System {
    /// A transfer function (with its dead time) and the step's amplitude.
    Tf {
        tf: TransferFunction,
        amplitude: f64,
    },
    /// The unity-feedback loop around K·C(s)·G(s): `plant` G, `controller` C, the gain K the
    /// solution arrives at (the app starts from it after Check).
    Loop {
        plant: TransferFunction,
        controller: Controller,
        gain: f64,
    },
    /// A figure of a step response: the readings the sheet takes off it, and the curve the
    /// figure shows (rebuilt from the readings by Degrau's answer: the sheet's figures are
    /// not in its text).
    Figure {
        curve: TransferFunction,
        amplitude: f64,
        readings: Vec<Reading>,
    },
    /// Specs to place in the s-plane, and the system of the solution.
    Specs {
        specs: Vec<Reading>,
        solution: TransferFunction,
    },
}

/// The controller of a loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Controller {
    /// C(s) = 1: the gain K alone.
    Proportional,
    /// C(s) = 1/(s + a): K/(s + a), the compensator of exercise 8.
    Pole { a: f64 },
}

/// A number read off a figure or given as a spec.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reading {
    /// Stable key (`tp`, `y_peak`, `y_final`, `overshoot`, …).
    pub key: String,
    pub label: Text,
    pub value: f64,
    pub unit: Unit,
}

/// A unit of a number answer (written the same in both languages).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Unit {
    None,
    Seconds,
    RadPerSecond,
    Percent,
    PerSecond,
    NewtonPerMetre,
    Kilogram,
    NewtonSecondPerMetre,
    Metre,
}

impl Unit {
    /// The symbol (empty for none).
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::None => "",
            Unit::Seconds => "s",
            Unit::RadPerSecond => "rad/s",
            Unit::Percent => "%",
            Unit::PerSecond => "s⁻¹",
            Unit::NewtonPerMetre => "N/m",
            Unit::Kilogram => "kg",
            Unit::NewtonSecondPerMetre => "N s/m",
            Unit::Metre => "m",
        }
    }
}

/// One question of a part: what the student answers in one field.
#[derive(Debug, Clone, Serialize)]
pub struct Question {
    /// `"1a.tau"`, `"8b.K"`: the part's id, a dot, the quantity's key.
    pub id: String,
    pub label: Text,
    /// Degrau's answer (with what it accepts besides).
    pub expected: Expected,
    pub tolerance: Tolerance,
    /// The sheet's printed answer, as a student would type it (`None` when the sheet prints
    /// none for this question).
    pub sheet: Option<String>,
    /// Why the sheet's printed answer differs from Degrau's, when it does.
    pub difference: Option<Text>,
}

/// What kind of field a question needs (the app picks its widget from it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AnswerKind {
    Number(Unit),
    TransferFunction,
    GainRange,
    Region,
    ClosedForm,
    Roots,
    Choice,
}

/// A number Degrau computed, and how.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Value {
    pub value: f64,
    /// How it was computed: "exact step response", "second-order formula", …
    pub how: Text,
}

/// Degrau's answer to a question.
#[derive(Debug, Clone, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Expected {
    /// A number (∞ allowed); `also`: other values accepted, each saying why (the
    /// second-order formula's value where the sheet asks for the formula, another
    /// definition of a metric).
    Number {
        unit: Unit,
        main: Value,
        also: Vec<Value>,
    },
    /// A transfer function: fixed, or the closed loop of K·G as a function of K.
    TransferFunction(TfAnswer),
    /// The gains K > 0 meeting a spec: [low, high], high = ∞ when unbounded; `also`: other
    /// ranges accepted.
    GainRange {
        main: GainRange,
        also: Vec<(GainRange, Text)>,
    },
    /// A region of the s-plane: ζ ≥ zeta_min and σ = −Re(s) ≥ sigma_min.
    Region(Region),
    /// y(t) as an expression of t: checked at `instants` against the exact response of
    /// `tf` to a step of `amplitude`.
    ClosedForm {
        tf: TransferFunction,
        amplitude: f64,
        instants: Vec<f64>,
    },
    /// A set of roots (poles or zeros), empty for none.
    Roots(Vec<C64>),
    /// One of several words.
    Choice { options: Vec<Choice>, right: Choice },
}

/// A fixed transfer function, or the closed loop K·G/(1 + K·G) of `open` for any K.
#[derive(Debug, Clone, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TfAnswer {
    Fixed(TransferFunction),
    ClosedLoopInK(TransferFunction),
}

/// A range of gains.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GainRange {
    pub low: f64,
    pub high: f64,
}

/// A region of the s-plane.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Region {
    pub zeta_min: f64,
    pub sigma_min: f64,
}

/// The words a choice question accepts, by stable id.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Choice {
    Overdamped,
    CriticallyDamped,
    Underdamped,
    Undamped,
    Yes,
    No,
}

impl Choice {
    /// The response types, in order.
    pub const RESPONSE_TYPES: [Choice; 4] = [
        Choice::Overdamped,
        Choice::CriticallyDamped,
        Choice::Underdamped,
        Choice::Undamped,
    ];
    /// Yes or no.
    pub const YES_NO: [Choice; 2] = [Choice::Yes, Choice::No];

    /// The stable id.
    pub fn id(self) -> &'static str {
        match self {
            Choice::Overdamped => "overdamped",
            Choice::CriticallyDamped => "critically_damped",
            Choice::Underdamped => "underdamped",
            Choice::Undamped => "undamped",
            Choice::Yes => "yes",
            Choice::No => "no",
        }
    }
}

/// How close a number must be.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Tolerance {
    /// |answer − expected| ≤ this·|expected|.
    Relative(f64),
    /// |answer − expected| ≤ this.
    Absolute(f64),
}

impl Tolerance {
    /// Whether `answer` is within the tolerance of `expected` (∞ only matches ∞).
    pub fn accepts(self, answer: f64, expected: f64) -> bool {
        if expected.is_infinite() || answer.is_infinite() {
            return answer == expected;
        }
        let bound = match self {
            Tolerance::Relative(r) => r * expected.abs(),
            Tolerance::Absolute(a) => a,
        };
        // A zero expected under a relative tolerance: only rounding noise is accepted.
        (answer - expected).abs() <= bound.max(1e-12)
    }
}

impl Question {
    /// The kind of field the question needs.
    pub fn kind(&self) -> AnswerKind {
        match &self.expected {
            Expected::Number { unit, .. } => AnswerKind::Number(*unit),
            Expected::TransferFunction(_) => AnswerKind::TransferFunction,
            Expected::GainRange { .. } => AnswerKind::GainRange,
            Expected::Region(_) => AnswerKind::Region,
            Expected::ClosedForm { .. } => AnswerKind::ClosedForm,
            Expected::Roots(_) => AnswerKind::Roots,
            Expected::Choice { .. } => AnswerKind::Choice,
        }
    }
}

impl Exercise {
    /// The part with this id.
    pub fn part(&self, id: &str) -> Option<&Part> {
        self.parts.iter().find(|p| p.id == id)
    }
}

impl Part {
    /// The question with this id.
    pub fn question(&self, id: &str) -> Option<&Question> {
        self.questions.iter().find(|q| q.id == id)
    }
}
