//! Wide CSV text, for the loading tests and the loading bench (`benches/data_load.rs` takes
//! this file by `#[path]`): a time column, an output column and many others, 5 rows.

use std::fmt::Write as _;

/// `t,<output>,c3,…,cN` (N = `columns`) and 5 rows, k = 0 to 4: the time k, the output
/// `output_at(k)`, column c `cell(c, k)`.
pub fn wide_csv(
    columns: usize,
    output: &str,
    output_at: impl Fn(usize) -> usize,
    cell: impl Fn(usize, usize) -> usize,
) -> String {
    let mut text = format!("t,{output}");
    for c in 3..=columns {
        // Writing to a String cannot fail.
        let _ = write!(text, ",c{c}");
    }
    text.push('\n');
    for k in 0..5 {
        let _ = write!(text, "{k},{}", output_at(k));
        for c in 3..=columns {
            let _ = write!(text, ",{}", cell(c, k));
        }
        text.push('\n');
    }
    text
}
