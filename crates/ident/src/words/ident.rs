//! The words of process identification (`crate::ident`): the notes on the data, every error
//! of loading, preparing and fitting, the fit's warnings and how it ended, the causes of the
//! diagnosis in plain words, their evidence and the verdict — in English and in Brazilian
//! Portuguese. Cause identifiers (`dead_time`, `extra_pole`, …) are not words and stay in
//! [`crate::diagnose::Cause::id`].
//!
//! Numbers in prose take the language's decimal separator ([`Lang::num`]); a number the
//! loader read from a file is shown in full (`Lang::localize_number` of its shortest form).

use crate::data::{
    Column, ColumnList, Columns, DataError, DataNote, FileKind, HeaderFound, MAX_FILE_BYTES, Role,
    Separator, Source,
};
use crate::diagnose::{Bias, Cause, Ending, Evidence, Verdict, Whiteness};
use crate::experiment::ExperimentError;
use crate::fit::{FitError, FitWarning, Termination};
use crate::handles::Handle;
use crate::models::{ModelError, Param, Requirement, Structure};
use crate::prepare::{Ewma, PrepareError};
use degrau_lti::LtiError;

use degrau_words::{Lang, Localize, Message};

/// A number as read, in full, with the language's separator.
fn full(lang: Lang, x: f64) -> String {
    lang.localize_number(&x.to_string())
}

/// `x` with four significant digits.
fn n4(lang: Lang, x: f64) -> String {
    lang.num(x, 4)
}

/// `x` with four decimals (the filter's and the warnings' figures).
fn d4(lang: Lang, x: f64) -> String {
    lang.localize_number(&format!("{x:.4}"))
}

/// The words of an [`LtiError`]: the one place that says them here, until the text layer's
/// `lti` catalogue renders them in either language (`Localize`), when this calls it.
pub fn lti_words(e: &LtiError, lang: Lang) -> String {
    e.text(lang)
}

/// `a, b and c` (`a, b e c`).
fn and_list(lang: Lang, items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} {} {last}", rest.join(", "), lang.pick("and", "e")),
    }
}

// ---------------------------------------------------------------------------------------
// Columns and lines

/// A column in a message: `"T1"`, or its position without names.
pub fn column_label(c: &Column) -> String {
    match &c.name {
        Some(name) => format!("\"{name}\""),
        None => c.position.to_string(),
    }
}

/// A column in a list: `4 "box temp"`, or `column 4` without names.
pub fn column_listing(c: &Column, lang: Lang) -> String {
    match &c.name {
        Some(name) => format!("{} \"{name}\"", c.position),
        None => format!("{} {}", lang.pick("column", "coluna"), c.position),
    }
}

/// Listed columns with commas, then how many more.
fn columns_text(list: &ColumnList, lang: Lang, each: impl Fn(&Column) -> String) -> String {
    let shown: Vec<String> = list.shown.iter().map(each).collect();
    if list.more == 0 {
        shown.join(", ")
    } else {
        let more = list.more;
        format!(
            "{}, {}",
            shown.join(", "),
            lang.pick(format!("… and {more} more"), format!("… e mais {more}"))
        )
    }
}

/// The columns of a file, as an error offers them.
fn available(columns: &Columns, lang: Lang) -> String {
    match columns {
        Columns::Unnamed { count } => lang.pick(
            format!("{count} unnamed column(s) (no header row): choose by position, 1 to {count}"),
            format!(
                "{count} coluna(s) sem nome (não há linha de cabeçalho): escolha pela posição, \
                 de 1 a {count}"
            ),
        ),
        Columns::Named(list) => columns_text(list, lang, |c| column_listing(c, lang)),
    }
}

/// "line 4" / "lines 4, 9 and 12" / "lines 4, 9, … and 37 more": `shown` are the first of
/// `total` lines.
pub fn lines_text(shown: &[usize], total: usize, lang: Lang) -> String {
    let text: Vec<String> = shown.iter().map(usize::to_string).collect();
    let (line, lines) = lang.pick(("line", "lines"), ("linha", "linhas"));
    match text[..] {
        [] => lang.pick("no line", "nenhuma linha").to_string(),
        [ref one] if total == 1 => format!("{line} {one}"),
        _ if total > shown.len() => {
            let more = total - shown.len();
            lang.pick(
                format!("{lines} {} and {more} more", text.join(", ")),
                format!("{lines} {} e mais {more}", text.join(", ")),
            )
        }
        _ => format!("{lines} {}", and_list(lang, &text)),
    }
}

