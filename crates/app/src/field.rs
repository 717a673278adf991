//! Numeric fields: what a student types becomes a number or a refusal that says why,
//! beside the field; a refused entry is never applied and the field keeps the text so it
//! can be corrected.
//!
//! [`parse_number`] accepts a decimal point or a decimal comma ("2,5"), `−` as a minus and
//! exponents ("1e-3"); [`Limits`] refuse values a role cannot hold. [`NumberField`] is the
//! widget: it returns the committed value (on Enter or when focus leaves) and the view turns
//! it into a command; it changes nothing itself. Its typing buffer lives in egui's widget
//! memory, as a `TextEdit`'s cursor does.

use eframe::egui::{self, Id, RichText, Ui};

use degrau_words::{Lang, Localize, Message};

degrau_words::phrases! {
    /// The words of a refused entry.
    pub enum FieldPhrase {
        Empty => ("type a number", "digite um número"),
        NotANumber => ("is not a number", "não é um número"),
        NotFinite => ("is not a finite number", "não é um número finito"),
        TwoSeparators => (
            "use one decimal separator, a point or a comma, and no thousands separator",
            "use um só separador decimal, ponto ou vírgula, sem separador de milhares"
        ),
        Below => ("is below the smallest allowed value", "é menor que o menor valor permitido"),
        Above => ("is above the largest allowed value", "é maior que o maior valor permitido"),
        Refused => ("is refused", "é recusado"),
    }
}

/// Why a typed entry was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum FieldError {
    /// Nothing but spaces.
    Empty,
    /// Not a number at all ("abc", "2..5").
    NotANumber { text: String },
    /// A number too large for double precision, or "inf"/"NaN".
    NotFinite { text: String },
    /// Both a point and a comma, or several commas ("1,234.5", "1,2,3").
    TwoSeparators { text: String },
    /// A number below what the role can hold; `why` says what the limit is for.
    Below {
        value: f64,
        min: f64,
        why: Option<LimitReason>,
    },
    /// A number above what the role can hold.
    Above {
        value: f64,
        max: f64,
        why: Option<LimitReason>,
    },
    /// A number in range on its own that the role refuses with the rest of what it holds
    /// (a root too far from the others).
    Refused { value: f64, why: LimitReason },
}

/// What a limit protects, said to the student beside the number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LimitReason {
    /// A pole or zero beyond this is outside what the exact response can show.
    RootMagnitude,
    /// A root this much faster than the slowest: the response cannot show both time scales.
    RootSpread,
    /// The step amplitude.
    Amplitude,
    /// A dead time, in seconds.
    DeadTime,
    /// A static gain.
    Gain,
    /// A count (of starts, of samples).
    Count,
    /// A controller's time (Ti, Td), in seconds.
    ControllerTime,
}

impl Localize for LimitReason {
    fn text(&self, lang: Lang) -> String {
        match self {
            LimitReason::RootMagnitude => lang.pick(
                "a pole or zero this far from the origin is beyond what the exact response can show",
                "um polo ou zero tão longe da origem está além do que a resposta exata pode mostrar",
            ),
            LimitReason::RootSpread => lang.pick(
                "a root more than 1e12 times faster than the slowest one is beyond what the exact \
                 response can show",
                "uma raiz mais de 1e12 vezes mais rápida que a mais lenta está além do que a \
                 resposta exata pode mostrar",
            ),
            LimitReason::Amplitude => lang.pick("the step amplitude", "a amplitude do degrau"),
            LimitReason::DeadTime => lang.pick("the dead time (s)", "o tempo morto (s)"),
            LimitReason::Gain => lang.pick("the gain", "o ganho"),
            LimitReason::Count => lang.pick("the count", "a contagem"),
            LimitReason::ControllerTime => lang.pick(
                "a controller's time Ti or Td (s)",
                "um tempo do controlador, Ti ou Td (s)",
            ),
        }
        .to_string()
    }
}

impl Localize for FieldError {
    fn text(&self, lang: Lang) -> String {
        let quoted = |t: &str, p: FieldPhrase| format!("\"{t}\" {}", p.get(lang));
        let why = |w: &Option<LimitReason>| match w {
            Some(w) => format!(" ({})", w.text(lang)),
            None => String::new(),
        };
        match self {
            FieldError::Empty => FieldPhrase::Empty.get(lang).to_string(),
            FieldError::NotANumber { text } => quoted(text, FieldPhrase::NotANumber),
            FieldError::NotFinite { text } => quoted(text, FieldPhrase::NotFinite),
            FieldError::TwoSeparators { text } => {
                format!("\"{text}\": {}", FieldPhrase::TwoSeparators.get(lang))
            }
            FieldError::Below { value, min, why: w } => format!(
                "{} {}, {}{}",
                lang.num(*value, 4),
                FieldPhrase::Below.get(lang),
                lang.num(*min, 4),
                why(w)
            ),
            FieldError::Above { value, max, why: w } => format!(
                "{} {}, {}{}",
                lang.num(*value, 4),
                FieldPhrase::Above.get(lang),
                lang.num(*max, 4),
                why(w)
            ),
            FieldError::Refused { value, why: w } => format!(
                "{} {}: {}",
                lang.num(*value, 4),
                FieldPhrase::Refused.get(lang),
                w.text(lang)
            ),
        }
    }
}

