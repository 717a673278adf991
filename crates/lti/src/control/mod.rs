//! From a model to a controller: P, PI, PD and PID controllers ([`controller`]), the
//! unity-feedback loop around a plant with a true dead time ([`delay_loop`]: setpoint and
//! load responses computed without replacing the delay) and their metrics ([`metrics`]).

pub mod controller;
pub mod frequency;
pub mod tuning;

pub use controller::{Action, Controller, ControllerError, Form, Parallel};
pub use frequency::{Sensitivity, StabilityError, Ultimate};
pub use tuning::{ModelError, NotApplicable, ProcessModel, Rule, Tuning};
