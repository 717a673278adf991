//! What the Tune views ask for: every change to the Tune mode's settings is one
//! [`Command`], returned by a view while it draws and applied by
//! [`super::session::Session::apply`] once per frame, after the views.

use degrau_lti::control::Action;

use super::model::{ModelKind, ModelParam, ProcessSettings};

/// One number of the controller.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Param {
    Kc,
    Ti,
    Td,
    /// The derivative filter N.
    N,
    /// The setpoint weight b.
    B,
}

impl Param {
    pub const ALL: [Param; 5] = [Param::Kc, Param::Ti, Param::Td, Param::N, Param::B];
}

/// One change to the Tune mode's settings.
#[must_use = "a command does nothing until the session applies it"]
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    SetModelKind(ModelKind),
    /// A model number typed (refused, with the reason shown, when it makes no model).
    SetModel(ModelParam, f64),
    /// A model received from the Identify mode (`code` is the fitted structure), or why it
    /// could not be taken.
    Receive {
        model: Result<ProcessSettings, super::model::ModelProblem>,
        code: String,
    },
    SetAction(Action),
    /// A controller number typed or dragged (refused, with the reason shown, when it makes
    /// no controller).
    SetParam(Param, f64),
    /// The closed-loop time constant τc of the rules that take one (none: τc = θ).
    SetTc(Option<f64>),
    /// A row of the rule table chosen: its Kc, Ti and Td are loaded into the controller.
    UseRule(String),
}
