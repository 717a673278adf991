//! Frequency facts of a plant with a true dead time and of the loop L(s) = C(s)·G0(s)·e^{−θs}
//! around it, the delay never replaced by a Padé approximant: the plant's unwrapped phase and
//! its ultimate gain and period ([`ultimate`]), L(jω) ([`loop_at`]), the number of closed-loop
//! roots in the right half-plane by the argument principle ([`closed_loop_unstable_roots`])
//! and the peak of the sensitivity ([`max_sensitivity`]). The Nyquist view stands on these.

use std::f64::consts::PI;

use serde::Serialize;

use crate::TransferFunction;
use crate::control::Controller;
use crate::golden::golden_max;
use crate::poly::{self, C64};

/// The ultimate (critical) gain and period of a plant under proportional control: the
/// phase of G(jω) reaches −180° at ω = `wcr`, so Kc = `kcr` puts the loop on the edge of
/// stability, oscillating with the period `pcr` = 2π/`wcr`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ultimate {
    /// Kcr = 1/|G(jωcr)|, with the sign of the plant's static gain.
    pub kcr: f64,
    /// Pcr = 2π/ωcr (s).
    pub pcr: f64,
    /// ωcr (rad/s), the phase crossover.
    pub wcr: f64,
}

/// The peak of the sensitivity |S(jω)| = |1/(1 + L(jω))| and where it is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sensitivity {
    /// Ms = sup over ω > 0 of |S(jω)|.
    pub ms: f64,
    /// The ω (rad/s) of the peak; infinite when the supremum is the high-frequency limit.
    pub w: f64,
}

/// Why the closed-loop roots in the right half-plane could not be counted.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum StabilityError {
    /// χ(jω) vanishes to rounding near this ω ≥ 0: closed-loop roots on the imaginary axis.
    Marginal { w: f64 },
    /// With a dead time, |L(s)| tends to this value ≥ 1 at high frequency (a neutral loop
    /// with infinitely many roots at or beyond the imaginary axis).
    Neutral { ratio: f64 },
    /// Without dead time, 1 + L(∞) = 0: the loop is not well posed.
    IllPosed,
    /// The count did not come within 0.05 of a whole number (or the frequencies to walk
    /// were too many).
    Unresolved { count: f64 },
    /// The roots of the controller's or the loop's polynomials were not found.
    Roots,
}

/// Samples of the phase crossover search and of the sensitivity per decade.
const PER_DECADE: f64 = 200.0;

/// The largest change of ωθ (rad) between two samples of a frequency grid.
const DELAY_STEP: f64 = 0.1;

/// The most frequencies the argument principle walks before giving up.
const MAX_SAMPLES: usize = 4_000_000;

/// L(jω) = C(jω)·G(jω), the dead time exact.
pub fn loop_at(plant: &TransferFunction, c: &Controller, w: f64) -> C64 {
    let s = C64::new(0.0, w);
    c.eval(s) * plant.eval(s)
}

/// The ultimate gain and period of `g` ([`Ultimate`]): the smallest ω > 0 where the phase of
/// G(jω) = G0(jω)·e^{−jωθ}, unwrapped continuously from ω → 0+ for the plant taken with the
/// sign of its static gain, is an odd multiple of −180° (the phase crossover), solved by
/// bisection on a bracket to the last bit. None when the phase never gets there.
pub fn ultimate(g: &TransferFunction) -> Option<Ultimate> {
    let phase = Phase::of(g);
    let scales = root_scales(g.zeros().iter().chain(g.poles()), g.delay());
    let (lo, hi) = scan_range(&scales, g.delay(), g.zeros().len() + g.poles().len())?;
    let extra = resonances(g.zeros().iter().chain(g.poles()));
    let grid = frequency_grid(lo, hi, g.delay(), &extra);
    let mut previous = (grid[0], branch(phase.at(grid[0])));
    for &w in &grid[1..] {
        let b = branch(phase.at(w));
        if b != previous.1 {
            // Down through the bottom of the previous interval, or up through its top.
            let edge = if b < previous.1 {
                previous.1
            } else {
                previous.1 + 1
            };
            let target = PI + 2.0 * PI * edge as f64;
            let wcr = bisect(|x| phase.at(x) - target, previous.0, w);
            let kcr = phase.sign / g.eval(C64::new(0.0, wcr)).norm();
            return (kcr.is_finite() && wcr > 0.0).then_some(Ultimate {
                kcr,
                pcr: 2.0 * PI / wcr,
                wcr,
            });
        }
        previous = (w, b);
    }
    None
}

