//! `degrau margins`: the JSON keys, K/(s(s+1)(s+2))'s margins worked by hand (ω_pc = √2,
//! GM = 6/K), "inf" for a margin that does not exist, the text in both languages and a
//! refused controller, through the binary.

use crate::run;

use run::{degrau, json, stderr, stdout};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-10 * b.abs().max(1.0), "{a} is not {b}");
}

#[test]
fn the_json_keys_and_the_margins_of_k_over_s_s1_s2() {
    let k = 2.0;
    let v = json(&[
        "margins", "--num", "1", "--den", "1,3,2,0", "--kc", "2", "--json",
    ]);
    for key in [
        "gm",
        "gm_db",
        "w_pc",
        "pm",
        "w_gc",
        "delay_margin",
        "ms",
        "bandwidth",
        "crossings",
    ] {
        assert!(v.get(key).is_some(), "no {key} in {v}");
    }
    close(num(&v["w_pc"]), 2f64.sqrt());
    close(num(&v["gm"]), 6.0 / k);
    close(num(&v["gm_db"]), 20.0 * (6.0 / k).log10());
    let w = num(&v["w_gc"]);
    close(w * (w * w + 1.0).sqrt() * (w * w + 4.0).sqrt(), k);
    let pm = 90.0 - w.atan().to_degrees() - (w / 2.0).atan().to_degrees();
    close(num(&v["pm"]), pm);
    close(num(&v["delay_margin"]), pm.to_radians() / w);
    assert!(num(&v["ms"]) > 1.0);
    assert!(num(&v["bandwidth"]) > 0.0);
    assert_eq!(v["crossings"]["phase"].as_array().map(Vec::len), Some(1));
    assert_eq!(v["crossings"]["gain"].as_array().map(Vec::len), Some(1));
}

#[test]
fn a_missing_margin_is_inf() {
    // 0.5/(s + 1): no phase crossover, no gain crossover.
    let v = json(&[
        "margins", "--num", "1", "--den", "1,1", "--kc", "0.5", "--json",
    ]);
    for key in ["gm", "gm_db", "pm", "delay_margin"] {
        assert_eq!(v[key], "inf", "{key} in {v}");
    }
    assert!(v["w_pc"].is_null() && v["w_gc"].is_null());
    // An unstable loop (K = 6·2): no Ms.
    let v = json(&[
        "margins", "--num", "1", "--den", "1,3,2,0", "--kc", "12", "--json",
    ]);
    assert!(v["ms"].is_null(), "{v}");
    assert!(num(&v["gm"]) < 1.0);
    // Its Nyquist curve goes round −1 (N = 2 over the whole contour), P = 0: Z = 2, the
    // complex pair of s³ + 3s² + 2s + 12 lies right of the axis.
    assert_eq!(v["nyquist"]["encirclements"], 2, "{v}");
    assert_eq!(v["nyquist"]["open_loop_unstable"], 0);
    assert_eq!(v["nyquist"]["closed_loop_unstable"], 2);
}

#[test]
fn the_nyquist_count_of_an_open_loop_unstable_plant() {
    // 2/(s − 1): closed loop s + 1, stable: P = 1 and one counterclockwise turn, N = −1.
    let v = json(&["margins", "--num", "2", "--den", "1,-1", "--json"]);
    assert_eq!(v["nyquist"]["encirclements"], -1, "{v}");
    assert_eq!(v["nyquist"]["open_loop_unstable"], 1);
    assert_eq!(v["nyquist"]["closed_loop_unstable"], 0);
    // At the edge, 8/(s + 1)³: a closed-loop pair on the axis (±j√3), no count.
    let out = degrau(&["margins", "--num", "8", "--den", "1,3,3,1"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("Nyquist: no count"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn the_text_in_both_languages() {
    for (lang, words) in [
        (
            "en",
            [
                "Gain margin: 3 (",
                "Phase margin:",
                "Delay margin:",
                "Z = N + P = 0 closed-loop poles there: stable",
            ],
        ),
        (
            "pt",
            [
                "Margem de ganho: 3 (",
                "Margem de fase:",
                "Margem de atraso:",
                "Z = N + P = 0 polos de malha fechada nele: estável",
            ],
        ),
    ] {
        let out = degrau(&[
            "--lang", lang, "margins", "--num", "1", "--den", "1,3,2,0", "--kc", "2",
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        for w in words {
            assert!(stdout(&out).contains(w), "{w}: {}", stdout(&out));
        }
    }
    let out = degrau(&["--lang", "pt", "margins", "--num", "1", "--den", "1,1"]);
    assert!(
        stdout(&out).contains("Margem de ganho: ∞"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn a_pi_with_a_dead_time_and_a_refused_controller() {
    let v = json(&[
        "margins",
        "--num",
        "1",
        "--den",
        "10,1",
        "--delay",
        "2",
        "--controller",
        "pi",
        "--kc",
        "2.5",
        "--ti",
        "10",
        "--json",
    ]);
    assert!(num(&v["pm"]) > 0.0 && num(&v["gm"]) > 1.0, "{v}");
    let out = degrau(&[
        "margins",
        "--num",
        "1",
        "--den",
        "10,1",
        "--controller",
        "pi",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--ti"), "{}", stderr(&out));
}
