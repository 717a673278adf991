//! What the loader refuses to read, and files of unusual shape: FIFOs, devices and
//! directories are refused before they are opened, files past [`MAX_FILE_BYTES`] before they
//! are read; files with 10⁵ columns load (in time linear in rows and columns: the bench
//! `data_load` measures it) and their messages stay short.

use crate::wide::wide_csv;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use degrau_ident::record::data::{
    ColumnChoice, DataError, FileKind, LoadOptions, MAX_FILE_BYTES, StepTest, load_file, load_str,
};
use degrau_words::{Lang, Localize};

/// A fresh path in the test's temporary directory (inside `target/`).
fn temp_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("data-files-{}-{name}", std::process::id()))
}

/// Loads on a thread and gives up after a minute, so a regression that blocks fails instead
/// of hanging the test run (this is a guard, not a timing assertion).
fn load_guarded(path: &Path) -> Result<StepTest, DataError> {
    let (tx, rx) = mpsc::channel();
    let path = path.to_path_buf();
    std::thread::spawn(move || {
        let _ = tx.send(load_file(&path, &LoadOptions::default()));
    });
    rx.recv_timeout(Duration::from_secs(60))
        .expect("the load returns instead of blocking")
}

#[test]
fn a_directory_is_refused() {
    let e = load_guarded(Path::new(env!("CARGO_TARGET_TMPDIR"))).unwrap_err();
    assert!(
        matches!(
            &e,
            DataError::NotAFile {
                kind: FileKind::Directory,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("is a directory, not a regular file"));
}

#[cfg(target_os = "linux")]
#[test]
fn devices_are_refused_before_reading() {
    for device in ["/dev/zero", "/dev/null", "/dev/urandom"] {
        let e = load_guarded(Path::new(device)).unwrap_err();
        assert_eq!(
            e,
            DataError::NotAFile {
                path: device.to_string(),
                kind: FileKind::Device
            }
        );
    }
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_waiting_for_a_writer() {
    let fifo = temp_path("step.fifo");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo {}", fifo.display());
    let result = load_guarded(&fifo);
    std::fs::remove_file(&fifo).ok();
    let e = result.unwrap_err();
    assert!(
        matches!(
            &e,
            DataError::NotAFile {
                kind: FileKind::NamedPipe,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn a_file_past_the_cap_is_refused_from_its_size() {
    // Sparse: no gigabyte is written or read.
    let path = temp_path("huge.csv");
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(MAX_FILE_BYTES + 1).unwrap();
    drop(file);
    let result = load_guarded(&path);
    std::fs::remove_file(&path).ok();
    match result {
        Err(DataError::TooLarge { size, .. }) => assert_eq!(size, MAX_FILE_BYTES + 1),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_missing_path_and_an_empty_file_say_so() {
    let e = load_guarded(&temp_path("missing.csv")).unwrap_err();
    assert!(matches!(e, DataError::Io { .. }), "{e:?}");
    let empty = temp_path("empty.csv");
    std::fs::write(&empty, "").unwrap();
    let result = load_guarded(&empty);
    std::fs::remove_file(&empty).ok();
    assert_eq!(result.unwrap_err(), DataError::Empty);
}

/// `t,y,c3,…` with `columns` columns and 5 rows: t = k, y = 10·k, column c = c + k·(c % 3 == 0).
fn wide(columns: usize, named_output: bool) -> String {
    let output = if named_output { "y" } else { "c2" };
    wide_csv(
        columns,
        output,
        |k| 10 * k,
        |c, k| c + if c % 3 == 0 { k } else { 0 },
    )
}

#[test]
fn a_hundred_thousand_columns_load() {
    let t = load_str(&wide(100_000, true), &LoadOptions::default()).unwrap();
    assert_eq!(t.time, [0.0, 1.0, 2.0, 3.0, 4.0]);
    assert_eq!(t.output, [0.0, 10.0, 20.0, 30.0, 40.0]);
    assert_eq!(t.input, None);
    assert!(
        t.notes
            .iter()
            .any(|n| n.text(Lang::En).contains("not guessed among the 99998")),
        "{:?}",
        t.notes
    );
    let by_position = LoadOptions {
        input: ColumnChoice::Position(99_999),
        ..LoadOptions::default()
    };
    let t = load_str(&wide(100_000, true), &by_position).unwrap();
    // Column 99999 is a multiple of 3: 99999 + k.
    assert_eq!(
        t.input.as_deref(),
        Some(&[99_999.0, 100_000.0, 100_001.0, 100_002.0, 100_003.0][..])
    );
    assert_eq!(t.input_name.as_deref(), Some("c99999"));
}

#[test]
fn messages_about_wide_files_stay_short() {
    let e = load_str(&wide(100_000, false), &LoadOptions::default()).unwrap_err();
    let message = e.to_string();
    assert!(matches!(e, DataError::AmbiguousOutput { .. }), "{e:?}");
    assert!(message.contains("… and 99979 more"), "{message}");
    assert!(message.len() < 1000, "{} bytes", message.len());
    let unknown = LoadOptions {
        output: ColumnChoice::Name("T9".into()),
        ..LoadOptions::default()
    };
    let message = load_str(&wide(100_000, true), &unknown)
        .unwrap_err()
        .to_string();
    assert!(message.contains("no column named \"T9\""), "{message}");
    assert!(message.len() < 1000, "{} bytes", message.len());
}

#[test]
fn a_wide_headerless_file_names_columns_by_position() {
    let text = "0 5 1\n1 5 2\n2 6 3\n3 6 4\n";
    let by_name = LoadOptions {
        output: ColumnChoice::Name("column 3".into()),
        ..LoadOptions::default()
    };
    let t = load_str(text, &by_name).unwrap();
    assert_eq!(t.output, [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(t.output_name, "column 3");
    assert_eq!(t.input.as_deref(), Some(&[5.0, 5.0, 6.0, 6.0][..]));
    let beyond = LoadOptions {
        output: ColumnChoice::Name("column 4".into()),
        ..LoadOptions::default()
    };
    assert!(matches!(
        load_str(text, &beyond),
        Err(DataError::UnknownColumn { .. })
    ));
}

#[test]
fn a_sampling_period_whose_times_overflow_is_refused() {
    let options = LoadOptions {
        sampling_period: Some(1e308),
        ..LoadOptions::default()
    };
    let e = load_str("y\n1\n2\n3\n", &options).unwrap_err();
    assert!(
        matches!(e, DataError::TimeOverflow { rows: 3, .. }),
        "{e:?}"
    );
}
