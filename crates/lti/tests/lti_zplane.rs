//! The sampled model on the z-plane: on 120 random continuous systems (orders 1 to 4, real
//! and complex poles, stable and unstable, integrators, with no dead time, a whole number of
//! samples or a fractional one θ = d·h + L, at h = 0.01, 0.1 and 0.5 s), the poles of
//! c2d(G, h) are e^{p·h} of G's poles, A(z)'s coefficients hold them, and the stairs of
//! H(z) equal the continuous step response at t = k·h (the zero-order hold is exact at the
//! samples) within 1e-12 of the response's scale over the window.
//!
//! The generator keeps 0.1 ≤ |p|·h ≤ 2.5 for the stable poles and, for the one unstable pole
//! or pair, Re p·50h ≤ 5 (growth e⁵ over the 50 samples). Why the lower bound: A(z)'s and
//! B(z)'s coefficients are rounded, and near z = 1 the difference equation turns their
//! rounding into an error of the order of eps·Σ|aᵢ|/|A(1)|, A(1) = Π(1 − e^{pᵢh}) ≈ Π pᵢh:
//! four poles at |p|h ≈ 0.05 (drawn from 0.02 up) missed 1e-12 by up to 4.7e-12, and
//! iterating the same rounded coefficients in 40-digit arithmetic (mpmath) missed the exact
//! y(kh) by as much, while the closed form `StepResponse` was exact to 2e-16: the
//! coefficient form's conditioning, not the hold. From |p|h ≥ 0.1 the worst is 7e-13 of the
//! response's scale. The growth bound is there for the same reason: the recursion carries
//! its rounding multiplied by the growth of the modes.

use degrau_lti::discrete::c2d;
use degrau_lti::{C64, StepResponse, TransferFunction};

use crate::rng::Lcg;

const SAMPLES: usize = 51;
const TOL: f64 = 1e-12;

/// A continuous system and its period: (G with its dead time, h).
fn random_case(rng: &mut Lcg, case: usize) -> (TransferFunction, f64) {
    let h = [0.01, 0.1, 0.5][case % 3];
    let order = 1 + (rng.next() * 4.0) as usize;
    let unstable = rng.next() < 0.3;
    // |p|·h between 0.1 and 2.5, log-uniform (the module doc says why).
    let magnitude = |rng: &mut Lcg| (rng.range((0.1f64).ln(), (2.5f64).ln())).exp() / h;
    let mut poles = Vec::new();
    if rng.next() < 0.2 {
        poles.push(C64::new(0.0, 0.0));
    }
    while poles.len() < order {
        let r = magnitude(rng);
        let growth = 5.0 / (50.0 * h);
        if order - poles.len() >= 2 && rng.next() < 0.5 {
            let angle = rng.range(0.05, 1.5);
            let mut re = -r * angle.cos();
            if unstable && poles.is_empty() {
                re = rng.range(0.0, growth);
            }
            let im = r * angle.sin();
            poles.push(C64::new(re, im));
            poles.push(C64::new(re, -im));
        } else {
            let re = if unstable && poles.is_empty() {
                rng.range(0.01, 1.0) * growth
            } else {
                -r
            };
            poles.push(C64::new(re, 0.0));
        }
    }
    // Zeros: strictly proper, or biproper in one case in eight; either half plane.
    let zero_count = if rng.next() < 0.125 {
        order
    } else {
        (rng.next() * order as f64) as usize
    };
    let zeros: Vec<C64> = (0..zero_count)
        .map(|_| {
            let sign = if rng.next() < 0.3 { 1.0 } else { -1.0 };
            C64::new(sign * magnitude(rng), 0.0)
        })
        .collect();
    let gain = rng.range(0.2, 5.0) * if rng.next() < 0.3 { -1.0 } else { 1.0 };
    let delay = match case % 4 {
        0 => 0.0,
        1 => (1.0 + (rng.next() * 5.0).floor()) * h,
        _ => (rng.next() * 5.0).floor() * h + rng.range(0.05, 0.95) * h,
    };
    let g = TransferFunction::from_zpk(&zeros, &poles, gain)
        .and_then(|g| g.with_delay(delay))
        .expect("a valid random system");
    (g, h)
}

/// Each of `expected` matched to a distinct one of `got` within `tol` relative.
fn same_multiset(got: &[C64], expected: &[C64], tol: f64) -> bool {
    let mut left: Vec<C64> = got.to_vec();
    got.len() == expected.len()
        && expected.iter().all(|&e| {
            let nearest = left
                .iter()
                .enumerate()
                .min_by(|a, b| (*a.1 - e).norm().total_cmp(&(*b.1 - e).norm()));
            match nearest {
                Some((i, &z)) if (z - e).norm() <= tol * e.norm().max(1.0) => {
                    left.swap_remove(i);
                    true
                }
                _ => false,
            }
        })
}

#[test]
fn poles_of_h_are_the_exponentials_of_g_poles() {
    let mut rng = Lcg(26);
    for case in 0..120 {
        let (g, h) = random_case(&mut rng, case);
        let d = c2d(&g, h).unwrap_or_else(|e| panic!("case {case}: {e}"));
        let expected: Vec<C64> = g.poles().iter().map(|p| (*p * h).exp()).collect();
        let poles = d.poles().unwrap();
        assert!(
            same_multiset(&poles, &expected, TOL),
            "case {case}: {poles:?} vs {expected:?}"
        );
        // A(z) = z^na + a1·z^(na−1) + … vanishes there (backward error of its coefficients).
        for z in &expected {
            let (value, size) = d.a().iter().fold((C64::new(0.0, 0.0), 0.0), |(v, s), &c| {
                (v * z + c, s * z.norm() + c.abs())
            });
            assert!(value.norm() <= TOL * size, "case {case}: A({z}) = {value}");
        }
    }
}

#[test]
fn stairs_equal_the_continuous_response_at_the_samples() {
    let mut rng = Lcg(26);
    let (mut fractional, mut whole) = (0, 0);
    for case in 0..120 {
        let (g, h) = random_case(&mut rng, case);
        let d = c2d(&g, h).unwrap_or_else(|e| panic!("case {case}: {e}"));
        let stairs = d.step(SAMPLES);
        let y = StepResponse::new(&g, 1.0).unwrap();
        let continuous: Vec<f64> = (0..SAMPLES).map(|k| y.value(k as f64 * h)).collect();
        let scale = continuous.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(scale > 0.0, "case {case}");
        for (k, (s, c)) in stairs.iter().zip(&continuous).enumerate() {
            assert!(
                (s - c).abs() <= TOL * scale,
                "case {case} (h {h}, θ {}, {g:?}, {d:?}) k {k}: {s} vs {c} (scale {scale})",
                g.delay()
            );
        }
        let fraction = (g.delay() / h).fract();
        if fraction > 0.01 && fraction < 0.99 {
            fractional += 1;
        } else if g.delay() > 0.0 {
            whole += 1;
        }
    }
    assert!(fractional >= 50 && whole >= 25, "{fractional} {whole}");
}
