//! `degrau approx`: a system (the flags of `degrau step`) replaced by a simpler model with
//! one of the notes' methods (`--method dominant|taylor|skogestad|pade`, `--order n` or
//! `m,n`), and what it costs: the largest gap relative to the step's effect, the ISE, each
//! step metric's difference (text, or `--json` with the keys `method`, `num`, `den`,
//! `delay`, `max_error`, `ise`, `metrics`, `metrics_error`).
//!
//! `degrau pade --delay θ --order m,n`: the Padé (m, n) polynomials of e^{−θs}, in the
//! notes' scaling (constant term (m + n)!/m!), text or `--json` (keys `num`, `den`).
//!
//! Exit codes as `degrau step`: 0 success, 2 bad input.

use std::collections::BTreeMap;
use std::io::{self, Write};
use std::process::ExitCode;

use clap::{Args, ValueEnum};
use serde::Serialize;

use super::{CliError, Samples, StepArgs, as_pairs, finite_f64, write_json_line};
use crate::lti::approx::{
    self, ApproxError, Approximated, Approximation, Method, MetricDifference, Reduction,
    pade_coefficients,
};
use crate::lti::poly::format_poly;
use crate::lti::root_error;
use crate::lti::{C64, StepInfo, StepResponse, TransferFunction, fmt_c};
use crate::text::approx::{ApproxPhrase as P, error_header, error_row, formula, measures, name};
use crate::text::cli::StepPhrase;
use crate::text::step::Metric;
use crate::text::{Lang, Localize};

const APPROX_EXAMPLES: &str = "\
Examples:
  degrau approx --zeros 10 --poles \"-0.2,-0.333333333333333,-2\" --dc-gain 2 --method skogestad
  degrau approx --num 1 --den 2,60,704,4144,12840,18000 --method dominant --order 2 --json
  degrau approx --num 2 --den 10,11,1 --method pade --order 1,1
  degrau pade --delay 0.5 --order 2,2";

/// The reduction methods, as `--method` spells them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Keep the poles nearest the imaginary axis, the zeros near them and the static gain.
    Dominant,
    /// Neglected lags and right-half-plane zeros become dead time.
    Taylor,
    /// Skogestad's half rule.
    Skogestad,
    /// Padé moment matching G_{m,n} at s = 0.
    Pade,
}

impl From<MethodArg> for Method {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Dominant => Method::Dominant,
            MethodArg::Taylor => Method::Taylor,
            MethodArg::Skogestad => Method::Skogestad,
            MethodArg::Pade => Method::Pade,
        }
    }
}

/// `degrau approx` options: the system flags of `degrau step`, the method and its order.
#[derive(Debug, Args)]
#[command(after_help = APPROX_EXAMPLES)]
pub struct ApproxArgs {
    #[command(flatten)]
    pub system: StepArgs,
    /// The reduction method.
    #[arg(long, value_enum)]
    pub method: MethodArg,
    /// The model's order n, or m,n for Padé (numerator degree m ≤ n; a single n means n,n).
    /// Default: 2 for dominant, 1 for taylor and skogestad, 1,1 for pade.
    #[arg(long, value_name = "N|M,N")]
    pub order: Option<String>,
    /// After the report, every method compared in one Markdown table (text output only).
    #[arg(long, conflicts_with = "json")]
    pub table: bool,
}

