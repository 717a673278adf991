//! The words of a step response, shared by the app's metrics table and `degrau step`: each
//! metric's name, unit and definition (with the thresholds in force), the cell text of a
//! value or of its absence, the response's behaviour and the system's stability.
//!
//! Definitions follow python-control's `step_info` (see `crate::metrics`).

use crate::tf::Stability;
use crate::{Behaviour, StepInfo, StepInfoOptions};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

/// A step metric of [`StepInfo`], in the order the table lists them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Metric {
    RiseTime,
    SettlingTime,
    Overshoot,
    Undershoot,
    Peak,
    PeakTime,
    SteadyState,
    SettlingMin,
    SettlingMax,
}

impl Metric {
    /// Every metric, in table order.
    pub const ALL: [Metric; 9] = [
        Metric::RiseTime,
        Metric::SettlingTime,
        Metric::Overshoot,
        Metric::Undershoot,
        Metric::Peak,
        Metric::PeakTime,
        Metric::SteadyState,
        Metric::SettlingMin,
        Metric::SettlingMax,
    ];

    /// The metric's name, capitalised as a table row.
    pub fn name(self, lang: Lang) -> &'static str {
        let (en, pt) = match self {
            Metric::RiseTime => ("Rise time", "Tempo de subida"),
            Metric::SettlingTime => ("Settling time", "Tempo de acomodação"),
            Metric::Overshoot => ("Overshoot", "Sobressinal"),
            Metric::Undershoot => ("Undershoot", "Subsinal"),
            Metric::Peak => ("Peak", "Valor de pico"),
            Metric::PeakTime => ("Peak time", "Tempo de pico"),
            Metric::SteadyState => ("Steady state", "Regime permanente"),
            Metric::SettlingMin => ("Settling min", "Mínimo após a subida"),
            Metric::SettlingMax => ("Settling max", "Máximo após a subida"),
        };
        lang.pick(en, pt)
    }

    /// The unit of the value ("s", "%" or none).
    pub fn unit(self) -> &'static str {
        match self {
            Metric::RiseTime | Metric::SettlingTime | Metric::PeakTime => "s",
            Metric::Overshoot | Metric::Undershoot => "%",
            _ => "",
        }
    }

    /// The value in `info`, if the response has it.
    pub fn value(self, info: &StepInfo) -> Option<f64> {
        match self {
            Metric::RiseTime => info.rise_time,
            Metric::SettlingTime => info.settling_time,
            Metric::Overshoot => info.overshoot,
            Metric::Undershoot => info.undershoot,
            Metric::Peak => info.peak,
            Metric::PeakTime => info.peak_time,
            Metric::SteadyState => info.steady_state,
            Metric::SettlingMin => info.settling_min,
            Metric::SettlingMax => info.settling_max,
        }
    }

    /// What the metric measures, with the thresholds in `options`.
    pub fn definition(self, options: &StepInfoOptions, lang: Lang) -> String {
        let (lo, hi) = options.rise_limits;
        let pct = |f: f64| lang.localize_number(&crate::number::sig(100.0 * f, 6));
        match self {
            Metric::RiseTime => match lang {
                Lang::En => format!(
                    "Rise time: from the first time y reaches {} % of the way from its initial \
                     to its final value to the first time it reaches {} %.",
                    pct(lo),
                    pct(hi)
                ),
                Lang::Pt => format!(
                    "Tempo de subida: do primeiro instante em que y percorre {} % do caminho do \
                     valor inicial ao final até o primeiro instante em que percorre {} %.",
                    pct(lo),
                    pct(hi)
                ),
            },
            Metric::SettlingTime => match lang {
                Lang::En => format!(
                    "Settling time: the first time after which |y − y_final| stays within {} % \
                     of |y_final − y_init| for ever (the shaded band), counted from the step.",
                    pct(options.settling_threshold)
                ),
                Lang::Pt => format!(
                    "Tempo de acomodação: o primeiro instante a partir do qual |y − y_final| \
                     fica para sempre dentro de {} % de |y_final − y_init| (a faixa sombreada), \
                     contado a partir do degrau.",
                    pct(options.settling_threshold)
                ),
            },
            Metric::Overshoot | Metric::Peak | Metric::PeakTime => lang
                .pick(
                    "Peak: the largest |y − y_init| and when it happens. Overshoot: how far the \
                     peak goes beyond the final value, in % of the change |y_final − y_init|. A \
                     response that never passes its final value has no peak time: it approaches \
                     its peak as t tends to ∞.",
                    "Valor de pico: o maior |y − y_init| e quando ocorre. Sobressinal: quanto o \
                     pico passa do valor final, em % da variação |y_final − y_init|. Uma \
                     resposta que nunca passa do valor final não tem tempo de pico: aproxima-se \
                     do pico quando t tende a ∞.",
                )
                .to_string(),
            Metric::Undershoot => lang
                .pick(
                    "Undershoot: how far y first moves the wrong way (opposite to its final \
                     change), in % of |y_final − y_init|: the mark of a right-half-plane zero.",
                    "Subsinal: quanto y se move primeiro no sentido contrário (oposto à variação \
                     final), em % de |y_final − y_init|: a marca de um zero no semiplano direito.",
                )
                .to_string(),
            Metric::SteadyState => lang
                .pick(
                    "Steady state: the final value y_final = A·G(0), when the response settles.",
                    "Regime permanente: o valor final y_final = A·G(0), quando a resposta se \
                     acomoda.",
                )
                .to_string(),
            Metric::SettlingMin => lang
                .pick(
                    "The smallest y once the response has risen (from the end of the rise on).",
                    "O menor y depois que a resposta subiu (do fim da subida em diante).",
                )
                .to_string(),
            Metric::SettlingMax => lang
                .pick(
                    "The largest y once the response has risen (the final value counts as the \
                     limit it approaches).",
                    "O maior y depois que a resposta subiu (o valor final conta como o limite \
                     de que ela se aproxima).",
                )
                .to_string(),
        }
    }

    /// The cell of this metric for a response: the value with its unit (5 significant
    /// digits, the language's decimal separator), or why it does not exist.
    pub fn cell(self, info: &StepInfo, lang: Lang) -> String {
        match self.value(info) {
            Some(v) if self.unit().is_empty() => lang.num(v, 5),
            Some(v) => format!("{} {}", lang.num(v, 5), self.unit()),
            None => Absence::of(self, info).text(lang),
        }
    }
}

