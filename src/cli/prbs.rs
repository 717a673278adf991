//! `degrau prbs --n N --clock K --levels LO,HI [--periods P] [--ts H] [--model CODE --params
//! Kp=…,Tp1=…]`: a PRBS test signal like MATLAB's `idinput(N, 'prbs', [0 1/K], [LO HI])`
//! (with `--periods P`, `idinput([N 1 P], …)`: P whole periods of the shortest register whose
//! period covers N samples), written as CSV `time,u` (and `y`, the chosen model's response
//! with `--noise` and `--seed`), readable by `degrau fit`, `arx` and `rls`; `--json` gives
//! the design and the columns.

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::ident::lsq::prbs::{Prbs, sample_times, simulate_record, taps, to_csv};
use crate::ident::model::{Model, Structure, Values};
use crate::text::Lang;

use super::CliError;
use super::arx::LsqCliError;

/// `degrau prbs` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau prbs --n 500 --clock 4 --levels 40,60 --ts 2 > prbs.csv
  degrau prbs --n 255 --clock 2 --levels 0,10 --periods 3 --ts 0.5 --model P1D --params Kp=2,Tp1=8,Td=1.5,Y0=20 --noise 0.05 > record.csv")]
pub struct PrbsArgs {
    /// Samples (idinput's N); with --periods, the length one period must cover.
    #[arg(long, value_name = "N")]
    pub n: usize,
    /// Clock period: samples per bit (idinput's band [0 1/K]).
    #[arg(long, default_value_t = 1)]
    pub clock: usize,
    /// The two levels, low then high.
    #[arg(
        long,
        value_name = "LO,HI",
        default_value = "-1,1",
        allow_hyphen_values = true
    )]
    pub levels: String,
    /// Whole periods to repeat.
    #[arg(long)]
    pub periods: Option<usize>,
    /// Register length in bits (default: the shortest whose period covers N).
    #[arg(long)]
    pub order: Option<u32>,
    /// Sampling period h (s) of the time column.
    #[arg(long, default_value_t = 1.0, value_parser = super::finite_f64)]
    pub ts: f64,
    /// Simulate this model's response (procest code: P1D, P2DU, …).
    #[arg(long)]
    pub model: Option<String>,
    /// The model's parameters, e.g. Kp=2,Tp1=8,Td=1.5,Y0=20.
    #[arg(long, allow_hyphen_values = true)]
    pub params: Option<String>,
    /// Standard deviation of the white noise added to y (output units).
    #[arg(long, default_value_t = 0.0, value_parser = super::finite_f64)]
    pub noise: f64,
    /// Seed of the noise.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print one JSON object instead of CSV.
    #[arg(long)]
    pub json: bool,
}

/// The PRBS JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PrbsJson {
    /// Register length n (bits).
    pub order: u32,
    /// Feedback taps (bit positions from 1).
    pub taps: Vec<u32>,
    pub clock: usize,
    /// Samples per period, (2ⁿ − 1)·clock.
    pub period: usize,
    pub low: f64,
    pub high: f64,
    pub samples: usize,
    pub time: Vec<f64>,
    pub u: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub y: Option<Vec<f64>>,
}

fn levels(text: &str) -> Result<(f64, f64), LsqCliError> {
    let values = super::parse_list("--levels", text, crate::lti::parse::parse_real_list)?;
    match values[..] {
        [lo, hi] => Ok((lo, hi)),
        _ => Err(LsqCliError::Levels(text.to_string())),
    }
}

/// `degrau prbs`.
pub fn run_prbs(args: &PrbsArgs, _lang: Lang) -> Result<(), LsqCliError> {
    let (low, high) = levels(&args.levels)?;
    let prbs = match args.order {
        Some(order) => Prbs::new(order, args.clock, low, high)?,
        None => Prbs::for_length(args.n, args.clock, low, high)?,
    };
    let u = match args.periods {
        Some(p) => prbs.periodic(p)?,
        None => prbs.signal(args.n)?,
    };
    let record = match &args.model {
        Some(code) => {
            let structure = Structure::parse(code).map_err(|e| CliError::Experiment(e.into()))?;
            let mut values = Values::default();
            if let Some(text) = &args.params {
                for (p, v) in super::fit::parse_values(text, "--params")? {
                    values.set(p, v);
                }
            }
            Some(simulate_record(
                &Model::new(structure, values),
                &u,
                args.ts,
                args.noise,
                args.seed,
            )?)
        }
        None => None,
    };
    let time = sample_times(u.len(), args.ts)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        super::write_json_line(
            &mut out,
            &PrbsJson {
                order: prbs.order,
                taps: taps(prbs.order).to_vec(),
                clock: prbs.clock,
                period: prbs.period(),
                low,
                high,
                samples: u.len(),
                y: record.as_ref().map(|r| r.y.clone()),
                time,
                u,
            },
        )
    } else {
        match &record {
            Some(r) => out.write_all(to_csv(r).as_bytes()),
            None => {
                let mut text = String::from("time,u\n");
                for (t, v) in time.iter().zip(&u) {
                    text.push_str(&format!("{t},{v}\n"));
                }
                out.write_all(text.as_bytes())
            }
        }
    };
    written.map_err(|e| LsqCliError::Cli(CliError::WriteOutput(e)))
}
