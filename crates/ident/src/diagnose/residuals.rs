//! Residual statistics of a fit: the numbers that say *what* a fitted model gets wrong,
//! computed from the residuals eᵢ = yᵢ − ŷᵢ alone (no GUI, no model fitting here).
//!
//! This module owns:
//! - the split of the record into regions (before the response, transient, tail) from the
//!   model's dead time and settling time ([`boundaries`]), and per region the bias, its
//!   trend and their significance ([`Region`]);
//! - the whiteness tests of the residuals: their autocorrelation with its 99 % band and the
//!   Wald–Wolfowitz runs test on their signs ([`ResidualAnalysis`], [`RunsTest`]);
//! - the cross-correlation of the residuals with the input, when the input is known;
//! - the period of an oscillation left in the residuals, if there is one.
//!
//! A good model leaves residuals that look like the measurement noise: no bias anywhere,
//! no trend, no memory (white). Each statistic here points at one way of failing that:
//! a bias before the response says Y0 is off, a bias or trend in the transient that the
//! dead time or the time constants are off, a bias in the tail that the gain is off, a
//! slow autocorrelation that a pole or the dead time is missing, an oscillating
//! autocorrelation that the model lacks an underdamped pair.
//!
//! Interpreting the diagnosis (which model change to suggest) is not done here.
//! Assumes finite numbers (no NaN); never panics, whatever the lengths. Scale-free: the
//! residuals and times are divided by powers of two near their size before the sums (exact,
//! so records of unit size are analysed as before) and the results scaled back, so residuals
//! of 1e300 or times of 1e200 s do not overflow a sum of squares.

use crate::fit::FitData;
use crate::model::{Model, Param};
use crate::record::timebase::sampling_period;
use crate::stats::mean;
use crate::stats::normal_quantile;

/// Which part of the record a region is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RegionKind {
    /// From the first sample to the start of the model's response (t0 + Td): before the step
    /// has any effect, the residuals test the operating point Y0 (and a drift).
    BeforeResponse,
    /// From the start of the response to the model's 2 % settling time: the residuals test
    /// the dynamics (dead time, time constants, damping, zero).
    Transient,
    /// From the settling time to the last sample: the residuals test the final value, that
    /// is the gain Kp (and a drift).
    Tail,
}

/// Statistics of the residuals in one region of the record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Region {
    pub kind: RegionKind,
    /// Start of the region (s, absolute time as in the record): the first sample's time or
    /// a boundary.
    pub start: f64,
    /// End of the region (s): a boundary or the last sample's time. Samples at exactly
    /// `end` belong to the next region, except the last sample, which belongs to the last
    /// region (see [`Boundaries`]).
    pub end: f64,
    /// Number of samples in the region.
    pub n: usize,
    /// Bias: the mean ē of the residuals in the region (output units). Nonzero where the
    /// model is systematically above (ē < 0) or below (ē > 0) the data.
    pub mean: f64,
    /// The t statistic of the bias, ē / (s/√n), with s the sample standard deviation of the
    /// residuals in the region (dimensionless). |mean_z| above about 2.6 says the bias is
    /// beyond what the noise explains (99 %, if the residuals were white: slowly varying
    /// residuals make it larger than that, so read it as a strength, not a probability).
    /// 0 when n < 2 or when the residuals are all zero; ±∞ when they are all equal and not
    /// zero (a quantised sensor can do that: the bias is certain but may be tiny, see `mean`).
    pub mean_z: f64,
    /// Least-squares trend of the residuals in the region, the slope b of e ≈ a + b·t
    /// (output units per second). Nonzero where the model drifts away from the data.
    pub slope: f64,
    /// The slope divided by its standard error √(SSR/(n − 2) / Σ(tᵢ − t̄)²), a t statistic
    /// (dimensionless; same reading as `mean_z`). 0 when n < 3 or the times are all equal;
    /// ±∞ when the residuals lie exactly on a line.
    pub slope_z: f64,
    /// Root mean square of the residuals in the region, √(Σeᵢ²/n) (output units): the size
    /// of the misfit there, bias included.
    pub rms: f64,
    /// Fraction (0 to 1) of the region's residuals that have the sign of the mean; 0 when the
    /// mean is exactly 0. Near 1 means the model is on one side of the data almost
    /// everywhere in the region (a real bias); near 0.5 means the mean is made by a few
    /// large residuals.
    pub same_sign_fraction: f64,
}

