//! The command line of the `degrau` binary: no arguments open the app; `degrau step`
//! prints the exact step response of one system (text or `--json`), or of one system per
//! JSON line on stdin (`--batch`); `degrau fit` fits a process model to a measured step
//! test ([`fit`]).
//!
//! This module owns the argument syntax, the JSON request and report formats, the human
//! report, and the exit codes: 0 success, 1 the window could not be opened, 2 bad input or
//! unreadable stdin (`--batch` reports a bad line on its own output line and goes on).
//! Every system, from flags or from a JSON line, goes through [`SystemSpec::analyse`] and
//! [`Report::new`]; the text report reads the same [`Analysis`].

use std::io::{self, BufReader, Write};
use std::process::ExitCode;

pub mod approx;
pub mod arx;
pub mod batch;
pub mod bode;
pub mod diagnose;
pub mod discrete;
pub mod exercise;
pub mod fit;
pub mod hand;
mod human;
pub mod loop_cmd;
pub mod loop_controller;
pub mod margins;
pub mod prbs;
mod report;
pub mod rls;
pub mod tune;
pub mod tune_plant;

pub use batch::run_batch;
pub use human::*;
pub use report::*;

use clap::{Args, Parser, Subcommand};
use serde::{Deserialize, Serialize};

use crate::ident::experiment::ExperimentError;
use crate::ident::fit::FitError;
use crate::ident::record::data::DataError;
use crate::lti::expr::{OscillationForm, expression};
use crate::lti::feedback::{Input, InputResponse};
use crate::lti::number::format_number;
use crate::lti::parse::{ParseError, parse_complex_list, parse_real_list};
use crate::lti::poly::format_poly;
use crate::lti::tf::Stability;
use crate::lti::{
    Behaviour, C64, LtiError, StepAnalysis, StepInfo, StepInfoOptions, StepResponse,
    TransferFunction, analyse, fmt_c_rounded,
};
use crate::text::cli::{Heading, StepPhrase};
use crate::text::step::{IntegratorPole, Metric, static_gain_words};
use crate::text::{Lang, Localize};

/// The most samples one system may ask for (8 MB each for t and y).
pub const MAX_SAMPLES: usize = 1_000_000;

/// Exit code for bad input, as clap uses for bad arguments.
const EXIT_BAD_INPUT: u8 = 2;
/// Exit code when the window cannot be opened.
const EXIT_NO_WINDOW: u8 = 1;

/// Degrau: exact step responses of transfer functions, for control students.
///
/// Without a subcommand, opens the app.
#[derive(Debug, Parser)]
#[command(name = "degrau", version)]
pub struct Cli {
    /// Language of the text output and of the messages: en (English) or pt (Português);
    /// --json output is the same in every language.
    #[arg(
        long,
        global = true,
        default_value = "en",
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<LangArg>::new(),
            Lang::from
        )
    )]
    pub lang: Lang,
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Exact step response, step metrics and closed-form y(t) of a transfer function.
    Step(StepArgs),
    /// Fit a process model (procest codes: P1D, P2DU, …) to a measured step test.
    Fit(fit::FitArgs),
    /// Name what a fitted model gets wrong, extend it, and measure what each extension gains.
    Diagnose(diagnose::DiagnoseArgs),
    /// Open the app on a measured step test.
    Open(fit::OpenArgs),
    /// Replace a system by a simpler model (dominant poles, Taylor, Skogestad, Padé) and
    /// measure what it costs.
    Approx(approx::ApproxArgs),
    /// The Padé (m, n) polynomials of a dead time e^{−θs}.
    Pade(approx::PadeArgs),
    /// Unity-feedback loop around Kp·G(s): closed loop, gain for specs, error constants, root locus.
    Loop(loop_cmd::LoopArgs),
    /// Gain, phase and delay margins of the loop C(s)·G(s), the dead time exact; Ms and the
    /// closed loop's bandwidth.
    Margins(margins::MarginsArgs),
    /// PI or PID controllers for a first- or second-order plant with a dead time, by the
    /// published rules, each judged on its loop (exact dead time).
    Tune(tune::TuneArgs),
    /// The Bode diagram of G(jω), exact with the dead time, with the notes' asymptotes.
    Bode(bode::BodeArgs),
    /// Least squares on the samples: an ARX model (na, nb, nk), its parameters and errors.
    Arx(arx::ArxArgs),
    /// Recursive least squares on the samples, with the parameter trajectory.
    Rls(rls::RlsArgs),
    /// A PRBS test signal (as MATLAB's idinput), and a model's response to it.
    Prbs(prbs::PrbsArgs),
    /// Zero-order-hold discretisation of a system with its dead time.
    C2d(discrete::C2dArgs),
    /// Back from a discrete model B/A·z^−nk to G(s) with its dead time.
    D2c(discrete::D2cArgs),
    /// The notes' hand methods (tangent, 63.2 %, Broida, Smith, points, three points) on a measured step.
    Hand(hand::HandArgs),
    /// The instructor's kit: hidden-effect records with an answer key (make), and the
    /// grading of a class's answers (check).
    Exercise(exercise::ExerciseArgs),
}

