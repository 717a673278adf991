//! Clusters of nearly equal poles against an independent reference: the plain residue
//! formula y(t) = A·k·[Π(−z)/Π(−p) + Σᵢ Π(pᵢ − z)/(pᵢ·Π_{j≠i}(pᵢ − pⱼ))·e^{pᵢt}] evaluated in
//! 768-bit arithmetic (astro-float, `tests/exact`), where the cancellation of the residues ~1/δ^{m−1}
//! (at most ~300 bits here) leaves well over 100 bits. It shares nothing with the library's
//! divided-difference evaluation.

use degrau_lti::{C64, StepInfo, StepInfoOptions, StepResponse, TransferFunction};
use proptest::prelude::*;

use crate::exact;
use exact::Reference;

fn reals(values: &[f64]) -> Vec<C64> {
    values.iter().map(|&v| C64::new(v, 0.0)).collect()
}

fn evenly(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from + (to - from) * i as f64 / (n - 1) as f64)
        .collect()
}

/// The rise time of the reference, bracketing the crossings where the library found them.
fn reference_rise(reference: &mut Reference, info: &StepInfo, y_final: f64) -> f64 {
    let widen = |t: f64| (0.9 * t, 1.1 * t + 1e-3);
    let (a, b) = widen(info.rise_start.expect("a rise start"));
    let start = reference.crossing(0.1 * y_final, a, b);
    let (a, b) = widen(info.rise_end.expect("a rise end"));
    let end = reference.crossing(0.9 * y_final, a, b);
    end - start
}

fn assert_rel(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol * want.abs(),
        "{what}: {got} vs reference {want} (relative {:e})",
        (got - want) / want
    );
}

/// Rise time to 1e-9 relative and the curve to 1e-9 of the final value, against the
/// reference.
fn check_known(zeros: &[C64], poles: &[C64], gain: f64, amplitude: f64, rise: f64) {
    let g = TransferFunction::from_zpk(zeros, poles, gain).unwrap();
    let r = StepResponse::new(&g, amplitude).unwrap();
    let info = StepInfo::of_response(&r, &StepInfoOptions::default());
    let mut reference = Reference::new(zeros, poles, gain * amplitude);
    let y_final = reference.final_value();
    assert_rel("final value", r.final_value().unwrap(), y_final, 1e-12);
    let want = reference_rise(&mut reference, &info, y_final);
    assert_rel("rise time", info.rise_time.unwrap(), want, 1e-9);
    assert!(
        (want - rise).abs() < 1e-4,
        "the issue's rise time {rise}, reference {want}"
    );
    assert_eq!(info.overshoot, Some(0.0), "monotone");
    assert_eq!(info.undershoot, Some(0.0), "monotone");
    let end = r.auto_horizon();
    let (t, y) = r.sample_uniform(0.0, end, 401);
    for (&t, &y) in t.iter().zip(&y) {
        let exact = reference.value(t);
        assert!(
            (y - exact).abs() <= 1e-9 * y_final.abs(),
            "y({t}) = {y}, reference {exact}"
        );
    }
}

#[test]
fn five_poles_a_ten_thousandth_apart() {
    check_known(&[], &reals(&evenly(-1.0, -1.0004, 5)), 1.0, 1.0, 5.5599);
}

#[test]
fn six_poles_from_the_issue_evenly_spaced() {
    // Six poles evenly spaced from −4.666983 to −4.669316, k = 0.23418, A = 0.5.
    let poles = reals(&evenly(-4.666983, -4.669316, 6));
    check_known(&[], &poles, 0.23418, 0.5, 1.3116);
}

#[test]
fn ten_poles_from_the_issue_evenly_spaced() {
    let poles = reals(&evenly(-0.41990, -0.42028, 10));
    let g = TransferFunction::from_zpk(&[], &poles, 1.0).unwrap();
    let r = StepResponse::new(&g, 1.0).unwrap();
    let rise = StepInfo::of_response(&r, &StepInfoOptions::default())
        .rise_time
        .unwrap();
    // 10 poles at ≈ 0.4201: a 10-fold pole there rises in ≈ 19.007 s.
    check_known(&[], &poles, 1.0, 1.0, rise);
    assert!((rise - 19.0071).abs() < 1e-3, "{rise}");
}

