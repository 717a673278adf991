//! Real polynomials in descending powers (MATLAB's convention: `[1, 7, 15, 25]` is
//! s³ + 7s² + 15s + 25), their roots and the polynomial built from a set of roots.
//!
//! Roots come from the eigenvalues of the balanced companion matrix (nalgebra's real Schur
//! form), are polished by a few guarded Newton steps, and are returned closed under
//! conjugation: every complex root is followed by its exact conjugate.
//!
//! Roots are only known to rounding, and for two questions that matters: whether a root is
//! real, and whether it lies on the imaginary axis (s³ + s² + s + 1 = (s + 1)(s² + 1) gives
//! ±j with a real part of about 2e-17, whose sign would decide between "oscillates forever"
//! and "unstable"). So a root within [`REAL_AXIS_TOLERANCE`] of its modulus of either axis
//! is put exactly on it: on the real axis always, on the imaginary axis only when the
//! polynomial has a root there to rounding ([`super::root_error::on_imaginary_axis`]: the
//! roots 1.5 ± 7.07e10j of s³ + 7s² + 5e21·s + 5e22 are 2e-11 from the axis relative to
//! their modulus, and unstable).

use std::cmp::Ordering;

use nalgebra::{Complex, DMatrix};

use super::root_error::mul_pow2;
use super::{LtiError, Polynomial, Quantity};

/// A complex number of `f64`s, as used for poles and zeros.
pub type C64 = Complex<f64>;

/// Roots whose imaginary part is below this fraction of their modulus are taken as real;
/// complex roots of [`roots`] whose real part is below it, as purely imaginary.
const REAL_AXIS_TOLERANCE: f64 = 1e-10;

/// Checks that every coefficient is finite; `what` names the polynomial in the message.
pub fn check_finite(coeffs: &[f64], what: Polynomial) -> Result<(), LtiError> {
    match coeffs.iter().position(|c| !c.is_finite()) {
        Some(i) => Err(LtiError::NonFiniteCoefficient { what, index: i + 1 }),
        None => Ok(()),
    }
}

/// Refuses subnormal coefficients (0 < |c| < 2.2e-308): they carry only a few significant
/// digits, and the roots and responses computed from them would not be right.
pub fn check_normal(coeffs: &[f64], what: Polynomial) -> Result<(), LtiError> {
    match coeffs.iter().position(|c| c.is_subnormal()) {
        Some(i) => Err(LtiError::Subnormal {
            what: Quantity::Coefficient {
                of: what,
                index: i + 1,
            },
            value: coeffs[i],
        }),
        None => Ok(()),
    }
}

/// Drops leading zero coefficients (as MATLAB's `tf` does); an all-zero polynomial is an error.
pub fn strip_leading_zeros(coeffs: &[f64], what: Polynomial) -> Result<Vec<f64>, LtiError> {
    check_finite(coeffs, what)?;
    check_normal(coeffs, what)?;
    match coeffs.iter().position(|&c| c != 0.0) {
        Some(first) => Ok(coeffs[first..].to_vec()),
        None => Err(LtiError::ZeroPolynomial { what }),
    }
}

/// Evaluates a real polynomial (descending powers) at a complex point by Horner's rule.
pub fn eval_complex(coeffs: &[f64], s: C64) -> C64 {
    coeffs
        .iter()
        .fold(C64::new(0.0, 0.0), |acc, &c| acc * s + C64::new(c, 0.0))
}

/// Coefficients (descending powers) of the monic polynomial Π (s − rᵢ).
///
/// The roots must be closed under conjugation; the imaginary parts of the product then
/// cancel and only the real parts are returned.
pub fn poly_from_roots(roots: &[C64]) -> Vec<f64> {
    let mut acc = vec![C64::new(1.0, 0.0)];
    for &r in roots {
        let mut next = vec![C64::new(0.0, 0.0); acc.len() + 1];
        for (i, &a) in acc.iter().enumerate() {
            next[i] += a;
            next[i + 1] -= a * r;
        }
        acc = next;
    }
    acc.iter().map(|c| c.re).collect()
}

