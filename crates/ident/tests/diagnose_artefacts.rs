//! Acceptance test of the test's causes (tracker issue 11): simulated step tests of a
//! *correct* start structure (cycling P1, P1D, P2, P2U, P2DU) with one artefact of the test
//! added, as a user meets it. For each artefact, in at least [`CASES`] cases: no structural
//! cause named in ≥ 95 %, the test's cause named in ≥ 90 %, and Kp and the lags (real poles
//! as a set, Tw) of the final model within 10 % of the truth in ≥ 90 %. A small step's
//! record may hold too little to place its lags within 10 %, for any estimator: where the
//! Cramér–Rao bound at the truth says so ([`resolvable`]), the case counts when Kp is within
//! 10 % and every true lag lies inside the 95 % interval Degrau reports (honest, not absent).
//!
//! Messy like real records: the step comes between two samples (the logged input shows it
//! at the next sample, the start structures estimate the lead), the operating point is far
//! from zero (y0 ∈ [−50, 100], u0 ∈ [0, 60]), the noise is 0.2–2 % of the step's effect,
//! Gaussian or uniform, white or coloured (AR(1), ρ 0.3–0.7), and a third of the records are
//! quantised (a quantum of half the noise's standard deviation). The artefacts:
//! - `disturbance`: a load step (±10–30 % of the effect) or ramp (the same over its window)
//!   after the response has settled;
//! - `saturation`: the output clipped at 80–92 % of its largest excursion;
//! - `outliers`: 2–6 % of the samples replaced by spikes or dropouts of 6–15 σ;
//! - `coloured_noise`: AR(1) noise with ρ 0.8–0.95;
//! - `not_at_rest`: the record starts while the process still answers an earlier change
//!   (20–50 % of the effect, made 0.3–1 slowest time constant before the record);
//! - `quantisation`: the output rounded to a coarse quantum, 2–10 % of the step's effect
//!   (above the noise: a DHT11's 1 °C on a 10–50 °C rise), in place of the fine one;
//! - `sampling`: half the records too slow (h 0.15–0.4 of the time constant the notes'
//!   rules read, Tw for a pair: 15–90 samples for a first order), half too fast (h
//!   0.001–0.004 of it, up to tens of thousands of samples) with the noise 0.5–2 % of the
//!   effect, so the model moves less than the noise between two samples (the notes' case
//!   against a fast rate: without noise a fast rate costs nothing, and nothing is named);
//! - `small_step`: the step's effect three to six times the noise's standard deviation,
//!   just under the notes' six (the 0.2–2 % noise cannot make a small step: this
//!   is the least departure from it that does), over 1500–4000 samples (a 10–50 Hz logger
//!   over a few minutes);
//! - `imperfect_step`: the actuator ramps over 0.2–1 time constant, or overshoots by
//!   20–50 % and settles with 0.1–0.3 of it, or wobbles ± 15–30 % with a period of 0.5–1.5
//!   of it (at least 8 samples, what the logger can show) dying out over four periods; the
//!   plant answers the actuator's motion, the logger records it at the samples, and the
//!   fit is given the logged input;
//! - `nonlinearity`: a second change after the first has settled, either back down (a gain
//!   that depends on the direction) or further the same way by 0.5–1.5 times the first (one
//!   that depends on the operating point), whose own gain differs from the first's by
//!   20–50 %; the dynamics are the same. The truth the final model is held to is the first
//!   change's: the diagnosis seeks the model on the first change's window once the gains
//!   are seen to differ, and shows the others in the per-step table.
//!
//! Run with `cargo test --test diagnose_artefacts -- --nocapture` to see the figures.

use crate::draw;
use draw::{range, signed};

use std::sync::OnceLock;

use degrau_ident::challenge::flaws::{noise, outliers, quantise};
use degrau_ident::challenge::test_flaw::Actuator;
use degrau_ident::diagnose::test_causes::{TestCauseKind, TestEvidence};
use degrau_ident::diagnose::{DiagnoseOptions, DiagnoseReport, diagnose};
use degrau_ident::fit::{FitData, FitReport};
use degrau_ident::model::excitation::{Excitation, Hold, InputStep};
use degrau_ident::model::{Model, Param, Structure, Values};
use degrau_ident::random::Lcg;

/// Cases per artefact.
const CASES: usize = 20;
const MIN_NO_STRUCTURE: f64 = 0.95;
const MIN_NAMED: f64 = 0.90;
const MIN_RECOVERED: f64 = 0.90;
const TOLERANCE: f64 = 0.10;

const STARTS: [&str; 5] = ["P1", "P1D", "P2", "P2U", "P2DU"];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Artefact {
    Disturbance,
    Saturation,
    Outliers,
    ColouredNoise,
    NotAtRest,
    Quantisation,
    Sampling,
    SmallStep,
    ImperfectStep,
    Nonlinearity,
}

/// How many artefacts there are (the cache's size).
const ARTEFACTS: usize = 10;

