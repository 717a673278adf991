//! Exercise 3: poles, zeros, type of response and the closed-form unit-step response of five
//! second-order systems (two with real poles and a zero, a double pole, a complex pair).

use degrau_lti::C64;

use super::*;
use crate::model::{Choice, Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let c = |re: f64| C64::new(re, 0.0);
    Ok(Exercise {
        id: "3".into(),
        statement: Text::new(
            "For each transfer function below, locate its poles and zeros and identify the type of its unit-step response. Find and sketch the unit-step responses.",
            "Para cada uma das funções de transferência abaixo apresentadas, localize os seus pólos e zeros, identificando o tipo de resposta para uma entrada em degrau unitário. Determine e esboce as respectivas respostas ao degrau unitário.",
        ),
        parts: vec![
            part(
                "3a",
                tf(&[4.0], &[1.0, 6.0, 8.0])?,
                "4/((s+2)(s+4))",
                Printed {
                    zeros: "nenhum",
                    poles: "-2; -4",
                    kind: "sobreamortecida",
                    overshoot: "não",
                    y: "1/2 - e^{-2t} + 1/2 e^{-4t}",
                    y_differs: None,
                },
            )?,
            part(
                "3b",
                tf(&[10.0, 70.0], &[1.0, 30.0, 200.0])?,
                "10(s+7)/((s+10)(s+20))",
                Printed {
                    zeros: "-7",
                    poles: "-10; -20",
                    kind: "sobreamortecida",
                    overshoot: "sim",
                    y: "7/20 - 13/20 e^{-20t} + 3/10 e^{-10t}",
                    y_differs: None,
                },
            )?,
            part(
                "3c",
                tf(&[30.0, 60.0], &[1.0, 17.0, 16.0])?,
                "30(s+2)/(s²+17s+16)",
                Printed {
                    zeros: "-2",
                    poles: "-1; -16",
                    kind: "sobreamortecida",
                    overshoot: "não",
                    y: "15/4 - 7/4 e^{-16t} - 2e^{-t}",
                    y_differs: None,
                },
            )?,
            part(
                "3d",
                degrau_lti::TransferFunction::from_zpk(&[c(-5.0)], &[c(-10.0), c(-10.0)], 1.0)?,
                "(s+5)/(s+10)²",
                Printed {
                    zeros: "-5",
                    poles: "-10; -10",
                    kind: "criticamente amortecida",
                    overshoot: "sim",
                    y: "1/20 - (1/2 t - 1/20) e^{-10t}",
                    y_differs: Some(Text::new(
                        "The sheet's typeset y(t) = 1/20 − (t/2 − 1/20)e^{−10t} has the wrong sign: its own MATLAB output (ilaplace) is 1/20 + (t/2 − 1/20)e^{−10t}. The printed form starts at y(0) = 1/10 instead of 0 and dips to 0.0432 at t = 0.2 s; the right one starts at 0, rises to 0.0568 at t = 0.2 s (13.5 % overshoot) and settles at 1/20.",
                        "A expressão impressa y(t) = 1/20 − (t/2 − 1/20)e^{−10t} tem o sinal trocado: a própria saída do MATLAB (ilaplace) é 1/20 + (t/2 − 1/20)e^{−10t}. A forma impressa começa em y(0) = 1/10 em vez de 0 e desce a 0,0432 em t = 0,2 s; a correta começa em 0, sobe a 0,0568 em t = 0,2 s (sobreelongação de 13,5 %) e estabelece-se em 1/20.",
                    )),
                },
            )?,
            part(
                "3e",
                tf(&[2.0, 5.0], &[1.0, 2.0, 5.0])?,
                "(2s+5)/(s²+2s+5)",
                Printed {
                    zeros: "-2,5",
                    poles: "-1 ± j2",
                    kind: "subamortecida",
                    overshoot: "sim",
                    y: "1 - e^{-t}[cos(2t) - 1/2 sin(2t)]",
                    y_differs: None,
                },
            )?,
        ],
    })
}

/// The sheet's answers to one part.
struct Printed {
    zeros: &'static str,
    poles: &'static str,
    kind: &'static str,
    overshoot: &'static str,
    y: &'static str,
    y_differs: Option<Text>,
}

/// The type of response the poles give.
fn response_type(poles: &[C64]) -> Choice {
    let scale = poles
        .iter()
        .map(|p| p.norm())
        .fold(0.0, f64::max)
        .max(1e-300);
    if poles.iter().any(|p| p.im != 0.0) {
        if poles
            .iter()
            .any(|p| p.im != 0.0 && p.re.abs() <= 1e-12 * scale)
        {
            Choice::Undamped
        } else {
            Choice::Underdamped
        }
    } else if poles.len() == 2 && (poles[0].re - poles[1].re).abs() <= 1e-9 * scale {
        Choice::CriticallyDamped
    } else {
        Choice::Overdamped
    }
}

