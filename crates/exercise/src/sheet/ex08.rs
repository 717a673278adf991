//! Exercise 8: the region of the s-plane where Mp ≤ 25 % and t_s ≤ 0.1 s, and the gain K
//! and compensator pole a of the loop K/(s + a) · 100/(s + 25) that place the closed-loop
//! poles at its corner; the exact response of the sheet's rounded design.

use degrau_lti::feedback::{SecondOrder, Spec};

use super::*;
use crate::model::{Controller, Mode, Part, Reading, Region, System};

pub fn exercise() -> Result<Exercise, SheetError> {
    let mp = 25.0;
    let ts = 0.1;
    let zeta = SecondOrder::damping_for_overshoot(mp)?;
    let sigma = 4.0 / ts;
    let wn = sigma / zeta;
    let a = 2.0 * sigma - 25.0;
    let k = (wn * wn - 25.0 * a) / 100.0;
    let plant = tf(&[100.0], &[1.0, 25.0])?;
    let open = |a: f64| tf(&[100.0], &[1.0, 25.0 + a, 25.0 * a]);
    let closed = |k: f64, a: f64| -> Result<_, SheetError> { Ok(open(a)?.closed_loop(k)?) };
    let ours = info(&closed(k, a)?)?;
    let ours_mp = need(ours.overshoot, "overshoot")?;
    let ours_ts = need(ours.settling_time, "settling time")?;
    // The sheet's design, from ζ rounded to 0.4.
    let (sheet_k, sheet_a) = (86.25, 55.0);
    let theirs = info(&closed(sheet_k, sheet_a)?)?;
    let sheet_mp = need(theirs.overshoot, "overshoot")?;
    let sheet_ts = need(theirs.settling_time, "settling time")?;
    // With a = 55, the gains whose exact response meets both specs.
    let runs = feasible_runs(
        &open(a)?,
        &[Spec::Overshoot(mp), Spec::Settling(ts)],
        0.1,
        200.0,
        400,
    );
    if runs.is_empty() {
        return Err(SheetError::Missing("gain range"));
    }
    let specs = vec![
        Reading {
            key: "overshoot".into(),
            label: label::overshoot(),
            value: mp,
            unit: Unit::Percent,
        },
        Reading {
            key: "settling".into(),
            label: label::settling(),
            value: ts,
            unit: Unit::Seconds,
        },
    ];
    let region_solution = vec![
        say::zeta_from_overshoot(mp, zeta),
        Text::by(|l| {
            l.pick(
                format!(
                    "Mp ≤ 25 % ⇒ ζ ≥ {} ⇒ θ = cos⁻¹ζ ≤ {}° (i)",
                    num(l, zeta),
                    num(l, zeta.acos().to_degrees())
                ),
                format!(
                    "Mp ≤ 25 % ⇒ ζ ≥ {} ⇒ θ = cos⁻¹ζ ≤ {}° (i)",
                    num(l, zeta),
                    num(l, zeta.acos().to_degrees())
                ),
            )
        }),
        Text::by(|l| {
            format!(
                "t_s = 4/(ζωn) ≤ {} s ⇒ σ = ζωn ≥ 4/{} = {} (ii)",
                num(l, ts),
                num(l, ts),
                num(l, sigma)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "The region: the wedge |arg(−s)| ≤ {}° left of the line Re(s) = −{}.",
                    num(l, zeta.acos().to_degrees()),
                    num(l, sigma)
                ),
                format!(
                    "A região: o setor |arg(−s)| ≤ {}° à esquerda da reta Re(s) = −{}.",
                    num(l, zeta.acos().to_degrees()),
                    num(l, sigma)
                ),
            )
        }),
    ];
    let note = Text::by(|l| {
        l.pick(
            format!(
                "The sheet rounds ζ = {} to 0.4, so ωn = 100 rad/s and K = 86.25: the poles then sit at ζ = 0.4, outside the region, and the exact closed-loop response overshoots by Mp = {} %, above the 25 % asked (t_s = {} s). With ζ = {} unrounded, ωn = {} rad/s and K = {} give Mp = {} % exactly.",
                num(l, zeta), num(l, sheet_mp), num(l, sheet_ts), num(l, zeta), num(l, wn), num(l, k), num(l, ours_mp)
            ),
            format!(
                "A folha arredonda ζ = {} para 0,4, logo ωn = 100 rad/s e K = 86,25: os pólos ficam em ζ = 0,4, fora da região, e a resposta exata em malha fechada tem Mp = {} %, acima dos 25 % pedidos (t_s = {} s). Com ζ = {} sem arredondar, ωn = {} rad/s e K = {} dão Mp = {} % exatamente.",
                num(l, zeta), num(l, sheet_mp), num(l, sheet_ts), num(l, zeta), num(l, wn), num(l, k), num(l, ours_mp)
            ),
        )
    });
    let mut k_q = Question::new(
        "8b",
        "K",
        Text::new("Compensator gain K", "Ganho K do compensador"),
        number(Unit::None, v(k, Phrase::Formula), vec![]),
    )
    .sheet("86,25");
    k_q.difference = Some(note);
    let design_solution = vec![
        Text::new(
            "Closed loop: Y(s)/R(s) = 100K/(s² + (25 + a)s + 25a + 100K) (i)",
            "Malha fechada: Y(s)/R(s) = 100K/(s² + (25 + a)s + 25a + 100K) (i)",
        ),
        say::zeta_from_overshoot(mp, zeta),
        Text::by(|l| {
            format!(
                "t_s = 4/(ζωn) = {} ⇒ ωn = 4/({}·{}) = {} rad/s",
                num(l, ts),
                num(l, zeta),
                num(l, ts),
                num(l, wn)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Comparing (i) with the canonical form: 25 + a = 2ζωn ⇒ a = 2·{} − 25 = {}",
                    num(l, sigma),
                    num(l, a)
                ),
                format!(
                    "Comparando (i) com a forma canónica: 25 + a = 2ζωn ⇒ a = 2·{} − 25 = {}",
                    num(l, sigma),
                    num(l, a)
                ),
            )
        }),
        Text::by(|l| {
            format!(
                "25a + 100K = ωn² ⇒ K = (ωn² − 25a)/100 = ({} − {})/100 = {}",
                num(l, wn * wn),
                num(l, 25.0 * a),
                num(l, k)
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "Exact closed-loop response with K = {}, a = {}: Mp = {} %, t_s (2 %) = {} s; the specs hold.",
                    num(l, k), num(l, a), num(l, ours_mp), num(l, ours_ts)
                ),
                format!(
                    "Resposta exata em malha fechada com K = {}, a = {}: Mp = {} %, t_s (2 %) = {} s; as especificações cumprem-se.",
                    num(l, k), num(l, a), num(l, ours_mp), num(l, ours_ts)
                ),
            )
        }),
        Text::by(|l| {
            let runs: Vec<String> = runs
                .iter()
                .map(|(lo, hi)| format!("{} ≤ K ≤ {}", num(l, *lo), num(l, *hi)))
                .collect();
            let runs = runs.join(l.pick(" or ", " ou "));
            l.pick(
                format!(
                    "Root locus of K·100/((s + 25)(s + {})): the branches meet at s = −40 and rise along Re(s) = −40 (σ = 40 for every K past the breakaway). On the exact response, both specs hold for {runs}: not one interval, because the exact 2 % settling time falls as K grows and jumps up each time one more peak of the response rises out of the band, while 4/σ stays at 0.1 s.",
                    num(l, a)
                ),
                format!(
                    "Lugar das raízes de K·100/((s + 25)(s + {})): os ramos encontram-se em s = −40 e sobem pela reta Re(s) = −40 (σ = 40 para todo o K depois do ponto de saída). Na resposta exata, as duas especificações cumprem-se para {runs}: não um só intervalo, porque o tempo de estabelecimento exato (2 %) diminui quando K cresce e sobe aos saltos cada vez que mais um pico da resposta sai da faixa, enquanto 4/σ fica em 0,1 s.",
                    num(l, a)
                ),
            )
        }),
        Text::by(|l| {
            l.pick(
                format!(
                    "The sheet's K = 86.25 (ζ rounded to 0.4) gives Mp = {} % > 25 %.",
                    num(l, sheet_mp)
                ),
                format!(
                    "O K = 86,25 da folha (ζ arredondado a 0,4) dá Mp = {} % > 25 %.",
                    num(l, sheet_mp)
                ),
            )
        }),
    ];
    Ok(Exercise {
        id: "8".into(),
        statement: Text::new(
            "Consider the unity-feedback system of the figure. Find the gain K and the location of the compensator's pole so that the closed loop's unit-step response has a maximum overshoot Mp ≤ 25 % and a settling time t_s ≤ 0.1 s.",
            "Considere o sistema de realimentação unitária apresentado na figura seguinte. Pretende-se obter o ganho K e a localização do pólo do compensador de forma que a resposta em malha fechada do sistema a uma entrada em degrau unitário possua uma sobreelongação máxima de M_p ≤ 25 % e um tempo de estabelecimento de t_s ≤ 0,1 s.",
        ),
        parts: vec![
            Part {
                id: "8a".into(),
                statement: Text::new(
                    "a) Sketch the region of the s-plane where both specs hold.",
                    "a) Esboce a região do plano-s onde ambas as especificações são satisfeitas.",
                ),
                system: System::Specs {
                    specs,
                    solution: closed(k, a)?,
                },
                mode: Mode::DesignPlane,
                questions: vec![
                    Question::new(
                        "8a",
                        "region",
                        Text::new(
                            "Region of the s-plane (ζ ≥ …; σ ≥ …)",
                            "Região do plano-s (ζ ≥ …; σ ≥ …)",
                        ),
                        Expected::Region(Region {
                            zeta_min: zeta,
                            sigma_min: sigma,
                        }),
                    )
                    .sheet("ζ ≥ 0,4; σ ≥ 40"),
                ],
                solution: region_solution,
            },
            Part {
                id: "8b".into(),
                statement: Text::new(
                    "b) Find (K, a) so that the specs hold. Loop: the compensator K/(s + a) in series with G(s) = 100/(s + 25), unity feedback.",
                    "b) Determine os valores de (K, a) do sistema de forma que as especificações sejam cumpridas. Malha: o compensador K/(s + a) em série com G(s) = 100/(s + 25), realimentação unitária.",
                ),
                system: System::Loop {
                    plant,
                    controller: Controller::Pole { a },
                    gain: k,
                },
                mode: Mode::DesignLoop,
                questions: vec![
                    Question::new(
                        "8b",
                        "a",
                        Text::new("Compensator pole a", "Pólo do compensador a"),
                        number(Unit::PerSecond, v(a, Phrase::Formula), vec![]),
                    )
                    .sheet("55"),
                    k_q,
                ],
                solution: design_solution,
            },
        ],
    })
}
