//! The sampling and amplitude advisor, with no egui in it: the course notes' rules for the
//! sampling period ([`degrau_ident::diagnose::test_causes::sampling_checks`]: h < 0.1·τmax,
//! 0.2 < h/θ < 1, 0.01 < h/τ < 0.05, t_s/15 < h < t_s/6) with the record's own h and the time
//! scales of the Identify mode's model (its fit, or the guess read off the curve before a
//! fit), and the amplitude rule: the step's effect over the noise above 6.
//!
//! - **The step's effect**: |K·Δu|, K the model's static gain and Δu the record's largest
//!   input change (none for a model without a finite static gain, an integrator).
//! - **The noise**: the standard deviation of a fit's residuals (robust), or before a fit
//!   the output's white noise read from its first differences
//!   ([`degrau_ident::fit::rest::difference_noise`], robust to the steps themselves).

use degrau_ident::diagnose::test_causes::RuleCheck;
use degrau_ident::diagnose::test_causes::{TimeScales, sampling_checks};
use degrau_ident::fit::FitData;
use degrau_ident::fit::rest::difference_noise;
use degrau_ident::model::Model;
use degrau_ident::stats::robust_scale;

/// The notes' lower bound on the step's effect over the noise.
pub const AMPLITUDE_RATIO: f64 = 6.0;

/// The step's effect and the noise it is read against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Amplitude {
    /// |K·Δu| (output units).
    pub effect: f64,
    /// The noise's standard deviation (output units).
    pub noise: f64,
}

impl Amplitude {
    /// effect/noise (infinite without noise).
    pub fn ratio(&self) -> f64 {
        if self.noise > 0.0 {
            self.effect / self.noise
        } else {
            f64::INFINITY
        }
    }

    pub fn holds(&self) -> bool {
        self.ratio() > AMPLITUDE_RATIO
    }
}

/// The rules on one record and model.
#[derive(Debug, Clone, PartialEq)]
pub struct Advice {
    pub model: Model,
    /// The model is a fit (not the guess).
    pub fitted: bool,
    /// The record's sampling period h (s).
    pub h: f64,
    pub scales: TimeScales,
    pub checks: Vec<RuleCheck>,
    pub amplitude: Option<Amplitude>,
}

impl Advice {
    /// The rules on the samples of `data` with `model`'s time scales.
    pub fn new(data: &FitData, model: Model, fitted: bool) -> Self {
        let h = data.sampling_period();
        let scales = TimeScales::of(&model);
        let gain = model
            .transfer_function()
            .map(|tf| tf.dc_gain())
            .unwrap_or(f64::NAN);
        let du = data.input.largest_change().map_or(0.0, |c| c.du);
        let amplitude = gain.is_finite().then(|| Amplitude {
            effect: (gain * du).abs(),
            noise: noise(data, &model, fitted),
        });
        Self {
            checks: sampling_checks(h, &scales),
            model,
            fitted,
            h,
            scales,
            amplitude,
        }
    }
}

/// The noise's standard deviation: of a fit's residuals (robust: 1.4826·MAD), or from the
/// first differences before a fit. On a record whose input changes every few samples (a
/// PRBS) the differences hold the response itself and read it as noise (a PRBS with 1 %
/// noise was called "too small for the noise", 3.77).
fn noise(data: &FitData, model: &Model, fitted: bool) -> f64 {
    let residuals = fitted
        .then(|| model.simulate(&data.input, &data.times).ok())
        .flatten()
        .map(|yhat| {
            data.y
                .iter()
                .zip(&yhat)
                .map(|(y, m)| y - m)
                .collect::<Vec<f64>>()
        });
    match residuals {
        Some(r) if !r.is_empty() => robust_scale(&r),
        _ => difference_noise(&data.y),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_ident::model::excitation::Excitation;
    use degrau_ident::model::{Param, Structure, Values};

    /// A PRBS (clocked every sample) through a fast first order, with 1 % noise: the first
    /// differences hold the response and read it as noise ("too small", issue 23, item 13);
    /// the fit's residuals read the noise itself.
    #[test]
    fn a_prbs_is_judged_on_its_fits_residuals() {
        let prbs = degrau_ident::lsq::prbs::Prbs::for_length(255, 1, 0.0, 1.0).unwrap();
        let u = prbs.signal(255).unwrap();
        let mut v = Values::default();
        v.set(Param::Kp, 2.0);
        v.set(Param::Tp1, 2.0);
        v.set(Param::Y0, 0.0);
        let model = Model::new(Structure::parse("P1").unwrap(), v);
        let rec = degrau_ident::lsq::prbs::simulate_record(&model, &u, 1.0, 0.02, 5).unwrap();
        let input = Excitation::measured(
            &rec.time,
            &rec.u,
            None,
            degrau_ident::model::excitation::Hold::Zoh,
        )
        .unwrap();
        let data = FitData {
            times: rec.time,
            y: rec.y,
            input,
        };
        let guessed = Advice::new(&data, model, false).amplitude.unwrap();
        let fitted = Advice::new(&data, model, true).amplitude.unwrap();
        assert!(!guessed.holds(), "{guessed:?}");
        assert!(fitted.holds(), "{fitted:?}");
        assert!((fitted.noise - 0.02).abs() < 0.005, "{fitted:?}");
    }

    #[test]
    fn a_foptd_sampled_at_a_second_of_its_twenty_second_time_constant() {
        let mut v = Values::default();
        v.set(Param::Kp, 2.0);
        v.set(Param::Tp1, 20.0);
        v.set(Param::Td, 3.0);
        v.set(Param::Y0, 50.0);
        let model = Model::new(Structure::parse("P1D").unwrap(), v);
        let times: Vec<f64> = (0..200).map(f64::from).collect();
        let input = Excitation::step(10.0, 5.0);
        let mut y = model.simulate(&input, &times).unwrap();
        // ±0.1 alternating: first differences of ±0.2 (σ from the MAD: 0.2/√2·1.4826…).
        for (k, v) in y.iter_mut().enumerate() {
            *v += if k % 2 == 0 { 0.1 } else { -0.1 };
        }
        let data = FitData { times, y, input };
        let a = Advice::new(&data, model, true);
        assert_eq!(a.h, 1.0);
        // h/τ = 0.05 (on the bound of 0.01–0.05), h/θ = 1/3 (within 0.2–1).
        let ratio = |rule| a.checks.iter().find(|c| c.rule == rule).unwrap().value;
        use degrau_ident::diagnose::test_causes::SamplingRule as R;
        assert!((ratio(R::TimeConstantRatio) - 0.05).abs() < 1e-15);
        assert!((ratio(R::DeadTimeRatio) - 1.0 / 3.0).abs() < 1e-15);
        let amp = a.amplitude.unwrap();
        assert!((amp.effect - 10.0).abs() < 1e-12);
        assert!(amp.holds(), "{amp:?}");
    }
}
