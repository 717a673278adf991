//! The hand methods (`degrau_ident::hand`) against closed forms: exact FOPDT and
//! second-order records (steps between samples, operating points far from zero), the exact
//! inflection tangent of an overdamped second-order curve, Mollenkamp's three points on
//! SOPTD records across the notes' damping range, noisy and quantised records, and the
//! typed refusals.

use degrau_ident::fit::FitData;
use degrau_ident::hand::{
    DeadTimeFrom, HandError, HandEstimate, HandMethod, HandWarning, Overrides, Record, estimate,
    estimate_all,
};
use degrau_ident::model::excitation::{Excitation, Hold};
use degrau_ident::random::Lcg;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// A normalised unit step response s(t) of the process without dead time, for t ≥ 0.
type Shape = dyn Fn(f64) -> f64;

fn first_order(tau: f64) -> impl Fn(f64) -> f64 {
    move |t| 1.0 - (-t / tau).exp()
}

/// (τ1 s + 1)(τ2 s + 1), τ1 ≠ τ2.
fn two_lags(t1: f64, t2: f64) -> impl Fn(f64) -> f64 {
    move |t| 1.0 - (t1 * (-t / t1).exp() - t2 * (-t / t2).exp()) / (t1 - t2)
}

/// ωn²/(s² + 2ζωn s + ωn²), any ζ > 0.
fn second_order(zeta: f64, wn: f64) -> impl Fn(f64) -> f64 {
    move |t| {
        let a = zeta * wn;
        if (zeta - 1.0).abs() < 1e-9 {
            1.0 - (1.0 + wn * t) * (-wn * t).exp()
        } else if zeta < 1.0 {
            let wd = wn * (1.0 - zeta * zeta).sqrt();
            1.0 - (-a * t).exp() * ((wd * t).cos() + a / wd * (wd * t).sin())
        } else {
            let r = wn * (zeta * zeta - 1.0).sqrt();
            let (p1, p2) = (-a + r, -a - r);
            1.0 - (p2 * (p1 * t).exp() - p1 * (p2 * t).exp()) / (p2 - p1)
        }
    }
}

/// A record of y0 + K Δu s(t − ts − θ), the true step at `ts` between samples `h` apart
/// (the record says t0 = the first sample at or after it), over `length` seconds.
struct Case {
    k: f64,
    du: f64,
    y0: f64,
    theta: f64,
    ts: f64,
    h: f64,
    length: f64,
}

impl Case {
    fn samples(&self, shape: &Shape) -> (Vec<f64>, Vec<f64>) {
        let n = (self.length / self.h) as usize + 1;
        let times: Vec<f64> = (0..n).map(|i| i as f64 * self.h).collect();
        let y = times
            .iter()
            .map(|&t| {
                let s = t - self.ts - self.theta;
                self.y0
                    + if s > 0.0 {
                        self.k * self.du * shape(s)
                    } else {
                        0.0
                    }
            })
            .collect();
        (times, y)
    }

    fn t0(&self) -> f64 {
        (self.ts / self.h).ceil() * self.h
    }

    fn record(&self, shape: &Shape) -> Record {
        let (times, y) = self.samples(shape);
        Record::new(&times, &y, self.t0(), self.du, self.y0).expect("a record")
    }

    /// The record with noise `sigma` (share of |K Δu|): white, AR(1) coloured (a = 0.8),
    /// quantised to `q`, and two outliers; the step read from a logged input column.
    fn noisy(&self, shape: &Shape, sigma: f64, q: f64, seed: u64) -> Record {
        let (times, mut y) = self.samples(shape);
        let mut rng = Lcg(seed);
        let scale = sigma * (self.k * self.du).abs();
        let mut coloured = 0.0;
        for v in y.iter_mut() {
            let white = gauss(&mut rng);
            coloured = 0.8 * coloured + 0.6 * gauss(&mut rng);
            *v += scale * std::f64::consts::FRAC_1_SQRT_2 * (white + coloured);
            if q > 0.0 {
                *v = (*v / q).round() * q;
            }
        }
        let n = y.len();
        y[n / 3] += 20.0 * scale.max(q);
        y[2 * n / 3] -= 20.0 * scale.max(q);
        let u: Vec<f64> = times
            .iter()
            .map(|&t| if t >= self.t0() { 30.0 + self.du } else { 30.0 })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).expect("a step");
        let data = FitData { times, y, input };
        Record::from_fit_data(&data, None).expect("a record")
    }
}

