//! The Design mode's session: the state it keeps between runs ([`Saved`]: the system, the
//! comparison, the s-plane view, the markers and thresholds), the undo history, and what is
//! derived from them (the analysis of the system and of the comparison, the ghost of the
//! response before the last edit), recomputed only when an input changed. No egui here: the
//! views read a session and return [`Command`]s, and [`Session::apply`] is the only place
//! the design state changes.

use serde::{Deserialize, Serialize};

use degrau_lti::StepInfoOptions;

use super::analysis::Analysis;
use super::closed_loop::{KP_LIMIT, LoopDerived, LoopSettings};
use super::commands::{Command, Markers};
use super::plane::SPlaneState;
use super::presets::{Preset, presets};
use super::state::{History, RootId, System};

/// What the Design mode keeps between runs (part of the app's state file, at its top
/// level).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub system: System,
    /// A system kept for comparison, with its name.
    pub compare: Option<(String, System)>,
    pub splane: SPlaneState,
    pub markers: Markers,
    pub options: StepInfoOptions,
    /// y(t) in amplitude–phase form rather than cos–sin.
    pub phase_form: bool,
    /// The closed loop, the locus, the specs and the Padé order the student chose.
    pub feedback: LoopSettings,
    /// The approximation shown, if any, and whether every method's table is open.
    pub approx: Option<degrau_lti::approx::Approximation>,
    pub approx_table: bool,
}

/// The Design mode's history and derived data.
pub struct Session {
    pub history: History,
    pub analysis: Analysis,
    pub compare_analysis: Option<Analysis>,
    /// The response before the current or last edit, drawn faintly.
    pub ghost: Option<Vec<[f64; 2]>>,
    /// What the pointer is over on the s-plane.
    pub readout: Option<String>,
    pub presets: Vec<Preset>,
    /// The closed loop's and the locus's derived data.
    pub feedback: LoopDerived,
    /// The root being dragged (its drag is one undoable edit).
    dragging: Option<RootId>,
    /// Whether a closed-loop pole is being dragged (its drag keeps one ghost).
    dragging_loop: bool,
    /// The approximation chosen and its derived model and comparison.
    pub approx: super::approx_state::ApproxView,
}

impl Session {
    /// The session of `kept` (its analyses computed now).
    pub fn new(kept: &Saved) -> Self {
        Self {
            history: History::default(),
            analysis: Analysis::new(&kept.system, kept.options),
            compare_analysis: kept
                .compare
                .as_ref()
                .map(|(_, s)| Analysis::new(s, kept.options)),
            ghost: None,
            readout: None,
            presets: presets(),
            feedback: {
                let mut f = LoopDerived::default();
                f.refresh(&kept.system, &kept.feedback, kept.options, false);
                f
            },
            dragging: None,
            dragging_loop: false,
            // Its model and comparison are derived at the first refresh.
            approx: {
                let mut a = super::approx_state::ApproxView::default();
                (a.choice, a.show_table) = (kept.approx, kept.approx_table);
                a
            },
        }
    }

