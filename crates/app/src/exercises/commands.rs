//! What the Exercises views ask for ([`Command`]), applied by
//! [`super::session::Session::apply`] once per frame, and what a command asks of the app
//! ([`Outcome`]: a part's system loaded into the Design mode).

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
}

/// What a command asks of the app.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Load this into the Design mode and show it.
    Load(Box<Load>),
}
