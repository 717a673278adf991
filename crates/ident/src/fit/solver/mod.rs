//! The solvers of a bounded nonlinear least-squares problem, apart from any model: minimise
//! S(x) = Σ rᵢ(x)² over lower ≤ x ≤ upper. A problem ([`LeastSquaresProblem`]) gives its bounds, the
//! sum of squares and the normal equations of its linearisation; a solver knows nothing of
//! records or process models (as the `levenberg-marquardt` crate keeps its `LeastSquaresProblem`
//! apart from its solver).
//!
//! - [`lm`]: projected Levenberg–Marquardt (steps clipped to the box, parameters held at an
//!   active bound removed from the step);
//! - [`nelder_mead`]: `fminsearch`'s simplex, kept in the box by clamping.

pub mod lm;
pub mod nelder_mead;
#[cfg(test)]
mod tests;

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

/// Why the optimiser stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    /// The gradient (projected onto the bounds) vanished.
    Gradient,
    /// Steps became negligible.
    SmallStep,
    /// The cost stopped decreasing.
    SmallCostChange,
    /// The iteration limit was reached.
    IterationLimit,
    /// The student cancelled.
    Cancelled,
    /// No step lowered the cost from the start: the values are the start's.
    NoImprovement,
}

/// One optimiser run, in internal units.
pub struct Run {
    pub x: Vec<f64>,
    /// Sum of squared residuals (internal units).
    pub sse: f64,
    pub iterations: usize,
    pub termination: Termination,
    pub path: Vec<Vec<f64>>,
}

/// The normal equations of the linearised problem at a point: A = JᵀJ, g = Jᵀr.
pub struct Normal {
    pub a: DMatrix<f64>,
    pub g: DVector<f64>,
}

/// A bounded nonlinear least-squares problem in p parameters: S(x) = Σ rᵢ(x)² with
/// lower ≤ x ≤ upper.
pub trait LeastSquaresProblem {
    /// The lower bound of each parameter (−∞ for none).
    fn lower(&self) -> &[f64];
    /// The upper bound of each parameter (+∞ for none).
    fn upper(&self) -> &[f64];
    /// Each parameter's typical magnitude: the scale of its steps and tolerances.
    fn typical(&self) -> &[f64];
    /// How many residuals rᵢ there are (a solver keeps them between the cost and the
    /// normal equations when there are few enough).
    fn residual_count(&self) -> usize;
    /// S(x), the residuals written into `keep` when given (of [`Self::residual_count`]
    /// length); `None` where S cannot be evaluated or is not finite.
    fn cost(&self, x: &[f64], keep: Option<&mut [f64]>) -> Option<f64>;
    /// The normal equations at `x` ([`Normal`]); `known` are the residuals at `x` when the
    /// solver kept them. `None` where they are not finite.
    fn normal_equations(&self, x: &[f64], known: Option<&[f64]>) -> Option<Normal>;
    /// `x` moved into the box.
    fn clamp(&self, mut x: Vec<f64>) -> Vec<f64> {
        for ((v, lo), hi) in x.iter_mut().zip(self.lower()).zip(self.upper()) {
            *v = v.clamp(*lo, *hi);
        }
        x
    }
}
