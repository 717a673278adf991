//! Numbers as the app shows them: a fixed count of significant digits, no trailing zeros,
//! scientific notation only for very large or small magnitudes.

use crate::lti::expr::format_number;

/// `x` with `digits` significant digits, e.g. `sig(0.773201, 4) == "0.7732"`.
pub fn sig(x: f64, digits: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return format_number(x);
    }
    if x.abs() >= 1e6 || x.abs() < 1e-4 {
        let text = format!("{:.*e}", (digits - 1).max(0) as usize, x);
        return match text.split_once('e') {
            Some((m, e)) => format!("{}e{e}", trim(m)),
            None => text,
        };
    }
    let decimals = (digits - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    trim(&format!("{x:.decimals$}"))
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::sig;

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
