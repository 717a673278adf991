//! `degrau loop`: the unity-feedback loop around Kp·G(s) for one system given as for
//! `degrau step`: the closed loop at a gain (`--kp`) or at the gain found for specs
//! (`--find "overshoot<=10"`, …), its exact step metrics, the error constants and
//! steady-state errors, the critical gain and crossing frequency, the breakaway points and,
//! with `--locus`, the root locus's points. Text (numbers with six significant digits), or
//! one JSON object with stable keys (every digit). A gain at which double precision cannot
//! give the closed loop's poles is refused ([`crate::lti::LtiError::LoopPolesUnresolved`]).
//!
//! A system with a dead time is closed through the Padé (m, n) approximant of its delay
//! (`--pade m,n`, default [`PadeOrder::default`]): everything after is of the approximated
//! loop, the text says so and the JSON names the approximant (`approximant`, null when G has
//! no delay).
//!
//! With `--controller p|pi|pd|pid` the loop is a controller's, its dead time kept exact
//! ([`super::loop_controller`]).

use std::io::{self, Write};
use std::process::ExitCode;

use clap::Args;
use serde::Serialize;

use crate::lti::approx::ApproxError;
use crate::lti::feedback::{
    ErrorConstants, GainSearch, Limit, LoopApproximant, PadeOrder, RationalLoop, Spec,
    SteadyStateErrors, find_gain,
};
use crate::lti::locus::{Breakaway, Locus, Side};
use crate::lti::{LtiError, StepInfoOptions, StepResponse, TransferFunction, analyse};
use crate::text::feedback::{Loop as P, LoopError as LoopErrorText};
use crate::text::{Lang, Localize};

use super::loop_controller::ControllerLoopError;
use super::{Analysis, CliError, Report, SystemSpec, finite_f64, human_report};

const LOOP_EXAMPLES: &str = "\
Examples:
  degrau loop --num 0.5 --den 1,7,15,25 --kp 1
  degrau loop --num 1 --den 1,2,0 --find \"overshoot<=10\" --json
  degrau loop --poles \"-1+2j,-1-2j,-5\" --zeros -10 --gain 0.5 --locus --json
  degrau loop --num 1 --den 10,1 --delay 2 --kp 3 --pade 3,3 --json
  degrau loop --num 1 --den 10,1 --delay 2 --controller pi --kc 2.5 --ti 10 --at 5,10,20
  degrau loop --num 1 --den 10,1 --delay 2 --controller pid --kc 3 --ti 8 --td 1 --response load --json";

/// `degrau loop` options: the system as for `degrau step`, then the gain or the specs.
#[derive(Debug, Default, Args)]
#[command(after_help = LOOP_EXAMPLES)]
pub struct LoopArgs {
    #[command(flatten)]
    pub system: super::SystemArgs,
    /// The proportional gain Kp of the loop (default 1). With --controller it is read as the
    /// controller gain Kc (the same number in the ideal and the parallel forms).
    #[arg(long, value_name = "KP", allow_hyphen_values = true, value_parser = finite_f64, conflicts_with = "find")]
    pub kp: Option<f64>,
    /// Find the gain meeting specs, e.g. "overshoot<=10" (%), "settling<=2" (s, 2 %),
    /// "rise<=1" (s, 10–90 %), "ess_step<=0.05", "ess_ramp<=0.5"; several separated by
    /// commas or given again.
    #[arg(long, value_name = "SPEC")]
    pub find: Vec<String>,
    /// The Padé order "m,n" (m zeros, n poles, m ≤ n, 1 ≤ n ≤ 8) standing in for the dead
    /// time in the loop (default 3,3: its phase follows the delay's within about 1° up to
    /// ωθ = π). Ignored without --delay.
    #[arg(long, value_name = "M,N")]
    pub pade: Option<String>,
    /// Add the root locus's points (K from 0 to ∞) to the report.
    #[arg(long)]
    pub locus: bool,
    /// With --locus: the complementary locus (K from 0 to −∞) instead.
    #[arg(long, requires = "locus")]
    pub complementary: bool,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub control: super::loop_controller::ControllerFlags,
}

