//! What the *test* got wrong, in words: each cause's name ([`TestCauseKind`]), its evidence
//! with its numbers and interval ([`TestEvidence`]), what Degrau did about it
//! ([`Handling`]), and what the student should do ([`remedy`]), in English and in Brazilian
//! Portuguese with the notes' terms (ensaio ao degrau, regime permanente, ponto de
//! operação, período de amostragem, ruído, distúrbio, não linearidade). Written once for
//! `degrau diagnose` and the app's "What the test got wrong" panel; the verdict line that
//! names the structure and the artefacts together is here too.

use crate::diagnose::{Cause, DiagnoseReport};
use crate::rest::Motion;
use crate::test_causes::{
    DisturbanceShape, Handling, Loss, RuleCheck, SamplingRule, Signal, StepGain, StepShape,
    TestCause, TestCauseKind, TestEvidence,
};

use super::ident::Naming;
use degrau_words::{Lang, Localize, Message};

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

fn motion_words(m: &Motion, lang: Lang) -> String {
    let (span, n, change, threshold) = (
        span_words(m.span, lang),
        m.samples,
        n4(lang, m.change),
        n4(lang, m.threshold),
    );
    lang.pick(
        format!(
            "Before the first input change ({span}, {n} samples) the output moved by {change} \
             (a line through those samples), more than the {threshold} the noise allows: the \
             process was not at equilibrium when the step came."
        ),
        format!(
            "Antes da primeira variação da entrada ({span}, {n} amostras) a saída variou \
             {change} (reta ajustada a essas amostras), mais que os {threshold} que o ruído \
             permite: o processo não estava em equilíbrio quando veio o degrau."
        ),
    )
}

/// The closed-loop evidence: the statistic, then why the gain is biased.
fn closed_loop_words(
    moves: f64,
    f: f64,
    dof: (usize, usize),
    explained: f64,
    lang: Lang,
) -> String {
    let (m, f, e) = (
        n4(lang, 100.0 * moves),
        n4(lang, f),
        n4(lang, 100.0 * explained),
    );
    let (d1, d2) = dof;
    lang.pick(
        format!(
            "The input moves at {m} % of the samples, and the fit's residuals (what the model \
             leaves of the output: its noise) at the same sample and the three before predict \
             those moves beyond what the input's own past does (F = {f} with {d1} and {d2} \
             degrees of freedom, p < 0.001; they explain {e} % of what the input's past leaves): \
             a controller set the input from the output's errors. The input is then correlated \
             with the noise through the feedback, and least squares pulls the gain towards \
             −1/(the controller's gain): the fitted Kp is biased and its interval does not \
             hold."
        ),
        format!(
            "A entrada muda em {m} % das amostras, e os resíduos do ajuste (o que o modelo \
             deixa da saída: o seu ruído) na mesma amostra e nas três anteriores preveem essas \
             mudanças além do que o passado da própria entrada prevê (F = {f} com {d1} e {d2} \
             graus de liberdade, p < 0,001; explicam {e} % do que o passado da entrada deixa): \
             um controlador definiu a entrada a partir dos erros da saída. A entrada \
             fica então correlacionada com o ruído pela realimentação, e os mínimos quadrados \
             puxam o ganho para −1/(o ganho do controlador): o Kp ajustado é viesado e seu \
             intervalo não vale."
        ),
    )
}

fn gain_words(g: &StepGain, lang: Lang) -> String {
    let ci = g.ci95.map_or(String::new(), |(a, b)| {
        format!(" [{}{} {}]", n4(lang, a), lang.pick(",", ";"), n4(lang, b))
    });
    let (from, to) = (n4(lang, g.u_before), n4(lang, g.u_before + g.du));
    format!(
        "Kp = {}{ci} ({from} → {to}, t = {} s)",
        n4(lang, g.kp),
        n4(lang, g.t)
    )
}

/// A sampling rule with the record's ratio: `h/τmax = 0.3 (h < 0.1·τmax, Kalman and
/// Bertram)`.
fn rule_words(c: &RuleCheck, lang: Lang) -> String {
    let v = n4(lang, c.value);
    let and = lang.pick("and", "e");
    match c.rule {
        SamplingRule::TenthOfSlowest => format!(
            "h/τmax = {v} (h < {}·τmax, Kalman {and} Bertram)",
            lang.pick("0.1", "0,1")
        ),
        SamplingRule::DeadTimeRatio => {
            format!("h/θ = {v} ({} < h/θ < 1)", lang.pick("0.2", "0,2"))
        }
        SamplingRule::TimeConstantRatio => format!(
            "h/τ = {v} ({} < h/τ < {}, Åström {and} Wittenmark)",
            lang.pick("0.01", "0,01"),
            lang.pick("0.05", "0,05")
        ),
        SamplingRule::SettlingRatio => format!("h/t_s = {v} (t_s/15 < h < t_s/6, Isermann)"),
    }
}

