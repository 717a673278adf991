//! Parsing people's text into numbers: complex roots such as `-1+2j`, lists such as
//! `-1+2j, -1-2j, -5`, and coefficient lists such as `1, 7, 15, 25`.
//!
//! This module owns the text syntax shared by the command line and the app:
//! - a complex number is `a`, `bj`, `a+bj` or `a-bj`, with `j` or `i` (either case) as the
//!   imaginary unit, `j` alone meaning 1j (`-j`, `2-j`), any real in Rust's float syntax
//!   (`2.5e-3`, `.5`), spaces only next to a sign (`-1 + 2j`), and `−` (U+2212, as the
//!   closed-form text writes it) read as `-`;
//! - a list separates items with commas or semicolons; an empty (or blank) text is an empty
//!   list, an empty item between two separators is an error;
//! - every number must be finite: `nan` and `inf` are refused here, naming the item.
//!
//! Errors name the item (1-based) and its text, e.g. `item 2 ("-1+xj") is not a number like
//! -1+2j`, so a student can find the typo.

use super::C64;

/// What is wrong with a piece of text that should hold numbers: a typed fact, said in words
/// by [`crate::words::lti`] (its `Display` is the English text), e.g. `item 2 ("-1+xj") is
/// not a number like -1+2j`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ParseError {
    /// Not readable as a complex number.
    NotComplex { index: Option<usize>, text: String },
    /// Not readable as a real number.
    NotReal { index: Option<usize>, text: String },
    /// Readable, but NaN or infinite.
    NotFinite { index: Option<usize>, text: String },
    /// Nothing between two separators (or before the first, or after the last).
    EmptyItem { index: usize },
}

impl std::fmt::Display for ParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&degrau_words::Localize::text(self, degrau_words::Lang::En))
    }
}

impl std::error::Error for ParseError {}

impl ParseError {
    /// The same error, located at item `index` (1-based) of a list.
    fn at(self, index: usize) -> Self {
        let index = Some(index);
        match self {
            Self::NotComplex { text, .. } => Self::NotComplex { index, text },
            Self::NotReal { text, .. } => Self::NotReal { index, text },
            Self::NotFinite { text, .. } => Self::NotFinite { index, text },
            empty @ Self::EmptyItem { .. } => empty,
        }
    }
}

/// Reads one complex number: `-1+2j`, `3`, `-2.5i`, `-j`, `+2.5e-3-1e2i`, `-1 + 2j`.
pub fn parse_complex(text: &str) -> Result<C64, ParseError> {
    let not_complex = || ParseError::NotComplex {
        index: None,
        text: text.trim().to_string(),
    };
    let compact = compact_complex(text).ok_or_else(not_complex)?;
    let value = match compact.strip_suffix(['j', 'J', 'i', 'I']) {
        Some(body) => {
            let (re, im) = body.split_at(imaginary_start(body));
            let re = if re.is_empty() {
                Some(0.0)
            } else {
                re.parse().ok()
            };
            let im = match im {
                "" | "+" => Some(1.0),
                "-" => Some(-1.0),
                coefficient => coefficient.parse().ok(),
            };
            re.zip(im).map(|(re, im)| C64::new(re, im))
        }
        None => compact.parse().ok().map(|re| C64::new(re, 0.0)),
    }
    .ok_or_else(not_complex)?;
    if value.re.is_finite() && value.im.is_finite() {
        Ok(value)
    } else {
        Err(ParseError::NotFinite {
            index: None,
            text: text.trim().to_string(),
        })
    }
}

/// Reads one real number: `7`, `-0.5`, `2.5e-3`.
pub fn parse_real(text: &str) -> Result<f64, ParseError> {
    let text = text.trim();
    let value: f64 = text
        .replace('\u{2212}', "-")
        .parse()
        .map_err(|_| ParseError::NotReal {
            index: None,
            text: text.to_string(),
        })?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ParseError::NotFinite {
            index: None,
            text: text.to_string(),
        })
    }
}

/// Reads a comma- or semicolon-separated list of complex numbers: `-1+2j, -1-2j; -5`.
pub fn parse_complex_list(text: &str) -> Result<Vec<C64>, ParseError> {
    parse_list(text, parse_complex)
}

/// Reads a comma- or semicolon-separated list of real numbers: `1, 7, 15, 25`.
pub fn parse_real_list(text: &str) -> Result<Vec<f64>, ParseError> {
    parse_list(text, parse_real)
}

/// Splits on commas and semicolons and parses every item, naming the first bad one.
fn parse_list<T>(
    text: &str,
    parse: impl Fn(&str) -> Result<T, ParseError>,
) -> Result<Vec<T>, ParseError> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    text.split([',', ';'])
        .enumerate()
        .map(|(i, piece)| {
            let index = i + 1;
            if piece.trim().is_empty() {
                Err(ParseError::EmptyItem { index })
            } else {
                parse(piece).map_err(|e| e.at(index))
            }
        })
        .collect()
}

