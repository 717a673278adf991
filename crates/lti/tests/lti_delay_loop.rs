//! The loop with a true dead time against independent computations: a fine fixed-step
//! integration of the delay equation written here from the block diagram (classic RK4, the
//! delayed input read from the stored past by cubic Hermite interpolation, the step a
//! divisor of θ so that the delay's kinks fall on grid points), and, without a delay, the
//! exact rational closed loop.

use degrau_lti::control::{Action, Controller, Horizon, LoopInput, loop_metrics, loop_response};
use degrau_lti::{StepResponse, TransferFunction};

/// A plant K/((τ1·s + 1)(τ2·s + 1))·e^{−θs} (τ2 = 0: first order).
#[derive(Debug, Clone, Copy)]
struct Plant {
    k: f64,
    tau1: f64,
    tau2: f64,
    theta: f64,
}

impl Plant {
    fn transfer_function(&self) -> TransferFunction {
        let den = if self.tau2 > 0.0 {
            vec![self.tau1 * self.tau2, self.tau1 + self.tau2, 1.0]
        } else {
            vec![self.tau1, 1.0]
        };
        TransferFunction::from_coeffs(&[self.k], &den)
            .unwrap()
            .with_delay(self.theta)
            .unwrap()
    }
}

/// The loop's states: plant (x1, y), integral z = ∫e, filter q = e/(1 + Tf·s).
#[derive(Debug, Clone, Copy, Default)]
struct State {
    x1: f64,
    y: f64,
    z: f64,
    q: f64,
}

/// The block diagram as equations, with the plant's delayed input w given.
struct Loop {
    plant: Plant,
    c: Controller,
    r: f64,
    d: f64,
}

impl Loop {
    fn tf(&self) -> f64 {
        self.c.td / self.c.n
    }

    fn error(&self, s: &State) -> f64 {
        self.r - s.y
    }

    /// u + d: Kc·(b·r − y) + Kc/Ti·z + Kc·Td·(e − q)/Tf + d.
    fn v(&self, s: &State) -> f64 {
        let c = &self.c;
        let e = self.error(s);
        let mut u = c.kc * (c.b * self.r - s.y);
        if c.action.integral() {
            u += c.kc * s.z / c.ti;
        }
        if c.action.derivative() && c.td > 0.0 {
            u += c.kc * c.td * (e - s.q) / self.tf();
        }
        u + self.d
    }

    fn derivative(&self, s: &State, w: f64) -> State {
        let p = &self.plant;
        let (x1_dot, y_dot) = if p.tau2 > 0.0 {
            ((p.k * w - s.x1) / p.tau1, (s.x1 - s.y) / p.tau2)
        } else {
            (0.0, (p.k * w - s.y) / p.tau1)
        };
        let e = self.error(s);
        let q_dot = if self.c.action.derivative() && self.c.td > 0.0 {
            (e - s.q) / self.tf()
        } else {
            0.0
        };
        State {
            x1: x1_dot,
            y: y_dot,
            z: e,
            q: q_dot,
        }
    }

    /// dv/dt from the state's derivative (r and d constant for t > 0).
    fn v_dot(&self, s: &State, ds: &State) -> f64 {
        let c = &self.c;
        let mut dv = -c.kc * ds.y;
        if c.action.integral() {
            dv += c.kc * ds.z / c.ti;
        }
        if c.action.derivative() && c.td > 0.0 {
            dv += c.kc * c.td * (-ds.y - ds.q) / self.tf();
        }
        let _ = s;
        dv
    }
}

fn add(s: &State, k: &State, h: f64) -> State {
    State {
        x1: s.x1 + h * k.x1,
        y: s.y + h * k.y,
        z: s.z + h * k.z,
        q: s.q + h * k.q,
    }
}

