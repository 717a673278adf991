//! The words of the closed loop, the root locus and the design specs: the inverse of the
//! second-order formulas refusing a spec ([`InverseError`]), the CLI's `degrau loop` report
//! and the Design mode's loop, locus and spec controls, in English and Brazilian Portuguese
//! (malha fechada, lugar das raízes, ganho crítico, erro em regime permanente, …).

use crate::lti::feedback::InverseError;

use super::{Lang, Localize, Message};

impl Localize for InverseError {
    fn text(&self, lang: Lang) -> String {
        match *self {
            InverseError::Overshoot(mp) => match lang {
                Lang::En => format!(
                    "the overshoot must be between 0 and 100 %, not {}",
                    lang.num(mp, 6)
                ),
                Lang::Pt => format!(
                    "o sobressinal deve estar entre 0 e 100 %, não {}",
                    lang.num(mp, 6)
                ),
            },
            InverseError::Time(t) => match lang {
                Lang::En => format!(
                    "a time must be a positive number of seconds, not {}",
                    lang.num(t, 6)
                ),
                Lang::Pt => format!(
                    "um tempo deve ser um número positivo de segundos, não {}",
                    lang.num(t, 6)
                ),
            },
        }
    }
}

crate::phrases! {
    /// The loop's fixed phrases (CLI report and Design mode).
    pub enum Loop {
        DelayNeedsApproximant => (
            "A dead time e^(−θs) in the loop cannot be closed exactly: the closed loop is not a rational transfer function. Replace the delay by a rational approximant (Padé) to close the loop; the result is then approximate.",
            "Um tempo morto e^(−θs) na malha não pode ser fechado exatamente: a malha fechada não é uma função de transferência racional. Substitua o atraso por uma aproximação racional (Padé) para fechar a malha; o resultado passa a ser aproximado."
        ),
    }
}

/// Every phrase and an example of every fact of this module.
pub fn messages() -> Vec<Message> {
    let mut all = Loop::messages();
    all.push(Message::of(
        "InverseError::Overshoot",
        &InverseError::Overshoot(120.0),
    ));
    all.push(Message::of("InverseError::Time", &InverseError::Time(-1.0)));
    all
}
