//! Known answers for the LTI core: closed forms from the course notes and from partial
//! fractions worked by hand, textbook second-order identities, and degenerate inputs.
//!
//! Every expected value here is computed independently of the library: from a hand-derived
//! closed form (evaluated with `exp_m1` where cancellation would otherwise bite), from a
//! root of that closed form found by bisection in this file, or from a dense grid of the
//! closed form with brute-force, linearly interpolated metrics.

use std::f64::consts::PI;

use degrau_lti::expr::{OscillationForm, expression};
use degrau_lti::response::Derivative;
use degrau_lti::tf::Stability;
use degrau_lti::{
    Behaviour, C64, LtiError, Polynomial, StepInfo, StepInfoOptions, StepResponse, TransferFunction,
};

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

fn c(re: f64, im: f64) -> C64 {
    C64::new(re, im)
}

fn zpk(zeros: &[C64], poles: &[C64], k: f64) -> TransferFunction {
    TransferFunction::from_zpk(zeros, poles, k).expect("valid zpk")
}

fn response(g: &TransferFunction, amplitude: f64) -> StepResponse {
    StepResponse::new(g, amplitude).expect("valid response")
}

fn info(r: &StepResponse) -> StepInfo {
    StepInfo::of_response(r, &StepInfoOptions::default())
}

/// |a − b| ≤ tol·|b| (relative), with a readable message.
#[track_caller]
fn assert_rel(what: &str, a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs(),
        "{what}: got {a:.17e}, expected {b:.17e} (rel. error {:.2e} > {tol:.0e})",
        ((a - b) / b).abs()
    );
}

/// |a − b| ≤ tol, with a readable message.
#[track_caller]
fn assert_abs(what: &str, a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol,
        "{what}: got {a:.17e}, expected {b:.17e} (error {:.2e} > {tol:.0e})",
        (a - b).abs()
    );
}

/// A root of f in [a, b] (f(a), f(b) of opposite signs) by bisection to the last bit.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let mut fa = f(a);
    assert!(
        fa * f(b) <= 0.0,
        "bisect: [{a}, {b}] does not bracket a root"
    );
    loop {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            return m;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
}

/// `stepinfo` by brute force on samples (t_i, y_i) of a settling response starting at rest,
/// crossings by linear interpolation between samples. The reference the metrics are
/// compared with; it knows nothing of the library's pieces or Newton refinement.
#[derive(Debug)]
struct GridInfo {
    rise_start: Option<f64>,
    rise_end: Option<f64>,
    settling_time: Option<f64>,
    /// Largest e = (y − 0)/Δ on the grid.
    max_e: f64,
    /// Smallest e on the grid.
    min_e: f64,
    /// Largest |y| on the grid and its time.
    peak: f64,
    peak_time: f64,
}

fn grid_info(t: &[f64], y: &[f64], y_final: f64) -> GridInfo {
    let e: Vec<f64> = y.iter().map(|v| v / y_final).collect();
    let first_crossing = |level: f64| {
        (1..t.len()).find_map(|i| {
            (e[i - 1] < level && e[i] >= level)
                .then(|| t[i - 1] + (level - e[i - 1]) / (e[i] - e[i - 1]) * (t[i] - t[i - 1]))
        })
    };
    let band = 0.02;
    let settling_time = e.iter().rposition(|v| (v - 1.0).abs() > band).map(|i| {
        assert!(i + 1 < t.len(), "grid too short to see the response settle");
        let edge = if e[i] > 1.0 { 1.0 + band } else { 1.0 - band };
        t[i] + (edge - e[i]) / (e[i + 1] - e[i]) * (t[i + 1] - t[i])
    });
    let argmax = |key: &dyn Fn(usize) -> f64| {
        (0..t.len()).fold(0, |best, i| if key(i) > key(best) { i } else { best })
    };
    let i_max = argmax(&|i| e[i]);
    let i_min = argmax(&|i| -e[i]);
    let i_peak = argmax(&|i| y[i].abs());
    GridInfo {
        rise_start: first_crossing(0.1),
        rise_end: first_crossing(0.9),
        settling_time,
        max_e: e[i_max],
        min_e: e[i_min],
        peak: y[i_peak].abs(),
        peak_time: t[i_peak],
    }
}

/// `n` evenly spaced instants on [0, end] and f at each.
fn grid(f: impl Fn(f64) -> f64, end: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
    let h = end / (n - 1) as f64;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * h).collect();
    let y = t.iter().map(|&t| f(t)).collect();
    (t, y)
}

// ---------------------------------------------------------------------------------------
// First order
// ---------------------------------------------------------------------------------------

#[test]
fn first_order_rise_and_settling_are_the_textbook_logs() {
    // 5/(s+5): y = 1 − e^{−5t}. 10 % at ln(10/9)/5, 90 % at ln(10)/5: rise = ln 9 / 5;
    // |y − 1| = 0.02 at ln 50 / 5.
    let rise = 9f64.ln() / 5.0;
    let settle = 50f64.ln() / 5.0;
    assert_rel("ln 9 / 5", rise, 0.439_444_915_467_243_9, 1e-15);
    for g in [
        zpk(&[], &[c(-5.0, 0.0)], 5.0),
        TransferFunction::from_coeffs(&[5.0], &[1.0, 5.0]).unwrap(),
        TransferFunction::from_coeffs(&[0.0, 10.0], &[0.0, 0.0, 2.0, 10.0]).unwrap(),
    ] {
        for amplitude in [1.0, -3.0, 0.01] {
            let i = info(&response(&g, amplitude));
            assert_rel("rise time", i.rise_time.unwrap(), rise, 1e-12);
            assert_rel(
                "rise start",
                i.rise_start.unwrap(),
                (10f64 / 9.0).ln() / 5.0,
                1e-12,
            );
            assert_rel("settling time", i.settling_time.unwrap(), settle, 1e-12);
            assert_eq!(i.overshoot, Some(0.0));
            assert_eq!(i.undershoot, Some(0.0));
            assert_eq!(
                i.peak_time, None,
                "no overshoot: the peak is only approached"
            );
            assert_rel("peak", i.peak.unwrap(), amplitude.abs(), 1e-15);
            assert_rel("steady state", i.steady_state.unwrap(), amplitude, 1e-15);
            assert_eq!(i.behaviour, Behaviour::Settles);
        }
    }
    // A dead time moves the settling time (counted from the step), not the rise time.
    let g = zpk(&[], &[c(-5.0, 0.0)], 5.0).with_delay(0.75).unwrap();
    let i = info(&response(&g, 1.0));
    assert_rel("rise time with delay", i.rise_time.unwrap(), rise, 1e-12);
    assert_rel(
        "settling with delay",
        i.settling_time.unwrap(),
        0.75 + settle,
        1e-12,
    );
}

// ---------------------------------------------------------------------------------------
// The notes' third-order example: G = 0.5/((s² + 2s + 5)(s + 5)), A = 2
// ---------------------------------------------------------------------------------------

