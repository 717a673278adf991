//! `degrau loop --controller p|pi|pd|pid`: the unity-feedback loop of a P, PI, PD or PID
//! controller (ideal form Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N)), setpoint weight b) around a
//! plant given as for `degrau step`, its dead time kept exact (no Padé stand-in: the lti
//! crate's [`loop_response`]). The report: the controller in both forms, the response chosen
//! (a setpoint step or a load step at the plant's input), its metrics ([`loop_metrics`]:
//! final value, overshoot, peak or peak deviation, settling time, IAE, ITAE), whether it
//! settled, and with `--at` the output at those instants.
//!
//! Without `--controller`, `degrau loop` is the proportional loop of [`super::loop_cmd`].

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::lti::TransferFunction;
use crate::lti::control::frequency::{closed_loop_unstable_roots, max_sensitivity};
use crate::lti::control::{
    Action, Controller, ControllerError, DelayLoopError, Horizon, LoopInput, LoopMetrics,
    LoopResponse, Sensitivity, loop_metrics, loop_response,
};
use crate::lti::feedback::Limit;
use crate::lti::parse::parse_real_list;
use crate::text::cli::Heading;
use crate::text::control::{self as words, ControlWord};
use crate::text::{Lang, Localize};

use super::loop_cmd::{LoopArgs, LoopError};
use super::{CliError, MAX_SAMPLES, Samples, finite_f64};

/// The controller flags of `degrau loop`.
#[derive(Debug, Default, Clone, Args)]
pub struct ControllerFlags {
    /// Close the loop with a P, PI, PD or PID controller (ideal form
    /// Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N))) instead of the gain Kp; the dead time is then
    /// kept exact (no Padé). --kp is read as Kc (the same gain in the ideal and parallel
    /// forms).
    #[arg(
        long,
        value_name = "ACTION",
        conflicts_with_all = ["find", "pade", "locus"],
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<ActionArg>::new(),
            Action::from
        )
    )]
    pub controller: Option<Action>,
    /// With --controller: the controller gain Kc (--kp says the same).
    #[arg(long, value_name = "KC", allow_hyphen_values = true, value_parser = finite_f64,
          requires = "controller", conflicts_with = "kp")]
    pub kc: Option<f64>,
    /// With --controller pi or pid: the integral time Ti (s).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64,
          requires = "controller")]
    pub ti: Option<f64>,
    /// With --controller pd or pid: the derivative time Td (s).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = finite_f64,
          requires = "controller")]
    pub td: Option<f64>,
    /// With --controller pd or pid: the derivative filter N, Tf = Td/N (default 10).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = finite_f64,
          requires = "controller")]
    pub n: Option<f64>,
    /// With --controller: the setpoint weight b on the proportional term, 0 ≤ b ≤ 1
    /// (default 1).
    #[arg(long, value_name = "B", allow_hyphen_values = true, value_parser = finite_f64,
          requires = "controller")]
    pub b: Option<f64>,
    /// With --controller: the response reported, to a unit setpoint step (the default) or
    /// to a unit load step at the plant's input.
    #[arg(
        long,
        value_name = "INPUT",
        requires = "controller",
        value_parser = clap::builder::TypedValueParser::map(
            clap::builder::EnumValueParser::<ResponseArg>::new(),
            LoopInput::from
        )
    )]
    pub response: Option<LoopInput>,
    /// With --controller: add y(t) at these instants (s), comma-separated, e.g. "1,2.5,10".
    #[arg(long, value_name = "LIST", requires = "controller")]
    pub at: Option<String>,
}

/// An action `--controller` takes: clap's side of [`Action`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ActionArg {
    /// Proportional.
    P,
    /// Proportional and integral.
    Pi,
    /// Proportional and derivative.
    Pd,
    /// Proportional, integral and derivative.
    Pid,
}

impl From<ActionArg> for Action {
    fn from(a: ActionArg) -> Self {
        match a {
            ActionArg::P => Action::P,
            ActionArg::Pi => Action::PI,
            ActionArg::Pd => Action::PD,
            ActionArg::Pid => Action::PID,
        }
    }
}

/// A response `--response` takes: clap's side of [`LoopInput`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ResponseArg {
    /// A unit step of the setpoint.
    Setpoint,
    /// A unit step of a load disturbance at the plant's input.
    Load,
}