/// Wald–Wolfowitz runs test on the signs of the residuals (zeros dropped).
///
/// A run is a maximal stretch of residuals of one sign. With n₊ positive and n₋ negative
/// residuals (n = n₊ + n₋) in random order, the number of runs R has mean
/// E[R] = 1 + 2n₊n₋/n and variance Var[R] = 2n₊n₋(2n₊n₋ − n) / (n²(n − 1)), and
/// z = (R − E[R]) / √Var[R] is about standard normal. Too few runs (z strongly negative)
/// means the residuals stay on one side of zero for long stretches: the model misses a
/// slow part of the response. Too many (z strongly positive) means they alternate more than
/// noise does (e.g. an over-filtered or aliased signal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunsTest {
    /// Number of runs R (0 when every residual is zero).
    pub runs: usize,
    /// Expected number of runs E[R] for random signs (0 when every residual is zero).
    pub expected: f64,
    /// Standardised deviation (R − E[R])/√Var[R]; 0 when the variance is zero (fewer than
    /// two nonzero residuals, or all of one sign).
    pub z: f64,
}

/// Everything this module says about a fit's residuals.
#[derive(Debug, Clone, PartialEq)]
pub struct ResidualAnalysis {
    /// The regions in time order; a region with no samples is left out.
    pub regions: Vec<Region>,
    /// Autocorrelation rₖ = Σᵢ eᵢ·eᵢ₊ₖ / Σᵢ eᵢ² for k = 0..=max_lag (dimensionless, r₀ = 1),
    /// the biased estimator (divided by the full sum, so it tapers at long lags), on the
    /// residuals as they are (a bias is not removed: it shows as a slowly decaying positive
    /// rₖ, which is a model error too). max_lag = min(N/4, 50); lag k is k sampling periods.
    /// White residuals have rₖ ≈ 0 for k ≥ 1; a slow decay means the model misses a slow
    /// part of the response; an alternating rₖ means it misses an oscillation.
    /// [1, 0, 0, …] when every residual is zero.
    pub autocorrelation: Vec<f64>,
    /// Half-width of the 99 % band of rₖ (k ≥ 1) for white residuals, z₀.₉₉₅/√N
    /// = 2.576/√N (0 when N = 0). The same band applies to `input_correlation`.
    pub band99: f64,
    /// Lags k ≥ 1 where |rₖ| > band99. For white residuals about 1 lag in 100 is outside by
    /// chance.
    pub outside_band: Vec<usize>,
    /// Runs test on the signs of the residuals.
    pub runs: RunsTest,
    /// Cross-correlation of the residuals with the input's deviation ũ = u − ū from its
    /// mean, ρₖ = Σᵢ ũᵢ·eᵢ₊ₖ / √(Σũ²·Σe²) for k = 0..=max_lag (dimensionless, −1 to 1): how
    /// much the residual k samples later follows the input. `None` when no input is given;
    /// all zeros when the input is constant or the residuals all zero. Values beyond ±band99
    /// say the model misses part of the input's effect (gain, dynamics). For a single step
    /// the input is one long plateau, so ρₖ is mostly "do the residuals differ before and
    /// after the step": the band assumes a white input and is only a rough guide here.
    pub input_correlation: Option<Vec<f64>>,
    /// Period (s) of an oscillation left in the residuals, if their autocorrelation shows
    /// one. A model without an underdamped pair cannot follow an oscillating response, and
    /// this is the period it misses (2π/ωd of the missing pair).
    ///
    /// The rule, on the autocorrelation ρₖ of the residuals *minus their mean* (a bias would
    /// lift ρₖ and hide the oscillation; the bias is reported by the regions), for lags up
    /// to N/2 (for very long records at most about 2·10⁷/N lags, never fewer than max_lag),
    /// with Ts the median sampling period:
    ///
    /// 1. An oscillation makes ρₖ alternate in sign: positive at lag 0, a negative lobe around
    ///    half a period, a positive lobe around one period. A lobe counts only when ρₖ stays
    ///    beyond the 99 % band ±band99 for at least two consecutive lags (one lag beyond the
    ///    band happens by chance once in a hundred lags for white residuals, two in a row
    ///    once in ten thousand).
    /// 2. Two sign changes beyond the band are required: a negative lobe, then a positive lobe.
    ///    A single slow bump in the residuals (a missing pole, a wrong dead time) gives a
    ///    positive ρₖ that may turn negative once but does not come back: no period.
    /// 3. The period is twice the distance between the zero crossings that open the two lobes:
    ///    ρₖ crossing downwards (z₁, interpolated linearly between lags) just before the
    ///    negative lobe and upwards (z₂) just before the positive lobe; period = 2·(z₂ − z₁)·Ts.
    ///    For a decaying oscillation e^{−t/τ}·sin(ωt) the autocorrelation is close to
    ///    e^{−k/τ}·cos(ωk − φ): the decay and the phase φ move its peaks (so "the lag of the
    ///    next peak" is biased) but not the spacing of its zeros, which is exactly π/ω.
    pub dominant_period: Option<f64>,
    /// The residuals look white: no more lags outside the 99 % band than white noise gives
    /// in 99 % of records ([`allowed_outside`]: 1 of 8 lags, 3 of 50) and |runs.z| < 2.576.
    /// True when there is nothing to test (N = 0, all zeros).
    pub white: bool,
    /// Sample standard deviation of the residuals, √(Σ(eᵢ − ē)²/(N − 1)) (output units; 0
    /// when N < 2): the noise level a good model leaves.
    pub std: f64,
}

