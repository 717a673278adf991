//! What Degrau did about each test cause, what the student should do, and the lines and verdict that name them.

use super::*;

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
