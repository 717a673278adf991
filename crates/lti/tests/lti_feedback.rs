//! The closed loop around a proportional gain, the error constants, the gain search and the
//! second-order formulas, against the course notes' numbers and answers worked by hand.

use degrau_lti::feedback::{
    ErrorConstants, FormulaCheck, Input, InputResponse, Limit, SecondOrder, Spec, SpecPair,
    find_gain,
};
use degrau_lti::{C64, LtiError, StepInfo, StepInfoOptions, StepResponse, TransferFunction};

fn tf(num: &[f64], den: &[f64]) -> TransferFunction {
    TransferFunction::from_coeffs(num, den).expect("valid system")
}

#[track_caller]
fn assert_rel(what: &str, a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs(),
        "{what}: {a} vs {b} (rel {})",
        (a - b).abs() / b.abs()
    );
}

#[test]
fn the_notes_closed_loop_with_unit_gain_has_the_printed_factors() {
    // Passold §1.3: FTMF = 0.5/(s³ + 7s² + 15s + 25.5) = 0.5/((s + 5.025)(s² + 1.975s + 5.075)).
    let g = tf(&[0.5], &[1.0, 7.0, 15.0, 25.0]);
    let cl = g.closed_loop(1.0).unwrap();
    for (a, b) in cl.den().iter().zip([1.0, 7.0, 15.0, 25.5]) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
    let real = cl.poles().iter().find(|p| p.im == 0.0).unwrap();
    assert_eq!(format!("{:.3}", -real.re), "5.025");
    let pair = cl.poles().iter().find(|p| p.im > 0.0).unwrap();
    // s² + 2σ s + |p|²: 1.975 and 5.075 to the printed digits.
    assert_eq!(format!("{:.3}", -2.0 * pair.re), "1.975");
    assert_eq!(format!("{:.3}", pair.norm_sqr()), "5.075");
}

#[test]
fn a_loop_around_a_dead_time_is_refused() {
    let g = tf(&[1.0], &[1.0, 1.0]).with_delay(0.5).unwrap();
    assert_eq!(g.closed_loop(2.0), Err(LtiError::DelayInLoop));
    assert_eq!(
        find_gain(&g, &[Spec::Overshoot(10.0)]),
        Err(LtiError::DelayInLoop)
    );
}

#[test]
fn error_constants_of_a_type_one_system() {
    // (s+2)/(s(s+4)): type 1, Kp = ∞, Kv = 2/4, Ka = 0; e_ss 0, 2, ∞.
    let g = tf(&[1.0, 2.0], &[1.0, 4.0, 0.0]);
    let c = ErrorConstants::of(&g, 1.0);
    assert_eq!(c.system_type, 1);
    assert_eq!(c.kp, Limit::Infinite);
    assert_rel("Kv", c.kv.value(), 0.5, 1e-15);
    assert_eq!(c.ka, Limit::Finite(0.0));
    let e = c.errors();
    assert_eq!(e.step, Limit::Finite(0.0));
    assert_rel("e_ss ramp", e.ramp.value(), 2.0, 1e-15);
    assert_eq!(e.parabola, Limit::Infinite);
    let json = serde_json::to_value(c).unwrap();
    assert_eq!(json["kp"], "inf");
    assert_eq!(json["type"], 1);
    // The ramp error read off the exact ramp response of the closed loop: r − y → 2.
    let cl = g.closed_loop(1.0).unwrap();
    let ramp = InputResponse::new(&cl, Input::Ramp, 1.0).unwrap();
    let t = 60.0;
    assert_rel("ramp error at 60 s", t - ramp.value(t), 2.0, 1e-9);
}