/// Absolute times (s) splitting the record into regions:
/// BeforeResponse = [first sample, response_start), Transient = [response_start, settled),
/// Tail = [settled, last sample]. When settled is at or after the last sample there is no
/// tail and the transient includes the last sample (a model that settles only at the end,
/// or never, e.g. with an integrator); [`analyse`] clamps both into the record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Boundaries {
    pub response_start: f64,
    pub settled: f64,
}

/// The 99 % two-sided normal quantile z₀.₉₉₅ ≈ 2.576.
fn z99() -> f64 {
    normal_quantile(0.995)
}

/// `x` clamped into [lo, hi] without panicking (NaN `x` gives `lo`; lo ≤ hi assumed).
fn clamp(x: f64, lo: f64, hi: f64) -> f64 {
    x.max(lo).min(hi)
}

/// The region boundaries of `model` on `data`.
///
/// - response_start = t0 + Td (Td = 0 without a dead time): the first instant the model's
///   output can differ from Y0.
/// - settled = the last input change + the model's 2 % settling time (t0 + it for one step),
///   from the exact step response of
///   G(s) (dead time included, as `stepinfo` counts it). A model that does not settle
///   (integrator) or is invalid has settled = the last sample time (no tail).
///
/// Both are clamped into the record, with response_start ≤ settled.
pub fn boundaries(model: &Model, data: &FitData) -> Boundaries {
    let t0 = data.input.t0();
    let (first, last) = data
        .times
        .iter()
        .fold(None, |acc: Option<(f64, f64)>, &t| match acc {
            None => Some((t, t)),
            Some((lo, hi)) => Some((lo.min(t), hi.max(t))),
        })
        .unwrap_or((t0, t0));
    let td = if model.structure.delay {
        model.get(Param::Td).max(0.0)
    } else {
        0.0
    };
    let settling = model.settling();
    let response_start = clamp(t0 + td, first, last);
    // With several changes the response settles after the last one's transient.
    let last_change = data.input.changes.last().map_or(t0, |c| c.t.max(t0));
    let settled = match settling {
        Some(ts) => clamp(last_change + ts, response_start, last),
        None => last,
    };
    Boundaries {
        response_start,
        settled,
    }
}

/// Analyses the residuals `residuals` sampled at `times` (increasing, seconds), with the
/// input `input` at the same instants if known, and the regions split at `boundaries`.
///
/// Only the first min(times, residuals) samples are used; an input shorter than that is
/// correlated over its length. Boundaries outside the record are clamped into it.
pub fn analyse(
    times: &[f64],
    residuals: &[f64],
    input: Option<&[f64]>,
    boundaries: Boundaries,
) -> ResidualAnalysis {
    let n = times.len().min(residuals.len());
    let (times, residuals) = (&times[..n], &residuals[..n]);
    let largest = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let (e_unit, t_unit) = (
        power_of_two_near(largest(residuals)),
        power_of_two_near(largest(times)),
    );
    if e_unit == 1.0 && t_unit == 1.0 {
        return analyse_as_given(times, residuals, input, boundaries);
    }
    let t: Vec<f64> = times.iter().map(|t| t / t_unit).collect();
    let e: Vec<f64> = residuals.iter().map(|e| e / e_unit).collect();
    let b = Boundaries {
        response_start: boundaries.response_start / t_unit,
        settled: boundaries.settled / t_unit,
    };
    let mut a = analyse_as_given(&t, &e, input, b);
    for r in &mut a.regions {
        r.start *= t_unit;
        r.end *= t_unit;
        r.mean *= e_unit;
        r.rms *= e_unit;
        r.slope *= e_unit / t_unit;
    }
    a.std *= e_unit;
    a.dominant_period = a.dominant_period.map(|p| p * t_unit);
    a
}

