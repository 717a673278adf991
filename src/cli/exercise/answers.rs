//! A class's answers: a CSV with the columns `student,file,cause,structure,kp` (any order,
//! named in its header; separated by commas, or by semicolons with a decimal comma as a
//! Brazilian spreadsheet saves it; a cause may be typed `Dead time` for `dead_time`). Each row becomes an answer or a bad row with its line number and
//! what is wrong with it (a wrong number of fields, an empty field, a gain that is not a
//! number, a record not in the key, a second answer for the same student and record); a
//! bad row is reported, never fatal.

use serde::Serialize;

use super::key::Key;

/// The answers file's columns, in the order their values are kept.
pub const COLUMNS: [&str; 5] = ["student", "file", "cause", "structure", "kp"];

/// One student's answer for one record.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// 1-based line of the file.
    pub line: usize,
    pub student: String,
    pub file: String,
    pub cause: String,
    pub structure: String,
    pub kp: f64,
}

/// What is wrong with a row.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "problem", rename_all = "snake_case")]
pub enum Problem {
    FieldCount { found: usize, expected: usize },
    EmptyField { column: &'static str },
    KpNotANumber { text: String },
    UnknownFile { file: String },
    Duplicate { first_line: usize },
}

/// A row left out, with its line.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BadRow {
    pub line: usize,
    #[serde(flatten)]
    pub problem: Problem,
}

/// The rows read: the answers and the bad rows, in the file's order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Answers {
    pub answers: Vec<Answer>,
    pub bad: Vec<BadRow>,
    /// Data rows (blank lines not counted).
    pub rows: usize,
}

/// The header's fault: the columns it lacks.
#[derive(Debug, Clone, PartialEq)]
pub struct MissingColumns(pub Vec<&'static str>);

/// Reads `text` against `key`.
pub fn read(text: &str, key: &Key) -> Result<Answers, MissingColumns> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty());
    let first = lines.next();
    let sep = match first {
        Some((_, l)) if l.contains(';') && !l.contains(',') => ';',
        _ => ',',
    };
    let header: Vec<String> = first
        .map(|(_, l)| split(l, sep).map(|c| c.to_ascii_lowercase()).collect())
        .unwrap_or_default();
    let positions: Vec<Option<usize>> = COLUMNS
        .iter()
        .map(|c| header.iter().position(|h| h == c))
        .collect();
    let missing: Vec<&'static str> = COLUMNS
        .iter()
        .zip(&positions)
        .filter(|(_, p)| p.is_none())
        .map(|(c, _)| *c)
        .collect();
    if !missing.is_empty() {
        return Err(MissingColumns(missing));
    }
    let positions: Vec<usize> = positions.into_iter().flatten().collect();
    let mut out = Answers::default();
    for (line, text) in lines {
        out.rows += 1;
        match row(line, text, sep, header.len(), &positions, key, &out.answers) {
            Ok(a) => out.answers.push(a),
            Err(problem) => out.bad.push(BadRow { line, problem }),
        }
    }
    Ok(out)
}

fn split(line: &str, sep: char) -> impl Iterator<Item = String> + '_ {
    line.split(sep)
        .map(|f| f.trim().trim_matches('"').trim().to_string())
}

/// A cause as typed (`Dead time`, `dead-time`) in the ids' spelling (`dead_time`).
fn cause_id(text: &str) -> String {
    text.to_ascii_lowercase()
        .split(|c: char| c.is_whitespace() || c == '-' || c == '_')
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("_")
}

/// One data row, checked.
fn row(
    line: usize,
    text: &str,
    sep: char,
    width: usize,
    positions: &[usize],
    key: &Key,
    earlier: &[Answer],
) -> Result<Answer, Problem> {
    let fields: Vec<String> = split(text, sep).collect();
    if fields.len() != width {
        return Err(Problem::FieldCount {
            found: fields.len(),
            expected: width,
        });
    }
    let value = |k: usize| fields[positions[k]].clone();
    if let Some(k) = (0..COLUMNS.len()).find(|&k| value(k).is_empty()) {
        return Err(Problem::EmptyField { column: COLUMNS[k] });
    }
    let kp_text = value(4);
    let number = if sep == ';' {
        kp_text.replace(',', ".")
    } else {
        kp_text.clone()
    };
    let kp = number
        .parse::<f64>()
        .ok()
        .filter(|k| k.is_finite())
        .ok_or(Problem::KpNotANumber { text: kp_text })?;
    let (student, file) = (value(0), value(1));
    if key.record(&file).is_none() {
        return Err(Problem::UnknownFile { file });
    }
    if let Some(first) = earlier
        .iter()
        .find(|a| a.student == student && a.file == file)
    {
        return Err(Problem::Duplicate {
            first_line: first.line,
        });
    }
    Ok(Answer {
        line,
        student,
        file,
        cause: cause_id(&value(2)),
        structure: value(3).to_ascii_uppercase(),
        kp,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::exercise::key::KeyRecord;

    fn key() -> Key {
        let record = KeyRecord {
            file: "record_01.csv".into(),
            causes: vec!["dead_time".into()],
            structure: "P1D".into(),
            kp: 2.0,
            kp_tolerance: 0.1,
        };
        Key::new(1, "clear", vec![record])
    }

    #[test]
    fn a_spreadsheet_s_semicolons_and_decimal_commas_are_read() {
        let text = "Student;File;Cause;Structure;Kp\nana;record_01.csv;Dead time;p1d;2,05\n";
        let a = read(text, &key()).expect("the columns");
        assert!(a.bad.is_empty(), "{:?}", a.bad);
        let first = &a.answers[0];
        assert_eq!(
            (
                first.cause.as_str(),
                first.structure.as_str(),
                first.kp,
                first.line
            ),
            ("dead_time", "P1D", 2.05, 2)
        );
    }

    #[test]
    fn a_header_without_the_columns_is_refused() {
        let missing = read("name,file\n", &key()).expect_err("columns missing");
        assert_eq!(missing.0, vec!["student", "cause", "structure", "kp"]);
    }
}
