//! The hidden truth of a challenge: which effect is hidden from the start model `P1` (a
//! dead time, one more pole, an oscillation, a zero, an inverse response, an integrator, a
//! drift, a dead time and a pole at once, or nothing structural but a flaw of the test),
//! with or without a flaw of the test beside it ([`Flaw::BESIDE`]: spikes, a coarse
//! converter), drawn at a level's size, and the process that carries it (Kp, time
//! constants, the operating point, the input's changes and the logger's flaws).

use serde::{Deserialize, Serialize};

use crate::diagnose::Cause;
use crate::model::excitation::InputStep;
use crate::model::{Model, Param, Structure, Values};
use crate::random::Lcg;

use super::Level;
use super::test_flaw::{self, Flaw, Setting};

/// The start model every challenge is meant to be fitted from (the CLI's default start).
pub const START: &str = "P1";

/// What is hidden from the start model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    DeadTime,
    ExtraPole,
    Oscillation,
    Zero,
    InverseResponse,
    Integrator,
    Drift,
    /// A dead time and one more pole at once (P2D): either is right named first.
    DeadTimeAndPole,
    /// Nothing structural: the start model is the truth, and the test has this flaw.
    TestOnly(Flaw),
}

impl Effect {
    /// Every effect, in the order the rates are reported: the structural ones, then each
    /// flaw of the test alone.
    pub const ALL: [Effect; 18] = [
        Effect::DeadTime,
        Effect::ExtraPole,
        Effect::Oscillation,
        Effect::Zero,
        Effect::InverseResponse,
        Effect::Integrator,
        Effect::Drift,
        Effect::DeadTimeAndPole,
        Effect::TestOnly(Flaw::Outliers),
        Effect::TestOnly(Flaw::Quantisation),
        Effect::TestOnly(Flaw::Disturbance),
        Effect::TestOnly(Flaw::Saturation),
        Effect::TestOnly(Flaw::NotAtRest),
        Effect::TestOnly(Flaw::ImperfectStep),
        Effect::TestOnly(Flaw::Nonlinearity),
        Effect::TestOnly(Flaw::Sampling),
        Effect::TestOnly(Flaw::SmallStep),
        Effect::TestOnly(Flaw::ColouredNoise),
    ];

    /// A short name for reports (the first cause's id, the pair's, or the flaw's with
    /// `_only`).
    pub fn id(self) -> String {
        match self {
            Effect::DeadTimeAndPole => "dead_time+extra_pole".to_string(),
            Effect::TestOnly(f) => format!("{}_only", f.kind().id()),
            e => e.causes()[0].id().to_string(),
        }
    }

    /// The structural causes hidden from `P1`, any of which is right named first (empty:
    /// none).
    pub fn causes(self) -> Vec<Cause> {
        match self {
            Effect::DeadTime => vec![Cause::DeadTime],
            Effect::ExtraPole => vec![Cause::ExtraPole],
            Effect::Oscillation => vec![Cause::Oscillation],
            Effect::Zero => vec![Cause::Zero, Cause::ExtraPole],
            Effect::InverseResponse => vec![Cause::InverseResponse, Cause::ExtraPole],
            Effect::Integrator => vec![Cause::Integrator],
            Effect::Drift => vec![Cause::Drift],
            Effect::DeadTimeAndPole => vec![Cause::DeadTime, Cause::ExtraPole],
            Effect::TestOnly(_) => Vec::new(),
        }
    }

    /// The true structure's procest code (the final structure the diagnosis should reach).
    pub fn code(self) -> &'static str {
        match self {
            Effect::DeadTime => "P1D",
            Effect::ExtraPole => "P2",
            Effect::Oscillation => "P2U",
            Effect::Zero | Effect::InverseResponse => "P2Z",
            Effect::Integrator => "P1I",
            Effect::Drift | Effect::TestOnly(_) => "P1",
            Effect::DeadTimeAndPole => "P2D",
        }
    }

    /// The flaw that is the whole challenge (none for a structural effect).
    pub fn flaw(self) -> Option<Flaw> {
        match self {
            Effect::TestOnly(f) => Some(f),
            _ => None,
        }
    }
}

