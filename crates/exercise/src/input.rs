//! Reading what a student types, robustly: a number with a decimal point or comma, with or
//! without its unit, `inf`/`∞`, a fraction (`1/2`); a transfer function as an expression
//! (`10/(s+2)`) or as MATLAB's coefficient lists (`[10], [1 2]`, `tf(10, [1 2])`); a range
//! of gains (`0 < K ≤ 2,86`, `K > 0.03`, `(0, 2.86]`); a region (`ζ ≥ 0,4; σ ≥ 40`); a list
//! of roots (`-2; -4`, `-80 ± j208,7`); a word (`sobreamortecido`, `yes`).
//!
//! This module owns the answer syntax; expressions are [`crate::expr`]'s, complex numbers
//! [`degrau_lti::parse`]'s. Nothing here panics on any text.

use degrau_lti::C64;
use serde::{Deserialize, Serialize};

use crate::expr::{Expr, ExprError};
use crate::model::{Choice, GainRange, Unit};

/// What a student gives for one question.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StudentAnswer {
    /// Typed text (any kind of question).
    Text(String),
    /// A number from a numeric field.
    Number(f64),
    /// A transfer function from two coefficient fields (descending powers).
    Coefficients { num: Vec<f64>, den: Vec<f64> },
}

/// Why an answer cannot be read (said in words by [`crate::words`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InputError {
    #[error("nothing typed")]
    Empty,
    #[error("not a number: {0:?}")]
    NotNumber(String),
    #[error("not an expression: {0}")]
    Expression(ExprError),
    #[error("not a list of coefficients: {0:?}")]
    Coefficients(String),
    #[error("not a range of gains: {0:?}")]
    Range(String),
    #[error("not a region: {0:?}")]
    Region(String),
    #[error("not a list of roots: {0:?}")]
    Roots(String),
    #[error("not one of the words offered: {0:?}")]
    Choice(String),
    #[error("this kind of answer is not read from this field")]
    WrongField,
}

/// A number: `0,2`, `-1.5e-3`, `62 rad/s`, `ωn = 62,03`, `26 %`, `1/2`, `inf`, `∞`.
/// Returns the value and whether a `%` was typed.
pub fn number(text: &str, unit: Unit) -> Result<(f64, bool), InputError> {
    let body = text.rsplit(['=', '≈']).next().unwrap_or(text).trim();
    if body.is_empty() {
        return Err(InputError::Empty);
    }
    let percent = body.contains('%');
    let lower = body.to_lowercase();
    let bare = lower.trim_end_matches(|c: char| c == '%' || c.is_whitespace());
    let sign = if bare.starts_with(['-', '−']) {
        -1.0
    } else {
        1.0
    };
    let word = bare.trim_start_matches(['+', '-', '−']).trim();
    if matches!(word, "inf" | "∞" | "infinity" | "infinito" | "infinite") {
        return Ok((sign * f64::INFINITY, percent));
    }
    let (value, rest) = leading_number(body).ok_or_else(|| InputError::NotNumber(body.into()))?;
    let rest = rest.trim();
    let scale = unit_scale(rest, unit);
    if let Some(scale) = scale {
        return Ok((value * scale, percent));
    }
    // Not a number and a unit: a constant expression (`1/2`, `15/4`, `sqrt(120)`), with the
    // unit, if any, at its end.
    let expression = strip_unit(body, unit);
    let expr = Expr::parse(expression).map_err(|_| InputError::NotNumber(body.into()))?;
    expr.uses_only(&[])
        .map_err(|_| InputError::NotNumber(body.into()))?;
    let z = expr.eval(&Default::default());
    if z.im.abs() <= 1e-12 * z.re.abs() && z.re.is_finite() {
        Ok((z.re, percent))
    } else {
        Err(InputError::NotNumber(body.into()))
    }
}

