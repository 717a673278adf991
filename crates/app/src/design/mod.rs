//! The Design mode: place poles and zeros on the s-plane, watch the exact step response.
//!
//! [`session`] owns the state and what is derived from it (no egui); the views here
//! ([`system_panel`], [`splane`], [`step_plot`], [`metrics_table`]) read the session and
//! return [`Command`]s, which the top level applies once per frame after the views have
//! drawn, so every view of a frame shows the same state. What a view keeps and the session
//! holds sits below the views, [`commands`] and [`session`] (the s-plane's [`plane`], the
//! approximation's [`approx_state`]), so the commands and the session import no view.

pub mod analysis;
pub mod approx;
pub mod approx_state;
pub mod closed_loop;
pub mod commands;
pub mod locus_view;
pub mod loop_panel;
pub mod metrics_table;
pub mod plane;
pub mod presets;
pub mod session;
pub mod splane;
pub mod state;
pub mod step_plot;
pub mod system_panel;

use eframe::egui::{self, Key, RichText, Ui};

pub use commands::Command;
pub use session::{Saved, Session};

use crate::look::Look;
use crate::words::design::Design as P;
use degrau_words::Localize as _;

/// Smallest width and height of each plot (points): below it a panel scrolls or shrinks,
/// the plots never vanish.
pub const PLOT_MIN: f32 = 220.0;

/// Smallest width of a panel holding a plot: the plot and the panel's margins.
const PANEL_MIN: f32 = PLOT_MIN + 20.0;

/// Below this height (points under the menu) an approximation shown takes the metrics
/// table into its words, so the four plots keep their smallest size.
const TALL: f32 = 760.0;

/// What one frame of the Design mode drew and asks for.
#[must_use = "the commands must be applied"]
pub struct Shown {
    pub commands: Vec<Command>,
    /// Where the step plot was drawn (the PNG export takes it).
    pub plot_rect: Option<egui::Rect>,
}

/// Draws the Design mode in `ui` (the area below the menu and notices): the system panel on
/// the right, the metrics at the bottom, the s-plane on the left and the step plot in the
/// middle.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Shown {
    let mut commands = Vec::new();
    let full = ui.available_rect_before_wrap();
    // The approximation takes the whole width at the bottom: its plots and its words side by
    // side (under the system panel its words were one letter wide).
    // With an approximation shown in a short window the metrics table folds into the
    // approximation's words (whose error table has the same metrics), so the four plots
    // keep their smallest size.
    let fold = session.approx.choice.is_some() && full.height() < TALL;
    let mut metrics = |ui: &mut Ui| metrics_table::show(ui, session, kept, look);
    let folded: Option<approx::Folded<'_>> = if fold { Some(&mut metrics) } else { None };
    commands.extend(approx::panel(
        ui,
        &session.approx,
        &session.analysis,
        look,
        folded,
    ));
    // The right panel takes at most what leaves room for the two plots.
    let side_max = (full.width() - 2.0 * PANEL_MIN).max(180.0);
    commands.extend(
        egui::Panel::right("system")
            .resizable(true)
            .default_size(330.0f32.min(side_max))
            .size_range(180.0..=side_max)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .show(ui, |ui| {
                        let mut out = system_panel::show(ui, session, kept, look);
                        ui.separator();
                        out.extend(loop_panel::show(ui, session, kept, look));
                        out
                    })
                    .inner
            })
            .inner,
    );
    if !fold {
        commands.extend(metrics_panel(ui, session, kept, look));
    }
    let rest = ui.available_rect_before_wrap().width();
    // The s-plane takes at most half: the step plot is what a class looks at.
    let left_max = (rest - PANEL_MIN).min(0.5 * rest).max(PANEL_MIN);
    commands.extend(
        egui::Panel::left("s-plane")
            .resizable(true)
            .default_size((rest * 0.45).clamp(PANEL_MIN, left_max))
            .size_range(PANEL_MIN..=left_max)
            .show(ui, |ui| splane_panel(ui, session, kept, look))
            .inner,
    );
    // A thinner margin than egui's 8 points: the step plot keeps its smallest height under
    // an approximation in a 1000×650 window.
    let frame = egui::Frame::central_panel(ui.style()).inner_margin(egui::Margin::symmetric(8, 4));
    let (more, plot_rect) = egui::CentralPanel::default()
        .frame(frame)
        .show(ui, |ui| plot_panel(ui, session, kept, look))
        .inner;
    commands.extend(more);
    Shown {
        commands,
        // A margin for the rotated y-axis label, which egui_plot paints a few points
        // outside the area it takes.
        plot_rect: Some(plot_rect.expand(PNG_MARGIN)),
    }
}

