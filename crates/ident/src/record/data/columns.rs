//! The columns: the layout of a file's table (delimiter, header row or comment header,
//! normalised names, number of columns) and the plan of which column is the time, the output
//! and the input (explicit choices, known names, distinctness, an input guessed among the
//! step-like columns, the output left over), with what is read of each column.

use super::cells::{Cell, DELIMITERS, Delimiter, Line, fields, lines, parse_cell, shorten};
use super::{
    Column, ColumnChoice, ColumnList, Columns, DataError, DataNote, HeaderFound, INPUT_NAMES,
    LISTED_COLUMNS, LoadOptions, MAX_GUESS_COLUMNS, MAX_INPUT_LEVELS, OUTPUT_NAMES, Role,
    SAMPLE_LINES, TIME_NAMES,
};

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
pub(super) struct Layout {
    pub(super) delimiter: Delimiter,
    decimal_comma: bool,
    header: Option<Header>,
    /// One per column from the header, or none (the columns are `column k`).
    names: Vec<String>,
    /// The names as matched against the known ones ([`normalise`]d), one per name.
    normalised: Vec<String>,
    pub(super) columns: usize,
    /// The line that defines the columns: the header row, else the first data row.
    pub(super) defined_at: usize,
}

impl Layout {
    pub(super) fn detect(text: &str, skip: usize) -> Result<Self, DataError> {
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
    pub(super) fn header_row(&self) -> Option<usize> {
        match self.header {
            Some(Header::Row(no) | Header::Ignored(no)) => Some(no),
            _ => None,
        }
    }

    /// Whether the columns have names.
    pub(super) fn named(&self) -> bool {
        matches!(self.header, Some(Header::Row(_) | Header::Comment(_)))
    }

    /// A column in a message: its position, and its (shortened) name when the file has names.
    pub(super) fn column(&self, column: usize) -> Column {
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

    pub(super) fn name(&self, column: usize) -> String {
        self.names
            .get(column)
            .cloned()
            .unwrap_or_else(|| format!("column {}", column + 1))
    }

    /// The columns, for a message.
    pub(super) fn available(&self) -> Columns {
        if !self.named() {
            return Columns::Unnamed {
                count: self.columns,
            };
        }
        Columns::Named(self.list(0..self.columns))
    }

    /// How the table was read.
    pub(super) fn note(&self) -> DataNote {
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
pub(super) fn choose_delimiter(sample: &[&str]) -> Delimiter {
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
pub(super) fn normalise(name: &str) -> String {
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

/// A pandas row index, from its normalised name: no name, or `unnamed: k`.
pub(super) fn is_index_normalised(n: &str) -> bool {
    n.is_empty() || n.starts_with("unnamed")
}

// ---------------------------------------------------------------------------------------
// Choosing the columns

/// The columns to read, decided before reading the rows (guesses need the values).
#[derive(Debug, Clone)]
pub(super) struct Plan {
    pub(super) time: Option<usize>,
    pub(super) output: Option<usize>,
    pub(super) input: Option<usize>,
    /// The input is to be guessed among `candidates`.
    guess_input: bool,
    /// Columns an automatic output or input may come from.
    candidates: Vec<usize>,
    pub(super) notes: Vec<DataNote>,
}

impl Plan {
    pub(super) fn new(
        layout: &Layout,
        options: &LoadOptions,
        paste: bool,
    ) -> Result<Self, DataError> {
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
    /// more is read again, [`Rows::reread_input`](super::rows)), and whether they are
    /// step-like when the input is guessed among at most [`MAX_GUESS_COLUMNS`].
    pub(super) fn reads(&self, capacity: usize) -> Vec<ColumnRead> {
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
    pub(super) fn finish(
        &mut self,
        layout: &Layout,
        columns: &[ColumnRead],
        paste: bool,
    ) -> Result<(), DataError> {
        if self.guess_input {
            self.guess_input_column(layout, columns);
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

    fn guess_input_column(&mut self, layout: &Layout, columns: &[ColumnRead]) {
        if self.candidates.len() > MAX_GUESS_COLUMNS {
            self.notes.push(DataNote::InputNotGuessed {
                columns: self.candidates.len(),
                limit: MAX_GUESS_COLUMNS,
            });
            return;
        }
        let step_like: Vec<usize> = columns
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
pub(super) struct StepLike {
    present: usize,
    changes: usize,
    last: Option<f64>,
    levels: [f64; MAX_INPUT_LEVELS],
    level_count: usize,
    too_many_levels: bool,
}

impl StepLike {
    pub(super) fn push(&mut self, v: f64) {
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

    pub(super) fn holds(&self) -> bool {
        let rare_changes = self.changes <= 1 || self.changes * 10 <= self.present;
        self.present > 0 && rare_changes && !self.too_many_levels
    }
}

// ---------------------------------------------------------------------------------------
// What is read of a column

/// What is read of one column: its values (NaN marks a missing cell), its first text cell,
/// whether it is step-like.
pub(super) struct ColumnRead {
    /// 0-based position in the row.
    pub(super) index: usize,
    pub(super) values: Option<Vec<f64>>,
    pub(super) bad: Option<(usize, String)>,
    step: Option<StepLike>,
}

impl ColumnRead {
    pub(super) fn new(index: usize, capacity: Option<usize>, step: bool) -> Self {
        Self {
            index,
            values: capacity.map(Vec::with_capacity),
            bad: None,
            step: step.then(StepLike::default),
        }
    }

    pub(super) fn push(&mut self, line: usize, cell: &str) {
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