impl Localize for Metric {
    fn text(&self, lang: Lang) -> String {
        self.name(lang).to_string()
    }
}

/// Why a metric has no value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Absence {
    /// The response does not settle, so no metric relative to its final value exists.
    DoesNotSettle(Behaviour),
    /// A monotone response: its peak is the final value, reached only as t → ∞.
    Monotone,
    /// None for another reason the metric's definition gives (e.g. no undershoot).
    None,
}

impl Absence {
    /// Why `metric` is missing from `info`.
    pub fn of(metric: Metric, info: &StepInfo) -> Self {
        if info.behaviour != Behaviour::Settles {
            Absence::DoesNotSettle(info.behaviour)
        } else if metric == Metric::PeakTime {
            Absence::Monotone
        } else {
            Absence::None
        }
    }
}

impl Localize for Absence {
    fn text(&self, lang: Lang) -> String {
        let none = lang.pick("none", "não há");
        match self {
            Absence::DoesNotSettle(b) => format!("{none}: {}", b.text(lang)),
            Absence::Monotone => format!(
                "{none}: {}",
                lang.pick(
                    "monotone, the peak is the final value (reached only as t tends to ∞)",
                    "monotônica, o pico é o valor final (atingido só quando t tende a ∞)",
                )
            ),
            Absence::None => none.to_string(),
        }
    }
}

impl Localize for Behaviour {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Behaviour::Settles => ("settles", "acomoda-se"),
            Behaviour::Integrating => (
                "does not settle: it ramps (integrator)",
                "não se acomoda: cresce em rampa (integrador)",
            ),
            Behaviour::Oscillating => (
                "does not settle: it oscillates forever",
                "não se acomoda: oscila para sempre",
            ),
            Behaviour::Unstable => (
                "does not settle: it grows without bound (unstable)",
                "não se acomoda: cresce sem limite (instável)",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

/// The stability of a system in a word or two, and with its reason: `[(en, pt); 2]`.
fn stability_words(s: Stability) -> [(&'static str, &'static str); 2] {
    match s {
        Stability::Stable => [
            ("stable", "estável"),
            (
                "stable (every pole in the left half plane)",
                "estável (todos os polos no semiplano esquerdo)",
            ),
        ],
        Stability::MarginallyStable => [
            ("marginally stable", "marginalmente estável"),
            (
                "marginally stable (poles on the imaginary axis, none to its right)",
                "marginalmente estável (polos no eixo imaginário, nenhum à sua direita)",
            ),
        ],
        Stability::Unstable => [
            ("unstable", "instável"),
            (
                "unstable (a pole in the right half plane)",
                "instável (um polo no semiplano direito)",
            ),
        ],
    }
}

/// The stability of a system, in a word or two.
pub fn stability(s: Stability, lang: Lang) -> &'static str {
    let [(en, pt), _] = stability_words(s);
    lang.pick(en, pt)
}

/// The stability of a system with the reason, as the CLI prints it.
pub fn stability_reason(s: Stability, lang: Lang) -> &'static str {
    let [_, (en, pt)] = stability_words(s);
    lang.pick(en, pt)
}

