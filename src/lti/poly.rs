//! Real polynomials in descending powers (MATLAB's convention: `[1, 7, 15, 25]` is
//! s³ + 7s² + 15s + 25), their roots and the polynomial built from a set of roots.
//!
//! Roots come from the eigenvalues of the balanced companion matrix (nalgebra's real Schur
//! form), are polished by a few guarded Newton steps, and are returned closed under
//! conjugation: every complex root is followed by its exact conjugate.

use nalgebra::{Complex, DMatrix};

use super::LtiError;

/// A complex number of `f64`s, as used for poles and zeros.
pub type C64 = Complex<f64>;

/// Roots whose imaginary part is below this fraction of their modulus are taken as real.
const REAL_AXIS_TOLERANCE: f64 = 1e-10;

/// Checks that every coefficient is finite; `what` names the polynomial in the message.
pub fn check_finite(coeffs: &[f64], what: &'static str) -> Result<(), LtiError> {
    match coeffs.iter().position(|c| !c.is_finite()) {
        Some(index) => Err(LtiError::NonFiniteCoefficient { what, index }),
        None => Ok(()),
    }
}

/// Drops leading zero coefficients (as MATLAB's `tf` does); an all-zero polynomial is an error.
pub fn strip_leading_zeros(coeffs: &[f64], what: &'static str) -> Result<Vec<f64>, LtiError> {
    check_finite(coeffs, what)?;
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
    let coeffs = strip_leading_zeros(coeffs, "polynomial")?;
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
    found.extend(raw.into_iter().map(|r| polish(reduced, r)));
    debug_assert_eq!(found.len(), n);
    Ok(conjugate_closed(found))
}

/// Roots of a·s² + b·s + c without cancellation (the citardauq form for the smaller root).
fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<C64> {
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
fn companion_roots(coeffs: &[f64]) -> Result<Vec<C64>, LtiError> {
    let n = coeffs.len() - 1;
    let lead = coeffs[0];
    let mut m = DMatrix::<f64>::zeros(n, n);
    for j in 0..n {
        m[(0, j)] = -coeffs[j + 1] / lead;
    }
    for i in 1..n {
        m[(i, i - 1)] = 1.0;
    }
    nalgebra::linalg::balancing::balance_parlett_reinsch(&mut m);
    let schur = nalgebra::linalg::Schur::try_new(m, f64::EPSILON, 10_000)
        .ok_or(LtiError::RootsDidNotConverge { degree: n })?;
    Ok(schur.complex_eigenvalues().iter().copied().collect())
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
        if !(residual < best_residual) {
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
            out.push_str(&super::expr::format_number(magnitude));
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
        let expected = [C64::new(-1.0, 2.0), C64::new(-1.0, -2.0), C64::new(-5.0, 0.0)];
        assert_eq!(r.len(), 3);
        for (a, b) in r.iter().zip(expected.iter()) {
            assert!((a - b).norm() < 1e-12, "{a} vs {b}");
        }
        assert_eq!(r[0], r[1].conj(), "pair must be exactly conjugate");
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
        assert!(matches!(roots(&[0.0, 0.0]), Err(LtiError::ZeroPolynomial { .. })));
        assert!(matches!(
            roots(&[1.0, f64::NAN]),
            Err(LtiError::NonFiniteCoefficient { index: 1, .. })
        ));
        assert!(matches!(roots(&[]), Err(LtiError::ZeroPolynomial { .. })));
    }

    #[test]
    fn formats_like_matlab_printsys() {
        assert_eq!(format_poly(&[1.0, 7.0, 15.0, 25.5]), "s^3 + 7 s^2 + 15 s + 25.5");
        assert_eq!(format_poly(&[-2.0, 0.0, 1.0]), "-2 s^2 + 1");
    }
}