/// Which interval [π + 2πb, π + 2π(b + 1)) a phase lies in.
fn branch(phase: f64) -> i64 {
    ((phase - PI) / (2.0 * PI)).floor() as i64
}

/// The root of `f` between `a` and `b` (where its signs differ), to the last bit.
pub(crate) fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if (f(mid) < 0.0) == (fa < 0.0) {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}

/// The phase of σ·G(jω), σ the sign of G's low-frequency gain: each zero's and pole's angle
/// followed continuously from ω = 0, the integrators' −90° each, and −ωθ.
struct Phase {
    zeros: Vec<C64>,
    poles: Vec<C64>,
    /// Net integrators (poles at the origin less zeros there).
    integrators: i32,
    delay: f64,
    /// σ: the sign of G(s)·s^type as s → 0+.
    sign: f64,
}

impl Phase {
    fn of(g: &TransferFunction) -> Self {
        let off = |roots: &[C64]| -> Vec<C64> {
            roots.iter().copied().filter(|r| *r != C64::ZERO).collect()
        };
        let (zeros, poles) = (off(g.zeros()), off(g.poles()));
        // Conjugate pairs give |r|² > 0; each real root r gives the sign of −r.
        let sign_of = |roots: &[C64]| {
            roots
                .iter()
                .filter(|r| r.im == 0.0)
                .fold(1.0, |acc, r| acc * (-r.re).signum())
        };
        let sign = g.gain().signum() * sign_of(&zeros) * sign_of(&poles);
        Self {
            zeros,
            poles,
            integrators: g.system_type(),
            delay: g.delay(),
            sign,
        }
    }

    /// The unwrapped phase (rad) at ω > 0.
    fn at(&self, w: f64) -> f64 {
        let turn = |roots: &[C64]| roots.iter().map(|&r| angle_change(r, w)).sum::<f64>();
        turn(&self.zeros)
            - turn(&self.poles)
            - f64::from(self.integrators) * PI / 2.0
            - w * self.delay
    }
}

/// How much the angle of jω − r has turned since ω = 0, followed continuously (a root on
/// the imaginary axis turns it by ±180° at once where ω passes it).
fn angle_change(r: C64, w: f64) -> f64 {
    let (a, b) = (r.re, r.im);
    if a == 0.0 {
        return ((w - b).signum() - (-b).signum()) * PI / 2.0;
    }
    let side = -a.signum();
    side * (((w - b) / a.abs()).atan() - (-b / a.abs()).atan())
}

/// The frequencies that set the scale of a transfer function: its roots' moduli (the origin
/// left out) and 1/θ.
pub(crate) fn root_scales<'a>(roots: impl Iterator<Item = &'a C64>, delay: f64) -> Vec<f64> {
    let mut scales: Vec<f64> = roots.map(|r| r.norm()).filter(|&m| m > 0.0).collect();
    if delay > 0.0 {
        scales.push(1.0 / delay);
    }
    scales
}

/// The range the phase crossover is looked for in: from 10⁻⁴ of the slowest scale to past
/// where the rational part's phase has settled and the delay has turned a full
/// (roots + 2)·180° more.
fn scan_range(scales: &[f64], delay: f64, roots: usize) -> Option<(f64, f64)> {
    let slowest = scales.iter().copied().fold(f64::INFINITY, f64::min);
    let fastest = scales.iter().copied().fold(0.0, f64::max);
    if !slowest.is_finite() {
        return None;
    }
    let mut hi = fastest * 1e4;
    if delay > 0.0 {
        hi = (fastest * 1e3).max(PI * (roots as f64 + 2.0) / delay);
    }
    Some((slowest * 1e-4, hi))
}

