//! Test data shared by the benches: a simulated step test with deterministic noise.

use degrau::ident::fit::FitData;
use degrau::ident::model::excitation::Excitation;
use degrau::ident::model::{Model, Structure, Values};

/// The model `code` at `truth` (in the order of its parameters, `Structure::params`: Kp,
/// the time constants, Td, Y0) driven by `input` at `times`, plus uniform noise of
/// peak-to-peak `noise` from the workspace's generator seeded with `seed`.
fn simulated(
    code: &str,
    truth: &[f64],
    input: Excitation,
    times: Vec<f64>,
    noise: f64,
    seed: u64,
) -> FitData {
    let s = Structure::parse(code).expect("a valid code");
    let params = s.params();
    assert_eq!(params.len(), truth.len(), "{code}: {params:?}");
    let mut y = Model::new(s, Values::default().with_vector(&params, truth))
        .simulate(&input, &times)
        .expect("a valid model");
    let mut rng = degrau::ident::random::Lcg(seed);
    for v in y.iter_mut() {
        *v += noise * (rng.unit() - 0.5);
    }
    FitData { times, y, input }
}

/// 800 samples (Ts = 0.25 s) of the model `code` with `truth` (its parameters in order),
/// plus uniform noise of peak-to-peak `noise` from a small LCG seeded with `seed`.
#[allow(dead_code)]
pub fn noisy_800(code: &str, truth: &[f64], setup: Excitation, noise: f64, seed: u64) -> FitData {
    let times: Vec<f64> = (0..800).map(|k| 0.25 * k as f64).collect();
    simulated(code, truth, setup, times, noise, seed)
}

/// The logger record's true process, a P1D: Kp, Tp1, Td, Y0.
#[allow(dead_code)]
pub const LOGGER_TRUTH: [f64; 4] = [1.5, 4.0, 0.75, 30.0];

/// The level at `t` of an input that starts at `first` and moves to each `(instant, level)`
/// of `changes` (in time order) at its instant.
fn level_at(first: f64, changes: &[(f64, f64)], t: f64) -> f64 {
    changes
        .iter()
        .rev()
        .find(|&&(at, _)| at <= t)
        .map_or(first, |&(_, level)| level)
}

/// A 1 kHz logger for 80 s (80,000 samples): a measured input that steps 2 → 4 → 1 → 3.5 →
/// 2.5 (at 5, 25, 45 and 62 s) into the P1D of [`LOGGER_TRUTH`], with ±0.02 uniform noise
/// (about 1 % of the effect of a step).
#[allow(dead_code)]
pub fn logger_80k() -> FitData {
    use degrau::ident::model::excitation::Hold;
    let times: Vec<f64> = (0..80_000).map(|k| 1e-3 * k as f64).collect();
    let levels = [(5.0, 4.0), (25.0, 1.0), (45.0, 3.5), (62.0, 2.5)];
    let u: Vec<f64> = times.iter().map(|&t| level_at(2.0, &levels, t)).collect();
    let input = Excitation::measured(&times, &u, None, Hold::Zoh).expect("an input that steps");
    simulated("P1D", &LOGGER_TRUTH, input, times, 0.04, 2026)
}

/// The input column of a record driven by its measured input, rebuilt from its steps.
#[allow(dead_code)]
pub fn input_column(data: &FitData) -> Vec<f64> {
    data.times
        .iter()
        .map(|&t| data.input.u0 + data.input.deviation_at(t))
        .collect()
}

/// scipy's `least_squares` (one start, in-process) on `data` from `guess` (Kp, Tp1, Td,
/// Y0), by `benches/scipy_p1d.py` on a CSV written under target/: its seconds and its
/// parameters, or `None` when python3 with numpy and scipy is not there.
#[allow(dead_code)]
pub fn scipy_p1d(data: &FitData, guess: [f64; 4]) -> Option<(f64, String)> {
    use std::fmt::Write as _;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target");
    let path = dir.join("bench_p1d_record.csv");
    let mut text = String::from("t,u,y\n");
    for ((t, u), y) in data.times.iter().zip(input_column(data)).zip(&data.y) {
        let _ = writeln!(text, "{t},{u},{y}");
    }
    std::fs::write(&path, text).ok()?;
    let script = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/scipy_p1d.py");
    let mut command = std::process::Command::new("python3");
    command.arg(script).arg(&path);
    command.args(guess.iter().map(|g| g.to_string()));
    let output = command.output().ok()?;
    if !output.status.success() {
        eprintln!(
            "scipy comparison skipped: {}",
            String::from_utf8_lossy(&output.stderr).trim()
        );
        return None;
    }
    let text = String::from_utf8_lossy(&output.stdout).into_owned();
    let seconds = text
        .lines()
        .find_map(|l| l.strip_prefix("seconds ")?.trim().parse().ok())?;
    Some((seconds, text))
}

/// The extruder record of `../shared/data/real`, when present.
#[allow(dead_code)]
pub fn extruder_path() -> Option<std::path::PathBuf> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/real/felypemaciel_temp_control_serial_output.csv");
    path.exists().then_some(path)
}

/// The extruder record loaded and prepared as the CLI does with `--time Timestamp --output
/// Data --input entrada` (driven by its measured input): its samples, the structure `code`
/// and the automatic guess; a message when it cannot be read.
#[allow(dead_code)]
pub fn extruder(
    path: &std::path::Path,
    code: &str,
) -> Result<(FitData, Structure, Values), String> {
    use degrau::ident::experiment::Experiment;
    use degrau::ident::record::data::{LoadOptions, load_file};
    let options = LoadOptions::from_text("Timestamp", "Data", "entrada", None, 0);
    let test = load_file(path, &options).map_err(|e| e.to_string())?;
    let experiment = Experiment::new(&test, None, None, None).map_err(|e| e.to_string())?;
    let data = experiment.fit_data(&test).map_err(|e| e.to_string())?;
    let s = experiment
        .structure(code, false, &data)
        .map_err(|e| e.to_string())?;
    let guess = experiment.guess(s, &data);
    Ok((data, s, guess))
}

/// [`extruder`] on the extruder record of `../shared/data/real` with the structure `code`,
/// or `None` (said on stderr) when it is absent or cannot be read.
#[allow(dead_code)]
pub fn extruder_or_skip(code: &str) -> Option<(FitData, Structure, Values)> {
    let Some(path) = extruder_path() else {
        eprintln!("extruder record absent: skipped");
        return None;
    };
    extruder(&path, code)
        .map_err(|e| eprintln!("extruder record unreadable ({e}): skipped"))
        .ok()
}
