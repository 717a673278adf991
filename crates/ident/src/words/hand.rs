//! The words of the hand methods (`crate::hand`): each method's name, the
//! construction's labels, the comparison table's headings, the warnings and the refusals, in
//! English and in Brazilian Portuguese with the notes' terms (reta tangente, constante de
//! tempo, tempo morto, ganho estático, fator de amortecimento).

use crate::fit::FitReport;
use crate::hand::{HandError, HandEstimate, HandMethod, HandWarning};
use crate::model::Param;

use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// Labels of the hand methods' construction and table.
    pub enum HandPhrase {
        Heading => ("Hand methods", "Métodos gráficos"),
        Method => ("Method", "Método"),
        Model => ("Model", "Modelo"),
        FitPercent => ("fit %", "ajuste %"),
        LeastSquares => ("least squares", "mínimos quadrados"),
        Failed => ("cannot be read:", "não se lê:"),
        InitialLevel => ("initial level y0", "nível inicial y0"),
        FinalLevel => ("final level y∞", "nível final y∞"),
        TangentLine => ("tangent", "reta tangente"),
        TangentPoint => ("tangent's point", "ponto da tangente"),
        PointsUsed => ("points used", "pontos usados"),
        HandModel => ("hand model", "modelo gráfico"),
        ResetConstruction => ("Reset the construction", "Refazer a construção"),
        ResetHelp => (
            "Back to the steepest rise and the measured levels.",
            "Volta à máxima inclinação e aos níveis medidos."
        ),
        DragHelp => (
            "Drag the tangent's point along the curve, or the level lines up and down.",
            "Arraste o ponto da tangente ao longo da curva, ou as linhas de nível para cima e para baixo."
        ),
        DeadTimeFromDeparture => (
            "θ from the first departure (else from the tangent)",
            "θ da primeira saída do nível (senão da tangente)"
        ),
        Cost => (
            "The fit % of each hand model beside the least-squares fit of the same structure: what reading by hand costs.",
            "O ajuste % de cada modelo gráfico ao lado do ajuste por mínimos quadrados da mesma estrutura: o que custa ler à mão."
        ),
        Window => ("samples per local line", "amostras por reta local"),
        Noise => ("noise σ", "ruído σ"),
        NoLeastSquares => ("not fitted", "não ajustado"),
    }
}

/// The method's name.
pub fn method_name(method: HandMethod, lang: Lang) -> &'static str {
    let (en, pt) = match method {
        HandMethod::Tangent => ("Tangent (reaction curve)", "Reta tangente"),
        HandMethod::SixtyThree => ("63.2 % time", "Constante de tempo (63,2 %)"),
        HandMethod::Broida => (
            "Broida's two points (28 %, 40 %)",
            "Dois pontos de Broida (28 %, 40 %)",
        ),
        HandMethod::Smith => (
            "Smith's two points (28.3 %, 63.2 %)",
            "Dois pontos de Smith (28,3 %, 63,2 %)",
        ),
        HandMethod::Points => ("Set of points", "Conjunto de pontos"),
        HandMethod::ThreePoint => ("Three points (Mollenkamp)", "Três pontos (Mollenkamp)"),
    };
    lang.pick(en, pt)
}

/// The method in words, for the list of the test of every message.
#[cfg(test)]
struct MethodName(HandMethod);

#[cfg(test)]
impl Localize for MethodName {
    fn text(&self, lang: Lang) -> String {
        method_name(self.0, lang).to_string()
    }
}

impl Localize for HandWarning {
    fn text(&self, lang: Lang) -> String {
        match *self {
            HandWarning::DampingOutsideRange { zeta } => lang.pick(
                format!(
                    "ζ = {} is outside 0.707 to 3, where the notes vouch for the three-point method",
                    lang.num(zeta, 3)
                ),
                format!(
                    "ξ = {} está fora de 0,707 a 3, onde as notas garantem o método dos três pontos",
                    lang.num(zeta, 3)
                ),
            ),
            HandWarning::NegativeDeadTime { theta } => lang.pick(
                format!(
                    "the construction puts the start of the response {} s before the step; the model uses θ = 0",
                    lang.num(-theta, 3)
                ),
                format!(
                    "a construção põe o início da resposta {} s antes do degrau; o modelo usa θ = 0",
                    lang.num(-theta, 3)
                ),
            ),
        }
    }
}

