//! Loading measured step tests: the malformed and well-formed corpus in tests/data (each
//! gives a clear error naming its line, or a correct load, never a panic), the lab records
//! in tests/data/records (real ones where their licence allows, else synthetic stand-ins of
//! the same format: see its SOURCES.md), random bytes and lines, 10⁶ rows, and the measured step
//! characteristics of the LECI test of the notes.

use degrau_ident::record::data::{
    ColumnChoice, DataError, LoadOptions, Role, StepTest, from_columns, load_bytes, load_file,
    load_str,
};
use degrau_ident::record::prepare::{
    detect_step, final_level, measured_step_info, operating_point,
};
use degrau_lti::StepInfoOptions;
use degrau_words::{Lang, Localize};
use proptest::prelude::*;

fn corpus(name: &str) -> String {
    format!(
        "{}/tests/data/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/../..")
    )
}

fn record(name: &str) -> String {
    format!(
        "{}/tests/data/records/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/../..")
    )
}

fn load(path: &str, options: &LoadOptions) -> Result<StepTest, DataError> {
    load_file(path, options)
}

fn auto() -> LoadOptions {
    LoadOptions::default()
}

fn name(n: &str) -> ColumnChoice {
    ColumnChoice::Name(n.to_string())
}

/// The error of loading a file, with its message checked for the given words.
fn error_of(file: &str, options: &LoadOptions, words: &[&str]) -> DataError {
    let e = load(file, options).expect_err(file);
    let message = e.to_string();
    for w in words {
        assert!(message.contains(w), "{file}: {message:?} lacks {w:?}");
    }
    e
}

fn has_note(test: &StepTest, words: &[&str]) -> bool {
    test.notes
        .iter()
        .any(|n| words.iter().all(|w| n.text(Lang::En).contains(w)))
}

/// The corpus file `file` loaded with the default options, checked for a note holding every
/// one of `words`.
fn loaded_noting(file: &str, words: &[&str]) -> StepTest {
    let t = load(&corpus(file), &auto()).unwrap();
    assert!(has_note(&t, words), "{file}: {:?}", t.notes);
    t
}

// ----------------------------------------------------------------------------------------
// Malformed corpus

#[test]
fn empty_and_comment_only_files_say_so() {
    assert_eq!(load(&corpus("empty.csv"), &auto()), Err(DataError::Empty));
    error_of(
        &corpus("comments_only.txt"),
        &auto(),
        &["no data", "4 line(s)"],
    );
    assert!(matches!(from_columns(""), Err(DataError::Empty)));
}

#[test]
fn header_only_and_one_row_need_more_samples() {
    let e = error_of(
        &corpus("header_only.csv"),
        &auto(),
        &["line 1", "at least 3 samples"],
    );
    assert!(matches!(e, DataError::TooFewSamples { found: 0, .. }));
    let e = error_of(
        &corpus("one_row.csv"),
        &auto(),
        &["line 2", "1 sample", "at least 3"],
    );
    assert!(matches!(
        e,
        DataError::TooFewSamples {
            line: 2,
            found: 1,
            needed: 3
        }
    ));
}

#[test]
fn text_in_a_number_column_names_line_column_and_text() {
    let e = error_of(&corpus("text_in_number.csv"), &auto(), &[]);
    assert_eq!(
        e.to_string(),
        "line 7, column \"y\": \"abc\" is not a number"
    );
}

#[test]
fn missing_output_or_input_skips_rows_with_a_note() {
    let t = loaded_noting(
        "missing_values.csv",
        &["lines 4, 5 and 6", "missing", "skipped"],
    );
    assert_eq!(t.time, [0.0, 1.0, 5.0, 6.0]);
    assert_eq!(t.output, [0.0, 0.1, 1.0, 1.1]);
    assert_eq!(t.input.as_deref(), Some(&[0.0, 1.0, 1.0, 1.0][..]));
}

#[test]
fn missing_time_is_an_error() {
    let e = error_of(
        &corpus("nan_time.csv"),
        &auto(),
        &["line 5", "\"t\"", "time is missing"],
    );
    assert!(matches!(e, DataError::TimeMissing { line: 5, .. }));
}

