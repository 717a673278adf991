//! Loading measured step tests from text files: what a student exports from a data logger,
//! a spreadsheet, an oscilloscope or MATLAB, turned into time, output and (optionally)
//! input columns, with errors that name the line and the problem in plain words.
//!
//! # Formats
//! Comma-, tab- or semicolon-separated values, or whitespace-separated numbers as MATLAB's
//! `load` reads them (runs of spaces collapse); decimal commas (`0,5;1,25`, as Portuguese
//! spreadsheets export) are read as decimal points. The separator is detected from up to 20
//! data lines: the first of `;`, tab, `,`, whitespace that splits them into the same number
//! (≥ 2) of numeric cells. Blank lines and lines starting with `#` or `%` are skipped; the
//! first non-numeric line is the header. Without one, the last comment line before the data
//! with as many fields as the data (`# time, control output, …`) names the columns. In a
//! whitespace-separated file, a header whose names hold spaces (`time (s)   y`) cannot be
//! split into the columns: it is skipped and the columns are numbered (with a note).
//! `skip_rows` drops metadata lines at the top (counted as lines of the file). Header and
//! cells may be quoted. A UTF-8 BOM is ignored, UTF-16 (with BOM) is decoded, and a file that
//! is not UTF-8 is read as Latin-1 (with a note); a zero byte means a binary file.
//!
//! # Columns
//! Each of time, output and input is [`ColumnChoice::Auto`], chosen by name (case-insensitive;
//! a trailing unit in brackets, `time (s)`, `y [°C]`, is ignored) or by 1-based position, or
//! [`ColumnChoice::None`]. Automatically:
//! - **time** is the first column named as in [`TIME_NAMES`]; failing that, with a sampling
//!   period the file has no time column (t = k·Ts, k counting data rows from 0), and in a file
//!   without a header column 1 is the time (MATLAB's `[t y]` convention). A time column by
//!   name wins over a given sampling period (said in a note); choose `None` to force k·Ts.
//! - **output** and **input** are the first columns named as in [`OUTPUT_NAMES`] and
//!   [`INPUT_NAMES`] (earlier names in the list first).
//! - An unnamed input is guessed among the remaining columns: a column is *step-like* when
//!   it takes at most [`MAX_INPUT_LEVELS`] distinct values and changes once, or between at
//!   most 1 in 10 consecutive rows (a constant column qualifies). Exactly one step-like
//!   candidate is taken as the input (with a note); several are left alone (with a note).
//!   With more than [`MAX_GUESS_COLUMNS`] candidates the input is not guessed (a note says
//!   so): choose it.
//! - An unnamed output is the one column left; several left is an error listing them.
//! - A column with an empty header name (or pandas' `Unnamed: 0`), the row index pandas
//!   writes, is never chosen automatically.
//!
//! # Rows
//! Every row needs a time: a missing (empty, NaN) time is an error, as is a time smaller than
//! the previous one. Equal consecutive times are kept with a note; when the input changes
//! between them, the first row is the state just before the step (TCLab logs t = 0 twice).
//! Rows whose output or input is missing (empty, `NaN`, `NA`, `N/A`, `null`, `none`) are
//! skipped with a note naming their lines. Text (or ±inf) in a chosen column is an error;
//! columns that are not used are not read. Every row must have as many cells as the header
//! (one extra empty cell from a trailing separator is tolerated). At least [`MIN_SAMPLES`]
//! samples must remain. Nothing here panics, whatever the bytes.
//!
//! # Files
//! Only regular files are read: a directory, a FIFO, a device or a socket is refused before
//! it is opened (opening a FIFO waits for a writer; `/dev/zero` never ends). A file (or text)
//! larger than [`MAX_FILE_BYTES`] is refused from its size, and the read stops one byte past
//! the cap should the file grow while it is read.
//!
//! # Cost
//! Time is linear in the rows and the columns: the cells of a row are split once, only the
//! chosen columns are parsed and kept, and the candidates for an unnamed input are judged
//! as their values come, without keeping them. A kept row costs 8 bytes per chosen column
//! and 4 for its line number; the text is read once, whole.
//!
//! Hand-written rather than with the `csv` crate: `csv` cannot collapse runs of whitespace
//! (MATLAB `.dat`/`.txt`), knows no comment headers or decimal commas, and the formats are
//! line-based and simple. Cells are borrowed slices of the text (no allocation per cell), so
//! 10⁶ rows load well within a second.

use std::borrow::Cow;
use std::convert::Infallible;
use std::fs::{FileType, Metadata};
use std::io::Read;
use std::path::Path;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// The fewest samples a step test can have.
pub const MIN_SAMPLES: usize = 3;
/// Header names recognised as the time (after lower-casing and dropping a unit in brackets).
pub const TIME_NAMES: [&str; 8] = [
    "t", "time", "tempo", "tiempo", "t_s", "time_s", "tempo_s", "seconds",
];
/// Header names recognised as the output.
pub const OUTPUT_NAMES: [&str; 8] = [
    "y", "output", "saida", "saída", "pv", "t1", "salida", "resposta",
];
/// Header names recognised as the input.
pub const INPUT_NAMES: [&str; 8] = [
    "u",
    "input",
    "entrada",
    "control output",
    "q1",
    "q",
    "mv",
    "op",
];
/// A step-like column takes at most this many distinct values.
pub const MAX_INPUT_LEVELS: usize = 8;
/// The largest file (or text) read, 1 GiB: a step test is far smaller (10⁶ rows of t, u, y
/// take about 25 MB), and a larger one would only fill the memory.
pub const MAX_FILE_BYTES: u64 = 1 << 30;
/// The most columns an unnamed input is guessed among; with more, choose it.
pub const MAX_GUESS_COLUMNS: usize = 256;
/// Columns listed in a message before "and N more".
const LISTED_COLUMNS: usize = 20;
/// Characters of a cell or a name shown in a message before "…".
const SHOWN_CHARS: usize = 60;
/// Lines looked at to detect the separator.
const SAMPLE_LINES: usize = 20;
/// Lines listed in a note before "and N more".
const LISTED_LINES: usize = 8;

/// How a column is chosen.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum ColumnChoice {
    /// By the rules of the module docs.
    #[default]
    Auto,
    /// By header name, case-insensitive.
    Name(String),
    /// By 1-based position in the file (an index column counts).
    Position(usize),
    /// There is no such column (time: t = k·Ts; input: none).
    None,
}

impl FromStr for ColumnChoice {
    type Err = Infallible;

    /// `auto` (or empty), `none`, a 1-based position, or a name: as a command line takes it.
    fn from_str(s: &str) -> Result<Self, Infallible> {
        let s = s.trim();
        Ok(if s.is_empty() || s.eq_ignore_ascii_case("auto") {
            Self::Auto
        } else if s.eq_ignore_ascii_case("none") {
            Self::None
        } else if let Ok(p) = s.parse::<usize>() {
            Self::Position(p)
        } else {
            Self::Name(s.to_string())
        })
    }
}

/// What to read from a file.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct LoadOptions {
    pub time: ColumnChoice,
    pub output: ColumnChoice,
    pub input: ColumnChoice,
    /// Seconds between samples, for a file without a time column.
    pub sampling_period: Option<f64>,
    /// Lines of the file dropped before anything else (metadata).
    pub skip_rows: usize,
}

