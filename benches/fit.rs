//! Fitting speed (issue 4 targets, on the 2-core machine):
//! - a P2DU fit of the LECI data from the automatic guess: ≤ 1 ms
//!   (scipy's least_squares takes 3.4 ms on the same problem from a good guess);
//! - a 32-start global fit of an 800-sample test: ≤ 150 ms.

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::ident::excitation::Excitation;
use degrau::ident::fit::{FitData, FitOptions, fit};
use degrau::ident::guess::auto_guess;
use degrau::ident::models::{Param, Structure};

mod common;

fn leci() -> FitData {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/leci_step.csv"))
            .expect("LECI data");
    let (times, y) = text
        .lines()
        .skip(1)
        .filter_map(|l| {
            let (a, b) = l.split_once(',')?;
            Some((a.trim().parse::<f64>().ok()?, b.trim().parse::<f64>().ok()?))
        })
        .unzip();
    FitData {
        times,
        y,
        input: Excitation::step(5.0, 10.0),
    }
}

/// 800 samples of a P2DU with ±1 % uniform noise (deterministic).
fn synthetic_800() -> FitData {
    let truth = [
        (Param::Kp, 0.8),
        (Param::Tw, 4.0),
        (Param::Zeta, 0.3),
        (Param::Td, 6.0),
        (Param::Y0, 20.0),
    ];
    common::noisy_800("P2DU", &truth, Excitation::step(10.0, 5.0), 0.04, 12345)
}

fn benches(c: &mut Criterion) {
    let data = leci();
    let mut s = Structure::parse("P2DU").unwrap();
    s.free_offset = false;
    let guess = auto_guess(&data, s, Some(50.0));
    let one = FitOptions {
        starts: 1,
        ..Default::default()
    };
    c.bench_function("LECI P2DU fit from the automatic guess", |b| {
        b.iter(|| fit(&data, s, guess, &one, &mut ()).unwrap())
    });

    let data = synthetic_800();
    let s = Structure::parse("P2DU").unwrap();
    let guess = auto_guess(&data, s, None);
    let many = FitOptions {
        starts: 32,
        ..Default::default()
    };
    let mut group = c.benchmark_group("global");
    group.sample_size(20);
    group.bench_function("32-start P2DU fit, 800 samples", |b| {
        b.iter(|| fit(&data, s, guess, &many, &mut ()).unwrap())
    });
    group.finish();
}

criterion_group!(fits, benches);
criterion_main!(fits);
