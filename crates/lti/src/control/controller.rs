//! The controllers of a first course: P, PI, PD and PID in the ideal (ISA) form
//! C(s) = Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N)), the default, or read in the parallel form
//! Kp + Ki/s + Kd·s/(1 + Tf·s) (Kp = Kc, Ki = Kc/Ti, Kd = Kc·Td, Tf = Td/N: the same
//! controller). The derivative is filtered (N = 10 by default, as MATLAB's `pidstd` advises)
//! so that C is proper; a setpoint weight b on the proportional term (u = Kc·(b·r − y) + …,
//! b = 1 by default) gives the two-degree-of-freedom form of Åström and Hägglund (2006,
//! §3.4): the feedback path C(s) is unchanged, the reference path is Cr(s).
//!
//! Parameters are kept in the ideal form; [`Controller::parallel`] converts.

use serde::{Deserialize, Serialize};

use crate::TransferFunction;
use crate::poly::C64;

/// Which actions a controller has.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Action {
    P,
    PI,
    PD,
    PID,
}

impl Action {
    pub const ALL: [Action; 4] = [Action::P, Action::PI, Action::PD, Action::PID];

    /// Whether the controller integrates (has Ti).
    pub fn integral(self) -> bool {
        matches!(self, Action::PI | Action::PID)
    }

    /// Whether the controller differentiates (has Td).
    pub fn derivative(self) -> bool {
        matches!(self, Action::PD | Action::PID)
    }

    /// The stable key of the command line and the JSON: `p`, `pi`, `pd`, `pid`.
    pub fn key(self) -> &'static str {
        match self {
            Action::P => "p",
            Action::PI => "pi",
            Action::PD => "pd",
            Action::PID => "pid",
        }
    }

    /// The action named by [`Self::key`] (any case).
    pub fn from_key(key: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|a| a.key().eq_ignore_ascii_case(key.trim()))
    }
}

/// How the parameters are written (the controller is the same).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Form {
    /// Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N)): ISA, "standard", MATLAB's `pidstd`.
    #[default]
    Ideal,
    /// Kp + Ki/s + Kd·s/(1 + Tf·s): MATLAB's `pid`.
    Parallel,
}

impl Form {
    /// `ideal` or `parallel` (the JSON key).
    pub fn key(self) -> &'static str {
        match self {
            Form::Ideal => "ideal",
            Form::Parallel => "parallel",
        }
    }
}

/// The parallel form's gains of a controller: Kp + Ki/s + Kd·s/(1 + Tf·s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Parallel {
    pub kp: f64,
    /// Ki = Kc/Ti (1/s); 0 without integral action.
    pub ki: f64,
    /// Kd = Kc·Td (s); 0 without derivative action.
    pub kd: f64,
    /// Tf = Td/N (s), the derivative filter's time constant; 0 without derivative action.
    pub tf: f64,
}

/// A P, PI, PD or PID controller in the ideal form, with its derivative filter and setpoint
/// weight. Build it with [`Controller::new`], which checks the numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Controller {
    pub action: Action,
    /// Kc, the proportional gain (the plant's input units per output unit).
    pub kc: f64,
    /// Ti (s), the integral time; ignored without integral action.
    pub ti: f64,
    /// Td (s), the derivative time; ignored without derivative action.
    pub td: f64,
    /// N, the derivative filter: the filter's time constant is Td/N.
    pub n: f64,
    /// b, the setpoint weight on the proportional term (0 ≤ b ≤ 1; 1 is the error form).
    pub b: f64,
}

/// The default derivative filter N.
pub const DEFAULT_FILTER: f64 = 10.0;

/// A controller parameter that cannot be used, with the value given.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum ControllerError {
    /// Kc is zero or not finite.
    Gain(f64),
    /// Ti is not a positive finite number of seconds.
    IntegralTime(f64),
    /// Td is negative or not finite.
    DerivativeTime(f64),
    /// N is not a positive finite number.
    Filter(f64),
    /// b is outside [0, 1].
    SetpointWeight(f64),
}

impl Controller {
    /// A controller from its ideal-form parameters (Ti ignored without I, Td without D),
    /// N = [`DEFAULT_FILTER`], b = 1.
    pub fn new(action: Action, kc: f64, ti: f64, td: f64) -> Result<Self, ControllerError> {
        Self {
            action,
            kc,
            ti,
            td,
            n: DEFAULT_FILTER,
            b: 1.0,
        }
        .checked()
    }

    /// A proportional controller Kc.
    pub fn proportional(kc: f64) -> Result<Self, ControllerError> {
        Self::new(Action::P, kc, f64::INFINITY, 0.0)
    }

    /// The same controller with the derivative filter N.
    pub fn with_filter(mut self, n: f64) -> Result<Self, ControllerError> {
        self.n = n;
        self.checked()
    }

    /// The same controller with the setpoint weight b.
    pub fn with_setpoint_weight(mut self, b: f64) -> Result<Self, ControllerError> {
        self.b = b;
        self.checked()
    }

    /// The controller whose parallel-form gains are these (Kp = Kc, Ti = Kc/Ki, Td = Kd/Kc).
    pub fn from_parallel(
        action: Action,
        kp: f64,
        ki: f64,
        kd: f64,
    ) -> Result<Self, ControllerError> {
        let ti = if action.integral() {
            kp / ki
        } else {
            f64::INFINITY
        };
        let td = if action.derivative() { kd / kp } else { 0.0 };
        Self::new(action, kp, ti, td)
    }