    /// The comparison's name and analysis, when comparing.
    pub fn compare<'a>(&'a self, kept: &'a Saved) -> Option<(&'a str, &'a Analysis)> {
        match (&kept.compare, &self.compare_analysis) {
            (Some((name, _)), Some(a)) => Some((name.as_str(), a)),
            _ => None,
        }
    }

    /// Re-analyses what changed in `kept` (nothing when nothing did).
    pub fn refresh(&mut self, kept: &Saved) {
        self.analysis.refresh(&kept.system, kept.options);
        match (&kept.compare, &mut self.compare_analysis) {
            (Some((_, s)), Some(a)) => a.refresh(s, kept.options),
            (Some((_, s)), None) => self.compare_analysis = Some(Analysis::new(s, kept.options)),
            (None, _) => self.compare_analysis = None,
        }
        self.approx.refresh(&self.analysis);
        let dragging = self.dragging.is_some();
        self.feedback
            .refresh(&kept.system, &kept.feedback, kept.options, dragging);
    }

    /// Applies one command to `kept`, then brings the derived data up to date.
    pub fn apply(&mut self, kept: &mut Saved, command: Command) {
        self.apply_one(kept, command);
        self.refresh(kept);
    }

    fn apply_one(&mut self, kept: &mut Saved, command: Command) {
        match command {
            Command::SetGain(gain) => self.edit(kept, |s| s.gain = gain),
            Command::SetGainMode(mode) => self.edit(kept, |s| keep_system_in_mode(s, mode)),
            Command::SetDelay(delay) => self.edit(kept, |s| s.delay = delay),
            Command::SetAmplitude(a) => self.edit(kept, |s| s.amplitude = a),
            // A typed value is taken as it is: beyond the limits it is refused, not clamped.
            Command::SetRoot { id, re, im } => self.edit(kept, |s| {
                if let Some(r) = s.root_mut(id) {
                    r.re = re;
                    if r.kind == super::state::RootKind::Pair {
                        r.im = im;
                    }
                }
            }),
            Command::DragRoot { id, re, im } => {
                if self.dragging != Some(id) {
                    self.history.record(&kept.system);
                    self.keep_ghost();
                    self.dragging = Some(id);
                }
                kept.splane.selected = Some(id);
                change_if_placeable(&mut kept.system, |s| {
                    if let Some(r) = s.root_mut(id) {
                        r.move_to(re, im);
                    }
                });
            }
            Command::EndDrag => {
                self.dragging = None;
                self.dragging_loop = false;
            }
            Command::Nudge { id, dre, dim } => self.edit(kept, |s| {
                if let Some(r) = s.root_mut(id) {
                    let (re, im) = (r.re + dre, r.im + dim);
                    r.move_to(re, im);
                }
            }),
            Command::AddRoot { role, root } => {
                if kept.system.has_room(role) {
                    let id = RootId {
                        role,
                        index: kept.system.roots(role).len(),
                    };
                    self.edit(kept, |s| {
                        s.add(role, root);
                    });
                    if kept.system.root(id).is_some() {
                        kept.splane.selected = Some(id);
                    }
                }
            }
            Command::RemoveRoot(id) => {
                self.edit(kept, |s| {
                    s.remove(id);
                });
                kept.splane.selected = None;
            }
            Command::TogglePair { id, im } => self.edit(kept, |s| s.toggle_pair(id, im)),
            Command::Select(id) => kept.splane.selected = id,
            Command::LoadPreset(i) => {
                if let Some(p) = self.presets.get(i) {
                    let compare = p.compare.as_ref().map(|(n, s)| (n.to_string(), s.clone()));
                    let system = p.system.clone();
                    self.replace(kept, system);
                    kept.compare = compare;
                }
            }
            Command::SetSystem(system) => self.replace(kept, system),
            Command::CompareWithCurrent => {
                kept.compare = Some((String::new(), kept.system.clone()));
            }
            Command::StopComparing => kept.compare = None,
            Command::Undo => {
                if self.history.undo(&mut kept.system) {
                    self.after_history_jump(kept);
                }
            }
            Command::Redo => {
                if self.history.redo(&mut kept.system) {
                    self.after_history_jump(kept);
                }
            }
            Command::SetView(view) => kept.splane.view = view.and_then(|v| v.sane()),
            Command::SetDampingGrid(on) => kept.splane.damping_grid = on,
            Command::SetSnap(on) => kept.splane.snap = on,
            Command::SetMarkers(m) => kept.markers = m,
            Command::SetOptions(o) => {
                if o.validate().is_ok() {
                    kept.options = o;
                }
            }
            Command::SetPhaseForm(on) => kept.phase_form = on,
            Command::Readout(text) => self.readout = text,
            Command::Approx(c) => {
                self.approx.apply(c);
                (kept.approx, kept.approx_table) = (self.approx.choice, self.approx.show_table);
            }
            Command::SetCoefficients { num, den } => {
                if let Some(system) = from_coefficients(&kept.system, &num, &den) {
                    self.replace(kept, system);
                }
            }
            Command::SetLoopClosed(on) => kept.feedback.closed = on,
            Command::SetKp(kp) => {
                if kp.is_finite() && kp.abs() <= KP_LIMIT && kp != kept.feedback.kp {
                    self.keep_loop_ghost(kept);
                    kept.feedback.kp = kp;
                }
            }
            Command::DragLoopPole { branch, re, im } => {
                self.feedback
                    .refresh(&kept.system, &kept.feedback, kept.options, false);
                if let Some(k) = self.feedback.gain_at(branch, degrau_lti::C64::new(re, im)) {
                    if !self.dragging_loop {
                        self.keep_loop_ghost(kept);
                        self.dragging_loop = true;
                    }
                    kept.feedback.kp = k;
                    kept.feedback.closed = true;
                }
            }
            Command::SetLocus {
                shown,
                complementary,
            } => {
                kept.feedback.locus = shown;
                kept.feedback.complementary = complementary;
            }
            Command::SetSpecs(specs) => kept.feedback.specs = specs,
            Command::FindGain => {
                self.feedback
                    .refresh(&kept.system, &kept.feedback, kept.options, false);
                if let Some(k) = self.feedback.find(&kept.feedback.specs) {
                    self.keep_loop_ghost(kept);
                    kept.feedback.kp = k;
                    kept.feedback.closed = true;
                }
            }
            Command::PlaceSecondOrder { zeta, wn } => {
                let pair = degrau_lti::feedback::SecondOrder { zeta, wn };
                if let Ok(tf) = pair.transfer_function() {
                    let mut system = System::from_transfer_function(&tf, kept.system.amplitude);
                    keep_system_in_mode(&mut system, kept.system.gain_mode);
                    self.replace(kept, system);
                }
            }
            Command::SetInput(input) => kept.feedback.input = input,
            Command::SetPadeOrder(order) => {
                if order.is_valid() {
                    kept.feedback.pade = order;
                }
            }
            Command::SetLoopController(shape) => {
                if shape.unit_gain().is_ok() {
                    kept.feedback.controller = shape;
                }
            }
        }
    }

    /// One undoable edit of the system: `change` applied to a copy, kept if it changed
    /// something and every root is placeable ([`System::placement`]).
    fn edit(&mut self, kept: &mut Saved, change: impl FnOnce(&mut System)) {
        let before = kept.system.clone();
        if change_if_placeable(&mut kept.system, change) {
            self.history.record(&before);
            self.ghost = Some(self.analysis.curve.clone());
            self.dragging = None;
        }
    }

    /// The system replaced whole (a preset, a model from the Identify mode), one undoable
    /// edit; the s-plane is fitted to it again.
    fn replace(&mut self, kept: &mut Saved, system: System) {
        if system.check().is_err() || system.placement().is_err() {
            return;
        }
        self.history.record(&kept.system);
        self.keep_ghost();
        kept.system = system;
        kept.splane.view = None;
        kept.splane.selected = None;
        self.dragging = None;
    }

    fn keep_ghost(&mut self) {
        self.ghost = Some(self.analysis.curve.clone());
    }

    /// Before a change of the loop's gain: the closed-loop curve it changes is the previous
    /// response (the open loop's does not move with Kp, so its ghost would be a system two
    /// edits old beside a closed loop that moves).
    fn keep_loop_ghost(&mut self, kept: &Saved) {
        if let Some(c) = self
            .feedback
            .closed
            .as_ref()
            .filter(|_| kept.feedback.closed)
        {
            self.ghost = Some(c.curve.clone());
        }
    }

    fn after_history_jump(&mut self, kept: &mut Saved) {
        self.keep_ghost();
        self.dragging = None;
        if let Some(sel) = kept.splane.selected
            && kept.system.root(sel).is_none()
        {
            kept.splane.selected = None;
        }
    }
}

