//! The words of the closed loop, the root locus and the design specs: the inverse of the
//! second-order formulas refusing a spec ([`InverseError`]), the CLI's `degrau loop` report
//! and the Design mode's loop, locus and spec controls, in English and Brazilian Portuguese
//! (malha fechada, lugar das raízes, ganho crítico, erro em regime permanente, …).

use crate::feedback::{Input, InverseError};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

impl Localize for InverseError {
    fn text(&self, lang: Lang) -> String {
        match *self {
            InverseError::Overshoot(mp) => match lang {
                Lang::En => format!(
                    "the overshoot must be between 0 and 100 %, not {}",
                    lang.num(mp, 6)
                ),
                Lang::Pt => format!(
                    "o sobressinal deve estar entre 0 e 100 %, não {}",
                    lang.num(mp, 6)
                ),
            },
            InverseError::Time(t) => match lang {
                Lang::En => format!(
                    "a time must be a positive number of seconds, not {}",
                    lang.num(t, 6)
                ),
                Lang::Pt => format!(
                    "um tempo deve ser um número positivo de segundos, não {}",
                    lang.num(t, 6)
                ),
            },
        }
    }
}

/// The heading of the response to an input: "Ramp response y(t) (exact closed form):".
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputHeading(pub Input);

impl Localize for InputHeading {
    fn text(&self, lang: Lang) -> String {
        match (self.0, lang) {
            (Input::Step, Lang::En) => "Step response y(t) (exact closed form):".into(),
            (Input::Step, Lang::Pt) => "Resposta ao degrau y(t) (forma fechada exata):".into(),
            (Input::Ramp, Lang::En) => "Ramp response y(t) (exact closed form):".into(),
            (Input::Ramp, Lang::Pt) => "Resposta à rampa y(t) (forma fechada exata):".into(),
            (Input::Parabola, Lang::En) => "Parabola response y(t) (exact closed form):".into(),
            (Input::Parabola, Lang::Pt) => "Resposta à parábola y(t) (forma fechada exata):".into(),
            (Input::Impulse, Lang::En) => {
                "Impulse response y(t) = dy_step/dt (for t > θ; a biproper system adds an impulse at θ):".into()
            }
            (Input::Impulse, Lang::Pt) => {
                "Resposta ao impulso y(t) = dy_degrau/dt (para t > θ; um sistema bipróprio soma um impulso em θ):".into()
            }
        }
    }
}

impl Loop {
    /// The closed loop's curve name, said approximate when a dead time was replaced.
    pub fn closed_loop_curve(approximate: bool) -> Self {
        if approximate {
            Loop::ClosedLoopCurveApproximate
        } else {
            Loop::ClosedLoopCurve
        }
    }

    /// The name of an input in the "also plot the response to" choice.
    pub fn input_name(input: Input) -> Self {
        match input {
            Input::Step => Loop::InputStep,
            Input::Impulse => Loop::InputImpulse,
            Input::Ramp => Loop::InputRamp,
            Input::Parabola => Loop::InputParabola,
        }
    }
}

/// A spec's checkbox in the Design mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpecName {
    Overshoot,
    Settling,
    Peak,
    Rise,
    WnMin,
    WnMax,
    EssStep,
    EssRamp,
}

impl SpecName {
    pub const ALL: [SpecName; 8] = [
        SpecName::Overshoot,
        SpecName::Settling,
        SpecName::Peak,
        SpecName::Rise,
        SpecName::WnMin,
        SpecName::WnMax,
        SpecName::EssStep,
        SpecName::EssRamp,
    ];

    /// The label of the spec's limit field (notation, with the input named in `lang`).
    pub fn field_label(self, lang: Lang) -> &'static str {
        match self {
            SpecName::Overshoot => "Mp ≤",
            SpecName::Settling => "t_s ≤",
            SpecName::Peak => "t_p ≤",
            SpecName::Rise => "t_r ≤",
            SpecName::WnMin => "ωn ≥",
            SpecName::WnMax => "ωn ≤",
            SpecName::EssStep => lang.pick("e_ss step ≤", "e_ss degrau ≤"),
            SpecName::EssRamp => lang.pick("e_ss ramp ≤", "e_ss rampa ≤"),
        }
    }
}