/// The hidden process and test of one challenge.
#[derive(Debug, Clone, PartialEq)]
pub struct Truth {
    pub effect: Effect,
    /// The flaw of the test: the effect's own, or one beside a structural effect.
    pub flaw: Option<Flaw>,
    /// The process, its dead time counted from the true instants of the changes (its gain
    /// the first change's when a second one has its own).
    pub model: Model,
    /// The input before the first change.
    pub u0: f64,
    /// The input's changes at their true instants (between samples); an imperfect step's
    /// actuator motion as the fine staircase the plant answers.
    pub changes: Vec<InputStep>,
    /// The sampling period (s) and the record's length (s).
    pub ts: f64,
    pub length: f64,
    /// The noise's standard deviation (output units), its AR(1) coefficient, the
    /// converter's quantum (none: not quantised).
    pub noise_sd: f64,
    pub rho: f64,
    pub quantum: Option<f64>,
    /// The sizes of the flaw that the plan above does not hold.
    pub setting: Option<Setting>,
    /// The size the noise is scaled on: |Kp·Δu| (the ramp's rise for an integrator).
    pub effect_size: f64,
}

/// Per level (clear, moderate, subtle): the noise as a share of the effect.
const NOISE: [(f64, f64); 3] = [(0.002, 0.005), (0.005, 0.01), (0.01, 0.02)];
/// Td / Tp1.
const DEAD: [(f64, f64); 3] = [(0.5, 1.0), (0.25, 0.5), (0.12, 0.25)];
/// Tp2 / Tp1.
const POLE: [(f64, f64); 3] = [(0.6, 1.0), (0.35, 0.6), (0.2, 0.35)];
/// ζ of the oscillation.
const ZETA: [(f64, f64); 3] = [(0.1, 0.3), (0.3, 0.45), (0.45, 0.6)];
/// Tz / Tp1 of the lead zero (the overshoot grows with it).
const ZERO: [(f64, f64); 3] = [(2.3, 3.0), (1.9, 2.3), (1.5, 1.9)];
/// −Tz / Tp1 of the inverse response.
const INVERSE: [(f64, f64); 3] = [(0.85, 1.2), (0.6, 0.85), (0.45, 0.6)];
/// The integrator's ramp over the record, in multiples of |Δu|.
const RAMP: [(f64, f64); 3] = [(5.0, 10.0), (3.0, 5.0), (2.0, 3.0)];
/// The drift over the record as a share of the effect.
const DRIFT: [(f64, f64); 3] = [(0.12, 0.18), (0.1, 0.15), (0.08, 0.12)];

/// Tp2 / Tp1 beside a zero (lead and inverse).
const ZERO_POLE: (f64, f64) = (0.1, 0.3);
const INVERSE_POLE: (f64, f64) = (0.2, 0.5);
const KP: (f64, f64) = (0.5, 5.0);
const DU: (f64, f64) = (1.0, 10.0);
const U0: (f64, f64) = (10.0, 60.0);
const Y0: (f64, f64) = (-50.0, 100.0);
const TP1: (f64, f64) = (1.0, 20.0);
const TW: (f64, f64) = (1.0, 8.0);
/// The record after a change: this many slowest time constants (+ the dead time).
const SETTLING: (f64, f64) = (6.0, 10.0);
/// The same with a load disturbance, which comes this many after the change.
const LOADED_SETTLING: (f64, f64) = (11.0, 13.0);
const LOAD_AFTER: (f64, f64) = (7.0, 8.0);
/// The first change's place in the record (share of its length).
const T0_SHARE: (f64, f64) = (0.1, 0.25);
/// The samples planned per input change (the round period makes it a few more).
const SAMPLES: (f64, f64) = (200.0, 800.0);
/// The share of samples turned into spikes or dropouts.
const OUTLIER_SHARE: (f64, f64) = (0.02, 0.04);
/// Odds of a flaw ([`Flaw::BESIDE`], even odds) beside a structural effect, of a second
/// change, of coloured noise, of a quantised output.
const FLAW_ODDS: f64 = 0.2;
const SECOND_CHANGE_ODDS: f64 = 1.0 / 3.0;
const COLOURED_ODDS: f64 = 0.5;
const QUANTISED_ODDS: f64 = 1.0 / 3.0;

