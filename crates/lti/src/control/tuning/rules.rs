//! The rules' formulas, each with its source: a model and an action in, the ideal-form
//! (Kc, Ti, Td) and what was read out ([`Found`]). [`super::tune`] has checked that the rule
//! applies.

use super::{Basis, NotApplicable, ProcessModel, Rule};
use crate::control::Action;
use crate::control::frequency;

/// A rule's numbers before they become a [`Controller`].
pub(super) struct Found {
    pub(super) kc: f64,
    pub(super) ti: f64,
    pub(super) td: f64,
    pub(super) tc: Option<f64>,
    pub(super) series: Option<[f64; 3]>,
    pub(super) basis: Basis,
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
    Basis::Model(*model)
}

/// Ziegler–Nichols reaction curve (Ziegler & Nichols 1942; Seborg et al., Process Dynamics
/// and Control, ch. 12; Åström & Hägglund 1995 §4.3), a = K·θ/τ: P Kc = 1/a; PI
/// Kc = 0.9/a, Ti = θ/0.3 = 3.33·θ (Ziegler and Nichols' 3.33 L, as Seborg prints it; some
/// texts round it to 3θ); PID Kc = 1.2/a, Ti = 2θ, Td = θ/2. A second-order model is read as
/// its reaction curve ([`reaction_curve`]).
pub(super) fn reaction_curve_rule(model: &ProcessModel, action: Action) -> Found {
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

/// Ziegler–Nichols ultimate cycle (Ziegler & Nichols 1942; Seborg et al., ch. 12): P
/// Kc = 0.5·Kcr; PI Kc = 0.45·Kcr, Ti = Pcr/1.2; PID Kc = 0.6·Kcr, Ti = Pcr/2, Td = Pcr/8,
/// with Kcr and Pcr exact with the dead time ([`frequency::ultimate`]).
pub(super) fn ultimate_rule(model: &ProcessModel, action: Action) -> Result<Found, NotApplicable> {
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

/// Cohen–Coon (Cohen & Coon 1953; Seborg et al., ch. 12), r = θ/τ: P
/// Kc = (τ/(Kθ))(1 + r/3); PI Kc = (τ/(Kθ))(0.9 + r/12), Ti = θ(30 + 3r)/(9 + 20r); PID
/// Kc = (τ/(Kθ))(4/3 + r/4), Ti = θ(32 + 6r)/(13 + 8r), Td = 4θ/(11 + 2r).
pub(super) fn cohen_coon(model: &ProcessModel, action: Action) -> Found {
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

/// IMC (Rivera, Morari & Skogestad 1986; Seborg et al., ch. 12), τc = θ by default:
/// FOPTD PI Kc = τ/(K(τc + θ)), Ti = τ; FOPTD PID (the delay as Padé 1/1)
/// Kc = (τ + θ/2)/(K(τc + θ/2)), Ti = τ + θ/2, Td = τθ/(2τ + θ); SOPTD PID
/// Kc = (τ1 + τ2)/(K(τc + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2).
pub(super) fn imc(
    model: &ProcessModel,
    action: Action,
    tc: Option<f64>,
) -> Result<Found, NotApplicable> {
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
pub(super) fn simc(
    model: &ProcessModel,
    action: Action,
    tc: Option<f64>,
) -> Result<Found, NotApplicable> {
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

/// AMIGO (Åström & Hägglund 2004; Advanced PID Control 2006, ch. 7): PI
/// Kc = 0.15/K + (0.35 − θτ/(θ + τ)²)·τ/(Kθ), Ti = 0.35θ + 13θτ²/(τ² + 12θτ + 7θ²); PID
/// Kc = (1/K)(0.2 + 0.45τ/θ), Ti = θ(0.4θ + 0.8τ)/(θ + 0.1τ), Td = 0.5θτ/(0.3θ + τ).
pub(super) fn amigo(model: &ProcessModel, action: Action) -> Found {
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

/// Lambda tuning (Dahlin 1968; Åström & Hägglund 2006), λ = τ by default (τ1 for a
/// second-order model): FOPTD PI Kc = τ/(K(λ + θ)), Ti = τ; SOPTD PID
/// Kc = (τ1 + τ2)/(K(λ + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2).
pub(super) fn lambda(model: &ProcessModel, tc: Option<f64>) -> Found {
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
