//! Small statistics needed across identification: the one mean (exact and without overflow
//! at any scale), and for the fit report and the residual diagnosis the quantiles of the
//! normal and Student-t distributions. Written here because they are a few lines each and a
//! statistics crate would add a second linear-algebra stack to the build.

/// The fewest robust standard deviations beyond which a sample is an outlier (the
/// outliers cause's rule, and the rest level's before it averages).
pub const OUTLIER_THRESHOLD: f64 = 5.0;

/// 2^⌊log₂ m⌋ for the largest finite magnitude m of `values`, within the normal range (1 when
/// there is none or it is 0): dividing by it is exact.
pub(crate) fn binary_unit(values: impl IntoIterator<Item = f64>) -> f64 {
    let m = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    if m == 0.0 {
        return 1.0;
    }
    let exponent = (m.log2().floor() as i64).clamp(-1022, 1023);
    f64::from_bits(((exponent + 1023) as u64) << 52)
}

/// The mean of `v` (NaN when empty), without overflow at any scale.
pub fn mean(v: &[f64]) -> f64 {
    let unit = binary_unit(v.iter().copied());
    unit * (v.iter().map(|x| x / unit).sum::<f64>() / v.len() as f64)
}

/// The standard normal quantile Φ⁻¹(p), 0 < p < 1 (Acklam's rational approximation refined
/// (relative error below 1.15e-9).
#[allow(clippy::excessive_precision)] // the published coefficients, digit for digit
pub fn normal_quantile(p: f64) -> f64 {
    if p.is_nan() || p <= 0.0 || p >= 1.0 {
        return f64::NAN;
    }
    const A: [f64; 6] = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.383577518672690e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

/// The Student-t quantile t_p(ν): exact for ν = 1, 2, 4; otherwise the Cornish–Fisher
/// expansion in 1/ν to fourth order (error below 1e-4 at ν = 3, shrinking fast with ν).
pub fn student_t_quantile(p: f64, dof: f64) -> f64 {
    if p.is_nan() || p <= 0.0 || p >= 1.0 || dof.is_nan() || dof <= 0.0 {
        return f64::NAN;
    }
    if dof == 1.0 {
        return (std::f64::consts::PI * (p - 0.5)).tan();
    }
    if dof == 2.0 {
        return (2.0 * p - 1.0) / (2.0 * p * (1.0 - p)).sqrt();
    }
    if dof == 4.0 {
        let a = 4.0 * p * (1.0 - p);
        let q = (a.sqrt().acos() / 3.0).cos() / a.sqrt();
        return (p - 0.5).signum() * 2.0 * (q - 1.0).max(0.0).sqrt();
    }
    let z = normal_quantile(p);
    let (z2, v) = (z * z, dof);
    let g1 = (z2 + 1.0) * z / 4.0;
    let g2 = ((5.0 * z2 + 16.0) * z2 + 3.0) * z / 96.0;
    let g3 = (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) * z / 384.0;
    let g4 = ((((79.0 * z2 + 776.0) * z2 + 1482.0) * z2 - 1920.0) * z2 - 945.0) * z / 92160.0;
    z + g1 / v + g2 / (v * v) + g3 / (v * v * v) + g4 / (v * v * v * v)
}

/// The median of `v` (NaN when empty); sorts a copy.
pub fn median(v: &[f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let mid = v.len() / 2;
    // A short slice (a running median's window) is copied to the stack: no allocation.
    let mut small = [0.0; 16];
    let mut large = Vec::new();
    let w: &mut [f64] = if v.len() <= small.len() {
        small[..v.len()].copy_from_slice(v);
        &mut small[..v.len()]
    } else {
        large.extend_from_slice(v);
        &mut large
    };
    *w.select_nth_unstable_by(mid, f64::total_cmp).1
}

/// A robust standard deviation: 1.4826·MAD (the median absolute deviation from the median),
/// which equals σ for Gaussian data and ignores up to half the samples being wild.
pub fn robust_scale(v: &[f64]) -> f64 {
    let m = median(v);
    let dev: Vec<f64> = v.iter().map(|x| (x - m).abs()).collect();
    1.4826 * median(&dev)
}

/// The quantum of a quantised signal as the median of the nonzero first differences' sizes:
/// a quantised record's level step; on continuous noise about σ.
pub fn quantum(y: &[f64]) -> f64 {
    let d: Vec<f64> = y
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|d| *d > 0.0)
        .collect();
    if d.is_empty() { 0.0 } else { median(&d) }
}

/// The values of `v` that are not wild: within `sigmas` robust standard deviations
/// ([`robust_scale`]) of the median, and within two quanta ([`quantum`]) at least, so that a
/// quantised signal's levels are never wild; every value when fewer than five.
pub fn tame(v: &[f64], sigmas: f64) -> Vec<f64> {
    if v.len() < 5 {
        return v.to_vec();
    }
    let m = median(v);
    let limit = (sigmas * robust_scale(v)).max(2.0 * quantum(v));
    v.iter()
        .copied()
        .filter(|x| limit.is_nan() || (x - m).abs() <= limit)
        .collect()
}

/// The lag-one autocorrelation of `v` about its mean (the AR(1) coefficient's estimate);
/// 0 for fewer than three samples or no spread.
pub fn lag_one(v: &[f64]) -> f64 {
    if v.len() < 3 {
        return 0.0;
    }
    // In units of the largest value, so that residuals at 1e300 do not overflow their squares.
    let unit = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if !(unit.is_finite() && unit > 0.0) {
        return 0.0;
    }
    let mean = v.iter().map(|x| x / unit).sum::<f64>() / v.len() as f64;
    let d = |x: f64| x / unit - mean;
    let c0: f64 = v.iter().map(|&x| d(x).powi(2)).sum();
    let c1: f64 = v.windows(2).map(|w| d(w[0]) * d(w[1])).sum();
    if c0 > 0.0 { c1 / c0 } else { 0.0 }
}

/// About how many standard deviations the largest of `n` Gaussian samples reaches:
/// √(2 ln n) (at least that of two samples). What a sample's excursion must pass to be more
/// than noise.
pub fn largest_of_gaussians(n: usize) -> f64 {
    (2.0 * (n.max(2) as f64).ln()).sqrt()
}

/// The running median of three (the ends kept): a single wild sample (a spike, a dropout)
/// is removed, a monotone curve kept as it is.
pub fn running_median3(y: &[f64]) -> Vec<f64> {
    let mut out = y.to_vec();
    for k in 1..y.len().saturating_sub(1) {
        let (a, b, c) = (y[k - 1], y[k], y[k + 1]);
        out[k] = a.max(b).min(a.min(b).max(c));
    }
    out
}

/// The factor by which intervals computed as if N residuals were independent widen for
/// residuals with lag-one autocorrelation `rho` (an AR(1) coefficient, clamped to
/// [0, 0.99]): √((1 + ρ)/(1 − ρ)), since the variance of a mean of AR(1) samples is that
/// factor squared times the white one's.
pub fn ar1_widening(rho: f64) -> f64 {
    let rho = rho.clamp(0.0, 0.99);
    ((1.0 + rho) / (1.0 - rho)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_running_median_removes_a_spike_and_keeps_a_monotone_curve() {
        assert_eq!(
            running_median3(&[0.0, 1.0, 9.0, 3.0, 4.0]),
            [0.0, 1.0, 3.0, 4.0, 4.0]
        );
        let rising = [0.0, 0.5, 0.7, 2.0, 2.1];
        assert_eq!(running_median3(&rising), rising);
    }

    #[test]
    fn normal_quantiles_match_tables() {
        assert!((normal_quantile(0.975) - 1.959963984540054).abs() < 1e-8);
        assert!((normal_quantile(0.995) - 2.5758293035489).abs() < 1e-8);
        assert!((normal_quantile(0.5)).abs() < 1e-12);
        assert!((normal_quantile(0.001) + 3.090232306167813).abs() < 1e-8);
    }

    #[test]
    fn student_t_quantiles_match_tables() {
        // Two-sided 95 %: t_{0.975}(ν).
        for (dof, t) in [
            (1.0, 12.706204736),
            (2.0, 4.302652730),
            (3.0, 3.182446305),
            (4.0, 2.776445105),
            (10.0, 2.228138852),
            (30.0, 2.042272456),
            (100.0, 1.983971519),
        ] {
            let got = student_t_quantile(0.975, dof);
            assert!((got - t).abs() < 2e-3 * t, "ν={dof}: {got} vs {t}");
        }
        assert!((student_t_quantile(0.975, 30.0) - 2.042272456).abs() < 1e-5);
    }

    #[test]
    fn robust_statistics_of_known_samples() {
        let v = [1.0, 2.0, 3.0, 4.0, 100.0];
        assert_eq!(median(&v), 3.0);
        // |v − 3| = 2, 1, 0, 1, 97: MAD 1.
        assert!((robust_scale(&v) - 1.4826).abs() < 1e-12);
        let alternating = [1.0, -1.0, 1.0, -1.0, 1.0, -1.0];
        assert!((lag_one(&alternating) + 5.0 / 6.0).abs() < 1e-12);
    }
}
