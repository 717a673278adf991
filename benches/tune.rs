//! Cost of the tuning table (issue 25): every rule's controller for one model with both
//! loop responses (setpoint and load, exact with the dead time, until they settle), their
//! metrics, the loop's stability and Ms. Target: under 20 ms for one model.
//!
//! - `table/foptd-pi`: K = 1, τ = 10 s, θ = 2 s, PI (7 rules);
//! - `table/foptd-pid`: the same model, PID (the derivative filter's fast pole makes the
//!   steps shorter);
//! - `table/soptd-pid`: K = 2, τ1 = 8 s, τ2 = 3 s, θ = 1 s, PID;
//! - `loop/pid-load`: one load response of a PID loop with its metrics (what a drag of Kc,
//!   Ti or Td recomputes, with the setpoint's).
//!
//! Run: `cargo bench --bench tune -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::lti::control::{
    Action, Controller, Horizon, LoopInput, ProcessModel, loop_metrics, loop_response, rule_table,
};

fn bench_tune(c: &mut Criterion) {
    let foptd = ProcessModel::foptd(1.0, 10.0, 2.0).expect("a valid model");
    let soptd = ProcessModel::soptd(2.0, 8.0, 3.0, 1.0).expect("a valid model");
    let mut group = c.benchmark_group("table");
    for (name, model, action) in [
        ("foptd-pi", foptd, Action::PI),
        ("foptd-pid", foptd, Action::PID),
        ("soptd-pid", soptd, Action::PID),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| black_box(rule_table(black_box(&model), action, None)))
        });
    }
    group.finish();
    let plant = foptd.transfer_function().expect("a valid plant");
    let pid = Controller::new(Action::PID, 6.0, 4.0, 1.0).expect("a valid controller");
    c.bench_function("loop/pid-load", |b| {
        b.iter(|| {
            let r = loop_response(&plant, &pid, LoopInput::Load, Horizon::Auto)
                .expect("a loop response");
            black_box(loop_metrics(&r))
        })
    });
}

criterion_group!(benches, bench_tune);
criterion_main!(benches);
