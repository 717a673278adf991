//! `degrau bode`: the Bode diagram of one system given as for `degrau step` (exact with its
//! dead time, [`crate::lti::bode`]): |G(jω)| in dB, ∠G(jω) in degrees (continuous) and the
//! notes' straight-line asymptote at each ω of a log grid (`--w-min`, `--w-max` in rad/s,
//! default two decades around the corners; `--points`, default 200). Text (a header with the
//! corners and slopes in words, then a table with six significant digits) or one JSON object
//! (`w`, `mag_db`, `phase_deg`, `asymptote_db`, `corners`, every digit).

use std::io::{self, Write};
use std::process::ExitCode;

use clap::Args;
use serde::Serialize;

use crate::lti::bode::{Asymptotes, Corner, asymptotes, bode, default_range, log_grid};
use crate::lti::number::format_number;
use crate::text::bode::Line;
use crate::text::{Lang, Localize};

use super::{CliError, MAX_SAMPLES, SystemArgs, finite_f64};

const BODE_EXAMPLES: &str = "\
Examples:
  degrau bode --num 0.5 --den 1,7,15,25
  degrau bode --num 1 --den 10,1 --delay 2 --w-min 0.01 --w-max 10 --points 50 --json";

/// `degrau bode` options: the system as for `degrau step`, then the frequencies.
#[derive(Debug, Default, Args)]
#[command(after_help = BODE_EXAMPLES)]
pub struct BodeArgs {
    #[command(flatten)]
    pub system: SystemArgs,
    /// The lowest frequency ω, rad/s (default: two decades below the lowest corner).
    #[arg(long, value_name = "RAD/S", allow_hyphen_values = true, value_parser = finite_f64)]
    pub w_min: Option<f64>,
    /// The highest frequency ω, rad/s (default: two decades above the highest corner).
    #[arg(long, value_name = "RAD/S", allow_hyphen_values = true, value_parser = finite_f64)]
    pub w_max: Option<f64>,
    /// How many frequencies, evenly spread in log ω (default 200).
    #[arg(long, value_name = "N", default_value_t = 200)]
    pub points: usize,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

/// What can go wrong in `degrau bode` (its words: [`crate::text::bode`]).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum BodeCliError {
    Cli(#[from] CliError),
    /// `--w-min` or `--w-max` is not a positive frequency (a log axis starts above 0).
    NotPositive {
        flag: &'static str,
        value: f64,
    },
    /// `--w-min` is not below `--w-max`.
    EmptyRange {
        w_min: f64,
        w_max: f64,
    },
    /// `--points` is below 2 or above [`MAX_SAMPLES`].
    Points(usize),
}

/// The JSON report of `degrau bode`.
#[derive(Debug, Serialize)]
pub struct BodeReport {
    /// ω, rad/s.
    pub w: Vec<f64>,
    pub mag_db: Vec<f64>,
    pub phase_deg: Vec<f64>,
    /// The notes' straight-line asymptote at each ω, dB.
    pub asymptote_db: Vec<f64>,
    pub corners: Vec<Corner>,
    /// The low-frequency line's value at ω = 1, 20·log10|K_bode| (dB).
    pub low_db_at_1: f64,
    /// The slope before the first corner, dB/decade.
    pub low_slope_db_per_decade: f64,
    pub system_type: i32,
    /// The dead time θ, s.
    pub delay: f64,
}

impl BodeArgs {
    /// The frequency range asked for, the defaults where not given.
    fn range(&self, default: (f64, f64)) -> Result<(f64, f64), BodeCliError> {
        for (flag, value) in [("--w-min", self.w_min), ("--w-max", self.w_max)] {
            if let Some(value) = value.filter(|v| *v <= 0.0 || !v.is_normal()) {
                return Err(BodeCliError::NotPositive { flag, value });
            }
        }
        let (w_min, w_max) = match (self.w_min, self.w_max) {
            (Some(lo), Some(hi)) => (lo, hi),
            (Some(lo), None) => (lo, default.1.max(lo * 100.0)),
            (None, Some(hi)) => (default.0.min(hi / 100.0), hi),
            (None, None) => default,
        };
        if w_min >= w_max || !w_max.is_finite() {
            return Err(BodeCliError::EmptyRange { w_min, w_max });
        }
        Ok((w_min, w_max))
    }
}

/// The report the flags ask for.
pub fn report(args: &BodeArgs) -> Result<BodeReport, BodeCliError> {
    if !(2..=MAX_SAMPLES).contains(&args.points) {
        return Err(BodeCliError::Points(args.points));
    }
    let step = super::StepArgs {
        system: args.system.clone(),
        ..Default::default()
    };
    let g = step.spec()?.transfer_function()?;
    let (w_min, w_max) = args.range(default_range(&g))?;
    let w = log_grid(w_min, w_max, args.points);
    let diagram = bode(&g, &w);
    let lines = asymptotes(&g);
    Ok(BodeReport {
        asymptote_db: w.iter().map(|&w| lines.value_db(w)).collect(),
        w: diagram.w,
        mag_db: diagram.mag_db,
        phase_deg: diagram.phase_deg,
        low_db_at_1: lines.low_db_at_1,
        low_slope_db_per_decade: lines.low_slope(),
        system_type: lines.system_type,
        corners: lines.corners,
        delay: g.delay(),
    })
}

/// The text report: the asymptotes in words, then the table.
pub fn text(report: &BodeReport, lang: Lang) -> String {
    let mut out = String::new();
    let mut say = |line: Line| {
        out.push_str(&line.text(lang));
        out.push('\n');
    };
    let asymptotes = Asymptotes {
        low_db_at_1: report.low_db_at_1,
        system_type: report.system_type,
        corners: report.corners.clone(),
    };
    for line in asymptotes.lines() {
        say(Line::Asymptote(line));
    }
    if report.delay > 0.0 {
        say(Line::Delay(report.delay));
    }
    say(Line::TableHeader);
    for i in 0..report.w.len() {
        let row = [
            report.w[i],
            report.mag_db[i],
            report.phase_deg[i],
            report.asymptote_db[i],
        ]
        .map(format_number);
        out.push_str(&format!(
            "{:>14} {:>14} {:>14} {:>14}\n",
            row[0], row[1], row[2], row[3]
        ));
    }
    out
}

/// Runs `degrau bode`.
pub fn run_bode(args: &BodeArgs, lang: Lang) -> Result<(), BodeCliError> {
    let report = report(args)?;
    let written = if args.json {
        let json = serde_json::to_string(&report)
            .map_err(|e| CliError::WriteOutput(io::Error::other(e)))?;
        writeln!(io::stdout(), "{json}")
    } else {
        write!(io::stdout(), "{}", text(&report, lang))
    };
    written
        .and_then(|()| io::stdout().flush())
        .map_err(|e| CliError::WriteOutput(e).into())
}

/// The exit code of `degrau bode`, its error printed in words (code 2, a closed pipe is
/// success).
pub fn main(args: &BodeArgs, lang: Lang) -> ExitCode {
    super::exit_code(
        run_bode(args, lang),
        |e| match e {
            BodeCliError::Cli(c) => Some(c),
            _ => None,
        },
        lang,
    )
}
