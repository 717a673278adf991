//! The stability margins against answers worked by hand: K/(s(s+1)(s+2)), a first-order
//! plant with a dead time (whose phase the delay lowers by exactly ω·θ), the delay margin
//! against the argument-principle count of closed-loop roots, a resonance with several gain
//! crossovers and a loop that never reaches −180°.

use degrau_lti::TransferFunction;
use degrau_lti::control::frequency::{closed_loop_unstable_roots, ultimate};
use degrau_lti::control::{Controller, margins};

fn close(a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{a} is not {b} (tolerance {tol})"
    );
}

fn foptd(tau: f64, theta: f64) -> TransferFunction {
    TransferFunction::from_coeffs(&[1.0], &[tau, 1.0])
        .unwrap()
        .with_delay(theta)
        .unwrap()
}

#[test]
fn third_order_with_integrator_has_gm_six_over_k() {
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 3.0, 2.0, 0.0]).unwrap();
    for k in [0.5, 1.0, 2.0, 4.0] {
        let m = margins(&g, &Controller::proportional(k).unwrap());
        close(m.w_pc.unwrap(), 2f64.sqrt(), 1e-12);
        close(m.gm, 6.0 / k, 1e-12);
        close(m.gm_db, 20.0 * (6.0 / k).log10(), 1e-11);
        // The gain crossover: ω·√(ω²+1)·√(ω²+4) = K, PM = 180° − 90° − atan ω − atan(ω/2).
        let w = m.w_gc.unwrap();
        close(w * (w * w + 1.0).sqrt() * (w * w + 4.0).sqrt(), k, 1e-12);
        let pm = 90.0 - w.atan().to_degrees() - (w / 2.0).atan().to_degrees();
        close(m.pm, pm, 1e-10);
        close(m.delay_margin, pm.to_radians() / w, 1e-10);
        assert_eq!(m.phase_crossings.len(), 1);
        assert_eq!(m.gain_crossings.len(), 1);
        assert_eq!(m.ms.is_some(), k < 6.0);
    }
}

#[test]
fn first_order_with_delay_matches_the_formula_and_the_ultimate_gain() {
    let (tau, k) = (2.0, 3.0);
    let wgc = (k * k - 1.0f64).sqrt() / tau;
    let without = margins(&foptd(tau, 0.0), &Controller::proportional(k).unwrap());
    close(without.pm, 180.0 - (wgc * tau).atan().to_degrees(), 1e-11);
    assert!(without.gm.is_infinite() && without.w_pc.is_none());
    for theta in [0.05, 0.3, 1.0, 2.5] {
        let g = foptd(tau, theta);
        let m = margins(&g, &Controller::proportional(k).unwrap());
        close(m.w_gc.unwrap(), wgc, 1e-12);
        let pm = 180.0 - (wgc * tau).atan().to_degrees() - (wgc * theta).to_degrees();
        close(m.pm, pm, 1e-10);
        // The delay lowers the phase by exactly ω_gc·θ: |L| does not change.
        close(without.pm - m.pm, (wgc * theta).to_degrees(), 1e-10);
        let u = ultimate(&g).unwrap();
        close(m.w_pc.unwrap(), u.wcr, 1e-10);
        close(m.gm, u.kcr / k, 1e-10);
    }
}

#[test]
fn the_delay_margin_puts_a_pole_on_the_axis() {
    let (tau, k, theta) = (2.0, 3.0, 0.3);
    let c = Controller::proportional(k).unwrap();
    let m = margins(&foptd(tau, theta), &c);
    let dm = m.delay_margin;
    assert!(dm > 0.0 && dm.is_finite());
    let below = foptd(tau, theta + dm * 0.99);
    let above = foptd(tau, theta + dm * 1.01);
    assert_eq!(closed_loop_unstable_roots(&below, &c), Ok(0));
    assert_eq!(closed_loop_unstable_roots(&above, &c), Ok(2));
    // And on the edge the phase margin is gone.
    let edge = margins(&foptd(tau, theta + dm), &c);
    assert!(edge.pm.abs() < 1e-8, "{}", edge.pm);
}