#[test]
fn clustered_denominator_typed_as_coefficients() {
    // The six-pole cluster expanded to coefficients: the roots come back perturbed by
    // ~eps^(1/6) (possibly complex), yet the steady state is num[−1]/den[−1].
    let poles = reals(&evenly(-4.666983, -4.669316, 6));
    let den = TransferFunction::from_zpk(&[], &poles, 1.0).unwrap().den();
    let num = [2.5, 0.23418 * den[6]];
    let g = TransferFunction::from_coeffs(&num, &den).unwrap();
    let r = StepResponse::new(&g, 1.0).unwrap();
    let info = StepInfo::of_response(&r, &StepInfoOptions::default());
    assert_rel(
        "steady state",
        info.steady_state.unwrap(),
        num[1] / den[6],
        1e-9,
    );
    // Against the reference built from the roots the library found.
    let mut reference = Reference::new(g.zeros(), g.poles(), g.gain());
    let y_final = reference.final_value();
    let want = reference_rise(&mut reference, &info, y_final);
    assert_rel("rise time", info.rise_time.unwrap(), want, 1e-9);
}

#[test]
fn a_near_pair_is_written_as_approximate() {
    use degrau_lti::expr::{OscillationForm, expression};
    let g = TransferFunction::from_zpk(&[], &reals(&evenly(-1.0, -1.01, 3)), 1.0).unwrap();
    let text = expression(
        &StepResponse::new(&g, 1.0).unwrap(),
        OscillationForm::CosSin,
    );
    assert!(text.starts_with("y(t) ≈ "), "{text}");
    assert!(text.contains("as a 3-fold pole at -1.005"), "{text}");
}

// ---------------------------------------------------------------------------------------
// Random clusters
// ---------------------------------------------------------------------------------------

#[derive(Debug, Clone)]
struct Case {
    poles: Vec<C64>,
    zeros: Vec<C64>,
}

/// 2–10 poles around a centre at relative spacings 1e-10…1e-2 (a real cluster, or a
/// complex one with its mirror), 0–2 real zeros, 0–2 far real poles.
fn case() -> impl Strategy<Value = Case> {
    (
        2usize..=10,
        -10.0f64..-2.0,
        0.1f64..10.0,
        prop_oneof![Just(0.0), 0.2f64..3.0],
        prop::collection::vec(-0.5f64..0.5, 10),
        prop::collection::vec(0.3f64..20.0, 0..=2),
        prop::collection::vec((0.1f64..0.6, any::<bool>()), 0..=2),
    )
        .prop_map(|(m, log_spacing, modulus, angle_tan, jitter, zeros, far)| {
            let spacing = 10f64.powf(log_spacing);
            let center = C64::new(-modulus, modulus * angle_tan);
            let complex = angle_tan != 0.0;
            let count = if complex { (m / 2).max(1) } else { m };
            let mut poles = Vec::new();
            for (k, wobble) in jitter.iter().enumerate().take(count) {
                let offset = modulus * spacing * (k as f64 + 0.3 * wobble);
                let p = if complex {
                    center + C64::new(-offset, 0.7 * offset)
                } else {
                    C64::new(center.re - offset, 0.0)
                };
                poles.push(p);
                if complex {
                    poles.push(p.conj());
                }
            }
            for (factor, faster) in far {
                let r = if faster {
                    modulus / factor
                } else {
                    modulus * factor
                };
                poles.push(C64::new(-r, 0.0));
            }
            Case {
                poles,
                zeros: reals(&zeros.iter().map(|z| -z).collect::<Vec<_>>()),
            }
        })
}

