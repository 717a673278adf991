//! `degrau step --batch`: one JSON system per line of stdin, one JSON reply per line of
//! stdout, in the input's order, each carrying the request's `id` and its line number.
//!
//! Lines are taken in blocks: what stdin has already delivered (at most [`BLOCK_LINES`]), so
//! a program that writes one line and waits for its reply gets it. Each block's replies,
//! metrics and JSON, are computed on every core and written in order.
//! Plain scoped threads rather than a pool crate: the jobs are independent and of similar
//! size, one `chunks` split is all the scheduling they need, and a dependency would buy
//! nothing here.

use std::io::{BufRead, BufWriter, Write};
use std::num::NonZero;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde::Serialize;
use serde_json::Value;

use super::{CliError, Report, SystemSpec};
use crate::lti::StepInfoOptions;
use crate::text::{Lang, Localize};

/// The most lines computed together (the reorder buffer's size).
pub const BLOCK_LINES: usize = 1024;

/// The bytes of stdin read at once (a pipe holds 64 KiB).
pub const READ_BYTES: usize = 1 << 18;

/// The lines a thread takes at a time (fewer than this in a block are not worth a second
/// thread).
const LINES_PER_TAKE: usize = 16;

/// One line of `--batch` output: the request's `id` (null when absent) and its 1-based line
/// number, then either the report's keys or `error`.
#[derive(Debug, Serialize)]
pub struct BatchReply {
    pub id: Value,
    pub line: usize,
    #[serde(flatten)]
    pub outcome: Outcome,
}

#[derive(Debug, Serialize)]
#[serde(untagged)]
pub enum Outcome {
    Report(Box<Report>),
    Error { error: String },
}

/// Reads JSON systems line by line from `input` and writes one JSON reply per line to
/// `output`, in order. Blank lines are skipped (replies carry their `line` number); a bad
/// line gets an `error` reply and the batch goes on. Fails only when reading or writing does.
pub fn run_batch(
    mut input: impl BufRead,
    output: impl Write,
    options: &StepInfoOptions,
) -> Result<(), CliError> {
    let threads = std::thread::available_parallelism().map_or(1, NonZero::get);
    let mut out = BufWriter::new(output);
    let mut next_line = 1;
    loop {
        let block = read_block(&mut input)?;
        if block.is_empty() {
            return Ok(());
        }
        for reply in replies(&block, next_line, options, threads) {
            out.write_all(&reply).map_err(CliError::WriteOutput)?;
        }
        next_line += block.len();
        out.flush().map_err(CliError::WriteOutput)?;
    }
}

/// The next lines of `input`: those it already holds (up to [`BLOCK_LINES`]), or when it
/// holds no whole line, the one line it delivers next. Empty at the end of the input. Only
/// an empty buffer is waited on: a writer that sends one line and waits for its reply is
/// answered.
fn read_block(input: &mut impl BufRead) -> Result<Vec<Vec<u8>>, CliError> {
    let available = input.fill_buf().map_err(CliError::ReadInput)?;
    let mut block: Vec<Vec<u8>> = available
        .split_inclusive(|&b| b == b'\n')
        .take_while(|line| line.ends_with(b"\n"))
        .take(BLOCK_LINES)
        .map(<[u8]>::to_vec)
        .collect();
    let used = block.iter().map(Vec::len).sum();
    input.consume(used);
    if block.is_empty() {
        let mut line = Vec::new();
        if input
            .read_until(b'\n', &mut line)
            .map_err(CliError::ReadInput)?
            > 0
        {
            block.push(line);
        }
    }
    Ok(block)
}

/// The JSON reply lines of `block` (empty for a blank line), its first line numbered
/// `first_line`, computed on up to `threads` threads and returned in order. The threads
/// take [`LINES_PER_TAKE`] lines at a time from a shared counter, so a run of high-order
/// systems does not hold the others up.
fn replies(
    block: &[Vec<u8>],
    first_line: usize,
    options: &StepInfoOptions,
    threads: usize,
) -> Vec<Vec<u8>> {
    let next = AtomicUsize::new(0);
    let work = || {
        let mut done = Vec::new();
        loop {
            let start = next.fetch_add(LINES_PER_TAKE, Ordering::Relaxed);
            let Some(lines) = block.get(start..(start + LINES_PER_TAKE).min(block.len())) else {
                return done;
            };
            for (i, bytes) in lines.iter().enumerate() {
                let line = start + i;
                done.push((line, reply_line(bytes, first_line + line, options)));
            }
        }
    };
    let helpers = threads
        .min(block.len().div_ceil(LINES_PER_TAKE))
        .saturating_sub(1);
    let mut done = std::thread::scope(|scope| {
        let others: Vec<_> = (0..helpers).map(|_| scope.spawn(work)).collect();
        let mut done = work();
        for handle in others {
            let part = handle
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            done.extend(part);
        }
        done
    });
    done.sort_unstable_by_key(|&(line, _)| line);
    done.into_iter().map(|(_, reply)| reply).collect()
}

