//! The Identify mode's hand methods, as state (no egui): whether the construction is drawn,
//! which method, what the student moved on it (the tangent's point, the two levels), every
//! method's result on the fit data ([`crate::ident::hand`]), and the least-squares fits of
//! the matching structures (P1D, P2D) they are compared with, run off the UI thread.

use crate::app::job::{Job, Waker};
use crate::ident::experiment::Experiment;
use crate::ident::fit::{FitData, FitOptions, FitReport};
use crate::ident::hand::{
    DeadTimeFrom, HandError, HandEstimate, HandMethod, Overrides, Record, estimate_all,
};

/// The structures the hand methods are compared with.
pub const COMPARED: [&str; 2] = ["P1D", "P2D"];

/// What the hand-methods section asks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HandCommand {
    /// Draw the construction on the plot (and compute the table), or not.
    Show(bool),
    Method(HandMethod),
    /// The tangent's point to the curve at this time (s).
    MoveTangent(f64),
    /// The initial level y0 (output units).
    SetInitialLevel(f64),
    /// The final level y∞ (output units).
    SetFinalLevel(f64),
    DeadTimeFrom(DeadTimeFrom),
    /// Back to the steepest rise and the measured levels.
    Reset,
}

type LeastSquaresJob = Job<(), Vec<FitReport>>;

/// The hand methods' state.
#[derive(Default)]
pub struct HandState {
    pub shown: bool,
    pub method: Option<HandMethod>,
    pub overrides: Overrides,
    /// Every method's result, in [`HandMethod::ALL`]'s order.
    pub results: Vec<(HandMethod, Result<HandEstimate, HandError>)>,
    /// Why the record cannot be read by hand at all.
    pub refused: Option<HandError>,
    pub least_squares: Vec<FitReport>,
    job: Option<LeastSquaresJob>,
    /// The data revision and operating point the results belong to.
    key: Option<(u64, Option<f64>)>,
    dirty: bool,
}

impl HandState {
    /// The method drawn (the tangent by default).
    pub fn method(&self) -> HandMethod {
        self.method.unwrap_or(HandMethod::Tangent)
    }

    /// The drawn method's result.
    pub fn current(&self) -> Option<&HandEstimate> {
        let method = self.method();
        self.results
            .iter()
            .find(|(m, _)| *m == method)
            .and_then(|(_, r)| r.as_ref().ok())
    }

    /// Whether the least-squares fits are running.
    pub fn is_fitting(&self) -> bool {
        self.job.is_some()
    }

    pub fn apply(&mut self, command: HandCommand) {
        let o = &mut self.overrides;
        match command {
            HandCommand::Show(on) => self.shown = on,
            HandCommand::Method(m) => self.method = Some(m),
            HandCommand::MoveTangent(t) => o.tangent_time = Some(t),
            HandCommand::SetInitialLevel(y) => o.y0 = Some(y),
            HandCommand::SetFinalLevel(y) => o.y_final = Some(y),
            HandCommand::DeadTimeFrom(from) => o.dead_time_from = from,
            HandCommand::Reset => *o = Overrides::default(),
        }
        self.dirty = true;
    }

    /// Reads every method again when the data, the operating point or the construction
    /// changed (only while shown), and starts the least-squares fits of new data.
    pub fn refresh(
        &mut self,
        data: Option<(&FitData, &Experiment)>,
        revision: u64,
        waker: Option<Waker>,
    ) {
        if !self.shown {
            return;
        }
        let y0 = data.and_then(|(d, e)| e.operating_point(d));
        let key = Some((revision, y0));
        let new_data = self.key != key;
        if !(new_data || self.dirty) {
            return;
        }
        if new_data {
            self.overrides = Overrides {
                dead_time_from: self.overrides.dead_time_from,
                ..Overrides::default()
            };
            self.least_squares.clear();
            self.job = data.map(|(d, e)| start_least_squares(d, e, waker));
        }
        self.key = key;
        self.dirty = false;
        let record = match data {
            Some((d, _)) => Record::from_fit_data(d, y0),
            None => {
                self.results.clear();
                return;
            }
        };
        match record {
            Ok(r) => {
                self.refused = None;
                self.results = estimate_all(&r, &self.overrides);
            }
            Err(e) => {
                self.refused = Some(e);
                self.results.clear();
            }
        }
    }

    /// Takes the least-squares fits when done; true while they run.
    pub fn poll(&mut self) -> bool {
        if let Some(job) = self.job.as_mut()
            && let Some(fits) = job.poll()
        {
            self.least_squares = fits;
            self.job = None;
        }
        self.job.is_some()
    }
}

fn start_least_squares(
    data: &FitData,
    experiment: &Experiment,
    waker: Option<Waker>,
) -> LeastSquaresJob {
    let (data, experiment) = (data.clone(), experiment.clone());
    Job::spawn(waker, move |job| {
        COMPARED
            .iter()
            .take_while(|_| !job.cancelled())
            .filter_map(|code| {
                experiment
                    .fit_prepared(&data, code, false, &[], &FitOptions::default(), &mut ())
                    .ok()
            })
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ident::excitation::Excitation;

    #[test]
    fn moving_the_tangent_reads_the_methods_again() {
        let times: Vec<f64> = (0..400).map(|k| k as f64 * 0.5).collect();
        let y: Vec<f64> = times
            .iter()
            .map(|&t| {
                3.0 + if t > 12.0 {
                    2.0 * (1.0 - (-(t - 12.0) / 20.0).exp())
                } else {
                    0.0
                }
            })
            .collect();
        let data = FitData {
            times,
            y,
            input: Excitation::step(10.0, 1.0),
        };
        let mut state = HandState::default();
        state.refresh(None, 0, None);
        assert!(state.results.is_empty());
        state.apply(HandCommand::Show(true));
        // Without an experiment the record's own level before the step is used.
        let record = Record::from_fit_data(&data, None).unwrap();
        state.results = estimate_all(&record, &state.overrides);
        let before = state.current().unwrap().theta;
        state.apply(HandCommand::MoveTangent(40.0));
        state.results = estimate_all(&record, &state.overrides);
        // Later on the concave part the tangent is flatter and meets y0 earlier.
        assert!(state.current().unwrap().theta < before - 1.0);
        state.apply(HandCommand::Reset);
        assert_eq!(state.overrides, Overrides::default());
    }
}