/// The same system with its gain read in `mode`: k when it means k, G(0) when it means the
/// static gain (a system without a finite, non-zero G(0) keeps meaning k).
fn keep_system_in_mode(system: &mut System, mode: super::state::GainMode) {
    use super::state::GainMode;
    let Ok(tf) = system.transfer_function() else {
        system.gain_mode = mode;
        return;
    };
    let gain = match mode {
        GainMode::Zpk => tf.gain(),
        GainMode::Static => tf.dc_gain(),
    };
    if gain.is_finite() && gain != 0.0 {
        system.gain = gain;
        system.gain_mode = mode;
    }
}

/// The system of typed coefficients, keeping the gain's meaning, the dead time and the step
/// amplitude of `current`; `None` when they are not a system.
pub fn from_coefficients(current: &System, num: &[f64], den: &[f64]) -> Option<System> {
    let tf = degrau_lti::TransferFunction::from_coeffs(num, den)
        .and_then(|tf| tf.with_delay(current.delay))
        .ok()?;
    let mut system = System::from_transfer_function(&tf, current.amplitude);
    keep_system_in_mode(&mut system, current.gain_mode);
    Some(system)
}

/// Applies `change` to `system` when the result is a different, placeable system; true
/// when it did.
fn change_if_placeable(system: &mut System, change: impl FnOnce(&mut System)) -> bool {
    let mut candidate = system.clone();
    change(&mut candidate);
    let ok = candidate != *system && candidate.check().is_ok() && candidate.placement().is_ok();
    if ok {
        *system = candidate;
    }
    ok
}

