//! `degrau fit FILE --model CODE …`: fits a process model to a measured step test, headless.
//! The data flags ([`DataArgs`]) are shared with `degrau diagnose`; the FIT JSON object
//! ([`FitJson`]) is the one graders read, in `fit` and inside `diagnose`.

use std::collections::BTreeMap;
use std::io::{self, Write};
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use serde::Serialize;

use crate::ident::diagnose::per_step::{MAX_PER_STEP, StepFit, per_step_fits};
use crate::ident::experiment::{Drive, Experiment, ExperimentError, Offset, OperatingPoint};
use crate::ident::fit::{FitData, FitOptions, FitReport, Method};
use crate::ident::model::excitation::{Excitation, Hold};
use crate::ident::model::{Param, Structure};
use crate::ident::record::data::{self, LoadOptions, StepTest};
use crate::text::{Lang, Localize};

use super::{CliError, finite_f64};

pub use crate::ident::fit::MAX_STARTS;

/// Which columns of the file are time, output and input, and where the input is when it
/// was logged to a file of its own (shared by `fit`, `diagnose` and `open`).
#[derive(Debug, Clone, Default, Args)]
pub struct ColumnArgs {
    /// Time column: name or 1-based position (default: recognised by name).
    #[arg(long)]
    pub time_col: Option<String>,
    /// Output column: name or 1-based position.
    #[arg(long)]
    pub y_col: Option<String>,
    /// Input column: name or 1-based position (in --u-file when one is given).
    #[arg(long)]
    pub u_col: Option<String>,
    /// The input in a second file (its own time and input columns, its own grid), joined
    /// on time: each sample takes the input's last value logged at or before it.
    #[arg(long, value_name = "FILE")]
    pub u_file: Option<PathBuf>,
    /// Sampling period in seconds, for a file without a time column.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub ts: Option<f64>,
}

/// How the measured file is read and prepared (shared by `fit` and `diagnose`).
#[derive(Debug, Clone, Default, Args)]
pub struct DataArgs {
    /// The step test: CSV, TSV, semicolon with decimal comma, or whitespace-separated.
    pub file: PathBuf,
    #[command(flatten)]
    pub columns: ColumnArgs,
    /// Lines to skip at the top (metadata before the table).
    #[arg(long, default_value_t = 0, allow_hyphen_values = true)]
    pub skip_rows: usize,
    /// Step time t0 (s); default: found in the input column.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub t0: Option<f64>,
    /// Step size Δu; default: found in the input column.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub du: Option<f64>,
    /// The input before the record started, when the step is at the first sample.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub initial_input: Option<f64>,
    /// Operating point Y0: auto (held at the output measured before the step: the mean of
    /// the samples before t0, or the sample at t0 when the record starts with the step;
    /// estimated when no sample is at or before t0, when the output still moved before it,
    /// or when fewer than 20 samples precede the first of several input changes), free
    /// (estimated with the other parameters), or a value to hold it at.
    #[arg(long, default_value = "auto", allow_hyphen_values = true)]
    pub y0: String,
    /// Keep only samples in this time range, e.g. 3.5,29.5.
    #[arg(long, allow_hyphen_values = true)]
    pub window: Option<String>,
    /// Low-pass the output first (the notes' EWMA filter), cut-off in Hz.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub filter: Option<f64>,
    /// Model one ideal step (the input column's largest change, or --t0/--du) instead of
    /// the measured input with every change (the default when the file has an input).
    #[arg(long)]
    pub single_step: bool,
    /// How the measured input moves between samples: zoh (held: a logged actuator
    /// command) or foh (a straight line: an analog input that was sampled).
    #[arg(long, value_enum, default_value_t = HoldArg::Zoh)]
    pub hold: HoldArg,
}

/// `--hold`, as typed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, ValueEnum)]
pub enum HoldArg {
    #[default]
    Zoh,
    Foh,
}

impl From<HoldArg> for Hold {
    fn from(h: HoldArg) -> Self {
        match h {
            HoldArg::Zoh => Hold::Zoh,
            HoldArg::Foh => Hold::Foh,
        }
    }
}

/// The optimiser, as typed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    #[default]
    Lm,
    NelderMead,
}

