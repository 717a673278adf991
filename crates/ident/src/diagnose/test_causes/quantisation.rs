//! `quantisation`: the output moves in steps of a sensor's or converter's resolution q (the
//! TCLab's 0.32 °C, a DHT11's 1 °C, SBHS's 0.1 °C), read off the data as the common step of
//! its sample-to-sample increments.
//!
//! **The rule.** The resolution is named when it is coarse against the step's effect
//! (q ≥ [`COARSE_SHARE`] = 0.5 % of |Kp·Δu|: each sample's level is then uncertain by
//! ± 0.25 % of the effect, a twentieth of the 5 % the per-step table resolves; a TCLab's
//! 0.32 °C on its 34 °C rise is 0.94 %, a DHT11's 1 °C on 12 °C is 8 %, a 10-bit converter
//! over a full-scale step 0.1 %), or coarse against the noise (the residuals' robust
//! standard deviation σ below q/2: the record is a staircase).
//!
//! **The intervals.** With σ ≥ q/2 the noise dithers the quantiser: rounding acts as added
//! white noise of variance q²/12, already inside the residuals the intervals are computed
//! from, so they hold. Below that the rounding error follows the signal instead of averaging
//! out: a level held for a long time is read with a bias of up to q/2, so Δy is known no
//! better than ± q and Kp no better than ± q/|Δu| (`kp_floor`), whatever its interval says.
//!
//! Cost: O(n) (one pass for the smallest increment, and per divisor of it tried, two to
//! refine it and one to check it).

use super::{FittedRecord, Handling, TestCause, TestCauseKind, TestEvidence};
use crate::fit::censored::censored_fit;
use crate::model::Param;

/// A resolution at or above this share of the step's effect is coarse (see the module docs).
pub const COARSE_SHARE: f64 = 0.005;

/// Share of the nonzero increments that must sit on a multiple of q (within ± [`ON_GRID`]·q).
const GRID_SHARE: f64 = 0.9;
const ON_GRID: f64 = 0.1;
/// The fewest nonzero increments a resolution is read from.
const MIN_INCREMENTS: usize = 10;

/// The resolution of `y`: the step all its sample-to-sample increments are multiples of,
/// or `None` when they are not (a continuous signal, or too few moves to tell).
pub fn resolution(y: &[f64]) -> Option<f64> {
    /// Multiples of the smallest increment used to refine q (printing rounds each level, so
    /// the smallest increment alone may be off by a printed digit: 0.32 for 0.322).
    const REFINE_UP_TO: f64 = 20.0;
    /// The most steps the smallest move is taken to span.
    const MAX_DIVISOR: usize = 8;
    let scale = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    // Below this an increment is floating-point dust, not a move.
    let dust = 1e-9 * scale.max(f64::MIN_POSITIVE);
    let moves = || {
        y.windows(2)
            .map(|w| (w[1] - w[0]).abs())
            .filter(move |d| *d > dust && d.is_finite())
    };
    let count = moves().count();
    if count < MIN_INCREMENTS {
        return None;
    }
    // The smallest move may be several steps (a converter that never moves by one count):
    // its divisors are tried in turn.
    let smallest = moves().fold(f64::INFINITY, f64::min);
    (1..=MAX_DIVISOR).find_map(|m| {
        let mut q = smallest / m as f64;
        for _ in 0..2 {
            // Least squares over the small multiples already on the grid.
            let (num, den) = moves()
                .map(|d| (d, (d / q).round()))
                .filter(|&(d, m)| m <= REFINE_UP_TO && (d - m * q).abs() <= ON_GRID * q)
                .fold((0.0, 0.0), |(n, s), (d, m)| (n + d * m, s + m * m));
            if den > 0.0 {
                q = num / den;
            }
        }
        let on_grid = moves()
            .filter(|d| {
                let m = (d / q).round().max(1.0);
                (d - m * q).abs() <= ON_GRID * q
            })
            .count();
        (q > 0.0 && on_grid as f64 >= GRID_SHARE * count as f64).then_some(q)
    })
}

