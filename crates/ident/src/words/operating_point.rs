//! The words of the operating point: what a fit did with Y0 ([`OperatingPoint`]: held at the
//! level measured before the step, at the sample at the step, at a value given, or
//! estimated, and why) and the names of the three choices of [`Offset`], for the CLI's fit
//! text and the app's Identify panel alike.

use crate::experiment::{EstimateReason, Offset, OperatingPoint};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// The names of the offset choices, as a selector lists them.
    pub enum OffsetChoice {
        /// [`Offset::Auto`].
        MeanBefore => ("mean before the step", "média antes do degrau"),
        /// [`Offset::Free`].
        Estimate => ("estimate", "estimar"),
        /// [`Offset::Fixed`].
        Fixed => ("fixed", "fixo"),
    }
}

impl OffsetChoice {
    /// The choice an offset is.
    pub fn of(offset: &Offset) -> Self {
        match offset {
            Offset::Auto => Self::MeanBefore,
            Offset::Free => Self::Estimate,
            Offset::Fixed(_) => Self::Fixed,
        }
    }
}

impl Localize for OperatingPoint {
    fn text(&self, lang: Lang) -> String {
        let value = |y0: f64| lang.num(y0, 6);
        match *self {
            OperatingPoint::MeanBefore { y0, samples: 1, .. } => match lang {
                Lang::En => format!("Y0 held at the sample before the step: {}", value(y0)),
                Lang::Pt => format!("Y0 mantido na amostra antes do degrau: {}", value(y0)),
            },
            OperatingPoint::MeanBefore {
                y0,
                samples,
                wild: 0,
            } => match lang {
                Lang::En => format!(
                    "Y0 held at the mean of the {samples} samples before the step: {}",
                    value(y0)
                ),
                Lang::Pt => format!(
                    "Y0 mantido na média das {samples} amostras antes do degrau: {}",
                    value(y0)
                ),
            },
            OperatingPoint::MeanBefore { y0, samples, wild } => match lang {
                Lang::En => format!(
                    "Y0 held at the mean of the {samples} samples before the step, {wild} wild \
                     one{} (a spike, a dropout) left out: {}",
                    if wild == 1 { "" } else { "s" },
                    value(y0)
                ),
                Lang::Pt => format!(
                    "Y0 mantido na média das {samples} amostras antes do degrau, {wild} \
                     {} (um pico, uma queda) deixada{} de fora: {}",
                    if wild == 1 { "espúria" } else { "espúrias" },
                    if wild == 1 { "" } else { "s" },
                    value(y0)
                ),
            },
            OperatingPoint::AtStep { y0 } => match lang {
                Lang::En => format!(
                    "Y0 held at the sample at the step instant (the record starts with the \
                     step, no sample is before it): {}",
                    value(y0)
                ),
                Lang::Pt => format!(
                    "Y0 mantido na amostra do instante do degrau (o registro começa com o \
                     degrau, nenhuma amostra vem antes dele): {}",
                    value(y0)
                ),
            },
            OperatingPoint::Given { y0 } => match lang {
                Lang::En => format!("Y0 held at the value given: {}", value(y0)),
                Lang::Pt => format!("Y0 mantido no valor informado: {}", value(y0)),
            },
            OperatingPoint::Estimated {
                reason: EstimateReason::Asked,
            } => lang
                .pick(
                    "Y0 estimated with the other parameters",
                    "Y0 estimado junto com os demais parâmetros",
                )
                .into(),
            OperatingPoint::Estimated {
                reason: EstimateReason::NoSampleBeforeStep,
            } => lang
                .pick(
                    "no sample at or before the step: Y0 estimated with the other parameters",
                    "nenhuma amostra no instante do degrau ou antes dele: Y0 estimado junto com \
                     os demais parâmetros",
                )
                .into(),
            OperatingPoint::Estimated {
                reason: EstimateReason::ShortRest,
            } => lang
                .pick(
                    "fewer than 20 samples before the first of several input changes: Y0 \
                     estimated with the other parameters (the record's responses measure it \
                     better than so short a stretch)",
                    "menos de 20 amostras antes da primeira de várias mudanças da entrada: Y0 \
                     estimado junto com os demais parâmetros (as respostas do registro o medem \
                     melhor que um trecho tão curto)",
                )
                .into(),
            OperatingPoint::Estimated {
                reason: EstimateReason::NotAtRest,
            } => lang
                .pick(
                    "the output still moved before the first input change (not at rest): Y0 and \
                     an initial transient estimated with the other parameters",
                    "a saída ainda se movia antes da primeira mudança da entrada (fora do \
                     repouso): Y0 e um transitório inicial estimados junto com os demais \
                     parâmetros",
                )
                .into(),
        }
    }
}

