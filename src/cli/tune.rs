//! `degrau tune`: PI or PID controllers for a first- or second-order plant with a dead time
//! (from the system flags of `degrau step`, or from a `degrau fit --json` output), by the
//! published rules (Ziegler–Nichols reaction curve and ultimate cycle, Cohen–Coon, IMC,
//! SIMC, AMIGO, Lambda: the lti crate's [`rule_table`]), each closed around the plant with
//! its dead time exact and judged on a setpoint step and a load step (overshoot, settling,
//! IAE; peak deviation and its time, IAE) and by its maximum sensitivity Ms. Text: one table,
//! a row per rule, then each rule's formula and source; or JSON (one object with `--rule`,
//! else a list), the same in every language.

use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Args;
use serde::Serialize;

use crate::lti::control::tuning::{ModelKind, formula, tune};
use crate::lti::control::{
    Action, ProcessModel, RowError, Rule, RuleRow, TunedLoop, Tuning, rule_table, tuned_loop,
};
use crate::text::control::{self as words, ControlWord, TuneWord};
use crate::text::{Lang, Localize};

use super::loop_controller::MetricKeys;
use super::tune_plant::{PlantError, model_of_fit_file, model_of_system};
use super::{CliError, SystemArgs, finite_f64};

const TUNE_EXAMPLES: &str = "\
Examples:
  degrau tune --num 1 --den 10,1 --delay 2
  degrau tune --num 1 --den 10,1 --delay 2 --rule simc --json
  degrau tune --poles -0.1,-0.5 --dc-gain 2 --delay 1 --controller pid --tc 2
  degrau fit record.csv --model P1D --json > fit.json && degrau tune --fit fit.json";

/// `degrau tune` options: the plant (system flags or `--fit`), the rule, the controller.
#[derive(Debug, Args)]
#[command(after_help = TUNE_EXAMPLES)]
pub struct TuneArgs {
    /// The plant, as for `degrau step`: no zeros, one or two real stable poles, a dead time.
    #[command(flatten)]
    pub system: SystemArgs,
    /// The plant from the JSON `degrau fit --json` wrote (a P1, P1D, P2 or P2D fit: its Kp,
    /// Tp1, Tp2 and Td), instead of the system flags.
    #[arg(
        long,
        value_name = "FILE.json",
        conflicts_with_all = ["poles", "zeros", "gain", "num", "den", "dc_gain", "delay"]
    )]
    pub fit: Option<PathBuf>,
    /// One rule (every rule when omitted).
    #[arg(
        long,
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<RuleArg>::new(),
            Rule::from
        )
    )]
    pub rule: Option<Rule>,
    /// The controller: pi (the default) or pid.
    #[arg(
        long,
        default_value = "pi",
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<TuneActionArg>::new(),
            Action::from
        )
    )]
    pub controller: Action,
    /// The closed-loop time constant τc of IMC and SIMC, and λ of Lambda tuning (s; default
    /// τc = θ, λ = τ or τ1); the other rules have none.
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64)]
    pub tc: Option<f64>,
    /// Print JSON instead of text: one object with --rule, else a list.
    #[arg(long)]
    pub json: bool,
}

/// A rule `--rule` takes: clap's side of [`Rule`] (the names are [`Rule::key`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum RuleArg {
    /// Ziegler–Nichols, reaction curve.
    ZnOpen,
    /// Ziegler–Nichols, ultimate cycle.
    ZnUltimate,
    /// Cohen–Coon.
    CohenCoon,
    /// Internal model control.
    Imc,
    /// Skogestad's IMC.
    Simc,
    /// Åström–Hägglund's AMIGO.
    Amigo,
    /// Lambda tuning.
    Lambda,
}

impl From<RuleArg> for Rule {
    fn from(r: RuleArg) -> Self {
        match r {
            RuleArg::ZnOpen => Rule::ZieglerNicholsOpen,
            RuleArg::ZnUltimate => Rule::ZieglerNicholsUltimate,
            RuleArg::CohenCoon => Rule::CohenCoon,
            RuleArg::Imc => Rule::Imc,
            RuleArg::Simc => Rule::Simc,
            RuleArg::Amigo => Rule::Amigo,
            RuleArg::Lambda => Rule::Lambda,
        }
    }
}

