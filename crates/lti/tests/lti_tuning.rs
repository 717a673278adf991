//! Tuning rules against their published formulas, typed again here from the sources each
//! test names; the ultimate gain against closed forms solved by bisection here; the count of
//! closed-loop roots in the right half-plane against the roots of high-order Padé loops; the
//! peak sensitivity against a dense grid.

use crate::rng::Lcg;
use degrau_lti::locus::multiply;
use std::f64::consts::{E, PI};

use degrau_lti::control::frequency::{
    StabilityError, closed_loop_unstable_roots, loop_at, max_sensitivity, ultimate,
};
use degrau_lti::control::tuning::{
    Basis, ModelError, ModelKind, NotApplicable, ProcessModel, Rule, formula, reaction_curve, tune,
};
use degrau_lti::control::{Action, Controller};
use degrau_lti::{C64, TransferFunction, poly};
use degrau_words::{Lang, Localize};

#[track_caller]
fn assert_rel(what: &str, a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs(),
        "{what}: {a} vs {b} (rel {:e})",
        (a - b).abs() / b.abs()
    );
}

fn foptd(k: f64, tau: f64, theta: f64) -> ProcessModel {
    ProcessModel::foptd(k, tau, theta).expect("valid model")
}

fn soptd(k: f64, tau1: f64, tau2: f64, theta: f64) -> ProcessModel {
    ProcessModel::soptd(k, tau1, tau2, theta).expect("valid model")
}

fn plant(model: &ProcessModel) -> TransferFunction {
    model.transfer_function().expect("a transfer function")
}

/// The root of a function increasing through 0 on [a, b], by bisection to the last bit.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    while b - a > 1e-15 * b {
        let m = 0.5 * (a + b);
        if f(m) < 0.0 { a = m } else { b = m }
    }
    0.5 * (a + b)
}

/// (Kc, Ti, Td) of a tuning, with Ti = ∞ and Td = 0 where the action has none.
fn parameters(model: &ProcessModel, rule: Rule, action: Action, tc: Option<f64>) -> [f64; 3] {
    let c = tune(model, rule, action, tc).expect("a tuning").controller;
    assert_eq!(c.action, action);
    let ti = if action.integral() {
        c.ti
    } else {
        f64::INFINITY
    };
    let td = if action.derivative() { c.td } else { 0.0 };
    [c.kc, ti, td]
}

#[track_caller]
fn assert_parameters(what: &str, got: [f64; 3], want: [f64; 3]) {
    for (name, (g, w)) in ["Kc", "Ti", "Td"].iter().zip(got.iter().zip(want)) {
        if w.is_infinite() || w == 0.0 {
            assert_eq!(*g, w, "{what} {name}");
        } else {
            assert_rel(&format!("{what} {name}"), *g, w, 1e-13);
        }
    }
}

// ---------------------------------------------------------------- ultimate gain and period

#[test]
fn the_ultimate_gain_of_a_first_order_lag_with_dead_time_is_exact() {
    // 1/(10s + 1)·e^{−2s}: atan(10ω) + 2ω = π at ω = 0.84434, Kcr = √(1 + 100ω²) = 8.5024
    // (a Padé (3,3) delay gives 8.50404 at 0.8445: the exact delay does not).
    let u = ultimate(&plant(&foptd(1.0, 10.0, 2.0))).expect("a crossover");
    assert_eq!(format!("{:.5}", u.wcr), "0.84434");
    assert_eq!(format!("{:.4}", u.kcr), "8.5024");
    assert!((u.kcr - 8.50404).abs() > 1e-3);
    assert_rel("Pcr", u.pcr, 2.0 * PI / u.wcr, 1e-15);
}

#[test]
fn the_ultimate_gain_matches_the_closed_form_over_a_table_of_dead_times() {
    // Phase crossover of K·e^{−θs}/(τs + 1): atan(ωτ) + ωθ = π, |G| = |K|/√(1 + ω²τ²).
    for ratio in [0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0] {
        for (k, tau) in [(1.0, 1.0), (2.5, 10.0), (-0.7, 3.0)] {
            let theta = ratio * tau;
            let w = bisect(|w| (w * tau).atan() + w * theta - PI, 1e-9, PI / theta);
            let kcr = (1.0 + w * w * tau * tau).sqrt() / k;
            let u = ultimate(&plant(&foptd(k, tau, theta))).expect("a crossover");
            assert_rel("ωcr", u.wcr, w, 1e-12);
            assert_rel("Kcr", u.kcr, kcr, 1e-12);
        }
    }
}

