//! The Design mode's closed loop: what it keeps ([`LoopSettings`]: whether the loop is
//! closed, the gain Kp, the locus and spec choices) and what it derives from the system
//! ([`LoopDerived`]: the root locus, cached per system; the closed loop's analysis, cached
//! per system, Kp and thresholds; the error constants, the gain search's answer, the
//! second-order check and the response to the chosen input). No egui here, and nothing is
//! recomputed while drawing: the views read these caches.
//!
//! The loop's controller is P (Kp alone) or a PI, PD or PID of fixed shape
//! ([`ControllerShape`]: Ti, Td and the filter N) whose gain Kc is the loop's K: the open
//! loop is then (C/Kc)·G, so the root locus, the gain search and the constants follow K
//! with the controller's zeros and poles in place (the Tune mode computes the loop with the
//! exact dead time).
//!
//! A system with a dead time is closed through a Padé approximant of its delay (of the
//! order the student chose, [`PadeOrder`]): the open loop, the locus, the closed loop and
//! the gain search are then of the approximated loop, and [`LoopDerived::approximant`]
//! says so for the views to label them approximate.

use serde::{Deserialize, Serialize};

use degrau_lti::approx::ApproxError;
use degrau_lti::control::{Action, Controller, ControllerError};
use degrau_lti::feedback::{
    ErrorConstants, FormulaCheck, GainSearch, Input, InputResponse, LoopApproximant, PadeOrder,
    RationalLoop, Spec, find_gain,
};
use degrau_lti::locus::{Locus, Side};
use degrau_lti::{C64, StepInfoOptions, TransferFunction};

use super::analysis::{Analysis, CURVE_SAMPLES};
use super::state::System;

/// Specs a student sets: shaded on the s-plane and used by "find K". `None` is off.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Specs {
    /// Mp ≤ this (%): ζ ≥ ζmin.
    pub overshoot: Option<f64>,
    /// t_s (2 %) ≤ this (s): σ ≥ 4/T.
    pub settling: Option<f64>,
    /// t_p ≤ this (s): ωd ≥ π/T.
    pub peak: Option<f64>,
    /// t_r (10–90 %) ≤ this (s), for the gain search.
    pub rise: Option<f64>,
    /// ωn ≥ this (rad/s).
    pub wn_min: Option<f64>,
    /// ωn ≤ this (rad/s).
    pub wn_max: Option<f64>,
    /// e_ss for a unit step ≤ this.
    pub ess_step: Option<f64>,
    /// e_ss for a unit ramp ≤ this.
    pub ess_ramp: Option<f64>,
}

impl Specs {
    /// The specs the gain search judges on the exact response.
    pub fn search_specs(&self) -> Vec<Spec> {
        [
            self.overshoot.map(Spec::Overshoot),
            self.settling.map(Spec::Settling),
            self.rise.map(Spec::Rise),
            self.ess_step.map(Spec::EssStep),
            self.ess_ramp.map(Spec::EssRamp),
        ]
        .into_iter()
        .flatten()
        .collect()
    }

    /// Whether any region is shaded on the s-plane.
    pub fn any_region(&self) -> bool {
        self.overshoot.is_some()
            || self.settling.is_some()
            || self.peak.is_some()
            || self.wn_min.is_some()
            || self.wn_max.is_some()
    }
}

/// What the Design mode keeps about the loop (in its state file).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LoopSettings {
    /// Unity feedback around Kp·G(s) is shown.
    pub closed: bool,
    /// The proportional gain Kp.
    pub kp: f64,
    /// The root locus is drawn on the s-plane.
    pub locus: bool,
    /// The complementary locus (K < 0) is drawn too.
    pub complementary: bool,
    pub specs: Specs,
    /// The input whose response is plotted beside the step (step: none more).
    pub input: Input,
    /// The Padé order standing in for a dead time in the loop.
    pub pade: PadeOrder,
    /// The controller's shape; its gain is Kp.
    pub controller: ControllerShape,
}

