//! A pseudo-random binary sequence (PRBS) to design an identification test, like MATLAB's
//! `idinput(N, 'prbs', [0 B], [lo hi])` and its periodic form `idinput([P 1 M], …)`.
//!
//! - **The sequence**: a maximal-length linear feedback shift register of n bits (a Fibonacci
//!   LFSR: the new bit is the XOR of the taps [`taps`], the register starts all ones), whose
//!   output repeats every 2ⁿ − 1 bits and, over one period, has 2ⁿ⁻¹ ones and 2ⁿ⁻¹ − 1
//!   zeros: one more high than low. The taps are the standard maximal-length table (Xilinx
//!   XAPP052); the tests check every order's period.
//! - **The clock period** (samples per bit, idinput's 1/B for band [0 B]): each bit is held
//!   for `clock` samples, so one period of the signal is (2ⁿ − 1)·clock samples.
//! - **Levels**: bit 1 → `high`, bit 0 → `low`.
//! - **Length or periods**: [`Prbs::for_length`] picks the shortest register whose period
//!   covers N samples (one non-repeating stretch, as idinput does for a non-periodic PRBS);
//!   [`Prbs::periodic`] repeats whole periods, for a test whose transients have died out.
//!
//! Written here rather than taken from a crate: the whole generator is a dozen lines and
//! no dependency offers idinput's conventions.
//!
//! [`simulate_record`] gives a chosen model's response to the signal with noise, exactly
//! (the measured input held between samples, [`Excitation::measured`] + [`Model::simulate`]),
//! and [`to_csv`] writes the record as `time,u,y`, readable by `degrau fit`. A time column
//! or an output beyond double precision (a huge period, gain or noise) is refused, never
//! written as infinities.

use serde::{Deserialize, Serialize};

use crate::model::excitation::{Excitation, Hold};
use crate::model::{Model, ModelError};
use crate::random::Lcg;

/// The shortest and longest registers offered.
pub const MIN_ORDER: u32 = 2;
pub const MAX_ORDER: u32 = 24;

/// The most samples a generated signal may have.
pub const MAX_SAMPLES: usize = 10_000_000;

/// The feedback taps of an n-bit maximal-length register (bit positions counted from 1).
pub fn taps(order: u32) -> &'static [u32] {
    match order {
        2 => &[2, 1],
        3 => &[3, 2],
        4 => &[4, 3],
        5 => &[5, 3],
        6 => &[6, 5],
        7 => &[7, 6],
        8 => &[8, 6, 5, 4],
        9 => &[9, 5],
        10 => &[10, 7],
        11 => &[11, 9],
        12 => &[12, 6, 4, 1],
        13 => &[13, 4, 3, 1],
        14 => &[14, 5, 3, 1],
        15 => &[15, 14],
        16 => &[16, 15, 13, 4],
        17 => &[17, 14],
        18 => &[18, 11],
        19 => &[19, 6, 2, 1],
        20 => &[20, 17],
        21 => &[21, 19],
        22 => &[22, 21],
        23 => &[23, 18],
        24 => &[24, 23, 22, 17],
        _ => &[],
    }
}

/// What stops a PRBS (`crate::words::lsq` says it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum PrbsError {
    /// The register order is outside [`MIN_ORDER`]..=[`MAX_ORDER`].
    BadOrder(u32),
    /// The clock period is 0 samples.
    BadClock,
    /// A level is not finite, or the two are equal.
    BadLevels { low: f64, high: f64 },
    /// No register of at most [`MAX_ORDER`] bits covers this many samples, or the signal
    /// would exceed [`MAX_SAMPLES`], or it has none.
    BadLength(usize),
    /// The noise level is negative or not finite, or the period is not positive.
    BadSimulation,
    /// `samples` samples every `ts` seconds end beyond double precision.
    TimeBeyondRange { samples: usize, ts: f64 },
    /// The simulated output (with its noise) goes beyond double precision.
    OutputBeyondRange,
    /// The model cannot be simulated.
    Model(ModelError),
}

/// A PRBS design.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Prbs {
    /// Register length n (bits): the sequence repeats every 2ⁿ − 1 bits.
    pub order: u32,
    /// Samples per bit.
    pub clock: usize,
    pub low: f64,
    pub high: f64,
}

impl Prbs {
    pub fn new(order: u32, clock: usize, low: f64, high: f64) -> Result<Self, PrbsError> {
        if !(MIN_ORDER..=MAX_ORDER).contains(&order) {
            return Err(PrbsError::BadOrder(order));
        }
        if clock == 0 {
            return Err(PrbsError::BadClock);
        }
        // A subnormal level carries too few digits: a model's response to it came out 0.
        let usable = |x: f64| x.is_finite() && !x.is_subnormal();
        if !(usable(low) && usable(high)) || low == high {
            return Err(PrbsError::BadLevels { low, high });
        }
        Ok(Self {
            order,
            clock,
            low,
            high,
        })
    }

    /// The shortest register whose period ((2ⁿ − 1)·clock samples) covers `samples`.
    pub fn for_length(
        samples: usize,
        clock: usize,
        low: f64,
        high: f64,
    ) -> Result<Self, PrbsError> {
        if samples == 0 || samples > MAX_SAMPLES {
            return Err(PrbsError::BadLength(samples));
        }
        let clock_ok = clock.max(1);
        let order = (MIN_ORDER..=MAX_ORDER)
            .find(|&n| ((1usize << n) - 1).saturating_mul(clock_ok) >= samples)
            .ok_or(PrbsError::BadLength(samples))?;
        Self::new(order, clock, low, high)
    }

    /// Bits per period, 2ⁿ − 1.
    pub fn bits_per_period(&self) -> usize {
        (1usize << self.order) - 1
    }

