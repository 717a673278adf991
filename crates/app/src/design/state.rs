//! The system a student edits, as the app holds it: roots (a real root or a conjugate pair
//! σ ± jω), the gain, the dead time and the step amplitude, with undo/redo history.
//! Nothing here draws; the views read these structs and the session changes them. What a
//! root is called ("pole 1", "zero") is said by [`crate::words::design`].

use serde::{Deserialize, Serialize};

use crate::field::LimitReason;
use degrau_lti::{C64, LtiError, TransferFunction};

/// Largest |σ|, |ω| and |s| of a root the app holds (1/s, rad/s): a root typed beyond it is
/// refused with the reason, a drag or an arrow key stops at it, a restored one is refused.
pub const ROOT_LIMIT: f64 = 1e6;
/// Largest ratio of the fastest root's |s| to the slowest (non-zero) one's: beyond it the
/// exact response cannot show both time scales, so such a placement is refused.
pub const SPREAD_LIMIT: f64 = 1e12;
/// Largest |k| or |G(0)| the app holds.
pub const GAIN_LIMIT: f64 = 1e100;
/// Largest |A| of the step.
pub const AMPLITUDE_LIMIT: f64 = 1e100;
/// Longest dead time θ the app holds (s, about 30 years).
pub const DELAY_LIMIT: f64 = 1e9;
/// Most handles (real roots or pairs) in the pole list and in the zero list.
pub const MAX_ROOTS: usize = 32;

/// `x` clamped to ±[`ROOT_LIMIT`] (NaN stays NaN, for [`System::check`] to refuse).
fn bounded(x: f64) -> f64 {
    x.clamp(-ROOT_LIMIT, ROOT_LIMIT)
}

/// A number of a system, as a problem with it names it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Quantity {
    /// A root's real part σ.
    Sigma(RootId),
    /// A root's imaginary part ω.
    Omega(RootId),
    Gain,
    Amplitude,
    Delay,
}

/// Why a system (or a part of it) is not one the app can hold; said in words by
/// [`crate::words::persist`].
#[derive(Debug, Clone, PartialEq)]
pub enum SystemProblem {
    /// Not a finite number within ±`limit`.
    OutOfRange {
        what: Quantity,
        value: f64,
        limit: f64,
    },
    /// A real root with ω ≠ 0.
    RealWithOmega { root: RootId, omega: f64 },
    /// A pair with ω < 0.
    NegativeOmega { root: RootId, omega: f64 },
    /// More handles in a list than the app holds ([`MAX_ROOTS`]).
    TooMany { role: RootRole, count: usize },
    /// A dead time below 0 (s).
    NegativeDelay(f64),
}

/// Whether `x` is finite with |x| ≤ `limit`, the problem when not.
fn check_number(what: Quantity, x: f64, limit: f64) -> Result<(), SystemProblem> {
    if x.is_finite() && x.abs() <= limit {
        Ok(())
    } else {
        Err(SystemProblem::OutOfRange {
            what,
            value: x,
            limit,
        })
    }
}

/// Whether a handle on the s-plane is one real root or a conjugate pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum RootKind {
    /// One root on the real axis at `re`.
    Real,
    /// Two roots re ± j·im (im ≥ 0; im = 0 is a double real root).
    Pair,
}

/// A pole or zero as the student places it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Root {
    pub kind: RootKind,
    /// Real part σ (1/s).
    pub re: f64,
    /// Imaginary part ω ≥ 0 of the upper member of a pair (rad/s); 0 for a real root.
    pub im: f64,
}

impl Root {
    /// A real root at `re` (clamped to ±[`ROOT_LIMIT`]).
    pub fn real(re: f64) -> Self {
        Self {
            kind: RootKind::Real,
            re: bounded(re),
            im: 0.0,
        }
    }

    /// A pair re ± j·|im| (each clamped to ±[`ROOT_LIMIT`]).
    pub fn pair(re: f64, im: f64) -> Self {
        Self {
            kind: RootKind::Pair,
            re: bounded(re),
            im: bounded(im.abs()),
        }
    }

