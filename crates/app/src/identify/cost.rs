//! The cost landscape's state: which two parameters span it, how far around the fit, the
//! background job that computes the MSE over the grid, and its result. No egui here; the
//! window that shows it is [`super::landscape`].

use crate::job::{Job, Waker};
use degrau_ident::fit::landscape::{self, Axis, Landscape};
use degrau_ident::fit::{FitData, FitReport};
use degrau_ident::model::Param;

use super::commands::LandscapeCommand;

/// Grid points per axis.
pub const RESOLUTION: usize = 60;

/// The spread a new window starts with.
const DEFAULT_SPREAD: f64 = 3.0;

/// The landscape window's state.
pub struct LandscapeState {
    pub open: bool,
    job: Option<Job<(usize, usize), Option<Landscape>>>,
    pub result: Option<Landscape>,
    /// The chosen axes (none: the default pair of the fit).
    pub axes: Option<(Axis, Axis)>,
    /// How far around the fit each axis reaches (×/÷ for log axes).
    pub spread: f64,
}

impl Default for LandscapeState {
    fn default() -> Self {
        Self {
            open: false,
            job: None,
            result: None,
            axes: None,
            spread: DEFAULT_SPREAD,
        }
    }
}

impl LandscapeState {
    /// Drops the result and any running job: the fit they were about is gone.
    pub fn forget(&mut self) {
        if let Some(j) = self.job.take() {
            j.cancel();
        }
        self.result = None;
        self.axes = None;
    }

    pub fn is_computing(&self) -> bool {
        self.job.is_some()
    }

    /// Rows done and total, while computing.
    pub fn progress(&self) -> Option<(usize, usize)> {
        self.job
            .as_ref()
            .map(|j| j.progress.unwrap_or((0, RESOLUTION)))
    }

    /// Takes a finished result.
    pub fn poll(&mut self) {
        if let Some(job) = self.job.as_mut()
            && let Some(result) = job.poll()
        {
            self.result = result;
            self.job = None;
        }
    }

    /// The axes shown for `report`: the chosen pair or the default one.
    pub fn axes_for(&self, report: &FitReport) -> (Axis, Axis) {
        self.axes
            .or_else(|| default_axes(report))
            .unwrap_or((Axis::Param(Param::Kp), Axis::Param(Param::Kp)))
    }

    /// Carries out a command; `fit` is the report and data the landscape is drawn around.
    pub fn apply(
        &mut self,
        command: LandscapeCommand,
        fit: Option<(&FitReport, &FitData)>,
        waker: Option<Waker>,
    ) {
        match command {
            LandscapeCommand::Open => self.open = true,
            LandscapeCommand::Close => self.open = false,
            LandscapeCommand::Axes(x, y) => self.axes = Some((x, y)),
            LandscapeCommand::Spread(s) if s.is_finite() => self.spread = s.clamp(1.2, 50.0),
            LandscapeCommand::Spread(_) => {}
            LandscapeCommand::Compute => {
                if let (Some((report, data)), None) = (fit, &self.job) {
                    self.start(report, data, waker);
                }
            }
            LandscapeCommand::Cancel => {
                if let Some(j) = &self.job {
                    j.cancel();
                }
            }
        }
    }

    fn start(&mut self, report: &FitReport, data: &FitData, waker: Option<Waker>) {
        let (x, y) = self.axes_for(report);
        let v = report.model.values;
        let (xr, yr) = (
            range(x, x.value(&v), self.spread),
            range(y, y.value(&v), self.spread),
        );
        let xs = landscape::grid(xr.0, xr.1, RESOLUTION, x.logarithmic());
        let ys = landscape::grid(yr.0, yr.1, RESOLUTION, y.logarithmic());
        let (data, model) = (data.clone(), report.model);
        self.job = Some(Job::spawn(waker, move |job| {
            landscape::compute(&data, &model, (x, xs), (y, ys), &mut |done, total| {
                job.report((done, total));
                job.cancelled()
            })
        }));
    }
}

/// The axes offered for a model: its parameters, with ωn instead of Tw.
pub fn axes_offered(report: &FitReport) -> Vec<Axis> {
    report
        .params
        .iter()
        .filter(|e| !matches!(e.param, Param::Y0 | Param::Drift))
        .map(|e| {
            if e.param == Param::Tw {
                Axis::NaturalFrequency
            } else {
                Axis::Param(e.param)
            }
        })
        .collect()
}

/// The default pair: ζ and ωn for an underdamped model (the notes' Figure 4), else the
/// first two parameters.
fn default_axes(report: &FitReport) -> Option<(Axis, Axis)> {
    let axes = axes_offered(report);
    if axes.contains(&Axis::NaturalFrequency) && axes.contains(&Axis::Param(Param::Zeta)) {
        return Some((Axis::Param(Param::Zeta), Axis::NaturalFrequency));
    }
    Some((*axes.first()?, *axes.get(1).or(axes.first())?))
}

/// The range shown along an axis around the fitted value.
fn range(axis: Axis, value: f64, spread: f64) -> (f64, f64) {
    match axis {
        Axis::Param(Param::Zeta) => (0.005, (value * spread).clamp(1.0, 2.0)),
        Axis::Param(Param::Td) => (0.0, value * spread.max(1.5) + 1e-3),
        _ if axis.logarithmic() => (value / (4.0 * spread), value * 8.0 * spread),
        _ => {
            let half = value.abs().max(1e-6) * (spread - 1.0).max(0.5);
            (value - half, value + half)
        }
    }
}

/// Where a value sits on the plot: log10 for logarithmic axes.
pub fn coordinate(axis: Axis, v: f64) -> f64 {
    if axis.logarithmic() { v.log10() } else { v }
}