/// Roots of a real polynomial given in descending powers, leading coefficient non-zero.
///
/// Conjugate pairs come out exactly conjugate, the member with positive imaginary part
/// first; real roots have an imaginary part of exactly zero.
pub fn roots(coeffs: &[f64]) -> Result<Vec<C64>, LtiError> {
    let coeffs = strip_leading_zeros(coeffs, Polynomial::Alone)?;
    let n = coeffs.len() - 1;
    // Roots at the origin are exact: count trailing zero coefficients.
    let at_origin = coeffs.iter().rev().take_while(|&&c| c == 0.0).count();
    let reduced = &coeffs[..coeffs.len() - at_origin];
    let mut found = vec![C64::new(0.0, 0.0); at_origin];
    let degree = reduced.len() - 1;
    let raw = match degree {
        0 => Vec::new(),
        1 => vec![C64::new(-reduced[1] / reduced[0], 0.0)],
        2 => quadratic_roots(reduced[0], reduced[1], reduced[2]),
        _ => companion_roots(reduced)?,
    };
    let clustered: Vec<C64> = raw.clone();
    for (root, multiplicity) in multiple_roots(reduced, raw) {
        if multiplicity == 1 && isolated(root, &clustered) {
            found.push(polish(reduced, root));
        } else if multiplicity == 1 {
            found.push(root);
        } else {
            found.extend(std::iter::repeat_n(root, multiplicity));
        }
    }
    debug_assert_eq!(found.len(), n);
    let mut closed = conjugate_closed(found);
    for r in closed.iter_mut() {
        if r.im != 0.0
            && r.re.abs() <= REAL_AXIS_TOLERANCE * r.norm()
            && super::root_error::on_imaginary_axis(reduced, r.im)
        {
            r.re = 0.0;
        }
    }
    sort_roots(&mut closed);
    Ok(closed)
}

/// Roots of a·s² + b·s + c without cancellation (the citardauq form for the smaller root).
/// The coefficients are first divided by the power of two nearest the largest of them, so
/// b² − 4ac cannot overflow (s² + 1e200·s + 1 has roots −1e200 and −1e−200); what underflows
/// then is negligible next to the largest term.
fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<C64> {
    let largest = a.abs().max(b.abs()).max(c.abs());
    let k = -(largest.log2().floor() as i32);
    let (a, b, c) = (mul_pow2(a, k), mul_pow2(b, k), mul_pow2(c, k));
    let disc = b * b - 4.0 * a * c;
    if disc >= 0.0 {
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        if q == 0.0 {
            return vec![C64::new(0.0, 0.0); 2];
        }
        vec![C64::new(q / a, 0.0), C64::new(c / q, 0.0)]
    } else {
        let re = -b / (2.0 * a);
        let im = (-disc).sqrt() / (2.0 * a.abs());
        vec![C64::new(re, im), C64::new(re, -im)]
    }
}

/// Eigenvalues of the balanced companion matrix of a polynomial of degree ≥ 3.
///
/// The matrix is built for the polynomial in x = s/2^e (see [`scaled_monic`]), whose
/// coefficients are all of order 1, and the eigenvalues are scaled back by 2^e. Without
/// this, coefficient ratios beyond ~1e154 overflow the squared norms inside nalgebra's
/// Parlett–Reinsch balancing (∞ ≥ 2·∞ forever), which then never returns.
fn companion_roots(coeffs: &[f64]) -> Result<Vec<C64>, LtiError> {
    let n = coeffs.len() - 1;
    let (monic, e) = scaled_monic(coeffs);
    let mut m = DMatrix::<f64>::zeros(n, n);
    for j in 0..n {
        m[(0, j)] = -monic[j + 1];
    }
    for i in 1..n {
        m[(i, i - 1)] = 1.0;
    }
    nalgebra::linalg::balancing::balance_parlett_reinsch(&mut m);
    let schur = nalgebra::linalg::Schur::try_new(m, f64::EPSILON, 10_000)
        .ok_or(LtiError::RootsDidNotConverge { degree: n })?;
    let (_, t) = schur.unpack();
    Ok(block_eigenvalues(&t)
        .into_iter()
        .map(|x| C64::new(mul_pow2(x.re, e), mul_pow2(x.im, e)))
        .collect())
}

