//! The Tune mode's left panel: the process model (typed or received), the controller (its
//! action, its numbers typed, Kc, Ti and Td dragged), τc and the rule table.

use eframe::egui::{self, RichText, Ui};

use degrau_lti::control::Action;
use degrau_lti::words::control::ControlWord as W;
use degrau_words::{Lang, Localize};

use super::commands::{Command, Param};
use super::model::{ModelKind, ModelParam};
use super::session::{Refusal, Saved, Session};
use crate::field::NumberField;
use crate::look::Look;
use crate::words::tune::{self as words, Tune as T};

/// The width of a number field (points).
const FIELD_WIDTH: f32 = 80.0;

/// Draws the panel's sections.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    model_section(ui, session, kept, look, out);
    ui.separator();
    controller_section(ui, session, kept, look, out);
    ui.separator();
    super::tc_field::show(ui, session, kept, look, out);
    ui.separator();
    super::table::show(ui, session, kept, look, out);
}

/// The refusal `matches` picks, in the error colour.
fn refusal_line(ui: &mut Ui, session: &Session, look: &Look, matches: impl Fn(&Refusal) -> bool) {
    if let Some(r) = session.refusal.as_ref().filter(|r| matches(r)) {
        ui.add(egui::Label::new(RichText::new(r.text(look.lang)).color(look.palette.error)).wrap());
    }
}

fn model_section(
    ui: &mut Ui,
    session: &Session,
    kept: &Saved,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    ui.heading(T::ModelHeading.get(lang));
    match &kept.received {
        Some(code) => ui.label(format!("{} {code}", T::ReceivedFrom.get(lang))),
        None => ui.weak(T::Typed.get(lang)),
    };
    refusal_line(ui, session, look, |r| matches!(r, Refusal::Received(_)));
    let m = &kept.model;
    ui.horizontal_wrapped(|ui| {
        for (kind, name) in [(ModelKind::Foptd, T::Foptd), (ModelKind::Soptd, T::Soptd)] {
            if ui.radio(m.kind == kind, name.get(lang)).clicked() && m.kind != kind {
                out.push(Command::SetModelKind(kind));
            }
        }
    });
    let formula = match m.kind {
        ModelKind::Foptd => words::FOPTD_FORMULA,
        ModelKind::Soptd => words::SOPTD_FORMULA,
    };
    ui.label(formula);
    let mut fields = vec![(ModelParam::Gain, T::ProcessGain)];
    match m.kind {
        ModelKind::Foptd => fields.push((ModelParam::Tau1, T::Tau)),
        ModelKind::Soptd => {
            fields.extend([(ModelParam::Tau1, T::Tau1), (ModelParam::Tau2, T::Tau2)])
        }
    }
    fields.push((ModelParam::Delay, T::DeadTime));
    let fields = fields.into_iter().map(|(p, label)| (p, label.get(lang)));
    number_fields(ui, lang, fields, |p| m.get(p), Command::SetModel, out);
    refusal_line(ui, session, look, |r| matches!(r, Refusal::Model(..)));
}

/// A number field per (parameter, label), each typed value a command.
fn number_fields<P: Copy>(
    ui: &mut Ui,
    lang: Lang,
    fields: impl Iterator<Item = (P, &'static str)>,
    value: impl Fn(P) -> f64,
    command: impl Fn(P, f64) -> Command,
    out: &mut Vec<Command>,
) {
    for (p, label) in fields {
        if let Some(v) = NumberField::new(label, value(p))
            .width(FIELD_WIDTH)
            .show(ui, lang)
        {
            out.push(command(p, v));
        }
    }
}

fn controller_section(
    ui: &mut Ui,
    session: &Session,
    kept: &Saved,
    look: &Look,
    out: &mut Vec<Command>,
) {
    let lang = look.lang;
    let c = &kept.controller;
    ui.heading(W::Controller.get(lang));
    ui.horizontal_wrapped(|ui| {
        ui.label(T::Action.get(lang));
        for action in Action::ALL {
            let name = action.key().to_uppercase();
            if ui.radio(c.action == action, name).clicked() && c.action != action {
                out.push(Command::SetAction(action));
            }
        }
    });
    let mut fields = vec![(Param::Kc, W::Gain)];
    if c.action.integral() {
        fields.push((Param::Ti, W::IntegralTime));
    }
    if c.action.derivative() {
        fields.extend([(Param::Td, W::DerivativeTime), (Param::N, W::Filter)]);
    }
    fields.push((Param::B, W::SetpointWeight));
    let fields = fields.into_iter().map(|(p, label)| (p, label.get(lang)));
    number_fields(ui, lang, fields, |p| c.get(p), Command::SetParam, out);
    refusal_line(ui, session, look, |r| matches!(r, Refusal::Controller(..)));
    drag_row(ui, kept, look, out);
    ui.weak(W::IdealForm.get(lang));
    if let Ok(controller) = c.controller() {
        let p = controller.parallel();
        let n = |x: f64| lang.num(x, 4);
        ui.add(
            egui::Label::new(
                RichText::new(format!(
                    "{}: Kp = {}, Ki = {} 1/s, Kd = {} s, Tf = {} s",
                    W::ParallelForm.get(lang),
                    n(p.kp),
                    n(p.ki),
                    n(p.kd),
                    n(p.tf)
                ))
                .weak(),
            )
            .wrap(),
        );
    }
}

/// Kc, Ti and Td as drag values: the responses follow the drag frame by frame.
fn drag_row(ui: &mut Ui, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let c = &kept.controller;
    ui.label(T::DragHeading.get(lang));
    ui.horizontal_wrapped(|ui| {
        let mut params = vec![Param::Kc];
        if c.action.integral() {
            params.push(Param::Ti);
        }
        if c.action.derivative() {
            params.push(Param::Td);
        }
        for p in params {
            let mut v = c.get(p);
            let (name, range) = match p {
                Param::Kc if v < 0.0 => ("Kc", -1e9..=-1e-9),
                Param::Kc => ("Kc", 1e-9..=1e9),
                Param::Ti => ("Ti", 1e-6..=1e6),
                _ => ("Td", 0.0..=1e6),
            };
            let label = ui.label(name);
            // A step of half a percent of the value per point: a drag across the panel
            // multiplies or divides it by a few.
            let speed = (v.abs() * 0.005).max(1e-4);
            let response = ui
                .add(
                    egui::DragValue::new(&mut v)
                        .speed(speed)
                        .range(range)
                        .custom_formatter(move |x, _| lang.num(x, 4))
                        .custom_parser(|text| crate::field::parse_number(text).ok()),
                )
                .labelled_by(label.id)
                .on_hover_text(T::DragHelp.get(lang));
            if response.changed() {
                out.push(Command::SetParam(p, v));
            }
        }
    });
}
