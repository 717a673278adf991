//! The reduced record a long fit searches on: every sample just after each input change (and
//! after the record's start), ever fewer as the response settles, so that each transient
//! keeps its detail while the settled stretches keep only enough samples to show their level.
//!
//! The multi-start search runs on it; the final fit and its intervals use every sample
//! ([`crate::fit::fit`]). The spacing is set in samples, not seconds, so it needs no time
//! constant: counting j samples since the latest change (or the record's start), the gap
//! between kept samples is the largest power of two not above max(1, j/[`DENSE`]), capped
//! at n/[`SETTLED`] samples. Every sample of the first 2·[`DENSE`] after a change is kept,
//! then [`DENSE`] samples per doubling of the time since it: a time constant of any length
//! is seen by about [`DENSE`] samples, and the dead time's end within 1/[`DENSE`] of its
//! value. The gaps are powers of two so that consecutive gaps repeat (the simulation
//! advances by one cached exponential per distinct gap).
//!
//! Each sample of the reduced record is the mean of a block of consecutive samples (one
//! sample where every sample is kept), at the block's mean instant, weighted by the block's
//! length: where the response is nearly straight over a block (the gaps grow with the time
//! since the change, so it is), the weighted sum of squares over the reduced record plus the
//! scatter within the blocks ([`Reduction::within`], which no model changes) is the full
//! record's, and the least-squares optimum is nearly the full record's (the noise of every
//! sample still counts: a block's mean carries its samples' information about the level).
//!
//! An input that changes nearly everywhere (a PRBS) leaves little to reduce this way; the
//! record is then averaged in uniform blocks of a length that keeps [`PER_INTERVAL`] of them
//! in the shortest interval between two changes. A record of at most [`MIN_SAMPLES`]
//! samples, or one that would not shrink by half, is its own reduction.

use crate::fit::FitData;
use crate::model::excitation::Excitation;
use crate::stats::mean;

/// A record of at most this many samples is not reduced.
pub const MIN_SAMPLES: usize = 4096;
/// Samples kept per doubling of the time since the latest change.
pub const DENSE: usize = 32;
/// The settled stretches keep a sample at least every n/`SETTLED` samples.
pub const SETTLED: usize = 512;
/// Samples a uniform decimation keeps in the shortest interval between two changes.
pub const PER_INTERVAL: usize = 8;

/// The blocks of consecutive samples a reduced record averages.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduction {
    /// The first sample of each block, ascending from 0; each block runs to the next one's
    /// first sample (the last to the record's end).
    pub starts: Vec<usize>,
    /// Samples in the record.
    pub n: usize,
}

impl Reduction {
    /// How many blocks (samples of the reduced record) there are.
    pub fn len(&self) -> usize {
        self.starts.len()
    }

    /// True when there is no block (never for a reduction [`reduce`] returns).
    pub fn is_empty(&self) -> bool {
        self.starts.is_empty()
    }

    /// The sample ranges of the blocks.
    pub fn blocks(&self) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
        let ends = self.starts.iter().skip(1).copied().chain([self.n]);
        self.starts.iter().zip(ends).map(|(&a, b)| a..b)
    }

    /// How many samples each block stands for (they add up to n).
    pub fn weights(&self) -> Vec<f64> {
        self.blocks().map(|b| b.len() as f64).collect()
    }

    /// The reduced record: each block's mean instant and mean output, with the same input.
    pub fn apply(&self, data: &FitData) -> FitData {
        FitData {
            times: self.blocks().map(|b| mean(&data.times[b])).collect(),
            y: self.blocks().map(|b| mean(&data.y[b])).collect(),
            input: data.input.clone(),
        }
    }

    /// What the record's sum of squares holds beyond the reduced record's weighted one: the
    /// noise within the blocks, which no model changes. Each block's scatter about its own
    /// least-squares line in time (so that the response's own slope across a block is not
    /// counted as scatter), times (k − 1)/(k − 2) for its k samples (the expected share of
    /// the noise the residuals keep there); about the mean for a block of two.
    pub fn within(&self, times: &[f64], y: &[f64]) -> f64 {
        self.blocks()
            .map(|b| scatter(&times[b.clone()], &y[b]))
            .sum()
    }
}

/// The scatter of one block (see [`Reduction::within`]).
fn scatter(t: &[f64], y: &[f64]) -> f64 {
    let k = y.len();
    let (tm, ym) = (mean(t), mean(y));
    let syy: f64 = y.iter().map(|v| (v - ym) * (v - ym)).sum();
    if k < 3 {
        return syy;
    }
    let stt: f64 = t.iter().map(|v| (v - tm) * (v - tm)).sum();
    let sty: f64 = t.iter().zip(y).map(|(a, b)| (a - tm) * (b - ym)).sum();
    let about_line = if stt > 0.0 {
        syy - sty * sty / stt
    } else {
        syy
    };
    about_line.max(0.0) * (k - 1) as f64 / (k - 2) as f64
}

