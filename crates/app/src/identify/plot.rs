//! The identification plots: the measured samples, the model (the guess being dragged, the
//! fit animating towards the data, the result, or a row of the diagnosis chain), the
//! measured curve's own step characteristics, draggable handles for the guesses and the step
//! time (their shared parts, with the hand methods', are [`super::grab`]), and the residuals
//! y − ŷ beneath on the same time axis.
//!
//! The axes come from the current curves only and are held still while a handle is dragged
//! (so the handle stays under the pointer); hovering near a curve reads that curve's value at
//! that time (the nearest sample of the data, the model's exact value), not the pointer's
//! coordinates. Everything here reads the session and returns commands.

use eframe::egui::{self, Align2, Id, Pos2, Rect, Sense, Stroke, TextStyle, Ui, Vec2};
use egui_plot::{
    HLine, Legend, Line, LineStyle, MarkerShape, Plot, PlotBounds, PlotPoint, PlotTransform,
    PlotUi, Points, Span, Text, VLine,
};

use crate::look::Look;
use crate::words::identify::Phrase;
use degrau_ident::fit::handles::Handle;
use degrau_lti::words::step::Metric;
use degrau_lti::{StepInfo, StepInfoOptions};

use super::commands::{Command, Frozen, Gesture, MeasuredMarkers};
use super::grab::{GRAB, Over, grab_area, paint_handle};
use super::session::{Session, Shown, nearest_point};
use super::steps::InputPlot;
use super::words;

/// The smallest height of the main plot (px).
pub const MIN_PLOT_HEIGHT: f32 = 200.0;

/// The smallest height of the residual plot (px).
const MIN_RESIDUAL_HEIGHT: f32 = 140.0;

/// The smallest and largest height of the input plot (px).
const INPUT_HEIGHT: (f32, f32) = (80.0, 170.0);

/// At most this many changes are labelled on the plots (more are drawn, unlabelled; each
/// still has its accessible mark).
const LABELLED_CHANGES: usize = 12;

/// How near (px) the pointer must be to a curve for its value to be read.
const READ_DISTANCE: f32 = 24.0;

/// The main plot's id (its `egui_plot::PlotMemory` holds the transform drawn last).
pub fn main_plot_id() -> Id {
    Id::unique("identification main plot")
}

/// The residual plot's id.
pub fn residual_plot_id() -> Id {
    Id::unique("identification residual plot")
}

/// The input plot's id.
pub fn input_plot_id() -> Id {
    Id::unique("identification input plot")
}

/// Draws the marker toggles and both plots into `ui`.
pub fn show(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let Some(loaded) = session.loaded.as_ref() else {
        ui.centered_and_justified(|ui| {
            ui.label(Phrase::NothingLoaded.get(lang));
        });
        return;
    };
    if loaded.data.is_err() {
        ui.label(Phrase::NothingToShow.get(lang));
        return;
    }
    // The measured curve's step characteristics belong to one step.
    if session.input_plot().changes.len() <= 1 {
        marker_controls(ui, session.markers, look, out);
    }
    egui::ScrollArea::vertical()
        .auto_shrink(false)
        .show(ui, |ui| plots(ui, session, look, out));
}

/// The checkboxes of the measured characteristics.
fn marker_controls(ui: &mut Ui, markers: MeasuredMarkers, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.horizontal_wrapped(|ui| {
        ui.label(Phrase::MeasuredMarkers.get(lang));
        let mut m = markers;
        ui.checkbox(&mut m.rise, Phrase::Rise.get(lang));
        ui.checkbox(&mut m.peak, Phrase::Peak.get(lang));
        ui.checkbox(&mut m.settling, Phrase::Settling.get(lang));
        ui.checkbox(&mut m.steady_state, Phrase::FinalLevel.get(lang));
        if m != markers {
            out.push(Command::SetMarkers(m));
        }
    });
}

/// The main plot's share of the height left by the input plot (its area keeps 220 points
/// in a 1156×650 window, 1600×900 at 1.38×).
const MAIN_SHARE: f32 = 0.625;

