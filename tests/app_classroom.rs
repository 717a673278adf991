//! The app in a classroom, through egui_kittest: a small window (1000×650), a presentation
//! size for the projector, and Portuguese.

mod kit;

use degrau::app::{DegrauApp, Saved};
use degrau::text::Lang;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness(app: DegrauApp, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(4);
    h
}

fn at_scale(scale: f32, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    harness(
        DegrauApp::new(Saved {
            scale,
            ..Saved::default()
        }),
        size,
    )
}

/// The rect of the canvas named `name` (the s-plane and the step plot name themselves).
fn canvas(h: &Harness<'_, DegrauApp>, name: &str) -> egui::Rect {
    h.get_by_label(name).rect()
}

#[test]
fn at_1000_by_650_both_plots_are_visible_and_the_markers_bar_does_not_wrap_letters() {
    for scale in [1.0, 1.2] {
        let h = at_scale(scale, [1000.0, 650.0]);
        for name in ["s-plane", "step response"] {
            let r = canvas(&h, name);
            assert!(
                r.width() > 200.0 && r.height() > 200.0,
                "{name} at {scale}×: {r:?}"
            );
        }
        // A wrapped "Settling" would be several lines tall.
        let settling = h.get_by_label("Settling").rect();
        assert!(settling.height() < 30.0, "{settling:?}");
    }
}

/// The tick labels painted on the step plot: (x labels, y labels).
fn ticks(h: &Harness<'_, DegrauApp>, lang: Lang) -> (Vec<f64>, Vec<f64>) {
    let plot = canvas(h, lang.pick("step response", "resposta ao degrau"));
    let decimal = lang.decimal();
    let around = plot.expand(60.0);
    let numbers = kit::numbers_in(h, around, decimal);
    let x = numbers
        .iter()
        .filter(|(_, r)| r.center().y > plot.bottom() - 30.0)
        .map(|(v, _)| *v)
        .collect();
    let y = numbers
        .iter()
        .filter(|(_, r)| r.center().x < plot.left() + 60.0 && r.center().y < plot.bottom() - 30.0)
        .map(|(v, _)| *v)
        .collect();
    (x, y)
}

#[test]
fn the_step_plot_keeps_its_tick_labels_at_every_presentation_size() {
    for scale in [1.0, 1.2, 1.6, 2.0] {
        let h = at_scale(scale, [1360.0, 860.0]);
        assert!((h.ctx.zoom_factor() - scale).abs() < 1e-3);
        let (x, y) = ticks(&h, Lang::En);
        assert!(x.len() >= 2, "x tick labels at {scale}×: {x:?}");
        assert!(y.len() >= 2, "y tick labels at {scale}×: {y:?}");
        // The default response runs from 0 to 0.04 and settles in about 4 s.
        assert!(y.iter().all(|v| (-0.01..=0.06).contains(v)), "{y:?}");
    }
}

#[test]
fn the_size_control_scales_and_is_remembered() {
    let mut h = at_scale(1.0, [1360.0, 860.0]);
    h.get_by_label("A+").click();
    h.run_steps(3);
    h.get_by_label("A+").click();
    h.run_steps(3);
    let scale = h.state().saved.scale;
    assert!((scale - 1.4).abs() < 1e-4, "{scale}");
    assert!((h.ctx.zoom_factor() - 1.4).abs() < 1e-3);
    let json = serde_json::to_string(&h.state().saved).unwrap();
    let restored: Saved = serde_json::from_str(&json).unwrap();
    assert!((DegrauApp::new(restored).saved.scale - 1.4).abs() < 1e-4);
}

#[test]
fn in_portuguese_the_metrics_table_reads_in_portuguese() {
    let mut h = at_scale(1.0, [1360.0, 860.0]);
    h.get_by_label("Rise time");
    h.get_by_label("View").click();
    h.run_steps(2);
    h.get_by_label("Português").click();
    h.run_steps(3);
    assert_eq!(h.state().saved.lang, Lang::Pt);
    for name in [
        "Tempo de subida",
        "Tempo de acomodação",
        "Sobressinal",
        "Valor de pico",
    ] {
        h.get_by_label(name);
    }
    assert!(h.query_by_label("Rise time").is_none());
    // Numbers take the decimal comma, in the table and on the plot's axes.
    h.get_by_label("Polos");
    let (_, y) = ticks(&h, Lang::Pt);
    assert!(y.len() >= 2, "{y:?}");
}
