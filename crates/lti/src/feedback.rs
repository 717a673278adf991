//! The unity-feedback loop around a proportional gain K·G(s), and what a course asks of it:
//! the steady-state error constants (system type, Kp, Kv, Ka) and errors for a step, a ramp
//! and a parabola; the responses to those inputs and to an impulse; the gain (or range of
//! gains) meeting overshoot, settling, rise and steady-state error specs, judged on the exact
//! closed-loop step response; and the second-order formulas (ζ, ωn, t_s ≈ 4/(ζωn), t_p,
//! t_r, Mp) beside the exact metrics, with their inverse (a pair of specs to ζ, ωn and the
//! canonical G(s)).
//!
//! A closed loop around a dead time is not rational: every exact function here refuses it
//! ([`LtiError::DelayInLoop`]). A caller that wants the loop anyway asks for
//! [`RationalLoop::new`]: G with e^{−θs} replaced by its Padé (m, n) approximant, and the
//! approximant recorded so that everything drawn or printed from it says it is approximate.
//! The library stays strict; the replacement is explicit at the call sites (the Design
//! mode's loop, `degrau loop`).

use serde::{Deserialize, Serialize};

use super::approx::{ApproxError, delay_free_with_pade};
use super::locus::{self, Side};
use super::poly::C64;
use super::tf::TransferFunction;
use super::{LtiError, StepInfo, StepInfoOptions, StepResponse};

/// The order (m, n) of the Padé approximant a loop around a dead time uses: m zeros, n
/// poles, m ≤ n, 1 ≤ n ≤ [`PadeOrder::MAX_N`].
///
/// The default (3, 3) matches e^{−θs}'s Taylor series to order 6, and its phase stays within
/// about 1° of the delay's −ωθ up to ωθ = π: past the frequency where the delay alone lags
/// 180°, so far past any loop's crossover. A lower order is visibly off there ((1, 1) lags
/// only 115° at ωθ = π); a higher one adds poles and zeros that crowd the root locus with
/// branches of no interest and worsen the conditioning of the closed loop's roots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct PadeOrder {
    pub m: usize,
    pub n: usize,
}

impl Default for PadeOrder {
    fn default() -> Self {
        Self { m: 3, n: 3 }
    }
}

impl PadeOrder {
    /// The largest n offered (beyond it the coefficients span too many decades).
    pub const MAX_N: usize = 8;

    /// Whether 1 ≤ n ≤ [`Self::MAX_N`] and m ≤ n.
    pub fn is_valid(self) -> bool {
        (1..=Self::MAX_N).contains(&self.n) && self.m <= self.n
    }

    /// The orders offered in a choice: (n − 1, n) and (n, n) for n = 1 … [`Self::MAX_N`].
    pub fn offered() -> Vec<PadeOrder> {
        (1..=Self::MAX_N)
            .flat_map(|n| [PadeOrder { m: n - 1, n }, PadeOrder { m: n, n }])
            .collect()
    }
}

/// The rational stand-in a loop around a dead time uses (recorded so that the result is
/// labelled approximate): Padé (m, n) of e^{−θs}, θ = `delay` seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoopApproximant {
    /// Always `"pade"` (a stable JSON key).
    pub kind: &'static str,
    pub m: usize,
    pub n: usize,
    /// θ (s).
    pub delay: f64,
}

/// The open loop a closed loop is built from: G itself when it has no dead time (exact), or
/// G with its dead time replaced by a Padé approximant (`approximant` says which: everything
/// derived from `g` is then approximate).
#[derive(Debug, Clone, PartialEq)]
pub struct RationalLoop {
    /// The rational open loop (no delay).
    pub g: TransferFunction,
    /// `None` when `g` is the system itself.
    pub approximant: Option<LoopApproximant>,
}

