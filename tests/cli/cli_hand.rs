//! `degrau hand` through the binary: one method's JSON with its construction, the table of
//! every method beside the least-squares fits, both languages, and the refusals.

use std::process::{Command, Output};

use crate::run;
use run::scaled_step;

const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);
const SPIKES: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_100_spikes.csv"
);

/// The TCLab copy's arguments (output T1, input Q1) followed by `extra`.
fn tclab<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    [&[TCLAB, "--y-col", "T1", "--u-col", "Q1"], extra].concat()
}

fn hand(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_degrau"))
        .arg("hand")
        .args(args)
        .output()
        .expect("run degrau")
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = hand(&[args, &["--json"]].concat());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn the_tangent_on_the_tclab_step_with_its_construction() {
    let j = json(&tclab(&["--method", "tangent"]));
    assert_eq!(j["method"], "tangent");
    assert_eq!(j["model"], "P1D");
    // The stand-in's process has K = 0.69537 °C/%.
    assert!((f(&j["K"]) - 0.695).abs() < 0.02, "{j}");
    let (tau, theta) = (f(&j["tau"]), f(&j["theta"]));
    let c = &j["construction"];
    let t = &c["tangent"];
    // The tangent's own numbers give θ and τ: where it meets the two levels.
    assert!((f(&t["t_initial"]) - f(&c["t0"]) - theta).abs() < 1e-9);
    assert!((f(&t["t_final"]) - f(&t["t_initial"]) - tau).abs() < 1e-9);
    let slope = f(&t["slope"]);
    assert!((f(&t["t_final"]) - f(&t["t"]) - (f(&c["y_final"]) - f(&t["y"])) / slope).abs() < 1e-6);
    // The tangent reads this overdamped heater slow (the source's P2 has lags of 20 s and
    // 141 s): its FOPTD fits worse than the level-reading methods.
    assert!(f(&j["fit_percent"]) > 60.0 && f(&j["fit_percent"]) < 100.0);
    assert!(j.get("zeta").is_none());
    // A tangent later on the concave part of the curve is flatter: it meets y0 earlier.
    let later = json(&tclab(&["--method", "tangent", "--tangent-at", "150"]));
    assert!(f(&later["theta"]) < theta - 5.0, "{later}");
    assert!(f(&later["tau"]) > tau + 5.0, "{later}");
}

#[test]
fn the_three_point_method_gives_the_second_order_keys() {
    let j = json(&tclab(&["--method", "three-point"]));
    for key in [
        "K",
        "theta",
        "zeta",
        "omega_n",
        "fit_percent",
        "construction",
    ] {
        assert!(j.get(key).is_some(), "missing {key}: {j}");
    }
    let levels = j["construction"]["levels"].as_array().unwrap();
    let percents: Vec<f64> = levels.iter().map(|l| f(&l["percent"])).collect();
    assert_eq!(percents, [15.0, 45.0, 75.0]);
    // ζ ≥ 1 on a heater: the two time constants, with τ1·τ2 = 1/ωn².
    if f(&j["zeta"]) >= 1.0 {
        let w = f(&j["omega_n"]);
        assert!((f(&j["tau1"]) * f(&j["tau2"]) * w * w - 1.0).abs() < 1e-9);
    }
}

#[test]
fn the_table_puts_every_method_beside_the_least_squares_fits() {
    let j = json(&tclab(&[]));
    let methods = j["methods"].as_array().unwrap();
    let keys: Vec<&str> = methods
        .iter()
        .map(|m| m["method"].as_str().unwrap())
        .collect();
    assert_eq!(
        keys,
        ["tangent", "63", "broida", "smith", "points", "three-point"]
    );
    let ls = j["least_squares"].as_array().unwrap();
    let codes: Vec<&str> = ls.iter().map(|m| m["model"].as_str().unwrap()).collect();
    assert_eq!(codes, ["P1D", "P2D"]);
    // Least squares minimises the very error the fit % measures: no hand FOPTD beats P1D.
    let best = f(&ls[0]["fit_percent"]);
    for m in methods.iter().filter(|m| m["model"] == "P1D") {
        assert!(f(&m["fit_percent"]) <= best + 1e-6, "{m} vs {best}");
    }
    let text = hand(&tclab(&["--lang", "pt"]));
    assert!(text.status.success());
    let words = String::from_utf8(text.stdout).unwrap();
    assert!(words.contains("Métodos gráficos"), "{words}");
    assert!(words.contains("mínimos quadrados"), "{words}");
    // --json is the same in both languages.
    let pt = hand(&tclab(&["--json", "--method", "smith", "--lang", "pt"]));
    let en = hand(&tclab(&["--json", "--method", "smith"]));
    assert_eq!(pt.stdout, en.stdout);
}

#[test]
fn the_spikes_record_reads_through_its_outliers() {
    // TCLab heater 1, 0 → 100 % from the first row, single-sample spikes.
    let j = json(&[
        SPIKES,
        "--y-col",
        "T1",
        "--u-col",
        "Q1",
        "--initial-input",
        "0",
        "--method",
        "smith",
    ]);
    let k = f(&j["K"]);
    assert!(k > 0.3 && k < 1.0, "{j}");
    assert!(f(&j["tau"]) > 60.0 && f(&j["tau"]) < 400.0, "{j}");
}

#[test]
fn refusals_are_said_in_words() {
    let out = hand(&tclab(&["--window", "0,30", "--method", "smith"]));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("settles") || err.contains("never reaches"),
        "{err}"
    );
    let out = hand(&tclab(&["--method", "nonsense"]));
    assert_eq!(out.status.code(), Some(2));
    let out = hand(&tclab(&[
        "--window", "0,30", "--method", "smith", "--lang", "pt",
    ]));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("estabilizar") || err.contains("nunca atinge"),
        "{err}"
    );
}