    /// How many roots of the polynomial this handle stands for.
    pub fn count(&self) -> usize {
        match self.kind {
            RootKind::Real => 1,
            RootKind::Pair => 2,
        }
    }

    /// The roots themselves (a pair gives re + jω, re − jω).
    pub fn roots(&self) -> Vec<C64> {
        match self.kind {
            RootKind::Real => vec![C64::new(self.re, 0.0)],
            RootKind::Pair => vec![C64::new(self.re, self.im), C64::new(self.re, -self.im)],
        }
    }

    /// Moves the root to s (a real root stays on the axis; a pair follows |Im s|), clamped
    /// to ±[`ROOT_LIMIT`].
    pub fn move_to(&mut self, re: f64, im: f64) {
        self.re = bounded(re);
        if self.kind == RootKind::Pair {
            self.im = bounded(im.abs());
        }
    }

    /// Whether the root is one the app can hold: finite, within ±[`ROOT_LIMIT`], a real
    /// root on the axis and a pair's ω ≥ 0. `id` is where the root is in its system.
    pub fn check(&self, id: RootId) -> Result<(), SystemProblem> {
        check_number(Quantity::Sigma(id), self.re, ROOT_LIMIT)?;
        check_number(Quantity::Omega(id), self.im, ROOT_LIMIT)?;
        let omega = self.im;
        match self.kind {
            RootKind::Real if omega != 0.0 => Err(SystemProblem::RealWithOmega { root: id, omega }),
            RootKind::Pair if omega < 0.0 => Err(SystemProblem::NegativeOmega { root: id, omega }),
            _ => Ok(()),
        }
    }

    /// Natural frequency ωn = |s| (rad/s).
    pub fn natural_frequency(&self) -> f64 {
        self.re.hypot(self.im)
    }

    /// Damping ratio ζ = −σ/ωn (1 for a stable real root, undefined at the origin).
    pub fn damping(&self) -> Option<f64> {
        let wn = self.natural_frequency();
        (wn > 0.0).then(|| -self.re / wn)
    }

    /// The `−1 ± 2j` text of the handle, with `lang`'s decimal separator.
    pub fn label(&self, lang: degrau_words::Lang) -> String {
        let re = lang.num(self.re, 6);
        match self.kind {
            RootKind::Real => re,
            RootKind::Pair => format!("{re} ± {}j", lang.num(self.im, 6)),
        }
    }
}

/// Which list a root belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum RootRole {
    Pole,
    Zero,
}

/// A root addressed by role and position (0-based) in its list.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct RootId {
    pub role: RootRole,
    pub index: usize,
}

/// What "gain" means in the system panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum GainMode {
    /// k of k·Π(s − zᵢ)/Π(s − pⱼ) (MATLAB's zpk gain): moving roots changes G(0).
    Zpk,
    /// The static gain G(0) (the notes' "ganho estático"): moving roots keeps it.
    Static,
}

/// The system the student edits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct System {
    pub poles: Vec<Root>,
    pub zeros: Vec<Root>,
    pub gain: f64,
    pub gain_mode: GainMode,
    /// Transport delay θ (s).
    pub delay: f64,
    /// Step amplitude A.
    pub amplitude: f64,
}

impl Default for System {
    /// The course notes' third-order example: 0.5/((s² + 2s + 5)(s + 5)), step of 2.
    fn default() -> Self {
        Self {
            poles: vec![Root::pair(-1.0, 2.0), Root::real(-5.0)],
            zeros: vec![],
            gain: 0.5,
            gain_mode: GainMode::Zpk,
            delay: 0.0,
            amplitude: 2.0,
        }
    }
}

