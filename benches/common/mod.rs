//! Test data shared by the benches: a simulated step test with deterministic noise.

use degrau::ident::excitation::Excitation;
use degrau::ident::fit::FitData;
use degrau::ident::models::{Model, Param, Structure, Values};

/// 800 samples (Ts = 0.25 s) of the model `code` with `truth`, plus uniform noise of
/// peak-to-peak `noise` from a small LCG seeded with `seed`.
pub fn noisy_800(
    code: &str,
    truth: &[(Param, f64)],
    setup: Excitation,
    noise: f64,
    seed: u64,
) -> FitData {
    let s = Structure::parse(code).expect("a valid code");
    let mut v = Values::default();
    for &(p, x) in truth {
        v.set(p, x);
    }
    let times: Vec<f64> = (0..800).map(|k| 0.25 * k as f64).collect();
    let mut y = Model::new(s, v)
        .simulate(&setup, &times)
        .expect("a valid model");
    let mut state = seed;
    for v in y.iter_mut() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        *v += noise * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
    }
    FitData {
        times,
        y,
        input: setup,
    }
}