/// Eigenvalues of a real Schur form: its 1×1 blocks and the pairs of its 2×2 blocks.
///
/// nalgebra's `Schur::complex_eigenvalues` assumes every 2×2 block left holds a complex
/// pair; a block holding two (nearly equal) real eigenvalues, as the Schur iteration leaves
/// for a double real root, then gives NaN imaginary parts (the roots of
/// (s + 1.3848)²(s² + 13.59s + 66.33) came out as NaN, and the conjugate pairing turned
/// the 4 roots into 6). Here such a block gives its two real eigenvalues.
fn block_eigenvalues(t: &DMatrix<f64>) -> Vec<C64> {
    let n = t.nrows();
    let mut out = Vec::with_capacity(n);
    let mut m = 0;
    while m < n {
        if m + 1 == n || t[(m + 1, m)] == 0.0 {
            out.push(C64::new(t[(m, m)], 0.0));
            m += 1;
            continue;
        }
        let (a, b, c, d) = (t[(m, m)], t[(m, m + 1)], t[(m + 1, m)], t[(m + 1, m + 1)]);
        let half_trace = 0.5 * (a + d);
        let half_gap = 0.5 * (a - d);
        let discriminant = b * c + half_gap * half_gap;
        if discriminant >= 0.0 {
            let r = discriminant.sqrt();
            out.push(C64::new(half_trace + r, 0.0));
            out.push(C64::new(half_trace - r, 0.0));
        } else {
            let r = (-discriminant).sqrt();
            out.push(C64::new(half_trace, r));
            out.push(C64::new(half_trace, -r));
        }
        m += 2;
    }
    out
}

/// The monic coefficients bⱼ = cⱼ/(c₀·2^{je}) of the polynomial in x = s/2^e, with e chosen
/// so that every |bⱼ| ≲ 2 (a power of two, so the scaling itself is exact), and e.
///
/// Leading coefficient non-zero and all coefficients finite. Ratios cⱼ/c₀ are never formed
/// directly (they may overflow); a bⱼ far below 1 may underflow to 0, harmlessly.
fn scaled_monic(coeffs: &[f64]) -> (Vec<f64>, i32) {
    let log_lead = coeffs[0].abs().log2();
    let e = coeffs
        .iter()
        .enumerate()
        .skip(1)
        .filter(|(_, c)| **c != 0.0)
        .map(|(j, c)| ((c.abs().log2() - log_lead) / j as f64).ceil())
        .fold(f64::NEG_INFINITY, f64::max);
    let e = if e.is_finite() { e as i32 } else { 0 };
    // c₀ = m₀·2^{x₀} with m₀ near 1: divide by m₀ only once everything is of order 1.
    let x0 = log_lead.floor() as i32;
    let m0 = mul_pow2(coeffs[0], -x0);
    let monic = coeffs
        .iter()
        .enumerate()
        .map(|(j, &c)| mul_pow2(c, -(j as i32) * e - x0) / m0)
        .collect();
    (monic, e)
}

/// Computed roots closer than this (relative) are candidates for one multiple root.
const MULTIPLE_SEARCH: f64 = 0.5;
/// A Taylor coefficient of p at a candidate multiple root counts as zero when it is below
/// this many unit roundings (times the degree) of its size (see [`is_multiple_root`]).
const MULTIPLE_TOLERANCE: f64 = 32.0;

