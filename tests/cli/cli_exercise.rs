//! `degrau exercise`: `make` twice with one seed writes byte-identical records and key, the
//! records carry only `t,u,y` and `degrau diagnose` finds in one what the key says; `check`
//! grades a class of 30 answer rows with typos, missing rows and a wrong record name,
//! reports each bad row by its line (English, Portuguese, JSON), and refuses an unreadable
//! key or answers file with exit code 2.

use std::path::{Path, PathBuf};

use crate::run;

use run::{degrau, json, stderr, stdout, succeeds};
use serde_json::Value;

/// A fresh folder for this test under Cargo's temporary directory.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("exercise_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn make(seed: &str, count: &str, level: &str, out: &Path) {
    let out = out.to_string_lossy();
    succeeds(&[
        "exercise", "make", "--seed", seed, "--count", count, "--level", level, "--out", &out,
    ]);
}

fn key(dir: &Path) -> Value {
    let text = std::fs::read_to_string(dir.join("key.json")).expect("key.json written");
    serde_json::from_str(&text).expect("the key is JSON")
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("the folder")
        .map(|e| {
            let p = e.expect("an entry").path();
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&p).expect("a file"))
        })
        .collect();
    out.sort();
    out
}

#[test]
fn make_twice_with_one_seed_writes_the_same_bytes_and_a_key_the_records_do_not_reveal() {
    let (a, b) = (folder("a"), folder("b"));
    make("41", "3", "moderate", &a);
    make("41", "3", "moderate", &b);
    let (fa, fb) = (files(&a), files(&b));
    let names: Vec<&str> = fa.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "key.json",
            "record_01.csv",
            "record_02.csv",
            "record_03.csv"
        ]
    );
    assert_eq!(fa, fb, "the same seed must give byte-identical files");
    let k = key(&a);
    assert_eq!(k["generator_version"], 3);
    assert_eq!(k["seed"], 41);
    assert_eq!(k["level"], "moderate");
    let records = k["records"].as_array().expect("records");
    assert_eq!(records.len(), 3);
    for r in records {
        for field in ["file", "causes", "structure", "kp", "kp_tolerance"] {
            assert!(r.get(field).is_some(), "no {field} in {r}");
        }
        assert!(!r["causes"].as_array().unwrap().is_empty());
    }
    for (name, bytes) in &fa[1..] {
        let text = String::from_utf8(bytes.clone()).expect("UTF-8");
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,u,y"), "{name}: only t,u,y");
        assert!(
            lines.all(|l| l.split(',').all(|f| f.parse::<f64>().is_ok())),
            "{name}: numbers only, no metadata"
        );
    }
    // Another seed, other records.
    let c = folder("c");
    make("42", "1", "moderate", &c);
    assert_ne!(files(&c)[1].1, fa[1].1);
    // `degrau diagnose` finds in the first record what the key says.
    let path = a.join("record_01.csv");
    let report = json(&["diagnose", &path.to_string_lossy(), "--json"]);
    let first = report["steps"]
        .as_array()
        .and_then(|s| s.first())
        .map_or("none".to_string(), |s| {
            s["cause"].as_str().unwrap().to_string()
        });
    let causes: Vec<&str> = records[0]["causes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert!(
        causes.contains(&first.as_str()) || (first == "none" && causes == ["outliers"]),
        "diagnose named {first}, the key says {causes:?}"
    );
    assert_eq!(report["final"]["model"], records[0]["structure"]);
    for d in [a, b, c] {
        let _ = std::fs::remove_dir_all(d);
    }
}

/// A class of 10 students × 3 records = 30 rows: six bad ones and two left out.
fn class(k: &Value) -> (String, Vec<usize>) {
    let records = k["records"].as_array().unwrap();
    let mut text = String::from("student,file,cause,structure,kp\n");
    let mut bad_lines = Vec::new();
    let mut line = 1;
    for s in 0..10 {
        for (i, r) in records.iter().enumerate() {
            let file = r["file"].as_str().unwrap();
            let cause = r["causes"][0].as_str().unwrap();
            let structure = r["structure"].as_str().unwrap();
            let kp = r["kp"].as_f64().unwrap();
            let row = match (s, i) {
                // Missing rows: student 9 skipped two records.
                (9, 1) | (9, 2) => continue,
                (1, 0) => Some(format!("s1,{file},{cause},{structure},{kp}x")),
                (2, 1) => Some(format!("s2,{file},{cause},{structure}")),
                (3, 2) => Some(format!("s3,record_99.csv,{cause},{structure},{kp}")),
                (4, 0) => Some(format!("s4,{file},,{structure},{kp}")),
                (5, 1) => Some(format!("s5,{file},zero,P9,{}", 3.0 * kp)),
                _ => None,
            };
            line += 1;
            match row {
                Some(r) => {
                    if s != 5 {
                        bad_lines.push(line);
                    }
                    text += &r;
                }
                None => text += &format!("s{s},{file},{cause},{structure},{kp}"),
            }
            text.push('\n');
        }
    }
    // A duplicate of s0's first answer, and a row with a gain typed with a comma.
    let first = records[0]["file"].as_str().unwrap();
    for extra in [
        format!("s0,{first},none,P1,1"),
        format!("s8,{first},none,P1,1,5"),
    ] {
        line += 1;
        bad_lines.push(line);
        text += &extra;
        text.push('\n');
    }
    (text, bad_lines)
}

