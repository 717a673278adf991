//! What a fitted model gets wrong, why, how to extend it, and how much the extension gains.
//!
//! The loop, as the ball-and-tube notes walk it by hand:
//! 1. fit the start model (the student's, or `P1`);
//! 2. for every extension the structure can still take (a dead time, a free offset, an
//!    underdamped pair, one more pole, a zero, an integrator, a drift term) refit the
//!    extended model, warm-started from the current fit (and from the extended structure's
//!    automatic guess);
//! 3. the extension that lowers the Bayesian information criterion most names the cause,
//!    provided it pays for its extra parameter: BIC = N·ln(MSE) + p·ln(N) must drop by more
//!    than [`BIC_THRESHOLD`] (10: "very strong" evidence on Kass & Raftery's scale; for one
//!    extra parameter the MSE must fall by a factor e^{(10 + ln N)/N}, i.e. 2.1 % at N = 800);
//! 4. the cause is explained with evidence from the current residuals (which statistic, over
//!    which time interval), the gain is measured (RMSE before and after and their ratio, fit %
//!    before and after, the BIC change), and the loop repeats until nothing pays: `none`.
//!
//! Trying the extensions, rather than reading the cause off residual patterns alone, makes the
//! naming robust when several patterns overlap (a missing dead time and a missing pole both
//! make the model rise too early); the residual statistics then say *where* and *how*.
//! A zero and an inverse response are the same extension (Tz): its fitted sign names the cause.

use serde::{Deserialize, Serialize};

use super::drift_evidence::read_drift;
use super::fit::{FitData, FitError, FitOptions, FitReport, Termination, fit, search_fit};
use super::guess::{auto_guess, features};
use super::holdout::Validation;
use super::models::{Model, Param, Structure, Values};
use super::residuals::{self, ResidualAnalysis};
use super::staircase::Staircase;
use super::stats::lag_one;
use super::test_causes::{TestCause, TestCauseKind, handling, time_constants};
use super::tracker::Tracker;

/// An extension must lower BIC by more than this to be kept.
pub const BIC_THRESHOLD: f64 = 10.0;

/// An underdamped pair fitted with ζ at or above this is taken as two real poles.
const OVERDAMPED_ZETA: f64 = 0.98;

/// A named cause, with a stable identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Cause {
    DeadTime,
    Offset,
    Oscillation,
    ExtraPole,
    Zero,
    InverseResponse,
    Integrator,
    Drift,
    None,
}

impl Cause {
    /// The stable identifier graders read (`dead_time`, `offset`, …, `none`).
    pub fn id(self) -> &'static str {
        match self {
            Cause::DeadTime => "dead_time",
            Cause::Offset => "offset",
            Cause::Oscillation => "oscillation",
            Cause::ExtraPole => "extra_pole",
            Cause::Zero => "zero",
            Cause::InverseResponse => "inverse_response",
            Cause::Integrator => "integrator",
            Cause::Drift => "drift",
            Cause::None => "none",
        }
    }
}

/// A structural change to try.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Extension {
    Delay,
    FreeOffset,
    Underdamped,
    Pole,
    Zero,
    Integrator,
    Drift,
}

const EXTENSIONS: [Extension; 7] = [
    Extension::Delay,
    Extension::FreeOffset,
    Extension::Underdamped,
    Extension::Pole,
    Extension::Zero,
    Extension::Integrator,
    Extension::Drift,
];

impl Extension {
    /// The extended structure, if this structure can take the extension.
    fn apply(self, s: Structure) -> Option<Structure> {
        let mut e = s;
        match self {
            Extension::Delay if !s.delay => e.delay = true,
            Extension::FreeOffset if !s.free_offset => e.free_offset = true,
            Extension::Underdamped if !s.underdamped => {
                e.underdamped = true;
                e.poles = s.poles.max(2);
            }
            Extension::Pole if s.poles < 3 => e.poles += 1,
            Extension::Zero if !s.zero => e.zero = true,
            Extension::Integrator if !s.integrator => e.integrator = true,
            // A test not at rest has its initial transient: a drift would absorb the same
            // motion before the step (an artefact of the test), not a trend of the process.
            Extension::Drift if !s.drift && !s.transient => e.drift = true,
            _ => return None,
        }
        Some(e)
    }

    /// The structure without this extension's term and the parameter whose null value (0)
    /// says the term is not needed, for the terms the backward look may take out again: a
    /// dead time, a zero and a drift (an offset, an integrator, a pole or a pair have no
    /// null value that leaves the same model).
    fn removed(self, s: Structure) -> Option<(Structure, Param)> {
        let mut r = s;
        let param = match self {
            Extension::Delay if s.delay => {
                r.delay = false;
                Param::Td
            }
            Extension::Zero if s.zero => {
                r.zero = false;
                Param::Tz
            }
            Extension::Drift if s.drift => {
                r.drift = false;
                Param::Drift
            }
            _ => return None,
        };
        Some((r, param))
    }

    fn cause(self, fitted: &Values) -> Cause {
        match self {
            Extension::Delay => Cause::DeadTime,
            Extension::FreeOffset => Cause::Offset,
            Extension::Underdamped => Cause::Oscillation,
            Extension::Pole => Cause::ExtraPole,
            Extension::Zero if fitted.get(Param::Tz) < 0.0 => Cause::InverseResponse,
            Extension::Zero => Cause::Zero,
            Extension::Integrator => Cause::Integrator,
            Extension::Drift => Cause::Drift,
        }
    }
}

/// How to run the loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DiagnoseOptions {
    /// Most extensions made.
    pub max_steps: usize,
    /// How the start model is fitted (the candidates use single warm starts).
    pub fit: FitOptions,
}

impl Default for DiagnoseOptions {
    fn default() -> Self {
        Self {
            max_steps: 4,
            fit: FitOptions {
                starts: 8,
                ..FitOptions::default()
            },
        }
    }
}

/// What an extension gained.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Gain {
    pub rmse_before: f64,
    pub rmse_after: f64,
    /// rmse_before / rmse_after (> 1 is a gain).
    pub rmse_ratio: f64,
    pub fit_percent_before: f64,
    pub fit_percent_after: f64,
    /// Change of BIC (negative is better).
    pub criterion_delta: f64,
}

/// Residuals over an interval: how many, their mean (output units) and the fraction that
/// share the mean's sign (0 to 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Bias {
    pub start: f64,
    pub end: f64,
    pub n: usize,
    pub mean: f64,
    pub same_sign: f64,
}

/// The evidence for a cause, with its numbers (`crate::words` says it); times in seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Evidence {
    /// The data stays near its operating point over `bias` while the model moves; a dead
    /// time `td` makes the model wait. On a record of several `changes`, `bias` gathers the
    /// `td` after every change (its residuals signed by each change's direction; `start` and
    /// `end` are the first window's start and the last one's end).
    DeadTime { bias: Bias, td: f64, changes: usize },
    /// The residuals are biased over the whole record; the model assumes `y0_held`, the
    /// data say `y0_estimated`.
    Offset {
        bias: Bias,
        y0_held: f64,
        y0_estimated: f64,
    },
    /// The residuals oscillate (of `period` when one is found: their autocorrelation
    /// alternates beyond the 99 % band); a pair with `omega_d` (rad/s) and `zeta` takes it up.
    Oscillation {
        period: Option<f64>,
        omega_d: Option<f64>,
        zeta: f64,
    },
    /// Right after the response starts (over `bias`) the data rises with zero slope while the
    /// model rises at once; the pole added, with its time constant.
    ExtraPole {
        bias: Bias,
        added: Option<(Param, f64)>,
    },
    /// The data overshoots its final level by `overshoot` (a fraction; peak at `peak_time`),
    /// more than the model's pair alone (`underdamped`) or although its poles are real; a
    /// zero `tz` lets it.
    Zero {
        overshoot: f64,
        peak_time: Option<f64>,
        underdamped: bool,
        tz: f64,
    },
    /// The data first moves the wrong way by `undershoot` (a fraction of the step's effect,
    /// deepest at `dip_time`); a right-half-plane zero `tz` does that.
    InverseResponse {
        undershoot: f64,
        dip_time: Option<f64>,
        tz: f64,
    },
    /// The data never levels off: over the last fifth it moves at `slope` (units/s),
    /// `per_time_constant` (a fraction) of the step's effect per time constant; the tail's
    /// residual trend z.
    Integrator {
        slope: f64,
        per_time_constant: f64,
        trend_z: Option<f64>,
    },
    /// After the response settles the residuals trend (the tail's slope in units/s and its
    /// z); a drift term of `drift` units/s takes it.
    Drift {
        tail: Option<(f64, f64)>,
        drift: f64,
    },
    /// A term the chain added earlier no longer pays once later ones are in (the backward
    /// look): its parameter `param` ended at `value` with its 95 % interval `ci95`, and the
    /// model without it is worse by only `criterion_delta` of the corrected BIC (under
    /// [`BIC_THRESHOLD`]), or the term ended where it means nothing (a dead time ≤ 0).
    NoLongerPays {
        param: Param,
        value: f64,
        ci95: Option<(f64, f64)>,
        criterion_delta: f64,
    },
    /// Nothing to name.
    None,
}

