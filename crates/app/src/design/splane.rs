//! The s-plane canvas: poles (×) and zeros (○) a student drags, with the axes, a grid, the
//! stable region shaded, optional constant-ζ rays and constant-ωn circles, zoom and pan.
//! Each handle is an accessible widget labelled "pole 1", "zero 2" (a pair's lower member is
//! "pole 1 mirror"), so tests find and drag it like a person would.
//! Which part of the plane is shown, the canvas's kept state and the mapping between screen
//! and plane are [`super::plane`]'s.

use std::sync::Arc;

use eframe::egui::{self, Align2, FontId, Pos2, Rect, Response, Sense, Shape, Stroke, Ui, Vec2};

use crate::look::{Look, Palette};
use crate::words::design::{Design as P, root_label};
use degrau_words::Lang;

use super::commands::Command;
use super::plane::{
    MAX_PIXELS_PER_UNIT, MIN_PIXELS_PER_UNIT, SPlaneState, Transform, View, fit_view, readout,
};
use super::state::{Root, RootId, RootKind, RootRole, System};

/// Size of the canvas's axis numbers and captions (points, before the presentation size).
const CANVAS_TEXT: f32 = 13.0;

/// Pixels around a handle that grab it.
const HANDLE_RADIUS: f32 = 9.0;
/// Size of the × and ○ marks.
const MARK_SIZE: f32 = 6.0;
/// Draws the canvas; returns the student's edits (drags, menu choices, pan and zoom) as
/// commands. `system` and `state` are only read; `overlay` adds the closed loop (spec
/// regions, root locus, closed-loop poles).
pub fn show(
    ui: &mut Ui,
    system: &System,
    state: &SPlaneState,
    look: &Look,
    overlay: Option<&super::locus_view::Overlay<'_>>,
) -> Vec<Command> {
    let mut out = Vec::new();
    let size = ui.available_size().max(Vec2::splat(120.0));
    let (rect, background) = ui.allocate_exact_size(size, Sense::click_and_drag());
    let name = P::PlaneName.get(look.lang);
    crate::look::name_canvas(&background, name);
    let view = state
        .view
        .and_then(View::sane)
        .unwrap_or_else(|| fit_view(system, rect.size()));
    if state.view != Some(view) {
        out.push(Command::SetView(Some(view)));
    }
    let transform = Transform { rect, view };
    let painter = ui.painter_at(rect);

    paint_background(&painter, &transform, state.damping_grid, look);
    if let Some(o) = overlay {
        super::locus_view::paint(&painter, &transform, o, look);
    }
    let mut readout_text = background
        .hover_pos()
        .map(|p| transform.to_plane(p))
        .map(|(re, im)| readout(re, im, "s", look.lang));

    if let Some(v) = pan_and_zoom(ui, &background, &transform)
        && v != view
    {
        out.push(Command::SetView(Some(v)));
    }
    out.extend(background_menu(
        ui,
        &background,
        &transform,
        system,
        state,
        look.lang,
    ));

    for id in system.ids() {
        out.extend(handle(
            ui,
            &painter,
            &transform,
            system,
            state,
            id,
            look,
            &mut readout_text,
        ));
    }
    // The closed-loop poles come last, so they take a drag over an open-loop root.
    if let Some(o) = overlay {
        out.extend(super::locus_view::handles(
            ui,
            &painter,
            &transform,
            o,
            look,
            background.hover_pos(),
            &mut readout_text,
        ));
    }
    out.push(Command::Readout(readout_text));
    out
}

