//! The Nyquist diagram of the loop L(s) = C(s)·G0(s)·e^{−θs}, the dead time exact: the curve
//! L(jω) for ω > 0 and the Nyquist criterion read from it ([`nyquist`]).
//!
//! The Nyquist contour runs up the imaginary axis from −jR to jR, round every open-loop pole
//! on the axis by a small half-circle to its right, and back by the half-circle |s| = R in
//! the right half-plane: clockwise round the right half-plane. By the argument principle the
//! image of 1 + L = χ/d (χ = d + n·e^{−θs} the closed loop's characteristic quasi-polynomial,
//! d = d_c·d_g, n = n_c·n_g, nothing cancelled) goes N times clockwise round 0, that is L's
//! image round −1, with N = Z − P: Z the closed-loop roots in the right half-plane and P the
//! roots of d there. The image of the lower half of the contour mirrors the upper half's, so
//! the upper half is walked (from s = 0, or round a pole at 0 from its right, to jR, then the
//! arc to R) and its turning doubled. Steps are taken so that 1 + L moves less than 0.2·|1 + L|
//! (and L less than 0.02·(|L| + 0.25), so the curve drawn is smooth); R is taken where a bound
//! keeps 1 + L within a disc that excludes 0 on the whole arc, so the arc adds only its
//! principal angle, and L within 1e-3 of its high-frequency limit, where the curve drawn ends.
//!
//! This counts the same Z as [`super::frequency::closed_loop_unstable_roots`] by a different
//! route (the winding of 1 + L itself, the open-loop poles on the axis indented rather than
//! moved), which is what the Nyquist view shows beside it; the tests check both against the
//! closed-loop polynomial's roots.

use std::f64::consts::{FRAC_PI_2, PI};

use serde::Serialize;

use crate::TransferFunction;
use crate::control::Controller;
use crate::control::frequency::StabilityError;
use crate::poly::{self, C64};

/// One point of the Nyquist curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NyquistPoint {
    /// ω (rad/s), > 0.
    pub w: f64,
    /// L(jω).
    pub l: C64,
}

/// The Nyquist diagram of a loop and its criterion ([`nyquist`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Nyquist {
    /// L(jω) for increasing ω > 0 (the ω < 0 branch is its mirror, the complex conjugate),
    /// up to where |L| has come within 1e-3 of its high-frequency limit; the branches that
    /// go to infinity at a pole on the axis are left out.
    pub curve: Vec<NyquistPoint>,
    /// N: the clockwise encirclements of −1 by L's image of the whole contour.
    pub encirclements: i64,
    /// P: the open-loop poles (controller's and plant's, none cancelled) in the open right
    /// half-plane.
    pub open_loop_unstable: usize,
    /// The open-loop poles on the imaginary axis (the contour goes round them).
    pub imaginary_poles: usize,
    /// Z = N + P: the closed loop's roots in the open right half-plane.
    pub closed_loop_unstable: i64,
}

/// The most steps of the walk before giving up.
const MAX_STEPS: usize = 4_000_000;

/// The largest step of the curve drawn, relative to |L| + 0.25.
const DRAWN: f64 = 0.02;

/// How close to its high-frequency limit |L| comes before the curve ends.
const SETTLED: f64 = 1e-3;

/// The indentation's radius, relative to the distance to the nearest other root.
const INDENT: f64 = 1e-4;

