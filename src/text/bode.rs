//! The words of `degrau bode`: its refusals and the lines of its report (the asymptotes of
//! the course notes in words), in English and Brazilian Portuguese.

use crate::cli::bode::BodeCliError;
use crate::lti::bode::AsymptoteLine;

#[cfg(test)]
use super::Message;
use super::{Lang, Localize};

impl Localize for BodeCliError {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match self {
            BodeCliError::Cli(e) => e.text(lang),
            BodeCliError::NotPositive { flag, value } => lang.pick(
                format!(
                    "{flag} {}: a frequency of the Bode diagram is a positive number of rad/s \
                     (its axis is logarithmic)",
                    n(*value)
                ),
                format!(
                    "{flag} {}: uma frequência do diagrama de Bode é um número positivo de \
                     rad/s (seu eixo é logarítmico)",
                    n(*value)
                ),
            ),
            BodeCliError::EmptyRange { w_min, w_max } => lang.pick(
                format!(
                    "the frequencies from {} to {} rad/s are no range: --w-min must be below \
                     --w-max",
                    n(*w_min),
                    n(*w_max)
                ),
                format!(
                    "as frequências de {} a {} rad/s não são um intervalo: --w-min deve ser \
                     menor que --w-max",
                    n(*w_min),
                    n(*w_max)
                ),
            ),
            BodeCliError::Points(p) => lang.pick(
                format!("--points {p}: give from 2 to 1000000 frequencies"),
                format!("--points {p}: dê de 2 a 1000000 frequências"),
            ),
        }
    }
}

/// A line of the text report of `degrau bode`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Line {
    /// A line of the asymptotes (the lti crate says it).
    Asymptote(AsymptoteLine),
    /// The dead time θ (s): phase only.
    Delay(f64),
    /// The table's column names.
    TableHeader,
}

impl Localize for Line {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match *self {
            Line::Asymptote(a) => a.text(lang),
            Line::Delay(theta) => lang.pick(
                format!(
                    "Dead time θ = {} s: the phase falls by ωθ rad (exactly), the magnitude \
                     does not change",
                    n(theta)
                ),
                format!(
                    "Tempo morto θ = {} s: a fase cai ωθ rad (exatamente), o módulo não muda",
                    n(theta)
                ),
            ),
            Line::TableHeader => lang.pick(
                format!(
                    "{:>14} {:>14} {:>14} {:>14}",
                    "ω (rad/s)", "|G| (dB)", "∠G (°)", "asymptote (dB)"
                ),
                format!(
                    "{:>14} {:>14} {:>14} {:>14}",
                    "ω (rad/s)", "|G| (dB)", "∠G (°)", "assíntota (dB)"
                ),
            ),
        }
    }
}

/// An example of every message of `degrau bode`, for the test of the words.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let errors = [
        BodeCliError::NotPositive {
            flag: "--w-min",
            value: -1.0,
        },
        BodeCliError::EmptyRange {
            w_min: 10.0,
            w_max: 1.0,
        },
        BodeCliError::Points(1),
    ];
    let lines = [
        Line::Asymptote(AsymptoteLine::NoCorner),
        Line::Delay(0.5),
        Line::TableHeader,
    ];
    let mut all: Vec<Message> = errors
        .iter()
        .map(|e| Message::of(format!("bode::BodeCliError::{e:?}"), e))
        .collect();
    all.extend(
        lines
            .iter()
            .map(|l| Message::of(format!("bode::Line::{l:?}"), l)),
    );
    all
}
