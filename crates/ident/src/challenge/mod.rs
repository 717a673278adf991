//! Hidden-effect challenges: step-test records drawn from a process with an effect hidden
//! from the start model `P1` (a dead time, one more pole, an oscillation, a zero, an
//! inverse response, an integrator, a drift, two at once, or nothing structural but a flaw
//! of the test: spikes, a coarse converter, a load disturbance, a clipped output, a process
//! not at rest, an actuator that ramps or overshoots, a gain that differs step to step, a
//! period too slow, a step too small, strongly coloured noise ([`test_flaw`])), at three
//! levels, with the answer key a teacher grades against. This module owns the
//! drawing and the key's facts; writing files and grading a class are the CLI's.
//!
//! A record is as messy as a real one: the input changes between two samples (the logger
//! shows it at the next one), the operating point is far from zero (u0 ∈ [10, 60], y0 ∈
//! [−50, 100]), the noise is 0.2–2 % of the step's effect, Gaussian or uniform, white or
//! AR(1)-coloured, a third of the records are quantised, a third of the steady ones have a
//! second change (back, or further the same way), and a fifth of the structural ones carry
//! a flaw of the test beside the hidden effect: spikes, or a coarse converter. Levels:
//! *clear* (the effect or flaw large, the noise 0.2–0.5 %), *moderate* (0.5–1 %), *subtle*
//! (the effect or flaw small, the noise 1–2 %).
//!
//! **A challenge Degrau cannot solve is not handed out.** Each draw is checked by running
//! the diagnosis on the record exactly as `degrau diagnose record.csv` would
//! ([`solve::solve`]); when its first structural cause is not one of the key's, its final
//! structure is not the key's, the key's flaw is not named, or its gain misses the key's
//! tolerance, the challenge is drawn again from the next sub-seed ([`seed::stream`]:
//! seed, index, attempt), deterministically. The rates the issue asks for are therefore
//! met by construction on what is handed out; the raw rates (first draws) are measured by
//! the test `challenge_rates`.
//!
//! Reproducible: the same seed, index and level give the same record on any machine. The
//! generator is the workspace's own LCG seeded through SplitMix64 (no crate's stream), the
//! physics uses only + − × ÷, `exp`, `ln`, `sqrt`, `sin`/`cos`, and the CSV keeps
//! [`logger::DIGITS`] significant digits so that the last bits of a platform's maths
//! library do not reach the file. A change to any of this bumps [`GENERATOR_VERSION`], and
//! so does a change to the diagnosis that changes which draws are handed out (version 3:
//! version 2's draws, of which the diagnosis now solves more at the first draw).
//! One limit: which draw is handed out depends on the diagnosis's verdict on the earlier
//! ones, an iterative fit; a record at the edge of a decision could in principle be judged
//! differently by another platform's maths library, and another draw be handed out. The
//! same Degrau build gives the same files.

pub mod flaws;
pub mod logger;
pub mod seed;
pub mod solve;
pub mod test_flaw;
pub mod truth;

use serde::{Deserialize, Serialize};

use crate::diagnose::Cause;
use crate::model::excitation::{Excitation, InputStep};
use crate::model::{Model, Param};
use crate::random::Lcg;

pub use logger::Record;
pub use solve::{Grade, Solution, diagnosis, kp_within, solve};
pub use test_flaw::{Flaw, Setting};
pub use truth::{Effect, START, Truth};

/// The generator's version, written in the key: the same seed gives the same files in
/// every Degrau that keeps it.
pub const GENERATOR_VERSION: u32 = 3;

/// Draws of one challenge before giving up on its effect (never reached in the measured
/// runs; then any effect is drawn).
pub const MAX_ATTEMPTS: usize = 100;

/// How plain the hidden effect is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    Clear,
    Moderate,
    Subtle,
}

impl Level {
    pub const ALL: [Level; 3] = [Level::Clear, Level::Moderate, Level::Subtle];

