//! The least-squares mode of the real app, through egui_kittest: ARX on the TCLab record with
//! θ and both fit % read off the panel, the notes' three-sample example, RLS animated to the
//! batch solution, and a PRBS test designed, exported and used as the record.

use crate::kit;

use kit::load;

use degrau::app::DegrauApp;
use degrau::app::lsq::Command;
use degrau::app::lsq::designer::PrbsSettings;
use degrau::ident::lsq::arx::{ArxOrders, operating_point};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

fn harness() -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1500.0, 950.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h
}

/// The app in the Identify mode with its reading settings `set`.
fn identify_with(
    set: impl FnOnce(&mut degrau::app::identify::Saved),
) -> Harness<'static, DegrauApp> {
    let mut h = harness();
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    set(&mut h.state_mut().ident.settings);
    h
}

/// The app in the least-squares mode on the TCLab record (output T1, input Q1).
fn tclab() -> Harness<'static, DegrauApp> {
    let mut h = identify_with(|s| {
        s.y_col = "T1".into();
        s.u_col = "Q1".into();
    });
    load(&mut h, TCLAB);
    h.get_by_label("Least squares on samples").click();
    h.run_steps(3);
    h
}

/// θ of y(k) = −a1·y(k−1) + b1·u(k−1) in deviations, by the normal equations written out
/// (an independent computation of the QR solve).
fn first_order_by_hand(u: &[f64], y: &[f64], u0: f64, y0: f64) -> [f64; 2] {
    let (mut s11, mut s12, mut s22, mut r1, mut r2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for k in 1..y.len() {
        let (p1, p2, t) = (-(y[k - 1] - y0), u[k - 1] - u0, y[k] - y0);
        s11 += p1 * p1;
        s12 += p1 * p2;
        s22 += p2 * p2;
        r1 += p1 * t;
        r2 += p2 * t;
    }
    let det = s11 * s22 - s12 * s12;
    [(s22 * r1 - s12 * r2) / det, (s11 * r2 - s12 * r1) / det]
}

/// Applies a least-squares command as the app does.
fn apply(h: &mut Harness<'static, DegrauApp>, command: Command) {
    let app = h.state_mut();
    let _ = app.lsq.apply(command, &app.ident, None);
}

#[test]
fn arx_on_the_tclab_record_shows_theta_and_both_fit_percents() {
    let h = tclab();
    let app = h.state();
    let s = app.lsq.samples.as_ref().expect("the record is taken in");
    assert!(s.y.len() > 790, "{} samples", s.y.len());
    let r = app
        .lsq
        .arx_fit()
        .expect("the ARX orders are fitted on load");
    assert_eq!(r.fit.model.orders, ArxOrders::new(1, 1, 1));
    let (u0, y0) = operating_point(&s.time, &s.u, &s.y, r.fit.offset);
    let want = first_order_by_hand(&s.u, &s.y, u0, y0);
    for (got, want) in r.fit.lsq.theta.iter().zip(want) {
        assert!((got - want).abs() <= 1e-9 * want.abs(), "{got} vs {want}");
    }
    // A slow heater: a pole near 1 and a small positive gain per sample.
    assert!(want[0] > -1.0 && want[0] < -0.9, "a1 = {}", want[0]);
    assert!(want[1] > 0.0, "b1 = {}", want[1]);
    // What the student reads: θ, and the two fit % side by side, the prediction's higher.
    let shown = |v: f64| degrau::text::Lang::En.num(v, 5);
    h.get_by_label(&shown(r.fit.lsq.theta[0]));
    h.get_by_label(&shown(r.fit.lsq.theta[1]));
    let (p, sim) = (
        r.fit.scores.fit_percent_prediction,
        r.fit.scores.fit_percent_simulation,
    );
    // (each also in the AIC table's row of these orders)
    for x in [p, sim] {
        assert!(
            h.query_all_by_label(&format!("{x:.1} %")).count() >= 1,
            "{x}"
        );
    }
    assert!(p > sim && p > 90.0, "prediction {p} %, simulation {sim} %");
    h.get_by_label("Fit % (one-step prediction)");
    h.get_by_label("Fit % (free simulation)");
    h.get_by_label_contains("One-step prediction: each ŷ(k) from the measured past outputs");
    // Φ as the notes write it, and the ARX model's G(s) with its dead time.
    assert!(
        h.query_all_by_label("−y(k−1)").count() >= 2,
        "θ table and Φ header"
    );
    h.get_by_label_contains("G(s) = ");
}

#[test]
fn the_notes_three_sample_example_with_its_regressors() {
    let mut h = harness();
    h.get_by_label("Least squares on samples").click();
    h.run_steps(2);
    h.get_by_label("Notes' example").click();
    h.run_steps(2);
    h.get_by_label("θ = [0, 0.9, 0.3]");
    h.get_by_label("Cost J = Σe(k)² = 0");
    for regressor in ["1", "u(k)", "u(k−1)"] {
        assert!(h.query_all_by_label(regressor).count() >= 1, "{regressor}");
    }
    // (the models are also named in the table and the legend: the first is the selector)
    h.get_all_by_label("y(k) = θ0 + θ1·u(k)")
        .next()
        .unwrap()
        .click();
    h.run_steps(2);
    h.get_by_label("θ = [-0.05, 1.05]");
    h.get_by_label("Cost J = Σe(k)² = 0.015");
    h.get_all_by_label("y(k) = θ0").next().unwrap().click();
    h.run_steps(2);
    h.get_by_label("θ = [1]");
    // E = [−1, −0.1, 1.1]: J = 2.22 (the notes round it to 2.2).
    h.get_by_label("Cost J = Σe(k)² = 2.22");
}

#[test]
fn rls_animates_to_the_batch_solution() {
    let mut h = tclab();
    h.get_by_label("Recursive (RLS)").click();
    h.run_steps(2);
    h.get_by_label("Run").click();
    h.run_steps(5);
    let taken = |h: &Harness<'_, DegrauApp>| match &h.state().lsq.animation {
        Some(Ok(a)) => (a.taken(), a.rows()),
        _ => panic!("no animation"),
    };
    let (partway, rows) = taken(&h);
    assert!(
        partway > 0 && partway < rows,
        "{partway} of {rows} after 5 frames"
    );
    assert!(h.state().lsq.is_running());
    let mut frames = 0;
    while h.state().lsq.is_running() {
        h.run_steps(10);
        frames += 10;
        assert!(frames < 2000, "the animation does not end");
    }
    assert_eq!(taken(&h).0, rows);
    // Finished, the mode stops asking for frames.
    h.run();
    let Some(Ok(a)) = &h.state().lsq.animation else {
        unreachable!()
    };
    let batch = a.batch.clone().unwrap();
    for (x, b) in a.theta().iter().zip(&batch.theta) {
        assert!((x - b).abs() < 1e-6 * b.abs().max(1.0), "{x} vs {b}");
    }
    // The trajectories and the batch lines are drawn, named as the parameters.
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|t| t.0).collect();
    for name in ["a1", "b1", "a1 batch", "b1 batch"] {
        assert!(
            painted.iter().any(|t| t == name) || h.query_by_label(name).is_some(),
            "{name} not drawn"
        );
    }
    h.get_by_label_contains("Every sample taken in");
    // Step takes one sample of a fresh run.
    h.get_by_label("Reset").click();
    h.run_steps(1);
    h.get_by_label("Step").click();
    h.run_steps(1);
    assert_eq!(taken(&h).0, 1);
}

