//! Issue 22, item 18: `degrau step --batch` on 2,000 random systems of orders 1–8 (the fixed
//! systems of `benches/systems`), as a whole process, beside python-control's `step_info`
//! on the same systems in the same run.
//!
//! - **process**: the release binary reading the 2,000 lines on stdin and writing the
//!   2,000 replies (best of 7; target ≤ 50 ms);
//! - **in process**: the metrics alone (`StepResponse::new` + `analyse`), and the whole
//!   batch path (`cli::run_batch`: parsing, metrics, closed forms, JSON), per system (best
//!   of 7);
//! - **python-control**: `step_info` per system (`benches/step_info_control.py`, when
//!   python3 with python-control is there) and its ratio to the whole process per system
//!   (target ≥ 200).
//!
//! Run: `cargo bench --bench batch`. Plain timing (`Instant`), not criterion: the figure is
//! one process of tens of milliseconds, and the ratio is what is read. The per-system
//! metrics in criterion are `cargo bench --bench step -- random`.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use degrau::lti::{StepInfoOptions, StepResponse, analyse};

mod systems;
mod timing;
use timing::best_of;

/// One run of `degrau step --batch` on `input`: the number of reply lines.
fn run_process(input: &Path) -> usize {
    let output = Command::new(env!("CARGO_BIN_EXE_degrau"))
        .args(["step", "--batch"])
        .stdin(std::fs::File::open(input).expect("the batch input"))
        .stderr(Stdio::inherit())
        .output()
        .expect("degrau runs");
    assert!(output.status.success(), "degrau step --batch failed");
    output.stdout.iter().filter(|&&b| b == b'\n').count()
}

/// python-control's step_info per system (seconds) and the systems it failed on, when it
/// is installed.
fn python_control(input: &Path) -> Option<(f64, usize)> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/step_info_control.py");
    let output = Command::new("python3")
        .arg(script)
        .arg(input)
        .stderr(Stdio::null())
        .output()
        .ok()?;
    let text = String::from_utf8(output.stdout).ok()?;
    let mut fields = text.split_whitespace();
    let seconds = fields.next()?.parse().ok()?;
    let failed = fields.nth(1)?.parse().ok()?;
    Some((seconds, failed))
}

fn main() {
    let systems = systems::systems();
    let count = systems.len();
    let input = Path::new(env!("CARGO_TARGET_TMPDIR")).join("batch_2000.jsonl");
    std::fs::File::create(&input)
        .and_then(|mut f| f.write_all(systems::batch_input(&systems).as_bytes()))
        .expect("the batch input is written");
    assert_eq!(run_process(&input), count, "one reply per system");

    let process = best_of(7, || run_process(&input));
    let options = StepInfoOptions::default();
    let metrics = best_of(7, || {
        systems
            .iter()
            .map(|s| {
                let response = StepResponse::new(&s.tf, 1.0).expect("a response");
                analyse(&response, &options).horizon
            })
            .sum::<f64>()
    });
    let text = systems::batch_input(&systems);
    let batch = best_of(7, || {
        let mut out = Vec::with_capacity(8 << 20);
        degrau::cli::run_batch(text.as_bytes(), &mut out, &options).expect("the batch runs");
        out.len()
    });
    let per = |seconds: f64| 1e6 * seconds / count as f64;
    eprintln!("{count} systems of orders 1–8 ({})", input.display());
    eprintln!(
        "whole process: {:.1} ms ({:.1} µs per system; target ≤ 50 ms)",
        1e3 * process,
        per(process)
    );
    eprintln!(
        "in process: metrics {:.1} µs, whole batch path {:.1} µs per system",
        per(metrics),
        per(batch)
    );
    match python_control(&input) {
        Some((python, failed)) => eprintln!(
            "python-control step_info: {:.2} ms per system ({failed} raised an error); ratio \
             to the whole process {:.0}× (target ≥ 200×)",
            1e3 * python,
            python * count as f64 / process
        ),
        None => eprintln!("python-control: absent (python3 -c 'import control' fails)"),
    }
}