#[test]
fn decreasing_time_names_the_line_and_both_times() {
    let e = error_of(&corpus("time_decreasing.csv"), &auto(), &[]);
    assert_eq!(
        e.to_string(),
        "line 12: time 3.1 comes after 3.5; the time must not decrease"
    );
}

#[test]
fn ragged_rows_name_the_line_and_the_counts() {
    let e = error_of(
        &corpus("ragged.csv"),
        &auto(),
        &["line 6 has 2 value(s), but line 1 has 3"],
    );
    assert!(matches!(
        e,
        DataError::Ragged {
            line: 6,
            found: 2,
            expected: 3,
            reference: 1
        }
    ));
}

#[test]
fn missing_columns_list_the_available_names() {
    let o = LoadOptions {
        output: name("T1"),
        ..auto()
    };
    let e = error_of(
        &corpus("text_in_number.csv"),
        &o,
        &[
            "line 1",
            "no column named \"T1\" for the output",
            "1 \"t\", 2 \"y\"",
        ],
    );
    assert!(matches!(
        e,
        DataError::UnknownColumn {
            role: Role::Output,
            ..
        }
    ));
    let o = LoadOptions {
        input: ColumnChoice::Position(4),
        ..auto()
    };
    error_of(
        &corpus("tabs.tsv"),
        &o,
        &["column 4 was chosen for the input", "3 \"y\""],
    );
    error_of(
        &corpus("only_time.csv"),
        &auto(),
        &["no column is left for the output", "\"time\""],
    );
    error_of(
        &corpus("no_time.csv"),
        &auto(),
        &["line 1", "no sampling period", "1 \"y\", 2 \"u\""],
    );
    let o = LoadOptions {
        time: name("t"),
        output: name("T"),
        ..auto()
    };
    error_of(
        &corpus("crlf_bom.csv"),
        &o,
        &["time and the output are the same column, \"t\""],
    );
    // Without a header, names cannot be found: the message says so.
    let o = LoadOptions {
        output: name("y"),
        ..auto()
    };
    error_of(
        &corpus("no_header_two_columns.txt"),
        &o,
        &["no header row", "position, 1 to 2"],
    );
}

#[test]
fn binary_garbage_is_refused_or_fails_cleanly() {
    let e = error_of(&corpus("garbage.bin"), &auto(), &["zero byte", "binary"]);
    assert!(matches!(e, DataError::Binary { .. }));
    // Bytes without a zero are read as Latin-1 text and fail as text would.
    assert!(load(&corpus("garbage_no_nul.bin"), &auto()).is_err());
}

#[test]
fn a_bad_sampling_period_is_refused() {
    for ts in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let o = LoadOptions {
            sampling_period: Some(ts),
            ..auto()
        };
        assert!(matches!(
            load(&corpus("no_time.csv"), &o),
            Err(DataError::BadSamplingPeriod(_))
        ));
    }
}

#[test]
fn a_missing_file_says_which() {
    let e = load(&corpus("does_not_exist.csv"), &auto()).unwrap_err();
    assert!(e.to_string().contains("does_not_exist.csv"), "{e}");
}

// ----------------------------------------------------------------------------------------
// Well-formed corpus

#[test]
fn semicolons_with_decimal_commas() {
    let t = loaded_noting(
        "semicolon_decimal_comma.csv",
        &["semicolon-separated with decimal commas"],
    );
    assert_eq!(t.time, [0.0, 0.5, 1.0, 1.5, 2.0]);
    assert_eq!(t.output, [1.25, 1.25, 2.5, 3.75, 4.5]);
    assert_eq!(t.input.as_deref(), Some(&[0.0, 10.0, 10.0, 10.0, 10.0][..]));
    assert_eq!(
        (t.time_name.as_str(), t.output_name.as_str()),
        ("tempo (s)", "saída")
    );
}