impl Localize for HandError {
    fn text(&self, lang: Lang) -> String {
        match self {
            HandError::NoStep(du) => lang.pick(
                format!("the step Δu = {} is not a step", lang.num(*du, 4)),
                format!("o degrau Δu = {} não é um degrau", lang.num(*du, 4)),
            ),
            HandError::SeveralChanges { count } => lang.pick(
                format!(
                    "the input changes {count} times; a hand method reads one step (use --single-step or a window around one change)"
                ),
                format!(
                    "a entrada muda {count} vezes; um método gráfico lê um só degrau (use --single-step ou uma janela em torno de uma mudança)"
                ),
            ),
            HandError::NoOperatingPoint => lang.pick(
                "no sample before the step gives the initial level: give it (--y0)".into(),
                "nenhuma amostra antes do degrau dá o nível inicial: informe-o (--y0)".into(),
            ),
            HandError::TooFewSamples { n, needed } => lang.pick(
                format!("only {n} samples from the step on; a construction needs at least {needed}"),
                format!("só {n} amostras a partir do degrau; uma construção precisa de pelo menos {needed}"),
            ),
            HandError::NoRise { change, noise } => lang.pick(
                format!(
                    "the output does not rise: it moves by {} against a noise σ of {}",
                    lang.num(*change, 3),
                    lang.num(*noise, 3)
                ),
                format!(
                    "a saída não sobe: move-se {} diante de um ruído σ de {}",
                    lang.num(*change, 3),
                    lang.num(*noise, 3)
                ),
            ),
            HandError::NotSettled { percent } => {
                let p = lang.num(*percent, 3);
                lang.pick(
                    format!(
                        "the record ends before the output settles (its last fifth still moves by {p} % of the change): its final level is unknown; give one"
                    ),
                    format!(
                        "o registro termina antes de a saída estabilizar (seu último quinto ainda se move {p} % da variação): o nível final é desconhecido; informe um"
                    ),
                )
            }
            HandError::LevelNotReached { percent } => lang.pick(
                format!("the curve never reaches {} % of the change", lang.num(*percent, 3)),
                format!("a curva nunca atinge {} % da variação", lang.num(*percent, 3)),
            ),
            HandError::NoSteepestRise => lang.pick(
                "no stretch of the curve rises towards the final level: no tangent to draw".into(),
                "nenhum trecho da curva sobe em direção ao nível final: não há tangente a traçar".into(),
            ),
            HandError::NoTimeConstant { tau } if !tau.is_finite() => lang.pick(
                "the construction gives a τ beyond double precision's range (about 1.8e308 s), not a time constant: rescale the units of time".into(),
                "a construção dá um τ além da faixa da precisão dupla (cerca de 1,8e308 s), que não é uma constante de tempo: mude a escala das unidades de tempo".into(),
            ),
            HandError::NoTimeConstant { tau } => lang.pick(
                format!("the construction gives τ = {} s, not a time constant", lang.num(*tau, 4)),
                format!("a construção dá τ = {} s, que não é uma constante de tempo", lang.num(*tau, 4)),
            ),
            HandError::ThreePointShape { x } if !x.is_finite() => lang.pick(
                "the three points (15 %, 45 %, 75 %) are read at one instant: the curve jumps there, and has no shape for the three-point method to read".into(),
                "os três pontos (15 %, 45 %, 75 %) são lidos num mesmo instante: a curva salta ali, e não tem forma para o método dos três pontos ler".into(),
            ),
            HandError::ThreePointShape { x } => lang.pick(
                format!(
                    "the three points give x = (t45 − t15)/(t75 − t15) = {}, no positive damping: the curve is first-order-like (x ≤ 0.356), use a first-order method",
                    lang.num(*x, 4)
                ),
                format!(
                    "os três pontos dão x = (t45 − t15)/(t75 − t15) = {}, sem amortecimento positivo: a curva é de primeira ordem (x ≤ 0,356), use um método de primeira ordem",
                    lang.num(*x, 4)
                ),
            ),
            HandError::BadOverride(v) => lang.pick(
                format!("{} is not a level or a time", lang.num(*v, 4)),
                format!("{} não é um nível nem um tempo", lang.num(*v, 4)),
            ),
            HandError::TangentOutside { t, start, end } => {
                let (t, start, end) = (lang.num(*t, 6), lang.num(*start, 6), lang.num(*end, 6));
                lang.pick(
                    format!(
                        "the tangent's point t = {t} s is outside the response, which runs from the step at {start} s to the record's end at {end} s"
                    ),
                    format!(
                        "o ponto da tangente t = {t} s está fora da resposta, que vai do degrau em {start} s ao fim do registro em {end} s"
                    ),
                )
            }
            HandError::Model(e) => e.text(lang),
        }
    }
}

