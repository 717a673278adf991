//! The side panel: the system as numbers a student can type (gain and what it means, dead
//! time, step amplitude, every pole and zero), presets, the comparison, and the transfer
//! function as MATLAB would print it. Every field is a [`NumberField`]: a decimal comma is
//! accepted, a refusal is said under the field and never applied, and nothing here grows
//! with a number (fields have a fixed width, long text wraps).

use eframe::egui::{self, RichText, Ui};

use crate::field::{FieldError, LimitReason, Limits, NumberField};
use crate::look::Look;
use crate::words::design::{Design as P, root_label};
use degrau_lti::poly::format_poly;
use degrau_words::Lang;
use degrau_words::Localize as _;

use super::commands::Command;
use super::session::{Saved, Session, placement_of};
use super::state::{
    AMPLITUDE_LIMIT, DELAY_LIMIT, GAIN_LIMIT, GainMode, MAX_ROOTS, ROOT_LIMIT, Root, RootId,
    RootKind, RootRole, System,
};

/// Width of a number field (points).
const FIELD_WIDTH: f32 = 86.0;

/// Draws the panel; returns the edits and requests as commands.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let mut out = Vec::new();
    ui.heading(P::SystemHeading.get(lang));
    // The label sits beside the box: the box leaves it room, so it is never wrapped.
    let label_width = ui.fonts_mut(|f| {
        f.layout_no_wrap(
            P::Example.get(lang).to_string(),
            egui::TextStyle::Body.resolve(ui.style()),
            look.palette.axis,
        )
        .size()
        .x
    });
    let room = ui.available_width() - label_width - 3.0 * ui.spacing().item_spacing.x - 20.0;
    egui::ComboBox::from_label(P::Example.get(lang))
        .selected_text(P::LoadExample.get(lang))
        .width(room.clamp(120.0, 260.0))
        .show_ui(ui, |ui| {
            for (i, p) in session.presets.iter().enumerate() {
                if ui.selectable_label(false, p.name(lang)).clicked() {
                    out.push(Command::LoadPreset(i));
                }
            }
        });
    ui.horizontal_wrapped(|ui| {
        if kept.compare.is_none() {
            if ui
                .button(P::CompareKeep.get(lang))
                .on_hover_text(P::CompareKeepHelp.get(lang))
                .clicked()
            {
                out.push(Command::CompareWithCurrent);
            }
        } else if ui.button(P::StopComparing.get(lang)).clicked() {
            out.push(Command::StopComparing);
        }
    });
    ui.separator();
    out.extend(gain_delay_amplitude(ui, &kept.system, lang));
    ui.separator();
    out.extend(root_list(
        ui,
        &kept.system,
        kept.splane.selected,
        RootRole::Pole,
        lang,
    ));
    ui.separator();
    out.extend(root_list(
        ui,
        &kept.system,
        kept.splane.selected,
        RootRole::Zero,
        lang,
    ));
    ui.separator();
    transfer_function(ui, session, lang);
    out.extend(coefficient_fields(ui, session, &kept.system, lang));
    out
}

/// What the coefficient fields hold between frames.
#[derive(Debug, Clone, Default)]
struct CoefficientBuffer {
    num: String,
    den: String,
    /// The coefficients the texts were written from, and in which language's numbers.
    source: Option<(Vec<f64>, Vec<f64>)>,
    written_in: Option<Lang>,
    editing: bool,
    /// The texts were just committed: they stay as the student typed them (not rewritten
    /// as the system's monic coefficients) until the system changes otherwise.
    typed: bool,
    error: Option<String>,
}

/// A typed list of coefficients: separated by spaces or semicolons (MATLAB's `[1 7 15 25]`),
/// or by commas in English; a decimal comma is read in Portuguese.
pub fn parse_coefficients(text: &str, lang: Lang) -> Result<Vec<f64>, crate::field::FieldError> {
    let inner = text.trim().trim_start_matches('[').trim_end_matches(']');
    let separators: &[char] = match lang {
        Lang::En => &[',', ';', ' ', '\t'],
        Lang::Pt => &[';', ' ', '\t'],
    };
    let items: Vec<&str> = inner
        .split(separators)
        .filter(|t| !t.trim().is_empty())
        .collect();
    if items.is_empty() {
        return Err(crate::field::FieldError::Empty);
    }
    items.into_iter().map(crate::field::parse_number).collect()
}