/// y at the grid t = i·h, h = θ/m, up to `end`.
fn integrate(lp: &Loop, m: usize, end: f64) -> (f64, Vec<f64>) {
    let h = lp.plant.theta / m as f64;
    let steps = (end / h).ceil() as usize + 1;
    let mut s = State::default();
    // v and v' at the grid (right limits at 0).
    let (mut v, mut dv, mut y) = (Vec::new(), Vec::new(), Vec::new());
    // The delayed input at offset c·h of step j: Hermite on grid interval j − m.
    let delayed = |v: &[f64], dv: &[f64], j: usize, c: f64| -> f64 {
        if j < m {
            return 0.0;
        }
        let k = j - m;
        let (p0, p1, m0, m1) = (v[k], v[k + 1], dv[k] * h, dv[k + 1] * h);
        let (c2, c3) = (c * c, c * c * c);
        (2.0 * c3 - 3.0 * c2 + 1.0) * p0
            + (c3 - 2.0 * c2 + c) * m0
            + (-2.0 * c3 + 3.0 * c2) * p1
            + (c3 - c2) * m1
    };
    for j in 0..steps {
        let w0 = delayed(&v, &dv, j, 0.0);
        let k1 = lp.derivative(&s, w0);
        v.push(lp.v(&s));
        dv.push(lp.v_dot(&s, &k1));
        y.push(s.y);
        // The grid value at j + 1 is needed by the step j + 1 − m ≤ j only when m ≥ 1.
        let wm = delayed(&v, &dv, j, 0.5);
        let w1 = delayed(&v, &dv, j, 1.0);
        let k2 = lp.derivative(&add(&s, &k1, h / 2.0), wm);
        let k3 = lp.derivative(&add(&s, &k2, h / 2.0), wm);
        let k4 = lp.derivative(&add(&s, &k3, h), w1);
        s = State {
            x1: s.x1 + h / 6.0 * (k1.x1 + 2.0 * k2.x1 + 2.0 * k3.x1 + k4.x1),
            y: s.y + h / 6.0 * (k1.y + 2.0 * k2.y + 2.0 * k3.y + k4.y),
            z: s.z + h / 6.0 * (k1.z + 2.0 * k2.z + 2.0 * k3.z + k4.z),
            q: s.q + h / 6.0 * (k1.q + 2.0 * k2.q + 2.0 * k3.q + k4.q),
        };
    }
    (h, y)
}

/// Gains of a reasonable loop, independent of the tuning module: Kc = τ1/(K·2θ) (PI, PID),
/// half of that for P; Ti = min(τ1, 8θ); Td = τ2 or θ/2.
fn controller(action: Action, p: &Plant) -> Controller {
    let kc = p.tau1 / (p.k * 2.0 * p.theta);
    let kc = if action == Action::P { kc / 2.0 } else { kc };
    let td = if p.tau2 > 0.0 { p.tau2 } else { p.theta / 2.0 };
    Controller::new(action, kc, p.tau1.min(8.0 * p.theta), td).unwrap()
}

#[test]
fn the_loop_with_a_true_dead_time_agrees_with_a_fine_integration_of_the_delay_equation() {
    let mut worst: f64 = 0.0;
    for ratio in [0.1, 0.5, 1.0, 2.0] {
        for (k, tau1, tau2) in [(2.5, 10.0, 0.0), (-0.7, 4.0, 1.5)] {
            let plant = Plant {
                k,
                tau1,
                tau2,
                theta: ratio * tau1,
            };
            let g = plant.transfer_function();
            for action in [Action::P, Action::PI, Action::PID] {
                let c = controller(action, &plant);
                for input in [LoopInput::Setpoint, LoopInput::Load] {
                    let end = 6.0 * (plant.theta + tau1 + tau2);
                    let exact = loop_response(&g, &c, input, Horizon::Until(end)).unwrap();
                    let (r, d) = match input {
                        LoopInput::Setpoint => (1.0, 0.0),
                        LoopInput::Load => (0.0, 1.0),
                    };
                    let lp = Loop { plant, c, r, d };
                    let m = 8000;
                    let (h, y) = integrate(&lp, m, end);
                    // The size of the response: the setpoint step, or the load's effect K.
                    let size = match input {
                        LoopInput::Setpoint => 1.0,
                        LoopInput::Load => k.abs(),
                    };
                    for i in 1..=50 {
                        let idx = (i * (y.len() - 1)) / 51;
                        let t = idx as f64 * h;
                        let err = (exact.value(t) - y[idx]).abs() / size;
                        worst = worst.max(err);
                        assert!(
                            err < 1e-6,
                            "{action:?} {input:?} θ/τ {ratio} K {k}: t {t}: {} vs {}",
                            exact.value(t),
                            y[idx]
                        );
                    }
                }
            }
        }
    }
    eprintln!("worst difference: {worst:e}");
}

