//! The text layer: the one place where the library's typed facts (notes on the data,
//! evidence, verdicts, warnings, errors) and the app's labels become words, in English or
//! in Brazilian Portuguese with the course notes' terms (the project's English–Portuguese glossary:
//! tempo de subida, tempo de acomodação, sobressinal, ganho estático, tempo morto, …).
//!
//! The library never builds a sentence; the CLI and the app both render through here. JSON
//! keys and cause identifiers are not text and never go through this layer.
//!
//! Two tools keep every message in both languages:
//! - [`phrases!`] declares a catalogue of fixed phrases, each written once with its English
//!   and its Portuguese side by side; the compiler refuses a phrase without both.
//! - [`Localize`] is implemented by every typed fact, with a `match` on the fact whose arms
//!   write both languages; each crate's tests list an example of every phrase and fact it
//!   says (`words::messages`, built only for its tests) and check that none is missing or
//!   left untranslated; [`every_message`] does it for the command line's.

pub use degrau_app::words::{app, code, design, identify, lsq_app};
pub use degrau_ident::words::{ident, operating_point, report, steps, test_causes};
pub use degrau_lti::words::{feedback, lti, step};
pub use degrau_words::{Lang, Localize, Message};

pub mod approx;
pub mod bode;
pub mod clap_words;
pub mod cli;
pub mod control;
pub mod exercise;
pub mod hand;
pub mod lsq;
pub mod margins;

/// Every message of the command line: its catalogues' phrases and an example of every fact
/// it says (the lti, ident and app crates' tests check theirs).
#[cfg(test)]
pub fn every_message() -> Vec<Message> {
    let mut all = cli::messages();
    all.extend(approx::cli_messages());
    all.extend(control::messages());
    all.extend(bode::messages());
    all.extend(margins::messages());
    all.extend(exercise::messages());
    all
}

#[cfg(test)]
#[test]
fn every_message_is_in_both_languages() {
    degrau_words::assert_said_in_both(&every_message());
}
