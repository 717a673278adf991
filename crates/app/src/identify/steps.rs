//! The input changes of a record in the Identify mode, with no egui in it: the input plot's
//! data (u(t) as the model sees it, each change and the span of the response it starts),
//! the per-step fits run as a background job with progress and cancel, and the comparison
//! of each step's own values with the joint fit's (which differ beyond their 95 % intervals:
//! a first hint of nonlinearity). The views are [`super::plot`] and [`super::panel`].

use crate::job::{Context, Job, Waker};
pub use degrau_ident::diagnose::per_step::{
    Agreement, Difference, RESOLVED_SHARE, agreement, compared_params,
};
use degrau_ident::diagnose::per_step::{StepFit, fit_change};
use degrau_ident::fit::{FitData, FitObserver, FitOptions, Progress};
use degrau_ident::model::Structure;
use degrau_ident::model::excitation::{Excitation, InputChange};

/// The input plot's data, derived from the fit data (rebuilt with them, never per frame).
#[derive(Debug, Clone, Default)]
pub struct InputPlot {
    /// u(t) as the model sees it (input units): a staircase with a zero-order hold, straight
    /// lines between samples with a first-order hold.
    pub curve: Vec<[f64; 2]>,
    /// The significant changes, in order.
    pub changes: Vec<InputChange>,
    /// Each change's response span (s): from its instant to the next change's, or to the
    /// end of the samples.
    pub spans: Vec<(f64, f64)>,
    /// The curve's range (input units).
    pub range: (f64, f64),
}

/// The input plot for `data`'s input over its samples.
pub fn input_plot(data: &FitData) -> InputPlot {
    let input = &data.input;
    let (Some(&first), Some(&last)) = (data.times.first(), data.times.last()) else {
        return InputPlot::default();
    };
    let curve = if input.ramps.is_empty() {
        staircase(input, first, last)
    } else {
        lines(input, &data.times)
    };
    let spans = input
        .changes
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let end = input.changes.get(k + 1).map_or(last, |next| next.t);
            (c.t, end.max(c.t))
        })
        .collect();
    let range = curve
        .iter()
        .map(|p| p[1])
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    InputPlot {
        curve,
        changes: input.changes.clone(),
        spans,
        range: if range.0 <= range.1 {
            range
        } else {
            (0.0, 1.0)
        },
    }
}

/// The zero-order-hold input from `first` to `last` (s): its level, and a vertical jump at
/// each step.
fn staircase(input: &Excitation, first: f64, last: f64) -> Vec<[f64; 2]> {
    let before: f64 = input
        .steps
        .iter()
        .take_while(|s| s.t < first)
        .map(|s| s.du)
        .sum();
    let mut level = input.u0 + before;
    let start = first.min(input.t0());
    let mut curve = vec![[start, level]];
    for s in input.steps.iter().filter(|s| s.t >= first && s.t <= last) {
        curve.push([s.t, level]);
        level += s.du;
        curve.push([s.t, level]);
    }
    curve.push([last, level]);
    curve
}

/// The first-order-hold input at each sample instant (straight lines between them), in one
/// pass: Σ steps + Σ slope·(t − t_ramp) kept as a running slope and offset.
fn lines(input: &Excitation, times: &[f64]) -> Vec<[f64; 2]> {
    let (mut steps, mut ramps) = (input.steps.iter().peekable(), input.ramps.iter().peekable());
    let (mut level, mut slope, mut offset) = (input.u0, 0.0, 0.0);
    let mut curve = Vec::with_capacity(times.len() + 1);
    if let (Some(&first), Some(s)) = (times.first(), input.steps.first())
        && s.t <= first
    {
        curve.push([first, input.u0]);
    }
    for &t in times {
        while let Some(s) = steps.next_if(|s| s.t <= t) {
            level += s.du;
        }
        while let Some(r) = ramps.next_if(|r| r.t <= t) {
            slope += r.du;
            offset += r.du * r.t;
        }
        curve.push([t, level + slope * t - offset]);
    }
    curve
}

/// What a per-step job reports: the change being fitted (0-based) and how many there are.
pub type StepProgress = (usize, usize);

type PerStepJob = Job<StepProgress, Option<Vec<StepFit>>>;

/// The per-step fits: the job that runs them, their result, whether they were cancelled.
#[derive(Default)]
pub struct PerStepState {
    job: Option<PerStepJob>,
    /// Each change's own fit, once the job is done.
    pub fits: Option<Vec<StepFit>>,
    /// The last job was cancelled (its fits are not shown).
    pub cancelled: bool,
}

impl PerStepState {
    /// Starts the fits of every change of `data` with `structure`'s process model (none for
    /// a record with one change). A running job is cancelled first.
    pub fn start(
        &mut self,
        data: FitData,
        structure: Structure,
        options: FitOptions,
        waker: Option<Waker>,
    ) {
        self.forget();
        if !data.input.is_multi_step() {
            return;
        }
        self.job = Some(Job::spawn(waker, move |job| {
            let n = data.input.changes.len();
            let mut fits = Vec::with_capacity(n);
            for k in 0..n {
                if job.cancelled() {
                    return None;
                }
                job.report((k, n));
                fits.extend(fit_change(&data, k, structure, &options, &mut Stop(job)));
            }
            Some(fits)
        }));
    }

    /// Cancels a running job (what it fitted is not shown).
    pub fn cancel(&mut self) {
        if let Some(j) = self.job.take() {
            j.cancel();
            self.cancelled = true;
        }
    }

    /// Drops the fits and any running job: the data or choices they were about changed.
    pub fn forget(&mut self) {
        if let Some(j) = self.job.take() {
            j.cancel();
        }
        self.fits = None;
        self.cancelled = false;
    }