fn gauss(rng: &mut Lcg) -> f64 {
    let (a, b) = (rng.unit().max(1e-300), rng.unit());
    (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
}

fn close(what: &str, got: f64, want: f64, share: f64) {
    assert!(
        (got - want).abs() <= share * want.abs(),
        "{what}: {got} vs {want} (allowed {} %)",
        100.0 * share
    );
}

/// The exact FOPDT of every test below: τ = 40 s, θ = 12 s, the step at 7.3 s between
/// samples 0.08 s apart (τ/500), y0 = 350, K = −1.7 per unit of a step of −4.
fn fopdt_case() -> Case {
    Case {
        k: -1.7,
        du: -4.0,
        y0: 350.0,
        theta: 12.0,
        ts: 7.33,
        h: 0.08,
        length: 7.33 + 12.0 + 8.0 * 40.0,
    }
}

#[test]
fn methods_exact_on_a_fopdt_are_within_one_percent() {
    let case = fopdt_case();
    let record = case.record(&first_order(40.0));
    // The record's t0 is the sample after the true step: θ as read includes that gap.
    let theta = case.theta + case.ts - case.t0();
    for (method, result) in estimate_all(&record, &Overrides::default()) {
        if method.second_order() {
            continue;
        }
        let e = result.unwrap_or_else(|err| panic!("{method:?}: {err}"));
        close(&format!("{method:?} K"), e.k, case.k, 0.01);
        close(&format!("{method:?} τ"), e.tau.unwrap(), 40.0, 0.01);
        close(&format!("{method:?} θ"), e.theta, theta, 0.01);
        assert!(e.fit_percent > 98.0, "{method:?}: {}", e.fit_percent);
    }
    // θ from the first departure: the curve leaves y0 by 2 % at θ + τ ln(1/0.98).
    let departure = Overrides {
        dead_time_from: DeadTimeFrom::FirstDeparture,
        ..Overrides::default()
    };
    let e = estimate(&record, HandMethod::SixtyThree, &departure).unwrap();
    close(
        "θ departure",
        e.theta,
        theta + 40.0 * (1.0 / 0.98f64).ln(),
        0.01,
    );
}

#[test]
fn the_tangent_of_an_overdamped_curve_is_its_inflection_tangent() {
    // τ1 = 30, τ2 = 8: the inflection at t* = τ1τ2/(τ1 − τ2)·ln(τ1/τ2) after θ.
    let (t1, t2) = (30.0, 8.0);
    let case = Case {
        k: 2.5,
        du: 10.0,
        y0: -120.0,
        theta: 5.0,
        ts: 3.0,
        h: 0.05,
        length: 3.0 + 5.0 + 10.0 * t1,
    };
    let s = two_lags(t1, t2);
    let record = case.record(&s);
    let star = t1 * t2 / (t1 - t2) * (t1 / t2).ln();
    let slope = ((-star / t1).exp() - (-star / t2).exp()) / (t1 - t2);
    let start = case.theta + star - s(star) / slope;
    let end = case.theta + star + (1.0 - s(star)) / slope;
    let e = estimate(&record, HandMethod::Tangent, &Overrides::default()).unwrap();
    let gap = case.t0() - case.ts;
    close("tangent θ", e.theta, start - gap, 0.01);
    close("tangent τ", e.tau.unwrap(), end - start, 0.01);
    // 63.2 %: the exact t63 (bisection on the closed form) minus the tangent's θ.
    let t63 = bisect(&s, 0.632) + case.theta;
    let e = estimate(&record, HandMethod::SixtyThree, &Overrides::default()).unwrap();
    close("63 % τ", e.tau.unwrap(), t63 - start, 0.01);
    // Smith's FOPTD passes through the curve's own 28.3 % and 63.2 % points.
    let e = estimate(&record, HandMethod::Smith, &Overrides::default()).unwrap();
    let (tau, theta) = (e.tau.unwrap(), e.theta + gap);
    close(
        "Smith 28.3 %",
        theta + tau * (1.0 / (1.0 - 0.283f64)).ln(),
        bisect(&s, 0.283) + case.theta,
        0.005,
    );
    close(
        "Smith 63.2 %",
        theta + tau * (1.0 / (1.0 - 0.632f64)).ln(),
        t63,
        0.005,
    );
    // The level-reading methods bracket the truth the usual way: θ between the true dead
    // time and it plus τ2, τ between τ1 and τ1 + τ2 (the lag τ2 read as dead time). The
    // tangent's own τ is longer (checked against the closed form above).
    for (method, result) in estimate_all(&record, &Overrides::default()) {
        if method.second_order() || method == HandMethod::Tangent {
            continue;
        }
        let e = result.unwrap();
        assert!(
            e.theta > case.theta - gap && e.theta < case.theta + t2,
            "{method:?} θ {}",
            e.theta
        );
        assert!(
            e.tau.unwrap() > 0.9 * t1 && e.tau.unwrap() < 1.1 * (t1 + t2),
            "{method:?} τ {}",
            e.tau.unwrap()
        );
    }
}

/// The first t with s(t) ≥ level, by bisection on [0, 1e4].
fn bisect(s: &dyn Fn(f64) -> f64, level: f64) -> f64 {
    let (mut a, mut b) = (0.0, 1e4);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if s(m) < level { a = m } else { b = m }
    }
    0.5 * (a + b)
}

