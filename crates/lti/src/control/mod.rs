//! From a model to a controller: P, PI, PD and PID controllers ([`controller`]), the
//! unity-feedback loop around a plant with a true dead time ([`delay_loop`]: setpoint and
//! load responses computed without replacing the delay) and their metrics ([`metrics`]),
//! the loop's frequency facts (ultimate gain, stability, Ms: [`frequency`]), its
//! stability margins ([`margins`]), the tuning rules ([`tuning`]) and the table that sets them side by side ([`table`]).

pub mod controller;
pub mod delay_loop;
pub mod frequency;
pub mod margins;
pub mod metrics;
pub mod nyquist;
pub mod table;
pub mod tuning;

pub use controller::{Action, Controller, ControllerError, Form, Parallel};
pub use delay_loop::{DelayLoopError, Horizon, LoopInput, LoopResponse, loop_response};
pub use frequency::{Sensitivity, StabilityError, Ultimate};
pub use margins::{GainCrossing, Margins, PhaseCrossing, margins};
pub use metrics::{LoopMetrics, Peak, loop_metrics};
pub use nyquist::{Nyquist, NyquistPoint, nyquist};
pub use table::{RowError, RuleRow, TunedLoop, rule_table, tuned_loop};
pub use tuning::{ModelError, NotApplicable, ProcessModel, Rule, Tuning};