const STEP_EXAMPLES: &str = "\
Examples:
  degrau step --poles \"-1+2j,-1-2j,-5\" --gain 0.5 --amplitude 2
  degrau step --num 0.5 --den 1,7,15,25 --json
  degrau step --poles \"-1+2j,-1-2j,-5\" --zeros -10 --dc-gain 1 --delay 0.3 --samples 201 --json
  echo '{\"id\": 1, \"num\": [5], \"den\": [1, 5]}' | degrau step --batch";

/// The system flags of `degrau step`, `loop` and `approx`: G by its poles (zeros, gain)
/// or by num and den, scaled to a static gain, with a dead time.
#[derive(Debug, Clone, Default, Args)]
pub struct SystemArgs {
    /// Poles, comma-separated, e.g. "-1+2j,-1-2j,-5" (complex ones in conjugate pairs).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub poles: Option<String>,
    /// Zeros, comma-separated, e.g. "-10" (default: none).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub zeros: Option<String>,
    /// k of the zero-pole-gain form k·Π(s−zᵢ)/Π(s−pⱼ), as MATLAB's zpk (default 1).
    #[arg(
        long,
        value_name = "K",
        allow_hyphen_values = true,
        conflicts_with = "dc_gain",
        value_parser = finite_f64
    )]
    pub gain: Option<f64>,
    /// Numerator coefficients in descending powers of s, e.g. "0.5".
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub num: Option<String>,
    /// Denominator coefficients in descending powers of s, e.g. "1,7,15,25".
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub den: Option<String>,
    /// Scale k so that the static gain G(0) is K.
    #[arg(long, value_name = "K", allow_hyphen_values = true, value_parser = finite_f64)]
    pub dc_gain: Option<f64>,
    /// Transport delay θ in seconds (default 0).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64)]
    pub delay: Option<f64>,
}

/// `degrau step` options. A system is given by its poles (zeros, gain) or by num and den.
#[derive(Debug, Default, Args)]
#[command(after_help = STEP_EXAMPLES)]
pub struct StepArgs {
    #[command(flatten)]
    pub system: SystemArgs,
    /// Step amplitude A (default 1).
    #[arg(long, value_name = "A", allow_hyphen_values = true, value_parser = finite_f64)]
    pub amplitude: Option<f64>,
    /// Settling band as a fraction of |y_final − y_init| (default 0.02).
    #[arg(
        long,
        value_name = "FRACTION",
        allow_hyphen_values = true,
        value_parser = finite_f64
    )]
    pub settling_threshold: Option<f64>,
    /// Rise-time limits as two fractions of the way to the final value (default 0.1,0.9).
    #[arg(long, value_name = "LOW,HIGH", allow_hyphen_values = true)]
    pub rise_limits: Option<String>,
    /// Add N samples of y(t), evenly spaced over [0, the automatic horizon].
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub samples: Option<usize>,
    /// The input: step (the default, with its metrics), impulse, ramp or parabola (y(t) and
    /// its samples, 201 unless --samples says).
    #[arg(
        long,
        default_value = "step",
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<InputArg>::new(),
            Input::from
        )
    )]
    pub response: Input,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    /// Read one JSON system per line on stdin, write one JSON line per system (--json is
    /// implied; --settling-threshold and --rise-limits apply to every line).
    #[arg(
        long,
        conflicts_with_all = [
            "poles", "zeros", "gain", "num", "den", "dc_gain", "delay", "amplitude", "samples",
            "response",
        ]
    )]
    pub batch: bool,
}

