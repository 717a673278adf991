//! The metrics of a loop's response ([`LoopMetrics`]), read from the polynomial that
//! interpolates the output on each step of [`LoopResponse`] (accurate to about 1e-8 of the
//! step's size), as python-control's `step_info` documents its own:
//!
//! - **final value** y(∞), from the loop's static gains (not read off the curve);
//! - **overshoot** (%): for a setpoint step, the largest excursion past y(∞) in the
//!   direction of the change, over |y(∞) − y(0)|; for a load step, the largest swing past
//!   y(∞) on the far side from the peak deviation, over |peak − y(∞)|;
//! - **peak**: the largest value for a setpoint step; for a load step the **peak
//!   deviation** from the setpoint, the largest |y| (with its sign), and its time;
//! - **settling time** (s): the last time |y − y(∞)| leaves the 2 % band, the band being 2 %
//!   of the setpoint change, or for a load of the larger of the peak's distance from y(∞)
//!   and y(∞) itself (without integral action the output creeps to its offset y(∞) without
//!   a peak: it settles as a step response does);
//! - a response that approaches y(∞) without passing it has its peak at the end of the time
//!   computed, as `stepinfo` reports it;
//! - **IAE** = ∫|e| dt and **ITAE** = ∫ t·|e| dt, e = r − y, only when e → 0 (the loop has
//!   integral action or an integrating plant); otherwise they grow without bound and are
//!   None.
//!
//! None everywhere the loop did not settle within the time computed.

use serde::Serialize;

use super::delay_loop::{LoopInput, LoopResponse};
use crate::golden::golden_max;

/// The settling band: 2 % (as `stepinfo` and the notes).
pub const SETTLING_BAND: f64 = 0.02;

/// A peak of a response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Peak {
    /// y at the peak.
    pub value: f64,
    /// When (s).
    pub time: f64,
}

/// The metrics of a loop's response to a unit step of its input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoopMetrics {
    /// y(∞); None when the loop has no steady state.
    pub final_value: Option<f64>,
    /// Overshoot (%), ≥ 0.
    pub overshoot: Option<f64>,
    /// The setpoint response's maximum, or the load response's peak deviation.
    pub peak: Option<Peak>,
    /// Settling time (s) to the 2 % band.
    pub settling_time: Option<f64>,
    /// ∫|e| dt (s).
    pub iae: Option<f64>,
    /// ∫ t·|e| dt (s²).
    pub itae: Option<f64>,
}

impl LoopMetrics {
    /// Every metric None (a loop that did not settle).
    pub const NONE: LoopMetrics = LoopMetrics {
        final_value: None,
        overshoot: None,
        peak: None,
        settling_time: None,
        iae: None,
        itae: None,
    };
}

/// The interpolating polynomial of y on one step, in barycentric form at the
/// Chebyshev–Lobatto nodes.
#[derive(Clone, Copy)]
struct Piece<'a> {
    t0: f64,
    offsets: &'a [f64],
    values: &'a [f64],
}

impl Piece<'_> {
    fn eval(&self, t: f64) -> f64 {
        let tau = t - self.t0;
        let last = self.offsets.len() - 1;
        let (mut num, mut den) = (0.0, 0.0);
        for (i, (&o, &v)) in self.offsets.iter().zip(self.values).enumerate() {
            let d = tau - o;
            if d == 0.0 {
                return v;
            }
            let mut w = if i % 2 == 0 { 1.0 } else { -1.0 };
            if i == 0 || i == last {
                w *= 0.5;
            }
            num += w * v / d;
            den += w / d;
        }
        num / den
    }

    fn time(&self, i: usize) -> f64 {
        self.t0 + self.offsets[i]
    }
}