/// The power of two nearest `x` in logarithm (1 for zero or a non-finite `x`).
fn power_of_two_near(x: f64) -> f64 {
    if x.is_finite() && x > 0.0 {
        2f64.powi((x.log2().round() as i32).clamp(-1000, 1000))
    } else {
        1.0
    }
}

/// [`analyse`] on the numbers as given, `times` and residuals `e` of one length.
fn analyse_as_given(
    times: &[f64],
    e: &[f64],
    input: Option<&[f64]>,
    boundaries: Boundaries,
) -> ResidualAnalysis {
    let regions = regions(times, e, boundaries);
    let Whiteness {
        autocorrelation,
        band99,
        outside_band,
        runs,
        white,
    } = whiteness_as_given(e);
    let max_lag = autocorrelation.len().saturating_sub(1);
    let input_correlation = input.map(|u| input_correlation(e, u, max_lag));
    let dominant_period =
        dominant_period(e, band99, sampling_period(times).unwrap_or(1.0), max_lag);
    let std = sample_std(e);

    ResidualAnalysis {
        regions,
        autocorrelation,
        band99,
        outside_band,
        runs,
        input_correlation,
        dominant_period,
        white,
        std,
    }
}

/// The whiteness test of [`ResidualAnalysis`] alone (its fields of the same names): the
/// autocorrelation to min(N/4, 50) lags against its 99 % band, and the runs test. Without
/// the regions and the period search (up to N × N/2 multiply-adds), for a verdict that
/// only asks whether the residuals are white.
#[derive(Debug, Clone, PartialEq)]
pub struct Whiteness {
    pub autocorrelation: Vec<f64>,
    pub band99: f64,
    pub outside_band: Vec<usize>,
    pub runs: RunsTest,
    pub white: bool,
}

/// [`Whiteness`] of the residuals `e` (of any size: scaled by a power of two first, as
/// [`analyse`] does, so that no square overflows).
pub fn whiteness(e: &[f64]) -> Whiteness {
    let unit = power_of_two_near(e.iter().fold(0.0f64, |m, x| m.max(x.abs())));
    if unit == 1.0 {
        return whiteness_as_given(e);
    }
    let scaled: Vec<f64> = e.iter().map(|e| e / unit).collect();
    whiteness_as_given(&scaled)
}

/// [`whiteness`] of residuals already of a size whose squares do not overflow.
fn whiteness_as_given(e: &[f64]) -> Whiteness {
    let n = e.len();
    let max_lag = if n >= 4 { (n / 4).min(50) } else { 0 };
    let autocorrelation = autocorrelation(e, max_lag);
    let band99 = if n > 0 {
        z99() / (n as f64).sqrt()
    } else {
        0.0
    };
    let outside_band: Vec<usize> = autocorrelation
        .iter()
        .enumerate()
        .skip(1)
        .filter(|(_, r)| r.abs() > band99)
        .map(|(k, _)| k)
        .collect();
    let runs = runs_test(e);
    let white = outside_band.len() <= allowed_outside(max_lag) && runs.z.abs() < z99();
    Whiteness {
        autocorrelation,
        band99,
        outside_band,
        runs,
        white,
    }
}

/// Sample standard deviation with N − 1 (0 when N < 2).
/// How many of `lags` autocorrelation lags white noise leaves outside the 99 % band in 99 %
/// of records: the smallest k with P(X > k) ≤ 1 % for X ~ Binomial(lags, 0.01) (the lags
/// taken as independent). Allowing only one would flag about 9 % of white records at 50 lags.
pub fn allowed_outside(lags: usize) -> usize {
    let (n, p) = (lags as i32, 0.01f64);
    let mut term = (1.0 - p).powi(n); // P(X = 0)
    let mut cumulative = term;
    let mut k = 0;
    while 1.0 - cumulative > 0.01 + 1e-12 && k < lags {
        term *= (n - k as i32) as f64 / (k + 1) as f64 * p / (1.0 - p);
        cumulative += term;
        k += 1;
    }
    k
}

