//! Scale-free fitting (issue 8, item 2): the same record at output scales from 1e-300 to
//! 1e300, with time and the step Δu scaled far from 1 too, fits to the same time constants
//! (1e-9 relative), the same fit %, and its diagnosis names the same causes.

use degrau_ident::diagnose::{DiagnoseOptions, diagnose};
use degrau_ident::fit::guess::auto_guess;
use degrau_ident::fit::{FitData, FitError, FitOptions, FitReport, FitWarning, Termination, fit};
use degrau_ident::model::excitation::Excitation;
use degrau_ident::model::{Model, Param, Structure, Values};

/// Output, time and Δu scales: the unit record first.
const SCALES: [(f64, f64, f64); 8] = [
    (1.0, 1.0, 1.0),
    (1e-300, 1e-5, 1e-4),
    (1e-150, 1e7, 1e100),
    (1e150, 1e-9, 1e-120),
    (1e300, 1e5, 1e200),
    (1e300, 1.0, 1.0),
    (1.0, 3.7e8, 1e-250),
    (1.0, 1.0, 1e250),
];

/// A deterministic uniform noise in [−1, 1).
fn noise(n: usize) -> Vec<f64> {
    let mut rng = degrau_ident::random::Lcg(0x9E37_79B9_7F4A_7C15);
    (0..n).map(|_| rng.symmetric()).collect()
}

fn values(pairs: &[(Param, f64)]) -> Values {
    let mut v = Values::default();
    for &(p, x) in pairs {
        v.set(p, x);
    }
    v
}

/// A P1D step test with the step between two samples and an operating point far from zero
/// (30 against an effect of 3), ±0.02 noise, at output scale `ky`, time scale `kt` and step
/// scale `kdu`.
fn record(scales: (f64, f64, f64)) -> FitData {
    record_of("P1D", scales)
}

/// [`record`] of a `code` process (P1: the same without the dead time).
fn record_of(code: &str, (ky, kt, kdu): (f64, f64, f64)) -> FitData {
    let truth = values(&[
        (Param::Kp, 1.5),
        (Param::Tp1, 4.0),
        (Param::Td, 1.2),
        (Param::Y0, 30.0),
    ]);
    let setup = Excitation::step(2.05, 2.0);
    let times: Vec<f64> = (0..400).map(|k| 0.1 * k as f64).collect();
    let model = Model::new(Structure::parse(code).unwrap(), truth);
    let y = model.simulate(&setup, &times).unwrap();
    FitData {
        times: times.iter().map(|t| t * kt).collect(),
        y: y.iter()
            .zip(noise(times.len()))
            .map(|(y, e)| (y + 0.02 * e) * ky)
            .collect(),
        input: Excitation::step(setup.t0() * kt, setup.du() * kdu),
    }
}