#[test]
fn the_ultimate_gain_of_second_and_third_order_plants() {
    // 2·e^{−0.3s}/((4s + 1)(s + 1)): atan(4ω) + atan(ω) + 0.3ω = π.
    let w = bisect(|w| (4.0 * w).atan() + w.atan() + 0.3 * w - PI, 1e-9, 100.0);
    let kcr = ((1.0 + 16.0 * w * w) * (1.0 + w * w)).sqrt() / 2.0;
    let u = ultimate(&plant(&soptd(2.0, 1.0, 4.0, 0.3))).expect("a crossover");
    assert_rel("ωcr", u.wcr, w, 1e-12);
    assert_rel("Kcr", u.kcr, kcr, 1e-12);
    // 1/(s + 1)³ without delay: ωcr = √3, Kcr = 8 (Routh).
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 3.0, 3.0, 1.0]).unwrap();
    let u = ultimate(&g).expect("a crossover");
    assert_rel("ωcr", u.wcr, 3f64.sqrt(), 1e-13);
    assert_rel("Kcr", u.kcr, 8.0, 1e-13);
    // A first- or second-order lag without delay never reaches −180°.
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 2.0, 1.0]).unwrap();
    assert_eq!(ultimate(&g), None);
}

// ---------------------------------------------------------------- models

#[test]
fn models_are_checked_and_read_from_transfer_functions() {
    assert_eq!(
        ProcessModel::foptd(0.0, 1.0, 1.0),
        Err(ModelError::Gain(0.0))
    );
    assert_eq!(
        ProcessModel::soptd(1.0, 1.0, -2.0, 1.0),
        Err(ModelError::TimeConstant(-2.0))
    );
    assert!(matches!(
        ProcessModel::foptd(1.0, 1.0, f64::NAN),
        Err(ModelError::DeadTime(_))
    ));
    // τ1 ≥ τ2, whatever the order typed.
    assert_eq!(soptd(2.0, 1.0, 5.0, 0.5), soptd(2.0, 5.0, 1.0, 0.5));
    for model in [foptd(-2.0, 3.0, 0.4), soptd(1.5, 5.0, 1.0, 0.5)] {
        let back = ProcessModel::from_transfer_function(&plant(&model)).expect("a model");
        match (back, model) {
            (
                ProcessModel::Soptd {
                    k,
                    tau1,
                    tau2,
                    theta,
                },
                ProcessModel::Soptd {
                    k: k0,
                    tau1: a,
                    tau2: b,
                    theta: t,
                },
            ) => {
                assert_rel("K", k, k0, 1e-14);
                assert_rel("τ1", tau1, a, 1e-14);
                assert_rel("τ2", tau2, b, 1e-14);
                assert_eq!(theta, t);
            }
            (
                ProcessModel::Foptd { k, tau, theta },
                ProcessModel::Foptd {
                    k: k0,
                    tau: t0,
                    theta: d,
                },
            ) => {
                assert_rel("K", k, k0, 1e-14);
                assert_rel("τ", tau, t0, 1e-14);
                assert_eq!(theta, d);
            }
            _ => panic!("kind changed: {back:?}"),
        }
    }
    // A zero, a complex pair, an unstable pole: not a model.
    let with_zero = TransferFunction::from_coeffs(&[1.0, 1.0], &[1.0, 3.0, 2.0]).unwrap();
    let complex = TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 1.0]).unwrap();
    let unstable = TransferFunction::from_coeffs(&[1.0], &[1.0, -1.0]).unwrap();
    for g in [with_zero, complex, unstable] {
        assert_eq!(ProcessModel::from_transfer_function(&g), None);
    }
}

// ---------------------------------------------------------------- the rules' formulas

const K: f64 = 2.0;
const TAU: f64 = 10.0;
const THETA: f64 = 2.0;

#[test]
fn ziegler_nichols_reaction_curve_on_a_first_order_model() {
    // Ziegler & Nichols (1942); Seborg et al., ch. 12: a = Kθ/τ; P 1/a; PI 0.9/a,
    // Ti = 3.33θ (θ/0.3); PID 1.2/a, 2θ, θ/2.
    let m = foptd(K, TAU, THETA);
    let a = K * THETA / TAU;
    let rule = Rule::ZieglerNicholsOpen;
    assert_parameters(
        "P",
        parameters(&m, rule, Action::P, None),
        [1.0 / a, f64::INFINITY, 0.0],
    );
    assert_parameters(
        "PI",
        parameters(&m, rule, Action::PI, None),
        [0.9 / a, THETA / 0.3, 0.0],
    );
    assert_parameters(
        "PID",
        parameters(&m, rule, Action::PID, None),
        [1.2 / a, 2.0 * THETA, 0.5 * THETA],
    );
}