fn notes_example() -> TransferFunction {
    zpk(&[], &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)], 0.5)
}

/// y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100.
fn notes_cos_sin(t: f64) -> f64 {
    1.0 / 25.0
        - 3.0 / 100.0 * (-t).exp() * ((2.0 * t).cos() + 4.0 / 3.0 * (2.0 * t).sin())
        - (-5.0 * t).exp() / 100.0
}

/// y(t) = 1/25 − (1/20)e^{−t} sin(2t + φ) − e^{−5t}/100, φ = atan(3/4) = 36.87°.
fn notes_amplitude_phase(t: f64) -> f64 {
    let phi = (3.0f64 / 4.0).atan();
    1.0 / 25.0 - (-t).exp() / 20.0 * (2.0 * t + phi).sin() - (-5.0 * t).exp() / 100.0
}

#[test]
fn notes_example_values_match_both_closed_forms() {
    let r = response(&notes_example(), 2.0);
    for g in [
        notes_example(),
        TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0]).unwrap(),
    ] {
        let r2 = response(&g, 2.0);
        for k in 0..=1000 {
            let t = k as f64 * 0.008;
            let a = notes_cos_sin(t);
            let b = notes_amplitude_phase(t);
            assert_abs("the two forms of the notes", a, b, 1e-16);
            assert_abs(&format!("y({t})"), r2.value(t), a, 2e-16);
        }
    }
    // y(0) = 0 and y → 1/25 = A·G(0) = 2·0.5/25.
    assert_abs("y(0)", r.value(0.0), 0.0, 1e-17);
    assert_rel("final value", r.final_value().unwrap(), 0.04, 1e-15);
    assert_abs("y(40)", r.value(40.0), 0.04, 1e-17);
    // The derivatives are those of the closed form: compare y' and y'' with central
    // differences of the notes' formula (truncation ~1e-11 and rounding ~1e-7 for h = 1e-5).
    for t in [0.3, 1.1, 2.7] {
        let h = 1e-5;
        let fd = (notes_cos_sin(t + h) - notes_cos_sin(t - h)) / (2.0 * h);
        assert_abs("y'", r.derivative(t), fd, 1e-10);
        let fd2 = (notes_cos_sin(t + h) - 2.0 * notes_cos_sin(t) + notes_cos_sin(t - h)) / (h * h);
        assert_abs("y''", r.eval(Derivative::Second, t), fd2, 1e-5);
    }
}

/// The notes' example in words, in either form of its oscillation.
const NOTES_TEXTS: [(OscillationForm, &str); 2] = [
    (
        OscillationForm::CosSin,
        "y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100",
    ),
    (
        OscillationForm::AmplitudePhase,
        "y(t) = 1/25 − (1/20)e^{−t} sin(2t + 36.87°) − e^{−5t}/100",
    ),
];

#[test]
fn notes_example_expression_text() {
    // From its poles, and built from the coefficients, whose roots carry rounding: the text
    // must not show it.
    let from_coeffs = TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0]).unwrap();
    for g in [notes_example(), from_coeffs] {
        let r = response(&g, 2.0);
        for (form, text) in NOTES_TEXTS {
            assert_eq!(expression(&r, form), text, "{form:?}");
        }
    }
    assert_eq!(
        format!("{:.2}", (3.0f64 / 4.0).atan().to_degrees()),
        "36.87"
    );
}

#[test]
fn notes_example_metrics_match_a_dense_reference() {
    let i = info(&response(&notes_example(), 2.0));
    // 1 000 001 samples of the notes' formula on [0, 10] s: h = 1e-5 s.
    let n = 1_000_001;
    let end = 10.0;
    let h = end / (n - 1) as f64;
    let (t, y) = grid(notes_cos_sin, end, n);
    let g = grid_info(&t, &y, 0.04);
    // Crossing times: the exact crossing and the interpolated one lie in the same cell.
    assert_abs(
        "rise start",
        i.rise_start.unwrap(),
        g.rise_start.unwrap(),
        h,
    );
    assert_abs("rise end", i.rise_end.unwrap(), g.rise_end.unwrap(), h);
    assert_abs(
        "rise time",
        i.rise_time.unwrap(),
        g.rise_end.unwrap() - g.rise_start.unwrap(),
        2.0 * h,
    );
    assert_abs(
        "settling time",
        i.settling_time.unwrap(),
        g.settling_time.unwrap(),
        h,
    );
    // Peak: the nearest sample is within h/2 of the true peak, where y' = 0, so it is lower
    // by at most max|y''|·(h/2)²/2 (|y''| ≤ 0.2 here): 1e-11 covers it with room.
    assert_abs("peak time", i.peak_time.unwrap(), g.peak_time, h);
    assert!(i.peak.unwrap() >= g.peak, "the grid found a higher peak");
    assert_abs("peak", i.peak.unwrap(), g.peak, 1e-11);
    assert_abs(
        "overshoot %",
        i.overshoot.unwrap(),
        100.0 * (g.max_e - 1.0),
        1e-11 / 0.04 * 100.0,
    );
    assert_eq!(i.undershoot, Some(0.0));
    assert!(g.min_e >= -1e-15);
    // And against the closed form directly: y' = 0 at the peak, with y'(t) ∝ e^{−t}·… found
    // by bisection on a central difference-free expression of y'.
    let dy = |t: f64| {
        // d/dt of the notes' cos–sin form.
        let e = (-t).exp();
        let (s, co) = (2.0 * t).sin_cos();
        0.03 * e * (co + 4.0 / 3.0 * s) - 0.03 * e * (-2.0 * s + 8.0 / 3.0 * co)
            + 0.05 * (-5.0 * t).exp()
    };
    let tp = bisect(dy, 1.0, 2.0);
    assert_rel("peak time vs y' = 0", i.peak_time.unwrap(), tp, 1e-12);
    assert_rel("peak value", i.peak.unwrap(), notes_cos_sin(tp), 1e-13);
    // The last exit of the band, through the edge the grid saw, by bisection on the formula.
    let tg = g.settling_time.unwrap();
    let edge = if notes_cos_sin(tg) > 0.04 { 1.02 } else { 0.98 };
    let ts = bisect(
        |t| notes_cos_sin(t) - 0.04 * edge,
        tg - 2.0 * h,
        tg + 2.0 * h,
    );
    assert_rel(
        "settling time (bisection)",
        i.settling_time.unwrap(),
        ts,
        1e-12,
    );
}

// ---------------------------------------------------------------------------------------
// Second order
// ---------------------------------------------------------------------------------------

