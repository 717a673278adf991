//! The test's causes on the repo's copies of real records (tracker issue 11): the TCLab
//! spikes record (a real copy) and the dropouts stand-in name `outliers` with their count
//! (at least the samples more than 1 °C from a 15-point running median, and at most a fifth
//! more),
//! and their robust Kp is within 3 % of the Kp of the same record after a 15-point running
//! median (least squares on the filtered output, the same final structure): the robust loss
//! gets from the raw record what a student would get by cleaning it by hand.
//!
//! Run with `cargo test --test diagnose_real -- --nocapture` to see the figures.

use std::path::PathBuf;

use degrau::ident::data::{LoadOptions, load_file};
use degrau::ident::diagnose::{DiagnoseOptions, DiagnoseReport, diagnose};
use degrau::ident::experiment::Experiment;
use degrau::ident::fit::{FitData, FitOptions, fit};
use degrau::ident::models::{Param, Values};
use degrau::ident::stats::median;
use degrau::ident::test_causes::{TestCauseKind, TestEvidence};

fn record(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/records")
        .join(name)
}

/// The record's data as `degrau diagnose FILE --t-col … --y-col … --u-col …` prepares
/// them, and its diagnosis from `start`.
fn diagnosed(
    name: &str,
    (time, y, u): (&str, &str, &str),
    initial_input: Option<f64>,
    start: &str,
) -> (FitData, DiagnoseReport) {
    let options = LoadOptions::from_text(time, y, u, None, 0);
    let test = load_file(record(name), &options).unwrap();
    let experiment = Experiment::new(&test, None, None, initial_input).unwrap();
    let data = experiment.fit_data(&test).unwrap();
    let start = experiment.structure(start, false, &data).unwrap();
    let values = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let report = diagnose(&data, start, values, &DiagnoseOptions::default()).unwrap();
    (data, report)
}

/// A running median of `width` samples (shorter at the ends).
fn running_median(y: &[f64], width: usize) -> Vec<f64> {
    let half = width / 2;
    (0..y.len())
        .map(|i| median(&y[i.saturating_sub(half)..(i + half + 1).min(y.len())]))
        .collect()
}

/// The outliers named with their count, and the robust Kp against the median-filtered one.
fn outliers_and_robust_gain(name: &str, columns: (&str, &str, &str), initial: Option<f64>) {
    let (data, report) = diagnosed(name, columns, initial, "P1D");
    let outliers = report
        .test_causes
        .iter()
        .find(|c| c.kind == TestCauseKind::Outliers)
        .unwrap_or_else(|| panic!("{name}: outliers not named: {:?}", report.test_causes));
    let TestEvidence::Outliers { count, .. } = outliers.evidence else {
        panic!()
    };
    let filtered = FitData {
        y: running_median(&data.y, 15),
        ..data.clone()
    };
    let last = &report.final_fit.model;
    let options = FitOptions::default();
    let clean = fit(&filtered, last.structure, last.values, &options, &mut ()).unwrap();
    let (robust, by_median) = (last.get(Param::Kp), clean.model.get(Param::Kp));
    let off = (robust - by_median) / by_median;
    let ids: Vec<&str> = report.test_causes.iter().map(|c| c.kind.id()).collect();
    eprintln!(
        "{name}: causes {ids:?}, {count} outliers; structure {}; robust Kp {robust:.5}, \
         median-filtered Kp {by_median:.5} ({:+.2} %)",
        last.structure.code(),
        100.0 * off
    );
    // The samples more than 1 °C from the 15-point running median, counted independently.
    let by_hand = data
        .y
        .iter()
        .zip(running_median(&data.y, 15))
        .filter(|(y, m)| (*y - m).abs() > 1.0)
        .count();
    eprintln!("{name}: {by_hand} samples more than 1 °C from the running median");
    assert!(
        count >= by_hand && count <= by_hand + by_hand / 5 + 2,
        "{name}: {count} outliers named, {by_hand} beyond 1 °C"
    );
    assert!(
        off.abs() <= 0.03,
        "{name}: robust Kp {robust} against {by_median}"
    );
}

#[test]
fn tclab_spikes_are_outliers_and_the_robust_gain_matches_the_cleaned_record() {
    outliers_and_robust_gain(
        "tclab_step_q1_100_spikes.csv",
        ("Time", "T1", "Q1"),
        Some(0.0),
    );
}

#[test]
fn tclab_dropouts_are_outliers_and_the_robust_gain_matches_the_cleaned_record() {
    outliers_and_robust_gain(
        "tclab_step_q1_50_dropouts_synthetic.csv",
        ("Time", "T1", "Q1"),
        Some(0.0),
    );
}
