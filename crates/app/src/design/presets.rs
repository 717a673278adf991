//! The course notes' examples, one click away, some with a system to compare against.

use crate::words::design::Design as P;
use degrau_words::Lang;

use super::state::{GainMode, Root, System};

/// One example: a name (English, and the Portuguese), the system, and optionally a second
/// system to overlay (its name kept in English in the state file, see [`compare_name`]).
pub struct Preset {
    pub name: &'static str,
    pub name_pt: &'static str,
    pub system: System,
    pub compare: Option<(&'static str, System)>,
}

impl Preset {
    /// The example's name in `lang`.
    pub fn name(&self, lang: Lang) -> &'static str {
        lang.pick(self.name, self.name_pt)
    }
}

/// The names of the comparisons the presets bring, in both languages.
const COMPARE_NAMES: [(&str, &str); 2] = [
    ("without the zero", "sem o zero"),
    ("second-order approximation", "aproximação de segunda ordem"),
];

/// The name of a kept comparison in `lang`: a preset's comparison is translated, the
/// system kept by "Compare" (no name) is "kept", any other name is shown as it is.
pub fn compare_name(name: &str, lang: Lang) -> String {
    if name.is_empty() || name == "kept" {
        return P::KeptName.get(lang).to_string();
    }
    COMPARE_NAMES
        .iter()
        .find(|(en, _)| *en == name)
        .map_or_else(
            || name.to_string(),
            |(en, pt)| lang.pick(*en, *pt).to_string(),
        )
}

fn zpk(poles: Vec<Root>, zeros: Vec<Root>, gain: f64, amplitude: f64) -> System {
    System {
        poles,
        zeros,
        gain,
        gain_mode: GainMode::Zpk,
        delay: 0.0,
        amplitude,
    }
}

/// All presets, in the order of the notes.
pub fn presets() -> Vec<Preset> {
    let third = |zeros: Vec<Root>| {
        zpk(
            vec![Root::pair(-1.0, 2.0), Root::real(-5.0)],
            zeros,
            0.5,
            2.0,
        )
    };
    // Fifth order of the notes: 1/(2(s+10)(s²+14s+50)(s²+6s+18)), dominant poles −3 ± 3j.
    let fifth = zpk(
        vec![
            Root::pair(-3.0, 3.0),
            Root::pair(-7.0, 1.0),
            Root::real(-10.0),
        ],
        vec![],
        0.5,
        2.0,
    );
    // Its second-order approximation with the same static gain: k = 0.5·18/9000.
    let dominant = zpk(
        vec![Root::pair(-3.0, 3.0)],
        vec![],
        0.5 * 18.0 / 9000.0,
        2.0,
    );
    vec![
        Preset {
            name: "First order with dead time: 5 e^(−0.5s)/(s + 2), A = 2",
            name_pt: "Primeira ordem com tempo morto: 5 e^(−0,5s)/(s + 2), A = 2",
            system: System {
                delay: 0.5,
                ..zpk(vec![Root::real(-2.0)], vec![], 5.0, 2.0)
            },
            compare: None,
        },
        Preset {
            name: "Second order: 9/(s² + 2s + 9)",
            name_pt: "Segunda ordem: 9/(s² + 2s + 9)",
            system: zpk(vec![Root::pair(-1.0, 8f64.sqrt())], vec![], 9.0, 1.0),
            compare: None,
        },
        Preset {
            name: "Third order: poles −1 ± 2j, −5 (notes)",
            name_pt: "Terceira ordem: polos −1 ± 2j, −5 (apostila)",
            system: third(vec![]),
            compare: None,
        },
        Preset {
            name: "Third order with a zero at −0.5",
            name_pt: "Terceira ordem com um zero em −0,5",
            system: third(vec![Root::real(-0.5)]),
            compare: Some(("without the zero", third(vec![]))),
        },
        Preset {
            name: "Third order with a zero at −3",
            name_pt: "Terceira ordem com um zero em −3",
            system: third(vec![Root::real(-3.0)]),
            compare: Some(("without the zero", third(vec![]))),
        },
        Preset {
            name: "Third order with a zero at −10",
            name_pt: "Terceira ordem com um zero em −10",
            system: zpk(
                vec![Root::pair(-1.0, 2.0), Root::real(-5.0)],
                vec![Root::real(-10.0)],
                0.5,
                5.0,
            ),
            compare: None,
        },
        Preset {
            name: "Fifth order vs its dominant pair −3 ± 3j",
            name_pt: "Quinta ordem vs. seu par dominante −3 ± 3j",
            system: fifth,
            compare: Some(("second-order approximation", dominant)),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_builds_and_the_approximation_keeps_the_static_gain() {
        for p in presets() {
            let tf = p.system.transfer_function().unwrap();
            if let Some((_, b)) = &p.compare {
                let tb = b.transfer_function().unwrap();
                if p.name.starts_with("Fifth") {
                    assert!((tf.dc_gain() - tb.dc_gain()).abs() < 1e-15);
                    assert!((tf.den()[5] - 9000.0).abs() < 1e-9);
                }
            }
        }
    }
}