impl Localize for SpecName {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            SpecName::Overshoot => ("overshoot", "sobressinal"),
            SpecName::Settling => ("settling time, 2 %", "tempo de acomodação, 2 %"),
            SpecName::Peak => ("peak time", "tempo de pico"),
            SpecName::Rise => ("rise time, 10–90 %", "tempo de subida, 10–90 %"),
            SpecName::WnMin => ("least natural frequency", "frequência natural mínima"),
            SpecName::WnMax => ("largest natural frequency", "frequência natural máxima"),
            SpecName::EssStep => (
                "steady-state error, step",
                "erro em regime permanente, degrau",
            ),
            SpecName::EssRamp => (
                "steady-state error, ramp",
                "erro em regime permanente, rampa",
            ),
        };
        lang.pick(en, pt).into()
    }
}

/// A refusal of `degrau loop` said here (the rest are the CLI's and the library's).
#[derive(Debug, Clone, PartialEq)]
pub enum LoopError {
    /// A `--find` item that is not `name<=number`.
    BadSpec(String),
    NoGain,
    /// A `--pade` value that is not `m,n` with 1 ≤ n ≤ the largest order and m ≤ n.
    BadPade(String),
}

impl Localize for LoopError {
    fn text(&self, lang: Lang) -> String {
        match self {
            LoopError::BadSpec(item) => match lang {
                Lang::En => format!(
                    "--find \"{item}\" is not a spec: write name<=number with a name among overshoot (%), settling (s), rise (s), ess_step, ess_ramp, e.g. \"overshoot<=10\""
                ),
                Lang::Pt => format!(
                    "--find \"{item}\" não é uma especificação: escreva nome<=número com um nome entre overshoot (sobressinal, %), settling (tempo de acomodação, s), rise (tempo de subida, s), ess_step, ess_ramp, por exemplo \"overshoot<=10\""
                ),
            },
            LoopError::BadPade(item) => {
                let most = crate::feedback::PadeOrder::MAX_N;
                match lang {
                    Lang::En => format!(
                        "--pade \"{item}\" is not a Padé order: write m,n with 1 ≤ n ≤ {most} and 0 ≤ m ≤ n, e.g. \"3,3\""
                    ),
                    Lang::Pt => format!(
                        "--pade \"{item}\" não é uma ordem de Padé: escreva m,n com 1 ≤ n ≤ {most} e 0 ≤ m ≤ n, por exemplo \"3,3\""
                    ),
                }
            }
            LoopError::NoGain => lang
                .pick(
                    "no proportional gain K > 0 meets every spec on the exact closed-loop response",
                    "nenhum ganho proporcional K > 0 atende a todas as especificações na resposta exata em malha fechada",
                )
                .into(),
        }
    }
}

/// A line of the loop's report, with its numbers already written in the language.
#[derive(Debug, Clone, PartialEq)]
pub enum LoopLine {
    OpenLoop(String),
    Gain(String),
    /// The range of gains meeting the specs: low, high (∞ when unbounded).
    Range(String, String),
    Constants {
        system_type: i32,
        kp: String,
        kv: String,
        ka: String,
    },
    /// e_ss for a step, a ramp, a parabola.
    Errors(String, String, String),
    /// The critical gain and the crossing frequency.
    Critical(String, String),
    /// Breakaway (true) or break-in, at σ, with K.
    Breakaway(bool, String, String),
    /// The centroid and the angles.
    Asymptotes(String, String),
    /// The gain found, and its range (low, high).
    Found(String, String, String),
    /// The dead time θ (s, written) replaced by Padé (m, n): the closed loop is approximate.
    Approximant {
        m: usize,
        n: usize,
        delay: String,
    },
}

