//! `outliers`: isolated samples that depart from what their neighbours say. A fit's
//! residuals are not judged against the model alone: a structure about to be extended (a
//! P1 start on a record with an overshoot, a zero, a dead time) leaves large *smooth*
//! residuals, and those are not wild samples. Each sample is judged on its isolation, twice:
//! - against a **local quadratic** through its neighbours ([`HALF_WINDOW`] each side, itself
//!   and the other candidates left out), which follows a peak or a bend of the residuals
//!   and of the data (a running median does not: it cuts a smooth peak by a share of its
//!   height); the deviation is divided by √(1 + the prediction's variance factor), so that
//!   on white noise it has the noise's own standard deviation;
//! - against the **running median** of seven samples, which follows a corner of a monotone
//!   stretch (a response starting after its dead time) where a quadratic does not.
//!
//! A sample is an outlier when its quadratic deviation exceeds the threshold and its running
//! median's half of it ([`RUNNING_SHARE`]), both in the residuals and in the data themselves (a model that misses the shape of a fast transient leaves
//! residuals that jump where the data are smooth), in a run of at most [`MAX_RUN`] samples;
//! more than [`MAX_SHARE`] of the record is not "isolated" and names nothing. The samples
//! right after an input change are not judged: the response turns a corner there.
//!
//! The scale is the noise's: 1.4826·MAD of the quadratic deviations of the residuals. The
//! threshold grows with the number of samples judged, N: the largest of N Gaussian values
//! is about √(2 ln N) σ, so a fixed multiple names wild samples on every long clean record;
//! it is max([`THRESHOLD`], √(2 ln N) + [`MARGIN`]) robust standard deviations (a clean
//! record of 10² to 10⁶ samples names none in more than 99 % of cases), and two output quanta
//! at least, so that a quantised record's level changes never count.
//!
//! The final fit weighs them with [`LOSS`], Cauchy's: its weight falls back towards zero
//! for a gross error (a spike or dropout of 6–15 σ counts for 1/7–1/40 of a sample), where
//! Huber's still lets each pull with a constant force; on P2 records with 2–6 % outliers
//! Cauchy's kept both lags within 10 % of the truth in 19 cases of 20, Huber's in 17.
//! Cost: O(N) (seven neighbours a sample).

use nalgebra::{Matrix3, Vector3};

use super::quantisation::resolution;
use super::{Handling, Loss, TestCause, TestCauseKind, TestEvidence};
use crate::fit::FitData;
use crate::stats::{median, robust_scale};

/// The robust loss the final fit weighs the outliers with.
pub const LOSS: Loss = Loss::Cauchy;
pub use crate::stats::OUTLIER_THRESHOLD as THRESHOLD;
/// Standard deviations over √(2 ln N) the threshold keeps (the chance that a clean
/// Gaussian record of N samples has one beyond it stays under about 0.5 % from 10² to 10⁶).
pub const MARGIN: f64 = 0.7;
/// The longest run of consecutive wild samples that is still isolated.
pub const MAX_RUN: usize = 3;
/// The largest share of the record that may be outliers.
pub const MAX_SHARE: f64 = 0.15;
/// The fewest samples a record needs for its outliers to be judged: below, seven neighbours
/// span a large part of the response (the LECI test's 35 samples: its first peak is three
/// samples wide), and an isolated sample cannot be told from the response's shape.
pub const MIN_SAMPLES: usize = 100;
/// Half the neighbourhood a sample is judged against (samples).
const HALF_WINDOW: usize = 3;
/// Robust standard deviations the neighbours may scatter about their own quadratic (root
/// mean square) for a sample to be judged against it: where they do not lie on one (a
/// response sampled too slowly for seven samples to follow its peak), a sample that departs
/// from them is not isolated from a smooth trend, and is not judged. Loose enough that a
/// half-recovered sample after a dropout run leaves its neighbours judged; white noise
/// never reaches it.
const SMOOTH: f64 = 8.0;
/// The farthest a neighbour in a sample's quadratic may be (sampling periods).
const MAX_REACH: f64 = 6.5;
/// Robust standard deviations beyond which a sample is left out of its neighbours'
/// quadratics (a candidate, see [`masked_deviations`]), so that a run of two or three wild
/// samples does not hide itself and a spike does not drag its neighbours' predictions.
const CANDIDATE: f64 = 3.0;
/// The share of the threshold a sample must stand out of the running median by: it only
/// tells a corner (where it stays at the noise) from a spike, and a spike on a steep slope
/// stands out of the median by less than its height.
const RUNNING_SHARE: f64 = 0.5;

