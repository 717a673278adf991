//! The errors of loading, preparing, the experiment, the model codes and the fit.

use super::*;

/// Why a file could not be read, in `lang`: the common kinds in words, any other in the
/// system's own (`reason`).
fn io_reason(kind: std::io::ErrorKind, reason: &str, lang: Lang) -> String {
    use std::io::ErrorKind;
    let words = match kind {
        ErrorKind::NotFound => ("there is no such file", "esse arquivo não existe"),
        ErrorKind::PermissionDenied => (
            "permission to read it was denied",
            "não há permissão para lê-lo",
        ),
        ErrorKind::IsADirectory => ("it is a folder, not a file", "é uma pasta, não um arquivo"),
        _ => return reason.to_string(),
    };
    lang.pick(words.0, words.1).to_string()
}

impl Localize for DataError {
    fn text(&self, lang: Lang) -> String {
        match self {
            DataError::Io { path, kind, reason } => {
                let reason = io_reason(*kind, reason, lang);
                lang.pick(
                    format!("could not read {path}: {reason}"),
                    format!("não foi possível ler {path}: {reason}"),
                )
            }
            DataError::Binary { line } => lang.pick(
                format!(
                    "line {line} contains a zero byte: this is a binary file (a .mat or a \
                     spreadsheet?), not text; export it as CSV or text"
                ),
                format!(
                    "a linha {line} contém um byte zero: este é um arquivo binário (um .mat ou \
                     uma planilha?), não texto; exporte-o como CSV ou texto"
                ),
            ),
            DataError::Empty => lang
                .pick("the file is empty", "o arquivo está vazio")
                .into(),
            DataError::NoData { lines } => lang.pick(
                format!(
                    "the file has no data: its {lines} line(s) are blank, comments or skipped rows"
                ),
                format!(
                    "o arquivo não tem dados: suas {lines} linha(s) estão em branco, são \
                     comentários ou linhas puladas"
                ),
            ),
            DataError::TooFewSamples {
                line,
                found,
                needed,
            } => lang.pick(
                format!(
                    "line {line}: the file ends after {found} sample(s) (rows with a time and an \
                     output); at least {needed} samples are needed"
                ),
                format!(
                    "linha {line}: o arquivo termina após {found} amostra(s) (linhas com tempo e \
                     saída); são necessárias pelo menos {needed} amostras"
                ),
            ),
            DataError::NotANumber { line, column, text } => {
                let c = column_label(column);
                lang.pick(
                    format!("line {line}, column {c}: \"{text}\" is not a number"),
                    format!("linha {line}, coluna {c}: \"{text}\" não é um número"),
                )
            }
            DataError::TimeMissing { line, column } => {
                let c = column_label(column);
                lang.pick(
                    format!(
                        "line {line}, column {c}: the time is missing (empty or NaN); every row \
                         needs a time"
                    ),
                    format!(
                        "linha {line}, coluna {c}: falta o tempo (vazio ou NaN); toda linha \
                         precisa de um tempo"
                    ),
                )
            }
            DataError::TimeNotIncreasing {
                line,
                time,
                previous,
                first_column_assumed,
            } => {
                let (t, p) = (full(lang, *time), full(lang, *previous));
                let hint = match (first_column_assumed, lang) {
                    (false, _) => "",
                    (true, Lang::En) => {
                        " (column 1 was taken as the time because the file has no header; if it \
                         has no time column, give the sampling period)"
                    }
                    (true, Lang::Pt) => {
                        " (a coluna 1 foi tomada como tempo porque o arquivo não tem cabeçalho; \
                         se ele não tem coluna de tempo, dê o período de amostragem)"
                    }
                };
                lang.pick(
                    format!(
                        "line {line}: time {t} comes after {p}; the time must not decrease{hint}"
                    ),
                    format!(
                        "linha {line}: o tempo {t} vem depois de {p}; o tempo não pode \
                         diminuir{hint}"
                    ),
                )
            }
            DataError::Ragged {
                line,
                found,
                expected,
                reference,
            } => lang.pick(
                format!("line {line} has {found} value(s), but line {reference} has {expected}"),
                format!(
                    "a linha {line} tem {found} valor(es), mas a linha {reference} tem {expected}"
                ),
            ),
            DataError::UnknownColumn {
                line,
                role,
                name,
                available: a,
            } => {
                let (r, a) = (role.text(lang), available(a, lang));
                lang.pick(
                    format!(
                        "line {line}: there is no column named \"{name}\" for {r}; the columns are \
                         {a}"
                    ),
                    format!(
                        "linha {line}: não há coluna chamada \"{name}\" para {r}; as colunas são {a}"
                    ),
                )
            }
            DataError::NoSuchPosition {
                line,
                role,
                position,
                available: a,
            } => {
                let (r, a) = (role.text(lang), available(a, lang));
                lang.pick(
                    format!(
                        "line {line}: column {position} was chosen for {r}, but the columns are {a}"
                    ),
                    format!(
                        "linha {line}: a coluna {position} foi escolhida para {r}, mas as colunas \
                         são {a}"
                    ),
                )
            }
            DataError::NoTime { line, available: a } => {
                let a = available(a, lang);
                lang.pick(
                    format!(
                        "line {line}: no column is named like a time (t, time, tempo, …) and no \
                         sampling period was given; choose the time column or give the sampling \
                         period (the columns are {a})"
                    ),
                    format!(
                        "linha {line}: nenhuma coluna tem nome de tempo (t, time, tempo, …) e não \
                         foi dado o período de amostragem; escolha a coluna de tempo ou dê o \
                         período de amostragem (as colunas são {a})"
                    ),
                )
            }
            DataError::SameColumn {
                line,
                first,
                second,
                column,
            } => {
                let (f, s, c) = (first.text(lang), second.text(lang), column_label(column));
                lang.pick(
                    format!("line {line}: {f} and {s} are the same column, {c}"),
                    format!("linha {line}: {f} e {s} são a mesma coluna, {c}"),
                )
            }
            DataError::AmbiguousOutput { line, candidates } => {
                let c = columns_text(candidates, lang, |c| column_listing(c, lang));
                lang.pick(
                    format!(
                        "line {line}: several columns could be the output ({c}); choose one by \
                         name or position"
                    ),
                    format!(
                        "linha {line}: várias colunas poderiam ser a saída ({c}); escolha uma pelo \
                         nome ou pela posição"
                    ),
                )
            }
            DataError::NoOutput { line, available: a } => {
                let a = available(a, lang);
                lang.pick(
                    format!("line {line}: no column is left for the output (the columns are {a})"),
                    format!("linha {line}: não sobra coluna para a saída (as colunas são {a})"),
                )
            }
            DataError::BadSamplingPeriod(ts) => bad_sampling_period(*ts, lang),
            DataError::PasteColumns { line, found } => lang.pick(
                format!("line {line} has {found} column(s); a paste needs 2 (t, y) or 3 (t, u, y)"),
                format!(
                    "a linha {line} tem {found} coluna(s); uma colagem precisa de 2 (t, y) ou 3 \
                     (t, u, y)"
                ),
            ),
            DataError::NotAFile { kind, .. } => {
                let k = kind.text(lang);
                lang.pick(
                    format!(
                        "this is {k}, not a regular file: give the file that holds the data (a \
                         pipe or a device is not read, it could wait or run for ever)"
                    ),
                    format!(
                        "isto é {k}, não um arquivo comum: dê o arquivo que contém os dados (um \
                         pipe ou um dispositivo não é lido, poderia esperar ou correr para sempre)"
                    ),
                )
            }
            DataError::TooLarge { what, size } => {
                let w = what.text(lang);
                lang.pick(
                    format!(
                        "{w} has {size} bytes or more, over the limit of {MAX_FILE_BYTES} (1 GiB): \
                         a step test is far smaller; keep the rows you need (or every n-th) and \
                         load that"
                    ),
                    format!(
                        "{w} tem {size} bytes ou mais, acima do limite de {MAX_FILE_BYTES} \
                         (1 GiB): um ensaio ao degrau é bem menor; mantenha as linhas de que \
                         precisa (ou uma a cada n) e carregue isso"
                    ),
                )
            }
            DataError::InputAfterOutput {
                input_start,
                output_end,
            } => {
                let (a, b) = (full(lang, *input_start), full(lang, *output_end));
                lang.pick(
                    format!(
                        "the input's file starts at t = {a} s, after the output's last sample \
                         (t = {b} s): the two files share no time"
                    ),
                    format!(
                        "o arquivo da entrada começa em t = {a} s, depois da última amostra da \
                         saída (t = {b} s): os dois arquivos não têm tempo em comum"
                    ),
                )
            }
            DataError::TimeOverflow {
                sampling_period,
                rows,
            } => {
                let ts = full(lang, *sampling_period);
                lang.pick(
                    format!(
                        "a sampling period of {ts} s over {rows} rows gives times beyond the \
                         largest number; give the period in seconds"
                    ),
                    format!(
                        "um período de amostragem de {ts} s em {rows} linhas dá tempos além do \
                         maior número; dê o período em segundos"
                    ),
                )
            }
        }
    }
}

