//! c2d and d2c against an independent discretisation: the matrix exponential of the augmented
//! state matrix [[A, B], [0, 0]] (nalgebra), with the dead time's fractional part L split
//! between two input samples, as a textbook derives the ZOH with a fractional delay; against
//! the continuous step response in 768-bit arithmetic (`tests/exact`) at the samples, down
//! to h = 1e-9; and through the binary (`degrau c2d`, `degrau d2c`): the static gain and
//! the dead time exact or refused, d2c checked by c2d(d2c(H)) = H, words for an infinite
//! gain in both languages.

use degrau::lti::discrete::{DiscreteError, DiscreteTf, c2d, foptd_zoh};
use degrau::lti::{C64, TransferFunction};
use nalgebra::DMatrix;
use proptest::prelude::*;
use serde_json::Value;

use crate::exact;
use crate::run;

use exact::Reference;
use run::{degrau, json, stderr, stdout};

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
        // Poles at e^{p·h}, once a pole equal to a zero has cancelled ((s + 2)/(s + 2)).
        let mut zp: Vec<f64> = d.poles().unwrap().iter().map(|z| z.norm()).collect();
        let mut want: Vec<f64> = tf
            .uncancelled_poles()
            .iter()
            .map(|p| (*p * h).exp().norm())
            .collect();
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

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("{v} is not a list"))
        .iter()
        .map(|x| x.as_f64().unwrap_or_else(|| panic!("{x} is not a number")))
        .collect()
}

