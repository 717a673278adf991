//! Checking a student's answer against Degrau's ([`check`]), and the text of Degrau's own
//! answer as a student would type it ([`typed_answer`], which [`check`] reads back as right).
//!
//! A number is right within the question's tolerance of Degrau's exact value or of a value
//! the question also accepts (the second-order formula's, another definition of a metric); a
//! transfer function when it equals Degrau's at points of the right half plane (for every K
//! tried, when it is a loop's in K); a closed form when it equals the exact y(t) at the
//! question's instants; a range when both ends match; a region when its ζ and σ bounds
//! match; roots as a multiset.

use degrau_lti::C64;
use degrau_words::{Lang, Localize};
use serde::Serialize;

use crate::expr::{Env, Expr, Var};
use crate::input::{self, InputError, RangeAnswer, RegionBound, StudentAnswer};
use crate::model::{Expected, GainRange, Question, Region, TfAnswer, Tolerance, Unit, Value};
use crate::text::{self, Text, num};
use crate::words::Phrase;

/// The outcome of a check.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    pub right: bool,
    /// Degrau's exact answer, in words.
    pub expected: Text,
    /// The other values accepted (the formula's), in words, when there are any.
    pub formula: Option<Text>,
    /// What to tell the student: right or not, which value matched, why the sheet differs.
    pub message: Text,
    /// The answer could not be read (then `right` is false).
    pub unreadable: bool,
}

/// Checks `answer` against Degrau's answer to `question`.
pub fn check(question: &Question, answer: &StudentAnswer) -> Verdict {
    let expected = Text::by(|l| describe_expected(question, l));
    let formula = also(question);
    match judge(question, answer) {
        Err(e) => Verdict {
            right: false,
            expected,
            formula,
            message: Text::by(|l| e.text(l)),
            unreadable: true,
        },
        Ok(matched) => {
            let right = matched.is_some();
            let message = Text::by(|l| {
                let mut m = match &matched {
                    Some(None) => Phrase::Right.get(l).to_string(),
                    Some(Some(how)) => format!(
                        "{} {}",
                        Phrase::Right.get(l),
                        l.pick(
                            format!("Accepted as the value of: {}.", how.get(l)),
                            format!("Aceite como o valor de: {}.", how.get(l)),
                        )
                    ),
                    None => format!(
                        "{} {}",
                        Phrase::Wrong.get(l),
                        l.pick(
                            format!("Degrau's answer: {}.", expected.get(l)),
                            format!("Resposta do Degrau: {}.", expected.get(l)),
                        )
                    ),
                };
                if let (Some(f), Some(_)) = (&formula, &matched) {
                    m.push(' ');
                    m.push_str(&l.pick(
                        format!("Exact: {}; also accepted: {}.", expected.get(l), f.get(l)),
                        format!("Exato: {}; também aceite: {}.", expected.get(l), f.get(l)),
                    ));
                }
                if !right && let Some(note) = sheet_note(question, answer) {
                    m.push(' ');
                    m.push_str(note.get(l));
                }
                m
            });
            Verdict {
                right,
                expected,
                formula,
                message,
                unreadable: false,
            }
        }
    }
}

/// When the answer is the sheet's printed one and the sheet differs from Degrau: why.
fn sheet_note(question: &Question, answer: &StudentAnswer) -> Option<Text> {
    let difference = question.difference.as_ref()?;
    let printed = question.sheet.as_ref()?;
    let same = same_as_sheet(question, answer, printed);
    let always = Text::by(|l| format!("{} {}", Phrase::SheetNote.get(l), difference.get(l)));
    // Said when the student typed the sheet's answer; otherwise only when it may help.
    same.then_some(always)
}

/// Whether the student's answer is the sheet's printed one: the same number or range
/// (within the question's tolerance), or the same text.
fn same_as_sheet(question: &Question, answer: &StudentAnswer, printed: &str) -> bool {
    let tol = question.tolerance;
    match (&question.expected, answer) {
        (Expected::Number { unit, .. }, _) => {
            let typed = match answer {
                StudentAnswer::Number(x) => Some(*x),
                StudentAnswer::Text(t) => input::number(t, *unit).ok().map(|(x, _)| x),
                StudentAnswer::Coefficients { .. } => None,
            };
            let sheet = input::number(printed, *unit).ok().map(|(x, _)| x);
            matches!((typed, sheet), (Some(a), Some(b)) if tol.accepts(a, b))
        }
        (Expected::GainRange { .. }, StudentAnswer::Text(t)) => {
            match (input::gain_range(t), input::gain_range(printed)) {
                (Ok(RangeAnswer::Range(a)), Ok(RangeAnswer::Range(b))) => {
                    range_matches(RangeAnswer::Range(a), b, tol)
                }
                (Ok(RangeAnswer::Bare(a)), Ok(RangeAnswer::Bare(b))) => tol.accepts(a, b),
                _ => false,
            }
        }
        (_, StudentAnswer::Text(t)) => normal(t) == normal(printed),
        _ => false,
    }
}

