//! The words of the approximations (`crate::approx`): each method's name, the refusals
//! ([`ApproxError`]), the reduced model's formula in the notes' time-constant form, the
//! error table of one approximation and the comparison table of every method (Markdown,
//! to paste into a report), in English and Brazilian Portuguese (aproximação, polos
//! dominantes, tempo morto, constante de tempo, ganho estático, …).

use crate::approx::{
    ApproxError, Approximation, Comparison, DelayApproximant, Method, MetricDifference, Reduction,
    Row,
};
use crate::words::step::Metric;
use crate::{C64, TransferFunction, fmt_c};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// The labels of the approximation view and of `degrau approx`.
    pub enum ApproxPhrase {
        Heading => ("Approximation", "Aproximação"),
        Method => ("Method", "Método"),
        NoMethod => ("none", "nenhuma"),
        Order => ("order n", "ordem n"),
        NumeratorDegree => ("numerator degree m", "grau do numerador m"),
        LimitTerms => ("lags n", "constantes n"),
        Original => ("original G(s)", "G(s) original"),
        Approximate => ("approximation", "aproximação"),
        MaxError => ("max |Δy| / step's effect", "máx |Δy| / efeito do degrau"),
        Ise => ("ISE: ∫ (Δy)² dt", "ISE: ∫ (Δy)² dt (erro quadrático)"),
        BeyondDouble => ("beyond double precision", "além da precisão dupla"),
        Metric => ("Metric", "Métrica"),
        Difference => ("Difference", "Diferença"),
        Within => ("Within 5 % (relative)", "Dentro de 5 % (relativo)"),
        Yes => ("yes", "sim"),
        No => ("no", "não"),
        Model => ("Model", "Modelo"),
        Formula => ("Formula", "Fórmula"),
        OrderColumn => ("Order", "Ordem"),
        NoneWithin => ("none", "nenhuma"),
        DoesNotApply => ("does not apply:", "não se aplica:"),
        CompareAll => ("Compare every method", "Comparar todos os métodos"),
        CopyTable => ("Copy the table", "Copiar a tabela"),
        CopyTableHelp => (
            "Copies the comparison of every method as a Markdown table, for a report.",
            "Copia a comparação de todos os métodos como uma tabela Markdown, para um relatório."
        ),
        NoApproximation => ("No approximation:", "Sem aproximação:"),
        PlaneCaption => (
            "poles (×) and zeros (o) of the approximation; the original's faint",
            "polos (×) e zeros (o) da aproximação; os do original, esmaecidos"
        ),
        PlotName => ("approximation's step response", "resposta ao degrau da aproximação"),
        PlaneName => ("approximation's s-plane", "plano s da aproximação"),
        ErrorTable => ("error table", "tabela de erros"),
        ReducedModel => ("Reduced model", "Modelo reduzido"),
        Errors => ("Errors", "Erros"),
        Poles => ("Poles", "Polos"),
        NoRoots => ("none", "nenhum"),
        DelayOrderHelp => (
            "Padé (m, n) of the dead time: m zeros (in the right half plane) and n poles.",
            "Padé (m, n) do tempo morto: m zeros (no semiplano direito) e n polos."
        ),
    }
}

/// The method's name, without its order.
pub fn kind_name(a: &Approximation, lang: Lang) -> &'static str {
    match a {
        Approximation::Reduce(r) => method_name(r.method, lang),
        Approximation::Delay(d) => match d {
            DelayApproximant::Pade { .. } => lang.pick("Dead time → Padé", "Tempo morto → Padé"),
            DelayApproximant::TaylorZero => lang.pick("Dead time → 1 − θs", "Tempo morto → 1 − θs"),
            DelayApproximant::TaylorLag => {
                lang.pick("Dead time → 1/(1 + θs)", "Tempo morto → 1/(1 + θs)")
            }
            DelayApproximant::Limit { .. } => {
                lang.pick("Dead time → (1 + θs/n)^−n", "Tempo morto → (1 + θs/n)^−n")
            }
        },
    }
}