impl Artefact {
    fn kind(self) -> TestCauseKind {
        match self {
            Artefact::Disturbance => TestCauseKind::Disturbance,
            Artefact::Saturation => TestCauseKind::Saturation,
            Artefact::Outliers => TestCauseKind::Outliers,
            Artefact::ColouredNoise => TestCauseKind::ColouredNoise,
            Artefact::NotAtRest => TestCauseKind::NotAtRest,
            Artefact::Quantisation => TestCauseKind::Quantisation,
            Artefact::Sampling => TestCauseKind::Sampling,
            Artefact::SmallStep => TestCauseKind::SmallStep,
            Artefact::ImperfectStep => TestCauseKind::ImperfectStep,
            Artefact::Nonlinearity => TestCauseKind::Nonlinearity,
        }
    }
}

struct Case {
    seed: u64,
    /// For `sampling`: whether the record is sampled too slowly (the side the cause must
    /// name).
    too_slow: Option<bool>,
    truth: Model,
    data: FitData,
    start: Structure,
    /// The noise's standard deviation (output units).
    sd: f64,
    note: String,
}

/// The input an actuator gave the process on a command `du` at `t0` (an ideal step's
/// change record of its fine motion: the plant sees it, no logger does).
fn driven_by(actuator: Actuator, t0: f64, du: f64) -> Excitation {
    let mut input = Excitation::step(t0, du);
    input.steps = actuator.changes(t0, du);
    input
}