#[test]
fn the_reaction_curve_of_a_second_order_model_is_its_inflection_tangent() {
    // Two equal lags τ: the tangent at t = τ gives θ′ = θ + (3 − e)τ, τ′ = e·τ.
    let (theta, tau) = reaction_curve(2.0, 2.0, 0.5);
    assert_rel("θ′", theta, 0.5 + (3.0 - E) * 2.0, 1e-14);
    assert_rel("τ′", tau, E * 2.0, 1e-14);
    // τ1 = 5, τ2 = 1: the steepest point of y(t) = 1 − (5e^{−t/5} − e^{−t})/4, found here
    // by golden section on the slope written out, and the tangent's intercepts.
    let y = |t: f64| 1.0 - (5.0 * (-t / 5.0).exp() - (-t).exp()) / 4.0;
    let slope = |t: f64| ((-t / 5.0).exp() - (-t).exp()) / 4.0;
    let (mut a, mut b) = (0.0, 10.0);
    while b - a > 1e-12 {
        let (x1, x2) = (a + 0.382 * (b - a), a + 0.618 * (b - a));
        if slope(x1) < slope(x2) {
            a = x1
        } else {
            b = x2
        }
    }
    let ti = 0.5 * (a + b);
    // (A maximum found by comparing values is only good to about √ε.)
    assert_rel("t_i", ti, 5.0 * 5f64.ln() / 4.0, 1e-7);
    let (theta, tau) = reaction_curve(5.0, 1.0, 0.3);
    assert_rel("θ′", theta, 0.3 + ti - y(ti) / slope(ti), 1e-12);
    assert_rel("τ′", tau, 1.0 / slope(ti), 1e-12);
    // Nearly equal lags give nearly the equal-lag answer (no cancellation).
    let (theta, tau) = reaction_curve(2.0 * (1.0 + 1e-12), 2.0, 0.0);
    assert_rel("θ′", theta, (3.0 - E) * 2.0, 1e-9);
    assert_rel("τ′", tau, E * 2.0, 1e-9);
    // The ZN rule reads that tangent on an SOPTD model.
    let t = tune(
        &soptd(K, 5.0, 1.0, 0.3),
        Rule::ZieglerNicholsOpen,
        Action::PID,
        None,
    )
    .unwrap();
    let (theta, tau) = reaction_curve(5.0, 1.0, 0.3);
    assert_eq!(t.basis, Basis::ReactionCurve { k: K, theta, tau });
    assert_rel("Kc", t.controller.kc, 1.2 * tau / (K * theta), 1e-14);
    assert_rel("Ti", t.controller.ti, 2.0 * theta, 1e-14);
}

#[test]
fn ziegler_nichols_ultimate_cycle() {
    // Ziegler & Nichols (1942): P 0.5Kcr; PI 0.45Kcr, Pcr/1.2; PID 0.6Kcr, Pcr/2, Pcr/8.
    let m = foptd(K, TAU, THETA);
    let w = bisect(|w| (w * TAU).atan() + w * THETA - PI, 1e-9, PI / THETA);
    let (kcr, pcr) = ((1.0 + w * w * TAU * TAU).sqrt() / K, 2.0 * PI / w);
    let rule = Rule::ZieglerNicholsUltimate;
    let tol = 1e-12;
    let got = parameters(&m, rule, Action::P, None);
    assert_rel("P Kc", got[0], 0.5 * kcr, tol);
    let got = parameters(&m, rule, Action::PI, None);
    assert_rel("PI Kc", got[0], 0.45 * kcr, tol);
    assert_rel("PI Ti", got[1], pcr / 1.2, tol);
    let got = parameters(&m, rule, Action::PID, None);
    assert_rel("PID Kc", got[0], 0.6 * kcr, tol);
    assert_rel("PID Ti", got[1], pcr / 2.0, tol);
    assert_rel("PID Td", got[2], pcr / 8.0, tol);
}

#[test]
fn cohen_coon() {
    // Cohen & Coon (1953); Seborg et al., ch. 12, r = θ/τ.
    let m = foptd(K, TAU, THETA);
    let r = THETA / TAU;
    let g = TAU / (K * THETA);
    let rule = Rule::CohenCoon;
    assert_parameters(
        "P",
        parameters(&m, rule, Action::P, None),
        [g * (1.0 + r / 3.0), f64::INFINITY, 0.0],
    );
    assert_parameters(
        "PI",
        parameters(&m, rule, Action::PI, None),
        [
            g * (0.9 + r / 12.0),
            THETA * (30.0 + 3.0 * r) / (9.0 + 20.0 * r),
            0.0,
        ],
    );
    assert_parameters(
        "PID",
        parameters(&m, rule, Action::PID, None),
        [
            g * (4.0 / 3.0 + r / 4.0),
            THETA * (32.0 + 6.0 * r) / (13.0 + 8.0 * r),
            4.0 * THETA / (11.0 + 2.0 * r),
        ],
    );
}

