//! `degrau exercise`: the instructor's kit. `make` writes hidden-effect challenges (records
//! as a lab logger writes them, `record_01.csv` …, and the answer key `key.json`; the same
//! seed gives the same bytes); `check` grades a class's answers against the key (text or
//! `--json`). Bad answer rows are reported by line and graded around; an unreadable key or
//! answers file is an error (exit code 2).

pub mod answers;
pub mod grade;
pub mod key;
mod make;

use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Subcommand, ValueEnum};

use crate::ident::challenge::Level;
use crate::text::Lang;
use crate::text::exercise::Line;

use super::CliError;

/// `degrau exercise` subcommands.
#[derive(Debug, Args)]
pub struct ExerciseArgs {
    #[command(subcommand)]
    pub command: ExerciseCommand,
}

#[derive(Debug, Subcommand)]
pub enum ExerciseCommand {
    /// Write N hidden-effect records (CSV) and their answer key (key.json) into a folder.
    Make(MakeArgs),
    /// Grade a class's answers (CSV: student,file,cause,structure,kp) against a key.
    Check(CheckArgs),
}

/// `degrau exercise make` options.
#[derive(Debug, Args)]
#[command(after_help = "Example:
  degrau exercise make --seed 7 --count 20 --level moderate --out lab3")]
pub struct MakeArgs {
    /// The seed: the same seed, count and level give byte-identical files.
    #[arg(long)]
    pub seed: u64,
    /// How many records (1 to 999).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=999))]
    pub count: u16,
    /// How plain the hidden effect is.
    #[arg(long, value_enum)]
    pub level: LevelArg,
    /// The folder to write into (made if missing).
    #[arg(long)]
    pub out: PathBuf,
}

/// `degrau exercise check` options.
#[derive(Debug, Args)]
#[command(after_help = "Example:
  degrau exercise check --key lab3/key.json --answers class.csv --json")]
pub struct CheckArgs {
    /// The key written by `degrau exercise make`.
    #[arg(long)]
    pub key: PathBuf,
    /// The answers: a CSV with the columns student,file,cause,structure,kp.
    #[arg(long)]
    pub answers: PathBuf,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// A level `--level` takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LevelArg {
    Clear,
    Moderate,
    Subtle,
}

impl From<LevelArg> for Level {
    fn from(l: LevelArg) -> Self {
        match l {
            LevelArg::Clear => Level::Clear,
            LevelArg::Moderate => Level::Moderate,
            LevelArg::Subtle => Level::Subtle,
        }
    }
}

/// What can go wrong (words in [`crate::text::exercise`]).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum ExerciseError {
    /// A file could not be read.
    Read {
        path: String,
        source: io::Error,
    },
    /// The folder or a file could not be written.
    Write {
        path: String,
        source: io::Error,
    },
    /// The key is not a key (serde_json's words).
    Key {
        path: String,
        reason: String,
    },
    /// The answers' header lacks columns.
    Columns {
        path: String,
        missing: Vec<String>,
    },
    Cli(#[from] CliError),
}

/// `degrau exercise …`.
pub fn main(args: &ExerciseArgs, lang: Lang) -> ExitCode {
    let result = match &args.command {
        ExerciseCommand::Make(m) => make::run(m, lang),
        ExerciseCommand::Check(c) => run_check(c, lang),
    };
    super::exit_code(
        result,
        |e| match e {
            ExerciseError::Cli(c) => Some(c),
            _ => None,
        },
        lang,
    )
}

fn read(path: &std::path::Path) -> Result<String, ExerciseError> {
    let bytes = std::fs::read(path).map_err(|source| ExerciseError::Read {
        path: path.display().to_string(),
        source,
    })?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// `degrau exercise check`.
fn run_check(args: &CheckArgs, lang: Lang) -> Result<(), ExerciseError> {
    let key_text = read(&args.key)?;
    let key: key::Key = serde_json::from_str(&key_text).map_err(|e| ExerciseError::Key {
        path: args.key.display().to_string(),
        reason: e.to_string(),
    })?;
    let text = read(&args.answers)?;
    let answers = answers::read(&text, &key).map_err(|m| ExerciseError::Columns {
        path: args.answers.display().to_string(),
        missing: m.0.iter().map(|c| c.to_string()).collect(),
    })?;
    let grading = grade::grade(&key, &answers);
    let mut out = io::stdout().lock();
    let written = if args.json {
        serde_json::to_writer(&mut out, &grading)
            .map_err(io::Error::other)
            .and_then(|()| writeln!(out))
    } else {
        writeln!(
            out,
            "{}",
            crate::text::exercise::grading_text(&grading, lang)
        )
    };
    written
        .and_then(|()| out.flush())
        .map_err(|e| ExerciseError::Cli(CliError::WriteOutput(e)))
}

/// Prints one line of words.
fn say(line: &Line, lang: Lang) -> Result<(), ExerciseError> {
    let mut out = io::stdout().lock();
    writeln!(out, "{}", crate::text::Localize::text(line, lang))
        .and_then(|()| out.flush())
        .map_err(|e| ExerciseError::Cli(CliError::WriteOutput(e)))
}
