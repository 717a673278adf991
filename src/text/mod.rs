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
//!   write both languages; [`every_message`] lists an example of every phrase and fact so a
//!   test can check that none is missing or left untranslated.

pub use degrau_app::words::{app, code, design, identify, lsq_app};
pub use degrau_ident::words::{ident, operating_point, report, steps, test_causes};
pub use degrau_lti::words::{feedback, lti, step};
pub use degrau_words::{Lang, Localize, Message};

pub mod approx;
pub mod clap_words;
pub mod cli;
pub mod hand;
pub mod lsq;

/// Every message Degrau can show: each catalogue's phrases and an example of every
/// variant of every typed fact. A new catalogue or fact type adds its line here.
pub fn every_message() -> Vec<Message> {
    let mut all = Vec::new();
    all.extend(crate::app::field::FieldPhrase::messages());
    all.extend(crate::app::field::examples());
    all.extend(step::messages());
    all.extend(steps::messages());
    all.extend(ident::messages());
    all.extend(report::messages());
    all.extend(cli::messages());
    all.extend(lti::messages());
    all.extend(degrau_lti::words::expr::messages());
    all.extend(operating_point::messages());
    all.extend(identify::messages());
    all.extend(design::messages());
    all.extend(feedback::messages());
    all.extend(app::messages());
    all.extend(approx::messages());
    all.extend(lsq::messages());
    all.extend(hand::messages());
    all.extend(test_causes::messages());
    all.extend(lsq_app::messages());
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Words that read the same in both languages (symbols, units, codes, proper names).
    fn same_in_both(text: &str) -> bool {
        text.chars().all(|c| !c.is_alphabetic())
            || text.split_whitespace().all(|w| {
                matches!(
                    w.trim_matches(|c: char| !c.is_alphanumeric()),
                    "" | "Kp"
                        | "Tp1"
                        | "Tp2"
                        | "Td"
                        | "Tz"
                        | "Y0"
                        | "Δu"
                        | "t0"
                        | "ζ"
                        | "ωn"
                        | "s"
                        | "PNG"
                        | "CSV"
                        | "MATLAB"
                        | "python-control"
                        | "Degrau"
                )
            })
    }

    #[test]
    fn every_message_is_in_both_languages() {
        let all = every_message();
        assert!(!all.is_empty());
        for m in &all {
            assert!(!m.en.trim().is_empty(), "{}: no English", m.id);
            assert!(!m.pt.trim().is_empty(), "{}: no Portuguese", m.id);
            assert!(
                m.en != m.pt || same_in_both(&m.en),
                "{}: the Portuguese is the English, \"{}\"",
                m.id,
                m.en
            );
        }
    }
}
