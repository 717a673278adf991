//! The words of the command line: the step report's labels and headings, and every error
//! of `degrau step`, `fit`, `diagnose` and `open` ([`CliError`], a refused flag value), in
//! English and in Brazilian Portuguese. Flags keep their names (`--y0`, `--guess`) and the
//! values echoed in a flag keep their decimal point, as they are typed; numbers in the prose
//! take the language's separator. clap's own help and usage text stay English.

use crate::cli::CliError;
use crate::cli::fit::StartsError;
use crate::ident::fit::MAX_STARTS;
use crate::ident::record::data::{Columns, DataError};
use crate::lti::Behaviour;
use crate::lti::parse::ParseError;
use crate::lti::tf::Stability;

#[cfg(test)]
use super::Message;
use super::ident::{Where, experiment_error, lti_words};
use super::{Lang, Localize};

/// The zeros' label of the step report: the same word in both languages.
pub const ZEROS: &str = "Zeros";

crate::phrases! {
    /// The step report's row labels, and the word before a message.
    pub enum StepPhrase {
        System => ("System", "Sistema"),
        Poles => ("Poles", "Polos"),
        DcGain => ("DC gain", "Ganho estático"),
        Stability => ("Stability", "Estabilidade"),
        Step => ("Step", "Degrau"),
        NoRoots => ("none", "nenhum"),
        Error => ("error", "erro"),
    }
}

crate::phrases! {
    /// The step report's headings.
    pub enum Heading {
        ClosedForm => ("Step response (exact closed form):", "Resposta ao degrau (forma fechada exata):"),
        Samples => ("Samples:", "Amostras:"),
    }
}

/// The words of a [`ParseError`] (a list or a number typed in a flag): the one place that
/// says them on the command line, until the text layer's `lti` catalogue renders them in
/// either language (`Localize`), when this calls it.
pub fn parse_words(e: &ParseError, lang: Lang) -> String {
    e.text(lang)
}

/// "stable (every pole in the left half plane); the step response settles".
pub fn stability_line(s: Stability, b: Behaviour, lang: Lang) -> String {
    let (reason, behaviour) = (super::step::stability_reason(s, lang), b.text(lang));
    lang.pick(
        format!("{reason}; the step response {behaviour}"),
        format!("{reason}; a resposta ao degrau {behaviour}"),
    )
}

/// "amplitude 2 at t = 0".
pub fn step_line(amplitude: &str, lang: Lang) -> String {
    lang.pick(
        format!("amplitude {amplitude} at t = 0"),
        format!("amplitude {amplitude} em t = 0"),
    )
}

/// The metrics' heading with the thresholds (already written as percentages).
pub fn metrics_heading(low: &str, high: &str, band: &str, lang: Lang) -> String {
    lang.pick(
        format!("Step metrics (rise {low}–{high} %, settling band {band} %):"),
        format!(
            "Métricas da resposta ao degrau (subida de {low} a {high} %, faixa de acomodação de \
             {band} %):"
        ),
    )
}

/// The window could not be opened (`reason` in the windowing library's words).
pub fn no_window(reason: &str, lang: Lang) -> String {
    lang.pick(
        format!(
            "could not open the Degrau window: {reason}\nWithout a display, use the command \
             line: degrau step --help"
        ),
        format!(
            "não foi possível abrir a janela do Degrau: {reason}\nSem tela, use a linha de \
             comando: degrau step --help"
        ),
    )
}

/// A file with one column asked for its time: it has no time column, and the flag that
/// gives the sampling period is said. `None` for any other load error.
fn no_time_column(error: &DataError, lang: Lang) -> Option<String> {
    let single = match error {
        DataError::NoTime { available, .. } => columns_count(available) == 1,
        _ => false,
    };
    single.then(|| {
        lang.pick(
            "the file has one column, the output, and no time column: give its sampling \
             period with --ts (seconds, e.g. --ts 0.1)"
                .to_string(),
            "o arquivo tem uma coluna, a saída, e nenhuma coluna de tempo: dê o período de \
             amostragem com --ts (segundos, por exemplo --ts 0.1)"
                .to_string(),
        )
    })
}