#[test]
fn second_order_overshoot_and_peak_time_identities() {
    // ωn²/(s² + 2ζωn s + ωn²): OS = 100·exp(−ζπ/√(1−ζ²)), tp = π/ωd, peak = 1 + OS/100.
    // ζ stops at 0.9: beyond, the overshoot (7e-5 at 0.95, 3e-10 at 0.99) is too close to
    // the final value for any double-precision evaluation of y to give it to 1e-10 relative.
    for &zeta in &[0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.6, 0.707, 0.8, 0.9] {
        for &wn in &[0.1, 1.0, 3.0, 50.0] {
            let wd = wn * (1.0f64 - zeta * zeta).sqrt();
            let g = zpk(&[], &[c(-zeta * wn, wd), c(-zeta * wn, -wd)], wn * wn);
            let i = info(&response(&g, 1.0));
            let os = 100.0 * (-zeta * PI / (1.0f64 - zeta * zeta).sqrt()).exp();
            let case = format!("ζ = {zeta}, ωn = {wn}");
            assert_rel(
                &format!("overshoot, {case}"),
                i.overshoot.unwrap(),
                os,
                1e-10,
            );
            assert_rel(
                &format!("peak time, {case}"),
                i.peak_time.unwrap(),
                PI / wd,
                1e-10,
            );
            assert_rel(
                &format!("peak, {case}"),
                i.peak.unwrap(),
                1.0 + os / 100.0,
                1e-13,
            );
            // From the coefficients of s² + 2ζωn s + ωn² as well.
            let g = TransferFunction::from_coeffs(&[wn * wn], &[1.0, 2.0 * zeta * wn, wn * wn])
                .unwrap();
            let i = info(&response(&g, -2.0));
            assert_rel(
                &format!("overshoot (coeffs), {case}"),
                i.overshoot.unwrap(),
                os,
                1e-10,
            );
            assert_rel(
                &format!("peak time (coeffs), {case}"),
                i.peak_time.unwrap(),
                PI / wd,
                1e-10,
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Real poles that overshoot: 10(s+7)/((s+10)(s+20))
// ---------------------------------------------------------------------------------------

#[test]
fn real_poles_overshoot_with_a_slow_zero() {
    // Y = 10(s+7)/(s(s+10)(s+20)): residues 0.35 at 0, 0.3 at −10, −0.65 at −20.
    // y = 0.35 + 0.3e^{−10t} − 0.65e^{−20t}; y' = 0 ⇔ e^{−10t} = 3/13: tp = ln(13/3)/10,
    // y(tp) = 0.35 + 0.9/13 − 5.85/169 = 0.35 + 5.85/169, overshoot = 100·(5.85/169)/0.35 %.
    let y = |t: f64| 0.35 + 0.3 * (-10.0 * t).exp() - 0.65 * (-20.0 * t).exp();
    let g = zpk(&[c(-7.0, 0.0)], &[c(-10.0, 0.0), c(-20.0, 0.0)], 10.0);
    let r = response(&g, 1.0);
    for k in 0..=200 {
        let t = k as f64 * 0.005;
        assert_abs("y", r.value(t), y(t), 2e-16);
    }
    let i = info(&r);
    let tp = (13.0f64 / 3.0).ln() / 10.0;
    let os = 100.0 * (5.85 / 169.0) / 0.35;
    assert!(i.overshoot.unwrap() > 0.0, "real poles, yet it overshoots");
    assert_rel("peak time", i.peak_time.unwrap(), tp, 1e-12);
    assert_rel("overshoot", i.overshoot.unwrap(), os, 1e-12);
    assert_rel(
        "overshoot ≈ 9.89 %",
        i.overshoot.unwrap(),
        9.890_109_890_109_89,
        1e-12,
    );
    // Brute force on 200 001 samples (h = 5e-6 s).
    let n = 200_001;
    let h = 1.0 / (n - 1) as f64;
    let (t, yy) = grid(y, 1.0, n);
    let gi = grid_info(&t, &yy, 0.35);
    assert_abs("peak time (grid)", i.peak_time.unwrap(), gi.peak_time, h);
    // |y''| ≤ 0.65·400 = 260: the nearest sample is at most 260·(h/2)²/2 ≈ 1e-9 low.
    assert_abs(
        "overshoot (grid)",
        i.overshoot.unwrap(),
        100.0 * (gi.max_e - 1.0),
        1e-9 / 0.35 * 100.0,
    );
    assert_abs(
        "rise start (grid)",
        i.rise_start.unwrap(),
        gi.rise_start.unwrap(),
        h,
    );
    assert_abs(
        "rise end (grid)",
        i.rise_end.unwrap(),
        gi.rise_end.unwrap(),
        h,
    );
    assert_abs(
        "settling (grid)",
        i.settling_time.unwrap(),
        gi.settling_time.unwrap(),
        h,
    );
    // Settles from above: |y − 0.35| = 0.007 on the way down from the peak.
    let ts = bisect(|t| y(t) - 0.35 * 1.02, tp, 1.0);
    assert_rel("settling time", i.settling_time.unwrap(), ts, 1e-12);
    assert_eq!(i.settling_max, i.peak);
}

// ---------------------------------------------------------------------------------------
// Repeated and nearly repeated poles
// ---------------------------------------------------------------------------------------

#[test]
fn double_pole_is_exact_from_zpk_and_from_coefficients() {
    // (s+5)/(s+10)²: y = 1/20 − e^{−10t}/20 + (t/2)e^{−10t}.
    let y = |t: f64| 0.05 - (-10.0 * t).exp() / 20.0 + t / 2.0 * (-10.0 * t).exp();
    let from_zpk = zpk(&[c(-5.0, 0.0)], &[c(-10.0, 0.0), c(-10.0, 0.0)], 1.0);
    let from_coeffs = TransferFunction::from_coeffs(&[1.0, 5.0], &[1.0, 20.0, 100.0]).unwrap();
    // A double root perturbed by rounding, as a companion-matrix solver would return it:
    // (s + 10 − 1e-8)(s + 10 + 1e-8) = s² + 20s + 100 − 1e-16.
    let near_pair = zpk(
        &[c(-5.0, 0.0)],
        &[c(-10.0 + 1e-8, 0.0), c(-10.0 - 1e-8, 0.0)],
        1.0,
    );
    let cubic =
        TransferFunction::from_coeffs(&[1.0, 6.0, 5.0], &[1.0, 21.0, 120.0, 100.0]).unwrap();
    for (name, g) in [
        ("zpk", from_zpk),
        ("coeffs", from_coeffs),
        ("near pair", near_pair),
        ("(s+1)/(s+1) × it, coeffs", cubic),
    ] {
        let r = response(&g, 1.0);
        for k in 0..=400 {
            let t = k as f64 * 0.0025;
            assert_abs(&format!("{name}: y({t})"), r.value(t), y(t), 1e-9);
        }
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = 1/20 − e^{−10t}/20 + (1/2)t·e^{−10t}",
            "{name}"
        );
    }
}

#[test]
fn nearly_repeated_poles_match_the_exact_formula() {
    // 1/((s+1)(s+1+d)): y = 1/(1+d) − e^{−t}/d + e^{−(1+d)t}/(d(1+d))
    //                     = [1 − e^{−t} − e^{−t}·(1 − e^{−dt})/d]/(1+d),
    // where (1 − e^{−dt})/d = −expm1(−dt)/d is evaluated without cancellation.
    let p2 = -1.000001f64;
    let d = -p2 - 1.0; // exact: the double nearest −1.000001, minus −1
    let y = |t: f64| {
        let e = (-t).exp();
        (1.0 - e - e * (-(-d * t).exp_m1()) / d) / (1.0 + d)
    };
    // From zpk the poles are exactly 1e-6 (relative) apart and the closed form treats them
    // as one double pole at their mean: error O(d²t³e^{−t}) ≈ 1e-13. From coefficients the
    // roots carry an error of eps/d ≈ 2e-10 and come out just beyond the merging threshold,
    // so the two residues ±1/d cancel: error ≈ eps/d ≈ 1e-10, the documented worst case.
    for (name, g, tolerance) in [
        ("zpk", zpk(&[], &[c(-1.0, 0.0), c(p2, 0.0)], 1.0), 1e-12),
        (
            "coeffs",
            TransferFunction::from_coeffs(&[1.0], &[1.0, 2.0 + d, 1.0 + d]).unwrap(),
            1e-9,
        ),
    ] {
        let r = response(&g, 1.0);
        for k in 0..=300 {
            let t = k as f64 * 0.05;
            assert_abs(&format!("{name}: y({t})"), r.value(t), y(t), tolerance);
        }
        // d = 1e-6 apart: the metrics are those of 1/(s+1)² to ~1e-6.
        let i = info(&r);
        let ts = bisect(|t| y(t) - 0.98 / (1.0 + d), 3.0, 10.0);
        assert_rel(
            &format!("{name}: settling"),
            i.settling_time.unwrap(),
            ts,
            1e-9,
        );
    }
}

// ---------------------------------------------------------------------------------------
// Integrator, unstable, undamped: no metrics
// ---------------------------------------------------------------------------------------

#[test]
fn integrator_ramps_and_has_no_metrics() {
    // 2/(s(s+2)), A = 3: Y = 6/(s²(s+2)); y = 3t − 3/2 + (3/2)e^{−2t}.
    let y = |t: f64| 3.0 * t - 1.5 + 1.5 * (-2.0 * t).exp();
    for g in [
        zpk(&[], &[c(0.0, 0.0), c(-2.0, 0.0)], 2.0),
        TransferFunction::from_coeffs(&[2.0], &[1.0, 2.0, 0.0]).unwrap(),
    ] {
        assert_eq!(g.stability(), Stability::MarginallyStable);
        assert_eq!(g.system_type(), 1);
        let r = response(&g, 3.0);
        assert_eq!(r.behaviour(), Behaviour::Integrating);
        assert_eq!(r.final_value(), None);
        for k in 0..=100 {
            let t = k as f64 * 0.3;
            assert_abs("ramp", r.value(t), y(t), 1e-13 * y(t).abs().max(1.0));
        }
        let i = info(&r);
        assert_eq!(i, StepInfo::not_settling(0.0, Behaviour::Integrating));
    }
    // Double integrator 1/s²: y = t²/2.
    let r = response(&zpk(&[], &[c(0.0, 0.0), c(0.0, 0.0)], 1.0), 1.0);
    assert_eq!(r.behaviour(), Behaviour::Integrating);
    assert_abs("t²/2", r.value(3.0), 4.5, 1e-14);
}

#[test]
fn unstable_pole_grows_and_has_no_metrics() {
    // 2/((s−1)(s+2)): Y = 2/(s(s−1)(s+2)); residues −1 at 0, 2/3 at 1, 1/3 at −2.
    let y = |t: f64| -1.0 + 2.0 / 3.0 * t.exp() + (-2.0 * t).exp() / 3.0;
    for g in [
        zpk(&[], &[c(1.0, 0.0), c(-2.0, 0.0)], 2.0),
        TransferFunction::from_coeffs(&[2.0], &[1.0, 1.0, -2.0]).unwrap(),
    ] {
        assert_eq!(g.stability(), Stability::Unstable);
        let r = response(&g, 1.0);
        assert_eq!(r.behaviour(), Behaviour::Unstable);
        for k in 0..=100 {
            let t = k as f64 * 0.1;
            assert_abs("growth", r.value(t), y(t), 1e-13 * y(t).abs().max(1.0));
        }
        assert_eq!(info(&r), StepInfo::not_settling(0.0, Behaviour::Unstable));
    }
    // 1/(s − 1): y = e^t − 1 = expm1(t), relative accuracy even near t = 0.
    let r = response(&zpk(&[], &[c(1.0, 0.0)], 1.0), 1.0);
    for t in [1e-3, 0.5, 5.0, 20.0] {
        assert_rel("expm1", r.value(t), t.exp_m1(), 1e-12);
    }
    // Unstable complex pair 1/(s² − 2s + 5), poles 1 ± 2j.
    let r = response(
        &TransferFunction::from_coeffs(&[1.0], &[1.0, -2.0, 5.0]).unwrap(),
        1.0,
    );
    assert_eq!(r.behaviour(), Behaviour::Unstable);
    assert_eq!(info(&r).settling_time, None);
}

#[test]
fn undamped_poles_oscillate_or_grow_even_from_coefficients() {
    // 1/((s+1)(s²+1)) = 1/(s³+s²+s+1), the Routh-array classic with a row of zeros:
    // Y = 1/(s(s+1)(s²+1)); residues 1 at 0, −1/2 at −1, −(1−j)/4 at j:
    // y = 1 − e^{−t}/2 − (cos t + sin t)/2.
    let y = |t: f64| 1.0 - (-t).exp() / 2.0 - (t.cos() + t.sin()) / 2.0;
    for (name, g) in [
        (
            "zpk",
            zpk(&[], &[c(-1.0, 0.0), c(0.0, 1.0), c(0.0, -1.0)], 1.0),
        ),
        (
            "coeffs",
            TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 1.0, 1.0]).unwrap(),
        ),
    ] {
        assert_eq!(
            g.stability(),
            Stability::MarginallyStable,
            "{name}: {:?}",
            g.poles()
        );
        let r = response(&g, 1.0);
        assert_eq!(r.behaviour(), Behaviour::Oscillating, "{name}");
        for k in 0..=200 {
            let t = k as f64 * 0.1;
            assert_abs(&format!("{name}: y({t})"), r.value(t), y(t), 1e-13);
        }
        let i = info(&r);
        assert_eq!(i.behaviour, Behaviour::Oscillating);
        assert_eq!(
            (i.rise_time, i.settling_time, i.overshoot),
            (None, None, None)
        );
        assert_eq!(i.steady_state, None);
        // Peak of |y|: the maxima of y tend to sup y = 1 + √2/2 as e^{−t}/2 dies out, so the
        // reported peak is a local maximum (y' = e^{−t}/2 + (sin t − cos t)/2 = 0) within the
        // shown horizon whose value equals that supremum to 1e-10 (e^{−t}/2 < 1e-10 there).
        let dy = |t: f64| (-t).exp() / 2.0 + (t.sin() - t.cos()) / 2.0;
        let t_peak = i.peak_time.unwrap();
        assert!(
            t_peak <= r.auto_horizon(),
            "{name}: peak time outside the horizon"
        );
        let tp = bisect(dy, t_peak - 0.1, t_peak + 0.1);
        assert_abs(&format!("{name}: peak time is a maximum"), t_peak, tp, 1e-9);
        assert_abs(
            &format!("{name}: peak = y(tp)"),
            i.peak.unwrap(),
            y(tp),
            1e-13,
        );
        assert_abs(
            &format!("{name}: peak = sup y"),
            i.peak.unwrap(),
            1.0 + 0.5f64.sqrt(),
            1e-10,
        );
        // Constant first, then the slowest terms (the undamped pair), as the module docs say.
        let expected_text = "y(t) = 1 − (1/2)[cos t + sin t] − e^{−t}/2";
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            expected_text,
            "{name}"
        );
    }
    // (s² + 1)²: t·sin t grows without bound however the repeated roots come out.
    for g in [
        zpk(
            &[],
            &[c(0.0, 1.0), c(0.0, -1.0), c(0.0, 1.0), c(0.0, -1.0)],
            1.0,
        ),
        TransferFunction::from_coeffs(&[1.0], &[1.0, 0.0, 2.0, 0.0, 1.0]).unwrap(),
        TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 2.0, 2.0, 1.0, 1.0]).unwrap(),
    ] {
        let r = response(&g, 1.0);
        assert_eq!(r.behaviour(), Behaviour::Unstable, "poles {:?}", g.poles());
        assert_eq!(info(&r), StepInfo::not_settling(0.0, Behaviour::Unstable));
    }
    // s² + 4 exactly: 4/(s²+4) gives y = 1 − cos 2t, peak 2 at π/2.
    let r = response(
        &TransferFunction::from_coeffs(&[4.0], &[1.0, 0.0, 4.0]).unwrap(),
        1.0,
    );
    assert_eq!(r.behaviour(), Behaviour::Oscillating);
    let i = info(&r);
    assert_abs("peak", i.peak.unwrap(), 2.0, 1e-13);
    assert_abs("peak time", i.peak_time.unwrap(), PI / 2.0, 1e-9);
}

