//! Cost of the exact step response and its metrics, by system order.
//!
//! For each order 1..=10 a representative stable system: lightly damped pairs (ζ ≈ 0.03–0.6)
//! mixed with real poles, a zero at −2 from order 2 on, scaled to a static gain of 1.
//! - `metrics`: `StepResponse::new` + `StepInfo::of_response` (targets: ≤ 50 µs up to
//!   order 8);
//! - `metrics+curve`: the same plus 2000 samples of y over the plotting horizon
//!   (target: ≤ 200 µs) over [0, 1.5 × settling time] (1.2 × peak time if later), the
//!   window `auto_horizon` shows, taken from the metrics just computed (`auto_horizon`
//!   itself would compute them a second time).
//!
//! Run: `cargo bench --bench step -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use degrau::lti::{C64, StepInfo, StepInfoOptions, StepResponse, TransferFunction};

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

fn metrics(g: &TransferFunction, options: &StepInfoOptions) -> (StepResponse, StepInfo) {
    let r = StepResponse::new(g, 1.0).expect("a valid response");
    let info = StepInfo::of_response(&r, options);
    (r, info)
}

/// The plotting window of a settling response, from metrics already computed.
fn horizon(r: &StepResponse, info: &StepInfo) -> f64 {
    let settle = info.settling_time.unwrap_or(0.0) - r.delay();
    let peak = info.peak_time.map_or(0.0, |t| t - r.delay());
    r.delay() + (1.5 * settle).max(1.2 * peak)
}

fn bench_step(c: &mut Criterion) {
    let options = StepInfoOptions::default();
    let systems: Vec<(usize, TransferFunction)> = (1..=10).map(|n| (n, system(n))).collect();

    let mut group = c.benchmark_group("metrics");
    for (order, g) in &systems {
        group.bench_with_input(BenchmarkId::from_parameter(order), g, |b, g| {
            b.iter(|| metrics(black_box(g), &options).1)
        });
    }
    group.finish();

    let mut group = c.benchmark_group("metrics+curve");
    for (order, g) in &systems {
        group.bench_with_input(BenchmarkId::from_parameter(order), g, |b, g| {
            b.iter(|| {
                let (r, info) = metrics(black_box(g), &options);
                let curve = r.sample_uniform(0.0, horizon(&r, &info), 2000);
                (info, curve)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_step);
criterion_main!(benches);
