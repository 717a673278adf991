//! Barbosa's solved exercise sheet on time responses ("Análise de Sistemas no Domínio dos
//! Tempos", ISEP) as guided exercises: data and logic, no GUI.
//!
//! - [`model`]: exercises, lettered parts, the system each part loads, questions, the
//!   sheet's printed answers and the documented differences (stable string ids).
//! - [`sheet`]: the 13 exercises, one file each; every expected answer is computed by
//!   `degrau-lti` (exact step responses, StepInfo, poles, loops, error constants, the
//!   second-order formulas), never typed in from the sheet, and each part's worked solution.
//! - [`check`]: a student's answer against Degrau's, within the question's tolerance.
//! - [`input`] and [`expr`]: reading what a student types (numbers with a decimal comma or
//!   point, units, `inf`; transfer functions; ranges; regions; roots; closed forms).
//! - [`text`] and [`words`]: both languages.

pub mod check;
pub mod expr;
pub mod input;
pub mod model;
pub mod sheet;
pub mod text;
pub mod words;

pub use check::{Verdict, check, typed_answer};
pub use degrau_words::Lang;
pub use input::StudentAnswer;
pub use model::{
    AnswerKind, Choice, Controller, Exercise, Expected, GainRange, Mode, Part, Question, Reading,
    Region, System, TfAnswer, Tolerance, Unit, Value,
};
pub use sheet::{SheetError, sheet};
pub use text::Text;

/// One step of a worked solution: a line of words and numbers in one language.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Step {
    pub line: String,
}

/// The worked solution of `part`, step by step, in `lang`.
pub fn solution(part: &Part, lang: Lang) -> Vec<Step> {
    part.solution
        .iter()
        .map(|t| Step {
            line: t.get(lang).to_string(),
        })
        .collect()
}

/// The part with this id (`"8b"`) in a sheet.
pub fn find_part<'a>(sheet: &'a [Exercise], id: &str) -> Option<&'a Part> {
    sheet
        .iter()
        .flat_map(|e| e.parts.iter())
        .find(|p| p.id == id)
}

/// The question with this id (`"8b.K"`) in a sheet.
pub fn find_question<'a>(sheet: &'a [Exercise], id: &str) -> Option<&'a Question> {
    sheet
        .iter()
        .flat_map(|e| e.parts.iter())
        .flat_map(|p| p.questions.iter())
        .find(|q| q.id == id)
}
