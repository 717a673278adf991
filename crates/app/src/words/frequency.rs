//! The Frequency mode's words (the source, the Bode diagram, the margins, the z-plane and
//! the sampling rules, the Nyquist verdict), each phrase in English and Brazilian Portuguese
//! (the glossary's terms: margem de ganho, margem de fase, frequência de cruzamento,
//! diagrama de Bode, diagrama de Nyquist, período de amostragem, segurador de ordem zero).

use degrau_words::{Lang, Localize, Message};

use crate::frequency::rules::{Missing, RuleKind};
use crate::frequency::session::Refusal;

degrau_words::phrases! {
    /// The labels the Frequency mode draws.
    pub enum Frequency {
        ModeName => ("Frequency", "Frequência"),
        SourceHeading => ("Source", "Origem"),
        SourceDesign => ("Poles and zeros: the system G(s)", "Polos e zeros: o sistema G(s)"),
        SourceTune => ("Tuning: the loop L(s) = C(s)·G(s)", "Sintonia: a malha L(s) = C(s)·G(s)"),
        SourceFitted => ("Identify: the fitted model G(s)", "Identificação: o modelo ajustado G(s)"),
        NoFit => ("(no fitted model yet)", "(ainda não há modelo ajustado)"),
        NoSource => (
            "This source has no transfer function now: fit a model in the Identify mode, or choose another source.",
            "Esta origem não tem função de transferência agora: ajuste um modelo no modo de identificação, ou escolha outra origem."
        ),
        NoLoop => ("No loop:", "Sem malha:"),
        Controller => ("Controller", "Controlador"),
        TabBode => ("Bode diagram", "Diagrama de Bode"),
        TabNyquist => ("Nyquist diagram", "Diagrama de Nyquist"),
        TabZPlane => ("z-plane (sampled)", "Plano z (amostrado)"),
        Magnitude => ("Bode magnitude", "Módulo de Bode"),
        Phase => ("Bode phase", "Fase de Bode"),
        Asymptotes => ("asymptotes", "assíntotas"),
        AsymptotesHeading => ("Bode asymptotes", "Assíntotas de Bode"),
        Corners => ("corner frequencies", "frequências de canto"),
        Curve => ("exact (dead time included)", "exata (com o tempo morto)"),
        GainCrossover => ("gain crossover ω_gc", "cruzamento de ganho ω_gc"),
        PhaseCrossover => ("phase crossover ω_pc", "cruzamento de fase ω_pc"),
        HoverHint => (
            "Hover a plot to read ω, the magnitude and the phase.",
            "Passe o ponteiro sobre um gráfico para ler ω, o módulo e a fase."
        ),
        MarginsHeading => ("Stability margins", "Margens de estabilidade"),
        GainMargin => ("Gain margin", "Margem de ganho"),
        PhaseMargin => ("Phase margin", "Margem de fase"),
        DelayMargin => ("Delay margin", "Margem de atraso"),
        MaxSensitivity => ("Maximum sensitivity Ms", "Sensibilidade máxima Ms"),
        Bandwidth => ("Closed-loop bandwidth", "Banda passante da malha fechada"),
        At => ("at", "em"),
        NoPhaseCrossover => ("no phase crossover", "não há cruzamento de fase"),
        NoGainCrossover => ("|L| never crosses 1: no gain crossover", "|L| nunca cruza 1: não há cruzamento de ganho"),
        NoneUnstable => ("none: the closed loop is not stable", "nenhuma: a malha fechada não é estável"),
        BandwidthBeyond => ("∞: beyond the frequencies scanned", "∞: além das frequências examinadas"),
        BandwidthNone => ("none: |T(0)| is 0 or infinite", "nenhuma: |T(0)| é 0 ou infinito"),
        PhaseCrossings => ("Every phase crossover:", "Todos os cruzamentos de fase:"),
        GainCrossings => ("Every gain crossover:", "Todos os cruzamentos de ganho:"),
        Unstable => ("The closed loop is unstable.", "A malha fechada é instável."),
        Stable => ("The closed loop is stable.", "A malha fechada é estável."),
        StandsAnyGain => (
            "The loop stands any larger gain (no phase crossover).",
            "A malha suporta qualquer ganho maior (não há cruzamento de fase)."
        ),
        StandsAnyDelay => (
            "The loop stands any extra dead time (no gain crossover).",
            "A malha suporta qualquer tempo morto a mais (não há cruzamento de ganho)."
        ),
        PeriodField => ("Sampling period h (s)", "Período de amostragem h (s)"),
        ZohHeading => ("Zero-order hold", "Segurador de ordem zero"),
        ZPlane => ("z-plane", "plano z"),
        UnitCircle => ("unit circle", "círculo unitário"),
        Poles => ("poles", "polos"),
        PolesOfH => ("Poles of H(z):", "Polos de H(z):"),
        ZerosOfH => ("Zeros of H(z):", "Zeros de H(z):"),
        NoZeros => ("none", "não há"),
        ZerosUnknown => ("could not be found", "não foram encontrados"),
        NoH => ("No H(z):", "Sem H(z):"),
        StepPlot => ("Sampled and continuous step responses", "Respostas ao degrau amostrada e contínua"),
        Stairs => ("sampled (held)", "amostrada (segurada)"),
        Continuous => ("continuous", "contínua"),
        Back => ("d2c back: G(s) =", "d2c de volta: G(s) ="),
        NoBack => ("d2c refuses:", "d2c recusa:"),
        RulesHeading => ("The notes' sampling rules", "As regras de amostragem das notas"),
        Met => ("met", "atendida"),
        NotMet => ("not met", "não atendida"),
        DoesNotApply => ("does not apply", "não se aplica"),
        SampledOf => ("H(z) of the plant G(s):", "H(z) da planta G(s):"),
        NyquistPlot => ("Nyquist diagram", "Diagrama de Nyquist"),
        NegativeW => ("L(jω), ω < 0 (mirror)", "L(jω), ω < 0 (espelho)"),
        WholeCurve => ("Whole curve", "Curva inteira"),
        WholeCurveHelp => (
            "Show the whole curve (points beyond 10⁶ left out); unticked: a window around −1",
            "Mostra a curva inteira (pontos além de 10⁶ omitidos); desmarcado: uma janela em torno de −1"
        ),
        Direct => (
            "Counted directly from the closed-loop characteristic equation:",
            "Contado diretamente da equação característica de malha fechada:"
        ),
        Disagree => (
            "The two counts disagree: both are shown as computed.",
            "As duas contagens discordam: ambas são mostradas como calculadas."
        ),
        Refused => ("Refused:", "Recusado:"),
        StairsCut => ("(first 2000 samples)", "(primeiras 2000 amostras)"),
    }
}

