//! Acceptance test of `closed_loop` (tracker issue 21, item 9): a test run under a
//! controller is named, and no open-loop test is.
//!
//! Closed-loop records: a P1D or P2D plant (Kp ±0.5–5, τ1 5–50 s, τ2 0.2–0.6 τ1, a dead
//! time 0.05–0.3 τ1) under a digital P or PI controller tuned by the SIMC rules (λ 0.5–2
//! times the effective dead time, P gains 0.5–1 of the PI's), excited by a setpoint step
//! (0.15–0.35 of the record in) or by a dither added to the controller's output (a random
//! binary signal switching every 3–10 samples on average, its effect 2–10 times the noise's
//! standard deviation: the small test signal a plant in production allows); operating
//! points far from zero (y0 20–100, u0 10–60); measurement noise 0.2–2 % of the loop's span
//! (the setpoint change), white or AR(1) (ρ 0.3–0.7), seen by the controller; the plant integrated exactly on a grid 20 times finer than the
//! sampling period (h 0.02–0.08 τ1), the input held between samples. The logged input is
//! the controller's output (with the dither), the logged output the measured one. Each is
//! diagnosed as a user would (`diagnose` from P1D): `closed_loop` must be named in at least
//! [`MIN_NAMED`] of them.
//!
//! Open-loop records: the same plants, noise and operating points driven by what a step
//! test applies: a step, a staircase, a doublet, a PRBS of one-sample clock, a PRBS of
//! 3–10 samples, an amplitude-modulated PRBS, and a step logged with the actuator's own
//! noise (the input column moves at every sample). Each change comes between two samples:
//! the plant answers it for part of a period before the logger shows it, so the output
//! moves at the sample where the input's change is logged, as it does under a controller.
//! And every record in
//! `tests/data/records/` as the CLI reads it. `closed_loop` must never be named there.
//!
//! Run with `cargo test --test diagnose_closed_loop -- --nocapture` to see the figures.

use crate::draw;
use crate::records;
use draw::{range, signed};

use degrau_ident::diagnose::test_causes::closed_loop::closed_loop;
use degrau_ident::diagnose::test_causes::{FittedRecord, TestCauseKind, TestEvidence};
use degrau_ident::diagnose::{DiagnoseOptions, diagnose};
use degrau_ident::experiment::Experiment;
use degrau_ident::fit::guess::auto_guess;
use degrau_ident::fit::{FitData, FitReport, fit};
use degrau_ident::model::Structure;
use degrau_ident::model::excitation::{Excitation, Hold};
use degrau_ident::random::Lcg;
use degrau_ident::record::data::{LoadOptions, load_file};

/// Closed-loop cases (every combination of plant, controller, excitation and noise three
/// times).
const CLOSED_CASES: usize = 24;
/// Open-loop generated cases.
const OPEN_CASES: usize = 70;
const MIN_NAMED: f64 = 0.90;
/// Fine integration steps per sampling period.
const FINE: usize = 20;

/// A plant Kp·e^(−θs)/((τ1 s + 1)(τ2 s + 1)) (no τ2: first order), integrated exactly for a
/// held input on a fine grid, the dead time a delay line of whole fine steps.
struct Plant {
    kp: f64,
    tau1: f64,
    tau2: Option<f64>,
    td: f64,
    x1: f64,
    x2: f64,
    delay: std::collections::VecDeque<f64>,
}

impl Plant {
    /// A plant of slowest lag `tau1`, sampled every `h`.
    fn new(rng: &mut Lcg, second_order: bool, tau1: f64, h: f64) -> Self {
        let tau2 = second_order.then(|| range(rng, (0.2, 0.6)) * tau1);
        let td = range(rng, (0.05, 0.3)) * tau1;
        let lag = ((td / (h / FINE as f64)).round() as usize).max(1);
        Plant {
            kp: signed(rng, (0.5, 5.0)),
            tau1,
            tau2,
            td,
            x1: 0.0,
            x2: 0.0,
            delay: std::iter::repeat_n(0.0, lag).collect(),
        }
    }

    /// The output's deviation after one sampling period `h` of the input deviation `du`.
    fn advance(&mut self, du: f64, h: f64) -> f64 {
        self.advance_switching(du, du, 0.0, h)
    }