/// Where the pole lies that makes a static gain infinite: s = 0 for G(s), z = 1 for H(z).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IntegratorPole {
    S,
    Z,
}

/// A static gain that is not a number in words ("infinite: the system integrates (a pole
/// at s = 0)"), `None` for a finite one, which the caller writes with its own digits.
pub fn static_gain_words(value: f64, pole: IntegratorPole, lang: Lang) -> Option<String> {
    if value.is_finite() {
        return None;
    }
    let at = match pole {
        IntegratorPole::S => "s = 0",
        IntegratorPole::Z => "z = 1",
    };
    Some(if value.is_nan() {
        lang.pick(
            format!("undefined: the numerator and the denominator both vanish at {at}"),
            format!("indefinido: o numerador e o denominador se anulam em {at}"),
        )
    } else {
        let sign = match (value > 0.0, lang) {
            (true, _) => "",
            (false, Lang::En) => ", negative",
            (false, Lang::Pt) => ", negativo",
        };
        lang.pick(
            format!("infinite{sign}: the system integrates (a pole at {at})"),
            format!("infinito{sign}: o sistema é integrador (um polo em {at})"),
        )
    })
}

/// Every metric name, definition, absence, behaviour and stability, for the catalogue test.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let options = StepInfoOptions::default();
    let mut all = Vec::new();
    for m in Metric::ALL {
        all.push(Message::of(format!("Metric::{m:?}"), &m));
        all.push(Message {
            id: format!("Metric::{m:?}::definition"),
            en: m.definition(&options, Lang::En),
            pt: m.definition(&options, Lang::Pt),
        });
    }
    let behaviours = [
        Behaviour::Settles,
        Behaviour::Integrating,
        Behaviour::Oscillating,
        Behaviour::Unstable,
    ];
    for b in behaviours {
        all.push(Message::of(format!("Behaviour::{b:?}"), &b));
        all.push(Message::of(
            format!("Absence::DoesNotSettle({b:?})"),
            &Absence::DoesNotSettle(b),
        ));
    }
    all.push(Message::of("Absence::Monotone", &Absence::Monotone));
    all.push(Message::of("Absence::None", &Absence::None));
    for s in [
        Stability::Stable,
        Stability::MarginallyStable,
        Stability::Unstable,
    ] {
        all.push(Message::said(format!("stability::{s:?}"), |lang| {
            format!("{} / {}", stability(s, lang), stability_reason(s, lang))
        }));
    }
    for (value, pole) in [
        (f64::INFINITY, IntegratorPole::S),
        (f64::NEG_INFINITY, IntegratorPole::Z),
        (f64::NAN, IntegratorPole::Z),
    ] {
        let words = |lang| static_gain_words(value, pole, lang).unwrap_or_default();
        all.push(Message {
            id: format!("static_gain_words({value}, {pole:?})"),
            en: words(Lang::En),
            pt: words(Lang::Pt),
        });
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TransferFunction;

    fn info_of(num: &[f64], den: &[f64]) -> StepInfo {
        let tf = TransferFunction::from_coeffs(num, den).unwrap();
        let r = crate::StepResponse::new(&tf, 1.0).unwrap();
        StepInfo::of_response(&r, &StepInfoOptions::default())
    }

    #[test]
    fn cells_of_a_first_order_lag() {
        // 1/(s+1): rise 10–90 % = ln 9 = 2.1972 s, 2 % settling = ln 50 = 3.9120 s.
        let info = info_of(&[1.0], &[1.0, 1.0]);
        assert_eq!(Metric::RiseTime.cell(&info, Lang::En), "2.1972 s");
        assert_eq!(Metric::RiseTime.cell(&info, Lang::Pt), "2,1972 s");
        assert_eq!(Metric::SettlingTime.cell(&info, Lang::Pt), "3,912 s");
        assert!(
            Metric::PeakTime
                .cell(&info, Lang::Pt)
                .contains("monotônica")
        );
    }

    #[test]
    fn an_integrator_says_why_in_both_languages() {
        let info = info_of(&[1.0], &[1.0, 0.0]);
        assert!(Metric::RiseTime.cell(&info, Lang::En).contains("ramps"));
        assert!(Metric::RiseTime.cell(&info, Lang::Pt).contains("rampa"));
    }

    #[test]
    fn definitions_carry_the_thresholds() {
        let options = StepInfoOptions {
            rise_limits: (0.05, 0.95),
            ..Default::default()
        };
        let pt = Metric::RiseTime.definition(&options, Lang::Pt);
        assert!(pt.contains("5 %") && pt.contains("95 %"), "{pt}");
    }
}