#[test]
fn imc() {
    // Rivera, Morari & Skogestad (1986); Seborg et al., ch. 12; τc = θ by default.
    let m = foptd(K, TAU, THETA);
    let t = tune(&m, Rule::Imc, Action::PI, None).unwrap();
    assert_eq!(t.closed_loop_time_constant, Some(THETA));
    assert_parameters(
        "PI",
        parameters(&m, Rule::Imc, Action::PI, None),
        [TAU / (K * 2.0 * THETA), TAU, 0.0],
    );
    let tc = 3.0;
    assert_parameters(
        "PID",
        parameters(&m, Rule::Imc, Action::PID, Some(tc)),
        [
            (TAU + THETA / 2.0) / (K * (tc + THETA / 2.0)),
            TAU + THETA / 2.0,
            TAU * THETA / (2.0 * TAU + THETA),
        ],
    );
    let m2 = soptd(K, 6.0, 2.0, 1.0);
    assert_parameters(
        "SOPTD PID",
        parameters(&m2, Rule::Imc, Action::PID, Some(tc)),
        [8.0 / (K * (tc + 1.0)), 8.0, 12.0 / 8.0],
    );
    assert_eq!(
        tune(&m2, Rule::Imc, Action::PI, None),
        Err(NotApplicable::ImcSecondOrderPi)
    );
    // No dead time: τc must be given.
    let fast = foptd(K, TAU, 0.0);
    assert_eq!(
        tune(&fast, Rule::Imc, Action::PI, None),
        Err(NotApplicable::NeedsTimeConstant { rule: Rule::Imc })
    );
    assert_parameters(
        "θ = 0",
        parameters(&fast, Rule::Imc, Action::PI, Some(1.0)),
        [TAU / K, TAU, 0.0],
    );
    assert_eq!(
        tune(&m, Rule::Imc, Action::PI, Some(-1.0)),
        Err(NotApplicable::BadTimeConstant(-1.0))
    );
}

#[test]
fn simc() {
    // Skogestad (2003), J. Process Control 13:291–309, eqs. (27)–(28).
    let m = foptd(K, TAU, THETA);
    // τc = θ: Kc = τ/(2Kθ), Ti = min(τ, 8θ) = 10.
    assert_parameters(
        "PI",
        parameters(&m, Rule::Simc, Action::PI, None),
        [TAU / (K * 4.0), 10.0f64.min(16.0), 0.0],
    );
    // τc = 0.5: 4(τc + θ) = 10 ≥ τ? no, 4·2.5 = 10 = τ; take τ = 20 so the min bites.
    let long = foptd(K, 20.0, THETA);
    assert_parameters(
        "PI, Ti = 4(τc + θ)",
        parameters(&long, Rule::Simc, Action::PI, Some(0.5)),
        [20.0 / (K * 2.5), 10.0, 0.0],
    );
    assert_eq!(
        tune(&m, Rule::Simc, Action::PID, None),
        Err(NotApplicable::SimcFirstOrderPid)
    );
    // SOPTD PID: series Kc = τ1/(K(τc + θ)), Ti = min(τ1, 4(τc + θ)), Td = τ2; ideal form
    // Kc(1 + Td/Ti), Ti + Td, TiTd/(Ti + Td).
    let m2 = soptd(K, 12.0, 3.0, 1.0);
    let t = tune(&m2, Rule::Simc, Action::PID, None).unwrap();
    let (kc, ti, td) = (12.0 / (K * 2.0), 8.0, 3.0);
    assert_eq!(t.series, Some([kc, ti, td]));
    assert_parameters(
        "SOPTD PID",
        parameters(&m2, Rule::Simc, Action::PID, None),
        [kc * (1.0 + td / ti), ti + td, ti * td / (ti + td)],
    );
    // SOPTD PI by the half rule: τ = 12 + 1.5, θ = 1 + 1.5, τc = θ.
    let (tau, theta) = (13.5, 2.5);
    assert_parameters(
        "SOPTD PI",
        parameters(&m2, Rule::Simc, Action::PI, None),
        [tau / (K * 2.0 * theta), tau.min(8.0 * theta), 0.0],
    );
}