/// The number at the start of `text` (decimal point, or one comma between digits; an
/// exponent) and what follows it.
fn leading_number(text: &str) -> Option<(f64, &str)> {
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let mut out = String::new();
    let mut i = 0;
    if let Some(&(_, c)) = chars.first()
        && matches!(c, '-' | '+' | '−')
    {
        out.push(if c == '+' { '+' } else { '-' });
        i = 1;
    }
    while chars.get(i).is_some_and(|(_, c)| c.is_whitespace()) {
        i += 1;
    }
    let digit = |k: usize| chars.get(k).is_some_and(|(_, c)| c.is_ascii_digit());
    let mut separator = false;
    let mut digits = 0;
    while let Some(&(_, c)) = chars.get(i) {
        if c.is_ascii_digit() {
            digits += 1;
            out.push(c);
        } else if !separator && (c == '.' || (c == ',' && digits > 0 && digit(i + 1))) {
            separator = true;
            out.push('.');
        } else {
            break;
        }
        i += 1;
    }
    if digits == 0 {
        return None;
    }
    if matches!(chars.get(i), Some((_, 'e' | 'E'))) {
        let signed = matches!(chars.get(i + 1), Some((_, '+' | '-')));
        let first = if signed { i + 2 } else { i + 1 };
        if digit(first) {
            out.push('e');
            if signed {
                out.push(chars[i + 1].1);
            }
            i = first;
            while digit(i) {
                out.push(chars[i].1);
                i += 1;
            }
        }
    }
    let rest = chars.get(i).map_or("", |&(at, _)| &text[at..]);
    out.parse()
        .ok()
        .filter(|x: &f64| x.is_finite())
        .map(|x| (x, rest))
}

/// The factor a typed unit means for a question in `unit` (`ms` for seconds is 1e-3), or
/// `None` when `rest` is not a unit.
fn unit_scale(rest: &str, unit: Unit) -> Option<f64> {
    let rest: String = rest.chars().filter(|c| !c.is_whitespace()).collect();
    let rest = rest.to_lowercase();
    if rest.is_empty() || rest == "%" {
        return Some(1.0);
    }
    let symbol: String = unit
        .symbol()
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect::<String>()
        .to_lowercase();
    if !symbol.is_empty() && rest == symbol {
        return Some(1.0);
    }
    match (unit, rest.as_str()) {
        (Unit::Seconds, "seg" | "sec" | "segundos" | "seconds") => Some(1.0),
        (Unit::Seconds, "ms") => Some(1e-3),
        (Unit::RadPerSecond, "rad/seg" | "rad.s^-1" | "rads^-1") => Some(1.0),
        (Unit::NewtonSecondPerMetre, "ns/m" | "n.s/m" | "n·s/m") => Some(1.0),
        (Unit::PerSecond, "1/s" | "s^-1" | "s-1") => Some(1.0),
        _ => None,
    }
}

/// `text` without the unit's symbol at its end.
fn strip_unit(text: &str, unit: Unit) -> &str {
    let symbol = unit.symbol();
    let trimmed = text.trim().trim_end_matches('%').trim_end();
    if !symbol.is_empty()
        && let Some(body) = trimmed.strip_suffix(symbol)
    {
        return body.trim_end();
    }
    trimmed
}

/// Numerator and denominator coefficients, descending powers.
pub type Coefficients = (Vec<f64>, Vec<f64>);

/// A transfer function typed as coefficient lists: `[10], [1 0.3 0]`, `tf([10],[1 2])`,
/// `num = [10]; den = [1 2]`. `None` when the text holds no brackets (an expression).
pub fn coefficient_lists(text: &str) -> Option<Result<Coefficients, InputError>> {
    if !text.contains('[') {
        return None;
    }
    let bad = || InputError::Coefficients(text.trim().to_string());
    let mut groups = Vec::new();
    let mut rest = text;
    while let Some(open) = rest.find('[') {
        let after = &rest[open + 1..];
        let Some(close) = after.find(']') else {
            return Some(Err(bad()));
        };
        groups.push(&after[..close]);
        rest = &after[close + 1..];
    }
    // tf(10, [1 2]): a bare numerator before the first bracket.
    if groups.len() == 1 {
        let head = text.split('[').next().unwrap_or("");
        let head = head.trim().trim_start_matches("tf").trim_start_matches('(');
        let head = head.trim().trim_end_matches([',', ';']).trim();
        if head.is_empty() {
            return Some(Err(bad()));
        }
        groups.insert(0, head);
    }
    if groups.len() != 2 {
        return Some(Err(bad()));
    }
    let list = |g: &str| -> Result<Vec<f64>, InputError> {
        let items = split_items(g);
        if items.is_empty() {
            return Err(bad());
        }
        items
            .iter()
            .map(|item| match leading_number(item) {
                Some((x, rest)) if rest.trim().is_empty() => Ok(x),
                _ => Err(bad()),
            })
            .collect()
    };
    Some(list(groups[0]).and_then(|num| Ok((num, list(groups[1])?))))
}

