//! Acceptance test of the diagnosis (tracker issue 5, item 6): simulated step tests in which
//! exactly one effect is missing from the start model. `diagnose` must name that effect
//! first, its extended (final) model must recover the true gain and time constants, and the
//! first step must pay (RMSE ratio before/after above 1); clean tests, where the start model
//! is the truth, must come out `none`.
//!
//! The truths are random but reproducible: a small LCG seeded per case (the seed is printed
//! with every failing case). Ranges: Kp ∈ ±[0.5, 5], Tp1 ∈ [1, 20] s, t0 at 5–20 % of the
//! record, Δu ∈ ±[0.5, 10], y0 ∈ [−50, 100], 150–800 samples covering t0 + 6–10 × the slowest
//! time constant (+ the dead time), uniform or Gaussian noise of standard deviation 0.2–2 % of
//! the step's effect |Kp·Δu| (of the ramp's rise for an integrator).
//!
//! The step comes between two samples, as in a real test (an operator's switch, a logger not
//! synchronised with the actuator): the true change is at t0, the logged input column shows
//! it at the first sample at or after t0, and the diagnosis sees only that column
//! (`Excitation::measured`, zero-order hold, so each start model may move the change up to
//! one sampling period earlier: `Ta`, or a `Td` down to −Ts). The truth is written as the
//! record sees it: its lead inside the sampling period is `Ta` (or comes off `Td`), so that
//! it reproduces the exact response on the logged input and the dead time compared is the
//! delay after the sample that shows the step. The offset cases start at the step itself.
//!
//! Recovery: Kp and every true time constant (the real poles as a set, since their order is
//! arbitrary; Tw for an underdamped pair; Tz; Td) within 10 %, except the drift cases (Kp and
//! Tp1 only); Y0 and Drift are never compared. A case that misses also prints what the true
//! structure, fitted from the true values on the same noisy data, misses: when that misses
//! too, the data do not determine the parameter to 10 % and the diagnosis is not to blame.
//!
//! Run with `cargo test --test diagnose_generator -- --nocapture` to see the figures, with
//! `DEGRAU_DIAGNOSE_CASES=40` for more cases per effect.

use crate::draw::Draws;
use degrau_ident::challenge::logger::logged_input;
use degrau_ident::challenge::truth::ramp_slope;
use degrau_ident::model::excitation::{Excitation, Hold, InputStep};
use std::sync::OnceLock;
use std::time::Instant;

use degrau_ident::diagnose::{Cause, DiagnoseOptions, DiagnoseReport, diagnose};
use degrau_ident::fit::guess::auto_guess;
use degrau_ident::fit::{FitData, FitOptions, fit};
use degrau_ident::model::{Model, Param, Structure, Values};

// ---------------------------------------------------------------------------------------------
// Acceptance numbers
// ---------------------------------------------------------------------------------------------

/// Fraction of an effect's cases whose first named cause must be that effect.
const MIN_RIGHT_FIRST: f64 = 0.95;
/// Fraction of the clean cases that must come out `none` (no step, adequate).
const MIN_CLEAN_NONE: f64 = 0.95;
/// Fraction of all the non-clean cases whose final model must recover the truth.
const MIN_RECOVERED: f64 = 0.90;
/// Relative tolerance of a recovered parameter.
const RECOVERY_TOLERANCE: f64 = 0.10;
/// Every correctly named first step must lower the RMSE by more than this factor.
const MIN_RMSE_RATIO: f64 = 1.0;

// Ranges of the random truths.
const KP: (f64, f64) = (0.5, 5.0);
const TP1: (f64, f64) = (1.0, 20.0);
const T0_FRACTION: (f64, f64) = (0.05, 0.2);
const DU: (f64, f64) = (0.5, 10.0);
const Y0: (f64, f64) = (-50.0, 100.0);
const SAMPLES: (usize, usize) = (150, 800);
const SETTLING_MULTIPLE: (f64, f64) = (6.0, 10.0);
const NOISE_FRACTION: (f64, f64) = (0.002, 0.02);
/// Dead time as a fraction of Tp1 (of Tw for an underdamped pair).
const TD_FRACTION: (f64, f64) = (0.2, 1.0);
/// Second time constant as a fraction of Tp1, where it is not the effect under test.
const TP2_FRACTION: (f64, f64) = (0.2, 0.6);
/// Second time constant of the extra-pole cases, as a fraction of Tp1.
const EXTRA_POLE_FRACTION: (f64, f64) = (0.3, 1.0);
const ZETA: (f64, f64) = (0.1, 0.5);
const TW: (f64, f64) = (1.0, 10.0);
/// Tz / Tp1 of the zero cases (overshoot with real poles).
const ZERO_FRACTION: (f64, f64) = (1.5, 4.0);
/// −Tz / Tp1 of the inverse-response cases.
const INVERSE_FRACTION: (f64, f64) = (0.3, 1.0);
/// Rise of the integrator's ramp over the record, in multiples of |Δu|.
const RAMP_RISE: (f64, f64) = (2.0, 10.0);
/// Drift over the whole record as a fraction of the step's effect.
const DRIFT_FRACTION: (f64, f64) = (0.1, 0.3);
/// Tz / Tp1 and Tp2 / Tp1 of the strong lead zero (the data overshoot to about twice their
/// final value).
const LEAD_ZERO_TZ: (f64, f64) = (2.0, 2.5);
const LEAD_ZERO_TP2: (f64, f64) = (0.05, 0.15);
/// |y0| of the offset cases is at least this fraction of the step's effect.
const MIN_OFFSET_FRACTION: f64 = 0.2;

