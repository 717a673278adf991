//! `small_step`: the step's effect |Kp·Δu| against the noise's standard deviation σ, the
//! notes' amplitude rule ("a relação entre o nível do sinal aplicado e o ruído deve ser
//! maior que 6"). σ is read robustly from the fit's residuals (1.4826·MAD, so a few outliers
//! or a short misfit do not count); the effect is the largest change's. Named when the
//! ratio is under [`SMALL_STEP_RATIO`]. Cost: O(n).

use super::{FittedRecord, Handling, TestCause, TestCauseKind, TestEvidence};

/// The least ratio of the step's effect to the noise (the notes' rule).
pub const SMALL_STEP_RATIO: f64 = 6.0;

/// `small_step` on a fit: `None` when the effect is at least six times the noise.
pub fn small_step(record: &FittedRecord) -> Option<TestCause> {
    let effect = record.effect();
    let noise = record.noise();
    let ratio = effect / noise;
    // A noiseless record (σ = 0) has an infinite ratio: nothing to name.
    (ratio < SMALL_STEP_RATIO).then(|| TestCause {
        kind: TestCauseKind::SmallStep,
        evidence: TestEvidence::SmallStep {
            effect,
            noise,
            ratio,
        },
        interval: None,
        handling: Handling::Reported,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ident::test_causes::testing::{Messy, messy};

    #[test]
    fn a_step_under_six_noises_is_named_with_its_ratio() {
        // Noise 25 % of the effect: ratio ≈ 4.
        let m = messy(Messy {
            noise: 0.25,
            seed: 3,
            ..Messy::default()
        });
        let cause = small_step(&m.record()).expect("a small step is named");
        let TestEvidence::SmallStep { ratio, effect, .. } = cause.evidence else {
            panic!("{cause:?}")
        };
        assert!((3.0..5.5).contains(&ratio), "{ratio}");
        assert!((effect - 12.0).abs() < 2.0, "{effect}");
    }

    #[test]
    fn a_clear_step_is_quiet_even_with_two_percent_noise() {
        for noise in [0.002, 0.02] {
            let m = messy(Messy {
                noise,
                ..Messy::default()
            });
            assert_eq!(small_step(&m.record()), None, "noise {noise}");
        }
    }
}