/// Groups the computed roots of p into (root, multiplicity): a group of m computed roots is
/// one m-fold root at their mean when p has one there, to rounding.
///
/// An m-fold root comes out of any eigenvalue solver split into m roots about eps^{1/m}
/// apart ((s + 1)³: 1e-5, (s + 1)⁸: 2e-2), while their mean is accurate to rounding. Kept
/// apart, such roots make partial fractions cancel catastrophically (error eps/δ^{m−1}: 2e-3
/// in the step response of 1/(s + 1)⁵ typed as coefficients); polished one by one by Newton,
/// they lose the symmetry that makes their mean accurate. Merging is backward stable: the
/// test is that p's Taylor coefficients at the mean, of order below m, all vanish to
/// rounding, i.e. that p is within rounding of a polynomial with an m-fold root there.
/// Candidate groups are formed by single linkage, the tolerance shrinking from
/// [`MULTIPLE_SEARCH`] until every group passes the test or is a single root.
fn multiple_roots(coeffs: &[f64], raw: Vec<C64>) -> Vec<(C64, usize)> {
    fn split(coeffs: &[f64], group: Vec<C64>, tolerance: f64, out: &mut Vec<(C64, usize)>) {
        let m = group.len();
        if m == 1 {
            out.push((group[0], 1));
            return;
        }
        let mean = group.iter().sum::<C64>() / m as f64;
        if is_multiple_root(coeffs, mean, m) {
            out.push((mean, m));
        } else if tolerance < 1e-12 {
            out.extend(group.into_iter().map(|r| (r, 1)));
        } else {
            for sub in single_linkage(group, tolerance / 3.0) {
                split(coeffs, sub, tolerance / 3.0, out);
            }
        }
    }
    let mut out = Vec::with_capacity(raw.len());
    for group in single_linkage(raw, MULTIPLE_SEARCH) {
        split(coeffs, group, MULTIPLE_SEARCH, &mut out);
    }
    out
}

/// Groups of roots connected by links |a − b| ≤ tolerance·max(|a|, |b|).
fn single_linkage(roots: Vec<C64>, tolerance: f64) -> Vec<Vec<C64>> {
    let n = roots.len();
    let mut group: Vec<usize> = (0..n).collect();
    for i in 0..n {
        for j in (i + 1)..n {
            let (a, b) = (roots[i], roots[j]);
            if (a - b).norm() <= tolerance * a.norm().max(b.norm()) && group[i] != group[j] {
                let (gi, gj) = (group[i], group[j]);
                group.iter_mut().filter(|g| **g == gj).for_each(|g| *g = gi);
            }
        }
    }
    let mut labels: Vec<usize> = group.clone();
    labels.sort_unstable();
    labels.dedup();
    labels
        .into_iter()
        .map(|l| {
            (0..n)
                .filter(|&i| group[i] == l)
                .map(|i| roots[i])
                .collect()
        })
        .collect()
}

/// True when the Taylor coefficients p^{(k)}(c)/k!, k < m, all vanish to rounding: each
/// below [`MULTIPLE_TOLERANCE`]·n·eps times the same coefficient of Σ|aᵢ|·x^i at x = |c|
/// (the size of the terms it sums, so the scale of its rounding error).
fn is_multiple_root(coeffs: &[f64], c: C64, m: usize) -> bool {
    let n = coeffs.len() - 1;
    if m > n {
        return false;
    }
    let limit = MULTIPLE_TOLERANCE * n as f64 * f64::EPSILON;
    let mut p: Vec<C64> = coeffs.iter().map(|&a| C64::new(a, 0.0)).collect();
    let mut size: Vec<f64> = coeffs.iter().map(|a| a.abs()).collect();
    let r = c.norm();
    for _ in 0..m {
        // Synthetic division by (s − c): the remainder is the next Taylor coefficient.
        for i in 1..p.len() {
            p[i] = p[i] + p[i - 1] * c;
            size[i] += size[i - 1] * r;
        }
        let (taylor, bound) = (p.pop().unwrap_or_default(), size.pop().unwrap_or_default());
        // Written so that a NaN fails the test too.
        if !matches!(
            taylor.norm().partial_cmp(&(limit * bound)),
            Some(Ordering::Less | Ordering::Equal)
        ) {
            return false;
        }
    }
    true
}

