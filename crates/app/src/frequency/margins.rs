//! The left panel's margins: GM (ratio and dB) at ω_pc, PM at ω_gc, the delay margin, Ms
//! and the bandwidth, every crossing when there are several, the closed loop's verdict and
//! a one-line reading of what the margins mean; then the Bode asymptotes in words (the
//! low-frequency line, each corner and the slopes around it).

use eframe::egui::{self, RichText, Ui};

use degrau_lti::control::Margins;
use degrau_words::{Lang, Localize};

use super::derived::LoopData;
use super::session::Session;
use super::value;
use crate::look::Look;
use crate::words::frequency::{self as words, Frequency as T};

/// Draws the margins of the session's loop (nothing without one).
pub fn show(ui: &mut Ui, session: &Session, look: &Look) {
    let Some(Ok(data)) = &session.loop_data else {
        return;
    };
    let lang = look.lang;
    ui.heading(T::MarginsHeading.get(lang));
    let stable = is_stable(data);
    let (verdict, colour) = if stable {
        (T::Stable, look.palette.main)
    } else {
        (T::Unstable, look.palette.error)
    };
    ui.label(RichText::new(verdict.get(lang)).color(colour));
    for line in lines(&data.margins, lang) {
        wrapped(ui, line);
    }
    crossings(ui, &data.margins, lang);
    ui.add_space(4.0);
    for line in readings(&data.margins, stable, lang) {
        ui.add(egui::Label::new(RichText::new(line).italics()).wrap());
    }
    ui.separator();
    asymptotes(ui, data, lang);
}

/// The asymptotes in words: the low-frequency line, then each corner and its slopes.
fn asymptotes(ui: &mut Ui, data: &LoopData, lang: Lang) {
    ui.heading(T::AsymptotesHeading.get(lang));
    for line in data.asymptotes.lines() {
        wrapped(ui, line.text(lang));
    }
}

/// Whether the closed loop is stable: its direct count, else Ms (found only when stable).
pub fn is_stable(data: &LoopData) -> bool {
    match data.closed_loop {
        Ok(z) => z == 0,
        Err(_) => data.margins.ms.is_some(),
    }
}

fn wrapped(ui: &mut Ui, text: String) {
    ui.add(egui::Label::new(text).wrap());
}

/// ω in rad/s as written.
fn rad_s(w: f64, lang: Lang) -> String {
    format!("{} rad/s", value(w, 4, lang))
}

/// The margins' lines, in words.
pub fn lines(m: &Margins, lang: Lang) -> Vec<String> {
    let at = T::At.get(lang);
    let gm = match m.w_pc {
        Some(w) if m.gm.is_finite() => format!(
            "{} GM = {} ({} dB) {at} ω_pc = {}",
            T::GainMargin.get(lang),
            value(m.gm, 4, lang),
            value(m.gm_db, 4, lang),
            rad_s(w, lang)
        ),
        _ => format!(
            "{} GM = {}: {}",
            T::GainMargin.get(lang),
            words::INFINITE,
            T::NoPhaseCrossover.get(lang)
        ),
    };
    let pm = match m.w_gc {
        Some(w) if m.pm.is_finite() => format!(
            "{} PM = {}° {at} ω_gc = {}",
            T::PhaseMargin.get(lang),
            value(m.pm, 4, lang),
            rad_s(w, lang)
        ),
        _ => format!(
            "{} PM = {}: {}",
            T::PhaseMargin.get(lang),
            words::INFINITE,
            T::NoGainCrossover.get(lang)
        ),
    };
    let dm = format!(
        "{} = {} s",
        T::DelayMargin.get(lang),
        value(m.delay_margin, 4, lang)
    );
    let ms = match m.ms {
        Some(ms) => format!("{} = {}", T::MaxSensitivity.get(lang), value(ms, 4, lang)),
        None => format!(
            "{}: {}",
            T::MaxSensitivity.get(lang),
            T::NoneUnstable.get(lang)
        ),
    };
    let bw = match m.bandwidth {
        Some(b) if b.is_finite() => format!("{} = {}", T::Bandwidth.get(lang), rad_s(b, lang)),
        Some(_) => format!(
            "{} = {}",
            T::Bandwidth.get(lang),
            T::BandwidthBeyond.get(lang)
        ),
        None => format!("{}: {}", T::Bandwidth.get(lang), T::BandwidthNone.get(lang)),
    };
    vec![gm, pm, dm, ms, bw]
}

/// The most crossings of a kind listed (a long dead time makes dozens).
const LISTED: usize = 6;

/// Every crossing, when there are several of a kind (the first [`LISTED`]).
fn crossings(ui: &mut Ui, m: &Margins, lang: Lang) {
    if m.phase_crossings.len() > 1 {
        ui.label(T::PhaseCrossings.get(lang));
        for c in m.phase_crossings.iter().take(LISTED) {
            wrapped(
                ui,
                format!(
                    "  ω = {}: GM = {} ({} dB)",
                    rad_s(c.w, lang),
                    value(c.gm, 4, lang),
                    value(c.gm_db, 4, lang)
                ),
            );
        }
    }
    more(ui, m.phase_crossings.len(), lang);
    if m.gain_crossings.len() > 1 {
        ui.label(T::GainCrossings.get(lang));
        for c in m.gain_crossings.iter().take(LISTED) {
            wrapped(
                ui,
                format!(
                    "  ω = {}: PM = {}°; {} = {} s",
                    rad_s(c.w, lang),
                    value(c.pm, 4, lang),
                    T::DelayMargin.get(lang),
                    value(c.delay_margin, 4, lang)
                ),
            );
        }
    }
    more(ui, m.gain_crossings.len(), lang);
}

/// "… and 12 more" after the first [`LISTED`] crossings.
fn more(ui: &mut Ui, count: usize, lang: Lang) {
    if count > LISTED {
        ui.weak(words::more_crossings(count - LISTED, lang));
    }
}

/// What the margins mean, in a line each.
fn readings(m: &Margins, stable: bool, lang: Lang) -> Vec<String> {
    let mut out = Vec::new();
    if m.gm.is_finite() {
        out.push(words::gain_reading(m.gm, lang));
    } else {
        out.push(T::StandsAnyGain.get(lang).to_string());
    }
    if stable {
        if m.delay_margin.is_finite() {
            out.push(words::delay_reading(m.delay_margin, lang));
        } else {
            out.push(T::StandsAnyDelay.get(lang).to_string());
        }
    }
    out
}
