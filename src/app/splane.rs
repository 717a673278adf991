//! The s-plane canvas: poles (×) and zeros (○) a student drags, with the axes, a grid, the
//! stable region shaded, optional constant-ζ rays and constant-ωn circles, zoom and pan.
//! Each handle is an accessible widget labelled "pole 1", "zero 2" (a pair's lower member is
//! "pole 1 mirror"), so tests find and drag it like a person would.

use eframe::egui::{
    self, Align2, Color32, FontId, Pos2, Rect, Response, Sense, Shape, Stroke, Ui, Vec2,
};
use serde::{Deserialize, Serialize};

use crate::app::state::{ROOT_LIMIT, Root, RootId, RootKind, RootRole, System};
use crate::lti::number::format_number;
use crate::lti::number::sig;

/// Pixels around a handle that grab it.
const HANDLE_RADIUS: f32 = 9.0;
/// Size of the × and ○ marks.
const MARK_SIZE: f32 = 6.0;
/// Target pixels between grid lines.
const GRID_PIXELS: f64 = 70.0;

/// Fewest pixels per unit (1/s) of a view: ±[`ROOT_LIMIT`] fits in a few hundred pixels.
pub const MIN_PIXELS_PER_UNIT: f64 = 1e-8;
/// Most pixels per unit of a view (a pixel is 0.1 µ(1/s)).
pub const MAX_PIXELS_PER_UNIT: f64 = 1e7;
/// Farthest a view's centre may be from the origin (1/s): ten times [`ROOT_LIMIT`].
pub const CENTER_LIMIT: f64 = 10.0 * ROOT_LIMIT;

/// Which part of the s-plane is shown: the point at the centre and pixels per unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct View {
    pub center_re: f64,
    pub center_im: f64,
    pub pixels_per_unit: f64,
}

impl View {
    /// The view clamped to finite, sane ranges (centre within ±[`CENTER_LIMIT`], scale in
    /// [[`MIN_PIXELS_PER_UNIT`], [`MAX_PIXELS_PER_UNIT`]]); `None` when a number is NaN,
    /// so the view is fitted to the roots again.
    pub fn sane(self) -> Option<View> {
        let View {
            center_re,
            center_im,
            pixels_per_unit,
        } = self;
        if center_re.is_nan() || center_im.is_nan() || pixels_per_unit.is_nan() {
            return None;
        }
        Some(View {
            center_re: center_re.clamp(-CENTER_LIMIT, CENTER_LIMIT),
            center_im: center_im.clamp(-CENTER_LIMIT, CENTER_LIMIT),
            pixels_per_unit: pixels_per_unit.clamp(MIN_PIXELS_PER_UNIT, MAX_PIXELS_PER_UNIT),
        })
    }

    /// True when the view is already within its sane ranges.
    pub fn is_sane(&self) -> bool {
        self.sane() == Some(*self)
    }
}

/// The canvas's own state (kept between frames and runs).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SPlaneState {
    /// `None` fits the view to the roots on the next frame.
    pub view: Option<View>,
    pub damping_grid: bool,
    pub snap: bool,
    pub selected: Option<RootId>,
    /// Where the last right-click on empty canvas happened (s-plane coordinates).
    #[serde(skip)]
    menu_at: Option<(f64, f64)>,
    /// What the pointer is over: a readout for the student.
    #[serde(skip)]
    pub readout: Option<String>,
}

impl Default for SPlaneState {
    fn default() -> Self {
        Self {
            view: None,
            damping_grid: true,
            snap: false,
            selected: None,
            menu_at: None,
            readout: None,
        }
    }
}

/// Mapping between screen and s-plane for one frame.
#[derive(Debug, Clone, Copy)]
pub struct Transform {
    rect: Rect,
    view: View,
}

impl Transform {
    pub fn to_screen(&self, re: f64, im: f64) -> Pos2 {
        let c = self.rect.center();
        Pos2::new(
            c.x + ((re - self.view.center_re) * self.view.pixels_per_unit) as f32,
            c.y - ((im - self.view.center_im) * self.view.pixels_per_unit) as f32,
        )
    }

    pub fn to_plane(&self, p: Pos2) -> (f64, f64) {
        let c = self.rect.center();
        (
            self.view.center_re + (p.x - c.x) as f64 / self.view.pixels_per_unit,
            self.view.center_im - (p.y - c.y) as f64 / self.view.pixels_per_unit,
        )
    }

