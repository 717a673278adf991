//! Acceptance test of issue 21's generator line: causes that leave the same slow residual
//! (a drift, a slow extra pole, a load disturbance, a test not at rest, a strong lead zero, an
//! inverse response) told apart on records as messy as real ones, and clean records left
//! alone. This file owns its generator, drawn unlike `diagnose_generator` and
//! `diagnose_artefacts`, and one `#[test]` per kind of record, each asserting the issue's
//! thresholds over [`CASES`] seeded cases.
//!
//! What every record has, as a logger gives it:
//! - the true input changes come between two samples; the logged input column shows each at
//!   the next sample, and the diagnosis sees only that column (`Excitation::measured`, zero
//!   order hold; the start structure estimates the lead, as the CLI's does);
//! - operating points far from zero: y0 ∈ [−200, 500], u0 ∈ [0, 80]; |Kp| ∈ [0.2, 8] and
//!   |Δu| ∈ [0.3, 20], both log-uniform, signs random;
//! - lags log-uniform in [0.5, 60] s, 150–800 samples, a stretch of 10–20 % of the record
//!   before the first change;
//! - noise of standard deviation 0.2–2 % of the first change's effect |Kp·Δu| (log-uniform),
//!   Gaussian or uniform, white in half the records and AR(1) with ρ ∈ [0.3, 0.7] in the
//!   other half; a third of the records quantised with a quantum of half the noise's σ;
//! - Y0 held at the mean of the samples before the first logged change in half the cases
//!   (what the CLI does when the record starts at rest), estimated in the other half.
//!
//! The start is `P1` (the CLI's default) unless the kind says otherwise; where the truth
//! carries a dead time that is not what the kind tests (the drift's P1D, the load
//! disturbance), the start carries it too, so that the only thing missing is the kind's.
//!
//! The kinds and what passes a case (a kind passes with ≥ 95 % of its cases):
//! - `drift`: P1 or P1D plus a linear drift of 10–30 % of the effect over the record, one step
//!   (record 6–10 lags after it) or an up-and-down pair (each change held 4–6 lags): `drift`
//!   is the first step's cause and the final Kp is within 10 %;
//! - `slow_pole`: P2 with Tp2 3–10 × Tp1, the record ending 1–2 × Tp2 after the step (it does
//!   not settle), start P1: `extra_pole` first, Kp within 10 %, and no drift anywhere in the
//!   chain or the final model;
//! - `load_disturbance`: P1D with a load step of ±10–30 % of the effect at 4–6 Tp1 after the
//!   response starts, held 4–7 Tp1 more, start P1D: the test cause `disturbance` named, no
//!   structural step, Kp within 10 %;
//! - `not_at_rest`: P1, the record starting while the process still answers an earlier change
//!   (20–50 % of the effect, made 0.3–1 Tp1 before the first sample): `not_at_rest` named and
//!   Kp within 10 %;
//! - `lead_zero`: P2Z with Tz 1.5–4 × Tp1 and Tp2 0.1–0.5 × Tp1 (an overshoot), start P1: the
//!   first step names `zero` or `extra_pole` (the zero, or the pole it comes with), the final
//!   structure is P2Z and nothing else (no dead time, drift, integrator, oscillation,
//!   transient, and Y0 held where the start held it), Kp within 10 %;
//! - `inverse_response`: the same with Tz −0.3 to −1.5 × Tp1 and Tp2 0.1–0.6 × Tp1: the first
//!   step names `inverse_response` or `extra_pole`, the final P2Z has a negative Tz and
//!   nothing else, Kp within 10 %;
//! - `clean`: P1, P1D, P2, P2U, P2DU and P2Z in turn, each fitted from its own structure, a
//!   third of them with a second change back: no structural step (`none`).
//!
//! Kp is the report's static gain against the true gain. Each test prints a one-line
//! summary and a line per failing case (the truth, the chain, the final model, and the Kp
//! the true structure reaches when fitted from the truth on the same record: where it misses
//! too, the record does not determine the gain and the diagnosis is not the one to blame);
//! run with
//! `cargo test --test diagnose_lookalikes -- --nocapture` to see them.

use std::time::Instant;

