//! Validation on what was not fitted, the notes' step 6 ("utilizar uma parte dos dados para
//! validar o modelo"): an extension of a model is kept only if, fitted without the record's
//! last part, it predicts that part about as well as the model it extends, or better.
//!
//! The split is in time (a blocked hold-out: the residuals of a record are correlated, so a
//! random split would validate on the neighbours of fitted samples): the estimation part
//! runs to [`ESTIMATION_SHARE`] of the span from the first input change to the last sample,
//! the validation part is the rest. Both models are refitted on the estimation part from
//! their whole-record optimum and simulated over the validation part, which on a record of
//! several changes holds the later responses. A spurious drift or zero extrapolates badly; a
//! real pole, dead time or pair predicts the held-out samples at least as well.
//!
//! A tie is no evidence against the extension (a dead time shows only in the first part): it
//! is refused only when its mean squared prediction error exceeds the current model's by more
//! than a tenth and by more than the output noise's own variance ([`HoldOut::keeps_candidate`]).

use crate::fit::rest::difference_noise;
use crate::fit::{FitData, FitOptions, FitReport, search_fit};
use crate::model::Model;

/// The share of the span after the first change the estimation part holds.
pub const ESTIMATION_SHARE: f64 = 0.7;

/// The fewest samples each part needs for the hold-out to say anything.
pub const MIN_PART: usize = 20;

/// A candidate predicting the held-out part with a mean squared error above this many
/// times the current model's (and by more than the noise's variance) predicts worse.
pub const WORSE_RATIO: f64 = 1.1;

/// Two models' predictions of the held-out part of a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoldOut {
    /// Mean squared prediction errors (output units²).
    pub current: f64,
    pub candidate: f64,
    /// The output's white-noise variance (output units², from its first differences): what
    /// no model predicts.
    pub noise: f64,
    /// Samples held out.
    pub samples: usize,
}

impl HoldOut {
    /// Whether the candidate predicts the held-out part about as well as the current model
    /// or better: its mean squared error at most [`WORSE_RATIO`] times the current's plus
    /// the noise's variance (a tie, or a difference within the noise, is no evidence).
    pub fn keeps_candidate(&self) -> bool {
        self.candidate <= WORSE_RATIO * self.current + self.noise
    }
}

/// The split instant (s): [`ESTIMATION_SHARE`] of the span from the first change to the
/// last sample; `None` when either part would hold fewer than [`MIN_PART`] samples.
pub fn split(data: &FitData) -> Option<f64> {
    let last = *data.times.last()?;
    let t0 = data.input.t0();
    let at = t0 + ESTIMATION_SHARE * (last - t0);
    let estimation = data.times.partition_point(|&t| t < at);
    (estimation >= MIN_PART && data.times.len() - estimation >= MIN_PART).then_some(at)
}

/// `r` refitted on `estimation` from its optimum (one start), and its prediction errors
/// over `data` from sample `held` on.
fn held_errors(
    estimation: &FitData,
    data: &FitData,
    held: usize,
    r: &FitReport,
) -> Option<Vec<f64>> {
    let options = FitOptions {
        starts: 1,
        screen: true,
        ..FitOptions::default()
    };
    let refit = search_fit(estimation, r.model.structure, r.model.values, &options).ok()?;
    let residuals = refit.residuals(data).ok()?;
    let tail = residuals.get(held..)?.to_vec();
    tail.iter().all(|e| e.is_finite()).then_some(tail)
}

/// The hold-out of one current model on one record: the split, and the current model's
/// refit and prediction errors, made once, for every candidate a step compares with it;
/// each candidate's, made once however often the step asks (its paying candidates first,
/// then its leader, which may be one of them).
pub struct Validation<'a> {
    data: &'a FitData,
    current: &'a FitReport,
    base: std::sync::OnceLock<Option<Base>>,
    candidates: std::sync::Mutex<Vec<(Model, Option<Vec<f64>>)>>,
}

/// What [`Validation`] keeps of the current model's hold-out.
struct Base {
    estimation: FitData,
    held: usize,
    current: Vec<f64>,
}

impl<'a> Validation<'a> {
    pub fn new(data: &'a FitData, current: &'a FitReport) -> Self {
        Self {
            data,
            current,
            base: std::sync::OnceLock::new(),
            candidates: std::sync::Mutex::new(Vec::new()),
        }
    }

    /// Both models refitted on the estimation part and compared on the held-out one;
    /// `None` when the record is too short to split or a refit fails (no evidence either
    /// way). The first call makes the two refits at once, one on each core.
    pub fn hold_out(&self, candidate: &FitReport) -> Option<HoldOut> {
        let mut fresh = None;
        let base = self.base.get_or_init(|| {
            let at = split(self.data)?;
            let keep: Vec<bool> = self.data.times.iter().map(|&t| t < at).collect();
            let estimation = self.data.keeping(&keep);
            let held = self.data.times.partition_point(|&t| t < at);
            let mut both = crate::parallel::map(&[self.current, candidate], |r| {
                held_errors(&estimation, self.data, held, r)
            });
            fresh = Some(both.pop().flatten());
            let current = both.pop().flatten()?;
            Some(Base {
                estimation,
                held,
                current,
            })
        });
        let base = base.as_ref()?;
        let model = candidate.model;
        let known = self.known(&model);
        let errors = match (fresh, known) {
            (Some(errors), _) | (None, Some(errors)) => errors,
            (None, None) => held_errors(&base.estimation, self.data, base.held, candidate),
        };
        if let Ok(mut list) = self.candidates.lock()
            && !list.iter().any(|(m, _)| *m == model)
        {
            list.push((model, errors.clone()));
        }
        let candidate = errors?;
        Some(HoldOut {
            current: mean_square(&base.current),
            candidate: mean_square(&candidate),
            noise: difference_noise(&self.data.y).powi(2),
            samples: base.current.len(),
        })
    }

