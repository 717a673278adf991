//! The Exercises mode's session: what it keeps between runs ([`Saved`]: the part open, and
//! per question the last answer typed and whether its last Check was right), the sheet
//! (built once, by the exercise crate), the verdicts of the last Check and which parts show
//! their worked solution. No egui here: the views read a session and return [`Command`]s,
//! and [`Session::apply`] is the only place anything changes.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use degrau_exercise::{Exercise, Part, SheetError, StudentAnswer, Verdict, check, sheet};

use super::challenges::{Board, Kept};
use super::commands::{ChallengeCommand, Command, Outcome};
use super::load::{self, LoadProblem};

/// The part open at first.
pub const FIRST_PART: &str = "1a";

/// What the Exercises mode keeps between runs (the state file's `exercises`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    /// The id of the part open (`"8b"`).
    pub part: String,
    /// Per question id (`"8b.K"`): the last answer typed and its last Check.
    pub answers: BTreeMap<String, Answer>,
    /// The Challenges' seed, level, the challenge handed out and its answers.
    pub challenges: Kept,
}

impl Default for Saved {
    fn default() -> Self {
        Self {
            part: FIRST_PART.into(),
            answers: BTreeMap::new(),
            challenges: Kept::default(),
        }
    }
}

/// A student's answer to one question.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Answer {
    pub text: String,
    /// Whether the last Check of this text found it right (`None`: not checked since typed).
    pub right: Option<bool>,
}

/// How far a student got with a part (the mark in the list).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Progress {
    NotTried,
    /// Some answers checked right, none wrong, some not checked yet.
    Started,
    Right,
    Wrong,
}

/// The mode's session.
#[derive(Debug, Default)]
pub struct Session {
    /// The verdicts of the last Check, per question id.
    verdicts: HashMap<String, Verdict>,
    /// The parts whose worked solution is shown.
    solutions: HashSet<String>,
    /// The part whose system could not be loaded, and why.
    pub load_problem: Option<(String, LoadProblem)>,
    /// The Challenges: the challenge drawn (or being drawn) and its last Check.
    pub board: Board,
}

impl Session {
    /// The session of a restored state: each answer that had been checked is checked
    /// again (its verdict shown as before the restart, its mark brought up to date).
    pub fn restored(kept: &mut Saved) -> Self {
        let mut session = Self {
            board: Board::restored(&mut kept.challenges),
            ..Self::default()
        };
        let checked: Vec<String> = kept
            .answers
            .iter()
            .filter(|(_, a)| a.right.is_some())
            .map(|(id, _)| id.clone())
            .collect();
        if checked.is_empty() {
            return session;
        }
        let Ok(sheet) = session.sheet() else {
            return session;
        };
        for id in checked {
            let (Some(q), Some(answer)) = (
                degrau_exercise::find_question(sheet, &id),
                kept.answers.get_mut(&id),
            ) else {
                continue;
            };
            let verdict = check(q, &StudentAnswer::Text(answer.text.trim().to_string()));
            answer.right = Some(verdict.right);
            session.verdicts.insert(id, verdict);
        }
        session
    }

    /// The sheet, or why it could not be built.
    pub fn sheet(&self) -> Result<&'static [Exercise], &'static SheetError> {
        the_sheet()
    }

    /// The part with this id.
    pub fn part(&self, id: &str) -> Option<&Part> {
        degrau_exercise::find_part(self.sheet().ok()?, id)
    }

    /// The verdict of the last Check of this question.
    pub fn verdict(&self, question: &str) -> Option<&Verdict> {
        self.verdicts.get(question)
    }

    /// Whether the part shows its worked solution.
    pub fn solution_shown(&self, part: &str) -> bool {
        self.solutions.contains(part)
    }

    /// Drops what names no part or question of the sheet (a state file from another
    /// version), and opens the first part when the one kept is unknown.
    pub fn sync(&self, kept: &mut Saved) {
        let Ok(sheet) = self.sheet() else {
            return;
        };
        prune(kept, sheet);
    }