#[test]
fn three_points_read_a_soptd_across_the_notes_damping_range() {
    // Mollenkamp's correlations are curve fits and no one publishes their error: the notes
    // say "boas estimativas para 0.707 ≤ ξ ≤ 3.0". Evaluated on exact curves (a bisection
    // of the closed forms, independent of this crate), they read ζ and ωn within 3 % for
    // 0.707 ≤ ζ ≤ 1.3 (worst: ζ 1.3 read 1.263, ωn 2.4 % low), but ζ = 2 reads 2.57 and from
    // ζ ≈ 2.5 on the ratio x = (t45 − t15)/(t75 − t15) is within 3e-4 of the formula's pole
    // 0.356 (x → 0.3557, the first-order value, as ζ grows), so ζ is meaningless there.
    // Tested: ζ, ωn within 3 % and θ within 2 % of the slowest time plus 5 % of θ on
    // 0.707–1.3, the fit % above 99; ζ = 2.5 and 3 refused as first-order-like.
    for &zeta in &[0.707f64, 0.8, 1.0, 1.3, 2.5, 3.0] {
        let wn = 0.2;
        let case = Case {
            k: 0.8,
            du: 25.0,
            y0: 1013.0,
            theta: 4.0,
            ts: 2.02,
            h: 0.02,
            length: 2.02 + 4.0 + 80.0 * zeta.max(1.0) / wn,
        };
        let record = case.record(&second_order(zeta, wn));
        let result = estimate(&record, HandMethod::ThreePoint, &Overrides::default());
        if zeta > 2.0 {
            assert!(
                matches!(result, Err(HandError::ThreePointShape { .. })),
                "ζ {zeta}: {result:?}"
            );
            continue;
        }
        let e = result.unwrap();
        let so = e.second_order.unwrap();
        close(&format!("ζ {zeta}"), so.zeta, zeta, 0.03);
        close(&format!("ωn {zeta}"), so.omega_n, wn, 0.03);
        let slowest = 1.0 / (zeta * wn) + (zeta * zeta - 1.0).max(0.0).sqrt() / wn;
        let theta = case.theta + case.ts - case.t0();
        assert!(
            (e.theta - theta).abs() < 0.02 * slowest + 0.05 * theta,
            "θ at ζ {zeta}: {} vs {theta}",
            e.theta
        );
        close(&format!("K {zeta}"), e.k, case.k, 1e-3);
        assert!(e.fit_percent > 99.0, "ζ {zeta}: fit {}", e.fit_percent);
        assert_eq!(so.tau1.is_some(), so.zeta >= 1.0);
        if let (Some(t1), Some(t2)) = (so.tau1, so.tau2) {
            close(
                "τ1τ2 = 1/ωn²",
                t1 * t2,
                1.0 / (so.omega_n * so.omega_n),
                1e-9,
            );
        }
        let (low, high) = degrau_ident::hand::THREE_POINT_ZETA;
        assert_eq!(
            e.warnings.is_empty(),
            (low..=high).contains(&so.zeta),
            "{:?}",
            e.warnings
        );
    }
    // Outside the range: ζ = 0.4 is read, with the notes' warning.
    let case = Case {
        k: 1.0,
        du: 1.0,
        y0: 5.0,
        theta: 1.0,
        ts: 0.0,
        h: 0.01,
        length: 200.0,
    };
    let e = estimate(
        &case.record(&second_order(0.4, 0.5)),
        HandMethod::ThreePoint,
        &Overrides::default(),
    )
    .unwrap();
    assert!(matches!(
        e.warnings[..],
        [HandWarning::DampingOutsideRange { .. }]
    ));
}

