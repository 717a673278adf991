//! The hand methods' views: the panel section (draw on the plot, the method, the table of
//! every method beside the least-squares fits), the construction drawn on the main plot (the
//! tangent through its point, the level lines, the times read off, the points used, the hand
//! model), and its handles: the tangent's point dragged along the curve, the two level lines
//! dragged up and down. Everything reads the session and returns commands.

use eframe::egui::{self, Id, Rect, RichText, Ui, Vec2};
use egui_plot::{HLine, Line, LineStyle, MarkerShape, PlotPoint, PlotUi, Points, VLine};

use crate::look::Look;
use degrau_ident::hand::{DeadTimeFrom, HandEstimate, HandMethod};
use degrau_ident::words::hand::{
    HandPhrase, estimate_row, least_squares_row, method_name, table_header,
};

use super::commands::Command;
use super::grab::{GRAB, Over, grab_area, paint_handle};
use super::hand_state::HandCommand;
use super::session::Session;

/// The panel's section.
pub fn section(ui: &mut Ui, session: &Session, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let hand = &session.hand;
    let mut shown = hand.shown;
    if ui
        .checkbox(&mut shown, HandPhrase::Heading.get(lang))
        .on_hover_text(HandPhrase::DragHelp.get(lang))
        .changed()
    {
        out.push(Command::Hand(HandCommand::Show(shown)));
    }
    if !hand.shown {
        return;
    }
    ui.horizontal_wrapped(|ui| {
        for m in HandMethod::ALL {
            if ui
                .selectable_label(hand.method() == m, method_name(m, lang))
                .clicked()
            {
                out.push(Command::Hand(HandCommand::Method(m)));
            }
        }
    });
    let mut departure = hand.overrides.dead_time_from == DeadTimeFrom::FirstDeparture;
    if hand.method() == HandMethod::SixtyThree
        && ui
            .checkbox(&mut departure, HandPhrase::DeadTimeFromDeparture.get(lang))
            .changed()
    {
        let from = if departure {
            DeadTimeFrom::FirstDeparture
        } else {
            DeadTimeFrom::Tangent
        };
        out.push(Command::Hand(HandCommand::DeadTimeFrom(from)));
    }
    if ui
        .button(HandPhrase::ResetConstruction.get(lang))
        .on_hover_text(HandPhrase::ResetHelp.get(lang))
        .clicked()
    {
        out.push(Command::Hand(HandCommand::Reset));
    }
    if let Some(e) = &hand.refused {
        ui.colored_label(look.palette.warning, degrau_words::Localize::text(e, lang));
        return;
    }
    table(ui, session, look);
}

/// One table: every method, then the least-squares fits, with the fit % of each.
fn table(ui: &mut Ui, session: &Session, look: &Look) {
    let lang = look.lang;
    let hand = &session.hand;
    egui::Grid::new("hand methods")
        .striped(true)
        .num_columns(7)
        .show(ui, |ui| {
            for head in table_header(lang) {
                ui.strong(head);
            }
            ui.end_row();
            for (m, r) in &hand.results {
                match r {
                    Ok(e) => {
                        // A method's warning (a construction starting before the step, θ
                        // taken as 0) is marked on its own row, drawn or not.
                        let warned = !e.warnings.is_empty();
                        for (c, cell) in estimate_row(e, lang).into_iter().enumerate() {
                            let marked = c == 0 && warned;
                            let text = if marked {
                                RichText::new(format!("{cell} (!)")).color(look.palette.warning)
                            } else {
                                RichText::new(cell)
                            };
                            let text = if *m == hand.method() && c == 0 {
                                text.strong()
                            } else {
                                text
                            };
                            let label = ui.label(text);
                            if marked {
                                let said: Vec<String> = e
                                    .warnings
                                    .iter()
                                    .map(|w| degrau_words::Localize::text(w, lang))
                                    .collect();
                                label.on_hover_text(said.join("\n"));
                            }
                        }
                    }
                    Err(err) => {
                        ui.label(method_name(*m, lang));
                        ui.label(HandPhrase::Failed.get(lang))
                            .on_hover_text(degrau_words::Localize::text(err, lang));
                    }
                }
                ui.end_row();
            }
            for r in &hand.least_squares {
                for cell in least_squares_row(r, lang) {
                    ui.label(cell);
                }
                ui.end_row();
            }
        });
    if hand.is_fitting() {
        ui.horizontal(|ui| {
            ui.spinner();
            ui.label(HandPhrase::LeastSquares.get(lang));
        });
    }
    if let Some(e) = hand.current() {
        for w in &e.warnings {
            ui.colored_label(look.palette.warning, degrau_words::Localize::text(w, lang));
        }
    }
    ui.weak(HandPhrase::Cost.get(lang));
}