fn normal(text: &str) -> String {
    text.chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| if c == ',' { '.' } else { c })
        .collect::<String>()
        .to_lowercase()
}

/// `Ok(Some(None))`: right, the exact value; `Ok(Some(Some(how)))`: right, a value also
/// accepted; `Ok(None)`: wrong; `Err`: unreadable.
fn judge(q: &Question, answer: &StudentAnswer) -> Result<Option<Option<Text>>, InputError> {
    let tol = q.tolerance;
    match &q.expected {
        Expected::Number { unit, main, also } => {
            let x = match answer {
                StudentAnswer::Number(x) => *x,
                StudentAnswer::Text(t) => {
                    let (x, percent) = input::number(t, *unit)?;
                    // Mp typed as a fraction (0,26 for 26 %).
                    if *unit == Unit::Percent && !percent && x.abs() < 1.0 && main.value > 1.0 {
                        100.0 * x
                    } else {
                        x
                    }
                }
                StudentAnswer::Coefficients { .. } => return Err(InputError::WrongField),
            };
            if tol.accepts(x, main.value) {
                return Ok(Some(None));
            }
            Ok(also
                .iter()
                .find(|v| tol.accepts(x, v.value))
                .map(|v| Some(v.how.clone())))
        }
        Expected::TransferFunction(tf) => {
            let same = same_tf(tf, answer, tol)?;
            Ok(same.then_some(None))
        }
        Expected::GainRange { main, also } => {
            let typed = match answer {
                StudentAnswer::Text(t) => input::gain_range(t)?,
                StudentAnswer::Number(x) => RangeAnswer::Bare(*x),
                StudentAnswer::Coefficients { .. } => return Err(InputError::WrongField),
            };
            if range_matches(typed, *main, tol) {
                return Ok(Some(None));
            }
            Ok(also
                .iter()
                .find(|(r, _)| range_matches(typed, *r, tol))
                .map(|(_, how)| Some(how.clone())))
        }
        Expected::Region(region) => {
            let StudentAnswer::Text(t) = answer else {
                return Err(InputError::WrongField);
            };
            let bounds = input::region(t)?;
            Ok(region_matches(&bounds, *region, tol).then_some(None))
        }
        Expected::ClosedForm {
            tf,
            amplitude,
            instants,
        } => {
            let StudentAnswer::Text(t) = answer else {
                return Err(InputError::WrongField);
            };
            let expr = Expr::parse(t).map_err(InputError::Expression)?;
            expr.uses_only(&[Var::T]).map_err(InputError::Expression)?;
            let response = degrau_lti::StepResponse::new(tf, *amplitude)
                .map_err(|_| InputError::WrongField)?;
            let exact: Vec<f64> = instants.iter().map(|&t| response.value(t)).collect();
            let scale = exact.iter().fold(0.0f64, |m, y| m.max(y.abs())).max(1e-300);
            let ok = instants.iter().zip(&exact).all(|(&t, &y)| {
                let z = expr.eval(&Env {
                    t,
                    ..Env::default()
                });
                let bound = match tol {
                    Tolerance::Relative(r) => r * scale,
                    Tolerance::Absolute(a) => a,
                };
                z.re.is_finite() && (z.re - y).abs() <= bound && z.im.abs() <= bound
            });
            Ok(ok.then_some(None))
        }
        Expected::Roots(expected) => {
            let StudentAnswer::Text(t) = answer else {
                return Err(InputError::WrongField);
            };
            let typed = input::roots(t)?;
            Ok(same_roots(&typed, expected, tol).then_some(None))
        }
        Expected::Choice { options, right } => {
            let StudentAnswer::Text(t) = answer else {
                return Err(InputError::WrongField);
            };
            let typed = input::choice(t, options)?;
            Ok((typed == *right).then_some(None))
        }
    }
}

/// Points of the right half plane at the scale of the roots, where no pole of a stable or
/// marginal system lies.
fn test_points(scale: f64) -> Vec<C64> {
    let mut out = Vec::new();
    for r in [0.5, 1.0, 2.0] {
        for angle in [0.2f64, 0.9, 1.4] {
            out.push(C64::new(angle.cos(), angle.sin()) * (r * scale));
        }
    }
    out
}

fn tf_scale(tf: &degrau_lti::TransferFunction) -> f64 {
    tf.poles()
        .iter()
        .chain(tf.zeros())
        .map(|r| r.norm())
        .fold(0.0, f64::max)
        .max(0.1)
}

/// The gains at which a loop's answer in K is compared.
const GAINS: [f64; 3] = [0.37, 1.9, 13.0];