fn fit_p1d(data: &FitData) -> FitReport {
    let s = Structure::parse("P1D").unwrap();
    let guess = auto_guess(data, s, None);
    fit(data, s, guess, &FitOptions::default(), &mut ()).unwrap()
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn a_record_fits_the_same_at_any_scale() {
    let unit = fit_p1d(&record(SCALES[0]));
    assert!(unit.fit_percent > 90.0, "{unit:?}");
    for scale @ (ky, kt, kdu) in SCALES {
        let r = fit_p1d(&record(scale));
        let at = format!("scales {scale:?}: {:?} {:?}", r.termination, r.warnings);
        assert!(r.iterations > 1, "{at}");
        assert!(
            !matches!(
                r.termination,
                Termination::NoImprovement | Termination::IterationLimit
            ),
            "{at}"
        );
        for p in [Param::Tp1, Param::Td] {
            // The record's scaled copy rounds differently in its last bits, and the cost is
            // flat to its own rounding within ~√ε·(the lags' correlation) of the optimum: the
            // copies agree to 10⁻⁹ (between 2·10⁻¹¹ and 1.6·10⁻⁹ measured), not to the bit.
            let e = relative(r.model.get(p) / kt, unit.model.get(p));
            assert!(e < 1e-8, "{p:?} off by {e:e} at {at}");
            let (lo, hi) = r.interval(p).unwrap();
            let (ulo, uhi) = unit.interval(p).unwrap();
            assert!(
                relative((hi - lo) / kt, uhi - ulo) < 1e-6,
                "{p:?} interval at {at}"
            );
        }
        let kp = r.model.get(Param::Kp) * kdu / ky;
        assert!(relative(kp, unit.model.get(Param::Kp)) < 1e-9, "Kp at {at}");
        assert!(relative(r.model.get(Param::Y0) / ky, unit.model.get(Param::Y0)) < 1e-9);
        assert!(
            (r.fit_percent - unit.fit_percent).abs() < 1e-7,
            "fit % at {at}"
        );
        assert!(relative(r.rmse / ky, unit.rmse) < 1e-9, "RMSE at {at}");
        assert!(
            (r.ln_mse - 2.0 * ky.ln() - unit.ln_mse).abs() < 1e-8,
            "ln MSE at {at}"
        );
        let aic_shift = 2.0 * r.n as f64 * ky.ln();
        assert!(
            (r.aic - aic_shift - unit.aic).abs() < 1e-6 * unit.aic.abs(),
            "{at}"
        );
        // The MSE is (1e-2·ky)²: beyond double precision at 1e±300, and then said so.
        let said = r
            .warnings
            .iter()
            .any(|w| matches!(w, FitWarning::Unrepresentable { .. }));
        assert_eq!(said, !r.mse.is_normal(), "{at}");
        assert_eq!(said, ky.log10().abs() > 150.0, "{at}");
    }
}

#[test]
fn the_issue_reproducer_at_1e200_converges_in_more_than_one_iteration() {
    // A first-order record scaled to an output of 1e200: "converged: the gradient vanished"
    // in one iteration, MSE inf and fit NaN % before.
    let s = Structure::parse("P1").unwrap();
    let fits: Vec<FitReport> = [1.0, 1e200, 1e154, 1e-150, 1e-154]
        .iter()
        .map(|&ky| {
            let data = record_of("P1", (ky, 1.0, 1.0));
            let guess = auto_guess(&data, s, None);
            fit(&data, s, guess, &FitOptions::default(), &mut ()).unwrap()
        })
        .collect();
    for (r, ky) in fits.iter().zip([1.0, 1e200, 1e154, 1e-150, 1e-154]) {
        assert!(r.iterations > 1 && r.fit_percent.is_finite(), "{ky}: {r:?}");
        assert!((r.fit_percent - fits[0].fit_percent).abs() < 1e-7, "{ky}");
        let e = relative(r.model.get(Param::Tp1), fits[0].model.get(Param::Tp1));
        assert!(
            e < 1e-9,
            "{ky}: Tp1 off by {e:e}: {:?} {} vs {:?} {}",
            r.termination,
            r.iterations,
            fits[0].termination,
            fits[0].iterations
        );
        for e in &r.params {
            let (lo, hi) = e.ci95.unwrap();
            assert!(
                lo < e.value && e.value < hi,
                "{ky}: zero-width interval {e:?}"
            );
        }
    }
}

#[test]
fn a_non_finite_cost_is_a_failure_not_a_convergence() {
    let data = record(SCALES[0]);
    let s = Structure::parse("P1D").unwrap();
    let mut guess = auto_guess(&data, s, None);
    guess.set(Param::Kp, 1e300);
    assert_eq!(
        fit(&data, s, guess, &FitOptions::default(), &mut ()),
        Err(FitError::NonFiniteCost)
    );
}

#[test]
fn a_gain_beyond_double_precision_is_refused_by_name() {
    // Output 1e300 per step 1e-300: Kp ≈ 1e600.
    let data = record((1e300, 1.0, 1e-300));
    let s = Structure::parse("P1D").unwrap();
    let guess = auto_guess(&data, s, None);
    match fit(&data, s, guess, &FitOptions::default(), &mut ()) {
        Err(FitError::Unrepresentable { param, log10 }) => {
            assert_eq!(param, "Kp");
            assert!((log10 - 600.0f64).abs() < 1.0, "{log10}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_diagnosis_names_the_same_causes_at_any_scale() {
    let chain = |scale| {
        let data = record(scale);
        let r = diagnose(
            &data,
            Structure::parse("P1").unwrap(),
            None,
            &DiagnoseOptions::default(),
        )
        .unwrap();
        for step in &r.steps {
            assert!(
                step.gain.criterion_delta.is_finite() && step.gain.criterion_delta < -10.0,
                "{scale:?}: {:?}",
                step.gain
            );
        }
        (
            r.steps.iter().map(|s| s.cause).collect::<Vec<_>>(),
            r.final_fit.model.get(Param::Tp1) / scale.1,
        )
    };
    let (unit, tp1) = chain(SCALES[0]);
    assert!(!unit.is_empty());
    for scale in &SCALES[1..6] {
        let (causes, t) = chain(*scale);
        assert_eq!(causes, unit, "{scale:?}");
        assert!(relative(t, tp1) < 1e-6, "{scale:?}: Tp1 {t} vs {tp1}");
    }
}

/// A long record (12,000 samples, so the search runs on its reduction) driven by a measured
/// input that steps four times, at output scale `ky`, time scale `kt` and input scale `kdu`:
/// the P1D of [`record_of`] with ±0.02 noise.
fn long_record((ky, kt, kdu): (f64, f64, f64)) -> FitData {
    use degrau_ident::model::excitation::Hold;
    let truth = values(&[
        (Param::Kp, 1.5),
        (Param::Tp1, 4.0),
        (Param::Td, 1.2),
        (Param::Y0, 30.0),
    ]);
    let times: Vec<f64> = (0..12_000).map(|k| 0.01 * k as f64).collect();
    let u: Vec<f64> = times
        .iter()
        .map(|&t| match t {
            t if t < 5.0 => 2.0,
            t if t < 35.0 => 4.0,
            t if t < 65.0 => 1.0,
            t if t < 90.0 => 3.5,
            _ => 2.5,
        })
        .collect();
    let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
    let y = Model::new(Structure::parse("P1D").unwrap(), truth)
        .simulate(&input, &times)
        .unwrap();
    let scaled_u: Vec<f64> = u.iter().map(|u| u * kdu).collect();
    let scaled_t: Vec<f64> = times.iter().map(|t| t * kt).collect();
    FitData {
        input: Excitation::measured(&scaled_t, &scaled_u, None, Hold::Zoh).unwrap(),
        times: scaled_t,
        y: y.iter()
            .zip(noise(times.len()))
            .map(|(y, e)| (y + 0.02 * e) * ky)
            .collect(),
    }
}

#[test]
fn a_long_record_searched_on_its_reduction_fits_the_same_at_any_scale() {
    let unit_data = long_record(SCALES[0]);
    assert!(degrau_ident::fit::reduce::reduce(&unit_data.times, &unit_data.input).is_some());
    let unit = fit_p1d(&unit_data);
    for (p, x) in [(Param::Kp, 1.5), (Param::Tp1, 4.0), (Param::Td, 1.2)] {
        let (lo, hi) = unit.interval(p).unwrap();
        assert!(lo < x && x < hi, "{p:?}: [{lo}, {hi}] misses {x}");
    }
    assert_eq!(unit.n, 12_000);
    for scale @ (ky, kt, kdu) in [SCALES[1], SCALES[4]] {
        let r = fit_p1d(&long_record(scale));
        for p in [Param::Tp1, Param::Td] {
            let e = relative(r.model.get(p) / kt, unit.model.get(p));
            assert!(e < 1e-7, "{p:?} off by {e:e} at {scale:?}");
        }
        let kp = r.model.get(Param::Kp) * kdu / ky;
        assert!(relative(kp, unit.model.get(Param::Kp)) < 1e-7, "{scale:?}");
        assert!((r.fit_percent - unit.fit_percent).abs() < 1e-6, "{scale:?}");
    }
}