/// What can go wrong on the command line, as facts (`crate::text::cli` says them in the
/// language of `--lang`; `Display` and the JSON `error` of `--batch` are English).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum CliError {
    /// A list flag (`--poles`, …) that does not parse.
    Parse {
        option: &'static str,
        source: ParseError,
    },
    Lti(#[from] LtiError),
    /// The step metrics' thresholds, refused in `crate::lti`'s words.
    Options(String),
    RiseLimitsCount(usize),
    EmptyCoefficients(&'static str),
    NoSystem,
    TwoDescriptions,
    ZerosWithoutPoles,
    NumWithoutDen,
    DenWithoutNum,
    GainWithCoefficients,
    GainAndDcGain,
    Samples(usize),
    /// A sample of y(t) asked for, or a step metric, lies beyond double precision's range
    /// (it would print as NaN or inf).
    ResponseBeyondRange,
    /// serde_json's own words.
    JsonSyntax(String),
    NotAnObject,
    /// serde_json's own words.
    JsonFields(String),
    NotUtf8,
    ReadInput(io::Error),
    WriteOutput(io::Error),
    /// The data file could not be loaded.
    Data {
        path: String,
        error: DataError,
    },
    /// The step, window, filter, model code or fit choices.
    Experiment(#[from] ExperimentError),
    /// The diagnosis could not fit its start model.
    Diagnose(FitError),
    /// `--y0` is not auto, free or a number.
    BadY0(String),
    /// `--window` is not two increasing times.
    BadWindow(String),
    /// A `--guess` (or `prbs --params`, the flag) item is not like `Kp=1.2` with a known
    /// name and a finite value.
    BadGuessItem {
        flag: &'static str,
        item: String,
    },
    GuessTwice {
        flag: &'static str,
        param: &'static str,
        first: f64,
        second: f64,
    },
    /// `--guess` (or `--params`, the flag) names no parameter.
    GuessEmpty(&'static str),
    /// `--guess Y0=value` while `--y0 flag` holds Y0 at `held`.
    GuessY0Fixed {
        value: f64,
        flag: String,
        held: f64,
    },
    /// `--guess Y0=value` while `--y0 auto` holds Y0 at the mean before the step, `held`.
    GuessY0Auto {
        value: f64,
        held: f64,
    },
    /// `--guess Drift=value` without `--drift`.
    GuessDrift(f64),
    GuessNotInModel {
        param: &'static str,
        value: f64,
        code: String,
        params: Vec<&'static str>,
    },
}

impl StepArgs {
    /// The metric thresholds, defaults where not given, validated.
    pub fn options(&self) -> Result<StepInfoOptions, CliError> {
        let defaults = StepInfoOptions::default();
        let rise_limits = match &self.rise_limits {
            None => defaults.rise_limits,
            Some(text) => match parse_list("--rise-limits", text, parse_real_list)?.as_slice() {
                &[low, high] => (low, high),
                other => return Err(CliError::RiseLimitsCount(other.len())),
            },
        };
        let options = StepInfoOptions {
            settling_threshold: self
                .settling_threshold
                .unwrap_or(defaults.settling_threshold),
            rise_limits,
        };
        options.check()?;
        Ok(options)
    }

    /// The system described by the flags.
    pub fn spec(&self) -> Result<SystemSpec, CliError> {
        let complex = |option, text: &Option<String>| {
            text.as_deref()
                .map(|t| parse_list(option, t, parse_complex_list))
                .transpose()
        };
        let coefficients = |option, text: &Option<String>| {
            let list = text
                .as_deref()
                .map(|t| parse_list(option, t, parse_real_list))
                .transpose()?;
            match list {
                Some(c) if c.is_empty() => Err(CliError::EmptyCoefficients(option)),
                list => Ok(list),
            }
        };
        Ok(SystemSpec {
            zeros: complex("--zeros", &self.system.zeros)?,
            poles: complex("--poles", &self.system.poles)?,
            gain: self.system.gain,
            num: coefficients("--num", &self.system.num)?,
            den: coefficients("--den", &self.system.den)?,
            dc_gain: self.system.dc_gain,
            delay: self.system.delay,
            amplitude: self.amplitude,
            samples: self.samples,
        })
    }
}

/// The value of every numeric flag: a finite number, read as the app reads its fields
/// ([`crate::lti::parse::parse_real`]). clap names the flag in the error
/// (`invalid value 'NaN' for '--t0 <T0>': "NaN" is not a finite number`); [`main`] says it
/// in the language of `--lang`.
pub fn finite_f64(text: &str) -> Result<f64, ParseError> {
    crate::lti::parse::parse_real(text)
}

/// Parses an option's list, naming the option in the error.
fn parse_list<T>(
    option: &'static str,
    text: &str,
    parse: impl Fn(&str) -> Result<Vec<T>, ParseError>,
) -> Result<Vec<T>, CliError> {
    parse(text).map_err(|source| CliError::Parse { option, source })
}

/// An input `--response` takes: clap's side of [`Input`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum InputArg {
    /// A unit impulse δ(t) (times the amplitude).
    Impulse,
    /// A step of the amplitude.
    Step,
    /// A ramp A·t.
    Ramp,
    /// A parabola A·t²/2.
    Parabola,
}

impl From<InputArg> for Input {
    fn from(input: InputArg) -> Self {
        match input {
            InputArg::Impulse => Input::Impulse,
            InputArg::Step => Input::Step,
            InputArg::Ramp => Input::Ramp,
            InputArg::Parabola => Input::Parabola,
        }
    }
}

/// A language `--lang` takes: clap's side of [`Lang`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LangArg {
    /// English.
    #[value(name = "en")]
    En,
    /// Brazilian Portuguese.
    #[value(name = "pt")]
    Pt,
}

impl From<LangArg> for Lang {
    fn from(lang: LangArg) -> Self {
        match lang {
            LangArg::En => Lang::En,
            LangArg::Pt => Lang::Pt,
        }
    }
}

/// The language asked for by `--lang` in `args`, read before clap parses them so that a
/// refused flag is said in that language too (English when absent or unknown).
fn lang_in(args: &[std::ffi::OsString]) -> Option<Lang> {
    let mut lang = None;
    let mut words = args.iter().map(|a| a.to_string_lossy());
    while let Some(word) = words.next() {
        let value = match word.strip_prefix("--lang") {
            Some("") => words.next().map(|v| v.into_owned()),
            Some(rest) => rest.strip_prefix('=').map(str::to_string),
            None => None,
        };
        if let Some(v) = value.and_then(|v| <LangArg as clap::ValueEnum>::from_str(&v, true).ok()) {
            lang = Some(v.into());
        }
    }
    lang
}

/// Runs the command line: the binary's `main`.
pub fn main() -> ExitCode {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let cli = match Cli::try_parse_from(&args) {
        Ok(cli) => cli,
        Err(e) => return refuse_arguments(&e, &args, lang_in(&args).unwrap_or_default()),
    };
    let lang = cli.lang;
    // The window takes the language only when it is asked for; else it keeps its own.
    let window_lang = lang_in(&args);
    match cli.command {
        None => open_app_with(None, lang, window_lang),
        Some(Command::Step(args)) => finish(run_step(&args, lang), lang),
        Some(Command::Fit(args)) => finish(fit::run_fit(&args, lang), lang),
        Some(Command::Diagnose(args)) => finish(diagnose::run_diagnose(&args, lang), lang),
        Some(Command::Open(args)) => open_app_with(Some(args.settings()), lang, window_lang),
        Some(Command::Approx(args)) => approx::finish(approx::run_approx(&args, lang), lang),
        Some(Command::Pade(args)) => approx::finish(approx::run_pade(&args, lang), lang),
        Some(Command::Loop(args)) => loop_cmd::main(&args, lang),
        Some(Command::Margins(args)) => margins::main(&args, lang),
        Some(Command::Tune(args)) => tune::main(&args, lang),
        Some(Command::Bode(args)) => bode::main(&args, lang),
        Some(Command::Arx(args)) => arx::finish(arx::run_arx(&args, lang), lang),
        Some(Command::Rls(args)) => arx::finish(rls::run_rls(&args, lang), lang),
        Some(Command::Prbs(args)) => arx::finish(prbs::run_prbs(&args, lang), lang),
        Some(Command::C2d(args)) => arx::finish(discrete::run_c2d(&args, lang), lang),
        Some(Command::D2c(args)) => arx::finish(discrete::run_d2c(&args, lang), lang),
        Some(Command::Hand(args)) => hand::finish(hand::run_hand(&args, lang), lang),
        Some(Command::Exercise(args)) => exercise::main(&args, lang),
    }
}

/// clap's refusal of the command line `args`: help and version go to stdout with code 0,
/// usage errors to stderr with code 2, said in `lang` ([`crate::text::clap_words`]).
fn refuse_arguments(e: &clap::Error, args: &[std::ffi::OsString], lang: Lang) -> ExitCode {
    let code = ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(EXIT_BAD_INPUT));
    let args: Vec<String> = args
        .iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    match crate::text::clap_words::refused_arguments(e, &args, lang) {
        Some(words) => eprintln!("{}: {words}", StepPhrase::Error.get(lang)),
        None => {
            let _ = e.print();
        }
    }
    code
}