fn same_tf(tf: &TfAnswer, answer: &StudentAnswer, tol: Tolerance) -> Result<bool, InputError> {
    let (open, in_k) = match tf {
        TfAnswer::Fixed(g) => (g, false),
        TfAnswer::ClosedLoopInK(g) => (g, true),
    };
    let expected = |s: C64, k: f64| {
        let g = open.eval(s);
        if in_k { g * k / (g * k + 1.0) } else { g }
    };
    let coeffs = match answer {
        StudentAnswer::Coefficients { num, den } => Some((num.clone(), den.clone())),
        StudentAnswer::Text(t) => input::coefficient_lists(t).transpose()?,
        StudentAnswer::Number(_) => return Err(InputError::WrongField),
    };
    let student: Box<dyn Fn(C64, f64) -> C64> = match (coeffs, answer) {
        (Some((num, den)), _) => {
            if in_k {
                // Coefficients hold no K: they cannot be the loop for every K.
                return Ok(false);
            }
            Box::new(move |s, _| {
                degrau_lti::poly::eval_complex(&num, s) / degrau_lti::poly::eval_complex(&den, s)
            })
        }
        (None, StudentAnswer::Text(t)) => {
            let expr = Expr::parse(t).map_err(InputError::Expression)?;
            let allowed: &[Var] = if in_k { &[Var::S, Var::K] } else { &[Var::S] };
            expr.uses_only(allowed).map_err(InputError::Expression)?;
            Box::new(move |s, k| {
                expr.eval(&Env {
                    s,
                    k,
                    ..Env::default()
                })
            })
        }
        (None, _) => return Err(InputError::WrongField),
    };
    let gains: &[f64] = if in_k { &GAINS } else { &[1.0] };
    let r = match tol {
        Tolerance::Relative(r) => r,
        Tolerance::Absolute(a) => a,
    };
    Ok(test_points(tf_scale(open)).into_iter().all(|s| {
        gains.iter().all(|&k| {
            let (a, b) = (student(s, k), expected(s, k));
            a.re.is_finite() && a.im.is_finite() && (a - b).norm() <= r * b.norm()
        })
    }))
}

fn range_matches(typed: RangeAnswer, expected: GainRange, tol: Tolerance) -> bool {
    match typed {
        RangeAnswer::Range(r) => {
            let low = if expected.low == 0.0 {
                r.low.abs() <= 1e-12
            } else {
                tol.accepts(r.low, expected.low)
            };
            low && tol.accepts(r.high, expected.high)
        }
        RangeAnswer::Bare(x) => {
            let ends: Vec<f64> = [expected.low, expected.high]
                .into_iter()
                .filter(|e| e.is_finite() && *e != 0.0)
                .collect();
            ends.len() == 1 && tol.accepts(x, ends[0])
        }
    }
}

fn region_matches(bounds: &[RegionBound], expected: Region, tol: Tolerance) -> bool {
    let zeta = bounds.iter().find_map(|b| match b {
        RegionBound::ZetaMin(z) => Some(*z),
        _ => None,
    });
    let sigma = bounds.iter().find_map(|b| match b {
        RegionBound::SigmaMin(s) => Some(*s),
        _ => None,
    });
    zeta.is_some_and(|z| tol.accepts(z, expected.zeta_min))
        && sigma.is_some_and(|s| tol.accepts(s, expected.sigma_min))
}

fn same_roots(typed: &[C64], expected: &[C64], tol: Tolerance) -> bool {
    if typed.len() != expected.len() {
        return false;
    }
    let mut left: Vec<C64> = typed.to_vec();
    expected.iter().all(|e| {
        let bound = match tol {
            Tolerance::Relative(r) => r * e.norm(),
            Tolerance::Absolute(a) => a,
        }
        .max(1e-9);
        let nearest = left
            .iter()
            .enumerate()
            .min_by(|a, b| (*a.1 - e).norm().total_cmp(&(*b.1 - e).norm()));
        match nearest {
            Some((i, r)) if (*r - e).norm() <= bound => {
                left.swap_remove(i);
                true
            }
            _ => false,
        }
    })
}

