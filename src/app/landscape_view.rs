//! The cost-landscape window: the MSE as a heat map over two parameters (the others held at
//! the fit), the optimiser's path drawn on it and the local minima marked, computed off the
//! UI thread with progress and a cancel button.

use eframe::egui::{self, Color32, Ui};
use egui_plot::{Heatmap, Line, MarkerShape, Plot, PlotPoint, Points};

use crate::app::job::Job;
use crate::ident::fit::{FitData, FitReport};
use crate::ident::landscape::{self, Axis, Landscape};
use crate::ident::models::Param;
use crate::lti::number::sig;

/// Grid points per axis.
const RESOLUTION: usize = 60;

/// The window's state.
#[derive(Default)]
pub struct LandscapeView {
    pub open: bool,
    job: Option<Job<(usize, usize), Option<Landscape>>>,
    pub result: Option<Landscape>,
    axes: Option<(Axis, Axis)>,
    /// Range factors: how far around the fit each axis reaches (×/÷ for log axes).
    pub spread: f64,
}

/// The axes offered for a model: its parameters, with ωn instead of Tw.
fn axes_for(report: &FitReport) -> Vec<Axis> {
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
    let axes = axes_for(report);
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
fn coordinate(axis: Axis, v: f64) -> f64 {
    if axis.logarithmic() { v.log10() } else { v }
}

fn axis_label(axis: Axis) -> String {
    if axis.logarithmic() {
        format!("log10 {}", axis.name())
    } else {
        axis.name()
    }
}

impl LandscapeView {
    /// Draws the window when open.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        report: Option<&FitReport>,
        data: Option<&FitData>,
    ) {
        if let Some(job) = self.job.as_mut()
            && let Some(result) = job.poll()
        {
            self.result = result;
            self.job = None;
        }
        let mut open = self.open;
        egui::Window::new("Cost landscape")
            .open(&mut open)
            .default_size([520.0, 480.0])
            .show(ctx, |ui| match (report, data) {
                (Some(r), Some(d)) => self.contents(ui, r, d),
                _ => {
                    ui.label("Fit a model first: the landscape is drawn around the fit.");
                }
            });
        self.open = open;
    }

    fn contents(&mut self, ui: &mut Ui, report: &FitReport, data: &FitData) {
        if self.spread < 1.0 {
            self.spread = 3.0;
        }
        let axes = axes_for(report);
        let (mut x, mut y) = self
            .axes
            .or_else(|| default_axes(report))
            .unwrap_or((Axis::Param(Param::Kp), Axis::Param(Param::Kp)));
        ui.horizontal(|ui| {
            for (label, a) in [("x", &mut x), ("y", &mut y)] {
                egui::ComboBox::from_label(label)
                    .selected_text(a.name())
                    .show_ui(ui, |ui| {
                        for &candidate in &axes {
                            ui.selectable_value(a, candidate, candidate.name());
                        }
                    });
            }
            ui.add(
                egui::DragValue::new(&mut self.spread)
                    .range(1.2..=50.0)
                    .speed(0.05)
                    .prefix("spread ×"),
            );
        });
        self.axes = Some((x, y));
        ui.horizontal(|ui| {
            if let Some(job) = &self.job {
                let (done, total) = job.progress.unwrap_or((0, RESOLUTION));
                ui.add(
                    egui::ProgressBar::new(done as f32 / total.max(1) as f32)
                        .desired_width(200.0)
                        .text(format!("row {done} of {total}")),
                );
                if ui.button("Cancel").clicked() {
                    job.cancel();
                }
            } else if ui.button("Compute").clicked() {
                self.start(ui.ctx().clone(), report, data, x, y);
            }
        });
        if let Some(l) = &self.result {
            draw(ui, l, report);
        }
    }

    fn start(&mut self, ctx: egui::Context, report: &FitReport, data: &FitData, x: Axis, y: Axis) {
        let v = report.model.values;
        let (xr, yr) = (
            range(x, x.value(&v), self.spread),
            range(y, y.value(&v), self.spread),
        );
        let xs = landscape::grid(xr.0, xr.1, RESOLUTION, x.logarithmic());
        let ys = landscape::grid(yr.0, yr.1, RESOLUTION, y.logarithmic());
        let (data, model) = (data.clone(), report.model);
        self.job = Some(Job::spawn(Some(ctx), move |job| {
            landscape::compute(&data, &model, (x, xs), (y, ys), &mut |done, total| {
                job.report((done, total));
                job.cancelled()
            })
        }));
    }
}

fn draw(ui: &mut Ui, l: &Landscape, report: &FitReport) {
    let (nx, ny) = (l.xs.len(), l.ys.len());
    if nx < 2 || ny < 2 {
        return;
    }
    let finite_max = l
        .cost
        .iter()
        .copied()
        .filter(|c| c.is_finite())
        .fold(f64::MIN_POSITIVE, f64::max);
    // The heat map's first row is its bottom one (lowest y), as our grid's.
    let mut values = Vec::with_capacity(nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            let c = l.cost[j * nx + i];
            values.push(if c.is_finite() {
                c.max(f64::MIN_POSITIVE).log10()
            } else {
                finite_max.log10()
            });
        }
    }
    let (x0, x1) = (
        coordinate(l.x_axis, l.xs[0]),
        coordinate(l.x_axis, l.xs[nx - 1]),
    );
    let (y0, y1) = (
        coordinate(l.y_axis, l.ys[0]),
        coordinate(l.y_axis, l.ys[ny - 1]),
    );
    let (dx, dy) = ((x1 - x0) / (nx - 1) as f64, (y1 - y0) / (ny - 1) as f64);
    let path: Vec<[f64; 2]> = report
        .path
        .iter()
        .map(|v| {
            [
                coordinate(l.x_axis, l.x_axis.value(v)),
                coordinate(l.y_axis, l.y_axis.value(v)),
            ]
        })
        .collect();
    let minima: Vec<[f64; 2]> = l
        .local_minima()
        .iter()
        .map(|m| [coordinate(l.x_axis, m.0), coordinate(l.y_axis, m.1)])
        .collect();
    let fit = [
        coordinate(l.x_axis, l.x_axis.value(&report.model.values)),
        coordinate(l.y_axis, l.y_axis.value(&report.model.values)),
    ];
    ui.label(format!(
        "log10 MSE over {} × {}; {} local minima on the grid; lowest MSE on the grid {}",
        l.x_axis.name(),
        l.y_axis.name(),
        minima.len(),
        l.minimum().map_or("none".into(), |m| sig(m.2, 4))
    ));
    Plot::new("landscape")
        .x_axis_label(axis_label(l.x_axis))
        .y_axis_label(axis_label(l.y_axis))
        .show(ui, |plot| {
            plot.heatmap(
                Heatmap::new(values, nx)
                    .at(PlotPoint::new(x0 - dx / 2.0, y0 - dy / 2.0))
                    .tile_size(dx as f32, dy as f32)
                    .show_labels(false)
                    .name("log10 MSE"),
            );
            plot.line(
                Line::new("optimiser path", path.clone())
                    .color(Color32::WHITE)
                    .width(1.5),
            );
            plot.points(
                Points::new("optimiser path", path)
                    .color(Color32::WHITE)
                    .radius(2.0),
            );
            plot.points(
                Points::new("local minima", minima)
                    .shape(MarkerShape::Cross)
                    .color(Color32::LIGHT_RED)
                    .radius(5.0),
            );
            plot.points(
                Points::new("fit", vec![fit])
                    .shape(MarkerShape::Diamond)
                    .color(Color32::YELLOW)
                    .radius(6.0),
            );
        });
}