/// The slope (per input unit) of an integrator with lag `tp1` whose answer to a unit step
/// rises by `rise` over the `after` seconds that follow it: K·(t − Tp1·(1 − e^{−t/Tp1})) =
/// rise at t = after.
pub fn ramp_slope(rise: f64, after: f64, tp1: f64) -> f64 {
    rise / (after - tp1 * (1.0 - (-after / tp1).exp()))
}

/// Draws the truth of `effect` at `level`.
pub fn draw(rng: &mut Lcg, effect: Effect, level: Level) -> Truth {
    let l = level.index();
    let flaw = effect.flaw();
    let (s, mut v, slowest) = process(rng, effect, level);
    let kp = v.get(Param::Kp);
    let du = rng.signed(DU);
    let u0 = rng.range(U0);
    let tp1 = v.get(Param::Tp1);
    let td = if s.delay { v.get(Param::Td) } else { 0.0 };
    // A load is read once the response has settled: the record runs longer after it.
    let settling = if flaw == Some(Flaw::Disturbance) {
        LOADED_SETTLING
    } else {
        SETTLING
    };
    let after = rng.range(settling) * slowest + td;
    let share = rng.range(T0_SHARE);
    let first = after * share / (1.0 - share);
    let mut changes = vec![InputStep { t: first, du }];
    let mut length = first + after;
    let steady = !matches!(effect, Effect::Integrator | Effect::Drift);
    let single = flaw.is_some_and(Flaw::single_change);
    let nonlinear = flaw == Some(Flaw::Nonlinearity);
    if nonlinear || (steady && !single && rng.unit() < SECOND_CHANGE_ODDS) {
        // Back to where it was, or further the same way.
        let du2 = if rng.unit() < 0.5 {
            -du
        } else {
            du * rng.range((0.5, 1.0))
        };
        changes.push(InputStep { t: length, du: du2 });
        length += after;
    }
    let samples = if flaw == Some(Flaw::SmallStep) {
        test_flaw::SMALL_SAMPLES
    } else {
        SAMPLES
    };
    let ts = if flaw == Some(Flaw::Sampling) {
        // A round period, and the lag set to give it its share of a time constant (the
        // record keeps its plan in seconds, a few more lags long).
        let share = rng.range(test_flaw::SLOW_SAMPLING[l]);
        let ts = super::logger::round_period(share * tp1);
        v.set(Param::Tp1, ts / share);
        ts
    } else {
        super::logger::round_period(after / rng.range(samples))
    };
    let mut effect_size = (kp * du).abs();
    if effect == Effect::Integrator {
        // Kp is a slope per input unit: the ramp rises by RAMP × |Δu| over the record.
        let rise = rng.range(RAMP[l]);
        v.set(Param::Kp, kp.signum() * ramp_slope(rise, after, tp1));
        effect_size = rise * du.abs();
    }
    if s.drift {
        v.set(Param::Drift, rng.signed(DRIFT[l]) * effect_size / length);
    }
    let noise_sd = if flaw == Some(Flaw::SmallStep) {
        effect_size / rng.range(test_flaw::SMALL[l])
    } else {
        rng.range(NOISE[l]) * effect_size
    };
    let rho = if flaw == Some(Flaw::ColouredNoise) {
        rng.range(test_flaw::COLOURED[l])
    } else if rng.unit() < COLOURED_ODDS {
        rng.range((0.3, 0.7))
    } else {
        0.0
    };
    let fine = (rng.unit() < QUANTISED_ODDS).then_some(0.5 * noise_sd);
    let flaw = flaw.or_else(|| (rng.unit() < FLAW_ODDS).then(|| *rng.pick(&Flaw::BESIDE)));
    let quantum = if effect.flaw() == Some(Flaw::Quantisation) {
        Some(rng.range(test_flaw::COARSE[l]) * effect_size)
    } else if flaw == Some(Flaw::Quantisation) {
        Some(rng.range(test_flaw::COARSE_BESIDE) * effect_size)
    } else {
        fine
    };
    let setting = match flaw {
        Some(Flaw::Disturbance) => {
            let at = first + td + rng.range(LOAD_AFTER) * slowest;
            Some(test_flaw::load(rng, level, at, effect_size))
        }
        Some(Flaw::Saturation) => Some(test_flaw::clip(rng, level)),
        Some(Flaw::NotAtRest) => Some(test_flaw::earlier(rng, level, du, slowest)),
        Some(Flaw::Nonlinearity) => Some(test_flaw::second_gain(rng, level, kp)),
        _ => None,
    };
    if flaw == Some(Flaw::ImperfectStep) {
        changes = test_flaw::actuator(rng, level, slowest).changes(first, du);
    }
    Truth {
        effect,
        flaw,
        model: Model::new(s, v),
        u0,
        changes,
        ts,
        length,
        noise_sd,
        rho,
        quantum,
        setting,
        effect_size,
    }
}