fn shape_words(shape: &StepShape, lang: Lang) -> String {
    match shape {
        StepShape::Ramp { duration } => {
            let d = n4(lang, *duration);
            lang.pick(
                format!("The input took {d} s to go from its old level to the new one: a ramp"),
                format!("A entrada levou {d} s para ir do nível antigo ao novo: uma rampa"),
            )
        }
        StepShape::Overshoot { fraction } => {
            let f = n4(lang, 100.0 * fraction);
            lang.pick(
                format!("The input went past its new level by {f} % of the change before settling"),
                format!("A entrada passou do novo nível em {f} % da variação antes de se acomodar"),
            )
        }
        StepShape::Wobble { amplitude } => {
            let a = n4(lang, *amplitude);
            lang.pick(
                format!("The input kept moving about its new level by ± {a}"),
                format!("A entrada continuou oscilando em torno do novo nível, ± {a}"),
            )
        }
    }
}

fn mistaken_words(shape: &StepShape, cause: Cause, lang: Lang) -> String {
    let what = match (cause, shape) {
        (Cause::DeadTime, StepShape::Ramp { duration }) => {
            let half = n4(lang, duration / 2.0);
            lang.pick(
                format!("a dead time of about {half} s (half the ramp)"),
                format!("um tempo morto de cerca de {half} s (metade da rampa)"),
            )
        }
        (Cause::ExtraPole, _) => lang
            .pick(
                "an extra pole (a lag)",
                "um polo a mais (um atraso de primeira ordem)",
            )
            .into(),
        (Cause::Zero, _) => lang.pick("a zero", "um zero").into(),
        (Cause::Oscillation, _) => lang.pick("an oscillation", "uma oscilação").into(),
        (other, _) => format!("{} ({})", other.id(), other.text(lang)),
    };
    lang.pick(
        format!("; an ideal-step model would have taken it for {what}."),
        format!("; um modelo de degrau ideal a teria tomado por {what}."),
    )
}

