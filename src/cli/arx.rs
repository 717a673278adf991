//! `degrau arx FILE --na N --nb N --nk N`: least squares on the samples of a record (the
//! data flags of `degrau fit`), with `--select` for the AIC grid and `--validate FRACTION`
//! for an estimation/validation split. Also the pieces `degrau rls` shares: the error type
//! of the least-squares commands, the model's JSON keys and its text table.

use std::io::{self, Write};
use std::process::ExitCode;

use clap::{Args, ValueEnum};
use serde::Serialize;

use crate::ident::lsq::arx::{
    ArxModel, ArxOrders, Candidate, LeastSquares, LsqError, Offset, Regression, Scores, arx,
    default_grid, select_orders,
};
use crate::ident::lsq::prbs::PrbsError;
use crate::ident::lsq::validation::{ArxValidation, Split, score_arx, split_index};
use crate::lti::discrete::DiscreteError;
use crate::text::cli::StepPhrase;
use crate::text::lsq::{LsqPhrase, parameter_name, percent};
use crate::text::{Lang, Localize};

use super::CliError;
use super::fit::DataArgs;

/// What stops a least-squares command (`crate::text::lsq` says it).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum LsqCliError {
    Cli(#[from] CliError),
    /// The file has no input column.
    NoInput,
    /// `--levels` is not two numbers.
    Levels(String),
    Lsq(#[from] LsqError),
    Discrete(#[from] DiscreteError),
    Prbs(#[from] PrbsError),
}

/// The exit code of a least-squares command, its error printed in words.
pub fn finish(result: Result<(), LsqCliError>, lang: Lang) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(LsqCliError::Cli(CliError::WriteOutput(e)))
            if e.kind() == io::ErrorKind::BrokenPipe =>
        {
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{}: {}", StepPhrase::Error.get(lang), e.text(lang));
            ExitCode::from(2)
        }
    }
}

/// `--offset`, as typed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, ValueEnum)]
pub enum OffsetArg {
    /// u − u0, y − y0 with the means before the input's first change.
    #[default]
    Initial,
    /// A constant regressor estimated with the others.
    Constant,
    /// The samples as they are.
    None,
}

impl From<OffsetArg> for Offset {
    fn from(o: OffsetArg) -> Self {
        match o {
            OffsetArg::Initial => Offset::Initial,
            OffsetArg::Constant => Offset::Constant,
            OffsetArg::None => Offset::None,
        }
    }
}

/// The orders and the operating point (shared by `arx` and `rls`).
#[derive(Debug, Clone, Args)]
pub struct OrderArgs {
    /// Number of a's (poles).
    #[arg(long, default_value_t = 1)]
    pub na: usize,
    /// Number of b's.
    #[arg(long, default_value_t = 1)]
    pub nb: usize,
    /// Delay of b1 in samples (1: the plain delay of a zero-order hold).
    #[arg(long, default_value_t = 1)]
    pub nk: usize,
    /// The operating point: initial (subtract the means before the input's first change),
    /// constant (estimate a constant term) or none.
    #[arg(long, value_enum, default_value_t = OffsetArg::Initial)]
    pub offset: OffsetArg,
    /// Estimate on this share of the samples (0 to 1) and validate on the rest.
    #[arg(long, value_name = "FRACTION", value_parser = super::finite_f64)]
    pub validate: Option<f64>,
}

impl OrderArgs {
    pub fn orders(&self) -> ArxOrders {
        ArxOrders::new(self.na, self.nb, self.nk)
    }
}

/// `degrau arx` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau arx tclab_step_q1_50.csv --y-col T1 --u-col Q1 --na 1 --nb 1 --nk 4
  degrau arx prbs.csv --na 2 --nb 2 --nk 1 --validate 0.5 --json
  degrau arx prbs.csv --select --json")]
pub struct ArxArgs {
    #[command(flatten)]
    pub data: DataArgs,
    #[command(flatten)]
    pub orders: OrderArgs,
    /// Choose the orders by AIC over na, nb in 1..=3 and nk in 0..=MAX_NK (then fit the best).
    #[arg(long)]
    pub select: bool,
    /// The largest delay of the --select grid (samples).
    #[arg(long, default_value_t = 5)]
    pub max_nk: usize,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The record's columns: time (s), u, y.
pub type Columns = (Vec<f64>, Vec<f64>, Vec<f64>);

/// Loads the record's columns.
pub fn columns(data: &DataArgs) -> Result<Columns, LsqCliError> {
    let test = data.samples()?;
    let u = test.input.ok_or(LsqCliError::NoInput)?;
    Ok((test.time, u, test.output))
}

/// The validation part, scored, as the JSON writes it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ValidationJson {
    /// The first validation sample (0-based).
    pub split: usize,
    pub estimation_fit_percent_prediction: f64,
    pub estimation_fit_percent_simulation: f64,
    pub fit_percent_prediction: f64,
    pub fit_percent_simulation: f64,
    /// The validation part's one-step errors look white.
    pub residuals_white: bool,
}

impl From<&ArxValidation> for ValidationJson {
    fn from(v: &ArxValidation) -> Self {
        Self {
            split: v.split,
            estimation_fit_percent_prediction: v.estimation.fit_percent_prediction,
            estimation_fit_percent_simulation: v.estimation.fit_percent_simulation,
            fit_percent_prediction: v.validation.fit_percent_prediction,
            fit_percent_simulation: v.validation.fit_percent_simulation,
            residuals_white: v.residuals.white,
        }
    }
}

/// The ARX object of the JSON outputs (stable keys).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ArxJson {
    pub na: usize,
    pub nb: usize,
    pub nk: usize,
    /// [1, a1, …].
    pub a: Vec<f64>,
    pub b: Vec<f64>,
    /// The constant term, with `--offset constant`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub constant: Option<f64>,
    /// Standard errors of [a1 … b_nb (c)], null when N = p.
    pub se: Vec<Option<f64>>,
    /// J, null beyond double precision (a record near 1e±300), when `j_log10` gives it.
    pub j: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub j_log10: Option<f64>,
    /// Fit %s, null when undefined (a constant output) or when the model's output diverges.
    pub fit_percent_prediction: f64,
    pub fit_percent_simulation: f64,
    pub aic: f64,
    /// Rows of Φ.
    pub n: usize,
    /// Sampling period h (s).
    pub ts: f64,
    pub u0: f64,
    pub y0: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub candidates: Option<Vec<Candidate>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub validation: Option<ValidationJson>,
}

