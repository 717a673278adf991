//! What the *test* got wrong, kept apart from what the *model* lacks: the artefacts of a
//! real step test that the course notes list as its hazards ("a saída é geralmente
//! contaminada por ruído", "distúrbios podem ocorrer durante o teste", "o degrau não é
//! perfeito", non-linearities, the sampling-time and amplitude rules).
//!
//! Each cause has a stable identifier ([`TestCauseKind::id`]), typed evidence (a statistic
//! and, where there is one, the time interval it points at), and what Degrau does about it
//! ([`Handling`]); the words and the remedy for the student are the text layer's
//! (`crate::words`). The diagnosis ([`crate::diagnose`]) checks these before it names any
//! structural cause: an artefact that explains the residuals is named and handled first,
//! and no structural extension is kept to absorb it.
//!
//! This module owns the facts and their detection from the data and a fit's residuals; it
//! fits nothing itself.

pub mod closed_loop;
pub mod coloured_noise;
pub mod disturbance;
pub mod handling;
pub mod outliers;
pub mod saturation;

use serde::{Deserialize, Serialize};

use crate::diagnose::cause::Cause;
use crate::fit::rest::{Motion, Rest, rest_before};
pub use crate::fit::robust::Loss;
use crate::fit::{FitData, FitReport};
use crate::model::Param;

mod imperfect_step;
mod nonlinearity;
mod quantisation;
mod sampling;
mod small_step;
#[cfg(test)]
mod testing;

pub use imperfect_step::{imperfect_step, input_at};
pub use nonlinearity::{
    HELD_LAGS, change_held, fit_held, nonlinearity, own_fit_held, step_gains, steps_held,
};
pub use quantisation::{COARSE_SHARE, quantisation, read_within_quanta, resolution};
pub use sampling::{TimeScales, sampling, sampling_checks, time_constants};
pub use small_step::{SMALL_STEP_RATIO, small_step};

/// A cause of the test, with a stable identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TestCauseKind {
    /// The output moved before the first input change beyond what the noise allows.
    NotAtRest,
    /// The output changed where no input did (a step or a ramp in the residuals).
    Disturbance,
    /// The per-step fits differ beyond their intervals (up against down, small against
    /// large, one operating point against another).
    Nonlinearity,
    /// The output or the input held flat at a limit while the model keeps moving.
    Saturation,
    /// Isolated samples far from the model on a robust scale.
    Outliers,
    /// Residuals correlated while no structural extension pays.
    ColouredNoise,
    /// The output moves in steps coarse against the step's effect.
    Quantisation,
    /// The sampling period against the notes' rules.
    Sampling,
    /// The step's effect under six times the noise (the notes' amplitude rule).
    SmallStep,
    /// The input ramps, overshoots or wobbles instead of stepping.
    ImperfectStep,
    /// The test ran in closed loop: the input answers the output's earlier errors.
    ClosedLoop,
}

impl TestCauseKind {
    /// Every cause, in the order the diagnosis checks and lists them.
    pub const ALL: [TestCauseKind; 11] = [
        TestCauseKind::ClosedLoop,
        TestCauseKind::NotAtRest,
        TestCauseKind::Saturation,
        TestCauseKind::Outliers,
        TestCauseKind::Disturbance,
        TestCauseKind::ImperfectStep,
        TestCauseKind::Nonlinearity,
        TestCauseKind::Quantisation,
        TestCauseKind::SmallStep,
        TestCauseKind::Sampling,
        TestCauseKind::ColouredNoise,
    ];

    /// The stable identifier graders read (`not_at_rest`, `outliers`, …).
    pub fn id(self) -> &'static str {
        match self {
            TestCauseKind::NotAtRest => "not_at_rest",
            TestCauseKind::Disturbance => "disturbance",
            TestCauseKind::Nonlinearity => "nonlinearity",
            TestCauseKind::Saturation => "saturation",
            TestCauseKind::Outliers => "outliers",
            TestCauseKind::ColouredNoise => "coloured_noise",
            TestCauseKind::Quantisation => "quantisation",
            TestCauseKind::Sampling => "sampling",
            TestCauseKind::SmallStep => "small_step",
            TestCauseKind::ImperfectStep => "imperfect_step",
            TestCauseKind::ClosedLoop => "closed_loop",
        }
    }
}

/// Which signal a finding is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Signal {
    Output,
    Input,
}

