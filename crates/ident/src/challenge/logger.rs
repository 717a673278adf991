//! The record as a lab logger writes it: samples at a round sampling period, the input
//! column showing a change at the first sample at or after the instant it happened (the
//! step comes between two samples), and a CSV of `t,u,y` with a fixed number of
//! significant digits, so that the last bits of a platform's `exp` cannot change a byte.

use crate::model::excitation::InputStep;

/// Round sampling periods a logger is set to (s).
const PERIODS: [f64; 13] = [
    0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0,
];

/// Significant digits of every number written.
pub const DIGITS: usize = 7;

/// The samples of one record: time (s), input, output.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub t: Vec<f64>,
    pub u: Vec<f64>,
    pub y: Vec<f64>,
}

/// The largest round period not above `h` (the smallest one when `h` is below them all).
pub fn round_period(h: f64) -> f64 {
    PERIODS
        .iter()
        .copied()
        .rfind(|&p| p <= h)
        .unwrap_or(PERIODS[0])
}

/// The instants `k·ts` covering `length` seconds.
pub fn sample_times(length: f64, ts: f64) -> Vec<f64> {
    let n = (length / ts).floor() as usize + 1;
    (0..n).map(|k| k as f64 * ts).collect()
}

/// The input column: `u0` plus every change that happened at or before each sample.
pub fn logged_input(times: &[f64], u0: f64, changes: &[InputStep]) -> Vec<f64> {
    times
        .iter()
        .map(|&t| {
            u0 + changes
                .iter()
                .filter(|c| c.t <= t)
                .map(|c| c.du)
                .sum::<f64>()
        })
        .collect()
}

/// `x` with [`DIGITS`] significant digits, in plain decimal notation (no exponent): Rust's
/// exact decimal conversion, not a logarithm, decides the digits.
pub fn significant(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".to_string();
    }
    let sci = format!("{:.*e}", DIGITS - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let negative = mantissa.starts_with('-');
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let point = exponent + 1; // digits before the decimal point
    let mut text = if point <= 0 {
        format!("0.{}{digits}", "0".repeat((-point) as usize))
    } else if point as usize >= digits.len() {
        format!("{digits}{}", "0".repeat(point as usize - digits.len()))
    } else {
        let (a, b) = digits.split_at(point as usize);
        format!("{a}.{b}")
    };
    if text.contains('.') {
        text = text.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    if negative { format!("-{text}") } else { text }
}

impl Record {
    /// The CSV text: a `t,u,y` header and one line per sample.
    pub fn csv(&self) -> String {
        let mut text = String::from("t,u,y\n");
        for ((t, u), y) in self.t.iter().zip(&self.u).zip(&self.y) {
            text += &format!(
                "{},{},{}\n",
                significant(*t),
                significant(*u),
                significant(*y)
            );
        }
        text
    }

    /// The record as its CSV says it: every number rounded to [`DIGITS`] digits.
    pub fn as_written(&self) -> Record {
        let round = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .map(|x| significant(*x).parse().unwrap_or(*x))
                .collect()
        };
        Record {
            t: round(&self.t),
            u: round(&self.u),
            y: round(&self.y),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_seven_significant_digits_without_exponent() {
        assert_eq!(significant(0.30000000000000004), "0.3");
        assert_eq!(significant(-123.456789), "-123.4568");
        assert_eq!(significant(0.000123456789), "0.0001234568");
        assert_eq!(significant(12345678.9), "12345680");
        assert_eq!(significant(50.0), "50");
        assert_eq!(significant(0.0), "0");
    }

    #[test]
    fn the_input_shows_a_change_at_the_next_sample() {
        let t = [0.0, 1.0, 2.0, 3.0];
        let u = logged_input(&t, 10.0, &[InputStep { t: 1.3, du: 2.0 }]);
        assert_eq!(u, vec![10.0, 10.0, 12.0, 12.0]);
    }

    #[test]
    fn periods_are_round() {
        assert_eq!(round_period(0.037), 0.02);
        assert_eq!(round_period(1.3), 1.0);
        assert_eq!(round_period(1e-5), 0.001);
    }
}
