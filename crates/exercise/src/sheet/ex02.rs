//! Exercise 2: K/(s + a) identified from a figure of its unit-step response (τ and y(∞)).

use super::*;
use crate::model::{Mode, Part, Reading, System, TfAnswer};

pub fn exercise() -> Result<Exercise, SheetError> {
    // The readings the sheet takes off its figure.
    let tau = 0.25;
    let y_final = 0.5;
    let a = 1.0 / tau;
    let k = y_final * a;
    let g = tf(&[k], &[1.0, a])?;
    // The curve rebuilt from the readings shows them back.
    let shown_tau = time_constant(&g)?;
    let shown_final = g.dc_gain();
    let readings = vec![
        Reading {
            key: "tau".into(),
            label: label::tau(),
            value: tau,
            unit: Unit::Seconds,
        },
        Reading {
            key: "y_final".into(),
            label: Text::new("Final value y(∞)", "Valor final y(∞)"),
            value: y_final,
            unit: Unit::None,
        },
    ];
    let questions = vec![
        Question::new(
            "2",
            "a",
            Text::new("Pole parameter a", "Parâmetro a (pólo)"),
            number(Unit::PerSecond, v(a, Phrase::Readings), vec![]),
        )
        .tol(READ)
        .sheet("4"),
        Question::new(
            "2",
            "K",
            Text::new("Gain K of K/(s + a)", "Ganho K de K/(s + a)"),
            number(Unit::None, v(k, Phrase::Readings), vec![]),
        )
        .tol(READ)
        .sheet("2"),
        Question::new(
            "2",
            "G",
            label::transfer_function(),
            Expected::TransferFunction(TfAnswer::Fixed(g.clone())),
        )
        .tol(READ)
        .sheet("2/(s+4)"),
    ];
    let solution = vec![
        Text::by(|l| {
            l.pick(
                format!(
                    "From the figure: y reaches 63.2 % of its final value at t = τ = {} s",
                    num(l, tau)
                ),
                format!(
                    "Do gráfico: y atinge 63,2 % do valor final em t = τ = {} s",
                    num(l, tau)
                ),
            )
        }),
        Text::by(|l| format!("τ = 1/a ⇒ a = 1/τ = {}", num(l, a))),
        Text::by(|l| {
            l.pick(
                format!(
                    "Final value theorem: y(∞) = lim_(s→0) K/(s + a) = K/a = {} ⇒ K = {}·a = {}",
                    num(l, y_final),
                    num(l, y_final),
                    num(l, k)
                ),
                format!(
                    "Teorema do valor final: y(∞) = lim_(s→0) K/(s + a) = K/a = {} ⇒ K = {}·a = {}",
                    num(l, y_final),
                    num(l, y_final),
                    num(l, k)
                ),
            )
        }),
        Text::by(|l| format!("G(s) = Y(s)/R(s) = {}", crate::text::tf(l, &g))),
        Text::by(|l| {
            l.pick(
                format!("Check: the exact response of this G(s) has τ = {} s and y(∞) = {}, the figure's readings", num(l, shown_tau), num(l, shown_final)),
                format!("Verificação: a resposta exata desta G(s) tem τ = {} s e y(∞) = {}, as leituras da figura", num(l, shown_tau), num(l, shown_final)),
            )
        }),
    ];
    Ok(Exercise {
        id: "2".into(),
        statement: Text::new(
            "A first-order system Y(s)/R(s) = K/(s + a) has the unit-step response shown in the figure. Find the parameters (K, a).",
            "Considere um sistema de primeira ordem dado por uma função de transferência da forma Y(s)/R(s) = K/(s + a). A resposta deste sistema a uma entrada em degrau unitário está representada na figura seguinte. Determine os valores dos parâmetros (K, a) que caracterizam o sistema.",
        ),
        parts: vec![Part {
            id: "2".into(),
            statement: Text::new(
                "Read τ and y(∞) off the figure; find (K, a).",
                "Retire τ e y(∞) do gráfico; determine (K, a).",
            ),
            system: System::Figure {
                curve: g,
                amplitude: 1.0,
                readings,
            },
            mode: Mode::Identify,
            questions,
            solution,
        }],
    })
}