impl LoadOptions {
    /// Options from the column choices as a person types them (name, 1-based position,
    /// `auto` or empty, `none`); with a sampling period and no time column given, the file
    /// is read as having no time column.
    pub fn from_text(
        time: &str,
        output: &str,
        input: &str,
        sampling_period: Option<f64>,
        skip_rows: usize,
    ) -> Self {
        let choice = |t: &str| t.parse().unwrap_or(ColumnChoice::Auto);
        let time = if sampling_period.is_some() && time.trim().is_empty() {
            ColumnChoice::None
        } else {
            choice(time)
        };
        Self {
            time,
            output: choice(output),
            input: choice(input),
            sampling_period,
            skip_rows,
        }
    }
}

/// A measured step test, one sample per kept row.
#[derive(Debug, Clone, PartialEq)]
pub struct StepTest {
    /// Time of each sample (s), non-decreasing.
    pub time: Vec<f64>,
    pub output: Vec<f64>,
    pub input: Option<Vec<f64>>,
    /// The time column's header name, `column k` without a header, `k·Ts` when generated.
    pub time_name: String,
    pub output_name: String,
    pub input_name: Option<String>,
    /// The sampling period the time was generated from, when the file had no time column.
    pub sampling_period: Option<f64>,
    /// What the loader decided or skipped, as facts (`crate::words` says them).
    pub notes: Vec<DataNote>,
}

/// Which column a message is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Time,
    Output,
    Input,
}

/// A column named in a note or an error: its 1-based position and, when the file names its
/// columns, its name (at most 60 characters, then "…").
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Column {
    pub position: usize,
    pub name: Option<String>,
}

/// Some columns listed in a message: the first few, and how many more there are.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ColumnList {
    pub shown: Vec<Column>,
    pub more: usize,
}

/// The columns of a file, as a message offers them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Columns {
    /// No names (no header row): a column is chosen by position, 1 to `count`.
    Unnamed { count: usize },
    /// The named columns.
    Named(ColumnList),
}

/// How the cells of a line were found to be separated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Separator {
    Semicolon,
    Tab,
    Comma,
    /// Spaces or tabs, as MATLAB's `load` reads.
    Whitespace,
}

/// Where the column names came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeaderFound {
    /// A header row on this line.
    Row { line: usize },
    /// A comment line before the data.
    Comment { line: usize },
    /// A header row whose names do not split into the `columns` columns: not used, the
    /// columns numbered.
    Ignored { line: usize, columns: usize },
    /// No names: the columns are numbered.
    None,
}

/// What a path that is not a regular file is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    Directory,
    NamedPipe,
    Device,
    Socket,
    Special,
}

/// What was too large.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    File,
    Data,
    Text,
    Paste,
}

/// What the loader decided or skipped; lines are 1-based.
#[derive(Debug, Clone, PartialEq)]
pub enum DataNote {
    /// The file is UTF-16 text.
    Utf16,
    /// The file is not UTF-8: it was read as Latin-1.
    Latin1,
    /// How the table was read.
    ReadAs {
        separator: Separator,
        decimal_comma: bool,
        header: HeaderFound,
    },
    /// A sampling period was given, but the time is read from a column.
    SamplingPeriodUnused { sampling_period: f64, time: Column },
    /// The only column left was taken as the output.
    OutputOnlyLeft { output: Column },
    /// Three pasted columns were read as t, u, y.
    PastedTuy,
    /// The input was not guessed among so many unnamed columns (more than `limit`).
    InputNotGuessed { columns: usize, limit: usize },
    /// The one piecewise-constant column was taken as the input.
    InputGuessed { input: Column },
    /// Several columns look like an input; none was taken.
    SeveralInputs { columns: ColumnList },
    /// No time column: t = k·Ts.
    GeneratedTime { sampling_period: f64 },
    /// Rows whose output or input is missing were skipped (the first `lines` of `total`).
    MissingValues { lines: Vec<usize>, total: usize },
    /// Two rows share a time and the input changes between them: the first is the state
    /// just before the step.
    StepBetweenEqualTimes {
        first: usize,
        second: usize,
        time: f64,
        before: f64,
        after: f64,
    },
    /// Two rows share a time; both were kept.
    EqualTimes {
        first: usize,
        second: usize,
        time: f64,
    },
    /// A window kept samples `first` to `last` (1-based) of `count`, from `start` to `end` (s).
    Window {
        first: usize,
        last: usize,
        count: usize,
        start: f64,
        end: f64,
    },
    /// Columns without a name (a pandas row index) were not used.
    IndexIgnored { columns: ColumnList },
    /// More pairs of rows share a time than were listed.
    MoreEqualTimes { pairs: usize },
    /// The input came from a second file joined on time ([`super::join`]); the first
    /// `held_back` output samples came before its first instant and took its first value.
    InputJoined { held_back: usize },
}

/// Why a file could not be loaded; lines are 1-based, as an editor shows them.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum DataError {
    /// The system's reason (its own words, and its kind) for not reading `path`.
    Io {
        path: String,
        kind: std::io::ErrorKind,
        reason: String,
    },
    /// A zero byte: a binary file, not text.
    Binary {
        line: usize,
    },
    Empty,
    /// Every one of the `lines` lines is blank, a comment or skipped.
    NoData {
        lines: usize,
    },
    TooFewSamples {
        line: usize,
        found: usize,
        needed: usize,
    },
    /// `text` (shortened) in a chosen column is not a number.
    NotANumber {
        line: usize,
        column: Column,
        text: String,
    },
    TimeMissing {
        line: usize,
        column: Column,
    },
    TimeNotIncreasing {
        line: usize,
        time: f64,
        previous: f64,
        /// Column 1 was taken as the time because the file has no header.
        first_column_assumed: bool,
    },
    Ragged {
        line: usize,
        found: usize,
        expected: usize,
        reference: usize,
    },
    UnknownColumn {
        line: usize,
        role: Role,
        name: String,
        available: Columns,
    },
    NoSuchPosition {
        line: usize,
        role: Role,
        position: usize,
        available: Columns,
    },
    /// No column is named like a time and no sampling period was given.
    NoTime {
        line: usize,
        available: Columns,
    },
    SameColumn {
        line: usize,
        first: Role,
        second: Role,
        column: Column,
    },
    AmbiguousOutput {
        line: usize,
        candidates: ColumnList,
    },
    NoOutput {
        line: usize,
        available: Columns,
    },
    BadSamplingPeriod(f64),
    PasteColumns {
        line: usize,
        found: usize,
    },
    NotAFile {
        path: String,
        kind: FileKind,
    },
    /// `what` has `size` bytes or more, over [`MAX_FILE_BYTES`].
    TooLarge {
        what: Source,
        size: u64,
    },
    TimeOverflow {
        sampling_period: f64,
        rows: usize,
    },
    /// The input's file ([`super::join`]) starts after the output's last sample.
    InputAfterOutput {
        input_start: f64,
        output_end: f64,
    },
}

/// Loads a step test from a file (any of the formats of the module docs). Only a regular
/// file of at most [`MAX_FILE_BYTES`] is read: a directory, a FIFO or a device is refused
/// before it is opened (opening a FIFO waits for a writer; `/dev/zero` never ends).
pub fn load_file(path: impl AsRef<Path>, options: &LoadOptions) -> Result<StepTest, DataError> {
    let bytes = read_capped(path.as_ref())?;
    load_bytes(&bytes, options)
}

