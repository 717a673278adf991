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
    fixed_trimmed(x, (5 - magnitude).max(0) as usize)
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
    fixed_trimmed(x, decimals)
}

/// `format!("{x:.decimals$}")` without trailing zeros, for finite `x`; the same text, found
/// faster (it is most of the closed-form text's cost, ~15 numbers per system in a batch):
/// x·10^decimals rounded to an integer, whose digits are the text. The product carries one
/// rounding error, so a product within 1e-6 of a half (where that error could pick the other
/// side) and magnitudes beyond 2^53 are left to the exact formatter.
fn fixed_trimmed(x: f64, decimals: usize) -> String {
    const EXACT_BELOW: f64 = 9.0e15;
    let scaled = x.abs() * 10f64.powi(decimals as i32);
    let fraction = scaled - scaled.floor();
    if decimals > 22 || scaled >= EXACT_BELOW || (fraction - 0.5).abs() < 1e-6 {
        return trim_zeros(&format!("{x:.decimals$}"));
    }
    // The digits of the rounded integer, least significant first, at least one more than
    // the decimals (the leading "0." of a number below one).
    let mut n = scaled.round() as u64;
    let mut digits = [b'0'; 40];
    let mut count = 0;
    while n > 0 || count <= decimals {
        digits[count] = b'0' + (n % 10) as u8;
        n /= 10;
        count += 1;
    }
    let zeros = digits[..decimals]
        .iter()
        .take_while(|&&d| d == b'0')
        .count();
    let mut text = String::with_capacity(count + 2);
    if x.is_sign_negative() {
        text.push('-');
    }
    text.extend(digits[decimals..count].iter().rev().map(|&d| char::from(d)));
    if zeros < decimals {
        text.push('.');
        text.extend(digits[zeros..decimals].iter().rev().map(|&d| char::from(d)));
    }
    text
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

    /// The fast path against the exact formatter, on random magnitudes, ties and near ties.
    #[test]
    fn fixed_text_is_the_exact_formatters() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut values: Vec<f64> = (0..200_000)
            .map(|_| {
                let mantissa = (next() >> 11) as f64 / (1u64 << 53) as f64;
                let sign = if next() % 2 == 0 { 1.0 } else { -1.0 };
                sign * mantissa * 10f64.powi((next() % 24) as i32 - 12)
            })
            .collect();
        values.extend([
            0.5, 1.5, 2.5, 0.125, 1.0000005, 2.0000015, 0.1234565, 999999.5, -0.0,
        ]);
        values.extend((1..2000).map(|k| k as f64 / 64.0));
        for &x in &values {
            for decimals in 0..14 {
                assert_eq!(
                    fixed_trimmed(x, decimals),
                    trim_zeros(&format!("{x:.decimals$}")),
                    "{x:e} with {decimals} decimals"
                );
            }
        }
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

/// A whole number in superscript digits (`12` → `¹²`), for powers written in words: s², z⁻³.
pub fn superscript(p: usize) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    p.to_string()
        .chars()
        .map(|c| c.to_digit(10).map_or(c, |d| DIGITS[d as usize]))
        .collect()
}

#[cfg(test)]
mod superscript_tests {
    #[test]
    fn digits_become_superscripts() {
        assert_eq!(super::superscript(0), "⁰");
        assert_eq!(super::superscript(120), "¹²⁰");
    }
}
