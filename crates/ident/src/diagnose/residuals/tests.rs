//! The tests of [`super`].

use super::*;
use crate::model::excitation::Excitation;
use crate::model::{Structure, Values};

/// Deterministic pseudo-random numbers: a 64-bit LCG (Knuth's MMIX constants) and
/// Box–Muller for normal deviates.
struct Noise(crate::random::Lcg);

impl Noise {
    /// Uniform in (0, 1): never 0, so that its logarithm is finite.
    fn unit(&mut self) -> f64 {
        (self.0.bits() as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (a, b) = (self.unit(), self.unit());
        (-2.0 * a.ln()).sqrt() * (2.0 * std::f64::consts::PI * b).cos()
    }
    fn series(seed: u64, n: usize, sigma: f64) -> Vec<f64> {
        let mut g = Noise(crate::random::Lcg(seed));
        (0..n).map(|_| sigma * g.normal()).collect()
    }
}

fn grid(n: usize, ts: f64) -> Vec<f64> {
    (0..n).map(|k| ts * k as f64).collect()
}

/// Boundaries that put every sample in the transient (no tail: settled ≥ last).
fn all_transient(_times: &[f64]) -> Boundaries {
    Boundaries {
        response_start: f64::NEG_INFINITY,
        settled: f64::INFINITY,
    }
}

#[test]
fn allowed_lags_follow_the_binomial_tail() {
    // 10 lags: P(X > 1) = 0.43 %; 20: P(X > 1) = 1.7 %, P(X > 2) = 0.10 %;
    // 50: P(X > 2) = 1.4 %, P(X > 3) = 0.16 %; 100: P(X > 3) = 1.8 %, P(X > 4) = 0.34 %.
    assert_eq!(allowed_outside(0), 0);
    assert_eq!(allowed_outside(1), 0);
    assert_eq!(allowed_outside(8), 1);
    assert_eq!(allowed_outside(10), 1);
    assert_eq!(allowed_outside(20), 2);
    assert_eq!(allowed_outside(50), 3);
    assert_eq!(allowed_outside(100), 4);
}

#[test]
fn white_noise_is_white() {
    let n = 800;
    let times = grid(n, 0.1);
    let e = Noise::series(7, n, 0.3);
    let a = analyse(&times, &e, None, all_transient(&times));
    assert!((a.band99 - 2.5758293035489 / 800f64.sqrt()).abs() < 1e-9);
    assert_eq!(a.autocorrelation.len(), 51);
    assert_eq!(a.autocorrelation[0], 1.0);
    assert!(a.white, "{:?} {:?}", a.outside_band, a.runs);
    assert!(a.runs.z.abs() < 2.576);
    assert!(a.dominant_period.is_none());
    assert!((a.std - 0.3).abs() < 0.03, "std {}", a.std);
    assert!(a.input_correlation.is_none());
    let region = &a.regions[0];
    assert_eq!(region.n, n);
    assert!(region.mean_z.abs() < 2.576);
    assert!(region.slope_z.abs() < 2.576);
    assert!((region.same_sign_fraction - 0.5).abs() < 0.1);
}

#[test]
fn white_noise_has_no_period_for_many_seeds() {
    let times = grid(800, 0.1);
    for seed in 1..=40 {
        let e = Noise::series(seed, 800, 1.0);
        let a = analyse(&times, &e, None, all_transient(&times));
        assert!(a.dominant_period.is_none(), "seed {seed}: {a:?}");
    }
}

#[test]
fn a_trend_is_not_white() {
    let n = 400;
    let times = grid(n, 0.05);
    let noise = Noise::series(3, n, 0.01);
    let e: Vec<f64> = times
        .iter()
        .zip(&noise)
        .map(|(t, w)| 0.1 * (t - 10.0) + w)
        .collect();
    let a = analyse(&times, &e, None, all_transient(&times));
    let r = &a.regions[0];
    assert!((r.slope - 0.1).abs() < 1e-3, "slope {}", r.slope);
    assert!(r.slope_z > 100.0, "slope_z {}", r.slope_z);
    assert!(a.runs.z < -10.0, "runs z {}", a.runs.z);
    assert!(!a.white);
    assert!(a.outside_band.len() > 40);
    assert!(a.dominant_period.is_none());

    // An exact line: the slope's standard error is (nearly) zero.
    let line: Vec<f64> = times.iter().map(|t| 2.0 * t - 3.0).collect();
    let a = analyse(&times, &line, None, all_transient(&times));
    assert!((a.regions[0].slope - 2.0).abs() < 1e-9);
    assert!(a.regions[0].slope_z > 1e6);
}

#[test]
fn regions_split_at_the_boundaries() {
    // 0, 0.1, …, 10 (101 samples); boundaries 2 and 6.
    let times: Vec<f64> = (0..=100).map(|k| k as f64 / 10.0).collect();
    let e: Vec<f64> = times
        .iter()
        .map(|&t| {
            if t < 2.0 {
                1.0 + 0.1 * (7.0 * t).sin()
            } else if t < 6.0 {
                0.0
            } else {
                -0.5
            }
        })
        .collect();
    let b = Boundaries {
        response_start: 2.0,
        settled: 6.0,
    };
    let a = analyse(&times, &e, None, b);
    let kinds: Vec<RegionKind> = a.regions.iter().map(|r| r.kind).collect();
    assert_eq!(
        kinds,
        [
            RegionKind::BeforeResponse,
            RegionKind::Transient,
            RegionKind::Tail
        ]
    );
    let counts: Vec<usize> = a.regions.iter().map(|r| r.n).collect();
    assert_eq!(counts, [20, 40, 41]);
    assert_eq!((a.regions[0].start, a.regions[0].end), (0.0, 2.0));
    assert_eq!((a.regions[1].start, a.regions[1].end), (2.0, 6.0));
    assert_eq!((a.regions[2].start, a.regions[2].end), (6.0, 10.0));
    // Before: a clear positive bias, every residual positive.
    assert!(a.regions[0].mean > 0.9 && a.regions[0].mean_z > 20.0);
    assert_eq!(a.regions[0].same_sign_fraction, 1.0);
    // Transient: all zero.
    assert_eq!(a.regions[1].mean, 0.0);
    assert_eq!(a.regions[1].mean_z, 0.0);
    assert_eq!(a.regions[1].slope_z, 0.0);
    assert_eq!(a.regions[1].rms, 0.0);
    assert_eq!(a.regions[1].same_sign_fraction, 0.0);
    // Tail: constant −0.5, so the bias is certain.
    assert_eq!(a.regions[2].mean, -0.5);
    assert_eq!(a.regions[2].rms, 0.5);
    assert_eq!(a.regions[2].mean_z, f64::NEG_INFINITY);
    assert_eq!(a.regions[2].slope, 0.0);
    assert_eq!(a.regions[2].same_sign_fraction, 1.0);

    // Empty regions are left out: a boundary at the first sample.
    let b = Boundaries {
        response_start: -5.0,
        settled: 6.0,
    };
    let a = analyse(&times, &e, None, b);
    let counts: Vec<(RegionKind, usize)> = a.regions.iter().map(|r| (r.kind, r.n)).collect();
    assert_eq!(
        counts,
        [(RegionKind::Transient, 60), (RegionKind::Tail, 41)]
    );
}

#[test]
fn region_mean_z_and_slope_z_match_hand_computation() {
    // e = 1, 2, 3, 6 at t = 0, 1, 2, 3.
    let t = [0.0, 1.0, 2.0, 3.0];
    let e = [1.0, 2.0, 3.0, 6.0];
    let r = region_stats(RegionKind::Transient, 0.0, 3.0, &t, &e);
    // mean 3, s² = (4 + 1 + 0 + 9)/3 = 14/3, t = 3/√(14/3/4).
    assert_eq!(r.mean, 3.0);
    assert!((r.mean_z - 3.0 / (14.0f64 / 12.0).sqrt()).abs() < 1e-12);
    // Sxx = 5, Sxy = (−1.5)(−2) + (−0.5)(−1) + (0.5)(0) + 1.5·3 = 8 → b = 1.6.
    assert!((r.slope - 1.6).abs() < 1e-12);
    // Fit: 3 + 1.6(t − 1.5) = 0.6, 2.2, 3.8, 5.4; SSR = 0.16 + 0.04 + 0.64 + 0.36 = 1.2.
    let se = (1.2f64 / 2.0 / 5.0).sqrt();
    assert!((r.slope_z - 1.6 / se).abs() < 1e-9);
    assert!((r.rms - (50.0f64 / 4.0).sqrt()).abs() < 1e-12);
    assert_eq!(r.same_sign_fraction, 1.0);
}

#[test]
fn runs_test_matches_the_textbook() {
    // + + − − + −: runs 4, n₊ = n₋ = 3, E = 1 + 18/6 = 4, z = 0.
    let r = runs_test(&[1.0, 2.0, -1.0, -0.5, 3.0, -2.0]);
    assert_eq!(r.runs, 4);
    assert!((r.expected - 4.0).abs() < 1e-12);
    assert!(r.z.abs() < 1e-12);

    // + + + + − − with a zero dropped: runs 2, n₊ = 4, n₋ = 2, n = 6.
    // E = 1 + 16/6, Var = 16·(16 − 6)/(36·5).
    let r = runs_test(&[1.0, 1.0, 0.0, 1.0, 1.0, -1.0, -1.0]);
    assert_eq!(r.runs, 2);
    let expected = 1.0 + 16.0 / 6.0;
    let var = 16.0 * 10.0 / (36.0 * 5.0);
    assert!((r.expected - expected).abs() < 1e-12);
    assert!((r.z - (2.0 - expected) / f64::sqrt(var)).abs() < 1e-12);

    // Alternating signs: too many runs, z > 0.
    let alt: Vec<f64> = (0..40)
        .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
        .collect();
    let r = runs_test(&alt);
    assert_eq!(r.runs, 40);
    assert!(r.z > 5.0);

    // All one sign, or nothing: no variance, z = 0.
    assert_eq!(runs_test(&[1.0, 2.0, 3.0]).z, 0.0);
    assert_eq!(runs_test(&[1.0, 2.0, 3.0]).runs, 1);
    let none = runs_test(&[0.0, 0.0]);
    assert_eq!((none.runs, none.expected, none.z), (0, 0.0, 0.0));
}

#[test]
fn residuals_equal_to_the_input_deviation_correlate_fully() {
    let n = 200;
    let times = grid(n, 0.1);
    let u: Vec<f64> = times
        .iter()
        .map(|&t| if t >= 5.0 { 3.0 } else { 1.0 } + 0.2 * (1.3 * t).sin())
        .collect();
    let um = u.iter().sum::<f64>() / n as f64;
    let e: Vec<f64> = u.iter().map(|v| v - um).collect();
    let a = analyse(&times, &e, Some(&u), all_transient(&times));
    let c = a.input_correlation.expect("an input was given");
    assert_eq!(c.len(), a.autocorrelation.len());
    assert!((c[0] - 1.0).abs() < 1e-12);
    // With a negated copy: −1.
    let neg: Vec<f64> = e.iter().map(|v| -v).collect();
    let a = analyse(&times, &neg, Some(&u), all_transient(&times));
    assert!((a.input_correlation.unwrap()[0] + 1.0).abs() < 1e-12);
    // A constant input carries no information: zeros.
    let flat = vec![2.0; n];
    let a = analyse(&times, &e, Some(&flat), all_transient(&times));
    assert!(a.input_correlation.unwrap().iter().all(|c| *c == 0.0));
}

#[test]
fn autocorrelation_of_a_known_sequence() {
    // e = 1, −1, 1, −1, … (N = 16, max_lag = 4): rₖ = (−1)ᵏ(16 − k)/16, all beyond the
    // band 2.576/4.
    let e: Vec<f64> = (0..16)
        .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
        .collect();
    let times = grid(16, 1.0);
    let a = analyse(&times, &e, None, all_transient(&times));
    assert_eq!(a.autocorrelation, vec![1.0, -0.9375, 0.875, -0.8125, 0.75]);
    assert!((a.band99 - 2.5758293035489 / 4.0).abs() < 1e-8);
    assert_eq!(a.outside_band, vec![1, 2, 3, 4]);
    assert!(!a.white);
    assert!(a.runs.z > 3.0);
}

#[test]
fn damped_oscillation_period_is_found() {
    let ts = 0.1;
    let n = 600;
    let times = grid(n, ts);
    for (seed, tau, sigma) in [
        (1, 15.0, 0.05),
        (2, 8.0, 0.1),
        (3, 30.0, 0.2),
        (4, 15.0, 0.0),
    ] {
        let noise = Noise::series(seed, n, sigma);
        let e: Vec<f64> = times
            .iter()
            .zip(&noise)
            .map(|(&t, w)| (-t / tau).exp() * (2.0 * std::f64::consts::PI * t / 7.0).sin() + w)
            .collect();
        let a = analyse(&times, &e, None, all_transient(&times));
        let p = a.dominant_period.expect("an oscillation");
        assert!((p - 7.0).abs() < 0.05 * 7.0, "τ = {tau}, σ = {sigma}: {p}");
        assert!(!a.white);
    }
}

#[test]
fn oscillation_on_a_bias_is_found() {
    let times = grid(600, 0.1);
    let noise = Noise::series(11, 600, 0.02);
    let e: Vec<f64> = times
        .iter()
        .zip(&noise)
        .map(|(&t, w)| 0.3 + 0.1 * (2.0 * std::f64::consts::PI * t / 4.0).sin() + w)
        .collect();
    let a = analyse(&times, &e, None, all_transient(&times));
    let p = a.dominant_period.expect("an oscillation");
    assert!((p - 4.0).abs() < 0.05 * 4.0, "{p}");
}

#[test]
fn a_single_bump_has_no_period() {
    let ts = 0.1;
    let n = 300;
    let times = grid(n, ts);
    let bump: Vec<f64> = times
        .iter()
        .map(|&t| (-t).exp() * (1.0 - (-t).exp()))
        .collect();
    let m = bump.iter().sum::<f64>() / n as f64;
    for (seed, sigma) in [(5, 0.0), (6, 0.005), (7, 0.02)] {
        let noise = Noise::series(seed, n, sigma);
        let raw: Vec<f64> = bump.iter().zip(&noise).map(|(b, w)| b + w).collect();
        let centred: Vec<f64> = raw.iter().map(|v| v - m).collect();
        for e in [raw, centred] {
            let a = analyse(&times, &e, None, all_transient(&times));
            assert!(a.dominant_period.is_none(), "σ = {sigma}: {a:?}");
            assert!(!a.white);
        }
    }
    // A bump after a dead time, in the middle of a longer record.
    let times = grid(1000, ts);
    let e: Vec<f64> = times
        .iter()
        .map(|&t| {
            let s = (t - 20.0).max(0.0) / 3.0;
            (-s).exp() * (1.0 - (-s).exp())
        })
        .collect();
    let a = analyse(&times, &e, None, all_transient(&times));
    assert!(a.dominant_period.is_none());
}

#[test]
fn degenerate_inputs_do_not_panic() {
    // Nothing at all.
    let a = analyse(&[], &[], Some(&[]), all_transient(&[]));
    assert!(a.regions.is_empty());
    assert_eq!(a.autocorrelation, vec![1.0]);
    assert_eq!(a.band99, 0.0);
    assert!(a.white);
    assert_eq!(a.std, 0.0);
    assert_eq!(a.input_correlation, Some(vec![0.0]));
    assert!(a.dominant_period.is_none());

    // One, two, three samples.
    for n in 1..4 {
        let times = grid(n, 1.0);
        let e: Vec<f64> = (0..n).map(|i| i as f64 - 0.7).collect();
        let a = analyse(&times, &e, None, all_transient(&times));
        assert_eq!(a.autocorrelation, vec![1.0]);
        assert!(a.outside_band.is_empty());
        assert_eq!(a.regions.iter().map(|r| r.n).sum::<usize>(), n);
        assert!(a.dominant_period.is_none());
    }

    // All zeros: white, zero statistics.
    let times = grid(100, 0.1);
    let zeros = vec![0.0; 100];
    let a = analyse(&times, &zeros, Some(&times), all_transient(&times));
    assert!(a.white);
    assert_eq!(a.std, 0.0);
    assert!(a.autocorrelation[1..].iter().all(|r| *r == 0.0));
    assert_eq!(a.autocorrelation[0], 1.0);
    assert!(a.input_correlation.unwrap().iter().all(|c| *c == 0.0));
    assert_eq!(a.runs.runs, 0);
    assert!(a.dominant_period.is_none());
    let r = &a.regions[0];
    assert_eq!(
        (r.mean, r.mean_z, r.slope, r.slope_z, r.rms),
        (0.0, 0.0, 0.0, 0.0, 0.0)
    );

    // Constant residuals: a bias, not white, no period.
    let ones = vec![1.0; 100];
    let a = analyse(&times, &ones, None, all_transient(&times));
    assert!(!a.white);
    assert_eq!(a.std, 0.0);
    assert!(a.dominant_period.is_none());
    assert_eq!(a.regions[0].mean_z, f64::INFINITY);
    assert_eq!(a.regions[0].slope_z, 0.0);

    // All samples at one instant; mismatched lengths; a short input.
    let same = vec![1.0; 10];
    let e = Noise::series(2, 10, 1.0);
    let a = analyse(&same, &e, Some(&e[..3]), all_transient(&same));
    assert_eq!(a.regions.len(), 1);
    assert_eq!(a.regions[0].slope, 0.0);
    assert_eq!(a.regions[0].slope_z, 0.0);
    assert!(a.dominant_period.is_none());
    let a = analyse(&grid(5, 1.0), &e, None, all_transient(&grid(5, 1.0)));
    assert_eq!(a.regions[0].n, 5);

    // Boundaries in the wrong order or outside the record are clamped.
    let times = grid(11, 1.0);
    let e = Noise::series(4, 11, 1.0);
    let b = Boundaries {
        response_start: 8.0,
        settled: 3.0,
    };
    let a = analyse(&times, &e, None, b);
    let counts: Vec<(RegionKind, usize)> = a.regions.iter().map(|r| (r.kind, r.n)).collect();
    assert_eq!(
        counts,
        [(RegionKind::BeforeResponse, 8), (RegionKind::Tail, 3)]
    );
    let b = Boundaries {
        response_start: f64::NAN,
        settled: 1e9,
    };
    let a = analyse(&times, &e, None, b);
    let counts: Vec<(RegionKind, usize)> = a.regions.iter().map(|r| (r.kind, r.n)).collect();
    assert_eq!(counts, [(RegionKind::Transient, 11)]);
    // The response starts at the last sample: everything is before it.
    let b = Boundaries {
        response_start: 10.0,
        settled: 10.0,
    };
    let a = analyse(&times, &e, None, b);
    let counts: Vec<(RegionKind, usize)> = a.regions.iter().map(|r| (r.kind, r.n)).collect();
    assert_eq!(counts, [(RegionKind::BeforeResponse, 11)]);
}

fn data(times: Vec<f64>, t0: f64) -> FitData {
    let y = vec![0.0; times.len()];
    FitData {
        times,
        y,
        input: Excitation::step(t0, 2.0),
    }
}

#[test]
fn boundaries_follow_dead_time_and_settling_time() {
    let times = grid(401, 0.1); // 0 … 40 s
    // P1D: Tp1 = 2, Td = 1.5, step at 5 s: starts at 6.5, settles at 6.5 + 2·ln 50.
    let mut v = Values::default();
    v.set(Param::Kp, 1.5);
    v.set(Param::Tp1, 2.0);
    v.set(Param::Td, 1.5);
    let model = Model::new(Structure::parse("P1D").unwrap(), v);
    let b = boundaries(&model, &data(times.clone(), 5.0));
    assert!((b.response_start - 6.5).abs() < 1e-12);
    assert!((b.settled - (6.5 + 2.0 * 50f64.ln())).abs() < 1e-9, "{b:?}");

    // Without D the dead time value is ignored.
    let model = Model::new(Structure::parse("P1").unwrap(), v);
    let b = boundaries(&model, &data(times.clone(), 5.0));
    assert_eq!(b.response_start, 5.0);
    assert!((b.settled - (5.0 + 2.0 * 50f64.ln())).abs() < 1e-9);

    // A slow model settles after the record ends: clamped to the last sample.
    v.set(Param::Tp1, 50.0);
    let model = Model::new(Structure::parse("P1D").unwrap(), v);
    let b = boundaries(&model, &data(times.clone(), 5.0));
    assert_eq!(b.settled, 40.0);

    // An integrator never settles.
    v.set(Param::Tp1, 1.0);
    let model = Model::new(Structure::parse("P1DI").unwrap(), v);
    let b = boundaries(&model, &data(times.clone(), 5.0));
    assert!((b.response_start - 6.5).abs() < 1e-12);
    assert_eq!(b.settled, 40.0);

    // A dead time beyond the record: both at the last sample.
    v.set(Param::Td, 100.0);
    let model = Model::new(Structure::parse("P1D").unwrap(), v);
    let b = boundaries(&model, &data(times.clone(), 5.0));
    assert_eq!((b.response_start, b.settled), (40.0, 40.0));

    // An invalid model (Tp1 ≤ 0) and an empty record do not panic.
    v.set(Param::Tp1, -1.0);
    v.set(Param::Td, 1.0);
    let model = Model::new(Structure::parse("P1D").unwrap(), v);
    let b = boundaries(&model, &data(times, 5.0));
    assert_eq!(b.settled, 40.0);
    let b = boundaries(&model, &data(Vec::new(), 5.0));
    assert_eq!((b.response_start, b.settled), (5.0, 5.0));
}

#[test]
fn fitted_residuals_of_an_underdamped_process_show_its_period() {
    // A P1 "model" of an underdamped process: the residuals oscillate at ωd.
    let times = grid(600, 0.1);
    let setup = Excitation::step(2.0, 1.0);
    let mut v = Values::default();
    v.set(Param::Tw, 1.0);
    v.set(Param::Zeta, 0.1);
    let process = Model::new(Structure::parse("P2U").unwrap(), v);
    let y = process.simulate(&setup, &times).unwrap();
    let mut m = Values::default();
    m.set(Param::Tp1, 1.0);
    let model = Model::new(Structure::parse("P1").unwrap(), m);
    let yhat = model.simulate(&setup, &times).unwrap();
    let e: Vec<f64> = y.iter().zip(&yhat).map(|(a, b)| a - b).collect();
    let d = FitData {
        times: times.clone(),
        y,
        input: setup,
    };
    let a = analyse(&times, &e, None, boundaries(&model, &d));
    let period = 2.0 * std::f64::consts::PI / (1.0f64 - 0.01).sqrt();
    let p = a.dominant_period.expect("an oscillation");
    assert!((p - period).abs() < 0.05 * period, "{p} vs {period}");
    assert_eq!(a.regions.len(), 3);
}
