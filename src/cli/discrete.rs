//! `degrau c2d` (the system flags of `degrau step` and `--ts`): the exact ZOH discretisation
//! of G(s)·e^{−θs}, fractional dead time included; `degrau d2c --num B --den A --nk N --ts H`:
//! back from H(z) = B(z⁻¹)/A(z⁻¹)·z^−nk (coefficients in powers of z⁻¹, as MATLAB's `arx`
//! writes them) to G(s) with its dead time, checked by c2d. `--json` on both (an infinite
//! static gain is `null` there, and words in the text).

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::lti::discrete::{DiscreteTf, c2d};
use crate::lti::parse::parse_real_list;
use crate::lti::{C64, TransferFunction, fmt_c};
use crate::text::Lang;
use crate::text::cli::StepPhrase;
use crate::text::lsq::LsqPhrase;
use crate::text::step::{IntegratorPole, static_gain_words};

use super::arx::LsqCliError;
use super::{CliError, StepArgs, SystemArgs, as_pairs};

/// `degrau c2d` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau c2d --num 2 --den 5,1 --delay 1.3 --ts 0.5
  degrau c2d --poles \"-1+2j,-1-2j\" --dc-gain 1 --ts 0.1 --json")]
pub struct C2dArgs {
    #[command(flatten)]
    pub system: SystemArgs,
    /// Sampling period h (s).
    #[arg(long, value_parser = super::finite_f64)]
    pub ts: f64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `degrau d2c` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau d2c --num 0.0784211,0.111904 --den 1,-0.904837 --nk 3 --ts 0.5 --json")]
pub struct D2cArgs {
    /// B: b1, b2, … (coefficients of z⁰, z⁻¹, … after the delay).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub num: String,
    /// A: 1, a1, a2, … (powers of z⁻¹).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub den: String,
    /// Delay of b1 in samples (0: b1 is a direct feedthrough, G biproper).
    #[arg(long, default_value_t = 1)]
    pub nk: usize,
    /// Sampling period h (s).
    #[arg(long, value_parser = super::finite_f64)]
    pub ts: f64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The discrete model's JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DiscreteJson {
    /// [1, a1, …].
    pub a: Vec<f64>,
    /// [b1, …].
    pub b: Vec<f64>,
    pub nk: usize,
    pub ts: f64,
    /// Poles in z as [re, im].
    pub poles: Vec<[f64; 2]>,
    pub dc_gain: f64,
}

/// The continuous model's JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContinuousJson {
    /// Descending powers of s.
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub zeros: Vec<[f64; 2]>,
    pub poles: Vec<[f64; 2]>,
    pub delay: f64,
    pub dc_gain: f64,
}

fn discrete_json(d: &DiscreteTf) -> Result<DiscreteJson, LsqCliError> {
    Ok(DiscreteJson {
        a: d.a().to_vec(),
        b: d.b().to_vec(),
        nk: d.nk(),
        ts: d.ts(),
        poles: as_pairs(&d.poles()?),
        dc_gain: d.dc_gain(),
    })
}

fn continuous_json(g: &TransferFunction) -> ContinuousJson {
    ContinuousJson {
        num: g.num(),
        den: g.den(),
        zeros: as_pairs(g.zeros()),
        poles: as_pairs(g.poles()),
        delay: g.delay(),
        dc_gain: g.dc_gain(),
    }
}

fn list(values: &[f64], lang: Lang) -> String {
    let v: Vec<String> = values.iter().map(|x| lang.num(*x, 8)).collect();
    v.join(", ")
}

/// The roots with every digit (a discrete pole 0.9999999999 must not read 1), or "none".
fn roots(values: &[C64], lang: Lang) -> String {
    if values.is_empty() {
        return StepPhrase::NoRoots.get(lang).to_string();
    }
    let v: Vec<String> = values
        .iter()
        .map(|z| lang.localize_number(&fmt_c(*z)))
        .collect();
    v.join(", ")
}

/// A static gain with 8 digits, or in words when a pole at `pole` makes it infinite.
fn static_gain(value: f64, pole: IntegratorPole, lang: Lang) -> String {
    static_gain_words(value, pole, lang).unwrap_or_else(|| lang.num(value, 8))
}

/// `degrau c2d`.
pub fn run_c2d(args: &C2dArgs, lang: Lang) -> Result<(), LsqCliError> {
    let step = StepArgs {
        system: args.system.clone(),
        ..StepArgs::default()
    };
    let tf = step.spec()?.transfer_function()?;
    let d = c2d(&tf, args.ts)?;
    let json = discrete_json(&d)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        super::write_json_line(&mut out, &json)
    } else {
        (|| {
            writeln!(out, "{}", LsqPhrase::DiscreteHeading.get(lang))?;
            writeln!(out, "A = [{}]", list(&json.a, lang))?;
            writeln!(out, "B = [{}]", list(&json.b, lang))?;
            writeln!(out, "{}: {}", LsqPhrase::Delay.get(lang), json.nk)?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::SamplingPeriod.get(lang),
                lang.num(d.ts(), 8)
            )?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::Poles.get(lang),
                roots(&d.poles().unwrap_or_default(), lang)
            )?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::StaticGain.get(lang),
                static_gain(d.dc_gain(), IntegratorPole::Z, lang)
            )
        })()
    };
    written.map_err(|e| LsqCliError::Cli(CliError::WriteOutput(e)))
}

/// `degrau d2c`.
pub fn run_d2c(args: &D2cArgs, lang: Lang) -> Result<(), LsqCliError> {
    let b = super::parse_list("--num", &args.num, parse_real_list)?;
    let a = super::parse_list("--den", &args.den, parse_real_list)?;
    let d = DiscreteTf::new(a, b, args.nk, args.ts)?;
    let g = d.d2c()?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        super::write_json_line(&mut out, &continuous_json(&g))
    } else {
        (|| {
            writeln!(out, "{}", LsqPhrase::ContinuousHeading.get(lang))?;
            writeln!(out, "num(s) = [{}]", list(&g.num(), lang))?;
            writeln!(out, "den(s) = [{}]", list(&g.den(), lang))?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::Poles.get(lang),
                roots(g.poles(), lang)
            )?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::DeadTime.get(lang),
                lang.num(g.delay(), 8)
            )?;
            writeln!(
                out,
                "{}: {}",
                LsqPhrase::StaticGain.get(lang),
                static_gain(g.dc_gain(), IntegratorPole::S, lang)
            )
        })()
    };
    written.map_err(|e| LsqCliError::Cli(CliError::WriteOutput(e)))
}