/// The metrics of `r`.
pub fn loop_metrics(r: &LoopResponse) -> LoopMetrics {
    let y_final = r.final_value;
    if !r.settled || !y_final.is_finite() {
        return LoopMetrics::NONE;
    }
    let pieces: Vec<Piece> = (0..r.steps()).map(|j| piece(r, j)).collect();
    let reference = r.input.reference();
    let peak = match r.input {
        LoopInput::Setpoint => extreme(&pieces, |y| y * (y_final).signum()),
        LoopInput::Load => extreme(&pieces, f64::abs),
    };
    let (overshoot, band) = match r.input {
        LoopInput::Setpoint => {
            let change = y_final;
            let over = extreme(&pieces, |y| (y - y_final) * change.signum());
            (
                (change != 0.0).then(|| 100.0 * over.value.max(0.0) / change.abs()),
                SETTLING_BAND * change.abs(),
            )
        }
        LoopInput::Load => {
            let deviation = peak.value - y_final;
            let after: Vec<Piece> = pieces
                .iter()
                .filter(|p| p.time(p.offsets.len() - 1) >= peak.time)
                .copied()
                .collect();
            let swing = extreme(&after, |y| -(y - y_final) * deviation.signum());
            (
                (deviation != 0.0).then(|| 100.0 * swing.value.max(0.0) / deviation.abs()),
                SETTLING_BAND * deviation.abs().max(y_final.abs()),
            )
        }
    };
    let peak = match r.input {
        LoopInput::Setpoint => Some(Peak {
            value: peak.value * y_final.signum(),
            time: peak.time,
        }),
        LoopInput::Load => Some(signed_peak(&pieces, peak)),
    };
    let offset_free = (y_final - reference).abs() <= 1e-9 * y_final.abs().max(1.0);
    let (iae, itae) = if offset_free {
        let (a, b) = error_integrals(&pieces, reference);
        (Some(a), Some(b))
    } else {
        (None, None)
    };
    LoopMetrics {
        final_value: Some(y_final),
        overshoot,
        peak,
        settling_time: (band > 0.0).then(|| settling_time(&pieces, y_final, band)),
        iae,
        itae,
    }
}

fn piece(r: &LoopResponse, j: usize) -> Piece<'_> {
    let (t0, offsets, values) = r.step_nodes(j);
    Piece {
        t0,
        offsets,
        values,
    }
}

/// The load's peak deviation with its sign (the extreme of |y| found, y read back).
fn signed_peak(pieces: &[Piece], abs_peak: Peak) -> Peak {
    let value = pieces
        .iter()
        .find(|p| p.t0 <= abs_peak.time && abs_peak.time <= p.time(p.offsets.len() - 1))
        .map_or(abs_peak.value, |p| p.eval(abs_peak.time));
    Peak {
        value,
        time: abs_peak.time,
    }
}

/// The largest value of f(y(t)) and where, refined between nodes by golden section.
fn extreme(pieces: &[Piece], f: impl Fn(f64) -> f64) -> Peak {
    let mut best = Peak {
        value: f64::NEG_INFINITY,
        time: 0.0,
    };
    let mut at = (0, 0);
    for (j, p) in pieces.iter().enumerate() {
        for (i, &v) in p.values.iter().enumerate() {
            if f(v) > best.value {
                best = Peak {
                    value: f(v),
                    time: p.time(i),
                };
                at = (j, i);
            }
        }
    }
    if pieces.is_empty() {
        return Peak {
            value: 0.0,
            time: 0.0,
        };
    }
    let p = &pieces[at.0];
    let last = p.offsets.len() - 1;
    for (lo, hi) in [(at.1.saturating_sub(1), at.1), (at.1, (at.1 + 1).min(last))] {
        if hi > lo {
            let (time, value) = golden_max(|t| f(p.eval(t)), p.time(lo), p.time(hi), 1e-15);
            let g = Peak { value, time };
            if g.value > best.value {
                best = g;
            }
        }
    }
    best
}

