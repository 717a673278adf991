//! `sampling`: the sampling period h against the course notes' four rules, from a model's
//! time constants, dead time θ and 95 % settling time t_s (Tognetti, "Escolha do tempo de
//! amostragem"):
//! - h < 0.1·τmax (Kalman and Bertram);
//! - 0.2 < h/θ < 1 (FOPTD);
//! - 0.01 < h/τ < 0.05 (Åström and Wittenmark; τ the dominant, slowest, time constant);
//! - t_s/15 < h < t_s/6 (Isermann; t_s the 95 % settling time from `degrau_lti`).
//!
//! [`sampling_checks`] is the advisor (issue 14 reads it): each rule with the record's
//! ratio and its bounds. A pair's time constant is 1/ωn (Tw); an integrator has none.
//!
//! **The cause** is named only when the record is clearly off, since most lab records break
//! one rule or another harmlessly:
//! - *too slow* (alias risk, dead time lost): a rule's upper bound exceeded by more than a
//!   factor of [`CLEARLY`] (fewer than 5 samples per time constant, fewer than 3 while the
//!   response settles, or a dead time that matters, θ ≥ 0.1·τmax, shorter than half a
//!   sample);
//! - *too fast* (noise dominates): every rule with a lower bound broken, one of them by
//!   more than a factor of [`CLEARLY`], and the model's largest move between two samples
//!   smaller than the noise's standard deviation (the notes: a high sampling rate is not
//!   advised when the noise is strong; filter instead).

use serde::{Deserialize, Serialize};

use crate::model::{Model, Param};

use super::{
    FittedRecord, Handling, RuleCheck, SamplingRule, TestCause, TestCauseKind, TestEvidence,
};

/// How far beyond a rule's bound a record must be to be clearly off.
pub const CLEARLY: f64 = 2.0;

/// The time scales of a model the rules read (s).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TimeScales {
    /// Its time constants (Tp1…Tp3, or Tw for a pair and Tp3), slowest first.
    pub time_constants: Vec<f64>,
    /// Its dead time θ (0 without one).
    pub dead_time: f64,
    /// Its 95 % settling time after the step, dead time included; `None` when it does not
    /// settle (an integrator, an undamped pair).
    pub settling_time: Option<f64>,
}

impl TimeScales {
    /// The time scales of `model`'s G(s).
    pub fn of(model: &Model) -> Self {
        Self {
            time_constants: time_constants(model),
            dead_time: model.dead_time(),
            settling_time: model.settling_time(0.05),
        }
    }
}

/// The time constants of `model`'s poles (s): Tp1…Tp3, or Tw for a pair and Tp3; finite
/// and positive ones, slowest first. Cheap: no response is computed.
pub fn time_constants(model: &Model) -> Vec<f64> {
    let s = &model.structure;
    let mut taus: Vec<f64> = if s.underdamped {
        let mut t = vec![model.get(Param::Tw)];
        if s.poles == 3 {
            t.push(model.get(Param::Tp3));
        }
        t
    } else {
        [Param::Tp1, Param::Tp2, Param::Tp3]
            .into_iter()
            .take(s.poles as usize)
            .map(|p| model.get(p))
            .collect()
    };
    taus.retain(|t| t.is_finite() && *t > 0.0);
    taus.sort_by(|a, b| b.total_cmp(a));
    taus
}

/// Each of the notes' rules that applies to `scales`, with the ratio of sampling period
/// `h` (s) it bounds: h/τmax (Kalman and Bertram, and Åström and Wittenmark), h/θ (with a
/// dead time), h/t_s (with a settling time).
pub fn sampling_checks(h: f64, scales: &TimeScales) -> Vec<RuleCheck> {
    let check = |rule, value, low, high| RuleCheck {
        rule,
        value,
        low,
        high,
    };
    let mut checks = Vec::new();
    if let Some(&slowest) = scales.time_constants.first() {
        checks.push(check(
            SamplingRule::TenthOfSlowest,
            h / slowest,
            None,
            Some(0.1),
        ));
    }
    if scales.dead_time > 0.0 {
        let ratio = h / scales.dead_time;
        checks.push(check(
            SamplingRule::DeadTimeRatio,
            ratio,
            Some(0.2),
            Some(1.0),
        ));
    }
    if let Some(&slowest) = scales.time_constants.first() {
        let ratio = h / slowest;
        checks.push(check(
            SamplingRule::TimeConstantRatio,
            ratio,
            Some(0.01),
            Some(0.05),
        ));
    }
    if let Some(ts) = scales.settling_time.filter(|t| *t > 0.0) {
        let ratio = h / ts;
        checks.push(check(
            SamplingRule::SettlingRatio,
            ratio,
            Some(1.0 / 15.0),
            Some(1.0 / 6.0),
        ));
    }
    checks
}

/// Whether a record sampled as `checks` say is clearly too slow (see the module docs).
fn clearly_too_slow(checks: &[RuleCheck], scales: &TimeScales) -> bool {
    let slowest = scales.time_constants.first().copied().unwrap_or(0.0);
    checks.iter().any(|c| {
        let matters = c.rule != SamplingRule::DeadTimeRatio || scales.dead_time >= 0.1 * slowest;
        matters && c.high.is_some_and(|h| c.value > CLEARLY * h)
    })
}

/// Whether every rule with a lower bound is broken, one clearly.
fn clearly_too_fast(checks: &[RuleCheck]) -> bool {
    let bounded: Vec<&RuleCheck> = checks.iter().filter(|c| c.low.is_some()).collect();
    !bounded.is_empty()
        && bounded.iter().all(|c| c.too_fast())
        && bounded
            .iter()
            .any(|c| c.low.is_some_and(|l| c.value * CLEARLY < l))
}