/// The heights of the main, input and residual plots in `available` px (with three titles
/// of `title` px above them): the input plot gets about 18 % (within [`INPUT_HEIGHT`]), the
/// main plot [`MAIN_SHARE`] of the rest, never less than [`MIN_PLOT_HEIGHT`].
pub fn heights(available: f32, title: f32) -> (f32, f32, f32) {
    let room = (available - 3.0 * title).max(0.0);
    let input = (0.18 * room).clamp(INPUT_HEIGHT.0, INPUT_HEIGHT.1);
    let rest = (room - input).max(0.0);
    let main = (MAIN_SHARE * rest).max(MIN_PLOT_HEIGHT);
    let residual = (rest - main).max(MIN_RESIDUAL_HEIGHT);
    (main, input, residual)
}

fn plots(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let palette = &look.palette;
    let plots = session.plots();
    let frame = session.plot_frame();
    let title = ui.text_style_height(&TextStyle::Body) + 2.0 * ui.spacing().item_spacing.y;
    let (main_height, input_height, residual_height) = heights(ui.available_height() - 8.0, title);
    let input = session.input_plot();
    let measured_drive = session
        .loaded
        .as_ref()
        .is_some_and(|l| l.experiment.drive != degrau_ident::experiment::Drive::Step);
    let shown = session.shown();
    let setup = session.setup();
    let evidence = session.evidence_interval();

    ui.label(Phrase::MeasuredAndModel.get(lang));
    // After a diagnosis the legend lists the regions too: smaller words, in the corner the
    // samples leave most empty.
    let many = session.diagnosis.is_some();
    let response = base_plot(main_plot_id(), main_height, lang)
        .legend(
            Legend::default()
                .position(emptiest_corner(&plots.measured, &frame))
                .text_style(if many {
                    TextStyle::Small
                } else {
                    TextStyle::Body
                }),
        )
        .y_axis_label("y")
        .show(ui, |plot| {
            plot.set_plot_bounds(PlotBounds::from_min_max(
                [frame.t.0, frame.y.0],
                [frame.t.1, frame.y.1],
            ));
            plot.points(
                Points::new(Phrase::Measured.get(lang), plots.measured.clone())
                    .color(palette.data)
                    .radius(2.5),
            );
            if input.changes.len() > 1 {
                step_windows(plot, input, frame.y.1, look);
            }
            if let Some(setup) = setup.as_ref().filter(|_| !measured_drive) {
                let t0 = lang.num(setup.t0(), 4);
                plot.vline(
                    VLine::new(Phrase::StepAt.with(lang, &[t0]), setup.t0())
                        .color(palette.data.gamma_multiply(0.5)),
                );
            }
            if let Some((a, b)) = evidence {
                // The label sits on the highest sample of the interval, at its start.
                let top = plots
                    .measured
                    .iter()
                    .filter(|p| (a..=b).contains(&p[0]))
                    .map(|p| p[1])
                    .fold(f64::NEG_INFINITY, f64::max);
                if top.is_finite() {
                    crate::plot_span::labelled_span(
                        plot,
                        Phrase::Evidence.get(lang).to_string(),
                        a..=b,
                        palette.evidence,
                        [a, top],
                        Align2::LEFT_BOTTOM,
                        palette.error,
                    );
                } else {
                    plot.span(Span::new(Phrase::Evidence.get(lang), a..=b).fill(palette.evidence));
                }
            }
            super::test_causes::shade(plot, session, &plots.measured, frame.y.1, look);
            if let (Some(info), Some(setup)) = (&plots.info, &setup)
                && input.changes.len() <= 1
            {
                draw_markers(
                    plot,
                    info,
                    &plots.measured,
                    (setup.t0(), plots.noise_band, plots.overshoot_is_noise()),
                    session.markers,
                    look,
                );
            }
            super::hand::draw(plot, session, look);
            if let Some((_, what)) = shown
                && !plots.model.is_empty()
            {
                let name = model_name(what, lang);
                plot.line(
                    Line::new(name, plots.model.clone())
                        .color(palette.model)
                        .width(2.0),
                );
            }
        });
    crate::look::name_canvas(&response.response, Phrase::PlotName.get(lang));
    let transform = response.transform;
    if !session.is_fitting() {
        // The line first, so that a model handle on top of it wins the pointer.
        let over = Over {
            session,
            transform: &transform,
            look,
        };
        let mut grabbed = !measured_drive && step_line(ui, &over, out);
        grabbed |= guess_handles(ui, &over, out);
        grabbed |= super::hand::handles(ui, &over, out);
        if session.frozen.is_some() && !grabbed {
            out.push(Command::Handle(Gesture::Release));
        }
    } else if session.frozen.is_some() {
        out.push(Command::Handle(Gesture::Release));
    }
    if let Some(pointer) = response.response.hover_pos()
        && ui.ctx().dragged_id().is_none()
    {
        read_main(ui, session, &transform, pointer, look);
    }
    if input.changes.len() > 1 {
        window_marks(ui, input, &transform, look);
    }
    super::test_causes::marks(ui, session, &transform, look);

    ui.label(Phrase::InputPlot.get(lang));
    let input_response = base_plot(input_plot_id(), input_height, lang)
        .y_axis_label("u")
        .show(ui, |plot| {
            let (lo, hi) = super::session::padded_by(input.range, 0.08);
            plot.set_plot_bounds(PlotBounds::from_min_max([frame.t.0, lo], [frame.t.1, hi]));
            input_curve(plot, input, hi, look);
        });
    change_marks(ui, input, &input_response.transform, look);
    if let Some(pointer) = input_response.response.hover_pos() {
        let t = input_response.transform.value_from_position(pointer).x;
        if let Some(p) = nearest_point(&input.curve, t) {
            readout(ui, &input_response.transform, p, pointer, "u", look);
        }
    }

    ui.label(Phrase::Residuals.get(lang));
    let residual = base_plot(residual_plot_id(), residual_height, lang)
        .y_axis_label("y − ŷ")
        .show(ui, |plot| {
            let (lo, hi) = plots.residual_range;
            plot.set_plot_bounds(PlotBounds::from_min_max([frame.t.0, lo], [frame.t.1, hi]));
            plot.hline(
                HLine::new(Phrase::ZeroLine.get(lang), 0.0).color(palette.data.gamma_multiply(0.5)),
            );
            plot.line(
                Line::new(Phrase::Residual.get(lang), plots.residuals.clone())
                    .color(palette.model)
                    .width(1.2),
            );
            plot.points(
                Points::new(Phrase::Residual.get(lang), plots.residuals.clone())
                    .color(palette.model)
                    .radius(1.8),
            );
        });
    if let Some(pointer) = residual.response.hover_pos() {
        let t = residual.transform.value_from_position(pointer).x;
        if let Some([ts, r]) = session.nearest_residual(t) {
            readout(ui, &residual.transform, [ts, r], pointer, "y − ŷ", look);
        }
    }
}