#[test]
fn without_a_dead_time_the_loop_is_the_rational_closed_loop() {
    let g = TransferFunction::from_coeffs(&[2.0], &[1.0, 3.0, 2.0]).unwrap();
    let c = Controller::proportional(4.0).unwrap();
    let cl = g.closed_loop(4.0).unwrap();
    let exact = StepResponse::new(&cl, 1.0).unwrap();
    let r = loop_response(&g, &c, LoopInput::Setpoint, Horizon::Until(10.0)).unwrap();
    for i in 0..=40 {
        let t = i as f64 * 0.25;
        assert!(
            (r.value(t) - exact.value(t)).abs() < 1e-10,
            "t {t}: {} vs {}",
            r.value(t),
            exact.value(t)
        );
    }
    assert!((r.final_value - 8.0 / 10.0).abs() < 1e-15);
}

#[test]
fn the_automatic_horizon_stops_once_settled_and_the_final_values_are_the_loops() {
    let plant = Plant {
        k: 1.0,
        tau1: 10.0,
        tau2: 0.0,
        theta: 2.0,
    };
    let g = plant.transfer_function();
    let c = Controller::new(Action::PI, 2.5, 10.0, 0.0).unwrap();
    let r = loop_response(&g, &c, LoopInput::Setpoint, Horizon::Auto).unwrap();
    assert!(r.settled);
    assert_eq!(r.final_value, 1.0);
    assert!((r.value(r.end()) - 1.0).abs() < 1e-6);
    assert!(r.end() < 400.0, "{}", r.end());
    // Proportional control leaves the offset 1/(1 + K·Kc).
    let p = Controller::proportional(3.0).unwrap();
    let r = loop_response(&g, &p, LoopInput::Setpoint, Horizon::Auto).unwrap();
    assert!(r.settled);
    assert!((r.final_value - 0.75).abs() < 1e-15);
    // Past the ultimate gain (8.50) the loop does not settle.
    let p = Controller::proportional(9.0).unwrap();
    let r = loop_response(&g, &p, LoopInput::Setpoint, Horizon::Auto).unwrap();
    assert!(!r.settled);
}

#[test]
fn integral_errors_equal_their_closed_forms_when_the_error_keeps_its_sign() {
    // ∫e dt = 1/lim(s·L(s)) = Ti/(Kc·K) for a setpoint step and ∫y dt = Ti/Kc for a load
    // step (the final-value theorem on E(s)/s); with no overshoot e keeps its sign, so IAE
    // is the same number. PI with Ti = τ on K·e^{−θs}/(τs + 1) leaves L = k·e^{−θs}/s,
    // k = Kc·K/τ, which does not overshoot while k·θ < 1/e: here k·θ = 0.1.
    for (k, tau, theta) in [(2.0, 5.0, 1.0), (0.4, 1.0, 3.0), (-1.5, 20.0, 2.0)] {
        let g = Plant {
            k,
            tau1: tau,
            tau2: 0.0,
            theta,
        }
        .transfer_function();
        let (kc, ti) = (0.1 * tau / (theta * k), tau);
        let c = Controller::new(Action::PI, kc, ti, 0.0).unwrap();
        let sp = loop_metrics(&loop_response(&g, &c, LoopInput::Setpoint, Horizon::Auto).unwrap());
        assert_eq!(sp.overshoot, Some(0.0));
        let iae = sp.iae.unwrap();
        assert!(
            (iae - ti / (kc * k)).abs() < 1e-7 * iae,
            "{iae} vs {}",
            ti / (kc * k)
        );
        let load = loop_metrics(&loop_response(&g, &c, LoopInput::Load, Horizon::Auto).unwrap());
        let iae = load.iae.unwrap();
        assert!(
            (iae - ti / kc.abs()).abs() < 1e-7 * iae,
            "{iae} vs {}",
            ti / kc.abs()
        );
    }
}