    /// Takes the job's news.
    pub fn poll(&mut self) {
        let Some(result) = self.job.as_mut().and_then(|j| j.poll()) else {
            return;
        };
        self.job = None;
        match result {
            Some(fits) => self.fits = Some(fits),
            None => self.cancelled = true,
        }
    }

    pub fn is_running(&self) -> bool {
        self.job.is_some()
    }

    /// The change being fitted and how many there are, while the job runs.
    pub fn progress(&self) -> Option<StepProgress> {
        let job = self.job.as_ref()?;
        Some(job.progress.unwrap_or((0, 0)))
    }
}

/// Stops a per-step fit when its job is cancelled.
struct Stop<'a>(&'a Context<StepProgress, Option<Vec<StepFit>>>);

impl FitObserver for Stop<'_> {
    fn progress(&mut self, _: &Progress) {}
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_ident::fit::guess::auto_guess;
    use degrau_ident::fit::{FitReport, fit};
    use degrau_ident::model::Param;
    use degrau_ident::model::excitation::Hold;

    fn record(hold: Hold) -> FitData {
        let times: Vec<f64> = (0..10).map(f64::from).collect();
        let u = [1.0, 1.0, 3.0, 3.0, 3.0, 2.0, 2.0, 2.0, 2.0, 2.0];
        let input = Excitation::measured(&times, &u, None, hold).unwrap();
        FitData {
            y: vec![0.0; times.len()],
            times,
            input,
        }
    }

    #[test]
    fn a_held_input_is_a_staircase_with_a_span_per_change() {
        let p = input_plot(&record(Hold::Zoh));
        assert_eq!(
            p.curve,
            vec![
                [0.0, 1.0],
                [2.0, 1.0],
                [2.0, 3.0],
                [5.0, 3.0],
                [5.0, 2.0],
                [9.0, 2.0]
            ]
        );
        assert_eq!(p.changes.len(), 2);
        assert_eq!(p.spans, vec![(2.0, 5.0), (5.0, 9.0)]);
        assert_eq!(p.range, (1.0, 3.0));
        // The change at t = 2 s may have happened from the previous sample on.
        assert_eq!(p.changes[0].earliest, 1.0);
    }

    #[test]
    fn a_first_order_hold_goes_through_every_sample() {
        let data = record(Hold::Foh);
        let u = [1.0, 1.0, 3.0, 3.0, 3.0, 2.0, 2.0, 2.0, 2.0, 2.0];
        let p = input_plot(&data);
        let expected: Vec<[f64; 2]> = data.times.iter().zip(u).map(|(t, u)| [*t, u]).collect();
        assert_eq!(p.curve.len(), expected.len());
        for (a, b) in p.curve.iter().zip(&expected) {
            assert!(
                (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-9,
                "{a:?} {b:?}"
            );
        }
    }

    /// A heater whose gain grows with its level (0.5 per unit at first, 1.5 at the top):
    /// the per-step fits disagree with the joint one, a linear one agrees.
    fn stepped(gain_of_level: impl Fn(f64) -> f64) -> (FitReport, Vec<StepFit>, f64) {
        use degrau_ident::model::{Model, Values};
        let times: Vec<f64> = (0..400).map(|k| 0.5 * k as f64).collect();
        let levels = [(0.0, 1.0), (20.0, 3.0), (70.0, 5.0), (120.0, 2.0)];
        let u: Vec<f64> = times
            .iter()
            .map(|&t| levels.iter().rev().find(|l| l.0 <= t).map_or(1.0, |l| l.1))
            .collect();
        let input = Excitation::measured(&times, &u, None, Hold::Zoh).unwrap();
        let structure = Structure::parse("P1").unwrap();
        // Each change's response with the gain of the level it goes to.
        let mut y = vec![10.0; times.len()];
        for c in &input.changes {
            let mut v = Values::default();
            v.set(Param::Kp, gain_of_level(c.u_before + c.du));
            v.set(Param::Tp1, 6.0);
            let one = Model::new(structure, v);
            let part = one.simulate(&Excitation::step(c.t, c.du), &times).unwrap();
            y.iter_mut().zip(part).for_each(|(y, p)| *y += p);
        }
        let data = FitData { times, y, input };
        let options = FitOptions::default();
        let joint = fit(
            &data,
            structure,
            auto_guess(&data, structure, None),
            &options,
            &mut (),
        )
        .unwrap();
        let fits = degrau_ident::diagnose::per_step::per_step_fits(&data, structure, &options);
        (joint, fits, data.sampling_period())
    }

    #[test]
    fn a_gain_that_changes_with_the_level_is_named_a_linear_one_is_not() {
        let (joint, fits, ts) = stepped(|_| 0.8);
        assert_eq!(agreement(&joint, &fits, ts), Agreement::Agree);
        let (joint, fits, ts) = stepped(|level| 0.5 + 0.2 * level);
        let Agreement::Differ(list) = agreement(&joint, &fits, ts) else {
            panic!("a nonlinear gain agrees");
        };
        assert!(list.iter().any(|d| d.param == Param::Kp), "{list:?}");
    }

    #[test]
    fn the_ideal_step_is_one_jump_from_zero() {
        let data = FitData {
            times: vec![0.0, 1.0, 2.0, 3.0],
            y: vec![0.0; 4],
            input: Excitation::step(1.5, 10.0),
        };
        let p = input_plot(&data);
        assert_eq!(
            p.curve,
            vec![[0.0, 0.0], [1.5, 0.0], [1.5, 10.0], [3.0, 10.0]]
        );
        assert_eq!(p.spans, vec![(1.5, 3.0)]);
    }
}