fn paint_background(painter: &egui::Painter, t: &Transform, damping_grid: bool, look: &Look) {
    let palette = &look.palette;
    let lang = look.lang;
    let rect = t.rect;
    let origin = t.to_screen(0.0, 0.0);
    // Stable region: the open left half plane.
    let stable = Rect::from_min_max(
        rect.min,
        Pos2::new(origin.x.clamp(rect.left(), rect.right()), rect.bottom()),
    );
    painter.rect_filled(stable, 0.0, palette.stable_region);

    // The caption's place is taken first: a tick or a damping label that would run into it,
    // or out of the canvas, is left out.
    let font = FontId::proportional(CANVAS_TEXT);
    let mut labels = CanvasLabels::new(rect);
    let caption_text = painter.layout_no_wrap(
        P::PlaneCaption.get(lang).to_owned(),
        font.clone(),
        palette.weak_text,
    );
    let at = rect.right_top() + Vec2::new(-6.0, 4.0);
    let caption = labels.reserve(at, Align2::RIGHT_TOP, caption_text);
    let step = t.grid_step();
    let (re0, im1) = t.to_plane(rect.left_top());
    let (re1, im0) = t.to_plane(rect.right_bottom());
    let grid = Stroke::new(0.5, palette.grid);
    for re in crate::grid::multiples(re0, re1, step) {
        let x = t.to_screen(re, 0.0).x;
        painter.line_segment(
            [Pos2::new(x, rect.top()), Pos2::new(x, rect.bottom())],
            grid,
        );
        if re != 0.0 {
            let y = origin.y.clamp(rect.top(), rect.bottom() - 14.0);
            labels.put(
                painter,
                Pos2::new(x + 2.0, y + 2.0),
                Align2::LEFT_TOP,
                &lang.num(re, 6),
                &font,
                palette.weak_text,
            );
        }
    }
    for im in crate::grid::multiples(im0, im1, step) {
        let y = t.to_screen(0.0, im).y;
        painter.line_segment(
            [Pos2::new(rect.left(), y), Pos2::new(rect.right(), y)],
            grid,
        );
        if im != 0.0 {
            let x = origin.x.clamp(rect.left(), rect.right() - 30.0);
            labels.put(
                painter,
                Pos2::new(x + 3.0, y),
                Align2::LEFT_CENTER,
                &format!("{}j", lang.num(im, 6)),
                &font,
                palette.weak_text,
            );
        }
    }
    if damping_grid {
        paint_damping_grid(painter, t, step, look, &mut labels);
    }
    let axis = Stroke::new(1.2, palette.axis);
    painter.line_segment(
        [
            Pos2::new(rect.left(), origin.y),
            Pos2::new(rect.right(), origin.y),
        ],
        axis,
    );
    painter.line_segment(
        [
            Pos2::new(origin.x, rect.top()),
            Pos2::new(origin.x, rect.bottom()),
        ],
        axis,
    );
    if let Some((at, galley)) = caption {
        painter.galley(at, galley, palette.weak_text);
    }
}

/// The texts painted on a canvas so far: a new one is painted only whole inside the canvas
/// and clear of the others (the caption ran into the "4j" tick).
struct CanvasLabels {
    canvas: Rect,
    taken: Vec<Rect>,
}

/// A text laid out and where its top left goes.
type Placed = (Pos2, Arc<egui::Galley>);

impl CanvasLabels {
    fn new(canvas: Rect) -> Self {
        Self {
            canvas,
            taken: Vec::new(),
        }
    }

    /// Takes the place of the laid-out text `galley` anchored at `at` if it is free; where
    /// its top left goes.
    fn reserve(&mut self, at: Pos2, anchor: Align2, galley: Arc<egui::Galley>) -> Option<Placed> {
        let rect = anchor.anchor_size(at, galley.size());
        let free =
            self.canvas.contains_rect(rect) && !self.taken.iter().any(|r| r.intersects(rect));
        free.then(|| {
            self.taken.push(rect);
            (rect.min, galley)
        })
    }

    /// Paints `text` anchored at `at` if its place is free.
    fn put(
        &mut self,
        painter: &egui::Painter,
        at: Pos2,
        anchor: Align2,
        text: &str,
        font: &FontId,
        color: egui::Color32,
    ) {
        let galley = painter.layout_no_wrap(text.to_owned(), font.clone(), color);
        if let Some((min, galley)) = self.reserve(at, anchor, galley) {
            painter.galley(min, galley, color);
        }
    }
}