#[test]
fn latin1_portuguese_header() {
    let t = loaded_noting("latin1_semicolon.csv", &["Latin-1"]);
    assert_eq!(t.output_name, "saída");
    assert_eq!(t.output, [1.5, 2.5, 3.0]);
}

#[test]
fn tab_separated() {
    let t = loaded_noting("tabs.tsv", &["tab-separated"]);
    assert_eq!(t.output, [0.0, 0.0, 0.35, 0.62, 0.81]);
    assert_eq!(t.input_name.as_deref(), Some("u"));
}

#[test]
fn quoted_header_and_cells_with_units() {
    let t = load(&corpus("quoted_header.csv"), &auto()).unwrap();
    assert_eq!(t.time_name, "time (s)");
    assert_eq!(t.output_name, "y [V]");
    assert_eq!(t.output, [0.0, 0.2, 0.55, 0.8]);
    // Chosen by the name with or without the unit.
    let o = LoadOptions {
        output: name("Y"),
        time: name("time (s)"),
        ..auto()
    };
    assert_eq!(
        load(&corpus("quoted_header.csv"), &o).unwrap().output.len(),
        4
    );
}

#[test]
fn matlab_whitespace_with_a_comment_header() {
    let t = loaded_noting(
        "matlab_comment_header.txt",
        &["whitespace-separated", "comment on line 1"],
    );
    assert_eq!(t.time, [0.0, 1.0, 2.0, 3.0, 4.0]);
    assert_eq!(t.output[3], 0.632);
    assert_eq!(t.input_name.as_deref(), Some("u"));
}

#[test]
fn headerless_two_columns_are_t_and_y() {
    let t = load(&corpus("no_header_two_columns.txt"), &auto()).unwrap();
    assert_eq!(t.time, [0.0, 0.1, 0.2, 0.3]);
    assert_eq!(t.output, [1.0, 1.5, 1.8, 1.9]);
    assert_eq!(t.input, None);
    assert_eq!(t.output_name, "column 2");
}

#[test]
fn bom_and_crlf_are_ignored() {
    let t = load(&corpus("crlf_bom.csv"), &auto()).unwrap();
    assert_eq!(t.time_name, "t");
    assert_eq!(t.output, [0.0, 0.6, 0.9, 1.0]);
}

#[test]
fn metadata_rows_are_skipped_on_request() {
    let o = LoadOptions {
        skip_rows: 3,
        ..auto()
    };
    let t = load(&corpus("metadata_rows.csv"), &o).unwrap();
    assert_eq!(t.time, [0.0, 0.01, 0.02, 0.03]);
    assert_eq!(t.output, [0.0, 0.1, 0.3, 0.45]);
    // Unskipped, the metadata are the header and the rows are text.
    assert!(load(&corpus("metadata_rows.csv"), &auto()).is_err());
}

#[test]
fn a_trailing_separator_is_tolerated() {
    let t = load(&corpus("trailing_separator.csv"), &auto()).unwrap();
    assert_eq!(t.output, [0.0, 0.5, 0.8]);
    assert!(!has_note(&t, &["no name"]), "{:?}", t.notes);
}

#[test]
fn whitespace_header_with_spaces_in_names_is_not_used() {
    // "time (s)   u   y (V)" splits into 5 names for 3 columns: numbered instead.
    let t = loaded_noting(
        "header_with_spaces.txt",
        &["header on line 1 was not used", "numbered"],
    );
    assert_eq!(t.time, [0.0, 0.5, 1.0, 1.5]);
    assert_eq!(t.output, [0.0, 0.39, 0.63, 0.78]);
    assert_eq!(t.input_name.as_deref(), Some("column 2"));
}

#[test]
fn a_headerless_first_column_that_is_not_time_hints_at_the_sampling_period() {
    let e = error_of(
        &corpus("headerless_not_time.txt"),
        &auto(),
        &[
            "line 4: time 1 comes after 2",
            "no header",
            "give the sampling period",
        ],
    );
    assert!(matches!(e, DataError::TimeNotIncreasing { line: 4, .. }));
    let o = LoadOptions {
        sampling_period: Some(0.1),
        input: ColumnChoice::Position(1),
        ..auto()
    };
    let t = load(&corpus("headerless_not_time.txt"), &o).unwrap();
    assert_eq!(t.output, [0.0, 0.1, 0.5, 0.7]);
    assert_eq!(t.time[3], 0.30000000000000004);
}

