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

use serde::{Deserialize, Serialize};

pub mod app;
pub mod approx;
pub mod clap_words;
pub mod cli;
pub mod code;
pub mod design;
pub mod feedback;
pub mod hand;
pub mod ident;
pub mod identify;
pub mod lsq;
pub mod lsq_app;
pub mod lti;
pub mod operating_point;
pub mod report;
pub mod step;
pub mod steps;
pub mod test_causes;

/// A language the app and the CLI speak.
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize, clap::ValueEnum,
)]
pub enum Lang {
    /// English.
    #[default]
    #[serde(rename = "en")]
    #[value(name = "en")]
    En,
    /// Brazilian Portuguese.
    #[serde(rename = "pt")]
    #[value(name = "pt")]
    Pt,
}

impl Lang {
    /// Every language, in the order the app offers them.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Pt];

    /// `en` in English, `pt` in Portuguese.
    pub fn pick<T>(self, en: T, pt: T) -> T {
        match self {
            Lang::En => en,
            Lang::Pt => pt,
        }
    }

    /// The language's own name, as its speakers write it.
    pub fn name(self) -> &'static str {
        self.pick("English", "Português")
    }

    /// The decimal separator of running text: a point in English, a comma in Portuguese.
    pub fn decimal(self) -> char {
        self.pick('.', ',')
    }

    /// `x` with `digits` significant digits and this language's decimal separator
    /// (`Lang::Pt.num(0.773201, 4) == "0,7732"`). Code, JSON and CSV never use this.
    pub fn num(self, x: f64, digits: i32) -> String {
        self.localize_number(&crate::lti::number::sig(x, digits))
    }

    /// A number already written with a decimal point, with this language's separator.
    pub fn localize_number(self, text: &str) -> String {
        match self {
            Lang::En => text.to_string(),
            Lang::Pt => text.replace('.', ","),
        }
    }
}

/// A typed fact that can be said in words.
pub trait Localize {
    /// The fact in `lang`, as one or more sentences (no trailing newline).
    fn text(&self, lang: Lang) -> String;
}

/// One message in both languages, as [`every_message`] lists them.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// Where the message comes from, e.g. `"design::Label::RiseTime"`.
    pub id: String,
    pub en: String,
    pub pt: String,
}

impl Message {
    /// The message of a fact (`id` names the fact and its variant).
    pub fn of(id: impl Into<String>, fact: &dyn Localize) -> Self {
        Self {
            id: id.into(),
            en: fact.text(Lang::En),
            pt: fact.text(Lang::Pt),
        }
    }
}

/// Declares a catalogue of fixed phrases, each with its English and Portuguese:
///
/// ```
/// degrau::phrases! {
///     /// Labels of an example.
///     pub enum Label {
///         RiseTime => ("Rise time", "Tempo de subida"),
///     }
/// }
/// use degrau::text::Lang;
/// assert_eq!(Label::RiseTime.get(Lang::Pt), "Tempo de subida");
/// assert_eq!(Label::ALL.len(), 1);
/// ```
#[macro_export]
macro_rules! phrases {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $( $(#[$vmeta:meta])* $variant:ident => ($en:expr, $pt:expr) ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        $vis enum $name {
            $( $(#[$vmeta])* $variant, )*
        }

        impl $name {
            /// Every phrase of the catalogue.
            pub const ALL: &'static [$name] = &[$($name::$variant),*];

            /// The phrase in `lang`.
            pub fn get(self, lang: $crate::text::Lang) -> &'static str {
                match self {
                    $( $name::$variant => lang.pick($en, $pt), )*
                }
            }

            /// Every phrase as a [`Message`]($crate::text::Message), for the test of the
            /// catalogue.
            pub fn messages() -> Vec<$crate::text::Message> {
                Self::ALL
                    .iter()
                    .map(|p| $crate::text::Message {
                        id: format!("{}::{:?}", stringify!($name), p),
                        en: p.get($crate::text::Lang::En).to_string(),
                        pt: p.get($crate::text::Lang::Pt).to_string(),
                    })
                    .collect()
            }
        }

        impl $crate::text::Localize for $name {
            fn text(&self, lang: $crate::text::Lang) -> String {
                self.get(lang).to_string()
            }
        }
    };
}

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

    #[test]
    fn numbers_take_the_language_separator() {
        assert_eq!(Lang::En.num(0.773201, 4), "0.7732");
        assert_eq!(Lang::Pt.num(0.773201, 4), "0,7732");
        assert_eq!(Lang::Pt.num(-1.5e-7, 3), "-1,5e-7");
        assert_eq!(Lang::Pt.num(12.0, 4), "12");
    }

    #[test]
    fn languages_round_trip_through_json() {
        for lang in Lang::ALL {
            let json = serde_json::to_string(&lang).unwrap();
            assert_eq!(serde_json::from_str::<Lang>(&json).unwrap(), lang);
        }
        assert_eq!(serde_json::to_string(&Lang::Pt).unwrap(), "\"pt\"");
    }
}
