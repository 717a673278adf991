//! The Challenges of the Exercises mode (issue 27, item 2): a record drawn from a process
//! with a hidden effect ([`degrau_ident::challenge`]), drawn off the UI thread, the
//! student's answers (cause, final structure, static gain), their Check against the hidden
//! truth ([`Grade::of`], the grading the CLI's class check uses), the evidence the diagnosis
//! gives for the true cause, and Degrau's own diagnosis, offered only after Check. No egui
//! here: [`Board::apply`] is the only place anything changes.

use serde::{Deserialize, Serialize};

use degrau_ident::challenge::{
    Challenge, GENERATOR_VERSION, Grade, Level, challenge_until, diagnosis,
};
use degrau_ident::diagnose::test_causes::TestCauseKind;
use degrau_ident::diagnose::{Cause, DiagnoseReport};

use crate::field::{FieldError, parse_number};
use crate::job::{Job, Waker};

/// A cause a student can name: what the model lacks, or what the test got wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Named {
    Model(Cause),
    Test(TestCauseKind),
}

impl Named {
    /// Its identifier, as the key and `degrau diagnose` write it.
    pub fn id(self) -> &'static str {
        match self {
            Named::Model(c) => c.id(),
            Named::Test(k) => k.id(),
        }
    }

    /// The one of `id`, if any.
    pub fn of_id(id: &str) -> Option<Named> {
        ANSWERS.into_iter().find(|n| n.id() == id)
    }
}

/// The causes a student can name, in the combo's order: the model's, the test's, `none`
/// last.
pub const ANSWERS: [Named; 20] = [
    Named::Model(Cause::DeadTime),
    Named::Model(Cause::ExtraPole),
    Named::Model(Cause::Oscillation),
    Named::Model(Cause::Zero),
    Named::Model(Cause::InverseResponse),
    Named::Model(Cause::Integrator),
    Named::Model(Cause::Drift),
    Named::Model(Cause::Offset),
    Named::Test(TestCauseKind::Outliers),
    Named::Test(TestCauseKind::Quantisation),
    Named::Test(TestCauseKind::Disturbance),
    Named::Test(TestCauseKind::Saturation),
    Named::Test(TestCauseKind::NotAtRest),
    Named::Test(TestCauseKind::ImperfectStep),
    Named::Test(TestCauseKind::Nonlinearity),
    Named::Test(TestCauseKind::Sampling),
    Named::Test(TestCauseKind::SmallStep),
    Named::Test(TestCauseKind::ColouredNoise),
    Named::Test(TestCauseKind::ClosedLoop),
    Named::Model(Cause::None),
];

/// What the Challenges keep between runs (the state file's `exercises.challenges`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Kept {
    /// This install's seed (drawn at the first challenge).
    pub seed: Option<u64>,
    /// The level the next challenge is drawn at.
    pub level: Level,
    /// The index of the next challenge.
    pub next: usize,
    /// Whether the centre shows the challenge (not a part of the sheet).
    pub open: bool,
    /// The challenge handed out and the student's answers.
    pub current: Option<Current>,
}

impl Default for Kept {
    fn default() -> Self {
        Self {
            seed: None,
            level: Level::Moderate,
            next: 0,
            open: false,
            current: None,
        }
    }
}

/// The challenge handed out (re-drawn from its seed, index and level on restore) and the
/// student's last answers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Current {
    pub seed: u64,
    pub index: usize,
    pub level: Level,
    /// A cause id (`dead_time`, …, `none`), or empty.
    #[serde(default)]
    pub cause: String,
    #[serde(default)]
    pub structure: String,
    #[serde(default)]
    pub kp: String,
    /// Whether the answers were checked (the verdicts shown again on restore).
    #[serde(default)]
    pub checked: bool,
    /// The challenge generator's version that drew it ([`GENERATOR_VERSION`]; 0: an
    /// earlier one, which did not write it). Another version draws another record from
    /// the same seed, so a restore by it says so.
    #[serde(default)]
    pub generator_version: u32,
}

/// One answer field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    Cause,
    Structure,
    Kp,
}

/// A challenge drawn, with Degrau's diagnosis of its record.
#[derive(Debug, Clone)]
pub struct Drawn {
    pub seed: u64,
    pub index: usize,
    pub level: Level,
    pub challenge: Challenge,
    pub report: Option<DiagnoseReport>,
}

/// The last Check: each answer right or not, and why the gain could not be read.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked {
    pub grade: Grade,
    pub kp_problem: Option<FieldError>,
}