#[test]
fn check_grades_a_class_and_reports_each_bad_row_by_line() {
    let dir = folder("class");
    make("7", "3", "clear", &dir);
    let k = key(&dir);
    let (answers, bad_lines) = class(&k);
    assert_eq!(answers.lines().count() - 1, 30, "30 answer rows");
    let path = dir.join("class.csv");
    std::fs::write(&path, &answers).unwrap();
    let (key_path, answers_path) = (
        dir.join("key.json").to_string_lossy().into_owned(),
        path.to_string_lossy().into_owned(),
    );
    let args = [
        "exercise",
        "check",
        "--key",
        &key_path,
        "--answers",
        &answers_path,
    ];
    let v = json(&[&args[..], &["--json"]].concat());
    for field in [
        "records", "rows", "graded", "students", "causes", "bad_rows",
    ] {
        assert!(v.get(field).is_some(), "no {field} in the JSON");
    }
    assert_eq!(v["records"], 3);
    assert_eq!(v["rows"], 30);
    let lines: Vec<u64> = v["bad_rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["line"].as_u64().unwrap())
        .collect();
    let expected: Vec<u64> = bad_lines.iter().map(|&l| l as u64).collect();
    assert_eq!(lines, expected, "{}", v["bad_rows"]);
    let problems: Vec<&str> = v["bad_rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["problem"].as_str().unwrap())
        .collect();
    assert_eq!(
        problems,
        [
            "kp_not_a_number",
            "field_count",
            "unknown_file",
            "empty_field",
            "duplicate",
            "field_count"
        ]
    );
    assert_eq!(v["graded"], 30 - 6);
    let students = v["students"].as_array().unwrap();
    assert_eq!(students.len(), 10);
    let of = |name: &str| {
        students
            .iter()
            .find(|s| s["student"] == name)
            .unwrap_or_else(|| panic!("no {name}"))
    };
    // s0 answered the key: all right.
    let s0 = of("s0");
    assert_eq!(
        (s0["cause_right"].as_u64(), s0["kp_right"].as_u64()),
        (Some(3), Some(3))
    );
    assert_eq!(s0["structure_right"], 3);
    // s5's second answer is wrong on every part.
    let wrong = &of("s5")["answers"][1];
    assert_eq!(
        (&wrong["cause"], &wrong["structure"], &wrong["kp"]),
        (
            &Value::Bool(
                k["records"][1]["causes"]
                    .as_array()
                    .unwrap()
                    .contains(&"zero".into())
            ),
            &Value::Bool(false),
            &Value::Bool(false)
        )
    );
    // s9 left two records out.
    assert_eq!(of("s9")["missing"].as_array().unwrap().len(), 2);
    let per_cause: u64 = v["causes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["answers"].as_u64().unwrap())
        .sum();
    assert_eq!(per_cause, 24);

    // The text says each bad row by its line, in both languages.
    let en = succeeds(&args);
    let pt = succeeds(&[&["--lang", "pt"], &args[..]].concat());
    for l in &bad_lines {
        assert!(en.contains(&format!("line {l}:")), "line {l} in:\n{en}");
        assert!(pt.contains(&format!("linha {l}:")), "linha {l} em:\n{pt}");
    }
    assert!(
        en.contains("is not a number") && en.contains("not in the key"),
        "{en}"
    );
    assert!(
        pt.contains("Por causa:") && pt.contains("sem resposta"),
        "{pt}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn an_unreadable_key_or_answers_file_is_exit_code_2() {
    let dir = folder("bad");
    std::fs::create_dir_all(&dir).unwrap();
    let not_json = dir.join("key.json");
    std::fs::write(&not_json, "{ not json").unwrap();
    let answers = dir.join("answers.csv");
    std::fs::write(&answers, "student,file\ns0,record_01.csv\n").unwrap();
    let key = r#"{"generator_version":1,"seed":1,"level":"clear","records":[]}"#;
    let good_key = dir.join("good.json");
    std::fs::write(&good_key, key).unwrap();
    let s = |p: &Path| p.to_string_lossy().into_owned();
    for (k, a, words) in [
        (s(&dir.join("missing.json")), s(&answers), "cannot read"),
        (s(&not_json), s(&answers), "is not an exercise key"),
        (
            s(&good_key),
            s(&answers),
            "lacks the columns cause, structure, kp",
        ),
        (s(&good_key), s(&dir.join("none.csv")), "cannot read"),
    ] {
        let out = degrau(&["exercise", "check", "--key", &k, "--answers", &a]);
        assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
        assert!(stderr(&out).contains(words), "{}", stderr(&out));
        assert!(stdout(&out).is_empty());
    }
    let _ = std::fs::remove_dir_all(dir);
}
