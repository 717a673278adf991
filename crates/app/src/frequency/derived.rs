//! What the Frequency mode shows, computed from its source: the loop's Bode diagram with its
//! asymptotes, its margins, its Nyquist curve and its closed-loop count ([`LoopData`]); the plant sampled with a
//! zero-order hold at h, its poles and zeros, its stairs over the continuous step response,
//! the sampling rules and d2c back ([`SampledData`]). Done on the UI thread when the source
//! or h changed, never every frame.

use degrau_lti::bode::{Asymptotes, Bode, asymptotes, bode, frequency_grid};
use degrau_lti::control::frequency::closed_loop_unstable_roots;
use degrau_lti::control::{Action, Controller, Margins, Nyquist, StabilityError, margins, nyquist};
use degrau_lti::discrete::{DiscreteError, DiscreteTf, c2d};
use degrau_lti::locus::multiply;
use degrau_lti::{C64, LtiError, StepInfoOptions, StepResponse, TransferFunction, analyse};

use super::rules::{Facts, Judged, judge};

/// The points of the Bode curves.
const BODE_POINTS: usize = 800;
/// The points of the continuous step response.
const STEP_POINTS: usize = 600;
/// The most samples of the sampled step response drawn.
pub const MAX_SAMPLES: usize = 2000;
/// The settling band of Isermann's rule (95 %).
const SETTLING_BAND: f64 = 0.05;

/// The loop L = C·G in frequency.
#[derive(Debug, Clone)]
pub struct LoopData {
    /// L(s) (G itself when there is no controller).
    pub l: TransferFunction,
    /// The Bode diagram of L on its default grid.
    pub bode: Bode,
    pub asymptotes: Asymptotes,
    /// The asymptotes at each ω of `bode` (dB).
    pub asymptote_db: Vec<f64>,
    pub margins: Margins,
    /// The closed loop's roots in the right half-plane, counted from its characteristic
    /// equation.
    pub closed_loop: Result<usize, StabilityError>,
    /// The Nyquist curve and its count Z = N + P.
    pub nyquist: Result<Nyquist, StabilityError>,
}

/// The unit controller (L = G).
fn unit() -> Controller {
    Controller {
        action: Action::P,
        kc: 1.0,
        ti: f64::INFINITY,
        td: 0.0,
        n: degrau_lti::control::controller::DEFAULT_FILTER,
        b: 1.0,
    }
}

/// The loop of `controller` (none: L = G) around `plant`.
pub fn loop_data(
    plant: &TransferFunction,
    controller: Option<&Controller>,
) -> Result<LoopData, LtiError> {
    let c = controller.copied().unwrap_or_else(unit);
    let (nc, dc) = c.feedback_coeffs();
    let (n, d) = (multiply(&nc, &plant.num()), multiply(&dc, &plant.den()));
    let l = TransferFunction::from_coeffs(&n, &d)?.with_delay(plant.delay())?;
    let w = frequency_grid(&l, BODE_POINTS);
    let asymptotes = asymptotes(&l);
    let asymptote_db = w.iter().map(|&w| asymptotes.value_db(w)).collect();
    Ok(LoopData {
        bode: bode(&l, &w),
        asymptotes,
        asymptote_db,
        margins: margins(plant, &c),
        closed_loop: closed_loop_unstable_roots(plant, &c),
        nyquist: nyquist(plant, &c),
        l,
    })
}

/// The plant sampled at h.
#[derive(Debug, Clone)]
pub struct SampledData {
    pub h: f64,
    /// H(z), or why there is none.
    pub zoh: Result<Zoh, DiscreteError>,
    /// The continuous step response (t, y), on the stairs' time span.
    pub continuous: Vec<[f64; 2]>,
    /// The sampling rules judged for h.
    pub rules: Vec<Judged>,
    pub facts: Facts,
}

