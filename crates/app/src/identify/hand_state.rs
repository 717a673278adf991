//! The Identify mode's hand methods, as state (no egui): whether the construction is drawn,
//! which method, what the student moved on it (the tangent's point, the two levels), every
//! method's result on the fit data ([`degrau_ident::hand`]), and the least-squares fits of
//! the matching structures ([`degrau_ident::hand::COMPARED`]) they are compared with, run
//! off the UI thread.

use crate::job::{Job, Waker};
use degrau_ident::experiment::Experiment;
use degrau_ident::fit::{FitData, FitReport};
use degrau_ident::hand::{
    DeadTimeFrom, HandError, HandEstimate, HandMethod, Overrides, Record, estimate_all,
    least_squares,
};

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
        least_squares(&data, &experiment, || job.cancelled())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_ident::record::data::StepTest;

    #[test]
    fn the_state_reads_every_method_and_follows_the_student() {
        let time: Vec<f64> = (0..400).map(|k| k as f64 * 0.5).collect();
        let output: Vec<f64> = time
            .iter()
            .map(|&t| {
                3.0 + if t > 12.0 {
                    2.0 * (1.0 - (-(t - 12.0) / 20.0).exp())
                } else {
                    0.0
                }
            })
            .collect();
        let test = StepTest {
            time,
            output,
            input: None,
            time_name: "t".into(),
            output_name: "y".into(),
            input_name: None,
            sampling_period: None,
            notes: vec![],
        };
        let experiment = Experiment::single_step(&test, Some(10.0), Some(1.0), None).unwrap();
        let data = experiment.fit_data(&test).unwrap();
        let mut state = HandState::default();
        // Hidden: nothing is read.
        state.refresh(Some((&data, &experiment)), 1, None);
        assert!(state.results.is_empty() && !state.is_fitting());
        state.apply(HandCommand::Show(true));
        state.refresh(Some((&data, &experiment)), 1, None);
        assert_eq!(state.results.len(), HandMethod::ALL.len());
        let before = state.current().unwrap().theta;
        // θ = 2 s after t0 = 10 s, read by the tangent at the kink.
        assert!((before - 2.0).abs() < 0.3, "{before}");
        // Later on the concave part the tangent is flatter and meets y0 earlier.
        state.apply(HandCommand::MoveTangent(40.0));
        state.refresh(Some((&data, &experiment)), 1, None);
        assert!(state.current().unwrap().theta < before - 1.0);
        state.apply(HandCommand::SetFinalLevel(4.0));
        state.refresh(Some((&data, &experiment)), 1, None);
        assert!((state.current().unwrap().k - 1.0).abs() < 1e-12);
        // New data (a new revision) forget the construction; the fits run and come back.
        state.refresh(Some((&data, &experiment)), 2, None);
        assert_eq!(state.overrides, Overrides::default());
        while state.poll() {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        assert_eq!(state.least_squares.len(), 2);
        assert!(state.least_squares[0].fit_percent > 99.0);
    }
}