#[test]
fn noisy_records_stay_sensible() {
    let case = fopdt_case();
    let theta = case.theta + case.ts - case.t0();
    let shape = first_order(40.0);
    // (noise share, quantum, allowed share on τ and on θ + τ/10 for the reading methods)
    for &(sigma, q, share) in &[(0.002, 0.0, 0.05), (0.02, 0.05, 0.2)] {
        for seed in [1, 7, 42] {
            let record = case.noisy(&shape, sigma, q, seed);
            for (method, result) in estimate_all(&record, &Overrides::default()) {
                if method.second_order() {
                    continue;
                }
                let e = result.unwrap_or_else(|err| panic!("{method:?} σ {sigma}: {err}"));
                close(&format!("{method:?} K σ {sigma}"), e.k, case.k, 0.03);
                close(
                    &format!("{method:?} τ σ {sigma}"),
                    e.tau.unwrap(),
                    40.0,
                    share,
                );
                assert!(
                    (e.theta - theta).abs() < share * (theta + 4.0),
                    "{method:?} θ σ {sigma} seed {seed}: {} vs {theta}",
                    e.theta
                );
                assert!(e.fit_percent > 90.0, "{method:?}: {}", e.fit_percent);
            }
        }
    }
}

#[test]
fn records_without_a_rise_or_too_short_are_refused() {
    let case = fopdt_case();
    // A flat record with noise: no rise.
    let flat = case.noisy(&|_| 0.0, 0.0, 0.0, 3);
    let (times, mut y) = case.samples(&|_| 0.0);
    let mut rng = Lcg(9);
    for v in y.iter_mut() {
        *v += 0.01 * gauss(&mut rng);
    }
    let noisy_flat = Record::new(&times, &y, case.t0(), case.du, case.y0).unwrap();
    for record in [flat, noisy_flat] {
        assert!(matches!(
            estimate(&record, HandMethod::Tangent, &Overrides::default()),
            Err(HandError::NoRise { .. })
        ));
    }
    // Cut at 1.2 time constants after the dead time: not settled, unless the student gives
    // the final level.
    let short = Case {
        length: case.ts + case.theta + 48.0,
        ..fopdt_case()
    };
    let record = short.record(&first_order(40.0));
    assert!(matches!(
        estimate(&record, HandMethod::Smith, &Overrides::default()),
        Err(HandError::NotSettled { .. })
    ));
    let given = Overrides {
        y_final: Some(case.y0 + case.k * case.du),
        ..Overrides::default()
    };
    let e = estimate(&record, HandMethod::Smith, &given).unwrap();
    close("τ with the final level given", e.tau.unwrap(), 40.0, 0.01);
    // The three-point method then needs 75 %, reached only at 1.39 τ.
    assert!(matches!(
        estimate(&record, HandMethod::ThreePoint, &given),
        Err(HandError::LevelNotReached { percent }) if percent == 75.0
    ));
    // Too few samples after the step.
    assert!(matches!(
        Record::new(&[0.0, 1.0, 2.0, 3.0], &[1.0, 1.0, 2.0, 3.0], 1.0, 1.0, 1.0),
        Err(HandError::TooFewSamples { n: 3, .. })
    ));
    assert!(matches!(
        Record::new(&times, &y, case.t0(), 0.0, case.y0),
        Err(HandError::NoStep(_))
    ));
    // Two input changes: a hand method reads one step.
    let u: Vec<f64> = times
        .iter()
        .map(|&t| {
            if t > 100.0 {
                2.0
            } else if t > 50.0 {
                1.0
            } else {
                0.0
            }
        })
        .collect();
    let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
    let data = FitData { times, y, input };
    assert!(matches!(
        Record::from_fit_data(&data, None),
        Err(HandError::SeveralChanges { count: 2 })
    ));
}