/// Computed roots nearer than this (relative) to another are left unpolished.
const POLISH_ISOLATION: f64 = 1e-2;

/// True when no other computed root lies within [`POLISH_ISOLATION`] of `root`. Roots of a
/// cluster of distinct roots are not polished one by one: Newton pulls each towards the
/// nearest exact root independently and spoils their symmetric functions, which the
/// eigenvalues keep to rounding (the six roots of a cluster 5e-4 wide, polished, gave a
/// static gain 1.3e-3 off num[−1]/den[−1]).
fn isolated(root: C64, all: &[C64]) -> bool {
    all.iter()
        .filter(|&&r| r != root)
        .all(|&r| (r - root).norm() > POLISH_ISOLATION * r.norm().max(root.norm()))
}

/// A few Newton steps on p, each kept only if it lowers |p|; returns the better root.
fn polish(coeffs: &[f64], root: C64) -> C64 {
    let derivative: Vec<f64> = {
        let n = coeffs.len() - 1;
        coeffs[..n]
            .iter()
            .enumerate()
            .map(|(i, &c)| c * (n - i) as f64)
            .collect()
    };
    let mut best = root;
    let mut best_residual = eval_complex(coeffs, root).norm();
    for _ in 0..3 {
        let slope = eval_complex(&derivative, best);
        if slope.norm() == 0.0 || best_residual == 0.0 {
            break;
        }
        let candidate = best - eval_complex(coeffs, best) / slope;
        let residual = eval_complex(coeffs, candidate).norm();
        if residual.partial_cmp(&best_residual) != Some(Ordering::Less) {
            break;
        }
        best = candidate;
        best_residual = residual;
    }
    best
}

/// Makes a list of roots of a real polynomial exactly closed under conjugation: nearly real
/// roots become real, and each complex root is paired with its nearest mirror image, both
/// replaced by the mean of the pair.
pub fn conjugate_closed(mut roots: Vec<C64>) -> Vec<C64> {
    let mut out = Vec::with_capacity(roots.len());
    for r in roots.iter_mut() {
        if r.im.abs() <= REAL_AXIS_TOLERANCE * r.norm() {
            r.im = 0.0;
        }
    }
    let (real, mut complex): (Vec<C64>, Vec<C64>) = roots.into_iter().partition(|r| r.im == 0.0);
    out.extend(real);
    while let Some(upper_index) = complex.iter().position(|r| r.im > 0.0) {
        let upper = complex.swap_remove(upper_index);
        let mirror = upper.conj();
        let partner = complex
            .iter()
            .enumerate()
            .filter(|(_, r)| r.im < 0.0)
            .min_by(|(_, a), (_, b)| (**a - mirror).norm().total_cmp(&(**b - mirror).norm()))
            .map(|(i, _)| i);
        let lower = partner.map(|i| complex.swap_remove(i)).unwrap_or(mirror);
        let mean = C64::new(0.5 * (upper.re + lower.re), 0.5 * (upper.im - lower.im));
        out.push(mean);
        out.push(mean.conj());
    }
    // Unpaired roots below the axis (cannot happen for a real polynomial) are mirrored too.
    for lower in complex {
        out.push(lower.conj());
        out.push(lower);
    }
    sort_roots(&mut out);
    out
}

/// Orders roots by real part descending (dominant first), then by imaginary part descending,
/// so that a conjugate pair is listed upper member first.
pub fn sort_roots(roots: &mut [C64]) {
    roots.sort_by(|a, b| b.re.total_cmp(&a.re).then(b.im.total_cmp(&a.im)));
}