/// Constant-ζ rays from the origin into the left half plane and constant-ωn circles.
fn paint_damping_grid(
    painter: &egui::Painter,
    t: &Transform,
    step: f64,
    look: &Look,
    labels: &mut CanvasLabels,
) {
    let (palette, lang) = (&look.palette, look.lang);
    let stroke = Stroke::new(0.7, palette.damping);
    let font = FontId::proportional(CANVAS_TEXT - 1.0);
    let origin = t.to_screen(0.0, 0.0);
    let reach = (t.rect.width().max(t.rect.height()) as f64) * 2.0 / t.view.pixels_per_unit;
    for zeta in [0.2, 0.4, 0.6, 0.8] {
        let angle = f64::acos(zeta);
        for sign in [1.0, -1.0] {
            let end = t.to_screen(-reach * zeta, sign * reach * angle.sin());
            painter.line_segment([origin, end], stroke);
        }
        // Label where the ray crosses a circle of two grid steps.
        let r = 2.5 * step;
        let at = t.to_screen(-r * zeta, r * angle.sin());
        labels.put(
            painter,
            at,
            Align2::RIGHT_BOTTOM,
            &format!("ζ={}", lang.num(zeta, 2)),
            &font,
            palette.damping,
        );
    }
    for k in 1..=6 {
        let wn = k as f64 * step * 2.0;
        let radius = (wn * t.view.pixels_per_unit) as f32;
        // Only the left half: a polyline over 90°..270°.
        let points: Vec<Pos2> = (0..=48)
            .map(|i| {
                let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * i as f64 / 48.0;
                t.to_screen(wn * a.cos(), wn * a.sin())
            })
            .collect();
        painter.add(Shape::line(points, stroke));
        let label_at = origin + Vec2::new(-radius * 0.72, -radius * 0.69);
        labels.put(
            painter,
            label_at,
            Align2::RIGHT_BOTTOM,
            &format!("ωn={}", lang.num(wn, 6)),
            &font,
            palette.damping,
        );
    }
}

/// The view after a pan (dragging the background) or a zoom (wheel or pinch at the
/// pointer), if the student did either.
fn pan_and_zoom(ui: &Ui, background: &Response, t: &Transform) -> Option<View> {
    let mut view = t.view;
    if background.dragged() {
        let d = background.drag_delta();
        view.center_re -= d.x as f64 / view.pixels_per_unit;
        view.center_im += d.y as f64 / view.pixels_per_unit;
    }
    if let Some(pointer) = background.hover_pos() {
        let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        let factor = pinch as f64 * (scroll as f64 / 300.0).exp();
        if factor != 1.0 && factor.is_finite() && factor > 0.0 {
            let (re, im) = t.to_plane(pointer);
            view.pixels_per_unit =
                (view.pixels_per_unit * factor).clamp(MIN_PIXELS_PER_UNIT, MAX_PIXELS_PER_UNIT);
            // Keep the point under the pointer fixed.
            let c = t.rect.center();
            view.center_re = re - (pointer.x - c.x) as f64 / view.pixels_per_unit;
            view.center_im = im + (pointer.y - c.y) as f64 / view.pixels_per_unit;
        }
    }
    view.sane()
}

/// The background's right-click menu (add a root where it was clicked, fit the view) and a
/// click that clears the selection.
fn background_menu(
    ui: &Ui,
    background: &Response,
    t: &Transform,
    system: &System,
    state: &SPlaneState,
    lang: Lang,
) -> Vec<Command> {
    let mut out = Vec::new();
    // Where the menu was opened (s-plane coordinates), kept with the widget as egui keeps
    // a text cursor.
    let menu_id = background.id.with("menu at");
    if background.secondary_clicked()
        && let Some(p) = background.interact_pointer_pos()
    {
        let at = t.to_plane(p);
        ui.data_mut(|d| d.insert_temp(menu_id, at));
    }
    if background.clicked() && state.selected.is_some() {
        out.push(Command::Select(None));
    }
    let at: (f64, f64) = ui.data(|d| d.get_temp(menu_id)).unwrap_or((-1.0, 1.0));
    let snap = state.snap.then(|| t.grid_step() / 5.0);
    let (re, im) = (snap_to(at.0, snap), snap_to(at.1, snap));
    let pair_im = if im.abs() > 0.0 {
        im.abs()
    } else {
        t.grid_step()
    };
    background.context_menu(|ui| {
        let mut add = |ui: &mut Ui, text: P, role: RootRole, root: Root| {
            if ui
                .add_enabled(system.has_room(role), egui::Button::new(text.get(lang)))
                .clicked()
            {
                out.push(Command::AddRoot { role, root });
                ui.close();
            }
        };
        let choices = [
            (P::AddRealPoleHere, RootRole::Pole, Root::real(re)),
            (P::AddPolePairHere, RootRole::Pole, Root::pair(re, pair_im)),
            (P::AddRealZeroHere, RootRole::Zero, Root::real(re)),
            (P::AddZeroPairHere, RootRole::Zero, Root::pair(re, pair_im)),
        ];
        for (phrase, role, root) in choices {
            add(ui, phrase, role, root);
        }
        ui.separator();
        if ui.button(P::FitViewToRoots.get(lang)).clicked() {
            out.push(Command::SetView(None));
            ui.close();
        }
    });
    out
}