// ---------------------------------------------------------------------------------------------
// The generator
// ---------------------------------------------------------------------------------------------

/// The generator of these cases: the workspace's one generator, started from a scrambled seed.
struct Lcg(degrau_ident::random::Lcg);

impl Lcg {
    fn new(seed: u64) -> Self {
        let mut g = degrau_ident::random::Lcg(seed ^ 0x9E37_79B9_7F4A_7C15);
        g.bits();
        Lcg(g)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        self.0.unit()
    }

    fn count(&mut self, (a, b): (usize, usize)) -> usize {
        // The state's top 31 bits.
        a + (self.0.bits() >> 22) as usize % (b - a + 1)
    }
}

impl Draws for Lcg {
    fn lcg(&mut self) -> &mut degrau_ident::random::Lcg {
        &mut self.0
    }
}

/// What is missing from the start model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// One effect: the cause `diagnose` must name first (never `Cause::None`: nothing
    /// missing is `Clean`).
    Missing(Cause),
    Clean,
    /// Two effects hidden at once, from a P1 start: a dead time and an extra pole (P2D).
    DeadTimeAndPole,
    /// A dead time and an oscillation (P2DU).
    DeadTimeAndOscillation,
    /// A strong lead zero (P2Z, the data overshoot to about twice their final value).
    LeadZero,
}

impl Kind {
    /// The cause `diagnose` must name first.
    fn expected(self) -> Cause {
        match self {
            Kind::Missing(cause) => cause,
            Kind::Clean => Cause::None,
            Kind::DeadTimeAndPole | Kind::DeadTimeAndOscillation => Cause::DeadTime,
            Kind::LeadZero => Cause::Zero,
        }
    }

    /// The causes right as the first named: the effect, or either of two hidden at once.
    fn right_causes(self) -> Vec<Cause> {
        match self {
            Kind::DeadTimeAndPole => vec![Cause::DeadTime, Cause::ExtraPole],
            Kind::DeadTimeAndOscillation => vec![Cause::DeadTime, Cause::Oscillation],
            Kind::LeadZero => vec![Cause::Zero, Cause::ExtraPole],
            k => vec![k.expected()],
        }
    }

    /// The kind's place, 1 to 12: the one-effect kinds in the order of [`EFFECTS`], then
    /// the clean and the two-effect ones. It numbers the seeds and the cached outcomes.
    fn ordinal(self) -> usize {
        match self {
            Kind::Missing(_) => {
                1 + EFFECTS
                    .iter()
                    .position(|&k| k == self)
                    .expect("a one-effect kind of EFFECTS")
            }
            Kind::Clean => 9,
            Kind::DeadTimeAndPole => 10,
            Kind::DeadTimeAndOscillation => 11,
            Kind::LeadZero => 12,
        }
    }

    fn base_seed(self) -> u64 {
        0xDE6A_0000 + 1000 * self.ordinal() as u64
    }

    /// Cases per missing effect (the environment variable `DEGRAU_DIAGNOSE_CASES` overrides
    /// it, for a longer run: 40 per effect take about 15 s in release on two cores).
    const CASES_PER_EFFECT: usize = 20;
    /// Clean cases (cycling through P1D, P2D and P2DU; the override applies here too).
    const CLEAN_CASES: usize = 20;

    fn cases(self) -> usize {
        if let Some(n) = std::env::var("DEGRAU_DIAGNOSE_CASES")
            .ok()
            .and_then(|v| v.trim().parse::<usize>().ok())
            .filter(|&n| n > 0)
        {
            return n;
        }
        if self == Kind::Clean {
            Kind::CLEAN_CASES
        } else {
            Kind::CASES_PER_EFFECT
        }
    }
}