fn part(
    id: &str,
    g: degrau_lti::TransferFunction,
    written: &str,
    printed: Printed,
) -> Result<Part, SheetError> {
    let exact = info(&g)?;
    let mp = need(exact.overshoot, "overshoot")?;
    let kind = response_type(g.poles());
    let overshoots = if mp > 0.0 { Choice::Yes } else { Choice::No };
    let horizon = 1.5 * need(exact.settling_time, "settling time")?;
    let mut y = Question::new(
        id,
        "y",
        label::response(),
        Expected::ClosedForm {
            tf: g.clone(),
            amplitude: 1.0,
            instants: super::ex01::instants(horizon),
        },
    )
    .sheet(printed.y);
    if let Some(d) = printed.y_differs {
        y.difference = Some(d);
    }
    let questions = vec![
        Question::new(
            id,
            "zeros",
            label::zeros(),
            Expected::Roots(g.zeros().to_vec()),
        )
        .sheet(printed.zeros),
        Question::new(
            id,
            "poles",
            label::poles(),
            Expected::Roots(g.poles().to_vec()),
        )
        .sheet(printed.poles),
        Question::new(
            id,
            "type",
            label::response_type(),
            Expected::Choice {
                options: Choice::RESPONSE_TYPES.to_vec(),
                right: kind,
            },
        )
        .sheet(printed.kind),
        Question::new(
            id,
            "overshoots",
            label::has_overshoot(),
            Expected::Choice {
                options: Choice::YES_NO.to_vec(),
                right: overshoots,
            },
        )
        .sheet(printed.overshoot),
        y,
    ];
    let zeros = g.zeros().to_vec();
    let poles = g.poles().to_vec();
    let list = |l: Lang, roots: &[C64]| {
        if roots.is_empty() {
            l.pick("none", "nenhum").to_string()
        } else {
            roots
                .iter()
                .map(|r| crate::text::complex(l, *r))
                .collect::<Vec<_>>()
                .join("; ")
        }
    };
    let mut solution = vec![
        Text::by(|l| {
            l.pick(
                format!(
                    "Zeros of G(s): {}. Poles of G(s): {}.",
                    list(l, &zeros),
                    list(l, &poles)
                ),
                format!(
                    "Zeros de G(s): {}. Pólos de G(s): {}.",
                    list(l, &zeros),
                    list(l, &poles)
                ),
            )
        }),
        Text::by(|l| {
            let why = match kind {
                Choice::Overdamped => l.pick(
                    "two distinct real poles (ζ > 1)",
                    "dois pólos reais e distintos (ζ > 1)",
                ),
                Choice::CriticallyDamped => {
                    l.pick("a double real pole (ζ = 1)", "um pólo real duplo (ζ = 1)")
                }
                Choice::Underdamped => l.pick(
                    "a complex-conjugate pair (0 < ζ < 1)",
                    "um par de pólos complexos conjugados (0 < ζ < 1)",
                ),
                Choice::Undamped | Choice::Yes | Choice::No => l.pick(
                    "poles on the imaginary axis (ζ = 0)",
                    "pólos no eixo imaginário (ζ = 0)",
                ),
            };
            l.pick(
                format!(
                    "Type of response: {why}, so the response is {}.",
                    kind.word(l)
                ),
                format!(
                    "Tipo de resposta: {why}, logo a resposta é {}.",
                    kind.word(l)
                ),
            )
        }),
        say::partial_fractions(&g, 1.0)?,
        say::closed_form(&g, 1.0)?,
    ];
    let peak = exact.peak_time;
    solution.push(Text::by(|l| {
        if mp > 0.0 {
            let at = peak.map_or(String::new(), |t| format!(" (t_p = {} s)", num(l, t)));
            l.pick(
                format!("The exact response overshoots its final value {} by Mp = {} %{at}.", num(l, g.dc_gain()), num(l, mp)),
                format!("A resposta exata ultrapassa o valor final {} com Mp = {} %{at}.", num(l, g.dc_gain()), num(l, mp)),
            )
        } else {
            let zero = if g.zeros().is_empty() { "" } else { l.pick(", despite the zero", ", apesar do zero") };
            l.pick(
                format!("The exact response rises monotonically to its final value {}: no overshoot{zero}.", num(l, g.dc_gain())),
                format!("A resposta exata sobe monotonamente até ao valor final {}: sem sobreelongação{zero}.", num(l, g.dc_gain())),
            )
        }
    }));
    if kind == Choice::Underdamped {
        let pair = degrau_lti::feedback::SecondOrder::dominant(g.poles())
            .ok_or(SheetError::Missing("complex pair"))?;
        solution.push(Text::by(|l| {
            l.pick(
                format!(
                    "Without the zero, the canonical system with the same poles (ζ = {}, ωn = {} rad/s) overshoots by {} %: the zero raises the overshoot to {} %.",
                    num(l, pair.zeta), num(l, pair.wn), num(l, pair.overshoot()), num(l, mp)
                ),
                format!(
                    "Sem o zero, o sistema canónico com os mesmos pólos (ζ = {}, ωn = {} rad/s) tem sobreelongação de {} %: o zero aumenta-a para {} %.",
                    num(l, pair.zeta), num(l, pair.wn), num(l, pair.overshoot()), num(l, mp)
                ),
            )
        }));
    }
    Ok(Part {
        id: id.into(),
        statement: Text::same(format!("G(s) = {written}")),
        system: System::Tf {
            tf: g,
            amplitude: 1.0,
        },
        mode: Mode::DesignStep,
        questions,
        solution,
    })
}
