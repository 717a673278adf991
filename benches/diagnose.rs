//! The whole diagnose loop on an 800-sample step test (issue 5 target: ≤ 300 ms on the
//! 2-core machine): a P2D process with noise, started from P1, so the loop names and adds
//! the dead time and the extra pole, then finds nothing more.
//!
//! Issue 10 (scale): the whole diagnosis of the 80,000-sample logger record (a P1D driven by
//! a measured input, started from P1) under 10 times scipy's single-start `least_squares` fit
//! of it, measured in the same run (`benches/scipy_p1d.py`, when python3 with numpy and scipy
//! is there); and the diagnosis of the 75,000-row extruder record of `../shared/data/real`
//! when present (it took 110 s).

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::ident::diagnose::{DiagnoseOptions, diagnose};
use degrau::ident::fit::guess::auto_guess;
use degrau::ident::model::excitation::Excitation;
use degrau::ident::model::{Param, Structure};
use std::time::Instant;

mod common;

fn bench(c: &mut Criterion) {
    // The P2D: Kp 1.8, Tp1 12 s, Tp2 5 s, Td 4 s, Y0 30.
    let truth = [1.8, 12.0, 5.0, 4.0, 30.0];
    let data = common::noisy_800("P2D", &truth, Excitation::step(20.0, 4.0), 0.07, 7);
    let start = Structure::parse("P1").unwrap();
    let options = DiagnoseOptions::default();
    let report = diagnose(&data, start, None, &options).unwrap();
    let chain: Vec<&str> = report.steps.iter().map(|s| s.cause.id()).collect();
    eprintln!(
        "chain: {chain:?}, final {}",
        report.final_fit.model.structure.label()
    );
    let mut group = c.benchmark_group("diagnose");
    group.sample_size(10);
    group.bench_function("whole loop, 800 samples, from P1", |b| {
        b.iter(|| diagnose(&data, start, None, &options).unwrap())
    });
    group.finish();
    long_records(c);
}

/// The 80,000-sample logger record against scipy, and the extruder record.
fn long_records(c: &mut Criterion) {
    let data = common::logger_80k();
    let start = Structure::parse("P1").unwrap();
    let options = DiagnoseOptions::default();
    let clock = Instant::now();
    let report = diagnose(&data, start, None, &options).unwrap();
    let chain: Vec<&str> = report.steps.iter().map(|s| s.cause.id()).collect();
    eprintln!(
        "80,000 samples: diagnosed once in {:.3} s; chain {chain:?}, final {}",
        clock.elapsed().as_secs_f64(),
        report.final_fit.model.structure.label()
    );
    let p1d = Structure::parse("P1D").unwrap();
    let guess = auto_guess(&data, p1d, None);
    let first = [Param::Kp, Param::Tp1, Param::Td, Param::Y0].map(|p| guess.get(p));
    match common::scipy_p1d(&data, first) {
        Some((seconds, text)) => eprintln!(
            "scipy least_squares P1D, one start: {seconds:.3} s (10× = {:.3} s)\n{text}",
            10.0 * seconds
        ),
        None => {
            eprintln!("scipy least_squares: not measured (python3 with numpy and scipy absent)")
        }
    }
    let mut group = c.benchmark_group("diagnose long");
    group.sample_size(10);
    group.bench_function("whole loop, 80,000 samples, from P1", |b| {
        b.iter(|| diagnose(&data, start, None, &options).unwrap())
    });
    group.finish();
    extruder();
}

/// The extruder record (75,323 rows), diagnosed from P1 as the CLI does, timed once.
fn extruder() {
    let Some((data, s, guess)) = common::extruder_or_skip("P1") else {
        return;
    };
    let clock = Instant::now();
    let held = (!s.free_offset).then_some(guess);
    match diagnose(&data, s, held, &DiagnoseOptions::default()) {
        Ok(report) => {
            let chain: Vec<&str> = report.steps.iter().map(|s| s.cause.id()).collect();
            eprintln!(
                "extruder: diagnosed in {:.3} s; chain {chain:?}, final {} fit {:.2} %",
                clock.elapsed().as_secs_f64(),
                report.final_fit.model.structure.label(),
                report.final_fit.fit_percent
            );
        }
        Err(e) => eprintln!("extruder diagnosis: {e}"),
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
