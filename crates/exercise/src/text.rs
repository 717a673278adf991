//! Text in both languages ([`Text`]) and numbers as the sheet's solutions print them
//! ([`num`]: four significant digits, the language's decimal separator, ∞ for infinity).
//!
//! This module owns only the carrier of words; the fixed phrases live in [`crate::words`],
//! and each exercise writes its own statements and steps beside its data.

use degrau_words::Lang;
use degrau_words::number::superscript;
use serde::Serialize;

/// One piece of text, in English and in Portuguese (the sheet's Portuguese where it is the
/// sheet's statement).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Text {
    pub en: String,
    pub pt: String,
}

impl Text {
    /// The text from its two languages.
    pub fn new(en: impl Into<String>, pt: impl Into<String>) -> Self {
        Self {
            en: en.into(),
            pt: pt.into(),
        }
    }

    /// The text `say` gives in each language.
    pub fn by(say: impl Fn(Lang) -> String) -> Self {
        Self {
            en: say(Lang::En),
            pt: say(Lang::Pt),
        }
    }

    /// The same text in both languages (symbols, numbers, formulas).
    pub fn same(text: impl Into<String>) -> Self {
        let text = text.into();
        Self {
            en: text.clone(),
            pt: text,
        }
    }

    /// The text in `lang`.
    pub fn get(&self, lang: Lang) -> &str {
        match lang {
            Lang::En => &self.en,
            Lang::Pt => &self.pt,
        }
    }
}

impl degrau_words::Localize for Text {
    fn text(&self, lang: Lang) -> String {
        self.get(lang).to_string()
    }
}

/// `x` with four significant digits and the language's decimal separator; `∞` and `−∞`.
pub fn num(lang: Lang, x: f64) -> String {
    digits(lang, x, 4)
}

/// `x` with `d` significant digits and the language's decimal separator; `∞` and `−∞`.
pub fn digits(lang: Lang, x: f64, d: i32) -> String {
    if x == f64::INFINITY {
        "∞".into()
    } else if x == f64::NEG_INFINITY {
        "−∞".into()
    } else {
        lang.num(x, d)
    }
}

/// A complex number `a ± bj` with four significant digits, in the language.
pub fn complex(lang: Lang, c: degrau_lti::C64) -> String {
    if c.im == 0.0 {
        num(lang, c.re)
    } else {
        let sign = if c.im < 0.0 { '−' } else { '+' };
        format!("{} {sign} j{}", num(lang, c.re), num(lang, c.im.abs()))
    }
}

/// Polynomial coefficients (descending powers) as `s² + 0,3s + 10`, in the language.
pub fn poly(lang: Lang, coeffs: &[f64]) -> String {
    let n = coeffs.len();
    let mut out = String::new();
    for (i, &c) in coeffs.iter().enumerate() {
        if c == 0.0 {
            continue;
        }
        let power = n - 1 - i;
        let magnitude = c.abs();
        let body = match (power, magnitude == 1.0) {
            (0, _) => num(lang, magnitude),
            (1, true) => "s".into(),
            (1, false) => format!("{}s", num(lang, magnitude)),
            (p, true) => format!("s{}", superscript(p)),
            (p, false) => format!("{}s{}", num(lang, magnitude), superscript(p)),
        };
        if out.is_empty() {
            if c < 0.0 {
                out.push('−');
            }
        } else {
            out.push_str(if c < 0.0 { " − " } else { " + " });
        }
        out.push_str(&body);
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

/// A transfer function as `num/(den)` from its coefficients, in the language.
pub fn tf(lang: Lang, g: &degrau_lti::TransferFunction) -> String {
    let num = poly(lang, &g.num());
    let num = if g.num().iter().filter(|c| **c != 0.0).count() > 1 {
        format!("({num})")
    } else {
        num
    };
    format!("{num}/({})", poly(lang, &g.den()))
}
