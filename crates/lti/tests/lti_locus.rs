//! The root locus: every point a root of den + K·num, continuous branches, breakaways where
//! dK/ds = 0, the asymptotes, and the jω crossings against the Routh array worked by hand.

use degrau_lti::locus::{Locus, Side, relative_residual};
use degrau_lti::{C64, TransferFunction};

fn tf(num: &[f64], den: &[f64]) -> TransferFunction {
    TransferFunction::from_coeffs(num, den).expect("valid system")
}

/// The notes' three poles with a zero at `z`: 0.5(s − z)/(s³ + 7s² + 15s + 25).
fn notes_with_zero(z: f64) -> TransferFunction {
    tf(&[0.5, -0.5 * z], &[1.0, 7.0, 15.0, 25.0])
}

/// Every point exact, and each branch moving little between consecutive points.
#[track_caller]
fn assert_exact_and_continuous(g: &TransferFunction, locus: &Locus) {
    let (num, den) = (g.num(), g.den());
    assert!(locus.points.len() > 50, "{} points", locus.points.len());
    for p in &locus.points {
        for &r in &p.roots {
            let res = relative_residual(&num, &den, p.k, r);
            assert!(res <= 1e-9, "K = {}: root {r} residual {res}", p.k);
        }
    }
    for w in locus.points.windows(2) {
        for (a, b) in w[0].roots.iter().zip(&w[1].roots) {
            let jump = (a - b).norm() / locus.scale.max(a.norm());
            assert!(jump <= 0.05, "K {} → {}: {a} → {b}", w[0].k, w[1].k);
        }
    }
}

#[test]
fn the_zero_at_minus_ten_has_a_critical_gain_and_the_routh_array_agrees() {
    // s³ + 7s² + (15 + K/2)s + (25 + 5K). Routh: row s¹ = (7(15 + K/2) − (25 + 5K))/7
    // = (80 − 1.5K)/7, zero at K = 160/3; the auxiliary row 7s² + 25 + 5K gives
    // ω² = (25 + 5K)/7 = 875/21.
    let g = notes_with_zero(-10.0);
    let locus = Locus::new(&g, Side::Positive).unwrap();
    let first = locus.crossings.first().expect("a crossing");
    assert!(
        (first.k - 160.0 / 3.0).abs() <= 1e-10 * first.k,
        "{}",
        first.k
    );
    let omega = (875.0f64 / 21.0).sqrt();
    assert!(
        (first.omega - omega).abs() <= 1e-10 * omega,
        "{}",
        first.omega
    );
    assert_exact_and_continuous(&g, &locus);
    // Below it stable, above it not.
    assert!(g.closed_loop(first.k * 0.99).unwrap().is_stable());
    assert!(!g.closed_loop(first.k * 1.01).unwrap().is_stable());
    // One asymptote pair at ±90° from (−7 + 10)/2.
    let a = locus.asymptotes.as_ref().unwrap();
    assert!((a.centroid - 1.5).abs() < 1e-12);
    assert_eq!(a.angles.len(), 2);
}

#[test]
fn the_zeros_at_minus_a_half_and_minus_three_never_cross() {
    for z in [-0.5, -3.0] {
        let g = notes_with_zero(z);
        let locus = Locus::new(&g, Side::Positive).unwrap();
        assert!(
            locus.crossings.is_empty(),
            "zero {z}: {:?}",
            locus.crossings
        );
        assert_exact_and_continuous(&g, &locus);
    }
}

#[test]
fn the_notes_three_poles_cross_where_routh_says() {
    // s³ + 7s² + 15s + 25 + K/2: row s¹ = (105 − 25 − K/2)/7 → K = 160, ω² = 15.
    let g = tf(&[0.5], &[1.0, 7.0, 15.0, 25.0]);
    let locus = Locus::new(&g, Side::Positive).unwrap();
    let c = locus.crossings[0];
    assert!((c.k - 160.0).abs() < 1e-9 * 160.0, "{}", c.k);
    assert!((c.omega - 15f64.sqrt()).abs() < 1e-10, "{}", c.omega);
    assert_exact_and_continuous(&g, &locus);
    let a = locus.asymptotes.as_ref().unwrap();
    assert!((a.centroid + 7.0 / 3.0).abs() < 1e-12);
    let degrees: Vec<f64> = a.angles.iter().map(|x| x.to_degrees()).collect();
    for (d, e) in degrees.iter().zip([60.0, 180.0, 300.0]) {
        assert!((d - e).abs() < 1e-9);
    }
}