#[test]
fn amigo() {
    // Åström & Hägglund, Advanced PID Control (2006), ch. 7.
    let m = foptd(K, TAU, THETA);
    let (l, t) = (THETA, TAU);
    assert_parameters(
        "PI",
        parameters(&m, Rule::Amigo, Action::PI, None),
        [
            0.15 / K + (0.35 - l * t / ((l + t) * (l + t))) * t / (K * l),
            0.35 * l + 13.0 * l * t * t / (t * t + 12.0 * l * t + 7.0 * l * l),
            0.0,
        ],
    );
    assert_parameters(
        "PID",
        parameters(&m, Rule::Amigo, Action::PID, None),
        [
            (0.2 + 0.45 * t / l) / K,
            l * (0.4 * l + 0.8 * t) / (l + 0.1 * t),
            0.5 * l * t / (0.3 * l + t),
        ],
    );
}

#[test]
fn lambda() {
    // Dahlin (1968); Åström & Hägglund (2006); λ = τ by default.
    let m = foptd(K, TAU, THETA);
    assert_parameters(
        "PI",
        parameters(&m, Rule::Lambda, Action::PI, None),
        [TAU / (K * (TAU + THETA)), TAU, 0.0],
    );
    let m2 = soptd(K, 6.0, 2.0, 1.0);
    assert_parameters(
        "SOPTD PID",
        parameters(&m2, Rule::Lambda, Action::PID, Some(4.0)),
        [8.0 / (K * 5.0), 8.0, 1.5],
    );
    assert!(matches!(
        tune(&m, Rule::Lambda, Action::PID, None),
        Err(NotApplicable::LambdaMismatch { .. })
    ));
}

#[test]
fn rules_that_do_not_apply_say_why() {
    let zero_delay = foptd(1.0, 5.0, 0.0);
    for rule in [Rule::ZieglerNicholsOpen, Rule::CohenCoon, Rule::Amigo] {
        assert_eq!(
            tune(&zero_delay, rule, Action::PI, None),
            Err(NotApplicable::NeedsDeadTime { rule })
        );
    }
    assert_eq!(
        tune(&zero_delay, Rule::ZieglerNicholsUltimate, Action::PI, None),
        Err(NotApplicable::NoPhaseCrossover)
    );
    let second = soptd(1.0, 5.0, 1.0, 1.0);
    for rule in [Rule::CohenCoon, Rule::Amigo] {
        assert_eq!(
            tune(&second, rule, Action::PI, None),
            Err(NotApplicable::FirstOrderOnly { rule })
        );
    }
    for rule in Rule::ALL {
        assert_eq!(
            formula(rule, Action::PD, ModelKind::Foptd),
            Err(NotApplicable::NoAction {
                rule,
                action: Action::PD
            })
        );
    }
    let said = NotApplicable::FirstOrderOnly {
        rule: Rule::CohenCoon,
    }
    .text(Lang::En);
    assert!(
        said.contains("defined for a first-order model with dead time"),
        "{said}"
    );
    assert!(
        NotApplicable::NoPhaseCrossover
            .text(Lang::Pt)
            .contains("ganho último")
    );
}

#[test]
fn a_negative_gain_gives_a_negative_controller_gain() {
    for rule in Rule::ALL {
        for action in [Action::PI, Action::PID] {
            let (pos, neg) = (foptd(2.0, 10.0, 2.0), foptd(-2.0, 10.0, 2.0));
            let (Ok(p), Ok(n)) = (
                tune(&pos, rule, action, None),
                tune(&neg, rule, action, None),
            ) else {
                continue;
            };
            assert_rel("−Kc", -n.controller.kc, p.controller.kc, 1e-14);
            assert_eq!(n.controller.ti, p.controller.ti);
            assert_eq!(n.controller.td, p.controller.td);
        }
    }
}

#[test]
fn every_rule_key_reads_back_and_every_formula_has_a_source() {
    for rule in Rule::ALL {
        assert_eq!(Rule::from_key(rule.key()), Some(rule));
        for kind in [ModelKind::Foptd, ModelKind::Soptd] {
            for action in Action::ALL {
                if let Ok(f) = formula(rule, action, kind) {
                    assert!(f.equations(Lang::En).starts_with("Kc = "));
                    assert!(!f.source(Lang::En).is_empty());
                }
            }
        }
    }
    let f = formula(Rule::Imc, Action::PI, ModelKind::Foptd).unwrap();
    assert_eq!(f.equations(Lang::En), "Kc = τ/(K(τc + θ)), Ti = τ");
    let f = formula(Rule::ZieglerNicholsOpen, Action::PI, ModelKind::Foptd).unwrap();
    assert_eq!(f.equations(Lang::Pt), "Kc = 0,9/a, Ti = θ/0,3 = 3,33θ");
    assert_eq!(Rule::from_key(" Cohen-Coon "), Some(Rule::CohenCoon));
    assert_eq!(Rule::from_key("zn"), None);
}

