//! Least squares on samples, end to end: the notes' example, ARX on exact ZOH records of a
//! known G(s) (recovering c2d's coefficients and, through d2c, G), RLS against the batch
//! solution, PRBS records fitted back, and estimation/validation splits. The records are
//! simulated exactly (the measured input held between samples through
//! `Excitation::measured` + `Model::simulate`), far from zero, some with noise.

use degrau::ident::arx::{
    ArxOrders, LsqError, Offset, Regressor, Start, arx, default_grid, least_squares, regression,
    select_orders,
};
use degrau::ident::fit::{FitData, FitOptions, Lcg};
use degrau::ident::models::{Model, Param, Structure, Values};
use degrau::ident::prbs::{Prbs, gaussian, simulate_record, to_csv};
use degrau::ident::rls::{RlsOptions, rls_arx, run};
use degrau::ident::validation::{Split, validate_arx, validate_continuous, validate_rls};
use degrau::lti::discrete::c2d;

fn model(code: &str, values: &[(Param, f64)]) -> Model {
    let mut v = Values::default();
    for &(p, x) in values {
        v.set(p, x);
    }
    Model::new(Structure::parse(code).unwrap(), v)
}

/// A PRBS between `lo` and `hi`, clocked every `clock` samples.
fn prbs(order: u32, clock: usize, lo: f64, hi: f64, samples: usize) -> Vec<f64> {
    Prbs::new(order, clock, lo, hi)
        .unwrap()
        .signal(samples)
        .unwrap()
}

fn close(a: &[f64], b: &[f64], tol: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tol, "{what}: {a:?} vs {b:?}");
    }
}

#[test]
fn the_notes_least_squares_example() {
    let (u, y) = ([0.0, 1.0, 2.0], [0.0, 0.9, 2.1]);
    let models: [(&[Regressor], &[f64], f64); 3] = [
        (&[Regressor::Constant], &[1.0], 2.22),
        (
            &[Regressor::Constant, Regressor::Input(0)],
            &[-0.05, 1.05],
            0.015,
        ),
        (
            &[
                Regressor::Constant,
                Regressor::Input(0),
                Regressor::Input(1),
            ],
            &[0.0, 0.9, 0.3],
            0.0,
        ),
    ];
    for (regressors, theta, j) in models {
        let reg = regression(&u, &y, regressors, Start::Zeros).unwrap();
        assert_eq!(reg.phi.nrows(), 3);
        let ls = least_squares(&reg).unwrap();
        close(&ls.theta, theta, 1e-14, "θ");
        assert!((ls.j - j).abs() < 1e-14, "J = {}", ls.j);
        // ΦᵀE ≈ 0: the residuals are orthogonal to every regressor.
        let e = nalgebra::DVector::from_vec(ls.residuals.clone());
        assert!((reg.phi.transpose() * e).norm() < 1e-14);
    }
    // Φ of the third model, as the notes' zeros before the record give it.
    let reg = regression(&u, &y, models[2].0, Start::Zeros).unwrap();
    assert_eq!(
        reg.phi.row(2).iter().copied().collect::<Vec<_>>(),
        [1.0, 2.0, 1.0]
    );
}

#[test]
fn arx_recovers_the_exact_zoh_coefficients_far_from_zero() {
    // P2D with a fractional dead time (2.7 samples), at y ≈ 250 with u between 40 and 60.
    let truth = model(
        "P2D",
        &[
            (Param::Kp, 1.8),
            (Param::Tp1, 6.0),
            (Param::Tp2, 1.5),
            (Param::Td, 1.35),
            (Param::Y0, 250.0),
        ],
    );
    let h = 0.5;
    let u = prbs(7, 4, 40.0, 60.0, 600);
    let rec = simulate_record(&truth, &u, h, 0.0, 1).unwrap();
    let exact = c2d(&truth.transfer_function().unwrap(), h).unwrap();
    assert_eq!((exact.nk(), exact.b().len()), (3, 3));
    let orders = ArxOrders::new(2, exact.b().len(), exact.nk());
    let fit = arx(&rec.time, &rec.u, &rec.y, orders, Offset::Initial).unwrap();
    close(&fit.model.a, exact.a(), 1e-9, "a");
    close(&fit.model.b, exact.b(), 1e-9, "b");
    assert!(fit.scores.fit_percent_prediction > 100.0 - 1e-7);
    assert!(fit.scores.fit_percent_simulation > 100.0 - 1e-7);
    assert!((fit.model.y0 - 250.0).abs() < 1e-12 && fit.model.u0 == u[0]);
    // The same with a constant regressor instead of the operating point.
    let c = arx(&rec.time, &rec.u, &rec.y, orders, Offset::Constant).unwrap();
    close(&c.model.a, exact.a(), 1e-8, "a (constant)");
}