impl Localize for Role {
    /// The role with its article: "the output" / "a saída".
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Role::Time => ("the time", "o tempo"),
            Role::Output => ("the output", "a saída"),
            Role::Input => ("the input", "a entrada"),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for Separator {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Separator::Semicolon => ("semicolon-separated", "separado por ponto e vírgula"),
            Separator::Tab => ("tab-separated", "separado por tabulações"),
            Separator::Comma => ("comma-separated", "separado por vírgulas"),
            Separator::Whitespace => (
                "whitespace-separated (as MATLAB's load)",
                "separado por espaços (como o load do MATLAB)",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for HeaderFound {
    fn text(&self, lang: Lang) -> String {
        match *self {
            HeaderFound::Row { line } => lang.pick(
                format!("header on line {line}"),
                format!("cabeçalho na linha {line}"),
            ),
            HeaderFound::Comment { line } => lang.pick(
                format!("column names from the comment on line {line}"),
                format!("nomes das colunas tirados do comentário da linha {line}"),
            ),
            HeaderFound::Ignored { line, columns } => lang.pick(
                format!(
                    "the header on line {line} was not used (its names do not split into the \
                     {columns} columns): the columns are numbered"
                ),
                format!(
                    "o cabeçalho da linha {line} não foi usado (seus nomes não se dividem nas \
                     {columns} colunas): as colunas são numeradas"
                ),
            ),
            HeaderFound::None => lang.pick("no header row", "sem linha de cabeçalho").into(),
        }
    }
}

impl Localize for FileKind {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            FileKind::Directory => ("a directory", "uma pasta"),
            FileKind::NamedPipe => ("a named pipe (FIFO)", "um pipe nomeado (FIFO)"),
            FileKind::Device => ("a device", "um dispositivo"),
            FileKind::Socket => ("a socket", "um socket"),
            FileKind::Special => ("a special file", "um arquivo especial"),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for Source {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Source::File => ("the file", "o arquivo"),
            Source::Data => ("the data", "os dados"),
            Source::Text => ("the text", "o texto"),
            Source::Paste => ("the pasted text", "o texto colado"),
        };
        lang.pick(en, pt).to_string()
    }
}

// ---------------------------------------------------------------------------------------
// Notes on the data

impl Localize for DataNote {
    fn text(&self, lang: Lang) -> String {
        match self {
            DataNote::Utf16 => lang
                .pick("the file is UTF-16 text", "o arquivo é texto UTF-16")
                .into(),
            DataNote::Latin1 => lang
                .pick(
                    "the file is not UTF-8: it was read as Latin-1 (Windows) text",
                    "o arquivo não é UTF-8: foi lido como texto Latin-1 (Windows)",
                )
                .into(),
            DataNote::ReadAs {
                separator,
                decimal_comma,
                header,
            } => {
                let decimal = match (decimal_comma, lang) {
                    (false, _) => "",
                    (true, Lang::En) => " with decimal commas",
                    (true, Lang::Pt) => " com vírgula decimal",
                };
                format!(
                    "{} {}{decimal}, {}",
                    lang.pick("read as", "lido como"),
                    separator.text(lang),
                    header.text(lang)
                )
            }
            DataNote::SamplingPeriodUnused {
                sampling_period,
                time,
            } => {
                let (ts, c) = (full(lang, *sampling_period), column_label(time));
                lang.pick(
                    format!(
                        "the sampling period given ({ts} s) was not used: the time is read from \
                         column {c}"
                    ),
                    format!(
                        "o período de amostragem dado ({ts} s) não foi usado: o tempo é lido da \
                         coluna {c}"
                    ),
                )
            }
            DataNote::OutputOnlyLeft { output } => {
                let c = column_label(output);
                lang.pick(
                    format!("column {c} was taken as the output: it is the only column left"),
                    format!("a coluna {c} foi tomada como saída: é a única coluna que resta"),
                )
            }
            DataNote::PastedTuy => lang
                .pick(
                    "the pasted columns were read as t, u, y",
                    "as colunas coladas foram lidas como t, u, y",
                )
                .into(),
            DataNote::InputNotGuessed { columns, limit } => lang.pick(
                format!(
                    "the input was not guessed among the {columns} unnamed columns (more than \
                     {limit}): choose it by name or position"
                ),
                format!(
                    "a entrada não foi adivinhada entre as {columns} colunas sem nome (mais de \
                     {limit}): escolha-a pelo nome ou pela posição"
                ),
            ),
            DataNote::InputGuessed { input } => {
                let c = column_label(input);
                lang.pick(
                    format!(
                        "column {c} was taken as the input: it is piecewise constant with few \
                         levels"
                    ),
                    format!(
                        "a coluna {c} foi tomada como entrada: é constante por partes, com poucos \
                         níveis"
                    ),
                )
            }
            DataNote::SeveralInputs { columns } => {
                let list = columns_text(columns, lang, column_label);
                lang.pick(
                    format!(
                        "columns {list} all look like an input (piecewise constant): none was \
                         taken; choose one"
                    ),
                    format!(
                        "as colunas {list} parecem todas uma entrada (constantes por partes): \
                         nenhuma foi tomada; escolha uma"
                    ),
                )
            }
            DataNote::GeneratedTime { sampling_period } => {
                let ts = full(lang, *sampling_period);
                lang.pick(
                    format!("the file has no time column: t = k·Ts with Ts = {ts} s (k = 0, 1, …)"),
                    format!(
                        "o arquivo não tem coluna de tempo: t = k·Ts com Ts = {ts} s (k = 0, 1, …)"
                    ),
                )
            }
            DataNote::MissingValues { lines, total } => {
                let which = lines_text(lines, *total, lang);
                let one = *total == 1;
                lang.pick(
                    format!(
                        "{which}: the output or input is missing (empty or NaN); {} skipped",
                        if one {
                            "that row was"
                        } else {
                            "those rows were"
                        }
                    ),
                    format!(
                        "{which}: falta a saída ou a entrada (vazia ou NaN); {}",
                        if one {
                            "essa linha foi pulada"
                        } else {
                            "essas linhas foram puladas"
                        }
                    ),
                )
            }
            DataNote::StepBetweenEqualTimes {
                first,
                second,
                time,
                before,
                after,
            } => {
                let (t, b, a) = (full(lang, *time), full(lang, *before), full(lang, *after));
                lang.pick(
                    format!(
                        "lines {first} and {second} have the same time {t} and the input changes \
                         between them ({b} → {a}): line {first} is the state just before the step \
                         (TCLab logs t = 0 twice this way)"
                    ),
                    format!(
                        "as linhas {first} e {second} têm o mesmo tempo {t} e a entrada muda entre \
                         elas ({b} → {a}): a linha {first} é o estado logo antes do degrau (o \
                         TCLab registra t = 0 duas vezes assim)"
                    ),
                )
            }
            DataNote::EqualTimes {
                first,
                second,
                time,
            } => {
                let t = full(lang, *time);
                lang.pick(
                    format!("lines {first} and {second} have the same time {t}; both were kept"),
                    format!(
                        "as linhas {first} e {second} têm o mesmo tempo {t}; as duas foram mantidas"
                    ),
                )
            }
            DataNote::Window {
                first,
                last,
                count,
                start,
                end,
            } => {
                let (a, b) = (full(lang, *start), full(lang, *end));
                lang.pick(
                    format!("kept samples {first} to {last} of {count} (t = {a} s to {b} s)"),
                    format!("mantidas as amostras {first} a {last} de {count} (t = {a} s a {b} s)"),
                )
            }
            DataNote::InputJoined { held_back: 0 } => lang
                .pick(
                    "the input was read from its own file and joined on time: each sample \
                     takes the input's last value logged at or before it",
                    "a entrada foi lida do seu próprio arquivo e unida pelo tempo: cada amostra \
                     recebe o último valor da entrada registrado até o seu instante",
                )
                .to_string(),
            DataNote::InputJoined { held_back } => lang.pick(
                format!(
                    "the input was read from its own file and joined on time: each sample takes \
                     the input's last value logged at or before it; the first {held_back} \
                     sample(s), before the input's first, took its first value"
                ),
                format!(
                    "a entrada foi lida do seu próprio arquivo e unida pelo tempo: cada amostra \
                     recebe o último valor da entrada registrado até o seu instante; a(s) \
                     {held_back} primeira(s) amostra(s), antes da primeira da entrada, \
                     recebeu(ram) o seu primeiro valor"
                ),
            ),
            DataNote::IndexIgnored { columns } => {
                let one = columns.shown.len() == 1 && columns.more == 0;
                let list = columns_text(columns, lang, |c| c.position.to_string());
                match (lang, one) {
                    (Lang::En, true) => format!(
                        "column {list} has no name (a row index, as pandas writes): not used"
                    ),
                    (Lang::En, false) => format!(
                        "columns {list} have no name (a row index, as pandas writes): not used"
                    ),
                    (Lang::Pt, true) => format!(
                        "a coluna {list} não tem nome (um índice de linhas, como o pandas \
                         escreve): não foi usada"
                    ),
                    (Lang::Pt, false) => format!(
                        "as colunas {list} não têm nome (um índice de linhas, como o pandas \
                         escreve): não foram usadas"
                    ),
                }
            }
            DataNote::MoreEqualTimes { pairs } => lang.pick(
                format!("{pairs} more pairs of rows share a time"),
                format!("mais {pairs} pares de linhas têm o mesmo tempo"),
            ),
        }
    }
}

// ---------------------------------------------------------------------------------------
// Errors

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

// ---------------------------------------------------------------------------------------
// The fit: parameters, termination, warnings, filter

/// What a parameter is, in words ("static gain Δy/Δu", "ganho estático Δy/Δu").
pub fn param_meaning(p: Param, lang: Lang) -> &'static str {
    let (en, pt) = match p {
        Param::Kp => ("static gain Δy/Δu", "ganho estático Δy/Δu"),
        Param::Tp1 => ("first time constant", "primeira constante de tempo"),
        Param::Tp2 => ("second time constant", "segunda constante de tempo"),
        Param::Tp3 => ("third time constant", "terceira constante de tempo"),
        Param::Tw => (
            "time constant of the underdamped pair, 1/ωn",
            "constante de tempo do par subamortecido, 1/ωn",
        ),
        Param::Zeta => ("damping ratio of the pair", "fator de amortecimento do par"),
        Param::Td => ("dead time", "tempo morto"),
        Param::Tz => (
            "time constant of the zero (negative: inverse response)",
            "constante de tempo do zero (negativa: resposta inversa)",
        ),
        Param::Y0 => (
            "output before the step (operating point)",
            "saída antes do degrau (ponto de operação)",
        ),
        Param::Drift => (
            "slope of a linear drift, output units per second",
            "inclinação de uma deriva linear, unidades da saída por segundo",
        ),
        Param::Ta => (
            "how long before the sample that first shows it each input change happened",
            "quanto antes da amostra que primeiro a mostra cada mudança da entrada ocorreu",
        ),
        Param::X1 | Param::X2 | Param::X3 => (
            "coefficient of the initial transient (the test was not at rest), output units",
            "coeficiente do transitório inicial (o ensaio não estava em repouso), unidades da saída",
        ),
    };
    lang.pick(en, pt)
}

/// A parameter's meaning as a fact, for the test of every message.
struct Meaning(Param);

impl Localize for Meaning {
    fn text(&self, lang: Lang) -> String {
        param_meaning(self.0, lang).to_string()
    }
}

impl Localize for Structure {
    /// The code plus what it does not say: `P2 + drift`, `P1D, Y0 held` (`Y0 fixo`).
    fn text(&self, lang: Lang) -> String {
        let mut l = self.code();
        if self.drift {
            l.push_str(lang.pick(" + drift", " + deriva"));
        }
        if self.transient {
            l.push_str(lang.pick(" + initial transient", " + transitório inicial"));
        }
        if !self.free_offset {
            l.push_str(lang.pick(", Y0 held", ", Y0 fixo"));
        }
        l
    }
}

impl Localize for Termination {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Termination::Gradient => (
                "converged: the gradient vanished",
                "convergiu: o gradiente se anulou",
            ),
            Termination::SmallStep => (
                "converged: the steps became negligible",
                "convergiu: os passos ficaram desprezíveis",
            ),
            Termination::SmallCostChange => (
                "converged: the cost stopped decreasing",
                "convergiu: o custo parou de diminuir",
            ),
            Termination::IterationLimit => (
                "stopped at the iteration limit (not converged)",
                "parou no limite de iterações (não convergiu)",
            ),
            Termination::Cancelled => ("cancelled", "cancelado"),
            Termination::NoImprovement => (
                "stopped: no step lowered the cost from the start (not converged)",
                "parou: nenhum passo baixou o custo a partir do início (não convergiu)",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for FitWarning {
    fn text(&self, lang: Lang) -> String {
        match self {
            FitWarning::AtBound { param, bound } => {
                let b = full(lang, *bound);
                lang.pick(
                    format!(
                        "{param} stopped at its bound {b}: the optimum may lie beyond it, or the \
                         model does not need this parameter"
                    ),
                    format!(
                        "{param} parou no seu limite {b}: o ótimo pode estar além dele, ou o \
                         modelo não precisa deste parâmetro"
                    ),
                )
            }
            FitWarning::OverdampedUnderdamped { zeta } => {
                let z = d4(lang, *zeta);
                lang.pick(
                    format!(
                        "Zeta = {z} ≥ 1 in an underdamped model: the pair is not oscillatory; an \
                         overdamped structure (two real poles) says the same with a clearer \
                         meaning"
                    ),
                    format!(
                        "Zeta = {z} ≥ 1 num modelo subamortecido: o par não oscila; uma estrutura \
                         sobreamortecida (dois polos reais) diz o mesmo com um sentido mais claro"
                    ),
                )
            }
            FitWarning::Alias {
                omega_d,
                nyquist,
                between_samples,
            } => {
                let (w, ny) = (d4(lang, *omega_d), d4(lang, *nyquist));
                let pct = format!("{:.0}", 100.0 * between_samples);
                lang.pick(
                    format!(
                        "alias: the model oscillates at ωd = {w} rad/s, but samples every Ts can \
                         only show up to π/Ts = {ny} rad/s; between the samples the model swings \
                         by {pct} % of the step's effect. Its samples may match the data while \
                         the model is wrong: start from a better guess (the oscillation period of \
                         the data) or use several starts"
                    ),
                    format!(
                        "alias: o modelo oscila em ωd = {w} rad/s, mas amostras a cada Ts só \
                         mostram até π/Ts = {ny} rad/s; entre as amostras o modelo oscila {pct} % \
                         do efeito do degrau. Suas amostras podem coincidir com os dados e o \
                         modelo estar errado: parta de uma estimativa melhor (o período de \
                         oscilação dos dados) ou use vários pontos de partida"
                    ),
                )
            }
            FitWarning::NotIdentifiable { param } => lang.pick(
                format!(
                    "{param} is not identifiable from this data (the fit does not depend on it): \
                     no interval can be given"
                ),
                format!(
                    "{param} não é identificável a partir destes dados (o ajuste não depende \
                     dele): não se pode dar um intervalo"
                ),
            ),
            FitWarning::CombinationNotIdentifiable => lang
                .pick(
                    "a combination of the parameters is not identifiable from this data (the fit \
                     does not depend on it): no interval can be given",
                    "uma combinação dos parâmetros não é identificável a partir destes dados (o \
                     ajuste não depende dela): não se pode dar um intervalo",
                )
                .into(),
            FitWarning::LagsNotResolved { larger, smaller } => lang.pick(
                format!(
                    "{larger} and {smaller} cannot be told apart from this data: two equal time \
                     constants explain it as well. Their intervals are read together (the range \
                     of each wherever the other may be); a larger step or a longer record \
                     separates them"
                ),
                format!(
                    "{larger} e {smaller} não se distinguem com estes dados: duas constantes de \
                     tempo iguais os explicam igualmente bem. Seus intervalos são lidos juntos \
                     (a faixa de cada uma onde quer que a outra esteja); um degrau maior ou um \
                     registro mais longo as separa"
                ),
            ),
            FitWarning::NotConverged => lang
                .pick(
                    "the optimiser did not converge: the values are not an optimum",
                    "o otimizador não convergiu: os valores não são um ótimo",
                )
                .into(),
            FitWarning::NoImprovement => lang
                .pick(
                    "the optimiser found no step that lowers the cost from the start: the values \
                     are the start's, not an optimum; try another guess or more starts",
                    "o otimizador não achou passo que baixe o custo a partir do início: os \
                     valores são os da partida, não um ótimo; tente outra estimativa ou mais \
                     pontos de partida",
                )
                .into(),
            FitWarning::Unrepresentable { statistic, log10 } => {
                let e = lang.localize_number(&format!("{log10:.1}"));
                let shown = if *log10 > 0.0 { "inf" } else { "0" };
                lang.pick(
                    format!(
                        "the {statistic} is about 1e{e} in the data's units, beyond double \
                         precision, so it shows as {shown}; the RMSE, fit % and AIC are exact"
                    ),
                    format!(
                        "o {statistic} é cerca de 1e{e} nas unidades dos dados, além da precisão \
                         dupla, e aparece como {shown}; o RMSE, o ajuste % e o AIC são exatos"
                    ),
                )
            }
            FitWarning::GainUndetermined { low, high } => {
                let (lo, hi) = (full(lang, *low), full(lang, *high));
                lang.pick(
                    format!(
                        "the 95 % interval of Kp, [{lo}, {hi}], contains 0: this record does \
                         not determine the gain, not even its sign. A larger step, a longer \
                         record or a test in open loop may"
                    ),
                    format!(
                        "o intervalo de 95 % de Kp, [{lo}; {hi}], contém 0: este registro não \
                         determina o ganho, nem mesmo o seu sinal. Um degrau maior, um registro \
                         mais longo ou um ensaio em malha aberta podem determinar"
                    ),
                )
            }
        }
    }
}

impl Localize for Ewma {
    /// α, RC, RC/Ts and the lag, then the notes' warning when Ts > RC/5.
    fn text(&self, lang: Lang) -> String {
        let (a, rc, ratio, lag) = (
            d4(lang, self.alpha),
            d4(lang, self.rc),
            d4(lang, self.ratio()),
            d4(lang, self.lag()),
        );
        let line = lang.pick(
            format!(
                "α = {a}, RC = {rc} s, RC/Ts = {ratio}; the filter delays the output by RC = {lag} s"
            ),
            format!("α = {a}, RC = {rc} s, RC/Ts = {ratio}; o filtro atrasa a saída em RC = {lag} s"),
        );
        if !self.too_coarse() {
            return line;
        }
        let (ts, rc5) = (full(lang, self.ts), d4(lang, self.rc / 5.0));
        let warning = lang.pick(
            format!(
                "Warning: the sampling period Ts = {ts} s is more than RC/5 = {rc5} s (RC/Ts = \
                 {ratio}, expected ≥ 5): this digital filter behaves quite differently from the \
                 RC filter it imitates; use a lower cut-off or faster sampling"
            ),
            format!(
                "Atenção: o período de amostragem Ts = {ts} s é maior que RC/5 = {rc5} s (RC/Ts \
                 = {ratio}, esperado ≥ 5): este filtro digital se comporta bem diferente do \
                 filtro RC que imita; use uma frequência de corte menor ou amostragem mais rápida"
            ),
        );
        format!("{line}. {warning}")
    }
}

// ---------------------------------------------------------------------------------------
// The guess handles

/// The accessible label of a guess handle ("dead time handle").
pub fn handle_label(h: Handle, lang: Lang) -> &'static str {
    let (en, pt) = match h {
        Handle::FinalValue => ("final value handle", "alça do valor final"),
        Handle::DeadTime => ("dead time handle", "alça do tempo morto"),
        Handle::TimeConstant => ("time constant handle", "alça da constante de tempo"),
        Handle::FirstPeak => ("first peak handle", "alça do primeiro pico"),
    };
    lang.pick(en, pt)
}

/// What dragging a guess handle changes, for a tooltip.
pub fn handle_help(h: Handle, lang: Lang) -> &'static str {
    let (en, pt) = match h {
        Handle::FinalValue => (
            "Drag up or down: the final value sets the static gain Kp.",
            "Arraste para cima ou para baixo: o valor final define o ganho estático Kp.",
        ),
        Handle::DeadTime => (
            "Drag left or right: where the response starts sets the dead time Td.",
            "Arraste para a esquerda ou a direita: onde a resposta começa define o tempo morto \
             Td.",
        ),
        Handle::TimeConstant => (
            "Drag left or right: the 63.2 % time sets the time constants.",
            "Arraste para a esquerda ou a direita: o instante de 63,2 % define as constantes de \
             tempo.",
        ),
        Handle::FirstPeak => (
            "Drag: the peak's height sets ζ (overshoot), its time sets ωd (peak time).",
            "Arraste: a altura do pico define ζ (sobressinal), seu instante define ωd (tempo de \
             pico).",
        ),
    };
    lang.pick(en, pt)
}

// ---------------------------------------------------------------------------------------
// The diagnosis: causes, remedies, evidence, verdict

/// How a cause is named at the head of its lines: by its stable identifier (the CLI's text,
/// which graders and scripts read, `extra_pole`), or in the student's words (the app).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Naming {
    Id,
    Words,
}