/// A reduction method's name.
pub fn method_name(m: Method, lang: Lang) -> &'static str {
    match m {
        Method::Dominant => lang.pick("Dominant poles", "Polos dominantes"),
        Method::Taylor => lang.pick(
            "Taylor (neglected lags → dead time)",
            "Taylor (constantes desprezadas → tempo morto)",
        ),
        Method::Skogestad => lang.pick("Skogestad's half rule", "Regra da metade de Skogestad"),
        Method::Pade => lang.pick("Padé moment matching", "Aproximação de Padé (momentos)"),
    }
}

/// The approximation's name with its order, e.g. "Skogestad's half rule, order 1" or
/// "Padé moment matching G_{1,1}".
pub fn name(a: &Approximation, lang: Lang) -> String {
    let kind = kind_name(a, lang);
    match a {
        Approximation::Reduce(Reduction {
            method: Method::Pade,
            m,
            n,
        }) => format!("{kind} G_{{{m},{n}}}"),
        Approximation::Reduce(r) => format!("{kind}, {} {}", lang.pick("order", "ordem"), r.n),
        Approximation::Delay(DelayApproximant::Pade { m, n }) => format!("{kind} ({m}, {n})"),
        Approximation::Delay(DelayApproximant::Limit { n }) => format!("{kind}, n = {n}"),
        Approximation::Delay(_) => kind.to_string(),
    }
}

impl Localize for ApproxError {
    fn text(&self, lang: Lang) -> String {
        let num = |x: f64| lang.localize_number(&crate::exact(x));
        match self {
            ApproxError::Lti(e) => e.text(lang),
            ApproxError::UnstablePole(p) => {
                let p = lang.localize_number(&fmt_c(*p));
                lang.pick(
                    format!(
                        "pole {p} is in the right half plane: this method ranks stable poles only"
                    ),
                    format!(
                        "o polo {p} está no semiplano direito: este método só ordena polos estáveis"
                    ),
                )
            }
            ApproxError::OrderZero => lang
                .pick(
                    "the order must be at least 1",
                    "a ordem deve ser ao menos 1",
                )
                .into(),
            ApproxError::NotLower { asked, order } => lang.pick(
                format!(
                    "order {asked} is not below the system's order, {order}: nothing is left out"
                ),
                format!(
                    "a ordem {asked} não é menor que a ordem do sistema, {order}: nada é desprezado"
                ),
            ),
            ApproxError::NothingToApproximate => lang
                .pick(
                    "nothing to approximate: no pole is left out, no zero is in the right half \
                     plane and no lead cancels a lag",
                    "nada a aproximar: nenhum polo é desprezado, nenhum zero está no semiplano \
                     direito e nenhum zero cancela uma constante de tempo",
                )
                .into(),
            ApproxError::PadeOrder { m, n } => match lang {
                Lang::En => format!("a Padé order ({m}, {n}) needs 1 ≤ n ≤ 30 and m ≤ n"),
                Lang::Pt => format!("a ordem de Padé ({m}, {n}) exige 1 ≤ n ≤ 30 e m ≤ n"),
            },
            ApproxError::PadeRange { delay, m, n } => {
                let theta = num(*delay);
                match lang {
                    Lang::En => format!(
                        "Padé ({m}, {n}) of a dead time of {theta} s has coefficients (multiples \
                         of θ^k up to θ^{n}) outside double precision's range (2.2e-308 to \
                         1.8e308): express the dead time in other units of time, or take a \
                         lower order"
                    ),
                    Lang::Pt => format!(
                        "o Padé ({m}, {n}) de um tempo morto de {theta} s tem coeficientes \
                         (múltiplos de θ^k até θ^{n}) fora da faixa da precisão dupla (2,2e-308 \
                         a 1,8e308): expresse o tempo morto em outras unidades de tempo, ou use \
                         uma ordem menor"
                    ),
                }
            }
            ApproxError::OriginRoots { m, n } => match lang {
                Lang::En => {
                    format!("order ({m}, {n}) leaves no room for the system's roots at the origin")
                }
                Lang::Pt => {
                    format!("a ordem ({m}, {n}) não comporta as raízes do sistema na origem")
                }
            },
            ApproxError::Singular { m, n } => match lang {
                Lang::En => format!(
                    "the moment equations of G_{{{m},{n}}} have no unique solution: try another order"
                ),
                Lang::Pt => format!(
                    "as equações de momentos de G_{{{m},{n}}} não têm solução única: tente outra ordem"
                ),
            },
            ApproxError::Incomparable => lang
                .pick(
                    "the two step responses cannot be compared in double precision: one is not a \
                     finite number somewhere in the window (a pole far in the right half plane \
                     grows beyond 1.8e308)",
                    "as duas respostas ao degrau não podem ser comparadas em precisão dupla: uma \
                     não é um número finito em algum ponto da janela (um polo longe no semiplano \
                     direito cresce além de 1,8e308)",
                )
                .into(),
            ApproxError::NoDelay => lang
                .pick(
                    "the system has no dead time to approximate",
                    "o sistema não tem tempo morto a aproximar",
                )
                .into(),
            ApproxError::BadDelay(x) => match lang {
                Lang::En => format!(
                    "the dead time must be a positive finite number of seconds, not {}",
                    num(*x)
                ),
                Lang::Pt => format!(
                    "o tempo morto deve ser um número finito e positivo de segundos, não {}",
                    num(*x)
                ),
            },
        }
    }
}