/// The drawn method's construction on the main plot.
pub fn draw(plot: &mut PlotUi<'_>, session: &Session, look: &Look) {
    let hand = &session.hand;
    if !hand.shown {
        return;
    }
    let Some(e) = hand.current() else { return };
    let (lang, palette) = (look.lang, &look.palette);
    let c = &e.construction;
    for (phrase, y) in [
        (HandPhrase::InitialLevel, c.y0),
        (HandPhrase::FinalLevel, c.y_final),
    ] {
        plot.hline(
            HLine::new(phrase.get(lang), y)
                .color(palette.marker)
                .style(LineStyle::dashed_loose()),
        );
    }
    if let Some(t) = c.tangent {
        plot.line(
            Line::new(
                HandPhrase::TangentLine.get(lang),
                vec![[t.t_initial, c.y0], [t.t_final, c.y_final]],
            )
            .color(palette.selected)
            .width(1.5),
        );
        for x in [t.t_initial, t.t_final] {
            plot.vline(VLine::new("", x).color(palette.marker.gamma_multiply(0.6)));
        }
    }
    for l in &c.levels {
        let name = format!("{} %", lang.num(l.percent, 4));
        plot.hline(HLine::new(name.clone(), l.y).color(palette.marker.gamma_multiply(0.5)));
        plot.points(
            Points::new(name, vec![[l.t, l.y]])
                .shape(MarkerShape::Diamond)
                .radius(5.0)
                .color(palette.marker),
        );
        plot.vline(VLine::new("", l.t).color(palette.marker.gamma_multiply(0.6)));
    }
    if !c.points.is_empty() {
        let points: Vec<[f64; 2]> = c.points.iter().map(|&(t, y)| [t, y]).collect();
        plot.points(
            Points::new(HandPhrase::PointsUsed.get(lang), points)
                .radius(2.0)
                .color(palette.marker),
        );
    }
    hand_model(plot, session, e, look);
}

/// The hand model's response over the record, dashed.
fn hand_model(plot: &mut PlotUi<'_>, session: &Session, e: &HandEstimate, look: &Look) {
    let Some(data) = session.loaded.as_ref().and_then(|l| l.data.as_ref().ok()) else {
        return;
    };
    let Ok(y) = e.model.simulate(&data.input, &data.times) else {
        return;
    };
    let points: Vec<[f64; 2]> = data.times.iter().zip(y).map(|(&t, y)| [t, y]).collect();
    plot.line(
        Line::new(HandPhrase::HandModel.get(look.lang), points)
            .color(look.palette.compare)
            .style(LineStyle::dashed_dense())
            .width(1.5),
    );
}

/// The handles of the construction over the main plot: the tangent's point (along the
/// curve) and the two levels (up and down). True while one is held.
pub(super) fn handles(ui: &mut Ui, over: &Over<'_>, out: &mut Vec<Command>) -> bool {
    let (session, transform, look) = (over.session, over.transform, over.look);
    let hand = &session.hand;
    let Some(e) = hand.current().filter(|_| hand.shown) else {
        return false;
    };
    let lang = look.lang;
    let help = HandPhrase::DragHelp.get(lang);
    let frame: Rect = *transform.frame();
    let c = &e.construction;
    let mut held = false;
    if let Some(t) = c.tangent {
        let id = Id::unique("hand tangent point");
        let at = transform.position_from_point(&PlotPoint::new(t.t, t.y));
        let rect = Rect::from_center_size(at, Vec2::splat(2.0 * GRAB));
        let label = HandPhrase::TangentPoint.get(lang);
        let response = grab_area(ui, (id, rect), (label, help), transform, out);
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            let time = transform.value_from_position(p).x;
            out.push(Command::Hand(HandCommand::MoveTangent(time)));
        }
        held |= response.dragged() && !response.drag_stopped();
        paint_handle(ui, frame, at, &response, look);
    }
    for (phrase, y, command) in [
        (
            HandPhrase::InitialLevel,
            c.y0,
            HandCommand::SetInitialLevel as fn(f64) -> HandCommand,
        ),
        (
            HandPhrase::FinalLevel,
            c.y_final,
            HandCommand::SetFinalLevel,
        ),
    ] {
        let id = Id::unique(("hand level", phrase));
        let at = transform.position_from_point(&PlotPoint::new(0.0, y)).y;
        let rect = Rect::from_x_y_ranges(frame.x_range(), at - 3.0..=at + 3.0);
        let response = grab_area(ui, (id, rect), (phrase.get(lang), help), transform, out)
            .on_hover_cursor(egui::CursorIcon::ResizeVertical);
        if response.dragged()
            && let Some(p) = ui.ctx().pointer_interact_pos()
        {
            out.push(Command::Hand(command(transform.value_from_position(p).y)));
        }
        held |= response.dragged() && !response.drag_stopped();
    }
    held
}
