//! A fit of a 5·10⁶-sample record (issue 8, item 6), for measuring its peak memory and time:
//! `cargo test --release --test ident_memory -- --ignored --nocapture` under
//! `/usr/bin/time -v`. Ignored by default: it is a measurement, not a check of speed; what it
//! asserts is only that the fit is right.

use degrau::ident::excitation::Excitation;
use std::time::Instant;

use degrau::ident::fit::{FitData, FitOptions, fit};
use degrau::ident::guess::auto_guess;
use degrau::ident::models::{Model, Param, Structure, Values};

const SAMPLES: usize = 5_000_000;

fn record(code: &str) -> FitData {
    let mut truth = Values::default();
    for (p, x) in [
        (Param::Kp, 1.5),
        (Param::Tp1, 40.0),
        (Param::Td, 12.0),
        (Param::Y0, 30.0),
    ] {
        truth.set(p, x);
    }
    let setup = Excitation::step(20.05, 2.0);
    let times: Vec<f64> = (0..SAMPLES).map(|k| 1e-4 * k as f64).collect();
    let mut y = Model::new(Structure::parse(code).unwrap(), truth)
        .simulate(&setup, &times)
        .unwrap();
    let mut state = 7u64;
    for v in y.iter_mut() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        *v += 0.02 * (2.0 * (state >> 11) as f64 / (1u64 << 53) as f64 - 1.0);
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