/// An example of every [`FieldError`] and [`LimitReason`], for the catalogue test.
pub fn examples() -> Vec<Message> {
    let reasons = [
        LimitReason::RootMagnitude,
        LimitReason::RootSpread,
        LimitReason::Amplitude,
        LimitReason::DeadTime,
        LimitReason::Gain,
        LimitReason::Count,
        LimitReason::ControllerTime,
    ];
    let errors = [
        FieldError::Empty,
        FieldError::NotANumber { text: "abc".into() },
        FieldError::NotFinite {
            text: "1e400".into(),
        },
        FieldError::TwoSeparators {
            text: "1,234.5".into(),
        },
        FieldError::Below {
            value: -2.0,
            min: 0.0,
            why: Some(LimitReason::DeadTime),
        },
        FieldError::Above {
            value: 1e300,
            max: 1e6,
            why: Some(LimitReason::RootMagnitude),
        },
        FieldError::Refused {
            value: 1e-9,
            why: LimitReason::RootSpread,
        },
    ];
    let reasons = reasons
        .iter()
        .map(|r| Message::of(format!("LimitReason::{r:?}"), r));
    let errors = errors
        .iter()
        .map(|e| Message::of(format!("FieldError::{e:?}"), e));
    reasons.chain(errors).collect()
}

/// Reads a typed number: a decimal point or a decimal comma, `−` or `-` as a minus,
/// surrounding spaces ignored; refused unless finite.
pub fn parse_number(text: &str) -> Result<f64, FieldError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(FieldError::Empty);
    }
    let commas = trimmed.matches(',').count();
    let points = trimmed.matches('.').count();
    if commas > 1 || (commas == 1 && points > 0) {
        return Err(FieldError::TwoSeparators {
            text: trimmed.to_string(),
        });
    }
    let normal = trimmed.replace(',', ".").replace('\u{2212}', "-");
    match normal.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(FieldError::NotFinite {
            text: trimmed.to_string(),
        }),
        Err(_) => Err(FieldError::NotANumber {
            text: trimmed.to_string(),
        }),
    }
}

/// The range a role can hold (inclusive), and what it protects.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    pub min: f64,
    pub max: f64,
    pub why: Option<LimitReason>,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            min: f64::MIN,
            max: f64::MAX,
            why: None,
        }
    }
}

impl Limits {
    /// Values from `min` to `max`, protecting `why`.
    pub fn new(min: f64, max: f64, why: LimitReason) -> Self {
        Self {
            min,
            max,
            why: Some(why),
        }
    }

    /// `value` if the role can hold it.
    pub fn check(&self, value: f64) -> Result<f64, FieldError> {
        if value < self.min {
            Err(FieldError::Below {
                value,
                min: self.min,
                why: self.why,
            })
        } else if value > self.max {
            Err(FieldError::Above {
                value,
                max: self.max,
                why: self.why,
            })
        } else {
            Ok(value)
        }
    }

    /// [`parse_number`] then [`Limits::check`].
    pub fn parse(&self, text: &str) -> Result<f64, FieldError> {
        parse_number(text).and_then(|v| self.check(v))
    }
}

/// How a value is written into the field when it is not being typed in.
fn shown(value: f64, lang: Lang) -> String {
    lang.num(value, 6)
}

/// The typing state of one field, kept in egui's memory under the field's id.
#[derive(Debug, Clone, Default)]
struct Buffer {
    text: String,
    /// The value the text was made from (a change from outside refreshes the text).
    source: f64,
    error: Option<FieldError>,
    editing: bool,
    /// The language the text was written in (a switch rewrites it).
    lang: Lang,
}

/// A check of a value against the rest of what the role holds (beyond its [`Limits`]).
type Validate<'a> = Box<dyn Fn(f64) -> Result<(), FieldError> + 'a>;

/// A labelled numeric field: the label names it for screen readers and kittest.
pub struct NumberField<'a> {
    label: &'a str,
    value: f64,
    limits: Limits,
    width: f32,
    suffix: &'a str,
    salt: Option<u64>,
    validate: Option<Validate<'a>>,
}

impl<'a> NumberField<'a> {
    pub fn new(label: &'a str, value: f64) -> Self {
        Self {
            label,
            value,
            limits: Limits::default(),
            width: 90.0,
            suffix: "",
            salt: None,
            validate: None,
        }
    }