/// How the loop ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Ending {
    /// The residuals look like noise and no extension lowers BIC by [`BIC_THRESHOLD`].
    Adequate,
    /// No extension lowers BIC by [`BIC_THRESHOLD`], although the residuals are not white.
    NotWhite,
    /// On a staircase (a resolution coarse against the noise), no extension gains more
    /// than rounding gives a model that lacks nothing ([`Staircase`]).
    WithinRounding,
    /// The step limit was reached.
    StepLimit,
}

/// The residuals' whiteness: lags of the autocorrelation outside the 99 % band, of how
/// many, and the runs test's z.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Whiteness {
    pub outside: usize,
    pub lags: usize,
    pub runs_z: f64,
}

/// Why the final model is adequate (or why the loop stopped), with the whiteness statistics.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    pub ending: Ending,
    pub whiteness: Option<Whiteness>,
    /// Which structure the loop ended on.
    #[serde(default)]
    pub structure: Option<Structure>,
    /// Which artefacts of the test were found (the report's `test_causes` has their
    /// evidence).
    #[serde(default)]
    pub artefacts: Artefacts,
}

/// A set of test causes, small enough to copy (a bit per [`TestCauseKind`], in
/// [`TestCauseKind::ALL`]'s order); its JSON is the list of their identifiers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Artefacts(u16);

impl Artefacts {
    pub fn of(causes: &[TestCause]) -> Self {
        Self::from_kinds(causes.iter().map(|c| c.kind))
    }

    fn from_kinds(kinds: impl Iterator<Item = TestCauseKind>) -> Self {
        Artefacts(kinds.fold(0, |bits, k| bits | 1 << Self::bit(k)))
    }

    fn bit(k: TestCauseKind) -> usize {
        TestCauseKind::ALL.iter().position(|x| *x == k).unwrap_or(0)
    }

    /// The causes in the set, in [`TestCauseKind::ALL`]'s order.
    pub fn kinds(self) -> Vec<TestCauseKind> {
        TestCauseKind::ALL
            .into_iter()
            .filter(|&k| self.0 & (1 << Self::bit(k)) != 0)
            .collect()
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
}

impl Serialize for Artefacts {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.kinds().serialize(s)
    }
}

impl<'de> Deserialize<'de> for Artefacts {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let kinds = Vec::<TestCauseKind>::deserialize(d)?;
        Ok(Self::from_kinds(kinds.into_iter()))
    }
}

/// One step of the loop: the cause named, why, and the extended fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Step {
    pub cause: Cause,
    /// A second cause named with it, when only the pair of extensions pays (two effects
    /// hidden at once); `evidence` is the first's.
    #[serde(default)]
    pub paired: Option<Cause>,
    pub evidence: Evidence,
    /// The time interval the evidence points at (s), when there is one.
    pub interval: Option<(f64, f64)>,
    pub fit: FitReport,
    pub gain: Gain,
    /// True for a term taken out again by the backward look ([`backward_step`]): `cause`
    /// names the term, `fit` is the model without it.
    #[serde(default)]
    pub removed: bool,
}

/// A term the gain trades with: the final fit's Kp estimate correlated with `with`'s by
/// `correlation` (|r| ≥ [`TRADE_CORRELATION`]) and its interval loose ([`TRADE_WIDTH`]), so
/// that the record measures the two only together; the 95 % interval of Kp is the range the
/// record allows.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GainTrade {
    pub with: Param,
    pub correlation: f64,
}

/// Kp correlated with another parameter by this much or more is not measured apart from it.
pub const TRADE_CORRELATION: f64 = 0.9;

/// A trade is said only when it leaves the gain loose: its 95 % interval's half-width above
/// this share of |Kp| (the 10 % a gain is read to). A correlated pair both pinned down is
/// measured, however correlated.
pub const TRADE_WIDTH: f64 = 0.1;

/// The terms a gain trades with on a record that has not settled or did not start at rest:
/// a drift, an initial transient, the operating point, a zero, and the slowest lag; said
/// when the gain's interval is loose ([`TRADE_WIDTH`]).
fn gain_trade(r: &FitReport) -> Option<GainTrade> {
    let kp = r.model.get(Param::Kp);
    let loose = r
        .interval(Param::Kp)
        .is_none_or(|(lo, hi)| 0.5 * (hi - lo) > TRADE_WIDTH * kp.abs());
    if !loose {
        return None;
    }
    let slowest = [Param::Tp3, Param::Tp2, Param::Tp1, Param::Tw]
        .into_iter()
        .filter(|p| r.model.structure.params().contains(p))
        .max_by(|a, b| r.model.get(*a).total_cmp(&r.model.get(*b)));
    let trading = [
        Param::Drift,
        Param::X1,
        Param::X2,
        Param::X3,
        Param::Y0,
        Param::Tz,
    ];
    r.kp_correlations
        .iter()
        .filter(|(p, _)| trading.contains(p) || Some(*p) == slowest)
        .filter(|(_, c)| c.abs() >= TRADE_CORRELATION)
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .map(|&(with, correlation)| GainTrade { with, correlation })
}

/// The whole chain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DiagnoseReport {
    pub start: FitReport,
    pub steps: Vec<Step>,
    pub final_fit: FitReport,
    /// True when the loop ended because nothing paid (not at the step limit).
    pub adequate: bool,
    /// Why the final model is considered adequate (or not), with the residual statistics;
    /// `None` for a chain still being built one step at a time.
    pub verdict: Option<Verdict>,
    /// The process's static gain Kp = Δy/Δu of the final model, with its 95 % interval.
    pub static_gain: (f64, Option<(f64, f64)>),
    /// The term the record does not separate the gain from, when there is one
    /// ([`GainTrade`]): the static gain is then measured only together with it.
    #[serde(default)]
    pub gain_trade: Option<GainTrade>,
    /// What the test itself got wrong (artefacts, not structure), in the order checked.
    #[serde(default)]
    pub test_causes: Vec<TestCause>,
}

impl DiagnoseReport {
    /// The fits of the chain: the start, then each step's.
    pub fn chain(&self) -> Vec<&FitReport> {
        std::iter::once(&self.start)
            .chain(self.steps.iter().map(|s| &s.fit))
            .collect()
    }

    /// Whether the final fit differs from the chain's last (refitted with a robust loss,
    /// its intervals widened for coloured noise): it is then shown as a row of its own.
    pub fn final_differs(&self) -> bool {
        let last = self.steps.last().map_or(&self.start, |s| &s.fit);
        let kp = |r: &FitReport| (r.model.get(Param::Kp), r.interval(Param::Kp));
        self.final_fit.model != last.model || kp(&self.final_fit) != kp(last)
    }

    /// The rows of the chain table: the chain, then the final fit when it differs.
    pub fn rows(&self) -> Vec<&FitReport> {
        let mut rows = self.chain();
        if self.final_differs() {
            rows.push(&self.final_fit);
        }
        rows
    }
}

/// BIC of a fit: N·ln(MSE) + p·ln(N), from the fit's ln MSE (finite at any scale).
pub fn bic(r: &FitReport) -> f64 {
    let n = r.n as f64;
    n * r.ln_mse + r.params.len() as f64 * n.ln()
}

/// The residual analysis of a fit on its data.
pub fn analyse(report: &FitReport, data: &FitData) -> Option<ResidualAnalysis> {
    let r = report.residuals(data).ok()?;
    let bounds = residuals::boundaries(&report.model, data);
    Some(residuals::analyse(&data.times, &r, None, bounds))
}

/// The whiteness test of a fit's residuals on its data ([`residuals::whiteness`]).
fn whiteness(report: &FitReport, data: &FitData) -> Option<residuals::Whiteness> {
    report
        .residuals(data)
        .ok()
        .map(|r| residuals::whiteness(&r))
}

