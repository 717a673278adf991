//! What the *test* got wrong, in words: each cause's name ([`TestCauseKind`]), its evidence
//! with its numbers and interval ([`TestEvidence`]), what Degrau did about it
//! ([`Handling`]), and what the student should do ([`remedy`]), in English and in Brazilian
//! Portuguese with the notes' terms (ensaio ao degrau, regime permanente, ponto de
//! operação, período de amostragem, ruído, distúrbio, não linearidade). Written once for
//! `degrau diagnose` and the app's "What the test got wrong" panel; the verdict line that
//! names the structure and the artefacts together is here too.

#[cfg(test)]
use crate::diagnose::test_causes::Loss;
use crate::diagnose::test_causes::{
    DisturbanceShape, Handling, RuleCheck, SamplingRule, Signal, StepGain, StepShape, TestCause,
    TestCauseKind, TestEvidence,
};
use crate::diagnose::{Cause, DiagnoseReport};
use crate::fit::rest::Motion;

use super::ident::Naming;
#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

/// `x` with four significant digits.
fn n4(lang: Lang, x: f64) -> String {
    lang.num(x, 4)
}

/// `t = a … b s`.
pub fn span_words((a, b): (f64, f64), lang: Lang) -> String {
    format!("t = {} … {} s", n4(lang, a), n4(lang, b))
}

degrau_words::phrases! {
    /// The fixed words of the test causes' texts.
    pub enum TestCausePhrase {
        Heading => ("What the test got wrong", "O que o ensaio teve de errado"),
        ModelHeading => ("What the model gets wrong", "O que falta ao modelo"),
        NothingFound => (
            "Nothing: the test meets the method's premises as far as the data show.",
            "Nada: o ensaio atende às premissas do método até onde os dados mostram."
        ),
        Remedy => ("What to do", "O que fazer"),
        Done => ("What Degrau did", "O que o Degrau fez"),
        NoArtefacts => ("no artefact found", "nenhum artefato encontrado"),
    }
}

/// A test cause's name: its identifier (`not_at_rest`), or a few words in `lang` ("Not at
/// rest", "Fora do repouso") short enough to label a span on a plot.
pub fn test_cause_name(k: TestCauseKind, naming: Naming, lang: Lang) -> &'static str {
    if naming == Naming::Id {
        return k.id();
    }
    let (en, pt) = match k {
        TestCauseKind::NotAtRest => ("Not at rest", "Fora do repouso"),
        TestCauseKind::Disturbance => ("Disturbance", "Perturbação"),
        TestCauseKind::Nonlinearity => ("Nonlinearity", "Não linearidade"),
        TestCauseKind::Saturation => ("Saturation", "Saturação"),
        TestCauseKind::Outliers => ("Outliers", "Valores espúrios"),
        TestCauseKind::ColouredNoise => ("Coloured noise", "Ruído colorido"),
        TestCauseKind::Quantisation => ("Quantisation", "Quantização"),
        TestCauseKind::Sampling => ("Sampling", "Amostragem"),
        TestCauseKind::SmallStep => ("Small step", "Degrau pequeno"),
        TestCauseKind::ImperfectStep => ("Imperfect step", "Degrau imperfeito"),
        TestCauseKind::ClosedLoop => ("Closed loop", "Malha fechada"),
    };
    lang.pick(en, pt)
}

impl Localize for TestCauseKind {
    /// The cause's name, as a heading.
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            TestCauseKind::NotAtRest => (
                "Not at rest before the step",
                "Fora do equilíbrio antes do degrau",
            ),
            TestCauseKind::Disturbance => (
                "A disturbance during the test",
                "Um distúrbio durante o ensaio",
            ),
            TestCauseKind::Nonlinearity => (
                "A nonlinearity: the gain depends on the step",
                "Uma não linearidade: o ganho depende do degrau",
            ),
            TestCauseKind::Saturation => (
                "Saturation: a signal held at a limit",
                "Saturação: um sinal preso num limite",
            ),
            TestCauseKind::Outliers => (
                "Outliers: isolated wrong samples",
                "Valores espúrios: amostras isoladas erradas",
            ),
            TestCauseKind::ColouredNoise => (
                "Coloured noise: correlated residuals",
                "Ruído colorido: resíduos correlacionados",
            ),
            TestCauseKind::Quantisation => (
                "Quantisation: a coarse output resolution",
                "Quantização: resolução grosseira da saída",
            ),
            TestCauseKind::Sampling => (
                "The sampling period breaks the rules",
                "O período de amostragem fere as regras",
            ),
            TestCauseKind::SmallStep => (
                "The step is small against the noise",
                "O degrau é pequeno diante do ruído",
            ),
            TestCauseKind::ImperfectStep => {
                ("The step was not a step", "O degrau não foi um degrau")
            }
            TestCauseKind::ClosedLoop => (
                "Closed loop: the input answers the output",
                "Malha fechada: a entrada responde à saída",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

mod evidence;
#[cfg(test)]
mod examples;
mod remedies;

#[cfg(test)]
pub use examples::*;
pub use remedies::*;