/// A controller `degrau tune --controller` takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TuneActionArg {
    /// Proportional and integral.
    Pi,
    /// Proportional, integral and derivative.
    Pid,
}

impl From<TuneActionArg> for Action {
    fn from(a: TuneActionArg) -> Self {
        match a {
            TuneActionArg::Pi => Action::PI,
            TuneActionArg::Pid => Action::PID,
        }
    }
}

/// What can go wrong in `degrau tune`.
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum TuneError {
    Cli(#[from] CliError),
    Plant(#[from] PlantError),
}

impl Localize for TuneError {
    fn text(&self, lang: Lang) -> String {
        match self {
            TuneError::Cli(e) => e.text(lang),
            TuneError::Plant(e) => e.text(lang),
        }
    }
}

/// The model of the flags: from `--fit` (with the fitted dead time when it was negative
/// and θ = 0 is used), or from the system flags.
pub fn model(args: &TuneArgs) -> Result<(ProcessModel, Option<f64>), TuneError> {
    if let Some(path) = &args.fit {
        return Ok(model_of_fit_file(path)?);
    }
    let step = super::StepArgs {
        system: args.system.clone(),
        ..Default::default()
    };
    let g = step.spec()?.transfer_function()?;
    Ok((model_of_system(&g)?, None))
}

/// The rows asked for: one rule's, or every rule's.
pub fn rows(args: &TuneArgs, model: &ProcessModel) -> Vec<RuleRow> {
    match args.rule {
        None => rule_table(model, args.controller, args.tc),
        Some(rule) => {
            let result = model
                .transfer_function()
                .map_err(RowError::Model)
                .and_then(|plant| {
                    let tuning = tune(model, rule, args.controller, args.tc)
                        .map_err(RowError::NotApplicable)?;
                    let tuned = tuned_loop(&plant, &tuning.controller).map_err(RowError::Loop)?;
                    Ok((tuning, tuned))
                });
            vec![RuleRow { rule, result }]
        }
    }
}

/// One rule's JSON: its controller and loop, or why it does not apply.
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub enum RuleJson {
    Applies(Box<TunedJson>),
    NotApplicable {
        rule: &'static str,
        applies: bool,
        reason: String,
    },
}

/// A rule's controller, its loop's metrics, its formula.
#[derive(Debug, Serialize)]
pub struct TunedJson {
    pub rule: &'static str,
    pub applies: bool,
    /// `pi` or `pid`.
    pub controller: &'static str,
    pub kc: f64,
    pub ti: f64,
    /// 0 for a PI.
    pub td: f64,
    /// `ideal`.
    pub form: &'static str,
    /// SIMC's series form [Kc, Ti, Td], when it gave one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series: Option<[f64; 3]>,
    /// The τc (IMC, SIMC) or λ (Lambda) used, null for the other rules.
    pub tc: Option<f64>,
    pub setpoint: MetricKeys,
    pub load: MetricKeys,
    /// Null when the loop is not stable.
    pub ms: Option<f64>,
    /// The closed loop has no root in the right half-plane (nor on the axis).
    pub stable: bool,
    /// The rule's equations (decimal points).
    pub formula: Option<String>,
    pub source: Option<String>,
}

impl RuleJson {
    pub fn new(row: &RuleRow, kind: ModelKind) -> Self {
        match &row.result {
            Ok((tuning, tuned)) => Self::Applies(Box::new(TunedJson::new(tuning, tuned, kind))),
            Err(e) => Self::NotApplicable {
                rule: row.rule.key(),
                applies: false,
                reason: e.text(Lang::En),
            },
        }
    }
}

impl TunedJson {
    fn new(tuning: &Tuning, tuned: &TunedLoop, kind: ModelKind) -> Self {
        let c = &tuning.controller;
        let f = formula(tuning.rule, c.action, kind).ok();
        Self {
            rule: tuning.rule.key(),
            applies: true,
            controller: c.action.key(),
            kc: c.kc,
            ti: c.ti,
            td: if c.action.derivative() { c.td } else { 0.0 },
            form: crate::lti::control::Form::Ideal.key(),
            series: tuning.series,
            tc: tuning.closed_loop_time_constant,
            setpoint: MetricKeys::new(&tuned.setpoint_metrics),
            load: MetricKeys::new(&tuned.load_metrics),
            ms: tuned.ms.filter(|m| m.is_finite()),
            stable: tuned.is_stable(),
            formula: f.map(|f| f.equations(Lang::En)),
            source: f.map(|f| f.source(Lang::En)),
        }
    }
}

/// The model's line: its kind and numbers.
fn model_line(model: &ProcessModel, lang: Lang) -> String {
    let n = |x: f64| lang.num(x, 6);
    let numbers = match *model {
        ProcessModel::Foptd { k, tau, theta } => {
            format!("K = {}, τ = {} s, θ = {} s", n(k), n(tau), n(theta))
        }
        ProcessModel::Soptd {
            k,
            tau1,
            tau2,
            theta,
        } => format!(
            "K = {}, τ1 = {} s, τ2 = {} s, θ = {} s",
            n(k),
            n(tau1),
            n(tau2),
            n(theta)
        ),
    };
    format!(
        "{}: {}, {numbers}",
        TuneWord::Model.get(lang),
        model.kind().text(lang)
    )
}

/// A table of cells, columns as wide as their widest cell, two spaces apart; a row's
/// `tail` (a reason in place of its numbers) is written after its first cell.
fn table(header: &[String], rows: &[(Vec<String>, Option<String>)]) -> Vec<String> {
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for (cells, _) in rows {
        for (w, c) in widths.iter_mut().zip(cells) {
            *w = (*w).max(c.chars().count());
        }
    }
    let line = |cells: &[String]| {
        cells
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c}{}", " ".repeat(w - c.chars().count())))
            .collect::<Vec<_>>()
            .join("  ")
            .trim_end()
            .to_string()
    };
    let mut lines = vec![line(header)];
    for (cells, tail) in rows {
        match tail {
            Some(reason) => {
                let first = &cells[0];
                let pad = widths[0].saturating_sub(first.chars().count());
                lines.push(format!("{first}{}  {reason}", " ".repeat(pad)));
            }
            None => lines.push(line(cells)),
        }
    }
    lines
}

/// The text report: the model, the table, the formulas.
pub fn human_report(model: &ProcessModel, action: Action, rows: &[RuleRow], lang: Lang) -> String {
    let n = |x: Option<f64>| {
        x.filter(|x| x.is_finite())
            .map_or("–".into(), |x| lang.num(x, 4))
    };
    let mut lines = vec![
        model_line(model, lang),
        words::tune_controller_line(action, lang),
        words::tune_loop_line(lang),
        String::new(),
    ];
    let header: Vec<String> = [
        TuneWord::RuleColumn.get(lang),
        "Kc",
        "Ti (s)",
        "Td (s)",
        TuneWord::OvershootColumn.get(lang),
        TuneWord::SettlingColumn.get(lang),
        "IAE",
        TuneWord::PeakDeviationColumn.get(lang),
        TuneWord::AtColumn.get(lang),
        "IAE",
        "Ms",
    ]
    .map(String::from)
    .to_vec();
    let cells: Vec<(Vec<String>, Option<String>)> = rows
        .iter()
        .map(|row| {
            let key = row.rule.key().to_string();
            match &row.result {
                Err(e) => (vec![key], Some(e.text(lang))),
                Ok((tuning, tuned)) => {
                    let c = &tuning.controller;
                    let (s, l) = (&tuned.setpoint_metrics, &tuned.load_metrics);
                    let ms = if tuned.is_stable() {
                        n(tuned.ms)
                    } else {
                        ControlWord::Unstable.get(lang).to_string()
                    };
                    let td = c.action.derivative().then_some(c.td);
                    (
                        vec![
                            key,
                            n(Some(c.kc)),
                            n(Some(c.ti)),
                            td.map_or("–".into(), |td| n(Some(td))),
                            n(s.overshoot),
                            n(s.settling_time),
                            n(s.iae),
                            n(l.peak.map(|p| p.value)),
                            n(l.peak.map(|p| p.time)),
                            n(l.iae),
                            ms,
                        ],
                        None,
                    )
                }
            }
        })
        .collect();
    let body = table(&header, &cells);
    // The responses' names over their columns.
    let col = |i: usize| {
        header[..i]
            .iter()
            .enumerate()
            .map(|(j, h)| {
                cells
                    .iter()
                    .filter(|(_, tail)| tail.is_none())
                    .map(|(c, _)| c[j].chars().count())
                    .fold(h.chars().count(), usize::max)
                    + 2
            })
            .sum::<usize>()
    };
    let (setpoint_at, load_at) = (col(4), col(7));
    let setpoint = TuneWord::SetpointColumns.get(lang);
    let gap = load_at
        .saturating_sub(setpoint_at + setpoint.chars().count())
        .max(1);
    lines.push(format!(
        "{}{setpoint}{}{}",
        " ".repeat(setpoint_at),
        " ".repeat(gap),
        TuneWord::LoadColumns.get(lang)
    ));
    lines.extend(body);
    lines.push(String::new());
    lines.push(TuneWord::Formulas.get(lang).to_string());
    for row in rows {
        lines.push(format!("{}: {}", row.rule.key(), row.rule.text(lang)));
        match formula(row.rule, action, model.kind()) {
            Ok(f) => {
                lines.push(format!("  {}", f.text(lang)));
                if let Ok((tuning, _)) = &row.result {
                    if let Some(tc) = tuning.closed_loop_time_constant {
                        lines.push(format!(
                            "  {}",
                            words::time_constant_line(row.rule, &lang.num(tc, 6), lang)
                        ));
                    }
                    if let Some([kc, ti, td]) = tuning.series {
                        let n6 = |x: f64| lang.num(x, 6);
                        lines.push(format!(
                            "  {}",
                            words::series_line([n6(kc), n6(ti), n6(td)], lang)
                        ));
                    }
                }
                lines.push(format!(
                    "  {}: {}",
                    ControlWord::Source.get(lang),
                    f.source(lang)
                ));
            }
            Err(e) => lines.push(format!("  {}", e.text(lang))),
        }
    }
    lines.join("\n")
}

/// `degrau tune`.
pub fn run_tune(args: &TuneArgs, lang: Lang) -> Result<(), TuneError> {
    let (model, negative_delay) = model(args)?;
    if let Some(td) = negative_delay {
        eprintln!("{}", words::negative_delay_note(&lang.num(td, 4), lang));
    }
    let rows = rows(args, &model);
    let mut out = io::stdout().lock();
    let written = if args.json {
        let json: Vec<RuleJson> = rows
            .iter()
            .map(|r| RuleJson::new(r, model.kind()))
            .collect();
        match (args.rule, json.as_slice()) {
            (Some(_), [one]) => serde_json::to_writer(&mut out, one),
            _ => serde_json::to_writer(&mut out, &json),
        }
        .map_err(io::Error::from)
        .and_then(|()| out.write_all(b"\n"))
    } else {
        writeln!(
            out,
            "{}",
            human_report(&model, args.controller, &rows, lang)
        )
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| TuneError::Cli(CliError::WriteOutput(e)))
}

/// The exit code of `degrau tune`, its error printed in words.
pub fn main(args: &TuneArgs, lang: Lang) -> ExitCode {
    super::exit_code(
        run_tune(args, lang),
        |e| match e {
            TuneError::Cli(c) => Some(c),
            _ => None,
        },
        lang,
    )
}
