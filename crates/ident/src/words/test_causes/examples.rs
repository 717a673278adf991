//! An example of every test cause, for the test of every message.

use super::*;

/// An example of every cause, for the test of every message.
#[cfg(test)]
pub fn examples() -> Vec<TestCause> {
    let motion = Motion {
        change: 5.2,
        span: (0.0, 248.0),
        samples: 250,
        threshold: 0.6,
    };
    let gain = |t, u_before, du, kp| StepGain {
        t,
        u_before,
        du,
        kp,
        ci95: Some((kp - 0.02, kp + 0.02)),
    };
    let check = |rule, value, low, high| RuleCheck {
        rule,
        value,
        low,
        high,
    };
    let cause = |kind, evidence, handling| TestCause {
        kind,
        evidence,
        interval: Some((10.0, 20.0)),
        handling,
    };
    use TestCauseKind as K;
    vec![
        cause(
            K::NotAtRest,
            TestEvidence::NotAtRest { motion },
            Handling::InitialTransient,
        ),
        cause(
            K::Disturbance,
            TestEvidence::Disturbance {
                at: 300.0,
                size: 1.5,
                shape: DisturbanceShape::Step,
                z: 12.0,
            },
            Handling::DisturbanceModelled { at: 300.0 },
        ),
        cause(
            K::Disturbance,
            TestEvidence::Disturbance {
                at: 300.0,
                size: 1.5,
                shape: DisturbanceShape::Ramp,
                z: 9.0,
            },
            Handling::Excluded {
                start: 300.0,
                end: 400.0,
            },
        ),
        cause(
            K::Nonlinearity,
            TestEvidence::Nonlinearity {
                steps: vec![gain(30.0, 30.0, 10.0, 1.2), gain(150.0, 40.0, -10.0, 0.9)],
            },
            Handling::PerStepTable,
        ),
        cause(
            K::Saturation,
            TestEvidence::Saturation {
                signal: Signal::Output,
                level: 100.0,
                samples: 40,
                spans: vec![(60.0, 100.0)],
            },
            Handling::Excluded {
                start: 60.0,
                end: 100.0,
            },
        ),
        cause(
            K::Saturation,
            TestEvidence::Saturation {
                signal: Signal::Input,
                level: 0.0,
                samples: 12,
                spans: vec![(5.0, 17.0)],
            },
            Handling::Reported,
        ),
        cause(
            K::Outliers,
            TestEvidence::Outliers {
                count: 9,
                times: (0..9).map(|k| 30.0 + 80.0 * k as f64).collect(),
                scale: 0.1,
                sigmas: 5.0,
                threshold: 0.5,
                worst: 14.6,
            },
            Handling::RobustLoss { loss: Loss::Huber },
        ),
        cause(
            K::Outliers,
            TestEvidence::Outliers {
                count: 2,
                times: vec![30.0, 640.0],
                scale: 0.1,
                sigmas: 5.0,
                threshold: 0.5,
                worst: 14.6,
            },
            Handling::RobustLoss { loss: Loss::Cauchy },
        ),
        cause(
            K::ColouredNoise,
            TestEvidence::ColouredNoise {
                lag1: 0.8,
                widening: 3.0,
            },
            Handling::IntervalsWidened { factor: 3.0 },
        ),
        cause(
            K::Quantisation,
            TestEvidence::Quantisation {
                resolution: 0.322,
                share: 0.0094,
                noise: 0.08,
                kp_floor: Some(0.0064),
                within_quanta: Some(0.6994),
            },
            Handling::Reported,
        ),
        cause(
            K::Quantisation,
            TestEvidence::Quantisation {
                resolution: 1.0,
                share: 0.083,
                noise: 0.6,
                kp_floor: None,
                within_quanta: None,
            },
            Handling::Reported,
        ),
        cause(
            K::Sampling,
            TestEvidence::Sampling {
                ts: 6.0,
                too_slow: true,
                broken: vec![
                    check(SamplingRule::TenthOfSlowest, 0.3, None, Some(0.1)),
                    check(SamplingRule::DeadTimeRatio, 3.0, Some(0.2), Some(1.0)),
                    check(SamplingRule::TimeConstantRatio, 0.3, Some(0.01), Some(0.05)),
                    check(
                        SamplingRule::SettlingRatio,
                        0.5,
                        Some(1.0 / 15.0),
                        Some(1.0 / 6.0),
                    ),
                ],
                per_sample: 3.0,
                noise: 0.1,
                ceiling: None,
            },
            Handling::Reported,
        ),
        cause(
            K::Sampling,
            TestEvidence::Sampling {
                ts: 0.05,
                too_slow: false,
                broken: vec![check(
                    SamplingRule::TimeConstantRatio,
                    0.0025,
                    Some(0.01),
                    Some(0.05),
                )],
                per_sample: 0.03,
                noise: 0.24,
                ceiling: Some(1.0),
            },
            Handling::Reported,
        ),
        cause(
            K::SmallStep,
            TestEvidence::SmallStep {
                effect: 1.0,
                noise: 0.25,
                ratio: 4.0,
            },
            Handling::Reported,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Ramp { duration: 3.0 },
                mistaken_for: Some(Cause::DeadTime),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Ramp { duration: 12.0 },
                mistaken_for: Some(Cause::ExtraPole),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Overshoot { fraction: 0.35 },
                mistaken_for: Some(Cause::Zero),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Wobble { amplitude: 2.0 },
                mistaken_for: Some(Cause::Oscillation),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Wobble { amplitude: 2.0 },
                mistaken_for: None,
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ClosedLoop,
            TestEvidence::ClosedLoop {
                moves: 0.98,
                f: 85.3,
                dof: (4, 1991),
                explained: 0.146,
            },
            Handling::Reported,
        ),
    ]
}