/// How many columns a file has, as a message lists them.
fn columns_count(columns: &Columns) -> usize {
    match columns {
        Columns::Unnamed { count } => *count,
        Columns::Named(list) => list.shown.len() + list.more,
    }
}

impl Localize for StartsError {
    fn text(&self, lang: Lang) -> String {
        match self {
            StartsError::NotAWholeNumber(text) => lang.pick(
                format!("\"{text}\" is not a whole number of starts"),
                format!("\"{text}\" não é um número inteiro de pontos de partida"),
            ),
            StartsError::OutOfRange(n) => lang.pick(
                format!(
                    "{n} starts: give 1 (the guess only) to {MAX_STARTS}; each start is a whole \
                     fit"
                ),
                format!(
                    "{n} pontos de partida: dê de 1 (só a estimativa) a {MAX_STARTS}; cada ponto \
                     de partida é um ajuste inteiro"
                ),
            ),
        }
    }
}

/// A value echoed in a flag, as it would be typed (a decimal point).
fn typed(x: f64) -> String {
    crate::lti::number::sig(x, 6)
}

impl Localize for CliError {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match self {
            CliError::Parse { option, source } => format!("{option}: {}", parse_words(source, lang)),
            CliError::Lti(e) => lti_words(e, lang),
            CliError::Options(words) => words.clone(),
            CliError::RiseLimitsCount(k) => lang.pick(
                format!("the rise limits are two fractions like 0.1,0.9, not {k} numbers"),
                format!("os limites de subida são duas frações como 0.1,0.9, não {k} números"),
            ),
            CliError::EmptyCoefficients(option) => lang.pick(
                format!(
                    "{option} is empty: give the coefficients in descending powers of s, e.g. \
                     1,7,15,25"
                ),
                format!(
                    "{option} está vazio: dê os coeficientes em potências decrescentes de s, p. \
                     ex. 1,7,15,25"
                ),
            ),
            CliError::NoSystem => lang
                .pick(
                    "no system given: give the poles (and zeros, gain) or the num and den \
                     coefficients",
                    "nenhum sistema dado: dê os polos (e zeros, ganho) ou os coeficientes num e den",
                )
                .into(),
            CliError::TwoDescriptions => lang
                .pick(
                    "the system is given twice: give the poles and zeros, or num and den, not both",
                    "o sistema foi dado duas vezes: dê os polos e zeros, ou num e den, não os dois",
                )
                .into(),
            CliError::ZerosWithoutPoles => lang
                .pick(
                    "zeros were given without poles: give the poles too",
                    "foram dados zeros sem polos: dê também os polos",
                )
                .into(),
            CliError::NumWithoutDen => lang
                .pick(
                    "num was given without den: give both coefficient lists",
                    "num foi dado sem den: dê as duas listas de coeficientes",
                )
                .into(),
            CliError::DenWithoutNum => lang
                .pick(
                    "den was given without num: give both coefficient lists",
                    "den foi dado sem num: dê as duas listas de coeficientes",
                )
                .into(),
            CliError::GainWithCoefficients => lang
                .pick(
                    "gain is the k of the zero-pole-gain form and goes with poles; with num and \
                     den the gain is in the coefficients (use dc_gain to set the static gain)",
                    "gain é o k da forma zero-polo-ganho e vai com os polos; com num e den o \
                     ganho está nos coeficientes (use dc_gain para fixar o ganho estático)",
                )
                .into(),
            CliError::GainAndDcGain => lang
                .pick(
                    "give gain (the k of the zero-pole-gain form) or dc_gain (the static gain), \
                     not both",
                    "dê gain (o k da forma zero-polo-ganho) ou dc_gain (o ganho estático), não \
                     os dois",
                )
                .into(),
            CliError::Samples(k) => lang.pick(
                format!(
                    "samples must be between 2 and {}, not {k}",
                    crate::cli::MAX_SAMPLES
                ),
                format!(
                    "samples deve estar entre 2 e {}, não {k}",
                    crate::cli::MAX_SAMPLES
                ),
            ),
            CliError::ResponseBeyondRange => lang
                .pick(
                    "the response reaches beyond double precision's range (about 1.8e308) in its \
                     samples or metrics: rescale the gain, the amplitude or the units of time",
                    "a resposta passa da faixa da precisão dupla (cerca de 1,8e308) nas suas \
                     amostras ou métricas: mude a escala do ganho, da amplitude ou das unidades \
                     de tempo",
                )
                .into(),
            CliError::JsonSyntax(why) => lang.pick(
                format!("the line is not valid JSON: {why}"),
                format!("a linha não é JSON válido: {why}"),
            ),
            CliError::NotAnObject => lang
                .pick(
                    r#"the line is not a JSON object like {"num": [1], "den": [1, 1]}"#,
                    r#"a linha não é um objeto JSON como {"num": [1], "den": [1, 1]}"#,
                )
                .into(),
            CliError::JsonFields(why) => lang.pick(
                format!("the line does not describe a system: {why}"),
                format!("a linha não descreve um sistema: {why}"),
            ),
            CliError::NotUtf8 => lang
                .pick(
                    "the line is not valid UTF-8 text",
                    "a linha não é texto UTF-8 válido",
                )
                .into(),
            CliError::ReadInput(e) => lang.pick(
                format!("could not read the standard input: {e}"),
                format!("não foi possível ler a entrada padrão: {e}"),
            ),
            CliError::WriteOutput(e) => lang.pick(
                format!("could not write the output: {e}"),
                format!("não foi possível escrever a saída: {e}"),
            ),
            CliError::Data { path, error } => match no_time_column(error, lang) {
                Some(words) => format!("{path}: {words}"),
                None => format!("{path}: {}", error.text(lang)),
            },
            CliError::Experiment(e) => experiment_error(e, lang, Where::Cli),
            CliError::Diagnose(e) => e.text(lang),
            CliError::BadY0(text) => lang.pick(
                format!("--y0 must be auto, free or a number, not \"{text}\""),
                format!("--y0 deve ser auto, free ou um número, não \"{text}\""),
            ),
            CliError::BadWindow(text) => lang.pick(
                format!("--window must be two times like 3.5,29.5, not \"{text}\""),
                format!("--window deve ser dois tempos como 3.5,29.5, não \"{text}\""),
            ),
            CliError::BadGuessItem { flag, item } => lang.pick(
                format!(
                    "{flag} item \"{item}\" must look like Kp=1.2 (names: Kp, Tp1, Tp2, Tp3, \
                     Tw, Zeta, Td, Tz, Y0, Drift; finite values)"
                ),
                format!(
                    "o item \"{item}\" de {flag} deve ser como Kp=1.2 (nomes: Kp, Tp1, Tp2, \
                     Tp3, Tw, Zeta, Td, Tz, Y0, Drift; valores finitos)"
                ),
            ),
            CliError::GuessTwice {
                flag,
                param,
                first,
                second,
            } => {
                let (a, b) = (n(*first), n(*second));
                lang.pick(
                    format!("{flag} gives {param} twice ({a} and {b}): give each parameter once"),
                    format!("{flag} dá {param} duas vezes ({a} e {b}): dê cada parâmetro uma vez"),
                )
            }
            CliError::GuessEmpty(flag) => lang.pick(
                format!("{flag} is empty: give values like Kp=1.2,Td=2, or leave the flag out"),
                format!("{flag} está vazio: dê valores como Kp=1.2,Td=2, ou não use a opção"),
            ),
            CliError::GuessY0Fixed { value, flag, held } => {
                let (v, h) = (typed(*value), n(*held));
                lang.pick(
                    format!(
                        "--guess Y0={v} conflicts with --y0 {flag}: Y0 is held at {h}, not \
                         estimated; give --y0 free to estimate it from {v}, or leave Y0 out of \
                         --guess"
                    ),
                    format!(
                        "--guess Y0={v} conflita com --y0 {flag}: Y0 está fixo em {h}, não é \
                         estimado; dê --y0 free para estimá-lo a partir de {v}, ou tire Y0 de \
                         --guess"
                    ),
                )
            }
            CliError::GuessY0Auto { value, held } => {
                let (v, h) = (typed(*value), n(*held));
                lang.pick(
                    format!(
                        "--guess Y0={v}: Y0 is held at {h} (the mean before the step, --y0 auto), \
                         not estimated; give --y0 free to estimate it from {v}, or --y0 {v} to \
                         hold it there"
                    ),
                    format!(
                        "--guess Y0={v}: Y0 está fixo em {h} (a média antes do degrau, --y0 \
                         auto), não é estimado; dê --y0 free para estimá-lo a partir de {v}, ou \
                         --y0 {v} para fixá-lo aí"
                    ),
                )
            }
            CliError::GuessDrift(value) => {
                let v = typed(*value);
                lang.pick(
                    format!("--guess Drift={v}: the model has no drift term; add --drift"),
                    format!("--guess Drift={v}: o modelo não tem termo de deriva; acrescente --drift"),
                )
            }
            CliError::GuessNotInModel {
                param,
                value,
                code,
                params,
            } => {
                let (v, list) = (typed(*value), params.join(", "));
                lang.pick(
                    format!(
                        "--guess {param}={v}: the model {code} has no {param} (its parameters: \
                         {list})"
                    ),
                    format!(
                        "--guess {param}={v}: o modelo {code} não tem {param} (seus parâmetros: \
                         {list})"
                    ),
                )
            }
        }
    }
}