/// The Nyquist diagram of the unity-feedback loop L = C·G and the closed loop's right
/// half-plane roots it counts ([`Nyquist`]). Fails when a closed-loop root lies on the
/// imaginary axis ([`StabilityError::Marginal`]), when the loop is neutral with
/// |L(∞)| ≥ 1 or not well posed, or when the count does not close on a whole number.
pub fn nyquist(plant: &TransferFunction, c: &Controller) -> Result<Nyquist, StabilityError> {
    let setup = Setup::of(plant, c)?;
    let mut walk = Walk::new(&setup);
    let mut start = 0.0;
    if setup.axis_poles.first() == Some(&0.0) {
        let eps = walk.indent(0.0)?;
        walk.path(|phi| C64::from_polar(eps, phi), 0.0, FRAC_PI_2, false)?;
        start = eps;
    }
    for &w0 in setup.axis_poles.iter().filter(|&&w| w > 0.0) {
        let eps = walk.indent(w0)?;
        walk.axis(start, w0 - eps)?;
        let centre = C64::new(0.0, w0);
        walk.path(
            |phi| centre + C64::from_polar(eps, phi),
            -FRAC_PI_2,
            FRAC_PI_2,
            false,
        )?;
        start = w0 + eps;
    }
    walk.axis(start, setup.radius)?;
    // The big arc, from jR to R: 1 + L stays in a disc that excludes 0.
    let r = setup.radius;
    let top = walk.one_plus_l(C64::new(0.0, r));
    let end = walk.one_plus_l(C64::new(r, 0.0));
    let turned = 2.0 * (walk.turned + (end / top).arg());
    let n = -turned / (2.0 * PI);
    let whole = n.round();
    if (n - whole).abs() > 0.05 {
        return Err(StabilityError::Unresolved { count: n });
    }
    let encirclements = whole as i64;
    Ok(Nyquist {
        curve: walk.curve,
        encirclements,
        open_loop_unstable: setup.unstable,
        imaginary_poles: setup.axis_count,
        closed_loop_unstable: encirclements + setup.unstable as i64,
    })
}

/// What the walk needs to know of the loop.
struct Setup<'a> {
    plant: &'a TransferFunction,
    c: &'a Controller,
    /// The distinct ω ≥ 0 of d's roots on the imaginary axis, increasing.
    axis_poles: Vec<f64>,
    /// Every root of d and n (to size the indentations).
    roots: Vec<C64>,
    /// How many of d's roots lie on the axis (both halves, with multiplicity).
    axis_count: usize,
    /// How many lie in the open right half-plane.
    unstable: usize,
    /// The arc's radius.
    radius: f64,
    /// |L(∞)|'s high-frequency limit (0 unless biproper).
    l_inf: f64,
}

impl<'a> Setup<'a> {
    fn of(plant: &'a TransferFunction, c: &'a Controller) -> Result<Self, StabilityError> {
        let (nc, dc) = c.feedback_coeffs();
        let mut poles = poly::roots(&dc).map_err(|_| StabilityError::Roots)?;
        poles.extend_from_slice(plant.poles());
        let mut zeros = poly::roots(&nc).map_err(|_| StabilityError::Roots)?;
        zeros.extend_from_slice(plant.zeros());
        let n = crate::locus::multiply(&nc, &plant.num());
        let d = crate::locus::multiply(&dc, &plant.den());
        let l_inf = if n.len() == d.len() { n[0] / d[0] } else { 0.0 };
        let delay = plant.delay() > 0.0;
        if delay && l_inf.abs() >= 1.0 {
            return Err(StabilityError::Neutral { ratio: l_inf.abs() });
        }
        let target = if delay {
            0.5 * (1.0 - l_inf.abs())
        } else {
            0.5 * (1.0 + l_inf).abs()
        };
        if !delay && (1.0 + l_inf).abs() <= 1e-12 {
            return Err(StabilityError::IllPosed);
        }
        let radius = arc_radius(&n, &d, &poles, l_inf, target.min(SETTLED)).ok_or(
            StabilityError::Unresolved {
                count: f64::INFINITY,
            },
        )?;
        let on_axis: Vec<f64> = poles.iter().filter(|p| p.re == 0.0).map(|p| p.im).collect();
        let mut axis_poles: Vec<f64> = on_axis.iter().map(|w| w.abs()).collect();
        axis_poles.sort_by(f64::total_cmp);
        axis_poles.dedup();
        let mut roots = poles.clone();
        roots.extend(zeros);
        Ok(Self {
            plant,
            c,
            axis_poles,
            roots,
            axis_count: on_axis.len(),
            unstable: poles.iter().filter(|p| p.re > 0.0).count(),
            radius,
            l_inf: l_inf.abs(),
        })
    }

    /// The distance from jω0 to the nearest other root (or a scale of ω0 when there is none).
    fn room_at(&self, w0: f64) -> f64 {
        let centre = C64::new(0.0, w0);
        let nearest = self
            .roots
            .iter()
            .map(|r| (r - centre).norm())
            .filter(|&d| d > 0.0)
            .fold(f64::INFINITY, f64::min);
        if nearest.is_finite() {
            nearest
        } else {
            w0.max(1.0)
        }
    }
}

