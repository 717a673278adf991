//! Cost of loading a measured step test: a generated CSV of 10⁶ rows (t, u, y; a unit step
//! into 1/(s + 1) sampled at 1 ms, about 24 MB) read from a temporary file by `load_file`,
//! columns detected automatically. Target: ≤ 1 s.
//!
//! Wide files: 10⁵ and 10⁶ columns (t, y and unnamed others) of 5 rows, so the time is
//! linear in the columns (it was quadratic: 1.5 s for 10⁵, minutes for 10⁶).
//!
//! Run: `cargo bench --bench data_load`.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use criterion::{Criterion, criterion_group, criterion_main};
use degrau::ident::record::data::{LoadOptions, load_file, load_str};

const ROWS: u32 = 1_000_000;

/// The file, written once into a temporary directory.
fn generated_file() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("degrau-bench-data-load-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join("million.csv");
    let mut text = String::with_capacity(32 * ROWS as usize);
    text.push_str("t,u,y\n");
    for k in 0..ROWS {
        let t = f64::from(k) * 0.001;
        let (u, y) = if k >= 10 {
            (1.0, 1.0 - (-(t - 0.01)).exp())
        } else {
            (0.0, 0.0)
        };
        // Writing to a String cannot fail.
        let _ = writeln!(text, "{t},{u},{y:.6}");
    }
    std::fs::write(&path, text).expect("the generated file");
    path
}

#[path = "../crates/ident/tests/wide/mod.rs"]
mod wide;

/// `t,y,c3,…,cN` and 5 rows of small integers.
fn wide_text(columns: usize) -> String {
    wide::wide_csv(columns, "y", |k| 2 * k, |c, k| (c + k) % 10)
}

fn bench(c: &mut Criterion) {
    let path = generated_file();
    let options = LoadOptions::default();
    let start = Instant::now();
    let test = load_file(&path, &options).expect("the generated file loads");
    println!(
        "one load of {} rows ({} MB): {:.3} s (target ≤ 1 s)",
        test.time.len(),
        std::fs::metadata(&path).map_or(0, |m| m.len() / 1_000_000),
        start.elapsed().as_secs_f64()
    );
    let mut group = c.benchmark_group("data_load");
    group.sample_size(10);
    group.bench_function("csv 10^6 rows t,u,y", |b| {
        b.iter(|| load_file(black_box(&path), black_box(&options)))
    });
    for columns in [100_000, 1_000_000] {
        let text = wide_text(columns);
        let start = Instant::now();
        let test = load_str(&text, &options).expect("the wide file loads");
        println!(
            "one load of {columns} columns × {} rows ({} MB): {:.3} s",
            test.time.len(),
            text.len() / 1_000_000,
            start.elapsed().as_secs_f64()
        );
        group.bench_function(format!("csv {columns} columns × 5 rows"), |b| {
            b.iter(|| load_str(black_box(&text), black_box(&options)))
        });
    }
    group.finish();
    if let Some(dir) = path.parent() {
        let _ = std::fs::remove_dir_all(dir);
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