#[test]
fn d2c_of_the_arx_model_returns_g() {
    // Whole-sample dead time: d2c returns the poles and the delay.
    let truth = model(
        "P2D",
        &[
            (Param::Kp, -0.6),
            (Param::Tp1, 3.0),
            (Param::Tp2, 0.8),
            (Param::Td, 0.6),
            (Param::Y0, -40.0),
        ],
    );
    let h = 0.2;
    let rec = simulate_record(&truth, &prbs(8, 3, 0.0, 5.0, 700), h, 0.0, 1).unwrap();
    let fit = arx(
        &rec.time,
        &rec.u,
        &rec.y,
        ArxOrders::new(2, 2, 4),
        Offset::Initial,
    )
    .unwrap();
    let g = fit.model.discrete().unwrap().d2c().unwrap();
    let mut poles: Vec<f64> = g.poles().iter().map(|p| p.re).collect();
    poles.sort_by(f64::total_cmp);
    close(&poles, &[-1.0 / 0.8, -1.0 / 3.0], 1e-6, "poles");
    assert!((g.delay() - 0.6).abs() < 1e-9);
    assert!((g.dc_gain() + 0.6).abs() < 1e-6);
    // A FOPTD with a fractional dead time, through the notes' formulas.
    let foptd = model(
        "P1D",
        &[
            (Param::Kp, 2.5),
            (Param::Tp1, 40.0),
            (Param::Td, 13.0),
            (Param::Y0, 21.0),
        ],
    );
    let rec = simulate_record(&foptd, &prbs(6, 5, 0.0, 50.0, 400), 5.0, 0.0, 1).unwrap();
    let fit = arx(
        &rec.time,
        &rec.u,
        &rec.y,
        ArxOrders::new(1, 2, 3),
        Offset::Initial,
    )
    .unwrap();
    let g = fit.model.discrete().unwrap().d2c().unwrap();
    assert!((g.poles()[0].re + 1.0 / 40.0).abs() < 1e-9);
    assert!((g.dc_gain() - 2.5).abs() < 1e-8);
    assert!((g.delay() - 13.0).abs() < 1e-7, "θ = {}", g.delay());
}

#[test]
fn rls_at_lambda_one_ends_at_the_batch_solution_on_a_noisy_record() {
    let truth = model(
        "P2",
        &[
            (Param::Kp, 3.0),
            (Param::Tp1, 10.0),
            (Param::Tp2, 2.0),
            (Param::Y0, 1000.0),
        ],
    );
    let rec = simulate_record(&truth, &prbs(8, 2, 10.0, 12.0, 500), 1.0, 0.05, 7).unwrap();
    let orders = ArxOrders::new(2, 2, 1);
    let batch = arx(&rec.time, &rec.u, &rec.y, orders, Offset::Initial).unwrap();
    let r = rls_arx(
        &rec.time,
        &rec.u,
        &rec.y,
        orders,
        Offset::Initial,
        &RlsOptions::default(),
    )
    .unwrap();
    close(&r.run.last, &batch.lsq.theta, 1e-6, "θ");
    assert_eq!(r.run.trajectory.len(), batch.regression.phi.nrows());
    // The trajectory's first step moves from θ0 = 0.
    assert!(r.run.trajectory[0].iter().any(|v| *v != 0.0));
    // With forgetting the last estimate weighs recent samples more: not the batch one.
    let forget = RlsOptions {
        lambda: 0.95,
        ..RlsOptions::default()
    };
    let f = run(&batch.regression, &forget).unwrap();
    assert!(
        f.last
            .iter()
            .zip(&batch.lsq.theta)
            .any(|(a, b)| (a - b).abs() > 1e-4)
    );
}

