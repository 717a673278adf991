//! The Tune mode through egui_kittest: a fitted model sent from the Identify mode, a
//! controller typed, dragged or taken from a rule, both responses' metrics read as a
//! student reads them, a refused entry, the layout at the classroom's sizes, and the
//! settings kept across a restart.

use crate::kit;

use degrau::app::tune::model::ModelKind;
use degrau::app::{DegrauApp, Mode, Saved};
use degrau::ident::model::Param as FitParam;
use degrau::lti::control::Action;
use degrau::text::Lang;
use eframe::egui::{self, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

fn harness(app: DegrauApp, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

/// The app in the Tune mode with `saved`'s settings.
fn tune_app(mut saved: Saved) -> Harness<'static, DegrauApp> {
    saved.mode = Mode::Tune;
    harness(DegrauApp::new(saved), [1360.0, 860.0])
}

/// The words painted beside the plot named `title` (its metrics), in reading order.
fn metrics_under(h: &Harness<'_, DegrauApp>, title: &str) -> Vec<String> {
    let plot = h
        .get_all_by_role(egui::accesskit::Role::Canvas)
        .find(|n| n.accesskit_node().label().as_deref() == Some(title))
        .unwrap_or_else(|| panic!("no plot {title:?}"))
        .rect();
    let mut texts: Vec<(String, egui::Rect)> = kit::painted_texts(h)
        .into_iter()
        .filter(|(_, r)| {
            r.left() > plot.right() && (plot.top()..=plot.bottom()).contains(&r.center().y)
        })
        .collect();
    texts.sort_by(|a, b| {
        (a.1.top(), a.1.left())
            .partial_cmp(&(b.1.top(), b.1.left()))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    texts.into_iter().map(|(t, _)| t).collect()
}

const SETPOINT: &str = "Setpoint step response";
const LOAD: &str = "Load disturbance response (step at the plant's input)";

/// The value written beside `name` under the plot `title`.
fn metric(h: &Harness<'_, DegrauApp>, title: &str, name: &str) -> String {
    let texts = metrics_under(h, title);
    let at = texts
        .iter()
        .position(|t| t == name)
        .unwrap_or_else(|| panic!("no {name:?} under {title:?}: {texts:?}"));
    texts[at + 1].clone()
}

/// Drags the drag value named `name` sideways by `dx` points, in a few moves.
fn drag_value(h: &mut Harness<'_, DegrauApp>, name: &str, dx: f32) {
    let from = h
        .get_by_role_and_label(egui::accesskit::Role::SpinButton, name)
        .rect()
        .center();
    h.hover_at(from);
    h.run_steps(1);
    h.drag_at(from);
    h.run_steps(1);
    for k in 1..=5 {
        h.hover_at(from + Vec2::new(dx * k as f32 / 5.0, 0.0));
        h.run_steps(1);
    }
    h.drop_at(from + Vec2::new(dx, 0.0));
    h.run_steps(2);
}

#[test]
fn a_fitted_tclab_model_is_tuned_and_its_responses_follow_ti() {
    let mut h = harness(DegrauApp::default(), [1360.0, 860.0]);
    kit::fit_tclab(&mut h, "P1D");
    let fitted = h.state().ident.report.clone().expect("a fit").model;
    h.get_by_label("Tune a controller").click_accesskit();
    h.run_steps(3);
    assert_eq!(h.state().saved.mode, Mode::Tune);
    h.get_by_label_contains("From the Identify mode: the fitted P1D");
    let model = h.state().saved.tune.model;
    assert_eq!(model.kind, ModelKind::Foptd);
    assert_eq!(model.k, fitted.get(FitParam::Kp));
    assert_eq!(model.tau1, fitted.get(FitParam::Tp1));
    assert_eq!(model.theta, fitted.get(FitParam::Td));
    // Both responses are measured and labelled as a student reads them.
    h.get_by_label("exact dead time (no Padé)");
    for title in [SETPOINT, LOAD] {
        let texts = metrics_under(&h, title);
        assert!(
            texts.iter().any(|t| t == "Overshoot (%)"),
            "{title}: {texts:?}"
        );
    }
    // The SIMC row: its Kc is Skogestad's τ/(K(τc + θ)) with τc = θ for the fitted model.
    let (k, tau, theta) = (model.k, model.tau1, model.theta);
    let kc = tau / (k * 2.0 * theta);
    let ti = tau.min(8.0 * theta);
    let shown = Lang::En.num(kc, 3);
    assert!(
        h.query_all_by_label(&shown).next().is_some(),
        "SIMC's Kc {shown} in the table"
    );
    h.get_by_label("SIMC").click_accesskit();
    h.run_steps(3);
    let c = h.state().saved.tune.controller;
    assert!((c.kc - kc).abs() < 1e-9 * kc.abs(), "{} vs {kc}", c.kc);
    assert!((c.ti - ti).abs() < 1e-9 * ti, "{} vs {ti}", c.ti);
    h.get_by_label("SIMC (Skogestad's IMC)");
    h.get_by_label_contains("Formula: PI: Kc = ");
    h.get_by_label_contains("Source: Skogestad (2003)");
    for title in [SETPOINT, LOAD] {
        let texts = metrics_under(&h, title);
        assert!(
            texts.iter().any(|t| t == "Overshoot (%)"),
            "{title}: {texts:?}"
        );
    }
    let load_before = metrics_under(&h, LOAD);
    let iae_before = metric(&h, LOAD, "IAE, integral of |e|");
    // Ti typed: the load response's metrics change.
    let ti = h.state().saved.tune.controller.ti;
    kit::type_number(&mut h, "Integral time Ti (s)", 0, &format!("{}", 2.0 * ti));
    assert_eq!(h.state().saved.tune.controller.ti, 2.0 * ti);
    let load_typed = metrics_under(&h, LOAD);
    assert_ne!(load_typed, load_before, "the load metrics follow Ti");
    assert_ne!(metric(&h, LOAD, "IAE, integral of |e|"), iae_before);
    // Ti dragged: they change again, frame by frame.
    drag_value(&mut h, "Ti", -60.0);
    assert!(h.state().saved.tune.controller.ti < 2.0 * ti);
    assert_ne!(
        metrics_under(&h, LOAD),
        load_typed,
        "the drag moves the metrics"
    );
}

#[test]
fn a_zero_ti_is_refused_with_a_reason_and_nothing_is_lost() {
    let mut h = tune_app(Saved::default());
    kit::type_number(&mut h, "Dead time θ (s)", 0, "3");
    kit::type_number(&mut h, "Time constant τ (s)", 0, "12");
    assert_eq!(h.state().saved.tune.model.theta, 3.0);
    assert_eq!(h.state().saved.tune.model.tau1, 12.0);
    h.get_by_label("Typed model");
    let before = h.state().saved.tune.clone();
    let metrics = metrics_under(&h, SETPOINT);
    kit::type_number(&mut h, "Integral time Ti (s)", 0, "0");
    h.get_by_label_contains("Refused: the integral time Ti must be a positive number of seconds");
    assert_eq!(h.state().saved.tune, before, "nothing changed");
    assert_eq!(metrics_under(&h, SETPOINT), metrics, "the responses stay");
    // The next good entry is taken and the message goes.
    kit::type_number(&mut h, "Integral time Ti (s)", 0, "15");
    assert_eq!(h.state().saved.tune.controller.ti, 15.0);
    assert!(h.query_by_label_contains("Refused:").is_none());
}

#[test]
fn a_typed_model_shows_each_rules_controller_and_a_rule_loads_it() {
    let mut h = tune_app(Saved::default());
    kit::type_number(&mut h, "Process gain K", 0, "2");
    kit::type_number(&mut h, "Time constant τ (s)", 0, "12");
    kit::type_number(&mut h, "Dead time θ (s)", 0, "3");
    // SIMC's PI: Kc = τ/(K(τc + θ)) = 12/(2·6) = 1, Ti = min(τ, 4(τc + θ)) = 12.
    let simc = h.state().tune.table.iter().find(|r| r.rule.key() == "simc");
    let (tuning, _) = simc
        .expect("a SIMC row")
        .result
        .as_ref()
        .expect("it applies");
    assert!((tuning.controller.kc - 1.0).abs() < 1e-12);
    h.get_by_label("SIMC").click_accesskit();
    h.run_steps(3);
    let c = h.state().saved.tune.controller;
    assert!((c.kc - 1.0).abs() < 1e-12 && (c.ti - 12.0).abs() < 1e-12);
    assert_eq!(h.state().saved.tune.rule.as_deref(), Some("simc"));
    // PD has no rule: each row says why.
    h.get_by_label("PD").click();
    h.run_steps(3);
    assert!(h.query_all_by_label_contains("does not apply:").count() >= 7);
}

#[test]
fn a_p_controller_says_why_it_has_no_iae_and_an_unstable_loop_says_it_did_not_settle() {
    let mut saved = Saved::default();
    saved.tune.controller.action = Action::P;
    let mut h = tune_app(saved);
    assert!(h.query_by_label("Integral time Ti (s)").is_none());
    assert_eq!(metric(&h, SETPOINT, "IAE, integral of |e|"), "none");
    h.get_all_by_label("none: the error does not vanish without integral action")
        .next()
        .expect("the reason");
    kit::type_number(&mut h, "Controller gain Kc", 0, "40");
    h.get_all_by_label("did not settle: the loop is unstable or too slow")
        .next()
        .expect("the loop does not settle");
}

#[test]
fn the_tune_settings_survive_a_restart() {
    let mut h = tune_app(Saved::default());
    h.get_by_label("Second order + dead time").click();
    h.run_steps(2);
    kit::type_number(&mut h, "Time constant τ2 (s)", 0, "4");
    h.get_by_label("PID").click();
    h.run_steps(2);
    kit::type_number(&mut h, "Derivative time Td (s)", 0, "1,5");
    kit::type_number(&mut h, "Controller gain Kc", 0, "1.8");
    let tune = h.state().saved.tune.clone();
    assert_eq!(tune.model.kind, ModelKind::Soptd);
    assert_eq!(tune.model.tau2, 4.0);
    assert_eq!(tune.controller.action, Action::PID);
    assert_eq!(tune.controller.td, 1.5);
    let load = metrics_under(&h, LOAD);
    // Through the state file: a second start shows the same settings and responses.
    let dir = std::env::temp_dir().join(format!("degrau-tune-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let path = dir.join("state.json");
    let json = serde_json::to_string_pretty(&h.state().saved).expect("JSON");
    degrau::app::persist::write_atomically(&path, json.as_bytes()).expect("written");
    let h2 = harness(DegrauApp::with_state_file(path), [1360.0, 860.0]);
    assert_eq!(h2.state().saved.mode, Mode::Tune);
    assert_eq!(h2.state().saved.tune, tune);
    assert!(h2.state().notices.is_empty());
    assert_eq!(metrics_under(&h2, LOAD), load);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_saved_controller_that_is_no_controller_falls_back_alone() {
    let mut saved = Saved::default();
    saved.tune.model.tau1 = 7.0;
    let mut value = serde_json::to_value(&saved).expect("JSON");
    value["tune"]["controller"]["ti"] = serde_json::json!(0.0);
    let (restored, problems) = degrau::app::persist::restore_value(&value);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(restored.tune.model.tau1, 7.0);
    assert_eq!(
        restored.tune.controller,
        degrau::app::tune::session::ControllerSettings::default()
    );
}

/// The classroom's layout (as every other mode's: 1000×650 and 1600×900, 1× to 1.6×, both
/// languages): the model, the PID controller with a refusal shown, both plots and their
/// metrics; then a P controller whose loop does not settle (its notes shown).
#[test]
fn the_tune_mode_fits_every_classroom_size() {
    let mut saved = Saved {
        mode: Mode::Tune,
        ..Default::default()
    };
    saved.tune.model.kind = ModelKind::Soptd;
    saved.tune.controller.action = Action::PID;
    saved.tune.rule = Some("simc".into());
    let mut h = harness(DegrauApp::new(saved), [1600.0, 900.0]);
    h.get_by_label_contains("Source: Skogestad (2003)");
    kit::type_number(&mut h, "Integral time Ti (s)", 0, "0");
    h.get_by_label_contains("Refused:");
    let mut problems = crate::app_classroom::problems_everywhere(&mut h, "Tune", 2);
    let mut saved = Saved {
        mode: Mode::Tune,
        ..Default::default()
    };
    saved.tune.controller.action = Action::P;
    saved.tune.controller.kc = 40.0;
    let mut unstable = harness(DegrauApp::new(saved), [1600.0, 900.0]);
    problems.extend(crate::app_classroom::problems_everywhere(
        &mut unstable,
        "Tune, unstable",
        2,
    ));
    crate::app_classroom::assert_no_problems(&problems);
}
