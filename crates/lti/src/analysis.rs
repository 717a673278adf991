//! One analysis of a step response: its metrics ([`StepInfo`]) and the time window that
//! shows them ([`StepAnalysis::horizon`]), the metrics computed once.
//!
//! The window of a settling response is 1.5 × its settling time (1.2 × its peak time if
//! later, and never shorter than its transient), so it depends on the metrics; the metrics
//! of an undamped oscillation depend on the window. Both directions meet here, above
//! [`super::response`] (which knows neither the metrics nor this module) and
//! [`super::metrics`] (which asks the response only for the window of a response that does
//! not settle).

use super::metrics::{StepInfo, StepInfoOptions};
use super::response::{Behaviour, StepResponse};

/// A step response's metrics and its plotting window.
#[derive(Debug, Clone, PartialEq)]
pub struct StepAnalysis {
    /// The metrics with the analysis's thresholds; instants in seconds from the step.
    pub info: StepInfo,
    /// The time window (seconds from the step, dead time included) that shows the whole
    /// transient and every instant of `info`: for a settling response
    /// max(1.5 × settling time, 1.2 × peak time, 1.5 × the transient's 2 % envelope time),
    /// counted from the end of the dead time; for one that does not settle, the stable
    /// part's transient and a few periods of the sustained oscillation or e-foldings of
    /// the growth.
    pub horizon: f64,
}

/// The metrics of `response` with `options` and the window that shows them, the metrics
/// computed once (the window is taken from them).
pub fn analyse(response: &StepResponse, options: &StepInfoOptions) -> StepAnalysis {
    let rational = StepInfo::of_rational(response, options);
    let horizon = response.delay() + response.rational_horizon(landmarks(&rational));
    StepAnalysis {
        info: rational.delayed(response.delay()),
        horizon,
    }
}

/// The latest instant (τ, from the end of the dead time) the metrics of a settling
/// response need shown: 1.5 × its settling time, 1.2 × its peak time if later; 0 for a
/// response that does not settle.
fn landmarks(rational: &StepInfo) -> f64 {
    if rational.behaviour != Behaviour::Settles {
        return 0.0;
    }
    let settle = rational.settling_time.unwrap_or(0.0);
    let peak = rational.peak_time.unwrap_or(0.0);
    (1.5 * settle).max(1.2 * peak)
}

impl StepResponse {
    /// The window [`analyse`] gives with the default thresholds (2 % band, 10–90 % rise):
    /// seconds from the step, dead time included. It computes the metrics; a caller that
    /// also needs them calls [`analyse`] instead.
    pub fn auto_horizon(&self) -> f64 {
        analyse(self, &StepInfoOptions::default()).horizon
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{C64, TransferFunction};

    fn response(poles: &[C64], k: f64, delay: f64) -> StepResponse {
        let g = TransferFunction::from_zpk(&[], poles, k)
            .and_then(|g| g.with_delay(delay))
            .unwrap();
        StepResponse::new(&g, 1.0).unwrap()
    }

    #[test]
    fn horizon_covers_the_transient() {
        // 5/(s+5): 2 % settling time ln(50)/5.
        let r = response(&[C64::new(-5.0, 0.0)], 5.0, 0.0);
        let h = r.auto_horizon();
        let settle = (50f64).ln() / 5.0;
        assert!((h - 1.5 * settle).abs() < 1e-9, "{h}");
    }

    #[test]
    fn one_analysis_gives_the_metrics_and_their_window() {
        // 5/(s+5) after 0.7 s: with a 1 % band the settling time is 0.7 + ln(100)/5, and
        // the window 0.7 + 1.5·ln(100)/5 shows it (the transient's own window, 1.5 × the
        // time its envelope needs to fall to 2 % of the response's size 2, is shorter).
        let r = response(&[C64::new(-5.0, 0.0)], 5.0, 0.7);
        let options = StepInfoOptions {
            settling_threshold: 0.01,
            ..Default::default()
        };
        let a = analyse(&r, &options);
        assert_eq!(a.info, StepInfo::of_response(&r, &options));
        let settle = 100f64.ln() / 5.0;
        assert!((a.info.settling_time.unwrap() - (0.7 + settle)).abs() < 1e-14);
        assert!(
            (a.horizon - (0.7 + 1.5 * settle)).abs() < 1e-12,
            "{}",
            a.horizon
        );
        // With the default thresholds, the window auto_horizon gives.
        let a = analyse(&r, &StepInfoOptions::default());
        assert_eq!(a.horizon, r.auto_horizon());
        assert!((a.horizon - (0.7 + 1.5 * 50f64.ln() / 5.0)).abs() < 1e-12);
    }

    #[test]
    fn a_lightly_damped_pair_shows_its_peak_and_settling() {
        // ωn = 3, ζ = 0.1: the window is 1.5 × the settling time, past the peak.
        let (zeta, wn) = (0.1f64, 3.0f64);
        let wd = wn * (1.0 - zeta * zeta).sqrt();
        let poles = [C64::new(-zeta * wn, wd), C64::new(-zeta * wn, -wd)];
        let r = response(&poles, wn * wn, 0.0);
        let a = analyse(&r, &StepInfoOptions::default());
        let ts = a.info.settling_time.unwrap();
        assert!((a.horizon - 1.5 * ts).abs() < 1e-12 * ts);
        assert!(a.info.peak_time.unwrap() < a.horizon);
    }

    #[test]
    fn an_undamped_oscillation_gets_periods_not_metrics() {
        // 1/(s² + 1): 4 periods of 2π s, and its peak (2 at π) inside them.
        let r = response(&[C64::new(0.0, 1.0), C64::new(0.0, -1.0)], 1.0, 0.0);
        let a = analyse(&r, &StepInfoOptions::default());
        assert!((a.horizon - 4.0 * std::f64::consts::TAU).abs() < 1e-12);
        assert!((a.info.peak_time.unwrap() - std::f64::consts::PI).abs() < 1e-9);
        assert_eq!(a.info.settling_time, None);
    }
}