/// `quantisation` on a fit (see the module docs): `None` when the output has no resolution
/// or it is fine against both the step's effect and the noise.
pub fn quantisation(record: &FittedRecord) -> Option<TestCause> {
    let q = resolution(&record.data.y)?;
    let effect = record.effect();
    let noise = record.noise();
    let share = q / effect;
    let dithered = noise >= 0.5 * q;
    if share < COARSE_SHARE && dithered {
        return None;
    }
    let du = record
        .data
        .input
        .largest_change()
        .map_or(0.0, |c| c.du.abs());
    Some(TestCause {
        kind: TestCauseKind::Quantisation,
        evidence: TestEvidence::Quantisation {
            resolution: q,
            share,
            noise,
            kp_floor: (!dithered && du > 0.0).then(|| q / du),
            within_quanta: None,
        },
        interval: None,
        handling: Handling::Reported,
    })
}

/// `cause` with the gain read within the quanta when it bounds least squares' gain (a
/// staircase): the final structure of `record`, Y0 free, refitted by the censored
/// likelihood (a few weighted fits, once per diagnosis).
pub fn read_within_quanta(mut cause: TestCause, record: &FittedRecord) -> TestCause {
    if let TestEvidence::Quantisation {
        resolution,
        kp_floor: Some(_),
        within_quanta,
        ..
    } = &mut cause.evidence
    {
        let mut structure = record.fit.model.structure;
        structure.free_offset = true;
        let fit = censored_fit(record.data, *resolution, structure, record.fit.model.values);
        *within_quanta = fit
            .map(|f| f.model.get(Param::Kp))
            .filter(|kp| kp.is_finite());
    }
    cause
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::test_causes::testing::{Messy, messy};

    fn round_to(x: f64, base: f64, q: f64) -> f64 {
        base + q * ((x - base) / q).round()
    }

    #[test]
    fn the_resolution_is_read_from_printed_levels() {
        // TCLab: multiples of 0.322 °C printed with two decimals (0.32, 0.33, 0.64, 0.65 …).
        let y: Vec<f64> = (0..400)
            .map(|k| {
                let t = k as f64;
                let v = round_to(20.911 + 34.0 * (1.0 - (-t / 140.0).exp()), 20.9, 0.322);
                (v * 100.0).round() / 100.0
            })
            .collect();
        let q = resolution(&y).unwrap();
        assert!((q - 0.322).abs() < 0.002, "{q}");
        // Integer counts of a converter that moves by 4 and 7 counts, never by one.
        let counts: Vec<f64> = (0..200).map(|k| ((k * 37) % 11) as f64 + 1241.0).collect();
        assert!((resolution(&counts).unwrap() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_continuous_signal_has_no_resolution() {
        let m = messy(Messy::default());
        assert_eq!(resolution(&m.data.y), None);
    }

    #[test]
    fn coarse_steps_are_named_and_fine_ones_are_not() {
        // Effect 12 (Kp 1.2 × Δu 10): a DHT11-like 1 °C (8 %) against 0.5 % noise.
        let coarse = messy(Messy {
            quantum: Some(1.0),
            ..Messy::default()
        });
        let record = coarse.record();
        let Some(TestCause {
            evidence:
                TestEvidence::Quantisation {
                    resolution, share, ..
                },
            ..
        }) = quantisation(&record)
        else {
            panic!("1 °C steps on a 12 °C effect not named")
        };
        assert!((resolution - 1.0).abs() < 1e-9 && (share - 1.0 / 12.0).abs() < 0.01);
        // 0.001 on 12 (0.008 %) under 0.5 % noise: dithered and fine.
        let fine = messy(Messy {
            quantum: Some(0.001),
            ..Messy::default()
        });
        assert_eq!(quantisation(&fine.record()), None);
        assert_eq!(quantisation(&messy(Messy::default()).record()), None);
    }

    #[test]
    fn a_staircase_without_dither_bounds_the_gain() {
        // 0.02 on 12 (0.17 %) with noise 0.002: not dithered; Kp known to ± 0.02/10.
        let m = messy(Messy {
            quantum: Some(0.02),
            noise: 0.002 / 12.0,
            ..Messy::default()
        });
        let cause = quantisation(&m.record()).expect("a staircase is named");
        let TestEvidence::Quantisation { kp_floor, .. } = cause.evidence else {
            panic!("{cause:?}")
        };
        assert!((kp_floor.unwrap() - 0.002).abs() < 1e-6, "{kp_floor:?}");
    }
}