/// A list as a flag value, every digit kept.
fn list_arg(values: &[f64]) -> String {
    values
        .iter()
        .map(|x| format!("{x:?}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// The discrete model of `degrau c2d --json`.
fn model(v: &Value) -> DiscreteTf {
    DiscreteTf::new(
        numbers(&v["a"]),
        numbers(&v["b"]),
        v["nk"].as_u64().expect("nk") as usize,
        v["ts"].as_f64().expect("ts"),
    )
    .expect("a model")
}

/// The largest |y(k) − s(k·h − θ)| over `y`'s samples, relative to the largest |s|: s the
/// continuous step response in 768-bit arithmetic (0 before θ).
fn sample_error(y: &[f64], reference: &mut Reference, h: f64, delay_samples: f64) -> f64 {
    let want: Vec<f64> = (0..y.len())
        .map(|k| {
            let tau = (k as f64 - delay_samples) * h;
            if tau < 0.0 { 0.0 } else { reference.value(tau) }
        })
        .collect();
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    y.iter()
        .zip(&want)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn c2d_at_a_nanosecond_has_its_static_gain_and_its_samples() {
    // 2/(10s² + 11s + 1) = 0.2/((s + 1)(s + 0.1)): b ≈ 1e-19 at h = 1e-9, G(0) = 2.
    for (ts, b1) in [("1e-9", 1e-19), ("1e-6", 1e-13)] {
        let v = json(&[
            "c2d", "--num", "2", "--den", "10,11,1", "--ts", ts, "--json",
        ]);
        let h: f64 = ts.parse().unwrap();
        assert_eq!(v["dc_gain"].as_f64(), Some(2.0), "{v}");
        let b = numbers(&v["b"]);
        assert!(b.iter().all(|x| (x / b1 - 1.0).abs() < 1e-3), "{b:?}");
        let mut poles: Vec<f64> = v["poles"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p[0].as_f64().unwrap())
            .collect();
        poles.sort_by(f64::total_cmp);
        assert_eq!(poles, vec![(-h).exp(), (-0.1 * h).exp()]);
        let mut reference = Reference::new(&[], &[C64::new(-1.0, 0.0), C64::new(-0.1, 0.0)], 0.2);
        let e = sample_error(&model(&v).step(12), &mut reference, h, 0.0);
        assert!(e < 1e-9, "h = {ts}: samples off by {e:e} of their size");
    }
}

#[test]
fn c2d_refuses_periods_whose_model_double_precision_cannot_hold() {
    for (args, en, pt) in [
        (
            ["--num", "1", "--den", "1,1", "--ts", "1e-20"],
            "is too short for the pole s = -1",
            "é curto demais para o polo s = -1",
        ),
        (
            ["--num", "1", "--den", "1,0,0", "--ts", "1e200"],
            "the coefficients of B(z) fall outside double precision's range",
            "os coeficientes de B(z) saem da faixa da precisão dupla",
        ),
    ] {
        for (lang, words) in [("en", en), ("pt", pt)] {
            let mut all = vec!["--lang", lang, "c2d"];
            all.extend_from_slice(&args);
            let out = degrau(&all);
            assert_eq!(out.status.code(), Some(2), "{all:?}: {}", stdout(&out));
            assert!(stderr(&out).contains(words), "{}", stderr(&out));
        }
    }
}

#[test]
fn c2d_refuses_a_delay_beyond_exact_sample_counts() {
    for delay in ["1e19", "1e18"] {
        for (lang, words) in [
            ("en", "sampling periods: at most 1.09951e12 are counted"),
            (
                "pt",
                "períodos de amostragem: no máximo 1,09951e12 são contados",
            ),
        ] {
            let out = degrau(&[
                "--lang", lang, "c2d", "--num", "1", "--den", "1,1", "--ts", "0.1", "--delay",
                delay,
            ]);
            assert_eq!(out.status.code(), Some(2), "{delay}: {}", stdout(&out));
            assert!(stderr(&out).contains(words), "{}", stderr(&out));
        }
    }
    // 1e10 s is 10¹¹ samples exactly, plus the hold's one, and d2c gives it back.
    let v = json(&[
        "c2d", "--num", "1", "--den", "1,1", "--ts", "0.1", "--delay", "1e10", "--json",
    ]);
    assert_eq!(v["nk"].as_u64(), Some(100_000_000_001));
    let g = there_and_back(&[
        "--num", "1", "--den", "1,1", "--ts", "0.1", "--delay", "1e10",
    ]);
    assert_eq!(g["delay"].as_f64(), Some(1e10), "{g}");
    // 0.3 s at 0.1 s is three whole samples, though 0.3 < 3 × 0.1 in binary.
    let v = json(&[
        "c2d", "--num", "1", "--den", "1,1", "--ts", "0.1", "--delay", "0.3", "--json",
    ]);
    assert_eq!(v["nk"].as_u64(), Some(4));
    assert_eq!(numbers(&v["b"]).len(), 1);
}

#[test]
fn c2d_of_s_over_s_is_the_gain_one() {
    let out = degrau(&["c2d", "--num", "1,0", "--den", "1,0", "--ts", "0.1"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("Static gain: 1\n"), "{text}");
    assert!(!text.contains("NaN"), "{text}");
    let v = json(&[
        "c2d", "--num", "1,0", "--den", "1,0", "--ts", "0.1", "--json",
    ]);
    assert_eq!(numbers(&v["a"]), vec![1.0]);
    assert_eq!(numbers(&v["b"]), vec![1.0]);
    assert_eq!(v["nk"].as_u64(), Some(0));
    assert_eq!(v["dc_gain"].as_f64(), Some(1.0));
}

#[test]
fn d2c_refuses_a_cancelled_pole_zero_pair() {
    // (0.5 − 0.45z⁻¹)/(1 − 0.9z⁻¹)·z⁻¹ is 0.5·z⁻¹: no continuous system with a pole has
    // its samples (0.5268/(s + 1.0536) gave 0.05 at t = 0.1 where H gives 0.5).
    for nk in ["1", "0"] {
        for (lang, words) in [
            ("en", "B(z) and A(z) share the root z = 0.9"),
            ("pt", "B(z) e A(z) têm a raiz z = 0,9 em comum"),
        ] {
            let out = degrau(&[
                "--lang",
                lang,
                "d2c",
                "--num",
                "0.5,-0.45",
                "--den",
                "1,-0.9",
                "--nk",
                nk,
                "--ts",
                "0.1",
            ]);
            assert_eq!(out.status.code(), Some(2), "{}", stdout(&out));
            assert!(stderr(&out).contains(words), "{}", stderr(&out));
        }
    }
}

/// `degrau d2c` of the model `degrau c2d` gives for these flags, as JSON.
fn there_and_back(c2d_flags: &[&str]) -> Value {
    let mut args = vec!["c2d", "--json"];
    args.extend_from_slice(c2d_flags);
    let v = json(&args);
    let (a, b) = (list_arg(&numbers(&v["a"])), list_arg(&numbers(&v["b"])));
    let (nk, ts) = (v["nk"].to_string(), v["ts"].to_string());
    json(&[
        "d2c", "--num", &b, "--den", &a, "--nk", &nk, "--ts", &ts, "--json",
    ])
}

fn assert_close(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}: {got:?} vs {want:?}");
    for (x, y) in got.iter().zip(want) {
        assert!(
            (x - y).abs() <= tol * y.abs().max(1.0),
            "{what}: {got:?} vs {want:?}"
        );
    }
}

#[test]
fn d2c_with_nk_0_is_biproper_and_c2d_output_round_trips() {
    // (s + 2)/(s + 1) at h = 0.1: nk = 0, a direct feedthrough of 1.
    let g = there_and_back(&["--num", "1,2", "--den", "1,1", "--ts", "0.1"]);
    assert_close("num", &numbers(&g["num"]), &[1.0, 2.0], 1e-9);
    assert_close("den", &numbers(&g["den"]), &[1.0, 1.0], 1e-9);
    assert_eq!(g["delay"].as_f64(), Some(0.0));
    // A biproper system delayed three whole samples.
    let g = there_and_back(&[
        "--num", "2,1,3", "--den", "1,3,2", "--delay", "0.3", "--ts", "0.1",
    ]);
    assert_close("num", &numbers(&g["num"]), &[2.0, 1.0, 3.0], 1e-9);
    assert_close("den", &numbers(&g["den"]), &[1.0, 3.0, 2.0], 1e-9);
    assert!((g["delay"].as_f64().unwrap() - 0.3).abs() < 1e-12, "{g}");
    // nk = 0 typed: H = 1 + 0.5z⁻¹/(1 − 0.5z⁻¹) has no delay, unlike nk = 1.
    let g = json(&[
        "d2c", "--num", "1", "--den", "1,-0.5", "--nk", "0", "--ts", "1", "--json",
    ]);
    assert_eq!(g["delay"].as_f64(), Some(0.0), "{g}");
    assert_eq!(numbers(&g["num"]).len(), 2, "biproper: {g}");
}

#[test]
fn infinite_static_gains_are_said_in_words() {
    let cases: [(&[&str], &str, &str); 3] = [
        (
            &["c2d", "--num", "1", "--den", "1,1,0", "--ts", "0.1"],
            "Static gain: infinite: the system integrates (a pole at z = 1)",
            "Ganho estático: infinito: o sistema é integrador (um polo em z = 1)",
        ),
        (
            &["d2c", "--num", "1", "--den", "1,-1", "--ts", "0.1"],
            "Static gain: infinite: the system integrates (a pole at s = 0)",
            "Ganho estático: infinito: o sistema é integrador (um polo em s = 0)",
        ),
        (
            &["step", "--num", "-1", "--den", "1,1,0"],
            "G(0) = infinite, negative: the system integrates (a pole at s = 0)",
            "G(0) = infinito, negativo: o sistema é integrador (um polo em s = 0)",
        ),
    ];
    for (args, en, pt) in cases {
        for (lang, words) in [("en", en), ("pt", pt)] {
            let mut all = vec!["--lang", lang];
            all.extend_from_slice(args);
            let out = degrau(&all);
            assert!(out.status.success(), "{all:?}: {}", stderr(&out));
            let text = stdout(&out);
            assert!(text.contains(words), "{all:?}: {text}");
            let words: Vec<&str> = text.split(|c: char| !c.is_alphanumeric()).collect();
            assert!(
                !words.iter().any(|w| ["inf", "NaN"].contains(w)),
                "{all:?}: {text}"
            );
        }
    }
}

prop_compose! {
    /// A stable real pole or conjugate pair, each part's size in [0.1, 100].
    fn stable_roots()(
        re in 0.1f64..100.0,
        im in prop_oneof![Just(0.0), 0.1f64..100.0],
    ) -> Vec<C64> {
        if im == 0.0 {
            vec![C64::new(-re, 0.0)]
        } else {
            vec![C64::new(-re, im), C64::new(-re, -im)]
        }
    }
}

prop_compose! {
    /// A real zero or a conjugate pair anywhere in ±[0.1, 100] (either half plane).
    fn any_roots()(
        re in -100.0f64..100.0,
        im in prop_oneof![Just(0.0), 0.1f64..100.0],
    ) -> Vec<C64> {
        let re = if re.abs() < 0.1 { 0.1 } else { re };
        if im == 0.0 { vec![C64::new(re, 0.0)] } else { vec![C64::new(re, im), C64::new(re, -im)] }
    }
}

/// The smallest distance between two roots relative to the larger modulus.
fn separation(roots: &[C64]) -> f64 {
    let mut least = f64::INFINITY;
    for (i, a) in roots.iter().enumerate() {
        for b in &roots[i + 1..] {
            least = least.min((a - b).norm() / a.norm().max(b.norm()));
        }
    }
    least
}

/// A random system: 1–4 distinct stable poles, up to as many zeros, a gain.
fn system(
    poles: Vec<Vec<C64>>,
    zeros: Vec<Vec<C64>>,
    gain: f64,
) -> Option<(Vec<C64>, Vec<C64>, f64)> {
    let poles: Vec<C64> = poles.concat();
    let mut zeros: Vec<C64> = zeros.concat();
    while zeros.len() > poles.len() {
        zeros.truncate(
            zeros.len()
                - if zeros[zeros.len() - 1].im != 0.0 {
                    2
                } else {
                    1
                },
        );
    }
    (poles.len() <= 4 && separation(&poles) > 0.05).then_some((poles, zeros, gain))
}

proptest! {
    #![proptest_config(run::proptest_config(96))]

    /// c2d's step samples, run through its difference equation, are the continuous step
    /// response at k·h (768-bit residue formula) to 1e-9 of their size, at any h from 1e-9 to
    /// twice the fastest time constant, with a whole or fractional dead time.
    #[test]
    fn c2d_samples_are_the_continuous_step_response(
        poles in prop::collection::vec(stable_roots(), 1..4),
        zeros in prop::collection::vec(any_roots(), 0..3),
        gain in prop_oneof![0.01f64..100.0, -100.0f64..-0.01],
        log_h in -9.0f64..0.0,
        whole in 0usize..3,
        fraction in prop_oneof![Just(0.0), 0.05f64..0.95],
    ) {
        let Some((poles, zeros, gain)) = system(poles, zeros, gain) else {
            return Ok(());
        };
        let fastest = poles.iter().map(|p| p.norm()).fold(0.0, f64::max);
        let h = 10f64.powf(log_h).min(2.0 / fastest);
        let delay_samples = whole as f64 + fraction;
        let g = TransferFunction::from_zpk(&zeros, &poles, gain)
            .unwrap()
            .with_delay(delay_samples * h)
            .unwrap();
        let d = c2d(&g, h).unwrap();
        prop_assert_eq!(d.dc_gain(), g.dc_gain());
        let mut reference = Reference::new(&zeros, &poles, gain);
        let e = sample_error(&d.step(16), &mut reference, h, delay_samples);
        prop_assert!(e < 1e-9, "{g:?} at h = {h}: samples off by {e:e} of their size");
    }

    /// d2c(c2d(G)) = G on random stable G (biproper included) sampled faster than its
    /// oscillations, with a whole-sample dead time (or a fractional one for a strictly
    /// proper first order): the same frequency response to 1e-6 and the same dead time.
    #[test]
    fn d2c_inverts_c2d_on_random_stable_systems(
        poles in prop::collection::vec(stable_roots(), 1..4),
        zeros in prop::collection::vec(any_roots(), 0..3),
        gain in prop_oneof![0.01f64..100.0, -100.0f64..-0.01],
        per_fastest in 0.01f64..2.0,
        whole in 0usize..3,
        fraction in 0.05f64..0.95,
    ) {
        let Some((poles, zeros, gain)) = system(poles, zeros, gain) else {
            return Ok(());
        };
        let fastest = poles.iter().map(|p| p.norm()).fold(0.0, f64::max);
        let h = per_fastest / fastest;
        // A first order with a fractional dead time has the samples of a biproper first
        // order delayed whole samples: d2c answers the notes' form, so a biproper first
        // order goes without a delay, and only a strictly proper one takes a fraction.
        let first_order = poles.len() == 1;
        let biproper = zeros.len() == poles.len();
        let delay = match (first_order, biproper) {
            (true, true) => 0.0,
            (true, false) => (whole as f64 + fraction) * h,
            (false, _) => whole as f64 * h,
        };
        let g = TransferFunction::from_zpk(&zeros, &poles, gain).unwrap().with_delay(delay).unwrap();
        let back = c2d(&g, h).unwrap().d2c().map_err(|e| TestCaseError::fail(format!("{g:?} at h = {h}: {e}")))?;
        prop_assert!((back.delay() - delay).abs() <= 1e-9 * h, "{back:?} from {g:?}");
        let (g0, b0) = (g.clone().with_delay(0.0).unwrap(), back.clone().with_delay(0.0).unwrap());
        for w in [0.0, 0.1, 0.5, 1.0, 2.0, 3.0] {
            let s = C64::new(0.0, w / h);
            let (want, got) = (g0.eval(s), b0.eval(s));
            prop_assert!(
                (want - got).norm() <= 1e-6 * want.norm().max(g0.eval(C64::new(0.0, 0.0)).norm()),
                "G(j{}) = {want} vs {got}: {back:?} from {g:?} at h = {h}", w / h
            );
        }
    }
}
