//! An identification experiment: a loaded test plus the choices a student makes on it (what
//! drove it: the measured input or one ideal step; operating point, window, filter), turned
//! into the data a fit sees. The command line and the app both go through here, so they fit
//! the same thing.
//!
//! By default a test with an input column is driven by that input, every change of it used
//! ([`Drive::Measured`]); one without, or where the student typed the step (t0 or Δu), or
//! asked for it (`--single-step`), by the ideal step Δu at t0 ([`Drive::Step`], the LECI
//! case, today's model).

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

use crate::fit::guess::auto_guess;
use crate::fit::{FitData, FitError, FitObserver, FitOptions, FitReport, fit};
use crate::model::excitation::Excitation;
use crate::model::excitation::Hold;
use crate::model::{ModelError, Param, Structure, Values};
use crate::record::data::StepTest;
use crate::record::prepare;

/// What to do with the output before the step, y0 (procest's offset).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Offset {
    /// Held at the measured level before the step (see [`crate::fit::guess::rest_level`]);
    /// estimated only when no sample shows it.
    Auto,
    /// Estimated with the other parameters.
    Free,
    /// Held at this value.
    Fixed(f64),
}

/// What was done with Y0, and why: the fact the CLI and the app state next to a fit
/// (words in [`crate::words::operating_point`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum OperatingPoint {
    /// [`Offset::Auto`]: Y0 held at the mean of the `samples` samples before the step,
    /// `wild` of them (spikes, dropouts) left out.
    MeanBefore {
        y0: f64,
        samples: usize,
        #[serde(default)]
        wild: usize,
    },
    /// [`Offset::Auto`] on a record that starts with the step: Y0 held at the sample at
    /// the step instant, where the output has not moved yet.
    AtStep { y0: f64 },
    /// [`Offset::Fixed`]: Y0 held at the value given.
    Given { y0: f64 },
    /// Y0 estimated with the other parameters.
    Estimated { reason: EstimateReason },
}

/// The fewest samples before the first change of a multi-change record for [`Offset::Auto`]
/// to hold Y0 at their mean (see [`EstimateReason::ShortRest`]).
pub const MIN_REST_SAMPLES: usize = 20;

/// Whether the first `samples` outputs (at least two) are all equal, or all within one
/// quantum on a quantised record ([`crate::diagnose::test_causes::resolution`]): a level that does not
/// move is the operating point however few samples show it, and Y0 is held there even under
/// [`MIN_REST_SAMPLES`].
fn level_at_rest(data: &FitData, samples: usize) -> bool {
    let Some(before) = data.y.get(..samples).filter(|b| b.len() >= 2) else {
        return false;
    };
    let (lo, hi) = before
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let spread = hi - lo;
    spread == 0.0
        || crate::diagnose::test_causes::resolution(&data.y)
            .is_some_and(|q| spread <= q * (1.0 + 1e-9))
}

/// Why Y0 is estimated rather than held.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EstimateReason {
    /// [`Offset::Free`] asks for it.
    Asked,
    /// [`Offset::Auto`], but no sample is at or before the step instant (it comes before the
    /// first sample kept).
    NoSampleBeforeStep,
    /// [`Offset::Auto`] on a record whose input changes more than once, with fewer than
    /// [`MIN_REST_SAMPLES`] samples before the first change: so short a stretch is a weaker
    /// measurement of the operating point than the record's several responses (and a slow
    /// creep in it biases the mean), so Y0 is estimated with the other parameters. Samples
    /// that are all equal (or within one quantum) hold Y0 however few: they do not creep.
    ShortRest,
    /// [`Offset::Auto`], but the output still moved before the first change
    /// ([`crate::fit::rest::Rest::NotAtRest`]): no level was at rest, and an initial transient is
    /// estimated with it.
    NotAtRest,
}

impl OperatingPoint {
    /// The value Y0 is held at, `None` when it is estimated.
    pub fn held(&self) -> Option<f64> {
        match *self {
            Self::MeanBefore { y0, .. } | Self::AtStep { y0 } | Self::Given { y0 } => Some(y0),
            Self::Estimated { .. } => None,
        }
    }
}

/// Problems with the experiment's choices (`crate::words` says them; the CLI and the app
/// add where to give what is missing, a flag or a field).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
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

/// What drove the test, as the model sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Drive {
    /// One ideal step Δu at t0 ([`Experiment::t0`], [`Experiment::du`]).
    #[default]
    Step,
    /// The measured input column, held between samples as `hold` says.
    Measured { hold: Hold },
}