use degrau_ident::diagnose::test_causes::TestCauseKind;
use degrau_ident::diagnose::{Cause, DiagnoseOptions, DiagnoseReport, diagnose};
use degrau_ident::fit::{FitData, FitOptions, fit};
use degrau_ident::model::excitation::{Excitation, Hold};
use degrau_ident::model::{Model, Param, Structure, Values};
use degrau_ident::random::Lcg;

use crate::draw::Draws;

/// Cases per kind.
const CASES: usize = 20;
/// Share of a kind's cases that must pass.
const MIN_PASS: f64 = 0.95;
/// Relative tolerance of the final Kp.
const KP_TOLERANCE: f64 = 0.10;

const Y0: (f64, f64) = (-200.0, 500.0);
const U0: (f64, f64) = (0.0, 80.0);
const KP: (f64, f64) = (0.2, 8.0);
const DU: (f64, f64) = (0.3, 20.0);
const LAG: (f64, f64) = (0.5, 60.0);
const SAMPLES: (usize, usize) = (150, 800);
const BEFORE_SHARE: (f64, f64) = (0.10, 0.20);
const NOISE_SHARE: (f64, f64) = (0.002, 0.02);
const RHO: (f64, f64) = (0.3, 0.7);

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Drift,
    SlowPole,
    LoadDisturbance,
    NotAtRest,
    LeadZero,
    InverseResponse,
    Clean,
}

impl Kind {
    fn id(self) -> &'static str {
        match self {
            Kind::Drift => "drift",
            Kind::SlowPole => "slow_pole",
            Kind::LoadDisturbance => "load_disturbance",
            Kind::NotAtRest => "not_at_rest",
            Kind::LeadZero => "lead_zero",
            Kind::InverseResponse => "inverse_response",
            Kind::Clean => "clean",
        }
    }

    /// The causes that are right as the first step's.
    fn right_first(self) -> &'static [Cause] {
        match self {
            Kind::Drift => &[Cause::Drift],
            Kind::SlowPole => &[Cause::ExtraPole],
            Kind::LeadZero => &[Cause::Zero, Cause::ExtraPole],
            Kind::InverseResponse => &[Cause::InverseResponse, Cause::ExtraPole],
            Kind::LoadDisturbance | Kind::NotAtRest | Kind::Clean => &[Cause::None],
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The generator
// ---------------------------------------------------------------------------------------------

/// The crate's LCG, seeded through a SplitMix64 scramble of the case's number; its draws
/// are the shared ones ([`Draws`]).
struct Rng(Lcg);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(Lcg(degrau_ident::challenge::seed::splitmix64(seed)))
    }

    fn unit(&mut self) -> f64 {
        self.0.unit()
    }

    fn signed_log(&mut self, r: (f64, f64)) -> f64 {
        let s = self.sign();
        s * self.log_range(r)
    }

    fn count(&mut self, (a, b): (usize, usize)) -> usize {
        a + self.0.below(b - a + 1)
    }
}

impl Draws for Rng {
    fn lcg(&mut self) -> &mut Lcg {
        &mut self.0
    }
}

/// One simulated test: the record the diagnosis sees, its truth and how it was drawn.
struct Case {
    kind: Kind,
    index: usize,
    seed: u64,
    /// The process (Y0 = 0, no drift; the operating point and the artefacts are added).
    truth: Model,
    /// The true input changes (instant, size), before the record logs them.
    changes: Vec<(f64, f64)>,
    data: FitData,
    start: Structure,
    /// Y0 held at this value in the start model; `None`: estimated.
    held_y0: Option<f64>,
    /// |Kp·Δu| of the first change.
    effect: f64,
    sd: f64,
    rho: f64,
    quantum: Option<f64>,
    /// What the kind added, in words.
    note: String,
}

impl Case {
    fn describe(&self) -> String {
        let t = &self.truth;
        let mut s = format!(
            "{} #{} seed {:#x}: truth {}",
            self.kind.id(),
            self.index,
            self.seed,
            t.structure.code()
        );
        for p in t.structure.params() {
            s += &format!(" {}={:.4}", p.name(), t.get(p));
        }
        let changes: Vec<String> = self
            .changes
            .iter()
            .map(|(t, du)| format!("{du:+.3}@{t:.3}"))
            .collect();
        s += &format!(
            " | {} | start {}{} | changes [{}] u0={:.2} N={} Ts={:.4} | noise {:.2} % of {:.3}, rho {:.2}{}",
            self.note,
            self.start.code(),
            self.held_y0
                .map_or(" (Y0 free)".to_string(), |y| format!(" (Y0 held {y:.3})")),
            changes.join(", "),
            self.data.input.u0,
            self.data.times.len(),
            self.data.sampling_period(),
            100.0 * self.sd / self.effect,
            self.effect,
            self.rho,
            self.quantum
                .map_or(String::new(), |q| format!(", quantum {q:.4}")),
        );
        s
    }
}

