//! `degrau loop` and `degrau step --response` / `--rise-limits 0,1`: the JSON keys, the
//! notes' numbers and the refusals, through the binary.

mod run;

use run::{degrau, stderr, stdout};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = degrau(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    serde_json::from_str(&stdout(&out)).expect("one JSON object")
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

#[test]
fn the_notes_loop_with_unit_gain() {
    let v = json(&[
        "loop",
        "--num",
        "0.5",
        "--den",
        "1,7,15,25",
        "--kp",
        "1",
        "--json",
    ]);
    assert_eq!(num(&v["kp"]), 1.0);
    assert_eq!(v["kp_range"], Value::Null);
    let den: Vec<f64> = v["closed_loop"]["den"]
        .as_array()
        .unwrap()
        .iter()
        .map(num)
        .collect();
    for (a, b) in den.iter().zip([1.0, 7.0, 15.0, 25.5]) {
        assert!((a - b).abs() < 1e-12, "{den:?}");
    }
    // The closed loop's step keys, as `degrau step` prints them.
    for key in [
        "rise_time",
        "settling_time",
        "overshoot",
        "steady_state",
        "expression",
    ] {
        assert!(!v[key].is_null(), "{key}");
    }
    assert!((num(&v["steady_state"]) - 0.5 / 25.5).abs() < 1e-12);
    assert_eq!(v["type"], 0);
    assert!((num(&v["error_constants"]["kp"]) - 0.02).abs() < 1e-15);
    assert_eq!(num(&v["error_constants"]["kv"]), 0.0);
    assert_eq!(v["ess"]["ramp"], "inf");
    assert!((num(&v["ess"]["step"]) - 1.0 / 1.02).abs() < 1e-12);
    // Routh: s³ + 7s² + 15s + 25 + K/2 crosses at K = 160, ω = √15.
    assert!((num(&v["critical_gain"]) - 160.0).abs() < 1e-8);
    assert!((num(&v["crossing_frequency"]) - 15f64.sqrt()).abs() < 1e-10);
    assert!(v["breakaway"].is_array());
    assert!(v.get("locus").is_none());
    assert_eq!(
        v["approximant"],
        Value::Null,
        "no dead time, no approximant"
    );
}

#[test]
fn find_the_gain_for_an_overshoot() {
    let v = json(&[
        "loop",
        "--num",
        "1",
        "--den",
        "1,2,0",
        "--find",
        "overshoot<=10",
        "--json",
    ]);
    assert_eq!(format!("{:.2}", num(&v["kp"])), "2.86");
    assert_eq!(num(&v["kp_range"][0]), 0.0);
    assert!((num(&v["kp_range"][1]) - num(&v["kp"])).abs() < 1e-12);
    assert!((num(&v["overshoot"]) - 10.0).abs() < 1e-6);
    assert_eq!(v["critical_gain"], Value::Null);
    assert_eq!(v["breakaway"][0]["kind"], "breakaway");
    assert!((num(&v["breakaway"][0]["s"]) + 1.0).abs() < 1e-12);
    // A steady-state error bound: a least gain and no upper end.
    let e = json(&[
        "loop",
        "--num",
        "10",
        "--den",
        "1,7,10",
        "--find",
        "ess_step<=0.1",
        "--json",
    ]);
    assert!((num(&e["kp"]) - 9.0).abs() < 1e-7);
    assert_eq!(e["kp_range"][1], Value::Null);
}

#[test]
fn the_constants_of_s_plus_2_over_s_s_plus_4() {
    let v = json(&["loop", "--num", "1,2", "--den", "1,4,0", "--json"]);
    assert_eq!(v["type"], 1);
    assert_eq!(v["error_constants"]["kp"], "inf");
    assert!((num(&v["error_constants"]["kv"]) - 0.5).abs() < 1e-15);
    assert_eq!(num(&v["error_constants"]["ka"]), 0.0);
    assert_eq!(num(&v["ess"]["step"]), 0.0);
    assert!((num(&v["ess"]["ramp"]) - 2.0).abs() < 1e-15);
    assert_eq!(v["ess"]["parabola"], "inf");
}

#[test]
fn the_locus_points_are_roots_of_the_characteristic_polynomial() {
    let v = json(&[
        "loop",
        "--poles",
        "-1+2j,-1-2j,-5",
        "--zeros",
        "-10",
        "--gain",
        "0.5",
        "--locus",
        "--json",
    ]);
    // 0.5(s+10)/(s³+7s²+15s+25): Routh gives K = 160/3 at ω² = 875/21.
    assert!((num(&v["critical_gain"]) - 160.0 / 3.0).abs() < 1e-9);
    assert!((num(&v["crossing_frequency"]) - (875.0f64 / 21.0).sqrt()).abs() < 1e-10);
    let points = v["locus"].as_array().unwrap();
    assert!(points.len() > 50);
    for p in points {
        let k = num(&p["k"]);
        for r in p["roots"].as_array().unwrap() {
            let (re, im) = (num(&r[0]), num(&r[1]));
            let r = re.hypot(im);
            let d = horner(&[1.0, 7.0, 15.0, 25.0], (re, im));
            let n = horner(&[0.5, 5.0], (re, im));
            let value = (d.0 + k * n.0).hypot(d.1 + k * n.1);
            // The terms' size: Σ|coefficient|·|s|^power of den and of K·num.
            let size = r.powi(3) + 7.0 * r * r + 15.0 * r + 25.0 + k.abs() * (0.5 * r + 5.0);
            assert!(
                value <= 1e-9 * size,
                "K {k}: {re}+{im}j, residual {value} of {size}"
            );
        }
    }
}

type C = (f64, f64);

fn horner(p: &[f64], s: C) -> C {
    p.iter().fold((0.0, 0.0), |acc, &c| {
        (acc.0 * s.0 - acc.1 * s.1 + c, acc.0 * s.1 + acc.1 * s.0)
    })
}

fn poles(v: &Value) -> Vec<C> {
    v["closed_loop"]["poles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (num(&p[0]), num(&p[1])))
        .collect()
}

#[test]
fn a_dead_time_is_closed_through_its_default_pade_3_3() {
    let v = json(&[
        "loop", "--num", "1", "--den", "10,1", "--delay", "2", "--kp", "3", "--json",
    ]);
    assert_eq!(v["approximant"]["kind"], "pade");
    assert_eq!(v["approximant"]["m"], 3);
    assert_eq!(v["approximant"]["n"], 3);
    assert_eq!(num(&v["approximant"]["delay"]), 2.0);
    // Padé (3, 3) of e^{−2s}: (−8s³ + 48s² − 120s + 120)/(8s³ + 48s² + 120s + 120), so
    // 1 + 3G = 0 ⇔ (10s + 1)(8s³ + 48s² + 120s + 120) + 3(−8s³ + 48s² − 120s + 120) = 0.
    let d = [8.0, 48.0, 120.0, 120.0];
    let n = [-8.0, 48.0, -120.0, 120.0];
    let mut characteristic = [0.0; 5];
    for (i, c) in d.iter().enumerate() {
        characteristic[i] += 10.0 * c;
        characteristic[i + 1] += c;
    }
    for (i, c) in n.iter().enumerate() {
        characteristic[i + 1] += 3.0 * c;
    }
    let roots = poles(&v);
    assert_eq!(roots.len(), 4);
    for s in roots {
        let value = horner(&characteristic, s);
        let r = s.0.hypot(s.1);
        let size: f64 = characteristic
            .iter()
            .enumerate()
            .map(|(i, c)| c.abs() * r.powi(4 - i as i32))
            .sum();
        assert!(value.0.hypot(value.1) <= 1e-10 * size, "{s:?}");
    }
    // Every approximant is 1 at s = 0: the steady state is the exact loop's 3/(1 + 3).
    assert!((num(&v["steady_state"]) - 0.75).abs() < 1e-12);
    let out = degrau(&["loop", "--num", "1", "--den", "10,1", "--json"]);
    let exact: Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(exact["approximant"], Value::Null);
}

#[test]
fn the_pade_1_1_loop_has_its_closed_form_poles() {
    let v = json(&[
        "loop", "--num", "1", "--den", "10,1", "--delay", "2", "--kp", "3", "--pade", "1,1",
        "--json",
    ]);
    assert_eq!(
        (v["approximant"]["m"].clone(), v["approximant"]["n"].clone()),
        (1.into(), 1.into())
    );
    // e^{−2s} ≈ (1 − s)/(1 + s): (10s + 1)(s + 1) + 3(1 − s) = 10s² + 8s + 4,
    // s = −0.4 ± j√0.24.
    let mut roots = poles(&v);
    roots.sort_by(|a, b| a.1.total_cmp(&b.1));
    assert_eq!(roots.len(), 2);
    for (s, sign) in roots.iter().zip([-1.0, 1.0]) {
        assert!((s.0 + 0.4).abs() < 1e-12, "{s:?}");
        assert!((s.1 - sign * 0.24f64.sqrt()).abs() < 1e-12, "{s:?}");
    }
    let den: Vec<f64> = v["closed_loop"]["den"]
        .as_array()
        .unwrap()
        .iter()
        .map(num)
        .collect();
    let scale = den[0] / 10.0;
    for (a, b) in den.iter().zip([10.0, 8.0, 4.0]) {
        assert!((a / scale - b).abs() < 1e-12, "{den:?}");
    }
}

#[test]
fn the_text_says_the_loop_is_approximate_in_both_languages() {
    for (lang, words) in [
        (
            "en",
            "Padé (2, 2) approximant: the closed loop is approximate",
        ),
        (
            "pt",
            "aproximação de Padé (2, 2): a malha fechada é aproximada",
        ),
    ] {
        let out = degrau(&[
            "--lang", lang, "loop", "--num", "1", "--den", "1,1", "--delay", "0.5", "--pade",
            "2,2", "--locus",
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        assert!(stdout(&out).contains(words), "{}", stdout(&out));
        assert!(
            stdout(&out).contains(if lang == "en" {
                "Padé-approximated loop, approximate"
            } else {
                "aproximada por Padé, aproximado"
            }),
            "{}",
            stdout(&out)
        );
    }
}

#[test]
fn a_bad_pade_order_and_a_bad_spec_are_refused() {
    for order in ["4,2", "0,0", "3", "a,b", "9,9"] {
        let out = degrau(&[
            "loop", "--num", "1", "--den", "1,1", "--delay", "0.5", "--pade", order,
        ]);
        assert_eq!(out.status.code(), Some(2), "{order}");
        assert!(
            stderr(&out).contains("not a Padé order"),
            "{}",
            stderr(&out)
        );
    }
    let out = degrau(&["loop", "--num", "1", "--den", "1,1", "--find", "mp=3"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("overshoot<=10"), "{}", stderr(&out));
}

#[test]
fn rise_limits_zero_to_one_are_matlabs() {
    let v = json(&[
        "step",
        "--num",
        "1,5,5",
        "--den",
        "1,1.65,5,6.5,2",
        "--rise-limits",
        "0,1",
        "--json",
    ]);
    assert_eq!(format!("{:.4}", num(&v["rise_time"])), "4.8143");
    let text = stdout(&degrau(&[
        "step",
        "--num",
        "1,5,5",
        "--den",
        "1,1.65,5,6.5,2",
        "--rise-limits",
        "0,1",
    ]));
    assert!(text.contains("4.8143"), "{text}");
}

#[test]
fn step_gives_impulse_ramp_and_parabola_responses() {
    // 1/(s+1): impulse e^{−t}, ramp t − 1 + e^{−t}, parabola t²/2 − t + 1 − e^{−t}.
    type Exact = fn(f64) -> f64;
    let exact: [(&str, Exact); 3] = [
        ("impulse", |t| (-t).exp()),
        ("ramp", |t| t - 1.0 + (-t).exp()),
        ("parabola", |t| 0.5 * t * t - t + 1.0 - (-t).exp()),
    ];
    for (input, f) in exact {
        let v = json(&[
            "step",
            "--num",
            "1",
            "--den",
            "1,1",
            "--response",
            input,
            "--samples",
            "11",
            "--json",
        ]);
        assert_eq!(v["response"], input);
        let t = v["samples"]["t"].as_array().unwrap();
        let y = v["samples"]["y"].as_array().unwrap();
        assert_eq!(t.len(), 11);
        for (t, y) in t.iter().zip(y) {
            let (t, y) = (num(t), num(y));
            assert!(
                (y - f(t)).abs() <= 1e-12 * (1.0 + f(t).abs()),
                "{input} at {t}: {y}"
            );
        }
        assert_eq!(v["expression"].is_null(), input == "impulse");
    }
}