/// Frequencies around each lightly damped root's ω = Im r, where the phase turns fast.
pub(crate) fn resonances<'a>(roots: impl Iterator<Item = &'a C64>) -> Vec<f64> {
    let mut out = Vec::new();
    for r in roots.filter(|r| r.im > 0.0) {
        for i in -24..=24 {
            out.push(r.im + f64::from(i) * 0.25 * r.re.abs());
        }
    }
    out
}

/// A grid from `lo` to `hi`: [`PER_DECADE`] points a decade, never more than
/// [`DELAY_STEP`]/θ apart, with the `extra` frequencies inside the range added.
pub(crate) fn frequency_grid(lo: f64, hi: f64, delay: f64, extra: &[f64]) -> Vec<f64> {
    let ratio = 10f64.powf(1.0 / PER_DECADE) - 1.0;
    let cap = if delay > 0.0 {
        DELAY_STEP / delay
    } else {
        f64::INFINITY
    };
    let mut grid = vec![lo];
    let mut w = lo;
    while w < hi {
        w += (w * ratio).min(cap);
        grid.push(w);
    }
    grid.extend(extra.iter().copied().filter(|&x| x > lo && x < hi));
    grid.sort_by(f64::total_cmp);
    grid.dedup();
    grid
}

/// The characteristic quasi-polynomial χ(s) = d(s) + n(s)·e^{−θs} of the loop, d = d_c·d_g and
/// n = n_c·n_g, divided by a polynomial q(s) = q₀·Π(s − r̃) with d's roots (those on the
/// imaginary axis moved left), so that w = χ/q is continuous on the axis and tends to 1.
struct Characteristic {
    /// d's roots, and the same moved off the imaginary axis.
    roots: Vec<C64>,
    shifted: Vec<C64>,
    d_lead: f64,
    q_lead: f64,
    d: Vec<f64>,
    n: Vec<f64>,
    delay: f64,
}

impl Characteristic {
    fn of(plant: &TransferFunction, c: &Controller) -> Result<Self, StabilityError> {
        let (nc, dc) = c.feedback_coeffs();
        let dc_roots = poly::roots(&dc).map_err(|_| StabilityError::Roots)?;
        let d = crate::locus::multiply(&dc, &plant.den());
        let n = crate::locus::multiply(&nc, &plant.num());
        let mut roots = dc_roots;
        roots.extend_from_slice(plant.poles());
        let scale = geometric_scale(&root_scales(roots.iter(), plant.delay()));
        let shifted = roots
            .iter()
            .map(|&r| {
                if r.re == 0.0 {
                    r - 0.5 * r.norm().max(scale)
                } else {
                    r
                }
            })
            .collect();
        let d_lead = d[0];
        let same_degree = n.len() == d.len();
        let q_lead = if plant.delay() == 0.0 && same_degree {
            d_lead + n[0]
        } else {
            d_lead
        };
        if q_lead == 0.0 || !q_lead.is_finite() {
            return Err(StabilityError::IllPosed);
        }
        if plant.delay() > 0.0 && same_degree && (n[0] / d_lead).abs() >= 1.0 {
            return Err(StabilityError::Neutral {
                ratio: (n[0] / d_lead).abs(),
            });
        }
        Ok(Self {
            roots,
            shifted,
            d_lead,
            q_lead,
            d,
            n,
            delay: plant.delay(),
        })
    }

    /// w(jω) = χ(jω)/q(jω).
    fn at(&self, w: f64) -> C64 {
        let s = C64::new(0.0, w);
        let mut ratio = C64::new(self.d_lead / self.q_lead, 0.0);
        let mut base = C64::new(self.q_lead, 0.0);
        for (&r, &t) in self.roots.iter().zip(&self.shifted) {
            if r != t {
                ratio *= (s - r) / (s - t);
            }
            base *= s - t;
        }
        ratio + poly::eval_complex(&self.n, s) * (-s * self.delay).exp() / base
    }