/// None when the library refused the system; Some(check) otherwise.
fn check_case(case: &Case) -> Result<bool, TestCaseError> {
    let g = TransferFunction::from_zpk(&case.zeros, &case.poles, 1.0)
        .and_then(|g| g.with_dc_gain(1.0))
        .map_err(|e| TestCaseError::fail(format!("{e}")))?;
    let r = match StepResponse::new(&g, 1.0) {
        Ok(r) => r,
        Err(_) => return Ok(false),
    };
    let mut reference = Reference::new(g.zeros(), g.poles(), g.gain());
    let y_final = reference.final_value();
    let tol = 1e-9 * y_final.abs();
    prop_assert!((r.final_value().unwrap() - y_final).abs() <= tol);
    let end = r.auto_horizon();
    let (t, y) = r.sample_uniform(0.0, end, 121);
    let mut largest: f64 = 0.0;
    for (&t, &y) in t.iter().zip(&y) {
        let exact = reference.value(t);
        largest = largest.max(exact);
        prop_assert!((y - exact).abs() <= tol, "y({}) = {} vs {}", t, y, exact);
        prop_assert!(
            (r.value(t) - exact).abs() <= tol,
            "value({}) vs {}",
            t,
            exact
        );
    }
    let info = StepInfo::of_response(&r, &StepInfoOptions::default());
    // Each reported instant is where the reference has the level it claims.
    let jump = reference.value(0.0);
    let at = |reference: &mut Reference,
              t: Option<f64>,
              level: f64,
              what: &str|
     -> Result<(), TestCaseError> {
        if t == Some(0.0) {
            // Inside the jump of a biproper system at the step: 0 before, y(0⁺) after.
            prop_assert!(
                level.abs() <= jump.abs() + tol && level * jump >= 0.0,
                "{}: at 0, level {} outside the jump to {}",
                what,
                level,
                jump
            );
            return Ok(());
        }
        if let Some(t) = t {
            let exact = reference.value(t);
            prop_assert!(
                (exact - level).abs() <= tol,
                "{}: y_ref({}) = {}, level {}",
                what,
                t,
                exact,
                level
            );
        }
        Ok(())
    };
    at(&mut reference, info.rise_start, 0.1 * y_final, "rise start")?;
    at(&mut reference, info.rise_end, 0.9 * y_final, "rise end")?;
    if let Some(ts) = info.settling_time {
        let exact = reference.value(ts);
        prop_assert!(
            ((exact - y_final).abs() - 0.02 * y_final.abs()).abs() <= tol,
            "settling: y_ref({}) = {}",
            ts,
            exact
        );
    }
    if let (Some(peak), Some(tp)) = (info.peak, info.peak_time) {
        // The peak is the largest |y| (MATLAB's Peak): compare with |y_ref(tp)|.
        let signed = peak * reference.value(tp).signum();
        at(&mut reference, Some(tp), signed, "peak")?;
    }
    let peak = info.peak.unwrap();
    prop_assert!(
        largest <= peak + tol,
        "grid max {} above the peak {}",
        largest,
        peak
    );
    Ok(true)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    #[test]
    fn random_clusters_match_the_reference(cases in prop::collection::vec(case(), 4)) {
        let mut refused = 0;
        for case in &cases {
            if !check_case(case)? {
                refused += 1;
            }
        }
        // Refusals must be rare: none of these systems is beyond double precision.
        prop_assert!(refused == 0, "{} of {} refused: {:?}", refused, cases.len(), cases);
    }
}

// ---------------------------------------------------------------------------------------
// Large and tiny arguments (library level; the CLI ones are in cli_step_large.rs)
// ---------------------------------------------------------------------------------------

#[test]
fn a_dead_time_of_1e16_leaves_every_duration_exact() {
    let poles = [
        C64::new(-1.0, 2.0),
        C64::new(-1.0, -2.0),
        C64::new(-5.0, 0.0),
    ];
    let g = TransferFunction::from_zpk(&[], &poles, 0.5).unwrap();
    let options = StepInfoOptions::default();
    let plain = StepInfo::of_response(&StepResponse::new(&g, 1.0).unwrap(), &options);
    for delay in [1e16, 1e17] {
        let r = StepResponse::new(&g.clone().with_delay(delay).unwrap(), 1.0).unwrap();
        let info = StepInfo::of_response(&r, &options);
        assert_eq!(info.rise_time, plain.rise_time, "delay {delay}");
        assert_eq!(info.overshoot, plain.overshoot);
        assert_eq!(info.peak, plain.peak);
        assert_eq!(info.settling_time, plain.settling_time.map(|t| t + delay));
    }
    assert!((plain.rise_time.unwrap() - 0.7732).abs() < 1e-4);
}

#[test]
fn subnormal_inputs_are_refused_by_name() {
    let tiny = C64::new(1e-320, 0.0);
    let err = TransferFunction::from_zpk(&[tiny], &[C64::new(-1.0, 0.0)], 1.0).unwrap_err();
    assert!(err.to_string().contains("zero 1 is 1e-320"), "{err}");
    let err = TransferFunction::from_zpk(&[], &[C64::new(-1.0, 0.0)], 1e-320).unwrap_err();
    assert!(err.to_string().contains("the gain k is 1e-320"), "{err}");
    let err = TransferFunction::from_coeffs(&[1.0], &[1.0, 1e-320]).unwrap_err();
    assert!(
        err.to_string().contains("coefficient 2 of the denominator"),
        "{err}"
    );
    let g = TransferFunction::from_zpk(&[], &[C64::new(-1.0, 0.0)], 1.0).unwrap();
    assert!(StepResponse::new(&g, 1e-320).is_err());
    // A final value below the normal range, from normal inputs: refused, not shown as 0.
    let g = TransferFunction::from_zpk(&[C64::new(-1e-200, 0.0)], &[C64::new(-1.0, 0.0)], 1e-150)
        .unwrap();
    let err = StepResponse::new(&g, 1.0).unwrap_err();
    assert!(err.to_string().contains("the final value"), "{err}");
}