/// The system's G(s) as num and den coefficients (descending powers), typed as in
/// `tf(num, den)`: committing a pair replaces the poles, zeros and gain.
fn coefficient_fields(ui: &mut Ui, session: &Session, system: &System, lang: Lang) -> Vec<Command> {
    use degrau_words::Localize;
    let mut out = Vec::new();
    let id = ui.make_persistent_id("typed coefficients");
    let mut buffer: CoefficientBuffer = ui.data(|d| d.get_temp(id)).unwrap_or_default();
    let current = session
        .analysis
        .tf
        .as_ref()
        .ok()
        .map(|tf| (tf.num(), tf.den()));
    // Written again when the system changes, or the language (0.5 reads 0,5 in Portuguese);
    // what the student typed stays as typed until the system changes otherwise.
    let relanguaged = buffer.written_in.is_some_and(|l| l != lang) && !buffer.typed;
    if !buffer.editing && (buffer.source != current || relanguaged) {
        buffer.written_in = Some(lang);
        if buffer.typed && buffer.source != current {
            buffer.typed = false;
        } else if let Some((num, den)) = &current {
            let list = |c: &[f64]| {
                c.iter()
                    .map(|x| lang.num(*x, 8))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            buffer.num = list(num);
            buffer.den = list(den);
        }
        buffer.source = current;
        buffer.error = None;
    }
    ui.label(degrau_lti::words::feedback::Loop::CoefficientsHelp.get(lang));
    let mut commit = false;
    for (label, text) in [("num", &mut buffer.num), ("den", &mut buffer.den)] {
        ui.horizontal(|ui| {
            let name = ui.label(label);
            let response = ui
                .add(egui::TextEdit::singleline(text).desired_width(180.0))
                .labelled_by(name.id);
            if response.has_focus() {
                buffer.editing = true;
            }
            if response.lost_focus() {
                commit = true;
            }
        });
    }
    if commit && buffer.editing {
        buffer.editing = false;
        let parsed = parse_coefficients(&buffer.num, lang)
            .and_then(|n| parse_coefficients(&buffer.den, lang).map(|d| (n, d)));
        match parsed {
            Err(e) => buffer.error = Some(e.text(lang)),
            Ok((num, den)) => match degrau_lti::TransferFunction::from_coeffs(&num, &den) {
                Err(e) => buffer.error = Some(e.text(lang)),
                Ok(_) => match super::session::from_coefficients(system, &num, &den) {
                    Some(s) if s.check().is_ok() && s.placement().is_ok() => {
                        buffer.error = None;
                        buffer.source = None;
                        buffer.typed = true;
                        out.push(Command::SetCoefficients { num, den });
                    }
                    _ => {
                        buffer.error = Some(
                            degrau_lti::words::feedback::Loop::CoefficientsBeyond
                                .get(lang)
                                .to_string(),
                        )
                    }
                },
            },
        }
    }
    if let Some(e) = &buffer.error {
        ui.add(egui::Label::new(RichText::new(e).color(ui.visuals().error_fg_color)).wrap());
    }
    ui.data_mut(|d| d.insert_temp(id, buffer));
    out
}

fn gain_delay_amplitude(ui: &mut Ui, system: &System, lang: Lang) -> Vec<Command> {
    let mut out = Vec::new();
    ui.horizontal_wrapped(|ui| {
        ui.label(P::GainMeans.get(lang))
            .on_hover_text(P::GainMeansHelp.get(lang));
        let mut mode = system.gain_mode;
        ui.radio_value(&mut mode, GainMode::Zpk, P::GainZpk.get(lang));
        ui.radio_value(&mut mode, GainMode::Static, P::GainStatic.get(lang));
        if mode != system.gain_mode {
            out.push(Command::SetGainMode(mode));
        }
    });
    let gain = NumberField::new(P::Gain.get(lang), system.gain)
        .limits(Limits::new(-GAIN_LIMIT, GAIN_LIMIT, LimitReason::Gain))
        .width(FIELD_WIDTH)
        .show(ui, lang);
    out.extend(gain.map(Command::SetGain));
    let delay = NumberField::new(P::DeadTime.get(lang), system.delay)
        .limits(Limits::new(0.0, DELAY_LIMIT, LimitReason::DeadTime))
        .width(FIELD_WIDTH)
        .suffix("s")
        .show(ui, lang);
    out.extend(delay.map(Command::SetDelay));
    let amplitude = NumberField::new(P::Amplitude.get(lang), system.amplitude)
        .limits(Limits::new(
            -AMPLITUDE_LIMIT,
            AMPLITUDE_LIMIT,
            LimitReason::Amplitude,
        ))
        .width(FIELD_WIDTH)
        .show(ui, lang);
    out.extend(amplitude.map(Command::SetAmplitude));
    out
}

/// A number typed in a field, read as the command line reads its numbers (− as a minus),
/// refused unless finite: "inf", "NaN" or "1e400" keep the field's value. (The Identify
/// mode's fields read their numbers with this until they use [`NumberField`].)
pub fn finite_number(text: &str) -> Option<f64> {
    degrau_lti::parse::parse_real(text).ok()
}

/// The limits of σ and ω, and what they protect.
fn root_limits(min: f64) -> Limits {
    Limits::new(min, ROOT_LIMIT, LimitReason::RootMagnitude)
}

/// A refusal of a root value that is in range alone but not with the other roots.
fn placement_refusal(
    system: &System,
    id: RootId,
    re: f64,
    im: f64,
    value: f64,
) -> Result<(), FieldError> {
    match placement_of(system, id, re, im) {
        Ok(()) => Ok(()),
        Err(LimitReason::RootMagnitude) => Err(FieldError::Above {
            value: re.hypot(im),
            max: ROOT_LIMIT,
            why: Some(LimitReason::RootMagnitude),
        }),
        Err(why) => Err(FieldError::Refused { value, why }),
    }
}

fn root_list(
    ui: &mut Ui,
    system: &System,
    selected: Option<RootId>,
    role: RootRole,
    lang: Lang,
) -> Vec<Command> {
    let mut out = Vec::new();
    let (add_real, add_pair, none) = match role {
        RootRole::Pole => (P::AddRealPole, P::AddPolePair, P::NoPoles),
        RootRole::Zero => (P::AddRealZero, P::AddZeroPair, P::NoZeros),
    };
    let title = crate::words::design::role_heading(role, lang);
    ui.horizontal_wrapped(|ui| {
        ui.strong(title);
        let room = system.has_room(role);
        let full = format!("{} {MAX_ROOTS}", P::AtMostRoots.get(lang));
        let mut add = |ui: &mut Ui, text: P, root: Root| {
            if ui
                .add_enabled(room, egui::Button::new(text.get(lang)).small())
                .on_disabled_hover_text(&full)
                .clicked()
            {
                out.push(Command::AddRoot { role, root });
            }
        };
        let re = next_free_real(system.roots(role));
        add(ui, add_real, Root::real(re));
        add(ui, add_pair, Root::pair(re, 1.0));
    });
    if system.roots(role).is_empty() {
        ui.weak(none.get(lang));
    }
    for (index, root) in system.roots(role).iter().enumerate() {
        let id = RootId { role, index };
        ui.push_id(("root row", id), |ui| {
            out.extend(root_row(ui, system, *root, id, selected == Some(id), lang));
        });
    }
    out
}

/// One root: its name (click to select), σ and ω, make pair / make real, delete.
fn root_row(
    ui: &mut Ui,
    system: &System,
    root: Root,
    id: RootId,
    is_selected: bool,
    lang: Lang,
) -> Vec<Command> {
    let mut out = Vec::new();
    ui.horizontal_wrapped(|ui| {
        // "pole 1:" (the s-plane's handle is "pole 1").
        let name = ui.selectable_label(is_selected, format!("{}:", root_label(id, lang)));
        if name.clicked() {
            out.push(Command::Select(Some(id)));
        }
        let sigma = NumberField::new("σ", root.re)
            .id_salt(("σ", id))
            .limits(root_limits(-ROOT_LIMIT))
            .width(FIELD_WIDTH)
            .validate(|re| placement_refusal(system, id, re, root.im, re))
            .show(ui, lang);
        if let Some(re) = sigma {
            out.push(Command::SetRoot {
                id,
                re,
                im: root.im,
            });
        }
        if root.kind == RootKind::Pair {
            let omega = NumberField::new("±jω", root.im)
                .id_salt(("ω", id))
                .limits(root_limits(0.0))
                .width(FIELD_WIDTH)
                .validate(|im| placement_refusal(system, id, root.re, im, im))
                .show(ui, lang);
            if let Some(im) = omega {
                out.push(Command::SetRoot {
                    id,
                    re: root.re,
                    im,
                });
            }
        }
        let toggle_text = match root.kind {
            RootKind::Pair => P::MakeReal,
            RootKind::Real => P::MakePair,
        };
        if ui
            .small_button(toggle_text.get(lang))
            .on_hover_text(P::TogglePairHelp.get(lang))
            .clicked()
        {
            out.push(Command::TogglePair { id, im: 1.0 });
        }
        if ui
            .small_button(P::DeleteSmall.get(lang))
            .on_hover_text(format!("{} {}", P::Delete.get(lang), root_label(id, lang)))
            .clicked()
        {
            out.push(Command::RemoveRoot(id));
        }
    });
    out
}

/// num over den as three monospace lines, each centred over the bar, and a factor after
/// the fraction on the bar's line (`e^(−0.5 s)` multiplies the whole fraction, not den).
pub fn fraction_text(num: &str, den: &str, factor: &str) -> String {
    let width = num.chars().count().max(den.chars().count()).max(1);
    let centred = |text: &str| {
        let pad = (width - text.chars().count().min(width)) / 2;
        format!("{}{text}", " ".repeat(pad))
    };
    format!(
        "{}\n{}{factor}\n{}",
        centred(num),
        "─".repeat(width),
        centred(den)
    )
}

/// A real part left of the existing roots, so a new root does not sit on another.
fn next_free_real(roots: &[Root]) -> f64 {
    let leftmost = roots.iter().map(|r| r.re).fold(0.0, f64::min);
    (leftmost - 1.0).floor()
}

fn transfer_function(ui: &mut Ui, session: &Session, lang: Lang) {
    ui.strong("G(s)");
    match &session.analysis.tf {
        Ok(tf) => {
            let num = lang.localize_number(&format_poly(&tf.num()));
            let den = lang.localize_number(&format_poly(&tf.den()));
            let delay = if tf.delay() > 0.0 {
                format!(" · e^(−{} s)", lang.num(tf.delay(), 6))
            } else {
                String::new()
            };
            ui.add(
                egui::Label::new(RichText::new(fraction_text(&num, &den, &delay)).monospace())
                    .wrap(),
            );
            let dc = tf.dc_gain();
            let dc_text = if dc.is_finite() {
                lang.num(dc, 6)
            } else {
                P::Integrator.get(lang).to_string()
            };
            ui.add(
                egui::Label::new(format!(
                    "{} {} · {} {} · {} G(0) = {dc_text}",
                    P::Order.get(lang),
                    tf.order(),
                    P::RelativeDegree.get(lang),
                    tf.relative_degree(),
                    P::StaticGain.get(lang),
                ))
                .wrap(),
            );
        }
        Err(reason) => {
            ui.add(
                egui::Label::new(
                    RichText::new(format!("{} {}", P::NoSystem.get(lang), reason.text(lang)))
                        .color(ui.visuals().error_fg_color),
                )
                .wrap(),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_words::Localize;

    #[test]
    fn only_finite_numbers_are_read() {
        assert_eq!(finite_number(" −1e3 "), Some(-1000.0));
        for bad in ["inf", "-inf", "NaN", "1e400", "", "abc"] {
            assert_eq!(finite_number(bad), None, "{bad}");
        }
    }

    #[test]
    fn a_root_too_far_from_the_others_is_refused_with_its_reason() {
        let system = System::default();
        let id = RootId {
            role: RootRole::Pole,
            index: 1,
        };
        // |s| = 1e-13 against the pair's 2.236: 2e13 times faster.
        let e = placement_refusal(&system, id, -1e-13, 0.0, -1e-13).unwrap_err();
        assert_eq!(
            e,
            FieldError::Refused {
                value: -1e-13,
                why: LimitReason::RootSpread
            }
        );
        assert!(e.text(Lang::En).contains("1e12"), "{}", e.text(Lang::En));
        assert!(placement_refusal(&system, id, -7.0, 0.0, -7.0).is_ok());
    }
}