    /// q's roots in the open right half-plane (d's there).
    fn right_roots(&self) -> usize {
        self.shifted.iter().filter(|r| r.re > 0.0).count()
    }

    /// A radius R past which |w(s) − 1| < 1 everywhere in the closed right half-plane: the
    /// bound |d − q|/|q| + |n|/|q| (each |e^{−θs}| ≤ 1) falls below (1 + ρ)/2, ρ = lim|n/d|.
    fn safe_radius(&self) -> Option<f64> {
        let with_delay = self.delay > 0.0;
        let q = poly_scaled(&poly::poly_from_roots(&self.shifted), self.q_lead);
        let mut p1: Vec<f64> = self.d.iter().zip(&q).map(|(a, b)| a - b).collect();
        if !with_delay {
            let offset = p1.len() - self.n.len();
            for (i, c) in self.n.iter().enumerate() {
                p1[offset + i] += c;
            }
        }
        let degree = self.d.len() - 1;
        let rho = if with_delay && self.n.len() == self.d.len() {
            (self.n[0] / self.d_lead).abs()
        } else {
            0.0
        };
        let target = 0.5 * (1.0 + rho);
        let largest = self.shifted.iter().map(|r| r.norm()).fold(0.0, f64::max);
        let mut radius = (2.0 * largest).max(f64::MIN_POSITIVE.sqrt());
        for _ in 0..200 {
            // Each term over R^degree, so nothing overflows.
            let over = |p: &[f64]| -> f64 {
                let top = p.len() - 1;
                p.iter()
                    .enumerate()
                    .map(|(i, c)| c.abs() * radius.powi(top as i32 - i as i32 - degree as i32))
                    .sum()
            };
            let mut bound = over(&p1);
            if with_delay {
                bound += over(&self.n);
            }
            let floor: f64 = self
                .shifted
                .iter()
                .map(|r| 1.0 - r.norm() / radius)
                .product();
            if bound / (self.q_lead.abs() * floor) <= target {
                return Some(radius);
            }
            radius *= 2.0;
        }
        None
    }
}

fn poly_scaled(p: &[f64], k: f64) -> Vec<f64> {
    p.iter().map(|c| c * k).collect()
}

/// The geometric mean of some frequencies (1 when there are none).
fn geometric_scale(scales: &[f64]) -> f64 {
    if scales.is_empty() {
        return 1.0;
    }
    (scales.iter().map(|s| s.ln()).sum::<f64>() / scales.len() as f64).exp()
}

/// How many roots the closed loop's characteristic quasi-polynomial
/// χ(s) = d_c(s)·d_g(s) + n_c(s)·n_g(s)·e^{−θs} has in the open right half-plane.
///
/// By the argument principle on the imaginary axis closed by a large half-circle in the
/// right half-plane: w = χ/q, q a polynomial with d's roots (those on the axis moved left,
/// so nothing needs indenting), is walked from ω = 0 to a radius R past which |w − 1| < 1 on
/// the whole right half-plane (so no root lies beyond, and the half-circle adds exactly
/// −2·Arg w(jR)); samples are taken so that w moves less than 0.2·|w| between them. Then
/// Z = Z_q − (Δarg_{0→R} w − Arg w(jR))/π, which must come within 0.05 of a whole number.
/// The loop may be retarded (L strictly proper) or neutral with |L(∞)| < 1.
pub fn closed_loop_unstable_roots(
    plant: &TransferFunction,
    c: &Controller,
) -> Result<usize, StabilityError> {
    let chi = Characteristic::of(plant, c)?;
    let radius = chi.safe_radius().ok_or(StabilityError::Unresolved {
        count: f64::INFINITY,
    })?;
    let turned = walk_argument(&chi, radius)?;
    let count = chi.right_roots() as f64 - (turned - chi.at(radius).arg()) / PI;
    let whole = count.round();
    if (count - whole).abs() > 0.05 || whole < 0.0 {
        return Err(StabilityError::Unresolved { count });
    }
    Ok(whole as usize)
}

