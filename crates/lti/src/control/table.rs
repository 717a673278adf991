//! The tuning table: each rule's controller for a process model with both loop responses
//! (setpoint and load, exact with the dead time), their metrics, the maximum sensitivity Ms
//! and the loop's stability, side by side, as the Tune mode and `degrau tune` show them.

use super::delay_loop::{DelayLoopError, Horizon, LoopInput, LoopResponse, loop_response};
use super::frequency::{closed_loop_unstable_roots, max_sensitivity};
use super::metrics::{LoopMetrics, loop_metrics};
use super::tuning::{NotApplicable, ProcessModel, Rule, Tuning, tune};
use super::{Action, Controller};
use crate::{LtiError, TransferFunction};

/// A controller closed around a plant: both responses, their metrics, Ms and stability.
#[derive(Debug, Clone)]
pub struct TunedLoop {
    pub controller: Controller,
    pub setpoint: LoopResponse,
    pub load: LoopResponse,
    pub setpoint_metrics: LoopMetrics,
    pub load_metrics: LoopMetrics,
    /// Ms = max |1/(1 + L(jω))|; None when the loop is not stable.
    pub ms: Option<f64>,
    /// The closed loop's roots in the right half-plane (the argument principle, exact with
    /// the dead time); None when they cannot be counted (a root on the imaginary axis).
    pub unstable_roots: Option<usize>,
}

impl TunedLoop {
    /// Whether the closed loop is stable (no root in the right half-plane, none on the axis).
    pub fn is_stable(&self) -> bool {
        self.unstable_roots == Some(0)
    }
}

/// Both responses of the loop of `controller` around `plant`, computed until they settle.
pub fn tuned_loop(
    plant: &TransferFunction,
    controller: &Controller,
) -> Result<TunedLoop, DelayLoopError> {
    let unstable_roots = closed_loop_unstable_roots(plant, controller).ok();
    let setpoint = loop_response(plant, controller, LoopInput::Setpoint, Horizon::Auto)?;
    let load = loop_response(plant, controller, LoopInput::Load, Horizon::Auto)?;
    let stable = unstable_roots == Some(0);
    let metrics = |r: &LoopResponse| {
        if stable {
            loop_metrics(r)
        } else {
            LoopMetrics::NONE
        }
    };
    Ok(TunedLoop {
        controller: *controller,
        setpoint_metrics: metrics(&setpoint),
        load_metrics: metrics(&load),
        setpoint,
        load,
        ms: if stable {
            max_sensitivity(plant, controller).map(|s| s.ms)
        } else {
            None
        },
        unstable_roots,
    })
}

/// Why a row of the table has no loop.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum RowError {
    /// The rule does not apply to this model or controller.
    NotApplicable(NotApplicable),
    /// The loop could not be computed.
    Loop(DelayLoopError),
    /// The model is not a valid transfer function.
    Model(LtiError),
}

/// One rule's row: its tuning and loop, or why there is none.
#[derive(Debug, Clone)]
pub struct RuleRow {
    pub rule: Rule,
    pub result: Result<(Tuning, TunedLoop), RowError>,
}

/// Every rule's row for `model`, a PI or PID (`action`), τc (or λ) typed or the rules'
/// defaults, in the order of [`Rule::ALL`]; the rows are computed on threads of their own.
pub fn rule_table(model: &ProcessModel, action: Action, tc: Option<f64>) -> Vec<RuleRow> {
    let plant = model.transfer_function();
    std::thread::scope(|scope| {
        let handles: Vec<_> = Rule::ALL
            .iter()
            .map(|&rule| {
                let plant = &plant;
                scope.spawn(move || RuleRow {
                    rule,
                    result: row(model, plant, rule, action, tc),
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}

fn row(
    model: &ProcessModel,
    plant: &Result<TransferFunction, LtiError>,
    rule: Rule,
    action: Action,
    tc: Option<f64>,
) -> Result<(Tuning, TunedLoop), RowError> {
    let plant = plant.as_ref().map_err(|e| RowError::Model(e.clone()))?;
    let tuning = tune(model, rule, action, tc).map_err(RowError::NotApplicable)?;
    let tuned = tuned_loop(plant, &tuning.controller).map_err(RowError::Loop)?;
    Ok((tuning, tuned))
}