impl RationalLoop {
    /// `system` made rational with Padé `order` when it has a dead time.
    pub fn new(system: &TransferFunction, order: PadeOrder) -> Result<Self, ApproxError> {
        let PadeOrder { m, n } = order;
        let g = delay_free_with_pade(system, m, n)?;
        let approximant = (system.delay() != 0.0).then(|| LoopApproximant {
            kind: "pade",
            m,
            n,
            delay: system.delay(),
        });
        Ok(Self { g, approximant })
    }
}

/// The input a response is computed for.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Input {
    /// A unit impulse δ(t) (times the amplitude).
    Impulse,
    /// A step of the amplitude.
    #[default]
    Step,
    /// A ramp A·t.
    Ramp,
    /// A parabola A·t²/2.
    Parabola,
}

/// The response of G to an input of amplitude A: the step response of G·s^{−n} (n = 1 for a
/// ramp, 2 for a parabola), or the derivative of G's step response for the impulse.
#[derive(Debug, Clone)]
pub struct InputResponse {
    pub input: Input,
    /// The step response whose value (or, for the impulse, whose derivative) is y(t).
    pub step: StepResponse,
}

impl InputResponse {
    pub fn new(g: &TransferFunction, input: Input, amplitude: f64) -> Result<Self, LtiError> {
        let integrators = match input {
            Input::Impulse | Input::Step => 0,
            Input::Ramp => 1,
            Input::Parabola => 2,
        };
        let step = StepResponse::new(&with_integrators(g, integrators)?, amplitude)?;
        Ok(Self { input, step })
    }

    /// y(t): for the impulse, the response for t > θ (a biproper G adds A·G(∞)·δ(t − θ),
    /// which no sample can show).
    pub fn value(&self, t: f64) -> f64 {
        match self.input {
            Input::Impulse => self.step.derivative(t),
            _ => self.step.value(t),
        }
    }

    /// `n` samples of y over [t0, t1].
    pub fn sample_uniform(&self, t0: f64, t1: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
        match self.input {
            Input::Impulse => {
                let t: Vec<f64> = (0..n)
                    .map(|i| t0 + (t1 - t0) * i as f64 / (n.max(2) - 1) as f64)
                    .collect();
                let y = t.iter().map(|&t| self.step.derivative(t)).collect();
                (t, y)
            }
            _ => self.step.sample_uniform(t0, t1, n),
        }
    }

    /// The closed form of y(t) (none for the impulse, which is the derivative of one).
    pub fn expression(&self, form: super::expr::OscillationForm) -> Option<String> {
        (self.input != Input::Impulse).then(|| super::expr::expression(&self.step, form))
    }

    /// The input itself at t (before its dead time there is none): δ drawn as 0.
    pub fn input_value(&self, t: f64) -> f64 {
        let a = self.step.amplitude();
        match self.input {
            Input::Impulse => 0.0,
            Input::Step => a,
            Input::Ramp => a * t,
            Input::Parabola => 0.5 * a * t * t,
        }
    }
}

/// G(s)/sⁿ: the same zeros, gain and delay with n more poles at the origin.
pub fn with_integrators(g: &TransferFunction, n: usize) -> Result<TransferFunction, LtiError> {
    if n == 0 {
        return Ok(g.clone());
    }
    let mut poles = g.poles().to_vec();
    poles.extend(std::iter::repeat_n(C64::new(0.0, 0.0), n));
    TransferFunction::from_zpk(g.zeros(), &poles, g.gain())?.with_delay(g.delay())
}

/// A constant of [`ErrorConstants`] or an error of [`SteadyStateErrors`]: finite, or ∞.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limit {
    Finite(f64),
    Infinite,
}

impl Limit {
    /// The number (∞ as `f64::INFINITY`).
    pub fn value(self) -> f64 {
        match self {
            Limit::Finite(x) => x,
            Limit::Infinite => f64::INFINITY,
        }
    }

    fn of(x: f64) -> Self {
        if x.is_finite() {
            Limit::Finite(x)
        } else {
            Limit::Infinite
        }
    }