/// Splits a list on spaces, semicolons, and commas that are not between two digits (those
/// are decimal commas).
fn split_items(text: &str) -> Vec<String> {
    split_outside_decimals(text, true)
}

/// Splits on semicolons, commas that are not between two digits and, with `on_space`,
/// whitespace; pieces that are only whitespace are dropped.
fn split_outside_decimals(text: &str, on_space: bool) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut current = String::new();
    for (i, &c) in chars.iter().enumerate() {
        let decimal_comma = c == ','
            && i > 0
            && chars[i - 1].is_ascii_digit()
            && chars.get(i + 1).is_some_and(char::is_ascii_digit);
        if (on_space && c.is_whitespace()) || c == ';' || (c == ',' && !decimal_comma) {
            out.push(std::mem::take(&mut current));
        } else {
            current.push(c);
        }
    }
    out.push(current);
    out.into_iter().filter(|c| !c.trim().is_empty()).collect()
}

/// What a range answer says: both ends, or a bare number (one end, left to the check).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RangeAnswer {
    Range(GainRange),
    Bare(f64),
}

/// A range of gains: `0 < K ≤ 2,86`, `K <= 2.86`, `K > 0.03`, `2.86 ≥ K`, `(0, 2.86]`,
/// `]0; 2,86]`, `[0.03, inf)`, or a bare number. A missing lower end is 0 (gains are
/// positive), a missing upper end ∞.
pub fn gain_range(text: &str) -> Result<RangeAnswer, InputError> {
    let bad = || InputError::Range(text.trim().to_string());
    let compact: String = text
        .trim()
        .replace('≤', "<=")
        .replace('≥', ">=")
        .replace('−', "-")
        .replace('k', "K");
    if compact.is_empty() {
        return Err(InputError::Empty);
    }
    if compact.contains('K') {
        let pieces = split_relations(&compact).ok_or_else(bad)?;
        let mut range = GainRange {
            low: 0.0,
            high: f64::INFINITY,
        };
        let at = pieces.iter().position(|(p, _)| p == "K").ok_or_else(bad)?;
        for (i, (piece, _)) in pieces.iter().enumerate() {
            if i == at {
                continue;
            }
            let value = number(piece, Unit::None).map_err(|_| bad())?.0;
            // The relation between this piece and K: the operator between them.
            let (op, left) = if i < at {
                (pieces[i].1, true)
            } else {
                (pieces[i - 1].1, false)
            };
            let below = matches!((op, left), ('<', true) | ('>', false));
            if below {
                range.low = value;
            } else {
                range.high = value;
            }
        }
        return Ok(RangeAnswer::Range(range));
    }
    let opened = compact.starts_with(['(', '[', ']']);
    if opened || compact.contains("..") {
        let inner = compact.trim_matches(['(', ')', '[', ']']);
        let items: Vec<String> = if inner.contains("..") {
            inner.split("..").map(str::to_string).collect()
        } else {
            split_items(inner)
        };
        if items.len() != 2 {
            return Err(bad());
        }
        let low = number(&items[0], Unit::None).map_err(|_| bad())?.0;
        let high = number(&items[1], Unit::None).map_err(|_| bad())?.0;
        return Ok(RangeAnswer::Range(GainRange { low, high }));
    }
    number(&compact, Unit::None)
        .map(|(x, _)| RangeAnswer::Bare(x))
        .map_err(|_| bad())
}

/// `0<K<=2.86` as [("0", '<'), ("K", '<'), ("2.86", ' ')]: each piece and the relation
/// (`<` or `>`, whether or not it allows equality) after it.
fn split_relations(text: &str) -> Option<Vec<(String, char)>> {
    let mut out = Vec::new();
    let mut current = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '<' || c == '>' {
            if chars.peek() == Some(&'=') {
                chars.next();
            }
            out.push((current.trim().to_string(), c));
            current.clear();
        } else {
            current.push(c);
        }
    }
    out.push((current.trim().to_string(), ' '));
    (out.len() >= 2 && out.iter().all(|(p, _)| !p.is_empty())).then_some(out)
}

/// One bound of a region answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RegionBound {
    /// ζ ≥ this.
    ZetaMin(f64),
    /// σ = −Re(s) ≥ this.
    SigmaMin(f64),
}