/// One simulated step test with its truth and the start model handed to `diagnose`.
#[derive(Debug, Clone)]
struct Case {
    kind: Kind,
    index: usize,
    seed: u64,
    truth: Model,
    /// The true instant of the step (s); the record shows it at the next sample.
    t_change: f64,
    data: FitData,
    start: Structure,
    /// The value Y0 is held at in the start model.
    start_y0: f64,
    /// The step's effect the noise is scaled on.
    effect: f64,
    noise_sd: f64,
    gaussian: bool,
}

impl Case {
    fn describe(&self) -> String {
        let v = &self.truth.values;
        let mut s = format!(
            "{:?} #{} seed {:#x}: truth {}{} ",
            self.kind,
            self.index,
            self.seed,
            self.truth.structure.code(),
            if self.truth.structure.drift {
                "+drift"
            } else {
                ""
            }
        );
        for p in self.truth.structure.params() {
            s += &format!("{}={:.4} ", p.name(), v.get(p));
        }
        s += &format!(
            "| start {} (Y0 held at {:.3}) | t0={:.2} (true {:.4}) du={:.3} N={} Ts={:.4} | noise {} sd={:.4} ({:.2} % of effect {:.3})",
            self.start.code(),
            self.start_y0,
            self.data.input.t0(),
            self.t_change,
            self.data.input.du(),
            self.data.times.len(),
            self.data.sampling_period(),
            if self.gaussian { "gauss" } else { "uniform" },
            self.noise_sd,
            100.0 * self.noise_sd / self.effect.max(f64::MIN_POSITIVE),
            self.effect
        );
        s
    }
}

/// The structure of `code` on a record whose step came between samples (`lead`).
fn structure(code: &str, free_offset: bool) -> Structure {
    let mut s = Structure::parse(code).unwrap();
    s.free_offset = free_offset;
    s.lead = true;
    s
}