/// A controller's shape: the action and, where it has them, Ti, Td and N (its gain is the
/// loop's K). P is the plain proportional loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ControllerShape {
    pub action: Action,
    /// Ti (s).
    pub ti: f64,
    /// Td (s).
    pub td: f64,
    /// The derivative filter N.
    pub n: f64,
}

impl Default for ControllerShape {
    fn default() -> Self {
        Self {
            action: Action::P,
            ti: 1.0,
            td: 0.1,
            n: degrau_lti::control::controller::DEFAULT_FILTER,
        }
    }
}

impl ControllerShape {
    /// C(s)/Kc as a transfer function, None for P; an error names a parameter refused.
    pub fn unit_gain(&self) -> Result<Option<TransferFunction>, ControllerError> {
        if self.action == Action::P {
            return Ok(None);
        }
        let c = Controller::new(self.action, 1.0, self.ti, self.td)?.with_filter(self.n)?;
        Ok(c.transfer_function())
    }
}

impl LoopSettings {
    /// Why these settings cannot be restored, if they cannot: Kp not finite or beyond
    /// ±[`KP_LIMIT`], a Padé order out of range.
    pub fn validate(&self) -> Result<(), LoopProblem> {
        if !(self.kp.is_finite() && self.kp.abs() <= KP_LIMIT) {
            return Err(LoopProblem::Gain(self.kp));
        }
        if !self.pade.is_valid() {
            return Err(LoopProblem::Pade(self.pade));
        }
        if let Err(e) = self.controller.unit_gain() {
            return Err(LoopProblem::Controller(e));
        }
        Ok(())
    }
}

/// Why saved loop settings cannot be restored; said in words by [`crate::words::persist`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoopProblem {
    /// Kp not finite or beyond ±[`KP_LIMIT`].
    Gain(f64),
    /// A Padé order the menu does not offer.
    Pade(PadeOrder),
    /// A controller parameter refused.
    Controller(ControllerError),
}

impl Default for LoopSettings {
    fn default() -> Self {
        Self {
            closed: false,
            kp: 1.0,
            locus: false,
            complementary: false,
            specs: Specs::default(),
            input: Input::Step,
            pade: PadeOrder::default(),
            controller: ControllerShape::default(),
        }
    }
}

/// The response to an input (t, y) and the input itself (t, r), both sampled for the plot.
pub type InputCurve = (Vec<[f64; 2]>, Vec<[f64; 2]>);

/// The largest |Kp| the app holds.
pub const KP_LIMIT: f64 = 1e12;

/// What the gain search found, or why it found nothing.
#[derive(Debug, Clone, PartialEq)]
pub enum Found {
    Gain(GainSearch),
    /// No K > 0 meets the specs.
    Nothing,
    /// No spec was set.
    NoSpecs,
    /// The search could not run.
    Refused(ApproxError),
}

/// The derived data of the loop, recomputed only when its inputs change.
#[derive(Debug, Clone, Default)]
pub struct LoopDerived {
    /// The system, the Padé order and the controller's shape the locus is for.
    system: Option<(System, PadeOrder, ControllerShape)>,
    /// The open loop G(s) (rational: a dead time replaced by its Padé approximant), or why
    /// there is no loop.
    pub open_loop: Option<Result<TransferFunction, ApproxError>>,
    /// The Padé approximant standing in for the system's dead time (`None` without one):
    /// when set, everything of the loop is approximate.
    pub approximant: Option<LoopApproximant>,
    pub locus: Option<Locus>,
    pub complementary: Option<Locus>,
    /// The locus's branches as plane points (cached for drawing).
    pub branches: Vec<Vec<[f64; 2]>>,
    pub complementary_branches: Vec<Vec<[f64; 2]>>,
    /// The Kp and thresholds the closed loop is for.
    closed_for: Option<(f64, StepInfoOptions, Input, bool, bool)>,
    /// The closed loop's analysis (its step response, metrics, curve).
    pub closed: Option<Analysis>,
    /// The closed-loop poles, in the locus's branch order.
    pub closed_poles: Vec<C64>,
    pub constants: Option<ErrorConstants>,
    /// Whether the loop at Kp is stable (its steady-state errors exist), closed or not.
    pub closed_stable: Option<bool>,
    /// The formulas of the dominant pair beside the exact metrics, of the loop shown
    /// (closed when it is closed).
    pub formulas: Option<FormulaCheck>,
    /// The response to the chosen input (of the closed loop when closed), with the input.
    pub input_curve: Option<InputCurve>,
    /// The last gain search's answer.
    pub found: Option<Found>,
}