/// The bytes of a regular file of at most [`MAX_FILE_BYTES`].
fn read_capped(path: &Path) -> Result<Vec<u8>, DataError> {
    let shown = || path.display().to_string();
    let io = |e: std::io::Error| DataError::Io {
        path: shown(),
        kind: e.kind(),
        reason: e.to_string(),
    };
    // Checked before opening, then again on the file opened (had the path been replaced).
    check_regular(&shown, &std::fs::metadata(path).map_err(io)?)?;
    let file = std::fs::File::open(path).map_err(io)?;
    let metadata = file.metadata().map_err(io)?;
    check_regular(&shown, &metadata)?;
    let expected = usize::try_from(metadata.len()).unwrap_or(0);
    let mut bytes = Vec::with_capacity(expected.saturating_add(1));
    // A file growing while it is read stops one byte past the cap.
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    check_size(Source::File, bytes.len())?;
    Ok(bytes)
}

/// A regular file within the size cap, from its metadata.
fn check_regular(shown: &dyn Fn() -> String, metadata: &Metadata) -> Result<(), DataError> {
    if let Some(kind) = special_kind(&metadata.file_type()) {
        return Err(DataError::NotAFile {
            path: shown(),
            kind,
        });
    }
    if metadata.len() > MAX_FILE_BYTES {
        return Err(DataError::TooLarge {
            what: Source::File,
            size: metadata.len(),
        });
    }
    Ok(())
}

/// What a file that is not a regular file is, in words; `None` for a regular file.
fn special_kind(file_type: &FileType) -> Option<FileKind> {
    if file_type.is_file() {
        return None;
    }
    if file_type.is_dir() {
        return Some(FileKind::Directory);
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return Some(FileKind::NamedPipe);
        }
        if file_type.is_char_device() || file_type.is_block_device() {
            return Some(FileKind::Device);
        }
        if file_type.is_socket() {
            return Some(FileKind::Socket);
        }
    }
    Some(FileKind::Special)
}

/// Text (or bytes) of at most [`MAX_FILE_BYTES`].
fn check_size(what: Source, len: usize) -> Result<(), DataError> {
    let len = u64::try_from(len).unwrap_or(u64::MAX);
    if len > MAX_FILE_BYTES {
        return Err(DataError::TooLarge { what, size: len });
    }
    Ok(())
}

/// Loads a step test from the raw bytes of a file: UTF-8, UTF-16 with BOM, else Latin-1.
pub fn load_bytes(bytes: &[u8], options: &LoadOptions) -> Result<StepTest, DataError> {
    check_size(Source::Data, bytes.len())?;
    let (text, note) = decode(bytes)?;
    let mut test = load_str(&text, options)?;
    if let Some(note) = note {
        test.notes.insert(0, note);
    }
    Ok(test)
}

/// Loads a step test from text.
pub fn load_str(text: &str, options: &LoadOptions) -> Result<StepTest, DataError> {
    check_size(Source::Text, text.len())?;
    if let Some(ts) = options.sampling_period
        && !(ts.is_finite() && ts > 0.0)
    {
        return Err(DataError::BadSamplingPeriod(ts));
    }
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let layout = Layout::detect(text, options.skip_rows)?;
    load_with_layout(text, &layout, options, false)
}

/// Two or three columns pasted from a spreadsheet or the clipboard: names are used when
/// recognised; otherwise column 1 is the time, and of three columns the step-like one is the
/// input (t, u, y when that does not decide).
pub fn from_columns(text: &str) -> Result<StepTest, DataError> {
    check_size(Source::Paste, text.len())?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let layout = Layout::detect(text, 0)?;
    if !(2..=3).contains(&layout.columns) {
        return Err(DataError::PasteColumns {
            line: layout.defined_at,
            found: layout.columns,
        });
    }
    load_with_layout(text, &layout, &LoadOptions::default(), true)
}

/// Decodes a file's bytes; the note says when it was not UTF-8.
fn decode(bytes: &[u8]) -> Result<(Cow<'_, str>, Option<DataNote>), DataError> {
    let utf16 = |rest: &[u8], unit: fn([u8; 2]) -> u16| {
        let units = rest.chunks_exact(2).map(|c| unit([c[0], c[1]]));
        let text: String = char::decode_utf16(units)
            .map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER))
            .collect();
        (Cow::Owned(text), Some(DataNote::Utf16))
    };
    if let Some(rest) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return Ok(utf16(rest, u16::from_le_bytes));
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return Ok(utf16(rest, u16::from_be_bytes));
    }
    if let Some(zero) = bytes.iter().position(|&b| b == 0) {
        let line = 1 + bytes.iter().take(zero).filter(|&&b| b == b'\n').count();
        return Err(DataError::Binary { line });
    }
    Ok(match std::str::from_utf8(bytes) {
        Ok(text) => (Cow::Borrowed(text), None),
        Err(_) => (
            Cow::Owned(bytes.iter().map(|&b| char::from(b)).collect()),
            Some(DataNote::Latin1),
        ),
    })
}

// ---------------------------------------------------------------------------------------
// Lines, cells and fields

/// A non-blank line after the skipped rows.
enum Line<'a> {
    Comment(&'a str),
    Data(&'a str),
}

/// Non-blank lines with their 1-based numbers, the first `skip` lines dropped.
fn lines(text: &str, skip: usize) -> impl Iterator<Item = (usize, Line<'_>)> {
    text.split('\n')
        .enumerate()
        .skip(skip)
        .filter_map(|(i, raw)| {
            let trimmed = raw.trim();
            if trimmed.is_empty() {
                None
            } else if trimmed.starts_with('#') || trimmed.starts_with('%') {
                Some((i + 1, Line::Comment(trimmed)))
            } else {
                // Untrimmed: a leading tab is an empty first cell of a tab-separated row.
                Some((i + 1, Line::Data(raw.strip_suffix('\r').unwrap_or(raw))))
            }
        })
}

/// A cell's content.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cell {
    Value(f64),
    Missing,
    Text,
}

/// Reads a cell: a finite number (decimal point or a single decimal comma), a missing value,
/// or text.
fn parse_cell(s: &str) -> Cell {
    if s.is_empty() {
        return Cell::Missing;
    }
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Cell::Value(v),
        Ok(v) if v.is_nan() => Cell::Missing,
        Ok(_) => Cell::Text,
        Err(_) if is_missing_word(s) => Cell::Missing,
        Err(_) if s.contains(',') => parse_decimal_comma(s),
        Err(_) => Cell::Text,
    }
}

fn is_missing_word(s: &str) -> bool {
    ["na", "n/a", "null", "none"]
        .iter()
        .any(|w| s.eq_ignore_ascii_case(w))
}

/// `1,25` as 1.25, through a stack buffer (no allocation).
fn parse_decimal_comma(s: &str) -> Cell {
    let mut buf = [0u8; 64];
    let bytes = s.as_bytes();
    let commas = bytes.iter().filter(|&&b| b == b',').count();
    if commas != 1 || bytes.contains(&b'.') {
        return Cell::Text;
    }
    let Some(out) = buf.get_mut(..bytes.len()) else {
        return Cell::Text;
    };
    for (o, &b) in out.iter_mut().zip(bytes) {
        *o = if b == b',' { b'.' } else { b };
    }
    match std::str::from_utf8(out).map(str::parse::<f64>) {
        Ok(Ok(v)) if v.is_finite() => Cell::Value(v),
        _ => Cell::Text,
    }
}

