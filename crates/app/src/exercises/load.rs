//! A part's system as the Design mode holds it: a transfer function (or a figure's curve,
//! or the solution of specs placed on the s-plane) becomes the poles and zeros of
//! [`System`]; a loop K·C(s)·G(s) becomes the system C(s)·G(s) with the loop closed around
//! the gain K (C = 1/(s + a) goes into the system, so the Design loop's Kp is the sheet's K);
//! specs are set as the Design loop's specs. What the Design mode cannot hold is refused
//! with the reason, never loaded changed.

use degrau_exercise::{Controller, Reading, System as Part};
use degrau_lti::{LtiError, TransferFunction};

use crate::design::closed_loop::Specs;
use crate::design::state::{System, SystemProblem};
use crate::field::LimitReason;

/// What the Design mode is given.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    pub system: System,
    /// The loop closed around this gain K (none: the open system alone).
    pub loop_gain: Option<f64>,
    /// The specs shaded on the s-plane (none: left as they are).
    pub specs: Option<Specs>,
}

/// Why a part's system cannot be loaded (said in words by
/// [`crate::words::exercises`]).
#[derive(Debug, Clone, PartialEq)]
pub enum LoadProblem {
    Lti(LtiError),
    System(SystemProblem),
    Placement(LimitReason),
}

/// The Design mode's load of a part's system.
pub fn design_load(part: &Part) -> Result<Load, LoadProblem> {
    let (tf, amplitude, loop_gain, specs) = match part {
        Part::Tf { tf, amplitude } => (tf.clone(), *amplitude, None, None),
        Part::Figure {
            curve, amplitude, ..
        } => (curve.clone(), *amplitude, None, None),
        Part::Loop {
            plant,
            controller,
            gain,
        } => (open_loop(plant, *controller)?, 1.0, Some(*gain), None),
        Part::Specs { specs, solution } => (solution.clone(), 1.0, None, Some(design_specs(specs))),
    };
    let system = System::from_transfer_function(&tf, amplitude);
    system.check().map_err(LoadProblem::System)?;
    system.placement().map_err(LoadProblem::Placement)?;
    Ok(Load {
        system,
        loop_gain,
        specs,
    })
}

/// C(s)·G(s) for the loop's controller.
fn open_loop(
    plant: &TransferFunction,
    controller: Controller,
) -> Result<TransferFunction, LoadProblem> {
    match controller {
        Controller::Proportional => Ok(plant.clone()),
        Controller::Pole { a } => TransferFunction::from_coeffs(&[1.0], &[1.0, a])
            .and_then(|c| c.series(plant))
            .map_err(LoadProblem::Lti),
    }
}

/// The Design loop's specs from the readings the part gives (Mp ≤ …, t_s ≤ …).
fn design_specs(readings: &[Reading]) -> Specs {
    let find = |key: &str| readings.iter().find(|r| r.key == key).map(|r| r.value);
    Specs {
        overshoot: find("overshoot"),
        settling: find("settling"),
        ..Specs::default()
    }
}
