//! The root locus of the unity-feedback loop around K·G(s): the roots of the characteristic
//! polynomial den(s) + K·num(s) as the loop gain K goes from 0 to ∞ (or, the complementary
//! locus, from 0 to −∞), with what a student reads off it: the asymptotes and their centroid,
//! the breakaway and break-in points on the real axis (where dK/ds = 0), and the crossings
//! of the imaginary axis with the critical gain and frequency.
//!
//! Every point is exact: the roots of den + K·num for that K, found by [`poly::roots`], never
//! an interpolation. The steps in K are adaptive: a step is halved until no root moves by
//! more than [`MAX_MOVE`] of the plane's scale (or of its own distance from the origin, along
//! the asymptotes), so the branches stay smooth where roots move fast (near a breakaway) and
//! the steps grow where they barely move. Roots are matched from one K to the next by
//! nearest distance, so each branch is one continuous curve.

use serde::{Deserialize, Serialize};

use super::LtiError;
use super::poly::{self, C64};
use super::tf::TransferFunction;

/// Largest move of a root between consecutive locus points, as a fraction of the plane's
/// scale (or of the root's own |s| when that is larger).
pub const MAX_MOVE: f64 = 0.02;
/// Most locus points computed for one system (each is one polynomial's roots).
pub const MAX_POINTS: usize = 4000;
/// The locus is followed until K is this many times the gain scale of the system.
const GAIN_SPAN: f64 = 1e7;
/// A root of dK/ds = 0 or of the jω condition is taken as real (or K as real) within this
/// fraction of its size.
const REAL_TOLERANCE: f64 = 1e-7;

/// Which half of the locus: K ≥ 0 (negative feedback, the usual one) or K ≤ 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Side {
    /// K from 0 to +∞.
    Positive,
    /// The complementary locus: K from 0 to −∞.
    Complementary,
}

impl Side {
    /// +1 or −1: the sign of K on this side.
    pub fn sign(self) -> f64 {
        match self {
            Side::Positive => 1.0,
            Side::Complementary => -1.0,
        }
    }
}

/// The closed-loop poles for one loop gain K; `roots[i]` lies on branch i.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LocusPoint {
    pub k: f64,
    pub roots: Vec<C64>,
}

/// Where a branch leaves the real axis (breakaway) or joins it (break-in), and the gain there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Breakaway {
    /// The point σ on the real axis (1/s).
    pub s: f64,
    pub k: f64,
    /// True when branches leave the axis as |K| grows; false for a break-in.
    pub leaves_axis: bool,
}

/// A crossing of the imaginary axis: closed-loop poles at ±jω for the gain K.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Crossing {
    pub k: f64,
    /// ω ≥ 0 (rad/s); 0 is a crossing through the origin.
    pub omega: f64,
}

/// The asymptotes of the branches that go to infinity.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Asymptotes {
    /// σ_a = (Σ pⱼ − Σ zᵢ)/(n − m) (1/s).
    pub centroid: f64,
    /// The angles (rad) from the positive real axis, one per branch going to infinity.
    pub angles: Vec<f64>,
}

/// The root locus of 1 + K·G(s) = 0 on one side.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Locus {
    pub side: Side,
    /// Points in order of growing |K|, the first at K = 0 (the open-loop poles).
    pub points: Vec<LocusPoint>,
    /// `None` when every branch ends on a zero (n = m).
    pub asymptotes: Option<Asymptotes>,
    pub breakaways: Vec<Breakaway>,
    /// In order of growing |K|.
    pub crossings: Vec<Crossing>,
    /// The plane's scale used for the steps (1/s).
    pub scale: f64,
}

impl Locus {
    /// The locus of G on `side` (G must have no dead time: e^{−θs} has no rational locus).
    pub fn new(g: &TransferFunction, side: Side) -> Result<Self, LtiError> {
        if g.delay() != 0.0 {
            return Err(LtiError::DelayInLoop);
        }
        let (num, den) = (g.num(), g.den());
        let scale = plane_scale(g);
        let k_scale = gain_scale(&num, &den, scale);
        let breakaways = breakaways(&num, &den, side);
        let crossings = crossings(&num, &den, side);
        let mut special: Vec<f64> = breakaways
            .iter()
            .map(|b| b.k)
            .chain(crossings.iter().map(|c| c.k))
            .map(f64::abs)
            .filter(|k| *k > 0.0)
            .collect();
        special.sort_by(f64::total_cmp);
        let points = trace(&num, &den, side, scale, k_scale, &special)?;
        Ok(Self {
            side,
            points,
            asymptotes: asymptotes(g, side),
            breakaways,
            crossings,
            scale,
        })
    }

