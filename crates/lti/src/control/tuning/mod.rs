//! Tuning rules: from a process model — first order plus dead time (FOPTD) or second order
//! plus dead time (SOPTD), [`ProcessModel`] — to an ideal-form controller, by the published
//! formulas of Ziegler–Nichols (reaction curve and ultimate cycle), Cohen–Coon, IMC, SIMC,
//! AMIGO and Lambda ([`tune`]), each formula also given as text with its source
//! ([`formula`], said by [`crate::words::tuning`]). A rule that has no formula for a model or
//! an action says why ([`NotApplicable`]).

use serde::{Deserialize, Serialize};

use crate::TransferFunction;
use crate::control::frequency::Ultimate;
use crate::control::{Action, Controller, ControllerError};
use crate::poly::C64;

mod rules;

pub use rules::reaction_curve;
use rules::{amigo, cohen_coon, imc, lambda, reaction_curve_rule, simc, ultimate_rule};

/// A process model with a true dead time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum ProcessModel {
    /// K·e^{−θs}/(τs + 1).
    Foptd { k: f64, tau: f64, theta: f64 },
    /// K·e^{−θs}/((τ1·s + 1)(τ2·s + 1)), τ1 ≥ τ2 > 0.
    Soptd {
        k: f64,
        tau1: f64,
        tau2: f64,
        theta: f64,
    },
}

/// The kind of a model, which decides which formulas apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ModelKind {
    Foptd,
    Soptd,
}

/// A model parameter that cannot be used, with the value given.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum ModelError {
    /// K is zero or not finite.
    Gain(f64),
    /// A time constant is not a positive finite number.
    TimeConstant(f64),
    /// θ is negative or not finite.
    DeadTime(f64),
}

impl ProcessModel {
    /// K·e^{−θs}/(τs + 1), checked.
    pub fn foptd(k: f64, tau: f64, theta: f64) -> Result<Self, ModelError> {
        check_gain(k)?;
        check_time_constant(tau)?;
        check_dead_time(theta)?;
        Ok(Self::Foptd { k, tau, theta })
    }

    /// K·e^{−θs}/((τ1·s + 1)(τ2·s + 1)), checked; the time constants are put in order
    /// (τ1 ≥ τ2) whatever order they come in.
    pub fn soptd(k: f64, tau1: f64, tau2: f64, theta: f64) -> Result<Self, ModelError> {
        check_gain(k)?;
        check_time_constant(tau1)?;
        check_time_constant(tau2)?;
        check_dead_time(theta)?;
        let (tau1, tau2) = (tau1.max(tau2), tau1.min(tau2));
        Ok(Self::Soptd {
            k,
            tau1,
            tau2,
            theta,
        })
    }

    /// The model a transfer function is, if it is one: no zeros, and one real stable pole
    /// (FOPTD) or two (SOPTD), with any dead time.
    pub fn from_transfer_function(g: &TransferFunction) -> Option<Self> {
        if !g.zeros().is_empty() || g.poles().iter().any(|p| p.im != 0.0 || p.re >= 0.0) {
            return None;
        }
        let k = g.dc_gain();
        let taus: Vec<f64> = g.poles().iter().map(|p| -1.0 / p.re).collect();
        match taus[..] {
            [tau] => Self::foptd(k, tau, g.delay()).ok(),
            [a, b] => Self::soptd(k, a, b, g.delay()).ok(),
            _ => None,
        }
    }

    /// The model as a transfer function, with its dead time.
    pub fn transfer_function(&self) -> Result<TransferFunction, crate::LtiError> {
        let (k, poles, theta) = match *self {
            Self::Foptd { k, tau, theta } => (k, vec![C64::new(-1.0 / tau, 0.0)], theta),
            Self::Soptd {
                k,
                tau1,
                tau2,
                theta,
            } => (
                k,
                vec![C64::new(-1.0 / tau1, 0.0), C64::new(-1.0 / tau2, 0.0)],
                theta,
            ),
        };
        TransferFunction::from_zpk(&[], &poles, 1.0)?
            .with_dc_gain(k)?
            .with_delay(theta)
    }

    pub fn kind(&self) -> ModelKind {
        match self {
            Self::Foptd { .. } => ModelKind::Foptd,
            Self::Soptd { .. } => ModelKind::Soptd,
        }
    }

    /// The static gain K.
    pub fn gain(&self) -> f64 {
        match *self {
            Self::Foptd { k, .. } | Self::Soptd { k, .. } => k,
        }
    }