#[test]
fn pasted_columns() {
    let t = from_columns("0\t1\n1\t2\n2\t3\n").unwrap();
    assert_eq!(
        (t.time, t.output, t.input),
        (vec![0.0, 1.0, 2.0], vec![1.0, 2.0, 3.0], None)
    );
    // The step-like column is the input wherever it is.
    let t = from_columns("0;0,1;0\n1;0,5;1\n2;0,9;1\n3;1,2;1\n4;1,4;1\n5;1,5;1\n6;1,6;1\n7;1,7;1\n8;1,7;1\n9;1,8;1\n10;1,8;1\n").unwrap();
    assert_eq!(t.input.as_ref().unwrap()[1], 1.0);
    assert_eq!(t.output[1], 0.5);
    // Nothing step-like: t, u, y.
    let t = from_columns("0 5 1\n1 6 3\n2 7 2\n").unwrap();
    assert_eq!(
        (t.input.unwrap(), t.output),
        (vec![5.0, 6.0, 7.0], vec![1.0, 3.0, 2.0])
    );
    // A header with unknown names: column 1 is still the time.
    let t = from_columns("a,b\n0,1\n1,2\n2,3\n").unwrap();
    assert_eq!(t.time, [0.0, 1.0, 2.0]);
    assert!(matches!(
        from_columns("1 2 3 4\n5 6 7 8\n"),
        Err(DataError::PasteColumns { line: 1, found: 4 })
    ));
}

// ----------------------------------------------------------------------------------------
// Real files

/// The LECI step test of the notes, `assets/leci_step.csv`.
fn leci() -> StepTest {
    let path = concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/assets/leci_step.csv"
    );
    load(path, &auto()).unwrap()
}

#[test]
fn leci_loads_35_rows_of_t_and_y() {
    let t = leci();
    assert_eq!(t.time.len(), 35);
    assert_eq!((t.time_name.as_str(), t.output_name.as_str()), ("t", "y"));
    assert_eq!(t.input, None);
    assert_eq!((t.time[5], t.output[5]), (10.1271, 65.3662));
    assert_eq!(detect_step(&t, None), None);
}

#[test]
fn leci_measured_step_characteristics() {
    let t = leci();
    let (t0, y0) = (5.0, 50.0);
    // The last 10 % of 5 … 39.8641 s starts at 36.378 s: the last four samples.
    let y_final = final_level(&t, 0.1).unwrap();
    let by_hand = (59.8903 + 59.3440 + 60.8542 + 59.7520) / 4.0;
    assert!((y_final - by_hand).abs() < 1e-12, "{y_final}");
    let info = measured_step_info(&t, t0, y0, y_final, &StepInfoOptions::default());
    // Peak 65.3662 at t = 10.1271 s, i.e. 5.1271 s after the step.
    assert!((y0 + info.peak.unwrap() - 65.3662).abs() < 1e-12);
    assert!((t0 + info.peak_time.unwrap() - 10.1271).abs() < 1e-12);
    let overshoot = 100.0 * (65.3662 - y_final) / (y_final - y0);
    assert!((info.overshoot.unwrap() - overshoot).abs() < 1e-9);
    assert!((overshoot - 54.277).abs() < 1e-3, "{overshoot}");
    // Rise 10 % → 90 % by linear interpolation between the samples around each level.
    let level = |f: f64| y0 + f * (y_final - y0);
    let lerp =
        |(ta, ya): (f64, f64), (tb, yb): (f64, f64), y: f64| ta + (y - ya) / (yb - ya) * (tb - ta);
    let start = lerp((7.0508, 50.0426), (8.0762, 55.8463), level(0.1)) - t0;
    let end = lerp((8.0762, 55.8463), (9.1017, 63.4892), level(0.9)) - t0;
    assert!(
        (info.rise_start.unwrap() - start).abs() < 1e-12,
        "{:?} vs {start}",
        info.rise_start
    );
    assert!((info.rise_end.unwrap() - end).abs() < 1e-12);
    assert!((info.rise_time.unwrap() - (end - start)).abs() < 1e-12);
    assert!(
        (start - 2.219).abs() < 1e-3 && (end - 3.495).abs() < 1e-3,
        "{start} {end}"
    );
    // The record starts with the step: its first sample, at t0, is the rest level.
    assert_eq!(operating_point(&t, t0), Some(49.9761));
    // A step before the first sample leaves nothing measured at rest.
    assert_eq!(operating_point(&t, t0 - 1.0), None);
}

