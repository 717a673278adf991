//! The words of the loader: columns and lines, and the notes on the data.

use super::*;

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
pub(super) fn columns_text(
    list: &ColumnList,
    lang: Lang,
    each: impl Fn(&Column) -> String,
) -> String {
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
pub(super) fn available(columns: &Columns, lang: Lang) -> String {
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