/// One reply as a line of compact JSON (non-finite numbers become `null`); empty for a
/// blank line.
fn reply_line(bytes: &[u8], line: usize, options: &StepInfoOptions) -> Vec<u8> {
    let Some(reply) = batch_reply(bytes, line, options) else {
        return Vec::new();
    };
    let mut text = serde_json::to_vec(&reply).unwrap_or_else(|e| {
        let error = BatchReply {
            id: Value::Null,
            line,
            outcome: Outcome::Error {
                error: e.to_string(),
            },
        };
        serde_json::to_vec(&error).unwrap_or_default()
    });
    text.push(b'\n');
    text
}

/// The reply to one line of a batch; `None` for a blank line.
fn batch_reply(bytes: &[u8], line: usize, options: &StepInfoOptions) -> Option<BatchReply> {
    let (id, outcome) = match std::str::from_utf8(bytes) {
        Err(_) => (Value::Null, Err(CliError::NotUtf8)),
        Ok(text) if text.trim().is_empty() => return None,
        Ok(text) => {
            let (id, spec) = read_request(text.trim());
            (id, spec.and_then(|s| s.analyse(options)))
        }
    };
    let outcome = match outcome {
        Ok(analysis) => Outcome::Report(Box::new(Report::new(&analysis))),
        Err(e) => Outcome::Error {
            error: e.text(Lang::En),
        },
    };
    Some(BatchReply { id, line, outcome })
}

/// The `id` of a JSON request (null when absent or unreadable) and its system.
fn read_request(text: &str) -> (Value, Result<SystemSpec, CliError>) {
    let mut object = match serde_json::from_str::<Value>(text) {
        Ok(Value::Object(object)) => object,
        Ok(_) => return (Value::Null, Err(CliError::NotAnObject)),
        Err(e) => return (Value::Null, Err(CliError::JsonSyntax(e.to_string()))),
    };
    let id = object.remove("id").unwrap_or(Value::Null);
    let spec = serde_json::from_value(Value::Object(object))
        .map_err(|e| CliError::JsonFields(e.to_string()));
    (id, spec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_echoes_ids_in_order_and_skips_blank_lines() {
        let input = "{\"id\": \"a\", \"num\": [5], \"den\": [1, 5]}\n\n\
                     {\"id\": [1], \"num\": [1, 0, 0], \"den\": [1, 1]}\n\
                     not json\n\
                     {\"id\": 3, \"pole\": [[-1, 0]]}\n";
        let mut out = Vec::new();
        run_batch(input.as_bytes(), &mut out, &StepInfoOptions::default()).unwrap();
        let replies: Vec<Value> = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(replies.len(), 4);
        assert_eq!(replies[0]["id"], "a");
        assert!((replies[0]["rise_time"].as_f64().unwrap() - 9f64.ln() / 5.0).abs() < 1e-12);
        assert_eq!(replies[1]["id"], serde_json::json!([1]));
        assert_eq!(replies[1]["line"], 3);
        assert!(replies[1]["error"].as_str().unwrap().contains("improper"));
        assert_eq!(replies[2]["id"], Value::Null);
        assert!(
            replies[2]["error"]
                .as_str()
                .unwrap()
                .contains("not valid JSON")
        );
        assert!(
            replies[3]["error"]
                .as_str()
                .unwrap()
                .contains("unknown field `pole`")
        );
    }

    #[test]
    fn many_lines_on_many_threads_come_back_in_order() {
        let line = |i: usize| format!("{{\"id\": {i}, \"poles\": [[-{}, 0]]}}\n", i % 7 + 1);
        let input: String = (0..2 * BLOCK_LINES + 37).map(line).collect();
        for threads in [1, 2, 5] {
            let block: Vec<Vec<u8>> = input.lines().map(|l| l.as_bytes().to_vec()).collect();
            let replies = replies(&block, 1, &StepInfoOptions::default(), threads);
            for (i, reply) in replies.iter().enumerate() {
                let reply: Value = serde_json::from_slice(reply).unwrap();
                assert_eq!(
                    (reply["id"].as_u64(), reply["line"].as_u64()),
                    (Some(i as u64), Some(i as u64 + 1))
                );
                let tau = 1.0 / (i % 7 + 1) as f64;
                let rise = reply["rise_time"].as_f64().unwrap();
                assert!(
                    (rise - tau * 9f64.ln()).abs() < 1e-12 * tau.max(1.0),
                    "line {i}"
                );
            }
        }
        let mut out = Vec::new();
        run_batch(input.as_bytes(), &mut out, &StepInfoOptions::default()).unwrap();
        let ids: Vec<u64> = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| {
                serde_json::from_str::<Value>(l).unwrap()["id"]
                    .as_u64()
                    .unwrap()
            })
            .collect();
        assert_eq!(ids, (0..2 * BLOCK_LINES as u64 + 37).collect::<Vec<_>>());
    }
}