    /// The level's word in the key and on the command line.
    pub fn id(self) -> &'static str {
        match self {
            Level::Clear => "clear",
            Level::Moderate => "moderate",
            Level::Subtle => "subtle",
        }
    }

    /// The level of its id.
    pub fn parse(text: &str) -> Option<Level> {
        Level::ALL.into_iter().find(|l| l.id() == text.trim())
    }

    /// 0, 1, 2 for clear, moderate, subtle.
    pub fn index(self) -> usize {
        self as usize
    }

    /// The gain's tolerance (relative) the key states.
    pub fn kp_tolerance(self) -> f64 {
        [0.05, 0.10, 0.15][self.index()]
    }
}

/// One challenge: the record and its key.
#[derive(Debug, Clone, PartialEq)]
pub struct Challenge {
    pub truth: Truth,
    /// The causes as `degrau diagnose` writes their ids (any is right named first), or
    /// `["none"]`.
    pub causes: Vec<String>,
    /// The final structure the diagnosis should end on (procest code).
    pub structure: String,
    pub kp: f64,
    /// Relative.
    pub kp_tolerance: f64,
    /// The samples as the CSV writes them.
    pub record: Record,
    /// The draw handed out (0: the first).
    pub attempt: usize,
}

impl Challenge {
    /// The record's CSV text.
    pub fn csv(&self) -> String {
        self.record.csv()
    }

    /// Whether `solution` names this challenge's cause right first: its first structural
    /// cause among the key's, or, when the key has none, no structural cause and the test's
    /// flaw among the test's causes named.
    pub fn names_cause(&self, solution: &Solution) -> bool {
        let causes = self.truth.effect.causes();
        if causes.is_empty() {
            solution.first_cause == Cause::None && self.flaw_named(solution)
        } else {
            causes.contains(&solution.first_cause)
        }
    }

    /// Whether the key's flaw of the test (if any) is among the test's causes `solution`
    /// names.
    pub fn flaw_named(&self, solution: &Solution) -> bool {
        self.truth
            .flaw
            .is_none_or(|f| solution.test_causes.contains(&f.kind()))
    }

    /// Whether `solution` gets every part of this challenge right (the check before it is
    /// handed out): the cause ([`Self::names_cause`]), the key's flaw named, the final
    /// structure, the gain within tolerance.
    pub fn solved_by(&self, solution: &Solution) -> bool {
        self.names_cause(solution)
            && self.flaw_named(solution)
            && solution.structure == self.structure
            && kp_within(solution.kp, self.kp, self.kp_tolerance)
    }
}

/// One draw (`attempt`) of challenge `index` of `seed`, unchecked; the effect drawn too
/// unless given.
pub fn draw(
    seed: u64,
    index: usize,
    attempt: usize,
    level: Level,
    effect: Option<Effect>,
) -> Challenge {
    let mut rng = seed::stream(seed::splitmix64(seed) ^ level as u64, index, attempt);
    let effect = effect.unwrap_or_else(|| *rng.pick(&Effect::ALL));
    let truth = truth::draw(&mut rng, effect, level);
    let record = sample(&mut rng, &truth).as_written();
    Challenge {
        causes: truth.cause_ids(),
        structure: truth.model.structure.code(),
        kp: truth.kp(),
        kp_tolerance: level.kp_tolerance(),
        truth,
        record,
        attempt,
    }
}

/// The challenge `index` of `seed` handed out: the first draw Degrau solves.
pub fn challenge(seed: u64, index: usize, level: Level) -> Challenge {
    checked(seed, index, level, None, &|| false).expect("a draw never stopped")
}

/// [`challenge`], given up (`None`) at the next draw once `stop` says so: a student's
/// Cancel ends the work within one diagnosis.
pub fn challenge_until(
    seed: u64,
    index: usize,
    level: Level,
    stop: &dyn Fn() -> bool,
) -> Option<Challenge> {
    checked(seed, index, level, None, stop)
}

/// [`challenge`] with its effect given (the rates per effect).
pub fn challenge_of(effect: Effect, seed: u64, index: usize, level: Level) -> Challenge {
    checked(seed, index, level, Some(effect), &|| false).expect("a draw never stopped")
}