/// The `index`-th case of `kind`; `noisy` false gives the same truth without noise.
fn generate(kind: Kind, index: usize, noisy: bool) -> Case {
    let seed = kind.base_seed() + index as u64;
    let mut rng = Lcg::new(seed);
    let mut v = Values::default();
    let kp = rng.signed(KP);
    let du = rng.signed(DU);
    let mut y0 = rng.range(Y0);
    let tp1 = rng.range(TP1);
    v.set(Param::Kp, kp);
    v.set(Param::Tp1, tp1);
    v.set(Param::Drift, 0.0);
    v.set(Param::Tz, 0.0);
    v.set(Param::Td, 0.0);
    let mut drift = false;
    let mut y0_held = None;

    // The truth, the start model, and the slowest time constant.
    let underdamped = |rng: &mut Lcg, v: &mut Values| {
        let tw = rng.range(TW);
        let zeta = rng.range(ZETA);
        v.set(Param::Tw, tw);
        v.set(Param::Zeta, zeta);
        v.set(Param::Td, rng.range(TD_FRACTION) * tw);
        tw / zeta
    };
    let (truth_code, start_code, slowest) = match kind {
        Kind::Missing(Cause::DeadTime) => {
            v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
            if index.is_multiple_of(2) {
                ("P1D", "P1", tp1)
            } else {
                v.set(Param::Tp2, rng.range(TP2_FRACTION) * tp1);
                ("P2D", "P2", tp1)
            }
        }
        Kind::Missing(Cause::Offset) => {
            v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
            while y0.abs() < MIN_OFFSET_FRACTION * (kp * du).abs() {
                y0 = rng.range(Y0);
            }
            y0_held = Some(0.0);
            ("P1D", "P1D", tp1)
        }
        Kind::Missing(Cause::Oscillation) => {
            let slowest = underdamped(&mut rng, &mut v);
            ("P2DU", "P2D", slowest)
        }
        Kind::Missing(Cause::ExtraPole) => {
            v.set(Param::Tp2, rng.range(EXTRA_POLE_FRACTION) * tp1);
            v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
            ("P2D", "P1D", tp1)
        }
        Kind::Missing(Cause::Zero) => {
            v.set(Param::Tp2, rng.range(TP2_FRACTION) * tp1);
            v.set(Param::Tz, rng.range(ZERO_FRACTION) * tp1);
            ("P2Z", "P2", tp1)
        }
        Kind::Missing(Cause::InverseResponse) => {
            v.set(Param::Tp2, rng.range(TP2_FRACTION) * tp1);
            v.set(Param::Tz, -rng.range(INVERSE_FRACTION) * tp1);
            ("P2Z", "P2", tp1)
        }
        Kind::Missing(Cause::Integrator) => ("P1I", "P1", tp1),
        Kind::Missing(Cause::Drift) => {
            v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
            drift = true;
            ("P1D", "P1D", tp1)
        }
        Kind::DeadTimeAndPole => {
            v.set(Param::Tp2, rng.range(EXTRA_POLE_FRACTION) * tp1);
            v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
            ("P2D", "P1", tp1)
        }
        Kind::DeadTimeAndOscillation => {
            let slowest = underdamped(&mut rng, &mut v);
            ("P2DU", "P1", slowest)
        }
        Kind::LeadZero => {
            v.set(Param::Tp2, rng.range(LEAD_ZERO_TP2) * tp1);
            v.set(Param::Tz, rng.range(LEAD_ZERO_TZ) * tp1);
            ("P2Z", "P1", tp1)
        }
        Kind::Clean => match index % 3 {
            0 => {
                v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
                ("P1D", "P1D", tp1)
            }
            1 => {
                v.set(Param::Tp2, rng.range(TP2_FRACTION) * tp1);
                v.set(Param::Td, rng.range(TD_FRACTION) * tp1);
                ("P2D", "P2D", tp1)
            }
            _ => {
                let slowest = underdamped(&mut rng, &mut v);
                ("P2DU", "P2DU", slowest)
            }
        },
        Kind::Missing(Cause::None) => unreachable!("nothing missing is Kind::Clean"),
    };
    v.set(Param::Y0, y0);
    let mut truth_structure = structure(truth_code, true);
    truth_structure.drift = drift;
    let start = structure(start_code, false);
    let mut start_y0 = y0_held.unwrap_or(y0);

    // The record: t0 + 6–10 × the slowest time constant + the dead time after the step.
    let after = rng.range(SETTLING_MULTIPLE) * slowest + v.get(Param::Td);
    let fraction = rng.range(T0_FRACTION);
    let length = after / (1.0 - fraction);
    let t0 = fraction * length;
    let n = rng.count(SAMPLES);
    let times: Vec<f64> = if kind == Kind::Missing(Cause::Offset) {
        // No sample before the step: the record starts at t0.
        (0..n)
            .map(|k| t0 + after * k as f64 / (n - 1) as f64)
            .collect()
    } else {
        (0..n).map(|k| length * k as f64 / (n - 1) as f64).collect()
    };
    let record = times[n - 1] - times[0];

    let mut effect = (kp * du).abs();
    if kind == Kind::Missing(Cause::Integrator) {
        // Kp is a slope per input unit: the ramp rises by 2–10 × |Δu| over the record.
        let rise = rng.range(RAMP_RISE);
        v.set(Param::Kp, kp.signum() * ramp_slope(rise, after, tp1));
        effect = rise * du.abs();
    }
    if drift {
        let total = rng.signed(DRIFT_FRACTION) * effect;
        v.set(Param::Drift, total / record);
    }

    // The exact response to the step at t0, sampled; the record logs the input at the
    // first sample at or after t0, and the truth is written as that record sees it.
    let clean = Model::new(truth_structure, v)
        .simulate(&Excitation::step(t0, du), &times)
        .unwrap();
    let k = times.partition_point(|&t| t < t0);
    let lead = times[k] - t0;
    let logged = logged_input(&times, 0.0, &[InputStep { t: t0, du }]);
    let before_record = (k == 0).then_some(0.0);
    let setup = Excitation::measured(&times, &logged, before_record, Hold::Zoh).unwrap();
    if truth_structure.delay {
        v.set(Param::Td, v.get(Param::Td) - lead);
    } else {
        v.set(Param::Ta, lead);
    }
    if drift {
        // The drift's origin is the first change's instant: the logged one, `lead` later.
        v.set(Param::Y0, y0 + v.get(Param::Drift) * lead);
        start_y0 = v.get(Param::Y0);
    }
    let truth = Model::new(truth_structure, v);
    let noise_sd = rng.range(NOISE_FRACTION) * effect;
    let gaussian = rng.unit() < 0.5;
    let y = clean
        .iter()
        .map(|&c| {
            let e = if gaussian {
                rng.gaussian()
            } else {
                3f64.sqrt() * (2.0 * rng.unit() - 1.0)
            };
            if noisy { c + noise_sd * e } else { c }
        })
        .collect();
    Case {
        kind,
        index,
        seed,
        truth,
        t_change: t0,
        data: FitData {
            times,
            y,
            input: setup,
        },
        start,
        start_y0,
        effect,
        noise_sd: if noisy { noise_sd } else { 0.0 },
        gaussian,
    }
}

// ---------------------------------------------------------------------------------------------
// Running and judging
// ---------------------------------------------------------------------------------------------

/// The start values handed over: the start structure's automatic guess, Y0 at the held value.
fn start_values(case: &Case) -> Values {
    let mut v = auto_guess(&case.data, case.start, Some(case.start_y0));
    v.set(Param::Y0, case.start_y0);
    v
}

fn first_cause(report: &DiagnoseReport) -> Cause {
    report.steps.first().map_or(Cause::None, |s| s.cause)
}