// ---------------------------------------------------------------- closed-loop stability

/// The coefficients (descending powers of s) of P(θs), P the Padé (m, m) polynomial of
/// e^{−x} = P(−x)/P(x), P(x) = Σ (2m − k)!·m!/((2m)!·k!·(m − k)!)·x^k.
fn pade(m: usize, theta: f64, sign: f64) -> Vec<f64> {
    let fact = |n: usize| (1..=n).map(|i| i as f64).product::<f64>();
    (0..=m)
        .rev()
        .map(|k| {
            fact(2 * m - k) * fact(m) / (fact(2 * m) * fact(k) * fact(m - k))
                * (sign * theta).powi(k as i32)
        })
        .collect()
}

fn add(a: &[f64], b: &[f64]) -> Vec<f64> {
    let n = a.len().max(b.len());
    let mut out = vec![0.0; n];
    for (i, x) in a.iter().enumerate() {
        out[n - a.len() + i] += x;
    }
    for (i, x) in b.iter().enumerate() {
        out[n - b.len() + i] += x;
    }
    out
}

/// Right-half-plane roots of the loop with the delay replaced by Padé (m, m):
/// d_c·d_g·P(θs) + n_c·n_g·P(−θs), from the polynomial's roots.
fn pade_count(g: &TransferFunction, c: &Controller, m: usize) -> usize {
    let (nc, dc) = c.feedback_coeffs();
    let d = multiply(&multiply(&dc, &g.den()), &pade(m, g.delay(), 1.0));
    let n = multiply(&multiply(&nc, &g.num()), &pade(m, g.delay(), -1.0));
    let roots = poly::roots(&add(&d, &n)).expect("roots");
    roots.iter().filter(|r| r.re > 0.0).count()
}

#[test]
fn proportional_control_of_a_first_order_lag_is_stable_just_below_the_ultimate_gain() {
    for (k, tau, theta) in [
        (1.0, 10.0, 2.0),
        (2.0, 1.0, 0.1),
        (0.5, 3.0, 6.0),
        (-1.5, 2.0, 1.0),
    ] {
        let g = plant(&foptd(k, tau, theta));
        let u = ultimate(&g).unwrap();
        let below = Controller::proportional(0.999 * u.kcr).unwrap();
        let above = Controller::proportional(1.001 * u.kcr).unwrap();
        assert_eq!(
            closed_loop_unstable_roots(&g, &below),
            Ok(0),
            "{k} {tau} {theta}"
        );
        // Past Kcr a pair of roots crosses into the right half-plane.
        assert_eq!(
            closed_loop_unstable_roots(&g, &above),
            Ok(2),
            "{k} {tau} {theta}"
        );
        // The wrong sign of Kc: one real root crosses at s = 0 when |Kc·K| > 1.
        let wrong = Controller::proportional(-2.0 / k).unwrap();
        assert_eq!(
            closed_loop_unstable_roots(&g, &wrong),
            Ok(1),
            "{k} {tau} {theta}"
        );
    }
}

#[test]
fn exactly_at_the_ultimate_gain_the_loop_is_marginal() {
    let g = plant(&foptd(1.0, 10.0, 2.0));
    let u = ultimate(&g).unwrap();
    let c = Controller::proportional(u.kcr).unwrap();
    assert!(matches!(
        closed_loop_unstable_roots(&g, &c),
        Err(StabilityError::Marginal { .. } | StabilityError::Unresolved { .. })
    ));
}

#[test]
fn an_integrating_controller_on_a_stable_plant() {
    // PI on 1/(s + 1)² without delay: χ = Ti·s(s + 1)² + Kc(Ti·s + 1), by Routh on
    // Ti·s³ + 2Ti·s² + Ti(1 + Kc)·s + Kc: stable iff 2Ti²(1 + Kc) > Ti·Kc, i.e.
    // Ti > Kc/(2(1 + Kc)).
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 2.0, 1.0]).unwrap();
    let kc = 4.0;
    let edge = kc / (2.0 * (1.0 + kc));
    let stable = Controller::new(Action::PI, kc, edge * 1.05, 0.0).unwrap();
    let unstable = Controller::new(Action::PI, kc, edge * 0.95, 0.0).unwrap();
    assert_eq!(closed_loop_unstable_roots(&g, &stable), Ok(0));
    assert_eq!(closed_loop_unstable_roots(&g, &unstable), Ok(2));
    // With a dead time the same controller agrees with a Padé (8, 8) loop.
    let g = g.with_delay(0.05).unwrap();
    for c in [stable, unstable] {
        assert_eq!(
            closed_loop_unstable_roots(&g, &c),
            Ok(pade_count(&g, &c, 8))
        );
    }
}

