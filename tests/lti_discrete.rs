//! c2d and d2c against an independent discretisation: the matrix exponential of the augmented
//! state matrix [[A, B], [0, 0]] (nalgebra), with the dead time's fractional part L split
//! between two input samples, as a textbook derives the ZOH with a fractional delay.

use degrau::lti::discrete::{DiscreteError, DiscreteTf, c2d, foptd_zoh};
use degrau::lti::{C64, TransferFunction};
use nalgebra::DMatrix;

/// ∫₀ᵗ e^{As} ds·B, via the exponential of [[A, B], [0, 0]]·t.
fn integral(a: &DMatrix<f64>, b: &DMatrix<f64>, t: f64) -> DMatrix<f64> {
    let n = a.nrows();
    let mut m = DMatrix::zeros(n + 1, n + 1);
    m.view_mut((0, 0), (n, n)).copy_from(&(a * t));
    m.view_mut((0, n), (n, 1)).copy_from(&(b * t));
    m.exp().view((0, n), (n, 1)).into_owned()
}

/// The pulse response h(0..count) of the ZOH discretisation of num/den (strictly proper,
/// monic den) with dead time θ at period h, from the state-space form.
fn pulse_by_expm(num: &[f64], den: &[f64], theta: f64, h: f64, count: usize) -> Vec<f64> {
    let n = den.len() - 1;
    // Controllable canonical form.
    let mut a = DMatrix::zeros(n, n);
    for i in 0..n - 1 {
        a[(i, i + 1)] = 1.0;
    }
    for j in 0..n {
        a[(n - 1, j)] = -den[n - j];
    }
    let b = DMatrix::from_fn(n, 1, |i, _| if i == n - 1 { 1.0 } else { 0.0 });
    let mut padded = vec![0.0; n - (num.len() - 1) - 1];
    padded.extend_from_slice(num);
    let c = DMatrix::from_fn(1, n, |_, j| padded[n - 1 - j]);
    let d = (theta / h).floor() as usize;
    let l = theta - d as f64 * h;
    let phi = (&a * h).exp();
    let gamma_late = integral(&a, &b, h - l);
    let gamma_early = (&a * (h - l)).exp() * integral(&a, &b, l);
    let mut out = vec![0.0; count];
    let mut power = DMatrix::identity(n, n);
    for m in 1..count {
        if m + d < count {
            out[m + d] += (&c * &power * &gamma_late)[(0, 0)];
        }
        if m + d + 1 < count {
            out[m + d + 1] += (&c * &power * &gamma_early)[(0, 0)];
        }
        power = &phi * power;
    }
    out
}

fn pulse(d: &DiscreteTf, count: usize) -> Vec<f64> {
    let mut u = vec![0.0; count];
    u[0] = 1.0;
    d.simulate(&u)
}

fn close(a: &[f64], b: &[f64], tol: f64) {
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!((x - y).abs() <= tol, "sample {k}: {x} vs {y}");
    }
}

#[test]
fn the_notes_foptd_formulas_match_the_matrix_exponential() {
    // (K, τ, θ, h): fractional delays, θ < h, θ a whole number of samples, no delay.
    for (k, tau, theta, h) in [
        (2.0, 5.0, 1.3, 0.5),
        (-0.7, 0.8, 0.05, 0.2),
        (1.5, 12.0, 3.0, 1.0),
        (3.0, 2.0, 0.0, 0.1),
        (0.25, 150.0, 37.5, 20.0),
    ] {
        let d = foptd_zoh(k, tau, theta, h).unwrap();
        let whole = (theta / h).floor();
        assert_eq!(d.nk(), whole as usize + 1);
        // Scalar state space: A = −1/τ, B = 1, C = K/τ.
        let a = DMatrix::from_element(1, 1, -1.0 / tau);
        let b = DMatrix::from_element(1, 1, 1.0);
        let l = theta - whole * h;
        let b0 = k / tau * integral(&a, &b, h - l)[(0, 0)];
        let b1 = k / tau * ((&a * (h - l)).exp() * integral(&a, &b, l))[(0, 0)];
        let a1 = -(&a * h).exp()[(0, 0)];
        assert!(
            (d.a()[1] - a1).abs() < 1e-12,
            "a1 for {k}, {tau}, {theta}, {h}"
        );
        assert!(
            (d.b()[0] - b0).abs() < 1e-12,
            "b0 for {k}, {tau}, {theta}, {h}"
        );
        assert!(
            (d.b()[1] - b1).abs() < 1e-12,
            "b1 for {k}, {tau}, {theta}, {h}"
        );
        // The general c2d gives the same model.
        let tf = TransferFunction::from_coeffs(&[k], &[tau, 1.0])
            .unwrap()
            .with_delay(theta)
            .unwrap();
        close(&pulse(&c2d(&tf, h).unwrap(), 40), &pulse(&d, 40), 1e-12);
    }
}

