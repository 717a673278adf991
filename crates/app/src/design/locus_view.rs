//! The closed loop on the s-plane: the spec regions shaded where the closed-loop poles must
//! not be, the root locus's branches (cached points, only transformed here), its asymptotes
//! and centroid, breakaway points and jω crossings, K read on hover, and the closed-loop
//! poles as handles ("closed-loop pole 1", …) a student drags along their branch.

use eframe::egui::{self, Align2, FontId, Pos2, Rect, Sense, Shape, Stroke, Ui, Vec2};

use crate::look::Look;
use degrau_lti::C64;
use degrau_lti::feedback::SecondOrder;
use degrau_lti::words::feedback::Loop as P;

use super::closed_loop::{Found, LoopDerived, LoopSettings, Specs};
use super::commands::Command;
use super::plane::Transform;

/// Pixels around a closed-loop pole that grab it, and around the locus that read K.
const GRAB: f32 = 9.0;

/// What the s-plane draws of the loop.
#[derive(Clone, Copy)]
pub struct Overlay<'a> {
    pub settings: &'a LoopSettings,
    pub derived: &'a LoopDerived,
}

/// The plane distance that covers the canvas from anywhere in view (for regions and rays).
fn reach(t: &Transform) -> f64 {
    let r = t.rect();
    let (a, b) = (t.to_plane(r.left_top()), t.to_plane(r.right_bottom()));
    4.0 * (a.0.abs() + a.1.abs() + b.0.abs() + b.1.abs() + (b.0 - a.0).abs())
}

/// Paints the regions, the locus and its landmarks (below the handles).
pub fn paint(painter: &egui::Painter, t: &Transform, overlay: &Overlay<'_>, look: &Look) {
    if overlay.settings.specs.any_region() {
        paint_regions(painter, t, &overlay.settings.specs, look);
    }
    if overlay.settings.locus {
        paint_locus(painter, t, overlay, look);
    }
}

/// Shades what each spec forbids (the unshaded part meets them all).
fn paint_regions(painter: &egui::Painter, t: &Transform, specs: &Specs, look: &Look) {
    let fill = look.palette.error.gamma_multiply(0.12);
    let rect = t.rect();
    let far = reach(t);
    let x_of = |re: f64| {
        t.to_screen(re, 0.0)
            .x
            .clamp(rect.left() - 1.0, rect.right() + 1.0)
    };
    let y_of = |im: f64| {
        t.to_screen(0.0, im)
            .y
            .clamp(rect.top() - 1.0, rect.bottom() + 1.0)
    };
    // The right half plane always fails a response spec.
    let origin_x = x_of(0.0);
    let any_time_spec = specs.overshoot.is_some() || specs.settling.is_some();
    if any_time_spec && origin_x < rect.right() {
        painter.rect_filled(
            Rect::from_min_max(Pos2::new(origin_x, rect.top()), rect.right_bottom()),
            0.0,
            fill,
        );
    }
    if let Some(mp) = specs.overshoot
        && let Ok(zeta) = SecondOrder::damping_for_overshoot(mp)
    {
        // ζ < ζmin: between the ray at arccos ζmin and the imaginary axis.
        let angle = zeta.acos();
        for sign in [1.0, -1.0] {
            let tip = t.to_screen(-far * angle.cos(), sign * far * angle.sin());
            let axis = t.to_screen(0.0, sign * far);
            painter.add(Shape::convex_polygon(
                vec![t.to_screen(0.0, 0.0), tip, axis],
                fill,
                Stroke::new(1.0, look.palette.error.gamma_multiply(0.6)),
            ));
        }
    }
    if let Some(ts) = specs.settling.filter(|t| *t > 0.0) {
        let x = x_of(-4.0 / ts);
        painter.rect_filled(
            Rect::from_min_max(
                Pos2::new(x, rect.top()),
                Pos2::new(origin_x.max(x), rect.bottom()),
            ),
            0.0,
            fill,
        );
        painter.line_segment(
            [Pos2::new(x, rect.top()), Pos2::new(x, rect.bottom())],
            Stroke::new(1.0, look.palette.error.gamma_multiply(0.6)),
        );
    }
    if let Some(tp) = specs.peak.filter(|t| *t > 0.0) {
        let wd = std::f64::consts::PI / tp;
        painter.rect_filled(
            Rect::from_min_max(
                Pos2::new(rect.left(), y_of(wd)),
                Pos2::new(rect.right(), y_of(-wd)),
            ),
            0.0,
            fill,
        );
    }
    let circle = |wn: f64| -> Vec<Pos2> {
        (0..=96)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 96.0;
                t.to_screen(wn * a.cos(), wn * a.sin())
            })
            .collect()
    };
    if let Some(wn) = specs.wn_min.filter(|w| *w > 0.0) {
        painter.add(Shape::convex_polygon(circle(wn), fill, Stroke::NONE));
    }
    if let Some(wn) = specs.wn_max.filter(|w| *w > 0.0) {
        painter.add(Shape::line(
            circle(wn),
            Stroke::new(2.0, look.palette.error.gamma_multiply(0.6)),
        ));
    }
}

