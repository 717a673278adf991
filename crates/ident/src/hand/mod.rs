//! The graphical ("hand") methods of the course notes (Tognetti, "Obtenção de modelo
//! empírico"), read off a measured step record with their construction kept as data for the
//! app to draw: K, τ, θ of G(s) = K e^{−θs}/(τs + 1), or K, ζ, ωn (τ1, τ2 when ζ ≥ 1), θ of a
//! second-order model. Times below are from the step instant t0; Δy = y∞ − y0, K = Δy/Δu.
//!
//! - **Tangent** (Ziegler–Nichols / Cohen–Coon reaction curve): the tangent at the point of
//!   steepest rise meets the initial level y0 at t0 + θ and the final level y∞ at t0 + θ + τ.
//! - **63.2 %**: θ from the tangent (or from the first departure, where the curve leaves y0 by
//!   2 % of Δy or 3σ of the noise, whichever is larger), τ = t63.2 − θ.
//! - **Broida** (two points, 28 % and 40 %): τ = 5.5 (t40 − t28), θ = 2.8 t28 − 1.8 t40.
//! - **Smith** (two points, 28.3 % and 63.2 %, C. L. Smith 1972): τ = 1.5 (t63.2 − t28.3),
//!   θ = t63.2 − τ; the FOPTD through both points exactly.
//! - **Set of points** (the notes' "uso de conjunto de pontos"): least squares of
//!   ln(1 − (y − y0)/Δy) = θ/τ − t/τ over the samples between 10 % and 90 % of Δy.
//! - **Three points** for a second-order model with dead time, the notes' "uso de 3 pontos
//!   (boas estimativas para 0.707 ≤ ξ ≤ 3.0)": Mollenkamp's method as given by Smith &
//!   Corripio (Principles and Practice of Automatic Process Control, "Mollenkamp's three-
//!   point method"), from t15, t45, t75 (15, 45, 75 % of Δy):
//!   x = (t45 − t15)/(t75 − t15), ζ = (0.0805 − 5.547 (0.475 − x)²)/(x − 0.356),
//!   f2(ζ) = 0.708·2.811^ζ for ζ < 1, 2.6 ζ − 0.60 for ζ ≥ 1, ωn = f2(ζ)/(t75 − t15),
//!   f3(ζ) = 0.922·1.66^ζ, θ = t45 − f3(ζ)/ωn, and for ζ ≥ 1 τ1,2 = (ζ ± √(ζ² − 1))/ωn.
//!   A ζ outside 0.707–3 is kept with a warning; a first-order curve (x ≤ 0.356, ζ → ∞) is
//!   refused. Measured on exact curves, the correlations read ζ and ωn within 3 % for
//!   0.707 ≤ ζ ≤ 1.3, but ζ = 2 reads 2.57, and from ζ ≈ 2.5 on x is within 3e-4 of the pole
//!   0.356 (x tends to the first-order 0.3557), so the notes' upper end 3.0 is not reached.
//!
//! The curve is read as [`curve`] says (levels crossed on straight lines between samples, the
//! steepest slope from local least-squares lines over a window chosen from the noise). The
//! student may move the tangent's point and the two levels ([`Overrides`]) and recompute.
//! Each method's model is simulated on the record's own excitation and scored with the fit %
//! of [`crate::fit`] (100·(1 − ‖y − ŷ‖/‖y − ȳ‖), summed without overflow at any scale)
//! over every sample of the record.
//!
//! A construction may put θ below 0 (the tangent meeting y0 before the step): the model then
//! uses θ = 0, and the estimate reports that θ, with a warning giving the construction's. A θ
//! within [`ROUNDING`] of the record's length of 0 is rounding, read as 0 without a warning.

mod curve;
mod methods;

use serde::Serialize;

use crate::fit::FitData;
use crate::model::excitation::Excitation;
use crate::model::{Model, ModelError, Param, Structure, Values};
use curve::Curve;

/// The fewest samples after the step a construction reads.
pub const MIN_SAMPLES_AFTER: usize = 8;