#[test]
fn a_controller_stabilises_an_unstable_plant() {
    // G = e^{−0.2s}/(s − 1) under P control: stable iff Kc > 1 and θ < atan(ω)/ω with
    // ω = √(Kc² − 1) (the phase condition at |Kc·G| = 1): for Kc = 2, θ < 0.6046.
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, -1.0])
        .unwrap()
        .with_delay(0.2)
        .unwrap();
    let count = |kc: f64| closed_loop_unstable_roots(&g, &Controller::proportional(kc).unwrap());
    assert_eq!(count(2.0), Ok(0));
    assert_eq!(count(0.5), Ok(1));
    // Past the upper limit: θ = 0.2 < atan(ω)/ω fails for ω ≈ 4.4, Kc ≈ 4.5.
    let upper = bisect(|w| 0.2 - w.atan() / w, 0.1, 100.0);
    let kc_max = (1.0 + upper * upper).sqrt();
    assert_eq!(count(kc_max * 0.99), Ok(0));
    assert_eq!(count(kc_max * 1.01), Ok(2));
    // A PI on the same plant, against a Padé (8, 8) loop.
    let c = Controller::new(Action::PI, 2.0, 3.0, 0.0).unwrap();
    assert_eq!(
        closed_loop_unstable_roots(&g, &c),
        Ok(pade_count(&g, &c, 8))
    );
}

/// A random loop: P, PI or PID (scaled from ZN ultimate-cycle settings) on a random FOPTD
/// or SOPTD model.
pub(crate) fn random_loop(rng: &mut Lcg) -> (TransferFunction, Controller) {
    let k = rng.log_uniform(0.3, 3.0) * if rng.next() < 0.2 { -1.0 } else { 1.0 };
    let tau = rng.log_uniform(0.5, 20.0);
    let theta = tau * rng.log_uniform(0.05, 2.0);
    let model = if rng.next() < 0.5 {
        foptd(k, tau, theta)
    } else {
        soptd(k, tau, tau * rng.log_uniform(0.05, 1.0), theta)
    };
    let action = [Action::P, Action::PI, Action::PID][(rng.next() * 3.0) as usize];
    let t = tune(&model, Rule::ZieglerNicholsUltimate, action, None).unwrap();
    let c = Controller::new(
        action,
        t.controller.kc * rng.log_uniform(0.2, 2.5),
        t.controller.ti * rng.log_uniform(0.3, 3.0),
        t.controller.td * rng.log_uniform(0.3, 3.0),
    )
    .unwrap();
    (plant(&model), c)
}

/// Whether |L(jω)| < `limit` for every ω ≥ `from` (a log grid of 2000 points a decade over
/// eight decades; L is strictly proper here, so it only falls past them).
fn small_loop_gain_past(g: &TransferFunction, c: &Controller, from: f64, limit: f64) -> bool {
    (0..16_000).all(|i| loop_at(g, c, from * 10f64.powf(i as f64 / 2000.0)).norm() < limit)
}

fn scaled(c: &Controller, f: f64) -> Controller {
    Controller::new(c.action, c.kc * f, c.ti, c.td).unwrap()
}

#[test]
fn the_count_agrees_with_high_order_pade_loops_on_random_loops() {
    let mut rng = Lcg(20240611);
    let (mut compared, mut stable, mut unstable) = (0, 0, 0);
    for _ in 0..400 {
        let (g, c) = random_loop(&mut rng);
        // Trust the Padé (8, 8) count only where its phase is right (to 5e-4 rad up to
        // ωθ = 8) wherever |L| ≥ 0.9 (past ωθ = 8 the all-pass Padé and the delay have the
        // same |L| < 0.9, so neither can encircle −1 there), and keep away from the
        // stability boundary (the same count at Kc ± 1 %).
        if !small_loop_gain_past(&g, &c, 8.0 / g.delay(), 0.9) {
            continue;
        }
        let reference = pade_count(&g, &c, 8);
        if pade_count(&g, &c, 10) != reference
            || pade_count(&g, &scaled(&c, 0.99), 8) != reference
            || pade_count(&g, &scaled(&c, 1.01), 8) != reference
        {
            continue;
        }
        assert_eq!(
            closed_loop_unstable_roots(&g, &c),
            Ok(reference),
            "G = {g:?}, C = {c:?}"
        );
        compared += 1;
        if reference == 0 {
            stable += 1;
        } else {
            unstable += 1;
        }
    }
    eprintln!("{compared} compared: {stable} stable, {unstable} unstable");
    assert!(compared >= 100, "only {compared} loops compared");
    assert!(
        stable >= 30 && unstable >= 30,
        "{stable} stable, {unstable} unstable"
    );
}

