//! `degrau margins`: the stability margins of the unity-feedback loop L(s) = C(s)·G(s), the
//! plant given as for `degrau step` with its dead time kept exact, the controller P (the
//! default, Kc = 1), PI, PD or PID as for `degrau loop --controller`: the gain margin and
//! its phase crossover, the phase margin and its gain crossover (the smallest, as MATLAB's
//! `margin`), the delay margin, Ms and the closed loop's −3 dB bandwidth, with every
//! crossing found ([`crate::lti::control::margins`]). Text, or one JSON object with stable
//! keys; an infinite margin is written "inf" in the JSON, as `degrau loop` writes ∞.

use std::io::{self, Write};
use std::process::ExitCode;

use clap::Args;
use serde::Serialize;

use crate::lti::control::{
    Action, GainCrossing, Margins, Nyquist, PhaseCrossing, StabilityError, margins, nyquist,
};
use crate::lti::feedback::Limit;
use crate::text::margins::MarginLine;
use crate::text::{Lang, Localize};

use super::loop_cmd::{LoopArgs, LoopError};
use super::loop_controller::{ActionArg, ControllerFlags, controller_of};
use super::{CliError, finite_f64};

const MARGINS_EXAMPLES: &str = "\
Examples:
  degrau margins --num 1 --den 1,3,2,0 --kc 2
  degrau margins --num 1 --den 10,1 --delay 2 --controller pi --kc 2.5 --ti 10 --json";

/// `degrau margins` options: the plant as for `degrau step`, then the controller.
#[derive(Debug, Default, Args)]
#[command(after_help = MARGINS_EXAMPLES)]
pub struct MarginsArgs {
    #[command(flatten)]
    pub system: super::SystemArgs,
    /// The controller: p (the default), pi, pd or pid, in the ideal form
    /// Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N)).
    #[arg(
        long,
        value_name = "ACTION",
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<ActionArg>::new(),
            Action::from
        )
    )]
    pub controller: Option<Action>,
    /// The controller gain Kc (default 1).
    #[arg(long, value_name = "KC", allow_hyphen_values = true, value_parser = finite_f64)]
    pub kc: Option<f64>,
    /// With --controller pi or pid: the integral time Ti (s).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64)]
    pub ti: Option<f64>,
    /// With --controller pd or pid: the derivative time Td (s).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64)]
    pub td: Option<f64>,
    /// With --controller pd or pid: the derivative filter N, Tf = Td/N (default 10).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = finite_f64)]
    pub n: Option<f64>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

/// The crossings of the JSON report.
#[derive(Debug, Serialize)]
pub struct Crossings<'a> {
    pub phase: &'a [PhaseCrossing],
    pub gain: &'a [GainCrossing],
}

/// The JSON report: infinite margins as "inf", a missing crossover frequency as null.
#[derive(Debug, Serialize)]
pub struct MarginsReport<'a> {
    pub gm: Limit,
    pub gm_db: Limit,
    pub w_pc: Option<f64>,
    pub pm: Limit,
    pub w_gc: Option<f64>,
    pub delay_margin: Limit,
    /// Null unless the closed loop is stable.
    pub ms: Option<f64>,
    /// Null when |T(0)| is 0 or infinite.
    pub bandwidth: Option<Limit>,
    pub crossings: Crossings<'a>,
    /// The Nyquist criterion; null when it could not be counted.
    pub nyquist: Option<NyquistCount>,
}

/// The Nyquist criterion's numbers: Z = N + P.
#[derive(Debug, Serialize)]
pub struct NyquistCount {
    /// N, clockwise encirclements of −1.
    pub encirclements: i64,
    /// P, open-loop poles in the right half-plane.
    pub open_loop_unstable: usize,
    /// Z, closed-loop poles in the right half-plane.
    pub closed_loop_unstable: i64,
}

fn limit(x: f64) -> Limit {
    if x.is_finite() {
        Limit::Finite(x)
    } else {
        Limit::Infinite
    }
}