#[test]
fn tclab_step_with_t0_logged_twice() {
    let o = LoadOptions {
        output: name("T1"),
        input: name("Q1"),
        ..auto()
    };
    let t = load(&record("tclab_step_q1_50_synthetic.csv"), &o).unwrap();
    assert_eq!(t.time.len(), 801);
    assert_eq!((t.time[0], t.time[1]), (0.0, 0.0));
    assert!(
        has_note(
            &t,
            &[
                "lines 2 and 3",
                "same time 0",
                "0 → 50",
                "line 2 is the state just before the step"
            ]
        ),
        "{:?}",
        t.notes
    );
    // The names are recognised without options too.
    assert_eq!(
        load(&record("tclab_step_q1_50_synthetic.csv"), &auto()).unwrap(),
        t
    );
    let edge = detect_step(&t, None).unwrap();
    assert_eq!((edge.t0, edge.du, edge.index), (0.0, 50.0, 1));
    assert_eq!(operating_point(&t, edge.t0), Some(20.9));
}

#[test]
fn tclab_with_a_pandas_index_column() {
    let t = load(&record("tclab_step_q1_100_spikes.csv"), &auto()).unwrap();
    assert_eq!(t.time.len(), 1002);
    assert_eq!(t.time_name, "Time");
    assert_eq!(t.output_name, "T1");
    assert_eq!(t.input_name.as_deref(), Some("Q1"));
    assert_eq!(t.output[0], 23.48);
    // The heater is on from the first row: a step only if the caller says it was off.
    assert_eq!(detect_step(&t, None), None);
    let edge = detect_step(&t, Some(0.0)).unwrap();
    assert_eq!((edge.t0, edge.du), (0.0, 100.0));
}

#[test]
fn tclab_dropouts_file() {
    let t = load(&record("tclab_step_q1_50_dropouts_synthetic.csv"), &auto()).unwrap();
    assert_eq!(t.time.len(), 801);
    assert_eq!(t.input_name.as_deref(), Some("Q1"));
}

#[test]
fn daisy_whitespace_without_header() {
    let by_position = LoadOptions {
        time: ColumnChoice::Position(1),
        input: ColumnChoice::Position(2),
        output: ColumnChoice::Position(3),
        ..auto()
    };
    let t = load(&record("daisy_heating_system.dat"), &by_position).unwrap();
    assert_eq!(t.time.len(), 801);
    assert_eq!(
        (t.time[800], t.output[0], t.output[800]),
        (1600.0, 129.32, 120.536)
    );
    // Automatically: column 1 is the time, the piecewise-constant column the input.
    let a = load(&record("daisy_heating_system.dat"), &auto()).unwrap();
    assert_eq!(
        (&a.time, &a.output, &a.input),
        (&t.time, &t.output, &t.input)
    );
    assert!(
        has_note(&a, &["column 2 was taken as the input"]),
        "{:?}",
        a.notes
    );
    // Largest jump: 9 → 4 V at 400 s (the equal 8 → 3 at 1000 s comes later).
    let edge = detect_step(&t, None).unwrap();
    assert_eq!((edge.t0, edge.du), (400.0, -5.0));
    // From the stated pre-experiment 6 V: the record starts with a step of +3 V.
    let edge = detect_step(&t, Some(6.0)).unwrap();
    assert_eq!((edge.t0, edge.du, edge.index), (0.0, 3.0, 0));
}