// ---------------------------------------------------------------------------------------
// Biproper systems (direct feedthrough)
// ---------------------------------------------------------------------------------------

#[test]
fn biproper_systems_jump_at_the_step() {
    // 3(s+2)/(s+1), A = 2: Y = 6(s+2)/(s(s+1)); y = 12 − 6e^{−t}, y(0⁺) = 6 = A·D.
    let g = zpk(&[c(-2.0, 0.0)], &[c(-1.0, 0.0)], 3.0);
    assert_eq!(g.relative_degree(), 0);
    let r = response(&g, 2.0);
    for k in 0..=100 {
        let t = k as f64 * 0.1;
        assert_abs("y", r.value(t), 12.0 - 6.0 * (-t).exp(), 1e-14);
    }
    assert_eq!(r.value(-1e-9), 0.0, "nothing before the step");
    let i = info(&r);
    // 10 % (1.2) is passed inside the jump; 90 % (10.8) when e^{−t} = 0.2.
    assert_eq!(i.rise_start, Some(0.0));
    assert_rel("rise", i.rise_time.unwrap(), 5f64.ln(), 1e-13);
    assert_rel(
        "settling",
        i.settling_time.unwrap(),
        (6.0f64 / 0.24).ln(),
        1e-13,
    );

    // (s−1)/(s+1), all-pass: y = −1 + 2e^{−t}: jumps to +1 then goes to −1.
    // Δ = −1: 10 % at y = −0.1 (t = ln(2/0.9)), 90 % at −0.9 (t = ln 20): rise = ln 9;
    // |y + 1| = 0.02 at t = ln 100; undershoot (excursion opposite to Δ) 100 % at t = 0.
    let g = TransferFunction::from_coeffs(&[1.0, -1.0], &[1.0, 1.0]).unwrap();
    let r = response(&g, 1.0);
    assert_abs("y(0+)", r.value(0.0), 1.0, 1e-15);
    let i = info(&r);
    assert_rel(
        "all-pass rise start",
        i.rise_start.unwrap(),
        (2.0f64 / 0.9).ln(),
        1e-13,
    );
    assert_rel("all-pass rise", i.rise_time.unwrap(), 9f64.ln(), 1e-13);
    assert_rel(
        "all-pass settling",
        i.settling_time.unwrap(),
        100f64.ln(),
        1e-13,
    );
    assert_rel("all-pass undershoot", i.undershoot.unwrap(), 100.0, 1e-13);
    assert_eq!(i.undershoot_time, Some(0.0));
    assert_eq!(i.overshoot, Some(0.0));
    assert_eq!(i.steady_state, Some(-1.0));

    // Biproper with a complex pair: (s² + 2s + 10)/(s² + 2s + 5) = 1 + 5/(s² + 2s + 5):
    // y = 1 + 1 − e^{−t}(cos 2t + sin(2t)/2) = 2 − e^{−t}(cos 2t + ½ sin 2t).
    let g = TransferFunction::from_coeffs(&[1.0, 2.0, 10.0], &[1.0, 2.0, 5.0]).unwrap();
    let r = response(&g, 1.0);
    for k in 0..=100 {
        let t = k as f64 * 0.07;
        let exact = 2.0 - (-t).exp() * ((2.0 * t).cos() + 0.5 * (2.0 * t).sin());
        assert_abs("biproper pair", r.value(t), exact, 1e-14);
    }
}

