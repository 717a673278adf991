//! `disturbance`: the output changed where no input did. After the response to the last
//! input change has settled (its dead time plus four times the sum of its lags, or of the
//! envelope Tw/ζ of a pair), the residuals of a model that lacks nothing are noise about
//! zero; a load disturbance puts a step (a door opened, a load added) or a ramp (a slow
//! leak) in them from one instant on. The search fits, at every candidate instant of that
//! settled tail, a step (two means) and a hinge (flat, then a straight line), and keeps the
//! best, which must beat a straight line through the whole tail (what a drift would leave)
//! by the BIC, corrected for its own residuals' correlation (an AR(1) coefficient ρ leaves
//! N·(1 − ρ)/(1 + ρ) independent samples, so coloured noise wandering about does not count),
//! be flat before its instant, be significant (z above [`MIN_Z`], with the same
//! correction), and explain the record better than any structural extension of the model
//! (a drift, an integrator, a zero, …) would (BIC). A fit of the whole record leans towards
//! the disturbed samples, so when this first look finds nothing the model is refitted
//! without the samples from the likeliest instant on and the test made again on what the
//! refit leaves. The samples from the instant on are then left out of the fit: they are
//! not the process's answer to the input, and not a drift.

use super::{DisturbanceShape, Handling, TestCause, TestCauseKind, TestEvidence};
use crate::ident::diagnose::{BIC_THRESHOLD, best_extension_bic};
use crate::ident::fit::{FitData, FitOptions, FitReport, fit};
use crate::ident::models::{Model, Param};
use crate::ident::stats::lag_one;

/// The least significance of a disturbance's size (z, correlation-corrected).
pub const MIN_Z: f64 = 5.0;
/// The fewest samples in the settled tail to look at.
const MIN_TAIL: usize = 30;
/// Candidate instants tried at most (evenly spread over the tail).
const CANDIDATES: usize = 200;
/// The line before (and, for a step, after) the instant may move by this share of the
/// disturbance at most.
const FLAT_SHARE: f64 = 0.25;

/// A disturbance in `residuals` of `current` on `data`, and the samples from it on.
///
/// A model fitted on the whole record has leant towards the disturbed samples (its gain or
/// lag took part of the load), so the tail it leaves is not flat before the instant. When
/// the first look finds nothing, the model is refitted without the samples from the
/// likeliest instant on, and the test is made again on what the refit leaves.
pub fn detect(
    data: &FitData,
    current: &FitReport,
    residuals: &[f64],
) -> Option<(TestCause, Vec<usize>)> {
    if let Some(found) = judge(data, current, residuals) {
        return Some(found);
    }
    let (first, tail) = settled_tail(data, current)?;
    let sums = Sums::new(&data.times[first..], &residuals[first..]);
    let (_, k, _) = best_instant(&sums, tail)?;
    let keep: Vec<bool> = (0..data.y.len()).map(|i| i < first + k).collect();
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let before = data.keeping(&keep);
    let refit = fit(
        &before,
        current.model.structure,
        current.model.values,
        &options,
        &mut (),
    )
    .ok()?;
    let r = refit.residuals(data).ok()?;
    judge(data, &refit, &r)
}

/// The index of the first sample of the settled tail after the last input change, and the
/// tail's length; `None` when the model never settles or the tail is too short.
fn settled_tail(data: &FitData, current: &FitReport) -> Option<(usize, usize)> {
    let settled = data.input.changes.last()?.t + settling(&current.model)?;
    let first = data.times.partition_point(|&t| t < settled);
    let n = data.times.len() - first;
    (n >= MIN_TAIL).then_some((first, n))
}

/// The tail's best disturbance: its shape, instant (index in the tail) and SSE.
fn best_instant(sums: &Sums, n: usize) -> Option<(DisturbanceShape, usize, f64)> {
    let m = (n / 20).max(5);
    let stride = ((n - 2 * m) / CANDIDATES).max(1);
    (m..n - m)
        .step_by(stride)
        .flat_map(|k| {
            [
                (DisturbanceShape::Step, k, sums.step_sse(k)),
                (DisturbanceShape::Ramp, k, sums.hinge(k).2),
            ]
        })
        .filter(|c| c.2.is_finite())
        .min_by(|a, b| a.2.total_cmp(&b.2))
}