/// The figures every least-squares model reports, whichever way it was estimated.
pub struct Figures<'a> {
    pub model: &'a ArxModel,
    pub offset: Offset,
    pub regression: &'a Regression,
    /// θ's standard errors and J.
    pub estimate: &'a LeastSquares,
    pub scores: &'a Scores,
    pub aic: f64,
}

impl ArxJson {
    pub fn new(f: &Figures) -> Self {
        let m = f.model;
        Self {
            na: m.orders.na,
            nb: m.orders.nb,
            nk: m.orders.nk,
            a: m.a.clone(),
            b: m.b.clone(),
            constant: (f.offset == Offset::Constant).then_some(m.constant),
            se: f.estimate.se.clone(),
            j: f.estimate.cost.value(),
            j_log10: f
                .estimate
                .cost
                .value()
                .is_none()
                .then(|| f.estimate.cost.log10()),
            fit_percent_prediction: f.scores.fit_percent_prediction,
            fit_percent_simulation: f.scores.fit_percent_simulation,
            aic: f.aic,
            n: f.regression.y.len(),
            ts: m.ts,
            u0: m.u0,
            y0: m.y0,
            candidates: None,
            validation: None,
        }
    }
}

/// The text table of a model's figures.
pub fn write_figures(out: &mut impl Write, f: &Figures, lang: Lang) -> io::Result<()> {
    let m = f.model;
    let num = |x: f64| lang.num(x, 6);
    let p = |x: LsqPhrase| x.get(lang);
    writeln!(
        out,
        "{}: na = {}, nb = {}, nk = {}",
        p(LsqPhrase::Orders),
        m.orders.na,
        m.orders.nb,
        m.orders.nk
    )?;
    writeln!(out, "{}: {}", p(LsqPhrase::SamplingPeriod), num(m.ts))?;
    let regressors: Vec<String> = f
        .regression
        .regressors
        .iter()
        .map(|&r| crate::text::lsq::regressor_symbol(r))
        .collect();
    writeln!(
        out,
        "{}: [{}]",
        p(LsqPhrase::Regressors),
        regressors.join("  ")
    )?;
    writeln!(out, "{}: {}", p(LsqPhrase::Rows), f.regression.y.len())?;
    if f.offset == Offset::Initial {
        writeln!(
            out,
            "{}: {}, {}",
            p(LsqPhrase::OperatingPoint),
            num(m.u0),
            num(m.y0)
        )?;
    }
    writeln!(
        out,
        "{:<10} {:>16} {:>16}",
        p(LsqPhrase::Parameter),
        p(LsqPhrase::Value),
        p(LsqPhrase::StandardError)
    )?;
    let theta = m.theta();
    for ((r, value), se) in f
        .regression
        .regressors
        .iter()
        .zip(&theta)
        .zip(&f.estimate.se)
    {
        let se = se.map_or_else(|| "—".to_string(), num);
        writeln!(
            out,
            "{:<10} {:>16} {:>16}",
            parameter_name(*r, m.orders.nk),
            num(*value),
            se
        )?;
    }
    writeln!(
        out,
        "{}: {}",
        p(LsqPhrase::Cost),
        crate::text::lsq::cost(&f.estimate.cost, lang)
    )?;
    writeln!(
        out,
        "{}: {}",
        p(LsqPhrase::FitPrediction),
        percent(f.scores.fit_percent_prediction, lang)
    )?;
    writeln!(
        out,
        "{}: {}",
        p(LsqPhrase::FitSimulation),
        percent(f.scores.fit_percent_simulation, lang)
    )?;
    writeln!(out, "{}: {}", p(LsqPhrase::Aic), lang.num(f.aic, 6))
}