/// What can go wrong in `degrau loop` (its words: [`crate::text::feedback`]).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum LoopError {
    Cli(#[from] CliError),
    /// The delay's approximant could not be built.
    Approx(ApproxError),
    /// A `--pade` value that is not `m,n` with an order offered.
    BadPade(String),
    /// A `--find` item that is not `name<=number` with a known name.
    BadSpec(String),
    /// No gain K > 0 meets the specs.
    NoGain,
    /// `--controller`: the controller or its loop.
    Controller(#[from] ControllerLoopError),
}

impl From<LtiError> for LoopError {
    fn from(e: LtiError) -> Self {
        LoopError::Cli(CliError::Lti(e))
    }
}

impl Localize for LoopError {
    fn text(&self, lang: Lang) -> String {
        match self {
            LoopError::Cli(e) => e.text(lang),
            LoopError::Approx(e) => e.text(lang),
            LoopError::BadPade(item) => LoopErrorText::BadPade(item.clone()).text(lang),
            LoopError::BadSpec(item) => LoopErrorText::BadSpec(item.clone()).text(lang),
            LoopError::NoGain => LoopErrorText::NoGain.text(lang),
            LoopError::Controller(e) => e.text(lang),
        }
    }
}

/// The JSON report of `degrau loop`.
#[derive(Debug, Serialize)]
pub struct LoopReport {
    /// The Padé approximant standing in for G's dead time (`{"kind": "pade", "m", "n",
    /// "delay"}`), null when G has none: when set, every other key is of the approximated
    /// loop.
    pub approximant: Option<LoopApproximant>,
    pub kp: f64,
    /// [lo, hi] of the gains meeting `--find` (hi null when unbounded), null without it.
    pub kp_range: Option<[Option<f64>; 2]>,
    pub closed_loop: ClosedLoopKeys,
    /// The step keys of `degrau step`, for the closed loop.
    #[serde(flatten)]
    pub step: Report,
    #[serde(rename = "type")]
    pub system_type: i32,
    pub error_constants: ConstantKeys,
    /// Null when the closed loop is not stable (no steady state).
    pub ess: Option<SteadyStateErrors>,
    pub critical_gain: Option<f64>,
    pub crossing_frequency: Option<f64>,
    pub breakaway: Vec<BreakawayKeys>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub locus: Option<Vec<LocusKeys>>,
}

#[derive(Debug, Serialize)]
pub struct ClosedLoopKeys {
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub poles: Vec<[f64; 2]>,
    pub zeros: Vec<[f64; 2]>,
}

#[derive(Debug, Serialize)]
pub struct ConstantKeys {
    pub kp: Limit,
    pub kv: Limit,
    pub ka: Limit,
}

#[derive(Debug, Serialize)]
pub struct BreakawayKeys {
    pub s: f64,
    pub k: f64,
    /// `breakaway` (the branches leave the real axis) or `break_in`.
    pub kind: &'static str,
}

#[derive(Debug, Serialize)]
pub struct LocusKeys {
    pub k: f64,
    pub roots: Vec<[f64; 2]>,
}

/// Everything `degrau loop` found.
pub struct LoopAnalysis {
    /// G as given (with its dead time, if any).
    pub system: TransferFunction,
    /// G made rational (the loop's open loop) and the approximant used, if any.
    pub rational: RationalLoop,
    pub kp: f64,
    pub search: Option<GainSearch>,
    /// The closed loop's Kp·num and den + Kp·num as computed from the coefficients
    /// ([`TransferFunction::closed_loop_coeffs`]).
    pub closed_coeffs: (Vec<f64>, Vec<f64>),
    pub closed: Analysis,
    pub constants: ErrorConstants,
    pub locus: Locus,
    pub drawn: Option<Locus>,
}

impl LoopArgs {
    pub(super) fn spec(&self) -> Result<SystemSpec, CliError> {
        let step = super::StepArgs {
            system: self.system.clone(),
            ..Default::default()
        };
        step.spec()
    }

    /// The Padé order of `--pade` (the default without it).
    pub fn pade_order(&self) -> Result<PadeOrder, LoopError> {
        let Some(text) = &self.pade else {
            return Ok(PadeOrder::default());
        };
        let bad = || LoopError::BadPade(text.clone());
        let (m, n) = text.split_once(',').ok_or_else(bad)?;
        let order = PadeOrder {
            m: m.trim().parse().map_err(|_| bad())?,
            n: n.trim().parse().map_err(|_| bad())?,
        };
        if order.is_valid() {
            Ok(order)
        } else {
            Err(bad())
        }
    }

    /// The specs of `--find`.
    pub fn specs(&self) -> Result<Vec<Spec>, LoopError> {
        self.find
            .iter()
            .flat_map(|f| f.split(','))
            .map(str::trim)
            .filter(|f| !f.is_empty())
            .map(parse_spec)
            .collect()
    }
}

/// `overshoot<=10` as a spec.
pub fn parse_spec(item: &str) -> Result<Spec, LoopError> {
    let bad = || LoopError::BadSpec(item.to_string());
    let (key, value) = item.split_once("<=").ok_or_else(bad)?;
    let value = finite_f64(value.trim()).map_err(|_| bad())?;
    if value < 0.0 {
        return Err(bad());
    }
    Spec::from_key(key.trim(), value).ok_or_else(bad)
}

/// The loop of the flags: the gain (given or found), the closed loop and its analysis.
pub fn analyse_loop(args: &LoopArgs) -> Result<LoopAnalysis, LoopError> {
    let system = args.spec()?.transfer_function()?;
    let rational = RationalLoop::new(&system, args.pade_order()?).map_err(LoopError::Approx)?;
    let g = rational.g.clone();
    let specs = args.specs()?;
    let search = if specs.is_empty() {
        None
    } else {
        Some(find_gain(&g, &specs)?.ok_or(LoopError::NoGain)?)
    };
    let kp = search.as_ref().map_or(args.kp.unwrap_or(1.0), |s| s.k);
    let cl = g.closed_loop(kp)?;
    let closed_coeffs = g.closed_loop_coeffs(kp)?;
    let options = StepInfoOptions::default();
    let response = StepResponse::new(&cl, 1.0).map_err(CliError::from)?;
    let info = analyse(&response, &options).info;
    super::finite_metrics(&info)?;
    let closed = Analysis {
        tf: cl,
        response,
        info,
        options,
        samples: None,
    };
    let locus = Locus::new(&g, Side::Positive)?;
    let drawn = match (args.locus, args.complementary) {
        (true, true) => Some(Locus::new(&g, Side::Complementary)?),
        (true, false) => Some(locus.clone()),
        _ => None,
    };
    Ok(LoopAnalysis {
        constants: ErrorConstants::of(&g, kp),
        system,
        rational,
        kp,
        search,
        closed_coeffs,
        closed,
        locus,
        drawn,
    })
}

fn pairs(roots: &[crate::lti::C64]) -> Vec<[f64; 2]> {
    roots.iter().map(|r| [r.re + 0.0, r.im + 0.0]).collect()
}

fn breakaway_kind(b: &Breakaway) -> &'static str {
    if b.leaves_axis {
        "breakaway"
    } else {
        "break_in"
    }
}

