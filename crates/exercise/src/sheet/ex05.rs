//! Exercise 5: from a pair of specs to ζ, ωn, the poles and the canonical G(s).

use degrau_lti::feedback::{SecondOrder, SpecPair};

use super::*;
use crate::model::{Mode, Part, Reading, System, TfAnswer};

pub fn exercise() -> Result<Exercise, SheetError> {
    Ok(Exercise {
        id: "5".into(),
        statement: Text::new(
            "Consider the canonical second-order system G(s) = ωn²/(s² + 2ζωn s + ωn²). For each pair of specs below, locate the system's poles and give its transfer function G(s).",
            "Considere a seguinte forma canónica de um sistema de segunda ordem: G(s) = ωn²/(s² + 2ζωn s + ωn²). Para cada par de especificações abaixo indicadas, localize os pólos do sistema e indique a respectiva função de transferência G(s).",
        ),
        parts: vec![
            part(
                "5a",
                SpecPair::OvershootSettling {
                    overshoot: 30.0,
                    settling: 0.05,
                },
                [
                    "0,358",
                    "223,46 rad/s",
                    "-80 ± j208,7",
                    "49934/(s^2 + 160s + 49934)",
                ],
            )?,
            part(
                "5b",
                SpecPair::OvershootPeak {
                    overshoot: 17.0,
                    peak: 0.5,
                },
                [
                    "0,491",
                    "7,21 rad/s",
                    "-3,54 ± j6,28",
                    "52/(s^2 + 7,1s + 52)",
                ],
            )?,
            part(
                "5c",
                SpecPair::SettlingPeak {
                    settling: 7.0,
                    peak: 3.0,
                },
                [
                    "0,479",
                    "1,193 rad/s",
                    "-0,57 ± j1,05",
                    "1,423/(s^2 + 1,143s + 1,423)",
                ],
            )?,
        ],
    })
}