/// The exit code of a headless command, its error printed in words.
fn finish(result: Result<(), CliError>, lang: Lang) -> ExitCode {
    exit_code(result, |e| Some(e), lang)
}

/// The exit code of a command's result: success, or a closed pipe (the reader stopped
/// reading: nothing left to do), is 0; any other error is printed in words and is
/// [`EXIT_BAD_INPUT`]. `cli` reads the command's error as the common [`CliError`] where it
/// is one.
pub fn exit_code<E: Localize>(
    result: Result<(), E>,
    cli: impl Fn(&E) -> Option<&CliError>,
    lang: Lang,
) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => match cli(&e) {
            Some(CliError::WriteOutput(w)) if w.kind() == io::ErrorKind::BrokenPipe => {
                ExitCode::SUCCESS
            }
            _ => {
                eprintln!("{}: {}", StepPhrase::Error.get(lang), e.text(lang));
                ExitCode::from(EXIT_BAD_INPUT)
            }
        },
    }
}

/// Opens the window (with a step test loaded), in `window_lang` when one was asked for;
/// a failure is said in `lang`.
fn open_app_with(
    test: Option<crate::app::identify::Saved>,
    lang: Lang,
    window_lang: Option<Lang>,
) -> ExitCode {
    match crate::app::run_with(test, window_lang) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!(
                "{}: {}",
                StepPhrase::Error.get(lang),
                crate::text::cli::no_window(&e.to_string(), lang)
            );
            ExitCode::from(EXIT_NO_WINDOW)
        }
    }
}

