//! The Bode diagram: magnitude and phase against a direct evaluation of G(jω) on random
//! systems with dead times, the phase continuous, and the notes' asymptotes.

use crate::rng::Lcg;
use degrau_lti::bode::{asymptotes, bode, frequency_grid, log_grid};
use degrau_lti::{C64, TransferFunction};

/// Roots of order `n`: real ones and complex pairs, in either half plane (mostly left).
fn random_roots(rng: &mut Lcg, n: usize) -> Vec<C64> {
    let mut roots = Vec::new();
    while roots.len() < n {
        let re = rng.range(-10.0, 2.0);
        if n - roots.len() >= 2 && rng.next() < 0.5 {
            let im = rng.range(0.1, 10.0);
            roots.push(C64::new(re, im));
            roots.push(C64::new(re, -im));
        } else {
            roots.push(C64::new(re, 0.0));
        }
    }
    roots
}

fn random_system(rng: &mut Lcg) -> TransferFunction {
    let order = 1 + (rng.next() * 6.0) as usize;
    let poles = random_roots(rng, order);
    let zero_count = (rng.next() * (order + 1) as f64) as usize;
    let zeros = random_roots(rng, zero_count);
    let gain = rng.range(-5.0, 5.0);
    let delay = if rng.next() < 0.2 {
        0.0
    } else {
        rng.range(0.0, 5.0)
    };
    TransferFunction::from_zpk(&zeros, &poles, gain)
        .and_then(|g| g.with_delay(delay))
        .expect("valid random system")
}

fn tf(num: &[f64], den: &[f64]) -> TransferFunction {
    TransferFunction::from_coeffs(num, den).expect("valid system")
}

#[test]
fn magnitude_and_phase_equal_a_direct_evaluation() {
    let mut rng = Lcg(7);
    for case in 0..200 {
        let g = random_system(&mut rng);
        let w = frequency_grid(&g, 60);
        let b = bode(&g, &w);
        for (i, &w) in w.iter().enumerate() {
            let direct = g.eval(C64::new(0.0, w));
            let mag = 10f64.powf(b.mag_db[i] / 20.0);
            assert!(
                (mag - direct.norm()).abs() <= 1e-9 * direct.norm(),
                "case {case} ω {w}: {mag} vs {}",
                direct.norm()
            );
            let diff = (b.phase_deg[i] - direct.arg().to_degrees()).rem_euclid(360.0);
            let diff = diff.min(360.0 - diff);
            assert!(
                diff <= 1e-9 * b.phase_deg[i].abs().max(1.0),
                "case {case} ω {w}: {} vs {}",
                b.phase_deg[i],
                direct.arg().to_degrees()
            );
        }
    }
}

#[test]
fn the_phase_is_continuous_up_to_the_highest_frequency() {
    let mut rng = Lcg(11);
    for case in 0..200 {
        let g = random_system(&mut rng);
        let (lo, hi) = degrau_lti::bode::default_range(&g);
        // On a fine log grid, each step less the delay's exact turn −Δω·θ is small.
        let w = log_grid(lo, hi, 4000);
        let b = bode(&g, &w);
        for (i, pair) in b.phase_deg.windows(2).enumerate() {
            let delay_turn = -(w[i + 1] - w[i]) * g.delay() * 180.0 / std::f64::consts::PI;
            assert!(
                (pair[1] - pair[0] - delay_turn).abs() < 90.0,
                "case {case}: {pair:?}"
            );
        }
    }
}

#[test]
fn the_phase_starts_where_matlab_shows_it() {
    let w = [1e-6];
    assert!(bode(&tf(&[1.0], &[1.0, 1.0]), &w).phase_deg[0].abs() < 1e-3);
    let integrators = tf(&[1.0], &[1.0, 2.0, 0.0, 0.0]);
    assert!((bode(&integrators, &w).phase_deg[0] + 180.0).abs() < 1e-3);
    let unstable_pair = tf(&[1.0], &[1.0, -2.0, 5.0]);
    assert!(bode(&unstable_pair, &w).phase_deg[0].abs() < 1e-3);
}

