//! A multi-step record in the Identify mode, through egui_kittest: every input change marked
//! on the input plot (at its instant, on the output plot's time axis), every step's window
//! on the output plot, the drive choices and their facts, the per-step table beside the
//! joint fit with what it says about linearity, its cancel, and a record not at rest.

use crate::kit;

use kit::{load, wait_for};

use degrau::app::DegrauApp;
use degrau::app::identify::commands::Command;
use degrau::app::identify::plot::{input_plot_id, main_plot_id};
use degrau::ident::model::Param;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

/// The heater stepped four times (see tests/data/records/SOURCES.md): 20 → 40 → 60 → 30 →
/// 45 % switched at 50.4, 200.7, 350.2 and 480.5 s, logged every second, so each change is
/// first seen at the next whole second; the plant is 0.8·e^(−4s)/(40s + 1).
const HEATER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/multistep_heater_synthetic.csv"
);
const DAISY: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/daisy_heating_system.dat"
);

/// The changes a student sees: (first sample that shows it (s), Δu, the level before).
const CHANGES: [(f64, &str, f64); 4] = [
    (51.0, "+20", 20.0),
    (201.0, "+20", 40.0),
    (351.0, "−30", 60.0),
    (481.0, "+15", 30.0),
];

/// The app in the identification mode with `path` loaded by typing it, model `code`.
fn loaded(path: &str, code: &str, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    loaded_from(path, ("", ""), code, size)
}

/// [`loaded`] with the output and input columns typed first (empty: automatic).
fn loaded_from(
    path: &str,
    (output, input): (&str, &str),
    code: &str,
    size: [f32; 2],
) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    let settings = &mut h.state_mut().ident.settings;
    settings.y_col = output.into();
    settings.u_col = input.into();
    settings.code = code.into();
    load(&mut h, path);
    h
}

fn plot_frame_x(h: &Harness<'_, DegrauApp>, id: egui::Id, t: f64) -> f32 {
    let memory = egui_plot::PlotMemory::load(&h.ctx, id).expect("the plot drew");
    memory
        .transform()
        .position_from_point(&egui_plot::PlotPoint::new(t, 0.0))
        .x
}

#[test]
fn every_change_is_marked_on_the_input_plot_under_the_output() {
    let h = loaded(HEATER, "P1D", [1360.0, 860.0]);
    h.get_by_label_contains("Loaded 600 samples");
    h.get_by_label("Input u(t) as the model sees it");
    h.get_by_label("Measured output and model");
    h.get_by_label("4 input changes used.");
    h.get_by_label_contains("Each change may have come up to 1 s before the sample");
    h.get_by_label_contains("The handles act on the largest change (step 3, t = 351 s)");
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|p| p.0).collect();
    for (k, &(t, du, _)) in CHANGES.iter().enumerate() {
        let label = format!("change {} at t = {t} s (Δu = {du})", k + 1);
        let mark = h.get_by_label(&label);
        // The mark sits at the change's instant, and the output plot above has the same
        // time at the same x: one time axis.
        let x = mark.rect().center().x;
        assert!(
            (x - plot_frame_x(&h, input_plot_id(), t)).abs() < 1.0,
            "{label}"
        );
        assert!(
            (x - plot_frame_x(&h, main_plot_id(), t)).abs() < 1.0,
            "{label}"
        );
        // Each step's window on the output plot, from its change to the next (or the end).
        let end = CHANGES.get(k + 1).map_or(599.0, |c| c.0);
        h.get_by_label(&format!("step {} window, {t} s to {end} s", k + 1));
        assert!(painted.contains(&format!("step {}", k + 1)), "{painted:?}");
        assert!(painted.contains(&format!("{}: {du}", k + 1)), "{painted:?}");
    }
    assert!(h.query_by_label_contains("change 5 at").is_none());
    // One model over every change: the step line of a single step is not offered.
    assert!(h.query_by_label("step time line").is_none());
}