    /// 1/(c + x): an error from a constant (1/∞ = 0, 1/0 = ∞).
    fn error(constant: Limit, plus: f64) -> Self {
        match constant {
            Limit::Infinite => Limit::Finite(0.0),
            Limit::Finite(c) => Limit::of(1.0 / (c + plus)),
        }
    }
}

impl Serialize for Limit {
    /// A number, or the string `"inf"`.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Limit::Finite(x) => s.serialize_f64(*x + 0.0),
            Limit::Infinite => s.serialize_str("inf"),
        }
    }
}

/// The static error constants of the open loop L(s) = K·G(s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ErrorConstants {
    /// The system type: the net number of integrators of L (negative: zeros at the origin).
    #[serde(rename = "type")]
    pub system_type: i32,
    /// Kp = lim_{s→0} L(s).
    pub kp: Limit,
    /// Kv = lim_{s→0} s·L(s).
    pub kv: Limit,
    /// Ka = lim_{s→0} s²·L(s).
    pub ka: Limit,
}

impl ErrorConstants {
    /// The constants of K·G (G without a dead time, which does not change them anyway).
    pub fn of(g: &TransferFunction, k: f64) -> Self {
        let n = g.system_type();
        // lim s^n·G(s): the gain over the roots that are not at the origin.
        let reduced =
            k * g.gain() * product_neg_nonzero(g.zeros()) / product_neg_nonzero(g.poles());
        // s^power·L(s) ~ reduced·s^(power − n) as s → 0.
        let constant = |power: i32| match power - n {
            0 => Limit::of(reduced),
            m if m > 0 => Limit::Finite(0.0),
            _ => Limit::Infinite,
        };
        Self {
            system_type: n,
            kp: constant(0),
            kv: constant(1),
            ka: constant(2),
        }
    }

    /// The steady-state errors of the unity-feedback loop for unit inputs (meaningful only
    /// when that loop is stable).
    pub fn errors(&self) -> SteadyStateErrors {
        SteadyStateErrors {
            step: Limit::error(self.kp, 1.0),
            ramp: Limit::error(self.kv, 0.0),
            parabola: Limit::error(self.ka, 0.0),
        }
    }
}

/// e_ss = lim e(t) for a unit step (1/(1 + Kp)), ramp (1/Kv) and parabola (1/Ka).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SteadyStateErrors {
    pub step: Limit,
    pub ramp: Limit,
    pub parabola: Limit,
}

use super::tf::product_neg_nonzero;

/// A design spec on the closed loop's unit-step response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Spec {
    /// Mp ≤ this (%).
    Overshoot(f64),
    /// t_s (2 % band) ≤ this (s).
    Settling(f64),
    /// t_r (10–90 %) ≤ this (s).
    Rise(f64),
    /// e_ss for a unit step ≤ this.
    EssStep(f64),
    /// e_ss for a unit ramp ≤ this.
    EssRamp(f64),
}

impl Spec {
    /// The limit of the spec.
    pub fn limit(self) -> f64 {
        match self {
            Spec::Overshoot(x)
            | Spec::Settling(x)
            | Spec::Rise(x)
            | Spec::EssStep(x)
            | Spec::EssRamp(x) => x,
        }
    }