#[test]
fn a_prbs_has_its_clock_levels_and_period() {
    let p = Prbs::new(6, 5, -3.0, 7.5).unwrap();
    assert_eq!(p.period(), 63 * 5);
    let s = p.periodic(3).unwrap();
    assert_eq!(s.len(), 3 * 315);
    assert!(s.iter().all(|&v| v == -3.0 || v == 7.5));
    // Constant over each clock interval; every change on a clock edge.
    for k in 1..s.len() {
        if s[k] != s[k - 1] {
            assert_eq!(k % 5, 0, "change at {k}");
        }
    }
    // Periodic, and one more high bit than low per period.
    assert_eq!(s[..315], s[315..630]);
    let highs = s[..315].iter().filter(|&&v| v == 7.5).count();
    assert_eq!(highs, 32 * 5);
    assert_eq!(315 - highs, 31 * 5);
    // idinput's non-periodic form: the shortest register covering the length.
    let q = Prbs::for_length(1000, 4, 0.0, 1.0).unwrap();
    assert_eq!((q.order, q.period()), (8, 255 * 4));
}

#[test]
fn a_prbs_response_is_fitted_back_by_arx() {
    let truth = model(
        "P1D",
        &[
            (Param::Kp, 0.9),
            (Param::Tp1, 25.0),
            (Param::Td, 7.0),
            (Param::Y0, 55.0),
        ],
    );
    let h = 2.0;
    let u = Prbs::new(7, 6, 20.0, 60.0).unwrap().periodic(2).unwrap();
    // Noise-free: exact.
    let rec = simulate_record(&truth, &u, h, 0.0, 3).unwrap();
    let fit = arx(
        &rec.time,
        &rec.u,
        &rec.y,
        ArxOrders::new(1, 2, 4),
        Offset::Initial,
    )
    .unwrap();
    let g = fit.model.discrete().unwrap().d2c().unwrap();
    assert!((g.dc_gain() - 0.9).abs() < 1e-9);
    assert!((g.delay() - 7.0).abs() < 1e-7);
    // 0.5 % noise (of the response's range): the model within a few percent.
    let noisy = simulate_record(&truth, &u, h, 0.18, 11).unwrap();
    let fit = arx(
        &noisy.time,
        &noisy.u,
        &noisy.y,
        ArxOrders::new(1, 2, 4),
        Offset::Initial,
    )
    .unwrap();
    let g = fit.model.discrete().unwrap().d2c().unwrap();
    assert!((g.dc_gain() - 0.9).abs() < 0.03 * 0.9, "K {}", g.dc_gain());
    assert!(
        (g.poles()[0].re * 25.0 + 1.0).abs() < 0.1,
        "τ {}",
        -1.0 / g.poles()[0].re
    );
    assert!(fit.scores.fit_percent_simulation > 95.0);
    // The CSV reads back as the record.
    let csv = to_csv(&noisy);
    let first = csv.lines().nth(1).unwrap();
    assert_eq!(first, format!("0,{},{}", noisy.u[0], noisy.y[0]));
}

#[test]
fn aic_finds_the_delay_on_a_slightly_noisy_record() {
    let truth = model(
        "P2D",
        &[
            (Param::Kp, 2.0),
            (Param::Tp1, 4.0),
            (Param::Tp2, 1.0),
            (Param::Td, 1.0),
            (Param::Y0, 80.0),
        ],
    );
    let rec = simulate_record(&truth, &prbs(9, 2, 0.0, 10.0, 800), 0.5, 0.01, 5).unwrap();
    let ranked =
        select_orders(&rec.time, &rec.u, &rec.y, &default_grid(4), Offset::Initial).unwrap();
    let best = ranked[0];
    // The delay is found; with output noise (not ARX's equation error) a higher na may win,
    // modelling the noise's colour: AIC on ARX does not promise the true na.
    assert_eq!(best.orders.nk, 3, "{best:?}");
    assert!(best.fit_percent_simulation > 99.0);
    assert!(ranked.windows(2).all(|w| w[0].aic <= w[1].aic));
}