fn bad_sampling_period(ts: f64, lang: Lang) -> String {
    let ts = full(lang, ts);
    lang.pick(
        format!("the sampling period must be a positive number of seconds, not {ts}"),
        format!("o período de amostragem deve ser um número positivo de segundos, não {ts}"),
    )
}

impl Localize for PrepareError {
    fn text(&self, lang: Lang) -> String {
        match *self {
            PrepareError::BadRange { first, last, count } => lang.pick(
                format!(
                    "samples {first} to {last} are not a range within 1 to {count} (counted from \
                     1, both included)"
                ),
                format!(
                    "as amostras {first} a {last} não são um intervalo dentro de 1 a {count} \
                     (contadas a partir de 1, ambas incluídas)"
                ),
            ),
            PrepareError::TooFewInWindow { kept, needed } => lang.pick(
                format!("the window keeps {kept} sample(s); at least {needed} are needed"),
                format!("a janela mantém {kept} amostra(s); são necessárias pelo menos {needed}"),
            ),
            PrepareError::BadTimeRange { start, end } => {
                let (a, b) = (full(lang, start), full(lang, end));
                lang.pick(
                    format!("the window from {a} s to {b} s is not a time range"),
                    format!("a janela de {a} s a {b} s não é um intervalo de tempo"),
                )
            }
            PrepareError::BadCutoff(fc) => {
                let fc = full(lang, fc);
                lang.pick(
                    format!("the filter cut-off must be a positive frequency in Hz, not {fc}"),
                    format!(
                        "a frequência de corte do filtro deve ser uma frequência positiva em Hz, \
                         não {fc}"
                    ),
                )
            }
            PrepareError::BadSamplingPeriod(ts) => bad_sampling_period(ts, lang),
        }
    }
}