#[test]
fn error_constants_of_type_zero_and_of_a_differentiator() {
    // 10/(s+2) with K = 3: Kp = 15, e_ss step = 1/16.
    let g = tf(&[10.0], &[1.0, 2.0]);
    let c = ErrorConstants::of(&g, 3.0);
    assert_eq!(c.system_type, 0);
    assert_rel("Kp", c.kp.value(), 15.0, 1e-15);
    assert_eq!(c.kv, Limit::Finite(0.0));
    assert_rel("e_ss", c.errors().step.value(), 1.0 / 16.0, 1e-15);
    assert_eq!(c.errors().ramp, Limit::Infinite);
    let d = ErrorConstants::of(&tf(&[1.0, 0.0], &[1.0, 1.0]), 1.0);
    assert_eq!(d.system_type, -1);
    assert_eq!(d.kp, Limit::Finite(0.0));
    assert_eq!(d.errors().step, Limit::Finite(1.0));
}

#[test]
fn the_gain_for_ten_percent_overshoot_of_k_over_s_s_plus_2() {
    // K/(s(s+2)): closed loop K/(s² + 2s + K), ζ = 1/√K; Mp = 10 % ⇔ ζ = 0.5912 ⇔ K = 2.861.
    let g = tf(&[1.0], &[1.0, 2.0, 0.0]);
    let found = find_gain(&g, &[Spec::Overshoot(10.0)]).unwrap().unwrap();
    assert_eq!(format!("{:.2}", found.k), "2.86");
    let zeta = SecondOrder::damping_for_overshoot(10.0).unwrap();
    assert_rel("K", found.k, 1.0 / (zeta * zeta), 1e-8);
    assert_eq!(found.range.0, 0.0);
    assert_rel("range end", found.range.1, found.k, 1e-12);
    // The answer's poles are the closed loop's, and its exact overshoot is the bound.
    let cl = g.closed_loop(found.k).unwrap();
    assert_eq!(found.poles, cl.poles());
    let info = StepInfo::of_response(&StepResponse::new(&cl, 1.0).unwrap(), &Default::default());
    assert!((info.overshoot.unwrap() - 10.0).abs() < 1e-6);
}

#[test]
fn a_steady_state_error_bound_gives_a_least_gain() {
    // 10/((s+2)(s+5)): Kp = K, e_ss = 1/(1 + K) ≤ 0.1 ⇔ K ≥ 9 (stable for every K > 0).
    let g = tf(&[10.0], &[1.0, 7.0, 10.0]);
    let found = find_gain(&g, &[Spec::EssStep(0.1)]).unwrap().unwrap();
    assert_rel("least K", found.k, 9.0, 1e-8);
    assert_eq!(found.range.1, f64::INFINITY);
    // With an overshoot bound too, the range closes above.
    let both = find_gain(&g, &[Spec::EssStep(0.1), Spec::Overshoot(40.0)])
        .unwrap()
        .unwrap();
    assert_rel("least K", both.k, 9.0, 1e-8);
    assert!(both.range.1.is_finite() && both.range.1 > 9.0);
    // No gain meets an impossible pair.
    assert_eq!(
        find_gain(&g, &[Spec::EssStep(0.01), Spec::Overshoot(1.0)]).unwrap(),
        None
    );
}

#[test]
fn second_order_formulas_and_their_inverse() {
    let p = SecondOrder { zeta: 0.5, wn: 2.0 };
    assert_rel("σ", p.sigma(), 1.0, 1e-15);
    assert_rel("t_s", p.settling_time(), 4.0, 1e-15);
    assert_rel(
        "t_p",
        p.peak_time(),
        std::f64::consts::PI / 3f64.sqrt(),
        1e-15,
    );
    assert_rel("Mp", p.overshoot(), 16.303_353_482_158_6, 1e-12);
    // The exact 0–100 % rise of the pure pair is the formula's.
    let check = FormulaCheck::of(&p.transfer_function().unwrap()).unwrap();
    assert_rel(
        "t_r exact",
        check.rise_time.exact.unwrap(),
        p.rise_time(),
        1e-10,
    );
    assert!(check.rise_time.difference_percent().unwrap().abs() < 1e-8);
    assert!(check.overshoot.difference_percent().unwrap().abs() < 1e-6);
    assert!(check.peak_time.difference_percent().unwrap().abs() < 1e-8);
    // Inverse: each pair of specs gives back the pair.
    for pair in [
        SpecPair::OvershootSettling {
            overshoot: p.overshoot(),
            settling: p.settling_time(),
        },
        SpecPair::OvershootPeak {
            overshoot: p.overshoot(),
            peak: p.peak_time(),
        },
        SpecPair::SettlingPeak {
            settling: p.settling_time(),
            peak: p.peak_time(),
        },
    ] {
        let q = SecondOrder::from_specs(pair).unwrap();
        assert_rel("ζ", q.zeta, 0.5, 1e-12);
        assert_rel("ωn", q.wn, 2.0, 1e-12);
    }
    assert!(
        SecondOrder::from_specs(SpecPair::OvershootPeak {
            overshoot: 0.0,
            peak: 1.0
        })
        .is_err()
    );
}