/// A plot with the app's axes, held where the session says (no pan or zoom of its own, no
/// pointer coordinates: the values read are the curves').
fn base_plot(id: Id, height: f32, lang: degrau_words::Lang) -> Plot<'static> {
    crate::grid::app_axes(Plot::new(id), lang)
        .id(id)
        .height(height)
        .x_axis_label("t (s)")
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .show_x(false)
        .show_y(false)
}

/// The measured curve's rise, peak, settling band and final level.
fn draw_markers(
    plot: &mut PlotUi<'_>,
    info: &StepInfo,
    measured: &[[f64; 2]],
    (t0, noise_band, overshoot_is_noise): (f64, f64, bool),
    markers: MeasuredMarkers,
    look: &Look,
) {
    let (lang, color) = (look.lang, look.palette.marker);
    let Some(y_final) = info.steady_state else {
        return;
    };
    let options = StepInfoOptions::default();
    let delta = y_final - info.initial_value;
    let value_at = |t: f64| interpolate(measured, t);
    let seconds = |x: f64| format!("{} s", lang.num(x, 4));
    if markers.steady_state {
        plot.hline(
            HLine::new(
                format!(
                    "{} {}",
                    Metric::SteadyState.name(lang),
                    lang.num(y_final, 4)
                ),
                y_final,
            )
            .color(color)
            .style(LineStyle::dashed_loose()),
        );
    }
    if markers.settling {
        let band = options.settling_threshold * delta.abs();
        let name =
            Phrase::SettlingBand.with(lang, &[lang.num(100.0 * options.settling_threshold, 3)]);
        for y in [y_final - band, y_final + band] {
            plot.hline(
                HLine::new(name.clone(), y)
                    .color(color.gamma_multiply(0.6))
                    .style(LineStyle::dotted_dense()),
            );
        }
        if let Some(ts) = info.settling_time {
            let name = format!("{} {}", Metric::SettlingTime.name(lang), seconds(ts));
            plot.vline(
                VLine::new(name.clone(), t0 + ts)
                    .color(color)
                    .style(LineStyle::dashed_dense()),
            );
        }
    }
    if markers.rise
        && let (Some(a), Some(b), Some(tr)) = (info.rise_start, info.rise_end, info.rise_time)
    {
        let name = format!("  {} {}", Metric::RiseTime.name(lang), seconds(tr));
        let end = t0 + b;
        crate::plot_span::labelled_span(
            plot,
            name,
            t0 + a..=end,
            color.gamma_multiply(0.12),
            [end, value_at(end)],
            Align2::LEFT_TOP,
            color,
        );
    }
    if markers.peak
        && let (Some(tp), Some(os)) = (info.peak_time, info.overshoot)
    {
        let name = if overshoot_is_noise {
            Phrase::OvershootWithinNoise.with(lang, &[lang.num(noise_band, 3)])
        } else {
            format!("{} {} %", Metric::Overshoot.name(lang), lang.num(os, 4))
        };
        plot.points(
            Points::new(name, vec![[t0 + tp, value_at(t0 + tp)]])
                .color(color)
                .shape(MarkerShape::Diamond)
                .radius(6.0),
        );
    }
}