/// Runs the loop from `start`, fitted from its automatic guess; Y0 is held at
/// `start_values`' Y0 when the structure holds it (e.g. 0 for a model that starts at zero).
pub fn diagnose(
    data: &FitData,
    start: Structure,
    start_values: Option<Values>,
    options: &DiagnoseOptions,
) -> Result<DiagnoseReport, FitError> {
    let held_y0 = start_values.map(|v| v.get(Param::Y0));
    let mut guess = auto_guess(data, start, held_y0);
    if let Some(y0) = held_y0 {
        guess.set(Param::Y0, y0);
    }
    let first = fit(data, start, guess, &options.fit, &mut ())?;
    Ok(diagnose_from(data, first, options))
}

/// Runs the loop from a fit the student already has.
///
/// The order of reasoning: the test's causes first ([`handling::handle`]: not at rest,
/// outliers, a clipped span, a disturbance), each handled so that the loop sees the handled
/// problem (the fits of the chain are on the samples left in); then the model's causes, one
/// extension at a time (or two at once, [`next_step`]); then the robust loss on the
/// outliers and the intervals widened for coloured noise ([`handling::finish`]).
pub fn diagnose_from(
    data: &FitData,
    start: FitReport,
    options: &DiagnoseOptions,
) -> DiagnoseReport {
    diagnose_tracked(data, start, options, &Tracker::none())
}

/// [`diagnose_from`] reporting its progress to `tracker`, and ending early (with the chain
/// made so far) when the tracker says it was cancelled.
pub fn diagnose_tracked(
    data: &FitData,
    start: FitReport,
    options: &DiagnoseOptions,
    tracker: &Tracker,
) -> DiagnoseReport {
    let handled = handling::handle(data, start, &options.fit);
    let (mut current, mut steps, mut adequate) = run_loop(&handled, options, &EXTENSIONS, tracker);
    if current.model.structure.underdamped && !oscillates(&current) {
        // The pair ended overdamped (ζ ≥ 1 within its interval, once the other extensions
        // took their part): it is two real poles, and the chain is made again without the
        // oscillation, so that its steps name the extra pole.
        let real: Vec<Extension> = EXTENSIONS
            .into_iter()
            .filter(|e| *e != Extension::Underdamped)
            .collect();
        (current, steps, adequate) = run_loop(&handled, options, &real, tracker);
    }
    let mut test_causes = handled.causes.clone();
    let current = handling::finish(&handled, current, adequate, &mut test_causes);
    let mut verdict = verdict(&handled.data, &current, adequate);
    verdict.structure = Some(current.model.structure);
    verdict.artefacts = Artefacts::of(&test_causes);
    let kp = current.model.get(Param::Kp);
    DiagnoseReport {
        start: handled.start,
        static_gain: (kp, current.interval(Param::Kp)),
        gain_trade: gain_trade(&current),
        final_fit: current,
        steps,
        adequate,
        verdict: Some(verdict),
        test_causes,
    }
}

/// The loop on the handled record from its start, with the extensions `allowed`: the last
/// fit, the steps, and whether it ended because no extension paid.
fn run_loop(
    handled: &handling::Handled,
    options: &DiagnoseOptions,
    allowed: &[Extension],
    tracker: &Tracker,
) -> (FitReport, Vec<Step>, bool) {
    let mut current = handled.start.clone();
    let mut steps = Vec::new();
    let mut allowed = allowed.to_vec();
    for k in 0..options.max_steps {
        if tracker.cancelled() {
            break;
        }
        tracker.extension(k + 1);
        // The first step's extensions may have been fitted by the test causes' handling.
        let known = handled.start_extensions.as_ref().filter(|_| k == 0);
        let Some(step) = next_step_with(&handled.data, &current, &allowed, known, tracker) else {
            return (current, steps, true);
        };
        current = step.step.fit.clone();
        let added = step.extension;
        steps.push(step.step);
        // The backward look: a term added earlier that the later ones made useless is
        // taken out, and not tried again (the chain would go round).
        while let Some((extension, removal)) = backward_step(&handled.data, &current, added) {
            allowed.retain(|e| *e != extension);
            current = removal.fit.clone();
            steps.push(removal);
        }
    }
    (current, steps, false)
}

/// The terms of `current` the backward look may take out, but not `added`, the one just
/// paid for: the first whose term no longer pays ([`no_longer_pays`]), with the step that
/// removes it.
fn backward_step(
    data: &FitData,
    current: &FitReport,
    added: Extension,
) -> Option<(Extension, Step)> {
    // The refits without each term are independent: spread over the cores, the first in
    // EXTENSIONS' order that no longer pays is taken.
    let removable: Vec<(Extension, Structure, Param)> = EXTENSIONS
        .into_iter()
        .filter(|e| *e != added)
        .filter_map(|e| {
            let (s, param) = e.removed(current.model.structure)?;
            Some((e, s, param))
        })
        .collect();
    let refits = super::parallel::map(&removable, |&(_, s, _)| refit_without(data, current, s));
    removable
        .into_iter()
        .zip(refits)
        .find_map(|((e, _, param), without)| {
            let without = without?;
            let delta = judged_change(data, &without, current);
            no_longer_pays(current, param, delta).then(|| {
                let step = Step {
                    cause: e.cause(&current.model.values),
                    paired: None,
                    evidence: Evidence::NoLongerPays {
                        param,
                        value: current.model.get(param),
                        ci95: current.interval(param),
                        criterion_delta: delta,
                    },
                    interval: None,
                    gain: gain(current, &without),
                    fit: without,
                    removed: true,
                };
                (e, step)
            })
        })
}

/// Whether the term of `param` no longer pays in `current`: the corrected BIC change of
/// adding it back (`delta`, from the model without it) is not below −[`BIC_THRESHOLD`], or
/// a dead time ended at or below zero (no dead time: a step-instant lead's share at most).
fn no_longer_pays(current: &FitReport, param: Param, delta: f64) -> bool {
    let null_dead_time = param == Param::Td && current.model.get(Param::Td) <= 0.0;
    null_dead_time || !(delta.is_finite() && delta < -BIC_THRESHOLD)
}

/// `current` refitted without a term (structure `s`), from its own values (one start).
fn refit_without(data: &FitData, current: &FitReport, s: Structure) -> Option<FitReport> {
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let r = search_fit(data, s, current.model.values, &options, &mut ()).ok()?;
    let full = full_fit(data, r)?;
    full.ln_mse.is_finite().then_some(full)
}

/// The leading cause of what `current` gets wrong and the extended fit, or `None` when no
/// extension pays for itself. An extension is judged by the BIC corrected for its own fit's
/// residual correlation ([`judged_change`]), so that coloured noise buys no structure; when
/// no single extension pays but the residuals are far from white, pairs of extensions are
/// tried ([`best_pair`]: P1 → P2Z, P1 → P2D, …), and a pair that pays is one step naming
/// both causes.
pub fn next_step(data: &FitData, current: &FitReport) -> Option<Step> {
    next_step_with(data, current, &EXTENSIONS, None, &Tracker::none()).map(|c| c.step)
}

/// A step of the loop with the extension it made.
struct Chosen {
    extension: Extension,
    step: Step,
}

