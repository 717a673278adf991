//! Runs the `degrau` binary as a user would: `degrau step` with flags, `--json`, `--batch`
//! on stdin, and bad input. Known answers come from the course notes and closed forms.

use std::io::Write;
use std::process::{Command, Output, Stdio};

use serde_json::Value;

const NOTES_POLES: &str = "-1+2j,-1-2j,-5";

/// The step's metrics in `--json`: a number each for a stable system, null for one that
/// has none (an integrator's).
const METRICS: [&str; 10] = [
    "rise_time",
    "settling_time",
    "peak",
    "peak_time",
    "overshoot",
    "undershoot",
    "steady_state",
    "settling_min",
    "settling_max",
    "dc_gain",
];

fn degrau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(args)
        .output()
        .expect("the degrau binary runs")
}

fn degrau_with_stdin(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the degrau binary runs");
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(stdin.as_bytes())
        .expect("stdin accepts the batch");
    child
        .wait_with_output()
        .expect("the degrau binary finishes")
}

fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("stdout is UTF-8")
}

fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("stderr is UTF-8")
}

/// `degrau step <args> --json`, checked to succeed with exactly one JSON object.
fn step_json(args: &[&str]) -> Value {
    let mut all = vec!["step"];
    all.extend_from_slice(args);
    all.push("--json");
    let output = degrau(&all);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    let text = stdout(&output);
    assert_eq!(text.trim().lines().count(), 1, "one JSON line: {text}");
    serde_json::from_str(&text).expect("stdout is JSON")
}