/// A dead time this share of the record's length after the step from 0 is rounding.
pub const ROUNDING: f64 = 1e-9;

/// The damping range the notes give the three-point method ("boas estimativas").
pub const THREE_POINT_ZETA: (f64, f64) = (0.707, 3.0);

/// A hand method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum HandMethod {
    Tangent,
    SixtyThree,
    Broida,
    Smith,
    Points,
    ThreePoint,
}

impl HandMethod {
    /// Every method, in the notes' order.
    pub const ALL: [HandMethod; 6] = [
        HandMethod::Tangent,
        HandMethod::SixtyThree,
        HandMethod::Broida,
        HandMethod::Smith,
        HandMethod::Points,
        HandMethod::ThreePoint,
    ];

    /// The method's key on the command line and in JSON.
    pub fn key(self) -> &'static str {
        match self {
            HandMethod::Tangent => "tangent",
            HandMethod::SixtyThree => "63",
            HandMethod::Broida => "broida",
            HandMethod::Smith => "smith",
            HandMethod::Points => "points",
            HandMethod::ThreePoint => "three-point",
        }
    }

    /// The method of a key (case-insensitive).
    pub fn parse(key: &str) -> Option<HandMethod> {
        Self::ALL
            .into_iter()
            .find(|m| m.key().eq_ignore_ascii_case(key.trim()))
    }

    /// Whether the method gives a second-order model.
    pub fn second_order(self) -> bool {
        self == HandMethod::ThreePoint
    }
}

/// Why a construction cannot be made (`crate::words::hand` says them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum HandError {
    /// No output level before the step to start from.
    NoOperatingPoint,
    /// The step Δu is zero or not a number.
    NoStep(f64),
    /// The input changes `count` times: a hand method reads one step.
    SeveralChanges { count: usize },
    /// `n` samples from the step on, fewer than `needed`.
    TooFewSamples { n: usize, needed: usize },
    /// The output moves by `change` (output units), not clearly above the noise σ `noise`.
    NoRise { change: f64, noise: f64 },
    /// The last fifth of the record still moves by `percent` % of the change: the record
    /// ends before the output settles, so its final level is unknown.
    NotSettled { percent: f64 },
    /// The curve never reaches `percent` % of the change.
    LevelNotReached { percent: f64 },
    /// No stretch of the curve rises towards the final level (no tangent to draw).
    NoSteepestRise,
    /// The construction gives a time constant `tau` (s) that is not positive.
    NoTimeConstant { tau: f64 },
    /// The three points' ratio x = (t45 − t15)/(t75 − t15) gives no positive damping:
    /// the curve is first-order-like (x ≤ 0.356) or not a second-order step.
    ThreePointShape { x: f64 },
    /// A level or time the student gave is not a finite number.
    BadOverride(f64),
    /// The tangent's point `t` (s) is outside the response, from the step at `start` to the
    /// record's end at `end` (s).
    TangentOutside { t: f64, start: f64, end: f64 },
    /// The method's model could not be simulated.
    Model(#[from] ModelError),
}

/// Something to know about a method's result.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum HandWarning {
    /// The three-point ζ is outside the range the notes vouch for.
    DampingOutsideRange { zeta: f64 },
    /// The construction put the response's start before the step; the model uses θ = 0.
    NegativeDeadTime { theta: f64 },
}

/// How θ is read in the 63.2 % method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub enum DeadTimeFrom {
    /// Where the tangent meets the initial level.
    #[default]
    Tangent,
    /// Where the curve first leaves the initial level.
    FirstDeparture,
}

/// What the student moved on the construction.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Overrides {
    /// The tangent's point (s, absolute): the tangent is the local line there instead of at
    /// the steepest rise (outside the response, the nearest one, as a drag past the end
    /// gives; [`Record::tangent_time`] refuses a typed time outside it).
    pub tangent_time: Option<f64>,
    /// The initial level (output units) instead of the operating point.
    pub y0: Option<f64>,
    /// The final level (output units) instead of the record's last tenth.
    pub y_final: Option<f64>,
    /// Where the 63.2 % method reads θ.
    pub dead_time_from: DeadTimeFrom,
}

