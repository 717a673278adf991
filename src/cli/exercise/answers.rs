//! A class's answers: a CSV with the columns `student,file,cause,structure,kp` (any order,
//! named in its header). Each row becomes an answer or a bad row with its line number and
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
    let header: Vec<String> = lines
        .next()
        .map(|(_, l)| split(l).map(|c| c.to_ascii_lowercase()).collect())
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
        match row(line, text, header.len(), &positions, key, &out.answers) {
            Ok(a) => out.answers.push(a),
            Err(problem) => out.bad.push(BadRow { line, problem }),
        }
    }
    Ok(out)
}

fn split(line: &str) -> impl Iterator<Item = String> + '_ {
    line.split(',')
        .map(|f| f.trim().trim_matches('"').trim().to_string())
}

/// One data row, checked.
fn row(
    line: usize,
    text: &str,
    width: usize,
    positions: &[usize],
    key: &Key,
    earlier: &[Answer],
) -> Result<Answer, Problem> {
    let fields: Vec<String> = split(text).collect();
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
    let kp = kp_text
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
        cause: value(2).to_ascii_lowercase(),
        structure: value(3).to_ascii_uppercase(),
        kp,
    })
}
