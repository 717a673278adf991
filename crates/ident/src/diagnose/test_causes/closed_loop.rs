//! `closed_loop`: the test ran in closed loop, the logged input being a controller's output
//! that answers the output's errors. A step test assumes the input chosen independently of
//! the output (a few steps, a staircase, a PRBS set in advance); under a controller the
//! input is correlated with the noise through the feedback, and least squares on (u, y)
//! pulls the gain towards −1/(the controller's gain): a fit then returns a wrong gain with an
//! interval that does not cover it.
//!
//! Read from a fit's residuals e = y − ŷ (what the model leaves: the noise, in open loop no
//! input can know it) by a Granger-type F test. The input's change u(k) − u(k−1) is
//! regressed on its own past levels u(k−1…k−12) (the restricted regression), then also on
//! the residuals e(k…k−3) (the full one). In an open-loop test nothing the input does
//! answers the residuals; under a controller every move does (a P or PI law moves u by
//! −Kc·Δy(k) − Ki·h·e(k), the controller seeing the same sample the logger does). Not the
//! output's past alone: a controller's output is a function of the output, so the input's
//! own past already holds the output's past, and only the current sample's noise is news
//! to it; and not the output itself: the output carries the input's far past (the plant's
//! memory), which tells a PRBS's clock or an input's level beyond the input's own lags.
//!
//! Named only when the input moves at more than [`MIN_MOVES`] of the samples (an open-loop
//! step or staircase moves at a handful of samples: its changes are zero almost everywhere
//! and nothing can be read from them) and the F statistic's p-value is under [`P_VALUE`]
//! (Paulson's normal approximation of the F distribution). Moves set from outside (a
//! setpoint's kick, a dither's switches) are left out of the sums first ([`TRIM`]). Cost:
//! O(n·p²), p = 16 regressors.

use nalgebra::{DMatrix, DVector};

use super::{FittedRecord, Handling, TestCause, TestCauseKind, TestEvidence, input_at};
use crate::stats::{normal_quantile, robust_scale};

/// The input's past levels the restricted regression uses: enough to hold what a PRBS's
/// clock or an amplitude-modulated PRBS lets the input's past say about its next move.
pub const INPUT_LAGS: usize = 12;
/// The residuals the full regression adds: the current one and three before.
pub const RESIDUAL_LAGS: usize = 4;
/// The least share of the samples at which the input must move.
pub const MIN_MOVES: f64 = 0.2;
/// The largest p-value of the F test named.
pub const P_VALUE: f64 = 1e-3;
/// The fewest regression rows per regressor of the full regression.
const ROWS_PER_REGRESSOR: usize = 10;
/// Robust standard deviations beyond which an input change is set from outside and left
/// out of the test.
pub const TRIM: f64 = 5.0;
/// The most refits of the restricted regression while rows are left out.
const TRIM_PASSES: usize = 8;
/// Relative rounding of the sums of squares.
const RESOLUTION: f64 = 1e-12;

/// What the F test found: the statistic, its degrees of freedom, and the share of the
/// input's moves (their variance about the restricted regression) the output's past
/// explains.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Granger {
    pub f: f64,
    pub dof: (usize, usize),
    pub explained: f64,
}

impl Granger {
    /// The standard normal deviate of the F statistic's upper tail (Paulson's
    /// approximation).
    pub fn z(&self) -> f64 {
        let (a, b) = (
            2.0 / (9.0 * self.dof.0 as f64),
            2.0 / (9.0 * self.dof.1 as f64),
        );
        let c = self.f.cbrt();
        ((1.0 - b) * c - (1.0 - a)) / (a + b * c * c).sqrt()
    }

    /// Whether the p-value is under [`P_VALUE`].
    pub fn significant(&self) -> bool {
        self.z() > normal_quantile(1.0 - P_VALUE)
    }
}

/// `closed_loop` on a fitted record (see the module docs).
pub fn closed_loop(record: &FittedRecord) -> Option<TestCause> {
    let data = record.data;
    let u = input_at(&data.input, &data.times);
    let moves = moving_share(&differences(&u), &u);
    if moves <= MIN_MOVES {
        return None;
    }
    let test = granger(&u, &record.residuals)?;
    if !test.significant() {
        return None;
    }
    let interval = data.times.first().zip(data.times.last());
    Some(TestCause {
        kind: TestCauseKind::ClosedLoop,
        evidence: TestEvidence::ClosedLoop {
            moves,
            f: test.f,
            dof: test.dof,
            explained: test.explained,
        },
        interval: interval.map(|(a, b)| (*a, *b)),
        handling: Handling::Reported,
    })
}