/// An example of every [`CliError`] variant. No wildcard in [`cli_error_id`]: a new variant
/// does not compile until it is named there, and a test counts the examples.
#[cfg(test)]
fn cli_errors() -> Vec<CliError> {
    use crate::ident::experiment::ExperimentError;
    use crate::ident::fit::FitError;
    use crate::ident::record::data::DataError;
    let io = || std::io::Error::other("disk full");
    vec![
        CliError::Parse {
            option: "--poles",
            source: ParseError::EmptyItem { index: 2 },
        },
        CliError::Lti(crate::lti::LtiError::NoPoles),
        CliError::Options("the rise limits must be fractions".into()),
        CliError::RiseLimitsCount(1),
        CliError::EmptyCoefficients("--num"),
        CliError::NoSystem,
        CliError::TwoDescriptions,
        CliError::ZerosWithoutPoles,
        CliError::NumWithoutDen,
        CliError::DenWithoutNum,
        CliError::GainWithCoefficients,
        CliError::GainAndDcGain,
        CliError::Samples(1),
        CliError::ResponseBeyondRange,
        CliError::JsonSyntax("expected value at line 1 column 1".into()),
        CliError::NotAnObject,
        CliError::JsonFields("unknown field `pole`".into()),
        CliError::NotUtf8,
        CliError::ReadInput(io()),
        CliError::WriteOutput(io()),
        CliError::Data {
            path: "step.csv".into(),
            error: DataError::Empty,
        },
        CliError::Experiment(ExperimentError::NoStep),
        CliError::Diagnose(FitError::NonFiniteData),
        CliError::BadY0("x".into()),
        CliError::BadWindow("5,1".into()),
        CliError::BadGuessItem {
            flag: "--guess",
            item: "Foo=1".into(),
        },
        CliError::GuessTwice {
            flag: "--params",
            param: "Kp",
            first: 1.0,
            second: 2.5,
        },
        CliError::GuessEmpty("--guess"),
        CliError::GuessY0Fixed {
            value: 40.0,
            flag: "50".into(),
            held: 50.0,
        },
        CliError::GuessY0Auto {
            value: 40.0,
            held: 20.9,
        },
        CliError::GuessDrift(0.1),
        CliError::GuessNotInModel {
            param: "Tz",
            value: 1.0,
            code: "P1D".into(),
            params: vec!["Kp", "Tp1", "Td"],
        },
    ]
}

