//! `degrau loop` and `degrau step --response` / `--rise-limits 0,1`: the JSON keys, the
//! notes' numbers and the refusals, through the binary.

use crate::run;

use proptest::prelude::*;
use run::{degrau, stderr, stdout};
use serde_json::Value;

/// The notes' G(s) = 0.5(s + 10)/((s² + 2s + 5)(s + 5)), by its roots: flag and value.
const NOTES_G: [[&str; 2]; 3] = [
    ["--poles", "-1+2j,-1-2j,-5"],
    ["--zeros", "-10"],
    ["--gain", "0.5"],
];

fn json(args: &[&str]) -> Value {
    let out = degrau(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    serde_json::from_str(&stdout(&out)).expect("one JSON object")
}

/// A JSON array of numbers.
fn numbers(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(num).collect()
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
    let den = numbers(&v["closed_loop"]["den"]);
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
    let v = json(&[&["loop"], &NOTES_G.concat()[..], &["--locus", "--json"]].concat());
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
    let den = numbers(&v["closed_loop"]["den"]);
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
    let args = [
        "step",
        "--num",
        "1,5,5",
        "--den",
        "1,1.65,5,6.5,2",
        "--rise-limits",
        "0,1",
    ];
    let v = json(&[&args[..], &["--json"]].concat());
    assert_eq!(format!("{:.4}", num(&v["rise_time"])), "4.8143");
    let text = stdout(&degrau(&args));
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

/// The coefficients of k·Π(s − rᵢ) (descending powers) for real or conjugate-paired roots.
fn from_roots(k: f64, roots: &[C]) -> Vec<f64> {
    let mut acc: Vec<C> = vec![(k, 0.0)];
    for &(re, im) in roots {
        let mut next = vec![(0.0, 0.0); acc.len() + 1];
        for (i, &(a, b)) in acc.iter().enumerate() {
            next[i].0 += a;
            next[i].1 += b;
            next[i + 1].0 -= a * re - b * im;
            next[i + 1].1 -= a * im + b * re;
        }
        acc = next;
    }
    acc.iter().map(|c| c.0).collect()
}

/// den + K·num, descending powers.
fn characteristic(den: &[f64], num: &[f64], k: f64) -> Vec<f64> {
    let mut p = den.to_vec();
    let offset = den.len() - num.len();
    for (i, c) in num.iter().enumerate() {
        p[offset + i] += k * c;
    }
    p
}

/// |p(r)| / Σ|cᵢ||r|ⁱ: how far r is from being a root of p, relative to the coefficients.
fn relative_residual(p: &[f64], r: C) -> f64 {
    let (re, im) = horner(p, r);
    let size = p
        .iter()
        .fold(0.0, |acc: f64, c| acc * re_im_norm(r) + c.abs());
    re.hypot(im) / size
}

fn re_im_norm(r: C) -> f64 {
    r.0.hypot(r.1)
}

#[test]
fn a_huge_gain_gives_the_unstable_poles_of_den_plus_k_num() {
    // 0.5(s + 10)/((s² + 2s + 5)(s + 5)) at Kp = 1e22: s³ + 7s² + (5e21 + 15)s + (5e22 + 25),
    // whose poles are 1.5 ± 7.07e10j (their sum is −7, the third tends to −10).
    let v = json(&[
        "loop",
        "--poles=-1+2j,-1-2j,-5",
        "--zeros=-10",
        "--gain",
        "0.5",
        "--kp",
        "1e22",
        "--json",
    ]);
    assert_eq!(v["stability"], "unstable");
    let p = poles(&v);
    let pair: Vec<&C> = p.iter().filter(|r| r.1 != 0.0).collect();
    assert_eq!(pair.len(), 2, "{p:?}");
    for r in &pair {
        assert!((r.0 - 1.5).abs() < 1e-6, "{p:?}");
        assert!((r.1.abs() / 5e21f64.sqrt() - 1.0).abs() < 1e-12, "{p:?}");
    }
    let den = numbers(&v["closed_loop"]["den"]);
    assert_eq!(den, vec![1.0, 7.0, 5e21, 5e22], "den + K·num as computed");
}

#[test]
fn a_gain_beyond_double_precision_is_refused_in_both_languages() {
    for system in [
        &["--poles=-1+2j,-1-2j,-5", "--zeros=-10", "--gain", "0.5"][..],
        &["--num", "1,5,5", "--den", "1,1.65,5,6.5,2"][..],
    ] {
        for (lang, words) in [
            ("en", "Kp = 1e300 the closed loop's poles"),
            ("pt", "Kp = 1e300 os polos da malha fechada"),
        ] {
            let mut args = vec!["--lang", lang, "loop", "--kp", "1e300", "--json"];
            args.extend_from_slice(system);
            let out = degrau(&args);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stdout(&out));
            assert!(stdout(&out).is_empty(), "{}", stdout(&out));
            assert!(stderr(&out).contains(words), "{}", stderr(&out));
        }
    }
}

#[test]
fn the_text_writes_six_digits_and_the_json_every_digit() {
    let args = ["loop", "--num", "0.5", "--den", "1,7,15,25", "--kp", "1"];
    let out = degrau(&args);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        text.contains("G(s) = 0.5 / ((s+1-2j)(s+1+2j)(s+5))"),
        "{text}"
    );
    assert!(text.contains("-0.987623+2.02472j"), "{text}");
    assert!(!text.contains("0000000"), "{text}");
    let mut json_args = args.to_vec();
    json_args.push("--json");
    let v = json(&json_args);
    let first = poles(&v)[0];
    assert!(format!("{}", first.0).len() > 10, "{first:?}");
}

