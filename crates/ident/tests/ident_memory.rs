//! A fit of a 5·10⁶-sample record (issue 8, item 6), for measuring its peak memory and time:
//! `cargo test --release --test ident_memory -- --ignored --nocapture` under
//! `/usr/bin/time -v`. Ignored by default: it is a measurement, not a check of speed; what it
//! asserts is only that the fit is right.
//!
//! Issue 10 (scale): a 10⁶-sample record driven by its measured input (a CSV of t, u, y
//! written to a temporary file) loads, fits P1D and is diagnosed from P1 in bounded memory:
//! `cargo test --release --test ident_memory -- --ignored --nocapture measured` under
//! `/usr/bin/time -v`.

use degrau_ident::model::excitation::Excitation;
use std::time::Instant;

use degrau_ident::fit::guess::auto_guess;
use degrau_ident::fit::{FitData, FitOptions, fit};
use degrau_ident::model::{Model, Param, Structure, Values};

use degrau_ident::diagnose::{DiagnoseOptions, diagnose};
use degrau_ident::experiment::Experiment;
use degrau_ident::model::excitation::Hold;
use degrau_ident::record::data::{LoadOptions, load_file};
use std::fmt::Write as _;

const SAMPLES: usize = 5_000_000;

/// The process of the records: Kp 1.5, Tp1 40 s, Td 12 s, Y0 30 (a P1 leaves Td unused).
fn truth() -> Values {
    Values::from_pairs(&[
        (Param::Kp, 1.5),
        (Param::Tp1, 40.0),
        (Param::Td, 12.0),
        (Param::Y0, 30.0),
    ])
}

fn record(code: &str) -> FitData {
    let setup = Excitation::step(20.05, 2.0);
    let times: Vec<f64> = (0..SAMPLES).map(|k| 1e-4 * k as f64).collect();
    let mut y = Model::new(Structure::parse(code).unwrap(), truth())
        .simulate(&setup, &times)
        .unwrap();
    let mut rng = degrau_ident::random::Lcg(7);
    for v in y.iter_mut() {
        *v += 0.02 * rng.symmetric();
    }
    FitData {
        times,
        y,
        input: setup,
    }
}

fn measure(code: &str) {
    let data = record(code);
    let s = Structure::parse(code).unwrap();
    let clock = Instant::now();
    let guess = auto_guess(&data, s, None);
    let r = fit(&data, s, guess, &FitOptions::default(), &mut ()).unwrap();
    eprintln!(
        "{code}: {} samples, {} starts, {} iterations, {:?}, {:.1} s; Tp1 {} fit {} %",
        r.n,
        r.starts,
        r.iterations,
        r.termination,
        clock.elapsed().as_secs_f64(),
        r.model.get(Param::Tp1),
        r.fit_percent
    );
    assert!((r.model.get(Param::Tp1) - 40.0).abs() < 0.01 * 40.0);
}

#[test]
#[ignore = "a measurement: run with --ignored under /usr/bin/time -v"]
fn fits_a_five_million_sample_p1d() {
    measure("P1D");
}

#[test]
#[ignore = "a measurement: run with --ignored under /usr/bin/time -v"]
fn fits_a_five_million_sample_p1() {
    measure("P1");
}

/// Samples of the measured-input record.
const MEASURED_SAMPLES: usize = 1_000_000;

/// A 1 kHz logger for 1000 s: the input steps 2 → 4 → 1 → 3 (at 100.0005, 400.0005 and
/// 700.0005 s, between samples) into the P1D Kp 1.5, Tp1 40 s, Td 12 s, Y0 30, with ±0.02
/// uniform noise; written as a CSV of t, u, y into a temporary directory.
fn measured_file() -> std::path::PathBuf {
    let times: Vec<f64> = (0..MEASURED_SAMPLES).map(|k| 1e-3 * k as f64).collect();
    let levels = [(100.0005, 4.0), (400.0005, 1.0), (700.0005, 3.0)];
    let level = |t: f64| {
        levels
            .iter()
            .take_while(|(s, _)| *s <= t)
            .last()
            .map_or(2.0, |l| l.1)
    };
    // The process sees the true instants; the logger's column shows each at the next sample.
    let fine: Vec<f64> = [0.0]
        .into_iter()
        .chain(levels.iter().map(|l| l.0))
        .collect();
    let fine_u: Vec<f64> = fine.iter().map(|&t| level(t)).collect();
    let truth_input = Excitation::measured(&fine, &fine_u, None, Hold::Zoh).unwrap();
    let y = Model::new(Structure::parse("P1D").unwrap(), truth())
        .simulate(&truth_input, &times)
        .unwrap();
    let mut rng = degrau_ident::random::Lcg(11);
    let mut text = String::with_capacity(40 * MEASURED_SAMPLES);
    text.push_str("t,u,y\n");
    for (&t, y) in times.iter().zip(y) {
        let e = 0.02 * rng.symmetric();
        let _ = writeln!(text, "{t},{},{:.6}", level(t), y + e);
    }
    let dir = std::env::temp_dir().join(format!("degrau-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("measured.csv");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
#[ignore = "a measurement: run with --ignored under /usr/bin/time -v"]
fn loads_fits_and_diagnoses_a_million_sample_measured_record() {
    let path = measured_file();
    let clock = Instant::now();
    let test = load_file(&path, &LoadOptions::default()).unwrap();
    let _ = std::fs::remove_file(&path);
    let experiment = Experiment::new(&test, None, None, None).unwrap();
    let data = experiment.fit_data(&test).unwrap();
    drop(test);
    let loaded = clock.elapsed().as_secs_f64();
    assert_eq!(data.input.changes.len(), 3);
    let clock = Instant::now();
    let s = experiment.structure("P1D", false, &data).unwrap();
    let guess = experiment.guess(s, &data);
    let r = fit(&data, s, guess, &FitOptions::default(), &mut ()).unwrap();
    let fitted = clock.elapsed().as_secs_f64();
    eprintln!(
        "measured P1D: {} samples, loaded in {loaded:.1} s, fitted in {fitted:.1} s; Kp {} Tp1 {} Td {} fit {} %",
        r.n,
        r.model.get(Param::Kp),
        r.model.get(Param::Tp1),
        r.model.get(Param::Td),
        r.fit_percent
    );
    for (p, x) in [(Param::Kp, 1.5), (Param::Tp1, 40.0), (Param::Td, 12.0)] {
        assert!(
            (r.model.get(p) - x).abs() < 0.01 * x,
            "{p:?}: {}",
            r.model.get(p)
        );
    }
    let clock = Instant::now();
    let start = experiment.structure("P1", false, &data).unwrap();
    let held = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let report = diagnose(&data, start, held, &DiagnoseOptions::default()).unwrap();
    let chain: Vec<&str> = report.steps.iter().map(|s| s.cause.id()).collect();
    eprintln!(
        "measured diagnosis from P1: {:.1} s; chain {chain:?}, final {}",
        clock.elapsed().as_secs_f64(),
        report.final_fit.model.structure.label()
    );
    assert!(report.final_fit.model.structure.delay);
}
