//! What the Exercises views ask for ([`Command`]), applied by
//! [`super::session::Session::apply`] once per frame, and what a command asks of the app
//! ([`Outcome`]: a part's system loaded into the Design mode).

use degrau_ident::challenge::Level;

use super::challenges::Field;
use super::load::Load;

/// One change to the Exercises mode.
#[must_use = "a command does nothing until the session applies it"]
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Open the part with this id.
    Select(String),
    /// The text typed for a question (by its id).
    Type { question: String, text: String },
    /// Check every answer typed in the part.
    Check(String),
    /// Show (or hide) the part's worked solution.
    ShowSolution(String, bool),
    /// Load the part's system into the Design mode.
    OpenInDesign(String),
    /// Something of the Challenges.
    Challenge(ChallengeCommand),
}

/// One change to the Challenges.
#[derive(Debug, Clone, PartialEq)]
pub enum ChallengeCommand {
    /// Show the challenge in the centre.
    Open,
    /// The level the next challenge is drawn at.
    SetLevel(Level),
    /// Draw the next challenge (off the UI thread).
    New,
    /// Stop drawing.
    Cancel,
    /// The text typed in an answer field.
    Type(Field, String),
    /// Grade the answers against the hidden truth.
    Check,
    /// Reveal Degrau's own diagnosis (after Check).
    ShowDiagnosis,
    /// Load the challenge's record into the Identify mode.
    OpenRecord,
}

/// What a command asks of the app.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Load this into the Design mode and show it.
    Load(Box<Load>),
    /// Load this record (CSV text, columns t,u,y) into the Identify mode and show it.
    Record(String),
}