/// The model curve's name in the legend and the readout.
fn model_name(what: Shown, lang: degrau_words::Lang) -> String {
    match what {
        Shown::Fitting => Phrase::ModelFitting.get(lang).to_string(),
        Shown::Fitted => Phrase::ModelFitted.get(lang).to_string(),
        Shown::Guess => Phrase::ModelGuess.get(lang).to_string(),
        Shown::ChainRow(k) => Phrase::ModelOfRow.with(lang, &[k.to_string()]),
    }
}

/// Linear interpolation of sorted (t, y) points.
fn interpolate(points: &[[f64; 2]], t: f64) -> f64 {
    match points.iter().position(|p| p[0] >= t) {
        Some(0) => points[0][1],
        Some(k) => {
            let (a, b) = (points[k - 1], points[k]);
            if b[0] == a[0] {
                b[1]
            } else {
                a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
            }
        }
        None => points.last().map_or(0.0, |p| p[1]),
    }
}

/// The value of the curve nearest the pointer, if one is near: the measured sample nearest in
/// time, or the model's exact value at the pointer's time.
fn read_main(ui: &Ui, session: &Session, transform: &PlotTransform, pointer: Pos2, look: &Look) {
    let t = transform.value_from_position(pointer).x;
    let screen = |p: [f64; 2]| transform.position_from_point(&PlotPoint::new(p[0], p[1]));
    let sample = session
        .nearest_sample(t)
        .map(|p| (p, Phrase::Measured.get(look.lang)));
    let name = session
        .shown()
        .map_or(String::new(), |(_, what)| model_name(what, look.lang));
    let model = session.model_value(t).map(|y| ([t, y], name.as_str()));
    let nearest = [sample, model]
        .into_iter()
        .flatten()
        .map(|(p, name)| (p, name, screen(p).distance(pointer)))
        .filter(|c| c.2 <= READ_DISTANCE)
        .min_by(|a, b| a.2.total_cmp(&b.2));
    if let Some((p, name, _)) = nearest {
        readout(ui, transform, p, pointer, name, look);
    }
}

