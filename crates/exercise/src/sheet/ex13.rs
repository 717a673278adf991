//! Exercise 13: (K, a) of the loop around K/(s(s + a)) for a 1 % ramp error and a 10 %
//! overshoot, then the exact step and ramp responses that check them.

use degrau_lti::feedback::{ErrorConstants, SecondOrder};

use super::*;
use crate::model::{Controller, Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let mp = 10.0;
    let ess = 0.01;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    // a = ess·K and a = 2ζ√K ⇒ √K = 2ζ/ess.
    let k = (2.0 * zeta / ess).powi(2);
    let a = ess * k;
    let plant = tf(&[1.0], &[1.0, a, 0.0])?;
    let cl = plant.closed_loop(k)?;
    let exact = info(&cl)?;
    let exact_mp = need(exact.overshoot, "overshoot")?;
    let ts = need(exact.settling_time, "settling time")?;
    let ramp_error = ErrorConstants::of(&plant, k).errors().ramp.value();
    let system = System::Loop {
        plant: plant.clone(),
        controller: Controller::Proportional,
        gain: k,
    };
    let part_a = Part {
        id: "13a".into(),
        statement: Text::new(
            "a) Find (K, a) giving a 1 % steady-state error and a 10 % maximum overshoot.",
            "a) Determine os valores de (K, a) que originam um erro em regime permanente de 1 % e uma sobreelongação máxima de 10 %.",
        ),
        system: system.clone(),
        mode: Mode::DesignLoop,
        questions: vec![
            Question::new(
                "13a",
                "zeta",
                label::zeta(),
                number(Unit::None, v(zeta, Phrase::Formula), vec![]),
            )
            .sheet("0,591"),
            Question::new(
                "13a",
                "K",
                Text::new("Gain K", "Ganho K"),
                number(Unit::None, v(k, Phrase::Formula), vec![]),
            )
            .sheet("13971"),
            Question::new(
                "13a",
                "a",
                Text::new("Pole parameter a", "Parâmetro a"),
                number(Unit::None, v(a, Phrase::Formula), vec![]),
            )
            .sheet("139,7"),
        ],
        solution: vec![
            Text::new(
                "Closed loop: Y(s)/R(s) = G/(1 + G) = K/(s² + as + K) ⇒ K = ωn², a = 2ζωn (i)",
                "Malha fechada: Y(s)/R(s) = G/(1 + G) = K/(s² + as + K) ⇒ K = ωn², a = 2ζωn (i)",
            ),
            say::zeta_from_overshoot(mp, zeta),
            Text::new(
                "Type 1: the error refers to a unit ramp; K_v = lim_(s→0) sG(s) = K/a; e_ss = 1/K_v = a/K = 0.01 ⇒ a = 0.01K (iii)",
                "Tipo 1: o erro refere-se a uma rampa unitária; K_v = lim_(s→0) sG(s) = K/a; e_ss = 1/K_v = a/K = 0,01 ⇒ a = 0,01K (iii)",
            ),
            say::root_locus(&plant),
            Text::by(|l| {
                format!(
                    "{}K = 2·{}·√K ⇒ √K = {} ⇒ K = {}, a = {}",
                    num(l, ess),
                    num(l, zeta),
                    num(l, k.sqrt()),
                    num(l, k),
                    num(l, a)
                )
            }),
        ],
    };
    let part_b = Part {
        id: "13b".into(),
        statement: Text::new(
            "b) Plot the unit step and ramp responses for the (K, a) of a) and check the specs.",
            "b) Utilize o MATLAB para obter as respostas ao degrau e rampa unitárias para os valores de (K, a) obtidos em a). Verifique se os gráficos estão consistentes com as especificações pretendidas em a).",
        ),
        system,
        mode: Mode::DesignLoop,
        questions: vec![
            Question::new(
                "13b",
                "Mp",
                label::overshoot(),
                number(Unit::Percent, v(exact_mp, Phrase::ExactLoop), vec![]),
            ),
            Question::new(
                "13b",
                "ess_ramp",
                Text::new("e_ss for a unit ramp", "e_ss para uma rampa unitária"),
                number(Unit::None, v(ramp_error, Phrase::ErrorConstants), vec![]),
            ),
        ],
        solution: vec![
            Text::by(|l| {
                l.pick(
                    format!("Exact closed-loop step response with K = {}, a = {}: Mp = {} %, t_s (2 %) = {} s", num(l, k), num(l, a), num(l, exact_mp), num(l, ts)),
                    format!("Resposta ao degrau exata em malha fechada com K = {}, a = {}: Mp = {} %, t_s (2 %) = {} s", num(l, k), num(l, a), num(l, exact_mp), num(l, ts)),
                )
            }),
            Text::by(|l| {
                l.pick(
                    format!("Ramp response: the error tends to e_ss = a/K = {} (1 %): both specs hold.", num(l, ramp_error)),
                    format!("Resposta à rampa: o erro tende para e_ss = a/K = {} (1 %): ambas as especificações se cumprem.", num(l, ramp_error)),
                )
            }),
        ],
    };
    Ok(Exercise {
        id: "13".into(),
        statement: Text::new(
            "A unity-feedback system has the forward-path transfer function G(s) = K/(s(s + a)).",
            "Um sistema de realimentação unitária possui uma função de transferência no ramo directo dada por G(s) = K/(s(s + a)).",
        ),
        parts: vec![part_a, part_b],
    })
}