/// How the cells of a line are separated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Delimiter {
    Char(char),
    Whitespace,
}

/// In order of preference when several split the data equally well.
const DELIMITERS: [Delimiter; 4] = [
    Delimiter::Char(';'),
    Delimiter::Char('\t'),
    Delimiter::Char(','),
    Delimiter::Whitespace,
];

impl Delimiter {
    fn separator(self) -> Separator {
        match self {
            Delimiter::Char(';') => Separator::Semicolon,
            Delimiter::Char('\t') => Separator::Tab,
            Delimiter::Char(_) => Separator::Comma,
            Delimiter::Whitespace => Separator::Whitespace,
        }
    }
}

/// The cells of a line, trimmed and unquoted, as slices of it.
struct Fields<'a> {
    rest: Option<&'a str>,
    delimiter: Delimiter,
}

fn fields(line: &str, delimiter: Delimiter) -> Fields<'_> {
    Fields {
        rest: Some(line),
        delimiter,
    }
}

/// A quoted cell's content and what follows the closing quote.
fn split_quoted(s: &str) -> Option<(&str, &str)> {
    let q = s.strip_prefix('"')?;
    Some(match q.find('"') {
        Some(j) => (&q[..j], &q[j + 1..]),
        None => (q, ""),
    })
}

impl<'a> Iterator for Fields<'a> {
    type Item = &'a str;