    /// The parameters checked: an error names the first unusable one.
    pub fn checked(self) -> Result<Self, ControllerError> {
        if !self.kc.is_finite() || self.kc == 0.0 {
            return Err(ControllerError::Gain(self.kc));
        }
        if self.action.integral() && !(self.ti.is_finite() && self.ti > 0.0) {
            return Err(ControllerError::IntegralTime(self.ti));
        }
        if self.action.derivative() && !(self.td.is_finite() && self.td >= 0.0) {
            return Err(ControllerError::DerivativeTime(self.td));
        }
        if !(self.n.is_finite() && self.n > 0.0) {
            return Err(ControllerError::Filter(self.n));
        }
        if !(0.0..=1.0).contains(&self.b) {
            return Err(ControllerError::SetpointWeight(self.b));
        }
        Ok(self)
    }

    /// Td when the controller differentiates and Td > 0, else None.
    fn derivative_time(&self) -> Option<f64> {
        (self.action.derivative() && self.td > 0.0).then_some(self.td)
    }

    /// Ti when the controller integrates, else None.
    fn integral_time(&self) -> Option<f64> {
        self.action.integral().then_some(self.ti)
    }

    /// The parallel form's gains.
    pub fn parallel(&self) -> Parallel {
        let td = self.derivative_time().unwrap_or(0.0);
        Parallel {
            kp: self.kc,
            ki: self.integral_time().map_or(0.0, |ti| self.kc / ti),
            kd: self.kc * td,
            tf: td / self.n,
        }
    }

    /// The feedback path's numerator and denominator (descending powers):
    /// C(s) = Kc·(1 + 1/(Ti·s) + Td·s/(1 + Tf·s)), Tf = Td/N, over the common denominator
    /// s^i·(1 + Tf·s)^d.
    pub fn feedback_coeffs(&self) -> (Vec<f64>, Vec<f64>) {
        self.coeffs_with_weight(1.0)
    }

    /// The reference path Cr(s) = Kc·(b + 1/(Ti·s) + Td·s/(1 + Tf·s)): u = Cr·r − C·y. Its
    /// denominator is the feedback path's.
    pub fn reference_coeffs(&self) -> (Vec<f64>, Vec<f64>) {
        self.coeffs_with_weight(self.b)
    }

    /// Kc·(w + 1/(Ti·s) + Td·s/(1 + Tf·s)) as (num, den).
    fn coeffs_with_weight(&self, w: f64) -> (Vec<f64>, Vec<f64>) {
        let kc = self.kc;
        match (self.integral_time(), self.derivative_time()) {
            (None, None) => (vec![kc * w], vec![1.0]),
            // Kc·(w·T·s + 1)/(T·s).
            (Some(ti), None) => (vec![kc * w * ti, kc], vec![ti, 0.0]),
            // Kc·(w·(1 + Tf·s) + Td·s)/(1 + Tf·s).
            (None, Some(td)) => {
                let tf = td / self.n;
                (vec![kc * (w * tf + td), kc * w], vec![tf, 1.0])
            }
            // Kc·(w·Ti·s·(1 + Tf·s) + (1 + Tf·s) + Ti·Td·s²)/(Ti·s·(1 + Tf·s)).
            (Some(ti), Some(td)) => {
                let tf = td / self.n;
                (
                    vec![kc * (w * ti * tf + ti * td), kc * (w * ti + tf), kc],
                    vec![ti * tf, ti, 0.0],
                )
            }
        }
    }

    /// C(s) as a transfer function (None for a pure gain, which has no poles: the loop uses
    /// [`Self::feedback_coeffs`]).
    pub fn transfer_function(&self) -> Option<TransferFunction> {
        let (num, den) = self.feedback_coeffs();
        TransferFunction::from_coeffs(&num, &den).ok()
    }

    /// C(s) at a complex s.
    pub fn eval(&self, s: C64) -> C64 {
        let (num, den) = self.feedback_coeffs();
        crate::poly::eval_complex(&num, s) / crate::poly::eval_complex(&den, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_forms_are_one_controller() {
        let c = Controller::new(Action::PID, 2.0, 4.0, 0.5).unwrap();
        let p = c.parallel();
        assert_eq!((p.kp, p.ki, p.kd, p.tf), (2.0, 0.5, 1.0, 0.05));
        let back = Controller::from_parallel(Action::PID, p.kp, p.ki, p.kd).unwrap();
        assert_eq!(back, c);
        // Both forms at one s.
        let s = C64::new(0.3, 1.7);
        let parallel = C64::new(p.kp, 0.0) + p.ki / s + s * p.kd / (s * p.tf + 1.0);
        assert!((c.eval(s) - parallel).norm() < 1e-14 * parallel.norm());
    }

    #[test]
    fn the_reference_path_weights_only_the_proportional_term() {
        let c = Controller::new(Action::PI, 3.0, 2.0, 0.0)
            .unwrap()
            .with_setpoint_weight(0.0)
            .unwrap();
        let (num, den) = c.reference_coeffs();
        // Kc/(Ti·s): num 3, den 2s.
        assert_eq!((num, den), (vec![0.0, 3.0], vec![2.0, 0.0]));
    }

    #[test]
    fn bad_numbers_are_named() {
        assert_eq!(
            Controller::new(Action::PI, 1.0, 0.0, 0.0),
            Err(ControllerError::IntegralTime(0.0))
        );
        assert!(matches!(
            Controller::proportional(f64::NAN),
            Err(ControllerError::Gain(_))
        ));
        assert!(Controller::new(Action::PD, 1.0, 0.0, -1.0).is_err());
        assert!(Controller::new(Action::P, 1.0, 0.0, -1.0).is_ok());
    }
}