/// The table's header: method, model, K, θ, τ, the second-order figures, fit %.
pub fn table_header(lang: Lang) -> [String; 7] {
    [
        HandPhrase::Method.get(lang).to_string(),
        HandPhrase::Model.get(lang).to_string(),
        "K".into(),
        "θ (s)".into(),
        "τ (s)".into(),
        lang.pick("τ1, τ2 (s) or ζ, ωn", "τ1, τ2 (s) ou ξ, ωn")
            .into(),
        HandPhrase::FitPercent.get(lang).to_string(),
    ]
}

/// A method's row of the table (numbers to four significant digits).
pub fn estimate_row(e: &HandEstimate, lang: Lang) -> [String; 7] {
    let n = |x: f64| lang.num(x, 4);
    let second = match e.second_order {
        Some(s) => match (s.tau1, s.tau2) {
            (Some(a), Some(b)) => format!("{}{} {}", n(a), lang.pick(",", ";"), n(b)),
            _ => format!(
                "{} = {}{} ωn = {} rad/s",
                lang.pick("ζ", "ξ"),
                n(s.zeta),
                lang.pick(",", ";"),
                n(s.omega_n)
            ),
        },
        None => String::new(),
    };
    [
        method_name(e.method, lang).to_string(),
        e.model.structure.code(),
        n(e.k),
        n(e.theta),
        e.tau.map(n).unwrap_or_default(),
        second,
        super::lsq::percent(e.fit_percent, lang),
    ]
}

/// A least-squares fit's row of the table.
pub fn least_squares_row(r: &FitReport, lang: Lang) -> [String; 7] {
    let n = |x: f64| lang.num(x, 4);
    let m = &r.model;
    let two = m.structure.poles == 2 && !m.structure.underdamped;
    [
        HandPhrase::LeastSquares.get(lang).to_string(),
        m.structure.code(),
        n(m.get(Param::Kp)),
        n(m.get(Param::Td)),
        if two {
            String::new()
        } else {
            n(m.get(Param::Tp1))
        },
        if two {
            format!(
                "{}{} {}",
                n(m.get(Param::Tp1)),
                lang.pick(",", ";"),
                n(m.get(Param::Tp2))
            )
        } else {
            String::new()
        },
        super::lsq::percent(r.fit_percent, lang),
    ]
}

/// Rows as aligned text lines.
fn aligned(rows: &[[String; 7]]) -> Vec<String> {
    let width = |c: usize| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0);
    let widths: Vec<usize> = (0..7).map(width).collect();
    rows.iter()
        .map(|r| {
            let cells: Vec<String> = r
                .iter()
                .zip(&widths)
                .enumerate()
                .map(|(c, (cell, &w))| {
                    let pad = w - cell.chars().count();
                    if c < 2 {
                        format!("{cell}{}", " ".repeat(pad))
                    } else {
                        format!("{}{cell}", " ".repeat(pad))
                    }
                })
                .collect();
            format!("  {}", cells.join("  ").trim_end())
        })
        .collect()
}

/// The table of every method beside the least-squares fits, as `degrau hand` prints it.
pub fn table_lines(
    rows: &[(HandMethod, Result<HandEstimate, HandError>)],
    fits: &[FitReport],
    lang: Lang,
) -> Vec<String> {
    let mut table = vec![table_header(lang)];
    let mut refused = Vec::new();
    for (m, r) in rows {
        match r {
            Ok(e) => table.push(estimate_row(e, lang)),
            Err(err) => refused.push(format!(
                "  {} {} {}",
                method_name(*m, lang),
                HandPhrase::Failed.get(lang),
                err.text(lang)
            )),
        }
    }
    table.extend(fits.iter().map(|r| least_squares_row(r, lang)));
    let mut lines = vec![format!("{}:", HandPhrase::Heading.get(lang))];
    lines.extend(aligned(&table));
    lines.extend(refused);
    for (m, r) in rows {
        if let Ok(e) = r {
            lines.extend(
                e.warnings
                    .iter()
                    .map(|w| format!("  {}: {}", method_name(*m, lang), w.text(lang))),
            );
        }
    }
    lines.push(HandPhrase::Cost.get(lang).to_string());
    lines
}