// ---------------------------------------------------------------------------------------
// Widely separated poles, near cancellation
// ---------------------------------------------------------------------------------------

#[test]
fn very_fast_next_to_very_slow_poles() {
    // 10/((s+0.01)(s+1000)): G(0) = 1; residues of Y: 1 at 0, −1000/999.99 at −0.01,
    // 0.01/999.99 at −1000. After a few ms the fast term is gone (e^{−1000t}), so with
    // a = 1000/999.99: rise = 100 ln 9 and settling = 100 ln(50a) exactly.
    let (p, q) = (0.01f64, 1000.0f64);
    let a = q / (q - p);
    let y = |t: f64| 1.0 - a * (-p * t).exp() + p / (q - p) * (-q * t).exp();
    let g = zpk(&[], &[c(-p, 0.0), c(-q, 0.0)], 10.0);
    let r = response(&g, 1.0);
    for t in [
        0.0, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 1.0, 10.0, 100.0, 1000.0, 5000.0,
    ] {
        assert_abs(&format!("y({t})"), r.value(t), y(t), 2e-16);
    }
    let i = info(&r);
    assert_rel("rise", i.rise_time.unwrap(), 100.0 * 9f64.ln(), 1e-12);
    assert_rel(
        "settling",
        i.settling_time.unwrap(),
        100.0 * (50.0 * a).ln(),
        1e-12,
    );
    assert_eq!(i.overshoot, Some(0.0));
    // From the coefficients s² + 1000.01s + 10: the small root by the stable quadratic form.
    let g = TransferFunction::from_coeffs(&[10.0], &[1.0, 1000.01, 10.0]).unwrap();
    let i2 = info(&response(&g, 1.0));
    assert_rel(
        "rise (coeffs)",
        i2.rise_time.unwrap(),
        100.0 * 9f64.ln(),
        1e-12,
    );
}

