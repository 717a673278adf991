//! The Tune mode's session: the settings it keeps between runs ([`Saved`]: the model, the
//! controller, τc and the rule chosen) and what is derived from them (the loop's responses
//! and metrics), recomputed only when the model or the controller changed. No egui here:
//! the views read a session and return [`Command`]s, and [`Session::apply`] is the only
//! place the settings change. An entry that makes no model or no controller is refused
//! ([`Refusal`], said beside the fields) and the settings are kept as they were.

use serde::{Deserialize, Serialize};

use degrau_lti::control::{
    Action, Controller, ControllerError, RuleRow, controller::DEFAULT_FILTER, rule_table,
};

use super::commands::{Command, Param};
use super::derived::{LoopTrouble, LoopView, compute};
use super::model::{ModelParam, ModelProblem, ProcessSettings};

/// The controller's numbers in the ideal form (Ti and Td kept whatever the action, so a
/// switch from PI to P and back loses nothing).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ControllerSettings {
    pub action: Action,
    pub kc: f64,
    pub ti: f64,
    pub td: f64,
    pub n: f64,
    pub b: f64,
}

impl Default for ControllerSettings {
    /// SIMC's PI for the default model (K = 1, τ = 10 s, θ = 2 s, τc = θ).
    fn default() -> Self {
        Self {
            action: Action::PI,
            kc: 2.5,
            ti: 10.0,
            td: 1.0,
            n: DEFAULT_FILTER,
            b: 1.0,
        }
    }
}

impl ControllerSettings {
    /// The controller these numbers make.
    pub fn controller(&self) -> Result<Controller, ControllerError> {
        Controller::new(self.action, self.kc, self.ti, self.td)?
            .with_filter(self.n)?
            .with_setpoint_weight(self.b)
    }

    /// Whether every number is usable, whatever the action (Ti and Td included).
    pub fn check(&self) -> Result<(), ControllerError> {
        Controller {
            action: Action::PID,
            kc: self.kc,
            ti: self.ti,
            td: self.td,
            n: self.n,
            b: self.b,
        }
        .checked()
        .map(|_| ())
    }

    pub fn get(&self, p: Param) -> f64 {
        match p {
            Param::Kc => self.kc,
            Param::Ti => self.ti,
            Param::Td => self.td,
            Param::N => self.n,
            Param::B => self.b,
        }
    }

    /// The same controller with `p` set to `value`, if it is still a controller.
    pub fn with(&self, p: Param, value: f64) -> Result<Self, ControllerError> {
        let mut c = *self;
        match p {
            Param::Kc => c.kc = value,
            Param::Ti => c.ti = value,
            Param::Td => c.td = value,
            Param::N => c.n = value,
            Param::B => c.b = value,
        }
        c.check().map(|()| c)
    }
}

/// What the Tune mode keeps between runs (the state file's `tune`).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub model: ProcessSettings,
    /// The structure of the Identify mode's fit the model came from (none: typed).
    pub received: Option<String>,
    pub controller: ControllerSettings,
    /// The closed-loop time constant τc (s) of the rules that take one; none: τc = θ.
    pub tc: Option<f64>,
    /// The key of the rule whose row was chosen last.
    pub rule: Option<String>,
}

impl Saved {
    /// The plant (its dead time included) and the controller of the loop, when both are
    /// usable (the Frequency mode's loop source).
    pub fn plant_and_controller(&self) -> Option<(degrau_lti::TransferFunction, Controller)> {
        self.model.check().ok()?;
        let plant = self.model.transfer_function()?;
        Some((plant, self.controller.controller().ok()?))
    }
}

/// Checks a τc: a positive number of seconds.
pub fn check_tc(tc: f64) -> Result<(), ModelProblem> {
    if tc.is_finite() && tc > 0.0 && tc <= super::model::MAX_TIME {
        Ok(())
    } else {
        Err(ModelProblem::TimeConstant(tc))
    }
}

/// An entry refused, said until the next accepted change.
#[derive(Debug, Clone, PartialEq)]
pub enum Refusal {
    Model(ModelParam, ModelProblem),
    /// The Identify mode's model could not be taken (its structure's code).
    Received(ModelProblem),
    Controller(Param, ControllerError),
    Tc(ModelProblem),
}

