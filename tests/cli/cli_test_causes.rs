//! `degrau diagnose` says what the test got wrong apart from what the model lacks: the SBHS
//! heater record (a synthetic stand-in, see tests/data/records/SOURCES.md) was still rising
//! before its step; the notes' LECI test was at rest.

use crate::run;

use run::LECI;

const SBHS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/sbhs_step_not_at_rest_synthetic.txt"
);

/// The SBHS columns: time from the sample number (one a second), heater, temperature.
const SBHS_COLUMNS: [&str; 6] = ["--time-col", "1", "--u-col", "2", "--y-col", "4"];

fn degrau(args: &[&str]) -> String {
    run::succeeds(&[&["diagnose"], args].concat())
}

#[test]
fn the_json_lists_not_at_rest_with_its_words_interval_handling_and_facts() {
    let mut args = vec![SBHS, "--json"];
    args.extend(SBHS_COLUMNS);
    let en = degrau(&args);
    let j: serde_json::Value = serde_json::from_str(&en).expect("one JSON object");
    let causes = j["test_causes"].as_array().expect("test_causes");
    let rest = causes
        .iter()
        .find(|c| c["cause"] == "not_at_rest")
        .unwrap_or_else(|| panic!("{causes:?}"));
    let evidence = rest["evidence"].as_str().unwrap();
    assert!(
        evidence.starts_with("Before the first input change (t = 1 … 250 s, 250 samples)"),
        "{evidence}"
    );
    assert_eq!(rest["interval"], serde_json::json!([1.0, 250.0]));
    assert_eq!(rest["handling"]["kind"], "initial_transient");
    assert!(
        rest["remedy"]
            .as_str()
            .unwrap()
            .starts_with("Wait for steady state")
    );
    // The typed facts: the line through the 250 samples before the step rose by about the
    // generator's 5.2 °C (29.3 → 34.5), beyond the threshold it reports.
    let motion = &rest["facts"]["motion"];
    assert_eq!(rest["facts"]["kind"], "not_at_rest");
    let change = motion["change"].as_f64().unwrap();
    assert!((4.0..6.0).contains(&change), "{motion}");
    assert!(change > motion["threshold"].as_f64().unwrap());
    // The chain stays for structure, and the gain is the source's 0.23 °C/% within 8 %.
    assert!(j["steps"].is_array());
    let kp = j["static_gain"]["value"].as_f64().unwrap();
    assert!((kp - 0.23).abs() <= 0.08 * 0.23, "Kp = {kp}");
}

#[test]
fn the_text_puts_the_test_before_the_model_and_the_verdict_names_both() {
    let mut args = vec![SBHS, "--lang", "pt"];
    args.extend(SBHS_COLUMNS);
    let text = degrau(&args);
    let test = text.find("O que o ensaio teve de errado:").expect(&text);
    let model = text.find("O que falta ao modelo:").expect(&text);
    assert!(test < model, "{text}");
    assert!(
        text.contains("1. not_at_rest: Fora do equilíbrio antes do degrau"),
        "{text}"
    );
    assert!(text.contains("O que fazer: Espere o regime permanente antes do degrau"));
    let verdict = text
        .lines()
        .find(|l| l.starts_with("Veredito: estrutura "))
        .expect(&text);
    assert!(
        verdict.contains("transitório inicial") && verdict.contains("ensaio: not_at_rest"),
        "{verdict}"
    );
}

/// The LECI test was at rest, its output is not quantised coarsely and it has no outliers,
/// but it samples an oscillation of ωn ≈ 1 rad/s every 1.025 s: by the notes' rules
/// (h < 0.1·τmax; 0.01 < h/τ < 0.05) far too slowly, the only thing to say about the test.
#[test]
fn the_leci_test_is_only_sampled_too_slowly() {
    let args = [
        LECI, "--t0", "5", "--du", "10", "--y0", "50", "--start", "P2DU",
    ];
    let json = degrau(&[&args[..], &["--json"]].concat());
    let j: serde_json::Value = serde_json::from_str(&json).unwrap();
    let causes = j["test_causes"].as_array().expect(&json);
    assert_eq!(causes.len(), 1, "{json}");
    assert_eq!(causes[0]["cause"], "sampling");
    assert_eq!(causes[0]["facts"]["too_slow"], true);
    assert!(causes[0]["facts"]["ts"].as_f64().unwrap() > 1.0);
    let pt = degrau(&[&args[..], &["--json", "--lang", "pt"]].concat());
    assert_eq!(pt, json, "--json is the same in every language");
    let text = degrau(&args);
    let test = text
        .find("What the test got wrong:\n1. sampling")
        .expect(&text);
    assert!(test < text.find("What the model gets wrong:").expect(&text));
    let verdict = text
        .lines()
        .find(|l| l.starts_with("Verdict: structure P2DU"))
        .expect(&text);
    assert!(verdict.ends_with("; test: sampling."), "{verdict}");
}