#[test]
fn the_per_step_table_sits_beside_the_joint_fit() {
    let mut h = loaded(HEATER, "P1D", [1360.0, 860.0]);
    h.get_by_label("Fit").click();
    wait_for(&mut h, |h| h.query_by_label("joint fit").is_some());
    h.get_by_label("Fitted P1D");
    h.get_by_label("Each step on its own");
    for head in ["Change", "t (s)", "Tp1 (s)", "Td (s)"] {
        h.get_by_label(head);
    }
    // Kp heads the fit's parameter table too; Δu and "from" are said elsewhere as well.
    for head in ["Kp", "Δu", "from"] {
        assert!(h.query_all_by_label(head).next().is_some(), "{head}");
    }
    let app = h.state();
    let joint = app.ident.report.clone().unwrap();
    let fits = app.ident.per_step.fits.clone().unwrap();
    assert_eq!(fits.len(), 4);
    for (k, (f, &(t, du, from))) in fits.iter().zip(&CHANGES).enumerate() {
        // The table's row (which says when the output still moved before the change: the
        // previous step's response is in its window) and the output plot's legend entry
        // for the step's window.
        let name = format!("step {}", k + 1);
        let moving = format!("step {} (output still moving)", k + 1);
        let rows = h.query_all_by_label(&moving).count();
        assert_eq!(rows, usize::from(f.not_at_rest), "{moving}");
        assert_eq!(h.query_all_by_label(&name).count() + rows, 2, "{name}");
        assert_eq!(f.change.t, t);
        assert!(h.query_all_by_label(du).next().is_some(), "{du}");
        assert_eq!(f.change.u_before, from);
        let r = f.fit.as_ref().unwrap();
        // A linear plant: each step gives its gain and time constant.
        assert!((r.model.get(Param::Kp) - 0.8).abs() < 0.03, "{r:?}");
        assert!((r.model.get(Param::Tp1) - 40.0).abs() < 3.0, "{r:?}");
        // The row shows the step's own Kp with its interval.
        let (lo, hi) = r.interval(Param::Kp).unwrap();
        let cell = format!("{} [{}, {}]", fmt(r.model.get(Param::Kp)), fmt(lo), fmt(hi));
        h.get_by_label(&cell);
    }
    let (lo, hi) = joint.interval(Param::Kp).unwrap();
    h.get_by_label(&format!(
        "{} [{}, {}]",
        fmt(joint.model.get(Param::Kp)),
        fmt(lo),
        fmt(hi)
    ));
    h.get_by_label(
        "Every step agrees with the joint fit, within the 95 % intervals or within what the \
         record resolves (5 %, and a sampling period for Td): nothing here says the process is \
         not linear.",
    );
}

/// A number as the table writes it in English (four significant digits).
fn fmt(x: f64) -> String {
    degrau::text::Lang::En.num(x, 4)
}

#[test]
fn the_per_step_fits_can_be_cancelled_and_run_again() {
    let mut h = loaded(HEATER, "P1", [1360.0, 860.0]);
    h.get_by_label("Fit").click();
    wait_for(&mut h, |h| h.query_by_label("joint fit").is_some());
    h.state_mut().ident.apply(Command::FitEachStep);
    h.run_steps(1);
    h.get_by_label_contains("Fitting step");
    h.state_mut().ident.apply(Command::CancelPerStep);
    h.run_steps(2);
    h.get_by_label("The per-step fits were cancelled.");
    assert!(h.query_by_label("joint fit").is_none());
    h.get_by_label("Fit each step").click_accesskit();
    wait_for(&mut h, |h| h.query_by_label("joint fit").is_some());
    // A new choice on the test drops them with the fit.
    h.get_by_label("one ideal step").click();
    h.run_steps(2);
    assert!(h.query_by_label("joint fit").is_none());
    assert!(h.state().ident.per_step.fits.is_none());
}

#[test]
fn the_drive_is_the_measured_input_or_one_ideal_step() {
    let mut h = loaded(HEATER, "P1D", [1360.0, 860.0]);
    h.get_by_label("Input that drove the test");
    h.get_by_label("4 input changes used.");
    h.get_by_label("one ideal step").click();
    h.run_steps(2);
    // Today's model: the largest change as one step, t0 and Δu typed or read off it.
    h.get_by_label("1 input change used.");
    let e = h.state().ident.loaded.as_ref().unwrap().experiment.clone();
    assert_eq!((e.t0, e.du), (351.0, -30.0));
    h.get_by_label("Step time t0 (s)");
    h.get_by_label("step time line");
    h.get_by_label("measured input").click();
    h.run_steps(2);
    h.get_by_label("4 input changes used.");
    h.get_by_label("straight line (first-order hold)").click();
    h.run_steps(2);
    // An analog input sampled: exact instants, no lead to estimate.
    h.get_by_label("4 input changes used.");
    assert!(
        h.query_by_label_contains("Each change may have come up to")
            .is_none()
    );
    let input = h.state().ident.setup().unwrap();
    assert!(!input.ramps.is_empty() && input.lead_range == 0.0);
}

#[test]
fn a_record_not_at_rest_says_so_and_shows_its_transient() {
    let mut h = loaded(DAISY, "P1", [1360.0, 860.0]);
    h.get_by_label("The output still moved before the first input change (not at rest): Y0 and an initial transient estimated with the other parameters.");
    h.get_by_label("Fit").click();
    wait_for(&mut h, |h| h.query_by_label("Fitted P1").is_some());
    h.get_by_label_contains("X1: coefficient of the initial transient");
    h.get_by_label_contains("Ta: how long before the sample that first shows it");
    // Six changes, each its own row once the per-step fits are done.
    wait_for(&mut h, |h| h.query_by_label("joint fit").is_some());
    let n = h.state().ident.setup().unwrap().changes.len();
    assert!(n >= 2);
    for k in 1..=n {
        // The row (and the plot's span of the same name).
        assert!(
            h.query_all_by_label(&format!("step {k}")).next().is_some()
                || h.query_by_label(&format!("step {k} (output still moving)"))
                    .is_some(),
            "row {k}"
        );
    }
}

