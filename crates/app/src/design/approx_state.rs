//! The approximation view's state, with no egui in it: what the view asks ([`ApproxCommand`]),
//! the choice and what is derived from it ([`ApproxView`], recomputed only when the system,
//! the thresholds or the choice change; the session holds one) and [`scene`], the pure
//! builder of what the plot and the small s-plane draw ([`Scene`]). The view that draws it
//! is [`super::approx`].

use degrau_lti::approx::{self, ApproxError, Approximated, Approximation, Row};
use degrau_lti::{C64, StepInfoOptions, StepResponse};

use super::analysis::Analysis;
use super::state::System;

/// Points of each curve of the overlay.
const OVERLAY_SAMPLES: usize = 600;

/// What the view asks the session for.
#[derive(Debug, Clone, PartialEq)]
pub enum ApproxCommand {
    /// Show this approximation (`None` closes the view to its one line).
    Choose(Option<Approximation>),
    /// Show (or hide) the table of every method.
    ShowTable(bool),
}

/// What the overlay and the small s-plane draw.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// (t, y) of the original's and of the model's exact responses, over the comparison's
    /// window; a jump (a biproper model's, or at a dead time) is a vertical segment.
    pub original: Vec<[f64; 2]>,
    pub approx: Vec<[f64; 2]>,
    pub model_poles: Vec<C64>,
    pub model_zeros: Vec<C64>,
    pub original_poles: Vec<C64>,
    pub original_zeros: Vec<C64>,
}

/// (t, y) of `r` over [0, horizon], with the instant of its dead time drawn as a jump from 0;
/// a value beyond double precision is left out (nothing that is not a number is plotted).
fn curve(r: &StepResponse, horizon: f64) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(OVERLAY_SAMPLES + 2);
    let theta = r.delay();
    let mut before = true;
    for i in 0..=OVERLAY_SAMPLES {
        let t = horizon * i as f64 / OVERLAY_SAMPLES as f64;
        if before && t >= theta {
            out.push([theta, 0.0]);
            out.push([theta, r.value(theta)]);
            before = false;
        }
        out.push([t, r.value(t)]);
    }
    out.retain(|p| p[0].is_finite() && p[1].is_finite());
    out
}

/// The scene of an approximation of `original` (the system's exact response and roots).
pub fn scene(original: &StepResponse, original_roots: (&[C64], &[C64]), a: &Approximated) -> Scene {
    let horizon = a.comparison.horizon;
    Scene {
        original: curve(original, horizon),
        approx: curve(&a.response, horizon),
        model_poles: a.model.poles().to_vec(),
        model_zeros: a.model.zeros().to_vec(),
        original_poles: original_roots.0.to_vec(),
        original_zeros: original_roots.1.to_vec(),
    }
}

/// What the view's derived data were computed for.
#[derive(Debug, Clone, PartialEq)]
struct Key {
    system: System,
    options: StepInfoOptions,
    choice: Option<Approximation>,
    show_table: bool,
}

/// The choice and its derived result (the session holds one).
#[derive(Debug, Clone, Default)]
pub struct ApproxView {
    pub choice: Option<Approximation>,
    pub show_table: bool,
    /// The chosen approximation's model and comparison, or why there is none (`None`:
    /// nothing chosen, or no system).
    pub outcome: Option<Result<Approximated, ApproxError>>,
    pub scene: Option<Scene>,
    /// Every method's row, when the table is shown.
    pub table: Option<Vec<Row>>,
    key: Option<Key>,
}

impl ApproxView {
    pub fn apply(&mut self, command: ApproxCommand) {
        match command {
            ApproxCommand::Choose(choice) => self.choice = choice,
            ApproxCommand::ShowTable(on) => self.show_table = on,
        }
    }

    /// Recomputes what changed since the last time (nothing when nothing did).
    pub fn refresh(&mut self, analysis: &Analysis) {
        let key = Key {
            system: analysis.system.clone(),
            options: analysis.options,
            choice: self.choice,
            show_table: self.show_table,
        };
        if self.key.as_ref() == Some(&key) {
            return;
        }
        self.key = Some(key);
        let (Ok(tf), Some(response)) = (&analysis.tf, &analysis.response) else {
            (self.outcome, self.scene, self.table) = (None, None, None);
            return;
        };
        let options = &analysis.options;
        self.outcome = self
            .choice
            .map(|c| approx::approximate(tf, response, c, options));
        self.scene = match &self.outcome {
            Some(Ok(a)) => Some(scene(response, (tf.poles(), tf.zeros()), a)),
            _ => None,
        };
        self.table = self
            .show_table
            .then(|| approx::table(tf, response, options));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_lti::TransferFunction;
    use degrau_lti::approx::{DelayApproximant, Method};

    #[test]
    fn the_scene_jumps_at_the_dead_time_and_holds_both_curves() {
        // (s + 2)/(2(s + 1))·e^{−s} against its Padé (1, 1): biproper, the model jumps to
        // −A·D = −0.5 at t = 0 while the true delay holds y at 0 until t = 1.
        let g = TransferFunction::from_zpk(&[C64::new(-2.0, 0.0)], &[C64::new(-1.0, 0.0)], 0.5)
            .unwrap()
            .with_delay(1.0)
            .unwrap();
        let r = StepResponse::new(&g, 1.0).unwrap();
        let a = approx::approximate(
            &g,
            &r,
            Approximation::Delay(DelayApproximant::Pade { m: 1, n: 1 }),
            &StepInfoOptions::default(),
        )
        .unwrap();
        let s = scene(&r, (g.poles(), g.zeros()), &a);
        assert_eq!(s.approx.len(), OVERLAY_SAMPLES + 3);
        assert_eq!(s.approx[0], [0.0, 0.0]);
        assert!(
            s.approx[1][1] < 0.0,
            "the wrong-way start: {:?}",
            s.approx[1]
        );
        // The original stays at 0 until θ = 1, then starts from 0.
        assert!(s.original.iter().all(|p| p[0] >= 1.0 || p[1] == 0.0));
        assert!(s.original.contains(&[1.0, 0.0]) && s.original.contains(&[1.0, r.value(1.0)]));
        // The system's zero −2 and the approximant's 2/θ = 2, in the right half plane.
        assert_eq!(s.model_zeros.len(), 2);
        assert_eq!(s.model_zeros.iter().filter(|z| z.re > 0.0).count(), 1);
    }

    #[test]
    fn the_view_recomputes_only_when_its_inputs_change() {
        let system = System::default();
        let analysis = Analysis::new(&system, StepInfoOptions::default());
        let mut v = ApproxView::default();
        v.refresh(&analysis);
        assert!(v.outcome.is_none() && v.table.is_none());
        v.apply(ApproxCommand::Choose(Some(Approximation::Reduce(
            Method::Skogestad.default_reduction(),
        ))));
        v.refresh(&analysis);
        let model = v.outcome.as_ref().unwrap().as_ref().unwrap().model.clone();
        let tf = analysis.tf.as_ref().unwrap();
        assert!((model.dc_gain() - tf.dc_gain()).abs() < 1e-12 * tf.dc_gain().abs());
        assert!(v.scene.is_some());
        v.apply(ApproxCommand::ShowTable(true));
        v.refresh(&analysis);
        assert!(!v.table.as_ref().unwrap().is_empty());
    }
}