/// Where h changes sign between a and b (h(a)·h(b) ≤ 0), by bisection.
fn crossing(h: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let ha = h(a);
    for _ in 0..100 {
        let m = (a + b) / 2.0;
        if m <= a || m >= b {
            break;
        }
        if (h(m) > 0.0) == (ha > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    (a + b) / 2.0
}

/// The last time |y − y(∞)| > band, interpolated between the nodes (0 if never).
fn settling_time(pieces: &[Piece], y_final: f64, band: f64) -> f64 {
    let outside = |v: f64| (v - y_final).abs() > band;
    for p in pieces.iter().rev() {
        for i in (0..p.values.len()).rev() {
            if outside(p.values[i]) {
                if i + 1 == p.values.len() {
                    return p.time(i);
                }
                let h = |t: f64| (p.eval(t) - y_final).abs() - band;
                return crossing(h, p.time(i), p.time(i + 1));
            }
        }
    }
    0.0
}

/// Gauss–Legendre nodes and weights on [−1, 1], 8 points (exact to degree 15).
const GAUSS: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// ∫|e| and ∫t·|e| over every step, e = reference − y, split where e changes sign.
fn error_integrals(pieces: &[Piece], reference: f64) -> (f64, f64) {
    let Some(first) = pieces.first() else {
        return (0.0, 0.0);
    };
    let basis = gauss_basis(first);
    let (mut iae, mut itae) = (0.0, 0.0);
    for p in pieces {
        let signs_change = p
            .values
            .windows(2)
            .any(|v| (reference - v[0]) * (reference - v[1]) < 0.0);
        let (a, b) = if signs_change {
            split_integrals(p, reference)
        } else {
            whole_integrals(p, reference, &basis)
        };
        iae += a;
        itae += b;
    }
    (iae, itae)
}

/// The interpolation basis of a step at its Gauss points: row g, the weights of the node
/// values giving y there (the same for every step: the nodes sit at the same offsets).
fn gauss_basis(p: &Piece) -> Vec<Vec<f64>> {
    let h = p.offsets[p.offsets.len() - 1];
    GAUSS
        .iter()
        .map(|&(x, _)| {
            let t = p.t0 + h * (1.0 + x) / 2.0;
            (0..p.values.len())
                .map(|i| {
                    let mut unit = vec![0.0; p.values.len()];
                    unit[i] = 1.0;
                    Piece {
                        values: &unit,
                        ..*p
                    }
                    .eval(t)
                })
                .collect()
        })
        .collect()
}

/// The integrals over a step where e keeps its sign.
fn whole_integrals(p: &Piece, reference: f64, basis: &[Vec<f64>]) -> (f64, f64) {
    let h = p.offsets[p.offsets.len() - 1];
    let half = h / 2.0;
    let (mut iae, mut itae) = (0.0, 0.0);
    for ((x, wt), row) in GAUSS.iter().zip(basis) {
        let y: f64 = row.iter().zip(p.values).map(|(l, v)| l * v).sum();
        let v = (reference - y).abs();
        iae += wt * half * v;
        itae += wt * half * (p.t0 + half * (1.0 + x)) * v;
    }
    (iae, itae)
}

/// The integrals over a step where e changes sign: cut at each change.
fn split_integrals(p: &Piece, reference: f64) -> (f64, f64) {
    let e = |t: f64| reference - p.eval(t);
    let mut cuts = vec![p.time(0)];
    for i in 0..p.values.len() - 1 {
        let (a, b) = (reference - p.values[i], reference - p.values[i + 1]);
        if a * b < 0.0 {
            cuts.push(crossing(e, p.time(i), p.time(i + 1)));
        }
    }
    cuts.push(p.time(p.values.len() - 1));
    let (mut iae, mut itae) = (0.0, 0.0);
    for w in cuts.windows(2) {
        let (mid, half) = ((w[0] + w[1]) / 2.0, (w[1] - w[0]) / 2.0);
        for (x, wt) in GAUSS {
            let t = mid + half * x;
            let v = e(t).abs();
            iae += wt * half * v;
            itae += wt * half * t * v;
        }
    }
    (iae, itae)
}