#[cfg(test)]
fn cli_error_id(e: &CliError) -> &'static str {
    match e {
        CliError::Parse { .. } => "Parse",
        CliError::Lti(_) => "Lti",
        CliError::Options(_) => "Options",
        CliError::RiseLimitsCount(_) => "RiseLimitsCount",
        CliError::EmptyCoefficients(_) => "EmptyCoefficients",
        CliError::NoSystem => "NoSystem",
        CliError::TwoDescriptions => "TwoDescriptions",
        CliError::ZerosWithoutPoles => "ZerosWithoutPoles",
        CliError::NumWithoutDen => "NumWithoutDen",
        CliError::DenWithoutNum => "DenWithoutNum",
        CliError::GainWithCoefficients => "GainWithCoefficients",
        CliError::GainAndDcGain => "GainAndDcGain",
        CliError::Samples(_) => "Samples",
        CliError::ResponseBeyondRange => "ResponseBeyondRange",
        CliError::JsonSyntax(_) => "JsonSyntax",
        CliError::NotAnObject => "NotAnObject",
        CliError::JsonFields(_) => "JsonFields",
        CliError::NotUtf8 => "NotUtf8",
        CliError::ReadInput(_) => "ReadInput",
        CliError::WriteOutput(_) => "WriteOutput",
        CliError::Data { .. } => "Data",
        CliError::Experiment(_) => "Experiment",
        CliError::Diagnose(_) => "Diagnose",
        CliError::BadY0(_) => "BadY0",
        CliError::BadWindow(_) => "BadWindow",
        CliError::BadGuessItem { .. } => "BadGuessItem",
        CliError::GuessTwice { .. } => "GuessTwice",
        CliError::GuessEmpty(_) => "GuessEmpty",
        CliError::GuessY0Fixed { .. } => "GuessY0Fixed",
        CliError::GuessY0Auto { .. } => "GuessY0Auto",
        CliError::GuessDrift(_) => "GuessDrift",
        CliError::GuessNotInModel { .. } => "GuessNotInModel",
    }
}
#[cfg(test)]
const CLI_ERROR_VARIANTS: usize = 32;