    fn next(&mut self) -> Option<&'a str> {
        let rest = self.rest?;
        match self.delimiter {
            Delimiter::Whitespace => {
                let s = rest.trim_start();
                if s.is_empty() {
                    self.rest = None;
                    return None;
                }
                let (field, after) = split_quoted(s).unwrap_or_else(|| {
                    let end = s.find(char::is_whitespace).unwrap_or(s.len());
                    s.split_at(end)
                });
                self.rest = Some(after);
                Some(field.trim())
            }
            Delimiter::Char(d) => {
                let s = rest.trim_start_matches(|c: char| c == ' ' || (c == '\t' && d != '\t'));
                if let Some((field, after)) = split_quoted(s) {
                    self.rest = after.find(d).map(|k| &after[k + d.len_utf8()..]);
                    return Some(field.trim());
                }
                Some(match s.find(d) {
                    Some(k) => {
                        self.rest = Some(&s[k + d.len_utf8()..]);
                        s[..k].trim()
                    }
                    None => {
                        self.rest = None;
                        s.trim()
                    }
                })
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Layout: separator, header, number of columns

/// Where the column names came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Header {
    /// A header row on this line.
    Row(usize),
    /// A comment line before the data.
    Comment(usize),
    /// A header row whose names do not split into the columns (whitespace-separated names
    /// with spaces): skipped, the columns numbered.
    Ignored(usize),
}

/// How a file's table is laid out.
#[derive(Debug, Clone, PartialEq)]
struct Layout {
    delimiter: Delimiter,
    decimal_comma: bool,
    header: Option<Header>,
    /// One per column from the header, or none (the columns are `column k`).
    names: Vec<String>,
    /// The names as matched against the known ones ([`normalise`]d), one per name.
    normalised: Vec<String>,
    columns: usize,
    /// The line that defines the columns: the header row, else the first data row.
    defined_at: usize,
}

impl Layout {
    fn detect(text: &str, skip: usize) -> Result<Self, DataError> {
        let mut comments = Vec::new();
        let mut data = Vec::new();
        for (no, line) in lines(text, skip) {
            match line {
                Line::Comment(c) if data.is_empty() => comments.push((no, c)),
                Line::Comment(_) => {}
                Line::Data(d) => data.push((no, d)),
            }
            if data.len() > SAMPLE_LINES {
                break;
            }
        }
        let Some(&(first_no, first)) = data.first() else {
            return Err(if text.trim().is_empty() {
                DataError::Empty
            } else {
                DataError::NoData {
                    lines: text.lines().count(),
                }
            });
        };
        let sample: Vec<&str> = data
            .iter()
            .skip(usize::from(data.len() > 1))
            .map(|d| d.1)
            .collect();
        let delimiter = choose_delimiter(&sample);
        let decimal_comma = sample.iter().any(|l| {
            fields(l, delimiter).any(|c| c.contains(',') && matches!(parse_cell(c), Cell::Value(_)))
        });
        let first_cells: Vec<&str> = fields(first, delimiter).collect();
        let is_header = first_cells.iter().any(|c| parse_cell(c) == Cell::Text);
        let mut layout = Self {
            delimiter,
            decimal_comma,
            header: None,
            names: Vec::new(),
            normalised: Vec::new(),
            columns: first_cells.len(),
            defined_at: first_no,
        };
        if is_header {
            layout.use_header_row(first_no, &first_cells, data.get(1).map(|d| d.1));
        } else if let Some((no, names)) = comment_header(&comments, delimiter, layout.columns) {
            layout.set_names(names);
            layout.header = Some(Header::Comment(no));
            layout.defined_at = no;
        }
        Ok(layout)
    }

    fn set_names(&mut self, names: Vec<String>) {
        self.normalised = names.iter().map(|n| normalise(n)).collect();
        self.names = names;
    }

    /// Takes the names of a header row, given the row after it.
    fn use_header_row(&mut self, no: usize, cells: &[&str], next: Option<&str>) {
        let mut names: Vec<String> = cells.iter().map(|c| c.to_string()).collect();
        let next: Option<Vec<&str>> = next.map(|l| fields(l, self.delimiter).collect());
        // A separator after the last name (the rows may end with one too).
        let trailing = names.len() > 1
            && names.last().is_some_and(String::is_empty)
            && next.as_ref().is_none_or(|c| {
                c.len() == names.len() - 1 || c.last().is_some_and(|x| x.is_empty())
            });
        if trailing {
            names.pop();
        }
        self.header = Some(Header::Row(no));
        match next.map(|c| c.len()) {
            // Names with spaces in a whitespace-separated file cannot be told apart.
            Some(n) if self.delimiter == Delimiter::Whitespace && n != names.len() => {
                self.columns = n;
                self.header = Some(Header::Ignored(no));
            }
            _ => {
                self.columns = names.len();
                self.set_names(names);
            }
        }
    }

    /// The line of the header row, which is not data.
    fn header_row(&self) -> Option<usize> {
        match self.header {
            Some(Header::Row(no) | Header::Ignored(no)) => Some(no),
            _ => None,
        }
    }

    /// Whether the columns have names.
    fn named(&self) -> bool {
        matches!(self.header, Some(Header::Row(_) | Header::Comment(_)))
    }

    /// A column in a message: its position, and its (shortened) name when the file has names.
    fn column(&self, column: usize) -> Column {
        Column {
            position: column + 1,
            name: self
                .named()
                .then(|| shorten(&self.name(column)).into_owned()),
        }
    }

    /// Some columns, for a message.
    fn list(&self, columns: impl ExactSizeIterator<Item = usize>) -> ColumnList {
        let total = columns.len();
        let shown: Vec<Column> = columns
            .take(LISTED_COLUMNS)
            .map(|i| self.column(i))
            .collect();
        ColumnList {
            more: total - shown.len(),
            shown,
        }
    }

    /// A column by name: exactly (ignoring case and quotes), else ignoring units; without
    /// names, `column k`.
    fn find(&self, name: &str) -> Option<usize> {
        let exact = name.trim().trim_matches('"').to_lowercase();
        if exact.is_empty() {
            return None;
        }
        if self.names.is_empty() {
            let k: usize = exact.strip_prefix("column")?.trim().parse().ok()?;
            return (1..=self.columns).contains(&k).then(|| k - 1);
        }
        self.names
            .iter()
            .position(|n| n.to_lowercase() == exact)
            .or_else(|| {
                let wanted = normalise(name);
                self.normalised.iter().position(|n| *n == wanted)
            })
    }

    /// The normalised name of a column, `None` without names.
    fn normalised(&self, column: usize) -> Option<&str> {
        self.normalised.get(column).map(String::as_str)
    }

    fn name(&self, column: usize) -> String {
        self.names
            .get(column)
            .cloned()
            .unwrap_or_else(|| format!("column {}", column + 1))
    }

    /// The columns, for a message.
    fn available(&self) -> Columns {
        if !self.named() {
            return Columns::Unnamed {
                count: self.columns,
            };
        }
        Columns::Named(self.list(0..self.columns))
    }

    /// How the table was read.
    fn note(&self) -> DataNote {
        DataNote::ReadAs {
            separator: self.delimiter.separator(),
            decimal_comma: self.decimal_comma,
            header: match self.header {
                Some(Header::Row(line)) => HeaderFound::Row { line },
                Some(Header::Comment(line)) => HeaderFound::Comment { line },
                Some(Header::Ignored(line)) => HeaderFound::Ignored {
                    line,
                    columns: self.columns,
                },
                None => HeaderFound::None,
            },
        }
    }
}

/// The separator that splits the sample lines into the most rows of equally many (≥ 2)
/// numeric cells; if none does, the first that splits the first line in two or more.
fn choose_delimiter(sample: &[&str]) -> Delimiter {
    let score = |d: Delimiter| -> usize {
        let Some(first) = sample.first() else {
            return 0;
        };
        let k = fields(first, d).count();
        if k < 2 {
            return 0;
        }
        let numeric_row = |l: &str| {
            let mut n = 0;
            fields(l, d).all(|c| {
                n += 1;
                parse_cell(c) != Cell::Text
            }) && n == k
        };
        sample.iter().filter(|l| numeric_row(l)).count()
    };
    let mut best = (0, None);
    for d in DELIMITERS {
        let s = score(d);
        if s > best.0 {
            best = (s, Some(d));
        }
    }
    best.1
        .or_else(|| {
            let first = sample.first()?;
            DELIMITERS
                .into_iter()
                .find(|&d| fields(first, d).count() >= 2)
        })
        .unwrap_or(Delimiter::Whitespace)
}

/// The last comment before the data that splits into `columns` names, not all numbers.
fn comment_header(
    comments: &[(usize, &str)],
    delimiter: Delimiter,
    columns: usize,
) -> Option<(usize, Vec<String>)> {
    comments.iter().rev().find_map(|&(no, c)| {
        let body = c.trim_start_matches(['#', '%']);
        let names: Vec<String> = fields(body, delimiter).map(str::to_string).collect();
        let named = names.iter().any(|n| parse_cell(n) == Cell::Text);
        (names.len() == columns && named).then_some((no, names))
    })
}

/// A header name as matched against the known names: lower case, unquoted, without a
/// trailing unit in brackets (`Time (s)` → `time`, `y(t)` → `y`).
fn normalise(name: &str) -> String {
    let mut n = name.trim().trim_matches('"').trim().to_lowercase();
    for (open, close) in [('(', ')'), ('[', ']')] {
        if n.ends_with(close)
            && let Some(k) = n.rfind(open)
            && k > 0
        {
            n.truncate(k);
            n = n.trim_end().to_string();
        }
    }
    n
}

/// A pandas row index: no name, or `Unnamed: k`.
#[cfg(test)]
fn is_index_name(name: &str) -> bool {
    is_index_normalised(&normalise(name))
}

/// [`is_index_name`] of a normalised name.
fn is_index_normalised(n: &str) -> bool {
    n.is_empty() || n.starts_with("unnamed")
}

/// Text for a message: at most [`SHOWN_CHARS`] characters, then "…".
fn shorten(text: &str) -> Cow<'_, str> {
    match text.char_indices().nth(SHOWN_CHARS) {
        Some((k, _)) => Cow::Owned(format!("{}…", &text[..k])),
        None => Cow::Borrowed(text),
    }
}

// ---------------------------------------------------------------------------------------
// Choosing the columns

/// The columns to read, decided before reading the rows (guesses need the values).
#[derive(Debug, Clone)]
struct Plan {
    time: Option<usize>,
    output: Option<usize>,
    input: Option<usize>,
    /// The input is to be guessed among `candidates`.
    guess_input: bool,
    /// Columns an automatic output or input may come from.
    candidates: Vec<usize>,
    notes: Vec<DataNote>,
}

impl Plan {
    fn new(layout: &Layout, options: &LoadOptions, paste: bool) -> Result<Self, DataError> {
        let excluded: Vec<bool> = (0..layout.columns)
            .map(|i| layout.named() && layout.normalised(i).is_some_and(is_index_normalised))
            .collect();
        let by_alias = |aliases: &[&str], taken: &[Option<usize>]| {
            aliases.iter().find_map(|alias| {
                (0..layout.columns).find(|&i| {
                    !excluded[i]
                        && !taken.contains(&Some(i))
                        && layout.normalised(i) == Some(*alias)
                })
            })
        };
        let mut notes = Vec::new();
        let time = match explicit(layout, Role::Time, &options.time)? {
            Some(i) => Some(i),
            None if options.time != ColumnChoice::Auto => None,
            None => by_alias(&TIME_NAMES, &[]).or_else(|| {
                let first_is_time = options.sampling_period.is_none()
                    && layout.columns >= 2
                    && (!layout.named() || paste);
                first_is_time.then_some(0)
            }),
        };
        match (time, options.sampling_period) {
            (None, None) => {
                return Err(DataError::NoTime {
                    line: layout.defined_at,
                    available: layout.available(),
                });
            }
            (Some(i), Some(ts)) => notes.push(DataNote::SamplingPeriodUnused {
                sampling_period: ts,
                time: layout.column(i),
            }),
            _ => {}
        }
        let output = match &options.output {
            ColumnChoice::None => {
                return Err(DataError::NoOutput {
                    line: layout.defined_at,
                    available: layout.available(),
                });
            }
            ColumnChoice::Auto => by_alias(&OUTPUT_NAMES, &[time]),
            choice => explicit(layout, Role::Output, choice)?,
        };
        let input = match &options.input {
            ColumnChoice::Auto => by_alias(&INPUT_NAMES, &[time, output]),
            choice => explicit(layout, Role::Input, choice)?,
        };
        check_distinct(
            layout,
            [
                (Role::Time, time),
                (Role::Output, output),
                (Role::Input, input),
            ],
        )?;
        let guess_input = options.input == ColumnChoice::Auto && input.is_none();
        let candidates = (0..layout.columns)
            .filter(|&i| !excluded[i] && ![time, output, input].contains(&Some(i)))
            .collect();
        if excluded.iter().any(|&e| e) && (output.is_none() || guess_input || time.is_none()) {
            let ignored: Vec<usize> = (0..layout.columns).filter(|&i| excluded[i]).collect();
            let mut columns = layout.list(ignored.into_iter());
            columns.shown.iter_mut().for_each(|c| c.name = None);
            notes.push(DataNote::IndexIgnored { columns });
        }
        Ok(Self {
            time,
            output,
            input,
            guess_input,
            candidates,
            notes,
        })
    }

