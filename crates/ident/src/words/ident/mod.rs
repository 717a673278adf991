//! The words of process identification (`crate::ident`): the notes on the data, every error
//! of loading, preparing and fitting, the fit's warnings and how it ended, the causes of the
//! diagnosis in plain words, their evidence and the verdict — in English and in Brazilian
//! Portuguese. Cause identifiers (`dead_time`, `extra_pole`, …) are not words and stay in
//! [`crate::diagnose::Cause::id`].
//!
//! Numbers in prose take the language's decimal separator ([`Lang::num`]); a number the
//! loader read from a file is shown in full (`Lang::localize_number` of its shortest form).

use crate::diagnose::{Bias, Cause, Ending, Evidence, Verdict, Whiteness};
use crate::experiment::ExperimentError;
use crate::fit::handles::Handle;
use crate::fit::{FitError, FitWarning, Termination};
use crate::model::{ModelError, Param, Requirement, Structure};
use crate::record::data::{
    Column, ColumnList, Columns, DataError, DataNote, FileKind, HeaderFound, MAX_FILE_BYTES, Role,
    Separator, Source,
};
use crate::record::prepare::{Ewma, PrepareError};
use degrau_lti::LtiError;

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

/// A number as read, in full, with the language's separator.
fn full(lang: Lang, x: f64) -> String {
    lang.localize_number(&x.to_string())
}

/// `x` with four significant digits.
fn n4(lang: Lang, x: f64) -> String {
    lang.num(x, 4)
}

/// `x` with four decimals (the filter's and the warnings' figures).
fn d4(lang: Lang, x: f64) -> String {
    lang.localize_number(&format!("{x:.4}"))
}

/// The words of an [`LtiError`]: the one place that says them here, until the text layer's
/// `lti` catalogue renders them in either language (`Localize`), when this calls it.
pub fn lti_words(e: &LtiError, lang: Lang) -> String {
    e.text(lang)
}

/// `a, b and c` (`a, b e c`).
fn and_list(lang: Lang, items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} {} {last}", rest.join(", "), lang.pick("and", "e")),
    }
}

mod data;
mod diagnosis;
mod errors;
#[cfg(test)]
mod examples;
mod fit;

pub use data::*;
pub use diagnosis::*;
pub use errors::*;
#[cfg(test)]
pub use examples::*;
pub use fit::*;