impl Localize for TestEvidence {
    fn text(&self, lang: Lang) -> String {
        match self {
            TestEvidence::NotAtRest { motion } => motion_words(motion, lang),
            TestEvidence::Disturbance { at, size, shape, z } => {
                let (at, size, z) = (n4(lang, *at), n4(lang, *size), n4(lang, *z));
                match shape {
                    DisturbanceShape::Step => lang.pick(
                        format!(
                            "At t = {at} s, where the input did not change, the residuals step \
                             by {size} (z = {z}): something else moved the output."
                        ),
                        format!(
                            "Em t = {at} s, sem variação da entrada, os resíduos dão um degrau \
                             de {size} (z = {z}): outra coisa moveu a saída."
                        ),
                    ),
                    DisturbanceShape::Ramp => lang.pick(
                        format!(
                            "From t = {at} s, where the input did not change, the residuals \
                             ramp by {size} (z = {z}): something else moved the output."
                        ),
                        format!(
                            "A partir de t = {at} s, sem variação da entrada, os resíduos \
                             variam em rampa {size} (z = {z}): outra coisa moveu a saída."
                        ),
                    ),
                }
            }
            TestEvidence::Nonlinearity { steps } => {
                let list: Vec<String> = steps.iter().map(|g| gain_words(g, lang)).collect();
                let list = list.join("; ");
                lang.pick(
                    format!("Each change's own gain differs beyond their intervals: {list}."),
                    format!("O ganho de cada variação difere além dos intervalos: {list}."),
                )
            }
            TestEvidence::Saturation {
                signal,
                level,
                samples,
                spans,
            } => {
                let spans: Vec<String> = spans.iter().map(|s| span_words(*s, lang)).collect();
                let (level, spans) = (n4(lang, *level), spans.join(", "));
                let (en_s, pt_s) = match signal {
                    Signal::Output => ("output", "saída"),
                    Signal::Input => ("input", "entrada"),
                };
                lang.pick(
                    format!(
                        "The {en_s} sits flat at {level} for {samples} samples ({spans}) while \
                         the model keeps moving: it was held at a limit."
                    ),
                    format!(
                        "A {pt_s} fica parada em {level} por {samples} amostras ({spans}) \
                         enquanto o modelo continua a se mover: ficou presa num limite."
                    ),
                )
            }
            TestEvidence::Outliers {
                count,
                times,
                scale,
                sigmas,
                threshold,
                worst,
            } => {
                let shown: Vec<String> = times.iter().take(8).map(|t| n4(lang, *t)).collect();
                let more = if times.len() > 8 { " …" } else { "" };
                let (list, scale_w, thr, worst) = (
                    shown.join(lang.pick(", ", "; ")),
                    n4(lang, *scale),
                    n4(lang, *threshold),
                    n4(lang, *worst),
                );
                // The threshold is `sigmas` robust σ (growing with the record's length), or
                // two output quanta when the noise's scale is below the resolution (a
                // quantised record's MAD is 0).
                let by_quanta = *threshold > sigmas * scale * (1.0 + 1e-9);
                let why = if by_quanta {
                    lang.pick(
                        format!(
                            "two output quanta: the noise's robust scale, {scale_w}, is \
                             below the resolution"
                        ),
                        format!(
                            "dois quanta da saída: a escala robusta do ruído, {scale_w}, \
                             está abaixo da resolução"
                        ),
                    )
                } else {
                    let k = n4(lang, *sigmas);
                    lang.pick(
                        format!(
                            "{k} × the noise's robust scale {scale_w}, each sample against \
                             its neighbours; the multiple grows with the record's length"
                        ),
                        format!(
                            "{k} × a escala robusta do ruído, {scale_w}, cada amostra contra \
                             suas vizinhas; o múltiplo cresce com o comprimento do registro"
                        ),
                    )
                };
                let (en, pt) = if *count == 1 {
                    ("1 sample lies".to_string(), "1 amostra está".to_string())
                } else {
                    (
                        format!("{count} samples lie"),
                        format!("{count} amostras estão"),
                    )
                };
                lang.pick(
                    format!(
                        "{en} more than {thr} off the neighbours' local trend ({why}), the worst by {worst}: \
                         t = {list}{more} s."
                    ),
                    format!(
                        "{pt} a mais de {thr} da tendência local das vizinhas ({why}), a pior a {worst}: t = \
                         {list}{more} s."
                    ),
                )
            }
            TestEvidence::ColouredNoise { lag1, widening } => {
                let (r, w) = (n4(lang, *lag1), n4(lang, *widening));
                lang.pick(
                    format!(
                        "The residuals are correlated (lag-one autocorrelation {r}) although no \
                         structural extension pays: the noise is coloured, not the model \
                         wrong. The intervals are widened × {w}."
                    ),
                    format!(
                        "Os resíduos são correlacionados (autocorrelação de atraso um {r}) \
                         embora nenhuma extensão da estrutura se pague: o ruído é colorido, \
                         não o modelo errado. Os intervalos foram alargados × {w}."
                    ),
                )
            }
            TestEvidence::Quantisation {
                resolution,
                share,
                noise,
                kp_floor,
            } => {
                let (q, s, sigma) = (
                    n4(lang, *resolution),
                    n4(lang, 100.0 * share),
                    n4(lang, *noise),
                );
                let head = lang.pick(
                    format!(
                        "The output moves in steps of {q}, {s} % of the step's effect, against \
                         noise of standard deviation {sigma}."
                    ),
                    format!(
                        "A saída anda em degraus de {q}, {s} % do efeito do degrau, diante de \
                         um ruído de desvio padrão {sigma}."
                    ),
                );
                let tail = match kp_floor {
                    Some(f) => {
                        let f = n4(lang, *f);
                        lang.pick(
                            format!(
                                " The noise is under half a step, so the rounding does not \
                                 average out: Kp is known no better than ± {f}, whatever its \
                                 interval says."
                            ),
                            format!(
                                " O ruído é menor que meio degrau, e o arredondamento não se \
                                 cancela na média: Kp não é conhecido melhor que ± {f}, diga o \
                                 que disser seu intervalo."
                            ),
                        )
                    }
                    None => {
                        let r = n4(lang, resolution / 12f64.sqrt());
                        lang.pick(
                            format!(
                                " The noise dithers the steps: the rounding (standard deviation \
                                 q/√12 = {r}) is part of the residuals the intervals come from."
                            ),
                            format!(
                                " O ruído espalha os degraus: o arredondamento (desvio padrão \
                                 q/√12 = {r}) faz parte dos resíduos de que vêm os intervalos."
                            ),
                        )
                    }
                };
                head + &tail
            }
            TestEvidence::Sampling {
                ts,
                too_slow,
                broken,
                per_sample,
                noise,
                ..
            } => {
                let h = n4(lang, *ts);
                let rules: Vec<String> = broken.iter().map(|c| rule_words(c, lang)).collect();
                let rules = rules.join("; ");
                if *too_slow {
                    lang.pick(
                        format!(
                            "Sampled every {h} s, too slowly for the notes' rules: {rules}. \
                             Fast dynamics alias and a dead time shorter than a sample is lost."
                        ),
                        format!(
                            "Amostrado a cada {h} s, devagar demais para as regras das notas: \
                             {rules}. Dinâmicas rápidas se confundem (aliasing) e um tempo \
                             morto menor que uma amostra se perde."
                        ),
                    )
                } else {
                    let (m, sigma) = (n4(lang, *per_sample), n4(lang, *noise));
                    lang.pick(
                        format!(
                            "Sampled every {h} s, faster than the notes' rules ask: {rules}. \
                             The model moves at most {m} between two samples, less than the \
                             noise's standard deviation {sigma}: the noise dominates."
                        ),
                        format!(
                            "Amostrado a cada {h} s, mais rápido do que pedem as regras das \
                             notas: {rules}. O modelo anda no máximo {m} entre duas amostras, \
                             menos que o desvio padrão do ruído, {sigma}: o ruído domina."
                        ),
                    )
                }
            }
            TestEvidence::SmallStep {
                effect,
                noise,
                ratio,
            } => {
                let (e, s, r) = (n4(lang, *effect), n4(lang, *noise), n4(lang, *ratio));
                lang.pick(
                    format!(
                        "The step's effect |Kp·Δu| = {e} is only {r} times the noise's standard \
                         deviation {s}; the notes ask for more than 6."
                    ),
                    format!(
                        "O efeito do degrau |Kp·Δu| = {e} é só {r} vezes o desvio padrão do \
                         ruído, {s}; as notas pedem mais que 6."
                    ),
                )
            }
            TestEvidence::ImperfectStep {
                shape,
                mistaken_for,
            } => {
                let head = shape_words(shape, lang);
                match mistaken_for {
                    Some(c) => head + &mistaken_words(shape, *c, lang),
                    None => head + ".",
                }
            }
            TestEvidence::ClosedLoop {
                moves,
                f,
                dof,
                explained,
            } => closed_loop_words(*moves, *f, *dof, *explained, lang),
        }
    }
}