/// A radius R past which, on the whole right half of |s| = R, |n/d − L∞| ≤ `target`:
/// |n − L∞·d| bounded by its coefficients' sum and |d| from below by its roots.
fn arc_radius(n: &[f64], d: &[f64], poles: &[C64], l_inf: f64, target: f64) -> Option<f64> {
    let mut p: Vec<f64> = d.iter().map(|c| -l_inf * c).collect();
    let offset = d.len() - n.len();
    for (i, c) in n.iter().enumerate() {
        p[offset + i] += c;
    }
    let largest = poles.iter().map(|r| r.norm()).fold(0.0, f64::max);
    let mut radius = (2.0 * largest).max(1e-6);
    let degree = d.len() - 1;
    for _ in 0..400 {
        let top = p.len() - 1;
        let over: f64 = p
            .iter()
            .enumerate()
            .map(|(i, c)| c.abs() * radius.powi(top as i32 - i as i32 - degree as i32))
            .sum();
        let floor: f64 = poles.iter().map(|r| 1.0 - r.norm() / radius).product();
        if over / (d[0].abs() * floor) <= target {
            return Some(radius);
        }
        radius *= 2.0;
    }
    None
}

/// The walk along the upper half of the contour: 1 + L's turning and the curve drawn.
struct Walk<'s, 'a> {
    setup: &'s Setup<'a>,
    turned: f64,
    curve: Vec<NyquistPoint>,
    steps: usize,
}

impl<'s, 'a> Walk<'s, 'a> {
    fn new(setup: &'s Setup<'a>) -> Self {
        Self {
            setup,
            turned: 0.0,
            curve: Vec::new(),
            steps: 0,
        }
    }

    fn l(&self, s: C64) -> C64 {
        self.setup.c.eval(s) * self.setup.plant.eval(s)
    }

    fn one_plus_l(&self, s: C64) -> C64 {
        self.l(s) + 1.0
    }

    /// Up the imaginary axis from jω `from` to jω `to`, the curve kept.
    fn axis(&mut self, from: f64, to: f64) -> Result<(), StabilityError> {
        if to <= from {
            return Ok(());
        }
        let first = self.l(C64::new(0.0, from));
        if from > 0.0 {
            self.push(from, first);
        }
        self.path(|w| C64::new(0.0, w), from, to, true)
    }

    /// The radius of the indentation round the pole at jω0: a small part of the room round
    /// it, made smaller until |L| ≥ 4 on it, so that no closed-loop root lies inside (|L| = 1
    /// there). A pole whose |L| stays small is cancelled by a zero: a closed-loop root on the
    /// axis.
    fn indent(&self, w0: f64) -> Result<f64, StabilityError> {
        let room = self.setup.room_at(w0);
        let centre = C64::new(0.0, w0);
        let mut eps = INDENT * room;
        while eps > 1e-13 * room.max(w0) {
            let large = [-FRAC_PI_2, 0.0, FRAC_PI_2]
                .iter()
                .all(|&phi| self.l(centre + C64::from_polar(eps, phi)).norm() >= 4.0);
            if large {
                return Ok(eps);
            }
            eps *= 1e-2;
        }
        Err(StabilityError::Marginal { w: w0 })
    }

    /// Walks s(t) for t from `from` to `to`, adding 1 + L's turning.
    fn path(
        &mut self,
        s: impl Fn(f64) -> C64,
        from: f64,
        to: f64,
        draw: bool,
    ) -> Result<(), StabilityError> {
        let span = to - from;
        let mut t = from;
        let mut step = span * 1e-6;
        let mut prev = self.l(s(t));
        while t < to {
            self.steps += 1;
            if self.steps > MAX_STEPS {
                return Err(StabilityError::Unresolved { count: f64::NAN });
            }
            let h = step.min(to - t);
            let mid = self.l(s(t + 0.5 * h));
            let next = self.l(s(t + h));
            let one = prev + 1.0;
            let vanished = one.norm() <= 1e-13 * (1.0 + prev.norm()) || one.norm().is_nan();
            if vanished {
                return Err(StabilityError::Marginal { w: s(t).im });
            }
            let tol = (0.2 * one.norm()).min(DRAWN * (prev.norm() + 0.25));
            let tol = if draw { tol } else { 0.2 * one.norm() };
            if (next - prev).norm() <= tol && (mid - prev).norm() <= tol {
                self.turned += ((next + 1.0) / one).arg();
                t += h;
                prev = next;
                step = 1.5 * h;
                if draw {
                    self.push(s(t).im, next);
                }
            } else {
                step = 0.5 * h;
                if step <= 4.0 * f64::EPSILON * t.abs().max(span.abs()) {
                    return Err(StabilityError::Marginal { w: s(t).im });
                }
            }
        }
        Ok(())
    }

