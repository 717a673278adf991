//! Acceptance test of identification from a measured input (tracker issue 10): generated
//! records as messy as real ones, fitted the way the CLI fits them (`Experiment::new` on a
//! `StepTest` with an input column, nothing typed).
//!
//! - **Excitations**: multi-step (3–6 levels), pulse, doublet, PRBS (seeded, switching every
//!   2–6 samples) and ramped steps (each change spread over 2–5 samples).
//! - **Changes between samples**: the true change comes at an instant inside
//!   (t_{k−1}, t_k]; the logged input shows it at t_k. Steps made by an operator (multi-step,
//!   pulse, doublet) each come at their own random instant; those of a clocked actuator (PRBS,
//!   ramped step) share one random phase against the logger.
//! - **Operating points away from zero**: u0 ∈ [20, 60] (%), y0 ∈ [100, 400] (°C), the time
//!   axis starting at 50–500 s.
//! - **Noise**: white or AR(1) (φ ∈ [0.5, 0.9]) of standard deviation 0.2–2 % of the largest
//!   effect |Kp·(u − u0)|, and in half of the records the output quantised to 0.2–1 σ.
//! - **Truths**: P1, P1D, P2D, P2DU (Kp of either sign, time constants 2–30 sampling periods
//!   … 10 % of the record).
//!
//! The truth is simulated exactly: its excitation has the true (between-sample) instants and
//! the output is sampled on the coarse grid; the record the fit sees has the coarse logged
//! input. Recovery: Kp, the time constants (the real poles as a set), Tw and ζ within 5 %;
//! the dead time is compared with the delay after the sample that shows the change (the true
//! Td minus the change's lead inside its sampling period, all the record can tell), within
//! 5 % of the true Td or 0.2 Ts. A case is recovered when every parameter is; the rate must
//! reach [`MIN_RECOVERED`] over the records that determine the truth to 5 % (a fit started
//! at the true values stays within it and fits at least as well as the one from the guess:
//! else the least-squares optimum is off, and noise, not the guess or the search, decides),
//! and those must be at least [`MIN_DETERMINED`] of all.
//!
//! The step instant: clean first-order steps (P1, one change between samples, white noise
//! 0.2–2 %) diagnosed from `P1` must come out `none` in at least [`MIN_CLEAN_NONE`] of the
//! cases.
//!
//! Run with `cargo test --test ident_excitation -- --nocapture` to see the rates.

use crate::draw::Draws;
use degrau_ident::diagnose::{Cause, DiagnoseOptions, diagnose};
use degrau_ident::experiment::Experiment;
use degrau_ident::fit::FitOptions;
use degrau_ident::model::excitation::{Excitation, Hold, InputStep};
use degrau_ident::model::{Model, Param, Structure, Values};
use degrau_ident::random::Lcg;
use degrau_ident::record::data::StepTest;

/// Fraction of the generated records whose every parameter must be recovered.
const MIN_RECOVERED: f64 = 0.95;
/// Fraction of the clean first-order steps between samples that must come out `none`.
const MIN_CLEAN_NONE: f64 = 0.95;
/// Fraction of the generated records that must determine the truth to 5 % (a fit started
/// at the truth stays within it), so the rate is over most of them.
const MIN_DETERMINED: f64 = 0.8;
/// Relative tolerance of a recovered parameter.
const TOLERANCE: f64 = 0.05;

/// The seeded generator of the project, with a few shapes on top.
struct Draw(Lcg);

impl Draw {
    fn new(seed: u64) -> Self {
        let mut g = Lcg(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x2545_F491_4F6C_DD1D);
        g.bits();
        Self(g)
    }

    fn count(&mut self, (a, b): (usize, usize)) -> usize {
        a + self.0.below(b - a + 1)
    }
}

