//! The closed loop's part of the system panel: close the loop around Kp·G(s), Kp typed or by
//! a slider, the root locus and its complementary half, the critical gain and breakaways,
//! the error constants and steady-state errors, the specs (shaded on the s-plane, and the
//! gain search that meets them on the exact response), the response to another input, and
//! the second-order formulas beside the exact metrics with their inverse. A dead time is
//! closed through its Padé approximant, of an order chosen here, and the loop says it is
//! approximate. Reads the settings kept and the session's caches only; returns commands.

use eframe::egui::{self, RichText, Ui};

use crate::field::{LimitReason, Limits, NumberField};
use crate::look::Look;
use degrau_lti::feedback::{
    Comparison, Input, Limit, LoopApproximant, PadeOrder, SecondOrder, SpecPair,
};
use degrau_lti::words::feedback::InputHeading;
use degrau_lti::words::feedback::{Loop as P, LoopLine, SpecName};
use degrau_words::Lang;
use degrau_words::Localize;

use super::closed_loop::{ControllerShape, Found, KP_LIMIT, LoopSettings, Specs};
use super::commands::Command;
use super::session::{Saved, Session};
use degrau_lti::control::Action;

/// Width of a number field (points).
const FIELD_WIDTH: f32 = 70.0;

/// Draws the loop's section; the commands it asks for.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let mut out = Vec::new();
    let settings = &kept.feedback;
    let derived = &session.feedback;
    ui.heading(P::LoopHeading.get(lang));
    let mut closed = settings.closed;
    if ui
        .checkbox(&mut closed, P::CloseLoop.get(lang))
        .on_hover_text(P::CloseLoopHelp.get(lang))
        .changed()
    {
        out.push(Command::SetLoopClosed(closed));
    }
    if let Some(Err(e)) = &derived.open_loop {
        warn(ui, &e.text(lang), look);
        return out;
    }
    if let Some(a) = &derived.approximant {
        out.extend(approximant(ui, a, settings.pade, look));
    }
    out.extend(controller_controls(ui, &settings.controller, lang));
    out.extend(gain_controls(ui, session, settings, lang));
    let mut shown = settings.locus;
    let mut complementary = settings.complementary;
    ui.horizontal_wrapped(|ui| {
        ui.checkbox(&mut shown, P::ShowLocus.get(lang));
        ui.checkbox(&mut complementary, P::Complementary.get(lang))
            .on_hover_text(P::ComplementaryHelp.get(lang));
    });
    if (shown, complementary) != (settings.locus, settings.complementary) {
        out.push(Command::SetLocus {
            shown,
            complementary,
        });
    }
    locus_facts(ui, session, lang);
    constants(ui, session, lang);
    out.extend(input_choice(ui, settings, lang));
    // The specs and the formulas fold away (closed at first): a panel laid out but unseen
    // still costs every frame.
    let specs_shown = egui::CollapsingHeader::new(P::SpecsHeading.get(lang))
        .id_salt("loop specs")
        .default_open(false)
        .show(ui, |ui| specs(ui, session, settings, look));
    out.extend(specs_shown.body_returned.unwrap_or_default());
    let formulas_shown = egui::CollapsingHeader::new(P::FormulasHeading.get(lang))
        .id_salt("loop formulas")
        .default_open(false)
        .show(ui, |ui| formulas(ui, session, lang));
    out.extend(formulas_shown.body_returned.unwrap_or_default());
    out
}

fn warn(ui: &mut Ui, text: &str, look: &Look) {
    ui.add(egui::Label::new(RichText::new(text).color(look.palette.warning)).wrap());
}

/// The dead time's Padé stand-in said approximate, and its order's choice.
fn approximant(ui: &mut Ui, a: &LoopApproximant, order: PadeOrder, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let line = LoopLine::Approximant {
        m: a.m,
        n: a.n,
        delay: lang.num(a.delay, 5),
    };
    warn(ui, &line.text(lang), look);
    let name = |o: PadeOrder| format!("({}, {})", o.m, o.n);
    let mut chosen = order;
    egui::ComboBox::from_label(P::PadeOrderLabel.get(lang))
        .selected_text(name(order))
        .show_ui(ui, |ui| {
            for o in PadeOrder::offered() {
                ui.selectable_value(&mut chosen, o, name(o));
            }
        })
        .response
        .on_hover_text(P::PadeOrderHelp.get(lang));
    if chosen == order {
        Vec::new()
    } else {
        vec![Command::SetPadeOrder(chosen)]
    }
}