/// Δarg w(jω) for ω from 0 to `radius`, sampled adaptively.
fn walk_argument(chi: &Characteristic, radius: f64) -> Result<f64, StabilityError> {
    let mut w_prev = chi.at(0.0);
    if vanishes(w_prev) {
        return Err(StabilityError::Marginal { w: 0.0 });
    }
    let (mut omega, mut step, mut turned) = (0.0, radius * 1e-9, 0.0);
    for _ in 0..MAX_SAMPLES {
        if omega >= radius {
            return Ok(turned);
        }
        let h = step.min(radius - omega);
        let mid = chi.at(omega + 0.5 * h);
        let next = chi.at(omega + h);
        let tolerance = 0.2 * w_prev.norm();
        if (next - w_prev).norm() <= tolerance && (mid - w_prev).norm() <= tolerance {
            turned += (next / w_prev).arg();
            omega += h;
            w_prev = next;
            step = h * 1.5;
            if vanishes(w_prev) {
                return Err(StabilityError::Marginal { w: omega });
            }
        } else {
            step = 0.5 * h;
            if step <= 4.0 * f64::EPSILON * omega.max(radius * 1e-12) {
                return Err(StabilityError::Marginal { w: omega });
            }
        }
    }
    Err(StabilityError::Unresolved { count: f64::NAN })
}

/// Whether w = χ/q is 0 to rounding (or not a number): w tends to 1 at high frequency, so
/// 1e-13 is far below its scale.
fn vanishes(w: C64) -> bool {
    w.norm().is_nan() || w.norm() <= 1e-13
}

/// Ms, the peak of |1/(1 + L(jω))| over ω > 0, with its frequency: a grid of
/// 200 points a decade at most 0.1/θ apart (ωθ moves 0.1 rad at most), out to where |L| is too
/// small to raise |S| above the peak found, each local peak near the highest refined by a
/// golden-section search to 1e-9 relative; the high-frequency limit when it is higher
/// (1/(1 − |L(∞)|) for a biproper loop with a dead time). None unless the closed loop is
/// stable ([`closed_loop_unstable_roots`] gives 0).
pub fn max_sensitivity(plant: &TransferFunction, c: &Controller) -> Option<Sensitivity> {
    if closed_loop_unstable_roots(plant, c).ok()? != 0 {
        return None;
    }
    let (nc, dc) = c.feedback_coeffs();
    let n = crate::locus::multiply(&nc, &plant.num());
    let d = crate::locus::multiply(&dc, &plant.den());
    let c_roots = poly::roots(&dc).ok()?;
    let c_zeros = poly::roots(&nc).ok()?;
    let all: Vec<C64> = plant
        .zeros()
        .iter()
        .chain(plant.poles())
        .chain(&c_roots)
        .chain(&c_zeros)
        .copied()
        .collect();
    let scales = root_scales(all.iter(), plant.delay());
    let slowest = scales.iter().copied().fold(f64::INFINITY, f64::min);
    let fastest = scales.iter().copied().fold(0.0, f64::max);
    let lo = if slowest.is_finite() {
        slowest * 1e-3
    } else {
        1e-3
    };
    let extra = resonances(all.iter());
    let s_at = |w: f64| 1.0 / (1.0 + loop_at(plant, c, w)).norm();
    let hi = (fastest * 10.0).max(last_crossing(&n, &d, 0.5)?);
    let mut grid = frequency_grid(lo, hi, plant.delay(), &extra);
    let mut values: Vec<f64> = grid.iter().map(|&w| s_at(w)).collect();
    let peak = values.iter().copied().fold(0.0, f64::max);
    let delta = (1.0 - 1.0 / peak).max(1e-3);
    let further = last_crossing(&n, &d, delta)?;
    if further > hi {
        let more = frequency_grid(hi, further, plant.delay(), &extra);
        values.extend(more.iter().skip(1).map(|&w| s_at(w)));
        grid.extend(more.into_iter().skip(1));
    }
    let best = refine_peaks(&grid, &values, s_at);
    let tail = high_frequency_limit(&n, &d, plant.delay());
    if tail > best.ms {
        return Some(Sensitivity {
            ms: tail,
            w: f64::INFINITY,
        });
    }
    Some(best)
}