    /// The stable key of the spec (`overshoot`, `settling`, `rise`, `ess_step`, `ess_ramp`).
    pub fn key(self) -> &'static str {
        match self {
            Spec::Overshoot(_) => "overshoot",
            Spec::Settling(_) => "settling",
            Spec::Rise(_) => "rise",
            Spec::EssStep(_) => "ess_step",
            Spec::EssRamp(_) => "ess_ramp",
        }
    }

    /// The spec of a key and a limit.
    pub fn from_key(key: &str, limit: f64) -> Option<Self> {
        Some(match key {
            "overshoot" => Spec::Overshoot(limit),
            "settling" => Spec::Settling(limit),
            "rise" => Spec::Rise(limit),
            "ess_step" => Spec::EssStep(limit),
            "ess_ramp" => Spec::EssRamp(limit),
            _ => return None,
        })
    }

    /// The measured value this spec bounds, for the loop around K·G (`None`: it does not
    /// exist, e.g. the loop is unstable), judged on the exact response.
    pub fn measure(self, g: &TransferFunction, k: f64) -> Option<f64> {
        let cl = g.closed_loop(k).ok()?;
        if !cl.is_stable() {
            return None;
        }
        let info = || {
            let r = StepResponse::new(&cl, 1.0).ok()?;
            Some(StepInfo::of_response(&r, &StepInfoOptions::default()))
        };
        match self {
            Spec::Overshoot(_) => info()?.overshoot,
            Spec::Settling(_) => info()?.settling_time,
            Spec::Rise(_) => info()?.rise_time,
            Spec::EssStep(_) => Some(ErrorConstants::of(g, k).errors().step.value()),
            Spec::EssRamp(_) => Some(ErrorConstants::of(g, k).errors().ramp.value()),
        }
    }

    /// Whether K meets the spec.
    pub fn holds(self, g: &TransferFunction, k: f64) -> bool {
        self.measure(g, k).is_some_and(|v| v <= self.limit())
    }
}

/// What the gain search found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GainSearch {
    /// The gain proposed: the smallest gain meeting every spec (the range's low end) or,
    /// when every small gain meets them (an overshoot bound), the largest (its high end).
    pub k: f64,
    /// The first range of K > 0 (from 0 up) in which every spec holds: [lo, hi], hi = ∞ when
    /// unbounded.
    pub range: (f64, f64),
    /// The closed-loop poles for `k`.
    pub poles: Vec<C64>,
}

/// Points of the coarse scan in K before the ends of the range are refined.
const SCAN_POINTS: usize = 240;
/// The range's ends are refined to this relative precision in K.
const GAIN_PRECISION: f64 = 1e-10;

/// The gains K > 0 for which the loop around K·G meets every spec, judged on the exact
/// closed-loop response: a scan over K (log-spaced, across the scale of the root locus),
/// then each end of the first feasible run refined by bisection. `None` when no K scanned
/// meets them all.
pub fn find_gain(g: &TransferFunction, specs: &[Spec]) -> Result<Option<GainSearch>, LtiError> {
    let g = g.clone();
    if g.delay() != 0.0 {
        return Err(LtiError::DelayInLoop);
    }
    let meets = |k: f64| specs.iter().all(|s| s.holds(&g, k));
    let (k_lo, k_hi) = scan_bounds(&g);
    let ratio = (k_hi / k_lo).powf(1.0 / (SCAN_POINTS - 1) as f64);
    let ks: Vec<f64> = (0..SCAN_POINTS)
        .map(|i| k_lo * ratio.powi(i as i32))
        .collect();
    let Some(first) = ks.iter().position(|&k| meets(k)) else {
        return Ok(None);
    };
    let lo = if first == 0 {
        0.0
    } else {
        refine(ks[first - 1], ks[first], &meets)
    };
    let last = ks[first..]
        .iter()
        .position(|&k| !meets(k))
        .map(|i| first + i);
    let hi = match last {
        None => f64::INFINITY,
        Some(i) => refine(ks[i], ks[i - 1], &meets),
    };
    let k = if lo > 0.0 {
        lo
    } else if hi.is_finite() {
        hi
    } else {
        ks[first]
    };
    let poles = g.closed_loop(k)?.poles().to_vec();
    Ok(Some(GainSearch {
        k,
        range: (lo, hi),
        poles,
    }))
}