/// v(k+1) − v(k).
fn differences(v: &[f64]) -> Vec<f64> {
    v.windows(2).map(|w| w[1] - w[0]).collect()
}

/// The share of the changes `du` that move the input by more than rounding does (relative
/// to the input's largest magnitude in `u`).
fn moving_share(du: &[f64], u: &[f64]) -> f64 {
    if du.is_empty() {
        return 0.0;
    }
    let scale = u.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let tiny = 1e-12 * scale;
    du.iter().filter(|d| d.abs() > tiny).count() as f64 / du.len() as f64
}

/// The F test of the module docs: the input's change u(k) − u(k−1) on its levels
/// u(k−1…k−[`INPUT_LAGS`]), then also on the residuals e(k…k−[`RESIDUAL_LAGS`]+1) (the
/// current one, which the input cannot answer in open loop, and the earlier ones). Rows
/// whose change the input's own past leaves beyond [`TRIM`] robust standard deviations (a
/// setpoint's kick, a dither's switch: moves set from outside, which would swamp the sums)
/// are left out first; which rows go is read from the input alone, so that in open loop
/// the residuals are still independent of the rows kept. `None` when the record is too
/// short for the test or nothing is left to explain.
pub fn granger(u: &[f64], e: &[f64]) -> Option<Granger> {
    let design = Design { u, e };
    let rows: Vec<usize> = design.rows().collect();
    if rows.len() < ROWS_PER_REGRESSOR * (design.width() + 1) {
        return None;
    }
    let kept = untrimmed(&design, &rows);
    f_test(&Normal::of(&design, &kept), kept.len())
}

/// The rows whose input change the input's own past explains within [`TRIM`] robust
/// standard deviations: the restricted regression refitted on the rows kept until they
/// stay the same (at most [`TRIM_PASSES`] times), so that moves set from outside at up to
/// half the rows (a dither switching every few samples) stop pulling the fit they are
/// judged by.
fn untrimmed(design: &Design, rows: &[usize]) -> Vec<usize> {
    let restricted: Vec<usize> = (0..INPUT_LAGS).collect();
    let mut kept = rows.to_vec();
    for _ in 0..TRIM_PASSES {
        let normal = Normal::of(design, &kept);
        let Some((beta, _)) = normal.solve(&restricted) else {
            break;
        };
        let residuals: Vec<f64> = rows
            .iter()
            .map(|&k| normal.residual(design, &restricted, &beta, k))
            .collect();
        let limit = TRIM * robust_scale(&residuals);
        let next: Vec<usize> = rows
            .iter()
            .zip(&residuals)
            .filter(|(_, r)| r.abs() <= limit)
            .map(|(k, _)| *k)
            .collect();
        if next == kept || next.len() < ROWS_PER_REGRESSOR * design.width() {
            break;
        }
        kept = next;
    }
    kept
}

/// The F statistic of the full regression against the restricted one on the normal
/// equations of `rows` rows.
fn f_test(normal: &Normal, rows: usize) -> Option<Granger> {
    let width = INPUT_LAGS + RESIDUAL_LAGS;
    let restricted: Vec<usize> = (0..INPUT_LAGS).filter(|&j| normal.varies(j)).collect();
    let full: Vec<usize> = (0..width).filter(|&j| normal.varies(j)).collect();
    let added = full.len() - restricted.len();
    let dof = rows.checked_sub(full.len() + 1)?;
    if added == 0 || dof == 0 {
        return None;
    }
    let ssr_r = normal.solve(&restricted)?.1;
    // Nothing left to explain: the input's own past gives its moves to rounding.
    if !ssr_r.is_finite() || ssr_r <= RESOLUTION * normal.yy {
        return None;
    }
    // An exact controller law leaves rounding only: F is then as large as the arithmetic
    // can tell, not infinite.
    let ssr_f = normal.solve(&full)?.1.clamp(RESOLUTION * ssr_r, ssr_r);
    let f = ((ssr_r - ssr_f) / added as f64) / (ssr_f / dof as f64);
    Some(Granger {
        f,
        dof: (added, dof),
        explained: (ssr_r - ssr_f) / ssr_r,
    })
}

/// The rows of the regressions: row k explains u(k) − u(k−1) by regressor
/// j < [`INPUT_LAGS`], u(k−1−j), and regressor [`INPUT_LAGS`] + j, e(k−j).
struct Design<'a> {
    u: &'a [f64],
    e: &'a [f64],
}