/// The Tune mode's derived data.
#[derive(Debug, Default)]
pub struct Session {
    /// The loop's responses and metrics, or why there are none.
    pub view: Option<Result<LoopView, LoopTrouble>>,
    /// The last entry refused.
    pub refusal: Option<Refusal>,
    /// The model and controller `view` was computed from.
    computed: Option<(ProcessSettings, ControllerSettings)>,
    /// How many times the loop was computed (a test sees it is not every frame).
    pub computations: usize,
    /// Every rule's row for the model, the action and τc (none: the model is no model).
    pub table: Vec<RuleRow>,
    /// The model, action and τc the table was computed from.
    table_inputs: Option<(ProcessSettings, Action, Option<f64>)>,
}

impl Session {
    /// The session of `kept`, its loop computed.
    pub fn new(kept: &Saved) -> Self {
        let mut s = Self::default();
        s.refresh(kept);
        s
    }

    /// Recomputes the loop when the model or the controller changed (else nothing).
    pub fn refresh(&mut self, kept: &Saved) {
        let table_inputs = (kept.model, kept.controller.action, kept.tc);
        if self.table_inputs != Some(table_inputs) {
            self.table = kept
                .model
                .process_model()
                .map(|m| rule_table(&m, kept.controller.action, kept.tc))
                .unwrap_or_default();
            self.table_inputs = Some(table_inputs);
        }
        let inputs = (kept.model, kept.controller);
        if self.computed == Some(inputs) {
            return;
        }
        self.view = Some(compute(&kept.model, &kept.controller));
        self.computed = Some(inputs);
        self.computations += 1;
    }

    /// Applies one command to `kept`, then brings the derived data up to date.
    pub fn apply(&mut self, kept: &mut Saved, command: Command) {
        if let Err(refusal) = carry_out(kept, command, &self.table) {
            self.refusal = Some(refusal);
        } else {
            self.refusal = None;
        }
        self.refresh(kept);
    }
}

fn carry_out(kept: &mut Saved, command: Command, table: &[RuleRow]) -> Result<(), Refusal> {
    match command {
        Command::SetModelKind(kind) => {
            kept.model.kind = kind;
            kept.received = None;
        }
        Command::SetModel(p, value) => {
            kept.model = kept
                .model
                .with(p, value)
                .map_err(|e| Refusal::Model(p, e))?;
            kept.received = None;
        }
        Command::Receive { model, code } => {
            kept.model = model.map_err(Refusal::Received)?;
            kept.received = Some(code);
        }
        Command::SetAction(action) => kept.controller.action = action,
        Command::SetParam(p, value) => {
            kept.controller = kept
                .controller
                .with(p, value)
                .map_err(|e| Refusal::Controller(p, e))?;
        }
        Command::SetTc(tc) => {
            if let Some(t) = tc {
                check_tc(t).map_err(Refusal::Tc)?;
            }
            kept.tc = tc;
        }
        Command::UseRule(key) => {
            let tuned = table
                .iter()
                .filter(|row| row.rule.key() == key)
                .find_map(|row| row.result.as_ref().ok());
            if let Some((tuning, _)) = tuned {
                let c = &tuning.controller;
                let k = &mut kept.controller;
                k.action = c.action;
                k.kc = c.kc;
                // A P controller's Ti (infinite) and a PI's Td (0) leave the student's kept.
                if c.action.integral() {
                    k.ti = c.ti;
                }
                if c.action.derivative() {
                    k.td = c.td;
                }
                kept.rule = Some(key);
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_ti_is_refused_and_nothing_is_lost() {
        let mut kept = Saved::default();
        let mut s = Session::new(&kept);
        let before = kept.clone();
        s.apply(&mut kept, Command::SetParam(Param::Ti, 0.0));
        assert_eq!(kept, before);
        assert!(matches!(
            s.refusal,
            Some(Refusal::Controller(
                Param::Ti,
                ControllerError::IntegralTime(_)
            ))
        ));
        assert!(matches!(s.view, Some(Ok(_))));
        s.apply(&mut kept, Command::SetParam(Param::Ti, 20.0));
        assert_eq!(s.refusal, None);
        assert_eq!(kept.controller.ti, 20.0);
    }

    #[test]
    fn the_loop_is_computed_only_on_change() {
        let kept = Saved::default();
        let mut s = Session::new(&kept);
        s.refresh(&kept);
        s.refresh(&kept);
        assert_eq!(s.computations, 1);
    }
}