#[test]
fn a_third_pole_breaks_the_formulas_and_the_check_shows_it() {
    // The notes' 0.5/((s² + 2s + 5)(s + 5)): a real pole near the pair.
    let g = tf(&[0.5], &[1.0, 7.0, 15.0, 25.0]);
    let check = FormulaCheck::of(&g).unwrap();
    assert_rel("ζ", check.pair.zeta, 1.0 / 5f64.sqrt(), 1e-12);
    assert!(check.overshoot.difference_percent().unwrap().abs() > 1.0);
}

#[test]
fn the_rise_time_from_zero_to_one_hundred_percent_is_matlabs() {
    // MATLAB's stepinfo example tf([1 5 5],[1 1.65 5 6.5 2]) with RiseTimeLimits [0 1]:
    // 4.8143 s (exact 4.81426 s); the default 10–90 % is MATLAB's 3.8456 s.
    let g = tf(&[1.0, 5.0, 5.0], &[1.0, 1.65, 5.0, 6.5, 2.0]);
    let r = StepResponse::new(&g, 1.0).unwrap();
    let full = StepInfoOptions {
        rise_limits: (0.0, 1.0),
        ..Default::default()
    };
    let info = StepInfo::of_response(&r, &full);
    assert_eq!(format!("{:.5}", info.rise_time.unwrap()), "4.81426");
    assert_eq!(info.rise_start, Some(0.0));
    let y_final = r.final_value().unwrap();
    assert!((r.value(info.rise_end.unwrap()) - y_final).abs() < 1e-9);
    let default = StepInfo::of_response(&r, &Default::default());
    assert_rel("10-90 % rise", default.rise_time.unwrap(), 3.8456, 1e-3);
    // A monotone response never reaches 100 %: no 0–100 % rise time.
    let first = tf(&[1.0], &[1.0, 1.0]);
    let r = StepResponse::new(&first, 1.0).unwrap();
    assert_eq!(StepInfo::of_response(&r, &full).rise_time, None);
}

#[test]
fn impulse_ramp_and_parabola_responses_are_exact() {
    // G = 1/(s+1): impulse e^{−t}, ramp t − 1 + e^{−t}, parabola t²/2 − t + 1 − e^{−t}.
    let g = tf(&[1.0], &[1.0, 1.0]);
    let at = |input| InputResponse::new(&g, input, 1.0).unwrap();
    let (imp, ramp, par) = (at(Input::Impulse), at(Input::Ramp), at(Input::Parabola));
    for t in [0.1, 1.0, 3.7] {
        assert_rel("impulse", imp.value(t), (-t).exp(), 1e-12);
        assert_rel("ramp", ramp.value(t), t - 1.0 + (-t).exp(), 1e-12);
        assert_rel(
            "parabola",
            par.value(t),
            0.5 * t * t - t + 1.0 - (-t).exp(),
            1e-11,
        );
    }
    let (t, y) = imp.sample_uniform(0.0, 2.0, 5);
    assert_eq!(t, vec![0.0, 0.5, 1.0, 1.5, 2.0]);
    assert_rel("sampled impulse", y[2], (-1f64).exp(), 1e-12);
    assert_eq!(ramp.input_value(2.0), 2.0);
    // With a dead time the responses wait for it.
    let late = InputResponse::new(&g.clone().with_delay(1.0).unwrap(), Input::Ramp, 1.0).unwrap();
    assert_eq!(late.value(0.5), 0.0);
    let _ = C64::new(0.0, 0.0);
}
