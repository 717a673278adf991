//! `degrau step` on the reproducers: clustered poles, huge dead times and subnormal
//! roots give the right numbers or a refusal that names the value.

use std::process::{Command, Output};

use degrau::lti::{C64, StepInfo, StepInfoOptions, StepResponse, TransferFunction};
use serde_json::Value;

fn degrau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(args)
        .output()
        .expect("the degrau binary runs")
}

fn json(args: &[&str]) -> Value {
    let out = degrau(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn number(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

/// The notes' 0.5/((s² + 2s + 5)(s + 5)): rise time 0.773200786… s without delay.
const NOTES: [&str; 5] = ["step", "--poles=-1+2j,-1-2j,-5", "--gain", "0.5", "--json"];

fn with_delay(delay: &str) -> Value {
    let mut args = NOTES.to_vec();
    args.extend(["--delay", delay]);
    json(&args)
}

#[test]
fn a_huge_dead_time_leaves_the_rise_time_alone() {
    let plain = with_delay("0");
    let rise = number(&plain, "rise_time");
    assert!((rise - 0.7732).abs() < 1e-4, "{rise}");
    for delay in ["1e16", "1e17"] {
        let v = with_delay(delay);
        let theta: f64 = delay.parse().unwrap();
        assert_eq!(number(&v, "rise_time"), rise, "delay {delay}");
        assert_eq!(number(&v, "overshoot"), number(&plain, "overshoot"));
        // Instants from the step: θ plus the undelayed ones, rounded to the nearest double.
        for key in ["settling_time", "peak_time"] {
            assert_eq!(
                number(&v, key),
                theta + number(&plain, key),
                "{key}, delay {delay}"
            );
        }
    }
}

#[test]
fn five_clustered_poles_rise_as_the_exact_response() {
    let v = json(&[
        "step",
        "--poles=-1,-1.0001,-1.0002,-1.0003,-1.0004",
        "--json",
    ]);
    let poles: Vec<C64> = (0..5)
        .map(|i| C64::new(-1.0 - 1e-4 * i as f64, 0.0))
        .collect();
    let g = TransferFunction::from_zpk(&[], &poles, 1.0).unwrap();
    let info = StepInfo::of_response(
        &StepResponse::new(&g, 1.0).unwrap(),
        &StepInfoOptions::default(),
    );
    // The library's value is checked against a 768-bit reference in lti_clusters.rs.
    assert_eq!(number(&v, "rise_time"), info.rise_time.unwrap());
    assert!((number(&v, "rise_time") - 5.5599).abs() < 1e-4);
    assert_eq!(number(&v, "overshoot"), 0.0);
    assert!(v["expression"].as_str().unwrap().starts_with("y(t) ≈"));
}

#[test]
fn a_subnormal_zero_is_refused_by_name() {
    let out = degrau(&["step", "--zeros", "1e-320", "--poles", "-1"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("zero 1 is 1e-320"), "{err}");
    assert!(err.contains("smallest normal"), "{err}");
    let out = degrau(&["step", "--num", "1,1e-320", "--den", "1,1"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("coefficient 2 of the numerator"));
}

#[test]
fn a_tiny_normal_zero_reports_the_true_peak() {
    // y = −1e-300 + (1 + 1e-300)e^{−t}: it jumps to 1 and decays; the peak is 1, not inf.
    let v = json(&["step", "--zeros", "1e-300", "--poles", "-1", "--json"]);
    assert_eq!(number(&v, "peak"), 1.0);
}

#[test]
fn a_huge_delay_and_a_subnormal_gain_and_a_needle_band() {
    // e^{−300 000 s}·… : the rise time of 1/(s + 1) is ln 9 whatever the delay.
    let v = json(&["step", "--poles=-1", "--delay", "1e300", "--json"]);
    assert!((number(&v, "rise_time") - 9f64.ln()).abs() < 1e-12);
    let out = degrau(&["step", "--poles=-1", "--gain", "1e-320"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("1e-320"));
    // A band of 1e-9 settles at ln(1e9) s, known to eps/1e-9 (y' = 1e-9 there); a narrower
    // one is refused in short words.
    let v = json(&[
        "step",
        "--poles=-1",
        "--settling-threshold",
        "1e-9",
        "--json",
    ]);
    assert!((number(&v, "settling_time") - 1e9f64.ln()).abs() < 1e-6);
    let out = degrau(&["step", "--poles=-1", "--settling-threshold", "1e-300"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("not 1e-300") && err.len() < 300, "{err}");
}
