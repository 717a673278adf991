//! The whole diagnose loop on an 800-sample step test (issue 5 target: ≤ 300 ms on the
//! 2-core machine): a P2D process with noise, started from P1, so the loop names and adds
//! the dead time and the extra pole, then finds nothing more.

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::ident::diagnose::{DiagnoseOptions, diagnose};
use degrau::ident::excitation::Excitation;
use degrau::ident::fit::FitData;
use degrau::ident::models::{Param, Structure};

mod common;

fn data() -> FitData {
    let truth = [
        (Param::Kp, 1.8),
        (Param::Tp1, 12.0),
        (Param::Tp2, 5.0),
        (Param::Td, 4.0),
        (Param::Y0, 30.0),
    ];
    common::noisy_800("P2D", &truth, Excitation::step(20.0, 4.0), 0.07, 7)
}

fn bench(c: &mut Criterion) {
    let data = data();
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
}

criterion_group!(benches, bench);
criterion_main!(benches);
