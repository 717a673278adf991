//! `degrau hand FILE --method tangent|63|broida|smith|points|three-point`: the notes' hand
//! methods read off a measured step test, headless. With `--method`, the method's K, τ, θ
//! (ζ, ωn, τ1, τ2), its construction and fit %; without, the table of every method beside the
//! least-squares fits of the matching structures (P1D, P2D) on the same data.

use std::io::{self, Write};

use clap::{Args, ValueEnum};
use serde::Serialize;

use crate::ident::fit::FitReport;
use crate::ident::hand::{
    Construction, DeadTimeFrom, HandError, HandEstimate, HandMethod, Overrides, Record, estimate,
    estimate_all, least_squares,
};
use crate::text::{Lang, Localize};

use super::fit::DataArgs;
use super::{CliError, finite_f64, write_json_line};

/// `--method`, as typed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    Tangent,
    #[value(name = "63")]
    SixtyThree,
    Broida,
    Smith,
    Points,
    ThreePoint,
}

impl From<MethodArg> for HandMethod {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Tangent => HandMethod::Tangent,
            MethodArg::SixtyThree => HandMethod::SixtyThree,
            MethodArg::Broida => HandMethod::Broida,
            MethodArg::Smith => HandMethod::Smith,
            MethodArg::Points => HandMethod::Points,
            MethodArg::ThreePoint => HandMethod::ThreePoint,
        }
    }
}

/// `degrau hand` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau hand tclab_step_q1_50.csv --y-col T1 --u-col Q1
  degrau hand tclab_step_q1_50.csv --y-col T1 --u-col Q1 --method tangent --json
  degrau hand leci_step.csv --t0 5 --du 10 --y0 50 --method three-point")]
pub struct HandArgs {
    #[command(flatten)]
    pub data: DataArgs,
    /// The hand method; without it, a table of every method beside the least-squares fits.
    #[arg(long, value_enum)]
    pub method: Option<MethodArg>,
    /// Draw the tangent at this time (s) instead of at the steepest rise.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub tangent_at: Option<f64>,
    /// The final level y∞ (output units) instead of the mean of the record's last tenth.
    #[arg(long, allow_hyphen_values = true, value_parser = finite_f64)]
    pub final_level: Option<f64>,
    /// The 63.2 % method's θ from where the curve first leaves y0 (else from the tangent).
    #[arg(long)]
    pub first_departure: bool,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// What can go wrong in `degrau hand` (said by `crate::text::hand`).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum HandCliError {
    Cli(#[from] CliError),
    Hand(#[from] HandError),
}

impl HandArgs {
    /// The student's construction, a typed tangent's point refused outside the response.
    fn overrides(&self, record: &Record) -> Result<Overrides, HandError> {
        Ok(Overrides {
            tangent_time: self
                .tangent_at
                .map(|t| record.tangent_time(t))
                .transpose()?,
            y0: None,
            y_final: self.final_level,
            dead_time_from: if self.first_departure {
                DeadTimeFrom::FirstDeparture
            } else {
                DeadTimeFrom::Tangent
            },
        })
    }
}

/// One method in the JSON output (stable keys; times in s, absolute in `construction`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HandJson {
    pub method: &'static str,
    /// The model simulated: P1D, P2D or P2DU.
    pub model: String,
    #[serde(rename = "K")]
    pub k: f64,
    pub theta: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tau: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tau1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tau2: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub omega_n: Option<f64>,
    pub y0: f64,
    pub fit_percent: f64,
    pub construction: Construction,
    pub warnings: Vec<String>,
}

impl HandJson {
    pub fn new(e: &HandEstimate) -> Self {
        let so = e.second_order;
        Self {
            method: e.method.key(),
            model: e.model.structure.code(),
            k: e.k,
            theta: e.theta,
            tau: e.tau,
            tau1: so.and_then(|s| s.tau1),
            tau2: so.and_then(|s| s.tau2),
            zeta: so.map(|s| s.zeta),
            omega_n: so.map(|s| s.omega_n),
            y0: e.construction.y0,
            fit_percent: e.fit_percent,
            construction: e.construction.clone(),
            warnings: e.warnings.iter().map(|w| w.text(Lang::En)).collect(),
        }
    }
}

/// A row of the table's JSON: a method's result or why it cannot be read.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum RowJson {
    Read(Box<HandJson>),
    Refused { method: &'static str, error: String },
}

/// A least-squares fit in the table's JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LeastSquaresJson {
    pub model: String,
    pub params: std::collections::BTreeMap<String, f64>,
    pub fit_percent: f64,
}

/// The table's JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TableJson {
    pub methods: Vec<RowJson>,
    pub least_squares: Vec<LeastSquaresJson>,
}

/// `degrau hand`.
pub fn run_hand(args: &HandArgs, lang: Lang) -> Result<(), HandCliError> {
    let (_, experiment, data) = args.data.prepare()?;
    let record = Record::from_fit_data(&data, experiment.operating_point(&data))?;
    let overrides = args.overrides(&record)?;
    let mut out = io::stdout().lock();
    let written = match args.method {
        Some(m) => {
            let e = estimate(&record, m.into(), &overrides)?;
            if args.json {
                write_json_line(&mut out, &HandJson::new(&e))
            } else {
                writeln!(
                    out,
                    "{}",
                    crate::text::hand::estimate_lines(&e, lang).join("\n")
                )
            }
        }
        None => {
            let rows = estimate_all(&record, &overrides);
            let fits = least_squares(&data, &experiment, || false);
            if args.json {
                write_json_line(&mut out, &table_json(&rows, &fits))
            } else {
                let lines = crate::text::hand::table_lines(&rows, &fits, lang);
                writeln!(out, "{}", lines.join("\n"))
            }
        }
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| HandCliError::Cli(CliError::WriteOutput(e)))
}

fn table_json(
    rows: &[(HandMethod, Result<HandEstimate, HandError>)],
    fits: &[FitReport],
) -> TableJson {
    TableJson {
        methods: rows
            .iter()
            .map(|(m, r)| match r {
                Ok(e) => RowJson::Read(Box::new(HandJson::new(e))),
                Err(err) => RowJson::Refused {
                    method: m.key(),
                    error: err.text(Lang::En),
                },
            })
            .collect(),
        least_squares: fits
            .iter()
            .map(|r| LeastSquaresJson {
                model: r.model.structure.code(),
                params: r
                    .params
                    .iter()
                    .map(|e| (e.param.name().to_string(), e.value))
                    .collect(),
                fit_percent: r.fit_percent,
            })
            .collect(),
    }
}

/// The exit code of `degrau hand`, its error said in `lang`.
pub fn finish(result: Result<(), HandCliError>, lang: Lang) -> std::process::ExitCode {
    match result {
        Err(HandCliError::Cli(e)) => super::finish(Err(e), lang),
        Err(e) => {
            eprintln!(
                "{}: {}",
                crate::text::cli::StepPhrase::Error.get(lang),
                e.text(lang)
            );
            std::process::ExitCode::from(2)
        }
        Ok(()) => std::process::ExitCode::SUCCESS,
    }
}
