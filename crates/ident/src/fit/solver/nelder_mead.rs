//! Bounded Nelder–Mead (MATLAB's `fminsearch`, the notes' method) on a least-squares
//! problem's sum of squares: fminsearch's initial simplex and coefficients, every vertex
//! clamped to the box. Written here for the bounds and to report its path as
//! Levenberg–Marquardt does; `argmin` would add its trait machinery for sixty lines of
//! algorithm.

use super::{LeastSquaresProblem, Run, Termination};

/// Bounded Nelder–Mead on the sum of squares from `x` (fminsearch's simplex and
/// coefficients).
pub fn nelder_mead<P: LeastSquaresProblem + ?Sized>(
    problem: &P,
    x: &[f64],
    max_iterations: usize,
    report: &mut dyn FnMut(usize, f64, &[f64]) -> bool,
) -> Option<Run> {
    let m = x.len();
    let typical = problem.typical();
    let f = |p: &[f64]| problem.cost(p, None).unwrap_or(f64::INFINITY);
    let mut simplex: Vec<(Vec<f64>, f64)> = Vec::with_capacity(m + 1);
    simplex.push((x.to_vec(), f(x)));
    for i in 0..m {
        let mut p = x.to_vec();
        p[i] = if p[i] != 0.0 { 1.05 * p[i] } else { 0.00025 };
        let p = problem.clamp(p);
        let v = f(&p);
        simplex.push((p, v));
    }
    let mut path = vec![x.to_vec()];
    let mut termination = Termination::IterationLimit;
    let mut iterations = 0;
    for iteration in 1..=max_iterations {
        iterations = iteration;
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        if report(iteration, simplex[0].1, &simplex[0].0) {
            termination = Termination::Cancelled;
            break;
        }
        if path.last() != Some(&simplex[0].0) {
            path.push(simplex[0].0.clone());
        }
        let spread_f = (simplex[m].1 - simplex[0].1).abs();
        let spread_x = simplex[1..]
            .iter()
            .flat_map(|(p, _)| {
                p.iter()
                    .zip(&simplex[0].0)
                    .enumerate()
                    .map(|(i, (a, b))| (a - b).abs() / (b.abs() + typical[i]))
            })
            .fold(0.0, f64::max);
        if spread_f <= 1e-12 * simplex[0].1.abs().max(f64::MIN_POSITIVE) && spread_x <= 1e-9 {
            termination = Termination::SmallStep;
            break;
        }
        let centroid: Vec<f64> = (0..m)
            .map(|i| simplex[..m].iter().map(|s| s.0[i]).sum::<f64>() / m as f64)
            .collect();
        let along = |t: f64| {
            problem.clamp(
                centroid
                    .iter()
                    .zip(&simplex[m].0)
                    .map(|(c, w)| c + t * (w - c))
                    .collect(),
            )
        };
        let reflected = along(-1.0);
        let fr = f(&reflected);
        if fr < simplex[0].1 {
            let expanded = along(-2.0);
            let fe = f(&expanded);
            simplex[m] = if fe < fr {
                (expanded, fe)
            } else {
                (reflected, fr)
            };
        } else if fr < simplex[m - 1].1 {
            simplex[m] = (reflected, fr);
        } else {
            let (contracted, fc) = if fr < simplex[m].1 {
                let c = along(-0.5);
                let v = f(&c);
                (c, v)
            } else {
                let c = along(0.5);
                let v = f(&c);
                (c, v)
            };
            if fc < simplex[m].1.min(fr) {
                simplex[m] = (contracted, fc);
            } else {
                let best = simplex[0].0.clone();
                for s in simplex.iter_mut().skip(1) {
                    let p = problem.clamp(
                        best.iter()
                            .zip(&s.0)
                            .map(|(b, v)| b + 0.5 * (v - b))
                            .collect(),
                    );
                    let v = f(&p);
                    *s = (p, v);
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
    let (x, sse) = simplex.swap_remove(0);
    let unmoved = path.len() == 1 && x == path[0];
    let termination = if unmoved && termination != Termination::Cancelled {
        Termination::NoImprovement
    } else {
        termination
    };
    sse.is_finite().then_some(Run {
        x,
        sse,
        iterations,
        termination,
        path,
    })
}