/// A region: bounds separated by `;`, a new line, `e`/`and`, or a comma followed by a space:
/// `ζ ≥ 0,4; σ ≥ 40`, `zeta >= 0.4, sigma >= 40`, `θ ≤ 66,4°`, `Re(s) ≤ -40`.
pub fn region(text: &str) -> Result<Vec<RegionBound>, InputError> {
    let bad = || InputError::Region(text.trim().to_string());
    let normal = text
        .replace('≤', "<=")
        .replace('≥', ">=")
        .replace('−', "-")
        .replace(" and ", ";")
        .replace(" e ", ";")
        .replace(", ", ";")
        .replace('\n', ";");
    let mut out = Vec::new();
    for item in normal.split(';').map(str::trim).filter(|i| !i.is_empty()) {
        let (key, op, value) = ["<=", ">=", "<", ">"]
            .iter()
            .find_map(|op| {
                item.split_once(op)
                    .map(|(k, v)| (k.trim().to_lowercase(), *op, v.trim()))
            })
            .ok_or_else(bad)?;
        let value = value.trim_end_matches(['°', 'º']).trim();
        let x = number(value, Unit::None).map_err(|_| bad())?.0;
        let at_least = op.starts_with('>');
        let bound = match key.as_str() {
            "ζ" | "zeta" | "ξ" | "csi" | "qsi" if at_least => RegionBound::ZetaMin(x),
            "θ" | "theta" if !at_least => RegionBound::ZetaMin(x.to_radians().cos()),
            "σ" | "sigma" | "ζωn" | "zeta*wn" | "-re(s)" if at_least => RegionBound::SigmaMin(x),
            "re(s)" | "re s" if !at_least => RegionBound::SigmaMin(-x),
            _ => return Err(bad()),
        };
        out.push(bound);
    }
    if out.is_empty() {
        return Err(InputError::Empty);
    }
    Ok(out)
}

/// A list of roots: `-2; -4`, `-2, -4`, `s = -10, -10`, `-1 ± j2`, `-80 ± j208,7`,
/// `-3+7j -3-7j`, `-1 + j2 -1 - j2`; `none`/`nenhum`/`-` for no roots.
pub fn roots(text: &str) -> Result<Vec<C64>, InputError> {
    let bad = || InputError::Roots(text.trim().to_string());
    let body = text
        .rsplit('=')
        .next()
        .unwrap_or(text)
        .trim()
        .replace('−', "-");
    let lower = body.to_lowercase();
    if matches!(
        lower.as_str(),
        "none" | "nenhum" | "nenhuma" | "não tem" | "nao tem" | "-" | "∅" | "{}"
    ) {
        return Ok(Vec::new());
    }
    if body.is_empty() {
        return Err(InputError::Empty);
    }
    let imaginary = |w: &str| w.contains(['j', 'i']);
    let mut items: Vec<String> = Vec::new();
    for chunk in split_separators(&body) {
        let words: Vec<&str> = chunk.split_whitespace().collect();
        // A sign standing alone belongs to the word after it.
        let mut merged: Vec<String> = Vec::new();
        let mut i = 0;
        while i < words.len() {
            if matches!(words[i], "+" | "-" | "±") && i + 1 < words.len() {
                merged.push(format!("{}{}", words[i], words[i + 1]));
                i += 2;
            } else {
                merged.push(words[i].to_string());
                i += 1;
            }
        }
        let mut in_chunk: Vec<String> = Vec::new();
        for w in merged {
            let signed = w.starts_with(['+', '-', '±']);
            match in_chunk.last_mut() {
                // `-3 +7j`: the imaginary part of the real part before it.
                Some(prev) if signed && imaginary(&w) && !imaginary(prev) => prev.push_str(&w),
                _ => in_chunk.push(w),
            }
        }
        items.extend(in_chunk);
    }
    let mut out = Vec::new();
    for item in items {
        match item.split_once('±') {
            Some((re, im)) => {
                let re = if re.trim().is_empty() {
                    0.0
                } else {
                    number(re, Unit::None).map_err(|_| bad())?.0
                };
                let im = imaginary_part(im).ok_or_else(bad)?;
                out.push(C64::new(re, im));
                out.push(C64::new(re, -im));
            }
            None => out.push(complex(&item).ok_or_else(bad)?),
        }
    }
    Ok(out)
}