/// The gain between `bad` and `good` where the specs start to hold, to [`GAIN_PRECISION`]:
/// the end nearest `bad` that still meets them.
fn refine(mut bad: f64, mut good: f64, meets: &impl Fn(f64) -> bool) -> f64 {
    while (good - bad).abs() > GAIN_PRECISION * good.abs().max(bad.abs()) {
        let mid = (bad * good).sqrt();
        let mid = if mid > bad.min(good) && mid < bad.max(good) {
            mid
        } else {
            0.5 * (bad + good)
        };
        if meets(mid) {
            good = mid;
        } else {
            bad = mid;
        }
    }
    good
}

/// The span of K to scan: from 1e-4 to 1e4 times the gain scale, and past the highest
/// crossing of the jω axis.
fn scan_bounds(g: &TransferFunction) -> (f64, f64) {
    let (num, den) = (g.num(), g.den());
    let scale = g
        .poles()
        .iter()
        .chain(g.zeros())
        .map(|r| r.norm())
        .fold(0.0f64, f64::max)
        .max(1e-3);
    let s = C64::new(0.0, scale);
    let k_scale = (super::poly::eval_complex(&den, s).norm()
        / super::poly::eval_complex(&num, s).norm())
    .clamp(1e-100, 1e100);
    let top = locus::crossings(&num, &den, Side::Positive)
        .iter()
        .map(|c| c.k)
        .fold(0.0, f64::max);
    (1e-4 * k_scale, (1e4 * k_scale).max(4.0 * top))
}

/// A standard second-order pair ωn²/(s² + 2ζωn s + ωn²), 0 < ζ < 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SecondOrder {
    pub zeta: f64,
    /// ωn (rad/s).
    pub wn: f64,
}

/// Why a pair of specs gives no underdamped second-order system.
/// Its words: [`crate::words::feedback`].
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum InverseError {
    /// The overshoot (%) is not in (0, 100).
    Overshoot(f64),
    /// A time (s) is not positive and finite.
    Time(f64),
}

/// Two specs or readings to turn into ζ and ωn.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpecPair {
    /// Mp (%) and t_s (s, 2 %: 4/(ζωn)).
    OvershootSettling { overshoot: f64, settling: f64 },
    /// Mp (%) and t_p (s).
    OvershootPeak { overshoot: f64, peak: f64 },
    /// t_s (s) and t_p (s).
    SettlingPeak { settling: f64, peak: f64 },
}

impl SecondOrder {
    /// The pair of poles σ ± jωd of the upper half plane first.
    pub fn poles(&self) -> [C64; 2] {
        let (s, wd) = (-self.sigma(), self.wd());
        [C64::new(s, wd), C64::new(s, -wd)]
    }

    /// σ = ζωn (1/s), the decay rate.
    pub fn sigma(&self) -> f64 {
        self.zeta * self.wn
    }

    /// ωd = ωn√(1 − ζ²) (rad/s).
    pub fn wd(&self) -> f64 {
        self.wn * (1.0 - self.zeta * self.zeta).sqrt()
    }

    /// t_s ≈ 4/(ζωn) (2 % band).
    pub fn settling_time(&self) -> f64 {
        4.0 / self.sigma()
    }

    /// t_p = π/ωd.
    pub fn peak_time(&self) -> f64 {
        std::f64::consts::PI / self.wd()
    }

    /// t_r (0–100 %) = (π − arccos ζ)/ωd.
    pub fn rise_time(&self) -> f64 {
        (std::f64::consts::PI - self.zeta.acos()) / self.wd()
    }

    /// Mp = 100·exp(−πζ/√(1 − ζ²)) (%).
    pub fn overshoot(&self) -> f64 {
        100.0 * (-std::f64::consts::PI * self.zeta / (1.0 - self.zeta * self.zeta).sqrt()).exp()
    }

    /// The canonical G(s) = ωn²/(s² + 2ζωn s + ωn²).
    pub fn transfer_function(&self) -> Result<TransferFunction, LtiError> {
        TransferFunction::from_zpk(&[], &self.poles(), self.wn * self.wn)
    }

