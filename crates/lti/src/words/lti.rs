//! The words of the exact LTI math's refusals: [`LtiError`] (a system that cannot be built
//! or analysed) and [`ParseError`] (text that does not hold the numbers it should), in
//! English and Brazilian Portuguese. Their `Display` is the English text written here, so
//! no sentence exists twice.
//!
//! Numbers keep the digits they were given ([`exact`]), with the language's decimal
//! separator; the syntax examples of [`ParseError`] keep Rust's decimal point, which is what
//! the parser reads.

use crate::parse::ParseError;
use crate::{LtiError, Polynomial, Quantity, RootRole, exact, fmt_c, tf};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

/// `x` with every digit it has, in `lang`'s decimal separator.
fn num(lang: Lang, x: f64) -> String {
    lang.localize_number(&exact(x))
}

/// `x` in scientific notation (`1e-320`), in `lang`'s decimal separator.
fn sci(lang: Lang, x: f64) -> String {
    lang.localize_number(&format!("{x:e}"))
}

/// A complex number as `-1+2j`, in `lang`'s decimal separator.
fn complex(lang: Lang, c: crate::C64) -> String {
    lang.localize_number(&fmt_c(c))
}

impl Polynomial {
    /// The polynomial's name, without an article (masculine in Portuguese).
    fn noun(self, lang: Lang) -> &'static str {
        match self {
            Polynomial::Numerator => lang.pick("numerator", "numerador"),
            Polynomial::Denominator => lang.pick("denominator", "denominador"),
            Polynomial::Alone => lang.pick("polynomial", "polinômio"),
        }
    }
}

impl RootRole {
    /// "pole" or "zero" (masculine in Portuguese).
    fn noun(self, lang: Lang) -> &'static str {
        match self {
            RootRole::Zero => "zero",
            RootRole::Pole => lang.pick("pole", "polo"),
        }
    }

    /// "poles" or "zeros".
    fn plural(self, lang: Lang) -> &'static str {
        match self {
            RootRole::Zero => "zeros",
            RootRole::Pole => lang.pick("poles", "polos"),
        }
    }
}

impl Localize for Quantity {
    /// The quantity as the subject of a sentence ("the gain k", "zero 1").
    fn text(&self, lang: Lang) -> String {
        match *self {
            Quantity::StepAmplitude => lang
                .pick("the step amplitude", "a amplitude do degrau")
                .into(),
            Quantity::Gain => lang.pick("the gain k", "o ganho k").into(),
            Quantity::FinalValue => lang
                .pick("the final value A·G(0)", "o valor final A·G(0)")
                .into(),
            Quantity::AmplitudeTimesGain => lang
                .pick(
                    "the product A·k of the step amplitude and the gain",
                    "o produto A·k da amplitude do degrau pelo ganho",
                )
                .into(),
            Quantity::Coefficient { of, index } => match lang {
                Lang::En => format!("coefficient {index} of the {}", of.noun(lang)),
                Lang::Pt => format!("o coeficiente {index} do {}", of.noun(lang)),
            },
            Quantity::Root { role, index } => match lang {
                Lang::En => format!("{} {index}", role.noun(lang)),
                Lang::Pt => format!("o {} {index}", role.noun(lang)),
            },
        }
    }
}