/// `degrau fit` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau fit leci_step.csv --model P2DU --t0 5 --du 10 --y0 50
  degrau fit tclab_step_q1_50.csv --model P2 --y-col T1 --u-col Q1 --json
  degrau fit ball.txt --ts 0.094 --model P2U --t0 3.4 --du 74.5 --guess Kp=5,Zeta=0.4")]
pub struct FitArgs {
    #[command(flatten)]
    pub data: DataArgs,
    /// Model structure as procest: P1, P1D, P2, P2D, P2U, P2DU, P2Z, P2DZ, P2DUZ, P3, P3D, P1I, P1DI, …
    #[arg(long, default_value = "P1D")]
    pub model: String,
    /// Initial guesses overriding the automatic ones, e.g. Kp=1.2,Td=2,Zeta=0.5,Tw=1.1.
    #[arg(long, allow_hyphen_values = true)]
    pub guess: Option<String>,
    /// Optimiser.
    #[arg(long, value_enum, default_value_t = MethodArg::Lm)]
    pub method: MethodArg,
    /// Number of starts (1: the guess only; at most 1000).
    #[arg(
        long,
        default_value_t = 16,
        allow_hyphen_values = true,
        value_parser = starts_count
    )]
    pub starts: usize,
    /// Add a linear drift term.
    #[arg(long)]
    pub drift: bool,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `degrau open FILE`: the app on a step test.
#[derive(Debug, Clone, Args)]
pub struct OpenArgs {
    /// The step test to load.
    pub file: PathBuf,
    #[command(flatten)]
    pub columns: ColumnArgs,
    /// The input's value before the record starts (a record whose first sample is already
    /// stepped, such as DaISy's heating system).
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub initial_input: Option<f64>,
    /// Model structure to start with (default: the one the record's shape suggests: P1D,
    /// or P2DU for an overshoot, P2Z for a dip first, P1DI for a ramp).
    #[arg(long)]
    pub model: Option<String>,
}

impl OpenArgs {
    /// The identification settings the app starts with.
    pub fn settings(&self) -> crate::app::identify::Saved {
        crate::app::identify::Saved {
            path: self.file.display().to_string(),
            time_col: self.columns.time_col.clone().unwrap_or_default(),
            y_col: self.columns.y_col.clone().unwrap_or_default(),
            u_col: self.columns.u_col.clone().unwrap_or_default(),
            u_path: self
                .columns
                .u_file
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default(),
            sampling_period: self.columns.ts.map(|t| t.to_string()).unwrap_or_default(),
            initial_input: self
                .initial_input
                .map(|u| u.to_string())
                .unwrap_or_default(),
            code: self
                .model
                .as_deref()
                .map(str::to_ascii_uppercase)
                .unwrap_or_default(),
            ..Default::default()
        }
    }
}

impl DataArgs {
    /// Loads and prepares the test: the data, the choices and the fit data.
    pub fn prepare(&self) -> Result<(StepTest, Experiment, FitData), CliError> {
        let test = self.read()?;
        let mut experiment = if self.single_step {
            Experiment::single_step(&test, self.t0, self.du, self.initial_input)?
        } else {
            Experiment::new(&test, self.t0, self.du, self.initial_input)?
        };
        if let Drive::Measured { .. } = experiment.drive {
            experiment.drive = Drive::Measured {
                hold: self.hold.into(),
            };
        }
        experiment.offset = parse_offset(&self.y0)?;
        experiment.window = self.window.as_deref().map(parse_window).transpose()?;
        experiment.filter_hz = self.filter;
        let fit_data = experiment.fit_data(&test)?;
        Ok((test, experiment, fit_data))
    }
}

