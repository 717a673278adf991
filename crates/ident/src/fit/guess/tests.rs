//! The tests of [`super`].

use super::*;

/// A record at rest at 20 before a step at 6 s: white noise ±0.05 (or rounded to a
/// 0.32 quantum), the spikes given added.
fn rest_record(spikes: &[(usize, f64)], quantum: Option<f64>) -> FitData {
    let times: Vec<f64> = (0..100).map(|k| 0.1 * k as f64).collect();
    let mut rng = crate::random::Lcg(5);
    let mut y: Vec<f64> = times
        .iter()
        .map(|_| 20.0 + 0.05 * rng.symmetric())
        .collect();
    for &(i, size) in spikes {
        y[i] += size;
    }
    if let Some(q) = quantum {
        y.iter_mut().for_each(|v| *v = (*v / q).round() * q);
    }
    FitData {
        times,
        y,
        input: Excitation::step(6.0, 1.0),
    }
}

#[test]
fn spikes_before_the_step_are_left_out_of_the_rest_level() {
    let data = rest_record(&[(7, 40.0), (33, -25.0)], None);
    let rest = rest_level(&data).unwrap();
    assert_eq!((rest.samples, rest.wild), (60, 2));
    let tame: Vec<f64> = (0..60)
        .filter(|i| ![7, 33].contains(i))
        .map(|i| data.y[i])
        .collect();
    let expected = tame.iter().sum::<f64>() / 58.0;
    assert!((rest.y0 - expected).abs() < 1e-12, "{} {expected}", rest.y0);
    // The plain mean would have been off by (40 − 25)/60 = 0.25, five times the noise.
    assert!((rest.y0 - 20.0).abs() < 0.03, "{}", rest.y0);
    // No spike: every sample counts, the plain mean.
    let clean = rest_record(&[], None);
    let rest = rest_level(&clean).unwrap();
    assert_eq!(rest.wild, 0);
    assert!((rest.y0 - clean.y[..60].iter().sum::<f64>() / 60.0).abs() < 1e-12);
}

#[test]
fn a_quantised_rest_keeps_all_its_levels() {
    // Noise of ±0.05 rounded to 0.32 stays on one or two levels: none is wild, even
    // with a robust scale of 0; a dropout of 5 °C still is.
    let data = rest_record(&[(12, -5.0)], Some(0.32));
    let rest = rest_level(&data).unwrap();
    assert_eq!(rest.wild, 1);
    let data = rest_record(&[(12, 0.32)], Some(0.32));
    assert_eq!(rest_level(&data).unwrap().wild, 0);
}