/// A small label at the point read: its time and value.
fn readout(
    ui: &Ui,
    transform: &PlotTransform,
    p: [f64; 2],
    pointer: Pos2,
    name: &str,
    look: &Look,
) {
    let lang = look.lang;
    let at = transform.position_from_point(&PlotPoint::new(p[0], p[1]));
    if !transform.frame().contains(at) || at.distance(pointer) > READ_DISTANCE {
        return;
    }
    let text = format!(
        "{name}\nt = {} s\ny = {}",
        lang.num(p[0], 5),
        lang.num(p[1], 5)
    );
    let painter = ui.painter_at(*transform.frame());
    let font = TextStyle::Body.resolve(ui.style());
    let galley = painter.layout_no_wrap(text, font, look.palette.axis);
    let anchor = if at.x > transform.frame().center().x {
        Align2::RIGHT_BOTTOM
    } else {
        Align2::LEFT_BOTTOM
    };
    let rect = anchor.anchor_size(
        at + Vec2::new(
            if anchor == Align2::LEFT_BOTTOM {
                10.0
            } else {
                -10.0
            },
            -10.0,
        ),
        galley.size(),
    );
    painter.circle_stroke(at, 5.0, Stroke::new(2.0, look.palette.selected));
    painter.rect_filled(rect.expand(4.0), 4.0, look.palette.grid);
    painter.galley(rect.min, galley, look.palette.axis);
}

/// The guess handles over the plot: accessible widgets a student (or a test) drags. True
/// while one is held.
fn guess_handles(ui: &mut Ui, over: &Over<'_>, out: &mut Vec<Command>) -> bool {
    let (session, transform, look) = (over.session, over.transform, over.look);
    let Some(handles) = session.handle_frame() else {
        return false;
    };
    let frame: Rect = *transform.frame();
    let mut held = false;
    for handle in handles.handles() {
        let Some((t, y)) = handles.position(handle) else {
            continue;
        };
        let id = Id::unique(("identification handle", handle_key(handle)));
        let at = transform.position_from_point(&PlotPoint::new(t, y));
        let dragging = ui.ctx().is_being_dragged(id);
        if !frame.expand(GRAB).contains(at) && !dragging {
            continue;
        }
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * GRAB));
        let label = words::handle_label(handle, look.lang);
        let help = words::handle_help(handle, look.lang);
        let response = grab_area(ui, (id, rect), (label, help), transform, out);
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let value = transform.value_from_position(p);
            out.push(Command::Handle(Gesture::Move {
                handle,
                to: (value.x, value.y),
            }));
        }
        held |= response.dragged() && !response.drag_stopped();
        paint_handle(ui, frame, at, &response, look);
    }
    held
}

/// The step time t0 as a vertical line dragged left or right, within the record. True while
/// it is held.
fn step_line(ui: &mut Ui, over: &Over<'_>, out: &mut Vec<Command>) -> bool {
    let (session, transform, look) = (over.session, over.transform, over.look);
    let Some(l) = session.loaded.as_ref() else {
        return false;
    };
    let (Some(&first), Some(&last)) = (l.test.time.first(), l.test.time.last()) else {
        return false;
    };
    let frame: Rect = *transform.frame();
    let x = transform
        .position_from_point(&PlotPoint::new(l.experiment.t0, 0.0))
        .x;
    let id = Id::unique("identification step time line");
    if !(frame.left()..=frame.right()).contains(&x) && !ui.ctx().is_being_dragged(id) {
        return false;
    }
    let rect = Rect::from_x_y_ranges(x - 4.0..=x + 4.0, frame.y_range());
    let words = (
        Phrase::StepLine.get(look.lang),
        Phrase::StepLineHelp.get(look.lang),
    );
    let response = grab_area(ui, (id, rect), words, transform, out)
        .on_hover_cursor(egui::CursorIcon::ResizeHorizontal);
    if response.dragged()
        && let Some(p) = ui.ctx().pointer_interact_pos()
    {
        let t0 = transform.value_from_position(p).x.clamp(first, last);
        out.push(Command::SetStepTime(t0));
    }
    if response.hovered() || response.dragged() {
        ui.painter_at(frame)
            .vline(x, frame.y_range(), Stroke::new(2.0, look.palette.selected));
    }
    response.dragged() && !response.drag_stopped()
}