/// Splits on semicolons and on commas that are not between two digits.
fn split_separators(text: &str) -> Vec<String> {
    split_outside_decimals(text, false)
}

/// `j2`, `2j`, `2,5j`, `j` as the imaginary coefficient.
fn imaginary_part(text: &str) -> Option<f64> {
    let t = text.trim();
    let digits = t
        .strip_prefix(['j', 'i'])
        .or_else(|| t.strip_suffix(['j', 'i']))?
        .trim()
        .trim_start_matches(['*', '·']);
    if digits.is_empty() {
        return Some(1.0);
    }
    match leading_number(digits) {
        Some((x, rest)) if rest.trim().is_empty() => Some(x),
        _ => None,
    }
}

/// One complex number in any of the sheet's spellings: `-2`, `-1+j2`, `-1+2j`, `-2,5`.
fn complex(item: &str) -> Option<C64> {
    let s = item.replace(',', ".");
    if let Some(p) = s.find(['j', 'i']) {
        let after = &s[p + 1..];
        if after.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
            if !after.chars().all(|c| c.is_ascii_digit() || c == '.') {
                return None;
            }
            return degrau_lti::parse::parse_complex(&format!("{}{after}j", &s[..p])).ok();
        }
    }
    degrau_lti::parse::parse_complex(&s).ok()
}

