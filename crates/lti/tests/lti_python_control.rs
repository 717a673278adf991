//! The margins against python-control's `margin` on 100 random rational loops.
//!
//! Provenance: `tests/data/python_control/python_control_margins.json`, written by
//! `python_control_margins.py` beside it (numpy's `default_rng(2026)`; python-control 0.10.2,
//! numpy 2.4.6, versions recorded in the fixture). Orders 1 to 5, numerator degree below the
//! denominator's, real and complex poles (some lightly damped), integrators, right-half-plane
//! poles and zeros, gains of both signs from 0.1 to 100 times the unit loop gain.
//!
//! How python-control 0.10.2 chooses (`control/margins.py`, `stability_margins`, method
//! "poly" for a continuous transfer function): the phase crossovers are the real roots
//! ω ≥ 0 (`epsw` = 0, so ω = 0 included) of Im(L(jω))·|den|² = 0 where Re L(jω) ≤ 0; the
//! gain crossovers the real roots ω > 0 of |num(jω)|² − |den(jω)|² = 0. GM = 1/|L| at the
//! phase crossover whose |ln GM| is smallest, PM = (∠L mod 360°) − 180° at the gain crossover
//! whose |PM| is smallest (the first by ω on a tie). No phase crossover (or only ones with
//! L = ∞, GM = 0) gives GM = inf and wcg = nan; no gain crossover PM = inf and wcp = nan.
//! That is MATLAB's rule, which Degrau follows (the smallest margins: GM nearest 0 dB, PM
//! nearest 0°). Im L(jω) is odd, so ω = 0 is always one of python-control's roots: whenever
//! L(0) is finite and negative (a negative gain, or an odd number of right-half-plane real
//! roots) it is a phase crossover with GM = 1/|L(0)| (a closed-loop root reaches s = 0 at
//! that gain), which Degrau counts too (it did not before this comparison: 27 of these
//! loops showed it).
//!
//! The tolerance: python-control's crossings are roots of polynomials of degree up to 10
//! (numpy's companion-matrix eigenvalues), Degrau's bisected on L(jω) to the last bit; on
//! these loops they agree to 7e-15 in ω, 1.2e-14 in GM and 2.8e-13° in PM (the worst when
//! this was written), so 1e-10 relative (PM: 1e-10·max(1, |PM|) degrees) leaves room for
//! the conditioning of lightly damped loops and still tells any other crossing apart.
//!
//! All 100 loops are compared in full: GM, PM, ω_pc, ω_gc and every crossing.

use degrau_lti::TransferFunction;
use degrau_lti::control::{Controller, Margins, margins};
use serde_json::Value;

const TOL: f64 = 1e-10;

fn fixture() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/python_control/python_control_margins.json"
    );
    let text = std::fs::read_to_string(path).expect("the fixture is in the repository");
    serde_json::from_str(&text).expect("the fixture is JSON")
}

/// A number of the fixture ("inf", "-inf" and "nan" as strings).
fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().unwrap(),
        Value::String(s) => s.parse().expect("inf, -inf or nan"),
        _ => panic!("not a number: {v}"),
    }
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("a list").iter().map(num).collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300)
}

/// Two phase margins in degrees: python-control's lie in [−180°, 180°), Degrau's in
/// (−180°, 180°], so ±180° are the same angle.
fn pm_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

#[test]
fn margins_equal_python_control_on_100_random_loops() {
    let data = fixture();
    let cases = data["cases"].as_array().expect("cases");
    assert_eq!(cases.len(), 100);
    let p = Controller::proportional(1.0).unwrap();
    let mut zero_crossings = 0;
    for (i, case) in cases.iter().enumerate() {
        let g = TransferFunction::from_coeffs(&nums(&case["num"]), &nums(&case["den"]))
            .unwrap_or_else(|e| panic!("case {i}: {e}"));
        let m: Margins = margins(&g, &p);
        let (gm, wcg) = (num(&case["gm"]), num(&case["wcg"]));
        let (all_gm, all_wcg) = (nums(&case["all_gm"]), nums(&case["all_wcg"]));

        // The gain margin.
        let expected = if gm.is_infinite() {
            assert!(wcg.is_nan(), "case {i}");
            None
        } else {
            Some((gm, wcg))
        };
        zero_crossings += usize::from(wcg == 0.0);
        match expected {
            None => assert!(
                m.gm.is_infinite() && m.w_pc.is_none(),
                "case {i}: python-control has no phase crossover, Degrau {m:?}"
            ),
            Some((gm, w)) => {
                let w_pc = m.w_pc.expect("a phase crossover");
                let ok = (w_pc == w || close(w_pc, w, TOL)) && close(m.gm, gm, TOL);
                assert!(ok, "case {i}: GM {gm} at {w}, Degrau {m:?}");
            }
        }

        // The phase margin.
        let (pm, wcp) = (num(&case["pm"]), num(&case["wcp"]));
        if pm.is_infinite() {
            assert!(wcp.is_nan(), "case {i}");
            assert!(m.pm.is_infinite() && m.w_gc.is_none(), "case {i}: {m:?}");
        } else {
            let w_gc = m.w_gc.expect("a gain crossover");
            let ok = close(w_gc, wcp, TOL) && pm_difference(m.pm, pm) <= TOL * pm.abs().max(1.0);
            assert!(ok, "case {i}: PM {pm} at {wcp}, Degrau {m:?}");
        }

        // Every crossing python-control finds is one of Degrau's, with its margin, and
        // Degrau finds no other.
        let pc: Vec<(f64, f64)> = all_wcg.iter().copied().zip(all_gm).collect();
        let gc: Vec<(f64, f64)> = nums(&case["all_wcp"])
            .into_iter()
            .zip(nums(&case["all_pm"]))
            .collect();
        assert_eq!(pc.len(), m.phase_crossings.len(), "case {i}: {pc:?} {m:?}");
        assert_eq!(gc.len(), m.gain_crossings.len(), "case {i}: {gc:?} {m:?}");
        for (w, gm) in pc {
            let found = m
                .phase_crossings
                .iter()
                .any(|c| (c.w == w || close(c.w, w, TOL)) && close(c.gm, gm, TOL));
            assert!(
                found,
                "case {i}: phase crossover {w} (GM {gm}) missed: {m:?}"
            );
        }
        for (w, pm) in gc {
            let found = m
                .gain_crossings
                .iter()
                .any(|c| close(c.w, w, TOL) && pm_difference(c.pm, pm) <= TOL * pm.abs().max(1.0));
            assert!(
                found,
                "case {i}: gain crossover {w} (PM {pm}) missed: {m:?}"
            );
        }
    }
    // The loops whose gain margin is the one at ω = 0.
    assert!(zero_crossings >= 20, "{zero_crossings} at ω = 0");
}
