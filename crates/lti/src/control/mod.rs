//! From a model to a controller: P, PI, PD and PID controllers ([`controller`]), the
//! unity-feedback loop around a plant with a true dead time ([`delay_loop`]: setpoint and
//! load responses computed without replacing the delay) and their metrics ([`metrics`]).

pub mod controller;

pub use controller::{Action, Controller, ControllerError, Form, Parallel};
pub mod delay_loop;

pub use delay_loop::{DelayLoopError, Horizon, LoopInput, LoopResponse, loop_response};
pub mod metrics;

pub use metrics::{LoopMetrics, Peak, loop_metrics};