/// A word of a choice: `sobreamortecido`, `overdamped`, `ζ > 1`, `sim`, `no`, or the
/// choice's id.
pub fn choice(text: &str, options: &[Choice]) -> Result<Choice, InputError> {
    let t = text.trim().to_lowercase().replace(['-', '_'], " ");
    if t.is_empty() {
        return Err(InputError::Empty);
    }
    let t = t.as_str();
    let found = options.iter().copied().find(|c| {
        let words: &[&str] = match c {
            Choice::Overdamped => &[
                "overdamped",
                "over damped",
                "sobreamortecid",
                "ζ > 1",
                "ζ>1",
            ],
            Choice::CriticallyDamped => &["critical", "crítica", "critica", "ζ = 1", "ζ=1"],
            Choice::Underdamped => &[
                "underdamped",
                "under damped",
                "subamortecid",
                "0<ζ<1",
                "0 < ζ < 1",
            ],
            Choice::Undamped => &[
                "undamped",
                "sem amortecimento",
                "não amortecid",
                "nao amortecid",
                "ζ = 0",
                "ζ=0",
            ],
            Choice::Yes => &["yes", "sim", "y", "s"],
            Choice::No => &["no", "não", "nao", "n"],
        };
        let short = matches!(c, Choice::Yes | Choice::No);
        t == c.id().replace('_', " ")
            || words
                .iter()
                .any(|w| if short { t == *w } else { t.contains(w) })
    });
    found.ok_or_else(|| InputError::Choice(text.trim().to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_with_commas_units_and_infinity() {
        let n = |t: &str, u: Unit| number(t, u).map(|(x, _)| x);
        assert_eq!(n("0,2", Unit::Seconds), Ok(0.2));
        assert_eq!(n(" 0.439 s", Unit::Seconds), Ok(0.439));
        assert_eq!(n("ωn = 62,03 rad/s", Unit::RadPerSecond), Ok(62.03));
        assert_eq!(n("26 %", Unit::Percent), Ok(26.0));
        assert_eq!(n("1/2", Unit::None), Ok(0.5));
        assert_eq!(n("15/4", Unit::None), Ok(3.75));
        assert_eq!(n("-2.5e-3", Unit::None), Ok(-2.5e-3));
        assert_eq!(n("780 ms", Unit::Seconds), Ok(0.78));
        assert_eq!(n("inf", Unit::None), Ok(f64::INFINITY));
        assert_eq!(n("∞", Unit::None), Ok(f64::INFINITY));
        assert_eq!(n("Kp = infinito", Unit::None), Ok(f64::INFINITY));
        assert_eq!(n("201,71 N s/m", Unit::NewtonSecondPerMetre), Ok(201.71));
        assert!(n("", Unit::None).is_err());
        assert!(n("abc", Unit::None).is_err());
        assert!(n("2.86 or 3", Unit::None).is_err());
        assert!(n("1,2,3", Unit::None).is_err());
    }

    #[test]
    fn coefficient_lists_in_matlab_form() {
        assert_eq!(
            coefficient_lists("[10], [1 0.3 0]"),
            Some(Ok((vec![10.0], vec![1.0, 0.3, 0.0])))
        );
        assert_eq!(
            coefficient_lists("tf(10, [1 0,3 0])"),
            Some(Ok((vec![10.0], vec![1.0, 0.3, 0.0])))
        );
        assert_eq!(
            coefficient_lists("num=[1, 2]; den=[1, 4, 0]"),
            Some(Ok((vec![1.0, 2.0], vec![1.0, 4.0, 0.0])))
        );
        assert_eq!(coefficient_lists("10/(s+2)"), None);
        assert!(matches!(coefficient_lists("[1 x]"), Some(Err(_))));
    }

    #[test]
    fn ranges_in_every_spelling() {
        let r = |low: f64, high: f64| Ok(RangeAnswer::Range(GainRange { low, high }));
        assert_eq!(gain_range("0 < K ≤ 2,86"), r(0.0, 2.86));
        assert_eq!(gain_range("K <= 2.86"), r(0.0, 2.86));
        assert_eq!(gain_range("K > 0.03"), r(0.03, f64::INFINITY));
        assert_eq!(gain_range("2.86 >= K"), r(0.0, 2.86));
        assert_eq!(gain_range("(0, 2.86]"), r(0.0, 2.86));
        assert_eq!(gain_range("]0; 2,86]"), r(0.0, 2.86));
        assert_eq!(gain_range("[0.03, inf)"), r(0.03, f64::INFINITY));
        assert_eq!(gain_range("2,86"), Ok(RangeAnswer::Bare(2.86)));
        assert!(gain_range("K <").is_err());
        assert!(gain_range("K ~ 3").is_err());
    }

    #[test]
    fn regions_and_roots() {
        assert_eq!(
            region("ζ ≥ 0,4; σ ≥ 40"),
            Ok(vec![RegionBound::ZetaMin(0.4), RegionBound::SigmaMin(40.0)])
        );
        assert_eq!(
            region("zeta >= 0.4, Re(s) <= -40"),
            Ok(vec![RegionBound::ZetaMin(0.4), RegionBound::SigmaMin(40.0)])
        );
        assert!(
            matches!(region("θ ≤ 60°").as_deref(), Ok([RegionBound::ZetaMin(z)]) if (z - 0.5).abs() < 1e-12)
        );
        assert!(region("ζ = 0.4").is_err());
        let c = |re: f64, im: f64| C64::new(re, im);
        assert_eq!(roots("-2; -4"), Ok(vec![c(-2.0, 0.0), c(-4.0, 0.0)]));
        assert_eq!(roots("s = -2, -4"), Ok(vec![c(-2.0, 0.0), c(-4.0, 0.0)]));
        assert_eq!(roots("-1 ± j2"), Ok(vec![c(-1.0, 2.0), c(-1.0, -2.0)]));
        assert_eq!(
            roots("-80 ± j208,7"),
            Ok(vec![c(-80.0, 208.7), c(-80.0, -208.7)])
        );
        assert_eq!(roots("-3+7j, -3-7j"), Ok(vec![c(-3.0, 7.0), c(-3.0, -7.0)]));
        assert_eq!(
            roots("-3 + 7j; -3 - 7j"),
            Ok(vec![c(-3.0, 7.0), c(-3.0, -7.0)])
        );
        assert_eq!(
            roots("-1 + j2 -1 - j2"),
            Ok(vec![c(-1.0, 2.0), c(-1.0, -2.0)])
        );
        assert_eq!(roots("-2,5"), Ok(vec![c(-2.5, 0.0)]));
        assert_eq!(roots("nenhum"), Ok(vec![]));
        assert!(roots("-1 ± x").is_err());
    }

    #[test]
    fn words_of_choices() {
        let types = Choice::RESPONSE_TYPES;
        assert_eq!(choice("Sobreamortecida", &types), Ok(Choice::Overdamped));
        assert_eq!(
            choice("criticamente amortecida", &types),
            Ok(Choice::CriticallyDamped)
        );
        assert_eq!(choice("under-damped", &types), Ok(Choice::Underdamped));
        assert_eq!(choice("sim", &Choice::YES_NO), Ok(Choice::Yes));
        assert_eq!(choice("Não", &Choice::YES_NO), Ok(Choice::No));
        assert!(choice("talvez", &Choice::YES_NO).is_err());
    }
}