    /// The number of branches (the order of G).
    pub fn branch_count(&self) -> usize {
        self.points.first().map_or(0, |p| p.roots.len())
    }

    /// Branch `i` as the curve of its roots, K growing.
    pub fn branch(&self, i: usize) -> Vec<C64> {
        self.points.iter().map(|p| p.roots[i]).collect()
    }

    /// The point of the locus nearest to `s`: (index of the point, branch, distance).
    pub fn nearest(&self, s: C64) -> Option<(usize, usize, f64)> {
        self.points
            .iter()
            .enumerate()
            .flat_map(|(i, p)| {
                p.roots
                    .iter()
                    .enumerate()
                    .map(move |(b, r)| (i, b, (r - s).norm()))
            })
            .min_by(|a, b| a.2.total_cmp(&b.2))
    }

    /// The gain K that puts a closed-loop pole nearest to `s` on branch `branch`, refined
    /// between the two locus points around the nearest one, and that pole.
    pub fn gain_near(&self, g: &TransferFunction, branch: usize, s: C64) -> Option<(f64, C64)> {
        let (num, den) = (g.num(), g.den());
        let i = self
            .points
            .iter()
            .enumerate()
            .filter_map(|(i, p)| p.roots.get(branch).map(|r| (i, (r - s).norm())))
            .min_by(|a, b| a.1.total_cmp(&b.1))?
            .0;
        let lo = self.points[i.saturating_sub(1)].k;
        let hi = self.points[(i + 1).min(self.points.len() - 1)].k;
        let start = self.points[i].roots[branch];
        // Golden-section search of |root − s| over K in [lo, hi], the root followed from the
        // locus point.
        let distance = |k: f64| -> Option<(f64, C64)> {
            let r = closest_root(&num, &den, k, start)?;
            Some(((r - s).norm(), r))
        };
        let (mut a, mut b) = (lo, hi);
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let c = b - phi * (b - a);
            let d = a + phi * (b - a);
            let (fc, fd) = (distance(c)?.0, distance(d)?.0);
            if fc < fd {
                b = d;
            } else {
                a = c;
            }
        }
        let k = 0.5 * (a + b);
        distance(k).map(|(_, r)| (k, r))
    }
}

/// The closed-loop poles for loop gain `k`: the roots of den + k·num.
pub fn closed_loop_roots(num: &[f64], den: &[f64], k: f64) -> Result<Vec<C64>, LtiError> {
    poly::roots(&characteristic(num, den, k))
}

/// den(s) + k·num(s), descending powers (den's degree ≥ num's).
pub fn characteristic(num: &[f64], den: &[f64], k: f64) -> Vec<f64> {
    add(den, &scale(num, k))
}

/// |den(s) + k·num(s)| relative to Σ|terms| at s: the residual a locus point must keep.
pub fn relative_residual(num: &[f64], den: &[f64], k: f64, s: C64) -> f64 {
    let p = characteristic(num, den, k);
    let value = poly::eval_complex(&p, s).norm();
    let r = s.norm();
    let n = den.len() - 1;
    let size: f64 = den
        .iter()
        .enumerate()
        .map(|(i, c)| c.abs() * r.powi((n - i) as i32))
        .chain(
            num.iter()
                .enumerate()
                .map(|(i, c)| (k * c).abs() * r.powi((num.len() - 1 - i) as i32)),
        )
        .sum();
    if size == 0.0 { value } else { value / size }
}

/// The root of den + k·num nearest `near`.
fn closest_root(num: &[f64], den: &[f64], k: f64, near: C64) -> Option<C64> {
    closed_loop_roots(num, den, k)
        .ok()?
        .into_iter()
        .min_by(|a, b| (a - near).norm().total_cmp(&(b - near).norm()))
}

/// The typical size of the plane: the largest |s| of the poles, zeros and centroid (at least
/// a small positive number).
fn plane_scale(g: &TransferFunction) -> f64 {
    let roots = g.poles().iter().chain(g.zeros()).map(|r| r.norm());
    let largest = roots.fold(0.0f64, f64::max);
    if largest > 0.0 { largest } else { 1.0 }
}