/// The heading of `degrau pade`: "Padé (m, n) of e^(-θ s):".
pub fn pade_heading(m: usize, n: usize, delay: f64, lang: Lang) -> String {
    let theta = lang.localize_number(&crate::exact(delay));
    match lang {
        Lang::En => format!("Padé ({m}, {n}) of e^(-{theta} s):"),
        Lang::Pt => format!("Padé ({m}, {n}) de e^(-{theta} s):"),
    }
}

/// A coefficient of the formula: 4 significant digits, the language's separator.
fn coefficient(x: f64, lang: Lang) -> String {
    lang.num(x, 4)
}

/// A coefficient multiplying a power of s: as [`coefficient`], but nothing for 1 (`s`, not
/// `1s`).
fn times(x: f64, lang: Lang) -> String {
    match coefficient(x, lang) {
        one if one == "1" => String::new(),
        other => other,
    }
}

/// `(Ts + 1)` for a real root r (T = −1/r), `(as² + bs + 1)` for a pair.
fn factor(root: C64, lang: Lang) -> String {
    let sign = |x: f64| if x < 0.0 { "-" } else { "" };
    if root.im == 0.0 {
        let t = -1.0 / root.re;
        format!("({}{}s + 1)", sign(t), times(t.abs(), lang))
    } else {
        let r2 = root.norm_sqr();
        let b = -2.0 * root.re / r2;
        let middle = if b == 0.0 {
            String::new()
        } else {
            let op = if b < 0.0 { "-" } else { "+" };
            format!(" {op} {}s", times(b.abs(), lang))
        };
        format!("({}s²{middle} + 1)", times(1.0 / r2, lang))
    }
}

/// The product of the factors of `roots` (a pair once, by its upper member; `s` for each
/// root at the origin), and whether there is any.
fn factors(roots: &[C64], lang: Lang) -> String {
    let origin = roots.iter().filter(|r| r.re == 0.0 && r.im == 0.0).count();
    let mut out = "s".repeat(origin);
    for r in roots
        .iter()
        .filter(|r| !(r.re == 0.0 && r.im == 0.0) && r.im >= 0.0)
    {
        out.push_str(&factor(*r, lang));
    }
    out
}