/// The PRBS tab with the designer's default test, noise-free: the FOPTD 2·e^(−3s)/(20s + 1)
/// sampled at 1 s, clock 4 samples, 600 samples, levels 0/1.
fn noise_free_prbs(h: &mut Harness<'static, DegrauApp>) {
    h.get_by_label("Least squares on samples").click();
    h.run_steps(2);
    h.get_by_label("PRBS test").click();
    h.run_steps(2);
    let settings = PrbsSettings {
        noise_percent: 0.0,
        ..PrbsSettings::default()
    };
    apply(h, Command::SetPrbs(settings));
    h.run_steps(2);
}

/// The record the PRBS tab designed.
fn designed(h: &Harness<'static, DegrauApp>) -> degrau::ident::lsq::prbs::Record {
    match &h.state().lsq.designed {
        Some(Ok(d)) => d.record.clone(),
        other => panic!("no PRBS designed: {other:?}"),
    }
}

#[test]
fn a_prbs_test_is_exported_and_used_as_the_record_and_arx_recovers_its_model() {
    let mut h = harness();
    noise_free_prbs(&mut h);
    h.get_by_label_contains("Register of 8 bits: 255 bits per period × 4 samples per bit");
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("prbs_test.csv");
    apply(&mut h, Command::ExportPrbs(path.clone()));
    let written = std::fs::read_to_string(&path).unwrap();
    assert!(written.starts_with("time,u,y\n"));
    assert_eq!(written.lines().count(), 601);
    h.get_by_label("Use as record").click();
    h.run_steps(3);
    let app = h.state();
    let loaded = app.ident.loaded.as_ref().expect("the Identify mode has it");
    assert_eq!(loaded.test.time.len(), 600);
    assert_eq!(app.lsq.samples.as_ref().unwrap().y.len(), 600);
    // ARX of the exact ZOH image (nk = 3 + 1) recovers a1 = −e^(−h/τ), b1 = K(1 − e^(−h/τ)).
    apply(&mut h, Command::FitOrders(ArxOrders::new(1, 1, 4)));
    h.run_steps(2);
    let fit = &h.state().lsq.arx_fit().unwrap().fit;
    let pole = (-1.0f64 / 20.0).exp();
    assert!(
        (fit.lsq.theta[0] + pole).abs() < 1e-9,
        "{:?}",
        fit.lsq.theta
    );
    assert!((fit.lsq.theta[1] - 2.0 * (1.0 - pole)).abs() < 1e-9);
}