    /// The columns to read, in file order: the chosen ones' values; the candidates' values
    /// when there are at most 3 (more cannot leave a single output; a guessed input among
    /// more is read again, [`Rows::reread_input`]), and whether they are step-like when the input
    /// is guessed among at most [`MAX_GUESS_COLUMNS`].
    fn reads(&self, capacity: usize) -> Vec<ColumnRead> {
        let chosen = [self.time, self.output, self.input];
        let guessing = self.output.is_none() || self.guess_input;
        let candidate_values = guessing && self.candidates.len() <= 3;
        let candidate_steps = self.guess_input && self.candidates.len() <= MAX_GUESS_COLUMNS;
        let mut reads: Vec<ColumnRead> = chosen
            .into_iter()
            .flatten()
            .map(|i| ColumnRead::new(i, Some(capacity), false))
            .collect();
        if candidate_values || candidate_steps {
            reads.extend(self.candidates.iter().map(|&i| {
                ColumnRead::new(i, candidate_values.then_some(capacity), candidate_steps)
            }));
        }
        reads.sort_by_key(|r| r.index);
        reads
    }

    /// Fills in the guessed input and the output left over, from the values read.
    fn finish(&mut self, layout: &Layout, rows: &Rows, paste: bool) -> Result<(), DataError> {
        if self.guess_input {
            self.guess_input_column(layout, rows);
        }
        if self.output.is_some() {
            return Ok(());
        }
        let left: Vec<usize> = self
            .candidates
            .iter()
            .copied()
            .filter(|&i| Some(i) != self.input)
            .collect();
        match left[..] {
            [only] => {
                self.output = Some(only);
                if layout.named() {
                    self.notes.push(DataNote::OutputOnlyLeft {
                        output: layout.column(only),
                    });
                }
                Ok(())
            }
            [] => Err(DataError::NoOutput {
                line: layout.defined_at,
                available: layout.available(),
            }),
            [.., last] if paste && self.input.is_none() && left.len() == 2 => {
                // A pasted t, u, y.
                self.output = Some(last);
                self.input = left.first().copied();
                self.notes.push(DataNote::PastedTuy);
                Ok(())
            }
            _ => Err(DataError::AmbiguousOutput {
                line: layout.defined_at,
                candidates: layout.list(left.iter().copied()),
            }),
        }
    }

    fn guess_input_column(&mut self, layout: &Layout, rows: &Rows) {
        if self.candidates.len() > MAX_GUESS_COLUMNS {
            self.notes.push(DataNote::InputNotGuessed {
                columns: self.candidates.len(),
                limit: MAX_GUESS_COLUMNS,
            });
            return;
        }
        let step_like: Vec<usize> = rows
            .columns
            .iter()
            .filter(|c| c.bad.is_none() && c.step.as_ref().is_some_and(StepLike::holds))
            .map(|c| c.index)
            .collect();
        let leaves_output = self.output.is_some() || self.candidates.len() >= 2;
        match step_like[..] {
            [only] if leaves_output => {
                self.input = Some(only);
                self.notes.push(DataNote::InputGuessed {
                    input: layout.column(only),
                });
            }
            [_, _, ..] => self.notes.push(DataNote::SeveralInputs {
                columns: layout.list(step_like.iter().copied()),
            }),
            _ => {}
        }
    }
}

/// A column chosen by name or position (`None` for Auto and None).
fn explicit(
    layout: &Layout,
    role: Role,
    choice: &ColumnChoice,
) -> Result<Option<usize>, DataError> {
    match choice {
        ColumnChoice::Name(name) => {
            layout
                .find(name)
                .map(Some)
                .ok_or_else(|| DataError::UnknownColumn {
                    line: layout.defined_at,
                    role,
                    name: name.clone(),
                    available: layout.available(),
                })
        }
        ColumnChoice::Position(p) if (1..=layout.columns).contains(p) => Ok(Some(p - 1)),
        ColumnChoice::Position(p) => Err(DataError::NoSuchPosition {
            line: layout.defined_at,
            role,
            position: *p,
            available: layout.available(),
        }),
        ColumnChoice::Auto | ColumnChoice::None => Ok(None),
    }
}

fn check_distinct(layout: &Layout, chosen: [(Role, Option<usize>); 3]) -> Result<(), DataError> {
    for (k, &(first, a)) in chosen.iter().enumerate() {
        for &(second, b) in &chosen[k + 1..] {
            if let (Some(a), Some(b)) = (a, b)
                && a == b
            {
                if layout.columns == 1 && first == Role::Time {
                    // One column, asked to be the time too: the file has no time column.
                    return Err(DataError::NoTime {
                        line: layout.defined_at,
                        available: layout.available(),
                    });
                }
                return Err(DataError::SameColumn {
                    line: layout.defined_at,
                    first,
                    second,
                    column: layout.column(a),
                });
            }
        }
    }
    Ok(())
}

/// Whether a column is step-like, decided value by value: at most [`MAX_INPUT_LEVELS`]
/// distinct values (missing ones aside), changing once or between at most 1 in 10
/// consecutive present values.
#[derive(Debug, Clone, Default)]
struct StepLike {
    present: usize,
    changes: usize,
    last: Option<f64>,
    levels: [f64; MAX_INPUT_LEVELS],
    level_count: usize,
    too_many_levels: bool,
}

impl StepLike {
    fn push(&mut self, v: f64) {
        if v.is_nan() {
            return;
        }
        self.present += 1;
        if self.last.is_some_and(|last| last != v) {
            self.changes += 1;
        }
        self.last = Some(v);
        let known = &self.levels[..self.level_count];
        if self.too_many_levels || known.contains(&v) {
            return;
        }
        match self.levels.get_mut(self.level_count) {
            Some(slot) => {
                *slot = v;
                self.level_count += 1;
            }
            None => self.too_many_levels = true,
        }
    }

    fn holds(&self) -> bool {
        let rare_changes = self.changes <= 1 || self.changes * 10 <= self.present;
        self.present > 0 && rare_changes && !self.too_many_levels
    }
}

/// [`StepLike`] of a whole column.
#[cfg(test)]
fn is_step_like(values: &[f64]) -> bool {
    let mut s = StepLike::default();
    values.iter().for_each(|&v| s.push(v));
    s.holds()
}

// ---------------------------------------------------------------------------------------
// Reading the rows

/// What is read of one column: its values (NaN marks a missing cell), its first text cell,
/// whether it is step-like.
struct ColumnRead {
    /// 0-based position in the row.
    index: usize,
    values: Option<Vec<f64>>,
    bad: Option<(usize, String)>,
    step: Option<StepLike>,
}

impl ColumnRead {
    fn new(index: usize, capacity: Option<usize>, step: bool) -> Self {
        Self {
            index,
            values: capacity.map(Vec::with_capacity),
            bad: None,
            step: step.then(StepLike::default),
        }
    }