fn number(report: &Value, key: &str) -> f64 {
    report[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is a number in {report}"))
}

#[test]
fn the_notes_third_order_example() {
    let report = step_json(&["--poles", NOTES_POLES, "--gain", "0.5", "--amplitude", "2"]);
    assert!((number(&report, "steady_state") - 0.04).abs() < 1e-15);
    assert!((number(&report, "dc_gain") - 0.02).abs() < 1e-15);
    assert_eq!(
        report["expression"],
        "y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100"
    );
    assert_eq!(
        report["poles"],
        serde_json::json!([[-1.0, 2.0], [-1.0, -2.0], [-5.0, 0.0]])
    );
    assert_eq!(report["zeros"], serde_json::json!([]));
    assert_eq!(report["den"], serde_json::json!([1.0, 7.0, 15.0, 25.0]));
}

#[test]
fn every_stable_key_is_present() {
    let report = step_json(&["--num", "0.5", "--den", "1,7,15,25"]);
    for key in METRICS.into_iter().chain(["poles", "zeros", "expression"]) {
        assert!(report.get(key).is_some(), "missing {key} in {report}");
    }
    assert!(report.get("samples").is_none());
}

#[test]
fn first_order_metrics_are_exact() {
    let report = step_json(&["--num", "5", "--den", "1,5"]);
    assert!((number(&report, "rise_time") - 9f64.ln() / 5.0).abs() < 1e-12);
    assert!((number(&report, "settling_time") - 50f64.ln() / 5.0).abs() < 1e-12);
    assert_eq!(report["overshoot"], 0.0);
    assert_eq!(report["peak"], 1.0);
    assert_eq!(report["peak_time"], Value::Null);
}

#[test]
fn an_integrator_has_no_metrics_and_no_dc_gain() {
    let report = step_json(&["--num", "1", "--den", "1,1,0"]);
    for key in METRICS {
        assert_eq!(report[key], Value::Null, "{key} in {report}");
    }
    assert_eq!(report["behaviour"], "integrating");
    assert_eq!(report["expression"], "y(t) = −1 + t + e^{−t}");
}

#[test]
fn samples_cover_the_response_from_zero() {
    let report = step_json(&["--poles", NOTES_POLES, "--gain", "0.5", "--samples", "101"]);
    let t = report["samples"]["t"].as_array().expect("t is an array");
    let y = report["samples"]["y"].as_array().expect("y is an array");
    assert_eq!((t.len(), y.len()), (101, 101));
    assert_eq!((&t[0], &y[0]), (&Value::from(0.0), &Value::from(0.0)));
    // y(t_end) is near the final value 0.02: the horizon covers the transient.
    let last = y[100].as_f64().expect("y is numbers");
    assert!((last - 0.02).abs() < 0.02 * 0.02, "{last}");
}

#[test]
fn batch_answers_every_line_in_order() {
    let input = concat!(
        r#"{"id": "first", "num": [5], "den": [1, 5]}"#,
        "\n",
        r#"{"id": 2, "zeros": [[-1, 0], [-2, 0]], "poles": [[-1, 0]]}"#,
        "\n\n",
        r#"{"zeros": [], "poles": [[-1, 2], [-1, -2], [-5, 0]], "gain": 0.5, "amplitude": 2, "id": {"k": 3}}"#,
        "\n",
    );
    let output = degrau_with_stdin(&["step", "--batch"], input);
    assert!(output.status.success(), "{}", stderr(&output));
    let replies: Vec<Value> = stdout(&output)
        .lines()
        .map(|l| serde_json::from_str(l).expect("each line is JSON"))
        .collect();
    assert_eq!(replies.len(), 3, "the blank line is skipped");
    assert_eq!(replies[0]["id"], "first");
    assert!((number(&replies[0], "rise_time") - 9f64.ln() / 5.0).abs() < 1e-12);
    assert_eq!(replies[1]["id"], 2);
    assert!(
        replies[1]["error"]
            .as_str()
            .is_some_and(|e| e.contains("improper")),
        "{}",
        replies[1]
    );
    assert!(replies[1].get("rise_time").is_none());
    assert_eq!(replies[2]["id"], serde_json::json!({"k": 3}));
    assert_eq!(replies[2]["line"], 4);
    assert!((number(&replies[2], "steady_state") - 0.04).abs() < 1e-15);
}

/// A program that writes one line and waits for its reply gets it while stdin stays open.
#[test]
fn batch_answers_a_line_before_the_next_is_written() {
    use std::io::{BufRead, BufReader};
    use std::sync::mpsc;
    use std::time::Duration;

    let mut child = Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(["step", "--batch"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("the degrau binary runs");
    let mut stdin = child.stdin.take().expect("stdin is piped");
    let stdout = BufReader::new(child.stdout.take().expect("stdout is piped"));
    let (lines, replies) = mpsc::channel();
    std::thread::spawn(move || {
        for line in stdout.lines().map_while(Result::ok) {
            if lines.send(line).is_err() {
                break;
            }
        }
    });
    for (id, pole) in [(1, 5.0), (2, 0.5)] {
        writeln!(stdin, r#"{{"id": {id}, "poles": [[-{pole}, 0]]}}"#).expect("a line is sent");
        stdin.flush().expect("the line leaves");
        let reply = replies
            .recv_timeout(Duration::from_secs(20))
            .expect("the reply comes while stdin is still open");
        let reply: Value = serde_json::from_str(&reply).expect("the reply is JSON");
        assert_eq!(reply["id"], id);
        assert!((number(&reply, "rise_time") - 9f64.ln() / pole).abs() < 1e-12);
    }
    drop(stdin);
    assert!(child.wait().expect("degrau ends").success());
}

#[test]
fn json_and_batch_give_the_same_report() {
    let single = step_json(&["--poles", NOTES_POLES, "--zeros", "-10", "--gain", "0.5"]);
    let output = degrau_with_stdin(
        &["step", "--batch"],
        r#"{"poles": [[-1, 2], [-1, -2], [-5, 0]], "zeros": [[-10, 0]], "gain": 0.5}"#,
    );
    let mut batch: Value = serde_json::from_str(&stdout(&output)).expect("batch line is JSON");
    let object = batch.as_object_mut().expect("an object");
    assert_eq!(object.remove("id"), Some(Value::Null));
    assert_eq!(object.remove("line"), Some(Value::from(1)));
    assert_eq!(batch, single);
}

#[test]
fn human_output_names_every_metric() {
    let output = degrau(&[
        "step",
        "--poles",
        NOTES_POLES,
        "--gain",
        "0.5",
        "--amplitude",
        "2",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    for words in [
        "Rise time",
        "Settling time",
        "Overshoot",
        "Undershoot",
        "Peak",
        "Peak time",
        "Steady state",
        "Settling min",
        "Settling max",
        "s^3 + 7 s^2 + 15 s + 25",
        "y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100",
        "y(t) = 1/25 − (1/20)e^{−t} sin(2t + 36.87°) − e^{−5t}/100",
    ] {
        assert!(text.contains(words), "missing {words:?} in\n{text}");
    }
}

#[test]
fn human_output_says_why_a_metric_is_missing() {
    let output = degrau(&["step", "--num", "1", "--den", "1,1,0"]);
    let text = stdout(&output);
    assert!(
        text.contains("Settling time  none: does not settle: it ramps (integrator)"),
        "{text}"
    );
    let output = degrau(&["step", "--num", "5", "--den", "1,5"]);
    assert!(
        stdout(&output).contains("Peak time      none: monotone, the peak is the final value"),
        "{}",
        stdout(&output)
    );
}

#[test]
fn an_improper_system_exits_2_with_a_message() {
    let output = degrau(&["step", "--num", "1,0,0", "--den", "1,1"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stdout(&output).is_empty());
    let message = stderr(&output);
    assert!(message.contains("improper"), "{message}");
    assert!(!message.contains("panicked"), "{message}");
}

#[test]
fn bad_input_is_refused_in_plain_words() {
    let cases: [(&[&str], &str); 6] = [
        (
            &["--poles", "-1+2j,-1+xj"],
            r#"--poles: item 2 ("-1+xj") is not a number like -1+2j"#,
        ),
        (
            &["--poles", "-1", "--samples", "1"],
            "samples must be between 2",
        ),
        (
            &["--poles", "-1", "--rise-limits", "0.9,0.1"],
            "rise limits",
        ),
        (&["--num", "1", "--den", "0,0"], "denominator is zero"),
        (
            &["--poles", "-1", "--gain", "1", "--dc-gain", "2"],
            "cannot be used with",
        ),
        (&["--poles", "-1", "--delay", "nan"], "delay"),
    ];
    for (args, words) in cases {
        let mut all = vec!["step"];
        all.extend_from_slice(args);
        let output = degrau(&all);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let message = stderr(&output);
        assert!(message.contains(words), "{args:?}: {message}");
        assert!(!message.contains("panicked"), "{args:?}: {message}");
    }
}
