//! What the Tune mode shows, computed from its settings: the loop's setpoint and load
//! responses with their metrics (the dead time exact, no Padé). A few milliseconds: done on
//! the UI thread when the model or the controller changed, never every frame.

use degrau_lti::control::{ControllerError, DelayLoopError, LoopMetrics, LoopResponse, tuned_loop};

use super::model::{ModelProblem, ProcessSettings};
use super::session::ControllerSettings;

/// How far a response that does not settle is drawn (a unit step's output units).
const GROWTH_SHOWN: f64 = 100.0;
/// The most points a curve is drawn with.
const MAX_POINTS: usize = 4000;
/// How far past the later settling time the curves are drawn (a factor).
const PAST_SETTLING: f64 = 1.6;

/// One response as drawn and measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
    /// (t, y) to draw, up to [`Response::shown_until`].
    pub curve: Vec<[f64; 2]>,
    pub metrics: LoopMetrics,
    /// Whether the loop settled within the time computed.
    pub settled: bool,
    /// Where the curve ends (s).
    pub shown_until: f64,
}

/// The loop's two responses.
#[derive(Debug, Clone, PartialEq)]
pub struct LoopView {
    pub setpoint: Response,
    pub load: Response,
    /// The maximum sensitivity Ms (none: the loop is not stable).
    pub ms: Option<f64>,
}

/// Why there are no responses.
#[derive(Debug, Clone, PartialEq)]
pub enum LoopTrouble {
    Model(ModelProblem),
    Controller(ControllerError),
    Loop(DelayLoopError),
}

/// The loop of `controller` around `model`, both responses measured.
pub fn compute(
    model: &ProcessSettings,
    controller: &ControllerSettings,
) -> Result<LoopView, LoopTrouble> {
    model.check().map_err(LoopTrouble::Model)?;
    let plant = model
        .transfer_function()
        .ok_or(LoopTrouble::Model(ModelProblem::Gain(model.k)))?;
    let c = controller.controller().map_err(LoopTrouble::Controller)?;
    let tuned = tuned_loop(&plant, &c).map_err(LoopTrouble::Loop)?;
    let (ms, ml) = (tuned.setpoint_metrics, tuned.load_metrics);
    // Both plots on one time scale: until a while after the later one settled.
    let settled = [ms.settling_time, ml.settling_time];
    let until = match settled {
        [Some(a), Some(b)] => (PAST_SETTLING * a.max(b)).max(model.theta * 4.0),
        _ => f64::INFINITY,
    };
    Ok(LoopView {
        setpoint: response(&tuned.setpoint, ms, until),
        load: response(&tuned.load, ml, until),
        ms: tuned.ms,
    })
}

fn response(r: &LoopResponse, metrics: LoopMetrics, until: f64) -> Response {
    let until = until.min(r.end());
    let (t, y) = r.samples();
    // A loop that does not settle is drawn until it leaves ±GROWTH_SHOWN: enough to see it
    // grow, and the axis stays readable.
    let bound = if r.settled {
        f64::INFINITY
    } else {
        GROWTH_SHOWN
    };
    let kept: Vec<[f64; 2]> = t
        .into_iter()
        .zip(y)
        .take_while(|(t, y)| *t <= until && y.abs() <= bound)
        .filter(|(_, y)| y.is_finite())
        .map(|(t, y)| [t, y])
        .collect();
    let stride = kept.len().div_ceil(MAX_POINTS).max(1);
    let mut curve: Vec<[f64; 2]> = kept.iter().step_by(stride).copied().collect();
    if let (Some(last), Some(shown)) = (kept.last(), curve.last())
        && last != shown
    {
        curve.push(*last);
    }
    Response {
        curve,
        metrics,
        settled: r.settled && metrics != LoopMetrics::NONE,
        shown_until: until,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_loop_settles_with_both_responses_measured() {
        let view =
            compute(&ProcessSettings::default(), &ControllerSettings::default()).expect("a loop");
        assert!(view.setpoint.settled && view.load.settled);
        let fv = view.setpoint.metrics.final_value.expect("a final value");
        assert!((fv - 1.0).abs() < 1e-6, "{fv}");
        assert!(view.load.metrics.peak.is_some());
        assert!(view.setpoint.curve.len() > 10 && view.setpoint.curve.len() <= MAX_POINTS + 1);
    }

    #[test]
    fn a_high_gain_does_not_settle() {
        let c = ControllerSettings {
            kc: 50.0,
            ..ControllerSettings::default()
        };
        let view = compute(&ProcessSettings::default(), &c).expect("a loop");
        assert!(!view.setpoint.settled);
        assert_eq!(view.setpoint.metrics, LoopMetrics::NONE);
    }
}