/// The offset choices and an example of every [`OperatingPoint`], for
/// the test of every message.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let examples = [
        OperatingPoint::MeanBefore {
            y0: 20.9,
            samples: 1,
            wild: 0,
        },
        OperatingPoint::MeanBefore {
            y0: 250.03,
            samples: 41,
            wild: 0,
        },
        OperatingPoint::MeanBefore {
            y0: 21.54,
            samples: 60,
            wild: 2,
        },
        OperatingPoint::AtStep { y0: 23.48 },
        OperatingPoint::Given { y0: 50.0 },
        OperatingPoint::Estimated {
            reason: EstimateReason::Asked,
        },
        OperatingPoint::Estimated {
            reason: EstimateReason::NoSampleBeforeStep,
        },
        OperatingPoint::Estimated {
            reason: EstimateReason::NotAtRest,
        },
        OperatingPoint::Estimated {
            reason: EstimateReason::ShortRest,
        },
    ];
    let mut all = OffsetChoice::messages();
    for fact in &examples {
        // Exhaustive: a new fact does not compile until it has an example above.
        let id = match fact {
            OperatingPoint::MeanBefore { samples: 1, .. } => "MeanBefore(1)",
            OperatingPoint::MeanBefore { wild: 0, .. } => "MeanBefore",
            OperatingPoint::MeanBefore { .. } => "MeanBefore(wild)",
            OperatingPoint::AtStep { .. } => "AtStep",
            OperatingPoint::Given { .. } => "Given",
            OperatingPoint::Estimated {
                reason: EstimateReason::Asked,
            } => "Estimated(Asked)",
            OperatingPoint::Estimated {
                reason: EstimateReason::NoSampleBeforeStep,
            } => "Estimated(NoSampleBeforeStep)",
            OperatingPoint::Estimated {
                reason: EstimateReason::NotAtRest,
            } => "Estimated(NotAtRest)",
            OperatingPoint::Estimated {
                reason: EstimateReason::ShortRest,
            } => "Estimated(ShortRest)",
        };
        all.push(Message::of(format!("OperatingPoint::{id}"), fact));
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_held_level_is_said_with_its_samples_and_value() {
        let cases = [
            (
                OperatingPoint::MeanBefore {
                    y0: 250.03,
                    samples: 41,
                    wild: 0,
                },
                Lang::En,
                "Y0 held at the mean of the 41 samples before the step: 250.03",
            ),
            (
                OperatingPoint::MeanBefore {
                    y0: 250.03,
                    samples: 41,
                    wild: 0,
                },
                Lang::Pt,
                "Y0 mantido na média das 41 amostras antes do degrau: 250,03",
            ),
            (
                OperatingPoint::MeanBefore {
                    y0: 21.54,
                    samples: 60,
                    wild: 2,
                },
                Lang::En,
                "Y0 held at the mean of the 60 samples before the step, 2 wild ones (a spike, a \
                 dropout) left out: 21.54",
            ),
            (
                OperatingPoint::MeanBefore {
                    y0: 21.54,
                    samples: 60,
                    wild: 1,
                },
                Lang::Pt,
                "Y0 mantido na média das 60 amostras antes do degrau, 1 espúria (um pico, uma \
                 queda) deixada de fora: 21,54",
            ),
            (
                OperatingPoint::MeanBefore {
                    y0: 20.9,
                    samples: 1,
                    wild: 0,
                },
                Lang::En,
                "Y0 held at the sample before the step: 20.9",
            ),
        ];
        for (fact, lang, expected) in cases {
            assert_eq!(fact.text(lang), expected);
        }
        assert_eq!(OffsetChoice::of(&Offset::Free).get(Lang::Pt), "estimar");
    }
}