    /// The dead time θ.
    pub fn dead_time(&self) -> f64 {
        match *self {
            Self::Foptd { theta, .. } | Self::Soptd { theta, .. } => theta,
        }
    }
}

fn check_gain(k: f64) -> Result<(), ModelError> {
    if k.is_finite() && k != 0.0 {
        Ok(())
    } else {
        Err(ModelError::Gain(k))
    }
}

fn check_time_constant(tau: f64) -> Result<(), ModelError> {
    if tau.is_finite() && tau > 0.0 {
        Ok(())
    } else {
        Err(ModelError::TimeConstant(tau))
    }
}

fn check_dead_time(theta: f64) -> Result<(), ModelError> {
    if theta.is_finite() && theta >= 0.0 {
        Ok(())
    } else {
        Err(ModelError::DeadTime(theta))
    }
}

/// A tuning rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Rule {
    /// Ziegler & Nichols (1942), the reaction curve (open loop).
    ZieglerNicholsOpen,
    /// Ziegler & Nichols (1942), the ultimate cycle (closed loop).
    ZieglerNicholsUltimate,
    /// Cohen & Coon (1953).
    CohenCoon,
    /// Internal model control: Rivera, Morari & Skogestad (1986).
    Imc,
    /// Skogestad (2003), "simple/Skogestad IMC".
    Simc,
    /// Åström & Hägglund (2004, 2006, ch. 7), approximate M-constrained integral gain
    /// optimisation.
    Amigo,
    /// Lambda tuning (Dahlin 1968).
    Lambda,
}

impl Rule {
    pub const ALL: [Rule; 7] = [
        Rule::ZieglerNicholsOpen,
        Rule::ZieglerNicholsUltimate,
        Rule::CohenCoon,
        Rule::Imc,
        Rule::Simc,
        Rule::Amigo,
        Rule::Lambda,
    ];

    /// The stable key of the command line and the JSON.
    pub fn key(self) -> &'static str {
        match self {
            Rule::ZieglerNicholsOpen => "zn-open",
            Rule::ZieglerNicholsUltimate => "zn-ultimate",
            Rule::CohenCoon => "cohen-coon",
            Rule::Imc => "imc",
            Rule::Simc => "simc",
            Rule::Amigo => "amigo",
            Rule::Lambda => "lambda",
        }
    }

    /// The rule named by [`Self::key`] (any case).
    pub fn from_key(key: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|r| r.key().eq_ignore_ascii_case(key.trim()))
    }

    /// Whether the formula reads θ in a denominator (ZN reaction curve, Cohen–Coon, AMIGO).
    pub fn needs_dead_time(self) -> bool {
        matches!(
            self,
            Rule::ZieglerNicholsOpen | Rule::CohenCoon | Rule::Amigo
        )
    }

    /// Whether the rule takes a closed-loop time constant (τc for IMC and SIMC, λ for Lambda).
    pub fn takes_time_constant(self) -> bool {
        matches!(self, Rule::Imc | Rule::Simc | Rule::Lambda)
    }
}

/// What a rule read to give its controller.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Basis {
    /// The model's own K, τ (or τ1, τ2), θ.
    Model(ProcessModel),
    /// SIMC's half rule on a second-order model: τ = τ1 + τ2/2, θ = θ + τ2/2.
    HalfRule { k: f64, tau: f64, theta: f64 },
    /// The reaction curve's tangent at the inflection of the step response: the apparent
    /// dead time θ′ and time constant τ′ it reads.
    ReactionCurve { k: f64, theta: f64, tau: f64 },
    /// The ultimate gain and period.
    Ultimate(Ultimate),
}

/// A controller a rule gave.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tuning {
    pub rule: Rule,
    /// The ideal-form controller, N = 10, b = 1.
    pub controller: Controller,
    /// The τc (IMC, SIMC) or λ (Lambda) used.
    pub closed_loop_time_constant: Option<f64>,
    /// SIMC's series-form (Kc, Ti, Td), when it gave one (a PID for a second-order model).
    pub series: Option<[f64; 3]>,
    pub basis: Basis,
}