impl Localize for Handling {
    /// What Degrau did about a cause.
    fn text(&self, lang: Lang) -> String {
        match self {
            Handling::InitialTransient => lang
                .pick(
                    "Degrau estimated an initial transient (the free response of the model's \
                     poles) and Y0 with it, instead of inventing structure.",
                    "O Degrau estimou um transitório inicial (a resposta livre dos polos do \
                     modelo) e Y0 junto, em vez de inventar estrutura.",
                )
                .into(),
            Handling::DisturbanceModelled { at } => {
                let at = n4(lang, *at);
                lang.pick(
                    format!("Degrau modelled a disturbance from t = {at} s (it is not a drift)."),
                    format!("O Degrau modelou um distúrbio a partir de t = {at} s (não é deriva)."),
                )
            }
            Handling::Excluded { start, end } => {
                let span = span_words((*start, *end), lang);
                lang.pick(
                    format!("Degrau left the samples at {span} out of the fit."),
                    format!("O Degrau deixou as amostras em {span} fora do ajuste."),
                )
            }
            Handling::RobustLoss { loss } => {
                let name = loss.name();
                lang.pick(
                    format!("Degrau fitted with a robust loss ({name}) instead of least squares."),
                    format!(
                        "O Degrau ajustou com uma perda robusta ({name}) em vez de mínimos \
                         quadrados."
                    ),
                )
            }
            Handling::IntervalsWidened { factor } => {
                let f = n4(lang, *factor);
                lang.pick(
                    format!("Degrau kept the model and widened its 95 % intervals × {f}."),
                    format!("O Degrau manteve o modelo e alargou seus intervalos de 95 % × {f}."),
                )
            }
            Handling::PerStepTable => lang
                .pick(
                    "Degrau shows each change's own fit in the per-step table.",
                    "O Degrau mostra o ajuste de cada variação na tabela por degrau.",
                )
                .into(),
            Handling::MeasuredInput => lang
                .pick(
                    "The fit already uses the measured input, so the model is not misled.",
                    "O ajuste já usa a entrada medida, e o modelo não se engana.",
                )
                .into(),
            Handling::Reported => lang
                .pick(
                    "Reported only: the fit is unchanged.",
                    "Apenas relatado: o ajuste não muda.",
                )
                .into(),
        }
    }
}

/// The sampling period the broken rules allow, on the side they were broken: the largest
/// h all of them allow when too slow, the smallest when too fast (s); none when too fast and
/// that h breaks a rule's upper bound (`ceiling`: the rules disagree for this model, so no
/// period meets them all; "every 23.71 s or more" for a time constant of 11.4 s).
fn advised_period(
    ts: f64,
    too_slow: bool,
    broken: &[RuleCheck],
    ceiling: Option<f64>,
) -> Option<f64> {
    let limits = broken.iter().filter_map(|c| {
        let bound = if too_slow { c.high } else { c.low }?;
        (c.value > 0.0).then(|| ts * bound / c.value)
    });
    if too_slow {
        limits.reduce(f64::min)
    } else {
        limits
            .reduce(f64::max)
            .filter(|h| ceiling.is_none_or(|c| *h <= c))
    }
}