impl Localize for LoopLine {
    fn text(&self, lang: Lang) -> String {
        match self {
            LoopLine::OpenLoop(g) => match lang {
                Lang::En => format!("Open loop         G(s) = {g}"),
                Lang::Pt => format!("Malha aberta      G(s) = {g}"),
            },
            LoopLine::Gain(k) => match lang {
                Lang::En => format!("Proportional gain Kp = {k} (unity feedback)"),
                Lang::Pt => format!("Ganho proporcional Kp = {k} (realimentação unitária)"),
            },
            LoopLine::Range(lo, hi) => match lang {
                Lang::En => format!(
                    "Gains meeting every spec: {lo} ≤ Kp ≤ {hi} (exact closed-loop response)"
                ),
                Lang::Pt => format!(
                    "Ganhos que atendem a todas as especificações: {lo} ≤ Kp ≤ {hi} (resposta exata em malha fechada)"
                ),
            },
            LoopLine::Constants {
                system_type,
                kp,
                kv,
                ka,
            } => match lang {
                Lang::En => format!(
                    "System type {system_type}; error constants of Kp·G: position K_p = {kp}, velocity K_v = {kv}, acceleration K_a = {ka}"
                ),
                Lang::Pt => format!(
                    "Tipo do sistema {system_type}; constantes de erro de Kp·G: posição K_p = {kp}, velocidade K_v = {kv}, aceleração K_a = {ka}"
                ),
            },
            LoopLine::Errors(step, ramp, parabola) => match lang {
                Lang::En => format!(
                    "Steady-state error: step {step}, ramp {ramp}, parabola {parabola} (unit inputs)"
                ),
                Lang::Pt => format!(
                    "Erro em regime permanente: degrau {step}, rampa {ramp}, parábola {parabola} (entradas unitárias)"
                ),
            },
            LoopLine::Critical(k, w) => match lang {
                Lang::En => format!(
                    "Critical gain Kcr = {k}: closed-loop poles on the jω axis at ±j{w} rad/s"
                ),
                Lang::Pt => format!(
                    "Ganho crítico Kcr = {k}: polos de malha fechada no eixo jω em ±j{w} rad/s"
                ),
            },
            LoopLine::Breakaway(away, s, k) => match (lang, away) {
                (Lang::En, true) => format!("Breakaway point s = {s} (K = {k})"),
                (Lang::En, false) => format!("Break-in point s = {s} (K = {k})"),
                (Lang::Pt, true) => format!("Ponto de saída do eixo real s = {s} (K = {k})"),
                (Lang::Pt, false) => format!("Ponto de chegada ao eixo real s = {s} (K = {k})"),
            },
            LoopLine::Found(k, lo, hi) => match lang {
                Lang::En => format!(
                    "Kp = {k} taken; every spec holds for {lo} ≤ Kp ≤ {hi} (exact closed-loop response); its poles are marked ■ on the s-plane"
                ),
                Lang::Pt => format!(
                    "Kp = {k} adotado; todas as especificações valem para {lo} ≤ Kp ≤ {hi} (resposta exata em malha fechada); seus polos estão marcados ■ no plano s"
                ),
            },
            LoopLine::Approximant { m, n, delay } => match lang {
                Lang::En => format!(
                    "Dead time e^(−θs), θ = {delay} s, replaced by its Padé ({m}, {n}) approximant: the closed loop is approximate"
                ),
                Lang::Pt => format!(
                    "Tempo morto e^(−θs), θ = {delay} s, substituído pela sua aproximação de Padé ({m}, {n}): a malha fechada é aproximada"
                ),
            },
            LoopLine::Asymptotes(c, angles) => match lang {
                Lang::En => format!("Asymptotes from the centroid σa = {c}, at {angles}"),
                Lang::Pt => format!("Assíntotas a partir do centroide σa = {c}, a {angles}"),
            },
        }
    }
}