/// `count` challenges of `seed` (indices 0..count), drawn over the machine's cores.
pub fn challenges(seed: u64, count: usize, level: Level) -> Vec<Challenge> {
    let indices: Vec<usize> = (0..count).collect();
    crate::parallel::map(&indices, |&i| challenge(seed, i, level))
}

/// The first draw Degrau solves (after [`MAX_ATTEMPTS`] of `effect`, any effect; the last
/// draw if none is solved), or `None` when `stop` said so before a draw.
fn checked(
    seed: u64,
    index: usize,
    level: Level,
    effect: Option<Effect>,
    stop: &dyn Fn() -> bool,
) -> Option<Challenge> {
    let mut last = None;
    for attempt in 0..2 * MAX_ATTEMPTS {
        if stop() {
            return None;
        }
        let fixed = effect.filter(|_| attempt < MAX_ATTEMPTS);
        let c = draw(seed, index, attempt, level, fixed);
        if solve(&c.csv()).is_some_and(|s| c.solved_by(&s)) {
            return Some(c);
        }
        last = Some(c);
    }
    last
}

/// The record of `truth`: the process's answer to the changes at their true instants (a
/// second change with its own gain, an earlier change still answered, a load), sampled,
/// with the logger's noise, spikes, range and resolution; the input as logged.
fn sample(rng: &mut Lcg, truth: &Truth) -> Record {
    let t = logger::sample_times(truth.length, truth.ts);
    let mut y = answer(truth, &t);
    let e = flaws::noise(rng, t.len(), truth.noise_sd, truth.rho);
    y.iter_mut().zip(&e).for_each(|(v, e)| *v += e);
    if truth.flaw == Some(Flaw::Outliers) {
        flaws::outliers(rng, &mut y, Truth::outlier_share(), truth.noise_sd);
    }
    if let Some(Setting::Clip { fraction }) = truth.setting {
        let dir = (truth.kp() * truth.changes[0].du).signum();
        test_flaw::add_clip(&mut y, truth.model.get(Param::Y0), dir, fraction);
    }
    if let Some(q) = truth.quantum {
        flaws::quantise(&mut y, q);
    }
    let u = logger::logged_input(&t, truth.u0, &truth.changes);
    Record { t, u, y }
}

/// The process's noiseless answer at the instants `t`.
fn answer(truth: &Truth, t: &[f64]) -> Vec<f64> {
    let model = &truth.model;
    let y0 = model.get(Param::Y0);
    let simulate = |m: &Model, changes: &[InputStep]| {
        let mut input = Excitation::step(changes[0].t, changes[0].du);
        input.steps = changes.to_vec();
        m.simulate(&input, t).unwrap_or_else(|_| vec![y0; t.len()])
    };
    // The same process from rest at zero, with gain `kp`.
    let from_zero = |kp: f64| {
        let mut v = model.values;
        v.set(Param::Kp, kp);
        v.set(Param::Y0, 0.0);
        Model::new(model.structure, v)
    };
    let (own, later) = match truth.setting {
        Some(Setting::SecondGain(_)) => truth.changes.split_at(1),
        _ => (&truth.changes[..], &[][..]),
    };
    let mut y = simulate(model, own);
    match truth.setting {
        Some(Setting::SecondGain(k2)) if !later.is_empty() => {
            let second = simulate(&from_zero(k2), later);
            y.iter_mut().zip(&second).for_each(|(v, s)| *v += s);
        }
        Some(Setting::Earlier { before, du }) => {
            // The earlier change's answer, still moving towards Kp·du: its decaying part.
            let kp = truth.kp();
            let earlier = simulate(&from_zero(kp), &[InputStep { t: -before, du }]);
            y.iter_mut()
                .zip(&earlier)
                .for_each(|(v, p)| *v += p - kp * du);
        }
        Some(Setting::Load { at, size, ramp }) => test_flaw::add_load(t, &mut y, at, size, ramp),
        _ => {}
    }
    y
}