fn structure(code: &str) -> Structure {
    let mut s = Structure::parse(code).unwrap();
    s.free_offset = false;
    s
}

/// The `index`-th case of `kind`.
fn generate(kind: Kind, index: usize) -> Case {
    let seed = 0x1005_A11C_0000 + 0x1_0000 * kind as u64 + index as u64;
    let mut rng = Rng::new(seed);
    let kp = rng.signed_log(KP);
    let du = rng.signed_log(DU);
    let y0 = rng.range(Y0);
    let u0 = rng.range(U0);
    let tp1 = rng.log_range(LAG);
    let effect = (kp * du).abs();
    let mut v = Values::default();
    v.set(Param::Kp, kp);
    v.set(Param::Tp1, tp1);
    let mut note = String::new();
    // The truth's code, the start's, the slowest lag, and how long each change is held
    // (the last one up to the record's end).
    let (truth_code, start_code, pair) = match kind {
        Kind::Drift => {
            let code = if (index / 2).is_multiple_of(2) {
                "P1"
            } else {
                "P1D"
            };
            (code, code, (index / 4).is_multiple_of(2))
        }
        Kind::SlowPole => ("P2", "P1", false),
        Kind::LoadDisturbance => ("P1D", "P1D", false),
        Kind::NotAtRest => ("P1", "P1", false),
        Kind::LeadZero | Kind::InverseResponse => ("P2Z", "P1", false),
        Kind::Clean => {
            let code = ["P1", "P1D", "P2", "P2U", "P2DU", "P2Z"][index % 6];
            (code, code, rng.unit() < 1.0 / 3.0)
        }
    };
    let truth_s = structure(truth_code);
    let mut slowest = tp1;
    match (kind, truth_code) {
        (Kind::SlowPole, _) => {
            let tp2 = rng.range((3.0, 10.0)) * tp1;
            v.set(Param::Tp2, tp2);
            slowest = tp2;
        }
        (Kind::LeadZero, _) => {
            v.set(Param::Tp2, rng.range((0.1, 0.5)) * tp1);
            v.set(Param::Tz, rng.range((1.5, 4.0)) * tp1);
        }
        (Kind::InverseResponse, _) => {
            v.set(Param::Tp2, rng.range((0.1, 0.6)) * tp1);
            v.set(Param::Tz, -rng.range((0.3, 1.5)) * tp1);
        }
        (_, "P2") => v.set(Param::Tp2, rng.range((0.2, 0.7)) * tp1),
        (_, "P2Z") => {
            v.set(Param::Tp2, rng.range((0.1, 0.5)) * tp1);
            let tz = if rng.unit() < 0.5 {
                rng.range((1.5, 3.0)) * tp1
            } else {
                -rng.range((0.3, 1.0)) * tp1
            };
            v.set(Param::Tz, tz);
        }
        (_, "P2U" | "P2DU") => {
            let tw = rng.log_range((0.5, 15.0));
            let zeta = rng.range((0.15, 0.6));
            v.set(Param::Tw, tw);
            v.set(Param::Zeta, zeta);
            slowest = tw / zeta;
        }
        _ => {}
    }
    if truth_s.delay {
        let base = if truth_s.underdamped {
            v.get(Param::Tw)
        } else {
            tp1
        };
        v.set(Param::Td, rng.range((0.1, 0.8)) * base);
    }
    let td = if truth_s.delay { v.get(Param::Td) } else { 0.0 };
    let truth = Model::new(truth_s, v);

    // The record's plan: how long after the first change it runs, the second change.
    let load_at = rng.range((4.0, 6.0)) * tp1 + td;
    let (after, second_at) = match kind {
        Kind::SlowPole => (rng.range((1.0, 2.0)) * slowest, None),
        Kind::LoadDisturbance => (load_at + rng.range((4.0, 7.0)) * tp1, None),
        Kind::Drift if pair => {
            let hold = rng.range((4.0, 6.0)) * slowest + td;
            (hold + rng.range((4.0, 6.0)) * slowest + td, Some(hold))
        }
        Kind::Clean if pair => {
            let hold = rng.range((5.0, 8.0)) * slowest + td;
            (hold + rng.range((5.0, 8.0)) * slowest + td, Some(hold))
        }
        _ => (rng.range((6.0, 10.0)) * slowest + td, None),
    };
    let before_share = rng.range(BEFORE_SHARE);
    let length = after / (1.0 - before_share);
    let n = rng.count(SAMPLES);
    let h = length / (n - 1) as f64;
    // The record's clock starts at an arbitrary instant, as a logger's does.
    let origin = rng.range((0.0, 1000.0)) * h;
    let times: Vec<f64> = (0..n).map(|k| origin + h * k as f64).collect();
    // The true instants: inside a sampling period, never on a sample.
    let at = |t: f64, rng: &mut Rng| {
        let k = ((t - origin) / h).floor();
        origin + h * (k + rng.range((0.05, 0.95)))
    };
    let t0 = at(origin + before_share * length, &mut rng);
    let mut changes = vec![(t0, du)];
    if let Some(hold) = second_at {
        let back = -du * rng.range((0.5, 1.2));
        changes.push((at(t0 + hold, &mut rng), back));
        note += &format!("pair held {:.2} lags ", hold / slowest);
    }

    // The process's answer to the true changes, around y0.
    let mut y = vec![y0; n];
    for &(t, d) in &changes {
        let answer = truth.simulate(&Excitation::step(t, d), &times).unwrap();
        y.iter_mut().zip(&answer).for_each(|(yi, a)| *yi += a);
    }
    match kind {
        Kind::Drift => {
            let total = rng.signed((0.1, 0.3)) * effect;
            let slope = total / (times[n - 1] - times[0]);
            for (yi, &t) in y.iter_mut().zip(&times) {
                *yi += slope * (t - times[0]);
            }
            note += &format!("drift {:+.1} % of the effect", 100.0 * total / effect);
        }
        Kind::LoadDisturbance => {
            let when = t0 + load_at;
            let size = rng.signed((0.1, 0.3)) * effect;
            for (yi, &t) in y.iter_mut().zip(&times) {
                if t >= when {
                    *yi += size;
                }
            }
            note += &format!(
                "load {size:+.3} ({:+.0} %) at {when:.2} ({:.2} Tp1 after the change)",
                100.0 * size / effect,
                (when - t0) / tp1
            );
        }
        Kind::NotAtRest => {
            let earlier = rng.signed((0.2, 0.5)) * du;
            let before = rng.range((0.3, 1.0)) * tp1;
            let answer = truth
                .simulate(&Excitation::step(times[0] - before, earlier), &times)
                .unwrap();
            // Still on its way to Kp·earlier, the level the record is centred on.
            for (yi, a) in y.iter_mut().zip(&answer) {
                *yi += a - kp * earlier;
            }
            note += &format!(
                "earlier change {earlier:+.3} ({:+.0} % of the effect) {:.2} Tp1 before the record",
                100.0 * kp * earlier / effect,
                before / tp1
            );
        }
        Kind::SlowPole => {
            note += &format!("record ends {:.2} Tp2 after the change", after / slowest);
        }
        Kind::LeadZero | Kind::InverseResponse => {
            note += &format!("Tz/Tp1 {:.2}", v.get(Param::Tz) / tp1);
        }
        Kind::Clean => note += "clean",
    }
    if note.is_empty() {
        note = "-".into();
    }

    // The noise: white or AR(1), Gaussian or uniform innovations; a third quantised.
    let sd = rng.log_range(NOISE_SHARE) * effect;
    let rho = if rng.unit() < 0.5 {
        0.0
    } else {
        rng.range(RHO)
    };
    let gaussian = rng.unit() < 0.5;
    let innovation = |rng: &mut Rng| {
        if gaussian {
            rng.gaussian()
        } else {
            3f64.sqrt() * (2.0 * rng.unit() - 1.0)
        }
    };
    let mut e = sd * innovation(&mut rng);
    let scale = sd * (1.0 - rho * rho).sqrt();
    for yi in &mut y {
        *yi += e;
        e = rho * e + scale * innovation(&mut rng);
    }
    let quantum = (rng.unit() < 1.0 / 3.0).then_some(0.5 * sd);
    if let Some(q) = quantum {
        y.iter_mut().for_each(|yi| *yi = (*yi / q).round() * q);
    }

    // The logged input: each change at the first sample after its true instant.
    let u: Vec<f64> = times
        .iter()
        .map(|&t| {
            u0 + changes
                .iter()
                .filter(|(tc, _)| *tc <= t)
                .map(|(_, d)| d)
                .sum::<f64>()
        })
        .collect();
    let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
    let data = FitData { times, y, input };

    let mut start = structure(start_code);
    start.lead = data.input.lead_range > 0.0;
    let held = if kind == Kind::Clean {
        (index / 6).is_multiple_of(2)
    } else {
        index.is_multiple_of(2)
    };
    let held_y0 = held.then(|| crate::draw::mean_before(&data));
    start.free_offset = !held;
    Case {
        kind,
        index,
        seed,
        truth,
        changes,
        data,
        start,
        held_y0,
        effect,
        sd,
        rho,
        quantum,
        note,
    }
}

