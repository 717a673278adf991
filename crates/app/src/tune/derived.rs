//! What the Tune mode shows, computed from its settings: the loop's setpoint and load
//! responses with their metrics (the dead time exact, no Padé). A few milliseconds: done on
//! the UI thread when the model or the controller changed, never every frame.

use degrau_lti::control::{ControllerError, DelayLoopError, LoopMetrics, LoopResponse, tuned_loop};

use super::model::{ModelProblem, ProcessSettings};
use super::session::ControllerSettings;

/// How far a response that does not settle is drawn (a unit step's output units).
const GROWTH_SHOWN: f64 = 100.0;
/// The points a curve is drawn with.
const CURVE_POINTS: usize = 1500;
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

/// `points` evenly spread over the span of `nodes` (sorted by time), each interpolated
/// between the two nodes around it; the last node closes the curve.
fn evenly(nodes: &[[f64; 2]], points: usize) -> Vec<[f64; 2]> {
    let (Some(first), Some(last)) = (nodes.first(), nodes.last()) else {
        return Vec::new();
    };
    let span = last[0] - first[0];
    if span <= 0.0 || points < 2 {
        return nodes.to_vec();
    }
    let mut out = Vec::with_capacity(points);
    let mut i = 0;
    for k in 0..points {
        let t = first[0] + span * k as f64 / (points - 1) as f64;
        while i + 1 < nodes.len() && nodes[i + 1][0] < t {
            i += 1;
        }
        let (a, b) = (nodes[i], nodes[(i + 1).min(nodes.len() - 1)]);
        let y = if b[0] > a[0] {
            a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
        } else {
            b[1]
        };
        out.push([t, y]);
    }
    out
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
    // The nodes cluster at each step's ends (Chebyshev–Lobatto): drawn as they are, the
    // segments far shorter than the line is wide tessellate as a broken line. The curve is
    // drawn through CURVE_POINTS instants evenly spread, each read between its two nodes
    // (a step holds eight, so the straight piece between them is within a pixel).
    let curve = evenly(&kept, CURVE_POINTS);
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
        assert_eq!(view.setpoint.curve.len(), CURVE_POINTS);
    }

    #[test]
    fn the_curve_is_evenly_spread_and_runs_through_the_nodes() {
        // y = t² at uneven nodes: the even points lie on the chords between them.
        let nodes: Vec<[f64; 2]> = [0.0, 0.1, 0.15, 1.0, 2.0]
            .iter()
            .map(|&t| [t, t * t])
            .collect();
        let curve = evenly(&nodes, 5);
        let t: Vec<f64> = curve.iter().map(|p| p[0]).collect();
        assert_eq!(t, vec![0.0, 0.5, 1.0, 1.5, 2.0]);
        // 0.5 between 0.15 (0.0225) and 1 (1): 0.0225 + 0.9775·0.35/0.85.
        assert!((curve[1][1] - (0.0225 + 0.9775 * 0.35 / 0.85)).abs() < 1e-15);
        assert_eq!((curve[2][1], curve[4][1]), (1.0, 4.0));
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