/// A cause's name: its identifier, or a few words in `lang` ("extra pole", "polo a mais").
pub fn cause_name(c: Cause, naming: Naming, lang: Lang) -> &'static str {
    if naming == Naming::Id {
        return c.id();
    }
    let (en, pt) = match c {
        Cause::DeadTime => ("Dead time", "Tempo morto"),
        Cause::Offset => ("Operating point", "Ponto de operação"),
        Cause::Oscillation => ("Oscillation", "Oscilação"),
        Cause::ExtraPole => ("Extra pole", "Polo a mais"),
        Cause::Zero => ("Zero", "Zero"),
        Cause::InverseResponse => ("Inverse response", "Resposta inversa"),
        Cause::Integrator => ("Integrator", "Integrador"),
        Cause::Drift => ("Drift", "Deriva"),
        Cause::None => ("Nothing", "Nada"),
    };
    lang.pick(en, pt)
}

impl Localize for Cause {
    /// The cause in plain words for a student.
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Cause::DeadTime => (
                "The model moves before the data does: the process has a dead time.",
                "O modelo se move antes dos dados: o processo tem tempo morto.",
            ),
            Cause::Offset => (
                "The model's baseline is off everywhere: the operating point y0 is not what the \
                 model assumes.",
                "A linha de base do modelo está deslocada em todo o registro: o ponto de operação \
                 y0 não é o que o modelo supõe.",
            ),
            Cause::Oscillation => (
                "The residuals oscillate at a frequency the model lacks: the process has an \
                 underdamped pair of poles.",
                "Os resíduos oscilam numa frequência que falta ao modelo: o processo tem um par \
                 de polos subamortecido.",
            ),
            Cause::ExtraPole => (
                "The data starts with zero slope (an S-shape) where the model rises at once: the \
                 process has one more pole.",
                "Os dados começam com inclinação nula (em forma de S) onde o modelo sobe de \
                 imediato: o processo tem mais um polo.",
            ),
            Cause::Zero => (
                "The data rises faster or overshoots more than the model's poles allow: the \
                 process has a zero.",
                "Os dados sobem mais rápido ou têm mais sobressinal do que os polos do modelo \
                 permitem: o processo tem um zero.",
            ),
            Cause::InverseResponse => (
                "The data first moves the wrong way: the process has a right-half-plane zero.",
                "Os dados primeiro vão para o lado errado: o processo tem um zero no semiplano \
                 direito.",
            ),
            Cause::Integrator => (
                "The data never levels off, it ramps: the process integrates.",
                "Os dados nunca se estabilizam, crescem em rampa: o processo é integrador.",
            ),
            Cause::Drift => (
                "A slow trend rides on top of the settled response: the output drifts.",
                "Uma tendência lenta se soma à resposta já acomodada: a saída tem deriva.",
            ),
            Cause::None => (
                "The residuals look like noise and no extension pays for itself: the model is \
                 adequate.",
                "Os resíduos parecem ruído e nenhuma extensão se paga: o modelo é adequado.",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

/// The extension a cause implies, in procest terms ("add a dead time Td").
pub fn remedy(cause: Cause, lang: Lang) -> &'static str {
    let (en, pt) = match cause {
        Cause::DeadTime => ("add a dead time Td", "acrescentar um tempo morto Td"),
        Cause::Offset => ("estimate Y0", "estimar Y0"),
        Cause::Oscillation => (
            "use an underdamped pair (U: Tw, Zeta)",
            "usar um par subamortecido (U: Tw, Zeta)",
        ),
        Cause::ExtraPole => (
            "add a pole (P1 → P2, P2 → P3)",
            "acrescentar um polo (P1 → P2, P2 → P3)",
        ),
        Cause::Zero => ("add a zero Tz", "acrescentar um zero Tz"),
        Cause::InverseResponse => (
            "add a right-half-plane zero (Tz < 0)",
            "acrescentar um zero no semiplano direito (Tz < 0)",
        ),
        Cause::Integrator => ("add an integrator (I)", "acrescentar um integrador (I)"),
        Cause::Drift => ("add a drift term", "acrescentar um termo de deriva"),
        Cause::None => ("keep the model", "manter o modelo"),
    };
    lang.pick(en, pt)
}

/// A cause's remedy as a fact, for the test of every message.
struct Remedy(Cause);

impl Localize for Remedy {
    fn text(&self, lang: Lang) -> String {
        remedy(self.0, lang).to_string()
    }
}

/// "the {n} residuals there average {mean} ({same} % of one sign)".
fn bias_words(b: &Bias, lang: Lang) -> String {
    let (n, mean, same) = (b.n, n4(lang, b.mean), n4(lang, 100.0 * b.same_sign));
    lang.pick(
        format!("the {n} residuals there average {mean} ({same} % of one sign)"),
        format!("os {n} resíduos ali têm média {mean} ({same} % de um mesmo sinal)"),
    )
}

/// A time that may be absent ("—").
fn maybe(lang: Lang, t: Option<f64>) -> String {
    t.map_or("—".into(), |t| n4(lang, t))
}

impl Localize for Evidence {
    fn text(&self, lang: Lang) -> String {
        match self {
            Evidence::DeadTime { bias, td, changes } if *changes > 1 => {
                let (a, b, td) = (n4(lang, bias.start), n4(lang, bias.end), n4(lang, *td));
                let (n, mean, same) = (
                    bias.n,
                    n4(lang, bias.mean),
                    n4(lang, 100.0 * bias.same_sign),
                );
                lang.pick(
                    format!(
                        "Just after each of the {changes} input changes (to the first sample \
                         {td} s or more after it; from t = {a} s to {b} s) the data has moved \
                         less than the model: the {n} residuals there, each signed by its \
                         change's direction, average {mean} ({same} % of one sign). A dead time \
                         Td = {td} s makes the model wait."
                    ),
                    format!(
                        "Logo depois de cada uma das {changes} mudanças da entrada (até a primeira \
                         amostra {td} s ou mais depois dela; de t = {a} s a {b} s) os dados se \
                         moveram menos que o modelo: os {n} resíduos ali, cada um com o sinal da \
                         direção da sua mudança, têm média {mean} ({same} % de um mesmo sinal). \
                         Um tempo morto Td = {td} s faz o modelo esperar."
                    ),
                )
            }
            Evidence::DeadTime { bias, td, .. } => {
                let (a, b, w, td) = (
                    n4(lang, bias.start),
                    n4(lang, bias.end),
                    bias_words(bias, lang),
                    n4(lang, *td),
                );
                lang.pick(
                    format!(
                        "From t = {a} s to {b} s the data stays near its operating point while \
                         the model already moves: {w}. A dead time Td = {td} s makes the model \
                         wait."
                    ),
                    format!(
                        "De t = {a} s a {b} s os dados ficam perto do ponto de operação enquanto \
                         o modelo já se move: {w}. Um tempo morto Td = {td} s faz o modelo \
                         esperar."
                    ),
                )
            }
            Evidence::Offset {
                bias,
                y0_held,
                y0_estimated,
            } => {
                let (n, mean, same) = (
                    bias.n,
                    n4(lang, bias.mean),
                    n4(lang, 100.0 * bias.same_sign),
                );
                let (held, est) = (n4(lang, *y0_held), n4(lang, *y0_estimated));
                lang.pick(
                    format!(
                        "The residuals are biased everywhere: over the whole record ({n} samples) \
                         they average {mean} ({same} % of one sign). The model assumes y0 = \
                         {held}; estimated, y0 = {est}."
                    ),
                    format!(
                        "Os resíduos estão deslocados em todo o registro: nas {n} amostras têm \
                         média {mean} ({same} % de um mesmo sinal). O modelo supõe y0 = {held}; \
                         estimado, y0 = {est}."
                    ),
                )
            }
            Evidence::Oscillation {
                period,
                omega_d,
                zeta,
            } => {
                let (wd, z) = (maybe(lang, *omega_d), n4(lang, *zeta));
                let what = match (period, lang) {
                    (Some(p), Lang::En) => format!("an oscillation of period {} s", n4(lang, *p)),
                    (Some(p), Lang::Pt) => format!("uma oscilação de período {} s", n4(lang, *p)),
                    (None, Lang::En) => "an oscillation".into(),
                    (None, Lang::Pt) => "uma oscilação".into(),
                };
                lang.pick(
                    format!(
                        "The residuals show {what} (their autocorrelation alternates beyond the \
                         99 % band), a frequency the model lacks. An underdamped pair with ωd = \
                         {wd} rad/s and ζ = {z} takes it up."
                    ),
                    format!(
                        "Os resíduos mostram {what} (sua autocorrelação alterna além da faixa de \
                         99 %), uma frequência que falta ao modelo. Um par subamortecido com ωd = \
                         {wd} rad/s e ζ = {z} a absorve."
                    ),
                )
            }
            Evidence::ExtraPole { bias, added } => {
                let (a, b, w) = (
                    n4(lang, bias.start),
                    n4(lang, bias.end),
                    bias_words(bias, lang),
                );
                let pole = added.map_or(String::new(), |(p, x)| {
                    format!(" ({} = {} s)", p.name(), n4(lang, x))
                });
                lang.pick(
                    format!(
                        "Right after the response starts (t = {a} s to {b} s) the data rises with \
                         zero slope, an S-shape, while the model rises at once: {w}. One more \
                         pole{pole} gives the S-shape."
                    ),
                    format!(
                        "Logo depois que a resposta começa (t = {a} s a {b} s) os dados sobem com \
                         inclinação nula, em forma de S, enquanto o modelo sobe de imediato: {w}. \
                         Mais um polo{pole} dá a forma de S."
                    ),
                )
            }
            Evidence::Zero {
                overshoot,
                peak_time,
                underdamped,
                tz,
            } => {
                let (os, tp, tz) = (
                    n4(lang, 100.0 * overshoot),
                    maybe(lang, *peak_time),
                    n4(lang, *tz),
                );
                let why = match (underdamped, lang) {
                    (true, Lang::En) => {
                        "more, and sooner, than the model's underdamped pair alone can follow"
                    }
                    (true, Lang::Pt) => {
                        "mais, e mais cedo, do que o par subamortecido do modelo sozinho consegue \
                         acompanhar"
                    }
                    (false, Lang::En) => "although the model's poles are real and cannot overshoot",
                    (false, Lang::Pt) => {
                        "embora os polos do modelo sejam reais e não possam dar sobressinal"
                    }
                };
                lang.pick(
                    format!(
                        "The data overshoots its final level by {os} % (peak at t = {tp} s) \
                         {why}. A zero with Tz = {tz} s speeds up the start of the response and \
                         lets it."
                    ),
                    format!(
                        "Os dados passam do valor final com sobressinal de {os} % (pico em t = \
                         {tp} s) {why}. Um zero com Tz = {tz} s acelera o início da resposta e o \
                         permite."
                    ),
                )
            }
            Evidence::InverseResponse {
                undershoot,
                dip_time,
                tz,
            } => {
                let (us, td, tz) = (
                    n4(lang, 100.0 * undershoot),
                    maybe(lang, *dip_time),
                    n4(lang, *tz),
                );
                lang.pick(
                    format!(
                        "The data first moves the wrong way, by {us} % of the step's effect \
                         (deepest at t = {td} s), before going towards its final level. A \
                         right-half-plane zero, Tz = {tz} s, does that."
                    ),
                    format!(
                        "Os dados primeiro vão para o lado errado, em {us} % do efeito do degrau \
                         (mais fundo em t = {td} s), antes de seguir para o valor final. Um zero \
                         no semiplano direito, Tz = {tz} s, faz isso."
                    ),
                )
            }
            Evidence::Integrator {
                slope,
                per_time_constant,
                trend_z,
            } => {
                let (s, pct) = (n4(lang, *slope), n4(lang, 100.0 * per_time_constant));
                let z = trend_z.map_or(String::new(), |z| {
                    lang.pick(
                        format!(" (trend z = {})", n4(lang, z)),
                        format!(" (tendência z = {})", n4(lang, z)),
                    )
                });
                lang.pick(
                    format!(
                        "The data never levels off: over the last fifth of the record it still \
                         moves at {s} units/s ({pct} % of the step's effect per time constant), \
                         and the residuals trend in the tail{z}. An integrator makes the model \
                         ramp."
                    ),
                    format!(
                        "Os dados nunca se estabilizam: no último quinto do registro ainda se \
                         movem a {s} unidades/s ({pct} % do efeito do degrau por constante de \
                         tempo), e os resíduos têm tendência no final{z}. Um integrador faz o \
                         modelo crescer em rampa."
                    ),
                )
            }
            Evidence::Drift { tail, drift } => {
                let d = n4(lang, *drift);
                let t = tail.map_or(String::new(), |(slope, z)| {
                    let (s, z) = (n4(lang, slope), n4(lang, z));
                    lang.pick(
                        format!(" (slope {s} units/s, z = {z})"),
                        format!(" (inclinação {s} unidades/s, z = {z})"),
                    )
                });
                lang.pick(
                    format!(
                        "Where no input change is still answered (before the first, and after \
                         each response has settled) the residuals trend alike, in a straight \
                         line{t}: a slow drift of {d} units/s rides on the output. A drift term \
                         takes it."
                    ),
                    format!(
                        "Onde nenhuma variação da entrada ainda está sendo respondida (antes da \
                         primeira e depois que cada resposta se acomoda) os resíduos têm a mesma \
                         tendência, em linha reta{t}: uma deriva lenta de {d} unidades/s se soma \
                         à saída. Um termo de deriva a absorve."
                    ),
                )
            }
            Evidence::NoLongerPays {
                param,
                value,
                ci95,
                criterion_delta,
            } => {
                let (name, v, d) = (param.name(), n4(lang, *value), n4(lang, *criterion_delta));
                let ci = ci95.map_or(String::new(), |(a, b)| {
                    format!(" [{}{} {}]", n4(lang, a), lang.pick(",", ";"), n4(lang, b))
                });
                if *param == Param::Td && *value <= 0.0 {
                    lang.pick(
                        format!(
                            "Once the later terms are in, {name} ends at {v}{ci}: a dead time \
                             at or below zero is no dead time. The term is taken out."
                        ),
                        format!(
                            "Com os termos seguintes incluídos, {name} termina em {v}{ci}: um \
                             tempo morto nulo ou negativo não é tempo morto. O termo é retirado."
                        ),
                    )
                } else {
                    lang.pick(
                        format!(
                            "Once the later terms are in, {name} = {v}{ci} no longer pays: \
                             adding it back changes BIC by only {d}. The term is taken out."
                        ),
                        format!(
                            "Com os termos seguintes incluídos, {name} = {v}{ci} não compensa \
                             mais: devolvê-lo muda o BIC só em {d}. O termo é retirado."
                        ),
                    )
                }
            }
            Evidence::None => Cause::None.text(lang),
        }
    }
}

impl Localize for Whiteness {
    fn text(&self, lang: Lang) -> String {
        let (o, l, z) = (self.outside, self.lags, n4(lang, self.runs_z));
        lang.pick(
            format!(
                "Residual autocorrelation: {o} of {l} lags outside the 99 % band; runs test z = \
                 {z}."
            ),
            format!(
                "Autocorrelação dos resíduos: {o} de {l} atrasos fora da faixa de 99 %; teste de \
                 sequências z = {z}."
            ),
        )
    }
}

impl Localize for Ending {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Ending::Adequate => (
                "Adequate: the residuals look like noise and no extension lowers BIC by 10.",
                "Adequado: os resíduos parecem ruído e nenhuma extensão baixa o BIC em 10.",
            ),
            Ending::NotWhite => (
                "No extension in the list lowers BIC by 10, although the residuals are not white: \
                 what is left is not one of the effects Degrau knows (nonlinearity, a \
                 disturbance, or noise that is not white).",
                "Nenhuma extensão da lista baixa o BIC em 10, embora os resíduos não sejam \
                 brancos: o que resta não é um dos efeitos que o Degrau conhece (não linearidade, \
                 um distúrbio, ou ruído que não é branco).",
            ),
            Ending::WithinRounding => (
                "Adequate to the output's resolution: the output is a staircase (its noise under \
                 half a quantum), and no extension gains more than rounding gives on records \
                 simulated from this model; what is left is the rounding, not structure.",
                "Adequado à resolução da saída: a saída é uma escada (seu ruído abaixo de meio \
                 quantum), e nenhuma extensão ganha mais do que o arredondamento dá em \
                 registros simulados com este modelo; o que resta é o arredondamento, não \
                 estrutura.",
            ),
            Ending::StepLimit => (
                "Stopped at the step limit: the model may still miss something.",
                "Parou no limite de passos: pode ainda faltar algo ao modelo.",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for Verdict {
    fn text(&self, lang: Lang) -> String {
        match &self.whiteness {
            Some(w) => format!("{} {}", self.ending.text(lang), w.text(lang)),
            None => self.ending.text(lang),
        }
    }
}

// ---------------------------------------------------------------------------------------
// Every message, for the test of both languages

/// The name of a data note's variant. No wildcard: a new variant does not compile until it
/// is named here, and [`data_notes`] must then give an example of it (a test counts them).
fn data_note_id(n: &DataNote) -> &'static str {
    match n {
        DataNote::Utf16 => "Utf16",
        DataNote::Latin1 => "Latin1",
        DataNote::ReadAs { .. } => "ReadAs",
        DataNote::SamplingPeriodUnused { .. } => "SamplingPeriodUnused",
        DataNote::OutputOnlyLeft { .. } => "OutputOnlyLeft",
        DataNote::PastedTuy => "PastedTuy",
        DataNote::InputNotGuessed { .. } => "InputNotGuessed",
        DataNote::InputGuessed { .. } => "InputGuessed",
        DataNote::SeveralInputs { .. } => "SeveralInputs",
        DataNote::GeneratedTime { .. } => "GeneratedTime",
        DataNote::MissingValues { .. } => "MissingValues",
        DataNote::StepBetweenEqualTimes { .. } => "StepBetweenEqualTimes",
        DataNote::EqualTimes { .. } => "EqualTimes",
        DataNote::Window { .. } => "Window",
        DataNote::IndexIgnored { .. } => "IndexIgnored",
        DataNote::MoreEqualTimes { .. } => "MoreEqualTimes",
        DataNote::InputJoined { .. } => "InputJoined",
    }
}
#[cfg(test)]
const DATA_NOTE_VARIANTS: usize = 17;

fn named(position: usize, name: &str) -> Column {
    Column {
        position,
        name: Some(name.into()),
    }
}

fn unnamed(position: usize) -> Column {
    Column {
        position,
        name: None,
    }
}

fn data_notes() -> Vec<DataNote> {
    let two = ColumnList {
        shown: vec![named(2, "u1"), named(3, "u2")],
        more: 0,
    };
    vec![
        DataNote::Utf16,
        DataNote::Latin1,
        DataNote::ReadAs {
            separator: Separator::Semicolon,
            decimal_comma: true,
            header: HeaderFound::Row { line: 1 },
        },
        DataNote::SamplingPeriodUnused {
            sampling_period: 0.1,
            time: named(1, "t"),
        },
        DataNote::OutputOnlyLeft {
            output: named(3, "T1"),
        },
        DataNote::PastedTuy,
        DataNote::InputNotGuessed {
            columns: 300,
            limit: 256,
        },
        DataNote::InputGuessed { input: unnamed(2) },
        DataNote::SeveralInputs { columns: two },
        DataNote::GeneratedTime {
            sampling_period: 0.094,
        },
        DataNote::MissingValues {
            lines: vec![4, 5, 6],
            total: 3,
        },
        DataNote::StepBetweenEqualTimes {
            first: 2,
            second: 3,
            time: 0.0,
            before: 0.0,
            after: 50.0,
        },
        DataNote::EqualTimes {
            first: 7,
            second: 8,
            time: 1.5,
        },
        DataNote::Window {
            first: 37,
            last: 313,
            count: 384,
            start: 3.4,
            end: 29.3,
        },
        DataNote::IndexIgnored {
            columns: ColumnList {
                shown: vec![unnamed(1)],
                more: 0,
            },
        },
        DataNote::InputJoined { held_back: 1 },
        DataNote::MoreEqualTimes { pairs: 4 },
    ]
}

fn data_error_id(e: &DataError) -> &'static str {
    match e {
        DataError::Io { .. } => "Io",
        DataError::Binary { .. } => "Binary",
        DataError::Empty => "Empty",
        DataError::NoData { .. } => "NoData",
        DataError::TooFewSamples { .. } => "TooFewSamples",
        DataError::NotANumber { .. } => "NotANumber",
        DataError::TimeMissing { .. } => "TimeMissing",
        DataError::TimeNotIncreasing { .. } => "TimeNotIncreasing",
        DataError::Ragged { .. } => "Ragged",
        DataError::UnknownColumn { .. } => "UnknownColumn",
        DataError::NoSuchPosition { .. } => "NoSuchPosition",
        DataError::NoTime { .. } => "NoTime",
        DataError::SameColumn { .. } => "SameColumn",
        DataError::AmbiguousOutput { .. } => "AmbiguousOutput",
        DataError::NoOutput { .. } => "NoOutput",
        DataError::BadSamplingPeriod(_) => "BadSamplingPeriod",
        DataError::PasteColumns { .. } => "PasteColumns",
        DataError::NotAFile { .. } => "NotAFile",
        DataError::TooLarge { .. } => "TooLarge",
        DataError::TimeOverflow { .. } => "TimeOverflow",
        DataError::InputAfterOutput { .. } => "InputAfterOutput",
    }
}
#[cfg(test)]
const DATA_ERROR_VARIANTS: usize = 21;

fn data_errors() -> Vec<DataError> {
    let named_columns = Columns::Named(ColumnList {
        shown: vec![named(1, "t"), named(2, "u"), named(3, "y")],
        more: 2,
    });
    vec![
        DataError::Io {
            path: "step.csv".into(),
            kind: std::io::ErrorKind::NotFound,
            reason: "No such file or directory (os error 2)".into(),
        },
        DataError::Binary { line: 3 },
        DataError::Empty,
        DataError::NoData { lines: 4 },
        DataError::TooFewSamples {
            line: 3,
            found: 2,
            needed: 3,
        },
        DataError::NotANumber {
            line: 5,
            column: named(2, "y"),
            text: "abc".into(),
        },
        DataError::TimeMissing {
            line: 6,
            column: unnamed(1),
        },
        DataError::TimeNotIncreasing {
            line: 7,
            time: 0.5,
            previous: 0.6,
            first_column_assumed: true,
        },
        DataError::Ragged {
            line: 9,
            found: 2,
            expected: 3,
            reference: 1,
        },
        DataError::UnknownColumn {
            line: 1,
            role: Role::Output,
            name: "T9".into(),
            available: named_columns.clone(),
        },
        DataError::NoSuchPosition {
            line: 1,
            role: Role::Input,
            position: 7,
            available: Columns::Unnamed { count: 3 },
        },
        DataError::NoTime {
            line: 1,
            available: named_columns.clone(),
        },
        DataError::SameColumn {
            line: 1,
            first: Role::Time,
            second: Role::Output,
            column: named(1, "t"),
        },
        DataError::AmbiguousOutput {
            line: 1,
            candidates: ColumnList {
                shown: vec![named(2, "T1"), named(3, "T2")],
                more: 0,
            },
        },
        DataError::NoOutput {
            line: 1,
            available: named_columns,
        },
        DataError::BadSamplingPeriod(-1.0),
        DataError::PasteColumns { line: 1, found: 5 },
        DataError::NotAFile {
            path: "/tmp".into(),
            kind: FileKind::Directory,
        },
        DataError::TooLarge {
            what: Source::File,
            size: 1 << 31,
        },
        DataError::TimeOverflow {
            sampling_period: 1e308,
            rows: 10,
        },
        DataError::InputAfterOutput {
            input_start: 12.5,
            output_end: 10.0,
        },
    ]
}

fn evidence_id(e: &Evidence) -> &'static str {
    match e {
        Evidence::DeadTime { .. } => "DeadTime",
        Evidence::Offset { .. } => "Offset",
        Evidence::Oscillation { .. } => "Oscillation",
        Evidence::ExtraPole { .. } => "ExtraPole",
        Evidence::Zero { .. } => "Zero",
        Evidence::InverseResponse { .. } => "InverseResponse",
        Evidence::Integrator { .. } => "Integrator",
        Evidence::Drift { .. } => "Drift",
        Evidence::NoLongerPays { .. } => "NoLongerPays",
        Evidence::None => "None",
    }
}
#[cfg(test)]
const EVIDENCE_VARIANTS: usize = 10;