/// One method's result and construction, as `degrau hand --method` prints it.
pub fn estimate_lines(e: &HandEstimate, lang: Lang) -> Vec<String> {
    let n = |x: f64| lang.num(x, 5);
    let c = &e.construction;
    let mut lines = vec![format!("{}:", method_name(e.method, lang))];
    lines.extend(aligned(&[table_header(lang), estimate_row(e, lang)]));
    lines.push(format!(
        "  {} = {}, {} = {}, t0 = {} s",
        HandPhrase::InitialLevel.get(lang),
        n(c.y0),
        HandPhrase::FinalLevel.get(lang),
        n(c.y_final),
        n(c.t0)
    ));
    if let Some(t) = c.tangent {
        lines.push(lang.pick(
            format!(
                "  tangent through ({} s, {}), slope {} /s: meets y0 at {} s and y∞ at {} s",
                n(t.t),
                n(t.y),
                n(t.slope),
                n(t.t_initial),
                n(t.t_final)
            ),
            format!(
                "  reta tangente por ({} s; {}), inclinação {} /s: cruza y0 em {} s e y∞ em {} s",
                n(t.t),
                n(t.y),
                n(t.slope),
                n(t.t_initial),
                n(t.t_final)
            ),
        ));
    }
    for l in &c.levels {
        lines.push(lang.pick(
            format!(
                "  {} % ({}) reached at {} s",
                lang.num(l.percent, 4),
                n(l.y),
                n(l.t)
            ),
            format!(
                "  {} % ({}) atingido em {} s",
                lang.num(l.percent, 4),
                n(l.y),
                n(l.t)
            ),
        ));
    }
    if !c.points.is_empty() {
        lines.push(format!(
            "  {}: {}",
            HandPhrase::PointsUsed.get(lang),
            c.points.len()
        ));
    }
    lines.push(format!(
        "  {} {}, {} {}",
        HandPhrase::Window.get(lang),
        c.window,
        HandPhrase::Noise.get(lang),
        lang.num(c.noise, 3)
    ));
    lines.extend(e.warnings.iter().map(|w| format!("  {}", w.text(lang))));
    lines
}

/// Every phrase, method name, warning and error, for the test of both languages.
#[cfg(test)]
pub fn messages() -> Vec<degrau_words::Message> {
    let mut all = HandPhrase::messages();
    for m in HandMethod::ALL {
        all.push(degrau_words::Message::of(
            format!("hand::method::{m:?}"),
            &MethodName(m),
        ));
    }
    for w in [
        HandWarning::DampingOutsideRange { zeta: 0.5 },
        HandWarning::NegativeDeadTime { theta: -0.3 },
    ] {
        all.push(degrau_words::Message::of(
            format!("hand::HandWarning::{w:?}"),
            &w,
        ));
    }
    let errors = [
        HandError::NoStep(0.0),
        HandError::SeveralChanges { count: 3 },
        HandError::NoOperatingPoint,
        HandError::TooFewSamples { n: 3, needed: 8 },
        HandError::NoRise {
            change: 0.01,
            noise: 0.1,
        },
        HandError::NotSettled { percent: 12.0 },
        HandError::LevelNotReached { percent: 75.0 },
        HandError::NoSteepestRise,
        HandError::NoTimeConstant { tau: -1.0 },
        HandError::NoTimeConstant { tau: f64::INFINITY },
        HandError::TangentOutside {
            t: 1e9,
            start: 2.0,
            end: 30.5,
        },
        HandError::ThreePointShape { x: 0.3 },
        HandError::ThreePointShape { x: f64::NAN },
        HandError::BadOverride(f64::NAN),
        HandError::Model(crate::model::ModelError::Overflow),
    ];
    for e in errors {
        all.push(degrau_words::Message::of(
            format!("hand::HandError::{e:?}"),
            &e,
        ));
    }
    all
}