fn chain(report: &DiagnoseReport) -> String {
    let mut s = report.start.model.structure.code();
    for step in &report.steps {
        s += &format!(
            " -[{} ×{:.3}]-> {}",
            step.cause.id(),
            step.gain.rmse_ratio,
            step.fit.model.structure.code()
        );
        if step.fit.model.structure.free_offset && !report.start.model.structure.free_offset {
            s += "+Y0";
        }
        if step.fit.model.structure.drift {
            s += "+drift";
        }
    }
    s += if report.adequate {
        " (adequate)"
    } else {
        " (step limit)"
    };
    s
}

/// The real time constants of a model's poles, sorted (an underdamped pair with ζ ≥ 1 counts
/// as its two real poles).
fn real_time_constants(m: &Model) -> Vec<f64> {
    let s = m.structure;
    let mut t = Vec::new();
    if s.underdamped {
        let (tw, zeta) = (m.get(Param::Tw), m.get(Param::Zeta));
        if zeta >= 1.0 {
            let r = (zeta * zeta - 1.0).sqrt();
            t.extend([tw * (zeta + r), tw * (zeta - r)]);
        }
        if s.poles == 3 {
            t.push(m.get(Param::Tp3));
        }
    } else {
        t.extend(
            [Param::Tp1, Param::Tp2, Param::Tp3]
                .into_iter()
                .take(s.poles as usize)
                .map(|p| m.get(p)),
        );
    }
    t.sort_by(f64::total_cmp);
    t
}

fn close(estimate: f64, truth: f64) -> bool {
    (estimate - truth).abs() <= RECOVERY_TOLERANCE * truth.abs()
}

/// The compared parameters the final model misses by more than the tolerance, as text.
/// Compared: Kp, every true pole time constant (Tw for an underdamped pair, the real ones as
/// a set, the fitted order being arbitrary), Tz and Td when the truth has them; the drift
/// cases compare Kp and Tp1 only; Y0 and Drift themselves are never compared.
fn misses(case: &Case, fitted: &Model) -> Vec<String> {
    let truth = &case.truth;
    let ts = truth.structure;
    let fs = fitted.structure;
    let mut out = Vec::new();
    let mut check = |name: &str, est: f64, tru: f64| {
        if !close(est, tru) {
            out.push(format!("{name} {est:.4} vs {tru:.4}"));
        }
    };
    check("Kp", fitted.get(Param::Kp), truth.get(Param::Kp));
    if case.kind == Kind::Missing(Cause::Drift) {
        let fitted_tp = real_time_constants(fitted);
        let tp1 = truth.get(Param::Tp1);
        let best = fitted_tp
            .iter()
            .copied()
            .min_by(|a, b| (a - tp1).abs().total_cmp(&(b - tp1).abs()))
            .unwrap_or(f64::NAN);
        check("Tp1", best, tp1);
        return out;
    }
    if ts.underdamped {
        let tw = if fs.underdamped {
            fitted.get(Param::Tw)
        } else {
            f64::NAN
        };
        check("Tw", tw, truth.get(Param::Tw));
    } else {
        let true_tp = real_time_constants(truth);
        let fitted_tp = real_time_constants(fitted);
        if fitted_tp.len() == true_tp.len() {
            for (k, (e, t)) in fitted_tp.iter().zip(&true_tp).enumerate() {
                check(&format!("T(pole {})", k + 1), *e, *t);
            }
        } else {
            for (k, t) in true_tp.iter().enumerate() {
                let best = fitted_tp
                    .iter()
                    .copied()
                    .min_by(|a, b| (a - t).abs().total_cmp(&(b - t).abs()))
                    .unwrap_or(f64::NAN);
                check(
                    &format!("T(pole {}, of {})", k + 1, fitted_tp.len()),
                    best,
                    *t,
                );
            }
        }
    }
    if ts.zero {
        let tz = if fs.zero { fitted.get(Param::Tz) } else { 0.0 };
        check("Tz", tz, truth.get(Param::Tz));
    }
    if ts.delay {
        let td = if fs.delay { fitted.get(Param::Td) } else { 0.0 };
        check("Td", td, truth.get(Param::Td));
    }
    out
}

/// What came out of one case.
struct Outcome {
    case: Case,
    first: Option<Cause>,
    /// `none`: no step and adequate.
    none: bool,
    chain: String,
    first_ratio: Option<f64>,
    misses: Vec<String>,
    /// The misses of the true structure fitted from the true values on the same noisy data:
    /// what no diagnosis could do better (computed for cases that miss).
    oracle_misses: Option<Vec<String>>,
    error: Option<String>,
    millis: f64,
}

impl Outcome {
    fn right_first(&self) -> bool {
        self.first
            .is_some_and(|c| self.case.kind.right_causes().contains(&c))
    }

    fn recovered(&self) -> bool {
        self.error.is_none() && self.misses.is_empty()
    }