/// Math and marks written the same in both languages.
pub const INFINITE: &str = "∞";
pub const ZEROS: &str = "zeros ○";
pub const POSITIVE_W: &str = "L(jω), ω > 0";
pub const MINUS_ONE: &str = "−1";

/// A rule's statement, its source named.
pub fn rule_text(kind: RuleKind, lang: Lang) -> &'static str {
    match kind {
        RuleKind::KalmanBertram => "h < 0.1·τ_max [Kalman & Bertram]",
        RuleKind::DeadTime => lang.pick("0.2 < h/θ < 1 (FOPTD)", "0,2 < h/θ < 1 (FOPTD)"),
        RuleKind::AstromWittenmark => lang.pick(
            "0.01 < h/τ < 0.05 [Åström & Wittenmark]",
            "0,01 < h/τ < 0,05 [Åström & Wittenmark]",
        ),
        RuleKind::Isermann => lang.pick(
            "t_s/15 < h < t_s/6, t_s the 95 % settling time [Isermann]",
            "t_s/15 < h < t_s/6, t_s o tempo de acomodação de 95 % [Isermann]",
        ),
    }
}

impl Localize for Missing {
    fn text(&self, lang: Lang) -> String {
        match self {
            Missing::TimeConstant => lang.pick(
                "no finite slowest time constant (an unstable or integrating pole)",
                "não há constante de tempo mais lenta finita (um polo instável ou integrador)",
            ),
            Missing::DeadTime => lang.pick(
                "there is no dead time (θ = 0)",
                "não há tempo morto (θ = 0)",
            ),
            Missing::Settling => lang.pick(
                "the step response does not settle",
                "a resposta ao degrau não se acomoda",
            ),
        }
        .to_string()
    }
}