// ---------------------------------------------------------------------------------------------
// Running and judging
// ---------------------------------------------------------------------------------------------

/// What came out of one case: the criteria it was judged on, and the text of a failure.
struct Outcome {
    /// (name, met) for each criterion of the kind.
    checks: Vec<(&'static str, bool)>,
    text: String,
    seconds: f64,
}

impl Outcome {
    fn passed(&self) -> bool {
        self.checks.iter().all(|(_, ok)| *ok)
    }
}

fn chain(report: &DiagnoseReport) -> String {
    let mut s = report.start.model.structure.label();
    for step in &report.steps {
        let paired = step
            .paired
            .map_or(String::new(), |c| format!("+{}", c.id()));
        s += &format!(
            " -[{}{paired}]-> {}",
            step.cause.id(),
            step.fit.model.structure.label()
        );
    }
    if report.steps.is_empty() {
        s += " (none)";
    }
    let causes: Vec<&str> = report.test_causes.iter().map(|c| c.kind.id()).collect();
    s + &format!(" | test causes [{}]", causes.join(", "))
}

fn final_model(report: &DiagnoseReport) -> String {
    let m = &report.final_fit.model;
    let mut s = m.structure.label();
    for p in m.structure.params() {
        s += &format!(" {}={:.4}", p.name(), m.get(p));
    }
    s
}

/// The final structure is P2Z and nothing else: no dead time, drift, integrator, oscillation
/// or transient, and Y0 held where the start held it.
fn bare_p2z(case: &Case, report: &DiagnoseReport) -> bool {
    let s = report.final_fit.model.structure;
    s.poles == 2
        && s.zero
        && !s.delay
        && !s.drift
        && !s.integrator
        && !s.underdamped
        && !s.transient
        && s.free_offset == case.start.free_offset
}

fn judge(case: &Case, report: &DiagnoseReport) -> Vec<(&'static str, bool)> {
    let first = report.steps.first().map_or(Cause::None, |s| s.cause);
    let right_first = case.kind.right_first().contains(&first);
    let true_kp = case.truth.get(Param::Kp);
    let kp_ok = ((report.static_gain.0 - true_kp) / true_kp).abs() <= KP_TOLERANCE;
    let named = |k: TestCauseKind| report.test_causes.iter().any(|c| c.kind == k);
    let no_drift = !report.final_fit.model.structure.drift
        && report
            .steps
            .iter()
            .all(|s| s.cause != Cause::Drift && s.paired != Some(Cause::Drift));
    match case.kind {
        Kind::Drift => vec![("right first", right_first), ("Kp", kp_ok)],
        Kind::SlowPole => vec![
            ("right first", right_first),
            ("Kp", kp_ok),
            ("no drift", no_drift),
        ],
        Kind::LoadDisturbance => vec![
            ("disturbance named", named(TestCauseKind::Disturbance)),
            ("no structural step", report.steps.is_empty()),
            ("Kp", kp_ok),
        ],
        Kind::NotAtRest => vec![
            ("not_at_rest named", named(TestCauseKind::NotAtRest)),
            ("Kp", kp_ok),
        ],
        Kind::LeadZero => vec![
            ("right first", right_first),
            ("final bare P2Z", bare_p2z(case, report)),
            ("Kp", kp_ok),
        ],
        Kind::InverseResponse => vec![
            ("right first", right_first),
            (
                "final bare P2Z, Tz < 0",
                bare_p2z(case, report) && report.final_fit.model.get(Param::Tz) < 0.0,
            ),
            ("Kp", kp_ok),
        ],
        Kind::Clean => vec![("none", report.steps.is_empty())],
    }
}

/// The Kp of the true structure (with the drift or the initial transient the kind adds, Y0
/// held or free as in the start) fitted by one Levenberg–Marquardt run from the true values.
fn oracle(case: &Case) -> String {
    let mut s = case.truth.structure;
    s.lead = case.start.lead;
    s.free_offset = case.start.free_offset;
    s.drift = case.kind == Kind::Drift;
    s.transient = case.kind == Kind::NotAtRest;
    let mut v = case.truth.values;
    v.set(
        Param::Y0,
        case.held_y0
            .unwrap_or_else(|| crate::draw::mean_before(&case.data)),
    );
    v.set(Param::Ta, 0.5 * case.data.sampling_period());
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let true_kp = case.truth.get(Param::Kp);
    match fit(&case.data, s, v, &options, &mut ()) {
        Ok(r) => {
            let kp = r.model.get(Param::Kp);
            format!(
                "true structure fitted: Kp {kp:.4} ({:+.1} %)",
                100.0 * (kp / true_kp - 1.0)
            )
        }
        Err(e) => format!("true structure fit failed: {e}"),
    }
}

fn run(kind: Kind, index: usize) -> Outcome {
    let case = generate(kind, index);
    let values = case.held_y0.map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let clock = Instant::now();
    let result = diagnose(&case.data, case.start, values, &DiagnoseOptions::default());
    let seconds = clock.elapsed().as_secs_f64();
    match result {
        Ok(report) => {
            let checks = judge(&case, &report);
            let failed: Vec<&str> = checks
                .iter()
                .filter(|(_, ok)| !ok)
                .map(|(name, _)| *name)
                .collect();
            let text = if failed.is_empty() {
                String::new()
            } else {
                format!(
                    "{}\n      failed [{}] | chain {} | final {} | Kp {:.4} vs {:.4} ({:+.1} %) | {} | {seconds:.1} s",
                    case.describe(),
                    failed.join(", "),
                    chain(&report),
                    final_model(&report),
                    report.static_gain.0,
                    case.truth.get(Param::Kp),
                    100.0 * (report.static_gain.0 / case.truth.get(Param::Kp) - 1.0),
                    oracle(&case),
                )
            };
            Outcome {
                checks,
                text,
                seconds,
            }
        }
        Err(e) => Outcome {
            checks: vec![("diagnose ran", false)],
            text: format!("{}\n      diagnose failed: {e}", case.describe()),
            seconds,
        },
    }
}

/// Runs the kind's cases, prints its summary and failures, and asserts the threshold.
fn accept(kind: Kind) {
    let clock = Instant::now();
    let outcomes: Vec<Outcome> = (0..CASES).map(|i| run(kind, i)).collect();
    let n = outcomes.len();
    let passed = outcomes.iter().filter(|o| o.passed()).count();
    let mut criteria: Vec<(&str, usize)> = Vec::new();
    for o in &outcomes {
        for (k, (name, ok)) in o.checks.iter().enumerate() {
            match criteria.get_mut(k) {
                Some(c) => c.1 += usize::from(*ok),
                None => criteria.push((name, usize::from(*ok))),
            }
        }
    }
    let criteria: Vec<String> = criteria
        .iter()
        .map(|(name, c)| format!("{name} {c}/{n}"))
        .collect();
    let (slowest_case, slowest) =
        outcomes
            .iter()
            .map(|o| o.seconds)
            .enumerate()
            .fold(
                (0, 0.0),
                |best, (i, s)| if s > best.1 { (i, s) } else { best },
            );
    let mut text = format!(
        "\n[{}] passed {passed}/{n} (needs {:.0} %) | {} | diagnose {:.2} s mean, {slowest:.2} s max (#{slowest_case}) | {:.1} s",
        kind.id(),
        100.0 * MIN_PASS,
        criteria.join(" | "),
        outcomes.iter().map(|o| o.seconds).sum::<f64>() / n as f64,
        clock.elapsed().as_secs_f64(),
    );
    for o in outcomes.iter().filter(|o| !o.passed()) {
        text += &format!("\n  FAIL {}", o.text);
    }
    eprintln!("{text}");
    assert!(
        passed as f64 >= MIN_PASS * n as f64,
        "{}: {passed}/{n} cases pass, below {:.0} % (the failing cases are listed above)",
        kind.id(),
        100.0 * MIN_PASS
    );
}

// ---------------------------------------------------------------------------------------------
// The tests
// ---------------------------------------------------------------------------------------------

#[test]
fn a_drift_is_named_first_and_leaves_the_gain() {
    accept(Kind::Drift);
}

#[test]
fn a_slow_pole_on_a_record_that_does_not_settle_is_a_pole_not_a_drift() {
    accept(Kind::SlowPole);
}

#[test]
fn a_load_disturbance_is_named_and_buys_no_structure() {
    accept(Kind::LoadDisturbance);
}

#[test]
fn a_test_not_at_rest_is_named_and_leaves_the_gain() {
    accept(Kind::NotAtRest);
}

#[test]
fn a_strong_lead_zero_from_p1_ends_at_a_bare_p2z() {
    accept(Kind::LeadZero);
}

#[test]
fn an_inverse_response_from_p1_ends_at_a_bare_p2z() {
    accept(Kind::InverseResponse);
}

#[test]
fn clean_records_of_every_structure_come_out_none() {
    accept(Kind::Clean);
}

/// The generator keeps its promises: the same seed gives the same record, the ranges hold,
/// every true change lies strictly inside the sampling period before the sample that logs
/// it, the noise is its share of the effect, and the quantised records sit on their grid.
#[test]
fn the_generator_keeps_its_promises() {
    let kinds = [
        Kind::Drift,
        Kind::SlowPole,
        Kind::LoadDisturbance,
        Kind::NotAtRest,
        Kind::LeadZero,
        Kind::InverseResponse,
        Kind::Clean,
    ];
    for kind in kinds {
        let mut held = 0;
        for index in 0..CASES {
            let case = generate(kind, index);
            let again = generate(kind, index);
            let what = case.describe();
            assert_eq!(case.data, again.data, "{what}");
            let d = &case.data;
            let n = d.times.len();
            assert!((SAMPLES.0..=SAMPLES.1).contains(&n), "{what}");
            assert!(
                (U0.0..=U0.1).contains(&d.input.u0),
                "{what}: u0 {}",
                d.input.u0
            );
            let kp = case.truth.get(Param::Kp).abs();
            assert!(kp >= KP.0 && kp <= KP.1, "{what}");
            let h = d.sampling_period();
            assert_eq!(d.input.changes.len(), case.changes.len(), "{what}");
            for (logged, (t, du)) in d.input.changes.iter().zip(&case.changes) {
                assert!(
                    logged.t > *t && logged.t - t < h,
                    "{what}: change at {t} logged at {}",
                    logged.t
                );
                assert!((logged.du - du).abs() <= 1e-9 * du.abs(), "{what}");
            }
            let record = d.times[n - 1] - d.times[0];
            let share = (case.changes[0].0 - d.times[0]) / record;
            assert!(
                share >= BEFORE_SHARE.0 - 2.0 * h / record
                    && share <= BEFORE_SHARE.1 + 2.0 * h / record,
                "{what}: {share}"
            );
            let noise = case.sd / case.effect;
            assert!(noise >= NOISE_SHARE.0 && noise <= NOISE_SHARE.1, "{what}");
            assert!(
                case.rho == 0.0 || (RHO.0..=RHO.1).contains(&case.rho),
                "{what}"
            );
            if let Some(q) = case.quantum {
                assert!(
                    d.y.iter().all(|y| ((y / q) - (y / q).round()).abs() < 1e-6),
                    "{what}"
                );
            }
            assert_eq!(case.start.free_offset, case.held_y0.is_none(), "{what}");
            held += usize::from(case.held_y0.is_some());
        }
        assert!((8..=12).contains(&held), "{}: Y0 held in {held}", kind.id());
    }
}