#[test]
fn every_method_reads_the_same_at_1e300_and_1e_minus_300() {
    // Issue 22, item 7: the table printed fit % NaN at 1e±300.
    // Each test writes its own files: tests run at once, and one writing a file another
    // reads made the other fail now and then.
    let unit = json(&[&scaled_step("hand_scales", 1.0)]);
    for k in [1e300, 1e-300] {
        let path = scaled_step("hand_scales", k);
        let scaled = json(&[&path]);
        let pairs = unit["methods"].as_array().unwrap().iter();
        for (u, s) in pairs.zip(scaled["methods"].as_array().unwrap()) {
            let at = format!("at {k:e}: {s} vs {u}");
            assert_eq!(u["model"], s["model"], "{at}");
            // K = Δy/Δu, τ, ζ, ωn are scale-free; θ to 1e-9 of the record's 30 s.
            for key in ["K", "tau", "tau1", "tau2", "zeta", "omega_n"] {
                if let Some(x) = u[key].as_f64() {
                    let y = f(&s[key]);
                    assert!((x - y).abs() <= 1e-9 * x.abs(), "{key} {at}");
                }
            }
            assert!(
                (f(&u["theta"]) - f(&s["theta"])).abs() <= 1e-9 * 30.0,
                "θ {at}"
            );
            assert!(
                (f(&u["fit_percent"]) - f(&s["fit_percent"])).abs() < 1e-7,
                "{at}"
            );
            assert_eq!(u["warnings"], s["warnings"], "{at}");
        }
        for lang in ["en", "pt"] {
            let out = hand(&[&path, "--lang", lang]);
            let text = String::from_utf8(out.stdout).unwrap();
            assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
        }
    }
}

#[test]
fn a_tangent_outside_the_record_is_refused() {
    // Issue 22, item 8: --tangent-at 1e9 was placed at the record's end (θ = −6236 s).
    let path = scaled_step("hand_tangent_outside", 1.0);
    for (t, lang, words) in [
        ("1e9", "en", "outside the response"),
        ("1e9", "pt", "fora da resposta"),
        ("-5", "en", "outside the response"),
        ("1", "pt", "fora da resposta"),
    ] {
        let out = hand(&[
            &path,
            "--method",
            "tangent",
            "--tangent-at",
            t,
            "--lang",
            lang,
        ]);
        assert_eq!(out.status.code(), Some(2), "{t}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(words), "{t} {lang}: {err}");
    }
    // Inside the response it is drawn there.
    let j = json(&[&path, "--method", "tangent", "--tangent-at", "6"]);
    assert!(
        (f(&j["construction"]["tangent"]["t"]) - 6.0).abs() <= 0.5,
        "{j}"
    );
}

#[test]
fn the_table_prints_the_dead_time_the_model_uses() {
    // Issue 22, item 8: a construction meeting y0 before the step printed θ < 0 while the
    // warning said the model uses θ = 0. A late tangent on the concave part, and the three
    // points on this clean first-order curve, both put the start before the step.
    let path = scaled_step("hand_dead_time", 1.0);
    for method in [
        vec!["--method", "tangent", "--tangent-at", "25"],
        vec!["--method", "three-point"],
    ] {
        let j = json(&[&[path.as_str()], &method[..]].concat());
        assert_eq!(f(&j["theta"]), 0.0, "{j}");
        let warnings = j["warnings"].as_array().unwrap();
        assert!(
            warnings
                .iter()
                .any(|w| w.as_str().unwrap().contains("the model uses θ = 0")),
            "{j}"
        );
        let out = hand(&[&[path.as_str()], &method[..]].concat());
        let text = String::from_utf8(out.stdout).unwrap();
        // The row's θ column (the fourth) says 0, as the warning does.
        let row = text.lines().nth(2).unwrap();
        let cells: Vec<&str> = row
            .split("  ")
            .map(str::trim)
            .filter(|c| !c.is_empty())
            .collect();
        assert_eq!(cells[3], "0", "{text}");
    }
}
