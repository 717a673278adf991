//! CPU time of one app frame while a pole of an 8th-order system is being dragged: egui's
//! layout, our analysis (exact response, 2000-sample curve, metrics, closed form) and the
//! tessellation of everything drawn, and the autosave (the session serialised when it changed,
//! at most once per debounce interval while the drag goes on, and handed to the saver thread,
//! which writes it to a temporary state file). Driven through egui_kittest, no GPU.
//! Target (issue 3): ≤ 4 ms per frame on the 2-core machine.

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::app::design::state::{GainMode, Root, System};
use degrau::app::{DegrauApp, Saved};
use eframe::egui::{Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn eighth_order() -> System {
    System {
        poles: vec![
            Root::pair(-0.5, 1.5),
            Root::pair(-1.0, 3.0),
            Root::pair(-2.0, 0.8),
            Root::real(-4.0),
            Root::real(-7.0),
        ],
        zeros: vec![Root::real(-1.5), Root::real(-3.0)],
        gain: 1.0,
        gain_mode: GainMode::Static,
        delay: 0.2,
        amplitude: 1.0,
    }
}

fn frame(c: &mut Criterion) {
    let mut saved = Saved::default();
    saved.design.system = eighth_order();
    let dir = std::env::temp_dir().join(format!("degrau-bench-app-frame-{}", std::process::id()));
    let path = dir.join(degrau::app::persist::FILE_NAME);
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    std::fs::write(&path, serde_json::to_string(&saved).expect("json")).expect("a state file");
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(
            |ui, app: &mut DegrauApp| app.show(ui),
            DegrauApp::with_state_file(path),
        );
    h.run_steps(3);
    let start: Pos2 = h.get_by_label("pole 1").rect().center();
    h.hover_at(start);
    h.step();
    h.drag_at(start);
    h.step();
    let mut k = 0u32;
    c.bench_function("app frame, dragging a pole of an 8th-order system", |b| {
        b.iter(|| {
            // Move back and forth over 40 px so the system changes every frame.
            k = k.wrapping_add(1);
            let phase = (k % 40) as f32;
            let offset = if (k / 40).is_multiple_of(2) {
                phase
            } else {
                40.0 - phase
            };
            h.hover_at(start + Vec2::new(-offset, offset * 0.5));
            h.step();
            let output = h.output();
            let shapes = output.shapes.clone();
            let primitives = h.ctx.tessellate(shapes, output.pixels_per_point);
            std::hint::black_box(primitives);
        })
    });
    h.drop_at(start);
    let moved = h.state().system().poles[0];
    assert!(
        moved != eighth_order().poles[0],
        "the drag must have changed the system"
    );
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}

criterion_group!(benches, frame);
criterion_main!(benches);
