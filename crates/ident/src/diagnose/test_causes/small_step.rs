//! `small_step`: the step's effect |Kp·Δu| against the noise's standard deviation σ, the
//! notes' amplitude rule ("a relação entre o nível do sinal aplicado e o ruído deve ser
//! maior que 6"). σ is read robustly from the fit's residuals (1.4826·MAD, so a few outliers
//! or a short misfit do not count); the effect is the largest change's. On an integrating
//! process Kp·Δu is a rate (output units a second), not a level: its effect is the rise it
//! makes from that change to the record's end. Named when the ratio is under
//! [`SMALL_STEP_RATIO`]. Cost: O(n).

use super::{FittedRecord, Handling, TestCause, TestCauseKind, TestEvidence};

/// The least ratio of the step's effect to the noise (the notes' rule).
pub const SMALL_STEP_RATIO: f64 = 6.0;

/// `small_step` on a fit: `None` when the effect is at least six times the noise.
pub fn small_step(record: &FittedRecord) -> Option<TestCause> {
    let effect = effect(record);
    let noise = record.noise();
    let ratio = effect / noise;
    // A noiseless record (σ = 0) has an infinite ratio: nothing to name.
    (ratio < SMALL_STEP_RATIO).then_some(TestCause {
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

/// The largest change's effect through the model: |Kp·Δu|, or on an integrating process
/// the rise |Kp·Δu|·(t_end − t) from the change's instant t to the record's end.
fn effect(record: &FittedRecord) -> f64 {
    let level = record.effect();
    if !record.fit.model.structure.integrator {
        return level;
    }
    let t_end = record.data.times.last().copied();
    let since = record
        .data
        .input
        .largest_change()
        .zip(t_end)
        .map_or(0.0, |(c, end)| (end - c.t).max(0.0));
    level * since
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::test_causes::testing::{Messy, messy};

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

    /// An integrator's Kp·Δu is a rate: 0.05 a second against noise 0.1 is a rise of 10 over
    /// the 200 s after the step, a hundred noises, not half of one.
    #[test]
    fn an_integrators_effect_is_its_rise_over_the_record() {
        let m = messy(Messy::default());
        let mut fit = m.fit.clone();
        let mut s = fit.model.structure;
        s.integrator = true;
        fit.model.structure = s;
        let record = crate::diagnose::test_causes::FittedRecord::new(&m.data, &fit);
        let record = record.expect("the model simulates");
        let rate = record.effect();
        let rise = effect(&record);
        let since = m.data.times.last().unwrap() - m.data.input.largest_change().unwrap().t;
        assert!(
            (rise - rate * since).abs() <= 1e-9 * rise.abs(),
            "{rise} {rate}"
        );
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