#[test]
fn without_a_delay_the_metrics_are_the_exponentials() {
    // PI with Ti = τ cancels the plant's pole: L = k/s, e(t) = e^{−kt}: IAE = 1/k,
    // ITAE = 1/k², settling when e^{−kt} = 0.02: t = ln 50/k.
    let (kk, tau) = (2.0, 4.0);
    let g = TransferFunction::from_coeffs(&[kk], &[tau, 1.0]).unwrap();
    let c = Controller::new(Action::PI, 3.0, tau, 0.0).unwrap();
    let k = 3.0 * kk / tau;
    let m = loop_metrics(&loop_response(&g, &c, LoopInput::Setpoint, Horizon::Auto).unwrap());
    assert!((m.iae.unwrap() - 1.0 / k).abs() < 1e-8, "{:?}", m.iae);
    assert!(
        (m.itae.unwrap() - 1.0 / (k * k)).abs() < 1e-8,
        "{:?}",
        m.itae
    );
    assert!((m.settling_time.unwrap() - 50f64.ln() / k).abs() < 1e-8);
    assert_eq!(m.overshoot, Some(0.0));
    // Proportional control: an offset, so no IAE.
    let p = Controller::proportional(3.0).unwrap();
    let m = loop_metrics(&loop_response(&g, &p, LoopInput::Setpoint, Horizon::Auto).unwrap());
    assert_eq!((m.iae, m.itae), (None, None));
    assert!((m.final_value.unwrap() - 6.0 / 7.0).abs() < 1e-15);
}

#[test]
fn the_metrics_agree_with_the_fine_integration() {
    for (k, tau1, tau2, theta) in [
        (1.0, 10.0, 0.0, 2.0),
        (3.0, 5.0, 2.0, 1.0),
        (0.5, 1.0, 0.0, 1.5),
    ] {
        let plant = Plant {
            k,
            tau1,
            tau2,
            theta,
        };
        let g = plant.transfer_function();
        for action in [Action::PI, Action::PID] {
            let c = controller(action, &plant);
            for input in [LoopInput::Setpoint, LoopInput::Load] {
                let r = loop_response(&g, &c, input, Horizon::Auto).unwrap();
                let m = loop_metrics(&r);
                let (rr, d) = match input {
                    LoopInput::Setpoint => (1.0, 0.0),
                    LoopInput::Load => (0.0, 1.0),
                };
                let lp = Loop { plant, c, r: rr, d };
                let (h, y) = integrate(&lp, 8000, r.end());
                let iae: f64 = y
                    .windows(2)
                    .map(|w| h * ((rr - w[0]).abs() + (rr - w[1]).abs()) / 2.0)
                    .sum();
                let itae: f64 = y
                    .windows(2)
                    .enumerate()
                    .map(|(i, w)| {
                        let t = i as f64 * h;
                        h * (t * (rr - w[0]).abs() + (t + h) * (rr - w[1]).abs()) / 2.0
                    })
                    .sum();
                let what = format!("{action:?} {input:?} {plant:?}");
                assert!(
                    (m.iae.unwrap() - iae).abs() < 1e-5 * iae,
                    "{what}: IAE {:?} vs {iae}",
                    m.iae
                );
                assert!(
                    (m.itae.unwrap() - itae).abs() < 1e-5 * itae,
                    "{what}: ITAE {:?} vs {itae}",
                    m.itae
                );
                let peak = m.peak.unwrap();
                let (i_max, y_max) = y
                    .iter()
                    .enumerate()
                    .map(|(i, v)| {
                        (
                            i,
                            if input == LoopInput::Load {
                                v.abs()
                            } else {
                                *v
                            },
                        )
                    })
                    .fold((0, f64::MIN), |a, b| if b.1 > a.1 { b } else { a });
                assert!(
                    (peak.value.abs() - y_max).abs() < 1e-6,
                    "{what}: peak {peak:?} vs {y_max}"
                );
                assert!(
                    (peak.time - i_max as f64 * h).abs() < 0.05 * theta,
                    "{what}: {peak:?} at {}",
                    i_max as f64 * h
                );
                // The settling time: the last grid point outside the band.
                let y_final = m.final_value.unwrap();
                let band = 0.02
                    * match input {
                        LoopInput::Setpoint => 1.0,
                        LoopInput::Load => (peak.value - y_final).abs(),
                    };
                let last = y.iter().rposition(|v| (v - y_final).abs() > band).unwrap();
                let ts = m.settling_time.unwrap();
                assert!(
                    (ts - last as f64 * h).abs() <= 1.01 * h,
                    "{what}: settling {ts} vs {}",
                    last as f64 * h
                );
            }
        }
    }
}

