//! The words of `degrau margins`: the lines of its report, in English and Brazilian
//! Portuguese (margem de ganho, margem de fase, margem de atraso, banda passante).

#[cfg(test)]
use super::Message;
use super::{Lang, Localize};

/// A line of the `degrau margins` report (numbers already rounded by the caller as they
/// should print; infinite ones say so).
#[derive(Debug, Clone, PartialEq)]
pub enum MarginLine {
    /// The loop L(s) = C(s)·G(s) (its description).
    Loop(String),
    /// The gain margin (ratio, dB) at the phase crossover ω (rad/s).
    Gain { gm: f64, gm_db: f64, w: f64 },
    /// No phase crossover: the gain margin is infinite.
    NoPhaseCrossover,
    /// The phase margin (degrees) at the gain crossover ω (rad/s).
    Phase { pm: f64, w: f64 },
    /// No gain crossover: the phase margin is infinite.
    NoGainCrossover,
    /// The delay margin (s).
    Delay(f64),
    /// Ms.
    Sensitivity(f64),
    /// The closed loop is not stable: no Ms.
    NoSensitivity,
    /// The closed loop's −3 dB bandwidth (rad/s; infinite when it never falls).
    Bandwidth(f64),
    /// |T(0)| is 0 or infinite: no bandwidth.
    NoBandwidth,
    /// How many crossings of each kind were found.
    Crossings { phase: usize, gain: usize },
    /// The Nyquist criterion: N clockwise encirclements of −1, P open-loop poles in the right
    /// half-plane, Z = N + P closed-loop roots there.
    Nyquist { n: i64, p: usize, z: i64 },
    /// The Nyquist count could not be made (the reason, in words).
    NoNyquist(String),
}

/// A number with six significant digits and `lang`'s decimal separator, ∞ as such.
fn num(x: f64, lang: Lang) -> String {
    if x.is_infinite() {
        "∞".into()
    } else {
        lang.num(x, 6)
    }
}

impl Localize for MarginLine {
    fn text(&self, lang: Lang) -> String {
        match self {
            MarginLine::Loop(l) => lang.pick(
                format!("Open loop L(s) = C(s)·G(s), G = {l}"),
                format!("Malha aberta L(s) = C(s)·G(s), G = {l}"),
            ),
            MarginLine::Gain { gm, gm_db, w } => {
                let (gm, db, w) = (num(*gm, lang), num(*gm_db, lang), num(*w, lang));
                lang.pick(
                    format!("Gain margin: {gm} ({db} dB) at the phase crossover ω = {w} rad/s"),
                    format!(
                        "Margem de ganho: {gm} ({db} dB) na frequência de cruzamento de fase ω = {w} rad/s"
                    ),
                )
            }
            MarginLine::NoPhaseCrossover => lang
                .pick(
                    "Gain margin: ∞ (the phase never reaches −180°)",
                    "Margem de ganho: ∞ (a fase nunca chega a −180°)",
                )
                .into(),
            MarginLine::Phase { pm, w } => {
                let (pm, w) = (num(*pm, lang), num(*w, lang));
                lang.pick(
                    format!("Phase margin: {pm}° at the gain crossover ω = {w} rad/s"),
                    format!(
                        "Margem de fase: {pm}° na frequência de cruzamento de ganho ω = {w} rad/s"
                    ),
                )
            }
            MarginLine::NoGainCrossover => lang
                .pick(
                    "Phase margin: ∞ (|L(jω)| never crosses 1)",
                    "Margem de fase: ∞ (|L(jω)| nunca cruza 1)",
                )
                .into(),
            MarginLine::Delay(d) => {
                let d = num(*d, lang);
                lang.pick(
                    format!("Delay margin: {d} s (the extra dead time that destabilises)"),
                    format!("Margem de atraso: {d} s (o tempo morto a mais que desestabiliza)"),
                )
            }
            MarginLine::Sensitivity(ms) => {
                let ms = num(*ms, lang);
                lang.pick(
                    format!("Maximum sensitivity Ms: {ms}"),
                    format!("Sensibilidade máxima Ms: {ms}"),
                )
            }
            MarginLine::NoSensitivity => lang
                .pick(
                    "Maximum sensitivity Ms: none (the closed loop is not stable)",
                    "Sensibilidade máxima Ms: nenhuma (a malha fechada não é estável)",
                )
                .into(),
            MarginLine::Bandwidth(w) => {
                let w = num(*w, lang);
                lang.pick(
                    format!("Closed-loop bandwidth (−3 dB): {w} rad/s"),
                    format!("Banda passante da malha fechada (−3 dB): {w} rad/s"),
                )
            }
            MarginLine::NoBandwidth => lang
                .pick(
                    "Closed-loop bandwidth: none (|T(0)| is 0 or infinite)",
                    "Banda passante da malha fechada: nenhuma (|T(0)| é 0 ou infinito)",
                )
                .into(),
            MarginLine::Crossings { phase, gain } => lang.pick(
                format!("Crossings found: {phase} of phase, {gain} of gain"),
                format!("Cruzamentos encontrados: {phase} de fase, {gain} de ganho"),
            ),
            MarginLine::Nyquist { n, p, z } => {
                let verdict = if *z == 0 {
                    lang.pick("stable", "estável")
                } else {
                    lang.pick("unstable", "instável")
                };
                lang.pick(
                    format!(
                        "Nyquist: N = {n} clockwise encirclements of −1, P = {p} open-loop poles in the right half-plane, Z = N + P = {z} closed-loop poles there: {verdict}"
                    ),
                    format!(
                        "Nyquist: N = {n} voltas de −1 no sentido horário, P = {p} polos de malha aberta no semiplano direito, Z = N + P = {z} polos de malha fechada nele: {verdict}"
                    ),
                )
            }
            MarginLine::NoNyquist(why) => lang.pick(
                format!("Nyquist: no count ({why})"),
                format!("Nyquist: sem contagem ({why})"),
            ),
        }
    }
}

/// An example of every line.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    [
        MarginLine::Loop("1/(s + 1)".into()),
        MarginLine::Gain {
            gm: 3.0,
            gm_db: 9.54,
            w: 1.41,
        },
        MarginLine::NoPhaseCrossover,
        MarginLine::Phase { pm: 30.0, w: 0.5 },
        MarginLine::NoGainCrossover,
        MarginLine::Delay(0.8),
        MarginLine::Sensitivity(1.6),
        MarginLine::NoSensitivity,
        MarginLine::Bandwidth(2.0),
        MarginLine::NoBandwidth,
        MarginLine::Crossings { phase: 1, gain: 1 },
        MarginLine::Nyquist { n: 2, p: 0, z: 2 },
        MarginLine::NoNyquist("a closed-loop root on the imaginary axis".into()),
    ]
    .iter()
    .map(|l| Message::of(format!("margins::{l:?}"), l))
    .collect()
}