/// The gain at which K·|num| and |den| are of one size at |s| = `scale`.
fn gain_scale(num: &[f64], den: &[f64], scale: f64) -> f64 {
    let s = C64::new(0.0, scale);
    let ratio = poly::eval_complex(den, s).norm() / poly::eval_complex(num, s).norm();
    if ratio.is_finite() && ratio > 0.0 {
        ratio
    } else {
        1.0
    }
}

/// The points of the locus from K = 0 to ±GAIN_SPAN·k_scale, with adaptive steps, passing
/// exactly through the gains in `special` (|K| of breakaways and crossings).
fn trace(
    num: &[f64],
    den: &[f64],
    side: Side,
    scale: f64,
    k_scale: f64,
    special: &[f64],
) -> Result<Vec<LocusPoint>, LtiError> {
    let sign = side.sign();
    let first = closed_loop_roots(num, den, 0.0)?;
    let mut points = vec![LocusPoint {
        k: 0.0,
        roots: first,
    }];
    let k_end = GAIN_SPAN * k_scale.max(special.last().copied().unwrap_or(0.0));
    let mut magnitude = 0.0f64;
    let mut step = 1e-4 * k_scale;
    let mut next_special = special.iter().copied().peekable();
    while magnitude < k_end && points.len() < MAX_POINTS {
        let last = &points[points.len() - 1].roots;
        let mut target = magnitude + step;
        while next_special.peek().is_some_and(|&k| k <= magnitude) {
            next_special.next();
        }
        let special_hit = next_special.peek().copied().filter(|&k| k <= target);
        if let Some(k) = special_hit {
            target = k;
        }
        let roots = matched(&closed_loop_roots(num, den, sign * target)?, last);
        let moved = roots
            .iter()
            .zip(last)
            .map(|(a, b)| (a - b).norm() / scale.max(b.norm()))
            .fold(0.0, f64::max);
        let tiny = target - magnitude <= 1e-13 * target.max(k_scale);
        if moved > MAX_MOVE && !tiny {
            step = 0.5 * (target - magnitude);
            continue;
        }
        let taken = target - magnitude;
        magnitude = target;
        points.push(LocusPoint {
            k: sign * magnitude,
            roots,
        });
        if special_hit.is_some() {
            next_special.next();
        }
        step = if moved < 0.5 * MAX_MOVE {
            taken.max(step) * 1.6
        } else {
            taken.max(step)
        };
        step = step.max(1e-12 * magnitude);
    }
    Ok(points)
}

/// `roots` reordered so that `roots[i]` is the one nearest `previous[i]` (greedy by distance
/// over all pairs, closest pairs first).
fn matched(roots: &[C64], previous: &[C64]) -> Vec<C64> {
    let n = previous.len();
    let mut pairs: Vec<(f64, usize, usize)> = (0..n)
        .flat_map(|i| (0..roots.len()).map(move |j| (i, j)))
        .map(|(i, j)| ((roots[j] - previous[i]).norm(), i, j))
        .collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out = vec![None; n];
    let mut used = vec![false; roots.len()];
    for (_, i, j) in pairs {
        if out[i].is_none() && !used[j] {
            out[i] = Some(roots[j]);
            used[j] = true;
        }
    }
    out.into_iter()
        .zip(previous)
        .map(|(r, p)| r.unwrap_or(*p))
        .collect()
}

/// The asymptotes for n − m ≥ 1.
fn asymptotes(g: &TransferFunction, side: Side) -> Option<Asymptotes> {
    let q = g.relative_degree();
    if q == 0 {
        return None;
    }
    let sum = |r: &[C64]| r.iter().map(|c| c.re).sum::<f64>();
    let centroid = (sum(g.poles()) - sum(g.zeros())) / q as f64;
    let offset = match side {
        Side::Positive => 1.0,
        Side::Complementary => 0.0,
    };
    let angles = (0..q)
        .map(|l| (2.0 * l as f64 + offset) * std::f64::consts::PI / q as f64)
        .collect();
    Some(Asymptotes { centroid, angles })
}

