//! The Nyquist criterion against the closed loop's poles: on random rational loops (plants
//! with poles in either half-plane, integrators and undamped pairs on the axis, zeros on
//! either side; P, PI, PD and PID controllers) Z = N + P equals the number of roots of the
//! closed-loop characteristic polynomial d_c·d_g + n_c·n_g in the right half-plane, found
//! by the polynomial root finder; with a dead time it equals the argument-principle count
//! of the quasi-polynomial (itself checked against Padé (8, 8) loops in `lti_tuning`).

use degrau_lti::control::frequency::closed_loop_unstable_roots;
use degrau_lti::control::{Action, Controller, nyquist};
use degrau_lti::{C64, TransferFunction, poly};

use crate::lti_tuning::random_loop;
use crate::rng::Lcg;

/// Poles of a random plant: real or complex, mostly stable, sometimes at the origin or an
/// undamped pair on the imaginary axis.
fn random_poles(rng: &mut Lcg, n: usize) -> Vec<C64> {
    let mut roots = Vec::new();
    while roots.len() < n {
        let pick = rng.next();
        let re = if pick < 0.1 {
            0.0
        } else {
            rng.range(-5.0, 1.5)
        };
        if n - roots.len() >= 2 && rng.next() < 0.4 {
            let im = rng.log_uniform(0.2, 5.0);
            roots.push(C64::new(re, im));
            roots.push(C64::new(re, -im));
        } else {
            roots.push(C64::new(re, 0.0));
        }
    }
    roots
}

fn random_rational_loop(rng: &mut Lcg) -> (TransferFunction, Controller) {
    let order = 1 + (rng.next() * 4.0) as usize;
    let poles = random_poles(rng, order);
    let zeros: Vec<C64> = (0..(rng.next() * order as f64) as usize)
        .map(|_| C64::new(rng.range(-6.0, 2.0), 0.0))
        .collect();
    let gain = rng.log_uniform(0.1, 30.0) * if rng.next() < 0.25 { -1.0 } else { 1.0 };
    let g = TransferFunction::from_zpk(&zeros, &poles, gain).expect("a plant");
    let action = [Action::P, Action::PI, Action::PD, Action::PID][(rng.next() * 4.0) as usize];
    let c = Controller::new(
        action,
        rng.log_uniform(0.1, 10.0),
        rng.log_uniform(0.2, 20.0),
        rng.log_uniform(0.05, 2.0),
    )
    .expect("a controller");
    (g, c)
}

/// The closed loop's roots in the right half-plane from its characteristic polynomial, or
/// None when a root lies within 1e-6 (relative) of the imaginary axis, where the count is
/// rounding's choice.
fn polynomial_count(g: &TransferFunction, c: &Controller) -> Option<i64> {
    let (nc, dc) = c.feedback_coeffs();
    let d = poly_mul(&dc, &g.den());
    let n = poly_mul(&nc, &g.num());
    let mut chi = d.clone();
    let offset = d.len() - n.len();
    for (i, x) in n.iter().enumerate() {
        chi[offset + i] += x;
    }
    let roots = poly::roots(&chi).ok()?;
    let scale = roots.iter().map(|r| r.norm()).fold(1e-3, f64::max);
    if roots.iter().any(|r| r.re.abs() <= 1e-6 * scale) {
        return None;
    }
    Some(roots.iter().filter(|r| r.re > 0.0).count() as i64)
}