#[test]
fn aeroshield_without_time_column() {
    let o = LoadOptions {
        sampling_period: Some(0.01),
        ..auto()
    };
    let t = load(&record("pendulum_aprbs_synthetic.txt"), &o).unwrap();
    assert_eq!(t.time.len(), 5001);
    assert!((t.time[5000] - 50.0).abs() < 1e-9);
    assert_eq!(
        (t.output_name.as_str(), t.input_name.as_deref()),
        ("y", Some("u"))
    );
    assert_eq!(t.sampling_period, Some(0.01));
    assert!(has_note(&t, &["no time column", "Ts = 0.01"]));
    let edge = detect_step(&t, Some(0.0)).unwrap();
    assert_eq!((edge.t0, edge.du), (0.0, 0.77618));
    error_of(
        &record("pendulum_aprbs_synthetic.txt"),
        &auto(),
        &["no sampling period"],
    );
}

#[test]
fn enclosure_with_a_comment_header() {
    let o = LoadOptions {
        output: name("box temp"),
        ..auto()
    };
    let t = load(&record("enclosure_heater_doublet.csv"), &o).unwrap();
    assert_eq!(t.time.len(), 722);
    assert_eq!(t.input_name.as_deref(), Some("control output"));
    assert!(has_note(&t, &["comment on line 1"]));
    let edge = detect_step(&t, None).unwrap();
    assert_eq!((edge.du, edge.index), (100.0, 49));
    assert!((edge.t0 - 60.8).abs() < 0.1, "{}", edge.t0);
    // Without an output name, the choice is left to the user, with the names.
    error_of(
        &record("enclosure_heater_doublet.csv"),
        &auto(),
        &[
            "line 1: several columns could be the output",
            "4 \"box temp\"",
        ],
    );
}

#[test]
fn oscilloscope_export_with_metadata_and_wall_clock_time() {
    let o = LoadOptions {
        skip_rows: 4,
        ..auto()
    };
    error_of(
        &record("rlc_step_underdamped_synthetic.csv"),
        &o,
        &["line 5: several columns could be the output", "3 \"V_C\""],
    );
    let o = LoadOptions {
        output: name("V_C"),
        ..o
    };
    // The time column holds wall-clock stamps: an error naming the first one.
    error_of(
        &record("rlc_step_underdamped_synthetic.csv"),
        &o,
        &[
            "line 6, column \"time\"",
            "09:33:31.638054\" is not a number",
        ],
    );
    let o = LoadOptions {
        skip_rows: 4,
        time: ColumnChoice::None,
        sampling_period: Some(3.3e-6),
        output: name("V_C"),
        input: name("V_S"),
    };
    let t = load(&record("rlc_step_underdamped_synthetic.csv"), &o).unwrap();
    assert_eq!(t.time.len(), 200);
    assert_eq!(t.output[0], 2.762514e-2);
}

#[test]
fn adc_counts_without_header_or_time() {
    let o = LoadOptions {
        sampling_period: Some(0.008),
        ..auto()
    };
    let t = load(&record("rc2_square_wave_adc_synthetic.csv"), &o).unwrap();
    assert_eq!(t.time.len(), 641);
    assert_eq!(t.input_name.as_deref(), Some("column 1"));
    assert_eq!(t.output_name, "column 2");
    let edge = detect_step(&t, None).unwrap();
    assert_eq!((edge.index, edge.du.abs()), (45, 1241.0));
}

// ----------------------------------------------------------------------------------------
// Robustness and size

/// Any option set a user can make.
fn options() -> impl Strategy<Value = LoadOptions> {
    let choice = prop_oneof![
        Just(ColumnChoice::Auto),
        Just(ColumnChoice::None),
        (0usize..5).prop_map(ColumnChoice::Position),
        "[a-zA-Z]{0,3}".prop_map(ColumnChoice::Name),
    ];
    (
        choice.clone(),
        choice.clone(),
        choice,
        prop::option::of(prop_oneof![Just(0.1), Just(-1.0), Just(0.0)]),
        0usize..3,
    )
        .prop_map(
            |(time, output, input, sampling_period, skip_rows)| LoadOptions {
                time,
                output,
                input,
                sampling_period,
                skip_rows,
            },
        )
}