/// Whether a root placed at (`re`, `im`) in `system` would be placeable, for a field to
/// refuse before committing: the reason when not.
pub fn placement_of(
    system: &System,
    id: RootId,
    re: f64,
    im: f64,
) -> Result<(), crate::field::LimitReason> {
    let mut candidate = system.clone();
    if let Some(r) = candidate.root_mut(id) {
        r.re = re;
        if r.kind == super::state::RootKind::Pair {
            r.im = im.abs();
        }
    }
    candidate.placement()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::state::{Root, RootRole};

    fn pole(index: usize) -> RootId {
        RootId {
            role: RootRole::Pole,
            index,
        }
    }

    #[test]
    fn a_drag_is_one_undoable_edit_and_the_analysis_follows_at_once() {
        let mut kept = Saved::default();
        let mut s = Session::new(&kept);
        let rise = s.analysis.info.as_ref().and_then(|i| i.rise_time);
        for k in 1..=5 {
            let re = -5.0 + 0.5 * k as f64;
            s.apply(
                &mut kept,
                Command::DragRoot {
                    id: pole(1),
                    re,
                    im: 0.0,
                },
            );
        }
        s.apply(&mut kept, Command::EndDrag);
        assert_eq!(kept.system.poles[1], Root::real(-2.5));
        assert!(s.analysis.is_for(&kept.system, &kept.options));
        assert_ne!(s.analysis.info.as_ref().and_then(|i| i.rise_time), rise);
        s.apply(&mut kept, Command::Undo);
        assert_eq!(
            kept.system,
            System::default(),
            "one undo undoes the whole drag"
        );
        assert!(!s.history.can_undo());
    }

    #[test]
    fn a_root_beyond_the_limits_is_never_applied() {
        let mut kept = Saved::default();
        let mut s = Session::new(&kept);
        let typed = [
            (-1e300, 0.0),
            (-2e6, 0.0),
            (-9e5, 9e5),
            (-1.0, -2.0),
            (f64::NAN, 1.0),
        ];
        for (re, im) in typed {
            s.apply(
                &mut kept,
                Command::SetRoot {
                    id: pole(0),
                    re,
                    im,
                },
            );
        }
        let tiny = Root::real(-1e-12);
        s.apply(
            &mut kept,
            Command::AddRoot {
                role: RootRole::Zero,
                root: tiny,
            },
        );
        assert_eq!(kept.system, System::default());
        assert!(!s.history.can_undo());
        assert_eq!(
            placement_of(&kept.system, pole(0), -1e300, 2.0),
            Err(crate::field::LimitReason::RootMagnitude)
        );
        // A drag stops at the limit, and a corner beyond |s| = 1e6 is not taken.
        let limit = crate::design::state::ROOT_LIMIT;
        s.apply(
            &mut kept,
            Command::DragRoot {
                id: pole(1),
                re: -1e300,
                im: 0.0,
            },
        );
        assert_eq!(kept.system.poles[1], Root::real(-limit));
        s.apply(
            &mut kept,
            Command::DragRoot {
                id: pole(0),
                re: -9e5,
                im: 9e5,
            },
        );
        assert_eq!(kept.system.poles[0], Root::pair(-1.0, 2.0));
    }

    #[test]
    fn a_preset_brings_its_comparison_and_its_analysis() {
        let mut kept = Saved::default();
        let mut s = Session::new(&kept);
        let last = s.presets.len() - 1;
        s.apply(&mut kept, Command::LoadPreset(last));
        assert_eq!(kept.system.counts(), (5, 0));
        let (_, b) = s.compare(&kept).expect("comparing");
        assert_eq!(b.system.counts(), (2, 0));
        s.apply(&mut kept, Command::StopComparing);
        assert!(s.compare(&kept).is_none() && s.compare_analysis.is_none());
    }
}
