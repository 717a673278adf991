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

use std::convert::Infallible;
use std::path::Path;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

mod cells;
mod columns;
mod file;
mod rows;
#[cfg(test)]
mod tests;

use columns::Layout;
use file::{check_size, decode, read_capped};
use rows::load_with_layout;

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
    /// The input came from a second file joined on time ([`crate::record::join`]); the first
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
    /// The input's file ([`crate::record::join`]) starts after the output's last sample.
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
