//! The Design mode's approximation view: pick one of the notes' approximations of the
//! system in view (a reduction or a stand-in for its dead time) and see the model's exact
//! step response over the original's, its poles and zeros on a small s-plane, its formula,
//! the error measures and the error table; optionally every method compared in one table,
//! copyable as Markdown for a report.
//!
//! [`panel`] draws the choice and what is derived from it ([`ApproxView`], with no egui:
//! [`super::approx_state`]) and returns [`Command`]s, as every Design view.

use eframe::egui::{self, Color32, Pos2, RichText, Sense, Stroke, Ui, Vec2};
use egui_plot::{Legend, Line, Plot};

use crate::look::Look;
use degrau_lti::C64;
use degrau_lti::approx::{Approximated, Approximation, DelayApproximant, Method, Reduction, Row};
use degrau_lti::words::approx::{self as words, ApproxPhrase as P};
use degrau_words::Lang;

use super::analysis::Analysis;
use super::approx_state::{ApproxCommand, ApproxView, Scene};
use super::commands::Command;

/// The legend name of the approximation's curve (notation, the same in every language).
pub const APPROX_CURVE_NAME: &str = "ỹ(t)";

/// The kinds a student picks from, each with the order it starts at.
fn kinds() -> [Approximation; 8] {
    [
        Approximation::Reduce(Method::Dominant.default_reduction()),
        Approximation::Reduce(Method::Taylor.default_reduction()),
        Approximation::Reduce(Method::Skogestad.default_reduction()),
        Approximation::Reduce(Method::Pade.default_reduction()),
        Approximation::Delay(DelayApproximant::Pade { m: 1, n: 1 }),
        Approximation::Delay(DelayApproximant::TaylorZero),
        Approximation::Delay(DelayApproximant::TaylorLag),
        Approximation::Delay(DelayApproximant::Limit { n: 3 }),
    ]
}

/// Whether two approximations are of the same kind (orders aside).
fn same_kind(a: &Approximation, b: &Approximation) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b)
        && match (a, b) {
            (Approximation::Reduce(x), Approximation::Reduce(y)) => x.method == y.method,
            (Approximation::Delay(x), Approximation::Delay(y)) => {
                std::mem::discriminant(x) == std::mem::discriminant(y)
            }
            _ => false,
        }
}

/// Draws a view folded into the approximation's words (the metrics table), with its commands.
pub type Folded<'a> = &'a mut dyn FnMut(&mut Ui) -> Vec<Command>;

/// Draws the approximation view as a panel at the bottom of the whole width; the commands
/// it asks for.
///
/// `metrics`, when given, draws the metrics table folded at the end of the words (a window
/// too short for both panels).
pub fn panel(
    ui: &mut Ui,
    view: &ApproxView,
    analysis: &Analysis,
    look: &Look,
    metrics: Option<Folded<'_>>,
) -> Vec<Command> {
    let open = view.choice.is_some();
    let id = if open {
        "approximation"
    } else {
        "approximation closed"
    };
    let mut panel = egui::Panel::bottom(id).resizable(open);
    if open {
        // Its plots at their smallest size; more when the window is tall enough.
        let need = open_height(ui);
        let full = ui.available_rect_before_wrap().height();
        let max = (full - super::PLOT_MIN - 160.0).max(need);
        panel = panel.default_size(need).size_range(need..=max);
    }
    panel
        .show(ui, |ui| {
            let mut out: Vec<Command> = chooser(ui, view, look)
                .into_iter()
                .map(Command::Approx)
                .collect();
            if open {
                out.extend(body(ui, (view, analysis), look, metrics));
            }
            out
        })
        .inner
}

/// The open panel's smallest height: one line of method buttons over plots of the smallest
/// size, with the panel's margins.
fn open_height(ui: &Ui) -> f32 {
    let spacing = ui.spacing();
    let chooser = spacing.interact_size.y + spacing.scroll.bar_width + spacing.item_spacing.y;
    chooser + 2.0 * spacing.item_spacing.y + super::PLOT_MIN + PLOT_AXIS + 20.0
}

/// Points egui_plot takes under a plot's area for its x axis (ticks and title).
const PLOT_AXIS: f32 = 12.0;