/// The choices made on a test.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Experiment {
    /// Step instant (s, in the file's time): the ideal step's, or the measured input's
    /// first change.
    pub t0: f64,
    /// Step size Δu (input units): the ideal step's, or the measured input's first change.
    pub du: f64,
    /// What drove the test.
    #[serde(default)]
    pub drive: Drive,
    /// The input before the record started, when given (a step at the first sample).
    #[serde(default)]
    pub initial_input: Option<f64>,
    pub offset: Offset,
    /// Time range kept (inclusive), `None` for everything.
    pub window: Option<(f64, f64)>,
    /// Cut-off of the notes' first-order low-pass filter (Hz), `None` for no filter.
    pub filter_hz: Option<f64>,
}

impl Experiment {
    /// Driven by the measured input when the test has one that changes and neither `t0`
    /// nor `du` is typed; else by one ideal step, read from the input's largest change
    /// where `t0`/`du` do not say it. `initial_input` is the input before the record
    /// started (e.g. 0 for a heater switched on at the first sample).
    pub fn new(
        test: &StepTest,
        t0: Option<f64>,
        du: Option<f64>,
        initial_input: Option<f64>,
    ) -> Result<Self, ExperimentError> {
        let typed = t0.is_some() || du.is_some();
        let measured = test
            .input
            .as_deref()
            .and_then(|u| Excitation::measured(&test.time, u, initial_input, Hold::Zoh))
            .filter(|_| !typed);
        if let Some(input) = measured {
            return Ok(Self {
                t0: input.t0(),
                du: input.du(),
                drive: Drive::Measured { hold: Hold::Zoh },
                initial_input,
                offset: Offset::Auto,
                window: None,
                filter_hz: None,
            });
        }
        Self::single_step(test, t0, du, initial_input)
    }

    /// Driven by one ideal step (today's model, `--single-step`): t0 and Δu typed, or the
    /// input column's largest change.
    pub fn single_step(
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
            drive: Drive::Step,
            initial_input,
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
            let ts = crate::record::timebase::sampling_period(&kept.time).unwrap_or(1.0);
            y = prepare::Ewma::try_new(fc, ts)?.apply(&y);
        }
        let input = self.input(test)?;
        Ok(FitData {
            times: kept.time.clone(),
            y,
            input,
        })
    }

    /// The input the model sees: the whole record's (a window chooses the samples the fit
    /// compares, not what drove the process: changes before it still act inside it).
    fn input(&self, test: &StepTest) -> Result<Excitation, ExperimentError> {
        match self.drive {
            Drive::Step => Ok(Excitation::step(self.t0, self.du)),
            Drive::Measured { hold } => test
                .input
                .as_deref()
                .and_then(|u| Excitation::measured(&test.time, u, self.initial_input, hold))
                .ok_or(ExperimentError::NoStep),
        }
    }

    /// What the offset choice does with Y0 on `data`: held (at the level measured before
    /// the step, or at the value given) or estimated, and why.
    pub fn operating_point_fact(&self, data: &FitData) -> OperatingPoint {
        match self.offset {
            Offset::Fixed(y0) => OperatingPoint::Given { y0 },
            Offset::Free => OperatingPoint::Estimated {
                reason: EstimateReason::Asked,
            },
            Offset::Auto if crate::fit::rest::rest_before(data).is_not_at_rest() => {
                OperatingPoint::Estimated {
                    reason: EstimateReason::NotAtRest,
                }
            }
            Offset::Auto => match crate::fit::guess::rest_level(data) {
                Some(rest)
                    if data.input.is_multi_step()
                        && rest.samples < MIN_REST_SAMPLES
                        && !level_at_rest(data, rest.samples) =>
                {
                    OperatingPoint::Estimated {
                        reason: EstimateReason::ShortRest,
                    }
                }
                Some(rest) if rest.at_step => OperatingPoint::AtStep { y0: rest.y0 },
                Some(rest) => OperatingPoint::MeanBefore {
                    y0: rest.y0,
                    samples: rest.samples,
                    wild: rest.wild,
                },
                None => OperatingPoint::Estimated {
                    reason: EstimateReason::NoSampleBeforeStep,
                },
            },
        }
    }

    /// The operating point y0 when it is held (given, or measured before the step).
    pub fn operating_point(&self, data: &FitData) -> Option<f64> {
        self.operating_point_fact(data).held()
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
        s.lead = data.input.lead_range > 0.0;
        s.transient =
            self.offset == Offset::Auto && crate::fit::rest::rest_before(data).is_not_at_rest();
        Ok(s)
    }

    /// The automatic guess, with y0 held where it is known.
    pub fn guess(&self, structure: Structure, data: &FitData) -> Values {
        let held = self.operating_point(data);
        let mut v = auto_guess(data, structure, held);
        if let Some(y0) = held {
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
