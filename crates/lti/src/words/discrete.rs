//! The words of discrete models' refusals ([`DiscreteError`]: c2d, d2c and H(z) as typed),
//! in English and Brazilian Portuguese.

use degrau_words::{Lang, Localize};

use crate::discrete::DiscreteError;
use crate::{C64, fmt_c};
#[cfg(test)]
use degrau_words::Message;

/// A pole as text in `lang`.
fn pole_text(p: C64, lang: Lang) -> String {
    lang.localize_number(&fmt_c(p))
}

impl Localize for DiscreteError {
    fn text(&self, lang: Lang) -> String {
        match self {
            DiscreteError::BadSamplingPeriod(h) => {
                let h = lang.num(*h, 6);
                lang.pick(
                    format!("the sampling period h = {h} s must be a positive number"),
                    format!("o período de amostragem h = {h} s deve ser um número positivo"),
                )
            }
            DiscreteError::BadCoefficients => lang
                .pick(
                    "the coefficients must be finite numbers, and A(z) must start with 1",
                    "os coeficientes devem ser números finitos, e A(z) deve começar com 1",
                )
                .into(),
            DiscreteError::NoNumerator => lang
                .pick(
                    "B(z) is zero: the input has no effect",
                    "B(z) é zero: a entrada não tem efeito",
                )
                .into(),
            DiscreteError::NoPoles => lang
                .pick(
                    "A(z) has no pole: d2c needs at least one",
                    "A(z) não tem polo: o d2c precisa de ao menos um",
                )
                .into(),
            DiscreteError::NoContinuousPole { pole } => {
                let p = pole_text(*pole, lang);
                lang.pick(
                    format!(
                        "pole z = {p} is on the negative real axis or at 0: no continuous system samples to it (d2c has no answer)"
                    ),
                    format!(
                        "o polo z = {p} está no semieixo real negativo ou em 0: nenhum sistema contínuo amostrado o dá (o d2c não tem resposta)"
                    ),
                )
            }
            DiscreteError::RepeatedPoles { pole } => {
                let p = pole_text(*pole, lang);
                lang.pick(
                    format!("pole z = {p} is repeated: d2c here needs distinct poles"),
                    format!("o polo z = {p} é repetido: o d2c aqui precisa de polos distintos"),
                )
            }
            DiscreteError::NumeratorTooLong { na, nb } => lang.pick(
                format!(
                    "nb = {nb} b's for na = {na}: the ZOH image of a proper G(s) has at most na + 1 (d2c inverts nb ≤ na + 1)"
                ),
                format!(
                    "nb = {nb} b's para na = {na}: a imagem ZOH de um G(s) próprio tem no máximo na + 1 (o d2c inverte nb ≤ na + 1)"
                ),
            ),
            DiscreteError::DelayTooLong { samples } => {
                // θ/h beyond 1.8e308 (θ = 1.8e308 s at h = 0.1 s) is said as that bound.
                let samples = if samples.is_finite() {
                    lang.num(*samples, 6)
                } else {
                    lang.pick("more than 1.8e308", "mais de 1,8e308").to_string()
                };
                let most = lang.num(crate::discrete::MAX_DELAY_SAMPLES as f64, 6);
                lang.pick(
                    format!(
                        "the dead time spans {samples} sampling periods: at most {most} are counted, beyond which double precision cannot place it within a sample"
                    ),
                    format!(
                        "o tempo morto abrange {samples} períodos de amostragem: no máximo {most} são contados, além disso a precisão dupla não o situa dentro de uma amostra"
                    ),
                )
            }
            DiscreteError::PeriodTooShort { ts, pole } => {
                let (h, p) = (lang.num(*ts, 6), pole_text(*pole, lang));
                lang.pick(
                    format!(
                        "h = {h} s is too short for the pole s = {p}: e^(p·h) differs from 1 by less than A(z)'s coefficients can hold in double precision, so they could not tell it from an integrator; sample more slowly"
                    ),
                    format!(
                        "h = {h} s é curto demais para o polo s = {p}: e^(p·h) difere de 1 menos do que os coeficientes de A(z) conseguem guardar em precisão dupla, então eles não o distinguiriam de um integrador; amostre mais devagar"
                    ),
                )
            }
            DiscreteError::NumeratorOutOfRange { ts } => {
                let h = lang.num(*ts, 6);
                lang.pick(
                    format!(
                        "at h = {h} s the coefficients of B(z) fall outside double precision's range (2.2e-308 to 1.8e308): change the sampling period or the units of time"
                    ),
                    format!(
                        "com h = {h} s os coeficientes de B(z) saem da faixa da precisão dupla (2,2e-308 a 1,8e308): mude o período de amostragem ou a unidade de tempo"
                    ),
                )
            }
            DiscreteError::CommonFactor { root } => {
                let z = pole_text(*root, lang);
                lang.pick(
                    format!(
                        "B(z) and A(z) share the root z = {z}: a pole cancelled by a zero, so H(z) is of lower order than A(z) says; write it without the common factor"
                    ),
                    format!(
                        "B(z) e A(z) têm a raiz z = {z} em comum: um polo cancelado por um zero, então H(z) é de ordem menor do que A(z) diz; escreva-o sem o fator comum"
                    ),
                )
            }
            DiscreteError::NoZohEquivalent => lang
                .pick(
                    "no continuous G(s)·e^(−θs) has these samples: the zero-order-hold discretisation of the candidate does not give H(z) back",
                    "nenhum G(s)·e^(−θs) contínuo tem estas amostras: a discretização com segurador de ordem zero do candidato não devolve H(z)",
                )
                .into(),
            DiscreteError::Lti(e) => e.text(lang),
        }
    }
}

/// An example of every refusal, for the test of the words.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let discrete = [
        DiscreteError::BadSamplingPeriod(0.0),
        DiscreteError::BadCoefficients,
        DiscreteError::NoNumerator,
        DiscreteError::NoPoles,
        DiscreteError::NoContinuousPole {
            pole: C64::new(-0.5, 0.0),
        },
        DiscreteError::RepeatedPoles {
            pole: C64::new(0.5, 0.0),
        },
        DiscreteError::NumeratorTooLong { na: 2, nb: 4 },
        DiscreteError::DelayTooLong { samples: 1e19 },
        DiscreteError::PeriodTooShort {
            ts: 1e-20,
            pole: C64::new(-1.0, 0.0),
        },
        DiscreteError::NumeratorOutOfRange { ts: 1e-160 },
        DiscreteError::CommonFactor {
            root: C64::new(0.9, 0.0),
        },
        DiscreteError::NoZohEquivalent,
    ];
    discrete
        .iter()
        .map(|e| Message::of(format!("lsq::DiscreteError::{e:?}"), e))
        .collect()
}