    fn describe(&self) -> String {
        match &self.error {
            Some(e) => format!("{}\n      error: {e}", self.case.describe()),
            None => format!(
                "{}\n      first {} | {} | misses: [{}]{} | {:.0} ms",
                self.case.describe(),
                self.first.map_or("—", |c| c.id()),
                self.chain,
                self.misses.join(", "),
                self.oracle_misses
                    .as_ref()
                    .map_or(String::new(), |m| format!(
                        " | true structure fitted from the truth misses: [{}]",
                        m.join(", ")
                    )),
                self.millis
            ),
        }
    }
}

/// The misses of the true structure fitted from the true values (a single LM start).
fn oracle(case: &Case) -> Vec<String> {
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let mut s = case.truth.structure;
    let mut v = case.truth.values;
    if case.kind != Kind::Missing(Cause::Offset) {
        s.free_offset = false;
    }
    v.set(Param::Y0, case.truth.get(Param::Y0));
    match fit(&case.data, s, v, &options, &mut ()) {
        Ok(r) => misses(case, &r.model),
        Err(e) => vec![format!("(fit failed: {e})")],
    }
}

fn run(case: Case) -> Outcome {
    let options = DiagnoseOptions::default();
    let values = start_values(&case);
    let clock = Instant::now();
    let result = diagnose(&case.data, case.start, Some(values), &options);
    let millis = clock.elapsed().as_secs_f64() * 1e3;
    match result {
        Ok(report) => {
            let misses = misses(&case, &report.final_fit.model);
            let oracle_misses = (!misses.is_empty()).then(|| oracle(&case));
            Outcome {
                first: Some(first_cause(&report)),
                none: report.steps.is_empty() && report.adequate,
                chain: chain(&report),
                first_ratio: report.steps.first().map(|s| s.gain.rmse_ratio),
                misses,
                oracle_misses,
                error: None,
                millis,
                case,
            }
        }
        Err(e) => Outcome {
            first: None,
            none: false,
            chain: String::new(),
            first_ratio: None,
            misses: vec!["(diagnose failed)".into()],
            oracle_misses: None,
            error: Some(e.to_string()),
            millis,
            case,
        },
    }
}

/// Runs every case of `kind`, prints the figures and the failures, and returns the outcomes.
fn run_kind(kind: Kind) -> Vec<Outcome> {
    let clock = Instant::now();
    let outcomes: Vec<Outcome> = (0..kind.cases())
        .map(|i| run(generate(kind, i, true)))
        .collect();
    let n = outcomes.len() as f64;
    let right = outcomes.iter().filter(|o| o.right_first()).count();
    let none = outcomes.iter().filter(|o| o.none).count();
    let recovered = outcomes.iter().filter(|o| o.recovered()).count();
    let ratios: Vec<f64> = outcomes
        .iter()
        .filter(|o| o.right_first())
        .filter_map(|o| o.first_ratio)
        .collect();
    let ratio_text = if ratios.is_empty() {
        "—".to_string()
    } else {
        let mut r = ratios.clone();
        r.sort_by(f64::total_cmp);
        format!("min {:.3} median {:.3}", r[0], r[r.len() / 2])
    };
    let slowest = outcomes.iter().map(|o| o.millis).fold(0.0, f64::max);
    let mean = outcomes.iter().map(|o| o.millis).sum::<f64>() / n;
    let mut text = format!(
        "\n[{:<16}] right first {right}/{} ({:.0} %) | none {none}/{} | recovered {recovered}/{} ({:.0} %) | \
         first-step RMSE ratio {ratio_text} | diagnose {mean:.0} ms mean, {slowest:.0} ms max | \
         {:.1} s total",
        kind.expected().id(),
        outcomes.len(),
        100.0 * right as f64 / n,
        outcomes.len(),
        outcomes.len(),
        100.0 * recovered as f64 / n,
        clock.elapsed().as_secs_f64()
    );
    for o in &outcomes {
        let wrong = if kind == Kind::Clean {
            !o.none
        } else {
            !o.right_first() || !o.recovered()
        };
        if wrong {
            text += &format!("\n  FAIL {}", o.describe());
        }
    }
    eprintln!("{text}");
    outcomes
}

/// The outcomes of every case of `kind`, computed once per test binary (the pooled recovery
/// test shares them with the per-effect tests).
fn outcomes(kind: Kind) -> &'static [Outcome] {
    static CACHE: [OnceLock<Vec<Outcome>>; 12] = [const { OnceLock::new() }; 12];
    CACHE[kind.ordinal() - 1].get_or_init(|| run_kind(kind))
}