/// H(z) = B(z)/A(z)·z^−nk and what is read from it.
#[derive(Debug, Clone)]
pub struct Zoh {
    pub tf: DiscreteTf,
    pub poles: Vec<C64>,
    /// The roots of B (none: they could not be found).
    pub zeros: Option<Vec<C64>>,
    /// The sampled step response held between samples: (t, y) corners of the stairs.
    pub stairs: Vec<[f64; 2]>,
    /// The continuous G(s) recovered by d2c, or why not.
    pub back: Result<TransferFunction, DiscreteError>,
}

/// `plant` sampled at `h`, with its continuous step response and the rules.
pub fn sampled(plant: &TransferFunction, h: f64) -> SampledData {
    let response = StepResponse::new(plant, 1.0).ok();
    let options = StepInfoOptions {
        settling_threshold: SETTLING_BAND,
        ..StepInfoOptions::default()
    };
    let analysis = response.as_ref().map(|r| analyse(r, &options));
    let settling = analysis.as_ref().and_then(|a| a.info.settling_time);
    let facts = Facts::of(plant, settling);
    let horizon = analysis
        .as_ref()
        .map_or(10.0 * h, |a| a.horizon)
        .clamp(h, MAX_SAMPLES as f64 * h);
    let continuous = response
        .as_ref()
        .map(|r| {
            (0..=STEP_POINTS)
                .map(|i| horizon * i as f64 / STEP_POINTS as f64)
                .map(|t| [t, r.value(t)])
                .filter(|p| p[1].is_finite())
                .collect()
        })
        .unwrap_or_default();
    SampledData {
        h,
        zoh: c2d(plant, h).map(|tf| zoh(tf, horizon)),
        continuous,
        rules: judge(&facts, h),
        facts,
    }
}

fn zoh(tf: DiscreteTf, horizon: f64) -> Zoh {
    let h = tf.ts();
    let n = ((horizon / h).ceil() as usize).clamp(2, MAX_SAMPLES);
    let y = tf.step(n);
    let stairs = y
        .iter()
        .enumerate()
        .filter(|(_, y)| y.is_finite())
        .flat_map(|(k, &y)| [[k as f64 * h, y], [(k + 1) as f64 * h, y]])
        .collect();
    Zoh {
        poles: tf.poles().unwrap_or_default(),
        zeros: tf.zeros().ok(),
        stairs,
        back: tf.d2c(),
        tf,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sampled_poles_are_e_to_the_p_h() {
        let g = TransferFunction::from_coeffs(&[2.0], &[1.0, 3.0, 2.0]).expect("a plant");
        let s = sampled(&g, 0.1);
        let zoh = s.zoh.expect("H(z)");
        let mut got: Vec<f64> = zoh.poles.iter().map(|p| p.re).collect();
        got.sort_by(f64::total_cmp);
        let want = [(-0.2f64).exp(), (-0.1f64).exp()];
        assert!((got[0] - want[0]).abs() < 1e-12 && (got[1] - want[1]).abs() < 1e-12);
        // The stairs equal the continuous response at the samples (ZOH is exact there).
        let r = StepResponse::new(&g, 1.0).expect("a response");
        for p in zoh.stairs.iter().step_by(2).take(50) {
            assert!((p[1] - r.value(p[0])).abs() < 1e-12, "{p:?}");
        }
        let back = zoh.back.expect("d2c");
        assert!((back.dc_gain() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn a_p_loop_of_one_is_the_plant() {
        let g = TransferFunction::from_coeffs(&[1.0], &[10.0, 1.0])
            .and_then(|g| g.with_delay(2.0))
            .expect("a plant");
        let d = loop_data(&g, None).expect("a loop");
        let direct = bode(&g, &d.bode.w);
        assert_eq!(direct.mag_db.len(), d.bode.mag_db.len());
        for (a, b) in direct.mag_db.iter().zip(&d.bode.mag_db) {
            assert!((a - b).abs() < 1e-9);
        }
        assert_eq!(d.closed_loop, Ok(0));
    }
}
