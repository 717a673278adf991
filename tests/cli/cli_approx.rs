//! `degrau approx` and `degrau pade` through the binary: the notes' numbers in the JSON, the
//! keys the issue names, the text report in both languages, and the refusals.

use crate::run;

use run::{degrau, stderr, stdout};
use serde_json::Value;

/// K(−0.1s + 1)/((5s + 1)(3s + 1)(0.5s + 1)), K = 2, as coefficients.
const THIRD: [&str; 4] = ["--num", "-0.2,2", "--den", "7.5,19,8.5,1"];

/// The notes' fifth-order system reduced to its dominant pair.
const FIFTH_DOMINANT: [&str; 7] = [
    "approx",
    "--num",
    "1",
    "--den",
    "2,60,704,4144,12840,18000",
    "--method",
    "dominant",
];

fn json(args: &[&str]) -> Value {
    let out = degrau(args);
    assert!(out.status.success(), "{}", stderr(&out));
    serde_json::from_str(stdout(&out).trim()).expect("one JSON object")
}

fn approx(method: &str, order: Option<&str>) -> Value {
    let mut args = vec!["approx"];
    args.extend(THIRD);
    args.extend(["--method", method, "--json"]);
    if let Some(o) = order {
        args.extend(["--order", o]);
    }
    json(&args)
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

#[test]
fn the_json_has_the_keys_the_issue_names() {
    let j = approx("taylor", None);
    for key in [
        "method",
        "num",
        "den",
        "delay",
        "max_error",
        "ise",
        "metrics",
        "metrics_error",
    ] {
        assert!(j.get(key).is_some(), "no {key} in {j}");
    }
    assert_eq!(j["method"], "taylor");
    assert!(j["metrics"]["rise_time"].is_number());
    let rise = &j["metrics_error"]["rise_time"];
    let difference = f(&rise["approx"]) - f(&rise["original"]);
    assert!((f(&rise["difference"]) - difference).abs() < 1e-12);
    assert!(rise["within"].is_boolean());
}

#[test]
fn taylor_and_skogestad_give_the_notes_models() {
    // K e^{−3.6s}/(5s + 1) and K e^{−2.1s}/(6.5s + 1), K = 2: den (monic) s + 1/τ.
    for (method, delay, tau) in [("taylor", 3.6, 5.0), ("skogestad", 2.1, 6.5)] {
        let j = approx(method, Some("1"));
        assert!((f(&j["delay"]) - delay).abs() < 1e-12, "{method}: {j}");
        let den: Vec<f64> = j["den"].as_array().unwrap().iter().map(f).collect();
        assert_eq!(den.len(), 2);
        assert!((den[1] - 1.0 / tau).abs() < 1e-12, "{den:?}");
        assert!((f(&j["dc_gain"]) - 2.0).abs() < 1e-12);
        assert!(f(&j["max_error"]) > 0.0 && f(&j["ise"]) > 0.0);
    }
}

#[test]
fn pade_moments_give_the_notes_g11() {
    // (−2.30s + 1)/(6.29s + 1) times 2: num = 2(−2.309s + 1)/6.2907, den = s + 1/6.2907.
    let j = approx("pade", Some("1,1"));
    let a1 = 54.1 / 8.6;
    let b1 = -8.6 + a1;
    let num: Vec<f64> = j["num"].as_array().unwrap().iter().map(f).collect();
    let den: Vec<f64> = j["den"].as_array().unwrap().iter().map(f).collect();
    assert!((num[0] - 2.0 * b1 / a1).abs() < 1e-12, "{num:?}");
    assert!((num[1] - 2.0 / a1).abs() < 1e-12);
    assert!((den[1] - 1.0 / a1).abs() < 1e-12, "{den:?}");
    assert_eq!(f(&j["delay"]), 0.0);
    assert_eq!(j["formula"], "2 (-2.309s + 1) / (6.291s + 1)");
}

#[test]
fn the_fifth_order_gives_its_dominant_pair() {
    let mut args = FIFTH_DOMINANT.to_vec();
    args.push("--json");
    let j = json(&args);
    let den: Vec<f64> = j["den"].as_array().unwrap().iter().map(f).collect();
    assert!(
        (den[1] - 6.0).abs() < 1e-12 && (den[2] - 18.0).abs() < 1e-12,
        "{den:?}"
    );
    assert!((f(&j["dc_gain"]) * 18000.0 - 1.0).abs() < 1e-12);
    assert_eq!(j["order"], 2);
}

#[test]
fn samples_of_both_responses_share_their_instants() {
    let mut args = vec!["approx"];
    args.extend(THIRD);
    args.extend(["--method", "skogestad", "--samples", "50", "--json"]);
    let j = json(&args);
    let s = &j["samples"];
    assert_eq!(s["t"].as_array().unwrap().len(), 50);
    // Before the model's dead time of 2.1 s its response is exactly 0.
    let t = s["t"].as_array().unwrap();
    let ya = s["y_approx"].as_array().unwrap();
    assert!(t.iter().zip(ya).all(|(t, y)| f(t) >= 2.1 || f(y) == 0.0));
}

#[test]
fn the_text_report_speaks_both_languages() {
    let mut args = vec!["approx"];
    args.extend(THIRD);
    args.extend(["--method", "skogestad"]);
    let out = degrau(&args);
    assert!(out.status.success());
    let en = stdout(&out);
    assert!(en.contains("G~(s) = 2 e^(-2.1s) / (6.5s + 1)"), "{en}");
    assert!(
        en.contains("Rise time") && en.contains("Within 5 %"),
        "{en}"
    );
    let mut pt_args = vec!["--lang", "pt"];
    pt_args.extend(args);
    let pt = stdout(&degrau(&pt_args));
    assert!(pt.contains("G~(s) = 2 e^(-2,1s) / (6,5s + 1)"), "{pt}");
    assert!(
        pt.contains("Tempo de subida") && pt.contains("Dentro de 5 %"),
        "{pt}"
    );
}

#[test]
fn pade_prints_the_notes_polynomials() {
    let j = json(&["pade", "--delay", "2", "--order", "1,2", "--json"]);
    // (−2θs + 6)/(θ²s² + 4θs + 6) with θ = 2.
    assert_eq!(j["num"], serde_json::json!([-4.0, 6.0]));
    assert_eq!(j["den"], serde_json::json!([4.0, 8.0, 6.0]));
    let j = json(&["pade", "--delay", "1", "--order", "3", "--json"]);
    assert_eq!(j["num"], serde_json::json!([-1.0, 12.0, -60.0, 120.0]));
    assert_eq!(j["den"], serde_json::json!([1.0, 12.0, 60.0, 120.0]));
    let text = stdout(&degrau(&["pade", "--delay", "0.5", "--order", "1,1"]));
    assert!(text.contains("num = -0.5 s + 2"), "{text}");
    assert!(text.contains("den = 0.5 s + 2"), "{text}");
}

#[test]
fn bad_input_is_refused_in_words_with_code_2() {
    let cases: [(&[&str], &str); 5] = [
        (&["pade", "--delay", "1", "--order", "2,1"], "m ≤ n"),
        (&["pade", "--delay", "0", "--order", "1,1"], "positive"),
        (&["pade", "--delay", "1", "--order", "a"], "--order"),
        (
            &[
                "approx", "--num", "1", "--den", "1,1", "--method", "dominant",
            ],
            "not below",
        ),
        (
            &["approx", "--poles", "1,-2,-3", "--method", "taylor"],
            "right half plane",
        ),
    ];
    for (args, words) in cases {
        let out = degrau(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(stderr(&out).contains(words), "{args:?}: {}", stderr(&out));
    }
    let out = degrau(&["--lang", "pt", "pade", "--delay", "1", "--order", "2,1"]);
    assert!(stderr(&out).contains("exige"), "{}", stderr(&out));
}

#[test]
fn the_table_compares_every_method_in_markdown() {
    let mut args = vec!["approx"];
    args.extend(THIRD);
    args.extend(["--method", "taylor", "--table"]);
    let out = degrau(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    let table: Vec<&str> = text.lines().filter(|l| l.starts_with('|')).collect();
    // Header, rule, and the ten reductions of a third order without dead time.
    assert_eq!(table.len(), 12, "{text}");
    assert!(table[0].contains("| Model |") && table[0].contains("Within 5 %"));
    let skogestad = table
        .iter()
        .find(|l| l.contains("Skogestad's half rule, order 1"))
        .expect("a Skogestad row");
    assert!(
        skogestad.contains("2 e^(-2.1s) / (6.5s + 1)"),
        "{skogestad}"
    );
    // Every row has the header's six cells (a | inside a cell is escaped).
    let cells = |l: &str| l.replace("\\|", "").matches(" | ").count() + 1;
    assert!(table.iter().skip(2).all(|l| cells(l) == 6), "{text}");
    assert_eq!(cells(table[0]), 6);
}

/// "Within 5 %" is judged on the relative change for every metric, the overshoot too:
/// 2.12 % → 4.32 % is a change of 103 %, not within (issue 22, item 14); the table says
/// what was judged.
#[test]
fn within_is_judged_on_the_relative_change() {
    let mut with_json = FIFTH_DOMINANT.to_vec();
    with_json.push("--json");
    let j = json(&with_json);
    let overshoot = &j["metrics_error"]["overshoot"];
    assert!(
        (f(&overshoot["original"]) - 2.124).abs() < 1e-3,
        "{overshoot}"
    );
    assert_eq!(overshoot["within"], false, "{overshoot}");
    for (name, m) in j["metrics_error"].as_object().unwrap() {
        if let Some(rel) = m["relative"].as_f64() {
            let negligible = m["difference"].as_f64().unwrap().abs() <= 0.1
                && ["overshoot", "undershoot"].contains(&name.as_str());
            assert_eq!(m["within"], rel.abs() <= 0.05 || negligible, "{name}: {m}");
        }
    }
    let text = stdout(&degrau(&FIFTH_DOMINANT));
    assert!(text.contains("Within 5 % (relative)"), "{text}");
}