/// A pole or zero drawn as text for `--poles`/`--zeros`, and its conjugate when complex.
fn roots_arg(roots: &[C]) -> String {
    roots
        .iter()
        .map(|&(re, im)| {
            if im == 0.0 {
                format!("{re}")
            } else {
                format!("{re}{:+}j", im)
            }
        })
        .collect::<Vec<_>>()
        .join(",")
}

prop_compose! {
    /// A real root or a conjugate pair, each part in ±[0.1, 100].
    fn root_set()(
        re in -100.0f64..100.0,
        im in prop_oneof![Just(0.0), 0.1f64..100.0],
    ) -> Vec<C> {
        let re = if re.abs() < 0.1 { re.signum() * 0.1 } else { re };
        if im == 0.0 { vec![(re, 0.0)] } else { vec![(re, im), (re, -im)] }
    }
}

proptest! {
    #![proptest_config(run::proptest_config(48))]

    /// Every pole `loop` gives is a root of den + K·num to 1e-9 of the coefficients' terms,
    /// and the stability it states follows from the poles; or the gain is refused as beyond
    /// double precision.
    #[test]
    fn closed_loop_poles_are_roots_of_the_characteristic_polynomial(
        poles in prop::collection::vec(root_set(), 1..4),
        zeros in prop::collection::vec(root_set(), 0..2),
        gain in 0.01f64..100.0,
        log_kp in -3.0f64..40.0,
    ) {
        let poles: Vec<C> = poles.concat();
        let mut zeros: Vec<C> = zeros.concat();
        zeros.truncate(poles.len());
        if zeros.last().is_some_and(|z| z.1 > 0.0) {
            zeros.pop();
        }
        let kp = 10f64.powf(log_kp);
        let (p, z, g, k) = (roots_arg(&poles), roots_arg(&zeros), format!("{gain}"), format!("{kp}"));
        let mut args = vec!["loop", "--poles", &p, "--gain", &g, "--kp", &k, "--json"];
        if !zeros.is_empty() {
            args.extend(["--zeros", &z]);
        }
        let out = degrau(&args);
        if !out.status.success() {
            prop_assert!(stderr(&out).contains("beyond double precision"), "{args:?}: {}", stderr(&out));
            return Ok(());
        }
        let v: Value = serde_json::from_str(&stdout(&out)).expect("one JSON object");
        let characteristic = characteristic(&from_roots(1.0, &poles), &from_roots(gain, &zeros), kp);
        let found = self::poles(&v);
        prop_assert_eq!(found.len(), poles.len());
        for &r in &found {
            let e = relative_residual(&characteristic, r);
            prop_assert!(e <= 1e-9, "{args:?}: pole {r:?}, residual {e:e}");
        }
        // A pole cancelled exactly by a zero does not count; a pole within a few units in
        // the last place of a zero (JSON's digits may not tell them apart) is not judged.
        let cl_zeros: Vec<C> = v["closed_loop"]["zeros"]
            .as_array()
            .unwrap()
            .iter()
            .map(|z| (num(&z[0]), num(&z[1])))
            .collect();
        let near_zero = |r: &C| {
            cl_zeros
                .iter()
                .any(|z| (z.0 - r.0).hypot(z.1 - r.1) <= 1e-14 * re_im_norm(*z))
        };
        if found.iter().any(near_zero) {
            return Ok(());
        }
        let expected = if found.iter().any(|r| r.0 > 0.0) {
            "unstable"
        } else if found.iter().any(|r| r.0 == 0.0) {
            "marginally_stable"
        } else {
            "stable"
        };
        prop_assert_eq!(v["stability"].as_str(), Some(expected), "{:?}", args);
        // Routh–Hurwitz on den + K·num, in 768 bits, says the same where it is clear.
        if let Some(right_half_plane) = routh_unstable_roots(&characteristic) {
            let stated = v["stability"].as_str().unwrap_or_default();
            prop_assert_eq!(
                stated == "unstable",
                right_half_plane > 0,
                "{:?}: Routh counts {} roots in the right half plane",
                args,
                right_half_plane
            );
        }
    }
}

