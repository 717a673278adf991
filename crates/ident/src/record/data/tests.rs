//! Unit tests of the loader's private parts: fields, cells, the delimiter, names, the
//! step-like rule, column choices, shortened text and decoding.

use super::cells::{Cell, Delimiter, fields, parse_cell, shorten};
use super::columns::{StepLike, choose_delimiter, is_index_normalised, normalise};
use super::*;

/// A pandas row index: no name, or `Unnamed: k`.
fn is_index_name(name: &str) -> bool {
    is_index_normalised(&normalise(name))
}

/// [`StepLike`] of a whole column.
fn is_step_like(values: &[f64]) -> bool {
    let mut s = StepLike::default();
    values.iter().for_each(|&v| s.push(v));
    s.holds()
}

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