impl LoopReport {
    pub fn new(a: &LoopAnalysis) -> Self {
        let cl = &a.closed.tf;
        let crossing = a.locus.crossings.first();
        Self {
            approximant: a.rational.approximant,
            kp: a.kp,
            kp_range: a.search.as_ref().map(|s| {
                let (lo, hi) = s.range;
                [Some(lo), hi.is_finite().then_some(hi)]
            }),
            closed_loop: ClosedLoopKeys {
                num: a.closed_coeffs.0.clone(),
                den: a.closed_coeffs.1.clone(),
                poles: pairs(cl.poles()),
                zeros: pairs(cl.zeros()),
            },
            step: Report::new(&a.closed),
            system_type: a.constants.system_type,
            error_constants: ConstantKeys {
                kp: a.constants.kp,
                kv: a.constants.kv,
                ka: a.constants.ka,
            },
            ess: cl.is_stable().then(|| a.constants.errors()),
            critical_gain: crossing.map(|c| c.k),
            crossing_frequency: crossing.map(|c| c.omega),
            breakaway: a
                .locus
                .breakaways
                .iter()
                .map(|b| BreakawayKeys {
                    s: b.s,
                    k: b.k,
                    kind: breakaway_kind(b),
                })
                .collect(),
            locus: a.drawn.as_ref().map(|l| {
                l.points
                    .iter()
                    .map(|p| LocusKeys {
                        k: p.k,
                        roots: pairs(&p.roots),
                    })
                    .collect()
            }),
        }
    }
}

