//! Grading a class against the key: per student and record, whether the cause (any of the
//! key's), the final structure and the gain (within the key's relative tolerance) are
//! right; the records a student left out; and a summary per cause over the class.

use serde::Serialize;

use crate::ident::challenge::Grade;

use super::answers::{Answer, Answers, BadRow};
use super::key::Key;

/// One graded answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Graded {
    pub file: String,
    pub line: usize,
    pub cause: bool,
    pub structure: bool,
    pub kp: bool,
}

/// A student's answers, graded, in the key's order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Student {
    pub student: String,
    pub answers: Vec<Graded>,
    /// The key's records the student did not answer.
    pub missing: Vec<String>,
    pub cause_right: usize,
    pub structure_right: usize,
    pub kp_right: usize,
}

/// The class on the records of one set of causes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CauseSummary {
    /// The key's causes, `/`-joined.
    pub causes: String,
    pub records: usize,
    pub answers: usize,
    pub cause_right: usize,
    pub structure_right: usize,
    pub kp_right: usize,
}

/// The class graded.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Grading {
    pub records: usize,
    pub rows: usize,
    pub graded: usize,
    pub students: Vec<Student>,
    pub causes: Vec<CauseSummary>,
    pub bad_rows: Vec<BadRow>,
}

/// Grades `answers` against `key`.
pub fn grade(key: &Key, answers: &Answers) -> Grading {
    let mut names: Vec<&str> = Vec::new();
    for a in &answers.answers {
        if !names.contains(&a.student.as_str()) {
            names.push(&a.student);
        }
    }
    let graded: Vec<(&Answer, Graded)> = answers
        .answers
        .iter()
        .filter_map(|a| Some((a, one(key, a)?)))
        .collect();
    let students = names
        .iter()
        .map(|&name| student(key, name, &graded))
        .collect();
    Grading {
        records: key.records.len(),
        rows: answers.rows,
        graded: graded.len(),
        students,
        causes: summary(key, &graded),
        bad_rows: answers.bad.clone(),
    }
}

fn one(key: &Key, a: &Answer) -> Option<Graded> {
    let r = key.record(&a.file)?;
    let g = Grade::of(
        &r.causes,
        &r.structure,
        r.kp,
        r.kp_tolerance,
        (&a.cause, &a.structure, a.kp),
    );
    Some(Graded {
        file: a.file.clone(),
        line: a.line,
        cause: g.cause,
        structure: g.structure,
        kp: g.kp,
    })
}

fn student(key: &Key, name: &str, graded: &[(&Answer, Graded)]) -> Student {
    let mine: Vec<&Graded> = key
        .records
        .iter()
        .filter_map(|r| {
            graded
                .iter()
                .find(|(a, g)| a.student == name && g.file == r.file)
                .map(|(_, g)| g)
        })
        .collect();
    let missing = key
        .records
        .iter()
        .filter(|r| !mine.iter().any(|g| g.file == r.file))
        .map(|r| r.file.clone())
        .collect();
    Student {
        student: name.to_string(),
        cause_right: mine.iter().filter(|g| g.cause).count(),
        structure_right: mine.iter().filter(|g| g.structure).count(),
        kp_right: mine.iter().filter(|g| g.kp).count(),
        answers: mine.into_iter().cloned().collect(),
        missing,
    }
}

fn summary(key: &Key, graded: &[(&Answer, Graded)]) -> Vec<CauseSummary> {
    let mut out: Vec<CauseSummary> = Vec::new();
    for r in &key.records {
        let label = r.label();
        let k = match out.iter().position(|s| s.causes == label) {
            Some(k) => k,
            None => {
                out.push(CauseSummary {
                    causes: label,
                    records: 0,
                    answers: 0,
                    cause_right: 0,
                    structure_right: 0,
                    kp_right: 0,
                });
                out.len() - 1
            }
        };
        let s = &mut out[k];
        s.records += 1;
        for (_, g) in graded.iter().filter(|(_, g)| g.file == r.file) {
            s.answers += 1;
            s.cause_right += usize::from(g.cause);
            s.structure_right += usize::from(g.structure);
            s.kp_right += usize::from(g.kp);
        }
    }
    out
}