    /// Samples per period, (2ⁿ − 1)·clock.
    pub fn period(&self) -> usize {
        self.bits_per_period() * self.clock
    }

    /// One period of the register's output bits.
    pub fn bits(&self) -> Vec<bool> {
        let n = self.order;
        let mask = (1u32 << n) - 1;
        let mut state = mask;
        let taps = taps(n);
        (0..self.bits_per_period())
            .map(|_| {
                let out = state & 1 == 1;
                let feedback = taps
                    .iter()
                    .fold(0, |acc, &t| acc ^ ((state >> (n - t)) & 1));
                state = ((state >> 1) | (feedback << (n - 1))) & mask;
                out
            })
            .collect()
    }

    /// The first `samples` samples of the signal (repeating its period as needed).
    pub fn signal(&self, samples: usize) -> Result<Vec<f64>, PrbsError> {
        if samples == 0 || samples > MAX_SAMPLES {
            return Err(PrbsError::BadLength(samples));
        }
        let bits = self.bits();
        Ok((0..samples)
            .map(|k| {
                if bits[(k / self.clock) % bits.len()] {
                    self.high
                } else {
                    self.low
                }
            })
            .collect())
    }

    /// `periods` whole periods of the signal.
    pub fn periodic(&self, periods: usize) -> Result<Vec<f64>, PrbsError> {
        self.signal(self.period().saturating_mul(periods))
    }
}

/// A simulated test record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// k·h (s).
    pub time: Vec<f64>,
    pub u: Vec<f64>,
    pub y: Vec<f64>,
}

/// The response of `model` to the input `u` sampled every `ts` seconds (held between
/// samples), at rest before the first sample with the input at `u[0]`, and Y0 the output
/// at rest at the input's lower level: levels 0/1 through a gain of 2 give an output
/// between Y0 and Y0 + 2 whichever the first bit (measured from a first high bit it ran
/// from −2 to 0). An integrating model has no rest but at its Y0. With white Gaussian noise
/// of standard deviation `noise` (output units) from the seed `seed`.
pub fn simulate_record(
    model: &Model,
    u: &[f64],
    ts: f64,
    noise: f64,
    seed: u64,
) -> Result<Record, PrbsError> {
    if !(noise.is_finite() && noise >= 0.0) || u.is_empty() {
        return Err(PrbsError::BadSimulation);
    }
    let time = sample_times(u.len(), ts)?;
    let mut y = match Excitation::measured(&time, u, None, Hold::Zoh) {
        Some(input) => model.simulate(&input, &time).map_err(PrbsError::Model)?,
        None => vec![model.get(crate::model::Param::Y0); u.len()],
    };
    let low = u.iter().copied().fold(f64::INFINITY, f64::min);
    let gain = model.transfer_function().map_or(f64::NAN, |g| g.dc_gain());
    let rest = gain * (u[0] - low);
    if rest.is_finite() && rest != 0.0 {
        y.iter_mut().for_each(|v| *v += rest);
    }
    let mut rng = Lcg(seed);
    if noise > 0.0 {
        for v in &mut y {
            *v += noise * rng.gaussian();
        }
    }
    if y.iter().any(|v| !v.is_finite()) {
        return Err(PrbsError::OutputBeyondRange);
    }
    Ok(Record {
        time,
        u: u.to_vec(),
        y,
    })
}

/// The instants k·`ts` of `samples` samples (s), refused when the period is not a positive
/// number or the last instant is beyond double precision.
pub fn sample_times(samples: usize, ts: f64) -> Result<Vec<f64>, PrbsError> {
    if !(ts.is_finite() && ts > 0.0) {
        return Err(PrbsError::BadSimulation);
    }
    if !(samples.saturating_sub(1) as f64 * ts).is_finite() {
        return Err(PrbsError::TimeBeyondRange { samples, ts });
    }
    Ok((0..samples).map(|k| k as f64 * ts).collect())
}

/// The record as CSV with the header `time,u,y`, every number written so it reads back
/// exactly.
pub fn to_csv(record: &Record) -> String {
    let mut out = String::from("time,u,y\n");
    for ((t, u), y) in record.time.iter().zip(&record.u).zip(&record.y) {
        out.push_str(&format!("{t},{u},{y}\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_register_is_maximal_length() {
        for n in MIN_ORDER..=18 {
            let p = Prbs::new(n, 1, 0.0, 1.0).unwrap();
            let bits = p.bits();
            // Maximal length: every nonzero n-bit window appears once per period.
            let len = bits.len();
            let windows: std::collections::HashSet<u32> = (0..len)
                .map(|k| (0..n as usize).fold(0, |w, i| (w << 1) | bits[(k + i) % len] as u32))
                .collect();
            assert_eq!(windows.len(), len, "order {n}");
            assert!(!windows.contains(&0));
            let ones = bits.iter().filter(|&&b| b).count();
            assert_eq!(ones, 1 << (n - 1), "order {n}");
        }
    }

    #[test]
    fn clock_and_levels() {
        let p = Prbs::new(5, 3, -2.0, 4.0).unwrap();
        let s = p.periodic(2).unwrap();
        assert_eq!(s.len(), 2 * 31 * 3);
        assert!(s.iter().all(|&v| v == -2.0 || v == 4.0));
        assert!(s.chunks(3).all(|c| c.iter().all(|&v| v == c[0])));
        assert_eq!(s[..93], s[93..]);
    }

    #[test]
    fn for_length_picks_the_shortest_register() {
        assert_eq!(Prbs::for_length(300, 1, 0.0, 1.0).unwrap().order, 9);
        assert_eq!(Prbs::for_length(300, 3, 0.0, 1.0).unwrap().order, 7);
    }
}