/// The threshold, in robust standard deviations, for `n` samples judged.
pub fn sigmas(n: usize) -> f64 {
    THRESHOLD.max(crate::stats::largest_of_gaussians(n) + MARGIN)
}

/// The outliers of `residuals` (of a fit on `data`) and their indices.
pub fn detect(data: &FitData, residuals: &[f64]) -> Option<(TestCause, Vec<usize>)> {
    let n = residuals.len();
    if n < MIN_SAMPLES || n != data.times.len() || n != data.y.len() {
        return None;
    }
    let h = data.sampling_period();
    let Masked {
        local,
        rough,
        skip: candidate,
        scale,
    } = masked_deviations(&data.times, residuals, h);
    let running = deviations(residuals);
    let (own_running, own_local) = (
        deviations(&data.y),
        local_deviations(&data.times, &data.y, &candidate, h),
    );
    let corner = near_changes(data);
    let judged = (0..n)
        .filter(|&i| !corner[i] && local[i].is_finite())
        .count();
    let sigmas = sigmas(judged);
    let quantum = resolution(&data.y).unwrap_or(0.0);
    let threshold = (sigmas * scale).max(2.0 * quantum);
    if threshold.is_nan() || threshold <= 0.0 {
        return None;
    }
    let beyond = |d: f64, share: f64| d.abs() > share * threshold;
    let wild: Vec<usize> = (0..n)
        .filter(|&i| {
            !corner[i]
                && rough[i] <= SMOOTH * scale
                && beyond(local[i], 1.0)
                && beyond(own_local[i], 1.0)
                && beyond(running[i], RUNNING_SHARE)
                && beyond(own_running[i], RUNNING_SHARE)
        })
        .collect();
    let isolated: Vec<usize> = runs(&wild)
        .into_iter()
        .filter(|r| r.len() <= MAX_RUN)
        .flatten()
        .collect();
    if isolated.is_empty() || isolated.len() as f64 > MAX_SHARE * n as f64 {
        return None;
    }
    let worst = isolated
        .iter()
        .map(|&i| running[i])
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(0.0);
    let times: Vec<f64> = isolated.iter().map(|&i| data.times[i]).collect();
    let interval = times.first().zip(times.last()).map(|(a, b)| (*a, *b));
    let cause = TestCause {
        kind: TestCauseKind::Outliers,
        evidence: TestEvidence::Outliers {
            count: isolated.len(),
            times,
            scale,
            sigmas,
            threshold,
            worst,
        },
        interval,
        handling: Handling::RobustLoss { loss: LOSS },
    };
    Some((cause, isolated))
}

/// The quadratic deviations of `x` ([`local_deviations`]) with the candidates left out of
/// their neighbours' quadratics, the candidates, and the noise's robust scale (from a first
/// look with every neighbour in). A candidate stands out by more than [`CANDIDATE`] robust
/// standard deviations both of the running median of seven ([`deviations`]), which a run
/// of up to three wild samples does not move (a first quadratic look takes a run's
/// neighbours for wild ones), and of that first look (a smooth peak stands out of a
/// running median, not of a quadratic: masking it would leave its neighbours' quadratics
/// to reach further and bend less).
fn masked_deviations(times: &[f64], x: &[f64], h: f64) -> Masked {
    let first_look = local_deviations(times, x, &vec![false; x.len()], h);
    let scale = robust_scale(&finite(&first_look));
    let beyond = |d: f64| d.abs() > CANDIDATE * scale;
    let skip: Vec<bool> = deviations(x)
        .iter()
        .zip(&first_look)
        .map(|(&running, &local)| beyond(running) && beyond(local))
        .collect();
    let (local, rough) = (0..x.len())
        .map(|i| local_deviation(times, x, &skip, h, i))
        .unzip();
    Masked {
        local,
        rough,
        skip,
        scale,
    }
}

/// What [`masked_deviations`] reads: each sample's quadratic deviation and its neighbours'
/// root mean square about their quadratic, the candidates, and the noise's robust scale.
struct Masked {
    local: Vec<f64>,
    rough: Vec<f64>,
    skip: Vec<bool>,
    scale: f64,
}