    /// The held-out errors of a candidate already compared (`None` if it was not).
    fn known(&self, model: &Model) -> Option<Option<Vec<f64>>> {
        let list = self.candidates.lock().ok()?;
        list.iter()
            .find(|(m, _)| m == model)
            .map(|(_, e)| e.clone())
    }

    /// Whether `candidate` may replace the current model by the hold-out: true when it
    /// predicts the held-out part about as well or better, or when the record cannot be
    /// split.
    pub fn keeps(&self, candidate: &FitReport) -> bool {
        self.hold_out(candidate).is_none_or(|h| h.keeps_candidate())
    }
}

/// The mean of the squares of `v`, in units of its largest value, so that errors of 1e200
/// do not overflow a square.
fn mean_square(v: &[f64]) -> f64 {
    let unit = v.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    if unit == 0.0 {
        return 0.0;
    }
    let mean = v.iter().map(|e| (e / unit).powi(2)).sum::<f64>() / v.len() as f64;
    mean * unit * unit
}

/// [`Validation::hold_out`] of one candidate.
pub fn hold_out(data: &FitData, current: &FitReport, candidate: &FitReport) -> Option<HoldOut> {
    Validation::new(data, current).hold_out(candidate)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::fit;
    use crate::model::excitation::{Excitation, Hold};
    use crate::model::{Model, Param, Structure, Values};
    use crate::random::Lcg;

    /// ECAM's MV test as a process with a slow second lag: 30 → 70 at 10 s, back to 30 at
    /// 316 s, 480 samples, noise ± 0.1.
    fn record() -> FitData {
        let times: Vec<f64> = (0..480).map(f64::from).collect();
        let u: Vec<f64> = times
            .iter()
            .map(|&t| {
                if (10.0..316.0).contains(&t) {
                    70.0
                } else {
                    30.0
                }
            })
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        let v = Values::from_pairs(&[
            (Param::Kp, 0.56),
            (Param::Tp1, 150.0),
            (Param::Tp2, 12.0),
            (Param::Y0, 40.2),
        ]);
        let truth = Model::new(Structure::parse("P2").unwrap(), v);
        let mut rng = Lcg(3);
        let y = truth
            .simulate(&input, &times)
            .unwrap()
            .into_iter()
            .map(|y| y + 0.1 * rng.symmetric())
            .collect();
        FitData { times, y, input }
    }

    fn fitted(data: &FitData, code: &str, from: Values) -> FitReport {
        let options = FitOptions {
            starts: 4,
            ..FitOptions::default()
        };
        fit(
            data,
            Structure::parse(code).unwrap(),
            from,
            &options,
            &mut (),
        )
        .unwrap()
    }

    #[test]
    fn a_drift_bought_on_the_fitted_part_predicts_the_rest_badly_and_a_pole_does_not() {
        let data = record();
        let from = Values::from_pairs(&[
            (Param::Kp, 0.5),
            (Param::Tp1, 100.0),
            (Param::Tp2, 5.0),
            (Param::Y0, 40.2),
        ]);
        let current = fitted(&data, "P1", from);
        let pole = fitted(&data, "P2", from);
        let pole_hold = hold_out(&data, &current, &pole).expect("splits");
        assert!(pole_hold.keeps_candidate(), "{pole_hold:?}");
        // A drift fitted on the record trades with the slow lag on the part it saw, and
        // extrapolates past the second change.
        let mut drift = Structure::parse("P1").unwrap();
        drift.drift = true;
        let mut d = current.model.values;
        d.set(Param::Drift, 0.01);
        let options = FitOptions {
            starts: 1,
            ..FitOptions::default()
        };
        let with_drift = fit(&data, drift, d, &options, &mut ()).unwrap();
        let drift_hold = hold_out(&data, &current, &with_drift).expect("splits");
        assert!(drift_hold.candidate > drift_hold.current, "{drift_hold:?}");
        assert!(!drift_hold.keeps_candidate(), "{drift_hold:?}");
        assert_eq!(drift_hold.samples, 141);
        // One validation compares both, each once however often it is asked, and says
        // what a fresh one says.
        let validation = Validation::new(&data, &current);
        for _ in 0..2 {
            assert_eq!(validation.hold_out(&pole), Some(pole_hold));
            assert_eq!(validation.hold_out(&with_drift), Some(drift_hold));
        }
        assert_eq!(validation.candidates.lock().map(|l| l.len()).ok(), Some(2));
    }

    #[test]
    fn a_record_too_short_to_split_is_no_evidence() {
        let mut data = record();
        data.times.truncate(30);
        data.y.truncate(30);
        assert_eq!(split(&data), None);
    }
}
