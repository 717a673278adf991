//! Approximations of a system by a simpler one, and what each costs: the reductions of the
//! Tognetti notes ([`reduce`]: dominant poles, Taylor, Skogestad's half rule, Padé moment
//! matching G_{m,n}), the rational stand-ins for a dead time ([`pade`]: Padé (m, n),
//! 1 − θs, 1/(1 + θs), (1 + θs/n)^{−n}), and the measure of the error between two exact step
//! responses ([`compare`]: max |Δy|, ISE, each step metric's difference).
//!
//! Every model here is a [`TransferFunction`]: a dead time stays a true delay, and every
//! response and metric comes from the exact core ([`StepResponse`], [`StepInfo`]).
//!
//! [`StepResponse`]: super::StepResponse
//! [`StepInfo`]: super::StepInfo

pub mod compare;
pub mod pade;
pub mod reduce;

use serde::{Deserialize, Serialize};

use super::{C64, LtiError, StepInfoOptions, StepResponse, TransferFunction};

pub use compare::{Comparison, MetricDifference, WITHIN, compare};
pub use pade::{
    DelayApproximant, DelayFactor, delay_factor, delay_free_with_pade, pade, pade_coefficients,
    replace_delay,
};
pub use reduce::{Method, Reduction, dominant, half_rule, moment_matching, reduce, taylor};

/// What can go wrong when a model is approximated: a typed fact, said in words by
/// [`crate::words::approx`]; its `Display` is the English text.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum ApproxError {
    /// The approximate model could not be built or analysed.
    Lti(#[from] LtiError),
    /// A pole in the right half plane: the method ranks stable poles only.
    UnstablePole(C64),
    /// A target order of 0.
    OrderZero,
    /// The target order (once a pair cut in two is kept whole) is not below the system's:
    /// nothing is left out.
    NotLower { asked: usize, order: usize },
    /// Nothing to approximate: no pole left out, no right-half-plane zero, no dead time.
    NothingToApproximate,
    /// A Padé order (m, n) without 1 ≤ n, m ≤ n.
    PadeOrder { m: usize, n: usize },
    /// A coefficient of Padé (m, n) of a dead time of `delay` s (a multiple of θ^k) falls
    /// outside double precision's normal range.
    PadeRange { delay: f64, m: usize, n: usize },
    /// More roots at the origin than the order (m, n) leaves room for.
    OriginRoots { m: usize, n: usize },
    /// The moment equations of G_{m,n} have no unique solution.
    Singular { m: usize, n: usize },
    /// A dead-time approximant asked of a system without dead time.
    NoDelay,
    /// The two step responses are not finite numbers somewhere in the window (a model with
    /// a pole far in the right half plane grows beyond double precision): no error to give.
    Incomparable,
    /// The dead time θ (s) is not a positive finite number.
    BadDelay(f64),
}

/// One way of approximating a system: a reduction, or a rational stand-in for its dead time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Approximation {
    Reduce(Reduction),
    Delay(DelayApproximant),
}

impl Approximation {
    /// The approximate model of `g`.
    pub fn apply(&self, g: &TransferFunction) -> Result<TransferFunction, ApproxError> {
        match self {
            Approximation::Reduce(r) => reduce(g, *r),
            Approximation::Delay(d) => replace_delay(g, *d),
        }
    }

    /// The approximations a comparison table lists for `g`: each reduction to first and
    /// second order below g's order, Padé G_{0,1}, G_{1,1}, G_{1,2}, G_{2,2} below it, and,
    /// when g has a dead time, its Padé (1,1), (2,2), (3,3), 1 − θs, 1/(1 + θs) and
    /// (1 + θs/3)^{−3}.
    pub fn catalogue(g: &TransferFunction) -> Vec<Approximation> {
        let order = g.order();
        let mut out = Vec::new();
        for method in [Method::Dominant, Method::Taylor, Method::Skogestad] {
            for n in (1..=2).filter(|&n| n < order) {
                out.push(Approximation::Reduce(Reduction { method, m: 0, n }));
            }
        }
        for (m, n) in [(0, 1), (1, 1), (1, 2), (2, 2)] {
            if n < order || (n == order && g.delay() > 0.0) {
                out.push(Approximation::Reduce(Reduction {
                    method: Method::Pade,
                    m,
                    n,
                }));
            }
        }
        if g.delay() > 0.0 {
            out.extend(
                [
                    DelayApproximant::Pade { m: 1, n: 1 },
                    DelayApproximant::Pade { m: 2, n: 2 },
                    DelayApproximant::Pade { m: 3, n: 3 },
                    DelayApproximant::TaylorZero,
                    DelayApproximant::TaylorLag,
                    DelayApproximant::Limit { n: 3 },
                ]
                .map(Approximation::Delay),
            );
        }
        out
    }
}

/// One row of a comparison: an approximation and its model with the error measures, or why
/// it does not apply.
#[derive(Debug, Clone)]
pub struct Row {
    pub approximation: Approximation,
    pub outcome: Result<Approximated, ApproxError>,
}

/// An approximate model with its exact step response and the comparison with the original.
#[derive(Debug, Clone)]
pub struct Approximated {
    pub model: TransferFunction,
    pub response: StepResponse,
    pub comparison: Comparison,
}

/// The model of `approximation` applied to `g` (whose step response is `original`), its
/// step response to the same step, and the comparison.
pub fn approximate(
    g: &TransferFunction,
    original: &StepResponse,
    approximation: Approximation,
    options: &StepInfoOptions,
) -> Result<Approximated, ApproxError> {
    let model = approximation.apply(g)?;
    let response = StepResponse::new(&model, original.amplitude())?;
    let comparison = compare(original, &response, options);
    if !(comparison.max_error.is_finite() && comparison.ise_relative.is_finite()) {
        return Err(ApproxError::Incomparable);
    }
    Ok(Approximated {
        model,
        response,
        comparison,
    })
}

/// Every approximation of [`Approximation::catalogue`] on `g`, compared with `original`.
pub fn table(g: &TransferFunction, original: &StepResponse, options: &StepInfoOptions) -> Vec<Row> {
    Approximation::catalogue(g)
        .into_iter()
        .map(|approximation| Row {
            approximation,
            outcome: approximate(g, original, approximation, options),
        })
        .collect()
}