/// The reduction of the record sampled at `times` (ascending) and driven by `input`, or
/// `None` when the record is its own reduction (see the module docs).
pub fn reduce(times: &[f64], input: &Excitation) -> Option<Reduction> {
    let n = times.len();
    if n <= MIN_SAMPLES {
        return None;
    }
    let origins = change_indices(times, input);
    let starts = by_elapsed_time(n, &origins);
    let starts = if starts.len() <= n / 2 {
        starts
    } else {
        uniform(n, &origins)?
    };
    (starts.len() <= n / 2).then_some(Reduction { starts, n })
}

/// `data` reduced, or a copy of it when it is its own reduction.
pub fn reduced(data: &FitData) -> FitData {
    match reduce(&data.times, &data.input) {
        Some(r) => r.apply(data),
        None => data.clone(),
    }
}

/// The first sample at or after each significant change, ascending and distinct (changes
/// before the record count at its first sample).
fn change_indices(times: &[f64], input: &Excitation) -> Vec<usize> {
    let mut out: Vec<usize> = input
        .changes
        .iter()
        .map(|c| times.partition_point(|&t| t < c.t))
        .filter(|&i| i < times.len())
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// Block starts: blocks doubling in length with the samples since the latest origin (the
/// record's start or a change), one sample long for the first 2·[`DENSE`]; the sample
/// before each change is a block of its own.
fn by_elapsed_time(n: usize, changes: &[usize]) -> Vec<usize> {
    let cap = largest_power_of_two(n / SETTLED).max(1);
    let mut starts = Vec::new();
    let mut next_change = changes.iter().copied().filter(|&c| c > 0).peekable();
    let mut origin = 0;
    let mut i = 0;
    while i < n {
        starts.push(i);
        let elapsed = i - origin;
        let gap = largest_power_of_two(elapsed / DENSE).clamp(1, cap);
        let mut next = i + gap;
        if let Some(&c) = next_change.peek()
            && c <= next
        {
            // The level just before the change, then the change itself.
            if c > i + 1 {
                starts.push(c - 1);
            }
            next = c;
            origin = c;
            next_change.next();
        }
        i = next;
    }
    starts
}

/// Blocks of k samples, k the largest that keeps [`PER_INTERVAL`] blocks in the shortest
/// interval between changes and at least [`MIN_SAMPLES`] blocks; `None` for k < 2.
fn uniform(n: usize, changes: &[usize]) -> Option<Vec<usize>> {
    let shortest = changes.windows(2).map(|w| w[1] - w[0]).min().unwrap_or(n);
    let k = (shortest / PER_INTERVAL).min(n / MIN_SAMPLES);
    (k >= 2).then(|| (0..n).step_by(k).collect())
}

/// The largest power of two not above `x` (0 for 0).
fn largest_power_of_two(x: usize) -> usize {
    if x == 0 { 0 } else { 1 << x.ilog2() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::guess::auto_guess;
    use crate::fit::{FitOptions, FitReport, fit, search_fit};
    use crate::model::excitation::Hold;
    use crate::model::{Model, Param, Structure, Values};
    use crate::random::Lcg;

    /// A P1D record of `n` samples every `ts` s driven by the input `levels` (instant, level)
    /// held between samples, with uniform noise ±`noise`, operating point 30.
    fn record(n: usize, ts: f64, levels: &[(f64, f64)], noise: f64, seed: u64) -> FitData {
        let times: Vec<f64> = (0..n).map(|k| ts * k as f64).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| {
                levels
                    .iter()
                    .take_while(|(s, _)| *s <= t)
                    .last()
                    .map_or(2.0, |l| l.1)
            })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        let mut y = truth().simulate(&input, &times).unwrap();
        let mut rng = Lcg(seed);
        y.iter_mut().for_each(|y| *y += noise * rng.symmetric());
        FitData { times, y, input }
    }

    /// The process: P1D, Kp 1.5, Tp1 4 s, Td 0.75 s, Y0 30.
    fn truth() -> Model {
        let mut v = Values::default();
        for (p, x) in [
            (Param::Kp, 1.5),
            (Param::Tp1, 4.0),
            (Param::Td, 0.75),
            (Param::Y0, 30.0),
        ] {
            v.set(p, x);
        }
        Model::new(Structure::parse("P1D").unwrap(), v)
    }

    fn p1d_fit(data: &FitData) -> FitReport {
        let s = Structure::parse("P1D").unwrap();
        let guess = auto_guess(data, s, None);
        fit(data, s, guess, &FitOptions::default(), &mut ()).unwrap()
    }

    const STEPS: [(f64, f64); 4] = [(5.0, 4.0), (25.0, 1.0), (45.0, 3.5), (62.0, 2.5)];

    #[test]
    fn a_short_record_is_its_own_reduction() {
        let data = record(MIN_SAMPLES, 80.0 / MIN_SAMPLES as f64, &STEPS, 0.01, 3);
        assert!(reduce(&data.times, &data.input).is_none());
        assert_eq!(reduced(&data), data);
    }

    #[test]
    fn every_sample_after_each_change_is_kept_and_the_weights_add_up() {
        let n = 80_000;
        let data = record(n, 1e-3, &STEPS, 0.01, 4);
        let r = reduce(&data.times, &data.input).unwrap();
        assert!(r.len() < n / 20, "{} kept", r.len());
        assert_eq!(r.weights().iter().sum::<f64>(), n as f64);
        let blocks: Vec<_> = r.blocks().collect();
        assert!(
            blocks
                .windows(2)
                .all(|w| w[0].end == w[1].start && !w[0].is_empty())
        );
        for (t, _) in STEPS {
            let first = data.times.partition_point(|&s| s < t);
            for i in first - 1..first + 2 * DENSE {
                assert!(r.starts.binary_search(&i).is_ok(), "sample {i} after {t}");
                assert_eq!(blocks[r.starts.binary_search(&i).unwrap()].len(), 1);
            }
        }
        let longest = blocks.iter().map(|b| b.len()).max().unwrap();
        assert!(longest <= n / SETTLED, "{longest}");
        // The block means and the noise within the blocks make up the residual scatter of
        // the true model: the weighted sum of squares plus `within` is the full one.
        let small = r.apply(&data);
        let model = truth();
        let full: f64 = model
            .simulate(&data.input, &data.times)
            .unwrap()
            .iter()
            .zip(&data.y)
            .map(|(m, y)| (y - m) * (y - m))
            .sum();
        let means: f64 = model
            .simulate(&data.input, &small.times)
            .unwrap()
            .iter()
            .zip(&small.y)
            .zip(r.weights())
            .map(|((m, y), w)| w * (y - m) * (y - m))
            .sum();
        let total = means + r.within(&data.times, &data.y);
        assert!((total / full - 1.0).abs() < 0.02, "{total} vs {full}");
    }

    #[test]
    fn an_input_changing_everywhere_is_averaged_in_uniform_blocks() {
        let levels: Vec<(f64, f64)> = (0..2000)
            .map(|k| (0.04 * k as f64 + 0.02, if k % 2 == 0 { 1.0 } else { 3.0 }))
            .collect();
        let data = record(80_000, 1e-3, &levels, 0.01, 5);
        let r = reduce(&data.times, &data.input).unwrap();
        let lengths: Vec<usize> = r.blocks().map(|b| b.len()).collect();
        // The shortest constant stretch is 39 or 40 samples (the instants round either way).
        let k = lengths[0];
        assert!(lengths[..lengths.len() - 1].iter().all(|&g| g == k));
        assert!(k >= 2 && 39 / k >= PER_INTERVAL, "{k}");
        assert_eq!(r.weights().iter().sum::<f64>(), 80_000.0);
    }

    #[test]
    fn the_reduced_fit_lands_within_the_full_fits_intervals() {
        let s = Structure::parse("P1D").unwrap();
        for (seed, noise) in [(11, 0.02), (12, 0.2), (13, 0.05)] {
            let data = record(20_000, 4e-3, &STEPS, noise, seed);
            assert!(reduce(&data.times, &data.input).is_some());
            let full = p1d_fit(&data);
            let guess = auto_guess(&data, s, None);
            let small = search_fit(&data, s, guess, &FitOptions::default()).unwrap();
            for p in [Param::Kp, Param::Tp1, Param::Td, Param::Y0] {
                let (lo, hi) = full.interval(p).unwrap();
                let v = small.model.get(p);
                assert!(lo <= v && v <= hi, "{p:?}: {v} outside [{lo}, {hi}]");
            }
            // Its statistics stand for the whole record's.
            assert_eq!(small.n, full.n);
            assert!(
                (small.rmse / full.rmse - 1.0).abs() < 0.01,
                "{} {}",
                small.rmse,
                full.rmse
            );
        }
    }
}