impl Localize for LtiError {
    fn text(&self, lang: Lang) -> String {
        use LtiError::*;
        let en = lang == Lang::En;
        match self {
            NonFiniteCoefficient { what, index } => {
                let what = what.noun(lang);
                if en {
                    format!(
                        "the {what} has a coefficient that is not a finite number (position {index})"
                    )
                } else {
                    format!(
                        "o {what} tem um coeficiente que não é um número finito (posição {index})"
                    )
                }
            }
            ZeroPolynomial { what } => {
                let what = what.noun(lang);
                if en {
                    format!("the {what} is zero: every coefficient is 0")
                } else {
                    format!("o {what} é zero: todos os coeficientes são 0")
                }
            }
            NonFiniteRoot { what, index } => {
                let what = what.noun(lang);
                if en {
                    format!("{what} {index} is not a finite number")
                } else {
                    format!("o {what} {index} não é um número finito")
                }
            }
            UnpairedComplexRoot { what, root } => {
                let (what, root, partner) = (
                    what.plural(lang),
                    complex(lang, *root),
                    complex(lang, root.conj()),
                );
                if en {
                    format!(
                        "the {what} must come in conjugate pairs: {root} has no partner {partner}"
                    )
                } else {
                    format!(
                        "os {what} devem vir em pares conjugados: {root} não tem o par {partner}"
                    )
                }
            }
            Improper {
                num_degree,
                den_degree,
            } => {
                if en {
                    format!(
                        "the system is improper: the numerator has degree {num_degree}, above \
                         the denominator's {den_degree}; it would respond to a step with an \
                         impulse"
                    )
                } else {
                    format!(
                        "o sistema é impróprio: o numerador tem grau {num_degree}, acima do grau \
                         {den_degree} do denominador; ele responderia a um degrau com um impulso"
                    )
                }
            }
            NoPoles => lang
                .pick(
                    "the system has no poles: it is a pure gain, with no dynamics to analyse",
                    "o sistema não tem polos: é um ganho puro, sem dinâmica para analisar",
                )
                .into(),
            BadGain(k) => {
                let k = num(lang, *k);
                if en {
                    format!("the gain is {k}: it must be a finite number other than zero")
                } else {
                    format!("o ganho é {k}: deve ser um número finito diferente de zero")
                }
            }
            GainOutOfRange => lang
                .pick(
                    "the gain k of k·Π(s − zᵢ)/Π(s − pⱼ) falls outside double precision's range \
                     (2.2e-308 to 1.8e308): rescale the coefficients, the gain or the units of \
                     time",
                    "o ganho k de k·Π(s − zᵢ)/Π(s − pⱼ) sai da faixa da precisão dupla \
                     (2,2e-308 a 1,8e308): mude a escala dos coeficientes, do ganho ou das \
                     unidades de tempo",
                )
                .into(),
            BadDelay(theta) => {
                let theta = num(lang, *theta);
                if en {
                    format!(
                        "the transport delay is {theta} s: it must be a finite number, zero or \
                         positive"
                    )
                } else {
                    format!(
                        "o tempo morto é {theta} s: deve ser um número finito, zero ou positivo"
                    )
                }
            }
            BadAmplitude(a) => {
                let a = num(lang, *a);
                if en {
                    format!("the step amplitude is {a}: it must be a finite number other than zero")
                } else {
                    format!(
                        "a amplitude do degrau é {a}: deve ser um número finito diferente de zero"
                    )
                }
            }
            DcGainNotScalable(g0) => {
                let g0 = num(lang, *g0);
                if en {
                    format!(
                        "the static (DC) gain is {g0}, so it cannot be set to another value by \
                         scaling"
                    )
                } else {
                    format!(
                        "o ganho estático (DC) é {g0}, então nenhuma mudança de escala o leva a \
                         outro valor"
                    )
                }
            }
            DelayInLoop => lang
                .pick(
                    "a closed loop around a transport delay is not a rational transfer \
                     function; remove the delay or approximate it first",
                    "uma malha fechada em torno de um tempo morto não é uma função de \
                     transferência racional; remova o tempo morto ou aproxime-o antes",
                )
                .into(),
            BadLoopGain(kp) => {
                let kp = num(lang, *kp);
                if en {
                    format!("the closed loop gain Kp = {kp} must be a finite number")
                } else {
                    format!(
                        "o ganho proporcional da malha fechada Kp = {kp} deve ser um número finito"
                    )
                }
            }
            LoopPolesUnresolved { kp } => {
                let kp = num(lang, *kp);
                if en {
                    format!(
                        "at Kp = {kp} the closed loop's poles (the roots of den + Kp·num) are \
                         beyond double precision: rounding in its coefficients hides a pole, or \
                         the side of the imaginary axis one lies on"
                    )
                } else {
                    format!(
                        "com Kp = {kp} os polos da malha fechada (as raízes de den + Kp·num) \
                         estão além da precisão dupla: o arredondamento dos seus coeficientes \
                         esconde um polo, ou o lado do eixo imaginário em que um deles está"
                    )
                }
            }
            OutOfRange => lang
                .pick(
                    "the poles and zeros span too many decades for double precision: the step \
                     response cannot be computed reliably (rescale time, or drop roots far \
                     faster than the rest)",
                    "os polos e zeros se espalham por décadas demais para a precisão dupla: a \
                     resposta ao degrau não pode ser calculada com confiança (mude a escala de \
                     tempo, ou descarte raízes muito mais rápidas que as demais)",
                )
                .into(),
            Subnormal { what, value } => {
                let (what, value) = (what.text(lang), sci(lang, *value));
                if en {
                    format!(
                        "{what} is {value}, below the smallest normal double-precision number \
                         (2.2e-308): it carries too few significant digits to compute with; \
                         type 0 if you mean 0, or rescale the units"
                    )
                } else {
                    format!(
                        "{what} é {value}, abaixo do menor número normal de precisão dupla \
                         (2,2e-308): tem dígitos significativos de menos para os cálculos; \
                         digite 0 se quer dizer 0, ou mude a escala das unidades"
                    )
                }
            }
            Underflow { what, value } if !value.is_finite() => {
                // A product of normal numbers that overflowed (A·k with k = 1.8e308).
                let what = what.text(lang);
                if en {
                    format!(
                        "{what} is beyond double precision's range (above 1.8e308), so the \
                         response cannot be computed; rescale the gain or the units"
                    )
                } else {
                    format!(
                        "{what} passa da faixa da precisão dupla (acima de 1,8e308), então a \
                         resposta não pode ser calculada; mude a escala do ganho ou das unidades"
                    )
                }
            }
            Underflow { what, value } => {
                let (what, value) = (what.text(lang), sci(lang, *value));
                if en {
                    format!(
                        "{what} is {value} (too small for double precision: below 2.2e-308), \
                         so the response cannot be computed reliably; rescale the gain or the \
                         units"
                    )
                } else {
                    format!(
                        "{what} é {value} (pequeno demais para a precisão dupla: abaixo de \
                         2,2e-308), então a resposta não pode ser calculada com confiança; mude \
                         a escala do ganho ou das unidades"
                    )
                }
            }
            RootsDidNotConverge { degree } => {
                if en {
                    format!(
                        "the roots of a degree-{degree} polynomial could not be found to double \
                         precision (the search did not converge, or what it found are not roots \
                         to rounding): use a lower order"
                    )
                } else {
                    format!(
                        "as raízes de um polinômio de grau {degree} não puderam ser achadas em \
                         precisão dupla (a busca não convergiu, ou o que achou não são raízes a \
                         menos de arredondamento): use uma ordem menor"
                    )
                }
            }
            OrderTooHigh(order) => {
                let max = tf::MAX_ORDER;
                if en {
                    format!("the system has order {order}; Degrau handles orders up to {max}")
                } else {
                    format!("o sistema tem ordem {order}; o Degrau trata ordens até {max}")
                }
            }
            BadSettlingBand(band) => {
                let (min, band) = (
                    num(lang, crate::metrics::MIN_SETTLING_THRESHOLD),
                    num(lang, *band),
                );
                if en {
                    format!(
                        "the settling band must be a fraction from {min} up to 1 of the step's \
                         effect, not {band} (a narrower band is below what double precision \
                         resolves)"
                    )
                } else {
                    format!(
                        "a faixa de acomodação deve ser uma fração de {min} até 1 do efeito do \
                         degrau, não {band} (uma faixa mais estreita está abaixo do que a \
                         precisão dupla distingue)"
                    )
                }
            }
            BadRiseLimits { low, high } => {
                let (low, high) = (num(lang, *low), num(lang, *high));
                if en {
                    format!(
                        "the rise limits must be fractions with 0 ≤ low < high ≤ 1, not {low} \
                         and {high}"
                    )
                } else {
                    format!(
                        "os limites do tempo de subida devem ser frações com 0 ≤ inferior < \
                         superior ≤ 1, não {low} e {high}"
                    )
                }
            }
        }
    }
}