/// Formats a polynomial in descending powers of s for people, e.g. `s^3 + 7 s^2 + 15 s + 25`.
pub fn format_poly(coeffs: &[f64]) -> String {
    let n = coeffs.len().saturating_sub(1);
    let mut out = String::new();
    for (i, &c) in coeffs.iter().enumerate() {
        if c == 0.0 {
            continue;
        }
        let power = n - i;
        let magnitude = c.abs();
        let sign = if c < 0.0 { "-" } else { "+" };
        if out.is_empty() {
            if c < 0.0 {
                out.push('-');
            }
        } else {
            out.push_str(&format!(" {sign} "));
        }
        let show_number = magnitude != 1.0 || power == 0;
        if show_number {
            out.push_str(&super::number::format_number(magnitude));
        }
        match power {
            0 => {}
            1 => out.push_str(if show_number { " s" } else { "s" }),
            p => out.push_str(&format!("{}s^{p}", if show_number { " " } else { "" })),
        }
    }
    if out.is_empty() { "0".into() } else { out }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted(mut r: Vec<C64>) -> Vec<C64> {
        sort_roots(&mut r);
        r
    }

    #[test]
    fn roots_of_the_notes_third_order_denominator() {
        let r = roots(&[1.0, 7.0, 15.0, 25.0]).unwrap();
        let expected = [
            C64::new(-1.0, 2.0),
            C64::new(-1.0, -2.0),
            C64::new(-5.0, 0.0),
        ];
        assert_eq!(r.len(), 3);
        for (a, b) in r.iter().zip(expected.iter()) {
            assert!((a - b).norm() < 1e-12, "{a} vs {b}");
        }
        assert_eq!(r[0], r[1].conj(), "pair must be exactly conjugate");
    }

    #[test]
    fn quadratics_at_extreme_scales_keep_both_roots() {
        let r = roots(&[1.0, 1e200, 1.0]).unwrap();
        let near = |x: f64| {
            r.iter()
                .any(|z| z.im == 0.0 && (z.re - x).abs() <= 1e-12 * x.abs())
        };
        assert!(near(-1e200) && near(-1e-200), "{r:?}");
        let r = roots(&[1e300, 0.0, 1e300]).unwrap();
        assert!(r.iter().all(|z| (z.norm() - 1.0).abs() < 1e-12), "{r:?}");
        let r = roots(&[1e-300, 3e-300, 2e-300]).unwrap();
        let near = |x: f64| r.iter().any(|z| (z.re - x).abs() < 1e-12 && z.im == 0.0);
        assert!(near(-2.0) && near(-1.0), "{r:?}");
    }

    #[test]
    fn round_trip_roots_and_coefficients() {
        let den = [1.0, 30.0, 352.0, 2072.0, 6420.0, 9000.0];
        let r = roots(&den).unwrap();
        let back = poly_from_roots(&r);
        for (a, b) in back.iter().zip(den.iter()) {
            assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} vs {b}");
        }
    }

    #[test]
    fn origin_roots_are_exact_and_leading_zeros_dropped() {
        let r = roots(&[0.0, 1.0, 3.0, 0.0]).unwrap();
        assert_eq!(sorted(r), vec![C64::new(0.0, 0.0), C64::new(-3.0, 0.0)]);
    }

    #[test]
    fn quadratic_without_cancellation() {
        // s² + 1e8 s + 1: roots near −1e−8 and −1e8.
        let r = roots(&[1.0, 1e8, 1.0]).unwrap();
        assert!((r[0].re + 1e-8).abs() < 1e-20);
        assert!((r[1].re + 1e8).abs() < 1e-6);
    }

    #[test]
    fn degenerate_polynomials_are_refused() {
        assert!(matches!(
            roots(&[0.0, 0.0]),
            Err(LtiError::ZeroPolynomial { .. })
        ));
        assert!(matches!(
            roots(&[1.0, f64::NAN]),
            Err(LtiError::NonFiniteCoefficient { index: 2, .. })
        ));
        assert!(matches!(roots(&[]), Err(LtiError::ZeroPolynomial { .. })));
    }

    #[test]
    fn formats_like_matlab_printsys() {
        assert_eq!(
            format_poly(&[1.0, 7.0, 15.0, 25.5]),
            "s^3 + 7 s^2 + 15 s + 25.5"
        );
        assert_eq!(format_poly(&[-2.0, 0.0, 1.0]), "-2 s^2 + 1");
    }
}