    /// A 1-2-5 grid step giving about [`GRID_PIXELS`] between lines.
    pub fn grid_step(&self) -> f64 {
        super::grid::nice_step(GRID_PIXELS / self.view.pixels_per_unit)
    }
}

/// A view showing every root and the origin with a margin (roots beyond ±[`ROOT_LIMIT`],
/// or not finite, count as at the limit), within the sane ranges of [`View::sane`].
pub fn fit_view(system: &System, size: Vec2) -> View {
    let bounded = |x: f64| {
        if x.is_nan() {
            0.0
        } else {
            x.clamp(-ROOT_LIMIT, ROOT_LIMIT)
        }
    };
    let points: Vec<(f64, f64)> = [RootRole::Pole, RootRole::Zero]
        .iter()
        .flat_map(|&role| system.roots(role).iter())
        .map(|r| (bounded(r.re), bounded(r.im)))
        .flat_map(|(re, im)| [(re, im), (re, -im)])
        .chain([(0.0, 0.0)])
        .collect();
    let (min_re, max_re) = points
        .iter()
        .fold((0.0f64, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
    // Leave part of the right half plane in view so the imaginary axis is not at the edge.
    let max_re = max_re.max(0.25 * (max_re - min_re).max(1.0));
    let max_im = points.iter().fold(0.0f64, |a, p| a.max(p.1.abs()));
    let half_width = (0.5 * (max_re - min_re) * 1.25).max(1.0);
    let half_height = (max_im * 1.25).max(1.0);
    let pixels_per_unit = (size.x as f64 / 2.0 / half_width).min(size.y as f64 / 2.0 / half_height);
    let view = View {
        center_re: 0.5 * (min_re + max_re),
        center_im: 0.0,
        pixels_per_unit,
    };
    view.sane().unwrap_or(View {
        center_re: 0.0,
        center_im: 0.0,
        pixels_per_unit: 100.0,
    })
}

/// Colours of the canvas for the current theme.
struct Palette {
    stable: Color32,
    grid: Color32,
    axis: Color32,
    damping: Color32,
    pole: Color32,
    zero: Color32,
    selected: Color32,
    text: Color32,
}

impl Palette {
    fn of(ui: &Ui) -> Self {
        let dark = ui.visuals().dark_mode;
        Self {
            stable: if dark {
                Color32::from_rgba_unmultiplied(40, 90, 50, 50)
            } else {
                Color32::from_rgba_unmultiplied(120, 200, 130, 45)
            },
            grid: ui.visuals().widgets.noninteractive.bg_stroke.color,
            axis: ui.visuals().text_color(),
            damping: if dark {
                Color32::from_rgb(90, 110, 160)
            } else {
                Color32::from_rgb(130, 150, 200)
            },
            pole: if dark {
                Color32::from_rgb(255, 120, 100)
            } else {
                Color32::from_rgb(200, 40, 30)
            },
            zero: if dark {
                Color32::from_rgb(110, 170, 255)
            } else {
                Color32::from_rgb(20, 80, 200)
            },
            selected: Color32::from_rgb(240, 170, 0),
            text: ui.visuals().weak_text_color(),
        }
    }
}

/// Draws the canvas and applies the student's edits to `system`. Returns the background's
/// response (hover, menus).
pub fn show(ui: &mut Ui, system: &mut System, state: &mut SPlaneState) -> Response {
    let size = ui.available_size().max(Vec2::splat(120.0));
    let (rect, background) = ui.allocate_exact_size(size, Sense::click_and_drag());
    let view = state
        .view
        .and_then(View::sane)
        .unwrap_or_else(|| fit_view(system, rect.size()));
    state.view = Some(view);
    let transform = Transform { rect, view };
    let palette = Palette::of(ui);
    let painter = ui.painter_at(rect);

    paint_background(&painter, &transform, state.damping_grid, &palette);
    state.readout = background
        .hover_pos()
        .map(|p| transform.to_plane(p))
        .map(|(re, im)| readout(re, im, "s"));

    pan_and_zoom(ui, &background, &transform, state);
    background_menu(&background, &transform, system, state);

    for id in system.ids() {
        handle(ui, &painter, &transform, system, state, id, &palette);
    }
    background
}

fn paint_background(painter: &egui::Painter, t: &Transform, damping_grid: bool, palette: &Palette) {
    let rect = t.rect;
    let origin = t.to_screen(0.0, 0.0);
    // Stable region: the open left half plane.
    let stable = Rect::from_min_max(
        rect.min,
        Pos2::new(origin.x.clamp(rect.left(), rect.right()), rect.bottom()),
    );
    painter.rect_filled(stable, 0.0, palette.stable);

    let step = t.grid_step();
    let (re0, im1) = t.to_plane(rect.left_top());
    let (re1, im0) = t.to_plane(rect.right_bottom());
    let grid = Stroke::new(0.5, palette.grid);
    let font = FontId::proportional(11.0);
    for re in super::grid::multiples(re0, re1, step) {
        let x = t.to_screen(re, 0.0).x;
        painter.line_segment(
            [Pos2::new(x, rect.top()), Pos2::new(x, rect.bottom())],
            grid,
        );
        if re != 0.0 {
            let y = origin.y.clamp(rect.top(), rect.bottom() - 14.0);
            painter.text(
                Pos2::new(x + 2.0, y + 2.0),
                Align2::LEFT_TOP,
                format_number(re),
                font.clone(),
                palette.text,
            );
        }
    }
    for im in super::grid::multiples(im0, im1, step) {
        let y = t.to_screen(0.0, im).y;
        painter.line_segment(
            [Pos2::new(rect.left(), y), Pos2::new(rect.right(), y)],
            grid,
        );
        if im != 0.0 {
            let x = origin.x.clamp(rect.left(), rect.right() - 30.0);
            painter.text(
                Pos2::new(x + 3.0, y),
                Align2::LEFT_CENTER,
                format!("{}j", format_number(im)),
                font.clone(),
                palette.text,
            );
        }
    }
    if damping_grid {
        paint_damping_grid(painter, t, step, palette);
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
    painter.text(
        rect.right_top() + Vec2::new(-6.0, 4.0),
        Align2::RIGHT_TOP,
        "s-plane: σ (1/s) across, jω (rad/s) up",
        font,
        palette.text,
    );
}

/// Constant-ζ rays from the origin into the left half plane and constant-ωn circles.
fn paint_damping_grid(painter: &egui::Painter, t: &Transform, step: f64, palette: &Palette) {
    let stroke = Stroke::new(0.7, palette.damping);
    let font = FontId::proportional(10.0);
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
        painter.text(
            at,
            Align2::RIGHT_BOTTOM,
            format!("ζ={zeta}"),
            font.clone(),
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
        painter.text(
            label_at,
            Align2::RIGHT_BOTTOM,
            format!("ωn={}", format_number(wn)),
            font.clone(),
            palette.damping,
        );
    }
}

fn pan_and_zoom(ui: &Ui, background: &Response, t: &Transform, state: &mut SPlaneState) {
    let Some(view) = state.view.as_mut() else {
        return;
    };
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
    state.view = state.view.and_then(View::sane);
}

fn background_menu(
    background: &Response,
    t: &Transform,
    system: &mut System,
    state: &mut SPlaneState,
) {
    if background.secondary_clicked() {
        state.menu_at = background.interact_pointer_pos().map(|p| t.to_plane(p));
    }
    if background.clicked() {
        state.selected = None;
    }
    let at = state.menu_at.unwrap_or((-1.0, 1.0));
    let snap = state.snap.then(|| t.grid_step() / 5.0);
    let (re, im) = (snap_to(at.0, snap), snap_to(at.1, snap));
    let pair_im = if im.abs() > 0.0 {
        im.abs()
    } else {
        t.grid_step()
    };
    background.context_menu(|ui| {
        let mut add = |ui: &mut Ui, text: &str, role: RootRole, root: Root| {
            if ui
                .add_enabled(system.has_room(role), egui::Button::new(text))
                .clicked()
            {
                state.selected = Some(system.add(role, root));
                ui.close();
            }
        };
        add(ui, "Add real pole here", RootRole::Pole, Root::real(re));
        add(
            ui,
            "Add complex pole pair here",
            RootRole::Pole,
            Root::pair(re, pair_im),
        );
        add(ui, "Add real zero here", RootRole::Zero, Root::real(re));
        add(
            ui,
            "Add complex zero pair here",
            RootRole::Zero,
            Root::pair(re, pair_im),
        );
        ui.separator();
        if ui.button("Fit view to the roots").clicked() {
            state.view = None;
            ui.close();
        }
    });
}

fn snap_to(v: f64, step: Option<f64>) -> f64 {
    match step {
        Some(s) if s > 0.0 => (v / s).round() * s,
        _ => v,
    }
}

/// One root's handle (two for a pair): paint, drag, select, menu.
fn handle(
    ui: &mut Ui,
    painter: &egui::Painter,
    t: &Transform,
    system: &mut System,
    state: &mut SPlaneState,
    id: RootId,
    palette: &Palette,
) {
    let Some(root) = system.root(id).copied() else {
        return;
    };
    let members: Vec<(f64, String)> = match root.kind {
        RootKind::Real => vec![(0.0, id.label())],
        RootKind::Pair => vec![
            (root.im, id.label()),
            (-root.im, format!("{} mirror", id.label())),
        ],
    };
    for (k, (im, label)) in members.into_iter().enumerate() {
        let at = t.to_screen(root.re, im);
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * HANDLE_RADIUS));
        let widget_id = ui.scope_id().with(("root", id, k));
        let response = ui.interact(rect, widget_id, Sense::click_and_drag());
        let text = label.clone();
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, &text));

        if response.drag_started() || response.clicked() {
            state.selected = Some(id);
        }
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let (re, im) = t.to_plane(p);
            let snap = state.snap.then(|| t.grid_step() / 5.0);
            if let Some(r) = system.root_mut(id) {
                r.move_to(snap_to(re, snap), snap_to(im, snap));
            }
        }
        if response.hovered() || response.dragged() {
            let r = system.root(id).copied().unwrap_or(root);
            state.readout = Some(format!("{}: {}", id.label(), readout(r.re, r.im, "s")));
        }
        let mut delete = false;
        let mut toggle = false;
        response.context_menu(|ui| {
            if ui.button(format!("Delete {}", id.label())).clicked() {
                delete = true;
                ui.close();
            }
            let toggle_text = match root.kind {
                RootKind::Real => "Make it a complex pair (adds its mirror)",
                RootKind::Pair => "Make it two real roots",
            };
            if ui.button(toggle_text).clicked() {
                toggle = true;
                ui.close();
            }
        });
        if delete {
            system.remove(id);
            state.selected = None;
            return;
        }
        if toggle {
            system.toggle_pair(id, t.grid_step());
            return;
        }
        let selected = state.selected == Some(id);
        paint_mark(
            painter,
            at,
            id.role,
            selected || response.hovered(),
            palette,
        );
    }
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