/// What the student should do about a cause.
pub fn remedy(cause: &TestCause, lang: Lang) -> String {
    let fixed = |en: &str, pt: &str| lang.pick(en, pt).to_string();
    match (&cause.kind, &cause.evidence) {
        (
            _,
            TestEvidence::Sampling {
                ts,
                too_slow,
                broken,
                ceiling,
                ..
            },
        ) => {
            let h = advised_period(*ts, *too_slow, broken, *ceiling).map(|h| n4(lang, h));
            match (too_slow, h) {
                (true, Some(h)) => lang.pick(
                    format!("Sample faster: every {h} s or less."),
                    format!("Amostre mais rápido: a cada {h} s ou menos."),
                ),
                (true, None) => fixed("Sample faster.", "Amostre mais rápido."),
                (false, h) => {
                    let h = h.map_or(String::new(), |h| {
                        lang.pick(
                            format!(" (every {h} s or more)"),
                            format!(" (a cada {h} s ou mais)"),
                        )
                    });
                    lang.pick(
                        format!(
                            "Sample more slowly{h}, or low-pass filter the output before \
                             fitting (the notes' filter)."
                        ),
                        format!(
                            "Amostre mais devagar{h}, ou aplique um filtro passa-baixa à saída \
                             antes do ajuste (o filtro das notas)."
                        ),
                    )
                }
            }
        }
        (TestCauseKind::NotAtRest, _) => fixed(
            "Wait for steady state before the step: the method assumes the process at \
             equilibrium before the input changes.",
            "Espere o regime permanente antes do degrau: o método admite o processo em \
             equilíbrio antes da variação da entrada.",
        ),
        (TestCauseKind::Disturbance, _) => fixed(
            "Repeat the test without the disturbance, or exclude its window.",
            "Repita o ensaio sem o distúrbio, ou exclua a sua janela.",
        ),
        (TestCauseKind::Nonlinearity, _) => fixed(
            "Use a smaller step around one operating point, and repeat it up and down.",
            "Use um degrau menor em torno de um ponto de operação, e repita-o subindo e \
             descendo.",
        ),
        (TestCauseKind::Saturation, _) => fixed(
            "Use a smaller step, or one away from the limit.",
            "Use um degrau menor, ou longe do limite.",
        ),
        (TestCauseKind::Outliers, _) => fixed(
            "Check the samples listed (a loose contact, a logging error); the robust fit keeps \
             them from pulling the model.",
            "Verifique as amostras listadas (mau contato, erro de registro); o ajuste robusto \
             impede que puxem o modelo.",
        ),
        (TestCauseKind::ColouredNoise, _) => fixed(
            "Keep the model: it is adequate; read its parameters with the widened intervals.",
            "Mantenha o modelo: ele é adequado; leia seus parâmetros com os intervalos \
             alargados.",
        ),
        (TestCauseKind::Quantisation, _) => fixed(
            "Use a finer sensor or converter, or a larger step.",
            "Use um sensor ou conversor mais fino, ou um degrau maior.",
        ),
        (TestCauseKind::SmallStep, _) => fixed(
            "Use a larger step: its effect should be over six times the noise.",
            "Use um degrau maior: seu efeito deve passar de seis vezes o ruído.",
        ),
        (TestCauseKind::ImperfectStep, _) => fixed(
            "Nothing to repeat: the measured input is used. Log the input beside the output \
             whenever you can.",
            "Nada a repetir: a entrada medida é usada. Registre a entrada junto com a saída \
             sempre que puder.",
        ),
        (TestCauseKind::Sampling, _) => fixed(
            "Check the sampling period.",
            "Verifique o período de amostragem.",
        ),
        (TestCauseKind::ClosedLoop, _) => fixed(
            "Open the loop (the controller in manual) and step the input, or keep the loop and \
             add an external test signal (a setpoint step, or a dither added to the controller's \
             output) and identify from that signal, not from the controller's output alone.",
            "Abra a malha (o controlador em manual) e aplique o degrau na entrada, ou mantenha a \
             malha e acrescente um sinal de teste externo (um degrau na referência, ou um sinal \
             de excitação somado à saída do controlador) e identifique a partir desse sinal, não \
             só da saída do controlador.",
        ),
    }
}

