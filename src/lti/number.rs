//! Numbers as people read them: [`format_number`] (integers as integers, else six
//! significant digits) and [`sig`] (a chosen count of significant digits), both without
//! trailing zeros and in scientific notation only for very large or small magnitudes.
//!
//! A leaf: it uses nothing else of the crate, so the closed-form text, the polynomials'
//! text and the text layer can all depend on it.

/// A number for people: integers as integers, else 6 significant digits without trailing
/// zeros, scientific notation for very large or small magnitudes.
pub fn format_number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == x.round() && x.abs() < 1e15 {
        return format!("{}", x as i64);
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-4..9).contains(&magnitude) {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        return format!("{}e{exponent}", trim_zeros(mantissa));
    }
    let decimals = (5 - magnitude).max(0) as usize;
    trim_zeros(&format!("{x:.decimals$}"))
}

/// `x` with `digits` significant digits, e.g. `sig(0.773201, 4) == "0.7732"`.
pub fn sig(x: f64, digits: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return format_number(x);
    }
    if x.abs() >= 1e6 || x.abs() < 1e-4 {
        let text = format!("{:.*e}", (digits - 1).max(0) as usize, x);
        return match text.split_once('e') {
            Some((m, e)) => format!("{}e{e}", trim_zeros(m)),
            None => text,
        };
    }
    let decimals = (digits - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    trim_zeros(&format!("{x:.decimals$}"))
}

/// The text without trailing zeros after a decimal point (and without the point itself
/// when nothing follows it).
fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_digits_for_people() {
        assert_eq!(format_number(0.439444915467244), "0.439445");
        assert_eq!(format_number(25.5), "25.5");
        assert_eq!(format_number(1.5e-7), "1.5e-7");
        assert_eq!(format_number(-3.0), "-3");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(sig(0.773201, 4), "0.7732");
        assert_eq!(sig(3.92096, 4), "3.921");
        assert_eq!(sig(-1.0, 4), "-1");
        assert_eq!(sig(2.23606797, 4), "2.236");
        assert_eq!(sig(1234.5678, 5), "1234.6");
        assert_eq!(sig(1.5e-7, 4), "1.5e-7");
        assert_eq!(sig(0.0, 4), "0");
    }
}