/// The line of method buttons (one line: the chosen one's settings are beside its words).
fn chooser(ui: &mut Ui, view: &ApproxView, look: &Look) -> Vec<ApproxCommand> {
    let lang = look.lang;
    let mut out = Vec::new();
    crate::look::one_line(ui, "approximation methods", |ui| {
        ui.label(RichText::new(format!("{}:", P::Heading.get(lang))).strong());
        if ui
            .selectable_label(view.choice.is_none(), P::NoMethod.get(lang))
            .clicked()
        {
            out.push(ApproxCommand::Choose(None));
        }
        for kind in kinds() {
            let chosen = view.choice.is_some_and(|c| same_kind(&c, &kind));
            let response = ui
                .selectable_label(chosen, button_name(&kind, lang))
                .on_hover_text(words::kind_name(&kind, lang));
            if response.clicked() && !chosen {
                out.push(ApproxCommand::Choose(Some(kind)));
            }
        }
    });
    out
}

/// The chosen method's order fields, the switch of the table of every method and its copy.
fn settings(
    ui: &mut Ui,
    view: &ApproxView,
    choice: Approximation,
    lang: Lang,
) -> Vec<ApproxCommand> {
    let mut out = Vec::new();
    ui.horizontal_wrapped(|ui| {
        if let Some(changed) = order_fields(ui, choice, lang) {
            out.push(ApproxCommand::Choose(Some(changed)));
        }
        let mut show = view.show_table;
        if ui.checkbox(&mut show, P::CompareAll.get(lang)).changed() {
            out.push(ApproxCommand::ShowTable(show));
        }
        if let Some(rows) = &view.table
            && ui
                .button(P::CopyTable.get(lang))
                .on_hover_text(P::CopyTableHelp.get(lang))
                .clicked()
        {
            ui.ctx().copy_text(words::comparison_table(rows, lang));
        }
    });
    out
}

/// The short name on a method's button.
fn button_name(a: &Approximation, lang: Lang) -> String {
    match a {
        Approximation::Reduce(Reduction {
            method: Method::Dominant,
            ..
        }) => lang.pick("Dominant poles", "Polos dominantes").into(),
        Approximation::Reduce(Reduction {
            method: Method::Taylor,
            ..
        }) => "Taylor".into(),
        Approximation::Reduce(Reduction {
            method: Method::Skogestad,
            ..
        }) => "Skogestad".into(),
        Approximation::Reduce(Reduction {
            method: Method::Pade,
            ..
        }) => "Padé G_{m,n}".into(),
        Approximation::Delay(DelayApproximant::Pade { .. }) => "θ → Padé".into(),
        Approximation::Delay(DelayApproximant::TaylorZero) => "θ → 1 − θs".into(),
        Approximation::Delay(DelayApproximant::TaylorLag) => "θ → 1/(1 + θs)".into(),
        Approximation::Delay(DelayApproximant::Limit { .. }) => "θ → (1 + θs/n)^−n".into(),
    }
}

/// A whole-number field; the new value when it changed.
fn count_field(
    ui: &mut Ui,
    label: &str,
    value: usize,
    range: std::ops::RangeInclusive<usize>,
) -> Option<usize> {
    let name = ui.label(label);
    let mut v = value;
    ui.add(egui::DragValue::new(&mut v).range(range).speed(0.05))
        .labelled_by(name.id);
    (v != value).then_some(v)
}

/// The order fields of `choice`; the changed approximation, if any.
fn order_fields(ui: &mut Ui, choice: Approximation, lang: Lang) -> Option<Approximation> {
    const TOP: usize = 10;
    match choice {
        Approximation::Reduce(r) if r.method == Method::Pade => {
            let m = count_field(ui, P::NumeratorDegree.get(lang), r.m, 0..=r.n);
            let n = count_field(ui, P::Order.get(lang), r.n, 1..=TOP);
            (m.is_some() || n.is_some()).then(|| {
                let n = n.unwrap_or(r.n);
                Approximation::Reduce(Reduction {
                    m: m.unwrap_or(r.m).min(n),
                    n,
                    ..r
                })
            })
        }
        Approximation::Reduce(r) => count_field(ui, P::Order.get(lang), r.n, 1..=TOP)
            .map(|n| Approximation::Reduce(Reduction { n, ..r })),
        Approximation::Delay(DelayApproximant::Pade { m, n }) => {
            let new_m = count_field(ui, P::NumeratorDegree.get(lang), m, 0..=n);
            let new_n = count_field(ui, P::Order.get(lang), n, 1..=TOP);
            ui.label("(?)").on_hover_text(P::DelayOrderHelp.get(lang));
            (new_m.is_some() || new_n.is_some()).then(|| {
                let n = new_n.unwrap_or(n);
                Approximation::Delay(DelayApproximant::Pade {
                    m: new_m.unwrap_or(m).min(n),
                    n,
                })
            })
        }
        Approximation::Delay(DelayApproximant::Limit { n }) => {
            count_field(ui, P::LimitTerms.get(lang), n, 1..=TOP)
                .map(|n| Approximation::Delay(DelayApproximant::Limit { n }))
        }
        Approximation::Delay(_) => None,
    }
}