/// A cause as the CLI and the app show it: `id: name`, the evidence (with its interval),
/// what Degrau did, what to do.
pub fn cause_lines(c: &TestCause, naming: Naming, lang: Lang) -> [String; 4] {
    let interval = c
        .interval
        .map_or(String::new(), |s| format!(" [{}]", span_words(s, lang)));
    [
        match naming {
            Naming::Id => format!("{}: {}", c.kind.id(), c.kind.text(lang)),
            // The kind's own words are already its heading.
            Naming::Words => c.kind.text(lang),
        },
        format!("{}{interval}", c.evidence.text(lang)),
        format!(
            "{}: {}",
            TestCausePhrase::Done.get(lang),
            c.handling.text(lang)
        ),
        format!("{}: {}", TestCausePhrase::Remedy.get(lang), remedy(c, lang)),
    ]
}

/// The "What the test got wrong" section of `degrau diagnose`: its heading, then each
/// cause's lines, or that nothing was found.
pub fn section(causes: &[TestCause], lang: Lang) -> Vec<String> {
    let mut lines = vec![format!("{}:", TestCausePhrase::Heading.get(lang))];
    if causes.is_empty() {
        lines.push(format!("   {}", TestCausePhrase::NothingFound.get(lang)));
    }
    for (k, c) in causes.iter().enumerate() {
        let [name, evidence, done, remedy] = cause_lines(c, Naming::Id, lang);
        lines.push(format!("{}. {name}", k + 1));
        for l in [evidence, done, remedy] {
            lines.push(format!("   {l}"));
        }
    }
    lines
}

/// The verdict's two halves on one line: the structure and the artefacts of the test
/// (`Structure: P1D + initial transient. Test: not_at_rest, quantisation.`).
pub fn verdict_line(d: &DiagnoseReport, lang: Lang) -> String {
    let structure = d.final_fit.model.structure.text(lang);
    let artefacts = if d.test_causes.is_empty() {
        TestCausePhrase::NoArtefacts.get(lang).to_string()
    } else {
        let ids: Vec<&str> = d.test_causes.iter().map(|c| c.kind.id()).collect();
        ids.join(", ")
    };
    lang.pick(
        format!("Verdict: structure {structure}; test: {artefacts}."),
        format!("Veredito: estrutura {structure}; ensaio: {artefacts}."),
    )
}