/// `sampling` on a fit (see the module docs): `None` unless the record is clearly too slow
/// or clearly too fast with the noise dominating.
pub fn sampling(record: &FittedRecord) -> Option<TestCause> {
    let h = record.data.sampling_period();
    let scales = TimeScales::of(&record.fit.model);
    let checks = sampling_checks(h, &scales);
    let noise = record.noise();
    // The model's largest move between two samples: ŷ = y − r.
    let per_sample = record
        .data
        .y
        .iter()
        .zip(&record.residuals)
        .map(|(y, r)| y - r)
        .collect::<Vec<f64>>()
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(0.0, f64::max);
    let too_slow = clearly_too_slow(&checks, &scales);
    let too_fast = !too_slow && clearly_too_fast(&checks) && per_sample < noise;
    if !(too_slow || too_fast) {
        return None;
    }
    let ceiling = checks
        .iter()
        .filter_map(|c| {
            c.high
                .filter(|_| c.value > 0.0)
                .map(|high| h * high / c.value)
        })
        .reduce(f64::min);
    let broken = checks
        .into_iter()
        .filter(|c| if too_slow { c.too_slow() } else { c.too_fast() })
        .collect();
    Some(TestCause {
        kind: TestCauseKind::Sampling,
        evidence: TestEvidence::Sampling {
            ts: h,
            too_slow,
            broken,
            per_sample,
            noise,
            ceiling,
        },
        interval: None,
        handling: Handling::Reported,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::test_causes::testing::{Messy, messy};
    use crate::model::Structure;

    fn model(code: &str, values: &[(Param, f64)]) -> Model {
        let mut v = crate::model::Values::default();
        for &(p, x) in values {
            v.set(p, x);
        }
        Model::new(Structure::parse(code).unwrap(), v)
    }

    #[test]
    fn the_rules_read_the_notes_ratios() {
        // FOPTD τ = 20 s, θ = 4 s; t_s(95 %) = θ + τ·ln 20 = 63.91 s.
        let m = model(
            "P1D",
            &[(Param::Kp, 2.0), (Param::Tp1, 20.0), (Param::Td, 4.0)],
        );
        let scales = TimeScales::of(&m);
        let ts = scales.settling_time.unwrap();
        assert!((ts - (4.0 + 20.0 * 20f64.ln())).abs() < 1e-9, "{ts}");
        let checks = sampling_checks(1.0, &scales);
        let value = |r| checks.iter().find(|c| c.rule == r).unwrap().value;
        assert_eq!(value(SamplingRule::TenthOfSlowest), 0.05);
        assert_eq!(value(SamplingRule::DeadTimeRatio), 0.25);
        assert_eq!(value(SamplingRule::TimeConstantRatio), 0.05);
        assert!((value(SamplingRule::SettlingRatio) - 1.0 / ts).abs() < 1e-12);
        // h = 1 s: within the first three rules, too fast for Isermann's (t_s/15 = 4.3 s).
        assert!(checks.iter().filter(|c| c.too_fast()).count() == 1);
        // Two lags: the slowest one counts; an integrator settles never.
        let p2 = TimeScales::of(&model(
            "P2",
            &[(Param::Kp, 1.0), (Param::Tp1, 3.0), (Param::Tp2, 30.0)],
        ));
        assert_eq!(p2.time_constants, vec![30.0, 3.0]);
        let p1i = TimeScales::of(&model("P1I", &[(Param::Kp, 1.0), (Param::Tp1, 3.0)]));
        assert_eq!(p1i.settling_time, None);
        assert_eq!(sampling_checks(1.0, &p1i).len(), 2);
    }

    #[test]
    fn a_coarse_record_is_too_slow_and_a_good_one_is_quiet() {
        assert_eq!(sampling(&messy(Messy::default()).record()), None);
        // τ = 20 s sampled every 6 s: h/τ = 0.3, three times Kalman and Bertram's bound.
        let slow = messy(Messy {
            h: 6.0,
            n: 60,
            td: 0.0,
            ..Messy::default()
        });
        let cause = sampling(&slow.record()).expect("too slow named");
        let TestEvidence::Sampling {
            too_slow, broken, ..
        } = cause.evidence
        else {
            panic!("{cause:?}")
        };
        assert!(too_slow);
        assert!(
            broken
                .iter()
                .any(|c| c.rule == SamplingRule::TenthOfSlowest)
        );
    }

    #[test]
    fn a_fast_noisy_record_is_too_fast() {
        // τ = 20 s sampled every 0.05 s with 2 % noise: the model moves 0.03 per sample,
        // the noise is 0.24.
        let fast = messy(Messy {
            h: 0.05,
            n: 2400,
            noise: 0.02,
            steps: vec![(20.013, 10.0, 1.2)],
            ..Messy::default()
        });
        let cause = sampling(&fast.record()).expect("too fast named");
        let TestEvidence::Sampling {
            too_slow,
            per_sample,
            noise,
            ..
        } = cause.evidence
        else {
            panic!("{cause:?}")
        };
        assert!(!too_slow && per_sample < noise, "{per_sample} {noise}");
        // The same sampling with 0.1 % noise (0.012): the motion shows, nothing to name.
        let quiet = messy(Messy {
            noise: 0.001,
            h: 0.05,
            n: 2400,
            steps: vec![(20.013, 10.0, 1.2)],
            ..Messy::default()
        });
        assert_eq!(sampling(&quiet.record()), None);
    }
}
