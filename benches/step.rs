//! Cost of the exact step response and its metrics, by system order.
//!
//! For each order 1..=10 a representative stable system: lightly damped pairs (ζ ≈ 0.03–0.6)
//! mixed with real poles, a zero at −2 from order 2 on, scaled to a static gain of 1.
//! - `metrics`: `StepResponse::new` + `StepInfo::of_response` (targets: ≤ 50 µs up to
//!   order 8);
//! - `metrics+curve`: `StepResponse::new` + `analyse` (the metrics and their window, the
//!   metrics computed once) plus 2000 samples of y over that window (target: ≤ 200 µs).
//!
//! - `random`: `StepResponse::new` + `analyse` of each of the 2,000 random systems of
//!   orders 1–8 of `benches/systems` (issue 22, item 18), all of them per iteration: the
//!   time per system is the time shown ÷ 2000 (target: the whole `degrau step --batch`
//!   on them ≤ 50 ms, `benches/batch.rs`).
//!
//! Run: `cargo bench --bench step -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use degrau::lti::{C64, StepInfo, StepInfoOptions, StepResponse, TransferFunction, analyse};

mod systems;

/// Lightly damped pairs first, then well damped ones.
const PAIRS: [(f64, f64); 4] = [(-0.5, 3.0), (-1.0, 6.0), (-0.3, 9.0), (-2.0, 1.5)];
const REALS: [f64; 4] = [-1.0, -4.0, -7.0, -12.0];
/// How many of the poles of each order are conjugate pairs.
const PAIR_COUNT: [usize; 10] = [0, 1, 1, 1, 2, 2, 2, 3, 3, 4];

fn system(order: usize) -> TransferFunction {
    let pairs = PAIR_COUNT[order - 1];
    let mut poles = Vec::with_capacity(order);
    for &(re, im) in &PAIRS[..pairs] {
        poles.push(C64::new(re, im));
        poles.push(C64::new(re, -im));
    }
    poles.extend(
        REALS[..order - 2 * pairs]
            .iter()
            .map(|&re| C64::new(re, 0.0)),
    );
    let zeros: &[C64] = if order >= 2 {
        &[C64::new(-2.0, 0.0)]
    } else {
        &[]
    };
    TransferFunction::from_zpk(zeros, &poles, 1.0)
        .and_then(|g| g.with_dc_gain(1.0))
        .expect("a valid benchmark system")
}

fn response(g: &TransferFunction) -> StepResponse {
    StepResponse::new(g, 1.0).expect("a valid response")
}

fn bench_step(c: &mut Criterion) {
    let options = StepInfoOptions::default();
    let systems: Vec<(usize, TransferFunction)> = (1..=10).map(|n| (n, system(n))).collect();

    let mut group = c.benchmark_group("metrics");
    for (order, g) in &systems {
        group.bench_with_input(BenchmarkId::from_parameter(order), g, |b, g| {
            b.iter(|| StepInfo::of_response(&response(black_box(g)), &options))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("metrics+curve");
    for (order, g) in &systems {
        group.bench_with_input(BenchmarkId::from_parameter(order), g, |b, g| {
            b.iter(|| {
                let r = response(black_box(g));
                let analysis = analyse(&r, &options);
                let curve = r.sample_uniform(0.0, analysis.horizon, 2000);
                (analysis.info, curve)
            })
        });
    }
    group.finish();
}

fn bench_random(c: &mut Criterion) {
    let options = StepInfoOptions::default();
    let systems = systems::systems();
    let mut group = c.benchmark_group("random");
    group.sample_size(20);
    group.throughput(Throughput::Elements(systems.len() as u64));
    group.bench_function("2000", |b| {
        b.iter(|| {
            systems
                .iter()
                .map(|s| analyse(&response(black_box(&s.tf)), &options).horizon)
                .sum::<f64>()
        })
    });
    group.finish();
}

criterion_group!(benches, bench_step, bench_random);
criterion_main!(benches);
