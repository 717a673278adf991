//! The challenges' rates (issue 27): how often the diagnosis, run as `degrau diagnose
//! record.csv` runs it, gets a challenge right on its *first* draw (the raw rate, before
//! the generator's re-draw of what Degrau cannot solve), per level and per hidden effect:
//! the first structural cause among the key's, the final structure, the gain within the
//! key's tolerance, the key's flaw named. Handed-out challenges are right by construction;
//! the test also counts the draws they took.
//!
//! The effects cycle with the index, so each is measured on the same number of cases.
//! `cargo test -p degrau-ident --test ident challenge_rates -- --nocapture` prints the
//! table; `DEGRAU_CHALLENGE_CASES=200` (in release) runs 200 per level,
//! `DEGRAU_CHALLENGE_SEED=n` another seed, and `DEGRAU_CHALLENGE_DUMP=folder` writes the
//! CSV of every first draw that is not solved there (and its hidden truth beside it, `.truth`), to look at with `degrau diagnose`.

use std::collections::BTreeMap;

use degrau_ident::challenge::{
    Challenge, Effect, Level, Solution, challenge, challenge_until, draw, kp_within, seed, solve,
};

/// Cases per level by default, two per effect (a debug build runs the three levels in
/// about half a minute on two cores).
const CASES: usize = 36;
/// The seed of the measured challenges.
const SEED: u64 = 2027;
/// Seed 1, index 0, first draw, per level: the effect, the CSV's lines and fingerprint.
const PINNED: [(&str, usize, u64); 3] = [
    ("zero", 1401, 9478847156283398130),
    ("integrator", 851, 4438423771511282950),
    ("coloured_noise_only", 1391, 8346904709437230820),
];
/// The rates of a right first cause asserted on the raw first draws, per level (clear,
/// moderate, subtle): the 99 %, 95 % and 80 %. Measured on 200 per level: 198, 198
/// and 200 on seed 9001 (a coarse converter's staircase no longer buys a pole and a zero
/// once each sample is read within its quantum), 200, 199 and 197 on seed 2027, 200, 200
/// and 195 on seed 4242. What is handed out is right by construction.
const RAW_FLOORS: [f64; 3] = [0.99, 0.95, 0.80];
/// Below this many cases per level (the default smoke run) the floors are asserted with
/// this slack: a few cases cannot measure a rate to a percent.
const FULL_RUN: usize = 100;
const SMOKE_SLACK: f64 = 0.10;

fn seed() -> u64 {
    std::env::var("DEGRAU_CHALLENGE_SEED")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(SEED)
}

/// Writes a missed first draw's CSV where `DEGRAU_CHALLENGE_DUMP` says (nowhere by default).
fn dump(level: Level, index: usize, c: &Challenge) {
    if let Ok(dir) = std::env::var("DEGRAU_CHALLENGE_DUMP") {
        let name = format!("{}_{index:03}_{}.csv", level.id(), c.truth.effect.id());
        let _ = std::fs::create_dir_all(&dir);
        let _ = std::fs::write(std::path::Path::new(&dir).join(&name), c.csv());
        let _ = std::fs::write(
            std::path::Path::new(&dir).join(format!("{name}.truth")),
            format!("{:#?}", c.truth),
        );
    }
}

fn cases() -> usize {
    std::env::var("DEGRAU_CHALLENGE_CASES")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .filter(|&n| n > 0)
        .unwrap_or(CASES)
}

/// One first draw and what the diagnosis made of it.
struct Outcome {
    effect: Effect,
    cause: bool,
    structure: bool,
    kp: bool,
    all: bool,
    /// Draws until one was solved (1: the first), at most `LIMIT`.
    draws: usize,
    note: String,
}

const LIMIT: usize = 30;

fn judge(c: &Challenge, s: &Option<Solution>) -> (bool, bool, bool, bool) {
    let Some(s) = s else {
        return (false, false, false, false);
    };
    let structure = s.structure == c.structure;
    let kp = kp_within(s.kp, c.kp, c.kp_tolerance);
    (c.names_cause(s), structure, kp, c.solved_by(s))
}

