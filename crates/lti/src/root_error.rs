//! How far a computed root of a real polynomial can be trusted, judged on the polynomial
//! itself: its backward error (the smallest relative change of the coefficients that makes
//! it an exact root), the radius within which rounding alone can move it, and whether the
//! polynomial has a root exactly on the imaginary axis there.
//!
//! Every evaluation is scaled by powers of two around the root (exact), so a root of 1e150
//! of a polynomial with coefficients of 1e300 is judged as well as one of 1 (the products
//! would overflow unscaled).

use nalgebra::Complex;

/// A complex number of `f64`s (the crate's `poly::C64`).
type C64 = Complex<f64>;

/// A root whose backward error is above this is not a root of the polynomial it was
/// computed from (Newton-polished roots and merged multiple roots are near 1e-15).
pub const BACKWARD_LIMIT: f64 = 1e-9;

/// Rounding of a Horner evaluation, per degree: |computed − exact| ≤ n·ROUNDING·Σ|cᵢ||r|ⁱ.
const ROUNDING: f64 = f64::EPSILON;

/// A root's even and odd parts count as vanishing below this many unit roundings (times the
/// degree) of their own size.
const AXIS_TOLERANCE: f64 = 32.0;

/// The polynomial seen from a point r: coefficients qᵢ = cᵢ·2^{e(n−i) − m} of q(x), x = r/2^e
/// with |x| in [1, 2), so that p(r) = 2^m·q(x) and the largest term of q is about 1.
struct Scaled {
    /// q's coefficients, descending powers.
    q: Vec<f64>,
    /// r/2^e.
    x: C64,
    /// e.
    exponent: i32,
}

impl Scaled {
    /// `coeffs` (descending powers, not all zero) seen from r ≠ 0.
    fn at(coeffs: &[f64], r: C64) -> Self {
        let n = coeffs.len() - 1;
        let exponent = r.norm().log2().floor() as i32;
        let x = C64::new(mul_pow2(r.re, -exponent), mul_pow2(r.im, -exponent));
        let log_term = |i: usize, c: f64| c.abs().log2().floor() as i32 + exponent * (n - i) as i32;
        let m = coeffs
            .iter()
            .enumerate()
            .filter(|(_, c)| **c != 0.0)
            .map(|(i, &c)| log_term(i, c))
            .max()
            .unwrap_or(0);
        let q = coeffs
            .iter()
            .enumerate()
            .map(|(i, &c)| mul_pow2(c, exponent * (n - i) as i32 - m))
            .collect();
        Self { q, x, exponent }
    }

    fn degree(&self) -> usize {
        self.q.len() - 1
    }

    /// q(x) by Horner's rule.
    fn value(&self) -> C64 {
        self.q
            .iter()
            .fold(C64::new(0.0, 0.0), |acc, &c| acc * self.x + c)
    }

    /// Σ|qᵢ||x|^{n−i}: the size of the terms q(x) sums (the scale of its rounding).
    fn size(&self) -> f64 {
        let r = self.x.norm();
        self.q.iter().fold(0.0, |acc, &c| acc * r + c.abs())
    }

    /// The Taylor coefficients q^{(k)}(x)/k!, k = 0..=n, by repeated synthetic division.
    fn taylor(&self) -> Vec<C64> {
        let mut p: Vec<C64> = self.q.iter().map(|&c| C64::new(c, 0.0)).collect();
        let mut out = Vec::with_capacity(p.len());
        while !p.is_empty() {
            for i in 1..p.len() {
                p[i] = p[i] + p[i - 1] * self.x;
            }
            out.push(p.pop().unwrap_or_default());
        }
        out
    }
}

/// |p(r)| / Σ|cᵢ||r|ⁱ: the backward error of r as a root of p (`coeffs` in descending
/// powers), relative to each coefficient. 0 for an exact root.
pub fn backward_error(coeffs: &[f64], r: C64) -> f64 {
    if coeffs.iter().all(|&c| c == 0.0) {
        return 0.0;
    }
    if r.norm() == 0.0 {
        // p(0) = c_n and Σ|cᵢ||0|ⁱ = |c_n|: 0 is a root only when c_n is 0 (judged against the
        // largest coefficient instead, a root put at 0 for a tiny c_n passed: the loop around
        // a dead time of 1e35 s called three poles of order 1e-35 integrators).
        return if coeffs[coeffs.len() - 1] == 0.0 {
            0.0
        } else {
            1.0
        };
    }
    let s = Scaled::at(coeffs, r);
    let size = s.size();
    if size == 0.0 {
        0.0
    } else {
        s.value().norm() / size
    }
}