/// Why a rule gives no controller here.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum NotApplicable {
    /// The rule has no formula for this action.
    NoAction { rule: Rule, action: Action },
    /// The rule is defined for a first-order model with dead time only.
    FirstOrderOnly { rule: Rule },
    /// The formula divides by θ: it needs a dead time θ > 0.
    NeedsDeadTime { rule: Rule },
    /// SIMC gives a PI for a first-order model (its Td is a second time constant).
    SimcFirstOrderPid,
    /// IMC gives a PID for a second-order model (its Td cancels the second lag).
    ImcSecondOrderPi,
    /// Lambda tuning gives a PI for a first-order model and a PID for a second-order one.
    LambdaMismatch { kind: ModelKind, action: Action },
    /// The plant's phase never reaches −180°: no ultimate gain.
    NoPhaseCrossover,
    /// θ = 0 makes the default τc = θ zero: a τc > 0 must be given.
    NeedsTimeConstant { rule: Rule },
    /// The τc or λ given is not a positive finite number.
    BadTimeConstant(f64),
    /// The parameters computed are not a usable controller (they overflowed).
    Controller(ControllerError),
}

/// A formula of a rule, for an action and a kind of model; its words
/// ([`crate::words::tuning`]) write it out and name its source.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub struct Formula {
    pub rule: Rule,
    pub action: Action,
    pub kind: ModelKind,
}

/// The formula `rule` uses for `action` on a model of `kind`, or why there is none (that a
/// rule needs θ > 0 is said by [`tune`], which sees the model).
pub fn formula(rule: Rule, action: Action, kind: ModelKind) -> Result<Formula, NotApplicable> {
    applies(rule, action, kind)?;
    Ok(Formula { rule, action, kind })
}

/// Whether `rule` has a formula for `action` on a model of `kind`.
fn applies(rule: Rule, action: Action, kind: ModelKind) -> Result<(), NotApplicable> {
    use {Action::*, ModelKind::*, Rule::*};
    let no_action = Err(NotApplicable::NoAction { rule, action });
    match (rule, action, kind) {
        (_, PD, _) => no_action,
        (CohenCoon | Amigo, _, Soptd) => Err(NotApplicable::FirstOrderOnly { rule }),
        (ZieglerNicholsOpen | ZieglerNicholsUltimate | CohenCoon, _, _) => Ok(()),
        (_, P, _) => no_action,
        (Imc, PI, Soptd) => Err(NotApplicable::ImcSecondOrderPi),
        (Simc, PID, Foptd) => Err(NotApplicable::SimcFirstOrderPid),
        (Lambda, PI, Soptd) | (Lambda, PID, Foptd) => {
            Err(NotApplicable::LambdaMismatch { kind, action })
        }
        _ => Ok(()),
    }
}

/// The controller `rule` gives for `model` with `action` (PI or PID; P where the rule has
/// one), `tc` the closed-loop time constant τc of IMC and SIMC or the λ of Lambda (None:
/// τc = θ, Seborg's and Skogestad's guideline; λ = τ, the open loop's own time constant, τ1
/// for a second-order model). Negative K gives negative Kc: the formulas keep K's sign.
pub fn tune(
    model: &ProcessModel,
    rule: Rule,
    action: Action,
    tc: Option<f64>,
) -> Result<Tuning, NotApplicable> {
    applies(rule, action, model.kind())?;
    if let Some(t) = tc
        && !(t.is_finite() && t > 0.0)
    {
        return Err(NotApplicable::BadTimeConstant(t));
    }
    // The reaction curve of a second-order model has an apparent dead time of its own
    // (the tangent's intercept), so ZN's reaction-curve rule applies to it without θ.
    let reads_tangent = rule == Rule::ZieglerNicholsOpen && model.kind() == ModelKind::Soptd;
    if rule.needs_dead_time() && model.dead_time() <= 0.0 && !reads_tangent {
        return Err(NotApplicable::NeedsDeadTime { rule });
    }
    let found = match rule {
        Rule::ZieglerNicholsOpen => Ok(reaction_curve_rule(model, action)),
        Rule::ZieglerNicholsUltimate => ultimate_rule(model, action),
        Rule::CohenCoon => Ok(cohen_coon(model, action)),
        Rule::Imc => imc(model, action, tc),
        Rule::Simc => simc(model, action, tc),
        Rule::Amigo => Ok(amigo(model, action)),
        Rule::Lambda => Ok(lambda(model, tc)),
    }?;
    let controller =
        Controller::new(action, found.kc, found.ti, found.td).map_err(NotApplicable::Controller)?;
    Ok(Tuning {
        rule,
        controller,
        closed_loop_time_constant: found.tc,
        series: found.series,
        basis: found.basis,
    })
}