impl<'a> MarginsReport<'a> {
    pub fn new(m: &'a Margins, ny: &Result<Nyquist, StabilityError>) -> Self {
        Self {
            gm: limit(m.gm),
            gm_db: limit(m.gm_db),
            w_pc: m.w_pc,
            pm: limit(m.pm),
            w_gc: m.w_gc,
            delay_margin: limit(m.delay_margin),
            ms: m.ms,
            bandwidth: m.bandwidth.map(limit),
            crossings: Crossings {
                phase: &m.phase_crossings,
                gain: &m.gain_crossings,
            },
            nyquist: ny.as_ref().ok().map(|n| NyquistCount {
                encirclements: n.encirclements,
                open_loop_unstable: n.open_loop_unstable,
                closed_loop_unstable: n.closed_loop_unstable,
            }),
        }
    }
}

/// What `degrau margins` reports of a loop.
struct Computed {
    plant: String,
    margins: Margins,
    nyquist: Result<Nyquist, StabilityError>,
}

/// The plant and the controller of the flags, their margins and the Nyquist count.
fn compute(args: &MarginsArgs) -> Result<Computed, LoopError> {
    let action = args.controller.unwrap_or(Action::P);
    let loop_args = LoopArgs {
        system: args.system.clone(),
        control: ControllerFlags {
            controller: Some(action),
            kc: Some(args.kc.unwrap_or(1.0)),
            ti: args.ti,
            td: args.td,
            n: args.n,
            ..Default::default()
        },
        ..Default::default()
    };
    let plant = loop_args.spec()?.transfer_function()?;
    let c = controller_of(&loop_args, action)?;
    Ok(Computed {
        plant: plant.describe_rounded(),
        margins: margins(&plant, &c),
        nyquist: nyquist(&plant, &c),
    })
}

/// The text report's lines.
fn text_lines(
    plant: &str,
    m: &Margins,
    ny: &Result<Nyquist, StabilityError>,
    lang: Lang,
) -> Vec<String> {
    let mut lines = vec![MarginLine::Loop(plant.to_string())];
    lines.push(match m.w_pc {
        Some(w) => MarginLine::Gain {
            gm: m.gm,
            gm_db: m.gm_db,
            w,
        },
        None => MarginLine::NoPhaseCrossover,
    });
    lines.push(match m.w_gc {
        Some(w) => MarginLine::Phase { pm: m.pm, w },
        None => MarginLine::NoGainCrossover,
    });
    lines.push(MarginLine::Delay(m.delay_margin));
    lines.push(m.ms.map_or(MarginLine::NoSensitivity, MarginLine::Sensitivity));
    lines.push(
        m.bandwidth
            .map_or(MarginLine::NoBandwidth, MarginLine::Bandwidth),
    );
    lines.push(MarginLine::Crossings {
        phase: m.phase_crossings.len(),
        gain: m.gain_crossings.len(),
    });
    lines.push(match ny {
        Ok(n) => MarginLine::Nyquist {
            n: n.encirclements,
            p: n.open_loop_unstable,
            z: n.closed_loop_unstable,
        },
        Err(e) => MarginLine::NoNyquist(e.text(lang)),
    });
    lines.iter().map(|l| l.text(lang)).collect()
}

fn run(args: &MarginsArgs, lang: Lang) -> Result<(), LoopError> {
    let c = compute(args)?;
    let out = if args.json {
        serde_json::to_string(&MarginsReport::new(&c.margins, &c.nyquist))
            .map_err(|e| CliError::JsonFields(e.to_string()))?
    } else {
        text_lines(&c.plant, &c.margins, &c.nyquist, lang).join("\n")
    };
    writeln!(io::stdout().lock(), "{out}").map_err(CliError::WriteOutput)?;
    Ok(())
}

/// Runs `degrau margins`: 0 on success, 2 on bad input.
pub fn main(args: &MarginsArgs, lang: Lang) -> ExitCode {
    super::exit_code(
        run(args, lang),
        |e| match e {
            LoopError::Cli(c) => Some(c),
            _ => None,
        },
        lang,
    )
}