/// The shape of a disturbance in the residuals.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DisturbanceShape {
    Step,
    Ramp,
}

/// How the input departed from an ideal step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "shape", rename_all = "snake_case")]
pub enum StepShape {
    /// It took `duration` seconds to go from the old level to the new one.
    Ramp { duration: f64 },
    /// It went past the new level by `fraction` of the change before settling.
    Overshoot { fraction: f64 },
    /// It kept moving about the new level by ± `amplitude` (input units).
    Wobble { amplitude: f64 },
}

/// One change's own gain, for the nonlinearity evidence.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepGain {
    /// The change's instant (s).
    pub t: f64,
    /// The input before it and its size (input units).
    pub u_before: f64,
    pub du: f64,
    /// Its own static gain and 95 % interval (output units per input unit).
    pub kp: f64,
    pub ci95: Option<(f64, f64)>,
}

/// A rule of the notes on the sampling period h, with the record's own value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SamplingRule {
    /// h < 0.1·τmax (Kalman and Bertram).
    TenthOfSlowest,
    /// 0.2 < h/θ < 1 (FOPTD).
    DeadTimeRatio,
    /// 0.01 < h/τ < 0.05 (Åström and Wittenmark).
    TimeConstantRatio,
    /// t_s/15 < h < t_s/6, t_s the 95 % settling time (Isermann).
    SettlingRatio,
}

/// A sampling rule checked on a record: the ratio it looks at and its bounds (`None`: no
/// bound on that side).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RuleCheck {
    pub rule: SamplingRule,
    /// The quantity the rule bounds (h/τ, h/θ, …; for [`SamplingRule::TenthOfSlowest`] h/τmax).
    pub value: f64,
    pub low: Option<f64>,
    pub high: Option<f64>,
}

impl RuleCheck {
    /// Below the rule's low bound: sampled too fast for it.
    pub fn too_fast(&self) -> bool {
        self.low.is_some_and(|l| self.value < l)
    }
    /// Above the rule's high bound: sampled too slowly for it.
    pub fn too_slow(&self) -> bool {
        self.high.is_some_and(|h| self.value > h)
    }
}

/// The evidence for a cause of the test, with its numbers; times in seconds, levels in the
/// signal's units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum TestEvidence {
    /// The line through the samples before the first change moved by more than the noise
    /// allows.
    NotAtRest { motion: Motion },
    /// The residuals step (or ramp) by `size` at `at`, where no input changed; `z` its
    /// significance against the residual noise.
    Disturbance {
        at: f64,
        size: f64,
        shape: DisturbanceShape,
        z: f64,
    },
    /// Each change's own gain; they differ beyond their intervals.
    Nonlinearity { steps: Vec<StepGain> },
    /// `signal` sits at `level` for `samples` samples in `spans` while the model moves.
    Saturation {
        signal: Signal,
        level: f64,
        samples: usize,
        spans: Vec<(f64, f64)>,
    },
    /// `count` samples lie beyond `threshold` (output units) from their neighbours' local
    /// trend, in the residuals and in the data, `threshold` being `sigmas` × the noise's
    /// robust scale `scale` (1.4826·MAD); `times` lists them, `worst` is the largest
    /// deviation.
    Outliers {
        count: usize,
        times: Vec<f64>,
        scale: f64,
        /// The multiple of `scale` the threshold is before the two quanta's floor.
        #[serde(default)]
        sigmas: f64,
        threshold: f64,
        worst: f64,
    },
    /// The residuals' lag-one autocorrelation `lag1` (an AR(1) coefficient), and the factor
    /// the parameters' intervals were widened by.
    ColouredNoise { lag1: f64, widening: f64 },
    /// The output moves in steps of `resolution`, `share` of the step's effect; `noise` is
    /// the residuals' robust standard deviation. `kp_floor`: when the noise is under half a
    /// step it does not dither the quantiser, and least squares' Kp is known no better than
    /// ± this (resolution/|Δu|), whatever its interval says. `within_quanta`: then, the Kp
    /// of the final structure refitted with each sample read as lying anywhere within its
    /// quantum ([`censored_fit`](crate::fit::censored::censored_fit)), when it could be.
    Quantisation {
        resolution: f64,
        share: f64,
        noise: f64,
        kp_floor: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        within_quanta: Option<f64>,
    },
    /// The sampling period `ts` against the notes' rules: clearly too slow, or (`too_slow`
    /// false) clearly too fast with the model's largest move between two samples
    /// (`per_sample`) under the noise's standard deviation (`noise`); the rules broken on
    /// that side are listed.
    Sampling {
        ts: f64,
        too_slow: bool,
        broken: Vec<RuleCheck>,
        per_sample: f64,
        noise: f64,
        /// The largest sampling period every rule with an upper bound allows (s), when one
        /// has: advice to sample more slowly goes no further.
        ceiling: Option<f64>,
    },
    /// The step's effect against the noise's standard deviation: `ratio` < 6.
    SmallStep { effect: f64, noise: f64, ratio: f64 },
    /// The input departed from an ideal step; an ideal-step model would have named
    /// `mistaken_for` instead.
    ImperfectStep {
        shape: StepShape,
        mistaken_for: Option<Cause>,
    },
    /// The input moves at `moves` of the samples, and the output's past changes predict
    /// those moves beyond the input's own past: F statistic `f` with `dof` degrees of
    /// freedom (p < 0.001), the output's past explaining `explained` of their variance.
    ClosedLoop {
        moves: f64,
        f: f64,
        dof: (usize, usize),
        explained: f64,
    },
}