impl System {
    /// The transfer function, or why there is none (e.g. more zeros than poles).
    pub fn transfer_function(&self) -> Result<TransferFunction, LtiError> {
        let roots = |list: &[Root]| list.iter().flat_map(Root::roots).collect::<Vec<_>>();
        let (zeros, poles) = (roots(&self.zeros), roots(&self.poles));
        let tf = match self.gain_mode {
            GainMode::Zpk => TransferFunction::from_zpk(&zeros, &poles, self.gain)?,
            GainMode::Static => {
                TransferFunction::from_zpk(&zeros, &poles, 1.0)?.with_dc_gain(self.gain)?
            }
        };
        tf.with_delay(self.delay)
    }

    pub fn roots(&self, role: RootRole) -> &[Root] {
        match role {
            RootRole::Pole => &self.poles,
            RootRole::Zero => &self.zeros,
        }
    }

    pub fn roots_mut(&mut self, role: RootRole) -> &mut Vec<Root> {
        match role {
            RootRole::Pole => &mut self.poles,
            RootRole::Zero => &mut self.zeros,
        }
    }

    pub fn root(&self, id: RootId) -> Option<&Root> {
        self.roots(id.role).get(id.index)
    }

    pub fn root_mut(&mut self, id: RootId) -> Option<&mut Root> {
        self.roots_mut(id.role).get_mut(id.index)
    }

    /// Adds a root and returns its id.
    pub fn add(&mut self, role: RootRole, root: Root) -> RootId {
        let list = self.roots_mut(role);
        list.push(root);
        RootId {
            role,
            index: list.len() - 1,
        }
    }

    /// Removes a root; false if there was none with that id.
    pub fn remove(&mut self, id: RootId) -> bool {
        let list = self.roots_mut(id.role);
        if id.index < list.len() {
            list.remove(id.index);
            true
        } else {
            false
        }
    }

    /// Turns a real root into a pair σ ± jω (adding its mirror) or a pair into two real roots
    /// (when the list has room for one more handle).
    pub fn toggle_pair(&mut self, id: RootId, new_im: f64) {
        let Some(root) = self.root(id).copied() else {
            return;
        };
        match root.kind {
            RootKind::Real => {
                if let Some(r) = self.root_mut(id) {
                    *r = Root::pair(root.re, new_im);
                }
            }
            RootKind::Pair if self.has_room(id.role) => {
                if let Some(r) = self.root_mut(id) {
                    *r = Root::real(root.re);
                }
                self.roots_mut(id.role)
                    .insert(id.index + 1, Root::real(root.re));
            }
            // A full list keeps the pair rather than drop a root.
            RootKind::Pair => {}
        }
    }

    /// Number of poles (the order) and of zeros, counting pairs twice.
    pub fn counts(&self) -> (usize, usize) {
        let count = |l: &[Root]| l.iter().map(Root::count).sum();
        (count(&self.poles), count(&self.zeros))
    }

    /// True when some pole lies in the right half plane.
    pub fn has_rhp_pole(&self) -> bool {
        self.poles.iter().any(|p| p.re > 0.0)
    }

    /// The system of a transfer function (its roots as handles, its k, its delay), stepped
    /// by `amplitude`.
    pub fn from_transfer_function(tf: &TransferFunction, amplitude: f64) -> Self {
        let handles = |roots: &[C64]| -> Vec<Root> {
            roots
                .iter()
                .filter(|r| r.im >= 0.0)
                .map(|r| {
                    if r.im == 0.0 {
                        Root::real(r.re)
                    } else {
                        Root::pair(r.re, r.im)
                    }
                })
                .collect()
        };
        Self {
            poles: handles(tf.poles()),
            zeros: handles(tf.zeros()),
            gain: tf.gain(),
            gain_mode: GainMode::Zpk,
            delay: tf.delay(),
            amplitude,
        }
    }

    /// Whether another root fits in the `role` list ([`MAX_ROOTS`] handles at most).
    pub fn has_room(&self, role: RootRole) -> bool {
        self.roots(role).len() < MAX_ROOTS
    }

    /// Whether every number is one the app can hold (see the limits at the top of this
    /// module), the problem of the first that is not.
    pub fn check(&self) -> Result<(), SystemProblem> {
        check_roots(RootRole::Pole, &self.poles)?;
        check_roots(RootRole::Zero, &self.zeros)?;
        check_gain(self.gain)?;
        check_amplitude(self.amplitude)?;
        check_delay(self.delay)
    }