// ---------------------------------------------------------------- peak sensitivity

/// The peak of |1/(1 + L(jω))| on a dense grid: 20 000 points a decade from 10⁻⁴ rad/s to
/// ωθ = 300, and no coarser than 0.002 rad of ωθ.
fn brute_force_ms(g: &TransferFunction, c: &Controller) -> f64 {
    let mut w = 1e-4;
    let mut best: f64 = 0.0;
    while w < 300.0 / g.delay() {
        best = best.max(1.0 / (1.0 + loop_at(g, c, w)).norm());
        w += (w * 1.151e-4).min(0.002 / g.delay().max(1e-12));
    }
    best
}

#[test]
fn the_peak_sensitivity_agrees_with_a_dense_grid() {
    let mut rng = Lcg(77);
    let mut checked = 0;
    while checked < 6 {
        let (g, c) = random_loop(&mut rng);
        let Some(s) = max_sensitivity(&g, &c) else {
            continue;
        };
        let brute = brute_force_ms(&g, &c);
        // The refined peak is the grid's, or a little higher.
        assert!(brute <= s.ms * (1.0 + 1e-9), "{brute} > {}", s.ms);
        assert!(brute >= s.ms * (1.0 - 1e-6), "{brute} ≪ {}", s.ms);
        assert_rel(
            "|S| at ω",
            1.0 / (1.0 + loop_at(&g, &c, s.w)).norm(),
            s.ms,
            1e-15,
        );
        checked += 1;
    }
}

#[test]
fn the_peak_sensitivity_of_simple_loops() {
    // L = 1/(s(s + 1)) (P control of an integrator with a lag, Kc = 1): |S|² =
    // ω²(1 + ω²)/((1 − ω²)² + ω²), whose maximum (found here by a dense grid on the
    // closed form) is Ms ≈ 1.2985.
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 0.0]).unwrap();
    let c = Controller::proportional(1.0).unwrap();
    let s = max_sensitivity(&g, &c).unwrap();
    let closed = |w: f64| (w * w * (1.0 + w * w) / ((1.0 - w * w).powi(2) + w * w)).sqrt();
    let mut best: f64 = 0.0;
    let mut w = 0.01;
    while w < 100.0 {
        best = best.max(closed(w));
        w *= 1.0 + 1e-6;
    }
    assert_rel("Ms", s.ms, best, 1e-10);
    assert_rel("Ms", closed(s.w), best, 1e-10);
    // An unstable loop has no Ms.
    let g = plant(&foptd(1.0, 10.0, 2.0));
    assert_eq!(
        max_sensitivity(&g, &Controller::proportional(9.0).unwrap()),
        None
    );
    // The same plant at Kc = Kcr/2: Ms from the dense grid.
    let c = Controller::proportional(8.5024 / 2.0).unwrap();
    let s = max_sensitivity(&g, &c).unwrap();
    assert_rel("Ms", s.ms, brute_force_ms(&g, &c), 1e-7);
    let _ = C64::new(0.0, 0.0);
}

#[test]
fn high_gain_proportional_loops_have_one_unstable_pair_per_crossing_above_unit_gain() {
    // Kc·K·e^{−θs}/(τs + 1): the phase is −(2m + 1)π at atan(ω_m·τ) + ω_m·θ = (2m + 1)π, and
    // as the gain grows each crossing where |L(jω_m)| = g/√(1 + ω_m²τ²) > 1 has let a pair of
    // roots into the right half-plane (roots of a retarded loop cross left to right there),
    // so Z = 2·#{m : |L(jω_m)| > 1}. These loops encircle −1 at ωθ far beyond a Padé's reach.
    for (g, tau, theta) in [
        (5.0, 1.0, 0.5),
        (20.0, 1.0, 0.5),
        (100.0, 2.0, 1.0),
        (60.0, 1.0, 3.0),
    ] {
        let mut expected = 0;
        for m in 0.. {
            let target = (2 * m + 1) as f64 * PI;
            let w = bisect(
                |w| (w * tau).atan() + w * theta - target,
                1e-9,
                target / theta,
            );
            if g / (1.0 + w * w * tau * tau).sqrt() <= 1.0 {
                break;
            }
            expected += 2;
        }
        assert!(expected >= 2);
        let plant = plant(&foptd(1.0, tau, theta));
        let c = Controller::proportional(g).unwrap();
        assert_eq!(
            closed_loop_unstable_roots(&plant, &c),
            Ok(expected),
            "g = {g}, τ = {tau}, θ = {theta}"
        );
    }
}
