//! The approximation view through egui_kittest: a system built by dragging, a method
//! picked with one click, the overlay of the model's exact response over the original's,
//! the error table's words, the table of every method, and a refusal said in words.

use crate::kit;

use degrau::app::DegrauApp;
use degrau::app::design::approx::APPROX_CURVE_NAME;
use degrau::app::design::state::{Root, System};
use degrau::lti::approx::Approximation;
use degrau::text::Lang;
use degrau::text::approx::{comparison_table, error_row};
use eframe::egui::Vec2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness(app: DegrauApp) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 960.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

/// Builds a system by hand: the example's real pole dragged to the right, then a zero
/// added and dragged too, so the system in view is one no preset holds.
fn dragged_system(h: &mut Harness<'static, DegrauApp>) {
    kit::drag_by(h, "pole 2", Vec2::new(30.0, 0.0), 4);
    h.run_steps(2);
    let system = h.state().system().clone();
    assert!(system.poles[1].re > -5.0, "the drag moved pole 2");
    assert_ne!(system, System::default());
}

#[test]
fn a_method_picked_on_a_dragged_system_shows_the_overlay_and_the_error_table() {
    let mut h = harness(DegrauApp::default());
    dragged_system(&mut h);
    // Closed, the view is one line of buttons and computes nothing.
    assert!(h.state().design.approx.outcome.is_none());
    assert!(h.query_by_label("approximation's step response").is_none());

    h.get_by_label("Skogestad").click();
    h.run_steps(3);
    let view = &h.state().design.approx;
    assert!(matches!(view.choice, Some(Approximation::Reduce(_))));
    let scene = view.scene.as_ref().expect("an overlay to draw");
    assert!(scene.original.len() > 100 && scene.approx.len() > 100);
    // The model's curve differs from the original's (it is an approximation) but ends at
    // the same final value (the static gain is kept).
    let (o, a) = (scene.original.last().unwrap(), scene.approx.last().unwrap());
    assert!((o[1] - a[1]).abs() < 0.02 * o[1].abs(), "{o:?} {a:?}");
    assert!(
        scene
            .original
            .iter()
            .zip(&scene.approx)
            .any(|(o, a)| o[1] != a[1])
    );
    h.get_by_label("approximation's step response");
    h.get_by_label("approximation's s-plane");
    assert!(!APPROX_CURVE_NAME.is_empty());

    // The error table: its header and, for every metric, the row the text layer writes.
    h.get_by_label("Within 5 % (relative)");
    h.get_by_label_contains("max |Δy| / step's effect");
    h.get_by_label_contains("G̃(s) = ");
    let outcome = h.state().design.approx.outcome.clone().unwrap().unwrap();
    for d in &outcome.comparison.metrics {
        let row = error_row(d, Lang::En);
        assert!(
            !h.get_all_by_label(&row[3]).collect::<Vec<_>>().is_empty(),
            "the difference cell of {}: {}",
            row[0],
            row[3]
        );
    }
    // The model keeps the dragged system's static gain.
    let tf = h.state().system().transfer_function().unwrap();
    assert!((outcome.model.dc_gain() - tf.dc_gain()).abs() < 1e-12 * tf.dc_gain().abs());
}

#[test]
fn every_method_in_one_table_and_a_refusal_in_words() {
    let mut h = harness(DegrauApp::default());
    dragged_system(&mut h);
    h.get_by_label("Dominant poles").click();
    h.run_steps(3);
    h.get_by_label("Compare every method").click();
    h.run_steps(3);
    let rows = h.state().design.approx.table.clone().expect("the table");
    assert!(rows.len() >= 8, "{}", rows.len());
    h.get_by_label("Skogestad's half rule, order 1");
    h.get_by_label("Padé moment matching G_{1,1}");
    // Copying puts the Markdown table of those rows on the clipboard.
    let copied = kit::click_and_copied(&mut h, "Copy the table");
    assert_eq!(copied, [comparison_table(&rows, Lang::En)]);
    assert_eq!(copied[0].lines().count(), rows.len() + 2);
    h.run_steps(2);

    // No dead time: its stand-ins say why they do not apply.
    h.get_by_label("θ → Padé").click();
    h.run_steps(3);
    h.get_by_label_contains("the system has no dead time to approximate");
    assert!(h.query_by_label("approximation's step response").is_none());
}

#[test]
fn a_dead_time_stand_in_starts_the_wrong_way_in_portuguese_too() {
    let mut app = DegrauApp::default();
    app.set_system(System {
        poles: vec![Root::real(-1.0)],
        zeros: vec![],
        gain: 1.0,
        delay: 1.0,
        ..System::default()
    });
    app.saved.lang = Lang::Pt;
    let mut h = harness(app);
    h.get_by_label("θ → Padé").click();
    h.run_steps(3);
    let scene = h.state().design.approx.scene.clone().expect("an overlay");
    // e^{−s}/(s + 1) with Padé (1, 1): (−0.5s + 1)/((0.5s + 1)(s + 1)) starts the wrong way
    // (its zero at 2 is in the right half plane), while the true delay holds y at 0.
    let first_dip = scene
        .approx
        .iter()
        .find(|p| p[1] != 0.0)
        .expect("a response");
    assert!(first_dip[1] < 0.0 && first_dip[0] < 0.1, "{first_dip:?}");
    assert!(scene.original.iter().all(|p| p[0] >= 1.0 || p[1] == 0.0));
    h.get_by_label("resposta ao degrau da aproximação");
    h.get_by_label("Dentro de 5 % (relativo)");
    h.get_by_label_contains("Tempo morto → Padé (1, 1)");
}