    /// Tells apart fields with the same label (the σ of each root).
    pub fn id_salt(mut self, salt: impl std::hash::Hash) -> Self {
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        std::hash::Hash::hash(&salt, &mut hasher);
        self.salt = Some(std::hash::Hasher::finish(&hasher));
        self
    }

    /// A further check of an accepted number; a refusal shows beside the field.
    pub fn validate(mut self, check: impl Fn(f64) -> Result<(), FieldError> + 'a) -> Self {
        self.validate = Some(Box::new(check));
        self
    }

    pub fn limits(mut self, limits: Limits) -> Self {
        self.limits = limits;
        self
    }

    pub fn width(mut self, width: f32) -> Self {
        self.width = width;
        self
    }

    /// A unit written after the field, e.g. `" s"`.
    pub fn suffix(mut self, suffix: &'a str) -> Self {
        self.suffix = suffix;
        self
    }

    /// Draws the field with its label; the value typed, once committed and accepted.
    /// A refusal is drawn under the field, in the error colour and wrapped to the space there
    /// is (so it never widens a panel), until the text is fixed.
    pub fn show(self, ui: &mut Ui, lang: Lang) -> Option<f64> {
        let id = field_id(ui, self.label, self.salt);
        let mut buffer: Buffer = ui.data(|d| d.get_temp(id)).unwrap_or_default();
        let changed_outside = buffer.source.to_bits() != self.value.to_bits();
        let blank = buffer.error.is_none() && (buffer.text.is_empty() || buffer.lang != lang);
        if !buffer.editing && (changed_outside || blank) {
            buffer.text = shown(self.value, lang);
            buffer.source = self.value;
            buffer.lang = lang;
            buffer.error = None;
        }
        let mut committed = None;
        ui.horizontal(|ui| {
            let name = ui.label(self.label);
            let edit = egui::TextEdit::singleline(&mut buffer.text)
                .id(id.with("text"))
                .desired_width(self.width);
            let response = ui.add(edit).labelled_by(name.id);
            if !self.suffix.is_empty() {
                ui.label(self.suffix);
            }
            if response.has_focus() {
                buffer.editing = true;
            }
            if response.lost_focus() && buffer.editing {
                buffer.editing = false;
                let checked = self.limits.parse(&buffer.text).and_then(|v| {
                    self.validate.as_ref().map_or(Ok(()), |check| check(v))?;
                    Ok(v)
                });
                match checked {
                    Ok(v) => {
                        buffer.error = None;
                        buffer.source = v;
                        buffer.text = shown(v, lang);
                        committed = Some(v);
                    }
                    Err(e) => buffer.error = Some(e),
                }
            }
        });
        if let Some(e) = &buffer.error {
            ui.add(
                egui::Label::new(RichText::new(e.text(lang)).color(ui.visuals().error_fg_color))
                    .wrap(),
            );
        }
        ui.data_mut(|d| d.insert_temp(id, buffer));
        committed
    }
}

/// The id of a field's typing buffer.
fn field_id(ui: &Ui, label: &str, salt: Option<u64>) -> Id {
    ui.make_persistent_id(("number field", label, salt))
}

/// The field's refusal, if its last entry was refused (for tests and status lines).
pub fn refusal(ui: &Ui, label: &str) -> Option<FieldError> {
    ui.data(|d| d.get_temp::<Buffer>(field_id(ui, label, None)))
        .and_then(|b| b.error)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_point_and_comma() {
        assert_eq!(parse_number("2,5"), Ok(2.5));
        assert_eq!(parse_number(" 2.5 "), Ok(2.5));
        assert_eq!(parse_number("\u{2212}0,125"), Ok(-0.125));
        assert_eq!(parse_number("1e-3"), Ok(1e-3));
        assert_eq!(parse_number("1,5e3"), Ok(1500.0));
    }

    #[test]
    fn refusals_name_their_cause() {
        assert_eq!(parse_number(""), Err(FieldError::Empty));
        assert!(matches!(
            parse_number("abc"),
            Err(FieldError::NotANumber { .. })
        ));
        assert!(matches!(
            parse_number("1e400"),
            Err(FieldError::NotFinite { .. })
        ));
        assert!(matches!(
            parse_number("inf"),
            Err(FieldError::NotFinite { .. })
        ));
        assert!(matches!(
            parse_number("1,234.5"),
            Err(FieldError::TwoSeparators { .. })
        ));
        assert!(matches!(
            parse_number("1,2,3"),
            Err(FieldError::TwoSeparators { .. })
        ));
        let root = Limits::new(-1e6, 1e6, LimitReason::RootMagnitude);
        assert!(matches!(
            root.parse("-1e300"),
            Err(FieldError::Below { .. })
        ));
        assert_eq!(root.parse("-3,5"), Ok(-3.5));
        let text = root.parse("1e300").unwrap_err().text(Lang::Pt);
        assert!(text.contains("maior"), "{text}");
        assert!(text.contains("1e6") || text.contains("1000000"), "{text}");
    }
}
