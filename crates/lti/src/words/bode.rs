//! The words of the Bode asymptotes ([`AsymptoteLine`]): the low-frequency line and each
//! corner, in English and Brazilian Portuguese, as the notes draw them by hand (said by the
//! command line's `degrau bode` and the app's frequency view alike).

use degrau_words::{Lang, Localize};

use crate::bode::AsymptoteLine;
#[cfg(test)]
use degrau_words::Message;

impl Localize for AsymptoteLine {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match *self {
            AsymptoteLine::Low {
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
            AsymptoteLine::NoCorner => lang
                .pick(
                    "No corner frequency: the asymptote is that one line",
                    "Nenhuma frequência de canto: a assíntota é essa única reta",
                )
                .into(),
            AsymptoteLine::Corner { w, change, slope } => lang.pick(
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
        }
    }
}

/// An example of each line.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    [
        AsymptoteLine::Low {
            db: -33.9794,
            slope: -20.0,
            system_type: 1,
        },
        AsymptoteLine::NoCorner,
        AsymptoteLine::Corner {
            w: 2.0,
            change: -40.0,
            slope: -60.0,
        },
    ]
    .iter()
    .map(|l| Message::of(format!("bode::AsymptoteLine::{l:?}"), l))
    .collect()
}
