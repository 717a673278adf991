//! The Exercises mode's words (the list, the part's buttons, the marks, the solution), each
//! phrase in English and Portuguese. The sheet's statements, labels, checks and worked
//! solutions are the exercise crate's own words ([`degrau_exercise`]).

use degrau_words::{Lang, Localize, Message};

use crate::exercises::load::LoadProblem;
use crate::exercises::session::Progress;
use crate::field::LimitReason;

degrau_words::phrases! {
    /// The labels the Exercises mode draws.
    pub enum Exercises {
        ModeName => ("Exercises", "Exercícios"),
        SheetHeading => ("Exercise sheet", "Folha de exercícios"),
        SheetSource => (
            "Barbosa, time responses (ISEP)",
            "Barbosa, análise no domínio dos tempos (ISEP)"
        ),
        Exercise => ("Exercise", "Exercício"),
        Part => ("Part", "Alínea"),
        OpenIn => ("Open in", "Abrir em"),
        OpenHelp => (
            "Load this part's system into the Poles and zeros mode (its poles, zeros and step; a loop with its gain K)",
            "Carrega o sistema desta alínea no modo Polos e zeros (os polos, os zeros e o degrau; uma malha com o seu ganho K)"
        ),
        Answers => ("Your answers", "As suas respostas"),
        FigureReadings => (
            "The readings the sheet takes off its figure:",
            "As leituras que a folha retira da figura:"
        ),
        FigureTitle => (
            "The sheet's figure, drawn from its readings",
            "A figura da folha, desenhada a partir das leituras"
        ),
        FigureName => ("the sheet's figure", "a figura da folha"),
        Specs => ("The specifications:", "As especificações:"),
        Check => ("Check", "Verificar"),
        CheckHelp => (
            "Compare each answer typed with Degrau's exact value, within the exercise's tolerance",
            "Compara cada resposta escrita com o valor exato do Degrau, dentro da tolerância do exercício"
        ),
        ShowSolution => ("Show solution", "Mostrar a resolução"),
        HideSolution => ("Hide solution", "Esconder a resolução"),
        Solution => ("Worked solution", "Resolução"),
        SheetDiffers => ("Where the sheet's printed answer differs", "Onde a resposta impressa na folha difere"),
        SheetPrints => ("The sheet prints", "A folha imprime"),
        NoSheet => (
            "The exercise sheet could not be built:",
            "A folha de exercícios não pôde ser construída:"
        ),
        MarkRight => ("right", "certo"),
        MarkWrong => ("wrong", "errado"),
        MarkStarted => ("started", "começado"),
        MarkNotTried => ("not tried", "por tentar"),
    }
}

/// The button that loads a part's system: "Open in" and the Design tab's name.
pub fn open_in_design(lang: Lang) -> String {
    format!(
        "{} {}",
        Exercises::OpenIn.get(lang),
        crate::words::app::App::ModeDesign.get(lang)
    )
}

impl Progress {
    /// The mark drawn before a part in the list.
    pub fn symbol(self) -> &'static str {
        match self {
            Progress::NotTried => "○",
            Progress::Started => "◐",
            Progress::Right => "●",
            Progress::Wrong => "×",
        }
    }

    /// The mark in words (its tooltip).
    pub fn word(self, lang: Lang) -> &'static str {
        match self {
            Progress::NotTried => Exercises::MarkNotTried,
            Progress::Started => Exercises::MarkStarted,
            Progress::Right => Exercises::MarkRight,
            Progress::Wrong => Exercises::MarkWrong,
        }
        .get(lang)
    }
}

impl Localize for LoadProblem {
    fn text(&self, lang: Lang) -> String {
        let why = match self {
            LoadProblem::Lti(e) => e.text(lang),
            LoadProblem::System(p) => p.text(lang),
            LoadProblem::Placement(r) => r.text(lang),
        };
        lang.pick(
            format!("This part's system cannot be loaded into the Poles and zeros mode: {why}."),
            format!("O sistema desta alínea não pode ser carregado no modo Polos e zeros: {why}."),
        )
    }
}

/// Every message of the mode.
pub fn messages() -> Vec<Message> {
    let mut all = Exercises::messages();
    all.push(Message::of(
        "exercises::LoadProblem::Placement",
        &LoadProblem::Placement(LimitReason::RootSpread),
    ));
    for p in [
        Progress::NotTried,
        Progress::Started,
        Progress::Right,
        Progress::Wrong,
    ] {
        all.push(Message {
            id: format!("exercises::Progress::{p:?}"),
            en: p.word(Lang::En).into(),
            pt: p.word(Lang::Pt).into(),
        });
    }
    all
}
