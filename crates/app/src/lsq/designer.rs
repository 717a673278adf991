//! The PRBS designer's state, with no egui in it: the test's settings (length, clock period,
//! levels, periods, sampling period), the model it is simulated on (a procest code and its
//! values, or the Design mode's G(s)) with noise, and the record it gives.
//!
//! - **The signal**: [`degrau_ident::lsq::prbs::Prbs`]. With one period, the shortest register
//!   whose period covers the length, cut to the length (idinput's non-periodic PRBS); with
//!   M ≥ 2 periods, the shortest register whose period covers length/M, repeated M whole
//!   times (idinput's `[P 1 M]`), so the record may be a little longer than asked.
//! - **The response**: a procest model through [`degrau_ident::lsq::prbs::simulate_record`]
//!   (exact, the input held between samples, at rest at Y0 with the input at its first
//!   level); the Design mode's G(s) through its exact ZOH discretisation
//!   ([`degrau_lti::discrete::c2d`]) driven by u − u(0), so it too starts at rest (at 0).
//! - **The noise**: white Gaussian, its standard deviation `noise_percent` % of the
//!   noise-free response's range (max − min), drawn from `seed` (reproducible).

use degrau_ident::lsq::prbs::{self, Prbs, PrbsError, Record};
use degrau_ident::model::{Model, ModelError, Param, Structure, Values};
use degrau_ident::random::Lcg;
use degrau_lti::TransferFunction;
use degrau_lti::discrete::{DiscreteError, c2d};

/// Where the simulated process comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ModelSource {
    /// A procest code and its values, typed here.
    #[default]
    Procest,
    /// The Design mode's G(s).
    Design,
}

/// What the student chose for the test.
#[derive(Debug, Clone, PartialEq)]
pub struct PrbsSettings {
    /// Samples asked for (N).
    pub samples: usize,
    /// Samples per bit (idinput's 1/B).
    pub clock: usize,
    pub low: f64,
    pub high: f64,
    /// Whole periods (1: one non-repeating stretch).
    pub periods: usize,
    /// Sampling period h (s).
    pub ts: f64,
    pub source: ModelSource,
    /// The procest code of the model (`P1D`, `P2DU`, …).
    pub code: String,
    pub values: Values,
    /// Noise standard deviation, % of the noise-free response's range.
    pub noise_percent: f64,
    pub seed: u64,
}

impl Default for PrbsSettings {
    fn default() -> Self {
        let mut values = Values::default();
        values.set(Param::Kp, 2.0);
        values.set(Param::Tp1, 20.0);
        values.set(Param::Td, 3.0);
        values.set(Param::Y0, 0.0);
        Self {
            samples: 600,
            clock: 4,
            low: 0.0,
            high: 1.0,
            periods: 1,
            ts: 1.0,
            source: ModelSource::Procest,
            code: "P1D".into(),
            values,
            noise_percent: 1.0,
            seed: 1,
        }
    }
}

/// What stops a design (`crate::words::lsq_app` says it).
#[derive(Debug, Clone, PartialEq)]
pub enum DesignError {
    Prbs(PrbsError),
    Model(ModelError),
    Discrete(DiscreteError),
    /// The Design mode has no valid G(s).
    NoDesignSystem,
    /// No periods, or a noise level that is negative or not finite.
    BadSettings,
}

/// A designed test: the signal, its record and the noise it carries.
#[derive(Debug, Clone, PartialEq)]
pub struct Designed {
    pub prbs: Prbs,
    pub record: Record,
    /// The noise's standard deviation (output units).
    pub noise_std: f64,
}

impl PrbsSettings {
    /// The model of the procest code and values.
    pub fn model(&self) -> Result<Model, ModelError> {
        Ok(Model::new(Structure::parse(&self.code)?, self.values))
    }

    /// The parameters the code's model has (Y0 always: where it rests).
    pub fn params(&self) -> Vec<Param> {
        let mut params = Structure::parse(&self.code)
            .map(|s| s.params())
            .unwrap_or_default();
        if !params.contains(&Param::Y0) {
            params.push(Param::Y0);
        }
        params
    }