fn part(id: &str, pair: SpecPair, printed: [&str; 4]) -> Result<Part, SheetError> {
    let design = SecondOrder::from_specs(pair)?;
    let g = canonical(design)?;
    let exact = info(&g)?;
    let ts_exact = need(exact.settling_time, "settling time")?;
    let tp_exact = need(exact.peak_time, "peak time")?;
    let mp_exact = need(exact.overshoot, "overshoot")?;
    let reading = |key: &str, label: Text, value: f64, unit: Unit| Reading {
        key: key.into(),
        label,
        value,
        unit,
    };
    // The specs, and the ωn for which the exact response meets a settling spec exactly.
    let (specs, wn_exact) = match pair {
        SpecPair::OvershootSettling {
            overshoot,
            settling,
        } => {
            // t_s·ωn depends on ζ only: ωn = (t_s at ωn = 1)/t_s.
            let unit_wn = canonical(SecondOrder {
                zeta: design.zeta,
                wn: 1.0,
            })?;
            let t1 = need(info(&unit_wn)?.settling_time, "settling time")?;
            (
                vec![
                    reading("overshoot", label::overshoot(), overshoot, Unit::Percent),
                    reading("settling", label::settling(), settling, Unit::Seconds),
                ],
                Some(t1 / settling),
            )
        }
        SpecPair::OvershootPeak { overshoot, peak } => (
            vec![
                reading("overshoot", label::overshoot(), overshoot, Unit::Percent),
                reading("peak_time", label::peak_time(), peak, Unit::Seconds),
            ],
            None,
        ),
        SpecPair::SettlingPeak { settling, peak } => (
            vec![
                reading("settling", label::settling(), settling, Unit::Seconds),
                reading("peak_time", label::peak_time(), peak, Unit::Seconds),
            ],
            None,
        ),
    };
    let also_wn: Vec<Value> = wn_exact.map(|w| v(w, Phrase::Exact)).into_iter().collect();
    let questions = vec![
        Question::new(
            id,
            "zeta",
            label::zeta(),
            number(Unit::None, v(design.zeta, Phrase::Formula), vec![]),
        )
        .sheet(printed[0]),
        Question::new(
            id,
            "wn",
            label::wn(),
            number(Unit::RadPerSecond, v(design.wn, Phrase::Formula), also_wn),
        )
        .sheet(printed[1]),
        Question::new(
            id,
            "poles",
            label::poles(),
            Expected::Roots(design.poles().to_vec()),
        )
        .sheet(printed[2]),
        Question::new(
            id,
            "G",
            label::transfer_function(),
            Expected::TransferFunction(TfAnswer::Fixed(g.clone())),
        )
        .sheet(printed[3]),
    ];
    let mut solution = Vec::new();
    match pair {
        SpecPair::OvershootSettling {
            overshoot,
            settling,
        } => {
            solution.push(say::zeta_from_overshoot(overshoot, design.zeta));
            solution.push(Text::by(|l| {
                format!(
                    "t_s = 4/(ζωn) ⇒ ωn = 4/({}·{}) = {} rad/s",
                    num(l, design.zeta),
                    num(l, settling),
                    num(l, design.wn)
                )
            }));
        }
        SpecPair::OvershootPeak { overshoot, peak } => {
            solution.push(say::zeta_from_overshoot(overshoot, design.zeta));
            solution.push(Text::by(|l| {
                l.pick(
                    format!(
                        "t_p = π/(ωn√(1 − ζ²)) ⇒ ωn = π/({}·√(1 − {}²)) = {} rad/s (the sheet prints 4 for π in this line, but its result uses π)",
                        num(l, peak), num(l, design.zeta), num(l, design.wn)
                    ),
                    format!(
                        "t_p = π/(ωn√(1 − ζ²)) ⇒ ωn = π/({}·√(1 − {}²)) = {} rad/s (a folha imprime 4 em vez de π nesta linha, mas o resultado usa π)",
                        num(l, peak), num(l, design.zeta), num(l, design.wn)
                    ),
                )
            }));
        }
        SpecPair::SettlingPeak { settling, peak } => {
            solution.push(Text::by(|l| {
                format!(
                    "σ = ζωn = 4/t_s = 4/{} = {}; ωd = ωn√(1 − ζ²) = π/t_p = π/{} = {}",
                    num(l, settling),
                    num(l, design.sigma()),
                    num(l, peak),
                    num(l, design.wd())
                )
            }));
            solution.push(Text::by(|l| {
                format!(
                    "ωn = √(σ² + ωd²) = {} rad/s; ζ = σ/ωn = {}",
                    num(l, design.wn),
                    num(l, design.zeta)
                )
            }));
        }
    }
    solution.push(Text::by(|l| {
        format!(
            "p₁,₂ = −ζωn ± jωn√(1 − ζ²) = {} ± j{}",
            num(l, -design.sigma()),
            num(l, design.wd())
        )
    }));
    solution.push(Text::by(|l| {
        format!(
            "G(s) = ωn²/(s² + 2ζωn s + ωn²) = {}",
            crate::text::tf(l, &g)
        )
    }));
    solution.push(Text::by(|l| {
        l.pick(
            format!(
                "Exact step response of this G(s): Mp = {} %, t_p = {} s, t_s (2 %) = {} s (the formula 4/(ζωn), from the envelope, gives {} s).",
                num(l, mp_exact), num(l, tp_exact), num(l, ts_exact), num(l, design.settling_time())
            ),
            format!(
                "Resposta ao degrau exata desta G(s): Mp = {} %, t_p = {} s, t_s (2 %) = {} s (a fórmula 4/(ζωn), da envolvente, dá {} s).",
                num(l, mp_exact), num(l, tp_exact), num(l, ts_exact), num(l, design.settling_time())
            ),
        )
    }));
    if let Some(w) = wn_exact {
        solution.push(Text::by(|l| {
            l.pick(
                format!("The exact response settles (2 %) in exactly the spec's time with ωn = {} rad/s (also accepted).", num(l, w)),
                format!("A resposta exata estabelece-se (2 %) exatamente no tempo especificado com ωn = {} rad/s (também aceite).", num(l, w)),
            )
        }));
    }
    Ok(Part {
        id: id.into(),
        statement: Text::by(|l| {
            specs
                .iter()
                .map(|r| {
                    format!(
                        "{} = {} {}",
                        r.label.get(l),
                        num(l, r.value),
                        r.unit.symbol()
                    )
                })
                .collect::<Vec<_>>()
                .join("; ")
        }),
        system: System::Specs { specs, solution: g },
        mode: Mode::DesignPlane,
        questions,
        solution,
    })
}