/// [`next_step`] with only the extensions `allowed`, choosing among the extensions `known`
/// when they were fitted already (of `current` on `data`).
fn next_step_with(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    known: Option<&Extensions>,
    tracker: &Tracker,
) -> Option<Chosen> {
    let candidates = match known {
        Some(Extensions(all)) => all
            .iter()
            .filter(|(e, _)| allowed.contains(e))
            .cloned()
            .collect(),
        None => candidates(data, current, allowed, tracker),
    };
    let lowest = |list: Vec<&(Extension, FitReport)>| {
        list.into_iter()
            .min_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)))
            .cloned()
    };
    let leader = lowest(candidates.iter().collect());
    let far = far_from_white(data, current);
    // Every candidate of the step is validated against the same current model.
    let validation = Validation::new(data, current);
    // The corrected BIC judges first: of the extensions that pay by it, the lowest BIC; only
    // when none does, and what is left is far from white, the lowest BIC by the plain one.
    // Of those, the lowest BIC that also predicts the part of the record it was not
    // fitted to ([`validates`]): a drift or a zero bought on the fitted part extrapolates
    // badly, a real pole does not.
    let mut paying: Vec<&(Extension, FitReport)> = candidates
        .iter()
        .filter(|(_, c)| pays(data, current, c))
        .collect();
    paying.sort_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)));
    prefer_pole_to_dead_time(&mut paying);
    let paying = paying
        .into_iter()
        .find(|(_, c)| validation.keeps(c))
        .cloned();
    let leader_extension = leader.as_ref().map(|(e, _)| *e);
    // The leader pays by the plain BIC but not by the corrected one: its residuals are
    // correlated, which coloured noise does, and so does a second effect still missing
    // (P2U without its dead time on the LECI test); pairs may tell, judged by the corrected
    // BIC, which coloured noise does not pass.
    let leader_plainly = leader
        .as_ref()
        .is_some_and(|(_, c)| plainly_pays(current, c));
    // A free Y0 pays by the corrected BIC only: one constant absorbs a share of any misfit
    // that is far from white (an actuator's motion the held input does not show, a model
    // still short of a pole), and an operating point that is really off leaves residuals
    // biased everywhere, which pay by both.
    let single = paying
        .or_else(|| leader.clone().filter(|(_, c)| far && validation.keeps(c)))
        .and_then(|w| on_every_sample(data, w))
        .filter(|(e, c)| {
            pays(data, current, c)
                || (far && *e != Extension::FreeOffset && plainly_pays(current, c))
        });
    let single = single.map(|w| look_ahead(data, current, allowed, w, &validation, tracker));
    let (extension, paired, candidate) = match single {
        Some(chosen) => chosen,
        None => {
            if !far && !leader_plainly {
                return None;
            }
            let ((mut e1, mut e2), c) = best_pair(data, current, allowed, tracker)?;
            if !pays(data, current, &c) || !validation.keeps(&c) {
                return None;
            }
            // The pair's member that did best alone is named first.
            if leader_extension == Some(e2) {
                std::mem::swap(&mut e1, &mut e2);
            }
            (e1, Some(e2.cause(&c.model.values)), c)
        }
    };
    // On a staircase, an extension must gain more than rounding alone lets it.
    if Staircase::of(data, current).is_some_and(|s| !s.beyond_rounding(data, current, &candidate)) {
        return None;
    }
    let cause = extension.cause(&candidate.model.values);
    let (evidence, interval) = explain(cause, data, current, &candidate);
    // The evidence points into the record, never past its ends (an interval set by a time
    // constant stuck at its bound may reach far beyond).
    let interval = interval.and_then(|i| data.within_record(i));
    Some(Chosen {
        extension,
        step: Step {
            cause,
            paired,
            evidence,
            interval,
            gain: gain(current, &candidate),
            fit: candidate,
            removed: false,
        },
    })
}

/// A dead time and one more pole the record cannot tell apart (their BICs within
/// [`BIC_THRESHOLD`]): the classic first-order-plus-dead-time reading of a slow second lag,
/// whose dead time trades with the slow lag and the gain on a record that has not settled.
/// The pole is put first: it is the process's own structure, and its gain the settled one.
fn prefer_pole_to_dead_time(paying: &mut [&(Extension, FitReport)]) {
    let Some(first) = paying.first() else { return };
    if first.0 != Extension::Delay {
        return;
    }
    let lead = bic(&first.1);
    if let Some(k) = paying
        .iter()
        .position(|(e, c)| *e == Extension::Pole && bic(c) - lead < BIC_THRESHOLD)
    {
        paying[..=k].rotate_right(1);
    }
}

/// Extensions that mimic a missing part of the dynamics from the first step: a dead time
/// takes an inverse response's dip or a fast lag's slow start, a drift a slow approach, a
/// free Y0 a share of any misfit. When one of them leads, the pairs are looked at too.
const STAND_INS: [Extension; 3] = [Extension::Delay, Extension::Drift, Extension::FreeOffset];

/// The one-step look-ahead, so that a first wrong turn does not trap the loop: when the
/// single extension chosen is a stand-in ([`STAND_INS`]) and what `current` leaves is far
/// from white, the best pair of dynamic extensions ([`best_pair`]) is taken instead if it
/// pays over the single one by the corrected BIC and predicts the held-out part as well
/// (P1 → P2Z for an inverse response, which a dead time first only approximates). The
/// chosen extension, a second one named with it, and the fit.
fn look_ahead(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    (e, c): (Extension, FitReport),
    validation: &Validation,
    tracker: &Tracker,
) -> (Extension, Option<Cause>, FitReport) {
    if !STAND_INS.contains(&e) || !far_from_white(data, current) {
        return (e, None, c);
    }
    let Some(((mut e1, mut e2), pair)) = best_pair(data, current, allowed, tracker) else {
        return (e, None, c);
    };
    let better = judged_change(data, &c, &pair) < -BIC_THRESHOLD;
    if !better || !validation.keeps(&pair) {
        return (e, None, c);
    }
    if e == e2 {
        std::mem::swap(&mut e1, &mut e2);
    }
    (e1, Some(e2.cause(&pair.model.values)), pair)
}

/// The residuals' RMSE must exceed the white noise read from the output's first differences
/// ([`super::rest::difference_noise`]) this many times for pairs to be tried: strongly
/// coloured noise (AR(1) up to ρ = 0.97) stays below it, a missing pair of effects leaves
/// tens of times the noise.
const FAR_FROM_WHITE: f64 = 8.0;

/// Whether what `current` leaves is far from white: not white by the residual analysis, and
/// its RMSE above [`FAR_FROM_WHITE`] times the output's white noise.
fn far_from_white(data: &FitData, current: &FitReport) -> bool {
    let noise = super::rest::difference_noise(&data.y);
    current.rmse > FAR_FROM_WHITE * noise && whiteness(current, data).is_some_and(|w| !w.white)
}

/// Whether `candidate` pays by the plain BIC: kept when what `current` leaves is far from
/// white (tens of times the noise is structure, not coloured noise, whatever the
/// correlation of a first extension's residuals).
fn plainly_pays(current: &FitReport, candidate: &FitReport) -> bool {
    let change = bic(candidate) - bic(current);
    change.is_finite() && change < -BIC_THRESHOLD
}

/// Whether `candidate` pays for its extra parameters over `current`: its corrected BIC
/// change is a finite number below −[`BIC_THRESHOLD`].
fn pays(data: &FitData, current: &FitReport, candidate: &FitReport) -> bool {
    let change = judged_change(data, current, candidate);
    change.is_finite() && change < -BIC_THRESHOLD
}

/// The BIC change of `candidate` over `current` with the likelihood term counted on the
/// candidate's effective number of independent residuals: N·(1 − ρ)/(1 + ρ), ρ the lag-one
/// autocorrelation of its residuals (clamped to [0, 0.99]; 0 leaves the plain BIC). A right
/// extension leaves white residuals and keeps its full gain; one that only absorbs coloured
/// noise leaves them correlated and must gain that much more.
pub fn judged_change(data: &FitData, current: &FitReport, candidate: &FitReport) -> f64 {
    let rho = candidate
        .residuals(data)
        .map_or(0.0, |r| lag_one(&r))
        .clamp(0.0, 0.99);
    let n = candidate.n as f64;
    let n_eff = n * (1.0 - rho) / (1.0 + rho);
    let extra = candidate.params.len() as f64 - current.params.len() as f64;
    n_eff * (candidate.ln_mse - current.ln_mse) + extra * n.ln()
}

/// Extensions tried in pairs: the dynamic ones (an offset, an integrator or a drift in a
/// pair would only absorb what the first named alone could not).
const PAIRED: [Extension; 4] = [
    Extension::Delay,
    Extension::Underdamped,
    Extension::Pole,
    Extension::Zero,
];

/// The pair of extensions whose refit has the lowest BIC, started from each one's starts.
fn best_pair(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    tracker: &Tracker,
) -> Option<((Extension, Extension), FitReport)> {
    let paired: Vec<Extension> = PAIRED.into_iter().filter(|e| allowed.contains(e)).collect();
    let pairs: Vec<((Extension, Extension), Structure)> = paired
        .iter()
        .enumerate()
        .flat_map(|(i, &e1)| paired[i + 1..].iter().map(move |&e2| (e1, e2)))
        .filter_map(|(e1, e2)| {
            let s = e1
                .apply(current.model.structure)
                .and_then(|s| e2.apply(s))?;
            Some(((e1, e2), s))
        })
        .collect();
    // The pairs' automatic guesses (a regression each) on every core; both members' fresh
    // starts begin with the pair's own guess (no pair holds a free offset: one Y0).
    let held = held_y0(current, Extension::Delay);
    let guesses = super::parallel::map(&pairs, |&(_, s)| extended_guess(data, s, held));
    let mut jobs = Vec::new();
    for (&((e1, e2), s), &auto) in pairs.iter().zip(&guesses) {
        let mut starts = fresh_starts_from(data, auto, e1, held);
        starts.extend(fresh_starts_from(data, auto, e2, held));
        starts.extend(warm_starts(data, current, e1));
        starts.extend(warm_starts(data, current, e2));
        // One run of a start is enough.
        let mut distinct: Vec<Values> = Vec::with_capacity(starts.len());
        starts.into_iter().for_each(|g| {
            if !distinct.contains(&g) {
                distinct.push(g);
            }
        });
        jobs.extend(distinct.into_iter().map(|g| ((e1, e2), s, g)));
    }
    let (pair, r) = best_fits(data, current, &jobs, PAIRS_TAKEN_ON, tracker)
        .into_iter()
        .reduce(|best, next| {
            if bic(&next.1) < bic(&best.1) {
                next
            } else {
                best
            }
        })?;
    on_every_sample(data, (pair.0, r)).map(|(_, r)| (pair, r))
}