/// The test of the module doc on the residuals of `current`.
fn judge(
    data: &FitData,
    current: &FitReport,
    residuals: &[f64],
) -> Option<(TestCause, Vec<usize>)> {
    let (first, n) = settled_tail(data, current)?;
    let (t, r) = (&data.times[first..], &residuals[first..]);
    let sums = Sums::new(t, r);
    let line = sums.line(0, n);
    let (shape, k, sse) = best_instant(&sums, n)?;
    let fitted: Vec<f64> = match shape {
        DisturbanceShape::Step => {
            let (a, b) = (sums.mean(0, k), sums.mean(k, n));
            (0..n).map(|i| if i < k { a } else { b }).collect()
        }
        DisturbanceShape::Ramp => {
            let (a, b, _) = sums.hinge(k);
            (0..n).map(|i| a + b * (t[i] - t[k]).max(0.0)).collect()
        }
    };
    let e: Vec<f64> = r.iter().zip(&fitted).map(|(r, f)| r - f).collect();
    let rho = lag_one(&e).clamp(0.0, 0.99);
    let correlation = (1.0 + rho) / (1.0 - rho);
    let n_eff = n as f64 / correlation;
    let gain = n_eff * (line.2 / sse).ln();
    if gain.is_nan() || gain <= BIC_THRESHOLD + (n as f64).ln() {
        return None;
    }
    let s = (sse / (n as f64 - 3.0)).sqrt() * correlation.sqrt();
    let (size, z) = match shape {
        DisturbanceShape::Step => {
            let size = sums.mean(k, n) - sums.mean(0, k);
            let se = s * (1.0 / k as f64 + 1.0 / (n - k) as f64).sqrt();
            (size, size / se)
        }
        DisturbanceShape::Ramp => {
            let (_, b, _) = sums.hinge(k);
            let h: Vec<f64> = t.iter().map(|&x| (x - t[k]).max(0.0)).collect();
            let mean = h.iter().sum::<f64>() / n as f64;
            let shh: f64 = h.iter().map(|x| (x - mean).powi(2)).sum();
            (b * (t[n - 1] - t[k]), b / (s / shh.sqrt()))
        }
    };
    let flat = |from: usize, to: usize| {
        let (_, slope, _) = sums.line(from, to);
        (slope * (t[to - 1] - t[from])).abs() <= FLAT_SHARE * size.abs()
    };
    let after_flat = shape == DisturbanceShape::Ramp || flat(k, n);
    if z.abs() < MIN_Z || !flat(0, k) || !after_flat {
        return None;
    }
    let before: f64 = residuals[..first].iter().map(|r| r * r).sum();
    if explained_by_structure(data, current, before + sse) {
        return None;
    }
    let (at, end) = (t[k], t[n - 1]);
    let cause = TestCause {
        kind: TestCauseKind::Disturbance,
        evidence: TestEvidence::Disturbance { at, size, shape, z },
        interval: Some((at, end)),
        handling: Handling::Excluded { start: at, end },
    };
    Some((cause, (first + k..data.times.len()).collect()))
}

/// Whether a structural extension of `current` (a drift, an integrator, a zero, a pole, …:
/// the best of the diagnosis's candidates) explains the record at least as well as the
/// disturbance (`sse`: the record's sum of squares with it, three more parameters: its
/// instant and the step's two levels or the hinge's level and slope), by the BIC. What the
/// model lacks leaves a pattern in the settled tail too (a slow zero's decay, a drift's
/// line), and it is the model's to name.
fn explained_by_structure(data: &FitData, current: &FitReport, sse: f64) -> bool {
    let n = data.y.len() as f64;
    let p = current.params.len() as f64 + 3.0;
    let disturbance = n * (sse / n).ln() + p * n.ln();
    best_extension_bic(data, current).is_some_and(|b| b <= disturbance + BIC_THRESHOLD)
}

/// How long the model's response takes to settle (s): its dead time plus four times its
/// lags (a pair's envelope Tw/ζ); `None` for an integrator, which never settles.
pub fn settling(model: &Model) -> Option<f64> {
    let s = model.structure;
    if s.integrator {
        return None;
    }
    let params = s.params();
    let has = |p: Param| params.contains(&p);
    let mut lags: f64 = [Param::Tp1, Param::Tp2, Param::Tp3]
        .into_iter()
        .filter(|&p| has(p))
        .map(|p| model.get(p).abs())
        .sum();
    if has(Param::Tw) {
        lags += model.get(Param::Tw) / model.get(Param::Zeta).max(0.05);
    }
    let td = if has(Param::Td) {
        model.get(Param::Td).max(0.0)
    } else {
        0.0
    };
    let total = td + 4.0 * lags;
    total.is_finite().then_some(total)
}

/// Prefix sums of a tail for O(1) least-squares fits of any segment.
struct Sums {
    t: Vec<f64>,
    /// Σ over the first k samples of 1·r, r², t, t², t·r (index k).
    r: Vec<f64>,
    r2: Vec<f64>,
    tt: Vec<f64>,
    t2: Vec<f64>,
    tr: Vec<f64>,
}

impl Sums {
    fn new(t: &[f64], r: &[f64]) -> Self {
        // Times about the tail's start keep the sums well conditioned.
        let origin = t[0];
        let t: Vec<f64> = t.iter().map(|x| x - origin).collect();
        let prefix = |f: &dyn Fn(usize) -> f64| {
            let mut out = Vec::with_capacity(t.len() + 1);
            let mut acc = 0.0;
            out.push(0.0);
            for i in 0..t.len() {
                acc += f(i);
                out.push(acc);
            }
            out
        };
        Sums {
            r: prefix(&|i| r[i]),
            r2: prefix(&|i| r[i] * r[i]),
            tt: prefix(&|i| t[i]),
            t2: prefix(&|i| t[i] * t[i]),
            tr: prefix(&|i| t[i] * r[i]),
            t,
        }
    }