#[test]
fn validation_shows_both_parts_and_the_split() {
    let mut h = tclab();
    h.get_by_label("Validation").click();
    h.run_steps(2);
    let app = h.state();
    let v = app.lsq.validation.as_ref().unwrap();
    let arx = v.arx.as_ref().unwrap();
    assert_eq!(*v.split.as_ref().unwrap(), 401);
    let t_split = app.lsq.split_time().unwrap();
    assert!((t_split - 400.0).abs() < 1.5, "{t_split}");
    for x in [
        arx.estimation.fit_percent_prediction,
        arx.validation.fit_percent_prediction,
        arx.estimation.fit_percent_simulation,
        arx.validation.fit_percent_simulation,
    ] {
        assert!(
            h.query_all_by_label(&format!("{x:.1} %")).count() >= 1,
            "{x}"
        );
    }
    h.get_by_label("ARX model — prediction");
    h.get_by_label("RLS (final θ) — simulation");
    // The split drawn on the plot.
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|t| t.0).collect();
    assert!(
        painted.iter().any(|t| t == "split") || h.query_by_label("split").is_some(),
        "no split line"
    );
}

#[test]
fn the_advisor_reads_the_notes_rules_with_the_record_numbers() {
    let mut h = tclab();
    // The time scales of a first-order guess read off the curve.
    let _ = h
        .state_mut()
        .ident
        .apply(degrau::app::identify::Command::SetCode("P1D".into()));
    h.run_steps(2);
    h.get_by_label("Sampling advisor").click();
    h.run_steps(2);
    let app = h.state();
    let a = app
        .lsq
        .advice
        .as_ref()
        .expect("the guess gives time scales");
    assert!(!a.fitted);
    assert_eq!(a.h, 1.0);
    let tau = a.scales.time_constants[0];
    assert!(tau > 50.0, "τmax = {tau}");
    h.get_by_label("h < 0.1·τmax (Kalman and Bertram)");
    h.get_by_label("0.01 < h/τ < 0.05 (Åström and Wittenmark)");
    h.get_by_label(&format!(
        "h/τ = {}",
        degrau::text::Lang::En.num(1.0 / tau, 3)
    ));
    // A heater sampled every second against a time constant of minutes: fast, not slow.
    let ratio = a.checks.iter().map(|c| c.value).fold(0.0, f64::max);
    assert!(ratio < 0.2, "{ratio}");
    let amplitude = a.amplitude.expect("a finite static gain");
    assert!(amplitude.holds(), "{amplitude:?}");
    h.get_by_label("step's effect / noise > 6");
}

