//! The real app driven through egui_kittest (no GPU): drag poles, add and delete zeros,
//! undo, watch the metrics, toggle markers. Assertions read what a student reads.

use crate::{kit, run};

use degrau::app::DegrauApp;
use degrau::app::design::state::{RootKind, System};
use degrau::ident::random::Lcg;
use eframe::egui::{self, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

fn harness(app: DegrauApp) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

fn center_of(h: &Harness<'_, DegrauApp>, label: &str) -> Pos2 {
    h.get_by_label(label).rect().center()
}

/// Presses at `from`, moves in small steps to `to`, releases: as a hand would.
fn drag(h: &mut Harness<'_, DegrauApp>, from: Pos2, to: Pos2) {
    h.hover_at(from);
    h.run_steps(1);
    h.drag_at(from);
    h.run_steps(1);
    for k in 1..=8 {
        let p = from + (to - from) * (k as f32 / 8.0);
        h.hover_at(p);
        h.run_steps(1);
    }
    h.drop_at(to);
    h.run_steps(2);
}

/// The text of the metrics-table cell right of `name` (the next label in the tree).
fn metric(h: &Harness<'_, DegrauApp>, name: &str) -> String {
    let labels: Vec<String> = h
        .get_all_by_role(egui::accesskit::Role::Label)
        .filter_map(|n| {
            n.accesskit_node()
                .label()
                .or_else(|| n.value())
                .map(|s| s.to_string())
        })
        .collect();
    let i = labels
        .iter()
        .position(|l| l == name)
        .unwrap_or_else(|| panic!("no {name} in {labels:?}"));
    labels[i + 1].clone()
}

fn seconds(cell: &str) -> f64 {
    cell.trim_end_matches(" s")
        .parse()
        .unwrap_or_else(|_| panic!("not seconds: {cell}"))
}

fn degrau_step(args: &[&str]) -> serde_json::Value {
    run::command_json("step", args)
}

#[test]
fn dragging_pole_1_updates_the_metrics_like_the_cli() {
    let mut h = harness(DegrauApp::default());
    let before = metric(&h, "Rise time");
    let from = center_of(&h, "pole 1");
    drag(&mut h, from, from + Vec2::new(-40.0, 25.0));
    let pole = h.state().system().poles[0];
    assert_eq!(pole.kind, RootKind::Pair);
    assert!(pole.re < -1.0 && pole.im < 2.0, "moved to {pole:?}");
    let after = metric(&h, "Rise time");
    assert_ne!(before, after);
    let poles = format!("{}+{}j,{}-{}j,-5", pole.re, pole.im, pole.re, pole.im);
    let cli = degrau_step(&["--poles", &poles, "--gain", "0.5", "--amplitude", "2"]);
    let expected = cli["rise_time"].as_f64().unwrap();
    assert!(
        (seconds(&after) - expected).abs() <= 1e-4 * expected,
        "{after} vs {expected}"
    );
    let settle = cli["settling_time"].as_f64().unwrap();
    assert!((seconds(&metric(&h, "Settling time")) - settle).abs() <= 1e-4 * settle);
}

#[test]
fn a_complex_pair_stays_conjugate_through_a_drag() {
    let mut h = harness(DegrauApp::default());
    let from = center_of(&h, "pole 1");
    drag(&mut h, from, from + Vec2::new(30.0, -50.0));
    let tf = h.state().system().transfer_function().unwrap();
    let p = tf.poles();
    let upper = p.iter().find(|r| r.im > 0.0).unwrap();
    assert!(p.contains(&upper.conj()), "poles {p:?}");
    let (top, mirror) = (center_of(&h, "pole 1"), center_of(&h, "pole 1 mirror"));
    let axis_y = 0.5 * (top.y + mirror.y);
    assert!((top.x - mirror.x).abs() < 0.5);
    let real = center_of(&h, "pole 2");
    assert!(
        (real.y - axis_y).abs() < 0.5,
        "the real axis is halfway between the pair"
    );
}

#[test]
fn undo_restores_the_previous_system_exactly() {
    let mut h = harness(DegrauApp::default());
    let original = h.state().system().clone();
    let from = center_of(&h, "pole 2");
    drag(&mut h, from, from + Vec2::new(60.0, 0.0));
    assert_ne!(h.state().system(), &original);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().system(), &original);
    h.key_press_modifiers(
        egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
        egui::Key::Z,
    );
    h.run_steps(2);
    assert_ne!(h.state().system(), &original, "redo re-applies the drag");
}

#[test]
fn add_and_delete_a_zero() {
    let mut h = harness(DegrauApp::default());
    assert!(h.query_by_label("zero 1").is_none());
    h.get_by_label("+ real zero").click();
    h.run_steps(2);
    assert_eq!(h.state().system().zeros.len(), 1);
    h.get_by_label("zero 1").click();
    h.run_steps(1);
    h.key_press(egui::Key::Delete);
    h.run_steps(2);
    assert!(h.state().system().zeros.is_empty());
    assert!(h.query_by_label("zero 1").is_none());
    assert_eq!(h.state().system(), &System::default());
}

#[test]
fn a_pole_dragged_into_the_right_half_plane_warns() {
    let mut h = harness(DegrauApp::default());
    let warning = "Unstable: a pole is in the right half plane";
    assert!(h.query_by_label(warning).is_none());
    let from = center_of(&h, "pole 2");
    let origin_x = center_of(&h, "pole 1").x + (center_of(&h, "pole 1").x - from.x) / 4.0;
    drag(&mut h, from, Pos2::new(origin_x + 60.0, from.y));
    assert!(h.state().system().poles[1].re > 0.0);
    h.get_by_label(warning);
    assert!(metric(&h, "Settling time").contains("does not settle"));
}