    /// Keeps a point of the curve until L has settled at its high-frequency limit.
    fn push(&mut self, w: f64, l: C64) {
        let settled = (l.norm() - self.setup.l_inf).abs() < SETTLED && self.curve.len() > 1;
        let last_settled = self
            .curve
            .last()
            .is_some_and(|p| (p.l.norm() - self.setup.l_inf).abs() < SETTLED);
        if !(settled && last_settled) && l.norm().is_finite() {
            self.curve.push(NyquistPoint { w, l });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tf(num: &[f64], den: &[f64]) -> TransferFunction {
        TransferFunction::from_coeffs(num, den).unwrap()
    }

    #[test]
    fn a_stable_first_order_loop_does_not_encircle() {
        let n = nyquist(
            &tf(&[2.0], &[1.0, 1.0]),
            &Controller::proportional(1.0).unwrap(),
        )
        .unwrap();
        assert_eq!(
            (
                n.encirclements,
                n.open_loop_unstable,
                n.closed_loop_unstable
            ),
            (0, 0, 0)
        );
        assert!((n.curve[0].l.re - 2.0).abs() < 1e-5);
    }

    #[test]
    fn the_triple_pole_loop_turns_unstable_at_eight() {
        let g = tf(&[1.0], &[1.0, 3.0, 3.0, 1.0]);
        for (k, z) in [(7.9, 0), (8.1, 2)] {
            let n = nyquist(&g, &Controller::proportional(k).unwrap()).unwrap();
            assert_eq!(n.closed_loop_unstable, z, "K = {k}");
            assert_eq!(n.encirclements, z);
        }
    }

    #[test]
    fn an_unstable_plant_stabilised_counts_a_counterclockwise_turn() {
        // 1/(s − 1) under K = 2: closed loop s + 1, stable; P = 1, so N = −1.
        let n = nyquist(
            &tf(&[1.0], &[1.0, -1.0]),
            &Controller::proportional(2.0).unwrap(),
        )
        .unwrap();
        assert_eq!(
            (
                n.encirclements,
                n.open_loop_unstable,
                n.closed_loop_unstable
            ),
            (-1, 1, 0)
        );
    }

    #[test]
    fn integrators_are_indented() {
        // K/(s(s + 1)(s + 2)): unstable past K = 6.
        let g = tf(&[1.0], &[1.0, 3.0, 2.0, 0.0]);
        for (k, z) in [(5.0, 0), (7.0, 2)] {
            let n = nyquist(&g, &Controller::proportional(k).unwrap()).unwrap();
            assert_eq!(
                (n.imaginary_poles, n.closed_loop_unstable),
                (1, z),
                "K = {k}"
            );
        }
        // A double integrator with a lead: (s + 1)/s² is stable for every K > 0.
        let n = nyquist(
            &tf(&[1.0, 1.0], &[1.0, 0.0, 0.0]),
            &Controller::proportional(3.0).unwrap(),
        )
        .unwrap();
        assert_eq!((n.imaginary_poles, n.closed_loop_unstable), (2, 0));
    }

    #[test]
    fn the_dead_time_is_exact() {
        // 1/(10s + 1)·e^{−2s}: Kcr = 8.5024.
        let g = tf(&[1.0], &[10.0, 1.0]).with_delay(2.0).unwrap();
        for (k, z) in [(8.4, 0), (8.6, 2)] {
            let n = nyquist(&g, &Controller::proportional(k).unwrap()).unwrap();
            assert_eq!(n.closed_loop_unstable, z, "K = {k}");
        }
    }

    #[test]
    fn a_closed_loop_root_on_the_axis_is_marginal() {
        let g = tf(&[1.0], &[1.0, 3.0, 3.0, 1.0]);
        let e = nyquist(&g, &Controller::proportional(8.0).unwrap()).unwrap_err();
        assert!(matches!(e, StabilityError::Marginal { .. }), "{e:?}");
    }
}
