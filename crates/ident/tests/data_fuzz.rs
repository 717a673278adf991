//! A re-runnable file fuzzer: mutated copies of every fixture in tests/data (truncations,
//! byte flips, inserted separators, NaN, huge and non-finite numbers, quotes, comment marks,
//! BOMs, zero bytes, long lines, wide rows), loaded with assorted options. Every outcome must
//! be a clean [`DataError`] with a message, or a [`StepTest`] whose every value is finite,
//! with consistent lengths, at least [`MIN_SAMPLES`] samples and a non-decreasing time.
//!
//! Deterministic: `DEGRAU_FUZZ_SEED` and `DEGRAU_FUZZ_CASES` (default 3000) choose the run;
//! `cargo test --test data_fuzz -- --nocapture` prints the outcomes by kind.

use std::collections::BTreeMap;

use degrau_ident::random::Lcg;

use degrau_ident::record::data::{
    ColumnChoice, DataError, LoadOptions, MIN_SAMPLES, StepTest, from_columns, load_bytes,
};

fn env_number(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Every fixture's bytes.
fn fixtures() -> Vec<(String, Vec<u8>)> {
    let dir = concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/tests/data");
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("tests/data")
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|e| {
            let bytes = std::fs::read(e.path()).ok()?;
            Some((e.file_name().to_string_lossy().into_owned(), bytes))
        })
        .collect();
    files.sort();
    assert!(files.len() >= 20, "the fixtures are there");
    files
}

/// Pieces inserted into a file.
const PIECES: [&str; 24] = [
    ",", ";", "\t", " ", "\n", "\r\n", "\"", "#", "%", "NaN", "nan", "inf", "-inf", "1e308",
    "-1e308", "1e309", "4.9e-324", "1,5", "0,5;1,25", "\u{feff}", "\0", "é", "N/A", ",,,,",
];

/// One mutation of `bytes`.
fn mutate(bytes: &mut Vec<u8>, rng: &mut Lcg) {
    let at = rng.below(bytes.len() + 1);
    match rng.below(7) {
        0 => bytes.truncate(at),
        1 if !bytes.is_empty() => {
            let k = at.min(bytes.len() - 1);
            bytes[k] ^= 1 << rng.below(8);
        }
        2 => {
            let line = "9".repeat(1 + rng.below(20_000));
            bytes.splice(at..at, line.into_bytes());
        }
        3 => {
            // A wide row of numbers.
            let row: String = (0..1 + rng.below(2_000)).map(|k| format!("{k},")).collect();
            bytes.splice(at..at, row.into_bytes());
        }
        4 if !bytes.is_empty() => {
            // A line repeated: rows with equal times, or a second header.
            let start = bytes[..at]
                .iter()
                .rposition(|&b| b == b'\n')
                .map_or(0, |k| k + 1);
            let end = bytes[at..]
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len(), |k| at + k + 1);
            let line = bytes[start..end].to_vec();
            bytes.splice(end..end, line);
        }
        _ => {
            let piece = rng.pick(&PIECES);
            bytes.splice(at..at, piece.bytes());
        }
    }
}

/// The default options half of the time (most files load), else assorted choices.
fn options(rng: &mut Lcg) -> LoadOptions {
    if rng.below(2) == 0 {
        return LoadOptions::default();
    }
    let choice = |rng: &mut Lcg| match rng.below(6) {
        0 => ColumnChoice::None,
        1 => ColumnChoice::Position(rng.below(5)),
        2 => ColumnChoice::Name(rng.pick(&["t", "y", "u", "T1", "time (s)", ""]).to_string()),
        _ => ColumnChoice::Auto,
    };
    LoadOptions {
        time: choice(rng),
        output: choice(rng),
        input: choice(rng),
        sampling_period: *rng.pick(&[None, None, Some(0.1), Some(1e308), Some(5e-324), Some(-1.0)]),
        skip_rows: *rng.pick(&[0, 0, 0, 1, 3]),
    }
}

/// The load's invariants; the outcome's kind for the tally.
fn check(result: &Result<StepTest, DataError>, what: &str) -> String {
    match result {
        Ok(t) => {
            let n = t.time.len();
            assert!(n >= MIN_SAMPLES, "{what}: {n} samples");
            assert_eq!(t.output.len(), n, "{what}");
            assert!(t.time.iter().all(|v| v.is_finite()), "{what}: time");
            assert!(t.output.iter().all(|v| v.is_finite()), "{what}: output");
            assert!(
                t.time.windows(2).all(|w| w[0] <= w[1]),
                "{what}: time order"
            );
            if let Some(u) = &t.input {
                assert_eq!(u.len(), n, "{what}");
                assert!(u.iter().all(|v| v.is_finite()), "{what}: input");
            }
            assert!(
                t.sampling_period
                    .is_none_or(|ts| ts.is_finite() && ts > 0.0)
            );
            "loaded".to_string()
        }
        Err(e) => {
            let message = e.to_string();
            assert!(
                !message.is_empty() && !message.contains("panicked"),
                "{what}"
            );
            assert!(
                message.len() < 4_000,
                "{what}: a {}-byte message",
                message.len()
            );
            let debug = format!("{e:?}");
            debug
                .split(|c: char| !c.is_alphanumeric())
                .next()
                .unwrap_or_default()
                .to_string()
        }
    }
}

#[test]
fn mutated_fixtures_load_or_fail_cleanly() {
    let seed = env_number("DEGRAU_FUZZ_SEED", 8);
    let cases = env_number("DEGRAU_FUZZ_CASES", 3000);
    let files = fixtures();
    let mut rng = Lcg(seed);
    let mut tally: BTreeMap<String, usize> = BTreeMap::new();
    for case in 0..cases {
        let (name, original) = rng.pick(&files);
        let mut bytes = original.clone();
        for _ in 0..1 + rng.below(4) {
            mutate(&mut bytes, &mut rng);
        }
        let o = options(&mut rng);
        let what = format!("case {case} (seed {seed}) from {name} with {o:?}");
        *tally
            .entry(check(&load_bytes(&bytes, &o), &what))
            .or_default() += 1;
        if let Ok(text) = std::str::from_utf8(&bytes) {
            let kind = check(&from_columns(text), &what);
            *tally.entry(format!("paste: {kind}")).or_default() += 1;
        }
    }
    println!("{cases} mutated files (seed {seed}), outcomes:");
    for (kind, count) in &tally {
        println!("  {kind:<28} {count}");
    }
    assert!(
        tally.get("loaded").is_some_and(|&n| n > 0),
        "some load: {tally:?}"
    );
    assert!(tally.len() > 5, "varied outcomes: {tally:?}");
}