#[test]
fn marker_toggles_hide_and_show_markers() {
    let mut h = harness(DegrauApp::default());
    let rise_marker =
        |h: &Harness<'_, DegrauApp>| h.query_by_label_contains("rise time ").is_some();
    assert!(rise_marker(&h), "the rise span is in the legend");
    h.get_by_label("Rise").click();
    h.run_steps(2);
    assert!(!rise_marker(&h));
    h.get_by_label("Rise").click();
    h.run_steps(2);
    assert!(rise_marker(&h));
}

#[test]
fn arrow_keys_nudge_the_selected_root() {
    let mut h = harness(DegrauApp::default());
    h.get_by_label("pole 2").click();
    h.run_steps(1);
    let before = h.state().system().poles[1].re;
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(1);
    let after = h.state().system().poles[1].re;
    assert!(after > before, "{before} -> {after}");
    h.key_press(egui::Key::ArrowUp);
    h.run_steps(1);
    assert_eq!(
        h.state().system().poles[1].im,
        0.0,
        "a real pole stays on the axis"
    );
}

#[test]
fn a_preset_loads_with_its_comparison() {
    let mut h = harness(DegrauApp::default());
    h.get_by_label("Example").click();
    h.run_steps(2);
    h.get_by_label("Fifth order vs its dominant pair −3 ± 3j")
        .click();
    h.run_steps(3);
    assert_eq!(h.state().system().counts(), (5, 0));
    assert!(
        h.get_all_by_label("B: second-order approximation").count() >= 1,
        "legend and table name B"
    );
    h.get_by_label("Stop comparing").click();
    h.run_steps(2);
    assert!(h.query_by_label("B: second-order approximation").is_none());
}

#[test]
fn the_session_survives_a_restart() {
    let mut h = harness(DegrauApp::default());
    let from = center_of(&h, "pole 2");
    drag(&mut h, from, from + Vec2::new(40.0, 0.0));
    let saved = serde_json::to_string(&h.state().saved).unwrap();
    let restored: degrau::app::Saved = serde_json::from_str(&saved).unwrap();
    let h2 = harness(DegrauApp::new(restored));
    assert_eq!(h2.state().system(), h.state().system());
    assert_eq!(metric(&h2, "Rise time"), metric(&h, "Rise time"));
}

#[test]
fn the_curve_exports_as_csv() {
    let mut h = harness(DegrauApp::default());
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Export…").click();
    // The command opens the window after that frame; the next one lays it out.
    h.run_steps(3);
    let dir = std::env::temp_dir().join(format!("degrau-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    kit::retype_field_ending(&mut h, "degrau_step.png", path.to_str().unwrap());
    h.run_steps(1);
    h.get_by_label("Save curve as CSV").click();
    h.run_steps(2);
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows[0], "t_s,y");
    assert_eq!(rows.len(), 2001);
    let last: Vec<f64> = rows[2000].split(',').map(|v| v.parse().unwrap()).collect();
    assert!(
        (last[1] - 0.04).abs() < 0.04 * 0.02,
        "settled near 1/25 at the end: {last:?}"
    );
    h.get_by_label_contains("Saved the curve to");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn no_sequence_of_edits_panics() {
    for seed in [1u64, 7, 42] {
        let mut rng = Lcg(seed);
        let mut h = harness(DegrauApp::default());
        let canvas = h.get_by_label("pole 1").rect().center();
        for _ in 0..60 {
            let labels: Vec<String> = h
                .get_all_by_role(egui::accesskit::Role::Button)
                .filter_map(|n| n.accesskit_node().label().map(|l| l.to_string()))
                .filter(|l| (l.starts_with("pole ") || l.starts_with("zero ")) && !l.ends_with(':'))
                .collect();
            match rng.below(9) {
                0..=2 if !labels.is_empty() => {
                    let label = &labels[rng.below(labels.len())];
                    let from = center_of(&h, label);
                    let to = canvas
                        + Vec2::new(
                            (rng.unit() as f32) * 500.0 - 250.0,
                            (rng.unit() as f32) * 400.0 - 200.0,
                        );
                    drag(&mut h, from, to);
                }
                3 => {
                    let add =
                        ["+ real pole", "+ pole pair", "+ real zero", "+ zero pair"][rng.below(4)];
                    h.get_by_label(add).click();
                }
                4 if !labels.is_empty() => {
                    h.get_by_label(&labels[rng.below(labels.len())]).click();
                    h.run_steps(1);
                    h.key_press(egui::Key::Delete);
                }
                5 => h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z),
                6 => h.key_press_modifiers(
                    egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
                    egui::Key::Z,
                ),
                7 => {
                    let toggles: Vec<String> = h
                        .get_all_by_role(egui::accesskit::Role::Button)
                        .filter_map(|n| n.accesskit_node().label().map(|l| l.to_string()))
                        .filter(|l| l == "make pair" || l == "make real")
                        .collect();
                    if !toggles.is_empty() {
                        h.get_all_by_label(&toggles[rng.below(toggles.len())])
                            .next()
                            .unwrap()
                            .click();
                    }
                }
                _ => {
                    let scroll = if rng.below(2) == 0 { 120.0 } else { -120.0 };
                    kit::wheel(&mut h, canvas, scroll);
                }
            }
            h.run_steps(2);
            // Whatever the edits did, the app shows either a response or why there is none.
            let shows_reason = h.query_by_label_contains("No step response:").is_some();
            assert_eq!(shows_reason, h.state().design.analysis.tf.is_err());
        }
    }
}