#[test]
fn a_resonance_with_two_gain_crossovers_picks_the_smallest_pm() {
    // L = K/(s² + 2ζs + 1): |L| = 1 where x = ω² solves x² − 2x(1 − 2ζ²) + 1 − K² = 0.
    let (zeta, k) = (0.05, 0.8);
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 2.0 * zeta, 1.0]).unwrap();
    let m = margins(&g, &Controller::proportional(k).unwrap());
    assert_eq!(m.gain_crossings.len(), 2);
    let b = 1.0 - 2.0 * zeta * zeta;
    let root = (b * b - 1.0 + k * k).sqrt();
    let expected = [(b - root).sqrt(), (b + root).sqrt()];
    for (c, w) in m.gain_crossings.iter().zip(expected) {
        close(c.w, w, 1e-12);
        let phase = -(2.0 * zeta * w).atan2(1.0 - w * w).to_degrees();
        close(c.pm, 180.0 + phase, 1e-10);
    }
    let smallest = m
        .gain_crossings
        .iter()
        .map(|c| c.pm.abs())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(m.pm.abs(), smallest);
    close(m.w_gc.unwrap(), expected[1], 1e-12);
    assert!(m.pm < 90.0);
    // A second-order loop never reaches −180°.
    assert!(m.gm.is_infinite() && m.gm_db.is_infinite() && m.w_pc.is_none());
}

#[test]
fn no_phase_crossover_gives_infinite_gm_and_no_gain_crossover_infinite_pm() {
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 0.0]).unwrap();
    let m = margins(&g, &Controller::proportional(2.0).unwrap());
    assert!(m.gm.is_infinite() && m.w_pc.is_none() && m.phase_crossings.is_empty());
    assert!(m.pm.is_finite() && m.pm > 0.0);
    let small = margins(&foptd(1.0, 0.0), &Controller::proportional(0.5).unwrap());
    assert!(small.pm.is_infinite() && small.w_gc.is_none());
    assert!(small.delay_margin.is_infinite());
    // T = 0.5/(s + 1.5): |T| falls 3 dB at ω = 1.5 (T(0) = 1/3).
    close(
        small.bandwidth.unwrap(),
        1.5 * (10f64.powf(0.3) - 1.0).sqrt(),
        1e-10,
    );
}

#[test]
fn bandwidth_of_a_first_order_closed_loop() {
    // L = 1/s: T = 1/(s + 1), bandwidth √(10^0.3 − 1).
    let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 0.0]).unwrap();
    let m = margins(&g, &Controller::proportional(1.0).unwrap());
    close(m.bandwidth.unwrap(), (10f64.powf(0.3) - 1.0).sqrt(), 1e-10);
    close(m.w_gc.unwrap(), 1.0, 1e-12);
    close(m.pm, 90.0, 1e-10);
}

#[test]
fn a_negative_static_loop_gain_is_a_phase_crossover_at_zero() {
    // L = −0.5/(s + 1): the closed loop s + 1 − 0.5·k has its root at s = 0 for k = 2, so
    // GM = 2 at ω = 0 (the phase never crosses −180° at ω > 0).
    let g = TransferFunction::from_coeffs(&[-0.5], &[1.0, 1.0]).unwrap();
    let m = margins(&g, &Controller::proportional(1.0).unwrap());
    assert_eq!(m.w_pc, Some(0.0));
    close(m.gm, 2.0, 1e-15);
    assert_eq!(m.phase_crossings.len(), 1);
    let count = |k: f64| closed_loop_unstable_roots(&g, &Controller::proportional(k).unwrap());
    assert_eq!(count(1.99), Ok(0));
    assert_eq!(count(2.01), Ok(1));
    // With an integrator L(0) is infinite: no crossing at 0.
    let g = TransferFunction::from_coeffs(&[-1.0], &[1.0, 1.0, 0.0]).unwrap();
    let m = margins(&g, &Controller::proportional(1.0).unwrap());
    assert!(m.phase_crossings.iter().all(|p| p.w > 0.0), "{m:?}");
}
