//! Exercise 11: system type, error constants and steady-state errors of the unity-feedback
//! loop around (s + 2)/(s(s + 4)).

use degrau_lti::feedback::{ErrorConstants, Limit};

use super::*;
use crate::model::{Controller, Mode, Part, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let g = tf(&[1.0, 2.0], &[1.0, 4.0, 0.0])?;
    let c = ErrorConstants::of(&g, 1.0);
    let e = c.errors();
    let stable = g.closed_loop(1.0)?.is_stable();
    let how = Phrase::ErrorConstants;
    let q = |key: &str, label: Text, x: Limit, printed: &str| {
        Question::new(
            "11",
            key,
            label,
            number(Unit::None, v(x.value(), how), vec![]),
        )
        .sheet(printed)
    };
    let questions = vec![
        Question::new(
            "11",
            "type",
            Text::new("System type", "Tipo do sistema"),
            number(Unit::None, v(c.system_type as f64, how), vec![]),
        )
        .sheet("1"),
        q(
            "Kp",
            Text::new(
                "Position error constant K_p",
                "Constante de erro de posição K_p",
            ),
            c.kp,
            "inf",
        ),
        q(
            "Kv",
            Text::new(
                "Velocity error constant K_v",
                "Constante de erro de velocidade K_v",
            ),
            c.kv,
            "1/2",
        ),
        q(
            "Ka",
            Text::new(
                "Acceleration error constant K_a",
                "Constante de erro de aceleração K_a",
            ),
            c.ka,
            "0",
        ),
        q(
            "ess_step",
            Text::new("e_ss for a unit step", "e_ss para um degrau unitário"),
            e.step,
            "0",
        ),
        q(
            "ess_ramp",
            Text::new("e_ss for a unit ramp", "e_ss para uma rampa unitária"),
            e.ramp,
            "2",
        ),
        q(
            "ess_parabola",
            Text::new(
                "e_ss for a unit parabola",
                "e_ss para uma parábola unitária",
            ),
            e.parabola,
            "inf",
        ),
    ];
    let n = |l: Lang, x: Limit| num(l, x.value());
    let solution = vec![
        Text::by(|l| {
            l.pick(
                format!(
                    "G(s) = {} has {} pole(s) at the origin: type {}",
                    crate::text::tf(l, &g),
                    c.system_type,
                    c.system_type
                ),
                format!(
                    "G(s) = {} tem {} pólo(s) na origem: sistema do Tipo {}",
                    crate::text::tf(l, &g),
                    c.system_type,
                    c.system_type
                ),
            )
        }),
        Text::by(|l| {
            format!(
                "K_p = lim_(s→0) G(s) = {}; K_v = lim_(s→0) sG(s) = 2/4 = {}; K_a = lim_(s→0) s²G(s) = {}",
                n(l, c.kp),
                n(l, c.kv),
                n(l, c.ka)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!("e_ss(step) = 1/(1 + K_p) = {}; e_ss(ramp) = 1/K_v = {}; e_ss(parabola) = 1/K_a = {}", n(l, e.step), n(l, e.ramp), n(l, e.parabola)),
                format!("e_ss(degrau) = 1/(1 + K_p) = {}; e_ss(rampa) = 1/K_v = {}; e_ss(parábola) = 1/K_a = {}", n(l, e.step), n(l, e.ramp), n(l, e.parabola)),
            )
        }),
        Text::by(|l| {
            let verdict = if stable {
                l.pick("stable", "estável")
            } else {
                l.pick("unstable", "instável")
            };
            l.pick(
                format!("The closed loop (poles of s² + 5s + 2) is {verdict}, so these errors are the real ones."),
                format!("A malha fechada (pólos de s² + 5s + 2) é {verdict}, logo estes erros são os reais."),
            )
        }),
        say::root_locus(&g),
    ];
    Ok(Exercise {
        id: "11".into(),
        statement: Text::new(
            "A unity-feedback system has the open-loop transfer function G(s) = (s + 2)/(s(s + 4)). Find the system type, the position, velocity and acceleration error constants (K_p, K_v, K_a) and the steady-state error (e_ss) for unit step, ramp and parabola inputs.",
            "Considere um sistema de realimentação unitária com a seguinte função de transferência em malha aberta: G(s) = (s + 2)/(s(s + 4)). Determine o sistema Tipo, as constantes de erro de posição, velocidade e aceleração (K_p, K_v, K_a) e o erro em regime permanente (e_ss) do sistema para as entradas em degrau, rampa e parábola unitárias.",
        ),
        parts: vec![Part {
            id: "11".into(),
            statement: Text::same("G(s) = (s + 2)/(s(s + 4))"),
            system: System::Loop {
                plant: g.clone(),
                controller: Controller::Proportional,
                gain: 1.0,
            },
            mode: Mode::DesignLoop,
            questions,
            solution,
        }],
    })
}
