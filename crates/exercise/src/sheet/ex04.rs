//! Exercise 4: K, ζ, ωn of K/(s² + 2ζωn s + ωn²) from a figure (t_p, y(t_p), y(∞)).

use degrau_lti::feedback::SecondOrder;

use super::*;
use crate::model::{Mode, Part, Reading, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    // The readings the sheet takes off its figure.
    let tp = 0.0551;
    let y_peak = 0.944;
    let y_final = 0.75;
    let mp = 100.0 * (y_peak - y_final) / y_final;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    let wn = std::f64::consts::PI / (tp * (1.0 - zeta * zeta).sqrt());
    let k = y_final * wn * wn;
    let g = tf(&[k], &[1.0, 2.0 * zeta * wn, wn * wn])?;
    let shown = info(&g)?;
    let shown_tp = need(shown.peak_time, "peak time")?;
    let shown_peak = need(shown.peak, "peak")?;
    // What the sheet's ωn would show.
    let sheet_wn = 6.2;
    let sheet_tp = std::f64::consts::PI / (sheet_wn * (1.0 - zeta * zeta).sqrt());
    let reading = |key: &str, label: Text, value: f64, unit: Unit| Reading {
        key: key.into(),
        label,
        value,
        unit,
    };
    let readings = vec![
        reading("tp", label::peak_time(), tp, Unit::Seconds),
        reading(
            "y_peak",
            Text::new("Peak value y(t_p)", "Valor máximo y(t_p)"),
            y_peak,
            Unit::None,
        ),
        reading(
            "y_final",
            Text::new("Final value y(∞)", "Valor final y(∞)"),
            y_final,
            Unit::None,
        ),
    ];
    let wn_note = Text::by(|l| {
        l.pick(
            format!(
                "π/(0.0551·√(1 − 0.394²)) = {} rad/s, not 6.2: the sheet slipped a factor of 10 (with ωn = 6.2 rad/s the peak would come at t_p = {} s, ten times the figure's). K follows it: 0.75·ωn² = {}, not 28.83.",
                num(l, wn), num(l, sheet_tp), num(l, k)
            ),
            format!(
                "π/(0,0551·√(1 − 0,394²)) = {} rad/s, não 6,2: a folha enganou-se num fator de 10 (com ωn = 6,2 rad/s o pico surgiria em t_p = {} s, dez vezes o da figura). K segue-o: 0,75·ωn² = {}, não 28,83.",
                num(l, wn), num(l, sheet_tp), num(l, k)
            ),
        )
    });
    let mut wn_q = Question::new(
        "4",
        "wn",
        label::wn(),
        number(Unit::RadPerSecond, v(wn, Phrase::Readings), vec![]),
    )
    .tol(READ)
    .sheet("6,2 rad/s");
    wn_q.difference = Some(wn_note.clone());
    let mut k_q = Question::new(
        "4",
        "K",
        Text::new("Gain K", "Ganho K"),
        number(Unit::None, v(k, Phrase::Readings), vec![]),
    )
    .tol(READ)
    .sheet("28,83");
    k_q.difference = Some(wn_note);
    let questions = vec![
        Question::new(
            "4",
            "Mp",
            label::overshoot(),
            number(Unit::Percent, v(mp, Phrase::Readings), vec![]),
        )
        .tol(READ)
        .sheet("26 %"),
        Question::new(
            "4",
            "zeta",
            label::zeta(),
            number(Unit::None, v(zeta, Phrase::Formula), vec![]),
        )
        .tol(READ)
        .sheet("0,394"),
        wn_q,
        k_q,
    ];
    let solution = vec![
        Text::by(|l| {
            l.pick(
                format!(
                    "From the figure: t_p = {} s, y(t_p) = {}, y(∞) = {}",
                    num(l, tp),
                    num(l, y_peak),
                    num(l, y_final)
                ),
                format!(
                    "Do gráfico: t_p = {} s, y(t_p) = {}, y(∞) = {}",
                    num(l, tp),
                    num(l, y_peak),
                    num(l, y_final)
                ),
            )
        }),
        Text::by(|l| {
            format!(
                "Mp = (y(t_p) − y(∞))/y(∞) = ({} − {})/{} = {} %",
                num(l, y_peak),
                num(l, y_final),
                num(l, y_final),
                num(l, mp)
            )
        }),
        say::zeta_from_overshoot(mp, zeta),
        Text::by(|l| {
            format!(
                "t_p = π/(ωn√(1 − ζ²)) ⇒ ωn = π/({}·√(1 − {}²)) = {} rad/s",
                num(l, tp),
                num(l, zeta),
                num(l, wn)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Final value theorem: y(∞) = K/ωn² = {} ⇒ K = {}·ωn² = {}",
                    num(l, y_final),
                    num(l, y_final),
                    num(l, k)
                ),
                format!(
                    "Teorema do valor final: y(∞) = K/ωn² = {} ⇒ K = {}·ωn² = {}",
                    num(l, y_final),
                    num(l, y_final),
                    num(l, k)
                ),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Check: the exact response of {} peaks at t_p = {} s with y(t_p) = {}, the figure's readings",
                    crate::text::tf(l, &g), num(l, shown_tp), num(l, shown_peak)
                ),
                format!(
                    "Verificação: a resposta exata de {} tem o pico em t_p = {} s com y(t_p) = {}, as leituras da figura",
                    crate::text::tf(l, &g), num(l, shown_tp), num(l, shown_peak)
                ),
            )
        }),
    ];
    Ok(Exercise {
        id: "4".into(),
        statement: Text::new(
            "A second-order system Y(s)/R(s) = K/(s² + 2ζωn s + ωn²) has the unit-step response shown in the figure. Find the parameters (K, ζ, ωn).",
            "Considere um sistema de segunda ordem dado por uma função de transferência da forma Y(s)/R(s) = K/(s² + 2ζωn s + ωn²). A resposta deste sistema a uma entrada em degrau unitário está representada na figura seguinte. Determine os valores dos parâmetros (K, ζ, ωn) que caracterizam o sistema.",
        ),
        parts: vec![Part {
            id: "4".into(),
            statement: Text::new(
                "Read t_p, y(t_p) and y(∞) off the figure; find (K, ζ, ωn).",
                "Retire t_p, y(t_p) e y(∞) do gráfico; determine (K, ζ, ωn).",
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