degrau_words::phrases! {
    /// The loop's fixed phrases (CLI report and Design mode).
    pub enum Loop {
        NoSteadyState => (
            "Steady-state error: none, the closed loop is not stable",
            "Erro em regime permanente: não há, a malha fechada não é estável"
        ),
        NoCriticalGain => (
            "No critical gain: the locus never crosses the jω axis for K > 0",
            "Sem ganho crítico: o lugar das raízes nunca cruza o eixo jω para K > 0"
        ),
        LocusHeading => ("Root locus (K, closed-loop poles):", "Lugar das raízes (K, polos de malha fechada):"),
        ControllerLabel => ("Controller:", "Controlador:"),
        ControllerHelp => (
            "P, or a PI, PD or PID of fixed Ti, Td and filter N whose gain Kc is Kp: the root locus then follows K with the controller's zeros and poles in place",
            "P, ou um PI, PD ou PID de Ti, Td e filtro N fixos cujo ganho Kc é o Kp: o lugar das raízes segue então K com os zeros e polos do controlador no lugar"
        ),
        ControllerGainIsK => (
            "Kc = Kp below (the locus's K). With a dead time this loop uses Padé; the Tune mode computes it with the exact dead time.",
            "Kc = Kp abaixo (o K do lugar das raízes). Com tempo morto esta malha usa Padé; o modo Sintonia a calcula com o atraso exato."
        ),
        ClosedLoopHeading => ("Closed loop:", "Malha fechada:"),
        LoopHeading => ("Closed loop", "Malha fechada"),
        CoefficientsHelp => (
            "G(s) as tf(num, den), descending powers of s (e.g. 0.5 and 1 7 15 25):",
            "G(s) como tf(num, den), em potências decrescentes de s (por exemplo 0,5 e 1 7 15 25):"
        ),
        CoefficientsBeyond => (
            "These coefficients give roots beyond what the app holds (|s| ≤ 1e6, at most 1e12 between the fastest and the slowest).",
            "Estes coeficientes dão raízes além do que o aplicativo comporta (|s| ≤ 1e6, no máximo 1e12 entre a mais rápida e a mais lenta)."
        ),
        CloseLoop => ("Close the loop: unity feedback around Kp·G(s)", "Fechar a malha: realimentação unitária em torno de Kp·G(s)"),
        CloseLoopHelp => (
            "Shows the closed loop Kp·G/(1 + Kp·G): its step response over the open loop's and its poles (■) on the s-plane. Drag a ■ along its branch of the root locus to change Kp.",
            "Mostra a malha fechada Kp·G/(1 + Kp·G): sua resposta ao degrau sobre a de malha aberta e seus polos (■) no plano s. Arraste um ■ ao longo do seu ramo do lugar das raízes para mudar Kp."
        ),
        KpSlider => ("Kp (logarithmic)", "Kp (escala logarítmica)"),
        ShowLocus => ("Root locus", "Lugar das raízes"),
        Complementary => ("complementary (K < 0)", "complementar (K < 0)"),
        ComplementaryHelp => (
            "Also draws the locus for negative gains, dashed.",
            "Desenha também o lugar para ganhos negativos, tracejado."
        ),
        SpecsHeading => ("Specs", "Especificações"),
        SpecsHelp => (
            "Each spec shades on the s-plane where the closed-loop poles must not be (by the second-order formulas); Find K judges them on the exact closed-loop response.",
            "Cada especificação sombreia no plano s onde os polos de malha fechada não devem estar (pelas fórmulas de segunda ordem); Encontrar K as julga na resposta exata em malha fechada."
        ),
        FindGain => ("Find K", "Encontrar K"),
        FindGainHelp => (
            "The smallest gain meeting every checked spec (or, when every small gain meets them, the largest), judged on the exact closed-loop step response; Mp, t_s, t_r and e_ss count, t_p and ωn only shade.",
            "O menor ganho que atende a todas as especificações marcadas (ou, quando todo ganho pequeno as atende, o maior), julgado na resposta exata ao degrau em malha fechada; contam Mp, t_s, t_r e e_ss, t_p e ωn só sombreiam."
        ),
        NoGainFound => (
            "No gain K > 0 meets every spec on the exact closed-loop response.",
            "Nenhum ganho K > 0 atende a todas as especificações na resposta exata em malha fechada."
        ),
        NoSpecs => (
            "Check a spec among Mp, t_s, t_r or e_ss first.",
            "Marque antes uma especificação entre Mp, t_s, t_r ou e_ss."
        ),
        ResponseTo => ("Also plot the response to", "Traçar também a resposta a"),
        InputStep => ("nothing more (step only)", "nada mais (só o degrau)"),
        InputImpulse => ("an impulse", "um impulso"),
        InputRamp => ("a ramp", "uma rampa"),
        InputParabola => ("a parabola", "uma parábola"),
        InputCurve => ("response", "resposta"),
        InputItself => ("input", "entrada"),
        ClosedLoopCurve => ("closed loop y(t)", "malha fechada y(t)"),
        ClosedLoopCurveApproximate => (
            "closed loop y(t), Padé approximate",
            "malha fechada y(t), aproximada por Padé"
        ),
        FormulasHeading => ("Second-order formulas vs the exact response", "Fórmulas de segunda ordem vs a resposta exata"),
        FormulasHelp => (
            "The formulas of the dominant pair (the closed loop's when it is closed) beside the exact metrics of the whole system: a third pole or a zero shows as a large difference.",
            "As fórmulas do par dominante (o da malha fechada quando fechada) ao lado das medidas exatas do sistema inteiro: um terceiro polo ou um zero aparece como uma diferença grande."
        ),
        Metric => ("metric", "medida"),
        Formula => ("formula", "fórmula"),
        Exact => ("exact", "exata"),
        Difference => ("difference", "diferença"),
        NoDominantPair => (
            "No dominant underdamped pair of poles: the formulas do not apply.",
            "Sem par dominante de polos subamortecidos: as fórmulas não se aplicam."
        ),
        InverseHeading => ("From two specs to ζ, ωn and G(s):", "De duas especificações a ζ, ωn e G(s):"),
        PairLabel => ("given", "dados"),
        PairMpTs => ("Mp and t_s", "Mp e t_s"),
        PairMpTp => ("Mp and t_p", "Mp e t_p"),
        PairTsTp => ("t_s and t_p", "t_s e t_p"),
        PlaceIt => ("Place on the s-plane", "Colocar no plano s"),
        ClosedLoopPole => ("closed-loop pole", "polo de malha fechada"),
        LocusGain => ("on the root locus", "no lugar das raízes"),
        LocusApproximate => (
            "Root locus of the loop with the dead time replaced by its Padé approximant: approximate.",
            "Lugar das raízes da malha com o tempo morto substituído pela sua aproximação de Padé: aproximado."
        ),
        LocusHeadingApproximate => (
            "Root locus of the Padé-approximated loop, approximate (K, closed-loop poles):",
            "Lugar das raízes da malha aproximada por Padé, aproximado (K, polos de malha fechada):"
        ),
        PadeOrderLabel => ("Padé order (m, n) of the dead time", "Ordem (m, n) de Padé do tempo morto"),
        PadeOrderHelp => (
            "m zeros and n poles standing in for e^(−θs) in the loop. (3, 3) follows the delay's phase within about 1° up to ωθ = π; a higher order adds branches to the root locus.",
            "m zeros e n polos no lugar de e^(−θs) na malha. (3, 3) segue a fase do atraso a menos de cerca de 1° até ωθ = π; uma ordem maior acrescenta ramos ao lugar das raízes."
        ),
    }
}

