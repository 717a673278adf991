//! The Design mode's words (system panel, s-plane, step plot, metrics strip), each phrase
//! with its English and its Brazilian Portuguese (the glossary's terms: polo, zero,
//! ganho estático, tempo morto, sobressinal, tempo de acomodação, …).
//! The facts it says (why there is no response, a root's role and place) are the Design
//! mode's own, below these words.

use degrau_words::{Lang, Localize, Message};

use crate::design::analysis::NoResponse;
use crate::design::state::{RootId, RootRole};

degrau_words::phrases! {
    /// The labels the Design mode draws.
    pub enum Design {
        SystemHeading => ("System", "Sistema"),
        Example => ("Example", "Exemplo"),
        LoadExample => ("Load an example…", "Carregar um exemplo…"),
        CompareKeep => ("Compare: keep this as B", "Comparar: guardar este como B"),
        CompareKeepHelp => (
            "Freeze the current system as B and overlay it while you edit.",
            "Congela o sistema atual como B e o sobrepõe enquanto você edita."
        ),
        StopComparing => ("Stop comparing", "Parar de comparar"),
        KeptName => ("kept", "guardado"),
        GainMeans => ("Gain means", "O ganho é"),
        GainMeansHelp => (
            "k: the k of k·Π(s − z_i)/Π(s − p_j), as MATLAB's zpk. Static gain: G(0), kept fixed while you move roots.",
            "k: o k de k·Π(s − z_i)/Π(s − p_j), como no zpk do MATLAB. Ganho estático: G(0), mantido fixo enquanto você move as raízes."
        ),
        GainZpk => ("k (MATLAB's zpk)", "k (zpk do MATLAB)"),
        GainStatic => ("static G(0)", "ganho estático G(0)"),
        Gain => ("Gain", "Ganho"),
        DeadTime => ("Dead time θ", "Tempo morto θ"),
        Amplitude => ("Step amplitude A", "Amplitude do degrau A"),
        AddRealPole => ("+ real pole", "+ polo real"),
        AddPolePair => ("+ pole pair", "+ par de polos"),
        AddRealZero => ("+ real zero", "+ zero real"),
        AddZeroPair => ("+ zero pair", "+ par de zeros"),
        AtMostRoots => ("At most this many handles (real roots or pairs):", "No máximo este número de raízes (reais ou pares):"),
        NoPoles => ("none: add at least one pole", "nenhum: acrescente ao menos um polo"),
        NoZeros => ("none", "nenhum"),
        MakeReal => ("make real", "tornar reais"),
        MakePair => ("make pair", "tornar par"),
        TogglePairHelp => (
            "Split a pair into two real roots, or make a real root a complex pair",
            "Separa um par em duas raízes reais, ou torna uma raiz real um par complexo"
        ),
        DeleteSmall => ("delete", "apagar"),
        Delete => ("Delete", "Apagar"),
        Order => ("Order", "Ordem"),
        RelativeDegree => ("relative degree", "grau relativo"),
        StaticGain => ("static gain", "ganho estático"),
        Integrator => ("∞ (integrator)", "∞ (integrador)"),
        NoSystem => ("No system:", "Sem sistema:"),
        NoSystemShort => ("no system", "sem sistema"),
        NoResponse => ("No step response:", "Sem resposta ao degrau:"),
        DampingGridShort => ("ζ / ωn grid", "grade ζ / ωn"),
        Snap => ("Snap", "Encaixar"),
        Fit => ("Fit", "Enquadrar"),
        FitViewToRoots => ("Fit the view to the roots", "Enquadrar a vista nas raízes"),
        Unstable => (
            "Unstable: a pole is in the right half plane",
            "Instável: há um polo no semiplano direito"
        ),
        SPlaneHelp => (
            "Drag a pole (×) or zero (o); right-click to add; scroll to zoom; drag the background to pan.",
            "Arraste um polo (×) ou zero (o); clique com o botão direito para acrescentar; role para ampliar; arraste o fundo para mover."
        ),
        PlaneCaption => (
            "s-plane: σ (1/s) across, jω (rad/s) up",
            "plano s: σ (1/s) na horizontal, jω (rad/s) na vertical"
        ),
        Mirror => ("mirror", "espelho"),
        PlaneName => ("s-plane", "plano s"),
        PlotName => ("step response", "resposta ao degrau"),
        MetricsFolded => (
            "Step metrics (here while an approximation is shown in a small window)",
            "Métricas do degrau (aqui enquanto uma aproximação é mostrada numa janela pequena)"
        ),
        AddRealPoleHere => ("Add real pole here", "Acrescentar polo real aqui"),
        AddPolePairHere => ("Add complex pole pair here", "Acrescentar par de polos complexos aqui"),
        AddRealZeroHere => ("Add real zero here", "Acrescentar zero real aqui"),
        AddZeroPairHere => ("Add complex zero pair here", "Acrescentar par de zeros complexos aqui"),
        MakeComplexPair => ("Make it a complex pair (adds its mirror)", "Tornar um par complexo (acrescenta o espelho)"),
        MakeTwoReal => ("Make it two real roots", "Tornar duas raízes reais"),
        MarkersLabel => ("Markers:", "Marcadores:"),
        Rise => ("Rise", "Subida"),
        Peak => ("Peak", "Pico"),
        Settling => ("Settling", "Acomodação"),
        SteadyState => ("Steady state", "Regime permanente"),
        Undershoot => ("Undershoot", "Subsinal"),
        Previous => ("Previous", "Anterior"),
        PreviousHelp => (
            "Show the response before the last edit as a faint ghost.",
            "Mostra a resposta de antes da última edição, em traço apagado."
        ),
        Band => ("Band", "Faixa"),
        BandHelp => (
            "Settling band, as a fraction of the change |y_final − y_init|.",
            "Faixa de acomodação, como fração da variação |y_final − y_init|."
        ),
        RiseHelp => (
            "Rise-time limits, as fractions of the way from y_init to y_final.",
            "Limites do tempo de subida, como frações do caminho de y_init a y_final."
        ),
        DoesNotSettle => ("does not settle", "não se acomoda"),
        PeakName => ("peak", "pico"),
        SteadyStateName => ("steady state", "regime permanente"),
        BandName => ("±{} % band", "faixa de ±{} %"),
        SettlingTimeName => ("settling time", "tempo de acomodação"),
        RiseTimeName => ("rise time", "tempo de subida"),
        CrossingName => ("{} % crossing", "passagem por {} %"),
        PeakOvershootName => ("peak, overshoot", "pico, sobressinal"),
        UndershootName => ("undershoot", "subsinal"),
        MetricHeading => ("Metric", "Métrica"),
        CurrentColumn => ("A (current)", "A (atual)"),
        ClosedForm => ("Closed form", "Forma fechada"),
        PhaseForm => ("amplitude–phase form", "forma amplitude–fase"),
        DcGain => ("DC gain", "Ganho estático"),
        StepAmplitudeLower => ("step amplitude", "amplitude do degrau"),
    }
}