impl From<ResponseArg> for LoopInput {
    fn from(r: ResponseArg) -> Self {
        match r {
            ResponseArg::Setpoint => LoopInput::Setpoint,
            ResponseArg::Load => LoopInput::Load,
        }
    }
}

/// What can go wrong in `degrau loop --controller` (its words: [`crate::text::control`]).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum ControllerLoopError {
    /// A parameter the action needs was not given (`flag`: `--kc`, `--ti`, `--td`).
    Missing { flag: &'static str, action: Action },
    /// A parameter given that the action does not have (`--ti` for P or PD, `--td` or
    /// `--n` for P or PI).
    Unused { flag: &'static str, action: Action },
    /// The controller's numbers, refused.
    Controller(#[from] ControllerError),
    /// The loop could not be computed.
    Loop(#[from] DelayLoopError),
    /// An `--at` instant that is not 0 or a positive number of seconds.
    BadTime(f64),
    /// More `--at` instants than [`MAX_SAMPLES`].
    TooManyTimes(usize),
}

/// The controller of the flags, checked.
pub fn controller_of(args: &LoopArgs, action: Action) -> Result<Controller, ControllerLoopError> {
    let f = &args.control;
    let missing = |flag| ControllerLoopError::Missing { flag, action };
    let unused = |flag| ControllerLoopError::Unused { flag, action };
    let kc = f.kc.or(args.kp).ok_or_else(|| missing("--kc"))?;
    let ti = if action.integral() {
        f.ti.ok_or_else(|| missing("--ti"))?
    } else if f.ti.is_some() {
        return Err(unused("--ti"));
    } else {
        f64::INFINITY
    };
    let td = if action.derivative() {
        f.td.ok_or_else(|| missing("--td"))?
    } else if f.td.is_some() {
        return Err(unused("--td"));
    } else if f.n.is_some() {
        return Err(unused("--n"));
    } else {
        0.0
    };
    let mut c = Controller::new(action, kc, ti, td)?;
    if let Some(n) = f.n {
        c = c.with_filter(n)?;
    }
    if let Some(b) = f.b {
        c = c.with_setpoint_weight(b)?;
    }
    Ok(c)
}

/// The instants of `--at`, checked.
pub fn at_times(text: &str) -> Result<Vec<f64>, LoopError> {
    let times = super::parse_list("--at", text, parse_real_list)?;
    if times.len() > MAX_SAMPLES {
        return Err(ControllerLoopError::TooManyTimes(times.len()).into());
    }
    match times.iter().find(|t| !(t.is_finite() && **t >= 0.0)) {
        Some(&t) => Err(ControllerLoopError::BadTime(t).into()),
        None => Ok(times),
    }
}

/// Everything `degrau loop --controller` found.
pub struct ControllerLoop {
    /// The plant as given, with its dead time.
    pub plant: TransferFunction,
    pub controller: Controller,
    pub response: LoopResponse,
    pub metrics: LoopMetrics,
    /// The closed loop's roots in the right half-plane (exact with the dead time); None
    /// when they cannot be counted (a root on the imaginary axis).
    pub unstable_roots: Option<usize>,
    /// Ms and where, when the loop is stable.
    pub sensitivity: Option<Sensitivity>,
    /// y at the `--at` instants.
    pub samples: Option<Samples>,
}

/// The loop of the flags.
pub fn analyse(args: &LoopArgs, action: Action) -> Result<ControllerLoop, LoopError> {
    let plant = args.spec()?.transfer_function()?;
    let controller = controller_of(args, action)?;
    let times = args.control.at.as_deref().map(at_times).transpose()?;
    let input = args.control.response.unwrap_or(LoopInput::Setpoint);
    let response = loop_response(&plant, &controller, input, Horizon::Auto)
        .map_err(ControllerLoopError::from)?;
    let metrics = loop_metrics(&response);
    let samples = match times {
        None => None,
        Some(t) => {
            // Beyond the automatic horizon, the same loop computed up to the last instant
            // (the same steps: they do not depend on the horizon).
            let last = t.iter().copied().fold(0.0, f64::max);
            let longer = if last > response.end() {
                Some(
                    loop_response(&plant, &controller, input, Horizon::Until(last))
                        .map_err(ControllerLoopError::from)?,
                )
            } else {
                None
            };
            let r = longer.as_ref().unwrap_or(&response);
            let y = t.iter().map(|&t| r.value(t)).collect();
            Some(Samples::checked(t, y)?)
        }
    };
    let unstable_roots = closed_loop_unstable_roots(&plant, &controller).ok();
    let sensitivity = if unstable_roots == Some(0) {
        max_sensitivity(&plant, &controller)
    } else {
        None
    };
    Ok(ControllerLoop {
        plant,
        controller,
        response,
        metrics,
        unstable_roots,
        sensitivity,
        samples,
    })
}

/// The controller's JSON keys: the ideal form's parameters and the parallel form's gains
/// (`ti` is `"inf"` without integral action, `td` 0 without derivative action).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ControllerKeys {
    pub action: &'static str,
    pub form: &'static str,
    pub kc: f64,
    pub ti: Limit,
    pub td: f64,
    pub n: f64,
    pub b: f64,
    pub kp: f64,
    pub ki: f64,
    pub kd: f64,
    pub tf: f64,
}

impl ControllerKeys {
    pub fn new(c: &Controller) -> Self {
        let p = c.parallel();
        Self {
            action: c.action.key(),
            form: crate::lti::control::Form::Ideal.key(),
            kc: c.kc,
            ti: if c.action.integral() {
                Limit::Finite(c.ti)
            } else {
                Limit::Infinite
            },
            td: if c.action.derivative() { c.td } else { 0.0 },
            n: c.n,
            b: c.b,
            kp: p.kp,
            ki: p.ki,
            kd: p.kd,
            tf: p.tf,
        }
    }
}

/// A response's metrics as JSON keys (null where not defined).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MetricKeys {
    pub final_value: Option<f64>,
    /// %.
    pub overshoot: Option<f64>,
    /// The setpoint response's peak, or the load response's peak deviation.
    pub peak: Option<f64>,
    pub peak_time: Option<f64>,
    pub settling_time: Option<f64>,
    pub iae: Option<f64>,
    pub itae: Option<f64>,
}

impl MetricKeys {
    pub fn new(m: &LoopMetrics) -> Self {
        let finite = |x: Option<f64>| x.filter(|x| x.is_finite());
        Self {
            final_value: finite(m.final_value),
            overshoot: finite(m.overshoot),
            peak: finite(m.peak.map(|p| p.value)),
            peak_time: finite(m.peak.map(|p| p.time)),
            settling_time: finite(m.settling_time),
            iae: finite(m.iae),
            itae: finite(m.itae),
        }
    }
}

/// The JSON report of `degrau loop --controller`.
#[derive(Debug, Serialize)]
pub struct ControllerLoopReport {
    pub controller: ControllerKeys,
    /// `setpoint` or `load`.
    pub response: &'static str,
    /// Always true: the dead time is in the loop as it is, not approximated.
    pub exact_delay: bool,
    /// θ (s).
    pub delay: f64,
    pub metrics: MetricKeys,
    /// Whether the response settled within the time computed.
    pub settled: bool,
    /// The closed loop's roots in the right half-plane (null when a root lies on the
    /// imaginary axis and they cannot be counted).
    pub unstable_roots: Option<usize>,
    /// Ms = max |1/(1 + L(jω))|, null when the loop is not stable.
    pub ms: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<Samples>,
}

impl ControllerLoopReport {
    pub fn new(a: &ControllerLoop) -> Self {
        Self {
            controller: ControllerKeys::new(&a.controller),
            response: a.response.input.key(),
            exact_delay: true,
            delay: a.plant.delay(),
            metrics: MetricKeys::new(&a.metrics),
            settled: a.response.settled,
            unstable_roots: a.unstable_roots,
            ms: a.sensitivity.map(|s| s.ms),
            samples: a.samples.clone(),
        }
    }
}

/// The controller's lines: its action and form, its parameters, its parallel gains.
pub fn controller_lines(c: &Controller, lang: Lang) -> Vec<String> {
    let n = |x: f64| lang.num(x, 6);
    let mut rows = vec![(ControlWord::Gain, n(c.kc))];
    if c.action.integral() {
        rows.push((ControlWord::IntegralTime, n(c.ti)));
    }
    if c.action.derivative() {
        rows.push((ControlWord::DerivativeTime, n(c.td)));
        rows.push((ControlWord::Filter, n(c.n)));
    }
    rows.push((ControlWord::SetpointWeight, n(c.b)));
    let mut lines = vec![words::controller_heading(c.action, lang)];
    lines.extend(aligned(
        rows.into_iter()
            .map(|(label, value)| (label.text(lang), value)),
    ));
    let p = c.parallel();
    lines.push(words::parallel_line(
        [n(p.kp), n(p.ki), n(p.kd), n(p.tf)],
        lang,
    ));
    lines
}

/// `label  value` rows with the values in one column, indented by two spaces.
pub fn aligned(rows: impl IntoIterator<Item = (String, String)>) -> Vec<String> {
    let rows: Vec<(String, String)> = rows.into_iter().collect();
    let width = rows
        .iter()
        .map(|(l, _)| l.chars().count())
        .max()
        .unwrap_or(0);
    rows.iter()
        .map(|(l, v)| {
            let pad = width - l.chars().count();
            format!("  {l}{}  {v}", " ".repeat(pad))
        })
        .collect()
}

/// A response's metric rows, each absent one with its reason.
pub fn metric_rows(m: &LoopMetrics, input: LoopInput, lang: Lang) -> Vec<(String, String)> {
    let n = |x: f64| lang.num(x, 6);
    let absent = |why: words::Absent| why.text(lang);
    let settled = m.final_value.is_some();
    let none = |integral: bool| {
        absent(match (settled, integral) {
            (false, _) => words::Absent::NotSettled,
            (true, true) => words::Absent::NoIntegralAction,
            (true, false) => words::Absent::NoChange,
        })
    };
    let value = |x: Option<f64>, integral: bool| x.map_or_else(|| none(integral), n);
    let peak_label = match input {
        LoopInput::Setpoint => ControlWord::Peak,
        LoopInput::Load => ControlWord::PeakDeviation,
    };
    vec![
        (
            ControlWord::FinalValue.text(lang),
            value(m.final_value, false),
        ),
        (ControlWord::Overshoot.text(lang), value(m.overshoot, false)),
        (
            peak_label.text(lang),
            m.peak.map_or_else(
                || none(false),
                |p| words::at_time(&n(p.value), &n(p.time), lang),
            ),
        ),
        (
            ControlWord::SettlingTime.text(lang),
            value(m.settling_time, false),
        ),
        (ControlWord::Iae.text(lang), value(m.iae, true)),
        (ControlWord::Itae.text(lang), value(m.itae, true)),
    ]
}

/// The text report: the plant, the controller, the loop, the response and its metrics.
pub fn human_report(a: &ControllerLoop, lang: Lang) -> String {
    use crate::text::feedback::LoopLine as L;
    let mut lines = vec![L::OpenLoop(a.plant.describe_rounded()).text(lang)];
    if a.plant.delay() > 0.0 {
        lines.push(words::exact_delay_line(&lang.num(a.plant.delay(), 6), lang));
    }
    lines.push(String::new());
    lines.extend(controller_lines(&a.controller, lang));
    lines.push(words::stability_line(
        a.unstable_roots,
        a.sensitivity.map(|s| (lang.num(s.ms, 4), lang.num(s.w, 4))),
        lang,
    ));
    lines.push(String::new());
    lines.push(words::response_heading(a.response.input, lang));
    lines.extend(aligned(metric_rows(&a.metrics, a.response.input, lang)));
    lines.push(words::settled_line(
        a.response.settled,
        &lang.num(a.response.end(), 6),
        lang,
    ));
    if let Some(Samples { t, y }) = &a.samples {
        lines.push(String::new());
        lines.push(format!("{}\n  t (s)\ty", Heading::Samples.get(lang)));
        lines.extend(t.iter().zip(y).map(|(t, y)| format!("  {t}\t{y}")));
    }
    lines.join("\n")
}

/// `degrau loop --controller`.
pub fn run(args: &LoopArgs, action: Action, lang: Lang) -> Result<(), LoopError> {
    let a = analyse(args, action)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        serde_json::to_writer(&mut out, &ControllerLoopReport::new(&a))
            .map_err(io::Error::from)
            .and_then(|()| out.write_all(b"\n"))
    } else {
        writeln!(out, "{}", human_report(&a, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| LoopError::Cli(CliError::WriteOutput(e)))
}
