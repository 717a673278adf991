//! What the Identify mode keeps between runs ([`Saved`]: the file or example loaded, the
//! reading choices, the choices made on the test, the model code and the fit's options),
//! its defaults, and the model codes the menu offers. A saved state is checked field by
//! field when restored ([`crate::persist`]).

use serde::{Deserialize, Serialize};

use super::super::commands::Choice;
use degrau_ident::experiment::Experiment;
use degrau_ident::fit::Method;

/// The model codes offered, in the order of the notes.
pub const CODES: [&str; 13] = [
    "P1", "P1D", "P2", "P2D", "P2U", "P2DU", "P2Z", "P2DZ", "P2DUZ", "P3", "P3D", "P1I", "P1DI",
];

/// Choices kept between runs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub path: String,
    /// The shipped example is what is loaded (it has no path).
    pub example: bool,
    /// The step, operating point, window and filter chosen on the loaded test, restored
    /// with it after a restart.
    pub experiment: Option<Experiment>,
    pub time_col: String,
    pub y_col: String,
    pub u_col: String,
    /// Sampling period (s) for files without a time column (empty: none).
    pub sampling_period: String,
    /// The input before the record started, for a test whose step came at the first sample
    /// (empty: none).
    pub initial_input: String,
    /// A second file that holds the input, joined on time (empty: the input is a column of
    /// the test's own file).
    pub u_path: String,
    pub code: String,
    pub drift: bool,
    pub method: Method,
    pub multistart: bool,
    pub starts: usize,
}

impl Default for Saved {
    fn default() -> Self {
        Self {
            path: String::new(),
            example: false,
            experiment: None,
            time_col: String::new(),
            y_col: String::new(),
            u_col: String::new(),
            sampling_period: String::new(),
            initial_input: String::new(),
            u_path: String::new(),
            code: "P2DU".into(),
            drift: false,
            method: Method::LevenbergMarquardt,
            multistart: true,
            starts: 16,
        }
    }
}

impl Saved {
    /// The reading choices that are not automatic, as typed.
    pub(super) fn reading_choices(&self) -> Vec<(Choice, String)> {
        [
            (Choice::TimeColumn, &self.time_col),
            (Choice::OutputColumn, &self.y_col),
            (Choice::InputColumn, &self.u_col),
            (Choice::SamplingPeriod, &self.sampling_period),
            (Choice::InitialInput, &self.initial_input),
        ]
        .into_iter()
        .filter(|(_, text)| !text.trim().is_empty())
        .map(|(c, text)| (c, text.trim().to_string()))
        .collect()
    }

    pub(super) fn clear_reading_choices(&mut self) {
        for text in [
            &mut self.time_col,
            &mut self.y_col,
            &mut self.u_col,
            &mut self.sampling_period,
            &mut self.initial_input,
        ] {
            text.clear();
        }
    }
}
