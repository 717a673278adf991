//! The z-plane tab: the sampling period h typed (a bad one refused, the old one kept), the
//! plant's H(z) = B(z)/A(z)·z^−nk by zero-order hold with its poles and zeros on the z-plane
//! (the unit circle drawn), its step response held as stairs over the continuous one, the
//! notes' sampling rules judged for h, and d2c back to G(s).

use eframe::egui::{self, RichText, Ui};
use egui_plot::{Legend, Line, LineStyle, MarkerShape, Plot, PlotPoints, Points};

use degrau_lti::C64;
use degrau_words::number::superscript;
use degrau_words::{Lang, Localize};

use super::commands::Command;
use super::derived::{MAX_SAMPLES, SampledData, Zoh};
use super::rules::Judged;
use super::session::{Saved, Session};
use crate::field::NumberField;
use crate::look::Look;
use crate::words::frequency::{self as words, Frequency as T};

/// Points of the unit circle.
const CIRCLE_POINTS: usize = 200;

pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    if let Some(h) = NumberField::new(T::PeriodField.get(lang), kept.h)
        .width(80.0)
        .show(ui, lang)
    {
        out.push(Command::SetPeriod(h));
    }
    if let Some(r) = &session.refusal {
        ui.add(egui::Label::new(RichText::new(r.text(lang)).color(look.palette.error)).wrap());
    }
    let Some(data) = &session.sampled else {
        return;
    };
    let plot_height = (0.55 * ui.available_height()).max(crate::design::PLOT_MIN);
    egui::ScrollArea::vertical()
        .id_salt("z-plane tab")
        .show(ui, |ui| match &data.zoh {
            Ok(zoh) => {
                written(ui, zoh, lang);
                plots(ui, data, zoh, plot_height, look);
                rules(ui, data, lang);
                back(ui, zoh, lang);
            }
            Err(e) => {
                let why = format!("{} {}", T::NoH.get(lang), e.text(lang));
                ui.add(egui::Label::new(RichText::new(why).color(look.palette.error)).wrap());
                rules(ui, data, lang);
            }
        });
}

/// H(z)'s coefficients, poles and zeros in words.
fn written(ui: &mut Ui, zoh: &Zoh, lang: Lang) {
    ui.label(RichText::new(T::SampledOf.get(lang)).strong());
    let tf = &zoh.tf;
    let text = format!(
        "H(z) = B(z)/A(z)·z⁻{}\nB(z) = {}\nA(z) = {}",
        superscript(tf.nk()),
        z_poly(tf.b(), lang),
        z_poly(tf.a(), lang)
    );
    ui.add(egui::Label::new(RichText::new(text).monospace()).wrap());
    ui.add(
        egui::Label::new(format!(
            "{} {}",
            T::PolesOfH.get(lang),
            roots_text(&zoh.poles, lang)
        ))
        .wrap(),
    );
    let zeros = match &zoh.zeros {
        Some(z) if z.is_empty() => T::NoZeros.get(lang).to_string(),
        Some(z) => roots_text(z, lang),
        None => T::ZerosUnknown.get(lang).to_string(),
    };
    ui.add(egui::Label::new(format!("{} {zeros}", T::ZerosOfH.get(lang))).wrap());
}

/// The most samples marked with a dot on the stairs.
const MARKED_SAMPLES: usize = 120;

/// c0 + c1 z⁻¹ + c2 z⁻² … with `lang`'s numbers.
pub fn z_poly(coeffs: &[f64], lang: Lang) -> String {
    let mut text = String::new();
    for (i, &c) in coeffs.iter().enumerate() {
        let power = match i {
            0 => String::new(),
            i => format!(" z⁻{}", superscript(i)),
        };
        let magnitude = lang.num(c.abs(), 6);
        match (i, c < 0.0) {
            (0, false) => text.push_str(&magnitude),
            (0, true) => text.push_str(&format!("−{magnitude}")),
            (_, false) => text.push_str(&format!(" + {magnitude}{power}")),
            (_, true) => text.push_str(&format!(" − {magnitude}{power}")),
        }
        if i == 0 {
            text.push_str(&power);
        }
    }
    text
}