impl LoopDerived {
    /// Brings the caches up to date with `system` and `settings`. The locus (thousands of
    /// polynomials' roots) is computed only when it is shown or the loop is closed, and not
    /// while `dragging` a root of the open loop: it follows when the drag ends.
    pub fn refresh(
        &mut self,
        system: &System,
        settings: &LoopSettings,
        options: StepInfoOptions,
        dragging: bool,
    ) {
        let for_system = (system.clone(), settings.pade, settings.controller);
        if self.system.as_ref() != Some(&for_system) {
            self.system = Some(for_system);
            let rational = open_loop(system, settings.pade, &settings.controller);
            self.approximant = rational.as_ref().ok().and_then(|r| r.approximant);
            self.open_loop = Some(rational.map(|r| r.g));
            self.locus = None;
            self.complementary = None;
            self.branches.clear();
            self.complementary_branches.clear();
            self.closed_for = None;
            self.found = None;
        }
        let wants_locus = settings.locus || settings.closed;
        if let Some(Ok(g)) = &self.open_loop
            && !dragging
        {
            if wants_locus && self.locus.is_none() {
                self.locus = Locus::new(g, Side::Positive).ok();
                self.branches = self.locus.as_ref().map(branches).unwrap_or_default();
                // The closed-loop poles are put in the branches' order.
                self.closed_for = None;
            }
            if settings.locus && settings.complementary && self.complementary.is_none() {
                self.complementary = Locus::new(g, Side::Complementary).ok();
                self.complementary_branches = self
                    .complementary
                    .as_ref()
                    .map(branches)
                    .unwrap_or_default();
            }
        }
        let key = (
            settings.kp,
            options,
            settings.input,
            settings.closed,
            dragging,
        );
        if self.closed_for != Some(key) {
            self.closed_for = Some(key);
            self.recompute_closed(system, settings, options, dragging);
        }
    }

    /// The closed loop's analysis (when the loop is closed), the constants, and (not while
    /// dragging, they cost two more analyses) the second-order check.
    fn recompute_closed(
        &mut self,
        system: &System,
        settings: &LoopSettings,
        options: StepInfoOptions,
        dragging: bool,
    ) {
        self.closed = None;
        self.closed_poles.clear();
        self.constants = None;
        self.closed_stable = None;
        let open = system.transfer_function().ok();
        let shown = match &self.open_loop {
            Some(Ok(g)) => {
                self.constants = Some(ErrorConstants::of(g, settings.kp));
                self.closed_stable = g.closed_loop(settings.kp).ok().map(|c| c.is_stable());
                match g.closed_loop(settings.kp).ok().filter(|_| settings.closed) {
                    Some(cl) => {
                        let as_system = System::from_transfer_function(&cl, system.amplitude);
                        self.closed = Some(Analysis::new(&as_system, options));
                        self.closed_poles = self.in_branch_order(cl.poles(), settings.kp);
                        Some(cl)
                    }
                    None => None,
                }
            }
            _ => None,
        };
        let loop_shown = if settings.closed { shown } else { open.clone() };
        self.formulas = loop_shown
            .as_ref()
            .filter(|_| !dragging)
            .and_then(FormulaCheck::of);
        self.input_curve = loop_shown
            .as_ref()
            .filter(|_| settings.input != Input::Step)
            .and_then(|g| input_curve(g, settings.input, system.amplitude));
    }