/// The metrics table at the bottom, resizable.
fn metrics_panel(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let full = ui.available_rect_before_wrap().height();
    let bottom_max = (full - PLOT_MIN - 80.0).max(90.0);
    egui::Panel::bottom("metrics")
        .resizable(true)
        .default_size(200.0f32.min(bottom_max))
        .size_range(90.0..=bottom_max)
        .show(ui, |ui| {
            egui::ScrollArea::both()
                .show(ui, |ui| metrics_table::show(ui, session, kept, look))
                .inner
        })
        .inner
}

/// Points kept around the step plot's area in its PNG.
const PNG_MARGIN: f32 = 8.0;

fn splane_panel(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let mut out = Vec::new();
    let state = &kept.splane;
    ui.horizontal_wrapped(|ui| {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        let mut grid = state.damping_grid;
        if ui
            .checkbox(&mut grid, P::DampingGridShort.get(lang))
            .changed()
        {
            out.push(Command::SetDampingGrid(grid));
        }
        let mut snap = state.snap;
        if ui.checkbox(&mut snap, P::Snap.get(lang)).changed() {
            out.push(Command::SetSnap(snap));
        }
        if ui
            .button(P::Fit.get(lang))
            .on_hover_text(P::FitViewToRoots.get(lang))
            .clicked()
        {
            out.push(Command::SetView(None));
        }
    });
    if kept.system.has_rhp_pole() {
        ui.add(
            egui::Label::new(
                RichText::new(P::Unstable.get(lang))
                    .color(look.palette.error)
                    .strong(),
            )
            .wrap(),
        );
    }
    let readout = session
        .readout
        .clone()
        .unwrap_or_else(|| P::SPlaneHelp.get(lang).to_string());
    // Two lines always, so the canvas below never moves while the readout changes, and
    // the text wraps rather than being cut.
    let line = ui.text_style_height(&egui::TextStyle::Body);
    let size = egui::vec2(
        ui.available_width(),
        2.0 * line + ui.spacing().item_spacing.y,
    );
    let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
    ui.put(
        rect,
        egui::Label::new(RichText::new(readout).weak())
            .wrap()
            .halign(egui::Align::LEFT),
    );
    let overlay = locus_view::Overlay {
        settings: &kept.feedback,
        derived: &session.feedback,
    };
    out.extend(splane::show(ui, &kept.system, state, look, Some(&overlay)));
    out
}

fn plot_panel(
    ui: &mut Ui,
    session: &Session,
    kept: &Saved,
    look: &Look,
) -> (Vec<Command>, egui::Rect) {
    let out = step_plot::controls(ui, kept, look);
    if let Err(reason) = &session.analysis.tf {
        ui.add(
            egui::Label::new(
                RichText::new(format!(
                    "{} {}",
                    P::NoResponse.get(look.lang),
                    reason.text(look.lang)
                ))
                .color(look.palette.error),
            )
            .wrap(),
        );
    }
    let rect = step_plot::show(ui, session, kept, look);
    (out, rect)
}

/// The Design mode's keys: Delete removes the selected root, the arrows nudge it (by a
/// tenth of the s-plane's grid step). Nothing while a text field has focus.
pub fn keyboard(ui: &Ui, kept: &Saved) -> Vec<Command> {
    let typing = ui.ctx().memory(|m| m.focused().is_some());
    let Some(id) = kept.splane.selected.filter(|_| !typing) else {
        return Vec::new();
    };
    if ui.input(|i| i.key_pressed(Key::Delete) || i.key_pressed(Key::Backspace)) {
        return vec![Command::RemoveRoot(id)];
    }
    let step = kept.splane.view.map_or(0.1, |v| {
        crate::grid::nice_step(70.0 / v.pixels_per_unit) / 10.0
    });
    let (dre, dim) = ui.input(|i| {
        let mut d = (0.0, 0.0);
        if i.key_pressed(Key::ArrowLeft) {
            d.0 -= step;
        }
        if i.key_pressed(Key::ArrowRight) {
            d.0 += step;
        }
        if i.key_pressed(Key::ArrowUp) {
            d.1 += step;
        }
        if i.key_pressed(Key::ArrowDown) {
            d.1 -= step;
        }
        d
    });
    if (dre, dim) == (0.0, 0.0) {
        Vec::new()
    } else {
        vec![Command::Nudge { id, dre, dim }]
    }
}