/// `item 2 ("-1+xj")` inside a list, `"-1+xj"` on its own.
fn item(lang: Lang, index: Option<usize>, text: &str) -> String {
    match index {
        Some(i) => format!("{} {i} ({text:?})", lang.pick("item", "o item")),
        None => format!("{text:?}"),
    }
}

impl Localize for ParseError {
    fn text(&self, lang: Lang) -> String {
        let en = lang == Lang::En;
        match self {
            ParseError::NotComplex { index, text } => {
                let item = item(lang, *index, text);
                if en {
                    format!("{item} is not a number like -1+2j")
                } else {
                    format!("{item} não é um número como -1+2j")
                }
            }
            ParseError::NotReal { index, text } => {
                let item = item(lang, *index, text);
                if en {
                    format!("{item} is not a real number like 7, -0.5 or 2.5e-3")
                } else {
                    format!("{item} não é um número real como 7, -0.5 ou 2.5e-3 (ponto decimal)")
                }
            }
            ParseError::NotFinite { index, text } => {
                let item = item(lang, *index, text);
                if en {
                    format!("{item} is not a finite number")
                } else {
                    format!("{item} não é um número finito")
                }
            }
            ParseError::EmptyItem { index } => {
                if en {
                    format!("item {index} is empty: remove the extra comma or semicolon")
                } else {
                    format!(
                        "o item {index} está vazio: remova a vírgula ou o ponto e vírgula a mais"
                    )
                }
            }
        }
    }
}