/// The validation lines of the text report.
pub fn write_validation(out: &mut impl Write, v: &ValidationJson, lang: Lang) -> io::Result<()> {
    let p = |x: LsqPhrase| x.get(lang);
    let pct = |x: f64| percent(x, lang);
    writeln!(
        out,
        "{} ({} 1..{}): {} {}, {} {}",
        p(LsqPhrase::Estimation),
        p(LsqPhrase::Samples).to_lowercase(),
        v.split,
        p(LsqPhrase::FitPrediction),
        pct(v.estimation_fit_percent_prediction),
        p(LsqPhrase::FitSimulation),
        pct(v.estimation_fit_percent_simulation)
    )?;
    writeln!(
        out,
        "{} ({} {}..): {} {}, {} {}; {}: {}",
        p(LsqPhrase::Validation),
        p(LsqPhrase::Samples).to_lowercase(),
        v.split + 1,
        p(LsqPhrase::FitPrediction),
        pct(v.fit_percent_prediction),
        p(LsqPhrase::FitSimulation),
        pct(v.fit_percent_simulation),
        p(LsqPhrase::ResidualsWhite),
        p(if v.residuals_white {
            LsqPhrase::Yes
        } else {
            LsqPhrase::No
        })
    )
}

/// The estimation part's end (exclusive) for `--validate`, or the whole record.
pub fn estimation_end(time: &[f64], validate: Option<f64>) -> Result<usize, LsqError> {
    match validate {
        Some(f) => split_index(time, Split::Fraction(f)),
        None => Ok(time.len()),
    }
}

/// `degrau arx`.
pub fn run_arx(args: &ArxArgs, lang: Lang) -> Result<(), LsqCliError> {
    let (time, u, y) = columns(&args.data)?;
    let offset: Offset = args.orders.offset.into();
    let end = estimation_end(&time, args.orders.validate)?;
    let (t_est, u_est, y_est) = (&time[..end], &u[..end], &y[..end]);
    let candidates = if args.select {
        let grid = default_grid(args.max_nk, y_est.len())?;
        Some(select_orders(t_est, u_est, y_est, &grid, offset)?)
    } else {
        None
    };
    let orders = candidates
        .as_ref()
        .and_then(|c| c.first())
        .map_or(args.orders.orders(), |c| c.orders);
    let fit = arx(t_est, u_est, y_est, orders, offset)?;
    let validation = args
        .orders
        .validate
        .map(|_| ValidationJson::from(&score_arx(&fit.model, &time, &u, &y, end)));
    let figures = Figures {
        model: &fit.model,
        offset,
        regression: &fit.regression,
        estimate: &fit.lsq,
        scores: &fit.scores,
        aic: fit.aic,
    };
    let mut out = io::stdout().lock();
    let written = if args.json {
        let mut json = ArxJson::new(&figures);
        json.candidates = candidates;
        json.validation = validation;
        super::write_json_line(&mut out, &json)
    } else {
        write_text(
            &mut out,
            &figures,
            candidates.as_deref(),
            validation.as_ref(),
            lang,
        )
    };
    written.map_err(|e| LsqCliError::Cli(CliError::WriteOutput(e)))
}

fn write_text(
    out: &mut impl Write,
    figures: &Figures,
    candidates: Option<&[Candidate]>,
    validation: Option<&ValidationJson>,
    lang: Lang,
) -> io::Result<()> {
    writeln!(out, "{}", LsqPhrase::ArxHeading.get(lang))?;
    if let Some(c) = candidates {
        writeln!(out, "{}:", LsqPhrase::Candidates.get(lang))?;
        for c in c.iter().take(5) {
            let exact = if c.exact {
                format!(" ({})", LsqPhrase::ExactFit.get(lang))
            } else {
                String::new()
            };
            writeln!(
                out,
                "  na = {}, nb = {}, nk = {}: AIC {}, {} {}{exact}",
                c.orders.na,
                c.orders.nb,
                c.orders.nk,
                lang.num(c.aic, 6),
                LsqPhrase::FitSimulation.get(lang),
                percent(c.fit_percent_simulation, lang)
            )?;
        }
    }
    write_figures(out, figures, lang)?;
    if let Some(v) = validation {
        write_validation(out, v, lang)?;
    }
    Ok(())
}
