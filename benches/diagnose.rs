//! The whole diagnose loop on an 800-sample step test (issue 5 target: ≤ 300 ms on the
//! 2-core machine): a P2D process with noise, started from P1, so the loop names and adds
//! the dead time and the extra pole, then finds nothing more.

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::ident::diagnose::{DiagnoseOptions, diagnose};
use degrau::ident::fit::FitData;
use degrau::ident::models::{Model, Param, StepSetup, Structure, Values};

fn data() -> FitData {
    let s = Structure::parse("P2D").unwrap();
    let mut v = Values::default();
    v.set(Param::Kp, 1.8);
    v.set(Param::Tp1, 12.0);
    v.set(Param::Tp2, 5.0);
    v.set(Param::Td, 4.0);
    v.set(Param::Y0, 30.0);
    let setup = StepSetup { t0: 20.0, du: 4.0 };
    let times: Vec<f64> = (0..800).map(|k| 0.25 * k as f64).collect();
    let mut y = Model::new(s, v).simulate(&setup, &times).unwrap();
    let mut state = 7u64;
    for v in y.iter_mut() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        *v += 0.07 * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
    }
    FitData { times, y, setup }
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