fn run(level: Level, index: usize) -> Outcome {
    let effect = Effect::ALL[index % Effect::ALL.len()];
    let first = draw(seed(), index, 0, level, Some(effect));
    let solution = solve(&first.csv());
    let (cause, structure, kp, all) = judge(&first, &solution);
    if !all {
        dump(level, index, &first);
    }
    // The draws the generator makes before handing this challenge out.
    let draws = if all {
        1
    } else {
        (1..LIMIT)
            .find(|&attempt| {
                let c = draw(seed(), index, attempt, level, Some(effect));
                solve(&c.csv()).is_some_and(|s| c.solved_by(&s))
            })
            .map_or(LIMIT, |attempt| attempt + 1)
    };
    let note = match &solution {
        Some(s) => format!(
            "#{index} {}: named {} → {} Kp {:.4} (true {:.4}{}) flaws {:?} | noise {:.2} % rho {:.2} changes {}",
            effect.id(),
            s.first_cause.id(),
            s.structure,
            s.kp,
            first.kp,
            first
                .truth
                .flaw
                .map_or(String::new(), |f| format!(", {f:?}")),
            s.test_causes.iter().map(|k| k.id()).collect::<Vec<_>>(),
            100.0 * first.truth.noise_sd / first.truth.effect_size,
            first.truth.rho,
            first.truth.changes.len()
        ),
        None => format!("#{index} {}: not solved at all", effect.id()),
    };
    Outcome {
        effect,
        cause,
        structure,
        kp,
        all,
        draws,
        note,
    }
}