/// How far the exact root of p near the computed root r can lie from it, given the rounding
/// of p's evaluation and the residual at r: the smallest δ at which one Taylor term
/// |p^{(k)}(r)/k!|·δ^k reaches them (δ = rounding/|p'(r)| for a simple root, its k-th root
/// for a k-fold one). Infinite when every derivative vanishes.
pub fn rounding_radius(coeffs: &[f64], r: C64) -> f64 {
    if r.norm() == 0.0 {
        return 0.0;
    }
    let s = Scaled::at(coeffs, r);
    let taylor = s.taylor();
    let noise = s.degree() as f64 * ROUNDING * s.size() + taylor[0].norm();
    let radius = taylor
        .iter()
        .enumerate()
        .skip(1)
        .filter(|(_, t)| t.norm() > 0.0)
        .map(|(k, t)| (noise / t.norm()).powf(1.0 / k as f64))
        .fold(f64::INFINITY, f64::min);
    mul_pow2(radius, s.exponent)
}

/// True when p has a root exactly on the imaginary axis at jω to rounding: a real p takes
/// at jω the value E(ω) + j·O(ω), its even and odd parts, and both must vanish relative to
/// the size of their own terms (a root 1.5 + 7e10j of s³ + 7s² + 5e21s + 5e22 is 2e-11
/// from the axis relative to its modulus, but E there is 18 % of its terms).
pub fn on_imaginary_axis(coeffs: &[f64], omega: f64) -> bool {
    if omega == 0.0 {
        return coeffs.last() == Some(&0.0);
    }
    let s = Scaled::at(coeffs, C64::new(0.0, omega));
    let n = s.degree();
    let w = s.x.im.abs();
    // The term qᵢ·(jω)^{n−i} is real for n − i even, imaginary for n − i odd.
    let (mut even, mut odd) = (0.0f64, 0.0f64);
    for (i, &c) in s.q.iter().enumerate() {
        let power = (n - i) as i32;
        let size = c.abs() * w.powi(power);
        if power % 2 == 0 {
            even += size;
        } else {
            odd += size;
        }
    }
    let v = s.value();
    let limit = AXIS_TOLERANCE * n as f64 * f64::EPSILON;
    v.re.abs() <= limit * even && v.im.abs() <= limit * odd
}

/// True when every root of `roots` is a root of p to [`BACKWARD_LIMIT`] and its sign is
/// known: a real root farther from 0 than its [`rounding_radius`], a complex one farther
/// from the imaginary axis (or exactly on it, as [`super::poly::roots`] puts only roots
/// that are there).
pub fn resolved(coeffs: &[f64], roots: &[C64]) -> bool {
    roots.iter().all(|&r| {
        if backward_error(coeffs, r) > BACKWARD_LIMIT {
            return false;
        }
        if r.re == 0.0 {
            return true;
        }
        rounding_radius(coeffs, r) < r.re.abs()
    })
}

/// x·2^k without overflow or underflow in the intermediate power of two.
pub(super) fn mul_pow2(mut x: f64, mut k: i32) -> f64 {
    while k > 1000 && x.is_finite() && x != 0.0 {
        x *= 2f64.powi(1000);
        k -= 1000;
    }
    while k < -1000 && x.is_finite() && x != 0.0 {
        x *= 2f64.powi(-1000);
        k += 1000;
    }
    x * 2f64.powi(k.clamp(-1000, 1000))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_exact_root_has_no_backward_error() {
        assert_eq!(backward_error(&[1.0, 3.0, 2.0], C64::new(-1.0, 0.0)), 0.0);
        let e = backward_error(&[1.0, 3.0, 2.0], C64::new(-1.5, 0.0));
        assert!((e - 0.25 / 8.75).abs() < 1e-15, "{e}");
    }

    #[test]
    fn huge_roots_are_judged_without_overflow() {
        // (s² + 1e300)(s + 1): roots ±1e150j and −1.
        let p = [1.0, 1.0, 1e300, 1e300];
        assert!(backward_error(&p, C64::new(0.0, 1e150)) < 1e-15);
        assert!(backward_error(&p, C64::new(-1.0, 0.0)) < 1e-15);
        assert!(backward_error(&p, C64::new(2.67e134, 0.0)) > 0.5);
        assert!(on_imaginary_axis(&p, 1e150));
    }

    #[test]
    fn the_axis_is_told_from_a_root_near_it() {
        // s³ + s² + s + 1 = (s + 1)(s² + 1): ±j exactly.
        assert!(on_imaginary_axis(&[1.0, 1.0, 1.0, 1.0], 1.0));
        // s³ + 7s² + 5e21·s + 5e22: roots 1.5 ± 7.07e10j.
        assert!(!on_imaginary_axis(&[1.0, 7.0, 5e21, 5e22], 5e21f64.sqrt()));
    }

    #[test]
    fn a_double_root_has_the_square_root_radius() {
        // (s + 1)²: rounding moves the roots by about √(n·eps·4).
        let r = rounding_radius(&[1.0, 2.0, 1.0], C64::new(-1.0, 0.0));
        assert!(r > 1e-9 && r < 1e-6, "{r}");
        let simple = rounding_radius(&[1.0, 3.0, 2.0], C64::new(-1.0, 0.0));
        assert!(simple < 1e-14, "{simple}");
    }
}
