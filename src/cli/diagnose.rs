//! `degrau diagnose FILE …`: what the fitted model gets wrong, the cause named with its
//! evidence, the extended models and what each extension gains, headless. The data flags are
//! `degrau fit`'s; every FIT object is [`FitJson`].

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::ident::diagnose::{DiagnoseOptions, DiagnoseReport, Gain, diagnose};
use crate::ident::models::{Param, Values};

use crate::text::{Lang, Localize};

use super::CliError;
use super::fit::{DataArgs, FitJson};

/// `degrau diagnose` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau diagnose leci_step.csv --t0 5 --du 10 --y0 50 --start P2U
  degrau diagnose tclab_step_q1_50.csv --y-col T1 --u-col Q1 --start P1 --json")]
pub struct DiagnoseArgs {
    #[command(flatten)]
    pub data: DataArgs,
    /// The start model (procest code); the loop extends it until nothing pays.
    #[arg(long, default_value = "P1")]
    pub start: String,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// One step of the chain in the JSON output.
#[derive(Debug, Serialize)]
struct StepJson {
    cause: &'static str,
    evidence: String,
    interval: Option<[f64; 2]>,
    fit: FitJson,
    gain: Gain,
}

/// The static gain with its interval.
#[derive(Debug, Serialize)]
struct StaticGainJson {
    value: f64,
    ci95: Option<[f64; 2]>,
}

/// The JSON object graders read (stable keys).
#[derive(Debug, Serialize)]
struct DiagnoseJson {
    start: FitJson,
    steps: Vec<StepJson>,
    #[serde(rename = "final")]
    final_fit: FitJson,
    adequate: bool,
    verdict: String,
    static_gain: StaticGainJson,
}

impl DiagnoseJson {
    fn new(r: &DiagnoseReport) -> Self {
        Self {
            start: FitJson::new(&r.start, None),
            steps: r
                .steps
                .iter()
                .map(|s| StepJson {
                    cause: s.cause.id(),
                    evidence: s.evidence.text(Lang::En),
                    interval: s.interval.map(|(a, b)| [a, b]),
                    fit: FitJson::new(&s.fit, None),
                    gain: s.gain,
                })
                .collect(),
            final_fit: FitJson::new(&r.final_fit, None),
            adequate: r.adequate,
            verdict: r.verdict.map_or(String::new(), |v| v.text(Lang::En)),
            static_gain: StaticGainJson {
                value: r.static_gain.0,
                ci95: r.static_gain.1.map(|(a, b)| [a, b]),
            },
        }
    }
}

/// `degrau diagnose`.
pub fn run_diagnose(args: &DiagnoseArgs, lang: Lang) -> Result<(), CliError> {
    let (_, experiment, data) = args.data.prepare()?;
    let start = experiment.structure(&args.start, false, &data)?;
    let start_values = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let mut options = DiagnoseOptions::default();
    options.fit.starts = options.fit.starts.max(1);
    let report = diagnose(&data, start, start_values, &options).map_err(CliError::Diagnose)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        serde_json::to_writer(&mut out, &DiagnoseJson::new(&report))
            .map_err(io::Error::other)
            .and_then(|()| writeln!(out))
    } else {
        writeln!(out, "{}", crate::text::report::diagnose_text(&report, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(CliError::WriteOutput)
}