/// Every message of the command line, for the test of both languages. `Options`, `Parse`
/// and `Lti` carry `crate::lti`'s words (its own catalogue lists them), so their examples
/// are left out.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = StepPhrase::messages();
    all.extend(Heading::messages());
    all.extend(
        cli_errors()
            .iter()
            .filter(|e| {
                !matches!(
                    e,
                    CliError::Options(_) | CliError::Parse { .. } | CliError::Lti(_)
                )
            })
            .map(|e| Message::of(format!("cli::CliError::{}", cli_error_id(e)), e)),
    );
    for e in [
        StartsError::NotAWholeNumber("x".into()),
        StartsError::OutOfRange(0),
    ] {
        all.push(Message::of(format!("cli::{e:?}"), &e));
    }
    let examples = [
        (
            "cli::stability_line",
            stability_line(Stability::Stable, Behaviour::Settles, Lang::En),
            stability_line(Stability::Stable, Behaviour::Settles, Lang::Pt),
        ),
        (
            "cli::step_line",
            step_line("2", Lang::En),
            step_line("2", Lang::Pt),
        ),
        (
            "cli::metrics_heading",
            metrics_heading("10", "90", "2", Lang::En),
            metrics_heading("10", "90", "2", Lang::Pt),
        ),
        (
            "cli::no_window",
            no_window("no display", Lang::En),
            no_window("no display", Lang::Pt),
        ),
    ];
    all.extend(examples.into_iter().map(|(id, en, pt)| Message {
        id: id.into(),
        en,
        pt,
    }));
    all
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    #[test]
    fn every_cli_error_has_an_example() {
        let ids: BTreeSet<_> = cli_errors().iter().map(cli_error_id).collect();
        assert_eq!(ids.len(), CLI_ERROR_VARIANTS);
    }

    #[test]
    fn errors_name_the_flags_in_both_languages() {
        let e = CliError::Experiment(crate::ident::experiment::ExperimentError::NoStep);
        for lang in Lang::ALL {
            assert!(e.text(lang).contains("--initial-input"), "{}", e.text(lang));
        }
        let held = CliError::GuessY0Auto {
            value: 40.5,
            held: 20.9,
        };
        assert!(held.text(Lang::Pt).contains("Y0=40.5"));
        assert!(held.text(Lang::Pt).contains("fixo em 20,9"));
    }
}
