//! Everything the app shows about one system, computed from the library and cached: the
//! transfer function (or why there is none), the exact step response sampled for the plot,
//! its `StepInfo` and the closed-form text. Recomputed only when the system or the metric
//! thresholds change. No drawing here.

use super::state::System;
use degrau_lti::expr::{OscillationForm, expression_in};
use degrau_lti::{LtiError, StepInfo, StepInfoOptions, StepResponse, TransferFunction};
use degrau_words::Lang;

/// Points of the plotted curve.
pub const CURVE_SAMPLES: usize = 2000;

/// Why the Design mode has no response to show, as a fact (its words, in the window's
/// language, are the app's: `crate::words::design`).
#[derive(Debug, Clone, PartialEq)]
pub enum NoResponse {
    /// The transfer function cannot be built (the lti crate's refusal).
    System(LtiError),
    /// The step amplitude is zero or not a finite number.
    Amplitude(f64),
    /// A value or an instant of the response is beyond double precision.
    BeyondDouble,
}

/// The derived view of one system.
#[derive(Debug, Clone)]
pub struct Analysis {
    pub system: System,
    pub options: StepInfoOptions,
    /// The transfer function, or why there is no response to show.
    pub tf: Result<TransferFunction, NoResponse>,
    pub response: Option<StepResponse>,
    pub info: Option<StepInfo>,
    /// (t, y) samples over [0, horizon].
    pub curve: Vec<[f64; 2]>,
    pub horizon: f64,
}

impl Analysis {
    /// Analyses `system` with the given metric thresholds.
    pub fn new(system: &System, options: StepInfoOptions) -> Self {
        let tf = system.transfer_function().map_err(NoResponse::System);
        let response = tf
            .as_ref()
            .ok()
            .and_then(|tf| StepResponse::new(tf, system.amplitude).ok());
        let mut out = Self {
            system: system.clone(),
            options,
            tf,
            response: None,
            info: None,
            curve: Vec::new(),
            horizon: 1.0,
        };
        if out.tf.is_ok() && response.is_none() {
            out.tf = Err(NoResponse::Amplitude(system.amplitude));
        }
        if let Some(r) = response {
            let horizon = r.auto_horizon();
            let (t, y) = r.sample_uniform(0.0, horizon, CURVE_SAMPLES);
            if !(horizon.is_finite() && horizon > 0.0) || t.iter().chain(&y).any(|v| !v.is_finite())
            {
                // Nothing that is not a number reaches the plot.
                out.tf = Err(NoResponse::BeyondDouble);
                return out;
            }
            out.horizon = horizon;
            out.curve = t.into_iter().zip(y).map(|(t, y)| [t, y]).collect();
            out.info = Some(StepInfo::of_response(&r, &options));
            out.response = Some(r);
        }
        out
    }

    /// y(t) in closed form, in `form` and in `lang`'s words and decimal separator; empty
    /// without a response (a few microseconds: written when drawn, in the language shown).
    pub fn expression(&self, form: OscillationForm, lang: Lang) -> String {
        self.response
            .as_ref()
            .map_or(String::new(), |r| expression_in(r, form, lang))
    }

    /// Whether this analysis is still current for `system` and `options`.
    pub fn is_for(&self, system: &System, options: &StepInfoOptions) -> bool {
        &self.system == system && &self.options == options
    }

    /// Re-analyses only when something changed.
    pub fn refresh(&mut self, system: &System, options: StepInfoOptions) {
        if !self.is_for(system, &options) {
            *self = Self::new(system, options);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_words::Localize;

    #[test]
    fn why_there_is_no_response_is_said_in_the_windows_language() {
        // A zero amplitude: the system exists, its response does not; the reason is a fact
        // the Portuguese window says in Portuguese, not an English string.
        let system = System {
            amplitude: 0.0,
            ..System::default()
        };
        let analysis = Analysis::new(&system, StepInfoOptions::default());
        let reason = analysis.tf.as_ref().expect_err("no response");
        assert_eq!(*reason, NoResponse::Amplitude(0.0));
        assert!(reason.text(Lang::Pt).starts_with("a amplitude do degrau"));
        assert!(reason.text(Lang::En).starts_with("the step amplitude"));
        // No poles: the lti crate's refusal, in its own words.
        let no_poles = NoResponse::System(LtiError::NoPoles);
        assert_eq!(no_poles.text(Lang::Pt), LtiError::NoPoles.text(Lang::Pt));
    }
}
