//! Cost of the frequency view (issue 26) for one loop, what the app recomputes when the
//! source or the controller changes: the Bode diagram on its default grid, the margins
//! (every crossing refined, the delay margin, Ms, the bandwidth) and the Nyquist curve with
//! its encirclement count.
//!
//! - `fopdt-pi`: G = e^{−2s}/(10s + 1) under SIMC's PI (Kc = 2.5, Ti = 10 s);
//! - `fifth-order`: G = 4(s + 3)/((s + 1)(s + 2)(s² + 0.4s + 4)(s + 10)) under P control
//!   (Kc = 1), a resonance and several crossings, no dead time.
//!
//! Run: `cargo bench --bench frequency -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::lti::TransferFunction;
use degrau::lti::bode::{bode, frequency_grid};
use degrau::lti::control::{Action, Controller, margins, nyquist};

fn loops() -> Vec<(&'static str, TransferFunction, Controller)> {
    let fopdt = TransferFunction::from_coeffs(&[1.0], &[10.0, 1.0])
        .and_then(|g| g.with_delay(2.0))
        .expect("a valid plant");
    let pi = Controller::new(Action::PI, 2.5, 10.0, 0.0).expect("a valid controller");
    let den = [1.0, 13.4, 41.2, 84.8, 136.0, 80.0];
    // (s + 1)(s + 2)(s² + 0.4s + 4)(s + 10) expanded.
    let fifth = TransferFunction::from_coeffs(&[4.0, 12.0], &den).expect("a valid plant");
    let p = Controller::proportional(1.0).expect("a valid controller");
    vec![("fopdt-pi", fopdt, pi), ("fifth-order", fifth, p)]
}

fn bench_frequency(c: &mut Criterion) {
    for (name, g, ctrl) in loops() {
        let l = ctrl
            .transfer_function()
            .map_or(Ok(g.clone()), |c| c.series(&g))
            .expect("the loop");
        let n = nyquist(&g, &ctrl).expect("a Nyquist count");
        eprintln!("{name}: {} points on the Nyquist curve", n.curve.len());
        let mut group = c.benchmark_group(name);
        group.bench_function("bode", |b| {
            b.iter(|| black_box(bode(&l, &frequency_grid(&l, 1000))))
        });
        group.bench_function("margins", |b| {
            b.iter(|| black_box(margins(black_box(&g), &ctrl)))
        });
        group.bench_function("nyquist", |b| {
            b.iter(|| black_box(nyquist(black_box(&g), &ctrl)))
        });
        group.finish();
    }
}

criterion_group!(benches, bench_frequency);
criterion_main!(benches);