fn evidence() -> Vec<Evidence> {
    let bias = Bias {
        start: 5.0,
        end: 6.76,
        n: 12,
        mean: -0.31,
        same_sign: 0.92,
    };
    vec![
        Evidence::DeadTime {
            bias,
            td: 1.76,
            changes: 1,
        },
        Evidence::DeadTime {
            bias,
            td: 0.008,
            changes: 266,
        },
        Evidence::Offset {
            bias,
            y0_held: 20.9,
            y0_estimated: 21.3,
        },
        Evidence::Oscillation {
            period: Some(6.5),
            omega_d: Some(0.95),
            zeta: 0.19,
        },
        Evidence::ExtraPole {
            bias,
            added: Some((Param::Tp2, 12.0)),
        },
        Evidence::Zero {
            overshoot: 0.12,
            peak_time: Some(8.0),
            underdamped: false,
            tz: 3.0,
        },
        Evidence::InverseResponse {
            undershoot: 0.08,
            dip_time: Some(1.2),
            tz: -0.7,
        },
        Evidence::Integrator {
            slope: 0.2,
            per_time_constant: 0.4,
            trend_z: Some(5.1),
        },
        Evidence::Drift {
            tail: Some((0.01, 4.2)),
            drift: 0.012,
        },
        Evidence::NoLongerPays {
            param: Param::Drift,
            value: 0.0002,
            ci95: Some((-0.001, 0.0014)),
            criterion_delta: -3.2,
        },
        Evidence::None,
    ]
}

