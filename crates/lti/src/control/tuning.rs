//! Tuning rules: from a process model — first order plus dead time (FOPTD) or second order
//! plus dead time (SOPTD), [`ProcessModel`] — to an ideal-form controller, by the published
//! formulas of Ziegler–Nichols (reaction curve and ultimate cycle), Cohen–Coon, IMC, SIMC,
//! AMIGO and Lambda ([`tune`]), each formula also given as text with its source
//! ([`formula`], said by [`crate::words::tuning`]). A rule that has no formula for a model or
//! an action says why ([`NotApplicable`]).

use serde::{Deserialize, Serialize};

use crate::TransferFunction;
use crate::control::frequency::{self, Ultimate};
use crate::control::{Action, Controller, ControllerError};
use crate::poly::C64;

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
    /// Åström & Hägglund (2004, 2006 §7.6), approximate M-constrained integral gain
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
    /// A first-order model's K, τ, θ.
    Foptd { k: f64, tau: f64, theta: f64 },
    /// A second-order model's K, τ1, τ2, θ.
    Soptd {
        k: f64,
        tau1: f64,
        tau2: f64,
        theta: f64,
    },
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
    if rule.needs_dead_time() && model.dead_time() <= 0.0 {
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

/// A rule's numbers before they become a [`Controller`].
struct Found {
    kc: f64,
    ti: f64,
    td: f64,
    tc: Option<f64>,
    series: Option<[f64; 3]>,
    basis: Basis,
}

impl Found {
    fn new(basis: Basis, [kc, ti, td]: [f64; 3]) -> Self {
        Self {
            kc,
            ti,
            td,
            tc: None,
            series: None,
            basis,
        }
    }

    fn with_tc(mut self, tc: f64) -> Self {
        self.tc = Some(tc);
        self
    }
}

/// The basis of a model as it is.
fn model_basis(model: &ProcessModel) -> Basis {
    match *model {
        ProcessModel::Foptd { k, tau, theta } => Basis::Foptd { k, tau, theta },
        ProcessModel::Soptd {
            k,
            tau1,
            tau2,
            theta,
        } => Basis::Soptd {
            k,
            tau1,
            tau2,
            theta,
        },
    }
}

/// Ziegler–Nichols reaction curve (Ziegler & Nichols 1942; Seborg et al., Process Dynamics
/// and Control, Table 12.6; Åström & Hägglund 1995 §4.3), a = K·θ/τ: P Kc = 1/a; PI
/// Kc = 0.9/a, Ti = θ/0.3 = 3.33·θ (Ziegler and Nichols' 3.33 L, as Seborg prints it; some
/// texts round it to 3θ); PID Kc = 1.2/a, Ti = 2θ, Td = θ/2. A second-order model is read as
/// its reaction curve ([`reaction_curve`]).
fn reaction_curve_rule(model: &ProcessModel, action: Action) -> Found {
    let (k, theta, tau) = match *model {
        ProcessModel::Foptd { k, tau, theta } => (k, theta, tau),
        ProcessModel::Soptd {
            k,
            tau1,
            tau2,
            theta,
        } => {
            let (apparent_theta, apparent_tau) = reaction_curve(tau1, tau2, theta);
            (k, apparent_theta, apparent_tau)
        }
    };
    let basis = match model {
        ProcessModel::Foptd { .. } => model_basis(model),
        ProcessModel::Soptd { .. } => Basis::ReactionCurve { k, theta, tau },
    };
    let a = k * theta / tau;
    let values = match action {
        Action::P => [1.0 / a, f64::INFINITY, 0.0],
        Action::PI => [0.9 / a, theta / 0.3, 0.0],
        _ => [1.2 / a, 2.0 * theta, theta / 2.0],
    };
    Found::new(basis, values)
}

/// The tangent at the inflection of the step response of e^{−θs}/((τ1·s + 1)(τ2·s + 1)):
/// (θ′, τ′), where it crosses 0 and where it reaches the final value. The inflection is at
/// t_i = τ1·τ2·ln(τ1/τ2)/(τ1 − τ2) after θ (t_i = τ when τ1 = τ2).
pub fn reaction_curve(tau1: f64, tau2: f64, theta: f64) -> (f64, f64) {
    let x = (tau1 - tau2) / tau2;
    let ti = if x == 0.0 { tau1 } else { tau1 * x.ln_1p() / x };
    // Slope of the unit response: (e^{−t/τ1} − e^{−t/τ2})/(τ1 − τ2), without cancellation.
    let slope = if tau1 == tau2 {
        ti / (tau1 * tau1) * (-ti / tau1).exp()
    } else {
        -(-ti / tau1).exp() * (-ti * (tau1 - tau2) / (tau1 * tau2)).exp_m1() / (tau1 - tau2)
    };
    let y = 1.0 - (-ti / tau1).exp() - tau2 * slope;
    (theta + ti - y / slope, 1.0 / slope)
}

/// Ziegler–Nichols ultimate cycle (Ziegler & Nichols 1942; Seborg et al., Table 12.7): P
/// Kc = 0.5·Kcr; PI Kc = 0.45·Kcr, Ti = Pcr/1.2; PID Kc = 0.6·Kcr, Ti = Pcr/2, Td = Pcr/8,
/// with Kcr and Pcr exact with the dead time ([`frequency::ultimate`]).
fn ultimate_rule(model: &ProcessModel, action: Action) -> Result<Found, NotApplicable> {
    let g = model
        .transfer_function()
        .map_err(|_| NotApplicable::NoPhaseCrossover)?;
    let u = frequency::ultimate(&g).ok_or(NotApplicable::NoPhaseCrossover)?;
    let values = match action {
        Action::P => [0.5 * u.kcr, f64::INFINITY, 0.0],
        Action::PI => [0.45 * u.kcr, u.pcr / 1.2, 0.0],
        _ => [0.6 * u.kcr, u.pcr / 2.0, u.pcr / 8.0],
    };
    Ok(Found::new(Basis::Ultimate(u), values))
}

/// The first-order model's (K, τ, θ); the callers have checked the kind.
fn first_order(model: &ProcessModel) -> (f64, f64, f64) {
    match *model {
        ProcessModel::Foptd { k, tau, theta } => (k, tau, theta),
        ProcessModel::Soptd { k, tau1, theta, .. } => (k, tau1, theta),
    }
}

/// Cohen–Coon (Cohen & Coon 1953; Seborg et al., Table 12.6), r = θ/τ: P
/// Kc = (τ/(Kθ))(1 + r/3); PI Kc = (τ/(Kθ))(0.9 + r/12), Ti = θ(30 + 3r)/(9 + 20r); PID
/// Kc = (τ/(Kθ))(4/3 + r/4), Ti = θ(32 + 6r)/(13 + 8r), Td = 4θ/(11 + 2r).
fn cohen_coon(model: &ProcessModel, action: Action) -> Found {
    let (k, tau, theta) = first_order(model);
    let r = theta / tau;
    let base = tau / (k * theta);
    let values = match action {
        Action::P => [base * (1.0 + r / 3.0), f64::INFINITY, 0.0],
        Action::PI => [
            base * (0.9 + r / 12.0),
            theta * (30.0 + 3.0 * r) / (9.0 + 20.0 * r),
            0.0,
        ],
        _ => [
            base * (4.0 / 3.0 + r / 4.0),
            theta * (32.0 + 6.0 * r) / (13.0 + 8.0 * r),
            4.0 * theta / (11.0 + 2.0 * r),
        ],
    };
    Found::new(model_basis(model), values)
}

/// τc given, or θ (Seborg's and Skogestad's guideline), refused when that is 0.
fn time_constant_or_dead_time(
    tc: Option<f64>,
    theta: f64,
    rule: Rule,
) -> Result<f64, NotApplicable> {
    match tc {
        Some(t) => Ok(t),
        None if theta > 0.0 => Ok(theta),
        None => Err(NotApplicable::NeedsTimeConstant { rule }),
    }
}

/// IMC (Rivera, Morari & Skogestad 1986; Seborg et al., Table 12.1), τc = θ by default:
/// FOPTD PI Kc = τ/(K(τc + θ)), Ti = τ; FOPTD PID (the delay as Padé 1/1)
/// Kc = (τ + θ/2)/(K(τc + θ/2)), Ti = τ + θ/2, Td = τθ/(2τ + θ); SOPTD PID
/// Kc = (τ1 + τ2)/(K(τc + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2).
fn imc(model: &ProcessModel, action: Action, tc: Option<f64>) -> Result<Found, NotApplicable> {
    let tc = time_constant_or_dead_time(tc, model.dead_time(), Rule::Imc)?;
    let values = match (*model, action) {
        (ProcessModel::Foptd { k, tau, theta }, Action::PI) => [tau / (k * (tc + theta)), tau, 0.0],
        (ProcessModel::Foptd { k, tau, theta }, _) => [
            (tau + theta / 2.0) / (k * (tc + theta / 2.0)),
            tau + theta / 2.0,
            tau * theta / (2.0 * tau + theta),
        ],
        (
            ProcessModel::Soptd {
                k,
                tau1,
                tau2,
                theta,
            },
            _,
        ) => second_order_pid(k, tau1, tau2, theta, tc),
    };
    Ok(Found::new(model_basis(model), values).with_tc(tc))
}

/// The IMC/Lambda PID of a second-order model: Kc = (τ1 + τ2)/(K(τc + θ)), Ti = τ1 + τ2,
/// Td = τ1τ2/(τ1 + τ2).
fn second_order_pid(k: f64, tau1: f64, tau2: f64, theta: f64, tc: f64) -> [f64; 3] {
    let sum = tau1 + tau2;
    [sum / (k * (tc + theta)), sum, tau1 * tau2 / sum]
}

/// SIMC (Skogestad 2003, J. Process Control 13:291–309, eqs. 27–28), τc = θ by default:
/// PI Kc = τ1/(K(τc + θ)), Ti = min(τ1, 4(τc + θ)); for a second-order model a PID in the
/// series form with Td = τ2, given here in the ideal form (Kc′ = Kc(1 + Td/Ti),
/// Ti′ = Ti + Td, Td′ = Ti·Td/(Ti + Td)) with the series values kept; a PI for a
/// second-order model uses Skogestad's half rule (τ1 + τ2/2, θ + τ2/2, τc = that θ by
/// default).
fn simc(model: &ProcessModel, action: Action, tc: Option<f64>) -> Result<Found, NotApplicable> {
    match (*model, action) {
        (ProcessModel::Foptd { k, tau, theta }, _) => {
            let tc = time_constant_or_dead_time(tc, theta, Rule::Simc)?;
            Ok(Found::new(model_basis(model), simc_pi(k, tau, theta, tc)).with_tc(tc))
        }
        (
            ProcessModel::Soptd {
                k,
                tau1,
                tau2,
                theta,
            },
            Action::PI,
        ) => {
            let (tau, theta) = (tau1 + tau2 / 2.0, theta + tau2 / 2.0);
            let tc = time_constant_or_dead_time(tc, theta, Rule::Simc)?;
            let basis = Basis::HalfRule { k, tau, theta };
            Ok(Found::new(basis, simc_pi(k, tau, theta, tc)).with_tc(tc))
        }
        (
            ProcessModel::Soptd {
                k,
                tau1,
                tau2,
                theta,
            },
            _,
        ) => {
            let tc = time_constant_or_dead_time(tc, theta, Rule::Simc)?;
            let [kc, ti, _] = simc_pi(k, tau1, theta, tc);
            let td = tau2;
            let ideal = [kc * (1.0 + td / ti), ti + td, ti * td / (ti + td)];
            let mut found = Found::new(model_basis(model), ideal).with_tc(tc);
            found.series = Some([kc, ti, td]);
            Ok(found)
        }
    }
}

/// SIMC's PI: Kc = τ/(K(τc + θ)), Ti = min(τ, 4(τc + θ)).
fn simc_pi(k: f64, tau: f64, theta: f64, tc: f64) -> [f64; 3] {
    [tau / (k * (tc + theta)), tau.min(4.0 * (tc + theta)), 0.0]
}

/// AMIGO (Åström & Hägglund 2004; Advanced PID Control 2006, §7.6): PI
/// Kc = 0.15/K + (0.35 − θτ/(θ + τ)²)·τ/(Kθ), Ti = 0.35θ + 13θτ²/(τ² + 12θτ + 7θ²); PID
/// Kc = (1/K)(0.2 + 0.45τ/θ), Ti = θ(0.4θ + 0.8τ)/(θ + 0.1τ), Td = 0.5θτ/(0.3θ + τ).
fn amigo(model: &ProcessModel, action: Action) -> Found {
    let (k, tau, theta) = first_order(model);
    let values = if action == Action::PI {
        [
            0.15 / k + (0.35 - theta * tau / (theta + tau).powi(2)) * tau / (k * theta),
            0.35 * theta
                + 13.0 * theta * tau * tau / (tau * tau + 12.0 * theta * tau + 7.0 * theta * theta),
            0.0,
        ]
    } else {
        [
            (0.2 + 0.45 * tau / theta) / k,
            theta * (0.4 * theta + 0.8 * tau) / (theta + 0.1 * tau),
            0.5 * theta * tau / (0.3 * theta + tau),
        ]
    };
    Found::new(model_basis(model), values)
}

/// Lambda tuning (Dahlin 1968; Åström & Hägglund 2006, §7.5), λ = τ by default (τ1 for a
/// second-order model): FOPTD PI Kc = τ/(K(λ + θ)), Ti = τ; SOPTD PID
/// Kc = (τ1 + τ2)/(K(λ + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2).
fn lambda(model: &ProcessModel, tc: Option<f64>) -> Found {
    match *model {
        ProcessModel::Foptd { k, tau, theta } => {
            let l = tc.unwrap_or(tau);
            Found::new(model_basis(model), [tau / (k * (l + theta)), tau, 0.0]).with_tc(l)
        }
        ProcessModel::Soptd {
            k,
            tau1,
            tau2,
            theta,
        } => {
            let l = tc.unwrap_or(tau1);
            Found::new(
                model_basis(model),
                second_order_pid(k, tau1, tau2, theta, l),
            )
            .with_tc(l)
        }
    }
}
