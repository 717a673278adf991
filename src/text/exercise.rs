//! The words of `degrau exercise`: what `make` wrote, the grading of a class (per student,
//! per record, per cause, the bad rows by line) and the errors, in English and Brazilian
//! Portuguese (causa, estrutura, ganho estático).

#[cfg(test)]
use super::Message;
use super::{Lang, Localize};
use crate::cli::exercise::ExerciseError;
use crate::cli::exercise::answers::{BadRow, Problem};
use crate::cli::exercise::grade::{CauseSummary, Grading, Student};

/// A line of `degrau exercise`'s text.
#[derive(Debug, Clone, PartialEq)]
pub enum Line {
    /// `make` wrote `count` records and the key into `dir`.
    Made {
        count: usize,
        dir: String,
        seed: u64,
        level: String,
    },
    /// The class's head line.
    Class {
        records: usize,
        rows: usize,
        graded: usize,
        bad: usize,
    },
    BadRowsHeading,
    StudentsHeading,
    CausesHeading,
    /// A student's totals.
    Student {
        name: String,
        answered: usize,
        records: usize,
        cause: usize,
        structure: usize,
        kp: usize,
    },
    /// One graded answer.
    Answer {
        file: String,
        cause: bool,
        structure: bool,
        kp: bool,
    },
    /// The records a student did not answer.
    Missing(Vec<String>),
    /// The class on one set of causes.
    Cause {
        causes: String,
        records: usize,
        answers: usize,
        cause: usize,
        structure: usize,
        kp: usize,
    },
}

fn mark(right: bool) -> &'static str {
    if right { "✓" } else { "✗" }
}

impl Localize for Line {
    fn text(&self, lang: Lang) -> String {
        match self {
            Line::Made {
                count,
                dir,
                seed,
                level,
            } => lang.pick(
                format!(
                    "Wrote {count} records and key.json to {dir} (seed {seed}, level {level}); fit each from P1"
                ),
                format!(
                    "Gravados {count} registros e key.json em {dir} (semente {seed}, nível {level}); ajuste cada um a partir de P1"
                ),
            ),
            Line::Class {
                records,
                rows,
                graded,
                bad,
            } => lang.pick(
                format!("Key: {records} records; answers: {rows} rows, {graded} graded, {bad} bad"),
                format!(
                    "Gabarito: {records} registros; respostas: {rows} linhas, {graded} corrigidas, {bad} com erro"
                ),
            ),
            Line::BadRowsHeading => lang.pick("Rows left out:", "Linhas deixadas de fora:").into(),
            Line::StudentsHeading => lang.pick("Students:", "Alunos:").into(),
            Line::CausesHeading => lang.pick("Per cause:", "Por causa:").into(),
            Line::Student {
                name,
                answered,
                records,
                cause,
                structure,
                kp,
            } => lang.pick(
                format!(
                    "{name}: {answered} of {records} answered; cause {cause}, structure {structure}, gain {kp} right"
                ),
                format!(
                    "{name}: {answered} de {records} respondidos; causa {cause}, estrutura {structure}, ganho {kp} certos"
                ),
            ),
            Line::Answer {
                file,
                cause,
                structure,
                kp,
            } => {
                let (c, s, k) = (mark(*cause), mark(*structure), mark(*kp));
                lang.pick(
                    format!("{file}: cause {c}, structure {s}, gain {k}"),
                    format!("{file}: causa {c}, estrutura {s}, ganho {k}"),
                )
            }
            Line::Missing(files) => {
                let list = files.join(", ");
                lang.pick(
                    format!("not answered: {list}"),
                    format!("sem resposta: {list}"),
                )
            }
            Line::Cause {
                causes,
                records,
                answers,
                cause,
                structure,
                kp,
            } => lang.pick(
                format!(
                    "{causes}: {records} records, {answers} answers; cause {cause}, structure {structure}, gain {kp} right"
                ),
                format!(
                    "{causes}: {records} registros, {answers} respostas; causa {cause}, estrutura {structure}, ganho {kp} certos"
                ),
            ),
        }
    }
}

impl Localize for BadRow {
    fn text(&self, lang: Lang) -> String {
        let line = self.line;
        let what = match &self.problem {
            Problem::FieldCount { found, expected } => lang.pick(
                format!("{found} fields, {expected} expected"),
                format!("{found} campos, {expected} esperados"),
            ),
            Problem::EmptyField { column } => lang.pick(
                format!("the {column} field is empty"),
                format!("o campo {column} está vazio"),
            ),
            Problem::KpNotANumber { text } => lang.pick(
                format!("the gain \"{text}\" is not a number"),
                format!("o ganho \"{text}\" não é um número"),
            ),
            Problem::UnknownFile { file } => lang.pick(
                format!("the record \"{file}\" is not in the key"),
                format!("o registro \"{file}\" não está no gabarito"),
            ),
            Problem::Duplicate { first_line } => lang.pick(
                format!("a second answer of this student for this record (the first on line {first_line} counts)"),
                format!("uma segunda resposta deste aluno para este registro (vale a da linha {first_line})"),
            ),
        };
        lang.pick(
            format!("line {line}: {what}"),
            format!("linha {line}: {what}"),
        )
    }
}