/// The text without spaces, `−` read as `-`; `None` when a space separates two parts that
/// are not joined by a sign (`-1 2j` must not silently become `-12j`).
fn compact_complex(text: &str) -> Option<String> {
    let chars: Vec<char> = text
        .trim()
        .chars()
        .map(|c| if c == '\u{2212}' { '-' } else { c })
        .collect();
    let is_sign = |c: &char| *c == '+' || *c == '-';
    let mut out = String::with_capacity(chars.len());
    for (i, c) in chars.iter().enumerate() {
        if !c.is_whitespace() {
            out.push(*c);
            continue;
        }
        let before = chars[..i].iter().rev().find(|c| !c.is_whitespace());
        let after = chars[i + 1..].iter().find(|c| !c.is_whitespace());
        if !before.is_some_and(is_sign) && !after.is_some_and(is_sign) {
            return None;
        }
    }
    Some(out)
}

/// Where the imaginary coefficient starts in `body` (the text before the unit): at the last
/// sign that is neither the first character nor an exponent's sign, else at 0.
fn imaginary_start(body: &str) -> usize {
    body.char_indices()
        .rev()
        .find(|&(i, c)| (c == '+' || c == '-') && i > 0 && !body[..i].ends_with(['e', 'E']))
        .map_or(0, |(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    #[test]
    fn complex_numbers_in_every_form() {
        let cases = [
            ("-1+2j", c(-1.0, 2.0)),
            ("-1-2j", c(-1.0, -2.0)),
            ("3", c(3.0, 0.0)),
            ("-5", c(-5.0, 0.0)),
            ("2j", c(0.0, 2.0)),
            ("-2.5i", c(0.0, -2.5)),
            ("j", c(0.0, 1.0)),
            ("-j", c(0.0, -1.0)),
            ("+j", c(0.0, 1.0)),
            ("4-j", c(4.0, -1.0)),
            ("4+J", c(4.0, 1.0)),
            ("+2.5e-3-1e2i", c(2.5e-3, -100.0)),
            ("1e-3+2E+1j", c(1e-3, 20.0)),
            ("1e2", c(100.0, 0.0)),
            ("  -1 + 2j ", c(-1.0, 2.0)),
            ("- 1 - 2j", c(-1.0, -2.0)),
            ("\u{2212}1\u{2212}2j", c(-1.0, -2.0)),
            (".5-.25I", c(0.5, -0.25)),
        ];
        for (text, expected) in cases {
            assert_eq!(parse_complex(text), Ok(expected), "{text:?}");
        }
    }

    #[test]
    fn bad_complex_numbers_are_refused_with_their_text() {
        for text in [
            "", "x", "1+xj", "1+-2j", "j2", "2*j", "1 2j", "2 j", "1e+j", "1++j", "--1", "1,5",
        ] {
            assert!(
                matches!(parse_complex(text), Err(ParseError::NotComplex { .. })),
                "{text:?} gave {:?}",
                parse_complex(text)
            );
        }
        assert_eq!(
            parse_complex("1+xj").unwrap_err().to_string(),
            r#""1+xj" is not a number like -1+2j"#
        );
        for text in ["nan", "inf", "-inf+2j", "1+infj", "1e400"] {
            assert!(
                matches!(parse_complex(text), Err(ParseError::NotFinite { .. })),
                "{text:?}"
            );
        }
    }

    #[test]
    fn complex_lists() {
        assert_eq!(
            parse_complex_list("-1+2j,-1-2j,-5"),
            Ok(vec![c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)])
        );
        assert_eq!(
            parse_complex_list(" -1 + 2j ; -1 - 2j ,-5 "),
            Ok(vec![c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)])
        );
        assert_eq!(parse_complex_list(""), Ok(vec![]));
        assert_eq!(parse_complex_list("   "), Ok(vec![]));
        assert_eq!(parse_complex_list("-10"), Ok(vec![c(-10.0, 0.0)]));
    }

    #[test]
    fn list_errors_name_the_item_and_its_position() {
        let error = parse_complex_list("-1+2j, -1+xj, -5").unwrap_err();
        assert_eq!(
            error,
            ParseError::NotComplex {
                index: Some(2),
                text: "-1+xj".into()
            }
        );
        assert_eq!(
            error.to_string(),
            r#"item 2 ("-1+xj") is not a number like -1+2j"#
        );
        assert_eq!(
            parse_complex_list("-1,,-2"),
            Err(ParseError::EmptyItem { index: 2 })
        );
        assert_eq!(
            parse_real_list("1,2,"),
            Err(ParseError::EmptyItem { index: 3 })
        );
        assert_eq!(
            parse_real_list("1, nan").unwrap_err().to_string(),
            r#"item 2 ("nan") is not a finite number"#
        );
    }

    #[test]
    fn real_lists() {
        assert_eq!(
            parse_real_list("1, 7, 15, 25"),
            Ok(vec![1.0, 7.0, 15.0, 25.0])
        );
        assert_eq!(parse_real_list("0.5"), Ok(vec![0.5]));
        assert_eq!(parse_real_list("-2.5e-3;4"), Ok(vec![-2.5e-3, 4.0]));
        assert_eq!(parse_real_list(""), Ok(vec![]));
        assert_eq!(
            parse_real_list("1 7 15"),
            Err(ParseError::NotReal {
                index: Some(1),
                text: "1 7 15".into()
            })
        );
        assert!(matches!(
            parse_real_list("1, 2j"),
            Err(ParseError::NotReal { index: Some(2), .. })
        ));
        assert!(matches!(
            parse_real("inf"),
            Err(ParseError::NotFinite { .. })
        ));
    }
}