    /// The output's deviation after one sampling period `h` in which the input deviation
    /// went from `before` to `after` with a share `late` of the period left.
    fn advance_switching(&mut self, before: f64, after: f64, late: f64, h: f64) -> f64 {
        let dt = h / FINE as f64;
        let a1 = 1.0 - (-dt / self.tau1).exp();
        let switch = ((1.0 - late) * FINE as f64).round() as usize;
        for i in 0..FINE {
            let du = if i >= switch { after } else { before };
            self.delay.push_back(du);
            let w = self.delay.pop_front().unwrap_or(du);
            self.x1 += (self.kp * w - self.x1) * a1;
            if let Some(t2) = self.tau2 {
                self.x2 += (self.x1 - self.x2) * (1.0 - (-dt / t2).exp());
            }
        }
        self.output()
    }

    fn output(&self) -> f64 {
        if self.tau2.is_some() {
            self.x2
        } else {
            self.x1
        }
    }
}

/// Measurement noise of standard deviation `sd`, AR(1) with `rho`.
struct Noise {
    sd: f64,
    rho: f64,
    x: f64,
}

impl Noise {
    /// Noise of standard deviation `sd`, white or (`coloured`) AR(1) with ρ drawn in
    /// 0.3–0.7.
    fn new(rng: &mut Lcg, sd: f64, coloured: bool) -> Self {
        let rho = if coloured {
            range(rng, (0.3, 0.7))
        } else {
            0.0
        };
        Noise { sd, rho, x: 0.0 }
    }

    fn next(&mut self, rng: &mut Lcg) -> f64 {
        let scale = self.sd * (1.0 - self.rho * self.rho).sqrt();
        self.x = self.rho * self.x + scale * rng.gaussian();
        self.x
    }
}

struct Record {
    data: FitData,
    note: String,
}

fn record(times: Vec<f64>, u: &[f64], y: Vec<f64>, note: String) -> Option<Record> {
    let input = Excitation::measured(&times, u, None, Hold::Zoh)?;
    Some(Record {
        data: FitData { times, y, input },
        note,
    })
}

/// What both generators draw first: the plant's first lag (s), the sampling period (2–8 %
/// of it), the plant, the record's length and its operating point far from zero.
struct Setting {
    tau1: f64,
    h: f64,
    plant: Plant,
    n: usize,
    y0: f64,
    u0: f64,
}

impl Setting {
    fn draw(rng: &mut Lcg, second_order: bool) -> Self {
        let tau1 = range(rng, (5.0, 50.0));
        let h = range(rng, (0.02, 0.08)) * tau1;
        let plant = Plant::new(rng, second_order, tau1, h);
        let n = 600 + rng.below(1401);
        let (y0, u0) = (range(rng, (20.0, 100.0)), range(rng, (10.0, 60.0)));
        Setting {
            tau1,
            h,
            plant,
            n,
            y0,
            u0,
        }
    }
}