/// Each job's structure fitted from its start (one start, on the record's reduction for a
/// long record), spread over the cores ([`super::parallel`]); for each key, in the order the
/// keys first come, the fit with the lowest cost that is not an alias, leans on no lag
/// beyond the record, and is finite.
///
/// The starts are screened first: each key's first runs [`SCREEN_ITERATIONS`] iterations,
/// its others [`PRE_SCREEN_ITERATIONS`], of which the [`PRE_SCREEN_KEPT`] lowest go on to
/// the whole screen; then only the [`KEPT_PER_KEY`] lowest of each key go on to convergence,
/// of the `leaders` keys whose best screened fit has the lowest BIC. When none of those ends
/// acceptable the next ones go on, until one ends where a rejected one ended
/// ([`same_optimum`]: the key's starts share that basin). Starts in the same basin agree
/// long before they converge, and one that is far behind after the screen does not
/// overtake the leaders.
fn best_fits<K: Copy + PartialEq + Sync + Send>(
    data: &FitData,
    current: &FitReport,
    jobs: &[(K, Structure, Values)],
    leaders: usize,
    tracker: &Tracker,
) -> Vec<(K, FitReport)> {
    let full = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let screen = FitOptions {
        max_iterations: SCREEN_ITERATIONS,
        screen: true,
        ..full
    };
    let pre_screen = FitOptions {
        max_iterations: PRE_SCREEN_ITERATIONS,
        ..screen
    };
    let screen_rest = FitOptions {
        max_iterations: SCREEN_ITERATIONS - PRE_SCREEN_ITERATIONS,
        ..screen
    };
    let fit_with = |options: &FitOptions, s: Structure, g: Values| {
        if tracker.cancelled() {
            return None;
        }
        let r = search_fit(data, s, g, options, &mut ());
        tracker.fitted();
        r.ok().filter(|r| r.ln_mse.is_finite())
    };
    // Each key's first start runs the whole screen, its others a short one, all at once;
    // then each key's leading few of those go on to the whole screen.
    let first_of_key: Vec<bool> = (0..jobs.len())
        .map(|i| !jobs[..i].iter().any(|j| j.0 == jobs[i].0))
        .collect();
    let all: Vec<usize> = (0..jobs.len()).collect();
    let mut screened = super::parallel::map(&all, |&i| {
        let options = if first_of_key[i] {
            &screen
        } else {
            &pre_screen
        };
        fit_with(options, jobs[i].1, jobs[i].2)
    });
    let later: Vec<usize> = all.into_iter().filter(|&i| !first_of_key[i]).collect();
    let going_on = pre_screen_leaders(jobs, &screened, &later);
    let fits = super::parallel::map(&going_on, |&i| {
        let r = screened[i].as_ref()?;
        fit_with(&screen_rest, r.model.structure, r.model.values)
    });
    for (&i, r) in going_on.iter().zip(fits) {
        if r.is_some() {
            screened[i] = r;
        }
    }
    let acceptable = |r: &FitReport| !aliased(r) && !beyond_record(data, &current.model, &r.model);
    let mut keys: Vec<K> = Vec::new();
    jobs.iter().for_each(|(k, _, _)| {
        if !keys.contains(k) {
            keys.push(*k);
        }
    });
    // Per key, its screened fits from the lowest cost.
    let mut queues: Vec<Vec<FitReport>> = keys
        .iter()
        .map(|key| {
            let mut q: Vec<FitReport> = jobs
                .iter()
                .zip(&screened)
                .filter(|((k, _, _), _)| k == key)
                .filter_map(|(_, r)| r.clone())
                .collect();
            q.sort_by(|a, b| a.ln_mse.total_cmp(&b.ln_mse));
            q.reverse();
            q
        })
        .collect();
    if leaders < keys.len() {
        // Only the keys whose best screened fit has the lowest BICs go on.
        let lead = |i: usize| queues[i].last().map_or(f64::INFINITY, bic);
        let mut order: Vec<usize> = (0..keys.len()).collect();
        order.sort_by(|&a, &b| lead(a).total_cmp(&lead(b)));
        order[leaders..].iter().for_each(|&i| queues[i].clear());
    }
    let mut best: Vec<Option<FitReport>> = vec![None; keys.len()];
    let mut rejected: Vec<Vec<f64>> = vec![Vec::new(); keys.len()];
    loop {
        let round: Vec<(usize, FitReport)> = queues
            .iter_mut()
            .enumerate()
            .filter(|(i, _)| best[*i].is_none())
            .flat_map(|(i, q)| {
                let take = q.len().min(KEPT_PER_KEY);
                q.split_off(q.len() - take)
                    .into_iter()
                    .rev()
                    .map(move |r| (i, r))
            })
            .collect();
        if round.is_empty() {
            break;
        }
        // Each goes on from where its screen left it (one that converged there is only
        // polished, and given its intervals).
        let finished = super::parallel::map(&round, |(_, r)| {
            fit_with(&full, r.model.structure, r.model.values)
        });
        for ((i, _), r) in round.iter().zip(finished) {
            let Some(r) = r else { continue };
            if !acceptable(&r) {
                // A start that ends where a rejected one ended: the key's starts share one
                // basin, and the rest of its queue would end there too.
                if rejected[*i].iter().any(|&b| same_optimum(b, bic(&r))) {
                    queues[*i].clear();
                }
                rejected[*i].push(bic(&r));
                continue;
            }
            if best[*i].as_ref().is_none_or(|b| r.ln_mse < b.ln_mse) {
                best[*i] = Some(r);
            }
        }
    }
    keys.into_iter()
        .zip(best)
        .filter_map(|(k, r)| Some((k, r?)))
        .collect()
}

/// Of the starts `picked` (all but each key's first), those of each key whose short screen
/// ([`PRE_SCREEN_ITERATIONS`]) ended unfinished with the lowest costs, [`PRE_SCREEN_KEPT`]
/// per key: they go on to the whole screen.
fn pre_screen_leaders<K: Copy + PartialEq>(
    jobs: &[(K, Structure, Values)],
    screened: &[Option<FitReport>],
    picked: &[usize],
) -> Vec<usize> {
    let unfinished = |i: usize| {
        screened[i]
            .as_ref()
            .filter(|r| r.termination == Termination::IterationLimit)
            .map(|r| r.ln_mse)
    };
    let mut going_on = Vec::new();
    for (k, &i) in picked.iter().enumerate() {
        let Some(cost) = unfinished(i) else { continue };
        let ahead = picked[..k]
            .iter()
            .chain(&picked[k + 1..])
            .filter(|&&j| jobs[j].0 == jobs[i].0)
            .filter(|&&j| unfinished(j).is_some_and(|c| c < cost || (c == cost && j < i)))
            .count();
        if ahead < PRE_SCREEN_KEPT {
            going_on.push(i);
        }
    }
    going_on
}

/// Iterations of the short screen of a key's later starts ([`best_fits`]): a start far
/// behind its key's others after these is not taken further.
const PRE_SCREEN_ITERATIONS: usize = 3;
/// A key's later starts that go on from the short screen to the whole one.
const PRE_SCREEN_KEPT: usize = 1;

/// Whether two converged fits of one structure, of BICs `a` and `b`, are the same optimum:
/// BICs within [`SAME_OPTIMUM`] (a tenth of a unit of N·ln MSE: far below any difference the
/// loop judges by, far above what two converged runs into one basin differ by).
fn same_optimum(a: f64, b: f64) -> bool {
    (a - b).abs() <= SAME_OPTIMUM
}

/// See [`same_optimum`].
const SAME_OPTIMUM: f64 = 0.1;