/// The supremum of |S| as ω → ∞: 1 for a strictly proper loop; for a biproper one with
/// L(∞) = ℓ, 1/(1 − |ℓ|) with a dead time (its phase turns forever), else 1/|1 + ℓ|.
fn high_frequency_limit(n: &[f64], d: &[f64], delay: f64) -> f64 {
    if n.len() < d.len() {
        return 1.0;
    }
    let ell = n[0] / d[0];
    if delay > 0.0 {
        1.0 / (1.0 - ell.abs())
    } else {
        1.0 / (1.0 + ell).abs()
    }
}

/// The largest ω ≥ 0 where |n(jω)| = δ·|d(jω)| (0 when none): past it |L(jω)| < δ for good
/// (δ above the high-frequency limit of |n/d|). None when the roots are not found.
pub(crate) fn last_crossing(n: &[f64], d: &[f64], delta: f64) -> Option<f64> {
    let nn = abs2_in_omega2(n);
    let dd = abs2_in_omega2(d);
    let len = nn.len().max(dd.len());
    let mut p = vec![0.0; len];
    for (i, c) in nn.iter().enumerate() {
        p[len - nn.len() + i] += c;
    }
    for (i, c) in dd.iter().enumerate() {
        p[len - dd.len() + i] -= delta * delta * c;
    }
    let first = p.iter().position(|&c| c != 0.0)?;
    let p = &p[first..];
    if p.len() == 1 {
        return Some(0.0);
    }
    let roots = poly::roots(p).ok()?;
    let largest = roots
        .iter()
        .filter(|r| r.im.abs() <= 1e-9 * r.norm() && r.re > 0.0)
        .map(|r| r.re)
        .fold(0.0, f64::max);
    Some(largest.sqrt() * (1.0 + 1e-6))
}

/// |p(jω)|² as a polynomial in x = ω² (descending powers): p(s)·p(−s) has only even powers,
/// and s² = −x.
fn abs2_in_omega2(p: &[f64]) -> Vec<f64> {
    let degree = p.len() - 1;
    let mirrored: Vec<f64> = p
        .iter()
        .enumerate()
        .map(|(i, c)| if (degree - i) % 2 == 1 { -c } else { *c })
        .collect();
    let product = crate::locus::multiply(p, &mirrored);
    // product has degree 2·degree; keep the even powers s^(2m), m = degree … 0.
    (0..=degree)
        .map(|i| {
            let m = degree - i;
            let c = product[2 * i];
            if m % 2 == 1 { -c } else { c }
        })
        .collect()
}

/// The highest of the grid's local peaks, each within 10 % of the top refined by a
/// golden-section search between its neighbours.
fn refine_peaks(grid: &[f64], values: &[f64], f: impl Fn(f64) -> f64) -> Sensitivity {
    let top = values.iter().copied().fold(0.0, f64::max);
    let mut best = Sensitivity { ms: 0.0, w: 0.0 };
    for i in 0..values.len() {
        let left = if i == 0 { 0.0 } else { values[i - 1] };
        let right = values.get(i + 1).copied().unwrap_or(0.0);
        if values[i] < left || values[i] < right || values[i] < 0.9 * top {
            continue;
        }
        let a = grid[i.saturating_sub(1)];
        let b = grid[(i + 1).min(grid.len() - 1)];
        let (w, ms) = golden_max(&f, a, b, 1e-12);
        let (w, ms) = if ms >= values[i] {
            (w, ms)
        } else {
            (grid[i], values[i])
        };
        if ms > best.ms {
            best = Sensitivity { ms, w };
        }
    }
    best
}