/// The process of `effect` at `level`: its structure, its values (Kp, Y0 and the lags; the
/// integrator's slope and the drift set later, from the record's plan) and its slowest
/// time scale (s).
fn process(rng: &mut Lcg, effect: Effect, level: Level) -> (Structure, Values, f64) {
    let l = level.index();
    let mut s = Structure::parse(effect.code()).expect("the effects' codes are procest codes");
    s.drift = effect == Effect::Drift;
    let mut v = Values::default();
    for p in [Param::Td, Param::Tz, Param::Drift] {
        v.set(p, 0.0);
    }
    let tp1 = rng.range(TP1);
    v.set(Param::Kp, rng.signed(KP));
    v.set(Param::Y0, rng.range(Y0));
    v.set(Param::Tp1, tp1);
    let mut slowest = tp1;
    match effect {
        Effect::DeadTime => v.set(Param::Td, rng.range(DEAD[l]) * tp1),
        Effect::ExtraPole => v.set(Param::Tp2, rng.range(POLE[l]) * tp1),
        Effect::Oscillation => {
            let tw = rng.range(TW);
            let zeta = rng.range(ZETA[l]);
            v.set(Param::Tw, tw);
            v.set(Param::Zeta, zeta);
            slowest = tw / zeta;
        }
        Effect::Zero => {
            v.set(Param::Tp2, rng.range(ZERO_POLE) * tp1);
            v.set(Param::Tz, rng.range(ZERO[l]) * tp1);
        }
        Effect::InverseResponse => {
            v.set(Param::Tp2, rng.range(INVERSE_POLE) * tp1);
            v.set(Param::Tz, -rng.range(INVERSE[l]) * tp1);
        }
        Effect::DeadTimeAndPole => {
            v.set(Param::Tp2, rng.range(POLE[l]) * tp1);
            v.set(Param::Td, rng.range(DEAD[l]) * tp1);
        }
        Effect::Integrator | Effect::Drift | Effect::TestOnly(_) => {}
    }
    (s, v, slowest)
}

impl Truth {
    /// The causes as the key writes them: the structural ids (or `none`), then the flaw's.
    pub fn cause_ids(&self) -> Vec<String> {
        let mut ids: Vec<String> = self
            .effect
            .causes()
            .iter()
            .map(|c| c.id().to_string())
            .collect();
        if let Some(f) = self.flaw {
            ids.push(f.kind().id().to_string());
        }
        if ids.is_empty() {
            ids.push(Cause::None.id().to_string());
        }
        ids
    }

    /// The static gain the answer is graded on (a slope per input unit for an integrator).
    pub fn kp(&self) -> f64 {
        self.model.get(Param::Kp)
    }

    /// The outliers' share drawn from when there are spikes.
    pub(super) fn outlier_share() -> (f64, f64) {
        OUTLIER_SHARE
    }
}
