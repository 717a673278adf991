//! The sampling and amplitude advisor: each of the notes' rules with the record's own
//! numbers (h, the model's τmax, θ and t_s, the step's effect and the noise) and whether it
//! holds. The plot: the record's samples, so the student sees how densely the response was
//! sampled.

use eframe::egui::{self, Ui};
use egui_plot::{Line, Points};

use crate::look::Look;
use crate::words::lsq_app::Phrase;
use degrau_ident::diagnose::test_causes::{RuleCheck, SamplingRule};
use degrau_ident::words::lsq::LsqPhrase as L;
use degrau_words::Lang;

use super::advisor::{AMPLITUDE_RATIO, Advice};
use super::session::Session;
use super::{heading, note, words};

/// The rule as the notes write it, with who gave it.
fn rule_name(rule: SamplingRule, lang: Lang) -> &'static str {
    match rule {
        SamplingRule::TenthOfSlowest => Phrase::RuleTenth,
        SamplingRule::DeadTimeRatio => Phrase::RuleDeadTime,
        SamplingRule::TimeConstantRatio => Phrase::RuleTimeConstant,
        SamplingRule::SettlingRatio => Phrase::RuleSettling,
    }
    .get(lang)
}

/// The ratio a rule looks at.
fn quantity(rule: SamplingRule) -> &'static str {
    match rule {
        SamplingRule::TenthOfSlowest => "h/τmax",
        SamplingRule::DeadTimeRatio => "h/θ",
        SamplingRule::TimeConstantRatio => "h/τ",
        SamplingRule::SettlingRatio => "h/t_s",
    }
}

/// Whether a check holds, in words.
fn verdict(c: &RuleCheck, lang: Lang) -> &'static str {
    if c.too_slow() {
        Phrase::TooSlow.get(lang)
    } else if c.too_fast() {
        Phrase::TooFast.get(lang)
    } else {
        L::Yes.get(lang)
    }
}

pub fn panel(ui: &mut Ui, session: &Session, look: &Look) {
    let lang = look.lang;
    heading(ui, Phrase::AdvisorHeading.get(lang));
    let Some(a) = &session.advice else {
        note(ui, look, Phrase::NoAdvice.get(lang));
        return;
    };
    let which = if a.fitted {
        Phrase::AdviceFromFit
    } else {
        Phrase::AdviceFromGuess
    };
    note(ui, look, &which.with(lang, &[a.model.structure.code()]));
    scales(ui, a, lang);
    egui::Grid::new("advisor")
        .striped(true)
        .num_columns(4)
        .show(ui, |ui| {
            ui.label(Phrase::Rule.get(lang));
            ui.label(Phrase::RecordValue.get(lang));
            ui.label(Phrase::Holds.get(lang));
            ui.end_row();
            for c in &a.checks {
                ui.label(rule_name(c.rule, lang));
                ui.label(format!("{} = {}", quantity(c.rule), lang.num(c.value, 3)));
                ui.label(verdict(c, lang));
                ui.end_row();
            }
            if let Some(amp) = &a.amplitude {
                ui.label(Phrase::RuleAmplitude.get(lang));
                ui.label(format!(
                    "{} / {} = {}",
                    lang.num(amp.effect, 3),
                    lang.num(amp.noise, 3),
                    lang.num(amp.ratio(), 3)
                ));
                ui.label(if amp.holds() {
                    L::Yes.get(lang)
                } else {
                    Phrase::TooSmall.get(lang)
                });
                ui.end_row();
            }
        });
    note(
        ui,
        look,
        &Phrase::AdvisorNote.with(lang, &[lang.num(AMPLITUDE_RATIO, 2)]),
    );
}

/// h and the model's time scales.
fn scales(ui: &mut Ui, a: &Advice, lang: Lang) {
    let s = &a.scales;
    let mut line = format!("h = {} s", words::num(a.h, lang));
    if let Some(t) = s.time_constants.first() {
        line.push_str(&format!(", τmax = {} s", words::num(*t, lang)));
    }
    if s.dead_time > 0.0 {
        line.push_str(&format!(", θ = {} s", words::num(s.dead_time, lang)));
    }
    if let Some(t) = s.settling_time {
        line.push_str(&format!(", t_s = {} s", words::num(t, lang)));
    }
    ui.label(line);
}

/// The record's samples.
pub fn plot(ui: &mut Ui, session: &Session, look: &Look) {
    let (lang, palette) = (look.lang, &look.palette);
    let Some(s) = &session.samples else { return };
    ui.label(Phrase::AdvisorPlot.get(lang));
    let shown = words::time_plot("advisor plot", ui.available_height(), lang).show(ui, |plot| {
        let points = words::pairs(&s.time, &s.y);
        plot.line(
            Line::new(Phrase::Measured.get(lang), points.clone())
                .color(palette.data.gamma_multiply(0.4)),
        );
        plot.points(
            Points::new(Phrase::Samples.get(lang), points)
                .color(palette.data)
                .radius(2.5),
        );
    });
    crate::look::name_canvas(&shown.response, Phrase::AdvisorPlot.get(lang));
}