/// The text report: the loop's facts, then the closed loop's step report.
pub fn human_loop_report(a: &LoopAnalysis, lang: Lang) -> String {
    use crate::text::feedback::LoopLine as L;
    let n = |x: f64| lang.num(x, 6);
    let limit = |l: Limit| match l {
        Limit::Finite(x) => n(x),
        Limit::Infinite => "∞".to_string(),
    };
    let mut lines = vec![L::OpenLoop(a.system.describe_rounded()).text(lang)];
    if let Some(p) = &a.rational.approximant {
        lines.push(
            L::Approximant {
                m: p.m,
                n: p.n,
                delay: n(p.delay),
            }
            .text(lang),
        );
    }
    lines.push(L::Gain(n(a.kp)).text(lang));
    if let Some(s) = &a.search {
        let hi = if s.range.1.is_finite() {
            n(s.range.1)
        } else {
            "∞".into()
        };
        lines.push(L::Range(n(s.range.0), hi).text(lang));
    }
    let c = &a.constants;
    lines.push(
        L::Constants {
            system_type: c.system_type,
            kp: limit(c.kp),
            kv: limit(c.kv),
            ka: limit(c.ka),
        }
        .text(lang),
    );
    lines.push(if a.closed.tf.is_stable() {
        let e = c.errors();
        L::Errors(limit(e.step), limit(e.ramp), limit(e.parabola)).text(lang)
    } else {
        P::NoSteadyState.get(lang).to_string()
    });
    lines.push(match a.locus.crossings.first() {
        Some(x) => L::Critical(n(x.k), n(x.omega)).text(lang),
        None => P::NoCriticalGain.get(lang).to_string(),
    });
    for b in &a.locus.breakaways {
        lines.push(L::Breakaway(b.leaves_axis, n(b.s), n(b.k)).text(lang));
    }
    if let Some(asym) = &a.locus.asymptotes {
        let angles: Vec<String> = asym
            .angles
            .iter()
            .map(|x| format!("{}°", lang.num(x.to_degrees(), 4)))
            .collect();
        lines.push(L::Asymptotes(n(asym.centroid), angles.join(", ")).text(lang));
    }
    if let Some(locus) = &a.drawn {
        lines.push(String::new());
        let heading = if a.rational.approximant.is_some() {
            P::LocusHeadingApproximate
        } else {
            P::LocusHeading
        };
        lines.push(heading.get(lang).to_string());
        for p in &locus.points {
            let roots: Vec<String> = p
                .roots
                .iter()
                .map(|r| lang.localize_number(&crate::lti::fmt_c_rounded(*r)))
                .collect();
            lines.push(format!("  K = {}\t{}", n(p.k), roots.join("  ")));
        }
    }
    lines.push(String::new());
    lines.push(P::ClosedLoopHeading.get(lang).to_string());
    lines.push(human_report(&a.closed, lang));
    lines.join("\n")
}

/// `degrau loop`.
pub fn run_loop(args: &LoopArgs, lang: Lang) -> Result<(), LoopError> {
    if let Some(action) = args.control.controller {
        return super::loop_controller::run(args, action, lang);
    }
    let a = analyse_loop(args)?;
    let mut out = io::stdout().lock();
    let written = if args.json {
        serde_json::to_writer(&mut out, &LoopReport::new(&a))
            .map_err(io::Error::from)
            .and_then(|()| out.write_all(b"\n"))
    } else {
        writeln!(out, "{}", human_loop_report(&a, lang))
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| LoopError::Cli(CliError::WriteOutput(e)))
}

/// The exit code of `degrau loop`, its error printed in words.
pub fn main(args: &LoopArgs, lang: Lang) -> ExitCode {
    super::exit_code(
        run_loop(args, lang),
        |e| match e {
            LoopError::Cli(c) => Some(c),
            _ => None,
        },
        lang,
    )
}
