//! The cost-landscape window: the MSE as a heat map over two parameters (the others held at
//! the fit), the optimiser's path drawn on it and the local minima marked, computed off the
//! UI thread (see [`super::cost`]) with progress and a cancel button. It reads the session
//! and returns commands.

use eframe::egui::{self, Ui};
use egui_plot::{Heatmap, Line, MarkerShape, Plot, PlotPoint, Points};

use crate::look::Look;
use crate::words::identify::Phrase;
use degrau_ident::fit::FitReport;
use degrau_ident::fit::landscape::{Axis, Landscape};
use degrau_lti::number::sig;

use super::commands::{Command, LandscapeCommand};
use super::cost::{axes_offered, coordinate};
use super::session::Session;

fn axis_label(axis: Axis) -> String {
    if axis.logarithmic() {
        format!("log10 {}", axis.name())
    } else {
        axis.name()
    }
}

/// Draws the window when it is open.
pub fn show(ctx: &egui::Context, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let state = &session.landscape;
    if !state.open {
        return;
    }
    let mut open = true;
    egui::Window::new(Phrase::LandscapeTitle.get(look.lang))
        .id(egui::Id::unique("cost landscape window"))
        .open(&mut open)
        .default_size([520.0, 480.0])
        .show(ctx, |ui| match &session.report {
            Some(r) if session.fitted.is_some() => contents(ui, session, r, look, out),
            _ => {
                ui.label(Phrase::FitFirst.get(look.lang));
            }
        });
    if !open {
        out.push(Command::Landscape(LandscapeCommand::Close));
    }
}

fn contents(
    ui: &mut Ui,
    session: &Session,
    report: &FitReport,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    let state = &session.landscape;
    let offered = axes_offered(report);
    let (x, y) = state.axes_for(report);
    ui.horizontal_wrapped(|ui| {
        let (mut nx, mut ny) = (x, y);
        for (label, a) in [("x", &mut nx), ("y", &mut ny)] {
            egui::ComboBox::from_label(label)
                .selected_text(a.name())
                .show_ui(ui, |ui| {
                    for &candidate in &offered {
                        ui.selectable_value(a, candidate, candidate.name());
                    }
                });
        }
        if (nx, ny) != (x, y) {
            out.push(Command::Landscape(LandscapeCommand::Axes(nx, ny)));
        }
        let mut spread = state.spread;
        if ui
            .add(
                egui::DragValue::new(&mut spread)
                    .range(1.2..=50.0)
                    .speed(0.05)
                    .prefix(Phrase::Spread.get(lang)),
            )
            .changed()
        {
            out.push(Command::Landscape(LandscapeCommand::Spread(spread)));
        }
    });
    ui.horizontal_wrapped(|ui| {
        if let Some((done, total)) = state.progress() {
            ui.add(
                egui::ProgressBar::new(done as f32 / total.max(1) as f32)
                    .desired_width(200.0)
                    .text(Phrase::RowOf.with(lang, &[done.to_string(), total.to_string()])),
            );
            if ui.button(Phrase::Cancel.get(lang)).clicked() {
                out.push(Command::Landscape(LandscapeCommand::Cancel));
            }
        } else if ui.button(Phrase::Compute.get(lang)).clicked() {
            out.push(Command::Landscape(LandscapeCommand::Compute));
        }
    });
    if let Some(l) = &state.result {
        draw(ui, l, report, look);
    }
}

fn draw(ui: &mut Ui, l: &Landscape, report: &FitReport, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
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
    let lowest = l
        .minimum()
        .map_or(Phrase::NoInterval.get(lang).to_string(), |m| sig(m.2, 4));
    ui.label(Phrase::LandscapeSummary.with(
        lang,
        &[
            l.x_axis.name(),
            l.y_axis.name(),
            minima.len().to_string(),
            lowest,
        ],
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
            let path_name = Phrase::OptimiserPath.get(lang);
            plot.line(
                Line::new(path_name, path.clone())
                    .color(palette.path)
                    .width(1.5),
            );
            plot.points(Points::new(path_name, path).color(palette.path).radius(2.0));
            plot.points(
                Points::new(Phrase::LocalMinima.get(lang), minima)
                    .shape(MarkerShape::Cross)
                    .color(palette.minimum)
                    .radius(5.0),
            );
            plot.points(
                Points::new(Phrase::TheFit.get(lang), vec![fit])
                    .shape(MarkerShape::Diamond)
                    .color(palette.fit_point)
                    .radius(6.0),
            );
        });
}