    /// Whether every root is one the exact response can show: |s| within [`ROOT_LIMIT`] and
    /// the fastest at most [`SPREAD_LIMIT`] times the slowest non-zero one; the reason when
    /// not.
    pub fn placement(&self) -> Result<(), LimitReason> {
        let magnitudes: Vec<f64> = self
            .poles
            .iter()
            .chain(&self.zeros)
            .map(Root::natural_frequency)
            .collect();
        if magnitudes
            .iter()
            .any(|m| !(m.is_finite() && *m <= ROOT_LIMIT))
        {
            return Err(LimitReason::RootMagnitude);
        }
        let nonzero = magnitudes.iter().copied().filter(|m| *m > 0.0);
        let (slowest, fastest) = nonzero.fold((f64::INFINITY, 0.0f64), |(lo, hi), m| {
            (lo.min(m), hi.max(m))
        });
        if fastest > SPREAD_LIMIT * slowest {
            return Err(LimitReason::RootSpread);
        }
        Ok(())
    }

    /// Every root id, poles first.
    pub fn ids(&self) -> Vec<RootId> {
        let ids = |role: RootRole, n: usize| (0..n).map(move |index| RootId { role, index });
        ids(RootRole::Pole, self.poles.len())
            .chain(ids(RootRole::Zero, self.zeros.len()))
            .collect()
    }
}

/// Whether a pole or zero list is one the app can hold: at most [`MAX_ROOTS`] handles, each
/// passing [`Root::check`].
pub fn check_roots(role: RootRole, list: &[Root]) -> Result<(), SystemProblem> {
    if list.len() > MAX_ROOTS {
        return Err(SystemProblem::TooMany {
            role,
            count: list.len(),
        });
    }
    list.iter()
        .enumerate()
        .try_for_each(|(index, root)| root.check(RootId { role, index }))
}

/// Whether a gain is finite within ±[`GAIN_LIMIT`].
pub fn check_gain(gain: f64) -> Result<(), SystemProblem> {
    check_number(Quantity::Gain, gain, GAIN_LIMIT)
}

/// Whether a step amplitude is finite within ±[`AMPLITUDE_LIMIT`].
pub fn check_amplitude(amplitude: f64) -> Result<(), SystemProblem> {
    check_number(Quantity::Amplitude, amplitude, AMPLITUDE_LIMIT)
}

/// Whether a dead time is finite in [0, [`DELAY_LIMIT`]] s.
pub fn check_delay(delay: f64) -> Result<(), SystemProblem> {
    check_number(Quantity::Delay, delay, DELAY_LIMIT)?;
    if delay < 0.0 {
        return Err(SystemProblem::NegativeDelay(delay));
    }
    Ok(())
}

/// Undo/redo of whole-system snapshots.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct History {
    undo: Vec<System>,
    redo: Vec<System>,
}

/// Most snapshots kept.
const HISTORY_LIMIT: usize = 500;

impl History {
    /// Records `before` as the state to return to; clears the redo list.
    pub fn record(&mut self, before: &System) {
        if self.undo.last() != Some(before) {
            self.undo.push(before.clone());
            if self.undo.len() > HISTORY_LIMIT {
                self.undo.remove(0);
            }
        }
        self.redo.clear();
    }

    /// Replaces `current` by the previous snapshot; false if there is none.
    pub fn undo(&mut self, current: &mut System) -> bool {
        match self.undo.pop() {
            Some(previous) => {
                self.redo.push(std::mem::replace(current, previous));
                true
            }
            None => false,
        }
    }

    /// Re-applies an undone edit; false if there is none.
    pub fn redo(&mut self, current: &mut System) -> bool {
        match self.redo.pop() {
            Some(next) => {
                self.undo.push(std::mem::replace(current, next));
                true
            }
            None => false,
        }
    }

    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_words::Localize;