/// The controller's shape: P, PI, PD or PID, with Ti, Td and N where it has them (its gain
/// is Kp below; the locus then runs over K with the controller's zeros and poles in place).
fn controller_controls(ui: &mut Ui, shape: &ControllerShape, lang: Lang) -> Vec<Command> {
    let mut next = *shape;
    ui.horizontal_wrapped(|ui| {
        ui.label(P::ControllerLabel.get(lang))
            .on_hover_text(P::ControllerHelp.get(lang));
        for action in Action::ALL {
            ui.selectable_value(&mut next.action, action, action.key().to_uppercase());
        }
    });
    let time = Limits::new(1e-6, 1e6, LimitReason::ControllerTime);
    ui.horizontal_wrapped(|ui| {
        if next.action.integral()
            && let Some(ti) = NumberField::new("Ti", next.ti)
                .limits(time)
                .width(FIELD_WIDTH)
                .show(ui, lang)
        {
            next.ti = ti;
        }
        if next.action.derivative() {
            if let Some(td) = NumberField::new("Td", next.td)
                .limits(time)
                .width(FIELD_WIDTH)
                .show(ui, lang)
            {
                next.td = td;
            }
            if let Some(n) = NumberField::new("N", next.n)
                .limits(Limits::new(1.0, 1000.0, LimitReason::Gain))
                .width(FIELD_WIDTH)
                .show(ui, lang)
            {
                next.n = n;
            }
        }
    });
    if next.action != Action::P {
        ui.add(egui::Label::new(P::ControllerGainIsK.get(lang)).wrap());
    }
    if next == *shape {
        Vec::new()
    } else {
        vec![Command::SetLoopController(next)]
    }
}

fn gain_controls(
    ui: &mut Ui,
    session: &Session,
    settings: &LoopSettings,
    lang: Lang,
) -> Vec<Command> {
    let mut out = Vec::new();
    let kp = settings.kp;
    let typed = NumberField::new("Kp", kp)
        .limits(Limits::new(-KP_LIMIT, KP_LIMIT, LimitReason::Gain))
        .width(FIELD_WIDTH)
        .show(ui, lang);
    out.extend(typed.map(Command::SetKp));
    let (lo, hi) = session.feedback.k_span();
    let mut value = kp.clamp(lo, hi.max(kp));
    let slider = egui::Slider::new(&mut value, lo..=hi.max(kp))
        .logarithmic(true)
        .show_value(false)
        .text(P::KpSlider.get(lang));
    if ui.add(slider).changed() {
        out.push(Command::SetKp(value));
    }
    out
}

fn locus_facts(ui: &mut Ui, session: &Session, lang: Lang) {
    let Some(locus) = &session.feedback.locus else {
        return;
    };
    if session.feedback.approximant.is_some() {
        ui.add(egui::Label::new(P::LocusApproximate.get(lang)).wrap());
    }
    let n = |x: f64| lang.num(x, 5);
    let line = match locus.crossings.first() {
        Some(c) => LoopLine::Critical(n(c.k), n(c.omega)).text(lang),
        None => P::NoCriticalGain.get(lang).to_string(),
    };
    ui.add(egui::Label::new(line).wrap());
    for b in &locus.breakaways {
        ui.add(
            egui::Label::new(LoopLine::Breakaway(b.leaves_axis, n(b.s), n(b.k)).text(lang)).wrap(),
        );
    }
    if let Some(a) = &locus.asymptotes {
        let angles: Vec<String> = a
            .angles
            .iter()
            .map(|x| format!("{}°", lang.num(x.to_degrees(), 4)))
            .collect();
        ui.add(
            egui::Label::new(LoopLine::Asymptotes(n(a.centroid), angles.join(", ")).text(lang))
                .wrap(),
        );
    }
}

fn limit(l: Limit, lang: Lang) -> String {
    match l {
        Limit::Finite(x) => lang.num(x, 5),
        Limit::Infinite => "∞".into(),
    }
}

fn constants(ui: &mut Ui, session: &Session, lang: Lang) {
    let Some(c) = &session.feedback.constants else {
        return;
    };
    ui.add(
        egui::Label::new(
            LoopLine::Constants {
                system_type: c.system_type,
                kp: limit(c.kp, lang),
                kv: limit(c.kv, lang),
                ka: limit(c.ka, lang),
            }
            .text(lang),
        )
        .wrap(),
    );
    let stable = session.feedback.closed_stable == Some(true);
    let text = if stable {
        let e = c.errors();
        LoopLine::Errors(
            limit(e.step, lang),
            limit(e.ramp, lang),
            limit(e.parabola, lang),
        )
        .text(lang)
    } else {
        P::NoSteadyState.get(lang).to_string()
    };
    ui.add(egui::Label::new(text).wrap());
}