/// The generator of the `index`-th case of a kind whose seeds start at `base`.
fn case_rng(base: u64, index: usize) -> Lcg {
    let mut rng = Lcg((base + index as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    rng.bits();
    rng
}

/// The `index`-th closed-loop case.
fn closed(index: usize) -> Option<Record> {
    let mut rng = case_rng(0xC1_05ED, index);
    let second_order = index % 2 == 1;
    let pi = (index / 2) % 2 == 1;
    let dither = (index / 4) % 2 == 1;
    let coloured = (index / 8) % 2 == 1;
    let Setting {
        tau1,
        h,
        mut plant,
        n,
        y0,
        u0,
    } = Setting::draw(&mut rng, second_order);
    // SIMC: the second lag counted half in the time constant, half in the dead time.
    let t2 = plant.tau2.unwrap_or(0.0);
    let theta = plant.td + t2 / 2.0 + h / 2.0;
    let tau = tau1 + t2 / 2.0;
    let lambda = range(&mut rng, (0.5, 2.0)) * theta.max(0.1 * tau);
    let mut kc = tau / (plant.kp * (lambda + theta));
    let ti = (tau.min(4.0 * (lambda + theta))).max(h);
    if !pi {
        kc *= range(&mut rng, (0.5, 1.0));
    }
    let (step_at, dr) = (
        range(&mut rng, (0.15, 0.35)) * n as f64 * h,
        signed(&mut rng, (0.5, 10.0)) * plant.kp.abs(),
    );
    // The noise against the loop's span (the setpoint change a record of this loop would
    // make); a dither a few times the noise in its effect, the small test signal a plant
    // in production allows, clocked at 3–10 samples.
    let sd = range(&mut rng, (0.002, 0.02)) * dr.abs();
    let amplitude = range(&mut rng, (2.0, 10.0)) * sd / plant.kp.abs();
    let hold = 3.0 + rng.below(8) as f64;
    let mut noise = Noise::new(&mut rng, sd, coloured);
    let (mut times, mut u, mut y) = (Vec::new(), Vec::new(), Vec::new());
    let (mut integral, mut d, mut deviation) = (0.0, amplitude, 0.0);
    for k in 0..n {
        let t = k as f64 * h;
        let measured = y0 + deviation + noise.next(&mut rng);
        let setpoint = y0 + if !dither && t >= step_at { dr } else { 0.0 };
        let e = setpoint - measured;
        if pi {
            integral += kc * h / ti * e;
        }
        if dither && rng.unit() < 1.0 / hold {
            d = -d;
        }
        let input = u0 + kc * e + integral + if dither { d } else { 0.0 };
        times.push(t);
        u.push(input);
        y.push(measured);
        deviation = plant.advance(input - u0, h);
    }
    let note = format!(
        "{} {} {} {} Kp={:.3} tau1={tau1:.2} td={:.2} h={h:.3} N={n} Kc={kc:.3} Ti={ti:.2} \
         sd={:.4} rho={:.2}",
        if second_order { "P2D" } else { "P1D" },
        if pi { "PI" } else { "P" },
        if dither { "dither" } else { "setpoint" },
        if coloured { "coloured" } else { "white" },
        plant.kp,
        plant.td,
        noise.sd,
        noise.rho,
    );
    record(times, &u, y, note)
}

/// What an open-loop test applies.
#[derive(Debug, Clone, Copy)]
enum Drive {
    Step,
    Staircase,
    Doublet,
    /// A random binary signal: a new level drawn (0 or Δu, even odds) every `clock`
    /// samples.
    Prbs {
        clock: usize,
    },
    /// The same with a new level drawn uniformly in [0, Δu].
    Aprbs {
        clock: usize,
    },
    /// A step logged with the actuator's own noise, `share` of the step.
    NoisyStep {
        share: f64,
    },
}

/// The `index`-th open-loop case.
fn open(index: usize) -> Option<Record> {
    let mut rng = case_rng(0x0_9E11, index);
    let drive = match index % 7 {
        0 => Drive::Step,
        1 => Drive::Staircase,
        2 => Drive::Doublet,
        3 => Drive::Prbs { clock: 1 },
        4 => Drive::Prbs {
            clock: 3 + rng.below(8),
        },
        5 => Drive::Aprbs {
            clock: 3 + rng.below(8),
        },
        _ => Drive::NoisyStep {
            share: range(&mut rng, (0.005, 0.03)),
        },
    };
    let second_order = (index / 7) % 2 == 1;
    let coloured = (index / 14) % 2 == 1;
    let mut setting = Setting::draw(&mut rng, second_order);
    let du = signed(&mut rng, (0.5, 10.0));
    let sd = range(&mut rng, (0.002, 0.02)) * (setting.plant.kp * du).abs();
    let mut noise = Noise::new(&mut rng, sd, coloured);
    let at = |share: f64| (share * setting.n as f64) as usize;
    let (mut level, mut times, mut u, mut y) = (0.0, Vec::new(), Vec::new(), Vec::new());
    let mut deviation = 0.0;
    for k in 0..setting.n {
        let before = level;
        level = match drive {
            Drive::Step | Drive::NoisyStep { .. } => du * f64::from(u8::from(k >= at(0.2))),
            Drive::Staircase => {
                du * [0.2, 0.4, 0.6, 0.8].iter().filter(|&&s| k >= at(s)).count() as f64
            }
            Drive::Doublet => {
                if (at(0.2)..at(0.5)).contains(&k) {
                    du
                } else if (at(0.5)..at(0.8)).contains(&k) {
                    -du
                } else {
                    0.0
                }
            }
            Drive::Prbs { clock } if k % clock == 0 => du * f64::from(u8::from(rng.unit() < 0.5)),
            Drive::Aprbs { clock } if k % clock == 0 => du * rng.unit(),
            _ => level,
        };
        let logged = match drive {
            Drive::NoisyStep { share } => level + share * du.abs() * rng.gaussian(),
            _ => level,
        };
        // Each change comes between two samples: the plant answers it for a part of the
        // period before the logger shows it.
        if k > 0 {
            let late = if level == before { 0.0 } else { rng.unit() };
            deviation = setting
                .plant
                .advance_switching(before, level, late, setting.h);
        }
        times.push(k as f64 * setting.h);
        u.push(setting.u0 + logged);
        y.push(setting.y0 + deviation + noise.next(&mut rng));
    }
    let note = format!(
        "{drive:?} {} {} Kp={:.3} tau1={:.2} h={:.3} N={} sd={:.4} rho={:.2}",
        if second_order { "P2D" } else { "P1D" },
        if coloured { "coloured" } else { "white" },
        setting.plant.kp,
        setting.tau1,
        setting.h,
        setting.n,
        noise.sd,
        noise.rho
    );
    record(times, &u, y, note)
}

fn start() -> Structure {
    Structure {
        lead: true,
        ..Structure::parse("P1D").unwrap()
    }
}

/// The start structure fitted as `diagnose` fits it first.
fn start_fit(data: &FitData) -> FitReport {
    let s = start();
    let options = DiagnoseOptions::default().fit;
    fit(data, s, auto_guess(data, s, None), &options, &mut ()).unwrap()
}

#[test]
fn closed_loop_records_are_named() {
    let mut named = 0;
    let mut made = 0;
    for index in 0..CLOSED_CASES {
        let Some(case) = closed(index) else {
            eprintln!("closed {index}: no significant input change");
            continue;
        };
        made += 1;
        let report = diagnose(&case.data, start(), None, &DiagnoseOptions::default());
        let report = report.unwrap_or_else(|e| panic!("closed {index} {}: {e}", case.note));
        let found = report
            .test_causes
            .iter()
            .find(|c| c.kind == TestCauseKind::ClosedLoop);
        named += usize::from(found.is_some());
        let ids: Vec<&str> = report.test_causes.iter().map(|c| c.kind.id()).collect();
        let statistic = found.map(|c| match c.evidence {
            TestEvidence::ClosedLoop {
                moves,
                f,
                explained,
                ..
            } => format!("moves {moves:.2} F {f:.1} explained {explained:.3}"),
            _ => String::new(),
        });
        eprintln!(
            "closed {index}: {} {} → {} Kp {:.4} {:?} {ids:?} {statistic:?}",
            case.note,
            if found.is_some() { "NAMED" } else { "missed" },
            report.final_fit.model.structure.code(),
            report.static_gain.0,
            report.static_gain.1,
        );
        let (first, last) = (
            case.data.times[0],
            case.data.times[case.data.times.len() - 1],
        );
        for c in &report.test_causes {
            if let Some((a, b)) = c.interval {
                assert!(a >= first && b <= last, "closed {index}: {c:?}");
            }
        }
    }
    let share = named as f64 / made as f64;
    eprintln!("closed_loop named in {named} of {made} closed-loop records");
    assert!(made >= 20, "only {made} records made");
    assert!(share >= MIN_NAMED, "named in {named} of {made}");
}

#[test]
fn open_loop_records_are_never_named() {
    let mut made = 0;
    let mut named = Vec::new();
    for index in 0..OPEN_CASES {
        let Some(case) = open(index) else {
            continue;
        };
        made += 1;
        let report = start_fit(&case.data);
        let record = FittedRecord::new(&case.data, &report).unwrap();
        if let Some(c) = closed_loop(&record) {
            eprintln!("open {index}: {} NAMED {:?}", case.note, c.evidence);
            named.push(index);
        }
    }
    eprintln!(
        "closed_loop named in {} of {made} open-loop records",
        named.len()
    );
    assert!(made >= OPEN_CASES - 5, "only {made} records made");
    assert!(named.is_empty(), "named on open-loop cases {named:?}");
}

#[test]
fn no_real_record_in_the_repo_is_named() {
    for (name, time, output, input, ts, skip, initial) in records::RECORDS {
        let options = LoadOptions::from_text(time, output, input, ts, skip);
        let test =
            load_file(records::path(name), &options).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let experiment =
            Experiment::new(&test, None, None, initial).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let data = experiment
            .fit_data(&test)
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let report = start_fit(&data);
        let found = closed_loop(&FittedRecord::new(&data, &report).unwrap());
        eprintln!("{name}: {} samples, {found:?}", data.y.len());
        assert_eq!(found, None, "{name}");
    }
}