impl DataArgs {
    /// The file as loaded, before any window or filter.
    pub fn read(&self) -> Result<StepTest, CliError> {
        let text = |c: &Option<String>| c.clone().unwrap_or_default();
        let input = match self.columns.u_file {
            Some(_) => "none".to_string(),
            None => text(&self.columns.u_col),
        };
        let options = LoadOptions::from_text(
            &text(&self.columns.time_col),
            &text(&self.columns.y_col),
            &input,
            self.columns.ts,
            self.skip_rows,
        );
        let load = |path: &std::path::Path, options: &LoadOptions| {
            data::load_file(path, options).map_err(|error| CliError::Data {
                path: path.display().to_string(),
                error,
            })
        };
        let test = load(&self.file, &options)?;
        let Some(u_file) = &self.columns.u_file else {
            return Ok(test);
        };
        // The input's file: its value column is read as that file's "output".
        let values =
            LoadOptions::from_text("", &text(&self.columns.u_col), "none", self.columns.ts, 0);
        let input = load(u_file, &values)?;
        crate::ident::record::join::join_on_time(test, &input).map_err(|error| CliError::Data {
            path: u_file.display().to_string(),
            error,
        })
    }

    /// The samples as they are, windowed and with the output filtered as `--window` and
    /// `--filter` say: for the methods that read the input column itself (ARX, RLS).
    pub fn samples(&self) -> Result<StepTest, CliError> {
        let mut test = self.read()?;
        if let Some(window) = self.window.as_deref() {
            let (start, end) = parse_window(window)?;
            test = crate::ident::record::prepare::apply_window(
                &test,
                crate::ident::record::prepare::Window::Time { start, end },
            )
            .map_err(ExperimentError::from)?;
        }
        if let Some(fc) = self.filter {
            let ts = crate::ident::record::timebase::sampling_period(&test.time).unwrap_or(1.0);
            let filter = crate::ident::record::prepare::Ewma::try_new(fc, ts)
                .map_err(ExperimentError::from)?;
            test.output = filter.apply(&test.output);
        }
        Ok(test)
    }
}

/// A `--starts` value that is refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum StartsError {
    /// Not a whole number.
    NotAWholeNumber(String),
    /// Outside 1 to [`MAX_STARTS`].
    OutOfRange(usize),
}

/// `--starts`: 1 to [`MAX_STARTS`].
fn starts_count(text: &str) -> Result<usize, StartsError> {
    let n: usize = text
        .trim()
        .parse()
        .map_err(|_| StartsError::NotAWholeNumber(text.to_string()))?;
    if (1..=MAX_STARTS).contains(&n) {
        Ok(n)
    } else {
        Err(StartsError::OutOfRange(n))
    }
}

fn parse_offset(text: &str) -> Result<Offset, CliError> {
    match text.trim().to_ascii_lowercase().as_str() {
        "auto" => Ok(Offset::Auto),
        "free" => Ok(Offset::Free),
        other => other
            .replace(',', ".")
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .map(Offset::Fixed)
            .ok_or_else(|| CliError::BadY0(text.to_string())),
    }
}

fn parse_window(text: &str) -> Result<(f64, f64), CliError> {
    let bad = || CliError::BadWindow(text.to_string());
    let (a, b) = text.split_once(',').ok_or_else(bad)?;
    let (a, b) = (
        finite_f64(a).map_err(|_| bad())?,
        finite_f64(b).map_err(|_| bad())?,
    );
    if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
        return Err(bad());
    }
    Ok((a, b))
}

/// `Kp=1.2,Td=2` into parameter values, each parameter once.
pub fn parse_guess(text: &str) -> Result<Vec<(Param, f64)>, CliError> {
    parse_values(text, "--guess")
}

/// Parameter values like `Kp=1.2,Td=2` typed in `flag` (`--guess`, `prbs --params`).
pub fn parse_values(text: &str, flag: &'static str) -> Result<Vec<(Param, f64)>, CliError> {
    let mut guesses: Vec<(Param, f64)> = Vec::new();
    for item in text.split(',').filter(|s| !s.trim().is_empty()) {
        let bad = || CliError::BadGuessItem {
            flag,
            item: item.to_string(),
        };
        let (name, value) = item.split_once('=').ok_or_else(bad)?;
        let p = Param::parse(name).ok_or_else(bad)?;
        let v = finite_f64(value).map_err(|_| bad())?;
        if let Some(&(_, first)) = guesses.iter().find(|g| g.0 == p) {
            return Err(CliError::GuessTwice {
                flag,
                param: p.name(),
                first,
                second: v,
            });
        }
        guesses.push((p, v));
    }
    if guesses.is_empty() {
        return Err(CliError::GuessEmpty(flag));
    }
    Ok(guesses)
}