/// One spec row: a checkbox naming it and its limit's field.
fn spec_row(
    ui: &mut Ui,
    name: SpecName,
    value: &mut Option<f64>,
    default: f64,
    unit: &str,
    lang: Lang,
) {
    ui.horizontal(|ui| {
        let mut on = value.is_some();
        if ui.checkbox(&mut on, name.text(lang)).changed() {
            *value = on.then_some(value.unwrap_or(default));
        }
        if let Some(v) = value {
            let label = name.field_label(lang);
            if let Some(typed) = NumberField::new(label, *v)
                .limits(Limits::new(1e-12, 1e12, LimitReason::Gain))
                .width(FIELD_WIDTH)
                .suffix(unit)
                .show(ui, lang)
            {
                *v = typed;
            }
        }
    });
}

fn specs(ui: &mut Ui, session: &Session, settings: &LoopSettings, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let mut out = Vec::new();
    ui.add(egui::Label::new(RichText::new(P::SpecsHelp.get(lang)).weak()).wrap());
    let mut s: Specs = settings.specs;
    spec_row(ui, SpecName::Overshoot, &mut s.overshoot, 10.0, "%", lang);
    spec_row(ui, SpecName::Settling, &mut s.settling, 4.0, "s", lang);
    spec_row(ui, SpecName::Peak, &mut s.peak, 2.0, "s", lang);
    spec_row(ui, SpecName::Rise, &mut s.rise, 1.0, "s", lang);
    spec_row(ui, SpecName::WnMin, &mut s.wn_min, 1.0, "rad/s", lang);
    spec_row(ui, SpecName::WnMax, &mut s.wn_max, 10.0, "rad/s", lang);
    spec_row(ui, SpecName::EssStep, &mut s.ess_step, 0.1, "", lang);
    spec_row(ui, SpecName::EssRamp, &mut s.ess_ramp, 0.5, "", lang);
    if s != settings.specs {
        out.push(Command::SetSpecs(s));
    }
    if ui
        .button(P::FindGain.get(lang))
        .on_hover_text(P::FindGainHelp.get(lang))
        .clicked()
    {
        out.push(Command::FindGain);
    }
    let n = |x: f64| lang.num(x, 5);
    match &session.feedback.found {
        Some(Found::Gain(g)) => {
            let hi = if g.range.1.is_finite() {
                n(g.range.1)
            } else {
                "∞".into()
            };
            ui.add(egui::Label::new(LoopLine::Found(n(g.k), n(g.range.0), hi).text(lang)).wrap());
        }
        Some(Found::Nothing) => warn(ui, P::NoGainFound.get(lang), look),
        Some(Found::NoSpecs) => warn(ui, P::NoSpecs.get(lang), look),
        Some(Found::Refused(e)) => warn(ui, &e.text(lang), look),
        None => {}
    }
    out
}

fn input_choice(ui: &mut Ui, settings: &LoopSettings, lang: Lang) -> Vec<Command> {
    let mut input = settings.input;
    let name = |i: Input| P::input_name(i).get(lang);
    egui::ComboBox::from_label(P::ResponseTo.get(lang))
        .selected_text(name(input))
        .show_ui(ui, |ui| {
            for i in [Input::Step, Input::Impulse, Input::Ramp, Input::Parabola] {
                ui.selectable_value(&mut input, i, name(i));
            }
        });
    if input != Input::Step {
        ui.add(egui::Label::new(RichText::new(InputHeading(input).text(lang)).weak()).wrap());
    }
    if input == settings.input {
        Vec::new()
    } else {
        vec![Command::SetInput(input)]
    }
}