/// What is missing when no step is found, said where the student gives it: the CLI's
/// flags, the app's fields, or in general words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Where {
    /// No place named (the library's own words).
    Anywhere,
    /// `degrau fit` and `degrau diagnose`: `--initial-input`, `--t0`, `--du`.
    Cli,
    /// The app's Identify panel: its fields of those names.
    App,
}

/// An [`ExperimentError`] with the place to give what is missing.
pub fn experiment_error(e: &ExperimentError, lang: Lang, place: Where) -> String {
    match e {
        ExperimentError::NoStep => {
            let head = lang.pick(
                "the step could not be found: the file has no input column, or the input never \
                 changes",
                "o degrau não foi encontrado: o arquivo não tem coluna de entrada, ou a entrada \
                 nunca muda",
            );
            let tail = match (place, lang) {
                (Where::Anywhere, Lang::En) => {
                    "when the step came at the first sample, give the input before the record; \
                     else give the step time t0 and its size Δu"
                }
                (Where::Anywhere, Lang::Pt) => {
                    "se o degrau veio na primeira amostra, dê a entrada de antes do registro; \
                     senão, dê o instante do degrau t0 e sua amplitude Δu"
                }
                (Where::Cli, Lang::En) => {
                    "when the step came at the first sample, give the input before the record \
                     with --initial-input; else give the step time and size with --t0 and --du"
                }
                (Where::Cli, Lang::Pt) => {
                    "se o degrau veio na primeira amostra, dê a entrada de antes do registro com \
                     --initial-input; senão, dê o instante e a amplitude do degrau com --t0 e --du"
                }
                (Where::App, Lang::En) => {
                    "when the step came at the first sample, type the input before the record in \
                     the field \"Input before the record\"; else type the step time t0 and its \
                     size Δu"
                }
                (Where::App, Lang::Pt) => {
                    "se o degrau veio na primeira amostra, digite a entrada de antes do registro \
                     no campo \"Entrada antes do registro\"; senão, digite o instante do degrau \
                     t0 e sua amplitude Δu"
                }
            };
            format!("{head} ({tail})")
        }
        ExperimentError::BadStep(du) => {
            let du = full(lang, *du);
            lang.pick(
                format!("the step size Δu must be a finite number other than zero, not {du}"),
                format!(
                    "a amplitude do degrau Δu deve ser um número finito diferente de zero, não {du}"
                ),
            )
        }
        ExperimentError::Prepare(e) => e.text(lang),
        ExperimentError::Model(e) => e.text(lang),
        ExperimentError::Fit(e) => e.text(lang),
    }
}

impl Localize for ExperimentError {
    fn text(&self, lang: Lang) -> String {
        experiment_error(self, lang, Where::Anywhere)
    }
}