/// The guesses fit the model: each of its parameters, and Y0 only when it is estimated.
fn check_guesses(
    guesses: &[(Param, f64)],
    structure: &Structure,
    held_y0: Option<f64>,
    y0_flag: &str,
) -> Result<(), CliError> {
    let params = structure.params();
    for &(p, v) in guesses {
        if params.contains(&p) {
            continue;
        }
        return Err(match (p, held_y0) {
            (Param::Y0, Some(held)) if parse_offset(y0_flag).is_ok_and(|o| o != Offset::Auto) => {
                CliError::GuessY0Fixed {
                    value: v,
                    flag: y0_flag.trim().to_string(),
                    held,
                }
            }
            (Param::Y0, Some(held)) => CliError::GuessY0Auto { value: v, held },
            (Param::Drift, _) => CliError::GuessDrift(v),
            _ => CliError::GuessNotInModel {
                param: p.name(),
                value: v,
                code: structure.code(),
                params: params.iter().map(|p| p.name()).collect(),
            },
        });
    }
    Ok(())
}

/// The FIT object of the JSON outputs (stable keys).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitJson {
    pub model: String,
    pub params: BTreeMap<String, f64>,
    pub ci95: BTreeMap<String, Option<[f64; 2]>>,
    pub mse: f64,
    /// ln MSE, finite even where the MSE itself is beyond double precision (`mse` is then
    /// null and a warning says so).
    pub ln_mse: f64,
    pub rmse: f64,
    pub fit_percent: f64,
    pub aic: f64,
    pub n: usize,
    pub iterations: usize,
    pub termination: String,
    pub warnings: Vec<String>,
    /// What was done with Y0 (`kind`: mean_before, at_step, given, estimated).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub operating_point: Option<OperatingPoint>,
    /// The input changes the fit used (the ideal step's one, or every measured change).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub steps: Option<Vec<InputStepJson>>,
    /// Each change fitted on its own window (a multi-step record), in order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub per_step: Option<Vec<FitJson>>,
}

/// One input change in the JSON outputs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputStepJson {
    /// The instant the model puts it at (s): the first sample that shows it.
    pub t: f64,
    pub du: f64,
    /// The input level before it.
    pub u_before: f64,
    /// The earliest instant it may have happened (s).
    pub earliest: f64,
}

/// The input changes of `input`, for the JSON outputs.
pub fn steps_json(input: &Excitation) -> Vec<InputStepJson> {
    input
        .changes
        .iter()
        .map(|c| InputStepJson {
            t: c.t,
            du: c.du,
            u_before: c.u_before,
            earliest: c.earliest,
        })
        .collect()
}

/// The per-step fits as FIT objects (a failed one as its error in `warnings`).
pub fn per_step_json(fits: &[StepFit]) -> Vec<FitJson> {
    fits.iter()
        .filter_map(|f| match &f.fit {
            Ok(r) => {
                let mut json = FitJson::new(r, None);
                json.steps = Some(vec![InputStepJson {
                    t: f.change.t,
                    du: f.change.du,
                    u_before: f.change.u_before,
                    earliest: f.change.earliest,
                }]);
                Some(json)
            }
            Err(_) => None,
        })
        .collect()
}

/// The per-step fits of `data` with `structure`, `None` when there are none to make (one
/// change, or more than [`MAX_PER_STEP`]).
pub fn per_step(
    data: &FitData,
    structure: Structure,
    options: &FitOptions,
) -> Option<Vec<StepFit>> {
    let n = data.input.changes.len();
    (2..=MAX_PER_STEP)
        .contains(&n)
        .then(|| per_step_fits(data, structure, options))
}