/// Pairs of extensions taken on to convergence after the screen (those whose best screened
/// fit has the lowest BIC): the pair search only needs its winner.
const PAIRS_TAKEN_ON: usize = 2;
/// Iterations the whole screen runs before the leaders are picked ([`best_fits`]): every
/// candidate's first start, and those of its others that lead after the short screen.
const SCREEN_ITERATIONS: usize = 6;
/// Screened starts of each candidate taken on to convergence at a time ([`best_fits`]): the
/// leader alone, since starts in the same basin agree after the screen; the next one goes
/// on only when the leader ends unacceptable (an alias, a lag beyond the record).
const KEPT_PER_KEY: usize = 1;

fn aliased(r: &FitReport) -> bool {
    r.warnings
        .iter()
        .any(|w| matches!(w, super::fit::FitWarning::Alias { .. }))
}

fn gain(before: &FitReport, after: &FitReport) -> Gain {
    Gain {
        rmse_before: before.rmse,
        rmse_after: after.rmse,
        rmse_ratio: if after.rmse > 0.0 {
            before.rmse / after.rmse
        } else {
            f64::INFINITY
        },
        fit_percent_before: before.fit_percent,
        fit_percent_after: after.fit_percent,
        criterion_delta: bic(after) - bic(before),
    }
}

/// The single extensions of one fit on one record ([`candidates`], every one allowed),
/// fitted once, when first asked for: the disturbance test asks whether one of them explains
/// the record as well as a disturbance would ([`StartExtensions::reach`]), and the loop's
/// first step chooses among the same fits when the record and the start it was asked on are
/// still the loop's ([`Extensions`]).
pub struct StartExtensions<'a> {
    data: &'a FitData,
    current: &'a FitReport,
    found: std::sync::OnceLock<Vec<(Extension, FitReport)>>,
}

impl<'a> StartExtensions<'a> {
    pub fn new(data: &'a FitData, current: &'a FitReport) -> Self {
        Self {
            data,
            current,
            found: std::sync::OnceLock::new(),
        }
    }

    fn get(&self) -> &[(Extension, FitReport)] {
        self.found
            .get_or_init(|| candidates(self.data, self.current, &EXTENSIONS, &Tracker::none()))
    }

    /// Whether the best of the extensions explains the record with a BIC at most `bound`
    /// (refitted on every sample when found on a long record's reduction).
    pub fn reach(&self, bound: f64) -> bool {
        self.get()
            .iter()
            .min_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)))
            .cloned()
            .and_then(|winner| on_every_sample(self.data, winner))
            .is_some_and(|(_, r)| bic(&r) <= bound)
    }

    /// The extensions fitted, if any were asked for.
    pub fn fitted(self) -> Option<Extensions> {
        self.found.into_inner().map(Extensions)
    }
}

/// The single extensions of the loop's start, fitted before the loop ([`StartExtensions`]).
#[derive(Debug, Clone)]
pub struct Extensions(Vec<(Extension, FitReport)>);

/// Every extension of `current` that can be fitted, with its refit (on the record's
/// reduction for a long record, [`search_fit`]); aliased fits, lags beyond the record and
/// "pairs" fitted overdamped left out.
fn candidates(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    tracker: &Tracker,
) -> Vec<(Extension, FitReport)> {
    let extended: Vec<(Extension, Structure)> = allowed
        .iter()
        .filter_map(|&e| Some((e, e.apply(current.model.structure)?)))
        .collect();
    // The starts (each an automatic guess: a regression) on every core.
    let starts = super::parallel::map(&extended, |&(e, s)| starts(data, current, e, s));
    let jobs: Vec<(Extension, Structure, Values)> = extended
        .iter()
        .zip(starts)
        .flat_map(|(&(e, s), starts)| starts.into_iter().map(move |g| (e, s, g)))
        .collect();
    best_fits(data, current, &jobs, usize::MAX, tracker)
        .into_iter()
        .filter(|(e, r)| kept_candidate(data, current, *e, r))
        .collect()
}

/// A candidate's own conditions: a pair that oscillates, a drift the record shows, a
/// finite BIC.
fn kept_candidate(data: &FitData, current: &FitReport, e: Extension, r: &FitReport) -> bool {
    let own = match e {
        Extension::Underdamped => oscillates(r),
        Extension::Drift => drift_shown(data, &current.model, r),
        _ => true,
    };
    own && bic(r).is_finite()
}

/// Whether a fit with a drift term shows it where only a drift explains it
/// ([`read_drift`]: on the stretches where no input change is still answered, the same
/// slope whatever the change, in a straight line).
fn drift_shown(data: &FitData, current: &Model, r: &FitReport) -> bool {
    read_drift(data, current, r).is_some_and(|d| d.shows(r.model.get(Param::Drift)))
}

/// Whether a fitted pair oscillates: ζ below [`OVERDAMPED_ZETA`], and its 95 % interval
/// below 1. A "pair" fitted with ζ ≥ 1 is two real poles, and one whose interval reaches 1
/// cannot be told from them (a dead time and two close poles make an S-shape a pair with
/// ζ ≈ 0.85 also draws): that is the extra-pole extension, not an oscillation, and must not
/// take its name.
fn oscillates(r: &FitReport) -> bool {
    r.model.get(Param::Zeta) < OVERDAMPED_ZETA
        && r.interval(Param::Zeta).is_none_or(|(_, hi)| hi < 1.0)
}

/// Scale (issue 10): on a long record the candidates are fitted on its reduction
/// ([`search_fit`], statistics standing for the whole record's) and only the chosen one is
/// refitted on every sample, from its optimum; a record [`super::reduce`] leaves as it is
/// keeps its fit.
fn on_every_sample(
    data: &FitData,
    (extension, r): (Extension, FitReport),
) -> Option<(Extension, FitReport)> {
    full_fit(data, r).map(|full| (extension, full))
}

/// A fit found on the record's reduction ([`search_fit`]) refitted on every sample from its
/// optimum; the fit itself when the record is not reduced.
fn full_fit(data: &FitData, r: FitReport) -> Option<FitReport> {
    if super::reduce::reduce(&data.times, &data.input).is_none() {
        return Some(r);
    }
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    fit(data, r.model.structure, r.model.values, &options, &mut ()).ok()
}

/// The starts of an extension: a few warm ones from the current fit, and the extended
/// structure's automatic guess.
fn starts(data: &FitData, current: &FitReport, extension: Extension, s: Structure) -> Vec<Values> {
    let mut starts = warm_starts(data, current, extension);
    starts.extend(fresh_starts(data, current, extension, s));
    starts
}

/// The slowest time constant of `model` (s): its poles' ([`time_constants`]: a pair's Tw,
/// not its envelope Tw/ζ, for a lightly damped ringing shows its period however slowly it
/// decays) and a zero's |Tz|; 0 for a model without any.
fn slowest_lag(model: &Model) -> f64 {
    let zero = if model.structure.zero {
        model.get(Param::Tz).abs()
    } else {
        0.0
    };
    time_constants(model)
        .first()
        .copied()
        .unwrap_or(0.0)
        .max(zero)
}

/// Whether `candidate` leans on a time constant slower than the record can show: longer
/// than the record after its first change, and more than twice `current`'s slowest. Such a
/// lag (a pole or zero of thousands of seconds on a record of minutes) is not identifiable:
/// it only bends the tail, as a drift would, and its static gain is an extrapolation. It is
/// the mirror of [`aliased`], a lag too fast for the sampling.
fn beyond_record(data: &FitData, current: &Model, candidate: &Model) -> bool {
    let slowest = slowest_lag(candidate);
    slowest > data.duration() && slowest > 2.0 * slowest_lag(current)
}

/// The current values with the new parameter set to a few plausible values.
fn warm_starts(data: &FitData, current: &FitReport, extension: Extension) -> Vec<Values> {
    let v = current.model.values;
    let s = current.model.structure;
    let t_char = characteristic_time(current, data);
    let with = |pairs: &[(Param, f64)]| {
        let mut w = v;
        for &(p, x) in pairs {
            w.set(p, x);
        }
        w
    };
    match extension {
        Extension::Delay => [0.1, 0.3, 0.7]
            .iter()
            .map(|f| with(&[(Param::Td, f * t_char)]))
            .collect(),
        Extension::FreeOffset | Extension::Integrator => vec![v],
        Extension::Drift => vec![with(&[(Param::Drift, 0.0)])],
        Extension::Underdamped => {
            let period = features(data, Some(v.get(Param::Y0))).period;
            let wd = period.map_or(1.0 / t_char, |p| std::f64::consts::TAU / p);
            [0.15, 0.4]
                .iter()
                .map(|&z: &f64| {
                    with(&[
                        (Param::Zeta, z),
                        (Param::Tw, (1.0 - z * z).sqrt() / wd),
                        (Param::Tp3, 0.3 * t_char),
                    ])
                })
                .collect()
        }
        Extension::Pole => {
            let next = match s.poles {
                1 => Param::Tp2,
                _ => Param::Tp3,
            };
            let td = if s.delay { v.get(Param::Td) } else { 0.0 };
            [0.15, 0.5]
                .iter()
                .flat_map(|f| {
                    let added = f * t_char;
                    // The new lag takes part of the old one and of the dead time.
                    [
                        with(&[(next, added)]),
                        with(&[
                            (next, added),
                            (Param::Tp1, (v.get(Param::Tp1) - added).max(0.1 * t_char)),
                            (Param::Td, (td - added).max(0.0)),
                        ]),
                    ]
                })
                .collect()
        }
        Extension::Zero => [-1.0, -0.3, 0.7, 2.5]
            .iter()
            .map(|f| with(&[(Param::Tz, f * t_char)]))
            .collect(),
    }
}