mod table {
    use degrau_lti::control::{
        Action, Controller, ProcessModel, RowError, Rule, rule_table, tuned_loop,
    };

    #[test]
    fn the_rule_table_sets_every_rule_side_by_side_with_both_responses() {
        // K = 1, τ = 10, θ = 2: SIMC (Skogestad 2003, τc = θ) gives Kc = τ/(K(τc + θ)) = 2.5
        // and Ti = min(τ, 4(τc + θ)) = 10.
        let model = ProcessModel::foptd(1.0, 10.0, 2.0).unwrap();
        let rows = rule_table(&model, Action::PI, None);
        assert_eq!(rows.len(), Rule::ALL.len());
        for row in &rows {
            let (tuning, tuned) = row
                .result
                .as_ref()
                .unwrap_or_else(|e| panic!("{:?}: {e}", row.rule));
            assert!(tuned.is_stable(), "{:?}", row.rule);
            let sp = tuned.setpoint_metrics;
            let load = tuned.load_metrics;
            assert_eq!(sp.final_value, Some(1.0), "{:?}", row.rule);
            assert_eq!(load.final_value, Some(0.0), "{:?}", row.rule);
            assert!(sp.iae.is_some() && load.iae.is_some() && sp.settling_time.is_some());
            // The load's peak deviation lies between 0 and the open loop's K = 1.
            let peak = load.peak.unwrap();
            assert!(
                peak.value > 0.0 && peak.value < 1.0,
                "{:?}: {peak:?}",
                row.rule
            );
            let ms = tuned.ms.unwrap();
            assert!((1.0..4.0).contains(&ms), "{:?}: Ms {ms}", row.rule);
            assert_eq!(tuning.rule, row.rule);
        }
        let simc = rows.iter().find(|r| r.rule == Rule::Simc).unwrap();
        let (tuning, _) = simc.result.as_ref().unwrap();
        assert!((tuning.controller.kc - 2.5).abs() < 1e-12);
        assert!((tuning.controller.ti - 10.0).abs() < 1e-12);
        // Ziegler–Nichols' quarter decay is the most aggressive: its load peak is the
        // smallest and its overshoot larger than SIMC's.
        let zn = rows
            .iter()
            .find(|r| r.rule == Rule::ZieglerNicholsOpen)
            .unwrap();
        let (_, zn) = zn.result.as_ref().unwrap();
        let (_, simc) = simc.result.as_ref().unwrap();
        assert!(zn.setpoint_metrics.overshoot > simc.setpoint_metrics.overshoot);
        assert!(zn.ms > simc.ms);
    }

