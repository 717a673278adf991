//! The words of `degrau bode`: its refusals and the lines of its report (the asymptotes of
//! the course notes in words), in English and Brazilian Portuguese.

use crate::cli::bode::BodeCliError;

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
    /// The low-frequency asymptote: `db` at ω = 1, its slope, the system type.
    Low {
        db: f64,
        slope: f64,
        system_type: i32,
    },
    /// No corner: the asymptote is the low-frequency line everywhere.
    NoCorner,
    /// A corner at `w`, where the slope changes by `change` to `slope` (dB/decade).
    Corner { w: f64, change: f64, slope: f64 },
    /// The dead time θ (s): phase only.
    Delay(f64),
    /// The table's column names.
    TableHeader,
}

impl Localize for Line {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match *self {
            Line::Low {
                db,
                slope,
                system_type,
            } => lang.pick(
                format!(
                    "Low-frequency asymptote (type {system_type}): 20·log10|K| = {} dB at \
                     ω = 1 rad/s, slope {} dB/decade",
                    n(db),
                    n(slope)
                ),
                format!(
                    "Assíntota de baixa frequência (tipo {system_type}): 20·log10|K| = {} dB \
                     em ω = 1 rad/s, inclinação {} dB/década",
                    n(db),
                    n(slope)
                ),
            ),
            Line::NoCorner => lang
                .pick(
                    "No corner frequency: the asymptote is that one line",
                    "Nenhuma frequência de canto: a assíntota é essa única reta",
                )
                .into(),
            Line::Corner { w, change, slope } => lang.pick(
                format!(
                    "Corner at ω = {} rad/s: the slope changes by {} dB/decade, to {} dB/decade",
                    n(w),
                    n(change),
                    n(slope)
                ),
                format!(
                    "Canto em ω = {} rad/s: a inclinação muda {} dB/década, para {} dB/década",
                    n(w),
                    n(change),
                    n(slope)
                ),
            ),
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
        Line::Low {
            db: -33.9794,
            slope: -20.0,
            system_type: 1,
        },
        Line::NoCorner,
        Line::Corner {
            w: 2.0,
            change: -40.0,
            slope: -60.0,
        },
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
