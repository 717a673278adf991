//! Golden-section search for the maximum of a function of one variable that is unimodal on
//! an interval: the one copy for a step response's peak between two sampled points, the
//! sensitivity's peak between two frequencies, an approximation's largest difference, and
//! the censored fit's noise. Written here rather than taken from a crate: it is a dozen
//! lines, needs no derivative, and every caller is in this crate or above it.

/// Iterations at most: 0.618⁹⁰ ≈ 1.6e-19 of the bracket, past double precision.
const MAX_ITERATIONS: usize = 90;

/// The maximum of `f` on [a, b] (f unimodal there): `(t, f(t))`, the better of the last
/// two interior points, once the bracket is narrower than `tolerance` × max(|a|, |b|) or
/// after [`MAX_ITERATIONS`].
pub fn golden_max(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tolerance: f64) -> (f64, f64) {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..MAX_ITERATIONS {
        if b - a <= tolerance * a.abs().max(b.abs()) {
            break;
        }
        if fc > fd {
            b = d;
            (d, fd) = (c, fc);
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            a = c;
            (c, fc) = (d, fd);
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    if fc > fd { (c, fc) } else { (d, fd) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_peak_of_a_smooth_bump_is_found_to_the_tolerance() {
        // t·e^{−t} peaks at t = 1, value 1/e.
        let (t, v) = golden_max(|t| t * (-t).exp(), 0.0, 5.0, 1e-12);
        assert!((t - 1.0).abs() < 1e-6, "{t}");
        assert!((v - (-1.0f64).exp()).abs() < 1e-13, "{v}");
        // A peak at an end of the bracket is approached from inside.
        let (t, _) = golden_max(|t| -t, 2.0, 3.0, 1e-12);
        assert!((t - 2.0).abs() < 1e-10, "{t}");
        // A coarse tolerance stops early: within a tenth of the bracket's scale.
        let (t, _) = golden_max(|t| -(t - 0.3) * (t - 0.3), 0.0, 1.0, 0.1);
        assert!((t - 0.3).abs() < 0.1, "{t}");
    }
}
