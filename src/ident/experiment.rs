//! An identification experiment: a loaded step test plus the choices a student makes on it
//! (step instant and size, operating point, window, filter), turned into the data a fit
//! sees. The command line and the app both go through here, so they fit the same thing.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

use super::data::StepTest;
use super::fit::{FitData, FitError, FitObserver, FitOptions, FitReport, fit};
use super::guess::auto_guess;
use super::models::{ModelError, Param, StepSetup, Structure, Values};
use super::prepare;

/// What to do with the output before the step, y0 (procest's offset).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Offset {
    /// The mean of the samples before the step, held fixed; estimated when there are none.
    Auto,
    /// Estimated with the other parameters.
    Free,
    /// Held at this value.
    Fixed(f64),
}

/// Problems with the experiment's choices (`crate::text` says them; the CLI and the app
/// add where to give what is missing, a flag or a field).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum ExperimentError {
    /// No step in the input: no input column, or it never changes. The input before the
    /// record (a step at the first sample), or the step time t0 and size Δu, are missing.
    NoStep,
    /// The step size Δu is zero or not a finite number.
    BadStep(f64),
    /// A window or filter that cannot be applied.
    Prepare(#[from] prepare::PrepareError),
    Model(#[from] ModelError),
    Fit(#[from] FitError),
}

/// The choices made on a test.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Experiment {
    /// Step instant (s, in the file's time).
    pub t0: f64,
    /// Step size Δu (input units).
    pub du: f64,
    pub offset: Offset,
    /// Time range kept (inclusive), `None` for everything.
    pub window: Option<(f64, f64)>,
    /// Cut-off of the notes' first-order low-pass filter (Hz), `None` for no filter.
    pub filter_hz: Option<f64>,
}

impl Experiment {
    /// Reads t0 and Δu from the test's input column; `t0`/`du` override what is found.
    /// `initial_input` is the input before the record started (e.g. 0 for a heater switched
    /// on at the first sample).
    pub fn new(
        test: &StepTest,
        t0: Option<f64>,
        du: Option<f64>,
        initial_input: Option<f64>,
    ) -> Result<Self, ExperimentError> {
        let edge = prepare::detect_step(test, initial_input);
        let t0 = t0
            .or(edge.as_ref().map(|e| e.t0))
            .ok_or(ExperimentError::NoStep)?;
        let du = du
            .or(edge.as_ref().map(|e| e.du))
            .ok_or(ExperimentError::NoStep)?;
        if !du.is_finite() || du == 0.0 {
            return Err(ExperimentError::BadStep(du));
        }
        Ok(Self {
            t0,
            du,
            offset: Offset::Auto,
            window: None,
            filter_hz: None,
        })
    }

    /// The samples the fit sees: windowed, then filtered.
    pub fn fit_data(&self, test: &StepTest) -> Result<FitData, ExperimentError> {
        if !self.du.is_finite() || self.du == 0.0 {
            return Err(ExperimentError::BadStep(self.du));
        }
        let kept = match self.window {
            Some((start, end)) => Cow::Owned(prepare::apply_window(
                test,
                prepare::Window::Time { start, end },
            )?),
            None => Cow::Borrowed(test),
        };
        let mut y = kept.output.clone();
        if let Some(fc) = self.filter_hz {
            let ts = prepare::sampling_period(&kept.time).unwrap_or(1.0);
            y = prepare::Ewma::try_new(fc, ts)?.apply(&y);
        }
        Ok(FitData {
            times: kept.time.clone(),
            y,
            setup: StepSetup {
                t0: self.t0,
                du: self.du,
            },
        })
    }

    /// The operating point y0 when it is known (fixed or measured before the step).
    pub fn operating_point(&self, data: &FitData) -> Option<f64> {
        match self.offset {
            Offset::Fixed(v) => Some(v),
            Offset::Free => None,
            Offset::Auto => super::guess::level_before(data),
        }
    }

    /// The structure for `code`, Y0 free or held as the offset choice says.
    pub fn structure(
        &self,
        code: &str,
        drift: bool,
        data: &FitData,
    ) -> Result<Structure, ExperimentError> {
        let mut s = Structure::parse(code)?;
        s.free_offset = self.operating_point(data).is_none();
        s.drift = drift;
        Ok(s)
    }

    /// The automatic guess, with y0 held where it is known.
    pub fn guess(&self, structure: Structure, data: &FitData) -> Values {
        let mut v = auto_guess(data, structure, self.operating_point(data));
        if let Some(y0) = self.operating_point(data) {
            v.set(Param::Y0, y0);
        }
        v
    }

    /// Fits `code` from the automatic guess with `overrides` applied.
    pub fn fit(
        &self,
        test: &StepTest,
        code: &str,
        drift: bool,
        overrides: &[(Param, f64)],
        options: &FitOptions,
        observer: &mut dyn FitObserver,
    ) -> Result<(FitData, FitReport), ExperimentError> {
        let data = self.fit_data(test)?;
        let report = self.fit_prepared(&data, code, drift, overrides, options, observer)?;
        Ok((data, report))
    }

    /// Fits `code` to samples already prepared by [`Experiment::fit_data`] (so a caller that
    /// holds them needs no second copy of the record).
    pub fn fit_prepared(
        &self,
        data: &FitData,
        code: &str,
        drift: bool,
        overrides: &[(Param, f64)],
        options: &FitOptions,
        observer: &mut dyn FitObserver,
    ) -> Result<FitReport, ExperimentError> {
        let structure = self.structure(code, drift, data)?;
        let mut guess = self.guess(structure, data);
        for &(p, v) in overrides {
            guess.set(p, v);
        }
        Ok(fit(data, structure, guess, options, observer)?)
    }
}
