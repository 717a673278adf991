//! Projected Levenberg–Marquardt on a bounded least-squares problem ([`LeastSquaresProblem`]):
//! damped Gauss–Newton steps on the free parameters, clipped to the box, a parameter at a
//! bound with the descent pointing out of the box held there. Written here because the
//! `levenberg-marquardt` crate has no bounds, and its usual workaround, a change of variables,
//! can never reach a bound (a dead time of exactly 0) and distorts the Jacobian the
//! confidence intervals come from.

use nalgebra::{DMatrix, DVector};

use super::{LeastSquaresProblem, Normal, Run, Termination};

/// The most residuals a run keeps between its cost and its normal equations (two vectors of
/// their length); a longer problem computes them again.
const KEEP: usize = 1 << 17;

/// When Levenberg–Marquardt stops.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// Also when an accepted step lowers the cost by less than 1e-10 of itself.
    CostSettles,
    /// Only when the steps become negligible (or no step lowers the cost): the parameters to
    /// about 1e-10, whatever the rounding of the data.
    StepsSettle,
}

/// Projected Levenberg–Marquardt from `x`.
pub fn levenberg_marquardt<P: LeastSquaresProblem + ?Sized>(
    problem: &P,
    x: &[f64],
    max_iterations: usize,
    stop: Stop,
    report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
) -> Option<Run> {
    let n = problem.residual_count();
    let m = x.len();
    let (lower, upper, typical) = (problem.lower(), problem.upper(), problem.typical());
    // A record of up to KEEP samples keeps its residuals between the cost and the Jacobian.
    let keep = n <= KEEP;
    let mut r = vec![0.0; if keep { n } else { 0 }];
    let mut trial = r.clone();
    let mut x = x.to_vec();
    let mut sse = problem.cost(&x, keep.then_some(&mut r[..]))?;
    let mut lambda = 1e-3;
    let mut path = vec![x.clone()];
    let mut termination = Termination::IterationLimit;
    let mut iterations = 0;
    for iteration in 1..=max_iterations {
        iterations = iteration;
        if report(iteration, sse, &x) {
            termination = Termination::Cancelled;
            break;
        }
        let Normal { a, g } = problem.normal_equations(&x, keep.then_some(&r[..]))?;
        // With r = y − ŷ and J = ∂r/∂x the cost gradient is 2Jᵀr: descent is −Jᵀr.
        // Active set: at a bound with the descent direction pointing out of the box.
        let free: Vec<usize> = (0..m)
            .filter(|&i| !((x[i] <= lower[i] && g[i] > 0.0) || (x[i] >= upper[i] && g[i] < 0.0)))
            .collect();
        let gradient_norm = free
            .iter()
            .map(|&i| (g[i] * typical[i]).abs())
            .fold(0.0, f64::max);
        if gradient_norm <= 1e-12 * sse.max(f64::MIN_POSITIVE) || free.is_empty() {
            termination = Termination::Gradient;
            break;
        }
        let mut accepted = false;
        let mut step_small = false;
        for _ in 0..30 {
            let k = free.len();
            let mut lhs = DMatrix::zeros(k, k);
            let mut rhs = DVector::zeros(k);
            for (a_i, &i) in free.iter().enumerate() {
                rhs[a_i] = -g[i];
                for (a_j, &jj) in free.iter().enumerate() {
                    lhs[(a_i, a_j)] = a[(i, jj)];
                }
                lhs[(a_i, a_i)] += lambda * a[(i, i)].max(1e-12 / (typical[i] * typical[i]));
            }
            let Some(delta) = lhs.cholesky().map(|c| c.solve(&rhs)) else {
                lambda *= 10.0;
                continue;
            };
            let mut candidate = x.clone();
            for (a_i, &i) in free.iter().enumerate() {
                candidate[i] = (x[i] + delta[a_i]).clamp(lower[i], upper[i]);
            }
            step_small = free
                .iter()
                .all(|&i| (candidate[i] - x[i]).abs() <= 1e-10 * (x[i].abs() + typical[i]));
            if let Some(new_sse) = problem.cost(&candidate, keep.then_some(&mut trial[..]))
                && new_sse < sse
            {
                let relative = (sse - new_sse) / sse.max(f64::MIN_POSITIVE);
                let rho = (sse - new_sse) / predicted_reduction(&g, &a, &x, &candidate);
                x = candidate;
                std::mem::swap(&mut r, &mut trial);
                sse = new_sse;
                lambda = damping_after_success(lambda, rho);
                accepted = true;
                path.push(x.clone());
                if relative < 1e-10 && stop == Stop::CostSettles {
                    termination = Termination::SmallCostChange;
                }
                break;
            }
            if step_small {
                break;
            }
            lambda *= 4.0;
        }
        if termination == Termination::SmallCostChange {
            break;
        }
        if !accepted {
            termination = if path.len() == 1 {
                Termination::NoImprovement
            } else if step_small {
                Termination::SmallStep
            } else {
                Termination::SmallCostChange
            };
            break;
        }
    }
    Some(Run {
        x,
        sse,
        iterations,
        termination,
        path,
    })
}
/// The fall of the sum of squares that the linearised model predicts for the step from `x`
/// to `candidate`: S − |r + Jd|² = −(2gᵀd + dᵀAd), with g = Jᵀr and A = JᵀJ.
fn predicted_reduction(g: &DVector<f64>, a: &DMatrix<f64>, x: &[f64], candidate: &[f64]) -> f64 {
    let d = DVector::from_iterator(x.len(), x.iter().zip(candidate).map(|(x, c)| c - x));
    -(2.0 * g.dot(&d) + d.dot(&(a * &d)))
}

/// The damping after an accepted step, from the gain ratio ρ = actual / predicted fall
/// (Moré's rule): a step the linear model overrated (ρ < 1/4, as on a poor fit with large
/// residuals, where Gauss–Newton steps overshoot and zigzag along the valley) doubles λ; a
/// step it predicted well (ρ > 3/4) divides λ by three.
fn damping_after_success(lambda: f64, rho: f64) -> f64 {
    if rho.is_nan() || rho < 0.25 {
        (lambda * 2.0).max(1e-6)
    } else if rho > 0.75 {
        (lambda / 3.0).max(1e-12)
    } else {
        lambda
    }
}