/// The number of roots of p in the right half plane by Routh's array in 768-bit arithmetic
/// (sign changes of its first column), `None` where a first-column entry is 0 or cancels to
/// within 1e-8 of the products it is the difference of (a root near the axis, where the
/// rounding of p's coefficients may decide).
fn routh_unstable_roots(p: &[f64]) -> Option<usize> {
    use astro_float::{BigFloat, RoundingMode};
    const BITS: usize = 768;
    const RM: RoundingMode = RoundingMode::ToEven;
    let big = |x: f64| BigFloat::from_f64(x, BITS);
    let float = |x: &BigFloat| x.to_string().parse::<f64>().unwrap_or(f64::NAN);
    let mut rows: Vec<Vec<BigFloat>> = vec![
        p.iter().step_by(2).map(|&c| big(c)).collect(),
        p.iter().skip(1).step_by(2).map(|&c| big(c)).collect(),
    ];
    let mut firsts: Vec<f64> = rows.iter().map(|row| float(&row[0])).collect();
    while rows.len() < p.len() {
        let (upper, lower) = (&rows[rows.len() - 2], &rows[rows.len() - 1]);
        let lead = lower[0].clone();
        if lead.is_zero() {
            return None;
        }
        let at = |row: &[BigFloat], j: usize| row.get(j).cloned().unwrap_or_else(|| big(0.0));
        let terms = |j: usize| {
            (
                lead.mul(&at(upper, j + 1), BITS, RM),
                upper[0].mul(&at(lower, j + 1), BITS, RM),
            )
        };
        let (a, b) = terms(0);
        let first = a.sub(&b, BITS, RM).div(&lead, BITS, RM);
        let size = (float(&a).abs() + float(&b).abs()) / float(&lead).abs();
        if float(&first).abs() <= 1e-8 * size {
            return None;
        }
        firsts.push(float(&first));
        let next: Vec<BigFloat> = (0..upper.len().saturating_sub(1).max(1))
            .map(|j| {
                let (a, b) = terms(j);
                a.sub(&b, BITS, RM).div(&lead, BITS, RM)
            })
            .collect();
        rows.push(next);
    }
    if firsts.iter().any(|x| x.is_nan() || *x == 0.0) {
        return None;
    }
    Some(
        firsts
            .windows(2)
            .filter(|w| w[0].signum() != w[1].signum())
            .count(),
    )
}

#[test]
fn routh_counts_the_right_half_plane_roots() {
    assert_eq!(routh_unstable_roots(&[1.0, 6.0, 11.0, 6.0]), Some(0));
    assert_eq!(routh_unstable_roots(&[1.0, 7.0, 5e21, 5e22]), Some(2));
    assert_eq!(routh_unstable_roots(&[1.0, -1.0]), Some(1));
    assert_eq!(routh_unstable_roots(&[1.0, 1.0, 1.0, 1.0]), None, "±j");
}

/// The plant of the controller tests: 1/(10s + 1)·e^{−2s}.
const FOPTD: [&str; 6] = ["--num", "1", "--den", "10,1", "--delay", "2"];

fn controller_loop(extra: &[&str]) -> Value {
    json(&[&["loop"], &FOPTD[..], extra, &["--json"]].concat())
}