/// The model in the notes' time-constant form, e.g. `2 (-0.9091s + 1) / (10.09s + 1)` or
/// `2 e^(-2.1s) / (6.5s + 1)`: the low-frequency gain (the static gain when there is no
/// integrator), then the normalised factors, then the dead time.
pub fn formula(tf: &TransferFunction, lang: Lang) -> String {
    let k = crate::approx::reduce::low_frequency_gain(tf);
    let num = factors(tf.zeros(), lang);
    let den = factors(tf.poles(), lang);
    let delay = if tf.delay() > 0.0 {
        format!(" e^(-{}s)", times(tf.delay(), lang))
    } else {
        String::new()
    };
    let num = if num.is_empty() {
        String::new()
    } else {
        format!(" {num}")
    };
    let den = if den.starts_with('(') && den.matches('(').count() == 1 {
        den
    } else {
        format!("({den})")
    };
    format!("{}{num}{delay} / {den}", coefficient(k, lang))
}

/// A metric's value with its unit, or a dash when it does not exist.
fn cell(value: Option<f64>, metric: Metric, lang: Lang) -> String {
    match value {
        None => "—".into(),
        Some(v) => match metric.unit() {
            "" => lang.num(v, 4),
            unit => format!("{} {unit}", lang.num(v, 4)),
        },
    }
}

/// One row of the error table: the metric, its original and approximate values, the
/// difference, and whether it is within 5 %.
pub fn error_row(d: &MetricDifference, lang: Lang) -> [String; 5] {
    let difference = match (d.difference, d.relative) {
        (Some(diff), Some(rel)) => format!(
            "{} ({} %)",
            cell(Some(diff), d.metric, lang),
            lang.num(100.0 * rel, 3)
        ),
        (diff, _) => cell(diff, d.metric, lang),
    };
    let within = if d.within {
        ApproxPhrase::Yes
    } else {
        ApproxPhrase::No
    };
    [
        d.metric.name(lang).to_string(),
        cell(d.original, d.metric, lang),
        cell(d.approx, d.metric, lang),
        difference,
        within.get(lang).to_string(),
    ]
}

/// The error table's header, matching [`error_row`].
pub fn error_header(lang: Lang) -> [String; 5] {
    [
        ApproxPhrase::Metric,
        ApproxPhrase::Original,
        ApproxPhrase::Approximate,
        ApproxPhrase::Difference,
        ApproxPhrase::Within,
    ]
    .map(|p| p.get(lang).to_string())
}

/// The two error measures as lines: the largest gap (in % of the step's effect, and when)
/// and the ISE.
pub fn measures(c: &Comparison, lang: Lang) -> [String; 2] {
    [
        format!(
            "{} = {} % (t = {} s)",
            ApproxPhrase::MaxError.get(lang),
            lang.num(100.0 * c.max_error, 3),
            lang.num(c.max_error_time, 3)
        ),
        format!("{} = {}", ApproxPhrase::Ise.get(lang), ise(c, lang)),
    ]
}

/// The ISE as text: the number, or its order of magnitude when it lies beyond double
/// precision.
pub fn ise(c: &Comparison, lang: Lang) -> String {
    match c.ise_value() {
        Some(ise) => lang.num(ise, 3),
        None => format!(
            "{} ({})",
            lang.power_of_ten(c.ise_log10(), 3),
            ApproxPhrase::BeyondDouble.get(lang)
        ),
    }
}