/// The exact answer in words.
fn describe_expected(q: &Question, lang: Lang) -> String {
    match &q.expected {
        Expected::Number { unit, main, .. } => value_text(lang, main.value, *unit),
        Expected::TransferFunction(TfAnswer::Fixed(g)) => text::tf(lang, g),
        Expected::TransferFunction(TfAnswer::ClosedLoopInK(g)) => {
            let num = text::poly(lang, &g.num());
            let den = text::poly(lang, &g.den());
            if g.num().len() == 1 {
                format!("{num}K/({den} + {num}K)")
            } else {
                format!("K({num})/({den} + K({num}))")
            }
        }
        Expected::GainRange { main, .. } => range_text(lang, *main),
        Expected::Region(r) => format!(
            "ζ ≥ {}; σ ≥ {} (θ ≤ {}°)",
            num(lang, r.zeta_min),
            num(lang, r.sigma_min),
            num(lang, r.zeta_min.acos().to_degrees())
        ),
        Expected::ClosedForm { tf, amplitude, .. } => closed_form_text(tf, *amplitude, lang),
        Expected::Roots(roots) => {
            if roots.is_empty() {
                lang.pick("none", "nenhum").into()
            } else {
                roots
                    .iter()
                    .map(|r| text::complex(lang, *r))
                    .collect::<Vec<_>>()
                    .join("; ")
            }
        }
        Expected::Choice { right, .. } => right.word(lang).into(),
    }
}

fn also(q: &Question) -> Option<Text> {
    match &q.expected {
        Expected::Number { unit, also, .. } if !also.is_empty() => Some(Text::by(|l| {
            also.iter()
                .map(|v: &Value| format!("{} ({})", value_text(l, v.value, *unit), v.how.get(l)))
                .collect::<Vec<_>>()
                .join("; ")
        })),
        Expected::GainRange { also, .. } if !also.is_empty() => Some(Text::by(|l| {
            also.iter()
                .map(|(r, how)| format!("{} ({})", range_text(l, *r), how.get(l)))
                .collect::<Vec<_>>()
                .join("; ")
        })),
        _ => None,
    }
}

/// y(t) of `tf` under a step of `amplitude`, written as the notes write it (cos and sin).
fn closed_form_text(tf: &degrau_lti::TransferFunction, amplitude: f64, lang: Lang) -> String {
    degrau_lti::StepResponse::new(tf, amplitude)
        .map(|r| {
            degrau_lti::expr::expression_in(&r, degrau_lti::expr::OscillationForm::CosSin, lang)
        })
        .unwrap_or_default()
}

fn value_text(lang: Lang, x: f64, unit: Unit) -> String {
    let n = num(lang, x);
    match unit {
        Unit::None => n,
        Unit::Percent => format!("{n} %"),
        u => format!("{n} {}", u.symbol()),
    }
}

fn range_text(lang: Lang, r: GainRange) -> String {
    match (r.low == 0.0, r.high.is_finite()) {
        (true, true) => format!("0 < K ≤ {}", num(lang, r.high)),
        (false, false) => format!("K > {}", num(lang, r.low)),
        (false, true) => format!("{} ≤ K ≤ {}", num(lang, r.low), num(lang, r.high)),
        (true, false) => "K > 0".into(),
    }
}

/// Degrau's exact answer as a student would type it in `lang` (decimal comma in
/// Portuguese), which [`check`] reads back as right.
pub fn typed_answer(q: &Question, lang: Lang) -> String {
    let full = |x: f64| lang.localize_number(&degrau_lti::exact(x));
    match &q.expected {
        Expected::Number { unit, main, .. } => {
            if main.value.is_infinite() {
                "inf".into()
            } else {
                format!("{} {}", full(main.value), unit.symbol())
                    .trim()
                    .into()
            }
        }
        Expected::TransferFunction(tf) => {
            let (g, in_k) = match tf {
                TfAnswer::Fixed(g) => (g, false),
                TfAnswer::ClosedLoopInK(g) => (g, true),
            };
            let poly = |c: &[f64]| {
                let n = c.len();
                c.iter()
                    .enumerate()
                    .map(|(i, x)| format!("({})*s^{}", full(*x), n - 1 - i))
                    .collect::<Vec<_>>()
                    .join(" + ")
            };
            let (n, d) = (poly(&g.num()), poly(&g.den()));
            if in_k {
                format!("K*({n})/({d} + K*({n}))")
            } else {
                format!("({n})/({d})")
            }
        }
        Expected::GainRange { main, .. } => {
            if main.high.is_finite() {
                format!("{} < K <= {}", full(main.low), full(main.high))
            } else {
                format!("K > {}", full(main.low))
            }
        }
        Expected::Region(r) => format!("ζ ≥ {}; σ ≥ {}", full(r.zeta_min), full(r.sigma_min)),
        Expected::ClosedForm { tf, amplitude, .. } => closed_form_text(tf, *amplitude, lang),
        Expected::Roots(roots) => {
            if roots.is_empty() {
                lang.pick("none", "nenhum").into()
            } else {
                roots
                    .iter()
                    .map(|r| {
                        if r.im == 0.0 {
                            full(r.re)
                        } else {
                            let sign = if r.im < 0.0 { '-' } else { '+' };
                            format!("{}{sign}{}j", full(r.re), full(r.im.abs()))
                        }
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            }
        }
        Expected::Choice { right, .. } => right.word(lang).into(),
    }
}