/// `s = −1 ± 2j · ζ = 0.447 · ωn = 2.236 rad/s · τ = 1 s` for a point of the plane.
pub fn readout(re: f64, im: f64, name: &str) -> String {
    let root = if im.abs() > 0.0 {
        Root::pair(re, im)
    } else {
        Root::real(re)
    };
    let mut text = format!("{name} = {}", sig(re, 4));
    if im.abs() > 0.0 {
        text.push_str(&format!(" ± {}j", sig(im.abs(), 4)));
    }
    if let Some(zeta) = root.damping() {
        text.push_str(&format!(" · ζ = {}", sig(zeta, 4)));
    }
    text.push_str(&format!(
        " · ωn = {} rad/s",
        sig(root.natural_frequency(), 4)
    ));
    if re != 0.0 {
        text.push_str(&format!(" · τ = 1/|σ| = {} s", sig(1.0 / re.abs(), 4)));
    }
    if im.abs() > 0.0 {
        text.push_str(&format!(" · ωd = {} rad/s", sig(im.abs(), 4)));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transform_round_trip() {
        let t = Transform {
            rect: Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(400.0, 300.0)),
            view: View {
                center_re: -2.0,
                center_im: 0.5,
                pixels_per_unit: 40.0,
            },
        };
        let p = t.to_screen(-3.25, 1.5);
        let (re, im) = t.to_plane(p);
        assert!((re + 3.25).abs() < 1e-5 && (im - 1.5).abs() < 1e-5);
    }

    #[test]
    fn readout_names_damping_and_frequency() {
        let r = readout(-1.0, 2.0, "s");
        assert_eq!(
            r,
            "s = -1 ± 2j · ζ = 0.4472 · ωn = 2.236 rad/s · τ = 1/|σ| = 1 s · ωd = 2 rad/s"
        );
    }

    #[test]
    fn fitting_shows_every_root() {
        let system = System::default();
        let v = fit_view(&system, Vec2::new(400.0, 400.0));
        let t = Transform {
            rect: Rect::from_min_size(Pos2::ZERO, Vec2::new(400.0, 400.0)),
            view: v,
        };
        for (re, im) in [(-5.0, 0.0), (-1.0, 2.0), (-1.0, -2.0), (0.0, 0.0)] {
            assert!(t.rect.contains(t.to_screen(re, im)));
        }
    }
}