    #[test]
    fn a_rule_that_does_not_apply_says_why_in_its_row() {
        let model = ProcessModel::soptd(2.0, 8.0, 3.0, 1.0).unwrap();
        let rows = rule_table(&model, Action::PID, None);
        let cohen = rows.iter().find(|r| r.rule == Rule::CohenCoon).unwrap();
        assert!(matches!(cohen.result, Err(RowError::NotApplicable(_))));
        let simc = rows.iter().find(|r| r.rule == Rule::Simc).unwrap();
        assert!(simc.result.as_ref().is_ok_and(|(_, t)| t.is_stable()));
    }

    #[test]
    fn past_the_ultimate_gain_the_loop_is_unstable_and_has_no_metrics() {
        let g = ProcessModel::foptd(1.0, 10.0, 2.0)
            .unwrap()
            .transfer_function()
            .unwrap();
        let t = tuned_loop(&g, &Controller::proportional(9.0).unwrap()).unwrap();
        assert_eq!(t.unstable_roots, Some(2));
        assert_eq!((t.ms, t.setpoint_metrics.overshoot), (None, None));
        let t = tuned_loop(&g, &Controller::proportional(8.0).unwrap()).unwrap();
        assert!(t.is_stable());
        assert!(t.setpoint_metrics.overshoot.unwrap() > 50.0);
    }
}

#[test]
fn a_load_without_integral_action_settles_to_its_offset_as_a_step_does() {
    // P control of 1.5·e^{−s}/(10s + 1), Kc = 2: y(∞) = K/(1 + K·Kc) = 0.375, reached
    // without a peak; the band is 2 % of 0.375, crossed long before the end computed.
    let g = Plant {
        k: 1.5,
        tau1: 10.0,
        tau2: 0.0,
        theta: 1.0,
    }
    .transfer_function();
    let p = Controller::proportional(2.0).unwrap();
    let r = loop_response(&g, &p, LoopInput::Load, Horizon::Auto).unwrap();
    let m = loop_metrics(&r);
    assert!((m.final_value.unwrap() - 0.375).abs() < 1e-15);
    let ts = m.settling_time.unwrap();
    assert!(ts < 0.5 * r.end(), "{ts} vs end {}", r.end());
    assert!((r.value(ts) - 0.375).abs() > 0.0199 * 0.375);
    assert!((r.value(ts) - 0.375).abs() < 0.0201 * 0.375);
    assert_eq!(m.overshoot, Some(0.0));
    assert_eq!((m.iae, m.itae), (None, None));
}

#[test]
fn the_reaction_curve_of_a_second_order_model_without_dead_time_is_tuned() {
    // Two lags and no θ: the tangent at the inflection still crosses 0 after t = 0, so
    // Ziegler–Nichols' reaction-curve rule reads an apparent dead time θ′ > 0 (for equal lags
    // τ: θ′ = (3 − e)τ, τ′ = e·τ).
    use degrau_lti::control::{ProcessModel, Rule, tuning::tune};
    let model = ProcessModel::soptd(2.0, 5.0, 5.0, 0.0).unwrap();
    let t = tune(&model, Rule::ZieglerNicholsOpen, Action::PI, None).unwrap();
    let (theta, tau) = ((3.0 - std::f64::consts::E) * 5.0, std::f64::consts::E * 5.0);
    // PI: Kc = 0.9·τ′/(K·θ′), Ti = θ′/0.3.
    assert!((t.controller.kc - 0.9 * tau / (2.0 * theta)).abs() < 1e-9 * t.controller.kc);
    assert!((t.controller.ti - theta / 0.3).abs() < 1e-9 * t.controller.ti);
}
