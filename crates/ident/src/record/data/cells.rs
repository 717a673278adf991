//! Lines, cells and fields: the non-blank lines of a text (comments told apart), a cell read
//! as a number, a missing value or text (missing words, decimal commas), the delimiters, the
//! fields of a line (trimmed, unquoted, borrowed slices of it), and text shortened for a
//! message.

use std::borrow::Cow;

use super::{SHOWN_CHARS, Separator};

/// A non-blank line after the skipped rows.
pub(super) enum Line<'a> {
    Comment(&'a str),
    Data(&'a str),
}

/// Non-blank lines with their 1-based numbers, the first `skip` lines dropped.
pub(super) fn lines(text: &str, skip: usize) -> impl Iterator<Item = (usize, Line<'_>)> {
    text.split('\n')
        .enumerate()
        .skip(skip)
        .filter_map(|(i, raw)| {
            let trimmed = raw.trim();
            if trimmed.is_empty() {
                None
            } else if trimmed.starts_with('#') || trimmed.starts_with('%') {
                Some((i + 1, Line::Comment(trimmed)))
            } else {
                // Untrimmed: a leading tab is an empty first cell of a tab-separated row.
                Some((i + 1, Line::Data(raw.strip_suffix('\r').unwrap_or(raw))))
            }
        })
}

/// A cell's content.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Cell {
    Value(f64),
    Missing,
    Text,
}

/// Reads a cell: a finite number (decimal point or a single decimal comma), a missing value,
/// or text.
pub(super) fn parse_cell(s: &str) -> Cell {
    if s.is_empty() {
        return Cell::Missing;
    }
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Cell::Value(v),
        Ok(v) if v.is_nan() => Cell::Missing,
        Ok(_) => Cell::Text,
        Err(_) if is_missing_word(s) => Cell::Missing,
        Err(_) if s.contains(',') => parse_decimal_comma(s),
        Err(_) => Cell::Text,
    }
}

fn is_missing_word(s: &str) -> bool {
    ["na", "n/a", "null", "none"]
        .iter()
        .any(|w| s.eq_ignore_ascii_case(w))
}

/// `1,25` as 1.25, through a stack buffer (no allocation).
fn parse_decimal_comma(s: &str) -> Cell {
    let mut buf = [0u8; 64];
    let bytes = s.as_bytes();
    let commas = bytes.iter().filter(|&&b| b == b',').count();
    if commas != 1 || bytes.contains(&b'.') {
        return Cell::Text;
    }
    let Some(out) = buf.get_mut(..bytes.len()) else {
        return Cell::Text;
    };
    for (o, &b) in out.iter_mut().zip(bytes) {
        *o = if b == b',' { b'.' } else { b };
    }
    match std::str::from_utf8(out).map(str::parse::<f64>) {
        Ok(Ok(v)) if v.is_finite() => Cell::Value(v),
        _ => Cell::Text,
    }
}

/// How the cells of a line are separated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Delimiter {
    Char(char),
    Whitespace,
}

/// In order of preference when several split the data equally well.
pub(super) const DELIMITERS: [Delimiter; 4] = [
    Delimiter::Char(';'),
    Delimiter::Char('\t'),
    Delimiter::Char(','),
    Delimiter::Whitespace,
];

impl Delimiter {
    pub(super) fn separator(self) -> Separator {
        match self {
            Delimiter::Char(';') => Separator::Semicolon,
            Delimiter::Char('\t') => Separator::Tab,
            Delimiter::Char(_) => Separator::Comma,
            Delimiter::Whitespace => Separator::Whitespace,
        }
    }
}

/// The cells of a line, trimmed and unquoted, as slices of it.
pub(super) struct Fields<'a> {
    rest: Option<&'a str>,
    delimiter: Delimiter,
}

pub(super) fn fields(line: &str, delimiter: Delimiter) -> Fields<'_> {
    Fields {
        rest: Some(line),
        delimiter,
    }
}

/// A quoted cell's content and what follows the closing quote.
fn split_quoted(s: &str) -> Option<(&str, &str)> {
    let q = s.strip_prefix('"')?;
    Some(match q.find('"') {
        Some(j) => (&q[..j], &q[j + 1..]),
        None => (q, ""),
    })
}

impl<'a> Iterator for Fields<'a> {
    type Item = &'a str;

    fn next(&mut self) -> Option<&'a str> {
        let rest = self.rest?;
        match self.delimiter {
            Delimiter::Whitespace => {
                let s = rest.trim_start();
                if s.is_empty() {
                    self.rest = None;
                    return None;
                }
                let (field, after) = split_quoted(s).unwrap_or_else(|| {
                    let end = s.find(char::is_whitespace).unwrap_or(s.len());
                    s.split_at(end)
                });
                self.rest = Some(after);
                Some(field.trim())
            }
            Delimiter::Char(d) => {
                let s = rest.trim_start_matches(|c: char| c == ' ' || (c == '\t' && d != '\t'));
                if let Some((field, after)) = split_quoted(s) {
                    self.rest = after.find(d).map(|k| &after[k + d.len_utf8()..]);
                    return Some(field.trim());
                }
                Some(match s.find(d) {
                    Some(k) => {
                        self.rest = Some(&s[k + d.len_utf8()..]);
                        s[..k].trim()
                    }
                    None => {
                        self.rest = None;
                        s.trim()
                    }
                })
            }
        }
    }
}

/// Text for a message: at most [`SHOWN_CHARS`] characters, then "…".
pub(super) fn shorten(text: &str) -> Cow<'_, str> {
    match text.char_indices().nth(SHOWN_CHARS) {
        Some((k, _)) => Cow::Owned(format!("{}…", &text[..k])),
        None => Cow::Borrowed(text),
    }
}
