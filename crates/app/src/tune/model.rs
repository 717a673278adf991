//! The process model the Tune mode designs for: first order plus dead time (FOPTD,
//! K·e^{−θs}/(τs + 1)) or second order plus dead time (SOPTD, K·e^{−θs}/((τ1 s + 1)(τ2 s + 1))),
//! typed by the student or received from the Identify mode. Its numbers are checked here
//! ([`ModelProblem`]), so a typed value that makes no model is refused and the model kept.

use serde::{Deserialize, Serialize};

use degrau_ident::model::{Model as Fitted, Param as FitParam};
use degrau_lti::TransferFunction;
use degrau_lti::control::{ModelError, ProcessModel};

/// Which of the two models.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ModelKind {
    /// K·e^{−θs}/(τs + 1).
    #[default]
    Foptd,
    /// K·e^{−θs}/((τ1 s + 1)(τ2 s + 1)).
    Soptd,
}

/// One number of the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ModelParam {
    /// The static gain K.
    Gain,
    /// τ (FOPTD) or τ1 (SOPTD), s.
    Tau1,
    /// τ2 (SOPTD), s.
    Tau2,
    /// The dead time θ, s.
    Delay,
}

/// The largest time constant or dead time accepted (s).
pub const MAX_TIME: f64 = 1e6;

/// Why the model's numbers make no model.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelProblem {
    /// K is 0 or not finite.
    Gain(f64),
    /// A time constant is not a positive number of seconds (up to [`MAX_TIME`]).
    TimeConstant(f64),
    /// The dead time is negative or beyond [`MAX_TIME`].
    Delay(f64),
    /// The Identify mode's model is not first or second order with dead time (its code).
    NotTunable(String),
}

/// The model's numbers (τ2 kept while FOPTD is chosen, so switching back loses nothing).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ProcessSettings {
    pub kind: ModelKind,
    pub k: f64,
    pub tau1: f64,
    pub tau2: f64,
    pub theta: f64,
}

impl Default for ProcessSettings {
    fn default() -> Self {
        Self {
            kind: ModelKind::Foptd,
            k: 1.0,
            tau1: 10.0,
            tau2: 2.0,
            theta: 2.0,
        }
    }
}

impl ProcessSettings {
    /// The number `p`.
    pub fn get(&self, p: ModelParam) -> f64 {
        match p {
            ModelParam::Gain => self.k,
            ModelParam::Tau1 => self.tau1,
            ModelParam::Tau2 => self.tau2,
            ModelParam::Delay => self.theta,
        }
    }

    /// The same model with `p` set to `value`, if it is still a model.
    pub fn with(&self, p: ModelParam, value: f64) -> Result<Self, ModelProblem> {
        let mut m = *self;
        match p {
            ModelParam::Gain => m.k = value,
            ModelParam::Tau1 => m.tau1 = value,
            ModelParam::Tau2 => m.tau2 = value,
            ModelParam::Delay => m.theta = value,
        }
        m.check().map(|()| m)
    }

    /// Whether the numbers make a model.
    pub fn check(&self) -> Result<(), ModelProblem> {
        if !(self.k.is_finite() && self.k != 0.0) {
            return Err(ModelProblem::Gain(self.k));
        }
        let time = |t: f64| t.is_finite() && t > 0.0 && t <= MAX_TIME;
        for tau in [self.tau1, self.tau2] {
            if !time(tau) {
                return Err(ModelProblem::TimeConstant(tau));
            }
        }
        if !(self.theta.is_finite() && (0.0..=MAX_TIME).contains(&self.theta)) {
            return Err(ModelProblem::Delay(self.theta));
        }
        Ok(())
    }

    /// The plant's transfer function, its dead time included.
    pub fn transfer_function(&self) -> Option<TransferFunction> {
        let den = match self.kind {
            ModelKind::Foptd => vec![self.tau1, 1.0],
            ModelKind::Soptd => vec![self.tau1 * self.tau2, self.tau1 + self.tau2, 1.0],
        };
        TransferFunction::from_coeffs(&[self.k], &den)
            .and_then(|tf| tf.with_delay(self.theta))
            .ok()
    }

    /// The lti crate's model, which the tuning rules read.
    pub fn process_model(&self) -> Result<ProcessModel, ModelError> {
        match self.kind {
            ModelKind::Foptd => ProcessModel::foptd(self.k, self.tau1, self.theta),
            ModelKind::Soptd => ProcessModel::soptd(self.k, self.tau1, self.tau2, self.theta),
        }
    }

    /// The model of a fit of the Identify mode: P1D (or P1) as FOPTD, P2D (or P2) as
    /// SOPTD; any other structure is not tuned here.
    pub fn from_fitted(fitted: &Fitted) -> Result<Self, ModelProblem> {
        let s = fitted.structure;
        let code = s.code();
        let plain = !(s.underdamped || s.zero || s.integrator);
        let kind = match s.poles {
            1 if plain => ModelKind::Foptd,
            2 if plain => ModelKind::Soptd,
            _ => return Err(ModelProblem::NotTunable(code)),
        };
        // A fit may place the step's effect up to a sample before the step logged (a step
        // between samples): a loop has no negative dead time, so that is θ = 0.
        let theta = if s.delay {
            fitted.get(FitParam::Td).max(0.0)
        } else {
            0.0
        };
        let (tau1, tau2) = match kind {
            ModelKind::Foptd => (fitted.get(FitParam::Tp1), Self::default().tau2),
            ModelKind::Soptd => (fitted.get(FitParam::Tp1), fitted.get(FitParam::Tp2)),
        };
        let m = Self {
            kind,
            k: fitted.get(FitParam::Kp),
            tau1,
            tau2,
            theta,
        };
        m.check().map(|()| m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_model_is_checked() {
        let m = ProcessSettings::default();
        assert!(m.check().is_ok());
        assert_eq!(m.with(ModelParam::Gain, 0.0), Err(ModelProblem::Gain(0.0)));
        assert!(matches!(
            m.with(ModelParam::Tau1, -1.0),
            Err(ModelProblem::TimeConstant(_))
        ));
        assert!(matches!(
            m.with(ModelParam::Delay, -1.0),
            Err(ModelProblem::Delay(_))
        ));
        assert_eq!(m.with(ModelParam::Delay, 0.0).map(|m| m.theta), Ok(0.0));
        let tf = m.transfer_function().expect("a plant");
        assert_eq!(tf.delay(), 2.0);
    }
}