#[test]
fn the_tclab_copy_gives_every_method() {
    let text = std::fs::read_to_string(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/tests/data/records/tclab_step_q1_50_synthetic.csv"
    ))
    .unwrap();
    let test = degrau_ident::record::data::load_str(&text, &Default::default()).unwrap();
    let u = test.input.clone().unwrap();
    let input = Excitation::measured(&test.time, &u, None, Hold::Zoh).unwrap();
    let data = FitData {
        times: test.time.clone(),
        y: test.output.clone(),
        input,
    };
    let record = Record::from_fit_data(&data, None).unwrap();
    assert_eq!(record.y0, 20.9);
    for (method, result) in estimate_all(&record, &Overrides::default()) {
        let e = result.unwrap_or_else(|err| panic!("{method:?}: {err}"));
        // The stand-in's process: 0.69537/((19.689s + 1)(141.41s + 1)).
        close(&format!("{method:?} K"), e.k, 0.69537, 0.03);
        // The tangent reads an overdamped curve slow; the level-reading methods fit well.
        let least = if method == HandMethod::Tangent {
            65.0
        } else {
            90.0
        };
        assert!(e.fit_percent > least, "{method:?}: {}", e.fit_percent);
        if let Some(tau) = e.tau {
            assert!(tau > 120.0 && tau < 200.0, "{method:?} τ {tau}");
        }
        // The stand-in has no dead time; a second-order reading may put θ a little negative.
        assert!(
            e.theta > -10.0 && e.theta < 40.0,
            "{method:?} θ {}",
            e.theta
        );
    }
}

/// `record` with its output and its input both multiplied by `scale`.
fn scaled(record: &Record, scale: f64) -> Record {
    let data = FitData {
        times: record.data.times.clone(),
        y: record.data.y.iter().map(|v| v * scale).collect(),
        input: record.data.input.rescaled(0.0, 1.0, 1.0 / scale),
    };
    Record {
        data,
        y0: record.y0 * scale,
    }
}

/// A method's reading against the unit record's: K, τ, ζ, ωn, τ1, τ2 to 1e-9 of themselves,
/// θ to 1e-9 of the record's length, the fit % to 1e-7, the same warnings' kinds.
fn same_reading(got: &HandEstimate, unit: &HandEstimate, length: f64) {
    let at = format!("{:?}: {got:?} vs {unit:?}", unit.method);
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-9 * y.abs();
    assert!(near(got.k, unit.k), "K {at}");
    assert!((got.theta - unit.theta).abs() <= 1e-9 * length, "θ {at}");
    assert!(
        (got.fit_percent - unit.fit_percent).abs() < 1e-7,
        "fit % {at}"
    );
    assert_eq!(got.tau.is_some(), unit.tau.is_some(), "{at}");
    let tau = got.tau.zip(unit.tau);
    assert!(tau.is_none_or(|(x, y)| near(x, y)), "τ {at}");
    if let (Some(g), Some(u)) = (got.second_order, unit.second_order) {
        assert!(
            near(g.zeta, u.zeta) && near(g.omega_n, u.omega_n),
            "ζ, ωn {at}"
        );
        for (x, y) in [(g.tau1, u.tau1), (g.tau2, u.tau2)] {
            assert!(x.zip(y).is_none_or(|(x, y)| near(x, y)), "τ1, τ2 {at}");
        }
    }
    let kinds = |e: &HandEstimate| {
        e.warnings
            .iter()
            .map(std::mem::discriminant)
            .collect::<Vec<_>>()
    };
    assert_eq!(kinds(got), kinds(unit), "warnings {at}");
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 32,
        rng_seed: RngSeed::Fixed(0x5ca1e),
        ..ProptestConfig::default()
    })]

    /// Issue 22, item 7: every hand method reads the same on a record scaled by 10^k (output
    /// and input alike), k from −300 to 300, exact or noisy and quantised.
    #[test]
    fn every_method_reads_the_same_at_any_scale(k in -300i32..=300, noisy in any::<bool>()) {
        let case = fopdt_case();
        let shape = first_order(40.0);
        let record = if noisy {
            case.noisy(&shape, 0.02, 0.05, 7)
        } else {
            case.record(&shape)
        };
        let at_scale = scaled(&record, 10f64.powi(k));
        let pairs = estimate_all(&at_scale, &Overrides::default())
            .into_iter()
            .zip(estimate_all(&record, &Overrides::default()));
        for ((method, got), (_, unit)) in pairs {
            match (got, unit) {
                (Ok(g), Ok(u)) => same_reading(&g, &u, case.length),
                (Err(g), Err(u)) => prop_assert_eq!(
                    std::mem::discriminant(&g),
                    std::mem::discriminant(&u),
                    "{:?}",
                    method
                ),
                (g, u) => prop_assert!(false, "{method:?}: {g:?} vs {u:?}"),
            }
        }
    }
}
