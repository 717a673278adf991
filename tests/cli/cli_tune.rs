//! `degrau tune`: the rules' controllers for a FOPTD or SOPTD plant, from the system flags
//! or a `degrau fit --json` output, their JSON shape and text in both languages, and the
//! refusals, through the binary.

use crate::run;

use run::{TCLAB, degrau, stderr, stdout};
use serde_json::Value;

/// K = 1, τ = 10 s, θ = 2 s.
const FOPTD: [&str; 6] = ["--num", "1", "--den", "10,1", "--delay", "2"];

fn tune(args: &[&str]) -> Value {
    run::command_json("tune", args)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

const METRICS: [&str; 7] = [
    "final_value",
    "overshoot",
    "peak",
    "peak_time",
    "settling_time",
    "iae",
    "itae",
];

#[test]
fn the_simc_pi_of_k1_tau10_theta2() {
    let v = tune(&[&FOPTD[..], &["--rule", "simc"]].concat());
    assert!(v.is_object(), "one object with --rule: {v}");
    assert_eq!(v["rule"], "simc");
    assert_eq!(v["applies"], true);
    assert_eq!(v["controller"], "pi");
    assert_eq!(v["form"], "ideal");
    // τc = θ = 2: Kc = τ/(K(τc + θ)) = 2.5, Ti = min(τ, 4(τc + θ)) = min(10, 16) = 10.
    assert!((num(&v["kc"]) - 2.5).abs() < 1e-12, "{v}");
    assert!((num(&v["ti"]) - 10.0).abs() < 1e-12, "{v}");
    assert_eq!(num(&v["td"]), 0.0);
    assert_eq!(num(&v["tc"]), 2.0);
    assert!(v.get("series").is_none(), "no series form for a PI: {v}");
    for key in METRICS {
        assert!(v["setpoint"][key].is_number(), "setpoint {key}: {v}");
        assert!(v["load"][key].is_number(), "load {key}: {v}");
    }
    assert!((num(&v["setpoint"]["final_value"]) - 1.0).abs() < 1e-12);
    assert!(num(&v["load"]["final_value"]).abs() < 1e-12);
    // The load's IAE of a PI is Ti/Kc = 4 (the integral of e is the load over Ki).
    assert!((num(&v["load"]["iae"]) - 4.0).abs() < 1e-6, "{v}");
    let ms = num(&v["ms"]);
    assert!(ms > 1.0 && ms < 2.0, "{ms}");
    assert_eq!(v["stable"], true);
    assert!(
        v["formula"]
            .as_str()
            .is_some_and(|f| f.contains("Ti = min(τ, 4(τc + θ))")),
        "{v}"
    );
    assert!(
        v["source"]
            .as_str()
            .is_some_and(|s| s.contains("Skogestad (2003)")),
        "{v}"
    );
}

#[test]
fn every_rule_is_a_row_of_the_list_in_order() {
    let v = tune(&FOPTD);
    let rows = v.as_array().expect("a list without --rule");
    let keys: Vec<&str> = rows.iter().map(|r| r["rule"].as_str().unwrap()).collect();
    assert_eq!(
        keys,
        [
            "zn-open",
            "zn-ultimate",
            "cohen-coon",
            "imc",
            "simc",
            "amigo",
            "lambda"
        ]
    );
    for r in rows {
        assert_eq!(r["applies"], true, "{r}");
        for key in ["kc", "ti", "td", "ms"] {
            assert!(r[key].is_number(), "{key}: {r}");
        }
        for key in ["formula", "source"] {
            assert!(r[key].is_string(), "{key}: {r}");
        }
        assert!(r["setpoint"].is_object() && r["load"].is_object(), "{r}");
    }
    // IMC's PI for a FOPTD is SIMC's here (τ < 4(τc + θ)); Lambda's λ = τ: Kc = 10/12.
    assert_eq!(rows[3]["kc"], rows[4]["kc"]);
    assert!((num(&rows[6]["kc"]) - 10.0 / 12.0).abs() < 1e-12);
    assert!((num(&rows[6]["tc"]) - 10.0).abs() < 1e-12);
}

#[test]
fn a_rule_that_does_not_apply_says_why() {
    // No dead time: the reaction-curve rules and AMIGO divide by θ.
    let v = tune(&["--num", "1", "--den", "10,1", "--tc", "1"]);
    let rows = v.as_array().unwrap();
    for key in ["zn-open", "cohen-coon", "amigo"] {
        let r = rows.iter().find(|r| r["rule"] == key).unwrap();
        assert_eq!(r["applies"], false, "{r}");
        assert!(
            r["reason"].as_str().is_some_and(|s| s.contains("θ > 0")),
            "{r}"
        );
        assert!(r.get("kc").is_none());
    }
    // With τc = 1 given, SIMC applies: Kc = 10/(1·(1 + 0)).
    let simc = rows.iter().find(|r| r["rule"] == "simc").unwrap();
    assert!((num(&simc["kc"]) - 10.0).abs() < 1e-12, "{simc}");
    // One rule asked for that does not apply: its object, and success.
    let one = tune(&["--num", "1", "--den", "10,1", "--rule", "cohen-coon"]);
    assert_eq!(one["applies"], false);
    assert_eq!(one["rule"], "cohen-coon");
}

#[test]
fn a_second_order_pid_gives_simcs_series_form() {
    // K = 1, τ1 = 1, τ2 = 1 (a double pole), θ = 1, τc = θ: the series Kc = τ1/(K(τc + θ))
    // = 0.5, Ti = min(τ1, 8) = 1, Td = τ2 = 1; ideal Kc·(1 + Td/Ti) = 1, Ti + Td = 2,
    // Ti·Td/(Ti + Td) = 0.5.
    let v = tune(&[
        "--num",
        "1",
        "--den",
        "1,2,1",
        "--delay",
        "1",
        "--controller",
        "pid",
        "--rule",
        "simc",
    ]);
    assert_eq!(v["controller"], "pid");
    let series: Vec<f64> = v["series"].as_array().unwrap().iter().map(num).collect();
    for (a, b) in series.iter().zip([0.5, 1.0, 1.0]) {
        assert!((a - b).abs() < 1e-9, "{series:?}");
    }
    for (key, want) in [("kc", 1.0), ("ti", 2.0), ("td", 0.5)] {
        assert!((num(&v[key]) - want).abs() < 1e-9, "{key}: {v}");
    }
}

#[test]
fn the_text_is_one_table_then_the_formulas_in_both_languages() {
    for (lang, words) in [
        (
            "en",
            vec![
                "Model: first order with dead time, K = 1, τ = 10 s, θ = 2 s",
                "exact dead time (no Padé)",
                "setpoint step",
                "load step at the plant's input",
                "overshoot %",
                "Formulas and sources:",
                "simc: SIMC (Skogestad's IMC)",
                "Source: Skogestad (2003)",
                "0.8333",
            ],
        ),
        (
            "pt",
            vec![
                "Modelo: primeira ordem com tempo morto, K = 1, τ = 10 s, θ = 2 s",
                "atraso exato (sem Padé)",
                "degrau de referência",
                "degrau de carga na entrada da planta",
                "sobressinal %",
                "Fórmulas e fontes:",
                "simc: SIMC (IMC de Skogestad)",
                "Fonte: Skogestad (2003)",
                "0,8333",
            ],
        ),
    ] {
        let out = degrau(&[&["--lang", lang, "tune"], &FOPTD[..]].concat());
        assert!(out.status.success(), "{}", stderr(&out));
        let text = stdout(&out);
        for w in words {
            assert!(text.contains(w), "{lang}: {w}\n{text}");
        }
        // The SIMC row: Kc 2.5, Ti 10, no Td.
        let simc = text
            .lines()
            .find(|l| l.starts_with("simc "))
            .expect("a simc row");
        let cells: Vec<&str> = simc.split_whitespace().collect();
        assert_eq!(
            cells[..4],
            ["simc", if lang == "en" { "2.5" } else { "2,5" }, "10", "–"]
        );
    }
    // A rule that does not apply prints its reason in its row.
    let text = stdout(&degrau(&["tune", "--num", "1", "--den", "10,1"]));
    let row = text.lines().find(|l| l.starts_with("amigo ")).unwrap();
    assert!(row.contains("needs a dead time θ > 0"), "{row}");
}

#[test]
fn a_fit_json_is_tuned_from_its_model() {
    let fit = run::succeeds(&[
        "fit", TCLAB, "--model", "P1D", "--y-col", "T1", "--u-col", "Q1", "--json",
    ]);
    let params = serde_json::from_str::<Value>(&fit).unwrap()["params"].clone();
    let (k, tau, theta) = (num(&params["Kp"]), num(&params["Tp1"]), num(&params["Td"]));
    assert!(theta > 0.0, "{params}");
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("tune_tclab_p1d_{}.json", std::process::id()));
    std::fs::write(&path, &fit).unwrap();
    let file = path.to_str().unwrap();
    let v = tune(&["--fit", file, "--rule", "simc"]);
    // SIMC with τc = θ.
    assert!((num(&v["kc"]) - tau / (k * 2.0 * theta)).abs() < 1e-9 * num(&v["kc"]));
    assert!((num(&v["ti"]) - tau.min(8.0 * theta)).abs() < 1e-9 * tau);
    let all = tune(&["--fit", file]);
    assert_eq!(all.as_array().map(Vec::len), Some(7));
    // The system flags and --fit are one or the other.
    let out = degrau(&["tune", "--fit", file, "--delay", "1"]);
    assert_eq!(out.status.code(), Some(2));
    // A fit whose model is not a FOPTD or SOPTD.
    std::fs::write(
        &path,
        r#"{"model": "P2DU", "params": {"Kp": 1, "Tw": 1, "Zeta": 0.5}}"#,
    )
    .unwrap();
    let out = degrau(&["tune", "--fit", file]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("P2DU"), "{}", stderr(&out));
    let _ = std::fs::remove_file(&path);
}

