//! The sheet's 13 exercises, one file each (`ex01.rs` … `ex13.rs`), and what they share:
//! building questions, computing with `degrau-lti` (exact metrics, the second-order
//! formulas, partial fractions), the common labels and the common solution lines.
//!
//! Every expected answer is computed here from the exercise's data; the sheet's printed
//! answers are recorded as text beside them (`Question::sheet`), and the tests check each
//! against Degrau's (a difference must be documented in `Question::difference`).

use degrau_lti::feedback::SecondOrder;
use degrau_lti::{LtiError, StepInfo, StepInfoOptions, StepResponse, TransferFunction};
use degrau_words::Lang;

use crate::model::{Exercise, Expected, Question, Tolerance, Unit, Value};
use crate::text::{Text, num};
use crate::words::Phrase;

mod ex01;
mod ex02;
mod ex03;
mod ex04;
mod ex05;
mod ex06;
mod ex07;
mod ex08;
mod ex09;
mod ex10;
mod ex11;
mod ex12;
mod ex13;

/// Why the sheet could not be built (a bug: the data are fixed).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SheetError {
    #[error("{0}")]
    Lti(#[from] LtiError),
    #[error("a metric does not exist: {0}")]
    Missing(&'static str),
    #[error("{0}")]
    Inverse(#[from] degrau_lti::feedback::InverseError),
}

/// Every exercise of the sheet, its answers computed.
pub fn sheet() -> Result<Vec<Exercise>, SheetError> {
    Ok(vec![
        ex01::exercise()?,
        ex02::exercise()?,
        ex03::exercise()?,
        ex04::exercise()?,
        ex05::exercise()?,
        ex06::exercise()?,
        ex07::exercise()?,
        ex08::exercise()?,
        ex09::exercise()?,
        ex10::exercise()?,
        ex11::exercise()?,
        ex12::exercise()?,
        ex13::exercise()?,
    ])
}

/// The default tolerance: the sheet rounds to three or four digits.
pub(crate) const ROUNDED: Tolerance = Tolerance::Relative(0.01);
/// Values read off a figure.
pub(crate) const READ: Tolerance = Tolerance::Relative(0.02);

impl Question {
    /// A question of part `part` with the key `key`, 1 % relative tolerance.
    pub(crate) fn new(part: &str, key: &str, label: Text, expected: Expected) -> Self {
        Self {
            id: format!("{part}.{key}"),
            label,
            expected,
            tolerance: ROUNDED,
            sheet: None,
            difference: None,
        }
    }

    pub(crate) fn tol(mut self, tolerance: Tolerance) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// The sheet's printed answer, as a student would type it.
    pub(crate) fn sheet(mut self, printed: &str) -> Self {
        self.sheet = Some(printed.to_string());
        self
    }
}

/// A number question's expected answer.
pub(crate) fn number(unit: Unit, main: Value, also: Vec<Value>) -> Expected {
    Expected::Number { unit, main, also }
}

/// A value and how it was computed.
pub(crate) fn v(value: f64, how: Phrase) -> Value {
    Value {
        value,
        how: Text::new(how.get(Lang::En), how.get(Lang::Pt)),
    }
}

/// G(s) from coefficients in descending powers.
pub(crate) fn tf(num: &[f64], den: &[f64]) -> Result<TransferFunction, SheetError> {
    Ok(TransferFunction::from_coeffs(num, den)?)
}

/// The exact metrics of the unit-step response (2 % band, 10–90 % rise).
pub(crate) fn info(g: &TransferFunction) -> Result<StepInfo, SheetError> {
    let r = StepResponse::new(g, 1.0)?;
    Ok(StepInfo::of_response(&r, &StepInfoOptions::default()))
}

/// The exact metrics with rise limits (low, high).
pub(crate) fn info_rise(g: &TransferFunction, low: f64, high: f64) -> Result<StepInfo, SheetError> {
    let r = StepResponse::new(g, 1.0)?;
    let options = StepInfoOptions {
        rise_limits: (low, high),
        ..StepInfoOptions::default()
    };
    options.check()?;
    Ok(StepInfo::of_response(&r, &options))
}

/// A metric that must exist.
pub(crate) fn need(x: Option<f64>, what: &'static str) -> Result<f64, SheetError> {
    x.ok_or(SheetError::Missing(what))
}

/// The exact 0–100 % rise time (first arrival at the final value).
pub(crate) fn rise_full(g: &TransferFunction) -> Result<f64, SheetError> {
    need(info_rise(g, 0.0, 1.0)?.rise_time, "rise time 0-100 %")
}

/// The exact time constant: when y first reaches (1 − e⁻¹) of its final value.
pub(crate) fn time_constant(g: &TransferFunction) -> Result<f64, SheetError> {
    need(
        info_rise(g, 0.0, 1.0 - (-1.0f64).exp())?.rise_time,
        "time constant",
    )
}

/// The canonical ωn²/(s² + 2ζωn s + ωn²) of a pair.
pub(crate) fn canonical(pair: SecondOrder) -> Result<TransferFunction, SheetError> {
    Ok(pair.transfer_function()?)
}

/// The pair (ζ, ωn) of a canonical denominator s² + b s + c.
pub(crate) fn pair_of(b: f64, c: f64) -> SecondOrder {
    let wn = c.sqrt();
    SecondOrder {
        zeta: b / (2.0 * wn),
        wn,
    }
}

/// Every run of gains in [lo, hi] where all `specs` hold on the exact closed loop of K·G: a
/// log-spaced scan of `n` gains, each end refined by bisection (lti's `find_gain` gives only
/// the first run; a settling-time spec can hold on several, the 2 % settling time jumping
/// when a peak of the response leaves the band).
pub(crate) fn feasible_runs(
    g: &TransferFunction,
    specs: &[degrau_lti::feedback::Spec],
    lo: f64,
    hi: f64,
    n: usize,
) -> Vec<(f64, f64)> {
    let meets = |k: f64| specs.iter().all(|s| s.holds(g, k));
    let ratio = (hi / lo).powf(1.0 / (n.max(2) - 1) as f64);
    let ks: Vec<f64> = (0..n).map(|i| lo * ratio.powi(i as i32)).collect();
    let ok: Vec<bool> = ks.iter().map(|&k| meets(k)).collect();
    let refine = |mut bad: f64, mut good: f64| {
        for _ in 0..60 {
            let mid = (bad * good).sqrt();
            if meets(mid) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        good
    };
    let mut runs = Vec::new();
    let mut i = 0;
    while i < n {
        if !ok[i] {
            i += 1;
            continue;
        }
        let start = if i == 0 {
            ks[0]
        } else {
            refine(ks[i - 1], ks[i])
        };
        let mut j = i;
        while j + 1 < n && ok[j + 1] {
            j += 1;
        }
        let end = if j + 1 < n {
            refine(ks[j + 1], ks[j])
        } else {
            ks[j]
        };
        runs.push((start, end));
        i = j + 1;
    }
    runs
}

/// Common labels.
pub(crate) mod label {
    use crate::text::Text;

    pub fn dc_gain() -> Text {
        Text::new("DC gain K", "Ganho DC K")
    }
    pub fn tau() -> Text {
        Text::new("Time constant τ", "Constante de tempo τ")
    }
    pub fn rise() -> Text {
        Text::new("Rise time t_r", "Tempo de subida t_r")
    }
    pub fn settling() -> Text {
        Text::new(
            "Settling time t_s (2 %)",
            "Tempo de estabelecimento t_s (2 %)",
        )
    }
    pub fn peak_time() -> Text {
        Text::new("Peak time t_p", "Tempo de pico t_p")
    }
    pub fn overshoot() -> Text {
        Text::new("Maximum overshoot Mp", "Sobreelongação máxima Mp")
    }
    pub fn zeta() -> Text {
        Text::new("Damping ratio ζ", "Coeficiente de amortecimento ζ")
    }
    pub fn wn() -> Text {
        Text::new("Natural frequency ωn", "Frequência natural ωn")
    }
    pub fn poles() -> Text {
        Text::new("Poles of G(s)", "Pólos de G(s)")
    }
    pub fn zeros() -> Text {
        Text::new("Zeros of G(s)", "Zeros de G(s)")
    }
    pub fn response() -> Text {
        Text::new(
            "Unit-step response y(t)",
            "Resposta ao degrau unitário y(t)",
        )
    }
    pub fn response_type() -> Text {
        Text::new("Type of response", "Tipo de resposta")
    }
    pub fn has_overshoot() -> Text {
        Text::new(
            "Does the response overshoot?",
            "A resposta tem sobreelongação?",
        )
    }
    pub fn transfer_function() -> Text {
        Text::new("Transfer function G(s)", "Função de transferência G(s)")
    }
}

/// Common solution lines.
pub(crate) mod say {
    use super::*;
    use degrau_lti::expr::{self, OscillationForm};

    /// `Y(s) = … = A/s + B/(s + 2) + …` with the residues Degrau computed.
    pub fn partial_fractions(g: &TransferFunction, amplitude: f64) -> Result<Text, SheetError> {
        let r = StepResponse::new(g, amplitude)?;
        let terms = expr::terms(&r);
        Ok(Text::by(|l| {
            let mut body = String::new();
            for t in &terms {
                let pole = |sigma: f64| {
                    if sigma == 0.0 {
                        "s".to_string()
                    } else if sigma < 0.0 {
                        format!("(s + {})", coefficient(l, -sigma))
                    } else {
                        format!("(s − {})", coefficient(l, sigma))
                    }
                };
                let (sign, text) = if t.omega == 0.0 {
                    let factorial: f64 = (1..=t.power).map(|k| k as f64).product();
                    let c = t.cos * factorial;
                    let power = if t.power == 0 {
                        pole(t.sigma)
                    } else {
                        format!("{}^{}", pole(t.sigma), t.power + 1)
                    };
                    (c.signum(), format!("{}/{power}", factor(l, c.abs())))
                } else {
                    // a cos ωt + b sin ωt ↔ (a(s − σ) + bω)/((s − σ)² + ω²)
                    let shift = pole(t.sigma);
                    let first = match t.cos {
                        1.0 => shift.clone(),
                        -1.0 => format!("−{shift}"),
                        a if a < 0.0 => format!("−{}{shift}", factor(l, -a)),
                        a => format!("{}{shift}", factor(l, a)),
                    };
                    let b = t.sin * t.omega;
                    let second = if b == 0.0 {
                        String::new()
                    } else if b < 0.0 {
                        format!(" − {}", coefficient(l, -b))
                    } else {
                        format!(" + {}", coefficient(l, b))
                    };
                    (
                        1.0,
                        format!(
                            "({first}{second})/({shift}² + {})",
                            coefficient(l, t.omega * t.omega)
                        ),
                    )
                };
                if body.is_empty() {
                    if sign < 0.0 {
                        body.push('−');
                    }
                } else {
                    body.push_str(if sign < 0.0 { " − " } else { " + " });
                }
                body.push_str(&text);
            }
            let y = crate::text::tf(l, g);
            let step = if amplitude == 1.0 {
                "1/s".to_string()
            } else {
                format!("{}/s", num(l, amplitude))
            };
            l.pick(
                format!("Partial fractions: Y(s) = {y} · {step} = {body}"),
                format!("Frações parciais: Y(s) = {y} · {step} = {body}"),
            )
        }))
    }

    /// A number as a simple fraction where it is one (`13/20`), else four digits.
    pub fn coefficient(lang: Lang, x: f64) -> String {
        match expr::fraction(x) {
            Some((p, 1)) => p.to_string(),
            Some((p, q)) if q <= 100 => format!("{p}/{q}"),
            _ => num(lang, x),
        }
    }

    /// A coefficient in front of something: `(1/2)`, `3`, `0,25`.
    fn factor(lang: Lang, x: f64) -> String {
        let c = coefficient(lang, x);
        if c.contains('/') { format!("({c})") } else { c }
    }

    /// `y(t) = …` as the notes write it.
    pub fn closed_form(g: &TransferFunction, amplitude: f64) -> Result<Text, SheetError> {
        let r = StepResponse::new(g, amplitude)?;
        Ok(Text::by(|l| {
            let y = expr::expression_in(&r, OscillationForm::CosSin, l);
            l.pick(
                format!("Inverse Laplace transform: {y}, t ≥ 0"),
                format!("Transformada inversa de Laplace: {y}, t ≥ 0"),
            )
        }))
    }

    /// The second-order formulas of a pair, each beside the exact metric of `g`.
    pub fn formulas_beside_exact(
        pair: SecondOrder,
        g: &TransferFunction,
    ) -> Result<Vec<Text>, SheetError> {
        let exact = info(g)?;
        let rise = rise_full(g)?;
        let rise_10_90 = need(exact.rise_time, "rise time")?;
        let ts = need(exact.settling_time, "settling time")?;
        let tp = exact.peak_time;
        let mp = need(exact.overshoot, "overshoot")?;
        Ok(vec![
            Text::by(|l| {
                l.pick(
                    format!(
                        "t_s = 4/(ζωn) = {} s; exact 2 % settling time of the response: {} s",
                        num(l, pair.settling_time()),
                        num(l, ts)
                    ),
                    format!(
                        "t_s = 4/(ζωn) = {} s; tempo de estabelecimento (2 %) exato da resposta: {} s",
                        num(l, pair.settling_time()),
                        num(l, ts)
                    ),
                )
            }),
            Text::by(|l| {
                let exact = tp.map_or("—".to_string(), |t| num(l, t));
                l.pick(
                    format!(
                        "t_p = π/(ωn√(1 − ζ²)) = {} s; exact: {exact} s",
                        num(l, pair.peak_time())
                    ),
                    format!(
                        "t_p = π/(ωn√(1 − ζ²)) = {} s; exato: {exact} s",
                        num(l, pair.peak_time())
                    ),
                )
            }),
            Text::by(|l| {
                l.pick(
                    format!(
                        "t_r = (π − cos⁻¹ζ)/(ωn√(1 − ζ²)) = {} s (0–100 %); exact: {} s (0–100 %), {} s (10–90 %, MATLAB's stepinfo)",
                        num(l, pair.rise_time()),
                        num(l, rise),
                        num(l, rise_10_90)
                    ),
                    format!(
                        "t_r = (π − cos⁻¹ζ)/(ωn√(1 − ζ²)) = {} s (0–100 %); exato: {} s (0–100 %), {} s (10–90 %, stepinfo do MATLAB)",
                        num(l, pair.rise_time()),
                        num(l, rise),
                        num(l, rise_10_90)
                    ),
                )
            }),
            Text::by(|l| {
                l.pick(
                    format!(
                        "Mp = e^(−πζ/√(1 − ζ²)) = {} %; exact: {} %",
                        num(l, pair.overshoot()),
                        num(l, mp)
                    ),
                    format!(
                        "Mp = e^(−πζ/√(1 − ζ²)) = {} %; exato: {} %",
                        num(l, pair.overshoot()),
                        num(l, mp)
                    ),
                )
            }),
        ])
    }

    /// The root locus reading of the loop around K·G: asymptotes, breakaway and break-in
    /// points with their gains, crossings of the imaginary axis.
    pub fn root_locus(g: &TransferFunction) -> Text {
        use degrau_lti::locus::{self, Side};
        let (numerator, denominator) = (g.num(), g.den());
        let breakaways = locus::breakaways(&numerator, &denominator, Side::Positive);
        let crossings = locus::crossings(&numerator, &denominator, Side::Positive);
        let excess = g.poles().len() - g.zeros().len();
        let centroid = if excess > 0 {
            let sum = |r: &[degrau_lti::C64]| r.iter().map(|x| x.re).sum::<f64>();
            Some((sum(g.poles()) - sum(g.zeros())) / excess as f64)
        } else {
            None
        };
        Text::by(|l| {
            let mut parts = Vec::new();
            if let Some(c) = centroid {
                let angles: Vec<String> = (0..excess)
                    .map(|k| format!("{}°", num(l, (2 * k + 1) as f64 * 180.0 / excess as f64)))
                    .collect();
                parts.push(l.pick(
                    format!(
                        "{excess} asymptote(s) from σ = {} at {}",
                        num(l, c),
                        angles.join(", ")
                    ),
                    format!(
                        "{excess} assíntota(s) a partir de σ = {} a {}",
                        num(l, c),
                        angles.join(", ")
                    ),
                ));
            }
            for b in &breakaways {
                parts.push(l.pick(
                    format!(
                        "branches meet the real axis at s = {} (K = {})",
                        num(l, b.s),
                        num(l, b.k)
                    ),
                    format!(
                        "os ramos encontram o eixo real em s = {} (K = {})",
                        num(l, b.s),
                        num(l, b.k)
                    ),
                ));
            }
            if crossings.is_empty() {
                parts.push(
                    l.pick(
                        "no crossing of the imaginary axis: the loop is stable for every K > 0"
                            .to_string(),
                        "não cruza o eixo imaginário: a malha é estável para todo o K > 0"
                            .to_string(),
                    ),
                );
            }
            for c in &crossings {
                parts.push(l.pick(
                    format!(
                        "crosses the imaginary axis at ω = {} rad/s for K = {}",
                        num(l, c.omega),
                        num(l, c.k)
                    ),
                    format!(
                        "cruza o eixo imaginário em ω = {} rad/s para K = {}",
                        num(l, c.omega),
                        num(l, c.k)
                    ),
                ));
            }
            l.pick(
                format!(
                    "Root locus of K·G(s), G(s) = {}: {}.",
                    crate::text::tf(l, g),
                    parts.join("; ")
                ),
                format!(
                    "Lugar das raízes de K·G(s), G(s) = {}: {}.",
                    crate::text::tf(l, g),
                    parts.join("; ")
                ),
            )
        })
    }

    /// ζ from an overshoot, as the sheet writes it.
    pub fn zeta_from_overshoot(mp: f64, zeta: f64) -> Text {
        Text::by(|l| {
            format!(
                "Mp = e^(−πζ/√(1 − ζ²)) ⇒ {} = e^(−πζ/√(1 − ζ²)) ⇒ ζ = −ln(Mp)/√(π² + ln²(Mp)) = {}",
                num(l, mp / 100.0),
                num(l, zeta)
            )
        })
    }
}