    /// The register and the input signal.
    pub fn signal(&self) -> Result<(Prbs, Vec<f64>), DesignError> {
        if self.periods == 0 {
            return Err(DesignError::BadSettings);
        }
        let per_period = self.samples.div_ceil(self.periods);
        let prbs = Prbs::for_length(per_period, self.clock, self.low, self.high)
            .map_err(DesignError::Prbs)?;
        let u = if self.periods == 1 {
            prbs.signal(self.samples)
        } else {
            prbs.periodic(self.periods)
        }
        .map_err(DesignError::Prbs)?;
        Ok((prbs, u))
    }

    /// The designed test on the chosen model (`design`: the Design mode's G(s), if valid).
    pub fn design(&self, design: Option<&TransferFunction>) -> Result<Designed, DesignError> {
        if !(self.noise_percent.is_finite() && self.noise_percent >= 0.0) {
            return Err(DesignError::BadSettings);
        }
        let (prbs, u) = self.signal()?;
        let mut record = match self.source {
            ModelSource::Procest => {
                let model = self.model().map_err(DesignError::Model)?;
                prbs::simulate_record(&model, &u, self.ts, 0.0, self.seed)
                    .map_err(DesignError::Prbs)?
            }
            ModelSource::Design => {
                let tf = design.ok_or(DesignError::NoDesignSystem)?;
                let h = c2d(tf, self.ts).map_err(DesignError::Discrete)?;
                let du: Vec<f64> = u.iter().map(|v| v - u[0]).collect();
                // At rest at the first sample, 0 the output at rest at the lower level, as
                // a procest model's record ([`prbs::simulate_record`]).
                let low = u.iter().copied().fold(f64::INFINITY, f64::min);
                let rest = tf.dc_gain() * (u[0] - low);
                let rest = if rest.is_finite() { rest } else { 0.0 };
                Record {
                    time: (0..u.len()).map(|k| k as f64 * self.ts).collect(),
                    y: h.simulate(&du).into_iter().map(|y| y + rest).collect(),
                    u,
                }
            }
        };
        let (lo, hi) = record
            .y
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            });
        let range = if hi > lo { hi - lo } else { 0.0 };
        let noise_std = self.noise_percent / 100.0 * range;
        let mut rng = Lcg(self.seed);
        if noise_std > 0.0 {
            for v in &mut record.y {
                *v += noise_std * rng.gaussian();
            }
        }
        Ok(Designed {
            prbs,
            record,
            noise_std,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn periods_repeat_the_register_whole() {
        let s = PrbsSettings {
            samples: 200,
            clock: 2,
            periods: 2,
            ..PrbsSettings::default()
        };
        let (prbs, u) = s.signal().unwrap();
        // 100 samples per period at clock 2: 50 bits, so 6 bits (63 per period).
        assert_eq!(prbs.order, 6);
        assert_eq!(u.len(), 2 * 63 * 2);
        assert_eq!(u[..126], u[126..]);
    }

    #[test]
    fn a_procest_model_and_its_transfer_function_give_the_same_record() {
        // The same FOPTD, simulated exactly (procest) and through its exact ZOH c2d.
        let s = PrbsSettings {
            noise_percent: 0.0,
            ..PrbsSettings::default()
        };
        let procest = s.design(None).unwrap();
        let tf = s.model().unwrap().transfer_function().unwrap();
        let design = PrbsSettings {
            source: ModelSource::Design,
            ..s
        }
        .design(Some(&tf))
        .unwrap();
        for (a, b) in procest.record.y.iter().zip(&design.record.y) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }

    #[test]
    fn the_noise_is_the_share_of_the_range_asked() {
        let s = PrbsSettings {
            samples: 4000,
            noise_percent: 2.0,
            ..PrbsSettings::default()
        };
        let clean = PrbsSettings {
            noise_percent: 0.0,
            ..s.clone()
        }
        .design(None)
        .unwrap();
        let noisy = s.design(None).unwrap();
        let e: Vec<f64> = noisy
            .record
            .y
            .iter()
            .zip(&clean.record.y)
            .map(|(a, b)| a - b)
            .collect();
        let std = (e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64).sqrt();
        assert!((std / noisy.noise_std - 1.0).abs() < 0.05, "{std}");
        // Kp = 2 on a 0–1 PRBS: the range is a little under 2.
        assert!(noisy.noise_std > 0.02 && noisy.noise_std <= 0.04);
    }
}