/// An example of every cause, for the test of every message.
pub fn examples() -> Vec<TestCause> {
    let motion = Motion {
        change: 5.2,
        span: (0.0, 248.0),
        samples: 250,
        threshold: 0.6,
    };
    let gain = |t, u_before, du, kp| StepGain {
        t,
        u_before,
        du,
        kp,
        ci95: Some((kp - 0.02, kp + 0.02)),
    };
    let check = |rule, value, low, high| RuleCheck {
        rule,
        value,
        low,
        high,
    };
    let cause = |kind, evidence, handling| TestCause {
        kind,
        evidence,
        interval: Some((10.0, 20.0)),
        handling,
    };
    use TestCauseKind as K;
    vec![
        cause(
            K::NotAtRest,
            TestEvidence::NotAtRest { motion },
            Handling::InitialTransient,
        ),
        cause(
            K::Disturbance,
            TestEvidence::Disturbance {
                at: 300.0,
                size: 1.5,
                shape: DisturbanceShape::Step,
                z: 12.0,
            },
            Handling::DisturbanceModelled { at: 300.0 },
        ),
        cause(
            K::Disturbance,
            TestEvidence::Disturbance {
                at: 300.0,
                size: 1.5,
                shape: DisturbanceShape::Ramp,
                z: 9.0,
            },
            Handling::Excluded {
                start: 300.0,
                end: 400.0,
            },
        ),
        cause(
            K::Nonlinearity,
            TestEvidence::Nonlinearity {
                steps: vec![gain(30.0, 30.0, 10.0, 1.2), gain(150.0, 40.0, -10.0, 0.9)],
            },
            Handling::PerStepTable,
        ),
        cause(
            K::Saturation,
            TestEvidence::Saturation {
                signal: Signal::Output,
                level: 100.0,
                samples: 40,
                spans: vec![(60.0, 100.0)],
            },
            Handling::Excluded {
                start: 60.0,
                end: 100.0,
            },
        ),
        cause(
            K::Saturation,
            TestEvidence::Saturation {
                signal: Signal::Input,
                level: 0.0,
                samples: 12,
                spans: vec![(5.0, 17.0)],
            },
            Handling::Reported,
        ),
        cause(
            K::Outliers,
            TestEvidence::Outliers {
                count: 9,
                times: (0..9).map(|k| 30.0 + 80.0 * k as f64).collect(),
                scale: 0.1,
                sigmas: 5.0,
                threshold: 0.5,
                worst: 14.6,
            },
            Handling::RobustLoss { loss: Loss::Huber },
        ),
        cause(
            K::Outliers,
            TestEvidence::Outliers {
                count: 2,
                times: vec![30.0, 640.0],
                scale: 0.1,
                sigmas: 5.0,
                threshold: 0.5,
                worst: 14.6,
            },
            Handling::RobustLoss { loss: Loss::Cauchy },
        ),
        cause(
            K::ColouredNoise,
            TestEvidence::ColouredNoise {
                lag1: 0.8,
                widening: 3.0,
            },
            Handling::IntervalsWidened { factor: 3.0 },
        ),
        cause(
            K::Quantisation,
            TestEvidence::Quantisation {
                resolution: 0.322,
                share: 0.0094,
                noise: 0.08,
                kp_floor: Some(0.0064),
            },
            Handling::Reported,
        ),
        cause(
            K::Quantisation,
            TestEvidence::Quantisation {
                resolution: 1.0,
                share: 0.083,
                noise: 0.6,
                kp_floor: None,
            },
            Handling::Reported,
        ),
        cause(
            K::Sampling,
            TestEvidence::Sampling {
                ts: 6.0,
                too_slow: true,
                broken: vec![
                    check(SamplingRule::TenthOfSlowest, 0.3, None, Some(0.1)),
                    check(SamplingRule::DeadTimeRatio, 3.0, Some(0.2), Some(1.0)),
                    check(SamplingRule::TimeConstantRatio, 0.3, Some(0.01), Some(0.05)),
                    check(
                        SamplingRule::SettlingRatio,
                        0.5,
                        Some(1.0 / 15.0),
                        Some(1.0 / 6.0),
                    ),
                ],
                per_sample: 3.0,
                noise: 0.1,
                ceiling: None,
            },
            Handling::Reported,
        ),
        cause(
            K::Sampling,
            TestEvidence::Sampling {
                ts: 0.05,
                too_slow: false,
                broken: vec![check(
                    SamplingRule::TimeConstantRatio,
                    0.0025,
                    Some(0.01),
                    Some(0.05),
                )],
                per_sample: 0.03,
                noise: 0.24,
                ceiling: Some(1.0),
            },
            Handling::Reported,
        ),
        cause(
            K::SmallStep,
            TestEvidence::SmallStep {
                effect: 1.0,
                noise: 0.25,
                ratio: 4.0,
            },
            Handling::Reported,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Ramp { duration: 3.0 },
                mistaken_for: Some(Cause::DeadTime),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Ramp { duration: 12.0 },
                mistaken_for: Some(Cause::ExtraPole),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Overshoot { fraction: 0.35 },
                mistaken_for: Some(Cause::Zero),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Wobble { amplitude: 2.0 },
                mistaken_for: Some(Cause::Oscillation),
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ImperfectStep,
            TestEvidence::ImperfectStep {
                shape: StepShape::Wobble { amplitude: 2.0 },
                mistaken_for: None,
            },
            Handling::MeasuredInput,
        ),
        cause(
            K::ClosedLoop,
            TestEvidence::ClosedLoop {
                moves: 0.98,
                f: 85.3,
                dof: (4, 1991),
                explained: 0.146,
            },
            Handling::Reported,
        ),
    ]
}

