//! The Tune mode's words (the model, the controller, the responses' plots and metrics, the
//! rule table), each phrase in English and Brazilian Portuguese (the glossary's terms:
//! sintonia, controlador, tempo morto, constante de tempo, perturbação de carga, …). The
//! names of a controller's parts and of the loop's metrics are the lti crate's
//! ([`degrau_lti::words::control::ControlWord`]).

use degrau_words::{Lang, Localize, Message};

use crate::tune::model::ModelProblem;
use crate::tune::session::Refusal;

degrau_words::phrases! {
    /// The labels the Tune mode draws.
    pub enum Tune {
        ModeName => ("Tuning", "Sintonia"),
        TuneButton => ("Tune a controller", "Sintonizar um controlador"),
        TuneButtonHelp => (
            "Open the fitted first- or second-order model with dead time in the Tune mode",
            "Abre o modelo ajustado de primeira ou segunda ordem com tempo morto no modo de sintonia"
        ),
        ModelHeading => ("Process model", "Modelo do processo"),
        Foptd => ("First order + dead time", "Primeira ordem + tempo morto"),
        Soptd => ("Second order + dead time", "Segunda ordem + tempo morto"),
        ProcessGain => ("Process gain K", "Ganho do processo K"),
        Tau => ("Time constant τ (s)", "Constante de tempo τ (s)"),
        Tau1 => ("Time constant τ1 (s)", "Constante de tempo τ1 (s)"),
        Tau2 => ("Time constant τ2 (s)", "Constante de tempo τ2 (s)"),
        DeadTime => ("Dead time θ (s)", "Tempo morto θ (s)"),
        Typed => ("Typed model", "Modelo digitado"),
        ReceivedFrom => ("From the Identify mode: the fitted", "Do modo de identificação: o modelo ajustado"),
        Action => ("Action", "Ações"),
        DragHeading => (
            "Drag to tune (the responses follow):",
            "Arraste para sintonizar (as respostas acompanham):"
        ),
        DragHelp => (
            "Drag sideways to change the value; the plots and metrics update as you drag",
            "Arraste para os lados para mudar o valor; os gráficos e as métricas acompanham"
        ),
        TiUnused => ("Ti and Td are kept but not used by this action.", "Ti e Td são guardados, mas esta ação não os usa."),
        Tc => ("Closed-loop time constant τc (s)", "Constante de tempo em malha fechada τc (s)"),
        TcEmpty => ("empty: τc = θ", "vazio: τc = θ"),
        Refused => ("Refused:", "Recusado:"),
        NoLoop => ("No responses:", "Sem respostas:"),
        Output => ("output y", "saída y"),
        SetpointLine => ("setpoint r", "referência r"),
        Undisturbed => ("undisturbed output (0)", "saída sem perturbação (0)"),
        NoneValue => ("none", "não há"),
        Use => ("Use", "Usar"),
        UseHelp => (
            "Load this rule's Kc, Ti and Td into the controller",
            "Carrega o Kc, o Ti e o Td desta regra no controlador"
        ),
        RulesHeading => ("Tuning rules", "Regras de sintonia"),
        RulesWaiting => (
            "The rule table needs a model and an action with rules.",
            "A tabela de regras precisa de um modelo e de uma ação com regras."
        ),
        NotApplicable => ("does not apply:", "não se aplica:"),
        ZnOpenShort => ("ZN (reaction curve)", "ZN (curva de reação)"),
        ZnUltimateShort => ("ZN (ultimate cycle)", "ZN (ciclo último)"),
        RulesHelp => (
            "Click a rule to load its Kc, Ti and Td into the controller. OS and ts: the setpoint step; peak dev. and the second IAE: the load step.",
            "Clique numa regra para carregar seu Kc, Ti e Td no controlador. Sobress. e ts: o degrau de referência; desvio máx. e o segundo IAE: o degrau de carga."
        ),
        Chosen => ("chosen", "escolhida"),
        SetpointShort => ("setpoint", "referência"),
        LoadShort => ("load", "carga"),
        OvershootShort => ("OS %", "Sobress. %"),
        PeakShort => ("peak dev.", "desvio máx."),
    }
}

/// Math written the same in both languages.
pub const FOPTD_FORMULA: &str = "G(s) = K·e^(−θs)/(τs + 1)";
pub const SOPTD_FORMULA: &str = "G(s) = K·e^(−θs)/((τ1 s + 1)(τ2 s + 1))";
pub const SETTLING_SHORT: &str = "ts (s)";
pub const IAE_SHORT: &str = "IAE";
pub const MS_SHORT: &str = "Ms";
/// A metric that has no value because the loop did not settle.
pub const NO_VALUE: &str = "—";

impl Localize for ModelProblem {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match self {
            ModelProblem::Gain(k) => lang.pick(
                format!("the process gain K must be a finite number other than 0, not {}", n(*k)),
                format!("o ganho do processo K deve ser um número finito diferente de 0, não {}", n(*k)),
            ),
            ModelProblem::TimeConstant(t) => lang.pick(
                format!("a time constant must be a positive number of seconds up to 1e6, not {}", n(*t)),
                format!("uma constante de tempo deve ser um número positivo de segundos até 1e6, não {}", n(*t)),
            ),
            ModelProblem::Delay(t) => lang.pick(
                format!("the dead time θ must be 0 or a positive number of seconds up to 1e6, not {}", n(*t)),
                format!("o tempo morto θ deve ser 0 ou um número positivo de segundos até 1e6, não {}", n(*t)),
            ),
            ModelProblem::NotTunable(code) => lang.pick(
                format!("the fitted {code} model is not first or second order with dead time: fit P1D or P2D to tune a controller"),
                format!("o modelo ajustado {code} não é de primeira ou segunda ordem com tempo morto: ajuste P1D ou P2D para sintonizar um controlador"),
            ),
        }
    }
}

impl Localize for Refusal {
    fn text(&self, lang: Lang) -> String {
        let refused = Tune::Refused.get(lang);
        match self {
            Refusal::Model(_, p) | Refusal::Received(p) | Refusal::Tc(p) => {
                format!("{refused} {}", p.text(lang))
            }
            Refusal::Controller(_, e) => format!("{refused} {}", e.text(lang)),
        }
    }
}

/// Every message of the Tune mode: its labels and an example of each refusal.
pub fn messages() -> Vec<Message> {
    let problems = [
        ModelProblem::Gain(0.0),
        ModelProblem::TimeConstant(-1.0),
        ModelProblem::Delay(-2.0),
        ModelProblem::NotTunable("P2DU".into()),
    ];
    let mut all = Tune::messages();
    all.extend(
        problems
            .iter()
            .map(|p| Message::of(format!("ModelProblem::{p:?}"), p)),
    );
    all
}