impl Design<'_> {
    fn rows(&self) -> std::ops::Range<usize> {
        INPUT_LAGS.max(RESIDUAL_LAGS)..self.u.len().min(self.e.len())
    }

    fn target(&self, k: usize) -> f64 {
        self.u[k] - self.u[k - 1]
    }

    fn regressor(&self, j: usize, k: usize) -> f64 {
        if j < INPUT_LAGS {
            self.u[k - 1 - j]
        } else {
            self.e[k - (j - INPUT_LAGS)]
        }
    }

    fn width(&self) -> usize {
        INPUT_LAGS + RESIDUAL_LAGS
    }
}

/// The centred normal equations of a regression with an intercept over some rows: the
/// regressors' and the target's means, the regressors' covariances (sums of centred
/// products), their covariances with the target, and the target's sum of squares about its
/// mean. Sums are taken about the first row's values, then moved to the means, so that
/// levels far from zero cost no precision.
struct Normal {
    means: Vec<f64>,
    target_mean: f64,
    xx: DMatrix<f64>,
    xy: DVector<f64>,
    yy: f64,
}

impl Normal {
    fn of(design: &Design, rows: &[usize]) -> Self {
        let p = design.width();
        let Some(&first) = rows.first() else {
            return Self {
                means: vec![0.0; p],
                target_mean: 0.0,
                xx: DMatrix::zeros(p, p),
                xy: DVector::zeros(p),
                yy: 0.0,
            };
        };
        let x0: Vec<f64> = (0..p).map(|j| design.regressor(j, first)).collect();
        let t0 = design.target(first);
        let count = rows.len() as f64;
        let (mut sx, mut st) = (vec![0.0; p], 0.0);
        let mut xx = DMatrix::zeros(p, p);
        let mut xy = DVector::zeros(p);
        let mut tt = 0.0;
        let mut row = vec![0.0; p];
        for &k in rows {
            row.iter_mut()
                .enumerate()
                .for_each(|(j, v)| *v = design.regressor(j, k) - x0[j]);
            let t = design.target(k) - t0;
            for (a, &ra) in row.iter().enumerate() {
                sx[a] += ra;
                xy[a] += ra * t;
                for (b, &rb) in row[..=a].iter().enumerate() {
                    xx[(a, b)] += ra * rb;
                }
            }
            st += t;
            tt += t * t;
        }
        for (a, &sa) in sx.iter().enumerate() {
            xy[a] -= sa * st / count;
            for (b, &sb) in sx[..=a].iter().enumerate() {
                xx[(a, b)] -= sa * sb / count;
                xx[(b, a)] = xx[(a, b)];
            }
        }
        Self {
            means: x0.iter().zip(&sx).map(|(a, s)| a + s / count).collect(),
            target_mean: t0 + st / count,
            xx,
            xy,
            yy: (tt - st * st / count).max(0.0),
        }
    }

    /// Whether regressor `j` varies at all (a constant one carries nothing but the
    /// intercept).
    fn varies(&self, j: usize) -> bool {
        self.xx[(j, j)] > 0.0
    }

