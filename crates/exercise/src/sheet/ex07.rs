//! Exercise 7: the proportional gain K of a unity-feedback loop around 1/(s(s + 2)) for
//! Mp ≤ 10 %, on the exact closed-loop response and by the formula; the root locus reading.

use degrau_lti::feedback::{SecondOrder, Spec, find_gain};
use degrau_lti::locus::{self, Side};

use super::*;
use crate::model::{Controller, GainRange, Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let plant = tf(&[1.0], &[1.0, 2.0, 0.0])?;
    let mp = 10.0;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    let wn = 2.0 / (2.0 * zeta);
    let k_formula = wn * wn;
    let search = find_gain(&plant, &[Spec::Overshoot(mp)])?.ok_or(SheetError::Missing("gain"))?;
    let range = GainRange {
        low: search.range.0,
        high: search.range.1,
    };
    let breakaways = locus::breakaways(&plant.num(), &plant.den(), Side::Positive);
    let cl = plant.closed_loop(range.high)?;
    let exact_mp = need(info(&cl)?.overshoot, "overshoot")?;
    let poles = cl.poles().to_vec();
    let questions = vec![
        Question::new(
            "7",
            "zeta",
            label::zeta(),
            number(Unit::None, v(zeta, Phrase::Formula), vec![]),
        )
        .sheet("0,591"),
        Question::new(
            "7",
            "wn",
            label::wn(),
            number(Unit::RadPerSecond, v(wn, Phrase::Formula), vec![]),
        )
        .sheet("1,692 rad/s"),
        Question::new(
            "7",
            "K",
            Text::new("Gains K with Mp ≤ 10 %", "Ganhos K com Mp ≤ 10 %"),
            Expected::GainRange {
                main: range,
                also: vec![(
                    GainRange {
                        low: 0.0,
                        high: k_formula,
                    },
                    Text::new(Phrase::Formula.get(Lang::En), Phrase::Formula.get(Lang::Pt)),
                )],
            },
        )
        .sheet("2,86"),
    ];
    let solution = vec![
        Text::by(|l| {
            l.pick(
                format!(
                    "Closed loop: Y(s)/R(s) = KG/(1 + KG) = K/(s² + 2s + K), G(s) = {}",
                    crate::text::tf(l, &plant)
                ),
                format!(
                    "Malha fechada: Y(s)/R(s) = KG/(1 + KG) = K/(s² + 2s + K), G(s) = {}",
                    crate::text::tf(l, &plant)
                ),
            )
        }),
        say::zeta_from_overshoot(mp, zeta),
        Text::by(|l| {
            l.pick(
                format!(
                    "Comparing with the canonical form: 2ζωn = 2 ⇒ ωn = {} rad/s; K = ωn² = {}",
                    num(l, wn),
                    num(l, k_formula)
                ),
                format!(
                    "Comparando com a forma canónica: 2ζωn = 2 ⇒ ωn = {} rad/s; K = ωn² = {}",
                    num(l, wn),
                    num(l, k_formula)
                ),
            )
        }),
        Text::by(|l| {
            let b = breakaways.first().map_or(String::new(), |b| {
                format!("s = {} (K = {})", num(l, b.s), num(l, b.k))
            });
            l.pick(
                format!(
                    "Root locus of K/(s(s + 2)): the branches leave the real axis at {b} and go up the line Re(s) = −1; the line ζ = {} meets them at s = {} (K = {}).",
                    num(l, zeta), crate::text::complex(l, poles[0]), num(l, range.high)
                ),
                format!(
                    "Lugar das raízes de K/(s(s + 2)): os ramos saem do eixo real em {b} e sobem pela reta Re(s) = −1; a reta ζ = {} cruza-os em s = {} (K = {}).",
                    num(l, zeta), crate::text::complex(l, poles[0]), num(l, range.high)
                ),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "On the exact closed-loop response: Mp ≤ 10 % for 0 < K ≤ {} (at that K, Mp = {} %): the loop is exactly second order, so the formula is exact here.",
                    num(l, range.high), num(l, exact_mp)
                ),
                format!(
                    "Na resposta exata em malha fechada: Mp ≤ 10 % para 0 < K ≤ {} (nesse K, Mp = {} %): a malha é exatamente de segunda ordem, logo a fórmula é exata aqui.",
                    num(l, range.high), num(l, exact_mp)
                ),
            )
        }),
    ];
    Ok(Exercise {
        id: "7".into(),
        statement: Text::new(
            "For the unity-feedback system of the figure, find the gain K (of the proportional controller) so that the output y(t) has a maximum overshoot Mp ≤ 10 % in response to a unit step.",
            "Para o sistema de realimentação unitária apresentado na figura seguinte, determine o ganho K (do controlador proporcional) de forma que a saída y(t) tenha uma sobreelongação máxima de M_p ≤ 10 % em resposta a uma entrada em degrau unitário.",
        ),
        parts: vec![Part {
            id: "7".into(),
            statement: Text::new(
                "Loop: K (proportional) in series with G(s) = 1/(s(s + 2)), unity feedback.",
                "Malha: K (proporcional) em série com G(s) = 1/(s(s + 2)), realimentação unitária.",
            ),
            system: System::Loop {
                plant,
                controller: Controller::Proportional,
                gain: range.high,
            },
            mode: Mode::DesignLoop,
            questions,
            solution,
        }],
    })
}