/// The tangent as drawn: through (t, y) with its slope, meeting the levels.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tangent {
    /// The tangent's point (s, absolute; output units).
    pub t: f64,
    pub y: f64,
    /// Output units per second.
    pub slope: f64,
    /// Where it meets the initial and the final level (s, absolute).
    pub t_initial: f64,
    pub t_final: f64,
}

/// A level line and the time read off where the curve crosses it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LevelTime {
    /// Share of the change, in % (63.2 for the 63.2 % time).
    pub percent: f64,
    /// The level (output units).
    pub y: f64,
    /// The crossing (s, absolute).
    pub t: f64,
}

/// A method's construction, for drawing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Construction {
    pub t0: f64,
    /// The initial and final levels (output units).
    pub y0: f64,
    pub y_final: f64,
    pub tangent: Option<Tangent>,
    pub levels: Vec<LevelTime>,
    /// The samples a least-squares method used (s, output units).
    pub points: Vec<(f64, f64)>,
    /// Samples in each local line fit (the tangent's and the smoothing's width).
    pub window: usize,
    /// The noise σ read off the record (output units).
    pub noise: f64,
}

/// A second-order method's own parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SecondOrder {
    pub zeta: f64,
    /// rad/s.
    pub omega_n: f64,
    /// The time constants (s) when ζ ≥ 1.
    pub tau1: Option<f64>,
    pub tau2: Option<f64>,
}

/// What a hand method reads off the record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HandEstimate {
    pub method: HandMethod,
    /// Static gain K = Δy/Δu (output units per input unit).
    pub k: f64,
    /// Dead time θ (s) the model uses: as read, or 0 when the construction puts it before
    /// the step (a warning then gives the construction's).
    pub theta: f64,
    /// The first-order time constant τ (s).
    pub tau: Option<f64>,
    pub second_order: Option<SecondOrder>,
    /// The model simulated (P1D, P2D, or P2DU when ζ < 1), with Y0 at the initial level.
    pub model: Model,
    pub construction: Construction,
    /// Fit % of the model on every sample of the record.
    pub fit_percent: f64,
    pub warnings: Vec<HandWarning>,
}

/// A measured single-step record and its operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub data: FitData,
    /// The output at rest before the step (output units).
    pub y0: f64,
}

impl Record {
    /// The record of prepared fit data with one input change; `y0` overrides the level
    /// measured before the step.
    pub fn from_fit_data(data: &FitData, y0: Option<f64>) -> Result<Self, HandError> {
        let count = data.input.changes.len();
        if count > 1 {
            return Err(HandError::SeveralChanges { count });
        }
        let y0 = y0
            .or_else(|| crate::fit::guess::level_before(data))
            .ok_or(HandError::NoOperatingPoint)?;
        Self::checked(data.clone(), y0)
    }

    /// The record of raw samples with an ideal step Δu at t0 from the level y0.
    pub fn new(times: &[f64], y: &[f64], t0: f64, du: f64, y0: f64) -> Result<Self, HandError> {
        let n = times.len().min(y.len());
        let data = FitData {
            times: times[..n].to_vec(),
            y: y[..n].to_vec(),
            input: Excitation::step(t0, du),
        };
        Self::checked(data, y0)
    }

    fn checked(data: FitData, y0: f64) -> Result<Self, HandError> {
        let du = data.input.du();
        if !(du.is_finite() && du != 0.0) {
            return Err(HandError::NoStep(du));
        }
        if !y0.is_finite() {
            return Err(HandError::BadOverride(y0));
        }
        let t0 = data.input.t0();
        let n = data.times.iter().filter(|&&t| t >= t0).count();
        if n < MIN_SAMPLES_AFTER {
            return Err(HandError::TooFewSamples {
                n,
                needed: MIN_SAMPLES_AFTER,
            });
        }
        Ok(Self { data, y0 })
    }