/// Text made of the pieces that matter to the parser.
fn soup() -> impl Strategy<Value = String> {
    let token = prop_oneof![
        Just(",".to_string()),
        Just(";".to_string()),
        Just("\t".to_string()),
        Just(" ".to_string()),
        Just("\n".to_string()),
        Just("\r\n".to_string()),
        Just("\"".to_string()),
        Just("#".to_string()),
        Just("%".to_string()),
        Just("NaN".to_string()),
        Just("t".to_string()),
        Just("y".to_string()),
        Just("u".to_string()),
        Just("é".to_string()),
        "-?[0-9]{1,3}([.,][0-9]{1,2})?(e-?[0-9])?",
    ];
    prop::collection::vec(token, 0..80).prop_map(|v| v.concat())
}

/// The load's invariants: equal lengths, enough samples, non-decreasing finite time.
fn check(result: Result<StepTest, DataError>) {
    match result {
        Ok(t) => {
            assert!(t.time.len() >= 3);
            assert_eq!(t.time.len(), t.output.len());
            if let Some(u) = &t.input {
                assert_eq!(u.len(), t.time.len());
                assert!(u.iter().all(|v| v.is_finite()));
            }
            assert!(t.output.iter().all(|v| v.is_finite()));
            assert!(t.time.windows(2).all(|w| w[0] <= w[1]));
        }
        Err(e) => assert!(!e.to_string().is_empty()),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400), o in options()) {
        check(load_bytes(&bytes, &o));
    }

    #[test]
    fn random_lines_never_panic(text in soup(), o in options()) {
        check(load_str(&text, &o));
        if let Ok(t) = from_columns(&text) {
            check(Ok(t));
        }
    }

    #[test]
    fn mutated_real_rows_never_panic(cut in 0usize..2000, junk in "[,;\t \n\"#a-z0-9.]{0,6}") {
        let text = std::fs::read_to_string(record("tclab_step_q1_50_synthetic.csv")).unwrap();
        let mut at = cut.min(text.len());
        while !text.is_char_boundary(at) {
            at -= 1;
        }
        let mutated = format!("{}{junk}{}", &text[..at], &text[at..]);
        check(load_str(&mutated, &auto()));
    }
}

#[test]
fn a_million_rows_load() {
    let dir = std::env::temp_dir().join(format!("degrau-data-loading-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("million.csv");
    std::fs::write(&path, million_rows()).unwrap();
    let start = std::time::Instant::now();
    let t = load_file(&path, &auto());
    let elapsed = start.elapsed();
    std::fs::remove_dir_all(&dir).ok();
    let t = t.unwrap();
    assert_eq!(t.time.len(), 1_000_000);
    assert_eq!(t.time[999_999], 999_999.0 * 0.001);
    assert_eq!(t.input.as_ref().unwrap()[10], 1.0);
    assert!((t.output[500_000] - (1.0 - (-500.0f64).exp())).abs() < 1e-6);
    if !cfg!(debug_assertions) {
        assert!(elapsed.as_secs_f64() <= 1.0, "{elapsed:?}");
    }
}

/// t,u,y: a unit step at t = 0.01 s into 1/(s + 1), Ts = 1 ms.
fn million_rows() -> String {
    let mut s = String::with_capacity(32_000_000);
    s.push_str("t,u,y\n");
    for k in 0..1_000_000u32 {
        let t = f64::from(k) * 0.001;
        let u = if k >= 10 { 1.0 } else { 0.0 };
        let y = if k >= 10 {
            1.0 - (-(t - 0.01)).exp()
        } else {
            0.0
        };
        s.push_str(&format!("{t},{u},{y:.6}\n"));
    }
    s
}