/// What the Challenges hold while the app runs.
#[derive(Default)]
pub struct Board {
    job: Option<Job<(), Option<Drawn>>>,
    waker: Option<Waker>,
    pub drawn: Option<Drawn>,
    pub checked: Option<Checked>,
    pub diagnosis_shown: bool,
    /// The challenge kept was drawn by another generator version (this one's number was
    /// written in its place): its record may differ from the one the student saw.
    pub drawn_again: bool,
}

impl std::fmt::Debug for Board {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Board")
            .field("drawing", &self.job.is_some())
            .field("drawn", &self.drawn)
            .field("checked", &self.checked)
            .finish()
    }
}

impl Board {
    /// The board of a restored state: the challenge kept is drawn again (deterministic
    /// within one generator version; one drawn by another is marked [`Board::drawn_again`]
    /// and from now on kept as this version's).
    pub fn restored(kept: &mut Kept) -> Self {
        let mut board = Self::default();
        if let Some(c) = kept.current.as_mut() {
            board.drawn_again = c.generator_version != GENERATOR_VERSION;
            c.generator_version = GENERATOR_VERSION;
            board.draw(c.seed, c.index, c.level);
        }
        board
    }

    /// Whether a challenge is being drawn.
    pub fn drawing(&self) -> bool {
        self.job.is_some()
    }

    pub fn has_waker(&self) -> bool {
        self.waker.is_some()
    }

    pub fn set_waker(&mut self, waker: Waker) {
        self.waker = Some(waker);
    }

    /// Takes in a challenge drawn; true when one arrived.
    pub fn poll(&mut self, kept: &mut Kept) -> bool {
        let Some(drawn) = self.job.as_mut().and_then(Job::poll) else {
            return false;
        };
        self.job = None;
        let Some(drawn) = drawn else {
            return false;
        };
        self.drawn = Some(drawn);
        self.checked = None;
        self.diagnosis_shown = false;
        if kept.current.as_ref().is_some_and(|c| c.checked) {
            self.check(kept);
        }
        true
    }

    /// Carries out one command of the Challenges.
    pub fn apply(&mut self, kept: &mut Kept, command: super::ChallengeCommand) {
        use super::ChallengeCommand as C;
        match command {
            C::Open => kept.open = true,
            C::SetLevel(level) => kept.level = level,
            C::New => {
                let seed = *kept.seed.get_or_insert_with(fresh_seed);
                let index = kept.next;
                kept.next += 1;
                kept.open = true;
                kept.current = Some(Current {
                    seed,
                    index,
                    level: kept.level,
                    cause: String::new(),
                    structure: String::new(),
                    kp: String::new(),
                    checked: false,
                    generator_version: GENERATOR_VERSION,
                });
                self.drawn = None;
                self.checked = None;
                self.diagnosis_shown = false;
                self.drawn_again = false;
                self.draw(seed, index, kept.level);
            }
            C::Cancel => {
                if let Some(job) = self.job.take() {
                    job.cancel();
                }
                kept.current = None;
            }
            C::Type(field, text) => {
                if let Some(c) = kept.current.as_mut() {
                    let slot = match field {
                        Field::Cause => &mut c.cause,
                        Field::Structure => &mut c.structure,
                        Field::Kp => &mut c.kp,
                    };
                    if *slot != text {
                        *slot = text;
                        c.checked = false;
                        self.checked = None;
                    }
                }
            }
            C::Check => self.check(kept),
            C::ShowDiagnosis => self.diagnosis_shown = self.checked.is_some(),
            // The session hands the record to the app.
            C::OpenRecord => {}
        }
    }

    /// Grades the answers kept against the challenge drawn.
    fn check(&mut self, kept: &mut Kept) {
        let (Some(c), Some(d)) = (kept.current.as_mut(), self.drawn.as_ref()) else {
            return;
        };
        let key = &d.challenge;
        let kp = parse_number(&c.kp);
        let grade = Grade::of(
            &key.causes,
            &key.structure,
            key.kp,
            key.kp_tolerance,
            (&c.cause, &c.structure, *kp.as_ref().unwrap_or(&f64::NAN)),
        );
        c.checked = true;
        self.checked = Some(Checked {
            grade,
            kp_problem: kp.err(),
        });
    }

    /// The CSV of the challenge drawn.
    pub fn csv(&self) -> Option<String> {
        self.drawn.as_ref().map(|d| d.challenge.csv())
    }

