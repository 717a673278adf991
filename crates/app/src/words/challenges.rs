//! The Challenges' words (issue 27, item 2), each phrase in English and Portuguese. The
//! causes, their evidence and Degrau's diagnosis are the diagnosis's own words
//! ([`degrau_ident::words`]).

use degrau_ident::challenge::Level;
use degrau_words::{Lang, Message};

degrau_words::phrases! {
    /// The labels the Challenges draw.
    pub enum Challenges {
        Heading => ("Challenges", "Desafios"),
        Intro => (
            "A record from a process with something hidden. Find it.",
            "Um registro de um processo com algo escondido. Encontre-o."
        ),
        LevelLabel => ("Level", "Nível"),
        LevelClear => ("clear", "claro"),
        LevelModerate => ("moderate", "moderado"),
        LevelSubtle => ("subtle", "sutil"),
        New => ("New challenge", "Novo desafio"),
        NewHelp => (
            "Draw a new record with a hidden effect at the level chosen",
            "Sorteia um novo registro com um efeito escondido no nível escolhido"
        ),
        Drawing => ("Drawing a challenge…", "Sorteando um desafio…"),
        Cancel => ("Cancel", "Cancelar"),
        Current => ("The challenge", "O desafio"),
        Task => (
            "This record (columns t, u, y) comes from a process with something hidden from a first-order model: a structural effect, a flaw of the test, or both. Open it in Identify, fit it from P1, extend the model as the record asks, and answer: the cause, the final structure and the static gain.",
            "Este registro (colunas t, u, y) vem de um processo com algo escondido de um modelo de primeira ordem: um efeito estrutural, uma falha do ensaio, ou ambos. Abra-o em Identificar, ajuste-o a partir de P1, estenda o modelo como o registro pede e responda: a causa, a estrutura final e o ganho estático."
        ),
        OpenRecord => ("Open the record in Identify", "Abrir o registro em Identificar"),
        Answers => ("Your answers", "As suas respostas"),
        Cause => ("Cause", "Causa"),
        ChooseCause => ("(choose)", "(escolha)"),
        Structure => ("Final structure (e.g. P2D)", "Estrutura final (ex.: P2D)"),
        Kp => ("Static gain Kp", "Ganho estático Kp"),
        Check => ("Check", "Verificar"),
        CheckHelp => (
            "Compare your answers with the hidden truth",
            "Compara as suas respostas com a verdade escondida"
        ),
        Right => ("right", "certo"),
        Wrong => ("wrong", "errado"),
        Truth => ("the hidden truth", "a verdade escondida"),
        Evidence => ("What in the record gave it away", "O que no registro o denunciou"),
        NoEvidence => (
            "Degrau's diagnosis names no structural cause: the first-order model is the process's.",
            "O diagnóstico do Degrau não nomeia causa estrutural: o modelo de primeira ordem é o do processo."
        ),
        ShowDiagnosis => ("Show Degrau's diagnosis", "Mostrar o diagnóstico do Degrau"),
        Diagnosis => ("Degrau's diagnosis", "O diagnóstico do Degrau"),
        NoDiagnosis => (
            "The diagnosis could not be run on this record.",
            "O diagnóstico não pôde ser feito neste registro."
        ),
        NumberLabel => ("Challenge", "Desafio"),
        DrawnAgain => (
            "This challenge was drawn by an earlier version of Degrau, whose challenge generator differed, and has been drawn again by this one from the same seed: the record may differ from the one you saw. Your answers are kept; check them against this record.",
            "Este desafio foi sorteado por uma versão anterior do Degrau, cujo gerador de desafios era outro, e foi sorteado de novo por esta a partir da mesma semente: o registro pode diferir do que você viu. As suas respostas foram mantidas; verifique-as com este registro."
        ),
    }
}

/// A level in words.
pub fn level(level: Level, lang: Lang) -> &'static str {
    match level {
        Level::Clear => Challenges::LevelClear,
        Level::Moderate => Challenges::LevelModerate,
        Level::Subtle => Challenges::LevelSubtle,
    }
    .get(lang)
}

/// Every message of the Challenges.
pub fn messages() -> Vec<Message> {
    Challenges::messages()
}