impl Localize for Requirement {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Requirement::Finite => ("it must be a finite number", "deve ser um número finito"),
            Requirement::Positive => ("it must be positive", "deve ser positivo"),
            Requirement::NotNegative => ("it must not be negative", "não pode ser negativo"),
            Requirement::NotZero => ("it must not be zero", "não pode ser zero"),
            Requirement::DelayNotNegative => (
                "a dead time cannot be negative",
                "um tempo morto não pode ser negativo",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for ModelError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ModelError::BadCode(code) => lang.pick(
                format!(
                    "\"{code}\" is not a model code: write P, the number of poles (1 to 3), then \
                     any of D (dead time), U (underdamped), Z (zero), I (integrator), e.g. P1D, \
                     P2DU, P2DUZ, P1DI"
                ),
                format!(
                    "\"{code}\" não é um código de modelo: escreva P, o número de polos (1 a 3), \
                     depois qualquer um de D (tempo morto), U (subamortecido), Z (zero), I \
                     (integrador), p. ex. P1D, P2DU, P2DUZ, P1DI"
                ),
            ),
            ModelError::UnderdampedNeedsTwoPoles(code) => lang.pick(
                format!("an underdamped pair (U) needs at least 2 poles: {code}"),
                format!("um par subamortecido (U) precisa de pelo menos 2 polos: {code}"),
            ),
            ModelError::BadValue {
                name,
                value,
                requirement,
            } if !value.is_finite() => {
                // Computed, not typed (a typed value is finite): Kp = Δy/Δu with Δu = 5e-324.
                let why = requirement.text(lang);
                lang.pick(
                    format!(
                        "{name} falls outside double precision's range (about 1.8e308) and is not allowed: {why}; rescale the units of u, y or time"
                    ),
                    format!(
                        "{name} sai da faixa da precisão dupla (cerca de 1,8e308) e não é permitido: {why}; mude a escala das unidades de u, y ou do tempo"
                    ),
                )
            }
            ModelError::BadValue {
                name,
                value,
                requirement,
            } => {
                let (v, why) = (full(lang, *value), requirement.text(lang));
                lang.pick(
                    format!("{name} = {v} is not allowed: {why}"),
                    format!("{name} = {v} não é permitido: {why}"),
                )
            }
            ModelError::Overflow => lang
                .pick(
                    "the model is not allowed: its response overflowed",
                    "o modelo não é permitido: sua resposta estourou o maior número",
                )
                .into(),
            ModelError::NotInModel(name) => lang.pick(
                format!("the model has no parameter {name}"),
                format!("o modelo não tem o parâmetro {name}"),
            ),
            ModelError::System(e) => lang.pick(
                format!("the model is not a valid system: {}", lti_words(e, lang)),
                format!("o modelo não é um sistema válido: {}", lti_words(e, lang)),
            ),
        }
    }
}

impl Localize for FitError {
    fn text(&self, lang: Lang) -> String {
        match self {
            FitError::TooFewSamples { n, p } => lang.pick(
                format!("{n} samples after the step are too few to estimate {p} parameters"),
                format!("{n} amostras depois do degrau são poucas para estimar {p} parâmetros"),
            ),
            FitError::BadStep(du) => {
                let du = full(lang, *du);
                lang.pick(
                    format!("the step size Δu is {du}: it must be a finite number other than zero"),
                    format!(
                        "a amplitude do degrau Δu é {du}: deve ser um número finito diferente de \
                         zero"
                    ),
                )
            }
            FitError::BadGuess(e) => lang.pick(
                format!("the initial guess is not a valid model: {}", e.text(lang)),
                format!(
                    "a estimativa inicial não é um modelo válido: {}",
                    e.text(lang)
                ),
            ),
            FitError::NonFiniteData => lang
                .pick(
                    "the data contain a value that is not a finite number",
                    "os dados contêm um valor que não é um número finito",
                )
                .into(),
            FitError::BadStepTime(t0) => {
                let t0 = full(lang, *t0);
                lang.pick(
                    format!("the step time t0 is {t0}: it must be a finite number"),
                    format!("o instante do degrau t0 é {t0}: deve ser um número finito"),
                )
            }
            FitError::NonFiniteCost => lang
                .pick(
                    "the model's error on the data is not a finite number at the initial guess: \
                     the guess is far from the data",
                    "o erro do modelo sobre os dados não é um número finito na estimativa \
                     inicial: a estimativa está longe dos dados",
                )
                .into(),
            FitError::Unrepresentable { param, log10 } => {
                let e = lang.localize_number(&format!("{log10:.1}"));
                lang.pick(
                    format!(
                        "the fitted {param} is about 1e{e} in the data's units, beyond double \
                         precision: give the data (or the step Δu) in other units"
                    ),
                    format!(
                        "o {param} ajustado é cerca de 1e{e} nas unidades dos dados, além da \
                         precisão dupla: dê os dados (ou o degrau Δu) em outras unidades"
                    ),
                )
            }
        }
    }
}