    /// The coefficients of the regression on the regressors `columns` (and the intercept),
    /// solved on the columns scaled to unit spread, and its sum of squared residuals,
    /// yy − xyᵀ·β.
    fn solve(&self, columns: &[usize]) -> Option<(DVector<f64>, f64)> {
        if columns.is_empty() {
            return Some((DVector::zeros(0), self.yy));
        }
        let scale: Vec<f64> = columns.iter().map(|&j| self.xx[(j, j)].sqrt()).collect();
        if scale.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
            return None;
        }
        let p = columns.len();
        let a = DMatrix::from_fn(p, p, |i, j| {
            self.xx[(columns[i], columns[j])] / (scale[i] * scale[j])
        });
        let b = DVector::from_fn(p, |i, _| self.xy[columns[i]] / scale[i]);
        let scaled = a.svd(true, true).solve(&b, 1e-12).ok()?;
        let explained = b.dot(&scaled);
        let beta = DVector::from_fn(p, |i, _| scaled[i] / scale[i]);
        explained
            .is_finite()
            .then(|| (beta, (self.yy - explained).max(0.0)))
    }

    /// Row k's residual under the coefficients `beta` of `columns`.
    fn residual(&self, design: &Design, columns: &[usize], beta: &DVector<f64>, k: usize) -> f64 {
        let fitted: f64 = columns
            .iter()
            .zip(beta.iter())
            .map(|(&j, b)| b * (design.regressor(j, k) - self.means[j]))
            .sum();
        design.target(k) - self.target_mean - fitted
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::guess::auto_guess;
    use crate::fit::{FitData, FitOptions, FitReport, fit};
    use crate::model::Structure;
    use crate::model::excitation::{Excitation, Hold};
    use crate::random::Lcg;

    /// A first-order plant y' = (Kp·u − y)/τ at h = 1 s, either under a PI controller
    /// (`closed`, with a setpoint step) or driven by a PRBS of one-sample clock (open loop),
    /// with white measurement noise; and its P1 fit.
    fn record(closed: bool, seed: u64) -> (FitData, FitReport) {
        let mut rng = Lcg(seed);
        let (kp, tau, n): (f64, f64, usize) = (2.0, 15.0, 800);
        let a = (-1.0 / tau).exp();
        let (mut x, mut integral) = (0.0, 0.0);
        let (mut times, mut u, mut y) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..n {
            let measured = 40.0 + x + 0.05 * rng.symmetric();
            let input = if closed {
                let setpoint = if k < 200 { 0.0 } else { 5.0 };
                let e = setpoint - (measured - 40.0);
                integral += 0.05 * e;
                20.0 + 0.4 * e + integral
            } else {
                20.0 + if rng.unit() < 0.5 { 0.0 } else { 3.0 }
            };
            times.push(k as f64);
            u.push(input);
            y.push(measured);
            x = a * x + (1.0 - a) * kp * (input - 20.0);
        }
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).expect("it moves");
        let data = FitData { times, y, input };
        let s = Structure::parse("P1").expect("a code");
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let report = fit(&data, s, auto_guess(&data, s, None), &options, &mut ()).expect("fits");
        (data, report)
    }

    fn named(closed: bool, seed: u64) -> Option<TestCause> {
        let (data, report) = record(closed, seed);
        closed_loop(&FittedRecord::new(&data, &report).expect("simulates"))
    }

    #[test]
    fn a_pi_loop_is_named_and_a_prbs_is_not() {
        for seed in 1..6 {
            let c = named(true, seed).expect("closed loop named");
            let TestEvidence::ClosedLoop { moves, f, dof, .. } = c.evidence else {
                panic!("{c:?}")
            };
            assert!(moves > 0.9 && f > 100.0 && dof.0 == RESIDUAL_LAGS, "{c:?}");
            assert_eq!(c.interval, Some((0.0, 799.0)));
            assert_eq!(named(false, seed), None, "seed {seed}");
        }
    }

    #[test]
    fn the_f_test_is_calibrated_on_independent_moves() {
        // Moves independent of the residuals: the statistic is F(4, ν); p < 0.001 in about
        // 1 of 1000.
        let mut rng = Lcg(5);
        let mut named = 0;
        for _ in 0..200 {
            let u: Vec<f64> = (0..400).map(|_| rng.symmetric()).collect();
            let e: Vec<f64> = (0..400).map(|_| rng.symmetric()).collect();
            let g = granger(&u, &e).expect("long enough");
            named += usize::from(g.significant());
        }
        assert!(named <= 2, "{named} of 200");
    }

    #[test]
    fn an_input_that_follows_the_residuals_is_found() {
        // u(k) = −0.5·e(k) + its own moves: the residuals explain a fifth of them.
        let mut rng = Lcg(8);
        let e: Vec<f64> = (0..400).map(|_| rng.symmetric()).collect();
        let u: Vec<f64> = e.iter().map(|x| 30.0 - 0.5 * x + rng.symmetric()).collect();
        let g = granger(&u, &e).expect("long enough");
        assert!(g.significant() && g.explained > 0.1, "{g:?}");
    }

    #[test]
    fn paulson_matches_tabulated_critical_values() {
        // F(4, 1000) at p = 0.001 is 4.65; F(4, 100) at p = 0.001 is 5.02.
        for (f, dof) in [(4.65, 1000), (5.02, 100)] {
            let g = Granger {
                f,
                dof: (4, dof),
                explained: 0.0,
            };
            assert!((g.z() - 3.09).abs() < 0.05, "{}", g.z());
        }
    }

    #[test]
    fn a_step_test_moves_too_rarely_to_be_read() {
        let times: Vec<f64> = (0..500).map(f64::from).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| if t < 50.0 { 10.0 } else { 20.0 })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        // Residuals that the input's change does follow, were it read.
        let y: Vec<f64> = times.iter().map(|&t| (t * 0.37).sin()).collect();
        let data = FitData { times, y, input };
        let s = Structure::parse("P1").unwrap();
        let report = fit(
            &data,
            s,
            auto_guess(&data, s, None),
            &FitOptions::default(),
            &mut (),
        );
        let report = report.unwrap();
        let record = FittedRecord::new(&data, &report).unwrap();
        assert_eq!(closed_loop(&record), None);
    }
}