/// Starts read off the data rather than the current fit, which may have collapsed where the
/// structure could not follow the curve (a P2 on an overshoot fits two tiny lags): the extended
/// structure's automatic guess, with Y0 at the current value, or read off the first samples
/// when the offset is the extension; for a zero, the guess with Tz spread over multiples of
/// the 63 % time on the side the curve points at (an overshoot: Tz above the lags; a dip first:
/// Tz < 0).
fn fresh_starts(
    data: &FitData,
    current: &FitReport,
    extension: Extension,
    s: Structure,
) -> Vec<Values> {
    let held_y0 = held_y0(current, extension);
    fresh_starts_from(data, extended_guess(data, s, held_y0), extension, held_y0)
}

/// The Y0 an extension's fresh starts hold: the current one, unless the offset is the
/// extension.
fn held_y0(current: &FitReport, extension: Extension) -> Option<f64> {
    (extension != Extension::FreeOffset).then(|| current.model.get(Param::Y0))
}

/// The automatic guess of the extended structure `s` with Y0 held at `held_y0` (the
/// costliest part of a fresh start: a regression over a grid of lags).
fn extended_guess(data: &FitData, s: Structure, held_y0: Option<f64>) -> Values {
    let mut auto = auto_guess(data, s, held_y0);
    if let Some(y0) = held_y0 {
        auto.set(Param::Y0, y0);
    }
    auto
}

/// [`fresh_starts`] from the extended structure's guess `auto`.
fn fresh_starts_from(
    data: &FitData,
    auto: Values,
    extension: Extension,
    held_y0: Option<f64>,
) -> Vec<Values> {
    if extension != Extension::Zero {
        return vec![auto];
    }
    let f = features(data, held_y0);
    let t63 = f.t63.unwrap_or(data.duration() / 3.0);
    let mut factors = vec![];
    if f.overshoot > 0.0 {
        factors.extend([1.0, 2.0, 4.0]);
    }
    if f.t_dip.is_some() {
        factors.extend([-0.3, -1.0]);
    }
    let mut starts = vec![auto];
    starts.extend(factors.iter().map(|k| {
        let mut v = auto;
        v.set(Param::Tz, k * t63);
        v
    }));
    starts
}

/// The model's main time constant (Tw for an underdamped pair, else Tp1), at least one
/// sampling period.
fn characteristic_time(report: &FitReport, data: &FitData) -> f64 {
    let m = &report.model;
    let t = if m.structure.underdamped {
        m.get(Param::Tw)
    } else {
        m.get(Param::Tp1)
    };
    t.max(data.sampling_period())
}

/// Mean of the residuals over [a, b], their count and the fraction sharing the mean's sign.
fn interval_stats(data: &FitData, r: &[f64], (a, b): (f64, f64)) -> Bias {
    let inside: Vec<f64> = data
        .times
        .iter()
        .zip(r)
        .filter(|(t, _)| **t >= a && **t <= b)
        .map(|(_, e)| *e)
        .collect();
    bias_of(&inside, (a, b))
}

/// The mean of the residuals `inside` and the share of them of its sign, said of (a, b).
fn bias_of(inside: &[f64], (start, end): (f64, f64)) -> Bias {
    let n = inside.len();
    let none = Bias {
        start,
        end,
        n: 0,
        mean: 0.0,
        same_sign: 0.0,
    };
    if n == 0 {
        return none;
    }
    let mean = inside.iter().sum::<f64>() / n as f64;
    let same = inside
        .iter()
        .filter(|e| e.signum() == mean.signum())
        .count() as f64
        / n as f64;
    Bias {
        n,
        mean,
        same_sign: same,
        ..none
    }
}

/// The residuals `r` just after every input change, each signed by its change's direction
/// (the dead time's misfit turns with the change), gathered into one [`Bias`] from the first
/// change to the last window's end. A change's window runs from the sample after it to the
/// first sample `td` or more after it: where the model has moved and the data has not yet
/// (or less), however short the dead time against the sampling.
fn after_each_change(data: &FitData, r: &[f64], td: f64) -> Bias {
    let changes = &data.input.changes;
    let t = &data.times;
    let mut end = f64::NAN;
    let mut oriented = Vec::new();
    for c in changes {
        let first = t.partition_point(|&s| s <= c.t);
        let last = t
            .partition_point(|&s| s < c.t + td)
            .min(t.len().saturating_sub(1));
        if first <= last && first < t.len() {
            oriented.extend(r[first..=last].iter().map(|e| c.du.signum() * e));
            end = t[last];
        }
    }
    let start = changes.first().map_or(0.0, |c| c.t);
    bias_of(&oriented, (start, if end.is_nan() { start } else { end }))
}

/// The evidence for a cause: which statistic over which interval.
fn explain(
    cause: Cause,
    data: &FitData,
    current: &FitReport,
    extended: &FitReport,
) -> (Evidence, Option<(f64, f64)>) {
    let r = current.residuals(data).unwrap_or_default();
    // The residual analysis (correlations at every lag: the costliest statistic here) only
    // for the causes whose evidence reads it.
    let analysis = std::cell::OnceCell::new();
    let analysis = || analysis.get_or_init(|| analyse(current, data));
    let v = extended.model.values;
    let t0 = data.input.t0();
    let t_first = data.times.first().copied().unwrap_or(t0);
    let t_last = data.times.last().copied().unwrap_or(t0);
    // The effect of the input's largest excursion from u0 (the step's, for one step).
    let effect = (extended.model.get(Param::Kp) * data.input.du_scale()).abs();
    let region = |kind: residuals::RegionKind| {
        analysis()
            .as_ref()
            .and_then(|a| a.regions.iter().find(|g| g.kind == kind).cloned())
    };
    match cause {
        Cause::DeadTime => {
            let td = v.get(Param::Td);
            let changes = data.input.changes.len();
            let bias = match changes {
                0 | 1 => interval_stats(data, &r, (t0, t0 + td)),
                _ => after_each_change(data, &r, td),
            };
            let interval = (bias.start, bias.end);
            (Evidence::DeadTime { bias, td, changes }, Some(interval))
        }
        Cause::Offset => {
            let bias = interval_stats(data, &r, (t_first, t_last));
            (
                Evidence::Offset {
                    bias,
                    y0_held: current.model.get(Param::Y0),
                    y0_estimated: v.get(Param::Y0),
                },
                Some((t_first, t_last)),
            )
        }
        Cause::Oscillation => {
            let period = analysis().as_ref().and_then(|a| a.dominant_period);
            let transient = region(residuals::RegionKind::Transient).map(|g| (g.start, g.end));
            (
                Evidence::Oscillation {
                    period,
                    omega_d: extended.model.damped_frequency(),
                    zeta: v.get(Param::Zeta),
                },
                transient,
            )
        }
        Cause::ExtraPole => {
            let start = t0
                + if current.model.structure.delay {
                    current.model.get(Param::Td)
                } else {
                    0.0
                };
            let interval = (start, start + characteristic_time(current, data));
            let bias = interval_stats(data, &r, interval);
            let added = [Param::Tp3, Param::Tp2]
                .into_iter()
                .find(|p| extended.model.structure.params().contains(p))
                .map(|p| (p, v.get(p)));
            (Evidence::ExtraPole { bias, added }, Some(interval))
        }
        Cause::Zero => {
            let f = features(data, Some(current.model.get(Param::Y0)));
            let tp = f.t_peak.map(|t| t + t0);
            (
                Evidence::Zero {
                    overshoot: f.overshoot,
                    peak_time: tp,
                    underdamped: current.model.structure.underdamped,
                    tz: v.get(Param::Tz),
                },
                tp.map(|t| (t0, t + (t - t0))),
            )
        }
        Cause::InverseResponse => {
            let f = features(data, Some(current.model.get(Param::Y0)));
            let dip = f.t_dip.map(|t| t + t0);
            (
                Evidence::InverseResponse {
                    undershoot: f.undershoot,
                    dip_time: dip,
                    tz: v.get(Param::Tz),
                },
                dip.map(|t| (t0, t + (t - t0))),
            )
        }
        Cause::Integrator => {
            let tail = region(residuals::RegionKind::Tail);
            let slope = features(data, None).final_slope;
            (
                Evidence::Integrator {
                    slope,
                    per_time_constant: slope.abs() * current.model.get(Param::Tp1)
                        / effect.max(f64::MIN_POSITIVE),
                    trend_z: tail.map(|g| g.slope_z),
                },
                tail.map(|g| (g.start, g.end)),
            )
        }
        Cause::Drift => {
            let reading = read_drift(data, &current.model, extended);
            let models = [&current.model, &extended.model];
            let stretches = crate::drift_evidence::settled_stretches(&models, data);
            let span = stretches
                .iter()
                .map(|s| (s.start.max(t_first), s.end.min(t_last)))
                .filter(|(a, b)| a < b)
                .fold(None, |acc: Option<(f64, f64)>, (a, b)| match acc {
                    None => Some((a, b)),
                    Some((lo, hi)) => Some((lo.min(a), hi.max(b))),
                });
            (
                Evidence::Drift {
                    tail: reading.map(|d| (d.slope, d.z)),
                    drift: v.get(Param::Drift),
                },
                span,
            )
        }
        Cause::None => (Evidence::None, None),
    }
}