/// What Degrau did about a cause.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Handling {
    /// An initial transient and Y0 estimated (the free response of G's poles).
    InitialTransient,
    /// A disturbance of the named shape modelled from `at` on.
    DisturbanceModelled { at: f64 },
    /// The samples in [start, end] left out of the fit.
    Excluded { start: f64, end: f64 },
    /// The fit uses a robust loss instead of least squares.
    RobustLoss { loss: Loss },
    /// The parameters' intervals widened by `factor` (the residuals' correlation).
    IntervalsWidened { factor: f64 },
    /// The per-step table shows each change's own fit.
    PerStepTable,
    /// The fit already uses the measured input.
    MeasuredInput,
    /// Reported only: nothing in the fit changes.
    Reported,
}

/// A cause of the test, found.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TestCause {
    pub kind: TestCauseKind,
    pub evidence: TestEvidence,
    /// The time interval the evidence points at (s), when there is one.
    pub interval: Option<(f64, f64)>,
    pub handling: Handling,
}

/// `not_at_rest`: the output moved before the first input change ([`rest_before`]).
pub fn not_at_rest(data: &FitData) -> Option<TestCause> {
    let Rest::NotAtRest(motion) = rest_before(data) else {
        return None;
    };
    Some(not_at_rest_with(motion))
}

/// `not_at_rest` with the motion it was found by.
pub fn not_at_rest_with(motion: Motion) -> TestCause {
    TestCause {
        kind: TestCauseKind::NotAtRest,
        interval: Some(motion.span),
        evidence: TestEvidence::NotAtRest { motion },
        handling: Handling::InitialTransient,
    }
}

/// A fit on its data, as the detectors that read a model read it: the residuals
/// y − ŷ computed once (output units).
#[derive(Debug, Clone)]
pub struct FittedRecord<'a> {
    pub data: &'a FitData,
    pub fit: &'a FitReport,
    pub residuals: Vec<f64>,
}

impl<'a> FittedRecord<'a> {
    /// `None` when the fitted model cannot be simulated on the data.
    pub fn new(data: &'a FitData, fit: &'a FitReport) -> Option<Self> {
        let residuals = fit.residuals(data).ok()?;
        Some(Self {
            data,
            fit,
            residuals,
        })
    }

    /// The effect of the input's largest change through the model, |Kp·Δu| (output units).
    pub fn effect(&self) -> f64 {
        let du = self.data.input.largest_change().map_or(0.0, |c| c.du);
        (self.fit.model.get(Param::Kp) * du).abs()
    }

    /// The noise's standard deviation read robustly from the residuals (1.4826·MAD), so that
    /// a few outliers do not count.
    pub fn noise(&self) -> f64 {
        crate::stats::robust_scale(&self.residuals)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identifiers_are_unique_and_listed_once() {
        let mut ids: Vec<&str> = TestCauseKind::ALL.iter().map(|k| k.id()).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), TestCauseKind::ALL.len());
    }

    #[test]
    fn a_rule_check_knows_its_side() {
        let c = RuleCheck {
            rule: SamplingRule::TimeConstantRatio,
            value: 0.2,
            low: Some(0.01),
            high: Some(0.05),
        };
        assert!(c.too_slow() && !c.too_fast());
    }
}