    /// The step instant (s) and size (input units).
    pub fn t0(&self) -> f64 {
        self.data.input.t0()
    }

    pub fn du(&self) -> f64 {
        self.data.input.du()
    }

    /// The record's last instant (s).
    pub fn end(&self) -> f64 {
        self.data.times.last().copied().unwrap_or_else(|| self.t0())
    }

    /// A typed tangent's point `t` (s), refused outside the response (from the step to the
    /// record's end).
    pub fn tangent_time(&self, t: f64) -> Result<f64, HandError> {
        let (start, end) = (self.t0(), self.end());
        if !t.is_finite() {
            return Err(HandError::BadOverride(t));
        }
        if !(start..=end).contains(&t) {
            return Err(HandError::TangentOutside { t, start, end });
        }
        Ok(t)
    }

    /// The final level: the mean of the samples in the last tenth of the record's time.
    pub fn final_level(&self) -> f64 {
        let times = &self.data.times;
        let (first, last) = (self.t0(), times.last().copied().unwrap_or(0.0));
        let from = times.partition_point(|&t| t < last - 0.1 * (last - first));
        let tail = &self.data.y[from.min(self.data.y.len().saturating_sub(1))..];
        crate::stats::mean(tail)
    }

    /// The record read for the constructions, with the student's levels.
    fn reading(&self, overrides: &Overrides) -> Result<Reading, HandError> {
        for v in [overrides.y0, overrides.y_final, overrides.tangent_time]
            .into_iter()
            .flatten()
        {
            if !v.is_finite() {
                return Err(HandError::BadOverride(v));
            }
        }
        let y0 = overrides.y0.unwrap_or(self.y0);
        let y_final = overrides.y_final.unwrap_or_else(|| self.final_level());
        let curve = Curve::new(&self.data.times, &self.data.y, self.t0(), y0, y_final);
        curve::check_rise(&curve, y0, y_final)?;
        if overrides.y_final.is_none() {
            let drift = curve::final_drift(&curve, y_final - y0).unwrap_or(0.0);
            let allowed = 0.05 + 3.0 * curve.noise / (y_final - y0).abs();
            if drift.abs() > allowed {
                return Err(HandError::NotSettled {
                    percent: 100.0 * drift,
                });
            }
        }
        Ok(Reading {
            curve,
            t0: self.t0(),
            y0,
            y_final,
            k: (y_final - y0) / self.du(),
        })
    }
}

/// The record as the methods read it.
#[derive(Debug, Clone)]
pub(crate) struct Reading {
    curve: Curve,
    t0: f64,
    y0: f64,
    y_final: f64,
    k: f64,
}

impl Reading {
    /// The level at `percent` % of the change.
    fn level(&self, percent: f64) -> f64 {
        self.y0 + percent / 100.0 * (self.y_final - self.y0)
    }

    /// The crossing of the level at `percent` %, as a [`LevelTime`].
    fn level_time(&self, percent: f64) -> Result<LevelTime, HandError> {
        let y = self.level(percent);
        Ok(LevelTime {
            percent,
            y,
            t: self.curve.crossing(y, percent)?,
        })
    }

    fn construction(&self) -> Construction {
        Construction {
            t0: self.t0,
            y0: self.y0,
            y_final: self.y_final,
            tangent: None,
            levels: Vec::new(),
            points: Vec::new(),
            window: self.curve.window,
            noise: self.curve.noise,
        }
    }
}

/// What a method read, before its model is simulated.
#[derive(Debug, Clone)]
pub(crate) struct Read {
    theta: f64,
    shape: Shape,
    construction: Construction,
    warnings: Vec<HandWarning>,
}

#[derive(Debug, Clone, Copy)]
pub(crate) enum Shape {
    First { tau: f64 },
    Second(SecondOrder),
}

/// One method on the record.
pub fn estimate(
    record: &Record,
    method: HandMethod,
    overrides: &Overrides,
) -> Result<HandEstimate, HandError> {
    let reading = record.reading(overrides)?;
    let read = methods::read(&reading, method, overrides)?;
    finish(record, &reading, method, read)
}