    fn push(&mut self, line: usize, cell: &str) {
        let v = match parse_cell(cell) {
            Cell::Value(v) => v,
            Cell::Missing => f64::NAN,
            Cell::Text => {
                if self.bad.is_none() {
                    self.bad = Some((line, shorten(cell).into_owned()));
                }
                f64::NAN
            }
        };
        if let Some(values) = self.values.as_mut() {
            values.push(v);
        }
        if let Some(step) = self.step.as_mut() {
            step.push(v);
        }
    }
}

/// The columns read from every data row.
struct Rows {
    /// File line of each row (the text is at most [`MAX_FILE_BYTES`], so lines fit).
    lines: Vec<u32>,
    /// In file order.
    columns: Vec<ColumnRead>,
    /// The last line looked at.
    last_line: usize,
}

impl Rows {
    /// Reads `columns` (from [`Plan::reads`], in file order) of every data row; `capacity`
    /// is at least the number of rows ([`row_bound`]).
    fn read(
        text: &str,
        skip: usize,
        layout: &Layout,
        columns: Vec<ColumnRead>,
        capacity: usize,
    ) -> Result<Self, DataError> {
        let mut rows = Self {
            lines: Vec::with_capacity(capacity),
            columns,
            last_line: layout.defined_at,
        };
        let header_row = layout.header_row();
        for (no, line) in lines(text, skip) {
            rows.last_line = no;
            let Line::Data(line) = line else { continue };
            if Some(no) == header_row {
                continue;
            }
            rows.read_row(no, line, layout)?;
        }
        Ok(rows)
    }

    fn read_row(&mut self, no: usize, line: &str, layout: &Layout) -> Result<(), DataError> {
        let mut count = 0;
        let mut last_empty = false;
        let mut next = 0;
        for (c, cell) in fields(line, layout.delimiter).enumerate() {
            count += 1;
            last_empty = cell.is_empty();
            if let Some(column) = self.columns.get_mut(next).filter(|r| r.index == c) {
                column.push(no, cell);
                next += 1;
            }
        }
        let tolerated = count == layout.columns + 1 && last_empty;
        if count != layout.columns && !tolerated {
            return Err(DataError::Ragged {
                line: no,
                found: count,
                expected: layout.columns,
                reference: layout.defined_at,
            });
        }
        self.lines.push(u32::try_from(no).unwrap_or(u32::MAX));
        Ok(())
    }

    /// The values of a guessed input that was judged without keeping them, read again.
    fn reread_input(
        &mut self,
        text: &str,
        skip: usize,
        layout: &Layout,
        input: Option<usize>,
    ) -> Result<(), DataError> {
        let Some(i) = input else { return Ok(()) };
        let Some(k) = self.columns.iter().position(|c| c.index == i) else {
            return Ok(());
        };
        if self.columns[k].values.is_none() {
            let capacity = self.lines.len();
            let again = vec![ColumnRead::new(i, Some(capacity), false)];
            let mut rows = Self::read(text, skip, layout, again, capacity)?;
            if let Some(column) = rows.columns.pop() {
                self.columns[k] = column;
            }
        }
        Ok(())
    }

    fn bad_at(&self, i: usize) -> Option<&(usize, String)> {
        self.columns.iter().find(|c| c.index == i)?.bad.as_ref()
    }

