//! `degrau bode` through the binary: the JSON keys, its values equal to the lti crate's,
//! the text report in both languages, and a bad frequency refused in words.

use crate::run;

use degrau::lti::TransferFunction;
use degrau::lti::bode::{asymptotes, bode, log_grid};
use run::{degrau, stderr, stdout};
use serde_json::Value;

/// The notes' 0.5/(s³ + 7s² + 15s + 25), with a dead time of 0.5 s.
const NOTES: [&str; 7] = [
    "bode",
    "--num",
    "0.5",
    "--den",
    "1,7,15,25",
    "--delay",
    "0.5",
];

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

/// Equal to the last digit serde_json's reading keeps (it may round the last bit).
#[track_caller]
fn assert_close(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len());
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= 1e-14 * w.abs().max(1.0), "{g} vs {w}");
    }
}

#[test]
fn json_has_the_keys_and_the_lti_values() {
    let mut args = NOTES.to_vec();
    args.extend([
        "--w-min", "0.1", "--w-max", "100", "--points", "31", "--json",
    ]);
    let out = degrau(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    let report: Value = serde_json::from_str(stdout(&out).trim()).expect("one JSON object");
    for key in ["w", "mag_db", "phase_deg", "asymptote_db", "corners"] {
        assert!(report.get(key).is_some(), "no {key}");
    }
    let g = TransferFunction::from_coeffs(&[0.5], &[1.0, 7.0, 15.0, 25.0])
        .and_then(|g| g.with_delay(0.5))
        .expect("valid system");
    let w = log_grid(0.1, 100.0, 31);
    let expected = bode(&g, &w);
    let lines = asymptotes(&g);
    assert_close(&numbers(&report["w"]), &w);
    assert_close(&numbers(&report["mag_db"]), &expected.mag_db);
    assert_close(&numbers(&report["phase_deg"]), &expected.phase_deg);
    let asymptote: Vec<f64> = w.iter().map(|&w| lines.value_db(w)).collect();
    assert_close(&numbers(&report["asymptote_db"]), &asymptote);
    let corners = report["corners"].as_array().expect("corners");
    assert_eq!(corners.len(), 2);
    assert_eq!(corners[0]["slope_change_db_per_decade"], -40.0);
    assert!((corners[1]["w"].as_f64().expect("a number") - 5.0).abs() < 1e-9);
    assert_eq!(corners[1]["slope_change_db_per_decade"], -20.0);
}

#[test]
fn the_default_grid_has_200_points() {
    let mut args = NOTES.to_vec();
    args.push("--json");
    let out = degrau(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    let report: Value = serde_json::from_str(stdout(&out).trim()).expect("one JSON object");
    let w = numbers(&report["w"]);
    assert_eq!(w.len(), 200);
    assert!((w[0] - 0.01).abs() < 1e-15 && (w[199] - 1000.0).abs() < 1e-9);
}

#[test]
fn text_says_the_corners_in_both_languages() {
    let mut args = NOTES.to_vec();
    args.extend(["--points", "5"]);
    let en = stdout(&degrau(&args));
    assert!(en.contains("Corner at ω = 5 rad/s"), "{en}");
    assert!(en.contains("to -60 dB/decade"), "{en}");
    assert!(en.contains("asymptote (dB)"), "{en}");
    assert_eq!(en.lines().count(), 5 + 5, "{en}");
    let pt = stdout(&degrau(&[&["--lang", "pt"], &args[..]].concat()));
    assert!(pt.contains("Canto em ω = 5 rad/s"), "{pt}");
    assert!(pt.contains("para -60 dB/década"), "{pt}");
    assert!(pt.contains("Tempo morto"), "{pt}");
}

#[test]
fn a_bad_frequency_is_refused_in_words() {
    for (lang, words) in [
        ("en", "positive number of rad/s"),
        ("pt", "número positivo"),
    ] {
        let mut args = vec!["--lang", lang];
        args.extend(NOTES);
        args.extend(["--w-min", "-1"]);
        let out = degrau(&args);
        assert_eq!(out.status.code(), Some(2));
        let err = stderr(&out);
        assert!(err.contains("--w-min -1") && err.contains(words), "{err}");
    }
    let mut args = NOTES.to_vec();
    args.extend(["--w-min", "10", "--w-max", "1"]);
    let out = degrau(&args);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--w-min must be below --w-max"));
    let mut args = NOTES.to_vec();
    args.extend(["--w-min", "abc"]);
    assert_eq!(degrau(&args).status.code(), Some(2));
}