#[test]
fn c2d_matches_the_matrix_exponential_for_higher_orders() {
    // (num, den monic, θ, h): real poles with a zero, a lightly damped pair, three poles.
    let cases: [(&[f64], &[f64], f64, f64); 4] = [
        (&[1.5, 3.0], &[1.0, 3.0, 2.0], 0.37, 0.2),
        (&[4.0], &[1.0, 0.4, 4.0], 1.05, 0.25),
        (&[2.0, 1.0, 6.0], &[1.0, 6.0, 11.0, 6.0], 0.0, 0.1),
        (&[0.02], &[1.0, 0.3, 0.02], 7.5, 2.0),
    ];
    for (num, den, theta, h) in cases {
        let tf = TransferFunction::from_coeffs(num, den)
            .unwrap()
            .with_delay(theta)
            .unwrap();
        let d = c2d(&tf, h).unwrap();
        let expect = pulse_by_expm(num, den, theta, h, 60);
        let scale = expect.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        close(&pulse(&d, 60), &expect, 1e-11 * scale.max(1.0));
        // Poles at e^{p·h}.
        let mut zp: Vec<f64> = d.poles().unwrap().iter().map(|z| z.norm()).collect();
        let mut want: Vec<f64> = tf.poles().iter().map(|p| (*p * h).exp().norm()).collect();
        zp.sort_by(f64::total_cmp);
        want.sort_by(f64::total_cmp);
        close(&zp, &want, 1e-12);
    }
}

#[test]
fn d2c_returns_the_continuous_poles_gain_and_dead_time() {
    // Whole-sample dead time, a zero, complex poles.
    let tf = TransferFunction::from_coeffs(&[0.5, 2.0], &[1.0, 1.2, 4.0])
        .unwrap()
        .with_delay(0.75)
        .unwrap();
    let back = c2d(&tf, 0.25).unwrap().d2c().unwrap();
    assert!((back.delay() - 0.75).abs() < 1e-12);
    assert!((back.dc_gain() - tf.dc_gain()).abs() < 1e-9);
    for p in tf.poles() {
        assert!(back.poles().iter().any(|q| (q - p).norm() < 1e-9), "{p}");
    }
    assert!((back.zeros()[0] - tf.zeros()[0]).norm() < 1e-8);
}

#[test]
fn d2c_of_a_foptd_with_fractional_delay_uses_the_notes_formulas() {
    for (k, tau, theta, h) in [
        (2.0, 5.0, 1.3, 0.5),
        (-1.2, 0.9, 0.07, 0.2),
        (40.0, 180.0, 25.0, 4.0),
    ] {
        let back = foptd_zoh(k, tau, theta, h).unwrap().d2c().unwrap();
        assert!((back.dc_gain() - k).abs() < 1e-9 * k.abs(), "K {k}");
        assert!(
            (back.poles()[0].re + 1.0 / tau).abs() < 1e-9 / tau,
            "τ {tau}"
        );
        assert!(
            (back.delay() - theta).abs() < 1e-9 * h,
            "θ {theta}: {}",
            back.delay()
        );
    }
}

#[test]
fn d2c_refuses_what_has_no_continuous_image() {
    let neg = DiscreteTf::new(vec![1.0, 0.5], vec![1.0], 1, 0.1).unwrap();
    assert_eq!(
        neg.d2c(),
        Err(DiscreteError::NoContinuousPole {
            pole: C64::new(-0.5, 0.0)
        })
    );
    let repeated = DiscreteTf::new(vec![1.0, -1.0, 0.25], vec![1.0], 1, 0.1).unwrap();
    assert!(matches!(
        repeated.d2c(),
        Err(DiscreteError::RepeatedPoles { .. })
    ));
    assert_eq!(
        DiscreteTf::new(vec![1.0, -0.5], vec![1.0], 1, 0.0),
        Err(DiscreteError::BadSamplingPeriod(0.0))
    );
}

#[test]
fn an_integrator_goes_there_and_back() {
    let tf =
        TransferFunction::from_zpk(&[], &[C64::new(0.0, 0.0), C64::new(-2.0, 0.0)], 3.0).unwrap();
    let d = c2d(&tf, 0.1).unwrap();
    let back = d.d2c().unwrap();
    for p in tf.poles() {
        assert!(back.poles().iter().any(|q| (q - p).norm() < 1e-9), "{p}");
    }
    assert!((back.gain() - 3.0).abs() < 1e-9, "{back:?} from {d:?}");
}
