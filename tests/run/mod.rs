//! Running the `degrau` binary from a test: its output, its standard output and error as
//! text, its JSON (shared by the command-line tests and the app's, which compare the window
//! with the CLI).
#![allow(dead_code)] // each test binary uses its own subset

use std::process::{Command, Output};

/// y = 50 + 2·(1 − e^{−(t−2)/5}) after a unit step at t = 2 s, Ts = 0.5 s.
pub const STEP: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/first_order_step.csv"
);

/// The notes' LECI step test (no input column: t0 = 5 s, Δu = 10, y0 = 50).
pub const LECI: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/leci_step.csv");

/// A TCLab heater step (Q1 to 50 %; columns T1 and Q1).
pub const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

/// `degrau args…`, run to the end.
pub fn degrau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(args)
        .output()
        .expect("the degrau binary runs")
}

/// The standard output as text.
pub fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The standard error as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// `degrau args…` that must succeed (its standard error said if not): its standard output,
/// which must be UTF-8.
pub fn succeeds(args: &[&str]) -> String {
    let out = degrau(args);
    assert!(out.status.success(), "{}", stderr(&out));
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// `degrau args…` that must succeed, its standard output read as one JSON object.
pub fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&succeeds(args)).expect("one JSON object")
}

/// `degrau command args… --json` that must succeed, its standard output read as one JSON
/// object.
pub fn command_json(command: &str, args: &[&str]) -> serde_json::Value {
    json(&[&[command], args, &["--json"]].concat())
}

/// A proptest configuration with a fixed seed, so that every run checks the same cases;
/// `DEGRAU_PROPTEST_SCALE` multiplies the count and `DEGRAU_PROPTEST_SEED` changes the seed
/// for a deeper search (as in `tests/lti_properties.rs`).
pub fn proptest_config(cases: u32) -> proptest::test_runner::Config {
    let env = |name: &str| std::env::var(name).ok().and_then(|v| v.parse::<u64>().ok());
    let scale = env("DEGRAU_PROPTEST_SCALE").unwrap_or(1) as u32;
    proptest::test_runner::Config {
        cases: cases.saturating_mul(scale.max(1)),
        rng_seed: proptest::test_runner::RngSeed::Fixed(
            env("DEGRAU_PROPTEST_SEED").unwrap_or(0x00de_9a00),
        ),
        failure_persistence: None,
        ..proptest::test_runner::Config::default()
    }
}

/// [`STEP`] (the notes' first-order step test) with u and y multiplied by `k`, written as
/// `{name}_{k}.csv` in the tests' temporary directory; its path. Written whole to a file of
/// this thread's, then renamed into place: tests run at once, and a test reading the file
/// while another rewrote it read it cut short (`cli_hand` failed now and then).
pub fn scaled_step(name: &str, k: f64) -> String {
    let mut out = String::new();
    for line in std::fs::read_to_string(STEP).unwrap().lines() {
        let cells: Vec<&str> = line.split(',').collect();
        if let (&[t, u, y], false) = (&cells[..], line.starts_with('#')) {
            match (u.parse::<f64>(), y.parse::<f64>()) {
                (Ok(u), Ok(y)) => out.push_str(&format!("{t},{:e},{:e}\n", u * k, y * k)),
                _ => out.push_str(&format!("{line}\n")),
            }
        }
    }
    let path = format!("{}/{name}_{k:e}.csv", env!("CARGO_TARGET_TMPDIR"));
    let own = format!(
        "{path}.{}.{:?}.part",
        std::process::id(),
        std::thread::current().id()
    );
    std::fs::write(&own, out).unwrap();
    std::fs::rename(&own, &path).unwrap();
    path
}
