//! The handles over the main plot, shared by the plot's guess and step-time handles
//! ([`super::plot`]) and the hand methods' ([`super::hand`]): how near a handle grabs
//! ([`GRAB`]), what they read ([`Over`]), the draggable area that holds the plot's axes when
//! grabbed ([`grab_area`]) and the disc a handle is drawn as ([`paint_handle`]).

use eframe::egui::{self, Id, Rect, Sense, Stroke, Ui};
use egui_plot::PlotTransform;

use crate::look::Look;

use super::commands::{Command, Frozen, Gesture};
use super::session::Session;

/// Pixels around a handle that grab it.
pub(super) const GRAB: f32 = 9.0;

/// The plot's bounds as they are drawn, to hold while a handle is dragged.
fn frozen(transform: &PlotTransform) -> Frozen {
    let b = transform.bounds();
    Frozen {
        t: (b.min()[0], b.max()[0]),
        y: (b.min()[1], b.max()[1]),
    }
}

/// What the handles over the main plot read.
pub(super) struct Over<'a> {
    pub session: &'a Session,
    pub transform: &'a PlotTransform,
    pub look: &'a Look,
}

/// A draggable area `rect` over the plot, named `label` for screen readers (and kittest),
/// explained by `help`; grabbing it holds the plot's axes as they are drawn.
pub(super) fn grab_area(
    ui: &mut Ui,
    (id, rect): (Id, Rect),
    (label, help): (&str, &str),
    transform: &PlotTransform,
    out: &mut Vec<Command>,
) -> egui::Response {
    let response = ui.interact(rect, id, Sense::drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, label));
    if response.drag_started() {
        out.push(Command::Handle(Gesture::Grab(frozen(transform))));
    }
    response.on_hover_text(help)
}

/// A draggable handle's disc at `at`, highlighted while hovered or dragged.
pub(super) fn paint_handle(
    ui: &egui::Ui,
    frame: egui::Rect,
    at: egui::Pos2,
    response: &egui::Response,
    look: &Look,
) {
    let color = if response.hovered() || response.dragged() {
        look.palette.selected
    } else {
        look.palette.handle
    };
    ui.painter_at(frame.expand(GRAB)).circle(
        at,
        5.5,
        color.gamma_multiply(0.35),
        Stroke::new(2.0, color),
    );
}