/// The `index`-th case of `artefact`.
fn generate(artefact: Artefact, index: usize) -> Case {
    let seed = 0xA87E_0000 + 1000 * artefact as u64 + index as u64;
    let mut rng = Lcg(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    rng.bits();
    let code = STARTS[index % STARTS.len()];
    let mut s = Structure::parse(code).unwrap();
    // Y0 estimated in half the cases, held at the level before the step (the CLI's and the
    // app's default) in the other half.
    s.free_offset = (index / STARTS.len()).is_multiple_of(2);
    s.lead = true;
    let mut v = Values::default();
    let kp = signed(&mut rng, (0.5, 5.0));
    let du = signed(&mut rng, (0.5, 10.0));
    let u0 = range(&mut rng, (0.0, 60.0));
    let y0 = range(&mut rng, (-50.0, 100.0));
    let tp1 = range(&mut rng, (1.0, 20.0));
    v.set(Param::Kp, kp);
    v.set(Param::Y0, y0);
    let slowest = if s.underdamped {
        let tw = range(&mut rng, (1.0, 8.0));
        let zeta = range(&mut rng, (0.2, 0.6));
        v.set(Param::Tw, tw);
        v.set(Param::Zeta, zeta);
        tw / zeta
    } else {
        v.set(Param::Tp1, tp1);
        if s.poles == 2 {
            v.set(Param::Tp2, range(&mut rng, (0.2, 0.6)) * tp1);
        }
        tp1
    };
    // The time constant the notes' sampling rules read: 1/ωn for a pair, else the slowest lag.
    let tau = if s.underdamped { v.get(Param::Tw) } else { tp1 };
    if s.delay {
        v.set(Param::Td, range(&mut rng, (0.2, 0.8)) * slowest.min(tp1));
    }
    let td = if s.delay { v.get(Param::Td) } else { 0.0 };
    let multiple = match artefact {
        Artefact::Disturbance => range(&mut rng, (11.0, 13.0)),
        _ => range(&mut rng, (6.0, 10.0)),
    };
    let after = multiple * slowest + td;
    let fraction = range(&mut rng, (0.12, 0.25));
    let mut length = after / (1.0 - fraction);
    let t0 = fraction * length;
    let mut n = 150 + rng.below(651);
    let mut truth_s = s;
    truth_s.lead = false;
    let clean_model = Model::new(truth_s, v);
    let effect = (kp * du).abs();
    let mut sd = range(&mut rng, (0.002, 0.02)) * effect;
    let mut note = String::new();
    let rho = if artefact == Artefact::ColouredNoise {
        range(&mut rng, (0.8, 0.95))
    } else if rng.unit() < 0.5 {
        range(&mut rng, (0.3, 0.7))
    } else {
        0.0
    };
    // The artefacts that change the record's plan: its sampling, its noise, its input.
    let too_slow = (artefact == Artefact::Sampling).then_some(index.is_multiple_of(2));
    let mut logged_at: Box<dyn Fn(f64) -> f64> = Box::new(move |t| if t < t0 { 0.0 } else { du });
    let mut driven = Excitation::step(t0, du);
    let mut second: Option<(f64, f64, f64)> = None;
    match artefact {
        Artefact::Sampling if too_slow == Some(true) => {
            let h = range(&mut rng, (0.15, 0.4)) * tau;
            n = (length / h) as usize + 1;
            note = format!("too slow h/tau {:.3}", h / tau);
        }
        Artefact::Sampling => {
            let h = range(&mut rng, (0.001, 0.004)) * tau;
            n = (length / h) as usize + 1;
            sd = range(&mut rng, (0.005, 0.02)) * effect;
            note = format!("too fast h/tau {:.4}", h / tau);
        }
        Artefact::SmallStep => {
            sd = effect / range(&mut rng, (3.0, 6.0));
            n = 1500 + rng.below(2501);
            note = format!("effect/sd {:.2}", effect / sd);
        }
        Artefact::ImperfectStep => {
            let actuator = match (index / STARTS.len()) % 3 {
                0 => Actuator::Ramp {
                    duration: range(&mut rng, (0.2, 1.0)) * tau,
                },
                1 => Actuator::Overshoot {
                    fraction: range(&mut rng, (0.2, 0.5)),
                    decay: range(&mut rng, (0.1, 0.3)) * tau,
                },
                _ => {
                    let h = length / (n - 1) as f64;
                    Actuator::Wobble {
                        amplitude: range(&mut rng, (0.15, 0.3)),
                        period: (range(&mut rng, (0.5, 1.5)) * tau).max(8.0 * h),
                    }
                }
            };
            driven = driven_by(actuator, t0, du);
            logged_at = Box::new(move |t| du * actuator.at(t - t0));
            note = format!("{actuator:?}");
        }
        Artefact::Nonlinearity => {
            // Up then down (a gain that depends on the direction), or two steps the same
            // way (one that depends on the operating point); the second change's own gain
            // differs from the first's by 20–50 %.
            let du2 = if index.is_multiple_of(2) {
                -du
            } else {
                du * range(&mut rng, (0.5, 1.5))
            };
            let k2 = kp * (1.0 + signed(&mut rng, (0.2, 0.5)));
            let t1 = t0 + after;
            length = t1 + after;
            n *= 2;
            second = Some((t1, du2, k2));
            logged_at = Box::new(move |t| {
                if t < t0 {
                    0.0
                } else if t < t1 {
                    du
                } else {
                    du + du2
                }
            });
            note = format!("du2={du2:.3} k2={k2:.3}");
        }
        _ => {}
    }
    let times: Vec<f64> = (0..n).map(|k| length * k as f64 / (n - 1) as f64).collect();
    let first = Model::new(truth_s, v);
    let mut y = first.simulate(&driven, &times).unwrap();
    if let Some((t1, du2, k2)) = second {
        let mut w = v;
        w.set(Param::Kp, k2);
        w.set(Param::Y0, 0.0);
        let answer = Model::new(truth_s, w)
            .simulate(&Excitation::step(t1, du2), &times)
            .unwrap();
        y.iter_mut().zip(&answer).for_each(|(yi, a)| *yi += a);
    }
    match artefact {
        Artefact::Disturbance => {
            let at = t0 + td + range(&mut rng, (7.0, 8.0)) * slowest;
            let size = signed(&mut rng, (0.1, 0.3)) * effect;
            let ramp = rng.unit() < 0.5;
            let end = times[n - 1];
            for (yi, &t) in y.iter_mut().zip(&times) {
                if t >= at {
                    *yi += if ramp {
                        size * (t - at) / (end - at)
                    } else {
                        size
                    };
                }
            }
            note = format!(
                "{} at {at:.2} size {size:.3}",
                if ramp { "ramp" } else { "step" }
            );
        }
        Artefact::NotAtRest => {
            let earlier = signed(&mut rng, (0.2, 0.5)) * du;
            let before = range(&mut rng, (0.3, 1.0)) * slowest;
            let previous = Model::new(truth_s, {
                let mut w = v;
                w.set(Param::Y0, 0.0);
                w.set(Param::Td, 0.0);
                w
            })
            .simulate(&Excitation::step(-before, earlier), &times)
            .unwrap();
            // The earlier change's answer, still moving: it tends to kp·earlier, reached
            // from below; subtracting its final value leaves the decaying part.
            for (yi, p) in y.iter_mut().zip(&previous) {
                *yi += p - kp * earlier;
            }
            note = format!("earlier change {earlier:.3} {before:.2} s before");
        }
        _ => {}
    }
    let e = noise(&mut rng, n, sd, rho);
    for (yi, ei) in y.iter_mut().zip(&e) {
        *yi += ei;
    }
    match artefact {
        Artefact::Outliers => {
            let count = outliers(&mut rng, &mut y, (0.02, 0.06), sd);
            note = format!("{count} wild samples");
        }
        Artefact::Saturation => {
            let dir = (kp * du).signum();
            let peak = y
                .iter()
                .map(|v| dir * (v - y0))
                .fold(f64::NEG_INFINITY, f64::max);
            let limit = y0 + dir * range(&mut rng, (0.8, 0.92)) * peak;
            for yi in &mut y {
                if dir * (*yi - limit) > 0.0 {
                    *yi = limit;
                }
            }
            note = format!("clipped at {limit:.3}");
        }
        _ => {}
    }
    let quantum = if artefact == Artefact::Quantisation {
        // A coarse converter or sensor: 2–10 % of the step's effect, above the noise.
        Some(range(&mut rng, (0.02, 0.10)) * effect)
    } else {
        (rng.unit() < 1.0 / 3.0).then_some(0.5 * sd)
    };
    if let Some(q) = quantum {
        quantise(&mut y, q);
        note += &format!(" quantised {q:.4}");
    }
    let logged: Vec<f64> = times.iter().map(|&t| u0 + logged_at(t)).collect();
    let input = Excitation::measured(&times, &logged, None, Hold::Zoh).unwrap();
    note = format!(
        "{code} Kp={kp:.3} du={du:.3} slowest={slowest:.3} td={td:.3} N={n} sd={sd:.4} rho={rho:.2} {note}"
    );
    Case {
        seed,
        too_slow,
        truth: clean_model,
        data: FitData { times, y, input },
        start: s,
        sd,
        note,
    }
}

/// The true lags: the real poles as a sorted set, and Tw.
fn lags(m: &Model) -> Vec<f64> {
    lag_params(m).into_iter().map(|p| m.get(p)).collect()
}

/// The parameters of [`lags`], in its order.
fn lag_params(m: &Model) -> Vec<Param> {
    let ps = m.structure.params();
    let mut real: Vec<Param> = [Param::Tp1, Param::Tp2, Param::Tp3]
        .into_iter()
        .filter(|p| ps.contains(p))
        .collect();
    real.sort_by(|a, b| m.get(*a).total_cmp(&m.get(*b)));
    if ps.contains(&Param::Tw) {
        real.push(Param::Tw);
    }
    real
}

/// The 95 % intervals of a fit's lags, in [`lags`]' order.
fn lag_intervals(r: &FitReport) -> Vec<Option<(f64, f64)>> {
    lag_params(&r.model)
        .into_iter()
        .map(|p| r.interval(p))
        .collect()
}

/// Whether any estimator could place every lag within 10 % of the truth in 90 % of such
/// records: the Cramér–Rao bound at the truth (white noise of the case's σ, on the logged
/// input, Jacobian of the exact response by central differences, the lead (and a held Y0)
/// not estimated: each makes the bound smaller, so a case is only excused when even it is
/// too wide) puts
/// 1.645 σ of every lag within 10 % of it.
fn resolvable(case: &Case) -> bool {
    let truth = &case.truth;
    let params = truth.structure.params();
    let respond = |m: &Model| m.simulate(&case.data.input, &case.data.times).unwrap();
    let columns: Vec<Vec<f64>> = params
        .iter()
        .map(|&p| {
            let h = 1e-5 * truth.get(p).abs().max(1.0);
            let moved = |d: f64| {
                let mut v = truth.values;
                v.set(p, truth.get(p) + d);
                respond(&Model::new(truth.structure, v))
            };
            let (up, down) = (moved(h), moved(-h));
            up.iter()
                .zip(&down)
                .map(|(a, b)| (a - b) / (2.0 * h))
                .collect()
        })
        .collect();
    let k = params.len();
    let fisher = nalgebra::DMatrix::from_fn(k, k, |i, j| {
        columns[i]
            .iter()
            .zip(&columns[j])
            .map(|(a, b)| a * b)
            .sum::<f64>()
            / (case.sd * case.sd)
    });
    let Some(covariance) = fisher.try_inverse() else {
        return false;
    };
    params.iter().enumerate().all(|(i, p)| {
        !matches!(p, Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw)
            || 1.645 * covariance[(i, i)].sqrt() <= TOLERANCE * truth.get(*p)
    })
}

fn recovered(case: &Case, r: &DiagnoseReport) -> bool {
    let fitted = &r.final_fit.model;
    let close = |a: f64, b: f64| ((a - b) / b).abs() <= TOLERANCE;
    let (mine, true_lags) = (lags(fitted), lags(&case.truth));
    close(fitted.get(Param::Kp), case.truth.get(Param::Kp))
        && mine.len() == true_lags.len()
        && mine.iter().zip(&true_lags).all(|(a, b)| close(*a, *b))
}

/// For a record that cannot resolve its lags to 10 % ([`resolvable`]): Kp within 10 % and
/// every true lag inside the 95 % interval the diagnosis reports for it (honest, not
/// absent).
fn honest(case: &Case, r: &DiagnoseReport) -> bool {
    let fitted = &r.final_fit;
    let kp = fitted.model.get(Param::Kp);
    let true_kp = case.truth.get(Param::Kp);
    let true_lags = lags(&case.truth);
    let intervals = lag_intervals(fitted);
    ((kp - true_kp) / true_kp).abs() <= TOLERANCE
        && intervals.len() == true_lags.len()
        && intervals
            .iter()
            .zip(&true_lags)
            .all(|(ci, t)| ci.is_some_and(|(lo, hi)| lo <= *t && *t <= hi))
}

struct Outcome {
    structural: bool,
    named: bool,
    /// Kp and the lags within 10 % of the truth; for a small step whose record cannot
    /// resolve them (see [`resolvable`]), Kp within 10 % and the lags inside their intervals.
    recovered: bool,
    /// Whether the record could resolve the lags to 10 % (always, but for a small step).
    resolvable: bool,
    text: String,
}

fn run(artefact: Artefact, index: usize) -> Outcome {
    let case = generate(artefact, index);
    let clock = std::time::Instant::now();
    let report = diagnose(&case.data, case.start, None, &DiagnoseOptions::default());
    match report {
        Ok(r) => {
            let named = r.test_causes.iter().any(|c| {
                c.kind == artefact.kind()
                    && match (&c.evidence, case.too_slow) {
                        (TestEvidence::Sampling { too_slow, .. }, Some(slow)) => *too_slow == slow,
                        _ => true,
                    }
            });
            let causes: Vec<&str> = r.test_causes.iter().map(|c| c.kind.id()).collect();
            let chain: Vec<&str> = r.steps.iter().map(|s| s.cause.id()).collect();
            let fitted = &r.final_fit.model;
            let resolvable = artefact != Artefact::SmallStep || resolvable(&case);
            let text = format!(
                "{:.1} s seed {:#x} {} | causes {causes:?} steps {chain:?} | Kp {:.4} (true {:.4}) lags {:?} {:?} (true {:?}){}",
                clock.elapsed().as_secs_f64(),
                case.seed,
                case.note,
                fitted.get(Param::Kp),
                case.truth.get(Param::Kp),
                lags(fitted),
                lag_intervals(&r.final_fit),
                lags(&case.truth),
                if resolvable {
                    ""
                } else {
                    " [lags beyond the Cramér–Rao bound]"
                },
            );
            if std::env::var_os("DEGRAU_ARTEFACTS_VERBOSE").is_some() {
                eprintln!("{text}");
            }
            Outcome {
                structural: !r.steps.is_empty(),
                named,
                recovered: if resolvable {
                    recovered(&case, &r)
                } else {
                    honest(&case, &r)
                },
                resolvable,
                text,
            }
        }
        Err(e) => Outcome {
            structural: false,
            named: false,
            recovered: false,
            resolvable: true,
            text: format!("seed {:#x} {}: diagnose failed: {e}", case.seed, case.note),
        },
    }
}

fn outcomes(artefact: Artefact) -> &'static [Outcome] {
    static CACHE: [OnceLock<Vec<Outcome>>; ARTEFACTS] = [const { OnceLock::new() }; ARTEFACTS];
    CACHE[artefact as usize].get_or_init(|| {
        let out: Vec<Outcome> = (0..CASES).map(|i| run(artefact, i)).collect();
        let count = |f: &dyn Fn(&Outcome) -> bool| out.iter().filter(|o| f(o)).count();
        let mut text = format!(
            "\n[{:<14}] no structural cause {}/{CASES} | named {}/{CASES} | Kp and lags within 10 % {}/{CASES}",
            artefact.kind().id(),
            count(&|o| !o.structural),
            count(&|o| o.named),
            count(&|o| o.recovered),
        );
        let beyond = count(&|o| !o.resolvable);
        if beyond > 0 {
            text += &format!(
                " ({beyond} beyond the Cramér–Rao bound: Kp within 10 % and the lags inside their intervals; Kp and lags within 10 % in {}/{} others)",
                count(&|o| o.resolvable && o.recovered),
                CASES - beyond,
            );
        }
        for o in out.iter().filter(|o| o.structural || !o.named || !o.recovered) {
            text += &format!("\n  MISS {}", o.text);
        }
        eprintln!("{text}");
        out
    })
}