    /// `poles` reordered to follow the branches of the locus at `kp` (index i on branch i).
    fn in_branch_order(&self, poles: &[C64], kp: f64) -> Vec<C64> {
        let Some(locus) = &self.locus else {
            return poles.to_vec();
        };
        let Some(near) = locus
            .points
            .iter()
            .min_by(|a, b| (a.k - kp).abs().total_cmp(&(b.k - kp).abs()))
        else {
            return poles.to_vec();
        };
        let mut left: Vec<C64> = poles.to_vec();
        near.roots
            .iter()
            .map(|r| {
                let i = left
                    .iter()
                    .enumerate()
                    .min_by(|a, b| (a.1 - r).norm().total_cmp(&(b.1 - r).norm()))
                    .map_or(0, |(i, _)| i);
                left.swap_remove(i)
            })
            .collect()
    }

    /// The gain K that puts a closed-loop pole of `branch` nearest `s` (for a drag).
    pub fn gain_at(&self, branch: usize, s: C64) -> Option<f64> {
        let (Some(Ok(g)), Some(locus)) = (&self.open_loop, &self.locus) else {
            return None;
        };
        locus
            .gain_near(g, branch, s)
            .map(|(k, _)| k)
            .filter(|k| k.is_finite() && k.abs() <= KP_LIMIT)
    }

    /// Runs the gain search for `specs` (on a command, never while drawing).
    pub fn find(&mut self, specs: &Specs) -> Option<f64> {
        let list = specs.search_specs();
        let found = match &self.open_loop {
            _ if list.is_empty() => Found::NoSpecs,
            Some(Ok(g)) => match find_gain(g, &list) {
                Ok(Some(s)) => Found::Gain(s),
                Ok(None) => Found::Nothing,
                Err(e) => Found::Refused(e.into()),
            },
            Some(Err(why)) => Found::Refused(why.clone()),
            None => Found::NoSpecs,
        };
        let k = match &found {
            Found::Gain(s) => Some(s.k),
            _ => None,
        };
        self.found = Some(found);
        k
    }

    /// The gain the locus and the K readout work with: the scale of the gains of interest.
    pub fn k_span(&self) -> (f64, f64) {
        let top = self
            .locus
            .as_ref()
            .and_then(|l| l.crossings.first().map(|c| c.k))
            .filter(|k| *k > 0.0);
        let scale = self
            .locus
            .as_ref()
            .and_then(|l| l.points.get(l.points.len() / 3).map(|p| p.k.abs()))
            .filter(|k| *k > 0.0)
            .unwrap_or(1.0);
        let hi = top.map_or(100.0 * scale, |k| 3.0 * k);
        (hi * 1e-5, hi)
    }
}

/// (C/Kc)·G(s) for the loop, rational: a dead time replaced by Padé `order`. A controller
/// refused leaves G alone (the panel says why).
fn open_loop(
    system: &System,
    order: PadeOrder,
    shape: &ControllerShape,
) -> Result<RationalLoop, ApproxError> {
    let mut rational = RationalLoop::new(&system.transfer_function()?, order)?;
    if let Ok(Some(c)) = shape.unit_gain() {
        rational.g = rational.g.series(&c)?;
    }
    Ok(rational)
}

fn branches(locus: &Locus) -> Vec<Vec<[f64; 2]>> {
    (0..locus.branch_count())
        .map(|b| {
            locus
                .branch(b)
                .iter()
                .filter(|r| r.re.is_finite() && r.im.is_finite())
                .map(|r| [r.re, r.im])
                .collect()
        })
        .collect()
}

