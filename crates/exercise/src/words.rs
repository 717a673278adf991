//! The crate's fixed words and the sentences of a check, in English and Portuguese (the
//! sheet's PT-PT terms where the glossary gives them: sobreelongação, tempo de
//! estabelecimento). The words of each exercise's statement and steps live in its file.

use degrau_words::{Lang, Localize};

use crate::expr::ExprError;
use crate::input::InputError;
use crate::model::Choice;

degrau_words::phrases! {
    /// How a value was computed, and the names of the choices.
    pub enum Phrase {
        Exact => ("exact step response", "resposta ao degrau exata"),
        ExactLoop => ("exact closed-loop step response", "resposta ao degrau exata em malha fechada"),
        Formula => ("second-order formula", "fórmula de segunda ordem"),
        FirstOrderFormula => ("first-order rule t_s = 4τ", "regra de primeira ordem t_s = 4τ"),
        Rise10to90 => ("10–90 % rise time, as MATLAB's stepinfo", "tempo de subida de 10–90 %, como o stepinfo do MATLAB"),
        Rise0to100 => ("0–100 % rise time, the formula's definition", "tempo de subida de 0–100 %, a definição da fórmula"),
        FinalValue => ("final value theorem", "teorema do valor final"),
        Readings => ("from the figure's readings", "a partir das leituras da figura"),
        Poles => ("from the poles", "a partir dos pólos"),
        ErrorConstants => ("error constants of the open loop", "constantes de erro da malha aberta"),
        Model => ("from the model's equations", "das equações do modelo"),
        Overdamped => ("overdamped", "sobreamortecida"),
        CriticallyDamped => ("critically damped", "criticamente amortecida"),
        Underdamped => ("underdamped", "subamortecida"),
        Undamped => ("undamped", "sem amortecimento"),
        Yes => ("yes", "sim"),
        No => ("no", "não"),
        Right => ("Right.", "Certo."),
        Wrong => ("Not right.", "Não está certo."),
        SheetNote => ("The sheet prints a different answer:", "A folha imprime uma resposta diferente:"),
    }
}

impl Choice {
    /// The choice's word in `lang`.
    pub fn word(self, lang: Lang) -> &'static str {
        match self {
            Choice::Overdamped => Phrase::Overdamped,
            Choice::CriticallyDamped => Phrase::CriticallyDamped,
            Choice::Underdamped => Phrase::Underdamped,
            Choice::Undamped => Phrase::Undamped,
            Choice::Yes => Phrase::Yes,
            Choice::No => Phrase::No,
        }
        .get(lang)
    }
}

impl Localize for ExprError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ExprError::Empty => lang.pick("nothing typed".into(), "nada escrito".into()),
            ExprError::Character(c) => lang.pick(
                format!("the character {c:?} is not understood"),
                format!("o carácter {c:?} não é reconhecido"),
            ),
            ExprError::Name(n) => lang.pick(
                format!("the name {n:?} is not known (use s, t, K, exp, sin, cos, sqrt)"),
                format!("o nome {n:?} não é conhecido (use s, t, K, exp, sin, cos, sqrt)"),
            ),
            ExprError::Bracket => lang.pick(
                "a bracket is not closed or not opened".into(),
                "há um parêntese por fechar ou por abrir".into(),
            ),
            ExprError::Syntax => lang.pick(
                "the expression ends too early or has something left over".into(),
                "a expressão acaba cedo demais ou tem algo a mais".into(),
            ),
            ExprError::TooLong => lang.pick(
                "the expression is too long or too deeply bracketed".into(),
                "a expressão é longa demais ou tem parênteses a mais".into(),
            ),
            ExprError::Variable(v) => lang.pick(
                format!("the variable {v} does not belong in this answer"),
                format!("a variável {v} não faz parte desta resposta"),
            ),
        }
    }
}

impl Localize for InputError {
    fn text(&self, lang: Lang) -> String {
        match self {
            InputError::Empty => lang.pick("Nothing typed.".into(), "Nada escrito.".into()),
            InputError::NotNumber(t) => lang.pick(
                format!("{t:?} is not a number (e.g. 0,25 or 0.25 s or inf)."),
                format!("{t:?} não é um número (p. ex. 0,25 ou 0.25 s ou inf)."),
            ),
            InputError::Expression(e) => lang.pick(
                format!("The expression cannot be read: {}.", e.text(lang)),
                format!("A expressão não pode ser lida: {}.", e.text(lang)),
            ),
            InputError::Coefficients(t) => lang.pick(
                format!("{t:?} is not two coefficient lists (e.g. [10], [1 2])."),
                format!("{t:?} não são duas listas de coeficientes (p. ex. [10], [1 2])."),
            ),
            InputError::Range(t) => lang.pick(
                format!("{t:?} is not a range of K (e.g. 0 < K ≤ 2.86, or K > 0.03)."),
                format!("{t:?} não é um intervalo de K (p. ex. 0 < K ≤ 2,86, ou K > 0,03)."),
            ),
            InputError::Region(t) => lang.pick(
                format!("{t:?} is not a region (e.g. ζ ≥ 0.4; σ ≥ 40)."),
                format!("{t:?} não é uma região (p. ex. ζ ≥ 0,4; σ ≥ 40)."),
            ),
            InputError::Roots(t) => lang.pick(
                format!("{t:?} is not a list of roots (e.g. -2; -4 or -1 ± j2)."),
                format!("{t:?} não é uma lista de raízes (p. ex. -2; -4 ou -1 ± j2)."),
            ),
            InputError::Choice(t) => lang.pick(
                format!("{t:?} is not one of the words offered."),
                format!("{t:?} não é uma das palavras propostas."),
            ),
            InputError::WrongField => lang.pick(
                "This kind of answer does not fit this question.".into(),
                "Este tipo de resposta não serve para esta pergunta.".into(),
            ),
        }
    }
}