/// A gain the record measures only together with another term is said under the chain, in
/// the student's language: the whole loop on the heater record, then its final gain marked
/// as traded with a drift (the record's own gain is pinned: the line must come from the
/// report, and go with it).
#[test]
fn a_gain_traded_with_another_term_is_said_under_the_chain() {
    let mut h = loaded(HEATER, "P1D", [1360.0, 860.0]);
    h.get_by_label_contains("Loaded 600 samples");
    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| !h.state().ident.is_fitting());
    h.get_by_label("Run the whole loop").click_accesskit();
    h.run_steps(1);
    let start = std::time::Instant::now();
    while h.state().ident.is_diagnosing() || h.state().ident.diagnosis.is_none() {
        assert!(start.elapsed().as_secs() < 180, "the loop never ended");
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    h.run_steps(2);
    assert!(h.query_by_label_contains("does not separate Kp").is_none());
    let d = h.state_mut().ident.diagnosis.as_mut().expect("a diagnosis");
    d.gain_trade = Some(degrau::ident::diagnose::GainTrade {
        with: Param::Drift,
        correlation: -0.95,
    });
    h.run_steps(2);
    h.get_by_label_contains(
        "The record does not separate Kp from Drift (their estimates are correlated -0.95)",
    );
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(2);
    h.get_by_label_contains(
        "O registro não separa Kp de Drift (as estimativas têm correlação -0,95)",
    );
}

/// ECAM's heater pulse (30 → 70 → 30 %): both changes held under three of the process's
/// time constants (306 s and 164 s on a lag of about 166 s). The app says so for each step,
/// as the CLI's table marks them, and reads no hint of nonlinearity into them.
#[test]
fn a_step_held_under_three_time_constants_is_said_and_not_compared() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/records/ecam_tclab_Open_loop_experiment_on_MV_2022-03-01-09h52.txt"
    );
    let mut h = loaded_from(path, ("PV", "MV"), "P1D", [1360.0, 860.0]);
    h.get_by_label("Fit").click();
    wait_for(&mut h, |h| h.query_by_label("joint fit").is_some());
    wait_for(&mut h, |h| {
        h.query_all_by_label_contains("not compared")
            .next()
            .is_some()
            || h.query_all_by_label_contains("not linear").next().is_some()
    });
    let fits = h
        .state()
        .ident
        .per_step
        .fits
        .clone()
        .expect("the per-step fits");
    assert_eq!(fits.len(), 2);
    for (k, f) in fits.iter().enumerate() {
        h.get_by_label(&format!(
            "Step {} (t = {} s) was held less than 3 time constants beyond its dead time: its \
             own values rest on the tail of the response before it, and are not compared.",
            k + 1,
            degrau::text::Lang::En.num(f.change.t, 5)
        ));
    }
    assert!(h.query_all_by_label_contains("not linear").next().is_none());
}

/// The input logged to its own file (issue 22, item 17): typed into "Input's own file"
/// under "How to read", the next load joins it on time; the model is driven by it (Kp
/// near the synthetic process's 0.9), and a missing input file is named, keeping the test.
#[test]
fn an_input_in_its_own_file_is_joined_on_time() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");
    let mut h = Harness::builder()
        .with_size([1000.0, 650.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    h.get_by_label("How to read the file").click();
    h.run_steps(2);
    let field = || egui::accesskit::Role::TextInput;
    h.get_by_role_and_label(field(), "Input's own file").focus();
    h.run_steps(1);
    h.get_by_role_and_label(field(), "Input's own file")
        .type_text(&format!("{dir}two_files_input.txt"));
    h.run_steps(1);
    load(&mut h, &format!("{dir}two_files_output.txt"));
    let loaded = h.state().ident.loaded.as_ref().expect("loaded");
    let input = loaded.test.input.as_ref().expect("the joined input");
    assert_eq!((input[0], input[input.len() - 1]), (165.0, 175.0));
    let _ = h.state_mut().ident.apply(Command::Fit);
    wait_for(&mut h, |h| h.state().ident.report.is_some());
    let kp = h
        .state()
        .ident
        .report
        .as_ref()
        .expect("a fit")
        .model
        .get(Param::Kp);
    assert!((kp - 0.9).abs() < 0.03, "Kp {kp}");
    // A missing input file is named, and the test loaded before stays.
    h.state_mut().ident.settings.u_path = format!("{dir}no_such_input.txt");
    load(&mut h, &format!("{dir}two_files_output.txt"));
    h.get_by_label_contains("no_such_input.txt");
    assert!(h.state().ident.loaded.is_some());
}