    /// Carries out one command; returns what it asks of the app.
    pub fn apply(&mut self, kept: &mut Saved, command: Command) -> Option<Outcome> {
        match command {
            Command::Select(part) => {
                if self.part(&part).is_some() {
                    kept.part = part;
                    kept.challenges.open = false;
                }
            }
            Command::Type { question, text } => self.type_answer(kept, question, text),
            Command::Check(part) => self.check_part(kept, &part),
            Command::Challenge(ChallengeCommand::OpenRecord) => {
                return self.board.csv().map(Outcome::Record);
            }
            Command::Challenge(c) => self.board.apply(&mut kept.challenges, c),
            Command::ShowSolution(part, shown) => {
                if shown {
                    self.solutions.insert(part);
                } else {
                    self.solutions.remove(&part);
                }
            }
            Command::OpenInDesign(id) => {
                let part = self.part(&id)?;
                match load::design_load(&part.system) {
                    Ok(load) => {
                        self.load_problem = None;
                        return Some(Outcome::Load(Box::new(load)));
                    }
                    Err(problem) => self.load_problem = Some((id, problem)),
                }
            }
        }
        None
    }

    /// A new text for a question: its last Check no longer stands.
    fn type_answer(&mut self, kept: &mut Saved, question: String, text: String) {
        let known = self
            .sheet()
            .is_ok_and(|s| degrau_exercise::find_question(s, &question).is_some());
        if !known {
            return;
        }
        self.verdicts.remove(&question);
        let answer = kept.answers.entry(question).or_default();
        if answer.text != text {
            answer.text = text;
            answer.right = None;
        }
    }

    /// Checks every answer typed in the part; a wrong one opens the worked solution.
    fn check_part(&mut self, kept: &mut Saved, id: &str) {
        let Some(part) = self.part(id) else {
            return;
        };
        let mut verdicts = Vec::new();
        for q in &part.questions {
            let typed = kept.answers.get(&q.id).map(|a| a.text.trim().to_string());
            let verdict = typed
                .filter(|t| !t.is_empty())
                .map(|text| check(q, &StudentAnswer::Text(text)));
            verdicts.push((q.id.clone(), verdict));
        }
        let mut any_wrong = false;
        for (question, verdict) in verdicts {
            match verdict {
                Some(v) => {
                    any_wrong |= !v.right;
                    if let Some(a) = kept.answers.get_mut(&question) {
                        a.right = Some(v.right);
                    }
                    self.verdicts.insert(question, v);
                }
                None => {
                    self.verdicts.remove(&question);
                }
            }
        }
        if any_wrong {
            self.solutions.insert(id.to_string());
        }
    }
}

/// The sheet, built once for the whole run (its answers are computed), or why it could not
/// be built.
pub fn the_sheet() -> Result<&'static [Exercise], &'static SheetError> {
    static SHEET: OnceLock<Result<Vec<Exercise>, SheetError>> = OnceLock::new();
    SHEET.get_or_init(sheet).as_deref()
}

/// The part's progress from the answers kept.
pub fn progress(part: &Part, kept: &Saved) -> Progress {
    let marks: Vec<Option<bool>> = part
        .questions
        .iter()
        .map(|q| kept.answers.get(&q.id).and_then(|a| a.right))
        .collect();
    if marks.contains(&Some(false)) {
        Progress::Wrong
    } else if marks.iter().all(|m| *m == Some(true)) {
        Progress::Right
    } else if marks.contains(&Some(true)) {
        Progress::Started
    } else {
        Progress::NotTried
    }
}

/// Drops the answers whose question is not in `sheet` and a challenge's cause that is no
/// cause id; an unknown part opens the first.
pub fn prune(kept: &mut Saved, sheet: &[Exercise]) {
    if let Some(c) = kept.challenges.current.as_mut()
        && !c.cause.is_empty()
        && super::challenges::Named::of_id(&c.cause).is_none()
    {
        c.cause.clear();
        c.checked = false;
    }
    kept.answers
        .retain(|id, _| degrau_exercise::find_question(sheet, id).is_some());
    if degrau_exercise::find_part(sheet, &kept.part).is_none() {
        kept.part = sheet
            .first()
            .and_then(|e| e.parts.first())
            .map_or_else(|| FIRST_PART.to_string(), |p| p.id.clone());
    }
}
