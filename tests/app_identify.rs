//! The identification view of the real app, through egui_kittest: load a file by path, drag
//! the dead-time handle, run a fit, cancel one, read the parameter table and residuals.

mod kit;

use std::time::{Duration, Instant};

use degrau::app::DegrauApp;
use degrau::ident::models::Param;
use eframe::egui::{self, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const LECI: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/leci_step.csv");
const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

fn harness() -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    h
}

/// Types `path` into the File field and presses Load.
fn load(h: &mut Harness<'_, DegrauApp>, path: &str) {
    let field = h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Step test file");
    field.focus();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Step test file")
        .type_text(path);
    h.run_steps(1);
    h.get_by_label("Load").click();
    h.run_steps(3);
}

/// Steps until `done` holds (the fit runs on its own thread), at most 20 s.
fn wait_for(h: &mut Harness<'_, DegrauApp>, done: impl Fn(&Harness<'_, DegrauApp>) -> bool) {
    let start = Instant::now();
    while !done(h) {
        assert!(start.elapsed() < Duration::from_secs(20), "timed out");
        std::thread::sleep(Duration::from_millis(5));
        h.run_steps(1);
    }
    h.run_steps(2);
}

#[test]
fn load_drag_the_dead_time_fit_and_read_the_results() {
    let mut h = harness();
    load(&mut h, LECI);
    h.get_by_label_contains("Loaded 35 samples");
    // The LECI file has no input column: the step and y0 of the notes are typed.
    h.state_mut().ident.loaded.as_mut().unwrap().experiment.du = 10.0;
    h.state_mut()
        .ident
        .loaded
        .as_mut()
        .unwrap()
        .experiment
        .offset = degrau::ident::experiment::Offset::Fixed(50.0);
    h.state_mut().ident.rebuild(true);
    h.run_steps(2);
    let td_before = h
        .state()
        .ident
        .loaded
        .as_ref()
        .unwrap()
        .guess
        .get(Param::Td);
    kit::drag_by(&mut h, "dead time handle", Vec2::new(30.0, 0.0), 5);
    let td_after = h
        .state()
        .ident
        .loaded
        .as_ref()
        .unwrap()
        .guess
        .get(Param::Td);
    assert!(td_after > td_before + 0.1, "Td {td_before} → {td_after}");

    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| h.query_by_label("Fitted P2DU").is_some());
    for name in ["Kp", "Tw", "Zeta", "Td", "95 % interval"] {
        h.get_by_label(name);
    }
    h.get_by_label("Residuals y − ŷ");
    let report = h.state().ident.report.clone().unwrap();
    let wn = 1.0 / report.model.get(Param::Tw);
    assert!((wn - 0.9659).abs() < 0.02, "ωn = {wn}");
    assert!((report.model.get(Param::Kp) - 1.0021).abs() < 0.02);
}

#[test]
fn a_fit_can_be_cancelled() {
    let mut h = harness();
    h.state_mut().ident.settings.y_col = "T1".into();
    h.state_mut().ident.settings.u_col = "Q1".into();
    h.state_mut().ident.settings.code = "P3D".into();
    h.state_mut().ident.settings.starts = 256;
    load(&mut h, TCLAB);
    h.get_by_label_contains("Loaded 801 samples");
    h.get_by_label("Fit").click();
    h.run_steps(1);
    assert!(h.state().ident.is_fitting(), "{}", h.state().ident.status);
    h.run_steps(1);
    h.get_by_label("Cancel").click();
    h.run_steps(1);
    wait_for(&mut h, |h| !h.state().ident.is_fitting());
    h.get_by_label_contains("cancelled");
}

#[test]
fn a_bad_file_keeps_what_was_loaded() {
    let mut h = harness();
    load(&mut h, LECI);
    h.get_by_label_contains("Loaded 35 samples");
    load(&mut h, "/nonexistent/file.csv");
    h.get_by_label_contains("What was loaded before is kept");
    assert_eq!(h.state().ident.loaded.as_ref().unwrap().test.time.len(), 35);
}

#[test]
fn the_whole_loop_fills_the_chain_table() {
    let mut h = harness();
    h.state_mut().ident.settings.y_col = "T1".into();
    h.state_mut().ident.settings.u_col = "Q1".into();
    h.state_mut().ident.settings.code = "P1".into();
    load(&mut h, TCLAB);
    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| h.query_by_label("Fitted P1").is_some());
    h.get_by_label("What does the model get wrong?");
    h.get_by_label("Run the whole loop").click();
    h.run_steps(1);
    wait_for(&mut h, |h| !h.state().ident.is_diagnosing());
    for head in ["Model", "RMSE", "Fit %", "BIC change", "Kp ± 95 %"] {
        h.get_by_label(head);
    }
    let d = h.state().ident.diagnosis.clone().expect("a chain");
    assert!(!d.steps.is_empty());
    // The chain's rows: the start P1 and each extension, selectable.
    // The table sits low in the scrolled side panel: select rows as a screen reader would.
    h.get_by_label(&d.start.model.structure.label())
        .click_accesskit();
    h.run_steps(2);
    assert_eq!(h.state().ident.selected_step, Some(0));
    h.get_by_label(&d.final_fit.model.structure.label())
        .click_accesskit();
    h.run_steps(2);
    h.get_by_label_contains("Remedy:");
}