impl Localize for ExerciseError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ExerciseError::Read { path, source } => lang.pick(
                format!("cannot read {path}: {source}"),
                format!("não foi possível ler {path}: {source}"),
            ),
            ExerciseError::Write { path, source } => lang.pick(
                format!("cannot write {path}: {source}"),
                format!("não foi possível gravar {path}: {source}"),
            ),
            ExerciseError::Key { path, reason } => lang.pick(
                format!("{path} is not an exercise key: {reason}"),
                format!("{path} não é um gabarito de exercícios: {reason}"),
            ),
            ExerciseError::Columns { path, missing } => {
                let list = missing.join(", ");
                lang.pick(
                    format!(
                        "{path}: the header lacks the columns {list} (expected student,file,cause,structure,kp)"
                    ),
                    format!(
                        "{path}: o cabeçalho não tem as colunas {list} (esperadas student,file,cause,structure,kp)"
                    ),
                )
            }
            ExerciseError::Cli(e) => e.text(lang),
        }
    }
}

fn student_lines(s: &Student, records: usize) -> Vec<Line> {
    let mut lines = vec![Line::Student {
        name: s.student.clone(),
        answered: s.answers.len(),
        records,
        cause: s.cause_right,
        structure: s.structure_right,
        kp: s.kp_right,
    }];
    lines.extend(s.answers.iter().map(|g| Line::Answer {
        file: g.file.clone(),
        cause: g.cause,
        structure: g.structure,
        kp: g.kp,
    }));
    if !s.missing.is_empty() {
        lines.push(Line::Missing(s.missing.clone()));
    }
    lines
}

fn cause_line(c: &CauseSummary) -> Line {
    Line::Cause {
        causes: c.causes.clone(),
        records: c.records,
        answers: c.answers,
        cause: c.cause_right,
        structure: c.structure_right,
        kp: c.kp_right,
    }
}

/// The grading as text: the class, the rows left out by line, each student (their answers
/// indented), and the summary per cause.
pub fn grading_text(g: &Grading, lang: Lang) -> String {
    let mut out = vec![
        Line::Class {
            records: g.records,
            rows: g.rows,
            graded: g.graded,
            bad: g.bad_rows.len(),
        }
        .text(lang),
    ];
    if !g.bad_rows.is_empty() {
        out.push(Line::BadRowsHeading.text(lang));
        out.extend(g.bad_rows.iter().map(|b| format!("  {}", b.text(lang))));
    }
    out.push(Line::StudentsHeading.text(lang));
    for s in &g.students {
        for (k, line) in student_lines(s, g.records).iter().enumerate() {
            let indent = if k == 0 { "  " } else { "    " };
            out.push(format!("{indent}{}", line.text(lang)));
        }
    }
    out.push(Line::CausesHeading.text(lang));
    out.extend(
        g.causes
            .iter()
            .map(|c| format!("  {}", cause_line(c).text(lang))),
    );
    out.join("\n")
}

/// An example of every line, bad row and error.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let lines = [
        Line::Made {
            count: 3,
            dir: "lab".into(),
            seed: 7,
            level: "moderate".into(),
        },
        Line::Class {
            records: 3,
            rows: 10,
            graded: 8,
            bad: 2,
        },
        Line::BadRowsHeading,
        Line::StudentsHeading,
        Line::CausesHeading,
        Line::Student {
            name: "ana".into(),
            answered: 2,
            records: 3,
            cause: 2,
            structure: 1,
            kp: 1,
        },
        Line::Answer {
            file: "record_01.csv".into(),
            cause: true,
            structure: false,
            kp: true,
        },
        Line::Missing(vec!["record_03.csv".into()]),
        Line::Cause {
            causes: "dead_time".into(),
            records: 1,
            answers: 4,
            cause: 3,
            structure: 2,
            kp: 4,
        },
    ];
    let problems = [
        Problem::FieldCount {
            found: 4,
            expected: 5,
        },
        Problem::EmptyField { column: "kp" },
        Problem::KpNotANumber {
            text: "1.2.3".into(),
        },
        Problem::UnknownFile {
            file: "record_99.csv".into(),
        },
        Problem::Duplicate { first_line: 3 },
    ];
    let errors = [
        ExerciseError::Read {
            path: "key.json".into(),
            source: std::io::Error::from(std::io::ErrorKind::NotFound),
        },
        ExerciseError::Write {
            path: "lab".into(),
            source: std::io::Error::from(std::io::ErrorKind::PermissionDenied),
        },
        ExerciseError::Key {
            path: "key.json".into(),
            reason: "expected value at line 1 column 1".into(),
        },
        ExerciseError::Columns {
            path: "class.csv".into(),
            missing: vec!["kp".into()],
        },
    ];
    let mut all: Vec<Message> = lines
        .iter()
        .map(|l| Message::of(format!("exercise::{l:?}"), l))
        .collect();
    all.extend(problems.into_iter().map(|problem| {
        let row = BadRow { line: 4, problem };
        Message::of(format!("exercise::{row:?}"), &row)
    }));
    all.extend(
        errors
            .iter()
            .map(|e| Message::of(format!("exercise::{e:?}"), e)),
    );
    all
}
