//! Exercise 1: the unit-step responses of 5/(s + 5) and 10/(s + 10); K, τ, t_r, t_s (2 %).

use super::*;
use crate::model::{Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    Ok(Exercise {
        id: "1".into(),
        statement: Text::new(
            "Find the unit-step response of each system below. Characterise its transient response by the DC gain (K), time constant (τ), rise time (t_r) and 2 % settling time (t_s). Sketch the unit-step responses.",
            "Determine a resposta ao degrau unitário de cada um dos sistemas abaixo indicados. Caracterize a sua resposta transitória em termos do ganho DC (K), constante de tempo (τ), tempo de subida (t_r) e tempo de estabelecimento a 2 % (t_s). Esboce as respectivas respostas ao degrau unitário.",
        ),
        parts: vec![
            part("1a", 5.0, ["1 - e^{-5t}", "1", "0,2", "0,439 s", "0,78 s"])?,
            part("1b", 10.0, ["1 - e^{-10t}", "1", "0,1", "0,22 s", "0,39 s"])?,
        ],
    })
}

/// Y(s)/R(s) = a/(s + a), and the sheet's answers: y(t), K, τ, t_r, t_s.
fn part(id: &str, a: f64, printed: [&str; 5]) -> Result<Part, SheetError> {
    let g = tf(&[a], &[1.0, a])?;
    let exact = info(&g)?;
    let k = g.dc_gain();
    let tau = time_constant(&g)?;
    let tr = need(exact.rise_time, "rise time")?;
    let ts = need(exact.settling_time, "settling time")?;
    let t1 = need(exact.rise_start, "rise start")?;
    let t2 = need(exact.rise_end, "rise end")?;
    let pole = g.poles()[0].re;
    let questions = vec![
        Question::new(
            id,
            "y",
            label::response(),
            Expected::ClosedForm {
                tf: g.clone(),
                amplitude: 1.0,
                instants: instants(5.0 * tau),
            },
        )
        .sheet(printed[0]),
        Question::new(
            id,
            "K",
            label::dc_gain(),
            number(Unit::None, v(k, Phrase::FinalValue), vec![]),
        )
        .sheet(printed[1]),
        Question::new(
            id,
            "tau",
            label::tau(),
            number(
                Unit::Seconds,
                v(tau, Phrase::Exact),
                vec![v(-1.0 / pole, Phrase::Poles)],
            ),
        )
        .sheet(printed[2]),
        Question::new(
            id,
            "tr",
            label::rise(),
            number(Unit::Seconds, v(tr, Phrase::Exact), vec![]),
        )
        .sheet(printed[3]),
        Question::new(
            id,
            "ts",
            label::settling(),
            number(
                Unit::Seconds,
                v(ts, Phrase::Exact),
                vec![v(4.0 * tau, Phrase::FirstOrderFormula)],
            ),
        )
        .sheet(printed[4]),
    ];
    let solution = vec![
        Text::by(|l| {
            l.pick(
                format!("Y(s)/R(s) = {}; R(s) = 1/s", crate::text::tf(l, &g)),
                format!("Y(s)/R(s) = {}; R(s) = 1/s", crate::text::tf(l, &g)),
            )
        }),
        say::partial_fractions(&g, 1.0)?,
        say::closed_form(&g, 1.0)?,
        Text::by(|l| {
            l.pick(
                format!("DC gain: K = lim_(s→0) Y(s)/R(s) = {}", num(l, k)),
                format!("Ganho DC: K = lim_(s→0) Y(s)/R(s) = {}", num(l, k)),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Time constant: y(τ) = 63.2 % of the final value ⇒ τ = {} s = 1/a, a = {} (the pole is s = {})",
                    num(l, tau),
                    num(l, a),
                    num(l, pole)
                ),
                format!(
                    "Constante de tempo: y(τ) = 63,2 % do valor final ⇒ τ = {} s = 1/a, a = {} (o pólo é s = {})",
                    num(l, tau),
                    num(l, a),
                    num(l, pole)
                ),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Rise time (10–90 %): y(t₁) = 0.1 ⇒ t₁ = {} s; y(t₂) = 0.9 ⇒ t₂ = {} s; t_r = t₂ − t₁ = τ·ln 9 = {} s",
                    num(l, t1),
                    num(l, t2),
                    num(l, tr)
                ),
                format!(
                    "Tempo de subida (10–90 %): y(t₁) = 0,1 ⇒ t₁ = {} s; y(t₂) = 0,9 ⇒ t₂ = {} s; t_r = t₂ − t₁ = τ·ln 9 = {} s",
                    num(l, t1),
                    num(l, t2),
                    num(l, tr)
                ),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Settling time (2 %): e^(−t_s/τ) = 0.02 ⇒ t_s = τ·ln 50 = {} s; the rule t_s ≈ 4τ gives {} s",
                    num(l, ts),
                    num(l, 4.0 * tau)
                ),
                format!(
                    "Tempo de estabelecimento (2 %): e^(−t_s/τ) = 0,02 ⇒ t_s = τ·ln 50 = {} s; a regra t_s ≈ 4τ dá {} s",
                    num(l, ts),
                    num(l, 4.0 * tau)
                ),
            )
        }),
    ];
    Ok(Part {
        id: id.into(),
        statement: Text::by(|l| format!("Y(s)/R(s) = {}", crate::text::tf(l, &g))),
        system: System::Tf {
            tf: g.clone(),
            amplitude: 1.0,
        },
        mode: Mode::DesignStep,
        questions,
        solution,
    })
}

/// Instants at which a closed form is checked: 12 points over [0, horizon].
pub(crate) fn instants(horizon: f64) -> Vec<f64> {
    (0..12).map(|i| horizon * i as f64 / 11.0).collect()
}
