//! What in the record shows each test cause: its evidence, with its numbers.

use super::*;

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
                within_quanta,
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
                        ) + &within_quanta.map_or_else(String::new, |k| {
                            let k = n4(lang, k);
                            lang.pick(
                                format!(
                                    " Read with each sample anywhere within its quantum (the \
                                     interval-censored fit), Kp = {k}."
                                ),
                                format!(
                                    " Lida cada amostra como estando em qualquer ponto do seu \
                                     quantum (o ajuste censurado por intervalo), Kp = {k}."
                                ),
                            )
                        })
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
