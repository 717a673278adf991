//! What a diagnosis says and keeps: its options, each step of the chain (the cause, the fit,
//! the gain and the evidence), how the chain ended, the verdict on the last model and the
//! test's artefacts, and the gain traded for a drift when the two cannot be told apart.

use super::cause::Cause;
use crate::diagnose::test_causes::{TestCause, TestCauseKind};
use crate::fit::{FitOptions, FitReport};
use crate::model::{Param, Structure};
use serde::{Deserialize, Serialize};

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
    /// [`BIC_THRESHOLD`](super::judge::BIC_THRESHOLD)), or the term ended where it means nothing (a dead time ≤ 0).
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
    /// The residuals look like noise and no extension lowers BIC by [`BIC_THRESHOLD`](super::judge::BIC_THRESHOLD).
    Adequate,
    /// No extension lowers BIC by [`BIC_THRESHOLD`](super::judge::BIC_THRESHOLD), although the residuals are not white.
    NotWhite,
    /// On a staircase (a resolution coarse against the noise), no extension gains more
    /// than rounding gives a model that lacks nothing ([`Staircase`](crate::diagnose::staircase::Staircase)).
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

    pub(super) fn from_kinds(kinds: impl Iterator<Item = TestCauseKind>) -> Self {
        Artefacts(kinds.fold(0, |bits, k| bits | 1 << Self::bit(k)))
    }

    pub(super) fn bit(k: TestCauseKind) -> usize {
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
    /// True for a term taken out again by the backward look ([`backward_step`](super::step::backward_step)): `cause`
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
pub(super) fn gain_trade(r: &FitReport) -> Option<GainTrade> {
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