    fn sum(v: &[f64], a: usize, b: usize) -> f64 {
        v[b] - v[a]
    }

    fn mean(&self, a: usize, b: usize) -> f64 {
        Self::sum(&self.r, a, b) / (b - a) as f64
    }

    /// Σ(r − mean)² over [a, b).
    fn spread(&self, a: usize, b: usize) -> f64 {
        let n = (b - a) as f64;
        let s = Self::sum(&self.r, a, b);
        (Self::sum(&self.r2, a, b) - s * s / n).max(0.0)
    }

    fn step_sse(&self, k: usize) -> f64 {
        self.spread(0, k) + self.spread(k, self.t.len())
    }

    /// The line a + b·t over [a, b): (intercept at the tail's start, slope, SSE).
    fn line(&self, a: usize, b: usize) -> (f64, f64, f64) {
        let n = (b - a) as f64;
        let (st, sr) = (Self::sum(&self.tt, a, b), Self::sum(&self.r, a, b));
        let stt = Self::sum(&self.t2, a, b) - st * st / n;
        let str = Self::sum(&self.tr, a, b) - st * sr / n;
        let slope = if stt > 0.0 { str / stt } else { 0.0 };
        let sse = (self.spread(a, b) - slope * str).max(0.0);
        ((sr - slope * st) / n, slope, sse)
    }

    /// The hinge a + b·max(0, t − t_k) over the whole tail: (a, b, SSE).
    fn hinge(&self, k: usize) -> (f64, f64, f64) {
        let n = self.t.len();
        let tk = self.t[k];
        let m = (n - k) as f64;
        // h = t − t_k on [k, n), 0 before.
        let sh = Self::sum(&self.tt, k, n) - m * tk;
        let shh = Self::sum(&self.t2, k, n) - 2.0 * tk * Self::sum(&self.tt, k, n) + m * tk * tk;
        let shr = Self::sum(&self.tr, k, n) - tk * Self::sum(&self.r, k, n);
        let (nn, sr) = (n as f64, Self::sum(&self.r, 0, n));
        let var_h = shh - sh * sh / nn;
        let cov = shr - sh * sr / nn;
        if var_h.is_nan() || var_h <= 0.0 {
            return (0.0, 0.0, f64::INFINITY);
        }
        let b = cov / var_h;
        let a = (sr - b * sh) / nn;
        (a, b, (self.spread(0, n) - b * cov).max(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ident::excitation::Excitation;
    use crate::ident::models::{Structure, Values};

    fn record(load: impl Fn(f64) -> f64) -> (FitData, FitReport) {
        let s = Structure::parse("P1").unwrap();
        let mut v = Values::default();
        v.set(Param::Kp, 2.0);
        v.set(Param::Tp1, 3.0);
        v.set(Param::Y0, 50.0);
        let times: Vec<f64> = (0..400).map(|k| 0.25 * k as f64).collect();
        let input = Excitation::step(5.0, 1.0);
        let clean = Model::new(s, v).simulate(&input, &times).unwrap();
        let mut rng = crate::ident::fit::Lcg(5);
        let y = clean
            .iter()
            .zip(&times)
            .map(|(c, t)| c + 0.01 * rng.symmetric() + load(*t))
            .collect();
        let data = FitData { times, y, input };
        let r = fit(&data, s, v, &FitOptions::default(), &mut ()).unwrap();
        (data, r)
    }

    #[test]
    fn a_load_step_after_settling_is_found_where_it_happened() {
        let (data, current) = record(|t| if t >= 70.0 { -0.4 } else { 0.0 });
        let r = current.residuals(&data).unwrap();
        let (cause, from) = detect(&data, &current, &r).unwrap();
        let TestEvidence::Disturbance {
            at, size, shape, ..
        } = cause.evidence
        else {
            panic!()
        };
        assert_eq!(shape, DisturbanceShape::Step);
        assert!((at - 70.0).abs() <= 0.5, "{at}");
        assert!((size + 0.4).abs() < 0.05, "{size}");
        assert_eq!(from[0], 280);
    }

    #[test]
    fn a_ramp_is_a_ramp_and_a_drift_is_no_disturbance() {
        let (data, current) = record(|t| 0.01 * (t - 60.0).max(0.0));
        let r = current.residuals(&data).unwrap();
        let (cause, _) = detect(&data, &current, &r).unwrap();
        assert!(matches!(
            cause.evidence,
            TestEvidence::Disturbance {
                shape: DisturbanceShape::Ramp,
                ..
            }
        ));
        let (data, current) = record(|t| 0.01 * t);
        let r = current.residuals(&data).unwrap();
        let found = detect(&data, &current, &r);
        assert!(found.is_none(), "{found:?} {:?}", current.model);
        let (data, current) = record(|_| 0.0);
        let r = current.residuals(&data).unwrap();
        let found = detect(&data, &current, &r);
        assert!(found.is_none(), "{found:?} {:?}", current.model);
    }
}