fn poly_mul(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

#[test]
fn encirclements_agree_with_the_closed_loop_poles_on_random_rational_loops() {
    let mut rng = Lcg(20_261_205);
    let (mut compared, mut stable, mut unstable, mut indented, mut open_unstable) = (0, 0, 0, 0, 0);
    while compared < 150 {
        let (g, c) = random_rational_loop(&mut rng);
        let Some(expected) = polynomial_count(&g, &c) else {
            continue;
        };
        let n = nyquist(&g, &c).unwrap_or_else(|e| panic!("{e:?}: G = {g:?}, C = {c:?}"));
        assert_eq!(
            n.closed_loop_unstable, expected,
            "N = {}, P = {}: G = {g:?}, C = {c:?}",
            n.encirclements, n.open_loop_unstable
        );
        assert_eq!(n.encirclements + n.open_loop_unstable as i64, expected);
        assert_eq!(
            closed_loop_unstable_roots(&g, &c).map(|z| z as i64),
            Ok(expected)
        );
        // The curve is L(jω) at increasing ω.
        assert!(n.curve.windows(2).all(|p| p[0].w < p[1].w));
        for p in n.curve.iter().step_by(37) {
            let direct = c.eval(C64::new(0.0, p.w)) * g.eval(C64::new(0.0, p.w));
            assert!((p.l - direct).norm() <= 1e-12 * direct.norm().max(1.0));
        }
        compared += 1;
        if expected == 0 {
            stable += 1;
        } else {
            unstable += 1;
        }
        indented += usize::from(n.imaginary_poles > 0);
        open_unstable += usize::from(n.open_loop_unstable > 0);
    }
    assert!(
        stable >= 30 && unstable >= 30,
        "{stable} stable, {unstable} unstable"
    );
    assert!(
        indented >= 30 && open_unstable >= 20,
        "{indented} indented, {open_unstable} open-loop unstable"
    );
}

#[test]
fn encirclements_agree_with_the_root_count_on_random_loops_with_dead_time() {
    let mut rng = Lcg(1936);
    let (mut stable, mut unstable) = (0, 0);
    for _ in 0..100 {
        let (g, c) = random_loop(&mut rng);
        // Half of them with three times the gain, so that many are unstable.
        let c = if rng.next() < 0.5 {
            Controller::new(c.action, 3.0 * c.kc, c.ti, c.td).expect("a controller")
        } else {
            c
        };
        let n = nyquist(&g, &c).unwrap_or_else(|e| panic!("{e:?}: G = {g:?}, C = {c:?}"));
        let z = closed_loop_unstable_roots(&g, &c).expect("a count");
        assert_eq!(n.closed_loop_unstable, z as i64, "G = {g:?}, C = {c:?}");
        if z == 0 {
            stable += 1;
        } else {
            unstable += 1;
        }
    }
    assert!(
        stable >= 25 && unstable >= 25,
        "{stable} stable, {unstable} unstable"
    );
}

#[test]
fn the_curve_spirals_in_with_the_dead_time() {
    // 2e^{−s}/(s + 1): |L| = 2/√(1 + ω²), ∠L = −atan ω − ω; the curve is drawn until |L| has
    // fallen within 1e-3 of 0.
    let g = TransferFunction::from_coeffs(&[2.0], &[1.0, 1.0])
        .unwrap()
        .with_delay(1.0)
        .unwrap();
    let n = nyquist(&g, &Controller::proportional(1.0).unwrap()).unwrap();
    let last = n.curve.last().unwrap();
    assert!(last.l.norm() < 2e-3 && last.w > 900.0, "{last:?}");
    // Consecutive points are close: the spiral is drawn smooth.
    for p in n.curve.windows(2) {
        assert!((p[1].l - p[0].l).norm() <= 0.02 * (p[0].l.norm() + 0.25));
    }
    // The phase crossover: atan ω + ω = π at ω = 2.029, where |G| = 0.884, so Kcr = 1.131:
    // K = 1 is stable, and at K = 1.2 the curve goes round −1 once (N = 2 counting both
    // halves of the contour), two closed-loop roots in the right half-plane.
    assert_eq!(n.closed_loop_unstable, 0);
    let n = nyquist(&g, &Controller::proportional(1.2).unwrap()).unwrap();
    assert_eq!((n.encirclements, n.closed_loop_unstable), (2, 2));
}