/// The finite values of `v`.
fn finite(v: &[f64]) -> Vec<f64> {
    v.iter().copied().filter(|x| x.is_finite()).collect()
}

/// Each value less the running median of its neighbours ([`HALF_WINDOW`] each side, itself
/// included).
fn deviations(x: &[f64]) -> Vec<f64> {
    let n = x.len();
    (0..n)
        .map(|i| {
            let lo = i.saturating_sub(HALF_WINDOW);
            let hi = (i + HALF_WINDOW + 1).min(n);
            x[i] - median(&x[lo..hi])
        })
        .collect()
}

/// Each value less the least-squares quadratic in time through its neighbours (the nearest
/// [`HALF_WINDOW`] each side not `skip`ped, see [`quadratic_prediction`]), divided by √(1 + v) where v·σ² is the prediction's variance on
/// white noise of σ: on white noise each has the noise's standard deviation. NaN where
/// fewer than four neighbours are left or one side has none (the record's ends).
fn local_deviations(times: &[f64], x: &[f64], skip: &[bool], h: f64) -> Vec<f64> {
    (0..x.len())
        .map(|i| local_deviation(times, x, skip, h, i).0)
        .collect()
}

/// Sample `i`'s deviation of [`local_deviations`] and the root mean square of its
/// neighbours about their own quadratic (NaN, NaN where none is fitted).
fn local_deviation(times: &[f64], x: &[f64], skip: &[bool], h: f64, i: usize) -> (f64, f64) {
    quadratic_prediction(times, x, skip, h, i).map_or((f64::NAN, f64::NAN), |(p, v, rms)| {
        ((x[i] - p) / (1.0 + v).sqrt(), rms)
    })
}

/// The prediction at sample `i` of the quadratic through its neighbours (see
/// [`local_deviations`]) and its variance factor: up to [`HALF_WINDOW`] on each side, the
/// nearest not skipped, within [`MAX_REACH`] sampling periods (a run of wild samples left
/// out pushes them further).
fn quadratic_prediction(
    times: &[f64],
    x: &[f64],
    skip: &[bool],
    h: f64,
    i: usize,
) -> Option<(f64, f64, f64)> {
    let usable = |j: &usize| *j != i && !skip[*j] && x[*j].is_finite();
    let near = |j: &usize| ((times[*j] - times[i]) / h).abs() <= MAX_REACH;
    let left = (i.saturating_sub(2 * MAX_REACH as usize)..i)
        .rev()
        .filter(usable)
        .take_while(near)
        .take(HALF_WINDOW);
    let right = (i + 1..(i + 2 * MAX_REACH as usize + 1).min(x.len()))
        .filter(usable)
        .take_while(near)
        .take(HALF_WINDOW);
    let (mut gram, mut moment) = (Matrix3::<f64>::zeros(), Vector3::<f64>::zeros());
    let (mut sides, mut count) = ([0usize; 2], 0);
    // Values about the sample's own level, so that a level far from zero costs no digits.
    let origin = x[i];
    let mut used = Vec::with_capacity(2 * HALF_WINDOW);
    for j in left.chain(right) {
        let k = (times[j] - times[i]) / h;
        let row = Vector3::new(1.0, k, k * k);
        gram += row * row.transpose();
        moment += row * (x[j] - origin);
        used.push((k, x[j] - origin));
        sides[usize::from(j > i)] += 1;
        count += 1;
    }
    if sides.contains(&0) || count < 4 {
        return None;
    }
    let inverse = gram.try_inverse()?;
    let c = inverse * moment;
    let misfit: f64 = used
        .iter()
        .map(|&(k, v)| (v - c[0] - c[1] * k - c[2] * k * k).powi(2))
        .sum();
    let rms = (misfit / (count - 3) as f64).sqrt();
    Some((origin + c[0], inverse[(0, 0)], rms))
}

/// The samples within a window after an input change: the response turns a corner there
/// (its slope jumps), which a running median leaves in the deviations; they are not judged.
fn near_changes(data: &FitData) -> Vec<bool> {
    let mut near = vec![false; data.times.len()];
    for c in &data.input.changes {
        let k = data.times.partition_point(|&t| t < c.t).min(near.len());
        let from = k.saturating_sub(HALF_WINDOW);
        let to = (k + 2 * HALF_WINDOW + 1).min(near.len());
        near[from..to].iter_mut().for_each(|x| *x = true);
    }
    near
}