/// Every phrase and an example of every fact of this module.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = Loop::messages();
    all.push(Message::of(
        "InverseError::Overshoot",
        &InverseError::Overshoot(120.0),
    ));
    all.push(Message::of("InverseError::Time", &InverseError::Time(-1.0)));
    all.push(Message::of(
        "LoopError::BadSpec",
        &LoopError::BadSpec("mp=3".into()),
    ));
    all.push(Message::of("LoopError::NoGain", &LoopError::NoGain));
    all.push(Message::of(
        "LoopError::BadPade",
        &LoopError::BadPade("4,2".into()),
    ));
    for name in SpecName::ALL {
        all.push(Message::of(format!("SpecName::{name:?}"), &name));
    }
    for input in [Input::Step, Input::Impulse, Input::Ramp, Input::Parabola] {
        all.push(Message::of(
            format!("InputHeading::{input:?}"),
            &InputHeading(input),
        ));
    }
    let n = |x: &str| x.to_string();
    for (id, line) in [
        ("OpenLoop", LoopLine::OpenLoop(n("1 / s"))),
        ("Gain", LoopLine::Gain(n("2"))),
        ("Range", LoopLine::Range(n("0"), n("2.86"))),
        (
            "Constants",
            LoopLine::Constants {
                system_type: 1,
                kp: n("∞"),
                kv: n("0.5"),
                ka: n("0"),
            },
        ),
        ("Errors", LoopLine::Errors(n("0"), n("2"), n("∞"))),
        ("Critical", LoopLine::Critical(n("53.3"), n("6.45"))),
        ("Breakaway", LoopLine::Breakaway(true, n("-1"), n("1"))),
        ("BreakIn", LoopLine::Breakaway(false, n("-5.4"), n("9.9"))),
        ("Asymptotes", LoopLine::Asymptotes(n("1.5"), n("90°, 270°"))),
        ("Found", LoopLine::Found(n("2.86"), n("0"), n("2.86"))),
        (
            "Approximant",
            LoopLine::Approximant {
                m: 3,
                n: 3,
                delay: n("2"),
            },
        ),
    ] {
        all.push(Message::of(format!("LoopLine::{id}"), &line));
    }
    all
}