/// The real points where dK/ds = 0 with K = −den/num of the side's sign: the roots of
/// den'·num − den·num' on the real axis.
pub fn breakaways(num: &[f64], den: &[f64], side: Side) -> Vec<Breakaway> {
    let condition = sub(
        &multiply(&derivative(den), num),
        &multiply(den, &derivative(num)),
    );
    let Ok(candidates) = poly::roots(&condition) else {
        return Vec::new();
    };
    let gain = |s: f64| -poly::eval_complex(den, C64::new(s, 0.0)).re / eval_real(num, s);
    let mut out: Vec<Breakaway> = candidates
        .into_iter()
        .filter(|r| r.im.abs() <= REAL_TOLERANCE * r.norm().max(1e-300))
        .map(|r| r.re)
        .filter_map(|s| {
            let k = gain(s);
            (k.is_finite() && k * side.sign() > 0.0).then(|| {
                // K(s) along the axis has a maximum of |K| where branches leave it.
                let h = 1e-4 * s.abs().max(1e-3);
                let leaves_axis = (gain(s - h) * side.sign() < k * side.sign())
                    && (gain(s + h) * side.sign() < k * side.sign());
                Breakaway { s, k, leaves_axis }
            })
        })
        .collect();
    out.sort_by(|a, b| a.k.abs().total_cmp(&b.k.abs()));
    out.dedup_by(|a, b| (a.s - b.s).abs() <= 1e-9 * a.s.abs().max(1.0));
    out
}

/// The crossings of the imaginary axis: ω ≥ 0 with den(jω) + K·num(jω) = 0 for a real K of the
/// side's sign (K ≠ 0), from the real roots of Re(den)·Im(num) − Im(den)·Re(num) = 0 in ω.
pub fn crossings(num: &[f64], den: &[f64], side: Side) -> Vec<Crossing> {
    let (dr, di) = on_axis(den);
    let (nr, ni) = on_axis(num);
    let condition = sub(&multiply(&dr, &ni), &multiply(&di, &nr));
    let Ok(omegas) = poly::roots(&trimmed(&condition)) else {
        return Vec::new();
    };
    let mut out: Vec<Crossing> = omegas
        .into_iter()
        .filter(|w| w.im.abs() <= REAL_TOLERANCE * w.norm().max(1e-300) && w.re >= -1e-12)
        .map(|w| w.re.max(0.0))
        .filter_map(|omega| {
            let s = C64::new(0.0, omega);
            let k = -poly::eval_complex(den, s) / poly::eval_complex(num, s);
            let real = k.im.abs() <= REAL_TOLERANCE * k.norm();
            (real && k.re.is_finite() && k.re * side.sign() > 0.0)
                .then_some(Crossing { k: k.re, omega })
        })
        .collect();
    out.sort_by(|a, b| a.k.abs().total_cmp(&b.k.abs()));
    out.dedup_by(|a, b| {
        (a.omega - b.omega).abs() <= 1e-9 * a.omega.max(1.0)
            && (a.k - b.k).abs() <= 1e-9 * a.k.abs()
    });
    out
}

/// The real and imaginary parts of p(jω) as real polynomials in ω (descending powers).
fn on_axis(p: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = p.len() - 1;
    let mut re = vec![0.0; n + 1];
    let mut im = vec![0.0; n + 1];
    for (i, &c) in p.iter().enumerate() {
        let power = n - i;
        // j^power: 1, j, −1, −j.
        match power % 4 {
            0 => re[i] = c,
            1 => im[i] = c,
            2 => re[i] = -c,
            _ => im[i] = -c,
        }
    }
    (re, im)
}

/// The polynomial without its leading zeros ([0] when all are zero).
fn trimmed(p: &[f64]) -> Vec<f64> {
    match p.iter().position(|&c| c != 0.0) {
        Some(i) => p[i..].to_vec(),
        None => vec![0.0],
    }
}

fn eval_real(p: &[f64], x: f64) -> f64 {
    p.iter().fold(0.0, |acc, &c| acc * x + c)
}

fn scale(p: &[f64], k: f64) -> Vec<f64> {
    p.iter().map(|c| c * k).collect()
}

/// a + b, aligned at the constant term.
pub fn add(a: &[f64], b: &[f64]) -> Vec<f64> {
    let n = a.len().max(b.len());
    let mut out = vec![0.0; n];
    for (i, c) in a.iter().enumerate() {
        out[n - a.len() + i] += c;
    }
    for (i, c) in b.iter().enumerate() {
        out[n - b.len() + i] += c;
    }
    out
}

fn sub(a: &[f64], b: &[f64]) -> Vec<f64> {
    add(a, &scale(b, -1.0))
}

/// The product of two polynomials.
pub fn multiply(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// The derivative dp/ds ([0] for a constant).
pub fn derivative(p: &[f64]) -> Vec<f64> {
    let n = p.len() - 1;
    if n == 0 {
        return vec![0.0];
    }
    p[..n]
        .iter()
        .enumerate()
        .map(|(i, c)| c * (n - i) as f64)
        .collect()
}