fn prepare_errors() -> Vec<PrepareError> {
    vec![
        PrepareError::BadRange {
            first: 0,
            last: 3,
            count: 10,
        },
        PrepareError::TooFewInWindow { kept: 2, needed: 3 },
        PrepareError::BadTimeRange {
            start: 5.0,
            end: 1.0,
        },
        PrepareError::BadCutoff(0.0),
        PrepareError::BadSamplingPeriod(0.0),
    ]
}

fn model_errors() -> Vec<ModelError> {
    vec![
        ModelError::BadCode("Q3".into()),
        ModelError::UnderdampedNeedsTwoPoles("P1U".into()),
        ModelError::BadValue {
            name: "Tp1",
            value: -1.0,
            requirement: Requirement::Positive,
        },
        ModelError::BadValue {
            name: "Kp",
            value: f64::INFINITY,
            requirement: Requirement::Finite,
        },
        ModelError::Overflow,
        ModelError::NotInModel("Tz"),
        ModelError::System(LtiError::NoPoles),
    ]
}

fn fit_errors() -> Vec<FitError> {
    vec![
        FitError::TooFewSamples { n: 2, p: 4 },
        FitError::BadStep(0.0),
        FitError::BadGuess(ModelError::NotInModel("Tz")),
        FitError::NonFiniteData,
        FitError::BadStepTime(f64::NAN),
        FitError::NonFiniteCost,
        FitError::Unrepresentable {
            param: "Kp",
            log10: 320.4,
        },
    ]
}

