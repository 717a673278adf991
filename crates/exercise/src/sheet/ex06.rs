//! Exercise 6: ζ, ωn, t_s, t_p, t_r and Mp of three canonical second-order systems, each
//! formula beside the exact metric of the step response.

use degrau_lti::C64;
use degrau_lti::feedback::SecondOrder;

use super::*;
use crate::model::{Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let c = pair_of(6.0, 58.0);
    Ok(Exercise {
        id: "6".into(),
        statement: Text::new(
            "Find ζ, ωn, t_s, t_p, t_r and the maximum percent overshoot (Mp) of each second-order system below (canonical form) under a unit step.",
            "Obtenha os valores de ζ, ωn, t_s, t_p, t_r e da sobreelongação máxima percentual (M_p) para cada um dos sistemas de segunda ordem (forma canónica) abaixo apresentados, quando sujeitos a uma entrada em degrau unitário.",
        ),
        parts: vec![
            part(
                "6a",
                pair_of(12.0, 120.0),
                Text::same("G(s) = 120/(s² + 12s + 120)"),
                Mode::DesignStep,
                [
                    "0,548",
                    "10,95 rad/s",
                    "0,666 s",
                    "0,343 s",
                    "0,2348 s",
                    "12,77 %",
                ],
            )?,
            part(
                "6b",
                pair_of(20.0, 1000.0),
                Text::same("G(s) = 1000/(s² + 20s + 1000)"),
                Mode::DesignStep,
                [
                    "0,316",
                    "31,62 rad/s",
                    "0,4 s",
                    "0,105 s",
                    "0,063 s",
                    "35,12 %",
                ],
            )?,
            part(
                "6c",
                c,
                Text::new(
                    "The poles of the canonical system in the s-plane of the figure: s = −3 ± j7.",
                    "Os pólos do sistema na forma canónica no plano-s da figura: s = −3 ± j7.",
                ),
                Mode::DesignPlane,
                [
                    "0,394",
                    "7,616 rad/s",
                    "1,333 s",
                    "0,449 s",
                    "0,2823 s",
                    "26 %",
                ],
            )?,
        ],
    })
}

fn part(
    id: &str,
    pair: SecondOrder,
    statement: Text,
    mode: Mode,
    printed: [&str; 6],
) -> Result<Part, SheetError> {
    let g = canonical(pair)?;
    let exact = info(&g)?;
    let ts = need(exact.settling_time, "settling time")?;
    let tp = need(exact.peak_time, "peak time")?;
    let mp = need(exact.overshoot, "overshoot")?;
    let tr = rise_full(&g)?;
    let tr_10_90 = need(exact.rise_time, "rise time")?;
    let f = |x: f64| v(x, Phrase::Formula);
    let questions = vec![
        Question::new(
            id,
            "zeta",
            label::zeta(),
            number(Unit::None, v(pair.zeta, Phrase::Poles), vec![]),
        )
        .sheet(printed[0]),
        Question::new(
            id,
            "wn",
            label::wn(),
            number(Unit::RadPerSecond, v(pair.wn, Phrase::Poles), vec![]),
        )
        .sheet(printed[1]),
        Question::new(
            id,
            "ts",
            label::settling(),
            number(
                Unit::Seconds,
                v(ts, Phrase::Exact),
                vec![f(pair.settling_time())],
            ),
        )
        .sheet(printed[2]),
        Question::new(
            id,
            "tp",
            label::peak_time(),
            number(
                Unit::Seconds,
                v(tp, Phrase::Exact),
                vec![f(pair.peak_time())],
            ),
        )
        .sheet(printed[3]),
        Question::new(
            id,
            "tr",
            label::rise(),
            number(
                Unit::Seconds,
                v(tr, Phrase::Rise0to100),
                vec![f(pair.rise_time()), v(tr_10_90, Phrase::Rise10to90)],
            ),
        )
        .sheet(printed[4]),
        Question::new(
            id,
            "Mp",
            label::overshoot(),
            number(
                Unit::Percent,
                v(mp, Phrase::Exact),
                vec![f(pair.overshoot())],
            ),
        )
        .sheet(printed[5]),
    ];
    let poles: Vec<C64> = pair.poles().to_vec();
    let mut solution = vec![Text::by(|l| {
        l.pick(
                format!(
                    "Comparing with ωn²/(s² + 2ζωn s + ωn²): 2ζωn = {}, ωn² = {} ⇒ ζ = {}, ωn = {} rad/s (poles {} ± j{})",
                    num(l, 2.0 * pair.sigma()), num(l, pair.wn * pair.wn), num(l, pair.zeta), num(l, pair.wn),
                    num(l, poles[0].re), num(l, poles[0].im)
                ),
                format!(
                    "Comparando com ωn²/(s² + 2ζωn s + ωn²): 2ζωn = {}, ωn² = {} ⇒ ζ = {}, ωn = {} rad/s (pólos {} ± j{})",
                    num(l, 2.0 * pair.sigma()), num(l, pair.wn * pair.wn), num(l, pair.zeta), num(l, pair.wn),
                    num(l, poles[0].re), num(l, poles[0].im)
                ),
            )
    })];
    if mode == Mode::DesignPlane {
        solution.insert(
            0,
            Text::by(|l| {
                format!(
                    "θ = tg⁻¹(ωd/σ) = tg⁻¹({}/{}) = {} rad ⇒ ζ = cos θ = {}; ωn = √(ωd² + σ²) = {} rad/s",
                    num(l, pair.wd()), num(l, pair.sigma()), num(l, pair.zeta.acos()), num(l, pair.zeta), num(l, pair.wn)
                )
            }),
        );
    }
    solution.extend(say::formulas_beside_exact(pair, &g)?);
    solution.push(Text::new(
        "Note 2 of the sheet: the formula's t_r is the 0–100 % rise time; MATLAB's stepinfo (and Degrau's table) give 10–90 %. Both are accepted here.",
        "Nota 2 da folha: o t_r da fórmula é o tempo de subida de 0–100 %; o stepinfo do MATLAB (e a tabela do Degrau) dão 10–90 %. Ambos são aceites aqui.",
    ));
    Ok(Part {
        id: id.into(),
        statement,
        system: System::Tf {
            tf: g,
            amplitude: 1.0,
        },
        mode,
        questions,
        solution,
    })
}