/// The input curve, each change's instant (a vertical line) and the interval it may have
/// happened in (a shaded span), labelled when there are few enough.
fn input_curve(plot: &mut PlotUi<'_>, input: &InputPlot, top: f64, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    plot.line(
        Line::new(Phrase::InputCurve.get(lang), input.curve.clone())
            .color(palette.main)
            .width(1.6)
            // A staircase is not a dense curve: drawn as bands, its jumps would be filled.
            .allow_band(false),
    );
    let labelled = input.changes.len() <= LABELLED_CHANGES;
    for (k, c) in input.changes.iter().enumerate() {
        plot.vline(
            VLine::new(words::change_mark(k, c, lang), c.t)
                .color(palette.marker.gamma_multiply(0.7))
                .style(LineStyle::dashed_dense()),
        );
        if c.earliest < c.t {
            plot.span(Span::new("", c.earliest..=c.t).fill(palette.marker.gamma_multiply(0.25)));
        }
        if labelled {
            plot.text(
                Text::new(
                    "",
                    PlotPoint::new(c.t, top),
                    egui::RichText::new(words::change_short(k, c, lang))
                        .text_style(TextStyle::Small),
                )
                .anchor(Align2::LEFT_TOP)
                .color(palette.marker),
            );
        }
    }
}

/// Each change's response span on the output plot, shaded in turn and labelled "step k".
fn step_windows(plot: &mut PlotUi<'_>, input: &InputPlot, top: f64, look: &Look) {
    let labelled = input.spans.len() <= LABELLED_CHANGES;
    for (k, &(a, b)) in input.spans.iter().enumerate() {
        let fill = look
            .palette
            .marker
            .gamma_multiply(if k % 2 == 0 { 0.07 } else { 0.14 });
        if labelled {
            crate::plot_span::labelled_span(
                plot,
                words::step_window(k, look.lang),
                a..=b,
                fill,
                [a, top],
                Align2::LEFT_TOP,
                look.palette.marker,
            );
        } else {
            plot.span(Span::new("", a..=b).fill(fill));
        }
    }
}

/// An accessible mark over each change's line on the input plot (its label says the
/// change, its tooltip the interval it may have happened in).
fn change_marks(ui: &mut Ui, input: &InputPlot, transform: &PlotTransform, look: &Look) {
    let frame: Rect = *transform.frame();
    for (k, c) in input.changes.iter().enumerate() {
        let x = transform.position_from_point(&PlotPoint::new(c.t, 0.0)).x;
        if !(frame.left()..=frame.right()).contains(&x) {
            continue;
        }
        let rect = Rect::from_x_y_ranges(x - 3.0..=x + 3.0, frame.y_range());
        let id = Id::unique(("identification input change", k));
        let label = words::change_mark(k, c, look.lang);
        let response = ui.interact(rect, id, Sense::hover());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, &label));
        response.on_hover_text(words::change_span(k, c, look.lang));
    }
}