fn experiment_errors() -> Vec<ExperimentError> {
    vec![
        ExperimentError::NoStep,
        ExperimentError::BadStep(0.0),
        ExperimentError::Prepare(PrepareError::BadCutoff(-1.0)),
        ExperimentError::Model(ModelError::Overflow),
        ExperimentError::Fit(FitError::NonFiniteCost),
    ]
}

fn fit_warnings() -> Vec<FitWarning> {
    vec![
        FitWarning::AtBound {
            param: "Td".into(),
            bound: 0.0,
        },
        FitWarning::OverdampedUnderdamped { zeta: 1.2 },
        FitWarning::Alias {
            omega_d: 40.0,
            nyquist: 31.4,
            between_samples: 0.3,
        },
        FitWarning::NotIdentifiable { param: "Tz".into() },
        FitWarning::CombinationNotIdentifiable,
        FitWarning::LagsNotResolved {
            larger: "Tp1".into(),
            smaller: "Tp2".into(),
        },
        FitWarning::NotConverged,
        FitWarning::NoImprovement,
        FitWarning::Unrepresentable {
            statistic: "MSE".into(),
            log10: 600.3,
        },
        FitWarning::GainUndetermined {
            low: -140.0,
            high: 109.0,
        },
    ]
}

fn prepare_error_id(e: &PrepareError) -> &'static str {
    match e {
        PrepareError::BadRange { .. } => "BadRange",
        PrepareError::TooFewInWindow { .. } => "TooFewInWindow",
        PrepareError::BadTimeRange { .. } => "BadTimeRange",
        PrepareError::BadCutoff(_) => "BadCutoff",
        PrepareError::BadSamplingPeriod(_) => "BadSamplingPeriod",
    }
}