    fn take(&mut self, i: usize) -> Vec<f64> {
        self.columns
            .iter_mut()
            .find(|c| c.index == i)
            .and_then(|c| c.values.take())
            .unwrap_or_default()
    }
}

/// At least as many as the text's data rows: its lines.
fn row_bound(text: &str) -> usize {
    1 + text.bytes().filter(|&b| b == b'\n').count()
}

fn load_with_layout(
    text: &str,
    layout: &Layout,
    options: &LoadOptions,
    paste: bool,
) -> Result<StepTest, DataError> {
    let mut plan = Plan::new(layout, options, paste)?;
    let capacity = row_bound(text);
    let reads = plan.reads(capacity);
    let mut rows = Rows::read(text, options.skip_rows, layout, reads, capacity)?;
    plan.finish(layout, &rows, paste)?;
    rows.reread_input(text, options.skip_rows, layout, plan.input)?;
    let output = plan.output.ok_or_else(|| DataError::NoOutput {
        line: layout.defined_at,
        available: layout.available(),
    })?;
    let chosen = [plan.time, Some(output), plan.input];
    if let Some((line, column, text)) = chosen
        .iter()
        .flatten()
        .filter_map(|&i| {
            rows.bad_at(i)
                .map(|(l, t)| (*l, layout.column(i), t.clone()))
        })
        .min_by_key(|b| b.0)
    {
        return Err(DataError::NotANumber { line, column, text });
    }

    let time = match plan.time {
        Some(i) => {
            let time = rows.take(i);
            let assumed = !layout.named();
            check_time(&time, &rows.lines, layout.column(i), assumed)?;
            time
        }
        None => {
            let ts = options.sampling_period.unwrap_or(1.0);
            plan.notes.push(DataNote::GeneratedTime {
                sampling_period: ts,
            });
            let time: Vec<f64> = (0..rows.lines.len()).map(|k| k as f64 * ts).collect();
            if time.last().is_some_and(|t| !t.is_finite()) {
                return Err(DataError::TimeOverflow {
                    sampling_period: ts,
                    rows: time.len(),
                });
            }
            time
        }
    };
    let output_values = rows.take(output);
    let input_values = plan.input.map(|i| rows.take(i));
    let mut test = StepTest {
        time,
        output: output_values,
        input: input_values,
        time_name: plan
            .time
            .map_or_else(|| "k·Ts".to_string(), |i| layout.name(i)),
        output_name: layout.name(output),
        input_name: plan.input.map(|i| layout.name(i)),
        sampling_period: plan
            .time
            .is_none()
            .then_some(options.sampling_period)
            .flatten(),
        notes: vec![layout.note()],
    };
    test.notes.append(&mut plan.notes);
    let lines = drop_missing(&mut test, std::mem::take(&mut rows.lines));
    note_equal_times(&mut test, &lines);
    test.time.shrink_to_fit();
    test.output.shrink_to_fit();
    if let Some(u) = test.input.as_mut() {
        u.shrink_to_fit();
    }
    if test.time.len() < MIN_SAMPLES {
        return Err(DataError::TooFewSamples {
            line: rows.last_line,
            found: test.time.len(),
            needed: MIN_SAMPLES,
        });
    }
    Ok(test)
}

/// Line `k` of a row list, as a line number.
fn line_of(lines: &[u32], k: usize) -> usize {
    lines.get(k).map_or(0, |&l| l as usize)
}

/// Every row has a time, and it never decreases.
fn check_time(
    time: &[f64],
    lines: &[u32],
    column: Column,
    first_column_assumed: bool,
) -> Result<(), DataError> {
    if let Some(k) = time.iter().position(|t| t.is_nan()) {
        return Err(DataError::TimeMissing {
            line: line_of(lines, k),
            column,
        });
    }
    match time.windows(2).position(|w| w[1] < w[0]) {
        Some(k) => Err(DataError::TimeNotIncreasing {
            line: line_of(lines, k + 1),
            time: time[k + 1],
            previous: time[k],
            first_column_assumed,
        }),
        None => Ok(()),
    }
}

/// Drops the rows whose output or input is missing, with a note; returns the kept rows' lines.
fn drop_missing(test: &mut StepTest, mut lines: Vec<u32>) -> Vec<u32> {
    let input = test.input.as_deref();
    let keep: Vec<bool> = (0..test.output.len())
        .map(|k| {
            !test.output[k].is_nan() && input.is_none_or(|u| u.get(k).is_some_and(|v| !v.is_nan()))
        })
        .collect();
    let mut dropped = keep.iter().zip(&lines).filter(|(k, _)| !**k);
    let total = dropped.clone().count();
    if total == 0 {
        return lines;
    }
    let shown: Vec<usize> = dropped
        .by_ref()
        .take(LISTED_LINES)
        .map(|(_, &l)| l as usize)
        .collect();
    test.notes.push(DataNote::MissingValues {
        lines: shown,
        total,
    });
    fn filter<T>(v: &mut Vec<T>, keep: &[bool]) {
        let mut flags = keep.iter();
        v.retain(|_| flags.next().copied().unwrap_or(false));
    }
    filter(&mut test.time, &keep);
    filter(&mut test.output, &keep);
    if let Some(u) = test.input.as_mut() {
        filter(u, &keep);
    }
    filter(&mut lines, &keep);
    lines.shrink_to_fit();
    lines
}

/// Notes the consecutive samples that share a time, saying which is before a step.
fn note_equal_times(test: &mut StepTest, lines: &[u32]) {
    let mut equal = (1..test.time.len()).filter(|&k| test.time[k] == test.time[k - 1]);
    let mut notes = Vec::new();
    for k in equal.by_ref().take(LISTED_LINES) {
        let (a, b, t) = (line_of(lines, k - 1), line_of(lines, k), test.time[k]);
        let change = test.input.as_deref().and_then(|u| {
            let (before, after) = (*u.get(k - 1)?, *u.get(k)?);
            (before != after).then_some((before, after))
        });
        notes.push(match change {
            Some((before, after)) => DataNote::StepBetweenEqualTimes {
                first: a,
                second: b,
                time: t,
                before,
                after,
            },
            None => DataNote::EqualTimes {
                first: a,
                second: b,
                time: t,
            },
        });
    }
    let more = equal.count();
    if more > 0 {
        notes.push(DataNote::MoreEqualTimes { pairs: more });
    }
    test.notes.append(&mut notes);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cells(line: &str, d: Delimiter) -> Vec<&str> {
        fields(line, d).collect()
    }

    #[test]
    fn fields_split_trim_and_unquote() {
        let ws = Delimiter::Whitespace;
        assert_eq!(
            cells("   0.00   9.000  129.320", ws),
            ["0.00", "9.000", "129.320"]
        );
        assert_eq!(cells("\"time (s)\" y", ws), ["time (s)", "y"]);
        let comma = Delimiter::Char(',');
        assert_eq!(cells("0.00000, 0.77618", comma), ["0.00000", "0.77618"]);
        assert_eq!(cells(",Time,Q1", comma), ["", "Time", "Q1"]);
        assert_eq!(cells("\"a, b\",c,", comma), ["a, b", "c", ""]);
        assert_eq!(cells("1\t\t3", Delimiter::Char('\t')), ["1", "", "3"]);
    }

    #[test]
    fn cells_read_numbers_missing_and_text() {
        assert_eq!(parse_cell("1.5e3"), Cell::Value(1500.0));
        assert_eq!(parse_cell("0,5"), Cell::Value(0.5));
        assert_eq!(parse_cell("-1,25"), Cell::Value(-1.25));
        assert_eq!(parse_cell("NaN"), Cell::Missing);
        assert_eq!(parse_cell("N/A"), Cell::Missing);
        assert_eq!(parse_cell(""), Cell::Missing);
        assert_eq!(parse_cell("inf"), Cell::Text);
        assert_eq!(parse_cell("1,2,3"), Cell::Text);
        assert_eq!(parse_cell("1.234,5"), Cell::Text);
        assert_eq!(parse_cell(&format!("0,{}", "1".repeat(80))), Cell::Text);
    }

    #[test]
    fn delimiter_is_detected() {
        assert_eq!(
            choose_delimiter(&["0,5;1,25", "1,0;2"]),
            Delimiter::Char(';')
        );
        assert_eq!(choose_delimiter(&["0.5\t1.25"]), Delimiter::Char('\t'));
        assert_eq!(choose_delimiter(&["0.5, 1.25"]), Delimiter::Char(','));
        assert_eq!(choose_delimiter(&["0,5 1,25"]), Delimiter::Whitespace);
        assert_eq!(choose_delimiter(&["  1  2  3"]), Delimiter::Whitespace);
        assert_eq!(choose_delimiter(&["t,y"]), Delimiter::Char(','));
        assert_eq!(choose_delimiter(&["42"]), Delimiter::Whitespace);
    }

    #[test]
    fn names_normalise_units_away() {
        assert_eq!(normalise(" \"Time (s)\" "), "time");
        assert_eq!(normalise("y [°C]"), "y");
        assert_eq!(normalise("u(t)"), "u");
        assert_eq!(normalise("SAÍDA"), "saída");
        assert_eq!(normalise("(s)"), "(s)");
        assert!(is_index_name("") && is_index_name("Unnamed: 0") && !is_index_name("t"));
    }

    #[test]
    fn step_like_rule() {
        let mut u = vec![0.0; 50];
        u.extend(vec![50.0; 50]);
        assert!(is_step_like(&u));
        assert!(is_step_like(&[3.0; 10]));
        let ramp: Vec<f64> = (0..100).map(f64::from).collect();
        assert!(!is_step_like(&ramp));
        let many_levels: Vec<f64> = (0..100).map(|k| f64::from(k / 10)).collect();
        assert!(!is_step_like(&many_levels), "10 levels");
        // A short record may change once, not more.
        assert!(is_step_like(&[0.0, 1.0, 1.0, 1.0]));
        assert!(!is_step_like(&[0.0, 1.0, 0.0, 1.0]));
    }

    #[test]
    fn column_choice_parses_like_a_command_line() {
        assert_eq!("T1".parse(), Ok(ColumnChoice::Name("T1".into())));
        assert_eq!("2".parse(), Ok(ColumnChoice::Position(2)));
        assert_eq!("none".parse(), Ok(ColumnChoice::None));
        assert_eq!("".parse(), Ok(ColumnChoice::Auto));
    }

    #[test]
    fn long_text_is_shortened_in_messages() {
        assert_eq!(shorten("T1"), "T1");
        let long = "é".repeat(100);
        assert_eq!(shorten(&long), format!("{}…", "é".repeat(SHOWN_CHARS)));
    }

    #[test]
    fn latin1_and_utf16_are_decoded() {
        let latin1 = b"tempo;sa\xedda\n0;1\n1;2\n2;3\n";
        let t = load_bytes(latin1, &LoadOptions::default()).unwrap();
        assert_eq!(t.output_name, "saída");
        assert_eq!(t.notes[0], DataNote::Latin1);
        let utf16: Vec<u8> = [0xFF, 0xFE]
            .into_iter()
            .chain(
                "t\ty\n0\t1\n1\t2\n2\t3\n"
                    .encode_utf16()
                    .flat_map(u16::to_le_bytes),
            )
            .collect();
        let t = load_bytes(&utf16, &LoadOptions::default()).unwrap();
        assert_eq!(t.output, [1.0, 2.0, 3.0]);
        assert_eq!(
            load_bytes(b"t,y\n0,1\n\x00\x01", &LoadOptions::default()),
            Err(DataError::Binary { line: 3 })
        );
    }
}