#[test]
fn pole_zero_near_cancellation() {
    // (s+z)/((s+1)(s+2)), z = 1.001: residues z/2 at 0, −(z−1) at −1, (z−2)/2 at −2:
    // y = z/2 − (z−1)e^{−t} + ((z−2)/2)e^{−2t}. The slow mode's weight is only 0.001.
    let z = 1.001f64;
    let y = |t: f64| z / 2.0 - (z - 1.0) * (-t).exp() + (z - 2.0) / 2.0 * (-2.0 * t).exp();
    for g in [
        zpk(&[c(-z, 0.0)], &[c(-1.0, 0.0), c(-2.0, 0.0)], 1.0),
        TransferFunction::from_coeffs(&[1.0, z], &[1.0, 3.0, 2.0]).unwrap(),
    ] {
        let r = response(&g, 1.0);
        for k in 0..=200 {
            let t = k as f64 * 0.05;
            assert_abs("y", r.value(t), y(t), 1e-15);
        }
        let i = info(&r);
        let yf = z / 2.0;
        let lo = bisect(|t| y(t) - 0.1 * yf, 0.0, 5.0);
        let hi = bisect(|t| y(t) - 0.9 * yf, 0.0, 5.0);
        let ts = bisect(|t| y(t) - 0.98 * yf, 0.0, 10.0);
        assert_rel("rise", i.rise_time.unwrap(), hi - lo, 1e-12);
        assert_rel("settling", i.settling_time.unwrap(), ts, 1e-12);
        assert_eq!(i.overshoot, Some(0.0));
        // The terms are all kept in the text, the slow one with its small weight.
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = 0.5005 − e^{−t}/1000 − 0.4995 e^{−2t}"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Closed loop
// ---------------------------------------------------------------------------------------

#[test]
fn closed_loop_of_the_notes_example() {
    let g = TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0]).unwrap();
    let cl = g.closed_loop(1.0).unwrap();
    let den = cl.den();
    assert_eq!(den.len(), 4);
    for (a, b) in den.iter().zip([1.0, 7.0, 15.0, 25.5]) {
        assert_abs("closed-loop denominator", *a, b, 1e-12);
    }
    for (a, b) in cl.num().iter().zip([0.5]) {
        assert_abs("closed-loop numerator", *a, b, 1e-15);
    }
    // G_cl(0) = 0.5/25.5 and G_cl(s)·(1 + G(s)) = G(s) at any s.
    assert_rel("closed-loop DC gain", cl.dc_gain(), 0.5 / 25.5, 1e-13);
    let s = c(0.3, 1.7);
    let lhs = cl.eval(s) * (C64::new(1.0, 0.0) + g.eval(s));
    assert!((lhs - g.eval(s)).norm() <= 1e-13 * g.eval(s).norm());
    // Kp scales the loop: Kp = 4 gives s³ + 7s² + 15s + 27.
    for (a, b) in g
        .closed_loop(4.0)
        .unwrap()
        .den()
        .iter()
        .zip([1.0, 7.0, 15.0, 27.0])
    {
        assert_abs("Kp = 4", *a, b, 1e-12);
    }
}

// ---------------------------------------------------------------------------------------
// Degenerate inputs: clear errors or documented values, never a panic
// ---------------------------------------------------------------------------------------

/// An error's text is a plain sentence: no Rust debug syntax leaking through.
#[track_caller]
fn assert_plain_words(e: &LtiError) {
    let text = e.to_string();
    assert!(!text.is_empty());
    for leak in [
        "{", "}", "Some(", "None", "Complex", "re:", "im:", "::", "Err(", "Ok(",
    ] {
        assert!(
            !text.contains(leak),
            "error text {text:?} contains {leak:?}"
        );
    }
    assert!(
        text.chars().next().unwrap().is_lowercase() || text.starts_with(char::is_numeric),
        "{text:?}"
    );
}

#[test]
fn degenerate_inputs_give_clear_errors() {
    let cases: Vec<(&str, Result<TransferFunction, LtiError>)> = vec![
        ("no poles (zpk)", TransferFunction::from_zpk(&[], &[], 1.0)),
        (
            "no poles (coeffs)",
            TransferFunction::from_coeffs(&[1.0], &[2.0]),
        ),
        (
            "no poles after dropping zeros",
            TransferFunction::from_coeffs(&[1.0], &[0.0, 0.0, 2.0]),
        ),
        (
            "empty denominator",
            TransferFunction::from_coeffs(&[1.0], &[]),
        ),
        (
            "empty numerator",
            TransferFunction::from_coeffs(&[], &[1.0, 1.0]),
        ),
        (
            "zero numerator",
            TransferFunction::from_coeffs(&[0.0, 0.0], &[1.0, 1.0]),
        ),
        (
            "zero denominator",
            TransferFunction::from_coeffs(&[1.0], &[0.0, 0.0]),
        ),
        (
            "NaN numerator",
            TransferFunction::from_coeffs(&[f64::NAN], &[1.0, 1.0]),
        ),
        (
            "inf denominator",
            TransferFunction::from_coeffs(&[1.0], &[1.0, f64::INFINITY]),
        ),
        (
            "−inf leading",
            TransferFunction::from_coeffs(&[1.0], &[f64::NEG_INFINITY, 1.0]),
        ),
        (
            "improper",
            TransferFunction::from_coeffs(&[1.0, 0.0, 0.0], &[1.0, 1.0]),
        ),
        (
            "improper zpk",
            TransferFunction::from_zpk(&[c(-1.0, 0.0), c(-2.0, 0.0)], &[c(-1.0, 0.0)], 1.0),
        ),
        (
            "NaN pole",
            TransferFunction::from_zpk(&[], &[c(f64::NAN, 0.0)], 1.0),
        ),
        (
            "inf zero",
            TransferFunction::from_zpk(
                &[c(0.0, f64::INFINITY), c(0.0, f64::NEG_INFINITY)],
                &[c(-1.0, 0.0)],
                1.0,
            ),
        ),
        (
            "unpaired pole",
            TransferFunction::from_zpk(&[], &[c(-1.0, 2.0)], 1.0),
        ),
        (
            "zero gain",
            TransferFunction::from_zpk(&[], &[c(-1.0, 0.0)], 0.0),
        ),
        (
            "NaN gain",
            TransferFunction::from_zpk(&[], &[c(-1.0, 0.0)], f64::NAN),
        ),
        (
            "order 31",
            TransferFunction::from_zpk(&[], &[c(-1.0, 0.0); 31], 1.0),
        ),
        (
            "negative delay",
            zpk(&[], &[c(-1.0, 0.0)], 1.0).with_delay(-0.1),
        ),
        (
            "NaN delay",
            zpk(&[], &[c(-1.0, 0.0)], 1.0).with_delay(f64::NAN),
        ),
        (
            "closed loop with delay",
            zpk(&[], &[c(-1.0, 0.0)], 1.0)
                .with_delay(0.1)
                .and_then(|g| g.closed_loop(1.0)),
        ),
        (
            "NaN loop gain",
            zpk(&[], &[c(-1.0, 0.0)], 1.0).closed_loop(f64::NAN),
        ),
        (
            "DC gain of an integrator",
            zpk(&[], &[c(0.0, 0.0)], 1.0).with_dc_gain(2.0),
        ),
    ];
    for (name, result) in cases {
        match result {
            Ok(g) => panic!("{name}: accepted as {g:?}"),
            Err(e) => assert_plain_words(&e),
        }
    }
    // The specific errors for the common mistakes.
    assert!(matches!(
        TransferFunction::from_coeffs(&[1.0, 0.0, 0.0], &[1.0, 1.0]),
        Err(LtiError::Improper {
            num_degree: 2,
            den_degree: 1
        })
    ));
    assert!(matches!(
        TransferFunction::from_coeffs(&[1.0], &[1.0, f64::NAN]),
        Err(LtiError::NonFiniteCoefficient {
            what: Polynomial::Denominator,
            ..
        })
    ));
    assert_eq!(
        TransferFunction::from_zpk(&[], &[], 1.0),
        Err(LtiError::NoPoles)
    );
    // Bad amplitudes.
    let g = zpk(&[], &[c(-1.0, 0.0)], 1.0);
    for a in [0.0, f64::NAN, f64::INFINITY] {
        let e = StepResponse::new(&g, a).unwrap_err();
        assert!(matches!(e, LtiError::BadAmplitude(_)));
        assert_plain_words(&e);
    }
}