    #[test]
    fn default_is_the_notes_example() {
        let tf = System::default().transfer_function().unwrap();
        let den = tf.den();
        assert!((den[3] - 25.0).abs() < 1e-12 && (den[1] - 7.0).abs() < 1e-12);
        assert_eq!(tf.gain(), 0.5);
    }

    #[test]
    fn static_gain_mode_keeps_g0() {
        let mut s = System {
            gain_mode: GainMode::Static,
            gain: 3.0,
            ..System::default()
        };
        s.poles[1].move_to(-2.0, 0.7);
        assert!((s.transfer_function().unwrap().dc_gain() - 3.0).abs() < 1e-12);
        assert_eq!(s.poles[1].im, 0.0, "a real root stays on the axis");
    }

    #[test]
    fn undo_and_redo_restore_exactly() {
        let mut s = System::default();
        let mut h = History::default();
        let original = s.clone();
        h.record(&s);
        s.poles[0].move_to(-0.3, 1.7);
        let moved = s.clone();
        assert!(h.undo(&mut s));
        assert_eq!(s, original);
        assert!(h.redo(&mut s));
        assert_eq!(s, moved);
        assert!(!h.redo(&mut s));
    }

    #[test]
    fn a_transfer_function_round_trips() {
        let s = System {
            delay: 0.4,
            ..System::default()
        };
        let tf = s.transfer_function().unwrap();
        assert_eq!(System::from_transfer_function(&tf, s.amplitude), s);
    }

    #[test]
    fn roots_stay_within_the_limit_and_bad_numbers_are_named() {
        let mut r = Root::real(-1e30);
        assert_eq!(ROOT_LIMIT, 1e6);
        assert_eq!(r.re, -ROOT_LIMIT);
        r.move_to(f64::INFINITY, 3.0);
        assert_eq!((r.re, r.im), (ROOT_LIMIT, 0.0));
        assert_eq!(Root::pair(0.0, -1e300).im, ROOT_LIMIT);
        assert!(System::default().check().is_ok());
        let mut s = System::default();
        s.poles[1].re = f64::NAN;
        let said = |s: &System| s.check().map_err(|e| e.text(degrau_words::Lang::En));
        let e = said(&s).unwrap_err();
        assert!(e.contains("pole 2: σ"), "{e}");
        let s = System {
            delay: -1.0,
            ..System::default()
        };
        assert!(said(&s).unwrap_err().contains("dead time"));
        let s = System {
            gain: f64::INFINITY,
            ..System::default()
        };
        assert!(said(&s).unwrap_err().contains("gain"));
        let s = System {
            zeros: vec![Root::real(-1.0); MAX_ROOTS + 1],
            ..System::default()
        };
        assert!(said(&s).unwrap_err().contains("zeros"));
    }

    #[test]
    fn placements_beyond_the_limits_are_named() {
        let mut s = System::default();
        assert_eq!(s.placement(), Ok(()));
        s.poles[1] = Root::pair(-0.8e6, 0.8e6);
        assert_eq!(
            s.placement(),
            Err(LimitReason::RootMagnitude),
            "|s| = 1.13e6"
        );
        s.poles[1] = Root::real(-1e6);
        assert_eq!(s.placement(), Ok(()));
        s.poles.push(Root::real(-1e-7));
        assert_eq!(
            s.placement(),
            Err(LimitReason::RootSpread),
            "1e13 times faster"
        );
        s.poles.pop();
        s.zeros.push(Root::real(0.0));
        assert_eq!(
            s.placement(),
            Ok(()),
            "a root at the origin has no time scale"
        );
    }

    #[test]
    fn pairs_split_and_join() {
        let mut s = System::default();
        let id = RootId {
            role: RootRole::Pole,
            index: 0,
        };
        s.toggle_pair(id, 0.0);
        assert_eq!(s.counts(), (3, 0));
        assert_eq!(s.poles[0], Root::real(-1.0));
        assert_eq!(s.poles[1], Root::real(-1.0));
        s.toggle_pair(id, 1.5);
        assert_eq!(s.counts(), (4, 0));
    }
}
