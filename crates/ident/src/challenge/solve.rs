//! Degrau's own answer to a challenge, found as a student would get it from `degrau
//! diagnose record.csv` (the CSV text loaded, the measured input driving the fits, Y0 held
//! at the level before the first change, the loop started from [`START`]), and the grading
//! of an answer against the key.

use crate::diagnose::test_causes::TestCauseKind;
use crate::diagnose::{Cause, DiagnoseOptions, DiagnoseReport, diagnose};
use crate::experiment::Experiment;
use crate::model::{Param, Values};
use crate::record::data::{LoadOptions, load_str};

use super::truth::START;

/// What the diagnosis ends on.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The first structural cause named (`None`: no extension paid).
    pub first_cause: Cause,
    /// The final structure's procest code.
    pub structure: String,
    /// The final static gain.
    pub kp: f64,
    /// The test's causes named.
    pub test_causes: Vec<TestCauseKind>,
}

/// The diagnosis of a record's CSV text from [`START`], as the CLI runs it; `None` when the
/// text cannot be loaded or fitted (never for a generated record).
pub fn solve(csv: &str) -> Option<Solution> {
    let report = diagnosis(csv)?;
    Some(Solution {
        first_cause: report.steps.first().map_or(Cause::None, |s| s.cause),
        structure: report.final_fit.model.structure.code(),
        kp: report.final_fit.model.get(Param::Kp),
        test_causes: report.test_causes.iter().map(|c| c.kind).collect(),
    })
}

/// The whole diagnosis of a record's CSV text from [`START`], as the CLI runs it (the
/// report [`solve`] reads, and the app shows a student after Check).
pub fn diagnosis(csv: &str) -> Option<DiagnoseReport> {
    let test = load_str(csv, &LoadOptions::from_text("", "", "", None, 0)).ok()?;
    let experiment = Experiment::new(&test, None, None, None).ok()?;
    let data = experiment.fit_data(&test).ok()?;
    let start = experiment.structure(START, false, &data).ok()?;
    let values = experiment.operating_point(&data).map(|y0| {
        let mut v = Values::default();
        v.set(Param::Y0, y0);
        v
    });
    let mut options = DiagnoseOptions::default();
    options.fit.starts = options.fit.starts.max(1);
    diagnose(&data, start, values, &options).ok()
}

/// An answer graded against a key: each part right or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Grade {
    pub cause: bool,
    pub structure: bool,
    pub kp: bool,
}

impl Grade {
    /// One answer graded against a key's facts: the cause among the key's ids (`none` when
    /// the key says so), the structure's code (case aside), the gain within the relative
    /// `kp_tolerance` of `kp`.
    pub fn of(
        causes: &[String],
        structure: &str,
        kp: f64,
        kp_tolerance: f64,
        answer: (&str, &str, f64),
    ) -> Self {
        let (cause, code, gain) = answer;
        Self {
            cause: causes.iter().any(|c| c == cause.trim()),
            structure: structure.eq_ignore_ascii_case(code.trim()),
            kp: kp_within(gain, kp, kp_tolerance),
        }
    }

    /// Every part right.
    pub fn all(self) -> bool {
        self.cause && self.structure && self.kp
    }
}

/// Whether `kp` lies within `tolerance` (relative) of the key's `truth`.
pub fn kp_within(kp: f64, truth: f64, tolerance: f64) -> bool {
    kp.is_finite() && (kp - truth).abs() <= tolerance * truth.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_answer_is_graded_part_by_part() {
        let causes = vec!["dead_time".to_string(), "extra_pole".to_string()];
        let g = Grade::of(&causes, "P2D", 2.0, 0.1, (" extra_pole", "p2d ", 2.19));
        assert_eq!(
            g,
            Grade {
                cause: true,
                structure: true,
                kp: true
            }
        );
        let g = Grade::of(&causes, "P2D", 2.0, 0.1, ("zero", "P1D", 2.21));
        assert!(!g.cause && !g.structure && !g.kp);
        assert!(!Grade::of(&causes, "P2D", 2.0, 0.1, ("dead_time", "P2D", f64::NAN)).kp);
    }
}