/// The formulas of the dominant pair beside the exact metrics, and the inverse.
fn formulas(ui: &mut Ui, session: &Session, lang: Lang) -> Vec<Command> {
    let mut out = Vec::new();
    ui.add(egui::Label::new(RichText::new(P::FormulasHelp.get(lang)).weak()).wrap());
    let n = |x: f64| lang.num(x, 4);
    match &session.feedback.formulas {
        Some(f) => {
            ui.label(format!(
                "ζ = {} · ωn = {} rad/s · σ = {} · ωd = {} rad/s",
                n(f.pair.zeta),
                n(f.pair.wn),
                n(f.pair.sigma()),
                n(f.pair.wd())
            ));
            egui::Grid::new("second order check")
                .striped(true)
                .show(ui, |ui| {
                    for h in [P::Metric, P::Formula, P::Exact, P::Difference] {
                        ui.strong(h.get(lang));
                    }
                    ui.end_row();
                    let rows: [(&str, &Comparison, &str); 4] = [
                        ("t_s ≈ 4/(ζωn)", &f.settling_time, "s"),
                        ("t_p = π/ωd", &f.peak_time, "s"),
                        ("t_r = (π − arccos ζ)/ωd", &f.rise_time, "s"),
                        ("Mp = e^(−πζ/√(1−ζ²))", &f.overshoot, "%"),
                    ];
                    for (name, c, unit) in rows {
                        ui.label(name);
                        ui.label(format!("{} {unit}", n(c.formula)));
                        ui.label(c.exact.map_or("—".into(), |e| format!("{} {unit}", n(e))));
                        ui.label(
                            c.difference_percent()
                                .map_or("—".into(), |d| format!("{} %", lang.num(d, 3))),
                        );
                        ui.end_row();
                    }
                });
        }
        None => {
            ui.add(egui::Label::new(RichText::new(P::NoDominantPair.get(lang)).weak()).wrap());
        }
    }
    out.extend(inverse(ui, lang));
    out
}

/// From two specs to ζ, ωn, the poles and the canonical G(s), placed in one click.
fn inverse(ui: &mut Ui, lang: Lang) -> Vec<Command> {
    let mut out = Vec::new();
    ui.label(P::InverseHeading.get(lang));
    let id = ui.make_persistent_id("second order inverse");
    let (mut mp, mut ts, mut tp): (f64, f64, f64) =
        ui.data(|d| d.get_temp(id)).unwrap_or((10.0, 4.0, 2.0));
    let mut pick: usize = ui.data(|d| d.get_temp(id.with("pick"))).unwrap_or(0);
    let pairs = [P::PairMpTs, P::PairMpTp, P::PairTsTp];
    egui::ComboBox::from_label(P::PairLabel.get(lang))
        .selected_text(pairs[pick].get(lang))
        .show_ui(ui, |ui| {
            for (i, p) in pairs.iter().enumerate() {
                ui.selectable_value(&mut pick, i, p.get(lang));
            }
        });
    let field = |ui: &mut Ui, label: &'static str, v: &mut f64, unit: &str| {
        if let Some(x) = NumberField::new(label, *v)
            .id_salt("inverse")
            .limits(Limits::new(1e-9, 1e9, LimitReason::Gain))
            .width(FIELD_WIDTH)
            .suffix(unit)
            .show(ui, lang)
        {
            *v = x;
        }
    };
    if pick != 2 {
        field(ui, "Mp", &mut mp, "%");
    }
    if pick != 1 {
        field(ui, "t_s", &mut ts, "s");
    }
    if pick != 0 {
        field(ui, "t_p", &mut tp, "s");
    }
    ui.data_mut(|d| {
        d.insert_temp(id, (mp, ts, tp));
        d.insert_temp(id.with("pick"), pick);
    });
    let pair = match pick {
        0 => SpecPair::OvershootSettling {
            overshoot: mp,
            settling: ts,
        },
        1 => SpecPair::OvershootPeak {
            overshoot: mp,
            peak: tp,
        },
        _ => SpecPair::SettlingPeak {
            settling: ts,
            peak: tp,
        },
    };
    match SecondOrder::from_specs(pair) {
        Ok(p) => {
            let [upper, _] = p.poles();
            let w2 = p.wn * p.wn;
            let n = |x: f64| lang.num(x, 5);
            ui.add(
                egui::Label::new(format!(
                    "ζ = {} · ωn = {} rad/s · s = {} ± {}j\nG(s) = {} / (s² + {} s + {})",
                    n(p.zeta),
                    n(p.wn),
                    n(upper.re),
                    n(upper.im),
                    n(w2),
                    n(2.0 * p.zeta * p.wn),
                    n(w2)
                ))
                .wrap(),
            );
            if ui.button(P::PlaceIt.get(lang)).clicked() {
                out.push(Command::PlaceSecondOrder {
                    zeta: p.zeta,
                    wn: p.wn,
                });
            }
        }
        Err(e) => {
            ui.add(
                egui::Label::new(RichText::new(e.text(lang)).color(ui.visuals().error_fg_color))
                    .wrap(),
            );
        }
    }
    out
}