#[test]
fn first_order_corner_at_one_over_tau() {
    let tau = 4.0;
    let g = tf(&[1.0], &[tau, 1.0]);
    let a = asymptotes(&g);
    assert_eq!(a.corners.len(), 1);
    assert!((a.corners[0].w - 1.0 / tau).abs() < 1e-15);
    assert_eq!(a.slopes(), vec![0.0, -20.0]);
    assert!(a.low_db_at_1.abs() < 1e-12);
    // At the corner the curve lies 10·log10(2) ≈ 3.01 dB below the lines; far away, on them.
    let b = bode(&g, &[0.25, 1e-5, 1e5]);
    let gap = a.value_db(0.25) - b.mag_db[0];
    assert!((gap - 10.0 * 2f64.log10()).abs() < 1e-9, "{gap}");
    assert!((a.value_db(1e-5) - b.mag_db[1]).abs() < 1e-6);
    assert!((a.value_db(1e5) - b.mag_db[2]).abs() < 1e-6);
}

#[test]
fn type_one_line_through_k_over_two_at_one() {
    let k = 8.0;
    let g = tf(&[k], &[1.0, 2.0, 0.0]);
    let a = asymptotes(&g);
    assert_eq!(a.system_type, 1);
    assert_eq!(a.slopes(), vec![-20.0, -40.0]);
    assert!((a.value_db(1.0) - 20.0 * (k / 2.0).log10()).abs() < 1e-12);
    assert!((a.value_db(0.1) - (20.0 * (k / 2.0).log10() + 20.0)).abs() < 1e-12);
}

#[test]
fn the_notes_third_order_system() {
    // 0.5/(s³ + 7s² + 15s + 25) = 0.5/((s + 5)(s² + 2s + 5)).
    let g = tf(&[0.5], &[1.0, 7.0, 15.0, 25.0]);
    let a = asymptotes(&g);
    assert_eq!(a.corners.len(), 2);
    assert!((a.corners[0].w - 5f64.sqrt()).abs() < 1e-9);
    assert_eq!(a.corners[0].slope_change_db_per_decade, -40.0);
    assert!((a.corners[1].w - 5.0).abs() < 1e-9);
    assert_eq!(a.corners[1].slope_change_db_per_decade, -20.0);
    assert_eq!(a.slopes(), vec![0.0, -40.0, -60.0]);
    assert!((a.low_db_at_1 - 20.0 * 0.02f64.log10()).abs() < 1e-9);
    let b = bode(&g, &[1e-4, 1e4]);
    assert!((a.value_db(1e-4) - b.mag_db[0]).abs() < 1e-6);
    assert!((a.value_db(1e4) - b.mag_db[1]).abs() < 1e-4);
}

#[test]
fn a_complex_pair_gives_one_corner_at_wn() {
    let wn = 3.0;
    let g = tf(&[wn * wn], &[1.0, 2.0 * 0.3 * wn, wn * wn]);
    let a = asymptotes(&g);
    assert_eq!(a.corners.len(), 1);
    assert!((a.corners[0].w - wn).abs() < 1e-12);
    assert_eq!(a.corners[0].slope_change_db_per_decade, -40.0);
    let with_zero =
        TransferFunction::from_zpk(&[C64::new(-1.0, 0.0)], g.poles(), 1.0).expect("valid system");
    assert_eq!(asymptotes(&with_zero).slopes(), vec![0.0, 20.0, -20.0]);
}

#[test]
fn the_grid_spans_two_decades_around_the_corners() {
    let g = tf(&[0.5], &[1.0, 7.0, 15.0, 25.0]);
    let w = frequency_grid(&g, 200);
    assert_eq!(w.len(), 200);
    assert!((w[0] - 0.01).abs() < 1e-15 && (w[199] - 1000.0).abs() < 1e-9);
    assert!(w.windows(2).all(|p| p[1] > p[0]));
}