/// Every case of `level`, over two threads.
fn outcomes(level: Level) -> Vec<Outcome> {
    let n = cases();
    let workers = std::thread::available_parallelism().map_or(1, |p| p.get());
    let mut out: Vec<(usize, Outcome)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                scope.spawn(move || {
                    (w..n)
                        .step_by(workers)
                        .map(|i| (i, run(level, i)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("a worker"))
            .collect()
    });
    out.sort_by_key(|(i, _)| *i);
    out.into_iter().map(|(_, o)| o).collect()
}

fn percent(k: usize, n: usize) -> String {
    format!("{k}/{n} ({:.0} %)", 100.0 * k as f64 / n.max(1) as f64)
}

/// Prints the table of `level` and returns its rate of a right first cause.
fn report(level: Level, outcomes: &[Outcome]) -> f64 {
    let mut by: BTreeMap<usize, Vec<&Outcome>> = BTreeMap::new();
    for o in outcomes {
        let k = Effect::ALL.iter().position(|&e| e == o.effect).unwrap_or(0);
        by.entry(k).or_default().push(o);
    }
    let count = |v: &[&Outcome], f: &dyn Fn(&Outcome) -> bool| v.iter().filter(|o| f(o)).count();
    let mut text = format!(
        "\n[challenge {} seed {}] raw (first draw): cause right first | structure | Kp within {:.0} % | all | draws to hand out (mean, max)",
        level.id(),
        seed(),
        100.0 * level.kp_tolerance()
    );
    let all: Vec<&Outcome> = outcomes.iter().collect();
    let mut rows: Vec<(String, Vec<&Outcome>)> = by
        .into_values()
        .map(|v| (v[0].effect.id().to_string(), v))
        .collect();
    rows.push(("ALL".to_string(), all.clone()));
    for (name, v) in &rows {
        let n = v.len();
        let draws: Vec<usize> = v.iter().map(|o| o.draws).collect();
        text += &format!(
            "\n  {name:<22} {:<14} {:<14} {:<14} {:<14} {:.2}, {}",
            percent(count(v, &|o| o.cause), n),
            percent(count(v, &|o| o.structure), n),
            percent(count(v, &|o| o.kp), n),
            percent(count(v, &|o| o.all), n),
            draws.iter().sum::<usize>() as f64 / n.max(1) as f64,
            draws.iter().max().copied().unwrap_or(0)
        );
    }
    for o in outcomes.iter().filter(|o| !o.all) {
        text += &format!("\n    miss {}", o.note);
    }
    eprintln!("{text}");
    count(&all, &|o| o.cause) as f64 / all.len().max(1) as f64
}

fn accept(level: Level) {
    let outcomes = outcomes(level);
    let rate = report(level, &outcomes);
    let handed = outcomes.iter().filter(|o| o.draws < LIMIT).count();
    assert_eq!(
        handed,
        outcomes.len(),
        "{}: a challenge needed {LIMIT} draws or more",
        level.id()
    );
    let slack = if outcomes.len() < FULL_RUN {
        SMOKE_SLACK
    } else {
        0.0
    };
    let floor = RAW_FLOORS[level.index()] - slack;
    assert!(
        rate >= floor,
        "{}: the first draws' cause is named right first in {:.1} %, below {:.0} %",
        level.id(),
        100.0 * rate,
        100.0 * floor
    );
}

#[test]
fn clear_challenges_are_solved_on_the_first_draw() {
    accept(Level::Clear);
}

#[test]
fn moderate_challenges_are_solved_on_the_first_draw() {
    accept(Level::Moderate);
}

#[test]
fn subtle_challenges_are_solved_on_the_first_draw() {
    accept(Level::Subtle);
}

/// The same seed, index and level give the same record; another seed another.
#[test]
fn a_challenge_is_reproducible_from_its_seed() {
    let a = draw(SEED, 3, 0, Level::Moderate, None);
    let b = draw(SEED, 3, 0, Level::Moderate, None);
    assert_eq!(a.csv(), b.csv());
    assert_ne!(a.csv(), draw(SEED + 1, 3, 0, Level::Moderate, None).csv());
    assert_ne!(
        seed::stream(SEED, 3, 0).bits(),
        seed::stream(SEED, 3, 1).bits()
    );
}

/// What is handed out is a draw Degrau solves, the same every time; an answer wrong in one
/// part does not solve it.
#[test]
fn a_handed_out_challenge_is_one_degrau_solves() {
    for index in 0..3 {
        let c = challenge(SEED, index, Level::Subtle);
        let s = solve(&c.csv()).expect("a generated record is diagnosed");
        assert!(c.solved_by(&s), "#{index}: {s:?} for {:?}", c.causes);
        assert_eq!(c, challenge(SEED, index, Level::Subtle));
        let mut off = s.clone();
        off.kp *= 1.0 + 2.0 * c.kp_tolerance;
        assert!(!c.solved_by(&off));
        let mut other = s.clone();
        other.structure = "P3DUZ".into();
        assert!(!c.solved_by(&other));
    }
}

/// A draw told to stop hands nothing out: at once, or at the draw after the stop (a
/// student's Cancel ends the work within one diagnosis).
#[test]
fn a_stopped_draw_hands_nothing_out() {
    assert_eq!(challenge_until(SEED, 0, Level::Clear, &|| true), None);
    let asked = std::sync::atomic::AtomicUsize::new(0);
    let stop = || asked.fetch_add(1, std::sync::atomic::Ordering::Relaxed) >= 1;
    // A challenge handed out at its first draw: asked once, not stopped.
    let (index, first) = (0..20)
        .map(|i| (i, challenge(SEED, i, Level::Clear)))
        .find(|(_, c)| c.attempt == 0)
        .expect("a clear challenge solved at its first draw");
    let handed = challenge_until(SEED, index, Level::Clear, &stop);
    assert_eq!(handed, Some(first));
}

/// FNV-1a of a text: a fingerprint of a record's bytes.
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The bytes of the generator's first draws, pinned: a change to the generator that changes
/// a record must bump `GENERATOR_VERSION` (and these fingerprints with it). Version 3 draws
/// as version 2 did; only which draws are handed out changed with the diagnosis.
#[test]
fn version_3_records_keep_their_bytes() {
    assert_eq!(degrau_ident::challenge::GENERATOR_VERSION, 3);
    let prints: Vec<(String, usize, u64)> = Level::ALL
        .iter()
        .map(|&level| {
            let c = draw(1, 0, 0, level, None);
            let csv = c.csv();
            (
                c.truth.effect.id().to_string(),
                csv.lines().count(),
                fnv1a(&csv),
            )
        })
        .collect();
    eprintln!("{prints:?}");
    assert_eq!(prints, PINNED.map(|(e, n, h)| (e.to_string(), n, h)));
}