/// Every phrase, cause name, evidence, handling and remedy, in both languages.
pub fn messages() -> Vec<Message> {
    let mut all = TestCausePhrase::messages();
    all.extend(
        TestCauseKind::ALL
            .iter()
            .map(|k| Message::of(format!("test_causes::TestCauseKind::{}", k.id()), k)),
    );
    for (i, c) in examples().iter().enumerate() {
        let id = |what: &str| format!("test_causes::{what}::{}#{i}", c.kind.id());
        all.push(Message::of(id("TestEvidence"), &c.evidence));
        all.push(Message::of(id("Handling"), &c.handling));
        all.push(Message {
            id: id("Remedy"),
            en: remedy(c, Lang::En),
            pt: remedy(c, Lang::Pt),
        });
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sampled too fast for Isermann's rule (h ≥ t_s/15) on a model whose slowest lag asks
    /// for h ≤ τ/10: the rules disagree, and no period is advised that breaks the other
    /// (issue 23, item 13: "every 23.71 s or more" for an 11.4 s time constant).
    #[test]
    fn no_period_is_advised_beyond_another_rules_bound() {
        let settling = RuleCheck {
            rule: SamplingRule::SettlingRatio,
            value: 0.5 / 355.0,
            low: Some(1.0 / 15.0),
            high: Some(1.0 / 6.0),
        };
        let evidence = |ceiling| TestEvidence::Sampling {
            ts: 0.5,
            too_slow: false,
            broken: vec![settling],
            per_sample: 0.01,
            noise: 0.1,
            ceiling,
        };
        let cause = |ceiling| TestCause {
            kind: TestCauseKind::Sampling,
            evidence: evidence(ceiling),
            interval: None,
            handling: Handling::Reported,
        };
        let conflicting = remedy(&cause(Some(1.14)), Lang::En);
        assert!(!conflicting.contains("or more"), "{conflicting}");
        assert!(conflicting.starts_with("Sample more slowly, or low-pass filter"));
        let agreeing = remedy(&cause(Some(60.0)), Lang::En);
        assert!(agreeing.contains("(every 23.67 s or more)"), "{agreeing}");
    }

    #[test]
    fn every_kind_and_handling_has_an_example() {
        let all = examples();
        for k in TestCauseKind::ALL {
            assert!(all.iter().any(|c| c.kind == k), "{k:?} has no example");
        }
        let handlings = [
            "initial_transient",
            "disturbance_modelled",
            "excluded",
            "robust_loss",
            "intervals_widened",
            "per_step_table",
            "measured_input",
            "reported",
        ];
        for h in handlings {
            assert!(
                all.iter()
                    .any(|c| serde_json::to_value(c.handling).unwrap()["kind"] == h),
                "{h} has no example"
            );
        }
    }

    #[test]
    fn one_outlier_on_a_quantised_record_is_said_without_an_infinite_ratio() {
        // A quantised record's MAD is 0: the threshold is two quanta, not k × 0.
        let e = TestEvidence::Outliers {
            count: 1,
            times: vec![93.82],
            scale: 0.0,
            sigmas: 5.0,
            threshold: 0.64,
            worst: -15.68,
        };
        let en = e.text(Lang::En);
        assert!(en.starts_with("1 sample lies more than 0.64"), "{en}");
        assert!(en.contains("two output quanta"), "{en}");
        assert!(!en.contains("inf"), "{en}");
        let pt = e.text(Lang::Pt);
        assert!(pt.starts_with("1 amostra está a mais de 0,64"), "{pt}");
        let many = TestEvidence::Outliers {
            count: 3,
            times: vec![1.0, 2.0, 3.0],
            scale: 0.1,
            sigmas: 5.0,
            threshold: 0.5,
            worst: 2.0,
        };
        let en = many.text(Lang::En);
        assert!(en.starts_with("3 samples lie more than 0.5"), "{en}");
        assert!(en.contains("5 × the noise's robust scale 0.1"), "{en}");
    }

    #[test]
    fn the_words_carry_the_numbers() {
        let all = examples();
        let q = all
            .iter()
            .find(|c| c.kind == TestCauseKind::Quantisation)
            .unwrap();
        let en = q.evidence.text(Lang::En);
        assert!(en.contains("steps of 0.322, 0.94 %"), "{en}");
        assert!(en.contains("± 0.0064"), "{en}");
        let pt = q.evidence.text(Lang::Pt);
        assert!(pt.contains("degraus de 0,322, 0,94 %"), "{pt}");
        let slow = all
            .iter()
            .find(|c| c.kind == TestCauseKind::Sampling)
            .unwrap();
        // h = 6 s with h/τmax = 0.3 against 0.1: τmax = 20 s, so every 2 s or less (the
        // strictest of the four rules: Åström and Wittenmark's 0.05 → 1 s).
        assert_eq!(remedy(slow, Lang::En), "Sample faster: every 1 s or less.");
        let rest = &all[0];
        let [name, evidence, done, remedy] = cause_lines(rest, Naming::Id, Lang::En);
        assert!(name.starts_with("not_at_rest: Not at rest"), "{name}");
        assert!(evidence.contains("moved by 5.2") && evidence.ends_with("[t = 10 … 20 s]"));
        assert!(done.contains("initial transient") && remedy.contains("steady state"));
    }

    #[test]
    fn closed_loop_says_its_statistic_why_and_what_to_do() {
        let all = examples();
        let c = all
            .iter()
            .find(|c| c.kind == TestCauseKind::ClosedLoop)
            .unwrap();
        let [name, evidence, _, remedy] = cause_lines(c, Naming::Id, Lang::En);
        assert!(name.starts_with("closed_loop: Closed loop"), "{name}");
        assert!(evidence.contains("98 % of the samples"), "{evidence}");
        assert!(evidence.contains("F = 85.3 with 4 and 1991"), "{evidence}");
        assert!(
            evidence.contains("−1/(the controller's gain)"),
            "{evidence}"
        );
        assert!(remedy.contains("Open the loop") && remedy.contains("dither"));
        let [name, evidence, _, remedy] = cause_lines(c, Naming::Id, Lang::Pt);
        assert!(name.starts_with("closed_loop: Malha fechada"), "{name}");
        assert!(evidence.contains("F = 85,3 com 4 e 1991"), "{evidence}");
        assert!(evidence.contains("viesado"), "{evidence}");
        assert!(remedy.contains("Abra a malha"), "{remedy}");
    }
}
