//! The hand methods in the Identify mode, through egui_kittest: load the TCLab record, draw
//! the tangent, drag its point along the curve and read θ and τ change in the table.

use crate::kit;

use kit::{load, wait_for};

use degrau::app::DegrauApp;
use degrau::ident::hand::HandMethod;
use eframe::egui::Vec2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

/// The app in the Identify mode with the TCLab record loaded (output T1, input Q1).
fn tclab() -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1500.0, 950.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    let settings = &mut h.state_mut().ident.settings;
    settings.y_col = "T1".into();
    settings.u_col = "Q1".into();
    load(&mut h, TCLAB);
    h.get_by_label_contains("Loaded 801 samples");
    h
}

/// The tangent row's θ and τ cells as a student reads them.
fn tangent_row(h: &Harness<'_, DegrauApp>) -> (f64, f64) {
    let e = h
        .state()
        .ident
        .hand
        .current()
        .expect("the tangent is drawn");
    assert_eq!(e.method, HandMethod::Tangent);
    let (theta, tau) = (e.theta, e.tau.unwrap());
    // The table shows them to four significant digits.
    for x in [theta, tau] {
        let cell = degrau::text::Lang::En.num(x, 4);
        assert!(h.get_all_by_label(&cell).count() > 0, "no cell {cell}");
    }
    (theta, tau)
}

#[test]
fn draw_the_tangent_drag_its_point_and_read_the_table() {
    let mut h = tclab();
    h.get_by_label("Hand methods").click();
    h.run_steps(3);
    // The method's selector comes before its row in the table.
    h.get_all_by_label("Tangent (reaction curve)")
        .next()
        .expect("the method selector")
        .click();
    h.run_steps(3);
    // Every method's row and the least-squares fits beside them.
    for m in ["63.2 % time", "Smith's two points (28.3 %, 63.2 %)"] {
        assert_eq!(h.get_all_by_label(m).count(), 2, "{m}: selector and row");
    }
    // Mollenkamp's row is marked: its construction starts before the step.
    h.get_by_label("Three points (Mollenkamp)");
    h.get_by_label("Three points (Mollenkamp) (!)");
    wait_for(&mut h, |h| h.state().ident.hand.least_squares.len() == 2);
    assert_eq!(h.get_all_by_label("least squares").count(), 2);
    let (theta, tau) = tangent_row(&h);
    // The steepest rise of the heater is early: drag the point later along the curve, where
    // the tangent is flatter and meets y0 earlier.
    kit::drag_by(&mut h, "tangent's point", Vec2::new(120.0, 0.0), 6);
    h.run_steps(3);
    let (theta_after, tau_after) = tangent_row(&h);
    assert!(theta_after < theta - 1.0, "θ {theta} → {theta_after}");
    assert!(tau_after > tau + 1.0, "τ {tau} → {tau_after}");
    let moved = h.state().ident.hand.overrides.tangent_time.expect("moved");
    let point = h
        .state()
        .ident
        .hand
        .current()
        .unwrap()
        .construction
        .tangent
        .unwrap();
    assert!((point.t - moved).abs() < 30.0, "{} vs {moved}", point.t);
    // Reset: back to the steepest rise.
    h.get_by_label("Reset the construction").click();
    h.run_steps(3);
    assert_eq!(tangent_row(&h), (theta, tau));
}

/// A method whose construction starts before the step is marked on its own row, drawn or
/// not (issue 23, item 13: Mollenkamp on TCLab read θ < 0 with no warning in sight, the
/// warning being shown for the drawn method only).
#[test]
fn a_methods_warning_is_marked_on_its_row() {
    let mut h = tclab();
    h.get_by_label("Hand methods").click();
    h.run_steps(3);
    let hand = &h.state().ident.hand;
    assert_ne!(
        hand.method(),
        HandMethod::ThreePoint,
        "another method is drawn"
    );
    let warned = hand
        .results
        .iter()
        .find(|(m, _)| *m == HandMethod::ThreePoint)
        .and_then(|(_, r)| r.as_ref().ok())
        .expect("Mollenkamp's estimate");
    assert!(
        !warned.warnings.is_empty(),
        "its construction starts before the step"
    );
    assert_eq!(warned.theta, 0.0);
    h.get_by_label("Three points (Mollenkamp) (!)");
}