/// The metrics within 5 %, named and joined (or "none").
pub fn kept_metrics(c: &Comparison, lang: Lang) -> String {
    let kept = c.kept();
    if kept.is_empty() {
        ApproxPhrase::NoneWithin.get(lang).to_string()
    } else {
        kept.iter()
            .map(|m| m.name(lang))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The comparison of every method as a Markdown table: model, formula, order, largest gap,
/// ISE, metrics within 5 % (or why the method does not apply).
pub fn comparison_table(rows: &[Row], lang: Lang) -> String {
    let header = [
        ApproxPhrase::Model,
        ApproxPhrase::Formula,
        ApproxPhrase::OrderColumn,
        ApproxPhrase::MaxError,
        ApproxPhrase::Ise,
        ApproxPhrase::Within,
    ]
    .map(|p| p.get(lang).replace('|', "\\|"));
    let mut lines = vec![
        format!("| {} |", header.join(" | ")),
        format!("|{}", "---|".repeat(header.len())),
    ];
    for row in rows {
        let model = name(&row.approximation, lang);
        let cells = match &row.outcome {
            Ok(a) => [
                model,
                formula(&a.model, lang),
                a.model.order().to_string(),
                format!("{} %", lang.num(100.0 * a.comparison.max_error, 3)),
                ise(&a.comparison, lang),
                kept_metrics(&a.comparison, lang),
            ],
            Err(e) => [
                model,
                format!("{} {}", ApproxPhrase::DoesNotApply.get(lang), e.text(lang)),
                String::new(),
                String::new(),
                String::new(),
                String::new(),
            ],
        };
        lines.push(format!("| {} |", cells.join(" | ")));
    }
    lines.join("\n")
}

/// Every phrase and an example of every refusal and name, for the test of the text layer.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = ApproxPhrase::messages();
    let errors = [
        ApproxError::Lti(crate::LtiError::NoPoles),
        ApproxError::UnstablePole(C64::new(1.0, 0.0)),
        ApproxError::OrderZero,
        ApproxError::NotLower { asked: 3, order: 3 },
        ApproxError::NothingToApproximate,
        ApproxError::PadeOrder { m: 2, n: 1 },
        ApproxError::PadeRange {
            delay: 1e-300,
            m: 2,
            n: 2,
        },
        ApproxError::OriginRoots { m: 0, n: 1 },
        ApproxError::Singular { m: 1, n: 1 },
        ApproxError::NoDelay,
        ApproxError::Incomparable,
        ApproxError::BadDelay(-1.0),
    ];
    all.extend(
        errors
            .iter()
            .map(|e| Message::of(format!("approx::ApproxError::{e:?}"), e)),
    );
    all.push(Message {
        id: "approx::pade_heading".into(),
        en: pade_heading(1, 1, 0.5, Lang::En),
        pt: pade_heading(1, 1, 0.5, Lang::Pt),
    });
    let mut names: Vec<Approximation> = Method::ALL
        .iter()
        .map(|m| Approximation::Reduce(m.default_reduction()))
        .collect();
    names.extend(
        [
            DelayApproximant::Pade { m: 1, n: 1 },
            DelayApproximant::TaylorZero,
            DelayApproximant::TaylorLag,
            DelayApproximant::Limit { n: 3 },
        ]
        .map(Approximation::Delay),
    );
    all.extend(names.iter().map(|a| Message {
        id: format!("approx::name::{a:?}"),
        en: name(a, Lang::En),
        pt: name(a, Lang::Pt),
    }));
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_formula_is_the_notes_time_constant_form() {
        // 2/((10s+1)(s+1)) with a dead time of 0.5 s.
        let g = TransferFunction::from_zpk(&[], &[C64::new(-0.1, 0.0), C64::new(-1.0, 0.0)], 0.2)
            .unwrap()
            .with_delay(0.5)
            .unwrap();
        assert_eq!(formula(&g, Lang::En), "2 e^(-0.5s) / ((10s + 1)(s + 1))");
        assert_eq!(formula(&g, Lang::Pt), "2 e^(-0,5s) / ((10s + 1)(s + 1))");
        let unit = TransferFunction::from_zpk(&[], &[C64::new(-1.0, 0.0)], 1.0)
            .unwrap()
            .with_delay(1.0)
            .unwrap();
        assert_eq!(formula(&unit, Lang::En), "1 e^(-s) / (s + 1)");
        // A zero in the right half plane and a pair: 18/(s² + 6s + 18) has 1/18 and 1/3.
        let h = TransferFunction::from_zpk(
            &[C64::new(10.0, 0.0)],
            &[C64::new(-3.0, 3.0), C64::new(-3.0, -3.0)],
            -1.8,
        )
        .unwrap();
        assert_eq!(
            formula(&h, Lang::En),
            "1 (-0.1s + 1) / (0.05556s² + 0.3333s + 1)"
        );
    }
}