/// `degrau step`: one system from the flags, or `--batch` from stdin.
pub fn run_step(args: &StepArgs, lang: Lang) -> Result<(), CliError> {
    let options = args.options()?;
    if args.batch {
        let input = BufReader::with_capacity(batch::READ_BYTES, io::stdin().lock());
        return run_batch(input, io::stdout(), &options);
    }
    if args.response != Input::Step {
        return run_input_response(args, &options, lang);
    }
    let analysis = args.spec()?.analyse(&options)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        write_json_line(&mut out, &Report::new(&analysis))
    } else {
        writeln!(out, "{}", human_report(&analysis, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(CliError::WriteOutput)
}

/// Samples of an impulse, ramp or parabola response when `--samples` does not say.
const INPUT_SAMPLES: usize = 201;

/// The JSON report of `degrau step --response impulse|ramp|parabola`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputReport {
    pub response: Input,
    /// y(t) in closed form (null for the impulse).
    pub expression: Option<String>,
    pub expression_amplitude_phase: Option<String>,
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub poles: Vec<[f64; 2]>,
    pub zeros: Vec<[f64; 2]>,
    pub delay: f64,
    pub amplitude: f64,
    /// Over the window of the step response of the same system.
    pub samples: Samples,
}

/// `degrau step --response impulse|ramp|parabola`: y(t) for that input, over the step
/// response's window.
fn run_input_response(
    args: &StepArgs,
    options: &StepInfoOptions,
    lang: Lang,
) -> Result<(), CliError> {
    let mut spec = args.spec()?;
    let n = check_samples(spec.samples.take().unwrap_or(INPUT_SAMPLES))?;
    let step = spec.analyse(options)?;
    let amplitude = step.response.amplitude();
    let input = InputResponse::new(&step.tf, args.response, amplitude)?;
    let horizon = Some(step.response.auto_horizon())
        .filter(|h| h.is_finite() && *h > 0.0)
        .unwrap_or(10.0);
    let (t, y) = input.sample_uniform(0.0, horizon, n);
    let samples = Samples::checked(t, y)?;
    let report = InputReport {
        response: args.response,
        expression: input.expression(OscillationForm::CosSin),
        expression_amplitude_phase: input.expression(OscillationForm::AmplitudePhase),
        num: step.tf.num(),
        den: step.tf.den(),
        poles: as_pairs(step.tf.poles()),
        zeros: as_pairs(step.tf.zeros()),
        delay: step.tf.delay(),
        amplitude,
        samples,
    };
    let mut out = io::stdout().lock();
    let written = if args.json {
        write_json_line(&mut out, &report)
    } else {
        writeln!(out, "{}", input_report_text(&step, &report, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(CliError::WriteOutput)
}

/// The text of an impulse, ramp or parabola response: the system, y(t), the samples.
fn input_report_text(step: &Analysis, report: &InputReport, lang: Lang) -> String {
    use crate::text::feedback::InputHeading;
    let mut lines = system_lines(step, lang);
    lines.push(String::new());
    lines.push(InputHeading(report.response).text(lang));
    for e in [&report.expression, &report.expression_amplitude_phase]
        .into_iter()
        .flatten()
    {
        lines.push(format!("  {e}"));
    }
    lines.push(String::new());
    lines.push(format!("{}\n  t (s)\ty", Heading::Samples.get(lang)));
    let Samples { t, y } = &report.samples;
    lines.extend(t.iter().zip(y).map(|(t, y)| format!("  {t}\t{y}")));
    lines.join("\n")
}

/// `value` as one line of compact JSON (non-finite numbers become `null`).
fn write_json_line(out: &mut impl Write, value: &impl Serialize) -> io::Result<()> {
    serde_json::to_writer(&mut *out, value)?;
    out.write_all(b"\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec_from(args: &[&str]) -> Result<SystemSpec, CliError> {
        let mut argv = vec!["degrau", "step"];
        argv.extend_from_slice(args);
        let cli = Cli::try_parse_from(argv).map_err(|e| CliError::Options(e.to_string()))?;
        match cli.command {
            Some(Command::Step(step)) => step.spec(),
            _ => Err(CliError::NoSystem),
        }
    }

    #[test]
    fn flags_and_json_describe_the_same_system() {
        let from_flags = spec_from(&[
            "--poles",
            "-1+2j,-1-2j,-5",
            "--zeros",
            "-10",
            "--gain",
            "0.5",
        ])
        .unwrap();
        let from_json: SystemSpec = serde_json::from_str(
            r#"{"poles": [[-1, 2], [-1, -2], [-5, 0]], "zeros": [[-10, 0]], "gain": 0.5}"#,
        )
        .unwrap();
        assert_eq!(from_flags, from_json);
        let tf = from_flags.transfer_function().unwrap();
        assert!((tf.dc_gain() - 0.2).abs() < 1e-15);
    }

    #[test]
    fn inconsistent_descriptions_are_refused() {
        let spec = |json: &str| serde_json::from_str::<SystemSpec>(json).unwrap();
        let cases = [
            (r#"{}"#, "no system given"),
            (r#"{"poles": [[-1, 0]], "den": [1, 1]}"#, "given twice"),
            (
                r#"{"zeros": [[-1, 0]], "num": [1], "den": [1, 1]}"#,
                "given twice",
            ),
            (r#"{"zeros": [[-1, 0]]}"#, "without poles"),
            (r#"{"num": [1]}"#, "without den"),
            (r#"{"den": [1, 1]}"#, "without num"),
            (
                r#"{"num": [1], "den": [1, 1], "gain": 2}"#,
                "goes with poles",
            ),
            (
                r#"{"poles": [[-1, 0]], "gain": 2, "dc_gain": 1}"#,
                "not both",
            ),
            (r#"{"poles": []}"#, "no poles"),
            (r#"{"num": [1, 0, 0], "den": [1, 1]}"#, "improper"),
            (
                r#"{"num": [1], "den": [1, 0], "dc_gain": 2}"#,
                "cannot be set",
            ),
            (r#"{"poles": [[-1, 0]], "samples": 1}"#, "between 2 and"),
        ];
        for (json, words) in cases {
            let error = spec(json)
                .analyse(&StepInfoOptions::default())
                .unwrap_err()
                .to_string();
            assert!(error.contains(words), "{json}: {error}");
        }
    }

    #[test]
    fn rise_limits_and_band_are_validated() {
        let options = |args: &[&str]| {
            let mut argv = vec!["degrau", "step"];
            argv.extend_from_slice(args);
            match Cli::try_parse_from(argv).unwrap().command {
                Some(Command::Step(step)) => step.options(),
                _ => unreachable!("the step subcommand was given"),
            }
        };
        assert_eq!(
            options(&["--rise-limits", "0.05,0.95", "--settling-threshold", "0.05"]).unwrap(),
            StepInfoOptions {
                settling_threshold: 0.05,
                rise_limits: (0.05, 0.95)
            }
        );
        assert!(matches!(
            options(&["--rise-limits", "0.1"]),
            Err(CliError::RiseLimitsCount(1))
        ));
        assert!(matches!(
            options(&["--rise-limits", "10,90"]),
            Err(CliError::Lti(LtiError::BadRiseLimits { .. }))
        ));
        assert!(matches!(
            options(&["--settling-threshold", "-0.02"]),
            Err(CliError::Lti(LtiError::BadSettlingBand(_)))
        ));
        assert!(matches!(
            options(&["--rise-limits", "0.1,x"]),
            Err(CliError::Parse { .. })
        ));
    }

    #[test]
    fn absent_metrics_say_why() {
        let report = |json: &str, lang| {
            let spec: SystemSpec = serde_json::from_str(json).unwrap();
            human_report(&spec.analyse(&StepInfoOptions::default()).unwrap(), lang)
        };
        let integrator = report(r#"{"num": [1], "den": [1, 1, 0]}"#, Lang::En);
        assert!(
            integrator.contains("Rise time      none: does not settle: it ramps"),
            "{integrator}"
        );
        let first_order = report(r#"{"num": [5], "den": [1, 5]}"#, Lang::En);
        assert!(
            first_order.contains("Peak time      none: monotone"),
            "{first_order}"
        );
        let derivative = report(r#"{"num": [1, 0], "den": [1, 1]}"#, Lang::En);
        assert!(derivative.contains("Rise time      none"), "{derivative}");
    }

    #[test]
    fn the_report_speaks_portuguese_with_decimal_commas() {
        let spec: SystemSpec = serde_json::from_str(r#"{"num": [5], "den": [1, 5]}"#).unwrap();
        let a = spec.analyse(&StepInfoOptions::default()).unwrap();
        let pt = human_report(&a, Lang::Pt);
        // 5/(s+5): rise time ln 9 / 5 = 0.43944 s, settling time ln 50 / 5 = 0.78240 s.
        assert!(pt.contains("Tempo de subida"), "{pt}");
        assert!(pt.contains("0,43944 s"), "{pt}");
        assert!(pt.contains("0,7824 s"), "{pt}");
        assert!(
            pt.contains("estável (todos os polos no semiplano esquerdo)"),
            "{pt}"
        );
        // The closed form keeps its points.
        assert!(pt.contains("y(t) = 1 − e^{−5t}"), "{pt}");
    }

    #[test]
    fn the_language_is_read_before_the_flags_are_parsed() {
        let args = |a: &[&str]| a.iter().map(std::ffi::OsString::from).collect::<Vec<_>>();
        assert_eq!(
            lang_in(&args(&["degrau", "step", "--lang", "pt"])),
            Some(Lang::Pt)
        );
        assert_eq!(
            lang_in(&args(&["degrau", "--lang=pt", "fit"])),
            Some(Lang::Pt)
        );
        assert_eq!(lang_in(&args(&["degrau", "step", "--lang"])), None);
        assert_eq!(lang_in(&args(&["degrau", "step"])), None);
    }
}