fn snap_to(v: f64, step: Option<f64>) -> f64 {
    match step {
        Some(s) if s > 0.0 => (v / s).round() * s,
        _ => v,
    }
}

/// One root's handle (two for a pair): paint, drag, select, menu; its readout replaces
/// `readout` while hovered or dragged.
#[allow(clippy::too_many_arguments)]
fn handle(
    ui: &mut Ui,
    painter: &egui::Painter,
    t: &Transform,
    system: &System,
    state: &SPlaneState,
    id: RootId,
    look: &Look,
    readout_text: &mut Option<String>,
) -> Vec<Command> {
    let mut out = Vec::new();
    let lang = look.lang;
    let Some(root) = system.root(id).copied() else {
        return out;
    };
    let name = root_label(id, lang);
    let members: Vec<(f64, String)> = match root.kind {
        RootKind::Real => vec![(0.0, name.clone())],
        RootKind::Pair => vec![
            (root.im, name.clone()),
            (-root.im, format!("{name} {}", P::Mirror.get(lang))),
        ],
    };
    for (k, (im, label)) in members.into_iter().enumerate() {
        let at = t.to_screen(root.re, im);
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * HANDLE_RADIUS));
        let widget_id = ui.scope_id().with(("root", id, k));
        if !t.holds_handle(ui, at, widget_id) {
            continue;
        }
        let response = ui.interact(rect, widget_id, Sense::click_and_drag());
        let text = label.clone();
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, &text));

        if (response.drag_started() || response.clicked()) && state.selected != Some(id) {
            out.push(Command::Select(Some(id)));
        }
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let (re, im) = t.to_plane(p);
            let snap = state.snap.then(|| t.grid_step() / 5.0);
            let (re, im) = (snap_to(re, snap), snap_to(im, snap));
            out.push(Command::DragRoot { id, re, im });
            *readout_text = Some(format!("{name}: {}", readout(re, im, "s", lang)));
        } else if response.hovered() {
            *readout_text = Some(format!("{name}: {}", readout(root.re, root.im, "s", lang)));
        }
        if response.drag_stopped() {
            out.push(Command::EndDrag);
        }
        response.context_menu(|ui| {
            if ui
                .button(format!("{} {name}", P::Delete.get(lang)))
                .clicked()
            {
                out.push(Command::RemoveRoot(id));
                ui.close();
            }
            let toggle_text = match root.kind {
                RootKind::Real => P::MakeComplexPair,
                RootKind::Pair => P::MakeTwoReal,
            };
            if ui.button(toggle_text.get(lang)).clicked() {
                out.push(Command::TogglePair {
                    id,
                    im: t.grid_step(),
                });
                ui.close();
            }
        });
        let selected = state.selected == Some(id);
        paint_mark(
            painter,
            at,
            id.role,
            selected || response.hovered(),
            &look.palette,
        );
    }
    out
}

fn paint_mark(
    painter: &egui::Painter,
    at: Pos2,
    role: RootRole,
    highlight: bool,
    palette: &Palette,
) {
    if highlight {
        painter.circle_stroke(at, HANDLE_RADIUS, Stroke::new(1.5, palette.selected));
    }
    match role {
        RootRole::Pole => {
            let s = Stroke::new(2.2, palette.pole);
            let d = MARK_SIZE;
            painter.line_segment([at + Vec2::new(-d, -d), at + Vec2::new(d, d)], s);
            painter.line_segment([at + Vec2::new(-d, d), at + Vec2::new(d, -d)], s);
        }
        RootRole::Zero => {
            painter.circle_stroke(at, MARK_SIZE, Stroke::new(2.2, palette.zero));
        }
    }
}