    /// The pair of `poles` nearest the imaginary axis (the dominant one), when it is an
    /// underdamped stable pair.
    pub fn dominant(poles: &[C64]) -> Option<Self> {
        let p = poles
            .iter()
            .filter(|p| p.im > 0.0 && p.re < 0.0)
            .max_by(|a, b| a.re.total_cmp(&b.re))?;
        let wn = p.norm();
        Some(Self {
            zeta: -p.re / wn,
            wn,
        })
    }

    /// The ζ giving an overshoot of `mp` % (0 < mp < 100).
    pub fn damping_for_overshoot(mp: f64) -> Result<f64, InverseError> {
        if !(mp > 0.0 && mp < 100.0) {
            return Err(InverseError::Overshoot(mp));
        }
        let l = (mp / 100.0).ln();
        Ok(-l / (std::f64::consts::PI.powi(2) + l * l).sqrt())
    }

    /// ζ and ωn from a pair of specs.
    pub fn from_specs(pair: SpecPair) -> Result<Self, InverseError> {
        let time = |t: f64| {
            if t.is_finite() && t > 0.0 {
                Ok(t)
            } else {
                Err(InverseError::Time(t))
            }
        };
        match pair {
            SpecPair::OvershootSettling {
                overshoot,
                settling,
            } => {
                let zeta = Self::damping_for_overshoot(overshoot)?;
                Ok(Self {
                    zeta,
                    wn: 4.0 / (zeta * time(settling)?),
                })
            }
            SpecPair::OvershootPeak { overshoot, peak } => {
                let zeta = Self::damping_for_overshoot(overshoot)?;
                let wd = std::f64::consts::PI / time(peak)?;
                Ok(Self {
                    zeta,
                    wn: wd / (1.0 - zeta * zeta).sqrt(),
                })
            }
            SpecPair::SettlingPeak { settling, peak } => {
                let sigma = 4.0 / time(settling)?;
                let wd = std::f64::consts::PI / time(peak)?;
                let wn = sigma.hypot(wd);
                Ok(Self {
                    zeta: sigma / wn,
                    wn,
                })
            }
        }
    }
}

/// One second-order formula beside the exact metric.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Comparison {
    /// From the dominant pair's formula.
    pub formula: f64,
    /// Of the exact response (`None` when the metric does not exist).
    pub exact: Option<f64>,
}

impl Comparison {
    /// 100·(formula − exact)/exact, when both exist and exact ≠ 0.
    pub fn difference_percent(&self) -> Option<f64> {
        self.exact
            .filter(|e| *e != 0.0)
            .map(|e| 100.0 * (self.formula - e) / e)
    }
}

/// The formulas of the dominant pair beside the exact metrics of the system's response
/// (settling 2 %, rise 0–100 %, peak time, overshoot).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FormulaCheck {
    pub pair: SecondOrder,
    pub settling_time: Comparison,
    pub peak_time: Comparison,
    pub rise_time: Comparison,
    pub overshoot: Comparison,
}

impl FormulaCheck {
    /// For a system with a dominant underdamped pair (else `None`).
    pub fn of(g: &TransferFunction) -> Option<Self> {
        let pair = SecondOrder::dominant(g.poles())?;
        let r = StepResponse::new(g, 1.0).ok()?;
        let info = StepInfo::of_response(&r, &StepInfoOptions::default());
        let full_rise = StepInfoOptions {
            rise_limits: (0.0, 1.0),
            ..StepInfoOptions::default()
        };
        let rise = StepInfo::of_response(&r, &full_rise).rise_time;
        Some(Self {
            pair,
            settling_time: Comparison {
                formula: pair.settling_time(),
                exact: info.settling_time,
            },
            peak_time: Comparison {
                formula: pair.peak_time(),
                exact: info.peak_time,
            },
            rise_time: Comparison {
                formula: pair.rise_time(),
                exact: rise,
            },
            overshoot: Comparison {
                formula: pair.overshoot(),
                exact: info.overshoot,
            },
        })
    }
}