impl FitJson {
    pub fn new(report: &FitReport, operating_point: Option<OperatingPoint>) -> Self {
        let mut params = BTreeMap::new();
        let mut ci95 = BTreeMap::new();
        for e in &report.params {
            params.insert(e.param.name().to_string(), e.value);
            ci95.insert(e.param.name().to_string(), e.ci95.map(|(a, b)| [a, b]));
        }
        // Y0 is always reported, estimated or held.
        params
            .entry("Y0".to_string())
            .or_insert(report.model.get(Param::Y0));
        ci95.entry("Y0".to_string()).or_insert(None);
        Self {
            model: report.model.structure.code(),
            params,
            ci95,
            mse: report.mse,
            ln_mse: report.ln_mse,
            rmse: report.rmse,
            fit_percent: report.fit_percent,
            aic: report.aic,
            n: report.n,
            iterations: report.iterations,
            termination: serde_json::to_value(report.termination)
                .ok()
                .and_then(|v| v.as_str().map(String::from))
                .unwrap_or_default(),
            warnings: report
                .warnings
                .iter()
                .map(|w| crate::text::Localize::text(w, Lang::En))
                .collect(),
            operating_point,
            steps: None,
            per_step: None,
        }
    }
}

impl FitArgs {
    pub fn options(&self) -> FitOptions {
        FitOptions {
            method: match self.method {
                MethodArg::Lm => Method::LevenbergMarquardt,
                MethodArg::NelderMead => Method::NelderMead,
            },
            starts: self.starts.clamp(1, MAX_STARTS),
            ..FitOptions::default()
        }
    }
}

/// `degrau fit`.
pub fn run_fit(args: &FitArgs, lang: Lang) -> Result<(), CliError> {
    let overrides = args
        .guess
        .as_deref()
        .map(parse_guess)
        .transpose()?
        .unwrap_or_default();
    let (test, experiment, data) = args.data.prepare()?;
    // The fit needs only the prepared samples: the record itself goes now.
    drop(test);
    let structure = experiment.structure(&args.model, args.drift, &data)?;
    check_guesses(
        &overrides,
        &structure,
        experiment.operating_point(&data),
        &args.data.y0,
    )?;
    let report = experiment.fit_prepared(
        &data,
        &args.model,
        args.drift,
        &overrides,
        &args.options(),
        &mut (),
    )?;
    let operating_point = experiment.operating_point_fact(&data);
    let per_step = per_step(&data, structure, &args.options());
    let mut out = io::stdout().lock();
    let written = if args.json {
        let mut json = FitJson::new(&report, Some(operating_point));
        json.steps = Some(steps_json(&data.input));
        json.per_step = per_step.as_deref().map(per_step_json);
        serde_json::to_writer(&mut out, &json)
            .map_err(io::Error::other)
            .and_then(|()| writeln!(out))
    } else {
        let mut lines = crate::text::report::fit_lines(&report, lang);
        lines.push(operating_point.text(lang));
        lines.push(crate::text::steps::input_line(&data.input, lang));
        match &per_step {
            Some(fits) => lines.extend(crate::text::steps::per_step_lines(fits, &report, lang)),
            None if data.input.changes.len() > MAX_PER_STEP => lines.push(
                crate::text::steps::StepsPhrase::Skipped
                    .get(lang)
                    .replace("{0}", &MAX_PER_STEP.to_string()),
            ),
            None => {}
        }
        writeln!(out, "{}", lines.join("\n"))
    };
    written
        .and_then(|()| out.flush())
        .map_err(CliError::WriteOutput)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guesses_and_offsets_parse() {
        assert_eq!(
            parse_guess("Kp=1.2, td=2").unwrap(),
            vec![(Param::Kp, 1.2), (Param::Td, 2.0)]
        );
        assert!(parse_guess("Kp").is_err());
        assert!(parse_guess("Foo=1").is_err());
        assert!(parse_guess("Kp=nan").is_err());
        assert!(parse_guess("Kp=1e999").is_err());
        let twice = parse_guess("Kp=1,kp=2").unwrap_err().to_string();
        assert!(twice.contains("Kp twice"), "{twice}");
        assert!(parse_guess(",").is_err());
        assert_eq!(starts_count("1000"), Ok(1000));
        assert!(starts_count("0").is_err() && starts_count("1001").is_err());
        assert!(parse_window("-inf,inf").is_err());
        assert_eq!(parse_offset("free").unwrap(), Offset::Free);
        assert_eq!(parse_offset("50").unwrap(), Offset::Fixed(50.0));
        assert!(parse_offset("x").is_err());
        assert_eq!(parse_window("3.5,29.5").unwrap(), (3.5, 29.5));
        assert!(parse_window("5,1").is_err());
    }
}