/// The messages of an example of every variant of an enum: `pattern => example` pairs. The
/// `match` it writes on the patterns is exhaustive, so a new variant does not compile until
/// it has a pair here; each message's id is its pattern, and the test below checks that no
/// two examples fall on the same pattern (so each pattern has its example).
#[cfg(test)]
macro_rules! every_variant {
    ($ty:ty; $( $pat:pat => $example:expr ),+ $(,)?) => {{
        fn variant(e: &$ty) -> &'static str {
            match e {
                $( $pat => stringify!($pat), )+
            }
        }
        let examples: Vec<$ty> = vec![$( $example ),+];
        examples
            .iter()
            .map(|e| Message::of(variant(e), e))
            .collect::<Vec<Message>>()
    }};
}

/// An example of every [`LtiError`], [`Quantity`] and [`ParseError`], for
/// the test of every message.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    use crate::C64;
    let coefficient = Quantity::Coefficient {
        of: Polynomial::Denominator,
        index: 2,
    };
    let mut all = every_variant! { LtiError;
        LtiError::NonFiniteCoefficient { .. } => LtiError::NonFiniteCoefficient {
            what: Polynomial::Numerator,
            index: 2,
        },
        LtiError::ZeroPolynomial { .. } => LtiError::ZeroPolynomial {
            what: Polynomial::Denominator,
        },
        LtiError::NonFiniteRoot { .. } => LtiError::NonFiniteRoot {
            what: RootRole::Pole,
            index: 3,
        },
        LtiError::UnpairedComplexRoot { .. } => LtiError::UnpairedComplexRoot {
            what: RootRole::Zero,
            root: C64::new(-0.5, 2.0),
        },
        LtiError::Improper { .. } => LtiError::Improper {
            num_degree: 3,
            den_degree: 2,
        },
        LtiError::NoPoles => LtiError::NoPoles,
        LtiError::BadGain(_) => LtiError::BadGain(0.0),
        LtiError::GainOutOfRange => LtiError::GainOutOfRange,
        LtiError::BadDelay(_) => LtiError::BadDelay(-0.5),
        LtiError::BadAmplitude(_) => LtiError::BadAmplitude(f64::NAN),
        LtiError::DcGainNotScalable(_) => LtiError::DcGainNotScalable(0.0),
        LtiError::DelayInLoop => LtiError::DelayInLoop,
        LtiError::BadLoopGain(_) => LtiError::BadLoopGain(f64::INFINITY),
        LtiError::LoopPolesUnresolved { .. } => LtiError::LoopPolesUnresolved { kp: 1e300 },
        LtiError::OutOfRange => LtiError::OutOfRange,
        LtiError::Subnormal { .. } => LtiError::Subnormal {
            what: coefficient,
            value: 1e-320,
        },
        LtiError::Underflow { .. } => LtiError::Underflow {
            what: Quantity::FinalValue,
            value: 4e-320,
        },
        LtiError::RootsDidNotConverge { .. } => LtiError::RootsDidNotConverge { degree: 9 },
        LtiError::OrderTooHigh(_) => LtiError::OrderTooHigh(25),
        LtiError::BadSettlingBand(_) => LtiError::BadSettlingBand(1.5),
        LtiError::BadRiseLimits { .. } => LtiError::BadRiseLimits {
            low: 0.9,
            high: 0.1,
        },
    };
    all.extend(every_variant! { Quantity;
        Quantity::StepAmplitude => Quantity::StepAmplitude,
        Quantity::Gain => Quantity::Gain,
        Quantity::FinalValue => Quantity::FinalValue,
        Quantity::AmplitudeTimesGain => Quantity::AmplitudeTimesGain,
        Quantity::Coefficient { .. } => coefficient,
        Quantity::Root { .. } => Quantity::Root {
            role: RootRole::Pole,
            index: 1,
        },
    });
    all.extend(every_variant! { ParseError;
        ParseError::NotComplex { .. } => ParseError::NotComplex {
            index: Some(2),
            text: "-1+xj".into(),
        },
        ParseError::NotReal { .. } => ParseError::NotReal {
            index: None,
            text: "2,5.1".into(),
        },
        ParseError::NotFinite { .. } => ParseError::NotFinite {
            index: Some(1),
            text: "nan".into(),
        },
        ParseError::EmptyItem { .. } => ParseError::EmptyItem { index: 3 },
    });
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_has_its_own_example() {
        let all = messages();
        let mut ids: Vec<&str> = all.iter().map(|m| m.id.as_str()).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), all.len(), "two examples of one variant: {ids:?}");
    }

    #[test]
    fn display_is_the_english_text() {
        let e = LtiError::Improper {
            num_degree: 3,
            den_degree: 2,
        };
        assert_eq!(e.to_string(), e.text(Lang::En));
        assert!(e.to_string().starts_with("the system is improper"));
        let p = ParseError::EmptyItem { index: 3 };
        assert_eq!(p.to_string(), p.text(Lang::En));
    }

    #[test]
    fn portuguese_uses_the_notes_terms_and_a_decimal_comma() {
        let delay = LtiError::BadDelay(-0.5).text(Lang::Pt);
        assert_eq!(
            delay,
            "o tempo morto é -0,5 s: deve ser um número finito, zero ou positivo"
        );
        let unpaired = LtiError::UnpairedComplexRoot {
            what: RootRole::Pole,
            root: crate::C64::new(-0.5, 2.0),
        };
        assert_eq!(
            unpaired.text(Lang::Pt),
            "os polos devem vir em pares conjugados: -0,5+2j não tem o par -0,5-2j"
        );
        assert_eq!(
            unpaired.text(Lang::En),
            "the poles must come in conjugate pairs: -0.5+2j has no partner -0.5-2j"
        );
        assert!(
            LtiError::DcGainNotScalable(0.0)
                .text(Lang::Pt)
                .starts_with("o ganho estático (DC) é 0")
        );
        let sub = LtiError::Subnormal {
            what: Quantity::Root {
                role: RootRole::Zero,
                index: 1,
            },
            value: 1e-320,
        };
        assert!(
            sub.to_string().starts_with("zero 1 is 1e-320, below"),
            "{sub}"
        );
        assert!(sub.text(Lang::Pt).starts_with("o zero 1 é 1e-320, abaixo"));
    }
}