impl Draws for Draw {
    fn lcg(&mut self) -> &mut Lcg {
        &mut self.0
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    MultiStep,
    Pulse,
    Doublet,
    Prbs,
    RampedStep,
}

const KINDS: [Kind; 5] = [
    Kind::MultiStep,
    Kind::Pulse,
    Kind::Doublet,
    Kind::Prbs,
    Kind::RampedStep,
];

const TRUTHS: [&str; 4] = ["P1", "P1D", "P2D", "P2DU"];

/// Records per kind of excitation.
const CASES_PER_KIND: usize = 12;

/// A generated record and what made it.
struct Case {
    label: String,
    code: &'static str,
    truth: Values,
    /// The lead of the first change inside its sampling period (s).
    first_lead: f64,
    ts: f64,
    test: StepTest,
}

/// The logged input on the grid (a level per sample) and the true steps behind it.
struct Input {
    logged: Vec<f64>,
    steps: Vec<InputStep>,
}

/// Level changes of the logged input: (sample index, new deviation from u0).
fn schedule(kind: Kind, n: usize, span: f64, g: &mut Draw) -> Vec<(usize, f64)> {
    let first = g.count((n / 10, n / 5));
    let level = |g: &mut Draw| g.sign() * g.range((0.4, 1.0)) * span;
    match kind {
        Kind::MultiStep => {
            let count = g.count((3, 6));
            let gap = (n - first) / count;
            (0..count)
                .map(|i| (first + i * gap + g.count((0, gap / 5)), level(g)))
                .collect()
        }
        Kind::Pulse => {
            let a = level(g);
            vec![
                (first, a),
                (first + g.count(((n - first) / 3, (n - first) / 2)), 0.0),
            ]
        }
        Kind::Doublet => {
            let a = level(g);
            let width = g.count(((n - first) / 4, (n - first) / 3));
            vec![(first, a), (first + width, -a), (first + 2 * width, 0.0)]
        }
        Kind::Prbs => {
            let a = g.range((0.4, 1.0)) * span;
            let mut at = first;
            let mut high = g.sign() > 0.0;
            let mut out = Vec::new();
            while at < n {
                out.push((at, if high { a } else { -a }));
                high = !high;
                at += g.count((2, 6)) * g.count((1, 4));
            }
            out
        }
        Kind::RampedStep => {
            let count = g.count((2, 3));
            let gap = (n - first) / count;
            let mut out = Vec::new();
            let mut from = 0.0;
            for i in 0..count {
                let to = level(g);
                let spread = g.count((2, 5));
                for j in 1..=spread {
                    out.push((
                        first + i * gap + j - 1,
                        from + (to - from) * j as f64 / spread as f64,
                    ));
                }
                from = to;
            }
            out
        }
    }
}

/// The logged input and its true steps: each level change shown at sample k came at
/// t_k − lead, the lead in [0, Ts) (one phase for a clocked actuator, one per change else).
fn input(
    kind: Kind,
    shared_phase: bool,
    times: &[f64],
    u0: f64,
    span: f64,
    g: &mut Draw,
) -> (Input, f64) {
    let n = times.len();
    let ts = times[1] - times[0];
    let clocked = shared_phase || matches!(kind, Kind::Prbs | Kind::RampedStep);
    let phase = g.0.unit() * ts;
    let mut logged = vec![u0; n];
    let mut steps = Vec::new();
    let mut level = 0.0;
    let mut first_lead = None;
    for (k, to) in schedule(kind, n, span, g) {
        if k >= n || to == level {
            continue;
        }
        let lead = if clocked { phase } else { g.0.unit() * ts };
        first_lead.get_or_insert(lead);
        steps.push(InputStep {
            t: times[k] - lead,
            du: to - level,
        });
        logged[k..].iter_mut().for_each(|u| *u = u0 + to);
        level = to;
    }
    (Input { logged, steps }, first_lead.unwrap_or(0.0))
}

/// Random true parameters for `code`, time constants measured in sampling periods.
fn truth(code: &str, ts: f64, record: f64, g: &mut Draw) -> Values {
    let s = Structure::parse(code).unwrap();
    let mut v = Values::default();
    v.set(Param::Kp, g.sign() * g.range((0.5, 5.0)));
    let slow = g.range((15.0 * ts, 0.08 * record));
    if s.underdamped {
        v.set(Param::Tw, slow / 2.0);
        v.set(Param::Zeta, g.range((0.2, 0.6)));
    } else {
        v.set(Param::Tp1, slow);
        if s.poles >= 2 {
            v.set(Param::Tp2, slow * g.range((0.2, 0.6)));
        }
    }
    if s.delay {
        v.set(Param::Td, g.range((0.2, 1.0)) * slow);
    }
    v
}

/// The effect's noise: white or AR(1) (white only when `white`), of standard deviation `sd`.
fn noise(n: usize, sd: f64, white: bool, g: &mut Draw) -> (Vec<f64>, String) {
    if g.0.unit() < 0.5 || white {
        ((0..n).map(|_| sd * g.gaussian()).collect(), "white".into())
    } else {
        let phi = g.range((0.5, 0.9));
        let innovation = sd * (1.0 - phi * phi).sqrt();
        let mut e = sd * g.gaussian();
        let out = (0..n)
            .map(|_| {
                e = phi * e + innovation * g.gaussian();
                e
            })
            .collect();
        (out, format!("AR(1) φ={phi:.2}"))
    }
}

/// A record of `kind` driving the truth `code`, with seed `seed`.
fn generate(kind: Kind, code: &'static str, seed: u64) -> Case {
    generate_with(kind, false, false, code, seed)
}

/// [`generate`], every change sharing one phase against the logger when `shared_phase`,
/// the noise white when `white`.
fn generate_with(
    kind: Kind,
    shared_phase: bool,
    white: bool,
    code: &'static str,
    seed: u64,
) -> Case {
    let mut g = Draw::new(seed);
    let n = g.count((400, 1500));
    let ts = [0.1, 0.5, 1.0, 2.0][g.0.below(4)];
    let start = g.range((50.0, 500.0));
    let times: Vec<f64> = (0..n).map(|k| start + ts * k as f64).collect();
    let record = ts * (n - 1) as f64;
    let (u0, y0) = (g.range((20.0, 60.0)), g.range((100.0, 400.0)));
    let span = g.range((5.0, 20.0));
    let mut values = truth(code, ts, record, &mut g);
    values.set(Param::Y0, y0);
    let (input, first_lead) = input(kind, shared_phase, &times, u0, span, &mut g);
    // The truth's excitation: the logged changes (for t0 and the plot), the true instants.
    let logged = Excitation::measured(&times, &input.logged, None, Hold::Zoh)
        .expect("the generated input changes");
    let exact = Excitation {
        steps: input.steps,
        lead_range: 0.0,
        start: None,
        ..logged
    };
    let s = Structure::parse(code).unwrap();
    let clean = Model::new(s, values).simulate(&exact, &times).unwrap();
    let effect = values.get(Param::Kp).abs() * exact.du_scale();
    let sd = g.range((0.002, 0.02)) * effect;
    let (e, colour) = noise(n, sd, white, &mut g);
    let quantum = (g.0.unit() < 0.5).then(|| g.range((0.2, 1.0)) * sd);
    let output = clean
        .iter()
        .zip(&e)
        .map(|(y, e)| {
            let y = y + e;
            quantum.map_or(y, |q| (y / q).round() * q)
        })
        .collect();
    let label = format!(
        "{kind:?} {code} seed {seed}: N={n} Ts={ts} u0={u0:.1} y0={y0:.1} noise {colour} {:.2} % q={quantum:?} truth {:?}",
        100.0 * sd / effect,
        values
    );
    Case {
        label,
        code,
        truth: values,
        first_lead,
        ts,
        test: StepTest {
            time: times,
            output,
            input: Some(input.logged),
            time_name: "t".into(),
            output_name: "y".into(),
            input_name: Some("u".into()),
            sampling_period: None,
            notes: Vec::new(),
        },
    }
}

fn close(estimate: f64, truth: f64) -> bool {
    (estimate - truth).abs() <= TOLERANCE * truth.abs()
}

/// The parameters of `fitted` that miss the truth (empty when all are recovered).
fn misses(case: &Case, fitted: &Model) -> Vec<String> {
    let s = Structure::parse(case.code).unwrap();
    let mut out = Vec::new();
    let mut check = |name: &str, est: f64, truth: f64, ok: bool| {
        if !ok {
            out.push(format!("{name} {est:.4} vs {truth:.4}"));
        }
    };
    let kp = (fitted.get(Param::Kp), case.truth.get(Param::Kp));
    check("Kp", kp.0, kp.1, close(kp.0, kp.1));
    if s.underdamped {
        for p in [Param::Tw, Param::Zeta] {
            let (e, t) = (fitted.get(p), case.truth.get(p));
            check(p.name(), e, t, close(e, t));
        }
    } else {
        let mut est = vec![fitted.get(Param::Tp1)];
        let mut tru = vec![case.truth.get(Param::Tp1)];
        if s.poles >= 2 {
            est.push(fitted.get(Param::Tp2));
            tru.push(case.truth.get(Param::Tp2));
        }
        est.sort_by(f64::total_cmp);
        tru.sort_by(f64::total_cmp);
        for (e, t) in est.into_iter().zip(tru) {
            check("Tp", e, t, close(e, t));
        }
    }
    if s.delay {
        let td = case.truth.get(Param::Td);
        let seen = td - case.first_lead;
        let e = fitted.get(Param::Td);
        check(
            "Td (after the logged change)",
            e,
            seen,
            (e - seen).abs() <= (TOLERANCE * td).max(0.2 * case.ts),
        );
    }
    out
}

/// Fits a case as the CLI does, from the automatic guess, or (`from_truth`) started at the
/// true values; the misses (or the error) and the fit's RMSE.
fn run(case: &Case, from_truth: bool) -> (Vec<String>, f64) {
    let experiment = Experiment::new(&case.test, None, None, None).unwrap();
    let s = Structure::parse(case.code).unwrap();
    let overrides: Vec<(Param, f64)> = if from_truth {
        s.params()
            .into_iter()
            .map(|p| (p, case.truth.get(p)))
            .collect()
    } else {
        Vec::new()
    };
    match experiment.fit(
        &case.test,
        case.code,
        false,
        &overrides,
        &FitOptions::default(),
        &mut (),
    ) {
        Ok((_, report)) => (misses(case, &report.model), report.rmse),
        Err(e) => (vec![format!("fit failed: {e}")], f64::INFINITY),
    }
}

#[test]
fn every_kind_of_excitation_recovers_the_truth() {
    let (mut total, mut recovered, mut all) = (0, 0, 0);
    let mut report = Vec::new();
    for (ki, kind) in KINDS.into_iter().enumerate() {
        let mut kind_ok = 0;
        for i in 0..CASES_PER_KIND {
            let code = TRUTHS[i % TRUTHS.len()];
            let case = generate(kind, code, 1000 * ki as u64 + i as u64);
            let (m, rmse) = run(&case, false);
            if m.is_empty() {
                kind_ok += 1;
            } else {
                report.push(format!("MISS {} → {}", case.label, m.join(", ")));
            }
            // The data determine the truth to 5 % when a fit started at it stays there and
            // fits at least as well as the one from the guess (else the least-squares
            // optimum itself is off: noise decides, not the guess or the search).
            let determined = m.is_empty() || {
                let (mt, rmse_t) = run(&case, true);
                let ok = mt.is_empty() && rmse_t <= rmse;
                report.push(format!(
                    "  from the truth: {} (RMSE {rmse_t:.5} vs {rmse:.5} from the guess){}",
                    if mt.is_empty() {
                        "recovered".into()
                    } else {
                        mt.join(", ")
                    },
                    if ok { "" } else { ": not counted" }
                ));
                ok
            };
            if determined {
                total += 1;
                recovered += usize::from(m.is_empty());
            }
            all += 1;
        }
        println!("{kind:?}: {kind_ok}/{CASES_PER_KIND} recovered within 5 %");
    }
    for line in &report {
        println!("{line}");
    }
    let rate = recovered as f64 / total as f64;
    println!(
        "recovered: {recovered}/{total} = {:.1} % of the records that determine the truth to 5 % ({all} generated)",
        100.0 * rate
    );
    assert!(
        total as f64 >= MIN_DETERMINED * all as f64,
        "only {total}/{all} records determine the truth: the generator is not testing"
    );
    assert!(rate >= MIN_RECOVERED, "recovered {recovered}/{total}");
}

/// Clean first-order steps diagnosed.
const CLEAN_CASES: usize = 60;
/// Clean first-order multi-step, pulse and doublet records diagnosed.
const CLEAN_MULTI_CASES: usize = 15;

/// A clean first-order step whose change came between two samples.
fn clean_step(seed: u64) -> Case {
    let mut g = Draw::new(0xC1EA_0000 + seed);
    let n = g.count((150, 800));
    let ts = g.range((0.05, 1.0));
    let start = g.range((0.0, 300.0));
    let times: Vec<f64> = (0..n).map(|k| start + ts * k as f64).collect();
    let record = ts * (n - 1) as f64;
    let tp1 = g.range((5.0 * ts, 0.15 * record));
    let mut values = Values::default();
    values.set(Param::Kp, g.sign() * g.range((0.5, 5.0)));
    values.set(Param::Tp1, tp1);
    values.set(Param::Y0, g.range((-50.0, 300.0)));
    let u0 = g.range((0.0, 60.0));
    let du = g.sign() * g.range((0.5, 20.0));
    let k = g.count((n / 20, n / 5));
    let lead = g.0.unit() * ts;
    let mut logged = vec![u0; n];
    logged[k..].iter_mut().for_each(|u| *u = u0 + du);
    let measured = Excitation::measured(&times, &logged, None, Hold::Zoh).unwrap();
    let exact = Excitation {
        steps: vec![InputStep {
            t: times[k] - lead,
            du,
        }],
        lead_range: 0.0,
        start: None,
        ..measured
    };
    let s = Structure::parse("P1").unwrap();
    let clean = Model::new(s, values).simulate(&exact, &times).unwrap();
    let sd = g.range((0.002, 0.02)) * (values.get(Param::Kp) * du).abs();
    let output = clean.iter().map(|y| y + sd * g.gaussian()).collect();
    Case {
        label: format!(
            "clean P1 seed {seed}: N={n} Ts={ts:.3} Tp1={tp1:.3} lead={:.2} Ts, sd {sd:.4}",
            lead / ts
        ),
        code: "P1",
        truth: values,
        first_lead: lead,
        ts,
        test: StepTest {
            time: times,
            output,
            input: Some(logged),
            time_name: "t".into(),
            output_name: "y".into(),
            input_name: Some("u".into()),
            sampling_period: None,
            notes: Vec::new(),
        },
    }
}

/// The first cause `diagnose` names on a case from `P1`, as the CLI runs it, and its chain.
fn first_cause(case: &Case) -> (Cause, Vec<&'static str>) {
    let experiment = Experiment::new(&case.test, None, None, None).unwrap();
    let data = experiment.fit_data(&case.test).unwrap();
    let start = experiment.structure("P1", false, &data).unwrap();
    let start_values = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let report = diagnose(&data, start, start_values, &DiagnoseOptions::default()).unwrap();
    let chain = report.steps.iter().map(|s| s.cause.id()).collect();
    (report.steps.first().map_or(Cause::None, |s| s.cause), chain)
}

/// Clean first-order multi-step, pulse and doublet records (white noise, each change at its
/// own instant inside its sampling period) diagnosed from `P1` come out `none`.
///
/// Known gap, measured on branch h-ident (`cargo test --test ident_excitation -- --ignored
/// --nocapture`): 13/15 `none`; the two misses are doublets named `offset` / `drift`: one
/// step-instant lead `Ta` cannot put every change at its own instant, and the misfit left at
/// each change is what a free Y0 or a drift takes up (with one shared phase: 14/15; with
/// AR(1) noise 9/15, BIC taking coloured noise for evidence). Needs a lead per change in
/// the model (models.rs, fit.rs).
#[test]
#[ignore = "known gap: one step-instant lead for every change (see the doc comment)"]
fn clean_first_order_multi_step_records_come_out_none() {
    let kinds = [Kind::MultiStep, Kind::Pulse, Kind::Doublet];
    let mut none = 0;
    for i in 0..CLEAN_MULTI_CASES {
        let case = generate_with(kinds[i % kinds.len()], false, true, "P1", 5000 + i as u64);
        let (first, chain) = first_cause(&case);
        if first == Cause::None {
            none += 1;
        } else {
            println!("NOT NONE {} → {chain:?}", case.label);
        }
    }
    println!("clean multi-step records: {none}/{CLEAN_MULTI_CASES} none");
    assert!(
        none as f64 >= MIN_CLEAN_NONE * CLEAN_MULTI_CASES as f64,
        "{none}/{CLEAN_MULTI_CASES} none"
    );
}

#[test]
fn clean_first_order_steps_between_samples_come_out_none() {
    let mut none = 0;
    for seed in 0..CLEAN_CASES as u64 {
        let case = clean_step(seed);
        let (first, chain) = first_cause(&case);
        if first == Cause::None {
            none += 1;
        } else {
            println!("NOT NONE {} → {chain:?}", case.label);
        }
    }
    let rate = none as f64 / CLEAN_CASES as f64;
    println!("clean steps between samples: {none}/{CLEAN_CASES} none");
    assert!(rate >= MIN_CLEAN_NONE, "{none}/{CLEAN_CASES} none");
}

/// The generator keeps its promises: the true changes lie inside their sampling period
/// before the sample that shows them, and the operating point is away from zero.
#[test]
fn the_generator_puts_changes_between_samples() {
    for (ki, kind) in KINDS.into_iter().enumerate() {
        let case = generate(kind, "P1", 77 + ki as u64);
        let u = case.test.input.as_ref().unwrap();
        assert!(
            u[0] >= 20.0 && case.test.output[0].abs() >= 50.0,
            "{}",
            case.label
        );
        assert!(
            case.first_lead >= 0.0 && case.first_lead < case.ts,
            "{}",
            case.label
        );
        let m = Excitation::measured(&case.test.time, u, None, Hold::Zoh).unwrap();
        assert!(m.lead_range > 0.0 && (m.lead_range - case.ts).abs() < 1e-9);
    }
}