/// The shipped example loads with the notes' step and operating point, and P2DU fits it to
/// the notes' answer (Gdc 1.0021, θ 1.759 s, ζ 0.1948, ωn 0.9659 rad/s) within 2 %.
#[test]
fn the_leci_example_loads_and_fits_to_the_notes_answer() {
    let mut h = harness();
    h.get_by_label("Example").click();
    h.run_steps(3);
    h.get_by_label_contains("Loaded the LECI example");
    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| h.query_by_label("Fitted P2DU").is_some());
    let report = h.state().ident.report.clone().expect("a fit");
    let m = &report.model;
    for (p, notes) in [
        (Param::Kp, 1.0021),
        (Param::Td, 1.759),
        (Param::Zeta, 0.1948),
    ] {
        let v = m.get(p);
        assert!(
            (v - notes).abs() < 0.02 * notes,
            "{}: {v} vs {notes}",
            p.name()
        );
    }
    let wn: f64 = 1.0 / m.get(Param::Tw);
    assert!((wn - 0.9659).abs() < 0.02 * 0.9659, "ωn {wn}");
    assert_eq!(m.get(Param::Y0), 50.0);
}

/// The step time is a vertical line on the plot: dragging it right moves t0 by what the
/// pointer moved, in the plot's own time units, and the field shows the new value.
#[test]
fn the_step_time_line_drags_t0() {
    let mut h = harness();
    h.get_by_label("Example").click();
    h.run_steps(3);
    let t0 = |h: &Harness<'_, DegrauApp>| h.state().ident.loaded.as_ref().unwrap().experiment.t0;
    assert_eq!(t0(&h), 5.0);
    kit::drag_by(&mut h, "step time line", Vec2::new(40.0, 0.0), 5);
    let moved = t0(&h);
    // 40 px on a plot of about 40 s across some 800 px: about 2 s later.
    assert!(moved > 5.5 && moved < 9.0, "t0 5 → {moved}");
    let d = h
        .state()
        .ident
        .loaded
        .as_ref()
        .unwrap()
        .data
        .clone()
        .unwrap();
    assert_eq!(d.setup.t0, moved, "the fit data follow the line");
}

/// A file dropped on the window, as eframe hands it over: a path.
#[derive(Debug)]
struct DroppedPath(std::path::PathBuf);

impl egui::DroppedFile for DroppedPath {
    fn path(&self) -> &std::path::Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// Dropping a file on the window loads it (switching to the identification view); pasting
/// columns outside a text field loads them; a paste that is not a step test keeps the file.
#[test]
fn a_dropped_file_and_pasted_columns_load() {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.input_mut()
        .dropped_files
        .push(std::sync::Arc::new(DroppedPath(TCLAB.into())));
    h.run_steps(3);
    h.get_by_label_contains("Loaded 801 samples");
    assert_eq!(
        h.state().ident.loaded.as_ref().unwrap().test.time.len(),
        801
    );

    h.event(egui::Event::Paste("hello, world".into()));
    h.run_steps(3);
    h.get_by_label_contains("The pasted text is not a step test");
    assert_eq!(
        h.state().ident.loaded.as_ref().unwrap().test.time.len(),
        801
    );

    let columns: String = (0..40)
        .map(|k| {
            let t = 0.5 * k as f64;
            let y = if t < 2.0 {
                0.0
            } else {
                1.0 - (-(t - 2.0) / 3.0).exp()
            };
            format!("{t}\t{y}\n")
        })
        .collect();
    h.event(egui::Event::Paste(columns));
    h.run_steps(3);
    h.get_by_label_contains("Loaded 40 samples from pasted data");
    assert_eq!(h.state().ident.loaded.as_ref().unwrap().test.time.len(), 40);
}

/// A restart loads the same test again with the choices made on it: the example, or a file.
#[test]
fn a_restart_reloads_the_test_and_its_choices() {
    let restart = |h: &Harness<'_, DegrauApp>| {
        let mut saved = h.state().saved.clone();
        saved.ident = h.state().ident.settings_to_save();
        let text = serde_json::to_string(&saved).unwrap();
        DegrauApp::new(serde_json::from_str(&text).unwrap())
    };
    let mut h = harness();
    h.get_by_label("Example").click();
    h.run_steps(3);
    h.state_mut().ident.set_step_time(5.5);
    let again = restart(&h);
    let l = again.ident.loaded.as_ref().expect("the example again");
    assert_eq!(l.test.time.len(), 35);
    assert_eq!(l.experiment.t0, 5.5);
    assert_eq!(l.experiment.du, 10.0);

    load(&mut h, TCLAB);
    h.get_by_label_contains("Loaded 801 samples");
    let again = restart(&h);
    let l = again.ident.loaded.as_ref().expect("the file again");
    assert_eq!(l.test.time.len(), 801);
    assert!(!again.ident.settings.example);
}

/// A test whose input is already stepped at the first sample (the heater on from t = 0): the
/// step is found once the input before the record is typed.
#[test]
fn the_input_before_the_record_finds_a_step_at_the_first_sample() {
    const DROPOUTS: &str = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/records/tclab_step_q1_50_dropouts_synthetic.csv"
    );
    let mut h = harness();
    h.state_mut().ident.settings.y_col = "T1".into();
    h.state_mut().ident.settings.u_col = "Q1".into();
    load(&mut h, DROPOUTS);
    h.get_by_label_contains("the step could not be found");
    h.state_mut().ident.settings.initial_input = "0".into();
    load(&mut h, DROPOUTS);
    let e = h.state().ident.loaded.as_ref().unwrap().experiment.clone();
    assert_eq!((e.t0, e.du), (0.0, 50.0));
    h.state_mut().ident.settings.initial_input = "zero".into();
    load(&mut h, DROPOUTS);
    h.get_by_label_contains("\"zero\" is not a number");
}