fn model_error_id(e: &ModelError) -> &'static str {
    match e {
        ModelError::BadCode(_) => "BadCode",
        ModelError::UnderdampedNeedsTwoPoles(_) => "UnderdampedNeedsTwoPoles",
        ModelError::BadValue { .. } => "BadValue",
        ModelError::Overflow => "Overflow",
        ModelError::NotInModel(_) => "NotInModel",
        ModelError::System(_) => "System",
    }
}

fn fit_error_id(e: &FitError) -> &'static str {
    match e {
        FitError::TooFewSamples { .. } => "TooFewSamples",
        FitError::BadStep(_) => "BadStep",
        FitError::BadGuess(_) => "BadGuess",
        FitError::NonFiniteData => "NonFiniteData",
        FitError::BadStepTime(_) => "BadStepTime",
        FitError::NonFiniteCost => "NonFiniteCost",
        FitError::Unrepresentable { .. } => "Unrepresentable",
    }
}

fn experiment_error_id(e: &ExperimentError) -> &'static str {
    match e {
        ExperimentError::NoStep => "NoStep",
        ExperimentError::BadStep(_) => "BadStep",
        ExperimentError::Prepare(_) => "Prepare",
        ExperimentError::Model(_) => "Model",
        ExperimentError::Fit(_) => "Fit",
    }
}

fn fit_warning_id(w: &FitWarning) -> &'static str {
    match w {
        FitWarning::AtBound { .. } => "AtBound",
        FitWarning::OverdampedUnderdamped { .. } => "OverdampedUnderdamped",
        FitWarning::Alias { .. } => "Alias",
        FitWarning::NotIdentifiable { .. } => "NotIdentifiable",
        FitWarning::CombinationNotIdentifiable => "CombinationNotIdentifiable",
        FitWarning::LagsNotResolved { .. } => "LagsNotResolved",
        FitWarning::NotConverged => "NotConverged",
        FitWarning::NoImprovement => "NoImprovement",
        FitWarning::Unrepresentable { .. } => "Unrepresentable",
        FitWarning::GainUndetermined { .. } => "GainUndetermined",
    }
}

