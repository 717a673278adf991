//! The approximations against the numbers the Tognetti notes print (Taylor, Skogestad, Padé
//! G_{1,1}, the dead time's Padé polynomials) and Passold §1.5 (the fifth order's dominant
//! pair), and against independent computations: the delay's Taylor series, static gains,
//! closed-form coefficients.

use degrau_lti::approx::{
    self, ApproxError, Approximation, DelayApproximant, Method, Reduction, delay_factor,
    delay_free_with_pade, pade, pade_coefficients, replace_delay,
};
use degrau_lti::{C64, StepInfoOptions, StepResponse, TransferFunction};

fn real(x: f64) -> C64 {
    C64::new(x, 0.0)
}

/// K(−0.1s + 1)/((5s + 1)(3s + 1)(0.5s + 1)) with K = 2, in zero-pole-gain form.
fn notes_third_order() -> TransferFunction {
    TransferFunction::from_zpk(
        &[real(10.0)],
        &[real(-0.2), real(-1.0 / 3.0), real(-2.0)],
        1.0,
    )
    .unwrap()
    .with_dc_gain(2.0)
    .unwrap()
}

/// 1/(2(s + 10)(s² + 14s + 50)(s² + 6s + 18)), Passold §1.5.
fn notes_fifth_order() -> TransferFunction {
    TransferFunction::from_coeffs(&[1.0], &[2.0, 60.0, 704.0, 4144.0, 12840.0, 18000.0]).unwrap()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// The time constant T of the factor (Ts + 1) of a real root r: −1/r.
fn time_constant(root: C64) -> f64 {
    assert_eq!(root.im, 0.0, "{root}");
    -1.0 / root.re
}

/// `x` cut (not rounded) to `decimals` decimals, as the notes print.
fn truncated(x: f64, decimals: i32) -> f64 {
    let scale = 10f64.powi(decimals);
    (x * scale).trunc() / scale
}

#[test]
fn taylor_gives_the_notes_first_order_with_dead_time() {
    let g = notes_third_order();
    let r = approx::taylor(&g, 1).unwrap();
    // K e^{−3.6s}/(5s + 1): lags 3 and 0.5 and the zero's 0.1 become dead time.
    assert!(close(r.delay(), 3.6, 1e-12), "{}", r.delay());
    assert_eq!(r.order(), 1);
    assert!(r.zeros().is_empty());
    assert!(close(time_constant(r.poles()[0]), 5.0, 1e-12));
    assert!(close(r.dc_gain(), 2.0, 1e-12));
    // To second order: (5s + 1)(3s + 1) kept, 0.5 + 0.1 of dead time.
    let r2 = approx::taylor(&g, 2).unwrap();
    assert!(close(r2.delay(), 0.6, 1e-12), "{}", r2.delay());
    assert_eq!(r2.order(), 2);
}

#[test]
fn the_half_rule_gives_the_notes_first_order_with_dead_time() {
    let g = notes_third_order();
    let r = approx::half_rule(&g, 1).unwrap();
    // K e^{−2.1s}/(6.5s + 1): half of 3 to the lag 5 and half to the dead time.
    assert!(close(r.delay(), 2.1, 1e-12), "{}", r.delay());
    assert!(close(time_constant(r.poles()[0]), 6.5, 1e-12));
    assert!(close(r.dc_gain(), 2.0, 1e-12));
    // Second order (Skogestad 2003): τ₂ = 3 + 0.25, θ = 0.25 + 0.1.
    let r2 = approx::half_rule(&g, 2).unwrap();
    let mut taus: Vec<f64> = r2.poles().iter().map(|&p| time_constant(p)).collect();
    taus.sort_by(f64::total_cmp);
    assert!(
        close(taus[0], 3.25, 1e-12) && close(taus[1], 5.0, 1e-12),
        "{taus:?}"
    );
    assert!(close(r2.delay(), 0.35, 1e-12), "{}", r2.delay());
}

#[test]
fn pade_moments_give_the_notes_g11_of_two_lags() {
    // 2/((10s + 1)(s + 1)) → 2(−0.909s + 1)/(10.09s + 1). Series 1 − 11s + 111s²: a₁ =
    // 111/11, b₁ = −11 + a₁ = −10/11.
    let g = TransferFunction::from_coeffs(&[2.0], &[10.0, 11.0, 1.0]).unwrap();
    let r = approx::moment_matching(&g, 1, 1).unwrap();
    let b1 = time_constant(r.zeros()[0]);
    let a1 = time_constant(r.poles()[0]);
    assert!(close(a1, 111.0 / 11.0, 1e-12), "{a1}");
    assert!(close(b1, -10.0 / 11.0, 1e-12), "{b1}");
    assert_eq!(truncated(a1, 2), 10.09);
    assert_eq!(truncated(b1, 3), -0.909);
    assert!(close(r.dc_gain(), 2.0, 1e-12));
    assert_eq!(r.delay(), 0.0);
}

#[test]
fn pade_moments_give_the_notes_g11_of_the_third_order() {
    // 2(−0.1s + 1)/((5s + 1)(3s + 1)(0.5s + 1)) → (−2.30s + 1)/(6.29s + 1) (times 2).
    // Series 1 − 8.6s + 54.1s²: a₁ = 54.1/8.6, b₁ = −8.6 + a₁.
    let g = notes_third_order();
    let r = approx::moment_matching(&g, 1, 1).unwrap();
    let (b1, a1) = (time_constant(r.zeros()[0]), time_constant(r.poles()[0]));
    assert!(close(a1, 54.1 / 8.6, 1e-12), "{a1}");
    assert!(close(b1, -8.6 + 54.1 / 8.6, 1e-12), "{b1}");
    assert_eq!(truncated(a1, 2), 6.29);
    assert_eq!(truncated(b1, 2), -2.30);
    assert!(close(r.dc_gain(), 2.0, 1e-12));
}

#[test]
fn pade_moments_count_the_dead_time() {
    // e^{−θs}/(τs + 1) to G_{0,1}: 1 − (θ + τ)s + … → 1/((θ + τ)s + 1), as Taylor's lag.
    let g = TransferFunction::from_zpk(&[], &[real(-0.5)], 0.5)
        .unwrap()
        .with_delay(0.7)
        .unwrap();
    let r = approx::moment_matching(&g, 0, 1).unwrap();
    assert!(close(time_constant(r.poles()[0]), 2.7, 1e-12));
    assert_eq!(r.delay(), 0.0);
}

#[test]
fn the_fifth_order_reduces_to_the_notes_dominant_pair() {
    let g = notes_fifth_order();
    let r = approx::dominant(&g, 2).unwrap();
    let den = r.den();
    assert_eq!(den.len(), 3);
    assert!(
        close(den[1], 6.0, 1e-12) && close(den[2], 18.0, 1e-12),
        "{den:?}"
    );
    assert!(r.zeros().is_empty());
    assert!(
        close(r.dc_gain(), g.dc_gain(), 1e-12),
        "{} {}",
        r.dc_gain(),
        g.dc_gain()
    );
    // 1/18000 of static gain: 0.001/(s² + 6s + 18).
    assert!(close(r.num()[0], 0.001, 1e-12));
    // Asking for 1 keeps the pair whole.
    assert_eq!(approx::dominant(&g, 1).unwrap().order(), 2);
    // Order 3: −7 ± j is nearer the axis than −10, and the pair stays whole, so 4.
    assert_eq!(approx::dominant(&g, 3).unwrap().order(), 4);
}

#[test]
fn neglecting_the_fast_pole_gives_the_notes_approximation_one() {
    // K/(s(s + 2)(s + 30)) → (K/30)/(s(s + 2)), here K = 60: 2/(s(s + 2)).
    let g = TransferFunction::from_zpk(&[], &[real(0.0), real(-2.0), real(-30.0)], 60.0).unwrap();
    let r = approx::dominant(&g, 2).unwrap();
    let (num, den) = (r.num(), r.den());
    assert!(close(num[0], 2.0, 1e-12), "{num:?}");
    assert_eq!(den.len(), 3);
    assert!(close(den[1], 2.0, 1e-12) && den[2] == 0.0, "{den:?}");
}

#[test]
fn dominant_poles_keep_the_zeros_near_them() {
    // Zeros at −4 (between the kept −1 ± 2j and the left-out −20) and −60 (beyond).
    let g = TransferFunction::from_zpk(
        &[real(-4.0), real(-60.0)],
        &[
            C64::new(-1.0, 2.0),
            C64::new(-1.0, -2.0),
            real(-20.0),
            real(-30.0),
        ],
        3.0,
    )
    .unwrap();
    let r = approx::dominant(&g, 2).unwrap();
    assert_eq!(r.zeros(), &[real(-4.0)]);
    assert!(close(r.dc_gain(), g.dc_gain(), 1e-12));
}

#[test]
fn every_reduction_keeps_the_static_gain() {
    let systems = [
        notes_third_order(),
        notes_fifth_order(),
        TransferFunction::from_zpk(
            &[real(-3.0), C64::new(2.0, 1.0), C64::new(2.0, -1.0)],
            &[
                real(-0.5),
                C64::new(-1.0, 1.5),
                C64::new(-1.0, -1.5),
                real(-4.0),
                real(-9.0),
            ],
            -0.7,
        )
        .unwrap()
        .with_delay(0.4)
        .unwrap(),
    ];
    for g in &systems {
        for method in Method::ALL {
            for (m, n) in [(0, 1), (1, 1), (0, 2), (1, 2), (2, 2)] {
                let r = Reduction { method, m, n };
                match approx::reduce(g, r) {
                    Ok(model) => assert!(
                        close(model.dc_gain(), g.dc_gain(), 1e-12),
                        "{r:?} of {}: {} vs {}",
                        g.describe(),
                        model.dc_gain(),
                        g.dc_gain()
                    ),
                    // Padé G_{m,n} may not exist; the others always apply below the order.
                    Err(ApproxError::Singular { .. }) if method == Method::Pade => {}
                    Err(e) => panic!("{r:?} of {}: {e}", g.describe()),
                }
            }
        }
        if g.delay() > 0.0 {
            for d in [
                DelayApproximant::Pade { m: 2, n: 3 },
                DelayApproximant::TaylorLag,
                DelayApproximant::Limit { n: 5 },
            ] {
                let model = replace_delay(g, d).unwrap();
                assert!(close(model.dc_gain(), g.dc_gain(), 1e-12), "{d:?}");
            }
        }
    }
}

#[test]
fn an_integrator_is_kept_with_its_velocity_gain() {
    // 2/(s(5s + 1)(s + 1)): Taylor to order 2 keeps s and (5s + 1), θ = 1.
    let g = TransferFunction::from_zpk(&[], &[real(0.0), real(-0.2), real(-1.0)], 0.4).unwrap();
    let r = approx::taylor(&g, 2).unwrap();
    assert!(close(r.delay(), 1.0, 1e-12));
    assert!(r.poles().contains(&real(0.0)));
    // lim s·G(s) = 2 in both.
    let velocity = |tf: &TransferFunction| {
        let s = C64::new(1e-9, 0.0);
        (tf.eval(s) * s).re
    };
    assert!(close(velocity(&r), 2.0, 1e-6) && close(velocity(&g), 2.0, 1e-6));
}

#[test]
fn the_ranking_methods_refuse_an_unstable_pole_and_a_useless_order() {
    let g = TransferFunction::from_zpk(&[], &[real(1.0), real(-2.0), real(-3.0)], 1.0).unwrap();
    assert!(matches!(
        approx::dominant(&g, 1),
        Err(ApproxError::UnstablePole(_))
    ));
    assert!(matches!(
        approx::taylor(&g, 1),
        Err(ApproxError::UnstablePole(_))
    ));
    let h = notes_third_order();
    assert_eq!(
        approx::dominant(&h, 3),
        Err(ApproxError::NotLower { asked: 3, order: 3 })
    );
    assert_eq!(approx::taylor(&h, 0), Err(ApproxError::OrderZero));
    assert_eq!(
        approx::moment_matching(&h, 2, 1),
        Err(ApproxError::PadeOrder { m: 2, n: 1 })
    );
    // Taylor at the full order still moves the zero −0.1s + 1 into the dead time.
    assert!(close(approx::taylor(&h, 3).unwrap().delay(), 0.1, 1e-12));
    let plain = TransferFunction::from_zpk(&[], &[real(-1.0)], 1.0).unwrap();
    assert_eq!(
        approx::taylor(&plain, 1),
        Err(ApproxError::NothingToApproximate)
    );
}

/// The notes' Padé polynomials of e^{−θs}, descending powers.
fn notes_pade(theta: f64, m: usize, n: usize) -> (Vec<f64>, Vec<f64>) {
    let t = theta;
    match (m, n) {
        (0, 1) => (vec![1.0], vec![t, 1.0]),
        (1, 1) => (vec![-t, 2.0], vec![t, 2.0]),
        (1, 2) => (vec![-2.0 * t, 6.0], vec![t * t, 4.0 * t, 6.0]),
        (2, 2) => (vec![t * t, -6.0 * t, 12.0], vec![t * t, 6.0 * t, 12.0]),
        (3, 3) => (
            vec![-t * t * t, 12.0 * (t * t), -60.0 * t, 120.0],
            vec![t * t * t, 12.0 * (t * t), 60.0 * t, 120.0],
        ),
        _ => unreachable!("the notes print these five"),
    }
}

#[test]
fn pade_of_the_dead_time_is_the_notes_polynomials_exactly() {
    for theta in [0.5, 1.0, 2.0, 0.3, 1.7, 12.25] {
        for (m, n) in [(0, 1), (1, 1), (1, 2), (2, 2), (3, 3)] {
            let (num, den) = pade_coefficients(theta, m, n).unwrap();
            assert_eq!(
                (num, den),
                notes_pade(theta, m, n),
                "θ = {theta}, ({m}, {n})"
            );
        }
    }
}

/// The first `count` Taylor coefficients of num(s)/den(s) (descending powers) at s = 0.
fn series(num: &[f64], den: &[f64], count: usize) -> Vec<f64> {
    let asc = |p: &[f64]| {
        let mut v: Vec<f64> = p.iter().rev().copied().collect();
        v.resize(count, 0.0);
        v
    };
    let (b, a) = (asc(num), asc(den));
    let mut c = vec![0.0; count];
    for k in 0..count {
        let known: f64 = (1..=k).map(|j| a[j] * c[k - j]).sum();
        c[k] = (b[k] - known) / a[0];
    }
    c
}

#[test]
fn pade_matches_the_delay_series_to_order_m_plus_n() {
    for theta in [0.5, 2.0] {
        for n in 1..=6 {
            for m in 0..=n {
                let (num, den) = pade_coefficients(theta, m, n).unwrap();
                let c = series(&num, &den, m + n + 2);
                let mut exact = 1.0;
                for (k, ck) in c.iter().enumerate() {
                    if k > 0 {
                        exact *= -theta / k as f64;
                    }
                    let agree = (ck - exact).abs() <= 1e-10 * exact.abs().max(1e-300);
                    if k <= m + n {
                        assert!(agree, "θ {theta} ({m},{n}) term {k}: {ck} vs {exact}");
                    } else {
                        assert!(!agree, "({m},{n}) should differ at order {k}");
                    }
                }
            }
        }
    }
}

#[test]
fn pade_zeros_are_on_the_right_and_its_step_jumps_the_wrong_way() {
    for (m, n) in [(1, 1), (2, 2), (3, 3), (2, 4)] {
        let p = pade(1.5, m, n).unwrap();
        assert_eq!(p.zeros().len(), m);
        assert!(p.zeros().iter().all(|z| z.re > 0.0), "({m},{n}) zeros");
        assert!(p.poles().iter().all(|z| z.re < 0.0), "({m},{n}) poles");
        assert!(close(p.dc_gain(), 1.0, 1e-12));
    }
    // (1, 1): y(0⁺) = −1 for a unit step, then 1 in the end.
    let r = StepResponse::new(&pade(1.5, 1, 1).unwrap(), 1.0).unwrap();
    assert!(close(r.value(0.0), -1.0, 1e-12), "{}", r.value(0.0));
    assert!(close(r.final_value().unwrap(), 1.0, 1e-12));
    assert!(matches!(pade(0.0, 1, 1), Err(ApproxError::BadDelay(_))));
    assert!(matches!(
        pade(1.0, 3, 2),
        Err(ApproxError::PadeOrder { .. })
    ));
}

#[test]
fn the_dead_time_replaced_by_each_approximant() {
    // 1/(s + 1)·e^{−0.5s}.
    let g = TransferFunction::from_zpk(&[], &[real(-1.0)], 1.0)
        .unwrap()
        .with_delay(0.5)
        .unwrap();
    let p11 = delay_free_with_pade(&g, 1, 1).unwrap();
    assert_eq!(p11.delay(), 0.0);
    assert_eq!(p11.order(), 2);
    // (−θs + 2)/(θs + 2): zero at 2/θ = 4, pole at −4.
    assert!(close(p11.zeros()[0].re, 4.0, 1e-12));
    assert!(p11.poles().iter().any(|p| close(p.re, -4.0, 1e-12)));
    let zero = replace_delay(&g, DelayApproximant::TaylorZero).unwrap();
    assert_eq!(zero.zeros(), &[real(2.0)]);
    let lag = replace_delay(&g, DelayApproximant::TaylorLag).unwrap();
    assert!(lag.poles().contains(&real(-2.0)));
    let limit = replace_delay(&g, DelayApproximant::Limit { n: 4 }).unwrap();
    assert_eq!(
        limit.poles().iter().filter(|&&p| p == real(-8.0)).count(),
        4
    );
    for model in [&p11, &zero, &lag, &limit] {
        assert!(close(model.dc_gain(), 1.0, 1e-12));
    }
    // Without a dead time: nothing to replace, and the closed-loop helper gets g back.
    let plain = TransferFunction::from_zpk(&[], &[real(-1.0)], 1.0).unwrap();
    assert_eq!(delay_free_with_pade(&plain, 2, 2).unwrap(), plain);
    assert_eq!(
        replace_delay(&plain, DelayApproximant::TaylorLag),
        Err(ApproxError::NoDelay)
    );
    // 1 − θs on a biproper system would be improper.
    let biproper = TransferFunction::from_zpk(&[real(-2.0)], &[real(-1.0)], 1.0)
        .unwrap()
        .with_delay(0.5)
        .unwrap();
    assert!(matches!(
        replace_delay(&biproper, DelayApproximant::TaylorZero),
        Err(ApproxError::Lti(_))
    ));
}

#[test]
fn more_lags_in_the_limit_come_closer_to_the_true_delay() {
    // e^{−s}/(s + 1) against its (1 + s/n)^{−n} stand-ins: the gap shrinks with n.
    let g = TransferFunction::from_zpk(&[], &[real(-1.0)], 1.0)
        .unwrap()
        .with_delay(1.0)
        .unwrap();
    let exact = StepResponse::new(&g, 1.0).unwrap();
    let options = StepInfoOptions::default();
    let gap = |n| {
        let a = approx::approximate(
            &g,
            &exact,
            Approximation::Delay(DelayApproximant::Limit { n }),
            &options,
        )
        .unwrap();
        a.comparison.max_error
    };
    let gaps: Vec<f64> = [1, 2, 4, 8, 16].map(gap).to_vec();
    assert!(gaps.windows(2).all(|w| w[1] < w[0]), "{gaps:?}");
}

#[test]
fn the_comparison_table_lists_every_method_on_the_notes_system() {
    let g = notes_third_order();
    let exact = StepResponse::new(&g, 1.0).unwrap();
    let rows = approx::table(&g, &exact, &StepInfoOptions::default());
    let reductions = rows
        .iter()
        .filter(|r| matches!(r.approximation, Approximation::Reduce(_)))
        .count();
    // Dominant, Taylor, Skogestad to 1 and 2; Padé (0,1), (1,1), (1,2), (2,2).
    assert_eq!(reductions, 10);
    for row in &rows {
        let a = row.outcome.as_ref().expect("every method applies here");
        assert!(a.comparison.max_error.is_finite() && a.comparison.ise >= 0.0);
        assert!(close(a.model.dc_gain(), 2.0, 1e-12));
        // A dead time in the model is the true delay of its exact response.
        assert_eq!(a.response.delay(), a.model.delay());
    }
}

#[test]
fn the_dead_time_factor_keeps_the_notes_scaling() {
    let f = delay_factor(DelayApproximant::Pade { m: 2, n: 2 }, 1.0).unwrap();
    assert_eq!(f.num, vec![1.0, -6.0, 12.0]);
    assert_eq!(f.den, vec![1.0, 6.0, 12.0]);
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    /// A stable system of order 2–6: real poles and pairs in the left half plane, up to two
    /// real zeros on either side, a dead time, a gain of either sign.
    fn stable_system() -> impl Strategy<Value = TransferFunction> {
        (
            prop::collection::vec((-8.0f64..-0.1, 0.0f64..4.0, any::<bool>()), 1..=3),
            prop::collection::vec(prop_oneof![-9.0f64..-0.2, 0.2f64..9.0], 0..=2),
            0.0f64..2.0,
            prop_oneof![-5.0f64..-0.1, 0.1f64..5.0],
        )
            .prop_map(|(poles, zeros, delay, dc)| {
                let poles: Vec<C64> = poles
                    .iter()
                    .flat_map(|&(re, im, pair)| {
                        if pair {
                            vec![C64::new(re, im + 0.1), C64::new(re, -(im + 0.1))]
                        } else {
                            vec![real(re), real(re - im - 0.05)]
                        }
                    })
                    .collect();
                let zeros: Vec<C64> = zeros.into_iter().map(real).collect();
                TransferFunction::from_zpk(&zeros, &poles, 1.0)
                    .and_then(|g| g.with_dc_gain(dc))
                    .and_then(|g| g.with_delay(delay))
                    .expect("a buildable system")
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

        /// Every reduction that applies keeps G(0) to 1e-12, and a true dead time stays a
        /// delay of the model's exact response; every dead-time stand-in keeps G(0) too.
        #[test]
        fn every_approximation_keeps_the_static_gain(g in stable_system()) {
            let k = g.dc_gain();
            let mut applied = 0;
            for approximation in Approximation::catalogue(&g) {
                match approximation.apply(&g) {
                    Ok(model) => {
                        applied += 1;
                        prop_assert!(
                            (model.dc_gain() - k).abs() <= 1e-12 * k.abs(),
                            "{approximation:?} of {}: {} vs {k}",
                            g.describe(),
                            model.dc_gain()
                        );
                        prop_assert!(model.delay() >= g.delay() || model.delay() == 0.0);
                    }
                    // Padé G_{m,n} need not exist; a zero left unpaired may make a
                    // reduction improper; a lone pair asked to order 1 stays whole: each
                    // is said, never a wrong model.
                    Err(
                        ApproxError::Singular { .. }
                        | ApproxError::Lti(_)
                        | ApproxError::NotLower { .. }
                        | ApproxError::NothingToApproximate,
                    ) => {}
                    Err(e) => prop_assert!(false, "{approximation:?} of {}: {e}", g.describe()),
                }
            }
            // At least Padé G_{0,1} (the first moment) exists for every such system.
            prop_assert!(applied > 0, "nothing applied to {}", g.describe());
        }
    }
}