/// Why the final model is adequate (or why the loop stopped), with the whiteness statistics.
fn verdict(data: &FitData, report: &FitReport, adequate: bool) -> Verdict {
    let analysis = whiteness(report, data);
    let white = analysis.as_ref().is_some_and(|a| a.white);
    Verdict {
        structure: None,
        artefacts: Artefacts::default(),
        ending: match (adequate, white) {
            (true, _) if Staircase::of(data, report).is_some() => Ending::WithinRounding,
            (true, true) => Ending::Adequate,
            (true, false) => Ending::NotWhite,
            (false, _) => Ending::StepLimit,
        },
        whiteness: analysis.map(|a| Whiteness {
            outside: a.outside_band.len(),
            lags: a.autocorrelation.len().saturating_sub(1),
            runs_z: a.runs.z,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::excitation::Excitation;

    fn model(code: &str, params: &[(Param, f64)]) -> Model {
        let mut v = Values::default();
        params.iter().for_each(|&(p, x)| v.set(p, x));
        Model::new(Structure::parse(code).unwrap(), v)
    }

    /// A P1 record (Kp 2, τ 10 s, Y0 50, step at 20.4 s between samples), noise ± 0.02.
    fn p1_record() -> FitData {
        let times: Vec<f64> = (0..=150).map(f64::from).collect();
        let input = Excitation::step(20.4, 1.0);
        let truth = model(
            "P1",
            &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
        );
        let mut rng = crate::random::Lcg(5);
        let y = truth
            .simulate(&input, &times)
            .unwrap()
            .into_iter()
            .map(|v| v + 0.02 * rng.symmetric())
            .collect();
        FitData { times, y, input }
    }

    fn fitted(data: &FitData, code: &str, params: &[(Param, f64)]) -> FitReport {
        let m = model(code, params);
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        fit(data, m.structure, m.values, &options, &mut ()).unwrap()
    }

    /// `r` with a drift term, refitted on `data` from its values and `drift` (one start).
    fn refitted_with_drift(data: &FitData, r: &FitReport, drift: f64) -> FitReport {
        let mut s = r.model.structure;
        s.drift = true;
        let mut v = r.model.values;
        v.set(Param::Drift, drift);
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        fit(data, s, v, &options, &mut ()).unwrap()
    }

    #[test]
    fn the_backward_look_takes_out_a_drift_that_no_longer_pays() {
        let data = p1_record();
        let current = fitted(
            &data,
            "P1",
            &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
        );
        let with_drift = refitted_with_drift(&data, &current, 1e-4);
        let (e, step) = backward_step(&data, &with_drift, Extension::Pole).expect("taken out");
        assert_eq!(e, Extension::Drift);
        assert!(step.removed && step.cause == Cause::Drift);
        assert!(!step.fit.model.structure.drift);
        let Evidence::NoLongerPays { param, .. } = step.evidence else {
            panic!("{:?}", step.evidence)
        };
        assert_eq!(param, Param::Drift);
        // The term just paid for is never taken out in the same step.
        assert!(backward_step(&data, &with_drift, Extension::Drift).is_none());
        // A P1 without the drift has nothing to take out.
        assert!(backward_step(&data, &current, Extension::Pole).is_none());
    }

    #[test]
    fn a_gain_measured_only_with_a_drift_is_said_and_a_settled_one_is_not() {
        let data = p1_record();
        let settled = fitted(
            &data,
            "P1",
            &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
        );
        assert!(!settled.kp_correlations.is_empty());
        assert_eq!(gain_trade(&settled), None, "{:?}", settled.kp_correlations);
        // The same record from 2 s before the step to 15 s after it (1.5 τ): nothing before
        // the step pins a drift, and the drift and the gain trade.
        let keep: Vec<bool> = data
            .times
            .iter()
            .map(|&t| (18.0..=35.0).contains(&t))
            .collect();
        let short = data.keeping(&keep);
        let with_drift = refitted_with_drift(&short, &settled, 0.0);
        let trade = gain_trade(&with_drift).expect("trades");
        assert!(matches!(trade.with, Param::Drift | Param::Tp1), "{trade:?}");
        assert!(trade.correlation.abs() >= TRADE_CORRELATION);
        // As correlated, but the gain pinned within 1 %: measured, nothing to say.
        let mut tight = with_drift.clone();
        let kp = tight.model.get(Param::Kp);
        for e in tight.params.iter_mut().filter(|e| e.param == Param::Kp) {
            e.ci95 = Some((0.99 * kp, 1.01 * kp));
        }
        assert_eq!(gain_trade(&tight), None);
    }

    #[test]
    fn a_dead_time_at_or_below_zero_is_no_dead_time() {
        let data = p1_record();
        let current = fitted(
            &data,
            "P1D",
            &[
                (Param::Kp, 2.0),
                (Param::Tp1, 10.0),
                (Param::Y0, 50.0),
                (Param::Td, 0.0),
            ],
        );
        let mut negative = current.clone();
        negative.model.values.set(Param::Td, -0.2);
        assert!(no_longer_pays(&negative, Param::Td, -50.0));
        let mut positive = current.clone();
        positive.model.values.set(Param::Td, 1.5);
        assert!(!no_longer_pays(&positive, Param::Td, -50.0));
        assert!(no_longer_pays(&positive, Param::Td, -5.0));
    }

    #[test]
    fn a_lag_slower_than_the_record_is_refused_and_a_ringing_is_not() {
        // 100 s after the step at 20 s.
        let times: Vec<f64> = (0..=120).map(f64::from).collect();
        let data = FitData {
            y: vec![0.0; times.len()],
            times,
            input: Excitation::step(20.0, 1.0),
        };
        let p1 = model("P1", &[(Param::Tp1, 10.0)]);
        let slow = model("P2", &[(Param::Tp1, 10.0), (Param::Tp2, 900.0)]);
        assert!(beyond_record(&data, &p1, &slow));
        // A slow zero as well: SBHS's P2Z with Tz = 758 s and a pole of 8,464 s.
        let zero = model("P1Z", &[(Param::Tp1, 10.0), (Param::Tz, -300.0)]);
        assert!(beyond_record(&data, &p1, &zero));
        let second = model("P2", &[(Param::Tp1, 10.0), (Param::Tp2, 40.0)]);
        assert!(!beyond_record(&data, &p1, &second));
        // A lightly damped pair: its envelope Tw/ζ = 200 s outlasts the record, but the
        // ringing shows its period; Tw = 10 s is what counts.
        let ringing = model("P2U", &[(Param::Tw, 10.0), (Param::Zeta, 0.05)]);
        assert!(!beyond_record(&data, &p1, &ringing));
        // A start already slower than the record is not refused its own lag.
        let long = model("P1", &[(Param::Tp1, 300.0)]);
        let longer = model("P2", &[(Param::Tp1, 300.0), (Param::Tp2, 20.0)]);
        assert!(!beyond_record(&data, &long, &longer));
    }
}