fn sample_std(x: &[f64]) -> f64 {
    if x.len() < 2 {
        return 0.0;
    }
    let m = mean(x);
    (x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (x.len() - 1) as f64).sqrt()
}

/// `num / den` as a z statistic: 0 when both are 0, ±∞ when only the denominator is.
fn ratio(num: f64, den: f64) -> f64 {
    if den > 0.0 {
        num / den
    } else if num == 0.0 {
        0.0
    } else {
        num.signum() * f64::INFINITY
    }
}

/// The regions of the record, in time order, without the empty ones.
fn regions(times: &[f64], e: &[f64], b: Boundaries) -> Vec<Region> {
    let (Some(&first), Some(&last)) = (times.first(), times.last()) else {
        return Vec::new();
    };
    let (first, last) = times
        .iter()
        .fold((first.min(last), first.max(last)), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    let rs = clamp(b.response_start, first, last);
    let st = clamp(b.settled, rs, last);
    [
        (RegionKind::BeforeResponse, first, rs),
        (RegionKind::Transient, rs, st),
        (RegionKind::Tail, st, last),
    ]
    .into_iter()
    .filter_map(|(kind, start, end)| {
        let (t, r): (Vec<f64>, Vec<f64>) = times
            .iter()
            .zip(e)
            .filter(|(t, _)| region_of(**t, rs, st, last) == kind)
            .map(|(&t, &r)| (t, r))
            .unzip();
        (!r.is_empty()).then(|| region_stats(kind, start, end, &t, &r))
    })
    .collect()
}

/// The region of a sample at `t`, with the boundaries already clamped into the record
/// (rs ≤ st ≤ last). Half-open intervals, except that the last sample always belongs to a
/// region that reaches it: when the model settles only at the end of the record or later
/// (st = last) there is no tail, and the last sample ends the transient (or the part before
/// the response, when that starts at the last sample too).
fn region_of(t: f64, rs: f64, st: f64, last: f64) -> RegionKind {
    if t < rs {
        RegionKind::BeforeResponse
    } else if t < st {
        RegionKind::Transient
    } else if st < last {
        RegionKind::Tail
    } else if rs < last {
        RegionKind::Transient
    } else {
        RegionKind::BeforeResponse
    }
}

/// The statistics of one region's residuals `e` at times `t` (not empty).
fn region_stats(kind: RegionKind, start: f64, end: f64, t: &[f64], e: &[f64]) -> Region {
    let n = e.len();
    let nf = n as f64;
    let m = mean(e);
    let mean_z = if n >= 2 {
        ratio(m, sample_std(e) / nf.sqrt())
    } else {
        0.0
    };

    let tm = mean(t);
    let sxx: f64 = t.iter().map(|&ti| (ti - tm) * (ti - tm)).sum();
    let sxy: f64 = t.iter().zip(e).map(|(&ti, &ei)| (ti - tm) * (ei - m)).sum();
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let slope_z = if n >= 3 && sxx > 0.0 {
        let ssr: f64 = t
            .iter()
            .zip(e)
            .map(|(&ti, &ei)| {
                let fit = m + slope * (ti - tm);
                (ei - fit) * (ei - fit)
            })
            .sum();
        ratio(slope, (ssr / (nf - 2.0) / sxx).sqrt())
    } else {
        0.0
    };

    let rms = (e.iter().map(|v| v * v).sum::<f64>() / nf).sqrt();
    let same_sign_fraction = if m == 0.0 {
        0.0
    } else {
        e.iter().filter(|&&v| v * m > 0.0).count() as f64 / nf
    };

    Region {
        kind,
        start,
        end,
        n,
        mean: m,
        mean_z,
        slope,
        slope_z,
        rms,
        same_sign_fraction,
    }
}

/// Σᵢ a[i]·b[i + k] over the overlap.
fn lagged_product(a: &[f64], b: &[f64], k: usize) -> f64 {
    a.iter().zip(b.iter().skip(k)).map(|(x, y)| x * y).sum()
}

/// Biased autocorrelation r₀..=r_max_lag of `e` (r₀ = 1; [1, 0, …] when Σe² = 0).
fn autocorrelation(e: &[f64], max_lag: usize) -> Vec<f64> {
    let c0 = lagged_product(e, e, 0);
    (0..=max_lag)
        .map(|k| {
            if k == 0 {
                1.0
            } else if c0 > 0.0 {
                lagged_product(e, e, k) / c0
            } else {
                0.0
            }
        })
        .collect()
}

/// Normalised cross-correlation of the input's deviation from its mean with the residuals
/// k samples later, k = 0..=max_lag.
fn input_correlation(e: &[f64], u: &[f64], max_lag: usize) -> Vec<f64> {
    let len = e.len().min(u.len());
    let (e, u) = (&e[..len], &u[..len]);
    let um = mean(u);
    let du: Vec<f64> = u.iter().map(|v| v - um).collect();
    let norm = (lagged_product(&du, &du, 0) * lagged_product(e, e, 0)).sqrt();
    (0..=max_lag)
        .map(|k| {
            if norm > 0.0 {
                lagged_product(&du, e, k) / norm
            } else {
                0.0
            }
        })
        .collect()
}

/// The runs test on the signs of `e`, zeros dropped.
fn runs_test(e: &[f64]) -> RunsTest {
    let signs: Vec<bool> = e.iter().filter(|v| **v != 0.0).map(|v| *v > 0.0).collect();
    if signs.is_empty() {
        return RunsTest {
            runs: 0,
            expected: 0.0,
            z: 0.0,
        };
    }
    let runs = 1 + signs.windows(2).filter(|w| w[0] != w[1]).count();
    let n_pos = signs.iter().filter(|s| **s).count() as f64;
    let n_neg = signs.len() as f64 - n_pos;
    let n = signs.len() as f64;
    let pq = 2.0 * n_pos * n_neg;
    let expected = 1.0 + pq / n;
    let variance = if n > 1.0 {
        pq * (pq - n) / (n * n * (n - 1.0))
    } else {
        0.0
    };
    let z = if variance > 0.0 {
        (runs as f64 - expected) / variance.sqrt()
    } else {
        0.0
    };
    RunsTest { runs, expected, z }
}

/// The longest lag the period search looks at is bounded so that the work, about N × lags
/// multiply-adds, stays below this (the search stops early once it finds a period).
const PERIOD_SEARCH_WORK: usize = 20_000_000;

/// The period (s) of an oscillation in the residuals `e`, sampled every `ts` seconds, or
/// `None`, by the rule documented at [`ResidualAnalysis::dominant_period`].
fn dominant_period(e: &[f64], band: f64, ts: f64, max_lag: usize) -> Option<f64> {
    let n = e.len();
    if n < 8 || band <= 0.0 || ts <= 0.0 || !ts.is_finite() {
        return None;
    }
    let m = mean(e);
    let d: Vec<f64> = e.iter().map(|v| v - m).collect();
    let c0 = lagged_product(&d, &d, 0);
    if c0 <= 0.0 || !c0.is_finite() {
        return None;
    }
    let longest = (n / 2).min((PERIOD_SEARCH_WORK / n).max(max_lag));

    let mut prev = 1.0;
    let mut down: Option<f64> = None; // latest downward zero crossing (lags)
    let mut up: Option<f64> = None; // latest upward zero crossing (lags)
    let mut lobe_start: Option<f64> = None; // z₁ once the negative lobe is found
    let mut beyond = 0; // consecutive lags beyond the band in the sought direction
    for k in 1..=longest {
        let r = lagged_product(&d, &d, k) / c0;
        let k_prev = (k - 1) as f64;
        if prev >= 0.0 && r < 0.0 {
            down = Some(k_prev + prev / (prev - r));
        } else if prev < 0.0 && r >= 0.0 {
            up = Some(k_prev - prev / (r - prev));
        }
        match lobe_start {
            None => {
                beyond = if r < -band { beyond + 1 } else { 0 };
                if beyond >= 2 {
                    // r₀ = 1 > 0, so a downward crossing precedes any negative lag.
                    lobe_start = Some(down?);
                    beyond = 0;
                }
            }
            Some(z1) => {
                beyond = if r > band { beyond + 1 } else { 0 };
                if beyond >= 2 {
                    let z2 = up.filter(|z2| *z2 > z1)?;
                    return Some(2.0 * (z2 - z1) * ts);
                }
            }
        }
        prev = r;
    }
    None
}

#[cfg(test)]
mod tests;