/// The acceptance of one missing effect: named first, and the first step pays.
fn accept(kind: Kind) {
    let outcomes = outcomes(kind);
    let n = outcomes.len() as f64;
    let failures = |pred: &dyn Fn(&Outcome) -> bool| {
        outcomes
            .iter()
            .filter(|o| pred(o))
            .map(|o| format!("  {}", o.describe()))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let right = outcomes.iter().filter(|o| o.right_first()).count() as f64;
    let paid_badly =
        failures(&|o| o.right_first() && !o.first_ratio.is_some_and(|r| r > MIN_RMSE_RATIO));
    assert!(
        paid_badly.is_empty(),
        "{}: a correctly named first step did not lower the RMSE:\n{paid_badly}",
        kind.expected().id()
    );
    assert!(
        right / n >= MIN_RIGHT_FIRST,
        "{}: named first in {right}/{n} cases, below {:.0} %:\n{}",
        kind.expected().id(),
        100.0 * MIN_RIGHT_FIRST,
        failures(&|o| !o.right_first())
    );
}

const EFFECTS: [Kind; 8] = [
    Kind::Missing(Cause::DeadTime),
    Kind::Missing(Cause::Offset),
    Kind::Missing(Cause::Oscillation),
    Kind::Missing(Cause::ExtraPole),
    Kind::Missing(Cause::Zero),
    Kind::Missing(Cause::InverseResponse),
    Kind::Missing(Cause::Integrator),
    Kind::Missing(Cause::Drift),
];

// ---------------------------------------------------------------------------------------------
// The tests
// ---------------------------------------------------------------------------------------------

#[test]
fn a_missing_dead_time_is_named_first() {
    accept(Kind::Missing(Cause::DeadTime));
}

#[test]
fn a_held_zero_offset_is_named_first() {
    accept(Kind::Missing(Cause::Offset));
}

#[test]
fn a_missing_oscillation_is_named_first() {
    accept(Kind::Missing(Cause::Oscillation));
}

#[test]
fn a_missing_extra_pole_is_named_first() {
    accept(Kind::Missing(Cause::ExtraPole));
}

#[test]
fn a_missing_zero_is_named_first() {
    accept(Kind::Missing(Cause::Zero));
}

#[test]
fn a_missing_inverse_response_is_named_first() {
    accept(Kind::Missing(Cause::InverseResponse));
}

#[test]
fn a_missing_integrator_is_named_first() {
    accept(Kind::Missing(Cause::Integrator));
}

#[test]
fn a_missing_drift_is_named_first() {
    accept(Kind::Missing(Cause::Drift));
}

/// Over all the non-clean cases, the final model recovers Kp and the true time constants.
#[test]
fn the_extended_model_recovers_the_truth() {
    let mut total = 0usize;
    let mut recovered = 0usize;
    let mut text = String::new();
    for kind in EFFECTS {
        let o = outcomes(kind);
        let r = o.iter().filter(|o| o.recovered()).count();
        total += o.len();
        recovered += r;
        text += &format!("  {:<16} {r}/{}\n", kind.expected().id(), o.len());
        for o in o.iter().filter(|o| !o.recovered()) {
            text += &format!("    {}\n", o.describe());
        }
    }
    let rate = recovered as f64 / total as f64;
    eprintln!(
        "\n[recovery] {recovered}/{total} ({:.0} %) within {:.0} %:\n{text}",
        100.0 * rate,
        100.0 * RECOVERY_TOLERANCE
    );
    assert!(
        rate >= MIN_RECOVERED,
        "the final model recovers the truth within {:.0} % in {recovered}/{total} cases, below {:.0} %:\n{text}",
        100.0 * RECOVERY_TOLERANCE,
        100.0 * MIN_RECOVERED
    );
}

#[test]
fn a_model_that_is_the_truth_comes_out_none() {
    let outcomes = outcomes(Kind::Clean);
    let none = outcomes.iter().filter(|o| o.none).count() as f64;
    let n = outcomes.len() as f64;
    let failures: Vec<String> = outcomes
        .iter()
        .filter(|o| !o.none)
        .map(|o| format!("  {}", o.describe()))
        .collect();
    assert!(
        none / n >= MIN_CLEAN_NONE,
        "clean: `none` in {none}/{n} cases, below {:.0} %:\n{}",
        100.0 * MIN_CLEAN_NONE,
        failures.join("\n")
    );
}

/// The generator itself: noise-free data of every kind, fitted in the true structure from the
/// true values, gives back the truth (residuals ~ 0, parameters within 1e-6).
#[test]
fn noise_free_cases_round_trip_through_the_true_structure() {
    /// The truth's precision (relative) given back by a fit from it on its noise-free data.
    const ROUND_TRIP_TOLERANCE: f64 = 1e-6;
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    for kind in EFFECTS.into_iter().chain([Kind::Clean]) {
        for index in 0..3 {
            let case = generate(kind, index, false);
            assert_eq!(case.noise_sd, 0.0);
            let truth = case.truth;
            let report = fit(&case.data, truth.structure, truth.values, &options, &mut ())
                .unwrap_or_else(|e| panic!("{}: {e}", case.describe()));
            assert!(
                report.rmse <= 1e-9 * case.effect,
                "{}: RMSE {} of the truth on its own noise-free data",
                case.describe(),
                report.rmse
            );
            for p in truth.structure.params() {
                let (est, tru) = (report.model.get(p), truth.get(p));
                assert!(
                    (est - tru).abs() <= ROUND_TRIP_TOLERANCE * tru.abs().max(1.0),
                    "{}: {} = {est} fitted, {tru} true",
                    case.describe(),
                    p.name()
                );
            }
        }
    }
}

/// The generator keeps its promises: ranges, no sample before t0 in the offset cases, the
/// ramp's rise and the drift's share, and fixed seeds give the same data.
#[test]
fn the_generator_keeps_its_ranges() {
    for kind in EFFECTS.into_iter().chain([Kind::Clean]) {
        for index in 0..kind.cases() {
            let case = generate(kind, index, true);
            let again = generate(kind, index, true);
            assert_eq!(case.data, again.data, "{}", case.describe());
            let d = &case.data;
            let v = &case.truth.values;
            let n = d.times.len();
            assert!((SAMPLES.0..=SAMPLES.1).contains(&n), "{}", case.describe());
            let du = d.input.du().abs();
            assert!(du >= DU.0 && du <= DU.1, "{}", case.describe());
            let record = d.times[n - 1] - d.times[0];
            let t0_share = (case.t_change - d.times[0]) / record;
            let lead = d.input.t0() - case.t_change;
            assert!(
                lead >= 0.0 && lead < d.input.lead_range,
                "{}: the step must come inside the sampling period before the sample showing it",
                case.describe()
            );
            let sd_share = case.noise_sd / case.effect;
            assert!(
                sd_share >= NOISE_FRACTION.0 && sd_share <= NOISE_FRACTION.1,
                "{}",
                case.describe()
            );
            if kind == Kind::Missing(Cause::Offset) {
                assert_eq!(d.times[0], d.input.t0(), "{}", case.describe());
                assert!(v.get(Param::Y0).abs() >= MIN_OFFSET_FRACTION * case.effect);
                assert_eq!(case.start_y0, 0.0);
            } else {
                assert!(
                    t0_share >= T0_FRACTION.0 - 1e-12 && t0_share <= T0_FRACTION.1 + 1e-12,
                    "{}",
                    case.describe()
                );
                assert_eq!(case.start_y0, v.get(Param::Y0));
            }
            if kind == Kind::Missing(Cause::Integrator) {
                let rise = (case.truth.simulate(&d.input, &d.times[n - 1..]).unwrap()[0]
                    - v.get(Param::Y0))
                .abs()
                    / du;
                assert!(
                    rise >= RAMP_RISE.0 * 0.999 && rise <= RAMP_RISE.1 * 1.001,
                    "{}: rise {rise}",
                    case.describe()
                );
            } else {
                let kp = v.get(Param::Kp).abs();
                assert!(kp >= KP.0 && kp <= KP.1, "{}", case.describe());
            }
            if kind == Kind::Missing(Cause::Drift) {
                let share = (v.get(Param::Drift) * record).abs() / case.effect;
                assert!(
                    share >= DRIFT_FRACTION.0 && share <= DRIFT_FRACTION.1,
                    "{}",
                    case.describe()
                );
            }
            // Exactly one effect missing: the start differs from the truth in one feature.
            let (t, s) = (case.truth.structure, case.start);
            let differences = [
                t.poles != s.poles,
                t.delay != s.delay,
                t.underdamped != s.underdamped,
                t.zero != s.zero,
                t.integrator != s.integrator,
                t.drift != s.drift,
                kind == Kind::Missing(Cause::Offset),
            ]
            .into_iter()
            .filter(|&d| d)
            .count();
            let expected = if kind == Kind::Clean { 0 } else { 1 };
            // P2D → P2DU changes the pole description, not the count.
            assert_eq!(differences, expected, "{}", case.describe());
            assert!(!s.free_offset);
        }
    }
}

/// Two effects hidden at once, from a P1 start: one of them is named first.
#[test]
fn a_dead_time_and_an_extra_pole_at_once_are_found() {
    accept(Kind::DeadTimeAndPole);
}

#[test]
fn a_dead_time_and_an_oscillation_at_once_are_found() {
    accept(Kind::DeadTimeAndOscillation);
}

/// A strong lead zero from P1: no single extension may pay, the pair P1 → P2Z does.
#[test]
fn a_strong_lead_zero_from_p1_is_found() {
    accept(Kind::LeadZero);
}
