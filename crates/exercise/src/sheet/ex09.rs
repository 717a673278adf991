//! Exercise 9: M, B and K of a mass–spring–damper from its response to a 10 N force step
//! (x(∞), the overshoot and t_p read off a figure).

use degrau_lti::feedback::SecondOrder;

use super::*;
use crate::model::{Mode, Part, Reading, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    // The force step and the readings the sheet takes off its figure.
    let f = 10.0;
    let x_final = 0.03;
    let x_over = 0.003;
    let tp = 2.0;
    let k = f / x_final;
    let mp = 100.0 * x_over / x_final;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    let wn = std::f64::consts::PI / (tp * (1.0 - zeta * zeta).sqrt());
    let m = k / (wn * wn);
    let b = 2.0 * zeta * wn * m;
    let g = tf(&[1.0], &[m, b, k])?;
    let r = degrau_lti::StepResponse::new(&g, f)?;
    let shown = degrau_lti::StepInfo::of_response(&r, &degrau_lti::StepInfoOptions::default());
    let shown_tp = need(shown.peak_time, "peak time")?;
    let shown_final = need(shown.steady_state, "final value")?;
    let shown_mp = need(shown.overshoot, "overshoot")?;
    let reading = |key: &str, label: Text, value: f64, unit: Unit| Reading {
        key: key.into(),
        label,
        value,
        unit,
    };
    let readings = vec![
        reading(
            "force",
            Text::new("Force step f", "Degrau de força f"),
            f,
            Unit::None,
        ),
        reading(
            "x_final",
            Text::new("Final displacement x(∞)", "Deslocamento final x(∞)"),
            x_final,
            Unit::Metre,
        ),
        reading(
            "x_over",
            Text::new("Overshoot x(t_p) − x(∞)", "Sobreelongação x(t_p) − x(∞)"),
            x_over,
            Unit::Metre,
        ),
        reading("tp", label::peak_time(), tp, Unit::Seconds),
    ];
    let q = |key: &str, label: Text, unit: Unit, value: f64, how: Phrase, printed: &str| {
        Question::new("9", key, label, number(unit, v(value, how), vec![]))
            .tol(READ)
            .sheet(printed)
    };
    let questions = vec![
        q(
            "K",
            Text::new("Spring constant K", "Constante da mola K"),
            Unit::NewtonPerMetre,
            k,
            Phrase::FinalValue,
            "333,33 N/m",
        ),
        q(
            "Mp",
            label::overshoot(),
            Unit::Percent,
            mp,
            Phrase::Readings,
            "10 %",
        ),
        q(
            "zeta",
            label::zeta(),
            Unit::None,
            zeta,
            Phrase::Formula,
            "0,591",
        ),
        q(
            "wn",
            label::wn(),
            Unit::RadPerSecond,
            wn,
            Phrase::Formula,
            "1,95 rad/s",
        ),
        q(
            "M",
            Text::new("Mass M", "Massa M"),
            Unit::Kilogram,
            m,
            Phrase::Formula,
            "87,66 kg",
        ),
        q(
            "B",
            Text::new("Damping B", "Amortecimento B"),
            Unit::NewtonSecondPerMetre,
            b,
            Phrase::Formula,
            "201,71 N s/m",
        ),
    ];
    let solution = vec![
        Text::new(
            "X(s)/F(s) = 1/(Ms² + Bs + K) = (1/M)/(s² + (B/M)s + K/M) (i); F(s) = 10/s",
            "X(s)/F(s) = 1/(Ms² + Bs + K) = (1/M)/(s² + (B/M)s + K/M) (i); F(s) = 10/s",
        ),
        Text::by(|l| {
            l.pick(
                format!(
                    "Final value theorem: x(∞) = lim_(s→0) sX(s) = 10/K = {} ⇒ K = {} N/m",
                    num(l, x_final),
                    num(l, k)
                ),
                format!(
                    "Teorema do valor final: x(∞) = lim_(s→0) sX(s) = 10/K = {} ⇒ K = {} N/m",
                    num(l, x_final),
                    num(l, k)
                ),
            )
        }),
        Text::by(|l| {
            format!(
                "Mp = {}/{} = {} %",
                num(l, x_over),
                num(l, x_final),
                num(l, mp)
            )
        }),
        say::zeta_from_overshoot(mp, zeta),
        Text::by(|l| {
            format!(
                "t_p = π/(ωn√(1 − ζ²)) = {} s ⇒ ωn = {} rad/s",
                num(l, tp),
                num(l, wn)
            )
        }),
        Text::by(|l| {
            format!(
                "K/M = ωn² ⇒ M = K/ωn² = {} kg; B/M = 2ζωn ⇒ B = 2ζωn·M = {} N s/m",
                num(l, m),
                num(l, b)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Check: the exact response to the 10 N step settles at x(∞) = {} m, peaks at t_p = {} s with Mp = {} %: the figure's readings.",
                    num(l, shown_final), num(l, shown_tp), num(l, shown_mp)
                ),
                format!(
                    "Verificação: a resposta exata ao degrau de 10 N estabelece-se em x(∞) = {} m, com pico em t_p = {} s e Mp = {} %: as leituras da figura.",
                    num(l, shown_final), num(l, shown_tp), num(l, shown_mp)
                ),
            )
        }),
    ];
    Ok(Exercise {
        id: "9".into(),
        statement: Text::new(
            "Consider the translational mechanical system of the figure. A force step of amplitude f = 10 N is applied; the output displacement x(t) is plotted on the right. Find the parameters M, B and K of the system.",
            "Considere o sistema mecânico de translacção representado na figura seguinte. Ao sistema é aplicado um degrau de força com amplitude de f = 10 N. A variação do deslocamento x(t) da saída está ilustrado no gráfico da direita. Determine os valores dos parâmetros M, B e K do sistema.",
        ),
        parts: vec![Part {
            id: "9".into(),
            statement: Text::new(
                "Read x(∞), the overshoot and t_p off the figure; find M, B and K.",
                "Retire x(∞), a sobreelongação e t_p do gráfico; determine M, B e K.",
            ),
            system: System::Figure {
                curve: g,
                amplitude: f,
                readings,
            },
            mode: Mode::Identify,
            questions,
            solution,
        }],
    })
}