/// A fit made in the Identify mode is the continuous fit the least-squares mode compares
/// with, as soon as the student switches (issue 23, item 3: it said "None yet" right after
/// a fit).
#[test]
fn a_fit_in_identify_is_compared_in_least_squares() {
    let mut h = identify_with(|s| {
        s.y_col = "T1".into();
        s.u_col = "Q1".into();
        s.code = "P1D".into();
    });
    load(&mut h, TCLAB);
    h.get_by_label("Fit").click();
    h.run_steps(1);
    kit::wait_for(&mut h, |h| h.query_by_label("Fitted P1D").is_some());
    h.get_by_label("Least squares on samples").click();
    h.run_steps(3);
    assert!(h.query_by_label_contains("None yet").is_none());
    h.get_by_label_contains("P1D: G(s) = ");
    h.get_by_label_contains("Its fit % on these samples");
    // After the whole loop, the model the chain ends on (or the row chosen) is compared.
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    h.get_by_label("Run the whole loop").click_accesskit();
    h.run_steps(1);
    kit::wait_for(&mut h, |h| !h.state().ident.is_diagnosing());
    let chain = h.state().ident.diagnosis.clone().expect("a chain");
    h.get_by_label(&chain.start.model.structure.label())
        .click_accesskit();
    h.run_steps(2);
    h.get_by_label("Least squares on samples").click();
    h.run_steps(3);
    assert!(h.query_by_label_contains("None yet").is_none());
    let code = chain.start.model.structure.code();
    h.get_by_label_contains(&format!("{code}: G(s) = "));
}

/// A PRBS test used as the record starts from its own columns (issue 23, item 3): the
/// input before DaISy's record (6), set for the record loaded before, invented a 6 → 1 step
/// and 69 input changes on it.
#[test]
fn a_prbs_used_as_the_record_takes_no_setting_of_the_last_record() {
    let mut h = identify_with(|s| {
        s.time_col = "1".into();
        s.y_col = "3".into();
        s.u_col = "2".into();
        s.initial_input = "6".into();
    });
    let daisy = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/records/daisy_heating_system.dat"
    );
    load(&mut h, daisy);
    let loaded = h.state().ident.loaded.as_ref().expect("DaISy is loaded");
    assert_eq!(loaded.experiment.initial_input, Some(6.0));
    h.get_by_label("Least squares on samples").click();
    h.run_steps(2);
    h.get_by_label("PRBS test").click();
    h.run_steps(2);
    h.get_by_label("Use as record").click();
    h.run_steps(3);
    let ident = &h.state().ident;
    let loaded = ident.loaded.as_ref().expect("the PRBS test is the record");
    assert_eq!(loaded.experiment.initial_input, None);
    assert!(ident.settings.initial_input.is_empty());
    let data = loaded.data.as_ref().expect("its fit data");
    let prbs = designed(&h);
    let changes = prbs.u.windows(2).filter(|w| w[0] != w[1]).count();
    assert_eq!(
        data.input.changes.len(),
        changes,
        "no step invented before the record"
    );
}

/// A PRBS of levels 0/1 through a P1D of gain 2 (the designer's default) gives an output
/// between Y0 = 0 and 2, as a test started at rest at the low level (issue 23, item 13: it
/// ran from −1.7 to 0, measured from the first, high, bit).
#[test]
fn a_prbs_output_starts_from_rest_at_its_low_level() {
    let mut h = harness();
    noise_free_prbs(&mut h);
    let record = designed(&h);
    assert_eq!(record.u[0], 1.0, "this seed's first bit is high");
    let (lo, hi) = record
        .y
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| {
            (a.min(y), b.max(y))
        });
    assert!(lo >= -1e-12 && hi <= 2.0 + 1e-12, "y from {lo} to {hi}");
    assert!(hi > 1.0, "the output rises with the high bits: {hi}");
}
