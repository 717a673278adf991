//! The app's commands, applied in one place: text pasted loads as the Identify mode's test
//! only there and not while a field is typed in; a file dropped loads from any mode; the
//! Identify mode's outcome (its fitted model on the s-plane) and the least-squares mode's
//! (a designed record used as the test) come back as the app's own commands; the export
//! window's view only asks, and only its apply writes; what a state file could not restore
//! is said in the window's language.

use crate::kit;

use std::path::PathBuf;

use degrau::app::export::{self, Ask, Curves, ExportState};
use degrau::app::persist::FILE_NAME;
use degrau::app::{Command, DegrauApp, Mode, identify, lsq};
use degrau::text::Lang;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

/// The app (Design mode, nothing loaded) after its first frames.
fn app() -> Harness<'static, DegrauApp> {
    harness(DegrauApp::default())
}

fn harness(app: DegrauApp) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(2);
    h
}

/// Applies `commands` as the app does at the end of a frame, then draws two frames.
fn apply(h: &mut Harness<'static, DegrauApp>, commands: Vec<Command>) {
    let ctx = h.ctx.clone();
    h.state_mut().apply(&ctx, commands);
    h.run_steps(2);
}

/// A step of 40 samples as tab-separated columns (t, y), as copied from a spreadsheet.
fn columns() -> String {
    (0..40)
        .map(|k| {
            let t = 0.5 * k as f64;
            let y = if t >= 2.0 {
                1.0 - (-(t - 2.0) / 3.0).exp()
            } else {
                0.0
            };
            format!("{t}\t{y}\n")
        })
        .collect()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("degrau-commands-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).expect("dir");
    dir
}

#[test]
fn a_paste_loads_in_the_identify_mode_only() {
    let mut h = app();
    h.event(egui::Event::Paste(columns()));
    h.run_steps(2);
    assert!(h.state().ident.loaded.is_none(), "not in the Design mode");

    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    h.event(egui::Event::Paste(columns()));
    h.run_steps(2);
    h.get_by_label_contains("Loaded 40 samples from pasted data");
    assert_eq!(h.state().saved.mode, Mode::Identify);
}

#[test]
fn a_paste_into_a_field_is_the_fields() {
    let mut h = app();
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Step test file")
        .focus();
    h.run_steps(1);
    h.event(egui::Event::Paste(columns()));
    h.run_steps(2);
    assert!(h.state().ident.loaded.is_none(), "typed, not loaded");
}

#[test]
fn a_dropped_path_and_pasted_text_are_commands_of_the_app() {
    let record = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/leci_step.csv");
    let mut h = app();
    apply(&mut h, vec![Command::LoadPath(record.into())]);
    assert_eq!(
        h.state().saved.mode,
        Mode::Identify,
        "a drop opens the Identify mode"
    );
    h.get_by_label_contains("Loaded 35 samples");
    apply(&mut h, vec![Command::LoadText(columns())]);
    h.get_by_label_contains("Loaded 40 samples from pasted data");
}

#[test]
fn the_fitted_model_opens_on_the_s_plane_through_the_apps_commands() {
    let mut h = app();
    apply(
        &mut h,
        vec![
            Command::SetMode(Mode::Identify),
            Command::Identify(identify::Command::LoadExample),
            Command::Identify(identify::Command::Fit),
        ],
    );
    kit::wait_for(&mut h, |h| h.state().ident.report.is_some());
    let before = h.state().system().clone();
    apply(
        &mut h,
        vec![Command::Identify(identify::Command::ShowOnSPlane)],
    );
    assert_eq!(h.state().saved.mode, Mode::Design);
    assert_ne!(
        h.state().system(),
        &before,
        "the fitted model is the system"
    );
    // One undoable edit, like any other.
    apply(
        &mut h,
        vec![Command::Design(degrau::app::design::Command::Undo)],
    );
    assert_eq!(h.state().system(), &before);
}

#[test]
fn a_designed_record_becomes_the_identify_modes_test() {
    let mut h = app();
    apply(
        &mut h,
        vec![
            Command::SetMode(Mode::LeastSquares),
            Command::Lsq(lsq::Command::SetSection(lsq::Section::Prbs)),
        ],
    );
    assert!(h.state().ident.loaded.is_none());
    apply(&mut h, vec![Command::Lsq(lsq::Command::UsePrbs)]);
    let loaded = h
        .state()
        .ident
        .loaded
        .as_ref()
        .expect("the designed record");
    assert!(loaded.test.time.len() > 10, "{}", loaded.test.time.len());
    assert_eq!(h.state().saved.mode, Mode::LeastSquares, "the mode stays");
}

/// The export window alone, drawn from its state: what it asks is kept, never applied.
fn export_window(state: ExportState) -> Harness<'static, (ExportState, Vec<export::Command>)> {
    let mut h = Harness::builder().with_size([800.0, 400.0]).build_ui_state(
        |ui, (export, asked): &mut (ExportState, Vec<export::Command>)| {
            asked.extend(export.show(ui.ctx(), Lang::En));
        },
        (state, Vec::new()),
    );
    h.run_steps(2);
    h
}

#[test]
fn the_export_window_only_asks_and_its_apply_writes() {
    let dir = temp_dir("export");
    let path = dir.join("curve.csv");
    let mut state = ExportState::default();
    state.open = true;
    state.path = path.display().to_string();
    let mut h = export_window(state);
    h.get_by_label("Save curve as CSV").click();
    h.run_steps(2);
    assert_eq!(h.state().1, [export::Command::Save(Ask::Csv)]);
    assert!(!path.exists(), "nothing is written while drawing");

    let curves = Curves {
        curve: &[[0.0, 0.0], [1.0, 0.5]],
        compare: None,
    };
    let (export, asked) = h.state_mut();
    for command in asked.drain(..) {
        assert_eq!(export.apply(command, curves), None);
    }
    assert_eq!(
        std::fs::read_to_string(&path).expect("written by apply"),
        "t_s,y\n0,0\n1,0.5\n"
    );
    h.run_steps(2);
    h.get_by_label_contains("Saved the curve to");
    h.get_by_label("Browse…").click();
    h.run_steps(2);
    assert_eq!(
        h.state().1,
        [export::Command::Browse],
        "the app opens the dialog"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn what_was_not_restored_is_said_in_the_windows_language() {
    let dir = temp_dir("pt-notice");
    let path = dir.join(FILE_NAME);
    let file = serde_json::json!({
        "lang": "pt",
        "scale": 7.0,
        "system": {"amplitude": "two"},
        "feedback": {"kp": 2e12},
    });
    std::fs::write(&path, file.to_string()).expect("write");
    let h = harness(DegrauApp::with_state_file(path));
    assert_eq!(h.state().saved.lang, Lang::Pt);
    h.get_by_label_contains("Parte da última sessão não pôde ser restaurada");
    h.get_by_label_contains("system.amplitude (\"two\" não é um valor que este campo aceite)");
    h.get_by_label_contains("scale (o tamanho de apresentação 7 não está entre 1 e 2)");
    h.get_by_label_contains("feedback (o ganho Kp = 2000000000000 está além de ±1e12)");
    for english in ["is not", "expected", "beyond", "could not"] {
        assert!(
            h.query_by_label_contains(english).is_none(),
            "English in the Portuguese window: {english}"
        );
    }
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}