/// `degrau pade` options.
#[derive(Debug, Args)]
pub struct PadeArgs {
    /// The dead time θ in seconds (> 0).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64)]
    pub delay: f64,
    /// m,n (numerator and denominator degrees, m ≤ n), or n for n,n as MATLAB's pade(θ, n).
    #[arg(long, value_name = "M,N", default_value = "1,1")]
    pub order: String,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

/// What can go wrong in `degrau approx` and `degrau pade` (said by
/// `crate::text::approx`; `Display` is English).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum ApproxCliError {
    /// The system flags, as `degrau step` refuses them.
    Cli(#[from] CliError),
    Approx(#[from] ApproxError),
    /// `--order` is not `n` or `m,n` with whole numbers.
    BadOrder(String),
    /// `--batch` belongs to `degrau step`.
    Batch,
}

impl From<crate::lti::LtiError> for ApproxCliError {
    fn from(e: crate::lti::LtiError) -> Self {
        ApproxCliError::Cli(CliError::Lti(e))
    }
}

/// `--order`: one whole number n or two, m,n.
pub fn parse_order(text: &str) -> Result<(Option<usize>, usize), ApproxCliError> {
    let bad = || ApproxCliError::BadOrder(text.to_string());
    let numbers: Vec<usize> = text
        .split(',')
        .map(|part| part.trim().parse::<usize>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    match *numbers.as_slice() {
        [n] => Ok((None, n)),
        [m, n] => Ok((Some(m), n)),
        _ => Err(bad()),
    }
}

/// The reduction `--method` and `--order` ask for.
pub fn reduction(method: Method, order: Option<&str>) -> Result<Reduction, ApproxCliError> {
    let default = method.default_reduction();
    let Some(text) = order else {
        return Ok(default);
    };
    let (m, n) = parse_order(text)?;
    Ok(match (method, m) {
        (Method::Pade, m) => Reduction {
            method,
            m: m.unwrap_or(n),
            n,
        },
        (_, Some(_)) => return Err(ApproxCliError::BadOrder(text.to_string())),
        (_, None) => Reduction { method, m: 0, n },
    })
}

/// The system, its approximation and the comparison.
pub struct ApproxRun {
    pub original: TransferFunction,
    /// Every method compared, when `--table` asks.
    pub table: Option<Vec<approx::Row>>,
    pub reduction: Reduction,
    pub approximated: Approximated,
    /// y(t) of the original and of the model at the same instants, when asked.
    pub samples: Option<(Samples, Vec<f64>)>,
}

/// Runs the approximation the flags describe.
pub fn approximate(args: &ApproxArgs) -> Result<ApproxRun, ApproxCliError> {
    if args.system.batch {
        return Err(ApproxCliError::Batch);
    }
    let options = args.system.options()?;
    let reduction = reduction(args.method.into(), args.order.as_deref())?;
    let spec = args.system.spec()?;
    let original = spec.transfer_function()?;
    let response = StepResponse::new(&original, spec.amplitude.unwrap_or(1.0))?;
    let approximated = approx::approximate(
        &original,
        &response,
        Approximation::Reduce(reduction),
        &options,
    )?;
    super::finite_metrics(&approximated.comparison.original)?;
    super::finite_metrics(&approximated.comparison.approx)?;
    let samples = match spec.samples {
        None => None,
        Some(n) => {
            if !(2..=super::MAX_SAMPLES).contains(&n) {
                return Err(CliError::Samples(n).into());
            }
            let horizon = approximated.comparison.horizon;
            let (t, y) = response.sample_uniform(0.0, horizon, n);
            let y_approx = approximated.response.sample(&t);
            if y_approx.iter().any(|v| !v.is_finite()) {
                return Err(CliError::ResponseBeyondRange.into());
            }
            Some((Samples::checked(t, y)?, y_approx))
        }
    };
    let table = args
        .table
        .then(|| approx::table(&original, &response, &options));
    Ok(ApproxRun {
        table,
        original,
        reduction,
        approximated,
        samples,
    })
}

/// The JSON key of a step metric (as `degrau step` names it).
pub fn metric_key(m: Metric) -> &'static str {
    match m {
        Metric::RiseTime => "rise_time",
        Metric::SettlingTime => "settling_time",
        Metric::Overshoot => "overshoot",
        Metric::Undershoot => "undershoot",
        Metric::Peak => "peak",
        Metric::PeakTime => "peak_time",
        Metric::SteadyState => "steady_state",
        Metric::SettlingMin => "settling_min",
        Metric::SettlingMax => "settling_max",
    }
}

/// The JSON report of `degrau approx`.
#[derive(Debug, Serialize)]
pub struct ApproxReport {
    pub method: &'static str,
    /// The reduction asked: [m, n] (m is Padé's numerator degree, 0 for the others).
    pub asked: [usize; 2],
    /// The model's order (a dominant pair cut in two is kept whole).
    pub order: usize,
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub delay: f64,
    pub zeros: Vec<[f64; 2]>,
    pub poles: Vec<[f64; 2]>,
    /// The static gain G(0) of the model (null when it integrates).
    pub dc_gain: Option<f64>,
    /// The model in the notes' time-constant form.
    pub formula: String,
    /// max |y − ŷ| over the step's effect (a fraction), and when (s).
    pub max_error: f64,
    pub max_error_time: f64,
    /// ∫ (y − ŷ)² dt over [0, horizon]; null beyond double precision (a response near
    /// 1e±160), when `ise_log10` gives its order of magnitude.
    pub ise: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ise_log10: Option<f64>,
    pub horizon: f64,
    /// The step metrics of the model's exact response.
    pub metrics: StepInfo,
    /// The original's.
    pub original_metrics: StepInfo,
    /// Each metric: original, approx, difference, relative, within (5 %).
    pub metrics_error: BTreeMap<&'static str, MetricDifference>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<ApproxSamples>,
}

/// y(t) of both systems at the same instants.
#[derive(Debug, Serialize)]
pub struct ApproxSamples {
    pub t: Vec<f64>,
    pub y: Vec<f64>,
    pub y_approx: Vec<f64>,
}

impl ApproxReport {
    pub fn new(run: &ApproxRun) -> Self {
        let model = &run.approximated.model;
        let c = &run.approximated.comparison;
        let dc = model.dc_gain();
        Self {
            method: run.reduction.method.key(),
            asked: [run.reduction.m, run.reduction.n],
            order: model.order(),
            num: model.num(),
            den: model.den(),
            delay: model.delay(),
            zeros: as_pairs(model.zeros()),
            poles: as_pairs(model.poles()),
            dc_gain: dc.is_finite().then_some(dc),
            formula: formula(model, Lang::En),
            max_error: c.max_error,
            max_error_time: c.max_error_time,
            ise: c.ise_value(),
            ise_log10: c.ise_value().is_none().then(|| c.ise_log10()),
            horizon: c.horizon,
            metrics: c.approx.clone(),
            original_metrics: c.original.clone(),
            metrics_error: c
                .metrics
                .iter()
                .map(|d| (metric_key(d.metric), d.clone()))
                .collect(),
            samples: run.samples.as_ref().map(|(s, y_approx)| ApproxSamples {
                t: s.t.clone(),
                y: s.y.clone(),
                y_approx: y_approx.clone(),
            }),
        }
    }
}

/// Roots as `-1+2j`, joined, or "none".
fn roots_text(roots: &[C64], lang: Lang) -> String {
    if roots.is_empty() {
        return P::NoRoots.get(lang).to_string();
    }
    roots
        .iter()
        .map(|&r| lang.localize_number(&fmt_c(r)))
        .collect::<Vec<_>>()
        .join(lang.pick(", ", "; "))
}

/// `num / den · e^(-θ s)` in descending powers.
fn polynomial_form(tf: &TransferFunction) -> String {
    let delay = if tf.delay() > 0.0 {
        format!(
            " · e^(-{} s)",
            crate::lti::number::format_number(tf.delay())
        )
    } else {
        String::new()
    };
    format!(
        "({}) / ({}){delay}",
        format_poly(&tf.num()),
        format_poly(&tf.den())
    )
}

/// The text report: the original, the model (time-constant and polynomial forms, poles,
/// zeros), the two error measures and the error table.
pub fn human_report(run: &ApproxRun, lang: Lang) -> String {
    let model = &run.approximated.model;
    let c = &run.approximated.comparison;
    let mut lines = vec![
        format!(
            "{}: G(s) = {}",
            P::Original.get(lang),
            formula(&run.original, lang)
        ),
        format!(
            "{}: {}",
            P::ReducedModel.get(lang),
            name(&Approximation::Reduce(run.reduction), lang)
        ),
        format!("  G~(s) = {}", formula(model, lang)),
        format!("  G~(s) = {}", polynomial_form(model)),
        format!(
            "  {}: {}",
            P::Poles.get(lang),
            roots_text(model.poles(), lang)
        ),
        format!(
            "  {}: {}",
            crate::text::cli::ZEROS,
            roots_text(model.zeros(), lang)
        ),
        String::new(),
        format!("{}:", P::Errors.get(lang)),
    ];
    lines.extend(measures(c, lang).map(|l| format!("  {l}")));
    lines.push(String::new());
    let rows: Vec<[String; 5]> = std::iter::once(error_header(lang))
        .chain(c.metrics.iter().map(|d| error_row(d, lang)))
        .collect();
    let widths: Vec<usize> = (0..5)
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    for row in &rows {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .map(|(text, &w)| format!("{text:<w$}"))
            .collect();
        lines.push(format!("  {}", cells.join("  ").trim_end()));
    }
    if let Some(rows) = &run.table {
        lines.push(String::new());
        lines.push(crate::text::approx::comparison_table(rows, lang));
    }
    if let Some((s, y_approx)) = &run.samples {
        lines.push(String::new());
        lines.push(format!(
            "{}\n  t (s)\ty\ty~",
            crate::text::cli::Heading::Samples.get(lang)
        ));
        for ((t, y), ya) in s.t.iter().zip(&s.y).zip(y_approx) {
            lines.push(format!("  {t}\t{y}\t{ya}"));
        }
    }
    lines.join("\n")
}

/// `degrau approx`.
pub fn run_approx(args: &ApproxArgs, lang: Lang) -> Result<(), ApproxCliError> {
    let run = approximate(args)?;
    let mut out = io::stdout().lock();
    let written = if args.system.json {
        write_json_line(&mut out, &ApproxReport::new(&run))
    } else {
        writeln!(out, "{}", human_report(&run, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| CliError::WriteOutput(e).into())
}

/// The JSON report of `degrau pade`.
#[derive(Debug, Serialize)]
pub struct PadeReport {
    pub delay: f64,
    pub m: usize,
    pub n: usize,
    /// Descending powers of s, constant term (m + n)!/m!.
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub zeros: Vec<[f64; 2]>,
    pub poles: Vec<[f64; 2]>,
}

/// The Padé report of the flags.
pub fn pade_report(args: &PadeArgs) -> Result<PadeReport, ApproxCliError> {
    let (m, n) = parse_order(&args.order)?;
    let m = m.unwrap_or(n);
    let (num, den) = pade_coefficients(args.delay, m, n)?;
    let zeros = trusted_roots(&num)?;
    let poles = trusted_roots(&den)?;
    Ok(PadeReport {
        delay: args.delay,
        m,
        n,
        zeros: as_pairs(&zeros),
        poles: as_pairs(&poles),
        num,
        den,
    })
}

/// The roots of `p`, refused when one is not a root to [`root_error::BACKWARD_LIMIT`]: the
/// companion eigenvalues lose the roots of high Padé orders (n ≥ 18 or so, coefficients
/// spanning 45 decades), which printed as roots would be wrong (Padé (30, 30)'s poles came
/// out with a backward error of 0.17, some in the right half plane).
fn trusted_roots(p: &[f64]) -> Result<Vec<C64>, crate::lti::LtiError> {
    let roots = crate::lti::poly::roots(p)?;
    if roots
        .iter()
        .all(|r| root_error::backward_error(p, *r) <= root_error::BACKWARD_LIMIT)
    {
        Ok(roots)
    } else {
        Err(crate::lti::LtiError::RootsDidNotConverge {
            degree: p.len() - 1,
        })
    }
}

/// `degrau pade`.
pub fn run_pade(args: &PadeArgs, lang: Lang) -> Result<(), ApproxCliError> {
    let report = pade_report(args)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        write_json_line(&mut out, &report)
    } else {
        let roots = |pairs: &[[f64; 2]]| {
            let list: Vec<C64> = pairs.iter().map(|&[re, im]| C64::new(re, im)).collect();
            roots_text(&list, lang)
        };
        writeln!(
            out,
            "{}\n  num = {}\n  den = {}\n  {}: {}\n  {}: {}",
            crate::text::approx::pade_heading(report.m, report.n, report.delay, lang),
            format_poly(&report.num),
            format_poly(&report.den),
            crate::text::cli::ZEROS,
            roots(&report.zeros),
            P::Poles.get(lang),
            roots(&report.poles)
        )
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| CliError::WriteOutput(e).into())
}

/// The exit code of `degrau approx` or `degrau pade`, its error printed in words (as
/// `degrau step` does: code 2, a closed pipe is success).
pub fn finish(result: Result<(), ApproxCliError>, lang: Lang) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(ApproxCliError::Cli(CliError::WriteOutput(e)))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orders_read_as_n_or_m_n() {
        assert_eq!(parse_order("2").unwrap(), (None, 2));
        assert_eq!(parse_order(" 1, 2").unwrap(), (Some(1), 2));
        assert!(parse_order("1,2,3").is_err() && parse_order("-1").is_err());
        assert_eq!(
            reduction(Method::Pade, Some("3")).unwrap(),
            Reduction {
                method: Method::Pade,
                m: 3,
                n: 3
            }
        );
        assert!(reduction(Method::Taylor, Some("1,2")).is_err());
        assert_eq!(
            reduction(Method::Dominant, None).unwrap(),
            Method::Dominant.default_reduction()
        );
    }
}