#[test]
fn breakaway_points_are_where_dk_ds_vanishes() {
    // K/(s(s+2)): K = −s² − 2s, dK/ds = −2s − 2 = 0 at s = −1, K = 1 (roots leave the axis).
    let g = tf(&[1.0], &[1.0, 2.0, 0.0]);
    let locus = Locus::new(&g, Side::Positive).unwrap();
    assert_eq!(locus.breakaways.len(), 1);
    let b = locus.breakaways[0];
    assert!((b.s + 1.0).abs() < 1e-12 && (b.k - 1.0).abs() < 1e-12);
    assert!(b.leaves_axis);
    assert_exact_and_continuous(&g, &locus);
    // The locus passes through the breakaway exactly (a double root at K = 1).
    let at = locus
        .points
        .iter()
        .find(|p| p.k == b.k)
        .expect("the breakaway's K");
    assert!(
        at.roots
            .iter()
            .all(|r| (r - C64::new(-1.0, 0.0)).norm() < 1e-6)
    );
    // No crossing of the jω axis for K > 0 (the crossing at K = 0 is the open-loop pole).
    assert!(locus.crossings.is_empty());
}

#[test]
fn a_break_in_point_joins_the_axis() {
    // (s+3)/(s(s+1)): K = −s(s+1)/(s+3); dK/ds = 0 ⇔ s² + 6s + 3 = 0: s = −3 ± √6.
    let g = tf(&[1.0, 3.0], &[1.0, 1.0, 0.0]);
    let locus = Locus::new(&g, Side::Positive).unwrap();
    assert_eq!(locus.breakaways.len(), 2);
    let away = locus.breakaways[0];
    let back = locus.breakaways[1];
    assert!((away.s - (-3.0 + 6f64.sqrt())).abs() < 1e-12 && away.leaves_axis);
    assert!((back.s - (-3.0 - 6f64.sqrt())).abs() < 1e-12 && !back.leaves_axis);
    for b in [away, back] {
        let s = b.s;
        let dk = -((2.0 * s + 1.0) * (s + 3.0) - s * (s + 1.0)) / (s + 3.0).powi(2);
        assert!(dk.abs() < 1e-12, "dK/ds = {dk} at {s}");
    }
    assert_exact_and_continuous(&g, &locus);
    // One branch ends on the zero at −3.
    let last = locus.points.last().unwrap();
    assert!(
        last.roots
            .iter()
            .any(|r| (r - C64::new(-3.0, 0.0)).norm() < 1e-4)
    );
}

#[test]
fn the_complementary_locus_is_for_negative_gains() {
    let g = notes_with_zero(-10.0);
    let locus = Locus::new(&g, Side::Complementary).unwrap();
    assert!(locus.points.iter().all(|p| p.k <= 0.0));
    assert_exact_and_continuous(&g, &locus);
    // K < 0 crosses at ω = 0 where 25 + 5K = 0: K = −5.
    assert!(
        locus
            .crossings
            .iter()
            .any(|c| (c.k + 5.0).abs() < 1e-12 && c.omega == 0.0)
    );
    let a = locus.asymptotes.as_ref().unwrap();
    assert!((a.angles[0]).abs() < 1e-15);
}

#[test]
fn the_gain_near_a_point_of_a_branch() {
    let g = tf(&[1.0], &[1.0, 2.0, 0.0]);
    let locus = Locus::new(&g, Side::Positive).unwrap();
    // On K/(s(s+2)) the pole −1 + 2j has K = |s||s + 2| = 5.
    let (branch, s) = locus
        .points
        .iter()
        .flat_map(|p| p.roots.iter().enumerate())
        .min_by(|a, b| {
            (a.1 - C64::new(-1.0, 2.0))
                .norm()
                .total_cmp(&(b.1 - C64::new(-1.0, 2.0)).norm())
        })
        .map(|(b, r)| (b, *r))
        .unwrap();
    let _ = s;
    let (k, pole) = locus.gain_near(&g, branch, C64::new(-1.0, 2.0)).unwrap();
    assert!((k - 5.0).abs() < 1e-6, "{k}");
    assert!((pole - C64::new(-1.0, 2.0)).norm() < 1e-6);
    let refused = g.clone().with_delay(1.0).unwrap();
    assert!(Locus::new(&refused, Side::Positive).is_err());
}
