//! Exercise 12: the gain K of the loop around K/((s + 2)(s + 10)) for a 10 % steady-state
//! error to a unit step.

use degrau_lti::feedback::ErrorConstants;

use super::*;
use crate::model::{Controller, Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let g = tf(&[1.0], &[1.0, 12.0, 20.0])?;
    let ess = 0.1;
    let c1 = ErrorConstants::of(&g, 1.0);
    let g0 = c1.kp.value();
    // e_ss = 1/(1 + K·G(0)) ⇒ K = (1/e_ss − 1)/G(0).
    let k = (1.0 / ess - 1.0) / g0;
    let check = ErrorConstants::of(&g, k).errors().step.value();
    let cl = g.closed_loop(k)?;
    let cl_mp = need(info(&cl)?.overshoot, "overshoot")?;
    let questions = vec![
        Question::new(
            "12",
            "type",
            Text::new("System type", "Tipo do sistema"),
            number(
                Unit::None,
                v(c1.system_type as f64, Phrase::ErrorConstants),
                vec![],
            ),
        )
        .sheet("0"),
        Question::new(
            "12",
            "K",
            Text::new("Gain K", "Ganho K"),
            number(Unit::None, v(k, Phrase::ErrorConstants), vec![]),
        )
        .sheet("180"),
    ];
    let solution = vec![
        Text::new(
            "No pole at the origin: type 0, so the error refers to a unit step.",
            "Nenhum pólo na origem: sistema do Tipo 0, logo o erro refere-se a um degrau unitário.",
        ),
        Text::by(|l| {
            l.pick(
                format!("K_p = lim_(s→0) KG(s) = K/{} (the open loop's limit; the sheet writes Y(s)/R(s) for it, but it is the open loop K/((s + 2)(s + 10)))", num(l, 1.0 / g0)),
                format!("K_p = lim_(s→0) KG(s) = K/{} (o limite da malha aberta; a folha escreve Y(s)/R(s), mas é a malha aberta K/((s + 2)(s + 10)))", num(l, 1.0 / g0)),
            )
        }),
        Text::by(|l| {
            format!(
                "e_ss = 1/(1 + K_p) = {0}/({0} + K) = {1} ⇒ K = {2}",
                num(l, 1.0 / g0),
                num(l, ess),
                num(l, k)
            )
        }),
        Text::by(|l| {
            let poles: Vec<String> = cl
                .poles()
                .iter()
                .map(|p| crate::text::complex(l, *p))
                .collect();
            l.pick(
                format!("Check: with K = {}, e_ss = {}; the closed loop's poles {} are stable, so the error is reached.", num(l, k), num(l, check), poles.join("; ")),
                format!("Verificação: com K = {}, e_ss = {}; os pólos da malha fechada {} são estáveis, logo o erro é atingido.", num(l, k), num(l, check), poles.join("; ")),
            )
        }),
        say::root_locus(&g),
        Text::by(|l| {
            let pair = degrau_lti::feedback::SecondOrder::dominant(cl.poles());
            let (zeta, wn) = pair.map_or((f64::NAN, f64::NAN), |p| (p.zeta, p.wn));
            l.pick(
                format!(
                    "At K = {}: ζ = {}, ωn = {} rad/s; the exact closed-loop step response settles at {} (error {}) with Mp = {} %.",
                    num(l, k), num(l, zeta), num(l, wn), num(l, cl.dc_gain()), num(l, 1.0 - cl.dc_gain()), num(l, cl_mp)
                ),
                format!(
                    "Em K = {}: ζ = {}, ωn = {} rad/s; a resposta ao degrau exata em malha fechada estabelece-se em {} (erro {}) com Mp = {} %.",
                    num(l, k), num(l, zeta), num(l, wn), num(l, cl.dc_gain()), num(l, 1.0 - cl.dc_gain()), num(l, cl_mp)
                ),
            )
        }),
    ];
    Ok(Exercise {
        id: "12".into(),
        statement: Text::new(
            "Consider the unity-feedback system of the figure. Find K so that the system has a steady-state error of 10 %.",
            "Considere o sistema de realimentação unitária representado na figura seguinte. Determine o valor de K de forma que o sistema apresente um erro em regime permanente de 10 %.",
        ),
        parts: vec![Part {
            id: "12".into(),
            statement: Text::new(
                "Loop: K/((s + 2)(s + 10)), unity feedback.",
                "Malha: K/((s + 2)(s + 10)), realimentação unitária.",
            ),
            system: System::Loop {
                plant: g.clone(),
                controller: Controller::Proportional,
                gain: k,
            },
            mode: Mode::DesignLoop,
            questions,
            solution,
        }],
    })
}
