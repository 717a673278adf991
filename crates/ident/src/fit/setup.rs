//! What a fit is given and how it reports as it goes: the record as the fit sees it
//! ([`FitData`]), the options, the observer that watches and may cancel, the parameters'
//! bounds, and the errors that stop a fit before it starts.

use serde::{Deserialize, Serialize};

use crate::model::excitation::Excitation;
use crate::model::scale::Unrepresentable;
use crate::model::{Model, ModelError, Param};

/// Samples per piece of the sums over the record.
pub const CHUNK: usize = 8192;

/// The time interval `[a, b]` (s) cut to the span of `times` (ascending); `None` when it
/// lies wholly outside it or there are no times.
pub fn within_span(times: &[f64], (a, b): (f64, f64)) -> Option<(f64, f64)> {
    let (&first, &last) = (times.first()?, times.last()?);
    let (a, b) = (a.max(first), b.min(last));
    (a <= b).then_some((a, b))
}

/// The measured test as the fit sees it (already windowed and filtered): the output at each
/// instant and the input that drove it.
#[derive(Debug, Clone, PartialEq)]
pub struct FitData {
    pub times: Vec<f64>,
    pub y: Vec<f64>,
    pub input: Excitation,
}

impl FitData {
    /// The median sampling period (s).
    pub fn sampling_period(&self) -> f64 {
        crate::record::timebase::sampling_period(&self.times).unwrap_or(1.0)
    }

    /// The time interval `[a, b]` (s) cut to the record's span, [first sample, last
    /// sample]; `None` when it lies wholly outside it.
    pub fn within_record(&self, interval: (f64, f64)) -> Option<(f64, f64)> {
        within_span(&self.times, interval)
    }

    /// Duration of the record after the step (s).
    pub fn duration(&self) -> f64 {
        self.duration_with(self.sampling_period())
    }

    /// The record without the samples `keep` says false of (outliers, a clipped span, a
    /// disturbance's window); the input is the same, so the model still sees every change.
    pub fn keeping(&self, keep: &[bool]) -> FitData {
        let kept = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .zip(keep)
                .filter(|(_, k)| **k)
                .map(|(x, _)| *x)
                .collect()
        };
        FitData {
            times: kept(&self.times),
            y: kept(&self.y),
            input: self.input.clone(),
        }
    }

    /// Duration of the record after the step (s), at least `ts` (the sampling period).
    pub fn duration_with(&self, ts: f64) -> f64 {
        let t0 = self.input.t0();
        let last = self.times.last().copied().unwrap_or(t0);
        (last - t0).max(ts)
    }
}

/// The optimiser.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Method {
    LevenbergMarquardt,
    NelderMead,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::LevenbergMarquardt => "lm",
            Method::NelderMead => "nelder-mead",
        }
    }
}

/// The most starts of one fit (the CLI and the app refuse more): each start is a whole local
/// fit, so the time grows with them (10⁵ starts took 18 s on the 35 samples of the LECI test,
/// uncapped).
pub const MAX_STARTS: usize = 1000;

/// How to fit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FitOptions {
    pub method: Method,
    /// Number of starts (1 = the guess only).
    pub starts: usize,
    /// Iteration limit per start.
    pub max_iterations: usize,
    /// Seed of the spread-out starts (fits are reproducible).
    pub seed: u64,
    /// A screen: a fit whose cost and values alone are read (the starts a search ranks,
    /// which go on later from their values or are dropped; a refit a test only compares).
    /// It is not polished, and its report carries no intervals (each costs a Jacobian) and
    /// no alias warning (the check costs 16 evaluations of the model per sample interval).
    pub screen: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            method: Method::LevenbergMarquardt,
            starts: 16,
            max_iterations: 200,
            seed: 1,
            screen: false,
        }
    }
}

/// One line of progress, for a live display.
#[derive(Debug, Clone, PartialEq)]
pub struct Progress {
    pub start: usize,
    pub starts: usize,
    pub iteration: usize,
    /// MSE of the current point, in (output units)² (inf where beyond double precision).
    pub cost: f64,
    pub best_cost: f64,
    pub model: Model,
}

/// Receives progress and may cancel. `()` ignores everything.
pub trait FitObserver {
    fn progress(&mut self, _progress: &Progress) {}
    fn cancelled(&self) -> bool {
        false
    }
    /// Whether this observer follows the fit's iterations (progress or cancel): a fit
    /// nobody watches screens its starts on every core and reports no progress.
    fn watches(&self) -> bool {
        true
    }
}

impl FitObserver for () {
    fn watches(&self) -> bool {
        false
    }
}

/// Errors that stop a fit before it starts (`crate::words` says them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum FitError {
    /// `n` samples after the step, too few for `p` parameters.
    TooFewSamples { n: usize, p: usize },
    /// The step size Δu is zero or not a finite number.
    BadStep(f64),
    /// The initial guess is not a valid model.
    BadGuess(ModelError),
    /// The data contain a value that is not a finite number.
    NonFiniteData,
    /// The step time t0 is not a finite number.
    BadStepTime(f64),
    /// The cost is not a finite number at the initial guess: the guess is far from the data.
    NonFiniteCost,
    /// The fitted `param` is about 10^`log10` in the data's units, beyond double precision.
    Unrepresentable { param: &'static str, log10: f64 },
}

impl From<Unrepresentable> for FitError {
    fn from(u: Unrepresentable) -> Self {
        FitError::Unrepresentable {
            param: u.param.name(),
            log10: u.log10,
        }
    }
}

/// Lower and upper bound of each parameter for this data (a structure with `lead` lets Td
/// go down to −[`Excitation::lead_range`], and bounds Ta by it).
pub fn bounds(p: Param, data: &FitData) -> (f64, f64) {
    bounds_with(
        p,
        data.sampling_period(),
        data.duration(),
        data.input.lead_range,
    )
}

/// [`bounds`] for a record sampled every `ts` seconds, `duration` seconds long after the
/// step, whose changes may have come up to `lead` seconds before they show.
pub(super) fn bounds_with(p: Param, ts: f64, duration: f64, lead: f64) -> (f64, f64) {
    match p {
        Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw => (1e-3 * ts, 100.0 * duration),
        Param::Zeta => (0.0, 10.0),
        Param::Td => (-lead, 0.95 * duration),
        Param::Ta => (0.0, lead),
        Param::Tz => (-100.0 * duration, 100.0 * duration),
        Param::Kp | Param::Y0 | Param::Drift | Param::X1 | Param::X2 | Param::X3 => {
            (f64::NEG_INFINITY, f64::INFINITY)
        }
    }
}
