//! The rule table of the Tune mode's left panel: one row per rule with its Kc, Ti, Td, the
//! setpoint response's overshoot, settling time and IAE, the load response's peak
//! deviation and IAE, and Ms; a rule that does not apply says why. Clicking a rule loads its
//! controller; the rule chosen shows its formula and its source.

use eframe::egui::{self, RichText, Ui};

use degrau_lti::control::Rule;
use degrau_lti::control::tuning::formula;
use degrau_lti::words::control::ControlWord as W;
use degrau_words::{Lang, Localize};

use super::commands::Command;
use super::session::{Saved, Session};
use crate::look::Look;
use crate::words::tune::{IAE_SHORT, MS_SHORT, NO_VALUE, SETTLING_SHORT, Tune as T};

/// A rule's name in a table cell.
pub fn short_name(rule: Rule, lang: Lang) -> String {
    match rule {
        Rule::ZieglerNicholsOpen => T::ZnOpenShort.get(lang).into(),
        Rule::ZieglerNicholsUltimate => T::ZnUltimateShort.get(lang).into(),
        Rule::CohenCoon => "Cohen–Coon".into(),
        Rule::Imc => "IMC".into(),
        Rule::Simc => "SIMC".into(),
        Rule::Amigo => "AMIGO".into(),
        Rule::Lambda => "Lambda".into(),
    }
}

pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.heading(T::RulesHeading.get(lang));
    if session.table.is_empty() {
        ui.weak(T::RulesWaiting.get(lang));
        return;
    }
    ui.add(egui::Label::new(RichText::new(T::RulesHelp.get(lang)).weak()).wrap());
    let num = |x: Option<f64>| x.map_or_else(|| NO_VALUE.to_string(), |x| lang.num(x, 3));
    egui::ScrollArea::horizontal()
        .id_salt("rule table")
        .show(ui, |ui| {
            egui::Grid::new("rules")
                .striped(true)
                .num_columns(10)
                .show(ui, |ui| {
                    let heads = [
                        W::Rule.get(lang),
                        "Kc",
                        "Ti",
                        "Td",
                        T::OvershootShort.get(lang),
                        SETTLING_SHORT,
                        IAE_SHORT,
                        T::PeakShort.get(lang),
                        IAE_SHORT,
                        MS_SHORT,
                    ];
                    for h in heads {
                        ui.strong(h);
                    }
                    ui.end_row();
                    for row in session.table.iter().filter(|r| r.result.is_ok()) {
                        let Ok((tuning, tuned)) = &row.result else {
                            continue;
                        };
                        let chosen = kept.rule.as_deref() == Some(row.rule.key());
                        if ui
                            .selectable_label(chosen, short_name(row.rule, lang))
                            .on_hover_text(T::UseHelp.get(lang))
                            .clicked()
                        {
                            out.push(Command::UseRule(row.rule.key().to_string()));
                        }
                        let c = &tuning.controller;
                        ui.label(num(Some(c.kc)));
                        ui.label(num(c.action.integral().then_some(c.ti)));
                        ui.label(num(c.action.derivative().then_some(c.td)));
                        let (s, l) = (&tuned.setpoint_metrics, &tuned.load_metrics);
                        ui.label(num(s.overshoot));
                        ui.label(num(s.settling_time));
                        ui.label(num(s.iae));
                        ui.label(num(l.peak.map(|p| p.value)));
                        ui.label(num(l.iae));
                        ui.label(num(tuned.ms));
                        ui.end_row();
                    }
                });
        });
    for row in &session.table {
        if let Err(why) = &row.result {
            ui.add(
                egui::Label::new(
                    RichText::new(format!(
                        "{} {} {}",
                        short_name(row.rule, lang),
                        T::NotApplicable.get(lang),
                        why.text(lang)
                    ))
                    .weak(),
                )
                .wrap(),
            );
        }
    }
    chosen_rule(ui, session, kept, look);
}

/// The chosen rule's full name, formula and source.
fn chosen_rule(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) {
    let lang = look.lang;
    let Some(row) = kept
        .rule
        .as_deref()
        .and_then(|key| session.table.iter().find(|r| r.rule.key() == key))
    else {
        return;
    };
    ui.separator();
    ui.label(RichText::new(row.rule.text(lang)).strong());
    let f = kept
        .model
        .process_model()
        .ok()
        .and_then(|m| formula(row.rule, kept.controller.action, m.kind()).ok());
    if let Some(f) = f {
        ui.add(egui::Label::new(format!("{}: {}", W::Formula.get(lang), f.text(lang))).wrap());
        ui.add(
            egui::Label::new(
                RichText::new(format!("{}: {}", W::Source.get(lang), f.source(lang))).weak(),
            )
            .wrap(),
        );
    }
    if let Err(why) = &row.result {
        ui.add(egui::Label::new(RichText::new(why.text(lang)).weak()).wrap());
    }
}