#[test]
fn leading_zero_coefficients_are_dropped_as_matlab_does() {
    let a = TransferFunction::from_coeffs(&[0.0, 0.0, 0.5], &[0.0, 1.0, 7.0, 15.0, 25.0]).unwrap();
    let b = TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0]).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.order(), 3);
    // −0.0 is a zero too.
    let c0 = TransferFunction::from_coeffs(&[-0.0, 0.5], &[-0.0, 1.0, 7.0, 15.0, 25.0]).unwrap();
    assert_eq!(c0, b);
}

#[test]
fn zero_over_zero_dc_gain_is_one() {
    // s/s: the zero and the pole at the origin cancel exactly: G(0) = 1 (documented), the
    // system is a pure gain of 1 and its step response is the step itself.
    let g = TransferFunction::from_coeffs(&[1.0, 0.0], &[1.0, 0.0]).unwrap();
    assert_eq!(g.dc_gain(), 1.0);
    assert_eq!(g.system_type(), 0);
    assert_eq!(g.stability(), Stability::Stable);
    let r = response(&g, 2.5);
    assert_eq!(r.behaviour(), Behaviour::Settles);
    assert_eq!(r.final_value(), Some(2.5));
    for t in [0.0, 0.1, 1.0, 100.0] {
        assert_abs("y = A", r.value(t), 2.5, 1e-15);
    }
    let i = info(&r);
    assert_eq!(i.rise_time, Some(0.0));
    assert_eq!(i.settling_time, Some(0.0));
    assert_eq!(i.overshoot, Some(0.0));
    assert_eq!(expression(&r, OscillationForm::CosSin), "y(t) = 5/2");
    // 3s(s+1)/(s(s+2)): G(0) = 3·1/2 after the exact cancellation at the origin.
    let g = TransferFunction::from_coeffs(&[3.0, 3.0, 0.0], &[1.0, 2.0, 0.0]).unwrap();
    assert_rel("DC gain", g.dc_gain(), 1.5, 1e-15);
    let r = response(&g, 1.0);
    for t in [0.0, 0.5, 3.0] {
        // 3(s+1)/(s+2): y = 1.5 + 1.5e^{−2t}.
        assert_abs("y", r.value(t), 1.5 + 1.5 * (-2.0 * t).exp(), 1e-14);
    }
}

#[test]
fn extreme_coefficients_give_an_answer_or_an_error() {
    // Coefficient ratios beyond 1e154 used to overflow the balancing of the companion
    // matrix into an endless loop (this test never finished); now they give roots, or a
    // non-finite-root error when a root itself is beyond the range of f64.
    for den in [
        vec![1.0, 1e200, 1.0, 1.0],
        vec![1e-200, 1.0, 1.0, 1.0],
        vec![1.0, 1.0, 1.0, 1e300],
        vec![f64::MAX, 1.0, f64::MIN_POSITIVE, 1.0],
        vec![1.0, -f64::MAX, f64::MAX, -f64::MAX, 1.0],
        vec![5e-324, 1.0, 1.0, 1.0, 1.0],
    ] {
        if let Ok(g) = TransferFunction::from_coeffs(&[1.0], &den)
            && let Ok(r) = StepResponse::new(&g, 1.0)
        {
            let _ = info(&r);
            let _ = expression(&r, OscillationForm::AmplitudePhase);
        }
    }
    // A scaled polynomial has the scaled roots: 1e100³·(x³ + 7x² + 15x + 25) in s = 1e100·x
    // is s³ + 7e100 s² + 15e200 s + 25e300.
    let r = degrau_lti::poly::roots(&[1.0, 7e100, 15e200, 25e300]).unwrap();
    let expected = [c(-1e100, 2e100), c(-1e100, -2e100), c(-5e100, 0.0)];
    for (a, b) in r.iter().zip(expected) {
        assert!((a - b).norm() <= 1e-12 * b.norm(), "{a} vs {b}");
    }
}