/// The name of a root's role ("pole", "zero"), as the handles and rows are labelled.
pub fn role_name(role: RootRole, lang: Lang) -> &'static str {
    match role {
        RootRole::Pole => lang.pick("pole", "polo"),
        RootRole::Zero => "zero",
    }
}

/// The accessible label of a root's handle: "pole 1", "zero 2" (1-based, as people count),
/// in `lang` ("polo 1").
pub fn root_label(id: RootId, lang: Lang) -> String {
    format!("{} {}", role_name(id.role, lang), id.index + 1)
}

/// The heading of a root list ("Poles", "Zeros").
pub fn role_heading(role: RootRole, lang: Lang) -> &'static str {
    match role {
        RootRole::Pole => lang.pick("Poles", "Polos"),
        RootRole::Zero => "Zeros",
    }
}

impl Localize for NoResponse {
    fn text(&self, lang: Lang) -> String {
        match self {
            NoResponse::System(e) => e.text(lang),
            NoResponse::Amplitude(a) => {
                let a = lang.num(*a, 6);
                lang.pick(
                    format!("the step amplitude must be a finite number other than zero, not {a}"),
                    format!(
                        "a amplitude do degrau deve ser um número finito diferente de zero, não {a}"
                    ),
                )
            }
            NoResponse::BeyondDouble => lang
                .pick(
                    "the response is beyond double precision (a value or time is not finite)",
                    "a resposta está além da precisão dupla (um valor ou instante não é finito)",
                )
                .into(),
        }
    }
}

/// Every message of the Design mode, for the catalogue test.
pub fn messages() -> Vec<Message> {
    let mut all = Design::messages();
    for reason in [
        NoResponse::System(degrau_lti::LtiError::NoPoles),
        NoResponse::Amplitude(0.0),
        NoResponse::BeyondDouble,
    ] {
        all.push(Message::of(
            format!("design::NoResponse::{reason:?}"),
            &reason,
        ));
    }
    all.push(Message::said("design::role_name", |lang| {
        format!(
            "{} 1, {} 2",
            role_name(RootRole::Pole, lang),
            role_name(RootRole::Zero, lang)
        )
    }));
    all.push(Message::said("design::role_heading", |lang| {
        format!(
            "{}, {}",
            role_heading(RootRole::Pole, lang),
            role_heading(RootRole::Zero, lang)
        )
    }));
    all
}
