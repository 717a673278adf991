//! Issue 21, item 7: fast enough for a class, linear in the record, measured side by side.
//!
//! - **records**: each record of `tests/data/records` loaded as the CLI loads it (the flags a
//!   user types, the default start P1): one default P1D fit (`degrau fit --model P1D`'s fit,
//!   16 starts; best of 5) against one whole diagnosis (best of 2), and their ratio (target
//!   ≤ 25).
//! - **scale**: a P1D process (Kp 2, Tp1 8 s, Td 3 s, Y0 5) driven by a measured input
//!   stepping 0 → 1 → 1.5 (at 20 s and 110 s of a 200 s record), Gaussian noise σ = 0.01, at
//!   10³, 10⁴, 10⁵ and 10⁶ samples: the default P1D fit (16 starts; and from one start) and
//!   the diagnosis (best of 3; one run at 10⁶) against scipy's single-start `least_squares`
//!   (`benches/scipy_p1d.py`, best of 3 in-process, when python3 with numpy and scipy is
//!   there). Targets: the fit within 1.5× scipy, the diagnosis within 10×.
//!
//! Run: `cargo bench --bench speed` (both), or `-- records`, `-- scale`. Plain timing
//! (`Instant`), not criterion: each figure is a whole fit or diagnosis of seconds, and the
//! ratios are what is read.

use degrau::ident::diagnose::{DiagnoseOptions, diagnose};
use degrau::ident::experiment::Experiment;
use degrau::ident::fit::{FitData, FitOptions};
use degrau::ident::model::excitation::{Excitation, Hold};
use degrau::ident::model::{Model, Param, Structure, Values};
use degrau::ident::record::data::{LoadOptions, load_file};

mod common;
mod timing;
use timing::best_of;
#[path = "../tests/records/mod.rs"]
mod records;

use records::{Flags, RECORDS};

/// The record's samples as the CLI prepares them, and the held Y0 of a start at rest.
fn prepared(flags: &Flags) -> Result<(Experiment, FitData, Option<Values>), String> {
    let (file, time, y, u, ts, skip, initial) = *flags;
    let path = records::path(file);
    let options = LoadOptions::from_text(time, y, u, ts, skip);
    let test = load_file(&path, &options).map_err(|e| e.to_string())?;
    let experiment = Experiment::new(&test, None, None, initial).map_err(|e| e.to_string())?;
    let data = experiment.fit_data(&test).map_err(|e| e.to_string())?;
    let held = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    Ok((experiment, data, held))
}

/// Seconds of one default P1D fit and of one diagnosis from P1, on `data`.
fn fit_and_diagnosis(experiment: &Experiment, data: &FitData, held: Option<Values>) -> (f64, f64) {
    let fit = best_of(5, || {
        experiment
            .fit_prepared(data, "P1D", false, &[], &FitOptions::default(), &mut ())
            .ok()
    });
    let start = experiment.structure("P1", false, data).ok();
    let options = DiagnoseOptions::default();
    let diagnosis = best_of(2, || start.map(|s| diagnose(data, s, held, &options).ok()));
    (fit, diagnosis)
}

fn records() {
    eprintln!("record | samples | P1D fit (s) | diagnosis (s) | ratio (target ≤ 25)");
    let mut worst: f64 = 0.0;
    for flags in &RECORDS {
        let (experiment, data, held) = match prepared(flags) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("{}: not loaded ({e})", flags.0);
                continue;
            }
        };
        let (fit, diagnosis) = fit_and_diagnosis(&experiment, &data, held);
        let ratio = diagnosis / fit;
        worst = worst.max(ratio);
        eprintln!(
            "{} | {} | {fit:.4} | {diagnosis:.3} | {ratio:.1}",
            flags.0,
            data.times.len()
        );
    }
    eprintln!("worst ratio: {worst:.1}");
}

/// The scale record of `n` samples (see the module docs).
fn scale_record(n: usize) -> FitData {
    let ts = 200.0 / n as f64;
    let times: Vec<f64> = (0..n).map(|k| ts * k as f64).collect();
    let u: Vec<f64> = times
        .iter()
        .map(|&t| match t {
            t if t < 20.0 => 0.0,
            t if t < 110.0 => 1.0,
            _ => 1.5,
        })
        .collect();
    let input = Excitation::measured(&times, &u, None, Hold::Zoh).expect("an input that steps");
    let mut v = Values::default();
    for (p, x) in [
        (Param::Kp, 2.0),
        (Param::Tp1, 8.0),
        (Param::Td, 3.0),
        (Param::Y0, 5.0),
    ] {
        v.set(p, x);
    }
    let s = Structure::parse("P1D").expect("a code");
    let mut y = Model::new(s, v).simulate(&input, &times).expect("a model");
    let mut rng = degrau::ident::random::Lcg(7);
    // Never 0, so that its logarithm is finite.
    let mut uniform = move || (rng.bits() as f64 + 0.5) / (1u64 << 53) as f64;
    for v in y.iter_mut() {
        // Box–Muller: σ = 0.01.
        let (a, b) = (uniform(), uniform());
        *v += 0.01 * (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos();
    }
    FitData { times, y, input }
}

fn scale() {
    eprintln!(
        "samples | P1D fit, 16 starts (s) | one start (s) | diagnosis (s) | scipy one start (s) | fit/scipy (≤ 1.5) | one start/scipy | diagnosis/scipy (≤ 10)"
    );
    let p1d = Structure::parse("P1D").expect("a code");
    let p1 = Structure::parse("P1").expect("a code");
    for n in [1_000, 10_000, 100_000, 1_000_000] {
        let data = scale_record(n);
        let guess = degrau::ident::fit::guess::auto_guess(&data, p1d, None);
        let runs = if n >= 1_000_000 { 2 } else { 3 };
        let fit = best_of(runs, || {
            degrau::ident::fit::fit(&data, p1d, guess, &FitOptions::default(), &mut ()).ok()
        });
        let one = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let single = best_of(runs, || {
            degrau::ident::fit::fit(&data, p1d, guess, &one, &mut ()).ok()
        });
        let options = DiagnoseOptions::default();
        // One diagnosis of the 10⁶-sample record (seconds each), the best of 3 below it.
        let diagnosis = best_of(runs.min(if n >= 1_000_000 { 1 } else { 3 }), || {
            diagnose(&data, p1, None, &options).ok()
        });
        let start = [Param::Kp, Param::Tp1, Param::Td, Param::Y0].map(|p| guess.get(p));
        match common::scipy_p1d(&data, start) {
            Some((scipy, _)) => eprintln!(
                "{n} | {fit:.4} | {single:.4} | {diagnosis:.3} | {scipy:.4} | {:.2} | {:.2} | {:.1}",
                fit / scipy,
                single / scipy,
                diagnosis / scipy
            ),
            None => {
                eprintln!("{n} | {fit:.4} | {single:.4} | {diagnosis:.3} | (scipy absent) | | | ")
            }
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let wants =
        |part: &str| args.iter().all(|a| a.starts_with('-')) || args.iter().any(|a| a == part);
    if wants("records") {
        records();
    }
    if wants("scale") {
        scale();
    }
}