#[test]
fn repeated_roots_typed_as_coefficients_are_exact() {
    // 1/(s+1)ⁿ typed as the binomial coefficients: y = 1 − e^{−t}·Σ_{k<n} t^k/k!.
    // An eigenvalue solver splits an n-fold root into n roots ~eps^{1/n} apart; kept apart
    // they made the partial fractions cancel (error 2e-3 in y for n = 5, 6e-3 for n = 8).
    for n in 2..=8usize {
        let mut den = vec![1.0f64];
        for _ in 0..n {
            den = (0..=den.len())
                .map(|i| den.get(i).unwrap_or(&0.0) + if i > 0 { den[i - 1] } else { 0.0 })
                .collect();
        }
        let g = TransferFunction::from_coeffs(&[1.0], &den).unwrap();
        assert!(
            g.poles().iter().all(|&p| p == g.poles()[0]),
            "n = {n}: {:?}",
            g.poles()
        );
        assert_abs(&format!("n = {n}: pole"), g.poles()[0].re, -1.0, 1e-14);
        let r = response(&g, 1.0);
        for k in 0..=300 {
            let t = k as f64 * 0.1;
            let (mut sum, mut term) = (0.0, 1.0);
            for j in 0..n {
                if j > 0 {
                    term *= t / j as f64;
                }
                sum += term;
            }
            let exact = 1.0 - (-t).exp() * sum;
            assert_abs(&format!("n = {n}: y({t})"), r.value(t), exact, 1e-12);
        }
    }
    // (s+2)³(s²+2s+5)², a repeated pair next to a repeated real root, and the notes' text.
    let g = zpk(
        &[],
        &[
            c(-2.0, 0.0),
            c(-2.0, 0.0),
            c(-2.0, 0.0),
            c(-1.0, 2.0),
            c(-1.0, -2.0),
            c(-1.0, 2.0),
            c(-1.0, -2.0),
        ],
        200.0,
    );
    let typed = TransferFunction::from_coeffs(&g.num(), &g.den()).unwrap();
    let (r1, r2) = (response(&g, 1.0), response(&typed, 1.0));
    for k in 0..=200 {
        let t = k as f64 * 0.05;
        assert_abs("repeated pair, typed", r2.value(t), r1.value(t), 1e-12);
    }
    assert_eq!(
        expression(&r2, OscillationForm::CosSin),
        expression(&r1, OscillationForm::CosSin)
    );
    // Distinct roots close together are not merged: (s+1)(s+1.001)(s+3).
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 5.001, 7.004, 3.003]).unwrap();
    let poles = g.poles();
    assert_abs("−1", poles[0].re, -1.0, 1e-12);
    assert_abs("−1.001", poles[1].re, -1.001, 1e-12);
    assert_abs("−3", poles[2].re, -3.0, 1e-12);
}

// ---------------------------------------------------------------------------------------
// Found by the property tests (lti_properties.rs), with closed forms
// ---------------------------------------------------------------------------------------

#[test]
fn early_undershoot_of_a_relative_degree_three_system() {
    // (20 − s)/(20(s+1)³): y = 1 − e^{−t}(1 + t + t²/2) − t²e^{−t}/40,
    // y' = t·e^{−t}(21t − 2)/40: y dips below 0 until t = 2/21, then rises to 1. y'(0) is 0
    // exactly, computed as rounding noise whose sign decided whether the dip was seen.
    let y = |t: f64| 1.0 - (-t).exp() * (1.0 + t + t * t / 2.0) - t * t * (-t).exp() / 40.0;
    for a in [1.0, -2.0] {
        let g = zpk(&[c(20.0, 0.0)], &[c(-1.0, 0.0); 3], -1.0 / 20.0);
        let r = response(&g, a);
        let i = info(&r);
        assert_rel(
            "undershoot time",
            i.undershoot_time.unwrap(),
            2.0 / 21.0,
            1e-12,
        );
        assert_rel(
            "undershoot",
            i.undershoot.unwrap(),
            -100.0 * y(2.0 / 21.0),
            1e-9,
        );
        let ts = bisect(|t| y(t) - 0.98, 3.0, 10.0);
        assert_rel("settling", i.settling_time.unwrap(), ts, 1e-12);
    }
}

#[test]
fn settling_max_counts_the_jump_when_the_rise_ends_inside_it() {
    // (2s + 1)/(s + 1): y = 1 + e^{−t}, y(0⁺) = 2: the rise (10 % and 90 %) is complete
    // inside the jump, and the largest y after it is y(0⁺) = 2 (it used to read 1).
    let g = TransferFunction::from_coeffs(&[2.0, 1.0], &[1.0, 1.0]).unwrap();
    let i = info(&response(&g, 1.0));
    assert_eq!(
        (i.rise_start, i.rise_end, i.rise_time),
        (Some(0.0), Some(0.0), Some(0.0))
    );
    assert_abs("settling max", i.settling_max.unwrap(), 2.0, 1e-15);
    assert_abs("settling min", i.settling_min.unwrap(), 0.9, 1e-15);
    assert_abs("overshoot", i.overshoot.unwrap(), 100.0, 1e-12);
    assert_eq!(i.peak_time, Some(0.0));
    assert_rel("settling", i.settling_time.unwrap(), 50f64.ln(), 1e-13);
}

#[test]
fn double_real_root_left_in_a_schur_block() {
    // (s + p)²(s² + 13.59s + 66.33) with p = 1.3848: the Schur iteration can leave the
    // double real root as one 2×2 block, whose eigenvalues nalgebra returns with NaN
    // imaginary parts (4 roots then came out as 6, and from_coeffs failed).
    let p = 1.384799736258139;
    let pair = [
        c(-6.793174953745909, 4.492676323537867),
        c(-6.793174953745909, -4.492676323537867),
    ];
    let g = zpk(
        &[c(0.87923567544087, 0.0)],
        &[pair[0], pair[1], c(-p, 0.0), c(-p, 0.0)],
        0.1787,
    );
    let typed = TransferFunction::from_coeffs(&g.num(), &g.den()).unwrap();
    assert_eq!(typed.order(), 4);
    let poles = typed.poles();
    assert_eq!(poles[0], poles[1], "{poles:?}");
    assert_abs("double root", poles[0].re, -p, 1e-13);
    assert_abs("pair", poles[2].re, pair[0].re, 1e-12);
    let (r1, r2) = (response(&g, 1.0), response(&typed, 1.0));
    for k in 0..=100 {
        let t = k as f64 * 0.05;
        assert_abs("y", r2.value(t), r1.value(t), 1e-13);
    }
}

/// Poles sixteen decades apart (s² + 1e8·s + 1: −1e−8 and −1e8): the slow pole alone sets the
/// metrics, rise ln 9·1e8 s and 2 % settling ln 50·1e8 s. Merging the step's pole with the
/// slow one (a tolerance relative to the fast pole did) made the response never rise.
/// Beyond what f64 can carry (1e200 apart) the response is refused, never shown wrong.
#[test]
fn poles_many_decades_apart() {
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 1e8, 1.0]).unwrap();
    let r = response(&g, 1.0);
    let i = info(&r);
    assert_rel("rise", i.rise_time.unwrap(), 9f64.ln() * 1e8, 1e-9);
    assert_rel("settling", i.settling_time.unwrap(), 50f64.ln() * 1e8, 1e-9);
    assert_rel(
        "y(1e8)",
        r.eval(Derivative::Value, 1e8),
        1.0 - (-1.0f64).exp(),
        1e-12,
    );
    let extreme = TransferFunction::from_coeffs(&[1.0], &[1.0, 1e200, 1.0]).unwrap();
    assert_eq!(
        StepResponse::new(&extreme, 1.0).err(),
        Some(LtiError::OutOfRange)
    );
}