/// Roots as "0.9048; 0.8 + 0.1j; 0.8 − 0.1j" (a semicolon between them: a comma is the
/// decimal separator in Portuguese).
pub fn roots_text(roots: &[C64], lang: Lang) -> String {
    roots
        .iter()
        .map(|r| {
            if r.im.abs() <= 1e-12 * r.norm().max(1e-300) {
                lang.num(r.re, 6)
            } else {
                let sign = if r.im < 0.0 { "−" } else { "+" };
                format!("{} {sign} {}j", lang.num(r.re, 6), lang.num(r.im.abs(), 6))
            }
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The z-plane and the step responses side by side.
fn plots(ui: &mut Ui, data: &SampledData, zoh: &Zoh, height: f32, look: &Look) {
    let lang = look.lang;
    let gap = ui.spacing().item_spacing.x;
    let width = ((ui.available_width() - gap) / 2.0).max(crate::design::PLOT_MIN);
    ui.horizontal_top(|ui| {
        let z = crate::grid::app_axes(Plot::new("z-plane"), lang)
            .x_grid_spacer(crate::grid::one_two_five())
            .data_aspect(1.0)
            .width(width)
            .height(height)
            .include_x(-1.2)
            .include_x(1.2)
            .include_y(-1.2)
            .include_y(1.2)
            .show_x(false)
            .show_y(false)
            .legend(Legend::default().background_alpha(0.75))
            .show(ui, |plot| {
                let circle = PlotPoints::from_parametric_callback(
                    |t| (t.cos(), t.sin()),
                    0.0..=std::f64::consts::TAU,
                    CIRCLE_POINTS,
                );
                plot.line(
                    Line::new(T::UnitCircle.get(lang), circle)
                        .color(look.palette.grid)
                        .style(LineStyle::dashed_dense()),
                );
                let xy = |r: &[C64]| r.iter().map(|c| [c.re, c.im]).collect::<Vec<_>>();
                plot.points(
                    Points::new(T::Poles.get(lang), xy(&zoh.poles))
                        .shape(MarkerShape::Cross)
                        .radius(7.0)
                        .color(look.palette.pole),
                );
                if let Some(zeros) = &zoh.zeros {
                    plot.points(
                        Points::new(words::ZEROS, xy(zeros))
                            .shape(MarkerShape::Circle)
                            .filled(false)
                            .radius(7.0)
                            .color(look.palette.zero),
                    );
                }
            });
        crate::look::name_canvas(&z.response, T::ZPlane.get(lang));
        let step = crate::grid::app_axes(Plot::new("sampled step"), lang)
            .x_grid_spacer(crate::grid::one_two_five())
            .x_axis_label("t (s)")
            .width(width)
            .height(height)
            .show_x(false)
            .show_y(false)
            .legend(
                Legend::default()
                    .position(egui_plot::Corner::RightBottom)
                    .background_alpha(0.75),
            )
            .show(ui, |plot| {
                plot.line(
                    Line::new(T::Continuous.get(lang), data.continuous.clone())
                        .color(look.palette.main)
                        .width(2.0),
                );
                plot.line(
                    Line::new(T::Stairs.get(lang), zoh.stairs.clone())
                        .color(look.palette.model)
                        .width(1.6)
                        // A staircase is not a dense curve: drawn as a band, its jumps
                        // would be filled.
                        .allow_band(false),
                );
                // The samples themselves, where the stairs equal the continuous response
                // (marked while they are few enough to tell apart).
                let samples: Vec<[f64; 2]> = zoh.stairs.iter().step_by(2).copied().collect();
                if samples.len() <= MARKED_SAMPLES {
                    plot.points(
                        Points::new(T::Stairs.get(lang), samples)
                            .color(look.palette.model)
                            .radius(2.5),
                    );
                }
            });
        crate::look::name_canvas(&step.response, T::StepPlot.get(lang));
    });
    if zoh.stairs.len() >= 2 * MAX_SAMPLES {
        ui.weak(T::StairsCut.get(lang));
    }
}

/// The notes' rules, each judged for h.
fn rules(ui: &mut Ui, data: &SampledData, lang: Lang) {
    ui.label(RichText::new(T::RulesHeading.get(lang)).strong());
    let f = &data.facts;
    let n = |x: f64| lang.num(x, 4);
    let facts = format!(
        "τ_max = {}, θ = {} s, t_s (95 %) = {}",
        f.tau_max.map_or("—".into(), |t| format!("{} s", n(t))),
        n(f.theta),
        f.settling.map_or("—".into(), |t| format!("{} s", n(t))),
    );
    ui.add(egui::Label::new(facts).wrap());
    for j in &data.rules {
        ui.add(egui::Label::new(rule_line(j, data.h, lang)).wrap());
    }
}

/// One rule: its statement, the interval of h it asks for and whether h is in it.
pub fn rule_line(j: &Judged, h: f64, lang: Lang) -> String {
    let n = |x: f64| lang.num(x, 3);
    let rule = words::rule_text(j.kind, lang);
    match j.range {
        Ok((lo, hi)) => {
            let range = if lo > 0.0 {
                format!("{} < h < {} s", n(lo), n(hi))
            } else {
                format!("h < {} s", n(hi))
            };
            let verdict = if j.met == Some(true) {
                T::Met
            } else {
                T::NotMet
            };
            format!("{rule}: {range}; h = {} s → {}", n(h), verdict.get(lang))
        }
        Err(why) => format!("{rule}: {} ({})", T::DoesNotApply.get(lang), why.text(lang)),
    }
}

/// d2c back: G(s) from H(z), or why not.
fn back(ui: &mut Ui, zoh: &Zoh, lang: Lang) {
    match &zoh.back {
        Ok(g) => {
            ui.label(T::Back.get(lang));
            super::source::written(ui, g, lang);
        }
        Err(e) => {
            ui.add(egui::Label::new(format!("{} {}", T::NoBack.get(lang), e.text(lang))).wrap());
        }
    }
}