fn accept(artefact: Artefact) {
    let out = outcomes(artefact);
    let n = out.len() as f64;
    let share = |f: &dyn Fn(&Outcome) -> bool| out.iter().filter(|o| f(o)).count() as f64 / n;
    let misses = |f: &dyn Fn(&Outcome) -> bool| {
        out.iter()
            .filter(|o| !f(o))
            .map(|o| format!("  {}", o.text))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let id = artefact.kind().id();
    assert!(
        share(&|o| !o.structural) >= MIN_NO_STRUCTURE,
        "{id}: a structural cause named:\n{}",
        misses(&|o| !o.structural)
    );
    assert!(
        share(&|o| o.named) >= MIN_NAMED,
        "{id}: not named:\n{}",
        misses(&|o| o.named)
    );
    assert!(
        share(&|o| o.recovered) >= MIN_RECOVERED,
        "{id}: Kp or a lag off by more than 10 %:\n{}",
        misses(&|o| o.recovered)
    );
}

#[test]
fn a_load_disturbance_is_named_and_not_taken_for_structure() {
    accept(Artefact::Disturbance);
}

#[test]
fn a_clipped_output_is_named_and_left_out() {
    accept(Artefact::Saturation);
}

#[test]
fn spikes_and_dropouts_are_named_and_fitted_robustly() {
    accept(Artefact::Outliers);
}

#[test]
fn strongly_coloured_noise_buys_no_structure() {
    accept(Artefact::ColouredNoise);
}

#[test]
fn a_test_not_at_rest_is_named_and_fitted_with_its_transient() {
    accept(Artefact::NotAtRest);
}

#[test]
fn a_coarse_resolution_is_named_and_buys_no_structure() {
    accept(Artefact::Quantisation);
}

#[test]
fn a_sampling_period_off_the_rules_is_named() {
    accept(Artefact::Sampling);
}

#[test]
fn a_step_under_six_noises_is_named() {
    accept(Artefact::SmallStep);
}

#[test]
fn an_actuator_that_ramps_overshoots_or_wobbles_is_named_and_not_taken_for_structure() {
    accept(Artefact::ImperfectStep);
}

#[test]
fn a_gain_that_differs_step_to_step_is_named_and_not_taken_for_structure() {
    accept(Artefact::Nonlinearity);
}

// ---------------------------------------------------------------------------------------------
// Edge records (issue 21, item 10): no index beyond a record's end
// ---------------------------------------------------------------------------------------------

/// What drives an edge record.
#[derive(Debug, Clone, Copy)]
enum EdgeInput {
    /// One step at the sample `at` (0: the first, the input before the record given).
    Step { at: usize },
    /// A PRBS holding each bit `hold` samples.
    Prbs { hold: usize },
    /// A staircase of `changes` changes of random sizes and signs.
    Staircase { changes: usize },
}

/// What the output does on an edge record.
#[derive(Debug, Clone, Copy, PartialEq)]
enum EdgeOutput {
    Response,
    Constant,
    Quantised,
}

/// An edge record: `n` samples driven by `input`, the output as `output` says, with up to
/// `wild` spikes, a moving-average filter, and the record then cut to a window and a
/// stretch left out (the input measured on the whole record, as the CLI's window keeps it).
#[derive(Debug, Clone, Copy)]
struct Edge {
    seed: u64,
    n: usize,
    input: EdgeInput,
    output: EdgeOutput,
    start: usize,
    free_offset: bool,
    wild: usize,
    filter: bool,
    window: bool,
    gap: bool,
}

fn edge_input(rng: &mut Lcg, n: usize, input: EdgeInput) -> (Vec<f64>, Option<f64>) {
    let u0 = range(rng, (0.0, 50.0));
    let mut u = vec![u0; n];
    let set_from =
        |u: &mut Vec<f64>, k: usize, v: f64| u[k.min(n)..].iter_mut().for_each(|x| *x = v);
    match input {
        EdgeInput::Step { at: 0 } => return (vec![u0 + signed(rng, (0.5, 10.0)); n], Some(u0)),
        EdgeInput::Step { at } => set_from(&mut u, at, u0 + signed(rng, (0.5, 10.0))),
        EdgeInput::Prbs { hold } => {
            let amp = signed(rng, (0.5, 10.0));
            for (k, chunk) in u.chunks_mut(hold).enumerate().skip(1) {
                let bit = if k == 1 || rng.unit() < 0.5 { amp } else { 0.0 };
                chunk.iter_mut().for_each(|x| *x = u0 + bit);
            }
        }
        EdgeInput::Staircase { changes } => {
            let mut level = u0;
            for _ in 0..changes {
                level += signed(rng, (0.5, 5.0));
                let at = rng.below(n);
                set_from(&mut u, at, level);
            }
        }
    }
    (u, None)
}

fn edge_record(e: Edge) -> (FitData, Structure) {
    let mut rng = Lcg(e.seed | 1);
    let n = e.n;
    let h = range(&mut rng, (0.01, 2.0));
    let t_first = range(&mut rng, (-100.0, 100.0));
    let times: Vec<f64> = (0..n).map(|k| t_first + h * k as f64).collect();
    let (u, before) = edge_input(&mut rng, n, e.input);
    let input = Excitation::measured(&times, &u, before, Hold::Zoh)
        .unwrap_or_else(|| Excitation::step(times[n / 2], 1.0));
    let code = STARTS[e.start % STARTS.len()];
    let mut truth = Structure::parse(code).unwrap();
    truth.lead = false;
    let mut v = Values::default();
    let span = h * n as f64;
    v.set(Param::Kp, signed(&mut rng, (0.5, 5.0)));
    v.set(Param::Y0, range(&mut rng, (-50.0, 100.0)));
    v.set(Param::Tp1, range(&mut rng, (0.02, 0.5)) * span);
    v.set(Param::Tp2, range(&mut rng, (0.2, 0.6)) * v.get(Param::Tp1));
    v.set(Param::Tw, range(&mut rng, (0.02, 0.2)) * span);
    v.set(Param::Zeta, range(&mut rng, (0.2, 0.6)));
    v.set(Param::Td, range(&mut rng, (0.0, 0.1)) * span);
    let mut y = match e.output {
        EdgeOutput::Constant => vec![v.get(Param::Y0); n],
        _ => Model::new(truth, v)
            .simulate(&input, &times)
            .unwrap_or_else(|_| vec![0.0; n]),
    };
    let effect = y
        .iter()
        .fold(0.0_f64, |m, x| m.max((x - y[0]).abs()))
        .max(1e-3);
    let sd = range(&mut rng, (0.002, 0.02)) * effect;
    if e.output != EdgeOutput::Constant {
        y.iter_mut().for_each(|x| *x += sd * rng.gaussian());
    }
    for _ in 0..e.wild {
        let i = rng.below(n);
        y[i] += signed(&mut rng, (6.0, 15.0)) * sd.max(1e-3);
    }
    if e.filter {
        let raw = y.clone();
        for k in 2..n {
            y[k] = (raw[k] + raw[k - 1] + raw[k - 2]) / 3.0;
        }
    }
    if e.output == EdgeOutput::Quantised {
        let q = range(&mut rng, (0.01, 0.1)) * effect;
        y.iter_mut().for_each(|x| *x = (*x / q).round() * q);
    }
    let mut keep = vec![true; n];
    if e.window && n > 16 {
        let (a, b) = (rng.below(n / 4), n - rng.below(n / 4));
        keep.iter_mut()
            .enumerate()
            .for_each(|(k, x)| *x = (a..b).contains(&k));
    }
    if e.gap && n > 16 {
        let a = rng.below(n);
        let b = (a + 1 + rng.below(n / 4)).min(n);
        keep[a..b].iter_mut().for_each(|x| *x = false);
    }
    let data = FitData { times, y, input }.keeping(&keep);
    let mut start = Structure::parse(code).unwrap();
    start.free_offset = e.free_offset;
    start.lead = data.input.lead_range > 0.0;
    (data, start)
}

fn edge_strategy() -> impl proptest::strategy::Strategy<Value = Edge> {
    use proptest::prelude::*;
    let n = prop_oneof![4 => 8usize..60, 3 => 60usize..400, 1 => 400usize..5000];
    let input = prop_oneof![
        (0usize..4).prop_map(|k| EdgeInput::Step { at: k }),
        Just(EdgeInput::Step { at: usize::MAX }),
        (1usize..8).prop_map(|hold| EdgeInput::Prbs { hold }),
        (1usize..6).prop_map(|changes| EdgeInput::Staircase { changes }),
    ];
    let output = prop_oneof![
        3 => Just(EdgeOutput::Response),
        1 => Just(EdgeOutput::Constant),
        1 => Just(EdgeOutput::Quantised),
    ];
    (
        any::<u64>(),
        n,
        input,
        output,
        0usize..STARTS.len(),
        any::<bool>(),
        prop_oneof![2 => Just(0usize), 1 => 1usize..8],
        any::<[bool; 3]>(),
    )
        .prop_map(
            |(seed, n, input, output, start, free_offset, wild, [filter, window, gap])| {
                // A step "at the last sample" and "at the second" land where the record has them.
                let input = match input {
                    EdgeInput::Step { at } if at >= 3 => EdgeInput::Step { at: n - 1 },
                    other => other,
                };
                Edge {
                    seed,
                    n,
                    input,
                    output,
                    start,
                    free_offset,
                    wild,
                    filter,
                    window,
                    gap,
                }
            },
        )
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 48,
        failure_persistence: None,
        ..proptest::prelude::ProptestConfig::default()
    })]

    /// `diagnose` on short and edge records (8 to 5000 samples; a change at the first, the
    /// second or the last sample, a PRBS, a staircase; spikes, a filter, a window and a
    /// stretch left out, constant and quantised outputs) never panics: it ends with a finite
    /// Kp or a typed error.
    #[test]
    fn diagnose_never_indexes_past_an_edge_record(e in edge_strategy()) {
        let (data, start) = edge_record(e);
        if let Ok(r) = diagnose(&data, start, None, &DiagnoseOptions::default()) {
            let kp = r.final_fit.model.get(Param::Kp);
            proptest::prop_assert!(kp.is_finite(), "{e:?}: Kp {kp}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Clean records (issue 21, item 8): a test cause only where the test shows it
// ---------------------------------------------------------------------------------------------

/// The true structures of the clean records, cycled.
const CLEAN_TRUTHS: [&str; 7] = ["P1", "P1D", "P2", "P2U", "P2DU", "P2Z", "P1I"];
/// The least share of clean records with no test cause but `sampling`.
const MIN_CLEAN_QUIET: f64 = 0.98;
/// The least share of clean records with no `outliers`.
const MIN_CLEAN_NO_OUTLIERS: f64 = 0.99;

/// The `index`-th clean record of `n` samples: an ideal step between two samples (every
/// third record a staircase of two or three, each held as long), far from zero, white Gaussian noise of 0.2–2 % of the effect (of the ramp's rise for an
/// integrator), no artefact. The start is the truth in half the records and P1 in the other
/// half (a wrong start: its large smooth residuals are no outliers); Y0 free or held.
fn clean(index: usize, n: usize) -> (FitData, Structure, String) {
    let seed = 0xC1EA_0000 + index as u64 + 7919 * n as u64;
    let mut rng = Lcg(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    rng.bits();
    let code = CLEAN_TRUTHS[index % CLEAN_TRUTHS.len()];
    let truth = Structure::parse(code).unwrap();
    let mut v = Values::default();
    let (kp, du) = (signed(&mut rng, (0.5, 5.0)), signed(&mut rng, (0.5, 10.0)));
    let u0 = range(&mut rng, (0.0, 60.0));
    let tp1 = range(&mut rng, (1.0, 20.0));
    v.set(Param::Kp, kp);
    v.set(Param::Y0, range(&mut rng, (-50.0, 100.0)));
    v.set(Param::Tp1, tp1);
    let mut slowest = tp1;
    if truth.underdamped {
        let (tw, zeta) = (range(&mut rng, (1.0, 8.0)), range(&mut rng, (0.2, 0.6)));
        v.set(Param::Tw, tw);
        v.set(Param::Zeta, zeta);
        slowest = tw / zeta;
    } else if truth.poles == 2 {
        v.set(Param::Tp2, range(&mut rng, (0.2, 0.6)) * tp1);
    }
    if truth.zero {
        v.set(Param::Tz, range(&mut rng, (1.5, 4.0)) * tp1);
    }
    let td = if truth.delay {
        range(&mut rng, (0.2, 0.8)) * slowest.min(tp1)
    } else {
        0.0
    };
    v.set(Param::Td, td);
    // Every third record a staircase: one or two more changes of either sign, each held
    // as long as the first, so that a linear process shows the same gain on each.
    let changes = if index % 3 == 2 && !truth.integrator {
        2 + (index / 3) % 2
    } else {
        1
    };
    let after = range(&mut rng, (6.0, 10.0)) * slowest + td;
    let fraction = range(&mut rng, (0.12, 0.25));
    let length = changes as f64 * after / (1.0 - fraction);
    let t0 = fraction * length;
    let hold = (length - t0) / changes as f64;
    let mut levels = vec![0.0, du];
    for _ in 1..changes {
        let last = *levels.last().unwrap();
        levels.push(last + signed(&mut rng, (0.5, 1.5)) * du);
    }
    // The later changes at the first one's fraction of the sampling period, as a logger
    // that sets the input gives them (one latency for every change).
    let h = length / (n - 1) as f64;
    let fraction_of_h = t0 / h - (t0 / h).floor();
    let mut excitation = Excitation::step(t0, du);
    for (k, w) in levels.windows(2).enumerate().skip(1) {
        excitation.steps.push(InputStep {
            t: (((t0 + k as f64 * hold) / h).floor() + fraction_of_h) * h,
            du: w[1] - w[0],
        });
    }
    let times: Vec<f64> = (0..n).map(|k| length * k as f64 / (n - 1) as f64).collect();
    let model = Model::new(truth, v);
    let mut y = model.simulate(&excitation, &times).unwrap();
    let effect = if truth.integrator {
        (kp * du * (length - t0)).abs()
    } else {
        (kp * du).abs()
    };
    let sd = range(&mut rng, (0.002, 0.02)) * effect;
    y.iter_mut().for_each(|x| *x += sd * rng.gaussian());
    let logged: Vec<f64> = times
        .iter()
        .map(|&t| {
            let k = excitation.steps.iter().filter(|s| s.t <= t).count();
            u0 + levels[k]
        })
        .collect();
    let input = Excitation::measured(&times, &logged, None, Hold::Zoh).unwrap();
    let mut start = if index.is_multiple_of(2) {
        truth
    } else {
        Structure::parse("P1").unwrap()
    };
    start.free_offset = (index / 2).is_multiple_of(2);
    start.lead = true;
    let note = format!(
        "seed {seed:#x} {code} from {} N={n} Kp={kp:.3} levels={levels:.3?} slowest={slowest:.3} td={td:.3} sd={sd:.4}",
        start.code()
    );
    (FitData { times, y, input }, start, note)
}

/// The test causes `diagnose` names on each clean record of the plan `(count, n)`, and the
/// records' notes.
fn clean_causes(plan: &[(usize, usize)]) -> Vec<(Vec<TestCauseKind>, String)> {
    let mut index = 0;
    let mut out = Vec::new();
    for &(count, n) in plan {
        for _ in 0..count {
            let (data, start, note) = clean(index, n);
            index += 1;
            let kinds = match diagnose(&data, start, None, &DiagnoseOptions::default()) {
                Ok(r) => r.test_causes.iter().map(|c| c.kind).collect(),
                Err(e) => panic!("{note}: diagnose failed: {e}"),
            };
            out.push((kinds, note));
        }
    }
    out
}

/// The shares of the acceptance, asserted, with the figures printed.
fn accept_clean(plan: &[(usize, usize)]) {
    let out = clean_causes(plan);
    let total = out.len() as f64;
    let loud: Vec<&(Vec<TestCauseKind>, String)> = out
        .iter()
        .filter(|(k, _)| k.iter().any(|k| *k != TestCauseKind::Sampling))
        .collect();
    let outliers = loud
        .iter()
        .filter(|(k, _)| k.contains(&TestCauseKind::Outliers))
        .count();
    let listing: String = loud
        .iter()
        .map(|(k, note)| {
            let ids: Vec<&str> = k.iter().map(|k| k.id()).collect();
            format!("\n  {ids:?} {note}")
        })
        .collect();
    eprintln!(
        "[clean] {} records: a test cause but sampling in {}, outliers in {outliers}{listing}",
        out.len(),
        loud.len()
    );
    assert!(
        1.0 - loud.len() as f64 / total >= MIN_CLEAN_QUIET,
        "test causes on clean records:{listing}"
    );
    assert!(
        1.0 - outliers as f64 / total >= MIN_CLEAN_NO_OUTLIERS,
        "outliers on clean records:{listing}"
    );
}

/// Clean records of 10², 10³ and 10⁴ samples, every structure, right and wrong (P1) starts:
/// no test cause but `sampling` in ≥ 98 %, no `outliers` in ≥ 99 %.
#[test]
fn clean_records_name_no_test_cause_but_sampling() {
    accept_clean(&[(70, 100), (24, 1000), (6, 10_000)]);
}

/// The same on long records (10⁵ and 10⁶ samples): ignored in the default run for its time
/// (`cargo test --release --test diagnose_artefacts -- --ignored`).
#[test]
#[ignore = "long records: minutes in the dev profile"]
fn long_clean_records_name_no_test_cause_but_sampling() {
    accept_clean(&[(5, 100_000), (2, 1_000_000)]);
}