#[test]
fn a_pi_controller_removes_the_offset_with_the_exact_dead_time() {
    let v = controller_loop(&["--controller", "pi", "--kc", "2.5", "--ti", "10"]);
    assert_eq!(v["exact_delay"], true);
    assert_eq!(v["response"], "setpoint");
    assert_eq!(v["settled"], true);
    let c = &v["controller"];
    assert_eq!(c["action"], "pi");
    assert_eq!(c["form"], "ideal");
    for (key, want) in [
        ("kc", 2.5),
        ("ti", 10.0),
        ("td", 0.0),
        ("n", 10.0),
        ("b", 1.0),
        ("kp", 2.5),
        ("ki", 0.25),
        ("kd", 0.0),
        ("tf", 0.0),
    ] {
        assert!((num(&c[key]) - want).abs() < 1e-15, "{key}: {}", c[key]);
    }
    let m = &v["metrics"];
    assert!((num(&m["final_value"]) - 1.0).abs() < 1e-12, "{m}");
    // Nothing moves before the dead time, and the error integrals exist (integral action).
    assert!(num(&m["peak_time"]) > 2.0, "{m}");
    assert!(num(&m["peak"]) >= 1.0, "{m}");
    assert!(num(&m["overshoot"]) >= 0.0, "{m}");
    assert!(num(&m["settling_time"]) > 2.0, "{m}");
    // IAE ≥ the dead time's share (e = 1 on [0, 2]); ITAE ≥ ∫0² t dt = 2.
    assert!(num(&m["iae"]) > 2.0 && num(&m["itae"]) > 2.0, "{m}");
    assert!(v.get("samples").is_none());
    assert!(
        v.get("approximant").is_none(),
        "no Padé in the controller's loop"
    );
}

#[test]
fn the_at_samples_are_the_loops_values_at_those_instants() {
    use degrau::lti::TransferFunction;
    use degrau::lti::control::{Action, Controller, Horizon, LoopInput, loop_response};
    let times = [0.0, 1.0, 2.0, 2.5, 5.0, 10.0, 30.0, 2000.0];
    let list = times.map(|t| t.to_string()).join(",");
    for (input, key) in [(LoopInput::Setpoint, "setpoint"), (LoopInput::Load, "load")] {
        let v = controller_loop(&[
            "--controller",
            "pid",
            "--kc",
            "3",
            "--ti",
            "8",
            "--td",
            "1",
            "--n",
            "8",
            "--b",
            "0.5",
            "--response",
            key,
            "--at",
            &list,
        ]);
        assert_eq!(v["response"], key);
        let plant = TransferFunction::from_coeffs(&[1.0], &[10.0, 1.0])
            .unwrap()
            .with_delay(2.0)
            .unwrap();
        let c = Controller::new(Action::PID, 3.0, 8.0, 1.0)
            .unwrap()
            .with_filter(8.0)
            .unwrap()
            .with_setpoint_weight(0.5)
            .unwrap();
        let r = loop_response(&plant, &c, input, Horizon::Until(2000.0)).unwrap();
        assert_eq!(numbers(&v["samples"]["t"]), times.to_vec());
        let y = numbers(&v["samples"]["y"]);
        for (t, y) in times.iter().zip(&y) {
            assert!((y - r.value(*t)).abs() < 1e-12, "{key} t = {t}: {y}");
        }
        // Nothing reaches the output before the dead time.
        assert_eq!(y[..3], [0.0, 0.0, 0.0], "{key}");
        let tf = num(&v["controller"]["tf"]);
        assert!((tf - 1.0 / 8.0).abs() < 1e-15);
    }
}

#[test]
fn a_p_controller_leaves_the_offset_k_kc_over_one_plus_k_kc() {
    // K = 1.5, Kc = 2: y(∞) = 3/4; no IAE or ITAE (the error does not vanish).
    let args = [
        "loop",
        "--num",
        "1.5",
        "--den",
        "10,1",
        "--delay",
        "1",
        "--controller",
        "p",
    ];
    for gain in [["--kc", "2"], ["--kp", "2"]] {
        let v = json(&[&args[..], &gain[..], &["--json"]].concat());
        let m = &v["metrics"];
        assert!((num(&m["final_value"]) - 0.75).abs() < 1e-12, "{m}");
        assert_eq!(m["iae"], Value::Null);
        assert_eq!(m["itae"], Value::Null);
        assert_eq!(v["controller"]["ti"], "inf");
        assert_eq!(num(&v["controller"]["kc"]), 2.0);
    }
    let text = stdout(&degrau(&[&args[..], &["--kc", "2"]].concat()));
    assert!(
        text.contains("none: the error does not vanish without integral action"),
        "{text}"
    );
}

