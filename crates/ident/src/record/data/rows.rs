//! Reading the rows into a step test: the chosen columns' cells of every data row (ragged
//! rows refused), the time checked or generated, rows whose output or input is missing
//! dropped, and equal times noted.

use super::cells::{Line, fields, lines};
use super::columns::{ColumnRead, Layout, Plan};
use super::{Column, DataError, DataNote, LISTED_LINES, LoadOptions, MIN_SAMPLES, StepTest};

/// The columns read from every data row.
struct Rows {
    /// File line of each row (the text is at most [`MAX_FILE_BYTES`](super::MAX_FILE_BYTES),
    /// so lines fit).
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

pub(super) fn load_with_layout(
    text: &str,
    layout: &Layout,
    options: &LoadOptions,
    paste: bool,
) -> Result<StepTest, DataError> {
    let mut plan = Plan::new(layout, options, paste)?;
    let capacity = row_bound(text);
    let reads = plan.reads(capacity);
    let mut rows = Rows::read(text, options.skip_rows, layout, reads, capacity)?;
    plan.finish(layout, &rows.columns, paste)?;
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