/// Consecutive runs of sorted indices.
pub(super) fn runs(indices: &[usize]) -> Vec<Vec<usize>> {
    let mut out: Vec<Vec<usize>> = Vec::new();
    for &i in indices {
        match out.last_mut() {
            Some(run) if run.last().is_some_and(|&l| l + 1 == i) => run.push(i),
            _ => out.push(vec![i]),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::excitation::Excitation;

    fn data(y: Vec<f64>) -> FitData {
        FitData {
            times: (0..y.len()).map(|k| k as f64).collect(),
            y,
            input: Excitation::step(10.0, 1.0),
        }
    }

    #[test]
    fn isolated_spikes_are_found_and_a_smooth_misfit_is_not() {
        let mut rng = crate::random::Lcg(7);
        let n: Vec<f64> = (0..200).map(|_| 0.005 * rng.symmetric()).collect();
        let noise = |i: usize| n[i];
        // A smooth bump the model lacks, plus spikes at 50 and 51 and 120.
        let mut r: Vec<f64> = (0..200)
            .map(|i| 0.5 * (-((i as f64 - 80.0) / 15.0).powi(2)).exp() + noise(i))
            .collect();
        for i in [50, 51, 120] {
            r[i] -= 1.0;
        }
        let d = data(r.clone());
        let (cause, samples) = detect(&d, &r).unwrap();
        assert_eq!(samples, vec![50, 51, 120]);
        let TestEvidence::Outliers { count, worst, .. } = cause.evidence else {
            panic!()
        };
        assert_eq!(count, 3);
        assert!(worst < -0.9);
        let clean: Vec<f64> = (0..200).map(noise).collect();
        assert!(detect(&d, &clean).is_none());
    }

    fn gaussian_noise(seed: u64, n: usize, sd: f64) -> Vec<f64> {
        let mut rng = crate::random::Lcg(seed);
        (0..n)
            .map(|_| {
                let (a, b) = (rng.unit().max(1e-300), rng.unit());
                sd * (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
            })
            .collect()
    }

    /// The residuals of a wrong start on an oscillating record: a decaying oscillation of
    /// twelve samples a period, 30 times the noise, whose peaks stand out of a running
    /// median of seven by half their height. They are smooth, not wild: nothing is named.
    #[test]
    fn the_peaks_of_a_smooth_misfit_are_not_outliers() {
        let noise = gaussian_noise(3, 400, 0.01);
        let r: Vec<f64> = (0..400)
            .map(|i| {
                let t = i as f64;
                0.3 * (-t / 150.0).exp() * (std::f64::consts::TAU * t / 12.0).sin() + noise[i]
            })
            .collect();
        assert!(detect(&data(r.clone()), &r).is_none());
        // The same with one spike of 12 σ: it alone is found.
        let mut spiked = r.clone();
        spiked[203] += 0.12;
        let (_, samples) = detect(&data(spiked.clone()), &spiked).expect("the spike");
        assert_eq!(samples, vec![203]);
    }

    /// The threshold grows with the record: 10⁵ samples of white Gaussian noise hold about
    /// 57 beyond 4.5 σ (a fixed threshold near that named them), none beyond √(2 ln N) + 0.7.
    #[test]
    fn a_long_clean_record_names_none() {
        assert_eq!(sigmas(100), THRESHOLD);
        assert!((sigmas(1_000_000) - 5.957).abs() < 0.01);
        for seed in [11, 12, 13] {
            let r = gaussian_noise(seed, 100_000, 0.01);
            let found = detect(&data(r.clone()), &r);
            assert!(found.is_none(), "{:?}", found.map(|f| f.0));
        }
    }

    #[test]
    fn a_block_is_not_isolated() {
        let mut rng = crate::random::Lcg(9);
        let mut r: Vec<f64> = (0..100).map(|_| 0.01 * rng.symmetric()).collect();
        for v in &mut r[40..46] {
            *v += 1.0;
        }
        assert!(detect(&data(r.clone()), &r).is_none());
        assert_eq!(
            runs(&[1, 2, 3, 7, 9, 10]),
            vec![vec![1, 2, 3], vec![7], vec![9, 10]]
        );
    }
}
