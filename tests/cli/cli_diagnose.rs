//! `degrau diagnose` on the notes' LECI test and the TCLab step, through the binary.

use crate::run;

use run::{LECI, TCLAB};

fn diagnose(args: &[&str]) -> serde_json::Value {
    run::command_json("diagnose", args)
}

#[test]
fn leci_from_p2u_names_the_dead_time_and_ends_at_the_notes_model() {
    let j = diagnose(&[
        LECI, "--t0", "5", "--du", "10", "--y0", "50", "--start", "P2U",
    ]);
    assert_eq!(j["start"]["model"], "P2U");
    let steps = j["steps"].as_array().unwrap();
    assert!(!steps.is_empty());
    assert_eq!(steps[0]["cause"], "dead_time", "{}", steps[0]["evidence"]);
    assert!(steps[0]["evidence"].as_str().unwrap().len() > 40);
    let interval = steps[0]["interval"].as_array().unwrap();
    assert!((interval[0].as_f64().unwrap() - 5.0).abs() < 1e-9);
    let gain = &steps[0]["gain"];
    assert!(gain["rmse_ratio"].as_f64().unwrap() > 1.5, "{gain}");
    assert!(gain["rmse_after"].as_f64().unwrap() < gain["rmse_before"].as_f64().unwrap());
    assert!(gain["criterion_delta"].as_f64().unwrap() < -10.0);
    assert!(
        gain["fit_percent_after"].as_f64().unwrap() > gain["fit_percent_before"].as_f64().unwrap()
    );
    let fin = &j["final"];
    assert_eq!(fin["model"], "P2DU");
    let p = &fin["params"];
    let close = |v: f64, truth: f64| (v - truth).abs() <= 0.02 * truth;
    assert!(close(p["Kp"].as_f64().unwrap(), 1.0021), "{p}");
    assert!(close(p["Td"].as_f64().unwrap(), 1.759), "{p}");
    assert!(close(p["Zeta"].as_f64().unwrap(), 0.1948), "{p}");
    assert!(close(1.0 / p["Tw"].as_f64().unwrap(), 0.9659), "{p}");
    assert_eq!(j["adequate"], true);
    let sg = &j["static_gain"];
    let ci = sg["ci95"].as_array().unwrap();
    assert!(
        ci[0].as_f64().unwrap() < sg["value"].as_f64().unwrap()
            && sg["value"].as_f64().unwrap() < ci[1].as_f64().unwrap()
    );
}

/// From the default start P1 the LECI test needs two effects at once: P2U alone still lacks
/// the dead time, so its residuals stay correlated and the corrected BIC refuses it; the
/// pair pays, and the chain ends at the notes' model.
#[test]
fn leci_from_p1_reaches_the_notes_model_through_a_pair() {
    let j = diagnose(&[LECI, "--t0", "5", "--du", "10", "--y0", "50"]);
    assert_eq!(j["start"]["model"], "P1");
    let fin = &j["final"];
    assert_eq!(fin["model"], "P2DU", "{}", j["steps"]);
    let p = &fin["params"];
    let close = |v: f64, truth: f64| (v - truth).abs() <= 0.02 * truth;
    assert!(close(p["Kp"].as_f64().unwrap(), 1.0021), "{p}");
    assert!(close(p["Td"].as_f64().unwrap(), 1.759), "{p}");
    assert!(close(p["Zeta"].as_f64().unwrap(), 0.1948), "{p}");
    assert!(fin["fit_percent"].as_f64().unwrap() > 85.0, "{fin}");
}

#[test]
fn tclab_from_p1_names_a_dead_time_or_a_pole_and_finds_the_gain() {
    let j = diagnose(&[TCLAB, "--y-col", "T1", "--u-col", "Q1", "--start", "P1"]);
    let steps = j["steps"].as_array().unwrap();
    assert!(!steps.is_empty());
    let first = steps[0]["cause"].as_str().unwrap();
    assert!(
        ["dead_time", "extra_pole"].contains(&first),
        "first cause {first}"
    );
    let kp = j["static_gain"]["value"].as_f64().unwrap();
    assert!((kp - 0.70).abs() <= 0.05 * 0.70, "Kp = {kp}");
    eprintln!(
        "TCLab chain: {}",
        steps
            .iter()
            .map(|s| s["cause"].as_str().unwrap())
            .collect::<Vec<_>>()
            .join(" → ")
    );
}

#[test]
fn an_adequate_start_has_no_steps() {
    // The notes' own model on the notes' data: nothing left to name.
    let j = diagnose(&[
        LECI, "--t0", "5", "--du", "10", "--y0", "50", "--start", "P2DU",
    ]);
    assert_eq!(j["steps"].as_array().unwrap().len(), 0, "{}", j["steps"]);
    assert_eq!(j["adequate"], true);
}

/// A dead time shorter than a sample on a PRBS record of 286 changes: its evidence gathers
/// the samples just after every change (each signed by its change's direction), not one
/// window shorter than a sample with one residual (issue 22, item 16). The record was made
/// by `degrau prbs --n 600 --ts 0.1 --model P1D --params Kp=2,Tp1=0.6,Td=0.05 --noise 0.005
/// --seed 3`.
#[test]
fn a_dead_time_on_many_changes_rests_on_all_of_them() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/prbs_short_dead_time.csv"
    );
    let j = diagnose(&[file]);
    let steps = j["steps"].as_array().expect("steps");
    let dead = steps
        .iter()
        .find(|s| s["cause"] == "dead_time")
        .unwrap_or_else(|| panic!("{j}"));
    let words = dead["evidence"].as_str().expect("evidence words");
    assert!(
        words.contains("after each of the 286 input changes"),
        "{words}"
    );
    let tokens: Vec<&str> = words.split_whitespace().collect();
    let n: usize = tokens
        .windows(3)
        .find(|w| w[0] == "the" && w[2] == "residuals")
        .and_then(|w| w[1].parse().ok())
        .unwrap_or(0);
    assert!(n >= 200, "{n}: {words}");
}