    /// Draws the challenge off the UI thread; a cancelled job ends at its next draw and
    /// hands back nothing.
    fn draw(&mut self, seed: u64, index: usize, level: Level) {
        self.job = Some(Job::spawn(self.waker.clone(), move |ctx| {
            let challenge = challenge_until(seed, index, level, &|| ctx.cancelled())?;
            let report = (!ctx.cancelled())
                .then(|| diagnosis(&challenge.csv()))
                .flatten();
            Some(Drawn {
                seed,
                index,
                level,
                challenge,
                report,
            })
        }));
    }
}

/// A seed for this install: the clock's nanoseconds.
fn fresh_seed() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(27, |d| d.as_nanos() as u64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exercises::ChallengeCommand as C;

    /// A board with a challenge drawn (its first draw, unchecked: no diagnosis run).
    fn board() -> (Board, Kept, Challenge) {
        let key = degrau_ident::challenge::draw(3, 0, 0, Level::Clear, None);
        let kept = Kept {
            current: Some(Current {
                seed: 3,
                index: 0,
                level: Level::Clear,
                cause: String::new(),
                structure: String::new(),
                kp: String::new(),
                checked: false,
                generator_version: GENERATOR_VERSION,
            }),
            ..Kept::default()
        };
        let board = Board {
            drawn: Some(Drawn {
                seed: 3,
                index: 0,
                level: Level::Clear,
                challenge: key.clone(),
                report: None,
            }),
            ..Board::default()
        };
        (board, kept, key)
    }

    #[test]
    fn the_keys_answers_are_right_and_a_retyped_one_unchecked() {
        let (mut b, mut kept, key) = board();
        let cause = key.causes.first().cloned().unwrap_or_else(|| "none".into());
        b.apply(&mut kept, C::ShowDiagnosis);
        assert!(!b.diagnosis_shown, "the diagnosis before Check");
        b.apply(&mut kept, C::Type(Field::Cause, cause));
        b.apply(
            &mut kept,
            C::Type(Field::Structure, key.structure.to_lowercase()),
        );
        let kp = format!("{:.6}", key.kp).replace('.', ",");
        b.apply(&mut kept, C::Type(Field::Kp, kp));
        b.apply(&mut kept, C::Check);
        let checked = b.checked.clone().expect("checked");
        assert!(checked.grade.all(), "{checked:?}");
        assert!(kept.current.as_ref().is_some_and(|c| c.checked));
        b.apply(&mut kept, C::ShowDiagnosis);
        assert!(b.diagnosis_shown);
        b.apply(&mut kept, C::Type(Field::Kp, "abc".into()));
        assert!(b.checked.is_none());
        assert!(kept.current.as_ref().is_some_and(|c| !c.checked));
        b.apply(&mut kept, C::Check);
        let checked = b.checked.clone().expect("checked");
        assert!(!checked.grade.kp);
        assert!(matches!(
            checked.kp_problem,
            Some(FieldError::NotANumber { .. })
        ));
    }

    #[test]
    fn a_challenge_of_another_generator_version_is_drawn_again_and_said_so() {
        let (_, mut kept, _) = board();
        let fresh = Board::restored(&mut kept);
        assert!(!fresh.drawn_again, "this version's own challenge");
        // A state written before the version was kept reads as version 0.
        let mut json = serde_json::to_value(&kept).unwrap();
        json["current"]
            .as_object_mut()
            .unwrap()
            .remove("generator_version");
        let mut old: Kept = serde_json::from_value(json).unwrap();
        assert_eq!(old.current.as_ref().unwrap().generator_version, 0);
        let again = Board::restored(&mut old);
        assert!(again.drawn_again);
        assert_eq!(
            old.current.as_ref().unwrap().generator_version,
            GENERATOR_VERSION
        );
        // Once kept as this version's, the next restore says nothing.
        assert!(!Board::restored(&mut old).drawn_again);
    }

    #[test]
    fn a_cancelled_draw_leaves_no_challenge() {
        let mut b = Board::default();
        let mut kept = Kept {
            seed: Some(3),
            ..Kept::default()
        };
        b.apply(&mut kept, C::New);
        assert!(b.drawing());
        assert_eq!(kept.next, 1);
        assert!(kept.open);
        b.apply(&mut kept, C::Cancel);
        assert!(!b.drawing());
        assert!(kept.current.is_none());
        assert!(!b.poll(&mut kept));
    }
}