/// Examples of every variant, one message each, with its id.
fn examples<T: Localize>(kind: &str, all: Vec<T>, id: fn(&T) -> &'static str) -> Vec<Message> {
    all.iter()
        .map(|x| Message::of(format!("ident::{kind}::{}", id(x)), x))
        .collect()
}

/// Every message of this module: an example of every variant of every fact.
pub fn messages() -> Vec<Message> {
    let mut all = examples("DataNote", data_notes(), data_note_id);
    all.extend(examples("DataError", data_errors(), data_error_id));
    all.extend(examples("Evidence", evidence(), evidence_id));
    all.extend(examples("PrepareError", prepare_errors(), prepare_error_id));
    all.extend(examples("ModelError", model_errors(), model_error_id));
    all.extend(examples("FitError", fit_errors(), fit_error_id));
    all.extend(examples(
        "ExperimentError",
        experiment_errors(),
        experiment_error_id,
    ));
    all.extend(examples("FitWarning", fit_warnings(), fit_warning_id));
    let requirements = [
        Requirement::Finite,
        Requirement::Positive,
        Requirement::NotNegative,
        Requirement::NotZero,
        Requirement::DelayNotNegative,
    ];
    all.extend(
        requirements
            .iter()
            .map(|r| Message::of(format!("ident::Requirement::{r:?}"), r)),
    );
    for place in [Where::Cli, Where::App] {
        all.push(Message {
            id: format!("ident::ExperimentError::NoStep::{place:?}"),
            en: experiment_error(&ExperimentError::NoStep, Lang::En, place),
            pt: experiment_error(&ExperimentError::NoStep, Lang::Pt, place),
        });
    }
    let terminations = [
        Termination::Gradient,
        Termination::SmallStep,
        Termination::SmallCostChange,
        Termination::IterationLimit,
        Termination::Cancelled,
        Termination::NoImprovement,
    ];
    all.extend(
        terminations
            .iter()
            .map(|t| Message::of(format!("ident::Termination::{t:?}"), t)),
    );
    let causes = [
        Cause::DeadTime,
        Cause::Offset,
        Cause::Oscillation,
        Cause::ExtraPole,
        Cause::Zero,
        Cause::InverseResponse,
        Cause::Integrator,
        Cause::Drift,
        Cause::None,
    ];
    for c in causes {
        all.push(Message::of(format!("ident::Cause::{c:?}"), &c));
        all.push(Message::of(format!("ident::Remedy::{c:?}"), &Remedy(c)));
    }
    for h in [
        Handle::FinalValue,
        Handle::DeadTime,
        Handle::TimeConstant,
        Handle::FirstPeak,
    ] {
        all.push(Message::said(format!("ident::Handle::{h:?}"), |lang| {
            format!("{} / {}", handle_label(h, lang), handle_help(h, lang))
        }));
    }
    for p in crate::models::ALL_PARAMS {
        all.push(Message::of(format!("ident::Param::{p:?}"), &Meaning(p)));
    }
    let whiteness = Some(Whiteness {
        outside: 3,
        lags: 40,
        runs_z: -2.5,
    });
    for ending in [
        Ending::Adequate,
        Ending::NotWhite,
        Ending::WithinRounding,
        Ending::StepLimit,
    ] {
        all.push(Message::of(
            format!("ident::Verdict::{ending:?}"),
            &Verdict {
                ending,
                whiteness,
                structure: None,
                artefacts: Default::default(),
            },
        ));
    }
    for kind in [
        FileKind::Directory,
        FileKind::NamedPipe,
        FileKind::Device,
        FileKind::Socket,
        FileKind::Special,
    ] {
        all.push(Message::of(format!("ident::FileKind::{kind:?}"), &kind));
    }
    for source in [Source::File, Source::Data, Source::Text, Source::Paste] {
        all.push(Message::of(format!("ident::Source::{source:?}"), &source));
    }
    for separator in [
        Separator::Semicolon,
        Separator::Tab,
        Separator::Comma,
        Separator::Whitespace,
    ] {
        all.push(Message::of(
            format!("ident::Separator::{separator:?}"),
            &separator,
        ));
    }
    all.push(Message::of(
        "ident::Structure",
        &Structure {
            poles: 2,
            delay: true,
            underdamped: false,
            zero: false,
            integrator: false,
            free_offset: false,
            drift: true,
            lead: false,
            transient: false,
        },
    ));
    all.push(Message::of("ident::Ewma", &Ewma::new(0.6, 0.094)));
    all
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::{LoadOptions, load_str};
    use std::collections::BTreeSet;

    fn distinct<T>(all: &[T], id: fn(&T) -> &'static str) -> usize {
        all.iter().map(id).collect::<BTreeSet<_>>().len()
    }

    #[test]
    fn every_variant_has_an_example() {
        assert_eq!(distinct(&data_notes(), data_note_id), DATA_NOTE_VARIANTS);
        assert_eq!(distinct(&data_errors(), data_error_id), DATA_ERROR_VARIANTS);
        assert_eq!(distinct(&evidence(), evidence_id), EVIDENCE_VARIANTS);
        assert_eq!(distinct(&prepare_errors(), prepare_error_id), 5);
        assert_eq!(distinct(&model_errors(), model_error_id), 6);
        assert_eq!(distinct(&fit_errors(), fit_error_id), 7);
        assert_eq!(distinct(&experiment_errors(), experiment_error_id), 5);
        assert_eq!(distinct(&fit_warnings(), fit_warning_id), 10);
    }

    #[test]
    fn lines_are_listed_briefly() {
        assert_eq!(lines_text(&[4], 1, Lang::En), "line 4");
        assert_eq!(lines_text(&[4, 9, 12], 3, Lang::En), "lines 4, 9 and 12");
        assert_eq!(lines_text(&[4, 9, 12], 3, Lang::Pt), "linhas 4, 9 e 12");
        assert_eq!(lines_text(&[4], 2, Lang::En), "lines 4 and 1 more");
        let many: Vec<usize> = (1..=8).collect();
        assert_eq!(
            lines_text(&many, 20, Lang::En),
            "lines 1, 2, 3, 4, 5, 6, 7, 8 and 12 more"
        );
    }

    #[test]
    fn columns_are_listed_with_how_many_more() {
        let list = ColumnList {
            shown: (1..=20).map(|k| named(k, &k.to_string())).collect(),
            more: 5,
        };
        let text = available(&Columns::Named(list), Lang::En);
        assert!(text.ends_with("20 \"20\", … and 5 more"), "{text}");
    }

    #[test]
    fn a_note_reads_the_same_numbers_in_both_languages() {
        let t = load_str(
            "t;y\n0;1,5\n1;2,5\n2;3,5\n",
            &LoadOptions {
                sampling_period: Some(0.25),
                ..LoadOptions::default()
            },
        )
        .unwrap();
        let en: Vec<String> = t.notes.iter().map(|n| n.text(Lang::En)).collect();
        let pt: Vec<String> = t.notes.iter().map(|n| n.text(Lang::Pt)).collect();
        assert!(
            en.iter().any(|n| n.contains("(0.25 s) was not used")),
            "{en:?}"
        );
        assert!(
            pt.iter().any(|n| n.contains("(0,25 s) não foi usado")),
            "{pt:?}"
        );
        assert!(pt[0].starts_with("lido como separado por ponto e vírgula com vírgula decimal"));
    }

    #[test]
    fn errors_display_their_english_words() {
        let e = DataError::BadSamplingPeriod(-0.5);
        assert_eq!(e.to_string(), e.text(Lang::En));
        assert!(e.text(Lang::Pt).contains("-0,5"));
    }

    #[test]
    fn no_step_names_the_place_to_give_what_is_missing() {
        let e = ExperimentError::NoStep;
        assert!(!e.to_string().contains("--"));
        assert!(experiment_error(&e, Lang::Pt, Where::Cli).contains("--initial-input"));
        assert!(experiment_error(&e, Lang::En, Where::App).contains("Input before the record"));
    }
}
