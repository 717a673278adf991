//! What the Design views ask for: every change to the design's state is one [`Command`],
//! returned by a view while it draws and applied by [`super::session::Session::apply`]
//! once per frame, after the views, so no view changes anything while drawing. The plain
//! settings a command carries that no lower module owns live here too ([`Markers`]).

use degrau_lti::StepInfoOptions;
use degrau_lti::feedback::{Input, PadeOrder};
use serde::{Deserialize, Serialize};

use super::closed_loop::{ControllerShape, Specs};

use super::plane::View;
use super::state::{GainMode, Root, RootId, RootRole, System};

/// One change to the design's state.
#[must_use = "a command does nothing until the session applies it"]
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// The gain (k or G(0), see [`GainMode`]), one undoable edit.
    SetGain(f64),
    SetGainMode(GainMode),
    /// The dead time θ (s).
    SetDelay(f64),
    /// The step amplitude A.
    SetAmplitude(f64),
    /// A root typed at σ = `re`, ω = `im` (one undoable edit).
    SetRoot {
        id: RootId,
        re: f64,
        im: f64,
    },
    /// A root dragged to `re`, `im`: the first move of a drag records the undo point, the
    /// rest of the drag is the same edit.
    DragRoot {
        id: RootId,
        re: f64,
        im: f64,
    },
    /// The drag (of a root) is over: the next one is a new edit.
    EndDrag,
    /// The selected root nudged by (`dre`, `dim`) (arrow keys).
    Nudge {
        id: RootId,
        dre: f64,
        dim: f64,
    },
    AddRoot {
        role: RootRole,
        root: Root,
    },
    RemoveRoot(RootId),
    /// A real root made a pair with ω = `im`, or a pair split into two real roots.
    TogglePair {
        id: RootId,
        im: f64,
    },
    Select(Option<RootId>),
    /// The example of that index in [`super::presets::presets`], with its comparison.
    LoadPreset(usize),
    /// A whole new system (from the Identify mode, a reset), one undoable edit.
    SetSystem(System),
    CompareWithCurrent,
    StopComparing,
    Undo,
    Redo,
    /// The s-plane's view (`None` fits it to the roots).
    SetView(Option<View>),
    SetDampingGrid(bool),
    SetSnap(bool),
    SetMarkers(Markers),
    SetOptions(StepInfoOptions),
    SetPhaseForm(bool),
    /// What the pointer is over on the s-plane (a readout), or nothing.
    Readout(Option<String>),
    /// The approximation view's choice ([`super::approx`]).
    Approx(super::approx_state::ApproxCommand),
    /// G(s) typed as coefficients (descending powers), one undoable edit keeping the gain's
    /// meaning, the dead time and the step.
    SetCoefficients {
        num: Vec<f64>,
        den: Vec<f64>,
    },
    /// Unity feedback around Kp·G(s) shown or not.
    SetLoopClosed(bool),
    /// The proportional gain Kp (typed or by the slider).
    SetKp(f64),
    /// A closed-loop pole of locus branch `branch` dragged towards s = `re` + j`im`: Kp
    /// becomes the gain that puts it nearest there on its branch.
    DragLoopPole {
        branch: usize,
        re: f64,
        im: f64,
    },
    /// The root locus drawn, and its complementary half.
    SetLocus {
        shown: bool,
        complementary: bool,
    },
    SetSpecs(Specs),
    /// Search the gain meeting the specs on the exact closed-loop response, and take it.
    FindGain,
    /// Replace the system by the canonical ωn²/(s² + 2ζωn s + ωn²).
    PlaceSecondOrder {
        zeta: f64,
        wn: f64,
    },
    /// The input whose response is plotted beside the step.
    SetInput(Input),
    /// The Padé order standing in for a dead time in the loop.
    SetPadeOrder(PadeOrder),
    /// The loop's controller shape (P, or a PI/PD/PID with Ti, Td, N; its gain is Kp).
    SetLoopController(ControllerShape),
}

/// Which markers the step plot draws (kept between runs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Markers {
    pub rise: bool,
    pub peak: bool,
    pub settling: bool,
    pub steady_state: bool,
    pub undershoot: bool,
    pub ghost: bool,
}

impl Default for Markers {
    fn default() -> Self {
        Self {
            rise: true,
            peak: true,
            settling: true,
            steady_state: true,
            undershoot: true,
            ghost: true,
        }
    }
}
