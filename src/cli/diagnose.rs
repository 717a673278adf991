//! `degrau diagnose FILE …`: what the test got wrong (its artefacts: `test_causes`), what the
//! fitted model gets wrong (the cause named with its evidence, the extended models and what
//! each extension gains: the `steps` chain), headless. The data flags are `degrau fit`'s;
//! every FIT object is [`FitJson`].

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::ident::diagnose::per_step::StepFit;
use crate::ident::diagnose::test_causes::{Handling, TestCause, TestEvidence};
use crate::ident::diagnose::{DiagnoseOptions, DiagnoseReport, Gain, diagnose};
use crate::ident::model::excitation::Excitation;
use crate::ident::model::{Param, Values};

use crate::text::{Lang, Localize};

use super::CliError;
use super::fit::{DataArgs, FitJson, InputStepJson, per_step, per_step_json, steps_json};

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

/// One cause of the test in the JSON output: its stable id, its evidence and remedy in
/// English words, its interval, what Degrau did, and the typed evidence (`facts`).
#[derive(Debug, Serialize)]
struct TestCauseJson {
    cause: &'static str,
    evidence: String,
    interval: Option<[f64; 2]>,
    handling: Handling,
    remedy: String,
    facts: TestEvidence,
}

impl TestCauseJson {
    fn new(c: &TestCause) -> Self {
        Self {
            cause: c.kind.id(),
            evidence: c.evidence.text(Lang::En),
            interval: c.interval.map(|(a, b)| [a, b]),
            handling: c.handling,
            remedy: crate::text::test_causes::remedy(c, Lang::En),
            facts: c.evidence.clone(),
        }
    }
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
    /// The input changes every fit used (the diagnosis's `steps` are its chain).
    input_steps: Vec<InputStepJson>,
    /// What the test got wrong (artefacts, not structure), in the order checked.
    test_causes: Vec<TestCauseJson>,
    /// Each change fitted on its own window with the final structure (a multi-step record).
    #[serde(skip_serializing_if = "Option::is_none")]
    per_step: Option<Vec<FitJson>>,
}

impl DiagnoseJson {
    fn new(r: &DiagnoseReport, input: &Excitation, per_step: Option<&[StepFit]>) -> Self {
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
            input_steps: steps_json(input),
            test_causes: r.test_causes.iter().map(TestCauseJson::new).collect(),
            per_step: per_step.map(per_step_json),
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
    let fits = per_step(&data, report.final_fit.model.structure, &options.fit);
    let mut out = io::stdout().lock();
    let written = if args.json {
        let json = DiagnoseJson::new(&report, &data.input, fits.as_deref());
        serde_json::to_writer(&mut out, &json)
            .map_err(io::Error::other)
            .and_then(|()| writeln!(out))
    } else {
        let mut text = crate::text::report::diagnose_text(&report, lang);
        text.push('\n');
        text.push_str(&crate::text::steps::input_line(&data.input, lang));
        if let Some(fits) = &fits {
            for line in crate::text::steps::per_step_lines(fits, &report.final_fit, lang) {
                text.push('\n');
                text.push_str(&line);
            }
        }
        writeln!(out, "{text}")
    };
    written
        .and_then(|()| out.flush())
        .map_err(CliError::WriteOutput)
}
