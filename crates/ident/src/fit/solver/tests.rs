//! Known answers of the solvers on a problem with no model in it: Rosenbrock's function as
//! least squares, r = (10·(x₂ − x₁²), 1 − x₁), minimum S = 0 at (1, 1) (Moré, Garbow and
//! Hillstrom 1981, problem 1, the `levenberg-marquardt` crate's first test), and the same
//! with x₁ ≤ ½, whose minimum is on the bound: x₂ = x₁² zeroes the first residual, so the
//! optimum is (½, ¼) with S = ¼.

use nalgebra::{DMatrix, DVector};

use super::lm::{Stop, levenberg_marquardt};
use super::nelder_mead::nelder_mead;
use super::{LeastSquaresProblem, Normal, Termination};

struct Rosenbrock {
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl Rosenbrock {
    fn free() -> Self {
        Self::up_to(f64::INFINITY)
    }
    fn up_to(x1_max: f64) -> Self {
        Rosenbrock {
            lower: vec![f64::NEG_INFINITY; 2],
            upper: vec![x1_max, f64::INFINITY],
        }
    }
    fn residuals(x: &[f64]) -> [f64; 2] {
        [10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]]
    }
}

impl LeastSquaresProblem for Rosenbrock {
    fn lower(&self) -> &[f64] {
        &self.lower
    }
    fn upper(&self) -> &[f64] {
        &self.upper
    }
    fn typical(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn residual_count(&self) -> usize {
        2
    }
    fn cost(&self, x: &[f64], keep: Option<&mut [f64]>) -> Option<f64> {
        let r = Self::residuals(x);
        if let Some(keep) = keep {
            keep.copy_from_slice(&r);
        }
        Some(r[0] * r[0] + r[1] * r[1])
    }
    fn normal_equations(&self, x: &[f64], _known: Option<&[f64]>) -> Option<Normal> {
        let j = DMatrix::from_row_slice(2, 2, &[-20.0 * x[0], 10.0, -1.0, 0.0]);
        let r = DVector::from_column_slice(&Self::residuals(x));
        Some(Normal {
            a: j.transpose() * &j,
            g: j.transpose() * r,
        })
    }
}

fn never(_: usize, _: f64, _: &[f64]) -> bool {
    false
}

fn close(x: &[f64], to: [f64; 2], tolerance: f64) -> bool {
    x.iter().zip(to).all(|(a, b)| (a - b).abs() <= tolerance)
}

#[test]
fn levenberg_marquardt_finds_rosenbrocks_minimum() {
    let run = levenberg_marquardt(
        &Rosenbrock::free(),
        &[-1.2, 1.0],
        200,
        Stop::StepsSettle,
        &mut never,
    )
    .expect("a run");
    assert!(close(&run.x, [1.0, 1.0], 1e-8), "{:?}", run.x);
    assert!(run.sse < 1e-16, "{}", run.sse);
    assert_ne!(run.termination, Termination::IterationLimit);
    assert!(run.path.len() > 2 && run.path[0] == [-1.2, 1.0]);
}

#[test]
fn levenberg_marquardt_stops_on_the_bound() {
    let run = levenberg_marquardt(
        &Rosenbrock::up_to(0.5),
        &[-1.2, 1.0],
        200,
        Stop::StepsSettle,
        &mut never,
    )
    .expect("a run");
    assert_eq!(run.x[0], 0.5, "held exactly on its bound");
    assert!(close(&run.x, [0.5, 0.25], 1e-8), "{:?}", run.x);
    assert!((run.sse - 0.25).abs() < 1e-12, "{}", run.sse);
}

#[test]
fn nelder_mead_finds_both_minima() {
    for (problem, optimum, cost) in [
        (Rosenbrock::free(), [1.0, 1.0], 0.0),
        (Rosenbrock::up_to(0.5), [0.5, 0.25], 0.25),
    ] {
        let run = nelder_mead(&problem, &[-1.2, 1.0], 5000, &mut never).expect("a run");
        assert!(close(&run.x, optimum, 1e-4), "{:?}", run.x);
        assert!((run.sse - cost).abs() < 1e-8, "{}", run.sse);
        assert!(run.x[0] <= 0.5 || optimum[0] == 1.0, "inside the box");
        // Its cost test is relative to the best cost: on a record's noise it ends the
        // search, but at an exact zero it never holds, and the iteration limit does.
        if cost > 0.0 {
            assert_eq!(run.termination, Termination::SmallStep);
        }
    }
}

#[test]
fn a_cancelled_run_says_so() {
    let mut cancel = |_: usize, _: f64, _: &[f64]| true;
    let run = levenberg_marquardt(
        &Rosenbrock::free(),
        &[-1.2, 1.0],
        200,
        Stop::CostSettles,
        &mut cancel,
    )
    .expect("a run");
    assert_eq!(run.termination, Termination::Cancelled);
    assert_eq!(run.x, [-1.2, 1.0]);
    let run = nelder_mead(&Rosenbrock::free(), &[-1.2, 1.0], 200, &mut cancel).expect("a run");
    assert_eq!(run.termination, Termination::Cancelled);
}