/// Every method on the record, in [`HandMethod::ALL`]'s order.
pub fn estimate_all(
    record: &Record,
    overrides: &Overrides,
) -> Vec<(HandMethod, Result<HandEstimate, HandError>)> {
    let reading = record.reading(overrides);
    HandMethod::ALL
        .into_iter()
        .map(|m| {
            let result = reading.clone().and_then(|r| {
                let read = methods::read(&r, m, overrides)?;
                finish(record, &r, m, read)
            });
            (m, result)
        })
        .collect()
}

fn finish(
    record: &Record,
    reading: &Reading,
    method: HandMethod,
    mut read: Read,
) -> Result<HandEstimate, HandError> {
    let rounding = ROUNDING * (record.end() - record.t0());
    if read.theta < -rounding {
        read.warnings
            .push(HandWarning::NegativeDeadTime { theta: read.theta });
    }
    let theta = if read.theta.abs() <= rounding {
        0.0
    } else {
        read.theta.max(0.0)
    };
    let model = model_of(reading.k, theta, read.shape, reading.y0);
    let fit_percent = fit_percent(&model, &record.data)?;
    let (tau, second_order) = match read.shape {
        Shape::First { tau } => (Some(tau), None),
        Shape::Second(s) => (None, Some(s)),
    };
    Ok(HandEstimate {
        method,
        k: reading.k,
        theta,
        tau,
        second_order,
        model,
        construction: read.construction,
        fit_percent,
        warnings: read.warnings,
    })
}

/// The model of a method's reading: P1D, P2D (ζ ≥ 1) or P2DU, Y0 held at `y0`.
fn model_of(k: f64, theta: f64, shape: Shape, y0: f64) -> Model {
    let code = match shape {
        Shape::First { .. } => "P1D",
        Shape::Second(s) if s.tau1.is_some() => "P2D",
        Shape::Second(_) => "P2DU",
    };
    let mut structure = Structure::parse(code).unwrap_or_else(|_| unreachable!("fixed code"));
    structure.free_offset = false;
    let mut values = Values::default();
    values.set(Param::Kp, k);
    values.set(Param::Td, theta);
    values.set(Param::Y0, y0);
    match shape {
        Shape::First { tau } => values.set(Param::Tp1, tau),
        Shape::Second(s) => match (s.tau1, s.tau2) {
            (Some(t1), Some(t2)) => {
                values.set(Param::Tp1, t1);
                values.set(Param::Tp2, t2);
            }
            _ => {
                values.set(Param::Tw, 1.0 / s.omega_n);
                values.set(Param::Zeta, s.zeta);
            }
        },
    }
    Model::new(structure, values)
}

/// The least-squares structures the hand methods are compared with: the first- and
/// second-order models with dead time they read.
pub const COMPARED: [&str; 2] = ["P1D", "P2D"];

/// The least-squares fits of [`COMPARED`] on the same data (default options; one that fails
/// is left out), until `cancelled` says stop.
pub fn least_squares(
    data: &FitData,
    experiment: &crate::experiment::Experiment,
    cancelled: impl Fn() -> bool,
) -> Vec<crate::fit::FitReport> {
    let options = crate::fit::FitOptions::default();
    COMPARED
        .iter()
        .take_while(|_| !cancelled())
        .filter_map(|code| {
            experiment
                .fit_prepared(data, code, false, &[], &options, &mut ())
                .ok()
        })
        .collect()
}

/// The fit % of `model` on every sample of `data`: 100·(1 − ‖y − ŷ‖/‖y − ȳ‖), as
/// [`crate::fit`] reports it, summed as [`crate::lsq::arx::fit_percent`] sums at any scale
/// (NaN for a constant record).
pub fn fit_percent(model: &Model, data: &FitData) -> Result<f64, ModelError> {
    let simulated = model.simulate(&data.input, &data.times)?;
    Ok(crate::lsq::arx::fit_percent(&data.y, &simulated))
}
