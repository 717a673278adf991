//! The closed form of y(t) as text, the way the course notes write it: partial fractions
//! with simple fractions where the numbers are simple, e.g. for 0.5/((s²+2s+5)(s+5)), A = 2:
//!
//! `y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100`
//!
//! or, in amplitude–phase form, `1/25 − (1/20)e^{−t} sin(2t + 36.87°) − e^{−5t}/100`.
//! Repeated poles give t·e^{pt} terms; a dead time θ writes (t − θ) for t and says that
//! y = 0 before it. A cluster of distinct but nearly equal poles is written as a repeated
//! pole at its centre; when that form differs visibly from the exact y(t), the text says
//! "≈", names the poles and states the largest difference.

use super::number::format_number;
use super::response::StepResponse;
use crate::words::expr as words;
use degrau_words::Lang;

/// How oscillatory terms are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OscillationForm {
    /// `C e^{σt}[cos ωt + β sin ωt]`
    CosSin,
    /// `R e^{σt} sin(ωt + φ)` with φ in degrees, −90° < φ ≤ 90°
    AmplitudePhase,
}

/// Largest denominator tried when a number is written as a fraction.
const MAX_DENOMINATOR: i64 = 1000;
/// A fraction must match the number to this relative accuracy.
const FRACTION_TOLERANCE: f64 = 1e-10;
/// A repeated-pole form this close to the exact y (relative to the size of its terms) is
/// written with "=": the difference is far below the six digits printed.
const INVISIBLE_ERROR: f64 = 1e-10;
/// Terms smaller than this fraction of the largest are dropped as rounding noise.
const NEGLIGIBLE_TERM: f64 = 1e-13;

/// One additive term: coefficient × t^power × e^{σt} × (oscillation or 1).
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    /// Power of t (repeated poles).
    pub power: usize,
    /// Real part of the pole, σ (1/s).
    pub sigma: f64,
    /// For an oscillatory term: (ω, a, b) meaning a·cos ωt + b·sin ωt; else the
    /// coefficient is `a` and ω = 0.
    pub omega: f64,
    pub cos: f64,
    pub sin: f64,
}

