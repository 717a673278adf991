//! The common ground of Degrau's words, which every crate of the workspace stands on: the
//! languages ([`Lang`], English and Brazilian Portuguese with the course notes' terms), how a
//! typed fact is said ([`Localize`]), the catalogues of fixed phrases ([`phrases!`]), a
//! message in both languages ([`Message`]) for the test that lists them all, and numbers as
//! people read them ([`number`]).
//!
//! Each crate holds the words of its own facts beside them, in both languages; none builds a
//! sentence outside its words. JSON keys and cause identifiers are not words and never come
//! here.

use serde::{Deserialize, Serialize};

pub mod number;

/// A language the app and the CLI speak.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Lang {
    /// English.
    #[default]
    #[serde(rename = "en")]
    En,
    /// Brazilian Portuguese.
    #[serde(rename = "pt")]
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
        self.localize_number(&crate::number::sig(x, digits))
    }

    /// 10^`log10` written as `m·e±E` with `digits` significant digits and this language's
    /// separator, for a number a double cannot hold.
    pub fn power_of_ten(self, log10: f64, digits: i32) -> String {
        let mut exponent = log10.floor();
        let mut m = crate::number::sig(10f64.powf(log10 - exponent), digits);
        if m == "10" {
            (m, exponent) = ("1".into(), exponent + 1.0);
        }
        self.localize_number(&format!("{m}e{exponent}"))
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

/// One message in both languages, as a crate's list of every message gives them (the
/// test that none is missing or left untranslated reads them).
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// Where the message comes from, e.g. `"design::Label::RiseTime"`.
    pub id: String,
    pub en: String,
    pub pt: String,
}

impl Message {
    /// The message `say` gives in each language (`id` names where it comes from).
    pub fn said(id: impl Into<String>, say: impl Fn(Lang) -> String) -> Self {
        Self {
            id: id.into(),
            en: say(Lang::En),
            pt: say(Lang::Pt),
        }
    }

    /// The message of a fact (`id` names the fact and its variant).
    pub fn of(id: impl Into<String>, fact: &dyn Localize) -> Self {
        Self {
            id: id.into(),
            en: fact.text(Lang::En),
            pt: fact.text(Lang::Pt),
        }
    }
}

/// Words that read the same in both languages: symbols, units, parameter names, codes and
/// proper names.
pub fn same_in_both(text: &str) -> bool {
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

/// What is wrong with the messages of `all`, one line each ("id: why"): a language
/// missing, or the Portuguese left as the English (unless it reads the same in both,
/// [`same_in_both`]). Every crate's test of its words asserts this is empty for its own
/// list of every message.
pub fn untranslated(all: &[Message]) -> Vec<String> {
    all.iter()
        .filter_map(|m| {
            if m.en.trim().is_empty() {
                Some(format!("{}: no English", m.id))
            } else if m.pt.trim().is_empty() {
                Some(format!("{}: no Portuguese", m.id))
            } else if m.en == m.pt && !same_in_both(&m.en) {
                Some(format!(
                    "{}: the Portuguese is the English, {:?}",
                    m.id, m.en
                ))
            } else {
                None
            }
        })
        .collect()
}

/// Panics, naming each, unless every message of `all` (a crate's whole list, never empty) is
/// said in both languages ([`untranslated`]): the body of each crate's test of its words.
pub fn assert_said_in_both(all: &[Message]) {
    assert!(!all.is_empty(), "no messages");
    let wrong = untranslated(all);
    assert!(wrong.is_empty(), "{wrong:#?}");
}

/// Declares a catalogue of fixed phrases, each with its English and Portuguese:
///
/// ```
/// degrau_words::phrases! {
///     /// Labels of an example.
///     pub enum Label {
///         RiseTime => ("Rise time", "Tempo de subida"),
///     }
/// }
/// use degrau_words::Lang;
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
            pub fn get(self, lang: $crate::Lang) -> &'static str {
                match self {
                    $( $name::$variant => lang.pick($en, $pt), )*
                }
            }

            /// Every phrase as a [`Message`]($crate::Message), for the test of the
            /// catalogue.
            pub fn messages() -> Vec<$crate::Message> {
                Self::ALL
                    .iter()
                    .map(|p| $crate::Message {
                        id: format!("{}::{:?}", stringify!($name), p),
                        en: p.get($crate::Lang::En).to_string(),
                        pt: p.get($crate::Lang::Pt).to_string(),
                    })
                    .collect()
            }
        }

        impl $crate::Localize for $name {
            fn text(&self, lang: $crate::Lang) -> String {
                self.get(lang).to_string()
            }
        }
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_message_in_one_language_only_is_named() {
        let message = |en: &str, pt: &str| Message {
            id: "example".into(),
            en: en.into(),
            pt: pt.into(),
        };
        assert!(untranslated(&[message("Rise time", "Tempo de subida")]).is_empty());
        assert!(untranslated(&[message("Kp (s)", "Kp (s)")]).is_empty());
        assert_eq!(
            untranslated(&[message("Rise time", "Rise time")]),
            ["example: the Portuguese is the English, \"Rise time\""]
        );
        assert_eq!(
            untranslated(&[message("Rise time", " ")]),
            ["example: no Portuguese"]
        );
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