impl Localize for Refusal {
    fn text(&self, lang: Lang) -> String {
        let refused = Frequency::Refused.get(lang);
        match self {
            Refusal::Period(h) => lang.pick(
                format!("{refused} the sampling period h must be a positive number of seconds, not {}; h stays as it was", lang.num(*h, 6)),
                format!("{refused} o período de amostragem h deve ser um número positivo de segundos, não {}; h continua como estava", lang.num(*h, 6)),
            ),
        }
    }
}

/// "the loop stands a gain 2.3× larger" (gm a ratio above 1), or how much smaller it must be.
pub fn gain_reading(gm: f64, lang: Lang) -> String {
    let x = lang.num(gm, 3);
    if gm >= 1.0 {
        lang.pick(
            format!("The loop stands a gain {x}× larger before it goes unstable."),
            format!("A malha suporta um ganho {x}× maior antes de ficar instável."),
        )
    } else {
        lang.pick(
            format!("The gain must be multiplied by {x} (made smaller) to reach the stability limit."),
            format!("O ganho deve ser multiplicado por {x} (reduzido) para chegar ao limite de estabilidade."),
        )
    }
}

/// "a dead time 0.8 s longer".
pub fn delay_reading(dm: f64, lang: Lang) -> String {
    let x = lang.num(dm, 3);
    lang.pick(
        format!("It stands a dead time {x} s longer."),
        format!("Suporta um tempo morto {x} s maior."),
    )
}

/// The Nyquist verdict: N, P and Z = N + P.
pub fn nyquist_verdict(n: i64, p: usize, z: i64, lang: Lang) -> String {
    let verdict = if z == 0 {
        lang.pick("stable", "estável")
    } else {
        lang.pick("unstable", "instável")
    };
    lang.pick(
        format!("N = {n} clockwise encirclements of −1, P = {p} open-loop poles in the right half-plane → Z = N + P = {z} closed-loop poles in the right half-plane: {verdict}"),
        format!("N = {n} voltas no sentido horário em torno de −1, P = {p} polos de malha aberta no semiplano direito → Z = N + P = {z} polos de malha fechada no semiplano direito: {verdict}"),
    )
}

/// The direct count's sentence end: "2 roots in the right half-plane: unstable".
pub fn direct_count(z: usize, lang: Lang) -> String {
    let verdict = if z == 0 {
        lang.pick("stable", "estável")
    } else {
        lang.pick("unstable", "instável")
    };
    lang.pick(
        format!("{z} roots in the right half-plane: {verdict}"),
        format!("{z} raízes no semiplano direito: {verdict}"),
    )
}

/// Every message of the Frequency mode: its labels and an example of each fact.
pub fn messages() -> Vec<Message> {
    let mut all = Frequency::messages();
    for m in [Missing::TimeConstant, Missing::DeadTime, Missing::Settling] {
        all.push(Message::of(format!("frequency::Missing::{m:?}"), &m));
    }
    all.push(Message::of(
        "frequency::Refusal::Period",
        &Refusal::Period(-1.0),
    ));
    all
}

/// "… and 3 more" after a list of crossings.
pub fn more_crossings(more: usize, lang: Lang) -> String {
    lang.pick(format!("  … and {more} more"), format!("  … e mais {more}"))
}

/// "The contour goes round 1 open-loop pole(s) on the imaginary axis …".
pub fn indented(poles: usize, lang: Lang) -> String {
    lang.pick(
        format!("The contour goes round the {poles} open-loop pole(s) on the imaginary axis by small half-circles to their right."),
        format!("O contorno passa em volta do(s) {poles} polo(s) de malha aberta no eixo imaginário por pequenos semicírculos à direita."),
    )
}