#[test]
fn the_load_response_has_a_peak_deviation_and_returns_to_zero() {
    let v = controller_loop(&[
        "--controller",
        "pi",
        "--kc",
        "2.5",
        "--ti",
        "10",
        "--response",
        "load",
    ]);
    let m = &v["metrics"];
    assert!(num(&m["final_value"]).abs() < 1e-12, "{m}");
    let (peak, at) = (num(&m["peak"]), num(&m["peak_time"]));
    // A unit load through 1/(10s + 1) for at least the dead time, before the controller acts.
    assert!(peak > 1.0 - (-0.2f64).exp() && peak < 1.0, "{m}");
    assert!(at > 2.0, "{m}");
}

#[test]
fn the_controllers_text_says_the_dead_time_is_exact_in_both_languages() {
    for (lang, words) in [
        (
            "en",
            [
                "exact dead time (no Padé)",
                "Controller PI",
                "Settling time, 2 % (s)",
                "Settled: yes",
            ],
        ),
        (
            "pt",
            [
                "atraso exato (sem Padé)",
                "Controlador PI",
                "Tempo de acomodação, 2 % (s)",
                "Acomodou: sim",
            ],
        ),
    ] {
        let out = degrau(
            &[
                &["--lang", lang, "loop"],
                &FOPTD[..],
                &[
                    "--controller",
                    "pi",
                    "--kc",
                    "2.5",
                    "--ti",
                    "10",
                    "--at",
                    "3",
                ],
            ]
            .concat(),
        );
        assert!(out.status.success(), "{}", stderr(&out));
        let text = stdout(&out);
        for w in words {
            assert!(text.contains(w), "{lang}: {w}\n{text}");
        }
        assert!(!text.contains("Padé (3, 3)"), "{text}");
    }
}

#[test]
fn a_controller_missing_a_parameter_is_refused_in_both_languages() {
    for (lang, args, words) in [
        (
            "en",
            vec!["--controller", "pi", "--kc", "2"],
            "--controller pi needs --ti (the integral time Ti, s)",
        ),
        (
            "pt",
            vec!["--controller", "pi", "--kc", "2"],
            "--controller pi precisa de --ti (o tempo integral Ti, s)",
        ),
        (
            "en",
            vec!["--controller", "pid", "--kc", "2", "--ti", "3"],
            "needs --td",
        ),
        ("en", vec!["--controller", "p"], "needs --kc"),
        (
            "en",
            vec!["--controller", "p", "--kc", "1", "--ti", "3"],
            "--ti is for a controller that has that action (pi, pid)",
        ),
        (
            "en",
            vec!["--controller", "pi", "--kc", "1", "--ti", "-3"],
            "the integral time Ti must be a positive number of seconds",
        ),
        (
            "pt",
            vec!["--controller", "pi", "--kc", "1", "--ti", "3", "--b", "2"],
            "o peso da referência b deve estar entre 0 e 1",
        ),
        (
            "en",
            vec![
                "--controller",
                "pi",
                "--kc",
                "1",
                "--ti",
                "3",
                "--at",
                "1,-2",
            ],
            "--at: each instant must be 0 or a positive number of seconds, not -2",
        ),
    ] {
        let out = degrau(&[&["--lang", lang, "loop"], &FOPTD[..], &args[..]].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(stderr(&out).contains(words), "{args:?}: {}", stderr(&out));
    }
    // Flags of the controller without it, and --kc with --kp, are clap's refusals.
    for args in [
        vec!["--kc", "2"],
        vec!["--ti", "2"],
        vec!["--controller", "p", "--kc", "2", "--kp", "2"],
        vec!["--controller", "p", "--kc", "2", "--pade", "1,1"],
    ] {
        let out = degrau(&[&["loop"], &FOPTD[..], &args[..]].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
}

#[test]
fn the_controllers_loop_says_whether_it_is_stable_and_its_ms() {
    // 1/(10s + 1)·e^{−2s}: P control is stable below Kcr = 8.5024, exactly.
    let v = controller_loop(&["--controller", "p", "--kc", "8.4"]);
    assert_eq!(v["unstable_roots"], 0);
    let ms = num(&v["ms"]);
    // Near the ultimate gain L(jωcr) ≈ −8.4/8.5024: Ms ≥ 1/(1 − 8.4/8.5024) ≈ 83.
    assert!(ms > 80.0, "{ms}");
    let v = controller_loop(&["--controller", "p", "--kc", "8.6"]);
    assert_eq!(v["unstable_roots"], 2);
    assert!(v["ms"].is_null());
    let out = degrau(&[
        "--lang",
        "pt",
        "loop",
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
    ]);
    assert!(
        stdout(&out).contains("Malha fechada: estável"),
        "{}",
        stdout(&out)
    );
}