#[test]
fn validation_of_a_noise_free_record_predicts_the_second_half_exactly() {
    let truth = model(
        "P2D",
        &[
            (Param::Kp, 1.2),
            (Param::Tp1, 5.0),
            (Param::Tp2, 2.0),
            (Param::Td, 1.0),
            (Param::Y0, 300.0),
        ],
    );
    let h = 0.5;
    let rec = simulate_record(&truth, &prbs(8, 3, 10.0, 30.0, 600), h, 0.0, 1).unwrap();
    let exact = c2d(&truth.transfer_function().unwrap(), h).unwrap();
    let orders = ArxOrders::new(2, exact.b().len(), exact.nk());
    let (_, v) = validate_arx(
        &rec.time,
        &rec.u,
        &rec.y,
        orders,
        Offset::Initial,
        Split::Fraction(0.5),
    )
    .unwrap();
    assert_eq!(v.split, 300);
    for k in v.split..rec.y.len() {
        assert!((v.validation.prediction[k] - rec.y[k]).abs() < 1e-9);
        assert!((v.validation.simulation[k] - rec.y[k]).abs() < 1e-9);
    }
    // RLS's last model, too (large α: near the batch).
    let (_, r) = validate_rls(
        &rec.time,
        &rec.u,
        &rec.y,
        orders,
        Offset::Initial,
        &RlsOptions::default(),
        Split::Time(150.0),
    )
    .unwrap();
    assert_eq!(r.split, 300);
    assert!(r.validation.fit_percent_simulation > 99.99);
}

#[test]
fn validation_of_the_continuous_fit_simulates_across_the_split() {
    let truth = model(
        "P1D",
        &[
            (Param::Kp, 1.5),
            (Param::Tp1, 4.0),
            (Param::Td, 1.2),
            (Param::Y0, 3.0),
        ],
    );
    let h = 0.25;
    let u = prbs(6, 8, 0.0, 2.0, 400);
    let rec = simulate_record(&truth, &u, h, 0.0, 1).unwrap();
    let test = degrau::ident::data::StepTest {
        time: rec.time.clone(),
        output: rec.y.clone(),
        input: Some(rec.u.clone()),
        time_name: "time".into(),
        output_name: "y".into(),
        input_name: Some("u".into()),
        sampling_period: None,
        notes: Vec::new(),
    };
    let experiment = degrau::ident::experiment::Experiment::new(&test, None, None, None).unwrap();
    let data: FitData = experiment.fit_data(&test).unwrap();
    let v = validate_continuous(
        &experiment,
        &data,
        "P1D",
        Split::Fraction(0.5),
        &FitOptions::default(),
    )
    .unwrap();
    let scale = 3.0;
    for e in &v.residuals[v.split..] {
        assert!(e.abs() < 1e-9 * scale, "{e}");
    }
    assert!(v.validation_fit_percent > 100.0 - 1e-6);
}

#[test]
fn bad_inputs_are_refused_in_words() {
    let t = [0.0, 1.0, 2.0, 3.0];
    let y = [0.0, 1.0, 2.0, 3.0];
    assert_eq!(
        arx(&t, &y, &y, ArxOrders::new(2, 2, 1), Offset::None).unwrap_err(),
        LsqError::TooFewSamples {
            rows: 2,
            parameters: 4
        }
    );
    assert_eq!(
        arx(&t, &y[..3], &y, ArxOrders::new(1, 1, 1), Offset::None).unwrap_err(),
        LsqError::LengthMismatch { u: 3, y: 4 }
    );
    // A record at rest: −y(k−1) and u(k−1) are both constant, so collinear.
    let time: Vec<f64> = (0..40).map(|k| k as f64).collect();
    assert_eq!(
        arx(
            &time,
            &[2.0; 40],
            &[5.0; 40],
            ArxOrders::new(1, 1, 1),
            Offset::None
        )
        .unwrap_err(),
        LsqError::Singular { index: 1 }
    );
    let split = Split::Fraction(1.2);
    assert_eq!(
        validate_arx(
            &time,
            &time,
            &time,
            ArxOrders::new(1, 1, 1),
            Offset::None,
            split
        )
        .unwrap_err(),
        LsqError::BadSplit
    );
    let words = LsqError::Singular { index: 1 }.to_string();
    assert!(words.contains("singular"), "{words}");
}

#[test]
fn gaussian_noise_has_unit_spread() {
    let mut rng = Lcg(99);
    let draws: Vec<f64> = (0..20000).map(|_| gaussian(&mut rng)).collect();
    let mean = draws.iter().sum::<f64>() / 2e4;
    let var = draws.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 2e4;
    assert!(
        mean.abs() < 0.03 && (var - 1.0).abs() < 0.05,
        "{mean} {var}"
    );
}