/// The response of `g` to `input` over its step response's window, with the input itself.
fn input_curve(g: &TransferFunction, input: Input, amplitude: f64) -> Option<InputCurve> {
    let step = degrau_lti::StepResponse::new(g, amplitude).ok()?;
    let horizon = Some(step.auto_horizon())
        .filter(|h| h.is_finite() && *h > 0.0)
        .unwrap_or(10.0);
    let r = InputResponse::new(g, input, amplitude).ok()?;
    let (t, y) = r.sample_uniform(0.0, horizon, CURVE_SAMPLES);
    if y.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let curve = t.iter().zip(&y).map(|(&t, &y)| [t, y]).collect();
    let reference = t.iter().map(|&t| [t, r.input_value(t)]).collect();
    Some((curve, reference))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shown() -> LoopSettings {
        LoopSettings {
            closed: true,
            locus: true,
            ..LoopSettings::default()
        }
    }

    #[test]
    fn the_locus_is_computed_once_per_system_and_not_while_dragging() {
        let system = System::default();
        let mut d = LoopDerived::default();
        d.refresh(&system, &shown(), StepInfoOptions::default(), false);
        let first = d.branches[0].as_ptr();
        // A frame with nothing changed keeps every cache.
        d.refresh(&system, &shown(), StepInfoOptions::default(), false);
        assert_eq!(d.branches[0].as_ptr(), first);
        // A new Kp recomputes the closed loop only.
        let mut k = shown();
        k.kp = 20.0;
        d.refresh(&system, &k, StepInfoOptions::default(), false);
        assert_eq!(d.branches[0].as_ptr(), first);
        let den = d.closed.as_ref().unwrap().tf.as_ref().unwrap().den();
        assert!((den[3] - 35.0).abs() < 1e-12, "25 + 20·0.5: {den:?}");
        // A root dragged: no locus until the drag ends.
        let mut moved = system.clone();
        moved.poles[1].move_to(-4.0, 0.0);
        d.refresh(&moved, &k, StepInfoOptions::default(), true);
        assert!(d.locus.is_none() && d.branches.is_empty());
        assert!(d.closed.is_some(), "the closed loop follows the drag");
        d.refresh(&moved, &k, StepInfoOptions::default(), false);
        assert!(d.locus.is_some());
    }

    #[test]
    fn a_dead_time_is_closed_through_its_pade_approximant() {
        // G = 1/(s + 1)·e^{−0.5 s}, Padé (1, 1): (−0.5 s + 2)/(0.5 s + 2)(s + 1).
        let system = System {
            delay: 0.5,
            poles: vec![crate::design::state::Root::real(-1.0)],
            zeros: Vec::new(),
            gain: 1.0,
            ..System::default()
        };
        let settings = LoopSettings {
            pade: PadeOrder { m: 1, n: 1 },
            ..shown()
        };
        let mut d = LoopDerived::default();
        d.refresh(&system, &settings, StepInfoOptions::default(), false);
        let approximant = d.approximant.expect("the delay is approximated");
        assert_eq!(
            (approximant.m, approximant.n, approximant.delay),
            (1, 1, 0.5)
        );
        assert!(d.locus.is_some(), "the approximated loop has a locus");
        // Kp = 1: 1 + G = 0 ⇔ (0.5 s + 2)(s + 1) + (−0.5 s + 2) = 0.5 s² + 2 s + 4 = 0,
        // s = −2 ± 2j.
        let mut poles = d.closed_poles.clone();
        poles.sort_by(|a, b| a.im.total_cmp(&b.im));
        assert_eq!(poles.len(), 2);
        assert!((poles[0] - C64::new(-2.0, -2.0)).norm() < 1e-9, "{poles:?}");
        assert!((poles[1] - C64::new(-2.0, 2.0)).norm() < 1e-9, "{poles:?}");
        // Another order is another loop.
        let three = LoopSettings {
            pade: PadeOrder::default(),
            ..settings
        };
        d.refresh(&system, &three, StepInfoOptions::default(), false);
        assert_eq!(d.approximant.map(|a| a.n), Some(3));
        assert_eq!(d.closed_poles.len(), 4);
    }

    #[test]
    fn a_system_without_dead_time_is_exact() {
        let mut d = LoopDerived::default();
        d.refresh(
            &System::default(),
            &shown(),
            StepInfoOptions::default(),
            false,
        );
        assert!(d.approximant.is_none());
        assert!(matches!(d.open_loop, Some(Ok(_))));
    }

    #[test]
    fn settings_out_of_range_are_refused() {
        assert!(LoopSettings::default().validate().is_ok());
        let huge = LoopSettings {
            kp: f64::INFINITY,
            ..LoopSettings::default()
        };
        assert!(huge.validate().is_err());
        let order = LoopSettings {
            pade: PadeOrder { m: 4, n: 2 },
            ..LoopSettings::default()
        };
        assert!(order.validate().is_err());
    }
}