/// An accessible mark over each step's window on the output plot, a strip at its top.
fn window_marks(ui: &mut Ui, input: &InputPlot, transform: &PlotTransform, look: &Look) {
    let frame: Rect = *transform.frame();
    for (k, &(a, b)) in input.spans.iter().enumerate() {
        let x = |t: f64| transform.position_from_point(&PlotPoint::new(t, 0.0)).x;
        let (left, right) = (x(a).max(frame.left()), x(b).min(frame.right()));
        if right <= left {
            continue;
        }
        let rect = Rect::from_x_y_ranges(left..=right, frame.top()..=frame.top() + 16.0);
        let id = Id::unique(("identification step window", k));
        let label = words::step_window_label(k, (a, b), look.lang);
        let response = ui.interact(rect, id, Sense::hover());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, &label));
    }
}

fn handle_key(h: Handle) -> u8 {
    match h {
        Handle::FinalValue => 0,
        Handle::DeadTime => 1,
        Handle::TimeConstant => 2,
        Handle::FirstPeak => 3,
    }
}

/// The corner of the plot's `frame` whose third (in time and in y) holds the fewest of the
/// `samples`: where the legend covers least of them (the right-hand ones first, the bottom
/// before the top, on a tie).
fn emptiest_corner(samples: &[[f64; 2]], frame: &Frozen) -> egui_plot::Corner {
    use egui_plot::Corner;
    let share = |v: f64, (lo, hi): (f64, f64)| (v - lo) / (hi - lo);
    let count = |right: bool, top: bool| {
        samples
            .iter()
            .filter(|p| {
                let (x, y) = (share(p[0], frame.t), share(p[1], frame.y));
                let across = if right {
                    x >= 2.0 / 3.0
                } else {
                    x <= 1.0 / 3.0
                };
                let up = if top { y >= 2.0 / 3.0 } else { y <= 1.0 / 3.0 };
                across && up
            })
            .count()
    };
    [
        (Corner::RightBottom, count(true, false)),
        (Corner::RightTop, count(true, true)),
        (Corner::LeftBottom, count(false, false)),
        (Corner::LeftTop, count(false, true)),
    ]
    .into_iter()
    .min_by_key(|(_, n)| *n)
    .map_or(Corner::RightBottom, |(c, _)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_legend_goes_where_the_samples_leave_room() {
        use egui_plot::Corner;
        let frame = Frozen {
            t: (0.0, 100.0),
            y: (0.0, 10.0),
        };
        // A rise from 1 to 9 after t = 20: empty below on the right.
        let rise: Vec<[f64; 2]> = (0..100)
            .map(|k| {
                let t = k as f64;
                [
                    t,
                    if t < 20.0 {
                        1.0
                    } else {
                        9.0 - 8.0 * (-(t - 20.0) / 8.0).exp()
                    },
                ]
            })
            .collect();
        assert_eq!(emptiest_corner(&rise, &frame), Corner::RightBottom);
        // The same fall: empty above on the right (the bottom-right corner would cover it).
        let fall: Vec<[f64; 2]> = rise.iter().map(|p| [p[0], 10.0 - p[1]]).collect();
        assert_eq!(emptiest_corner(&fall, &frame), Corner::RightTop);
        // No samples: the usual corner.
        assert_eq!(emptiest_corner(&[], &frame), Corner::RightBottom);
    }

    #[test]
    fn the_main_plot_keeps_its_height() {
        // 1000×650 leaves about 520 px below the menu and the marker bar.
        let (main, input, residual) = heights(520.0, 20.0);
        assert!(main >= MIN_PLOT_HEIGHT && residual >= MIN_RESIDUAL_HEIGHT);
        assert!(input >= INPUT_HEIGHT.0 && main + input + residual <= 460.0 + 1e-3);
        // A tiny window: the plots keep their minimum and the area scrolls.
        assert_eq!(
            heights(100.0, 20.0),
            (MIN_PLOT_HEIGHT, INPUT_HEIGHT.0, MIN_RESIDUAL_HEIGHT)
        );
        let (main, input, residual) = heights(1000.0, 20.0);
        let rest = 940.0 - input;
        assert!((input - 0.18 * 940.0).abs() < 1e-3);
        assert!((main - MAIN_SHARE * rest).abs() < 1e-3);
        assert!((residual - (1.0 - MAIN_SHARE) * rest).abs() < 1e-3);
    }
}