/// The overlay, the s-plane and the words, side by side; the commands of the words' column.
fn body(
    ui: &mut Ui,
    (view, analysis): (&ApproxView, &Analysis),
    look: &Look,
    metrics: Option<Folded<'_>>,
) -> Vec<Command> {
    let lang = look.lang;
    let outcome = match &view.outcome {
        Some(Ok(a)) => Ok(a),
        Some(Err(e)) => Err(degrau_words::Localize::text(e, lang)),
        None => Err(analysis
            .tf
            .as_ref()
            .err()
            .map(|reason| degrau_words::Localize::text(reason, lang))
            .unwrap_or_else(|| crate::words::design::Design::NoSystemShort.get(lang).into())),
    };
    let size = ui.available_size();
    let mut out = Vec::new();
    ui.horizontal_top(|ui| {
        let scene = view.scene.as_ref().filter(|_| outcome.is_ok());
        if let Some(scene) = scene {
            let side = size.y.min(size.x * 0.25).max(super::PLOT_MIN);
            let width = (size.x * 0.4).max(super::PLOT_MIN);
            overlay(ui, scene, look, Vec2::new(width, size.y));
            plane(ui, scene, look, side);
        }
        ui.vertical(|ui| {
            if let Some(choice) = view.choice {
                out = settings(ui, view, choice, lang)
                    .into_iter()
                    .map(Command::Approx)
                    .collect();
            }
            egui::ScrollArea::both()
                .id_salt("approximation words")
                .auto_shrink(false)
                .show(ui, |ui| {
                    match outcome {
                        Ok(a) => {
                            if scene.is_some() {
                                ui.label(RichText::new(P::PlaneCaption.get(lang)).weak().small());
                            }
                            details(ui, view, a, look);
                        }
                        Err(reason) => {
                            ui.add(
                                egui::Label::new(
                                    RichText::new(format!(
                                        "{} {reason}",
                                        P::NoApproximation.get(lang)
                                    ))
                                    .color(look.palette.error),
                                )
                                .wrap(),
                            );
                        }
                    }
                    if let Some(metrics) = metrics {
                        ui.separator();
                        let folded = egui::CollapsingHeader::new(
                            crate::words::design::Design::MetricsFolded.get(lang),
                        )
                        .id_salt("metrics folded")
                        .show(ui, |ui| metrics(ui));
                        out.extend(folded.body_returned.unwrap_or_default());
                    }
                });
        });
    });
    out
}

/// The two responses on one plot of `size`.
fn overlay(ui: &mut Ui, scene: &Scene, look: &Look, size: Vec2) {
    let lang = look.lang;
    let response = crate::grid::app_axes(Plot::new("approximation overlay"), lang)
        .width(size.x)
        .height(size.y)
        .legend(Legend::default().position(egui_plot::Corner::RightBottom))
        .x_axis_label("t (s)")
        .allow_scroll(false)
        .show(ui, |plot| {
            plot.line(
                Line::new(super::step_plot::CURVE_NAME, scene.original.clone())
                    .color(look.palette.main)
                    .width(2.2),
            );
            plot.line(
                Line::new(APPROX_CURVE_NAME, scene.approx.clone())
                    .color(look.palette.compare)
                    .width(1.8),
            );
        });
    let name = P::PlotName.get(lang);
    crate::look::name_canvas(&response.response, name);
}