/// Every phrase, cause name, evidence, handling and remedy, in both languages.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = TestCausePhrase::messages();
    all.extend(
        TestCauseKind::ALL
            .iter()
            .map(|k| Message::of(format!("test_causes::TestCauseKind::{}", k.id()), k)),
    );
    for (i, c) in examples().iter().enumerate() {
        let id = |what: &str| format!("test_causes::{what}::{}#{i}", c.kind.id());
        all.push(Message::of(id("TestEvidence"), &c.evidence));
        all.push(Message::of(id("Handling"), &c.handling));
        all.push(Message {
            id: id("Remedy"),
            en: remedy(c, Lang::En),
            pt: remedy(c, Lang::Pt),
        });
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sampled too fast for Isermann's rule (h ≥ t_s/15) on a model whose slowest lag asks
    /// for h ≤ τ/10: the rules disagree, and no period is advised that breaks the other
    /// (issue 23, item 13: "every 23.71 s or more" for an 11.4 s time constant).
    #[test]
    fn no_period_is_advised_beyond_another_rules_bound() {
        let settling = RuleCheck {
            rule: SamplingRule::SettlingRatio,
            value: 0.5 / 355.0,
            low: Some(1.0 / 15.0),
            high: Some(1.0 / 6.0),
        };
        let evidence = |ceiling| TestEvidence::Sampling {
            ts: 0.5,
            too_slow: false,
            broken: vec![settling],
            per_sample: 0.01,
            noise: 0.1,
            ceiling,
        };
        let cause = |ceiling| TestCause {
            kind: TestCauseKind::Sampling,
            evidence: evidence(ceiling),
            interval: None,
            handling: Handling::Reported,
        };
        let conflicting = remedy(&cause(Some(1.14)), Lang::En);
        assert!(!conflicting.contains("or more"), "{conflicting}");
        assert!(conflicting.starts_with("Sample more slowly, or low-pass filter"));
        let agreeing = remedy(&cause(Some(60.0)), Lang::En);
        assert!(agreeing.contains("(every 23.67 s or more)"), "{agreeing}");
    }

    #[test]
    fn every_kind_and_handling_has_an_example() {
        let all = examples();
        for k in TestCauseKind::ALL {
            assert!(all.iter().any(|c| c.kind == k), "{k:?} has no example");
        }
        let handlings = [
            "initial_transient",
            "disturbance_modelled",
            "excluded",
            "robust_loss",
            "intervals_widened",
            "per_step_table",
            "measured_input",
            "reported",
        ];
        for h in handlings {
            assert!(
                all.iter()
                    .any(|c| serde_json::to_value(c.handling).unwrap()["kind"] == h),
                "{h} has no example"
            );
        }
    }

    #[test]
    fn one_outlier_on_a_quantised_record_is_said_without_an_infinite_ratio() {
        // A quantised record's MAD is 0: the threshold is two quanta, not k × 0.
        let e = TestEvidence::Outliers {
            count: 1,
            times: vec![93.82],
            scale: 0.0,
            sigmas: 5.0,
            threshold: 0.64,
            worst: -15.68,
        };
        let en = e.text(Lang::En);
        assert!(en.starts_with("1 sample lies more than 0.64"), "{en}");
        assert!(en.contains("two output quanta"), "{en}");
        assert!(!en.contains("inf"), "{en}");
        let pt = e.text(Lang::Pt);
        assert!(pt.starts_with("1 amostra está a mais de 0,64"), "{pt}");
        let many = TestEvidence::Outliers {
            count: 3,
            times: vec![1.0, 2.0, 3.0],
            scale: 0.1,
            sigmas: 5.0,
            threshold: 0.5,
            worst: 2.0,
        };
        let en = many.text(Lang::En);
        assert!(en.starts_with("3 samples lie more than 0.5"), "{en}");
        assert!(en.contains("5 × the noise's robust scale 0.1"), "{en}");
    }

    #[test]
    fn the_words_carry_the_numbers() {
        let all = examples();
        let q = all
            .iter()
            .find(|c| c.kind == TestCauseKind::Quantisation)
            .unwrap();
        let en = q.evidence.text(Lang::En);
        assert!(en.contains("steps of 0.322, 0.94 %"), "{en}");
        assert!(en.contains("± 0.0064"), "{en}");
        let pt = q.evidence.text(Lang::Pt);
        assert!(pt.contains("degraus de 0,322, 0,94 %"), "{pt}");
        let slow = all
            .iter()
            .find(|c| c.kind == TestCauseKind::Sampling)
            .unwrap();
        // h = 6 s with h/τmax = 0.3 against 0.1: τmax = 20 s, so every 2 s or less (the
        // strictest of the four rules: Åström and Wittenmark's 0.05 → 1 s).
        assert_eq!(remedy(slow, Lang::En), "Sample faster: every 1 s or less.");
        let rest = &all[0];
        let [name, evidence, done, remedy] = cause_lines(rest, Naming::Id, Lang::En);
        assert!(name.starts_with("not_at_rest: Not at rest"), "{name}");
        assert!(evidence.contains("moved by 5.2") && evidence.ends_with("[t = 10 … 20 s]"));
        assert!(done.contains("initial transient") && remedy.contains("steady state"));
    }

    #[test]
    fn closed_loop_says_its_statistic_why_and_what_to_do() {
        let all = examples();
        let c = all
            .iter()
            .find(|c| c.kind == TestCauseKind::ClosedLoop)
            .unwrap();
        let [name, evidence, _, remedy] = cause_lines(c, Naming::Id, Lang::En);
        assert!(name.starts_with("closed_loop: Closed loop"), "{name}");
        assert!(evidence.contains("98 % of the samples"), "{evidence}");
        assert!(evidence.contains("F = 85.3 with 4 and 1991"), "{evidence}");
        assert!(
            evidence.contains("−1/(the controller's gain)"),
            "{evidence}"
        );
        assert!(remedy.contains("Open the loop") && remedy.contains("dither"));
        let [name, evidence, _, remedy] = cause_lines(c, Naming::Id, Lang::Pt);
        assert!(name.starts_with("closed_loop: Malha fechada"), "{name}");
        assert!(evidence.contains("F = 85,3 com 4 e 1991"), "{evidence}");
        assert!(evidence.contains("viesado"), "{evidence}");
        assert!(remedy.contains("Abra a malha"), "{remedy}");
    }
}
