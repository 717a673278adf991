//! `degrau fit` and `degrau diagnose` on real multi-step records, from their files as they
//! are, with the flags a user would give: the model driven by the measured input, every
//! change used, the per-step fits beside the joint one. The figures are the sources' own
//! (tests/data/records/SOURCES.md says where each states them).

use crate::run;

use run::{degrau, stdout};
use serde_json::Value;

fn record(name: &str) -> String {
    format!("{}/tests/data/records/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// `degrau fit FILE args… --json`, parsed.
fn fit(name: &str, args: &[&str]) -> Value {
    let file = record(name);
    let mut all = vec!["fit", file.as_str(), "--json"];
    all.extend(args);
    let out = degrau(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_str(&stdout(&out)).expect("one JSON object")
}

fn param(v: &Value, name: &str) -> f64 {
    v["params"][name]
        .as_f64()
        .unwrap_or_else(|| panic!("{name} in {v}"))
}

fn within(value: f64, target: f64, share: f64) -> bool {
    (value - target).abs() <= share * target.abs()
}

#[test]
fn apmonitor_heater_gives_the_sources_first_order_model() {
    let v = fit(
        "apmonitor_arduino_1st_order_SISO_data.csv",
        &["--model", "P1"],
    );
    let (kp, tp1) = (param(&v, "Kp"), param(&v, "Tp1"));
    assert!(within(kp, 0.2555, 0.05), "Kp {kp}");
    assert!(within(tp1, 231.45, 0.03), "Tp1 {tp1}");
    let steps = v["steps"].as_array().unwrap();
    let seen: Vec<(f64, f64)> = steps
        .iter()
        .map(|s| (s["t"].as_f64().unwrap(), s["du"].as_f64().unwrap()))
        .collect();
    assert_eq!(seen, vec![(63.0, 100.0), (168.0, 155.0), (505.0, -205.0)]);
    assert_eq!(v["per_step"].as_array().unwrap().len(), 3);
}

#[test]
fn ecam_tclab_pulses_on_the_heater_and_on_the_disturbance() {
    let mv = fit(
        "ecam_tclab_Open_loop_experiment_on_MV_2022-03-01-09h52.txt",
        &["--u-col", "MV", "--y-col", "PV", "--model", "P1D"],
    );
    // Ten samples before the first of two changes: Y0 is estimated, and said so.
    assert_eq!(
        mv["operating_point"]["reason"].as_str(),
        Some("short_rest"),
        "{mv}"
    );
    let (kp, tp1) = (param(&mv, "Kp"), param(&mv, "Tp1"));
    assert!(within(kp, 0.561, 0.08), "MV Kp {kp}");
    assert!(within(tp1, 166.2, 0.05), "MV Tp1 {tp1}");
    assert!(mv["fit_percent"].as_f64().unwrap() >= 88.0, "{mv}");
    let dv = fit(
        "ecam_tclab_Open_loop_experiment_on_DV_2022-03-22-20h49.txt",
        &["--u-col", "DV", "--y-col", "PV", "--model", "P1D"],
    );
    let (kp, tp1, td) = (param(&dv, "Kp"), param(&dv, "Tp1"), param(&dv, "Td"));
    assert!(within(kp, 0.312, 0.05), "DV Kp {kp}");
    assert!(within(tp1, 157.0, 0.05), "DV Tp1 {tp1}");
    assert!(within(td, 25.5, 0.10), "DV Td {td}");
    assert_eq!(
        dv["steps"].as_array().unwrap().len(),
        2,
        "both edges of the pulse"
    );
}

/// The DaISy record's flags: input and output columns, 6 V before the record, P1.
const DAISY: &[&str] = &[
    "--u-col",
    "2",
    "--y-col",
    "3",
    "--initial-input",
    "6",
    "--model",
    "P1",
];

#[test]
fn daisy_heating_one_model_over_six_steps_with_the_per_step_gains() {
    let v = fit("daisy_heating_system.dat", DAISY);
    assert!(v["fit_percent"].as_f64().unwrap() >= 85.0, "{v}");
    assert_eq!(v["steps"].as_array().unwrap().len(), 6);
    let per_step = v["per_step"].as_array().unwrap();
    assert_eq!(per_step.len(), 6);
    for s in per_step {
        assert!(param(s, "Kp") > 0.0, "{s}");
    }
    // The text output shows the same table.
    let file = record("daisy_heating_system.dat");
    let mut args = vec!["fit", file.as_str()];
    args.extend(DAISY);
    let out = degrau(&args);
    let text = stdout(&out);
    assert!(text.contains("6 change(s) used"), "{text}");
    assert!(
        text.contains("Each change fitted on its own window"),
        "{text}"
    );
    assert!(text.lines().any(|l| l.starts_with("all steps")), "{text}");
}

#[test]
fn enclosure_doublet_uses_both_steps() {
    let v = fit(
        "enclosure_heater_doublet.csv",
        &["--u-col", "2", "--y-col", "4", "--model", "P1D"],
    );
    assert!(v["fit_percent"].as_f64().unwrap() >= 90.0, "{v}");
    let du: Vec<f64> = v["steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["du"].as_f64().unwrap())
        .collect();
    assert_eq!(du, vec![100.0, -50.0]);
}

#[test]
fn rc_ladder_square_wave_gives_unit_gain() {
    let v = fit(
        "rc2_square_wave_adc_synthetic.csv",
        &[
            "--ts", "0.008", "--u-col", "1", "--y-col", "2", "--model", "P2D",
        ],
    );
    let kp = param(&v, "Kp");
    assert!(within(kp, 1.0, 0.02), "Kp {kp}");
    assert!(v["fit_percent"].as_f64().unwrap() >= 97.0, "{v}");
    assert_eq!(v["steps"].as_array().unwrap().len(), 6);
}

#[test]
fn single_step_keeps_the_ideal_step_of_the_largest_change() {
    let v = fit(
        "apmonitor_arduino_1st_order_SISO_data.csv",
        &["--model", "P1", "--single-step"],
    );
    let steps = v["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 1);
    assert_eq!(steps[0]["du"].as_f64(), Some(-205.0));
    assert!(v.get("per_step").is_none());
}

#[test]
fn a_first_order_hold_is_accepted_and_used() {
    let zoh = fit(
        "enclosure_heater_doublet.csv",
        &["--u-col", "2", "--y-col", "4"],
    );
    let foh = fit(
        "enclosure_heater_doublet.csv",
        &["--u-col", "2", "--y-col", "4", "--hold", "foh"],
    );
    assert_ne!(zoh["params"], foh["params"]);
    assert!(foh.get("ci95").is_some());
}

#[test]
fn diagnose_reports_the_input_steps_and_the_per_step_fits() {
    let file = record("enclosure_heater_doublet.csv");
    let out = degrau(&[
        "diagnose", &file, "--u-col", "2", "--y-col", "4", "--start", "P1D", "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(v["input_steps"].as_array().unwrap().len(), 2);
    assert_eq!(v["per_step"].as_array().unwrap().len(), 2);
    assert!(v["final"]["fit_percent"].as_f64().unwrap() >= 90.0);
}