/// The model's poles (×) and zeros (o) over the original's, faint.
fn plane(ui: &mut Ui, scene: &Scene, look: &Look, side: f32) {
    let (rect, response) = ui.allocate_exact_size(Vec2::splat(side), Sense::hover());
    let name = P::PlaneName.get(look.lang);
    crate::look::name_canvas(&response, name);
    let all: Vec<C64> = [
        &scene.model_poles,
        &scene.model_zeros,
        &scene.original_poles,
        &scene.original_zeros,
    ]
    .into_iter()
    .flatten()
    .copied()
    .filter(|r| r.re.is_finite() && r.im.is_finite())
    .collect();
    let reach = all
        .iter()
        .fold(1.0f64, |m, r| m.max(r.re.abs()).max(r.im.abs()))
        * 1.2;
    let scale = (side as f64) / (2.0 * reach);
    let at = |r: C64| {
        Pos2::new(
            rect.center().x + (r.re * scale) as f32,
            rect.center().y - (r.im * scale) as f32,
        )
    };
    let painter = ui.painter_at(rect);
    let p = &look.palette;
    painter.rect_stroke(
        rect,
        2.0,
        Stroke::new(1.0, p.grid),
        egui::StrokeKind::Inside,
    );
    painter.line_segment(
        [
            Pos2::new(rect.left(), rect.center().y),
            Pos2::new(rect.right(), rect.center().y),
        ],
        Stroke::new(1.0, p.axis),
    );
    painter.line_segment(
        [
            Pos2::new(rect.center().x, rect.top()),
            Pos2::new(rect.center().x, rect.bottom()),
        ],
        Stroke::new(1.0, p.axis),
    );
    let cross = |c: Pos2, color: Color32| {
        let d = 5.0;
        for (a, b) in [((-d, -d), (d, d)), ((-d, d), (d, -d))] {
            painter.line_segment(
                [c + Vec2::new(a.0, a.1), c + Vec2::new(b.0, b.1)],
                Stroke::new(2.0, color),
            );
        }
    };
    let circle = |c: Pos2, color: Color32| painter.circle_stroke(c, 5.0, Stroke::new(2.0, color));
    for &r in &scene.original_poles {
        cross(at(r), p.ghost);
    }
    for &r in &scene.original_zeros {
        circle(at(r), p.ghost);
    }
    for &r in &scene.model_poles {
        cross(at(r), p.pole);
    }
    for &r in &scene.model_zeros {
        circle(at(r), p.zero);
    }
}

/// The formula, the measures, the error table and, when asked, the table of every method.
fn details(ui: &mut Ui, view: &ApproxView, a: &Approximated, look: &Look) {
    let lang = look.lang;
    if let Some(choice) = &view.choice {
        ui.label(RichText::new(words::name(choice, lang)).strong());
    }
    ui.label(RichText::new(format!("G̃(s) = {}", words::formula(&a.model, lang))).monospace());
    for line in words::measures(&a.comparison, lang) {
        ui.label(line);
    }
    egui::Grid::new("approximation errors")
        .striped(true)
        .show(ui, |ui| {
            for cell in words::error_header(lang) {
                ui.label(RichText::new(cell).strong());
            }
            ui.end_row();
            for d in &a.comparison.metrics {
                for cell in words::error_row(d, lang) {
                    ui.label(cell);
                }
                ui.end_row();
            }
        });
    if let Some(rows) = &view.table {
        ui.separator();
        comparison_grid(ui, rows, lang);
    }
}

/// Every method: name, order, largest gap, ISE, metrics within 5 % (or why not).
fn comparison_grid(ui: &mut Ui, rows: &[Row], lang: Lang) {
    egui::Grid::new("every approximation")
        .striped(true)
        .show(ui, |ui| {
            for p in [P::Model, P::OrderColumn, P::MaxError, P::Ise, P::Within] {
                ui.label(RichText::new(p.get(lang)).strong());
            }
            ui.end_row();
            for row in rows {
                ui.label(words::name(&row.approximation, lang));
                match &row.outcome {
                    Ok(a) => {
                        ui.label(a.model.order().to_string());
                        ui.label(format!("{} %", lang.num(100.0 * a.comparison.max_error, 3)));
                        ui.label(lang.num(a.comparison.ise, 3));
                        ui.label(words::kept_metrics(&a.comparison, lang));
                    }
                    Err(e) => {
                        ui.label(format!(
                            "{} {}",
                            P::DoesNotApply.get(lang),
                            degrau_words::Localize::text(e, lang)
                        ));
                    }
                }
                ui.end_row();
            }
        });
}