/// A step record of `code` (values `params`) far from zero, from 10 s of rest on 0.25 s
/// samples to 120 s, the step between two samples, with Gaussian noise of `noise` of
/// the effect: white for `noise` ≤ 0.01, else AR(1) with ρ = 0.8 and quantised to a
/// tenth of it.
fn shaped(code: &str, params: &[(Param, f64)], noise: f64) -> FitData {
    let s = Structure::parse(code).unwrap();
    let mut v = Values::default();
    v.set(Param::Y0, 40.0);
    params.iter().for_each(|&(p, x)| v.set(p, x));
    let times: Vec<f64> = (0..480).map(|k| 0.25 * k as f64).collect();
    let input = Excitation::step(10.1, 5.0);
    let mut y = Model::new(s, v).simulate(&input, &times).unwrap();
    let effect = 5.0 * v.get(Param::Kp).abs();
    let mut rng = crate::random::Lcg(3);
    let coloured = noise > 0.01;
    let (rho, quantum) = if coloured {
        (0.8_f64, 0.1 * noise * effect)
    } else {
        (0.0, 0.0)
    };
    let mut e = 0.0;
    for x in y.iter_mut() {
        let (a, b) = (rng.unit().max(1e-300), rng.unit());
        let white = (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos();
        e = rho * e + (1.0 - rho * rho).sqrt() * white;
        *x += noise * effect * e;
        if quantum > 0.0 {
            *x = quantum * (*x / quantum).round();
        }
    }
    FitData { times, y, input }
}

#[test]
fn a_staircase_is_judged_on_its_first_change() {
    // A P1D heater stepped 0 → 5 → 1 → 0.5: the record's last level is near its first,
    // so the whole record read as one step would show a huge "overshoot".
    let s = Structure::parse("P1D").unwrap();
    let mut v = Values::default();
    for (p, x) in [
        (Param::Kp, 0.8),
        (Param::Tp1, 8.0),
        (Param::Td, 1.0),
        (Param::Y0, 30.0),
    ] {
        v.set(p, x);
    }
    let times: Vec<f64> = (0..800).map(|k| 0.25 * k as f64).collect();
    let level = |t: f64| match t {
        t if t < 10.0 => 0.0,
        t if t < 60.0 => 5.0,
        t if t < 110.0 => 1.0,
        _ => 0.5,
    };
    let u: Vec<f64> = times.iter().map(|&t| level(t)).collect();
    let input = Excitation::measured(&times, &u, None, crate::model::excitation::Hold::Zoh)
        .expect("changes");
    let y = Model::new(s, v).simulate(&input, &times).unwrap();
    let data = FitData { times, y, input };
    assert_eq!(suggested_structure(&data).code(), "P1D");
}

#[test]
fn the_suggested_structure_follows_the_shape() {
    let code = |d: &FitData| suggested_structure(d).code();
    for noise in [0.002, 0.02] {
        // A first-order heater, with and without a dead time, even at 2 % coloured and
        // quantised noise.
        let heater = shaped(
            "P1D",
            &[(Param::Kp, 0.8), (Param::Tp1, 20.0), (Param::Td, 2.0)],
            noise,
        );
        assert_eq!(code(&heater), "P1D", "noise {noise}");
        let slow = shaped("P1", &[(Param::Kp, -2.0), (Param::Tp1, 150.0)], noise);
        assert_eq!(code(&slow), "P1D", "unsettled, noise {noise}");
        let two = shaped(
            "P2",
            &[(Param::Kp, 1.5), (Param::Tp1, 12.0), (Param::Tp2, 4.0)],
            noise,
        );
        assert_eq!(code(&two), "P1D", "noise {noise}");
        let ringing = shaped(
            "P2U",
            &[(Param::Kp, 2.0), (Param::Tw, 3.0), (Param::Zeta, 0.3)],
            noise,
        );
        assert_eq!(code(&ringing), "P2DU", "noise {noise}");
        let inverse = shaped(
            "P2Z",
            &[
                (Param::Kp, 1.0),
                (Param::Tp1, 10.0),
                (Param::Tp2, 4.0),
                (Param::Tz, -8.0),
            ],
            noise,
        );
        assert_eq!(code(&inverse), "P2Z", "noise {noise}");
        let ramp = shaped("P1I", &[(Param::Kp, 0.1), (Param::Tp1, 5.0)], noise);
        assert_eq!(code(&ramp), "P1DI", "noise {noise}");
    }
}

#[test]
fn guesses_a_p1d_close_to_the_truth() {
    let s = Structure::parse("P1D").unwrap();
    let mut truth = Values::default();
    truth.set(Param::Kp, 2.0);
    truth.set(Param::Tp1, 5.0);
    truth.set(Param::Td, 1.5);
    truth.set(Param::Y0, 10.0);
    let setup = Excitation::step(3.0, 0.5);
    let times: Vec<f64> = (0..300).map(|k| 0.1 * k as f64).collect();
    let y = Model::new(s, truth).simulate(&setup, &times).unwrap();
    let data = FitData {
        times,
        y,
        input: setup,
    };
    let g = auto_guess(&data, s, None);
    assert!((g.get(Param::Y0) - 10.0).abs() < 1e-12);
    assert!(
        (g.get(Param::Kp) - 2.0).abs() < 0.05,
        "{}",
        g.get(Param::Kp)
    );
    assert!(
        (g.get(Param::Tp1) - 5.0).abs() < 0.5,
        "{}",
        g.get(Param::Tp1)
    );
    assert!((g.get(Param::Td) - 1.5).abs() < 0.3, "{}", g.get(Param::Td));
}

#[test]
fn guesses_an_underdamped_pair_from_the_period() {
    let s = Structure::parse("P2U").unwrap();
    let mut truth = Values::default();
    truth.set(Param::Kp, 1.0);
    truth.set(Param::Tw, 1.0 / 0.9659);
    truth.set(Param::Zeta, 0.1948);
    truth.set(Param::Y0, 50.0);
    let setup = Excitation::step(5.0, 10.0);
    let times: Vec<f64> = (0..400).map(|k| 5.0 + 0.1 * k as f64).collect();
    let y = Model::new(s, truth).simulate(&setup, &times).unwrap();
    let data = FitData {
        times,
        y,
        input: setup,
    };
    let g = auto_guess(&data, s, Some(50.0));
    let wn = 1.0 / g.get(Param::Tw);
    assert!((wn - 0.9659).abs() < 0.1, "{wn}");
    assert!(
        (g.get(Param::Zeta) - 0.1948).abs() < 0.05,
        "{}",
        g.get(Param::Zeta)
    );
}

fn noisy(structure: &str, truth: &[(Param, f64)], noise: f64) -> FitData {
    let s = Structure::parse(structure).unwrap();
    let mut v = Values::default();
    for &(p, x) in truth {
        v.set(p, x);
    }
    let setup = Excitation::step(2.0, 1.0);
    let times: Vec<f64> = (0..600).map(|k| 0.1 * k as f64).collect();
    let y = Model::new(s, v).simulate(&setup, &times).unwrap();
    let mut rng = crate::random::Lcg(0x2545_F491_4F6C_DD1D);
    let y = y.iter().map(|y| y + noise * rng.symmetric()).collect();
    FitData {
        times,
        y,
        input: setup,
    }
}

#[test]
fn noise_about_a_settled_level_makes_no_period() {
    let data = noisy(
        "P2",
        &[(Param::Kp, 1.0), (Param::Tp1, 3.0), (Param::Tp2, 1.0)],
        0.02,
    );
    // Many noise crossings of the final level in the tail, but no swing beyond the band.
    assert_eq!(features(&data, Some(0.0)).period, None);
}

#[test]
fn the_period_of_a_noisy_oscillation_is_read_between_swings() {
    // ζ = 0.2, ωn = 2 rad/s: ωd = 1.9596 rad/s, period 3.2064 s.
    let data = noisy(
        "P2U",
        &[(Param::Kp, 1.0), (Param::Tw, 0.5), (Param::Zeta, 0.2)],
        0.01,
    );
    let period = features(&data, Some(0.0)).period.unwrap();
    let exact = std::f64::consts::TAU / (2.0 * (1.0f64 - 0.04).sqrt());
    assert!((period - exact).abs() < 0.05 * exact, "{period} vs {exact}");
}

#[test]
fn an_overshoot_without_oscillation_guesses_a_zero_above_the_lags() {
    // (1 + 20 s) / ((1 + 8 s)(1 + 2 s)): peaks near 1.9 and decays with the 8 s lag.
    let truth = [
        (Param::Kp, 1.0),
        (Param::Tp1, 8.0),
        (Param::Tp2, 2.0),
        (Param::Tz, 20.0),
    ];
    let data = noisy("P2Z", &truth, 0.005);
    let g = auto_guess(&data, Structure::parse("P2Z").unwrap(), Some(0.0));
    let (tp1, tz) = (g.get(Param::Tp1), g.get(Param::Tz));
    // A start, not a fit: the fast lag still adds to the decay read after the peak.
    assert!((tp1 - 8.0).abs() < 0.4 * 8.0, "Tp1 {tp1}");
    assert!(tz > tp1 && (tz - 20.0).abs() < 0.4 * 20.0, "Tz {tz}");
}