fn polyline(t: &Transform, points: &[[f64; 2]]) -> Vec<Pos2> {
    points.iter().map(|p| t.to_screen(p[0], p[1])).collect()
}

fn paint_locus(painter: &egui::Painter, t: &Transform, overlay: &Overlay<'_>, look: &Look) {
    let d = overlay.derived;
    let color = look.palette.path;
    let stroke = Stroke::new(1.8, color);
    for b in &d.branches {
        painter.add(Shape::line(polyline(t, b), stroke));
    }
    if overlay.settings.complementary {
        let dashed = Stroke::new(1.2, color.gamma_multiply(0.7));
        for b in &d.complementary_branches {
            painter.extend(Shape::dashed_line(&polyline(t, b), dashed, 6.0, 4.0));
        }
    }
    let Some(locus) = &d.locus else {
        return;
    };
    let font = FontId::proportional(12.0);
    if let Some(a) = &locus.asymptotes {
        let centre = t.to_screen(a.centroid, 0.0);
        let far = reach(t);
        let faint = Stroke::new(1.0, color.gamma_multiply(0.5));
        for angle in &a.angles {
            let end = t.to_screen(a.centroid + far * angle.cos(), far * angle.sin());
            painter.extend(Shape::dashed_line(&[centre, end], faint, 5.0, 5.0));
        }
        painter.circle_stroke(centre, 4.0, Stroke::new(1.5, color));
        painter.text(
            centre + Vec2::new(4.0, 4.0),
            Align2::LEFT_TOP,
            "σa",
            font.clone(),
            color,
        );
    }
    for b in &locus.breakaways {
        let at = t.to_screen(b.s, 0.0);
        let diamond = vec![
            at + Vec2::new(0.0, -5.0),
            at + Vec2::new(5.0, 0.0),
            at + Vec2::new(0.0, 5.0),
            at + Vec2::new(-5.0, 0.0),
        ];
        painter.add(Shape::convex_polygon(diamond, color, Stroke::NONE));
    }
    for c in &locus.crossings {
        for sign in [1.0, -1.0] {
            let at = t.to_screen(0.0, sign * c.omega);
            painter.circle_filled(at, 4.0, look.palette.error);
        }
        let at = t.to_screen(0.0, c.omega);
        let text = format!("Kcr = {}", look.lang.num(c.k, 4));
        painter.text(
            at + Vec2::new(6.0, -2.0),
            Align2::LEFT_BOTTOM,
            text,
            font.clone(),
            look.palette.error,
        );
    }
}

/// The closed-loop poles as draggable handles (when the loop is closed), and K on hover
/// over the locus; the readout replaces `readout` then.
pub fn handles(
    ui: &mut Ui,
    painter: &egui::Painter,
    t: &Transform,
    overlay: &Overlay<'_>,
    look: &Look,
    hover: Option<Pos2>,
    readout: &mut Option<String>,
) -> Vec<Command> {
    let mut out = Vec::new();
    let lang = look.lang;
    let d = overlay.derived;
    if overlay.settings.locus
        && let (Some(p), Some(locus)) = (hover, &d.locus)
    {
        let (re, im) = t.to_plane(p);
        if let Some((i, _, dist)) = locus.nearest(C64::new(re, im))
            && (dist * t.pixels_per_unit()) as f32 <= GRAB
        {
            let k = locus.points[i].k;
            *readout = Some(format!(
                "K = {} {} · {}",
                lang.num(k, 5),
                P::LocusGain.get(lang),
                super::plane::readout(re, im, "s", lang)
            ));
        }
    }
    if !overlay.settings.closed {
        return out;
    }
    let found = matches!(d.found, Some(Found::Gain(_)));
    for (branch, pole) in d.closed_poles.iter().enumerate() {
        let at = t.to_screen(pole.re, pole.im);
        let name = format!("{} {}", P::ClosedLoopPole.get(lang), branch + 1);
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * GRAB));
        let widget_id = ui.scope_id().with(("closed-loop pole", branch));
        if !t.holds_handle(ui, at, widget_id) {
            continue;
        }
        let response = ui.interact(rect, widget_id, Sense::drag());
        let label = name.clone();
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, &label));
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let (re, im) = t.to_plane(p);
            out.push(Command::DragLoopPole { branch, re, im });
        }
        if response.drag_stopped() {
            out.push(Command::EndDrag);
        }
        if response.hovered() || response.dragged() {
            *readout = Some(format!(
                "{name}: Kp = {} · {}",
                lang.num(overlay.settings.kp, 5),
                super::plane::readout(pole.re, pole.im, "s", lang)
            ));
        }
        let color = look.palette.minimum;
        let square = Rect::from_center_size(at, Vec2::splat(9.0));
        painter.rect_filled(square, 1.0, color);
        if found || response.hovered() {
            painter.rect_stroke(
                square.expand(3.0),
                2.0,
                Stroke::new(1.5, look.palette.selected),
                egui::StrokeKind::Outside,
            );
        }
    }
    out
}