#[test]
fn bad_plants_and_rules_are_refused_in_words() {
    for (lang, args, words) in [
        (
            "en",
            vec!["--num", "1,1", "--den", "10,1,1", "--delay", "2"],
            "no zeros, one or two real stable poles; this system has 1 zero(s)",
        ),
        (
            "pt",
            vec!["--num", "1,1", "--den", "10,1,1", "--delay", "2"],
            "sem zeros, um ou dois polos reais estáveis; este sistema tem 1 zero(s)",
        ),
        (
            "en",
            vec!["--num", "1", "--den", "1,1,1"],
            "this system has complex poles",
        ),
        ("en", vec!["--poles", "-1,-2,-3"], "this system has 3 poles"),
        (
            "en",
            vec!["--num", "1", "--den", "1,-1"],
            "this system has a pole at s = 1",
        ),
        (
            "en",
            vec!["--num", "1", "--den", "10,1", "--rule", "ziegler"],
            "[possible values: zn-open, zn-ultimate, cohen-coon, imc, simc, amigo, lambda]",
        ),
        (
            "pt",
            vec!["--num", "1", "--den", "10,1", "--rule", "ziegler"],
            "os valores possíveis são zn-open",
        ),
        (
            "en",
            vec!["--num", "1", "--den", "10,1", "--controller", "pd"],
            "possible values: pi, pid",
        ),
        (
            "en",
            vec!["--fit", "/nonexistent/fit.json"],
            "cannot read /nonexistent/fit.json",
        ),
    ] {
        let out = degrau(&[&["--lang", lang, "tune"], &args[..]].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(err.contains(words), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn a_fit_whose_dead_time_came_out_negative_is_tuned_with_theta_zero_and_says_so() {
    let dir = std::env::temp_dir().join(format!("degrau-tune-negative-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("p2d.json");
    std::fs::write(
        &path,
        r#"{"model":"P2D","params":{"Kp":0.7,"Td":-0.57,"Tp1":20.0,"Tp2":140.0,"Y0":20.9}}"#,
    )
    .unwrap();
    let out = degrau(&[
        "tune",
        "--fit",
        path.to_str().unwrap(),
        "--rule",
        "zn-open",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("tuned with θ = 0"),
        "{}",
        stderr(&out)
    );
    let v: Value = serde_json::from_str(&stdout(&out)).unwrap();
    // Two lags and no dead time: the reaction curve's tangent still gives ZN a θ′ > 0.
    assert_eq!(v["applies"], true, "{v}");
    std::fs::remove_dir_all(&dir).ok();
}