/// The real terms of y(t) (for t ≥ θ, in the shifted time t − θ).
pub fn terms(response: &StepResponse) -> Vec<Term> {
    let mut out = Vec::new();
    for c in response.clusters() {
        for (j, q) in c.coeffs.iter().enumerate() {
            let term = if c.weight == 2.0 {
                Term {
                    power: j,
                    sigma: c.center.re,
                    omega: c.center.im,
                    cos: 2.0 * q.re,
                    sin: -2.0 * q.im,
                }
            } else {
                Term {
                    power: j,
                    sigma: c.center.re,
                    omega: 0.0,
                    cos: q.re,
                    sin: 0.0,
                }
            };
            out.push(term);
        }
    }
    let largest = out
        .iter()
        .map(|t| t.cos.abs().max(t.sin.abs()))
        .fold(0.0, f64::max);
    out.retain(|t| t.cos.abs().max(t.sin.abs()) > NEGLIGIBLE_TERM * largest);
    // Constant first, then by decay rate (slowest first), as the notes order them.
    out.sort_by(|a, b| {
        let key = |t: &Term| (t.sigma != 0.0 || t.omega != 0.0, -t.sigma, t.power);
        key(a)
            .partial_cmp(&key(b))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    out
}

/// `y(t) = …` for a step response, in English (the CLI's text and JSON).
pub fn expression(response: &StepResponse, form: OscillationForm) -> String {
    expression_in(response, form, Lang::En)
}

/// `y(t) = …` for a step response, its words in `lang`; in Portuguese the numbers take the
/// decimal comma and a list of poles is separated by semicolons.
pub fn expression_in(response: &StepResponse, form: OscillationForm, lang: Lang) -> String {
    let text = english_numbers(response, form, lang);
    lang.localize_number(&text)
}

/// [`expression_in`] with the numbers still written with points.
fn english_numbers(response: &StepResponse, form: OscillationForm, lang: Lang) -> String {
    let delay = response.delay();
    let var = if delay > 0.0 {
        format!("(t − {})", format_number(delay))
    } else {
        "t".to_string()
    };
    let mut body = String::new();
    for term in terms(response) {
        let (sign, text) = format_term(&term, &var, form);
        if body.is_empty() {
            if sign < 0.0 {
                body.push('−');
            }
        } else {
            body.push_str(if sign < 0.0 { " − " } else { " + " });
        }
        body.push_str(&text);
    }
    if body.is_empty() {
        body.push('0');
    }
    let (relation, note) = approximation_note(response, lang);
    if delay > 0.0 {
        let d = format_number(delay);
        let after = words::after_the_delay(&d, lang);
        format!("y(t) {relation} {body} {after}{note}")
    } else {
        format!("y(t) {relation} {body}{note}")
    }
}

/// "=" when the text is the exact form (to far below the digits it prints); "≈" and a note
/// naming the clusters of distinct poles written as repeated poles at their centres, and
/// how far that form is from the exact y(t), otherwise.
fn approximation_note(response: &StepResponse, lang: Lang) -> (&'static str, String) {
    let error = response.repeated_form_error();
    if error <= INVISIBLE_ERROR * response.magnitude_scale() {
        return ("=", String::new());
    }
    let clusters: Vec<String> = response
        .clusters()
        .iter()
        .filter(|c| !c.is_repeated())
        .map(|c| {
            let poles: Vec<String> = c.poles().iter().map(|&p| format_root(p)).collect();
            words::cluster(&poles, c.multiplicity, &format_root(c.center), lang)
        })
        .collect();
    let error = error.is_finite().then(|| format_number(error));
    let note = words::approximation_note(&clusters, error.as_deref(), lang);
    ("≈", note)
}

/// `-1.0002`, `-0.5+3j` with [`format_number`]'s digits.
fn format_root(p: super::C64) -> String {
    if p.im == 0.0 {
        format_number(p.re)
    } else {
        let sign = if p.im < 0.0 { '-' } else { '+' };
        format!(
            "{}{sign}{}j",
            format_number(p.re),
            format_number(p.im.abs())
        )
    }
}

/// The sign of a term and its text without sign.
fn format_term(term: &Term, var: &str, form: OscillationForm) -> (f64, String) {
    let time_factor = match term.power {
        0 => String::new(),
        1 => var.to_string(),
        p => format!("{var}^{p}"),
    };
    let exponential = exponential(term.sigma, var);
    let factors: Vec<&str> = [time_factor.as_str(), exponential.as_str()]
        .into_iter()
        .filter(|s| !s.is_empty())
        .collect();
    let core = factors.join("·");
    if term.omega == 0.0 {
        let coefficient = term.cos;
        return (coefficient.signum(), scaled(coefficient.abs(), &core));
    }
    let w = frequency(term.omega, var);
    match form {
        OscillationForm::CosSin => {
            if term.cos.abs() <= NEGLIGIBLE_TERM * term.sin.abs() {
                let core = join_nonempty(&core, &format!("sin {w}"));
                return (term.sin.signum(), scaled(term.sin.abs(), &core));
            }
            let beta = term.sin / term.cos;
            let bracket = if beta.abs() <= NEGLIGIBLE_TERM {
                format!("cos {w}")
            } else {
                let sign = if beta < 0.0 { "−" } else { "+" };
                // [cos t + sin t], not [cos t + 1 sin t].
                let factor = match factor_text(beta.abs()) {
                    one if one == "1" => String::new(),
                    factor => format!("{factor} "),
                };
                format!("[cos {w} {sign} {factor}sin {w}]")
            };
            let core = format!("{core}{bracket}");
            (term.cos.signum(), scaled(term.cos.abs(), &core))
        }
        OscillationForm::AmplitudePhase => {
            // a cos x + b sin x = R sin(x + φ), φ = atan2(a, b); keep |φ| ≤ 90°.
            let mut amplitude = term.cos.hypot(term.sin);
            let mut phase = term.cos.atan2(term.sin).to_degrees();
            if phase > 90.0 {
                phase -= 180.0;
                amplitude = -amplitude;
            } else if phase <= -90.0 {
                phase += 180.0;
                amplitude = -amplitude;
            }
            let shift = if phase.abs() < 0.005 {
                String::new()
            } else if phase < 0.0 {
                format!(" − {:.2}°", -phase)
            } else {
                format!(" + {phase:.2}°")
            };
            let core = join_nonempty(&core, &format!("sin({w}{shift})"));
            (amplitude.signum(), scaled(amplitude.abs(), &core))
        }
    }
}

/// `core` multiplied by a positive coefficient: `1/25`, `e^{−5t}/100`, `(3/100)e^{−t}`,
/// `2e^{−t}`, `0.12345 t`.
fn scaled(coefficient: f64, core: &str) -> String {
    if core.is_empty() {
        return coefficient_text(coefficient);
    }
    match fraction(coefficient) {
        Some((1, 1)) => core.to_string(),
        Some((p, 1)) => format!("{p}{core}"),
        Some((1, q)) if core.starts_with("e^") && !core.contains(' ') => format!("{core}/{q}"),
        Some((p, q)) => format!("({p}/{q}){core}"),
        None => format!("{} {core}", format_number(coefficient)),
    }
}

fn join_nonempty(a: &str, b: &str) -> String {
    if a.is_empty() {
        b.to_string()
    } else {
        format!("{a} {b}")
    }
}

/// `e^{−t}`, `e^{−5t}`, `e^{0.5(t − 0.3)}`; empty for σ = 0.
fn exponential(sigma: f64, var: &str) -> String {
    if sigma == 0.0 {
        return String::new();
    }
    let sign = if sigma < 0.0 { "−" } else { "" };
    let magnitude = sigma.abs();
    // Compare the text, not the number: a rate of 1.0000000000000002 (roots computed from
    // coefficients) prints as "1" and must be left out just like an exact 1.
    let number = match format_number(magnitude) {
        one if one == "1" => String::new(),
        number => number,
    };
    format!("e^{{{sign}{number}{var}}}")
}

/// `2t`, `t`, `2.5(t − 0.3)`.
fn frequency(omega: f64, var: &str) -> String {
    match format_number(omega) {
        one if one == "1" => var.to_string(),
        number => format!("{number}{var}"),
    }
}

/// A factor inside a bracket: `(4/3)`, `2`, `0.123457`.
fn factor_text(x: f64) -> String {
    match fraction(x) {
        Some((p, q)) if q != 1 => format!("({p}/{q})"),
        _ => coefficient_text(x),
    }
}

/// A positive coefficient as a fraction when it is a simple one, else a decimal.
fn coefficient_text(x: f64) -> String {
    match fraction(x) {
        Some((p, 1)) => p.to_string(),
        Some((p, q)) => format!("{p}/{q}"),
        None => format_number(x),
    }
}

/// The fraction p/q (q ≤ 1000) equal to x to 1e-10 relative, by continued fractions.
pub fn fraction(x: f64) -> Option<(i64, i64)> {
    if !x.is_finite() || x.abs() > 1e9 {
        return None;
    }
    let (mut h0, mut h1) = (0i64, 1i64);
    let (mut k0, mut k1) = (1i64, 0i64);
    let mut rest = x.abs();
    for _ in 0..20 {
        let a = rest.floor();
        if a > 1e9 {
            break;
        }
        let a = a as i64;
        let (h2, k2) = (a * h1 + h0, a * k1 + k0);
        if k2 > MAX_DENOMINATOR {
            return None;
        }
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        let value = h1 as f64 / k1 as f64;
        if (value - x.abs()).abs() <= FRACTION_TOLERANCE * x.abs() {
            return Some((h1 * x.signum() as i64, k1));
        }
        let frac = rest - a as f64;
        if frac == 0.0 {
            break;
        }
        rest = 1.0 / frac;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{C64, TransferFunction};

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    fn response(zeros: &[C64], poles: &[C64], k: f64, a: f64) -> StepResponse {
        StepResponse::new(&TransferFunction::from_zpk(zeros, poles, k).unwrap(), a).unwrap()
    }

    /// The note on clustered poles in Portuguese: its words, the decimal comma, and the
    /// poles listed with semicolons (a comma would split -1,0001).
    #[test]
    fn a_cluster_note_in_portuguese() {
        let poles: Vec<C64> = (0..5).map(|i| c(-1.0 - 1e-4 * i as f64, 0.0)).collect();
        let r = response(&[], &poles, 1.0, 1.0);
        let en = expression_in(&r, OscillationForm::CosSin, Lang::En);
        let pt = expression_in(&r, OscillationForm::CosSin, Lang::Pt);
        assert!(
            en.starts_with("y(t) ≈") && en.contains("the poles -1, -1.0001"),
            "{en}"
        );
        assert!(
            pt.contains("[escrita com os polos -1; -1,0001; -1,0002"),
            "{pt}"
        );
        assert!(
            pt.contains("como um polo de multiplicidade 5 em -1,0002"),
            "{pt}"
        );
        assert!(pt.contains("difere do y(t) exato em até"), "{pt}");
        assert!(!pt.contains('.'), "{pt}");
    }

    #[test]
    fn the_notes_example_in_both_forms() {
        let r = response(&[], &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)], 0.5, 2.0);
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = 1/25 − (3/100)e^{−t}[cos 2t + (4/3) sin 2t] − e^{−5t}/100"
        );
        assert_eq!(
            expression(&r, OscillationForm::AmplitudePhase),
            "y(t) = 1/25 − (1/20)e^{−t} sin(2t + 36.87°) − e^{−5t}/100"
        );
    }

    #[test]
    fn the_notes_zero_at_minus_ten_example() {
        // 0.5(s+10)/(s³+7s²+15s+25), A = 5: y = 1 − (7/8)e^{−t}[cos 2t + (6/7) sin 2t] − e^{−5t}/8.
        let r = response(
            &[c(-10.0, 0.0)],
            &[c(-1.0, 2.0), c(-1.0, -2.0), c(-5.0, 0.0)],
            0.5,
            5.0,
        );
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = 1 − (7/8)e^{−t}[cos 2t + (6/7) sin 2t] − e^{−5t}/8"
        );
    }

    #[test]
    fn repeated_poles_give_t_terms() {
        let r = response(&[c(-5.0, 0.0)], &[c(-10.0, 0.0), c(-10.0, 0.0)], 1.0, 1.0);
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = 1/20 − e^{−10t}/20 + (1/2)t·e^{−10t}"
        );
    }

    #[test]
    fn delay_and_ramp() {
        let g = TransferFunction::from_zpk(&[], &[c(0.0, 0.0), c(-1.0, 0.0)], 1.0)
            .unwrap()
            .with_delay(0.3)
            .unwrap();
        let r = StepResponse::new(&g, 1.0).unwrap();
        assert_eq!(
            expression(&r, OscillationForm::CosSin),
            "y(t) = −1 + (t − 0.3) + e^{−(t − 0.3)} for t ≥ 0.3 (y = 0 before 0.3)"
        );
    }

    #[test]
    fn numbers_and_fractions() {
        assert_eq!(fraction(0.04), Some((1, 25)));
        assert_eq!(fraction(4.0 / 3.0), Some((4, 3)));
        assert_eq!(fraction(std::f64::consts::PI), None);
    }
}
