//! Exercise 10: an armature-controlled DC motor: its speed and position transfer functions,
//! the steady speed for 10 V, the position servo's closed loop in K, the largest K for
//! Mp ≤ 20 %, the gains for t_r < 4 s (with ζ following K, not fixed), and the exact Mp
//! and t_r at K = 0.01, 0.02 and 0.04.

use degrau_lti::feedback::{SecondOrder, Spec, find_gain};
use degrau_lti::locus::{self, Side};

use super::*;
use crate::model::{Controller, GainRange, Mode, Part, System, TfAnswer};

/// The motor's parameters.
const J: f64 = 0.01;
const B: f64 = 0.001;
const KE: f64 = 0.02;
const KT: f64 = 1.0;
const RA: f64 = 10.0;

pub fn exercise() -> Result<Exercise, SheetError> {
    let gain = KT / (RA * J);
    let pole = B / J + KT * KE / (RA * J);
    let speed = tf(&[gain], &[1.0, pole])?;
    let position = tf(&[gain], &[1.0, pole, 0.0])?;
    let loop_system = |k: f64| System::Loop {
        plant: position.clone(),
        controller: Controller::Proportional,
        gain: k,
    };
    let w_final = degrau_lti::StepResponse::new(&speed, 10.0)?
        .final_value()
        .ok_or(SheetError::Missing("final value"))?;

    // e) the largest K for Mp ≤ 20 %.
    let mp = 20.0;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    let wn = pole / (2.0 * zeta);
    let k_formula = wn * wn / gain;
    let k_max = find_gain(&position, &[Spec::Overshoot(mp)])?
        .ok_or(SheetError::Missing("gain"))?
        .range
        .1;

    // f) t_r < 4 s: the 0–100 % rise time on the exact loop (the formula's, with ζ following
    // K), and MATLAB's 10–90 %.
    let tr_spec = 4.0;
    let k_rise = rise_threshold(&position, tr_spec)?;
    let k_rise_10_90 = find_gain(&position, &[Spec::Rise(tr_spec)])?
        .ok_or(SheetError::Missing("gain"))?
        .range
        .0;
    // The sheet's way: ζ kept at 0.456 (Mp = 20 %).
    let wn_fixed = (std::f64::consts::PI - zeta.acos()) / (tr_spec * (1.0 - zeta * zeta).sqrt());
    let k_fixed = wn_fixed * wn_fixed / gain;
    let tr_at_fixed = rise_full(&position.closed_loop(k_fixed)?)?;

    let statement = Text::new(
        "Consider the armature-controlled DC motor of the figure, with a negligible inductance L_a. Take J = 0.01 kg m², B = 0.001 N m s, K_e = 0.02 V s, K_t = 1 N m/A, R_a = 10 Ω.",
        "Considere o motor DC controlado pela armadura representado na figura seguinte. Considere que a inductância L_a é desprezável. Assuma os seguintes valores para os parâmetros: J = 0,01 kg m², B = 0,001 N m s, K_e = 0,02 V s, K_t = 1 N m/A, R_a = 10 Ω.",
    );
    let a = Part {
        id: "10a".into(),
        statement: Text::new(
            "a) Find the transfer function between the applied voltage v_a and the motor speed ω_m.",
            "a) Determine a função de transferência entre a tensão aplicada v_a e a velocidade do motor ω_m.",
        ),
        system: System::Tf {
            tf: speed.clone(),
            amplitude: 1.0,
        },
        mode: Mode::DesignStep,
        questions: vec![
            Question::new(
                "10a",
                "G",
                Text::new("ω_m(s)/V_a(s)", "ω_m(s)/V_a(s) (função de transferência)"),
                Expected::TransferFunction(TfAnswer::Fixed(speed.clone())),
            )
            .sheet("10/(s+0,3)"),
        ],
        solution: vec![
            Text::new(
                "J ω̇_m + (B + K_t K_e/R_a) ω_m = (K_t/R_a) v_a ⇒ ω_m(s)/V_a(s) = (K_t/(R_a J))/(s + B/J + K_t K_e/(R_a J))",
                "J ω̇_m + (B + K_t K_e/R_a) ω_m = (K_t/R_a) v_a ⇒ ω_m(s)/V_a(s) = (K_t/(R_a J))/(s + B/J + K_t K_e/(R_a J))",
            ),
            Text::by(|l| {
                format!(
                    "K_t/(R_a J) = {}; B/J + K_t K_e/(R_a J) = {} + {} = {} ⇒ ω_m(s)/V_a(s) = {}",
                    num(l, gain),
                    num(l, B / J),
                    num(l, KT * KE / (RA * J)),
                    num(l, pole),
                    crate::text::tf(l, &speed)
                )
            }),
        ],
    };
    let b = Part {
        id: "10b".into(),
        statement: Text::new(
            "b) Find the motor's steady-state speed after a voltage v_a = 10 V is applied.",
            "b) Calcule a velocidade em regime permanente do motor após a aplicação de uma tensão de v_a = 10 V.",
        ),
        system: System::Tf {
            tf: speed.clone(),
            amplitude: 10.0,
        },
        mode: Mode::DesignStep,
        questions: vec![
            Question::new(
                "10b",
                "w_final",
                Text::new(
                    "Steady-state speed ω_m(∞)",
                    "Velocidade em regime permanente ω_m(∞)",
                ),
                number(Unit::RadPerSecond, v(w_final, Phrase::FinalValue), vec![]),
            )
            .sheet("333,3 rad/s"),
        ],
        solution: vec![
            Text::by(|l| {
                format!(
                    "V_a(s) = 10/s ⇒ ω_m(s) = {}/(s(s + {}))",
                    num(l, 10.0 * gain),
                    num(l, pole)
                )
            }),
            Text::by(|l| {
                l.pick(
                    format!(
                        "Final value theorem: ω_m(∞) = lim_(s→0) s ω_m(s) = {}/{} = {} rad/s",
                        num(l, 10.0 * gain),
                        num(l, pole),
                        num(l, w_final)
                    ),
                    format!(
                        "Teorema do valor final: ω_m(∞) = lim_(s→0) s ω_m(s) = {}/{} = {} rad/s",
                        num(l, 10.0 * gain),
                        num(l, pole),
                        num(l, w_final)
                    ),
                )
            }),
        ],
    };
    let c = Part {
        id: "10c".into(),
        statement: Text::new(
            "c) Find the transfer function G(s) between the applied voltage v_a and the shaft's angular position θ_m.",
            "c) Determine a função de transferência G(s) entre a tensão aplicada v_a e a posição angular do veio θ_m.",
        ),
        system: System::Tf {
            tf: position.clone(),
            amplitude: 1.0,
        },
        mode: Mode::DesignStep,
        questions: vec![
            Question::new(
                "10c",
                "G",
                Text::new(
                    "G(s) = θ_m(s)/V_a(s)",
                    "G(s) = θ_m(s)/V_a(s) (função de transferência)",
                ),
                Expected::TransferFunction(TfAnswer::Fixed(position.clone())),
            )
            .sheet("10/(s(s+0,3))"),
        ],
        solution: vec![
            Text::new("ω_m(s) = s θ_m(s)", "ω_m(s) = s θ_m(s)"),
            Text::by(|l| format!("G(s) = θ_m(s)/V_a(s) = {}", crate::text::tf(l, &position))),
        ],
    };
    let d = Part {
        id: "10d".into(),
        statement: Text::new(
            "d) A position feedback of gain K is added (figure). Find the transfer function of the position servo between θ_r and θ_m.",
            "d) Suponha que é adicionado ao sistema uma realimentação da posição angular, tal como se ilustra na figura abaixo, em que K é o ganho de realimentação. Encontre a função de transferência do agora sistema servo de posição que relaciona θ_r e θ_m.",
        ),
        system: loop_system(k_max),
        mode: Mode::DesignLoop,
        questions: vec![
            Question::new(
                "10d",
                "T",
                Text::new(
                    "θ_m(s)/θ_r(s) as a function of K",
                    "θ_m(s)/θ_r(s) em função de K",
                ),
                Expected::TransferFunction(TfAnswer::ClosedLoopInK(position.clone())),
            )
            .sheet("10K/(s^2 + 0,3s + 10K)"),
        ],
        solution: vec![
            Text::new(
                "θ_m(s)/θ_r(s) = KG(s)/(1 + KG(s))",
                "θ_m(s)/θ_r(s) = KG(s)/(1 + KG(s))",
            ),
            Text::by(|l| {
                format!(
                    "= {}K/(s² + {}s + {}K) (ii)",
                    num(l, gain),
                    num(l, pole),
                    num(l, gain)
                )
            }),
        ],
    };
    let k_note = Text::by(|l| {
        l.pick(
            format!("The sheet rounds K = ωn²/10 = {} to one significant digit: K = 0.01 meets the spec but is not the largest K.", num(l, k_formula)),
            format!("A folha arredonda K = ωn²/10 = {} a um algarismo significativo: K = 0,01 cumpre a especificação mas não é o maior K.", num(l, k_formula)),
        )
    });
    let mut k_q = Question::new(
        "10e",
        "K_max",
        Text::new(
            "Largest K with Mp ≤ 20 %",
            "Valor máximo de K com Mp ≤ 20 %",
        ),
        number(
            Unit::None,
            v(k_max, Phrase::ExactLoop),
            vec![v(k_formula, Phrase::Formula)],
        ),
    )
    .sheet("0,01");
    k_q.difference = Some(k_note);
    let e = Part {
        id: "10e".into(),
        statement: Text::new(
            "e) What is the largest K that gives a maximum overshoot Mp ≤ 20 %?",
            "e) Qual é o valor máximo de K que se pode utilizar para se obter uma sobreelongação máxima de M_p ≤ 20 %?",
        ),
        system: loop_system(k_max),
        mode: Mode::DesignLoop,
        questions: vec![
            Question::new(
                "10e",
                "zeta",
                label::zeta(),
                number(Unit::None, v(zeta, Phrase::Formula), vec![]),
            )
            .sheet("0,456"),
            Question::new(
                "10e",
                "wn",
                label::wn(),
                number(Unit::RadPerSecond, v(wn, Phrase::Formula), vec![]),
            )
            .sheet("0,329 rad/s"),
            k_q,
        ],
        solution: vec![
            say::zeta_from_overshoot(mp, zeta),
            Text::by(|l| {
                l.pick(
                    format!("Comparing (ii) with ωn²/(s² + 2ζωn s + ωn²): 0.3 = 2ζωn ⇒ ωn = {} rad/s; 10K = ωn² ⇒ K = {}", num(l, wn), num(l, k_formula)),
                    format!("Comparando (ii) com ωn²/(s² + 2ζωn s + ωn²): 0,3 = 2ζωn ⇒ ωn = {} rad/s; 10K = ωn² ⇒ K = {}", num(l, wn), num(l, k_formula)),
                )
            }),
            Text::by(|l| {
                let b = locus::breakaways(&position.num(), &position.den(), Side::Positive);
                let at = b.first().map_or(String::new(), |b| {
                    format!("s = {} (K = {})", num(l, b.s), num(l, b.k))
                });
                l.pick(
                    format!("Root locus of 10K/(s(s + 0.3)): breakaway at {at}, then the branches rise along Re(s) = −0.15 and ζ falls as K grows: Mp ≤ 20 % ⇔ K ≤ {}.", num(l, k_max)),
                    format!("Lugar das raízes de 10K/(s(s + 0,3)): ponto de saída em {at}, depois os ramos sobem pela reta Re(s) = −0,15 e ζ diminui com K: Mp ≤ 20 % ⇔ K ≤ {}.", num(l, k_max)),
                )
            }),
        ],
    };
    let rise_note = Text::by(|l| {
        l.pick(
            format!(
                "The sheet keeps ζ = 0.456 (the Mp = 20 % of part e) while raising K, but in this loop ζ = 0.15/ωn falls as K grows. With ζ following K, t_r (0–100 %) < 4 s for K > {} (MATLAB's 10–90 %: K > {}); at the sheet's K = {} the exact t_r is {} s. And no K meets both parts e and f: Mp ≤ 20 % needs K ≤ {}.",
                num(l, k_rise), num(l, k_rise_10_90), num(l, k_fixed), num(l, tr_at_fixed), num(l, k_max)
            ),
            format!(
                "A folha mantém ζ = 0,456 (o Mp = 20 % da alínea e) ao aumentar K, mas nesta malha ζ = 0,15/ωn diminui quando K cresce. Com ζ a acompanhar K, t_r (0–100 %) < 4 s para K > {} (10–90 % do MATLAB: K > {}); no K = {} da folha o t_r exato é {} s. E nenhum K cumpre as alíneas e e f ao mesmo tempo: Mp ≤ 20 % exige K ≤ {}.",
                num(l, k_rise), num(l, k_rise_10_90), num(l, k_fixed), num(l, tr_at_fixed), num(l, k_max)
            ),
        )
    });
    let mut range_q = Question::new(
        "10f",
        "K_range",
        Text::new("Gains K with t_r < 4 s", "Valores de K com t_r < 4 s"),
        Expected::GainRange {
            main: GainRange {
                low: k_rise,
                high: f64::INFINITY,
            },
            also: vec![(
                GainRange {
                    low: k_rise_10_90,
                    high: f64::INFINITY,
                },
                Text::new(
                    Phrase::Rise10to90.get(Lang::En),
                    Phrase::Rise10to90.get(Lang::Pt),
                ),
            )],
        },
    )
    .sheet("K > 0,03");
    range_q.difference = Some(rise_note.clone());
    let f = Part {
        id: "10f".into(),
        statement: Text::new(
            "f) Which values of K give a rise time t_r < 4 s?",
            "f) Quais são os valores de K para os quais se obtém um tempo de subida t_r < 4 s?",
        ),
        system: loop_system(k_rise),
        mode: Mode::DesignLoop,
        questions: vec![range_q],
        solution: vec![
            Text::new(
                "t_r = (π − cos⁻¹ζ)/(ωn√(1 − ζ²)) < 4 s, with ωn = √(10K) and ζ = 0.3/(2ωn) = 0.15/ωn from (ii)",
                "t_r = (π − cos⁻¹ζ)/(ωn√(1 − ζ²)) < 4 s, com ωn = √(10K) e ζ = 0,3/(2ωn) = 0,15/ωn de (ii)",
            ),
            Text::by(|l| {
                l.pick(
                    format!("t_r falls as K grows; it equals 4 s at K = {} (ζ = {}): t_r < 4 s ⇔ K > {}", num(l, k_rise), num(l, 0.15 / (10.0 * k_rise).sqrt()), num(l, k_rise)),
                    format!("t_r diminui quando K cresce; vale 4 s em K = {} (ζ = {}): t_r < 4 s ⇔ K > {}", num(l, k_rise), num(l, 0.15 / (10.0 * k_rise).sqrt()), num(l, k_rise)),
                )
            }),
            Text::by(|l| {
                l.pick(
                    format!("The sheet's way, ζ kept at 0.456: ωn > {} rad/s ⇒ K > {}; but at that K the loop's ζ is {}, not 0.456.", num(l, wn_fixed), num(l, k_fixed), num(l, 0.15 / wn_fixed)),
                    format!("O caminho da folha, ζ mantido em 0,456: ωn > {} rad/s ⇒ K > {}; mas nesse K o ζ da malha é {}, não 0,456.", num(l, wn_fixed), num(l, k_fixed), num(l, 0.15 / wn_fixed)),
                )
            }),
            rise_note,
        ],
    };
    let mut g_questions = Vec::new();
    let mut g_solution = vec![Text::new(
        "Exact closed-loop step responses of 10K/(s² + 0.3s + 10K):",
        "Respostas ao degrau exatas em malha fechada de 10K/(s² + 0,3s + 10K):",
    )];
    for (key, k) in [("K0_01", 0.01), ("K0_02", 0.02), ("K0_04", 0.04)] {
        let cl = position.closed_loop(k)?;
        let exact = info(&cl)?;
        let mp = need(exact.overshoot, "overshoot")?;
        let tr = rise_full(&cl)?;
        let tr_10_90 = need(exact.rise_time, "rise time")?;
        let pair = pair_of(pole, gain * k);
        let kt = Text::by(|l| format!("K = {}", num(l, k)));
        g_questions.push(Question::new(
            "10g",
            &format!("Mp_{key}"),
            Text::by(|l| format!("Mp ({}), %", kt.get(l))),
            number(
                Unit::Percent,
                v(mp, Phrase::ExactLoop),
                vec![v(pair.overshoot(), Phrase::Formula)],
            ),
        ));
        g_questions.push(Question::new(
            "10g",
            &format!("tr_{key}"),
            Text::by(|l| format!("t_r ({}), s", kt.get(l))),
            number(
                Unit::Seconds,
                v(tr, Phrase::Rise0to100),
                vec![
                    v(pair.rise_time(), Phrase::Formula),
                    v(tr_10_90, Phrase::Rise10to90),
                ],
            ),
        ));
        g_solution.push(Text::by(|l| {
            l.pick(
                format!(
                    "K = {}: ζ = {}, ωn = {} rad/s; Mp = {} % ({} 20 %), t_r = {} s (0–100 %), {} s (10–90 %) ({} 4 s)",
                    num(l, k), num(l, pair.zeta), num(l, pair.wn), num(l, mp),
                    if mp <= 20.0 { "≤" } else { ">" }, num(l, tr), num(l, tr_10_90),
                    if tr < 4.0 { "<" } else { "≥" }
                ),
                format!(
                    "K = {}: ζ = {}, ωn = {} rad/s; Mp = {} % ({} 20 %), t_r = {} s (0–100 %), {} s (10–90 %) ({} 4 s)",
                    num(l, k), num(l, pair.zeta), num(l, pair.wn), num(l, mp),
                    if mp <= 20.0 { "≤" } else { ">" }, num(l, tr), num(l, tr_10_90),
                    if tr < 4.0 { "<" } else { "≥" }
                ),
            )
        }));
    }
    g_solution.push(Text::by(|l| {
        l.pick(
            format!(
                "Consistent with e) and f): Mp ≤ 20 % only for K ≤ {}; t_r < 4 s only for K > {}.",
                num(l, k_max),
                num(l, k_rise)
            ),
            format!(
                "Consistente com e) e f): Mp ≤ 20 % só para K ≤ {}; t_r < 4 s só para K > {}.",
                num(l, k_max),
                num(l, k_rise)
            ),
        )
    }));
    let g = Part {
        id: "10g".into(),
        statement: Text::new(
            "g) Plot the position servo's step response for K = 0.01, 0.02 and 0.04; find Mp and t_r in each case and check them against e) and f).",
            "g) Utilize o MATLAB para obter a resposta ao degrau do sistema servo de posição para os valores do ganho de K = 0,01, 0,02 e 0,04. Calcule a sobreelongação máxima M_p e o tempo de subida t_r para cada um dos casos referidos. Verifique se os gráficos estão consistentes com os valores calculados nas alíneas e) e f).",
        ),
        system: loop_system(0.02),
        mode: Mode::DesignLoop,
        questions: g_questions,
        solution: g_solution,
    };
    Ok(Exercise {
        id: "10".into(),
        statement,
        parts: vec![a, b, c, d, e, f, g],
    })
}

/// The K where the exact 0–100 % rise time of the loop around K·G equals `tr` (it falls as
/// K grows once the loop is underdamped), by bisection in log K.
fn rise_threshold(g: &degrau_lti::TransferFunction, tr: f64) -> Result<f64, SheetError> {
    let rise = |k: f64| -> Result<f64, SheetError> { rise_full(&g.closed_loop(k)?) };
    // Underdamped from K = 0.00225 (ζ = 1): start just above it.
    let (mut lo, mut hi) = (0.003f64, 10.0f64);
    if rise(lo)? < tr || rise(hi)? > tr {
        return Err(SheetError::Missing("rise-time threshold"));
    }
    for _ in 0..80 {
        let mid = (lo * hi).sqrt();
        if rise(mid)? > tr {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(hi)
}
