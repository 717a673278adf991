//! Continuous-time linear time-invariant systems, exactly: polynomials and their roots,
//! transfer functions with an optional transport delay, the closed-form step response,
//! the step metrics of MATLAB's `stepinfo` and the window that shows them ([`analyse`]), and
//! the text of y(t) as the course notes write it.
//!
//! Its modules depend on each other in one direction: [`number`] (numbers as text) is a
//! leaf; [`response`] knows nothing of the metrics; [`metrics`] reads the response;
//! [`analysis`] puts the metrics and the window together.
//!
//! Pure math: nothing here knows about the GUI or the command line.

pub mod analysis;
pub mod divided;
pub mod expr;
pub mod metrics;
pub mod number;
pub mod parse;
pub mod poly;
pub mod response;
pub mod tf;

pub use analysis::{StepAnalysis, analyse};
pub use metrics::{StepInfo, StepInfoOptions};
pub use poly::C64;
pub use response::{Behaviour, StepResponse};
pub use tf::TransferFunction;

/// What can go wrong when a system is built or analysed, in words a student can act on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LtiError {
    #[error("the {what} has a coefficient that is not a finite number (position {index})")]
    NonFiniteCoefficient {
        what: &'static str,
        /// Position of the coefficient, counted from 1 (the highest power first).
        index: usize,
    },
    #[error("the {what} is zero: every coefficient is 0")]
    ZeroPolynomial { what: &'static str },
    #[error("{what} {index} is not a finite number")]
    NonFiniteRoot { what: &'static str, index: usize },
    #[error(
        "the {what}s must come in conjugate pairs: {root} has no partner {conjugate}",
        root = fmt_c(*.root),
        conjugate = fmt_c(.root.conj())
    )]
    UnpairedComplexRoot { what: &'static str, root: C64 },
    #[error(
        "the system is improper: the numerator has degree {num_degree}, above the denominator's \
         {den_degree}; it would respond to a step with an impulse"
    )]
    Improper {
        num_degree: usize,
        den_degree: usize,
    },
    #[error("the system has no poles: it is a pure gain, with no dynamics to analyse")]
    NoPoles,
    #[error("the gain is {0}: it must be a finite number other than zero")]
    BadGain(f64),
    #[error("the transport delay is {0} s: it must be a finite number, zero or positive")]
    BadDelay(f64),
    #[error("the step amplitude is {0}: it must be a finite number other than zero")]
    BadAmplitude(f64),
    #[error("the static (DC) gain is {0}, so it cannot be set to another value by scaling")]
    DcGainNotScalable(f64),
    #[error(
        "a closed loop around a transport delay is not a rational transfer function; \
         remove the delay or approximate it first"
    )]
    DelayInLoop,
    #[error("the closed loop gain Kp = {0} must be a finite number")]
    BadLoopGain(f64),
    #[error(
        "the poles and zeros span too many decades for double precision: the step response \
         cannot be computed reliably (rescale time, or drop roots far faster than the rest)"
    )]
    OutOfRange,
    #[error(
        "{what} is {value:e}, below the smallest normal double-precision number (2.2e-308): \
         it carries too few significant digits to compute with; type 0 if you mean 0, or \
         rescale the units"
    )]
    Subnormal { what: String, value: f64 },
    #[error(
        "{what} is {value:e} (too small for double precision: below 2.2e-308), so the \
         response cannot be computed reliably; rescale the gain or the units"
    )]
    Underflow { what: String, value: f64 },
    #[error("finding the roots of a degree-{degree} polynomial did not converge")]
    RootsDidNotConverge { degree: usize },
    #[error("the system has order {0}; Degrau handles orders up to {max}", max = tf::MAX_ORDER)]
    OrderTooHigh(usize),
}

/// `-1+2j` style text for a complex number.
pub fn fmt_c(c: C64) -> String {
    if c.im == 0.0 {
        exact(c.re)
    } else {
        let sign = if c.im < 0.0 { '-' } else { '+' };
        format!("{}{}{}j", exact(c.re), sign, exact(c.im.abs()))
    }
}

/// The shortest text that reads back as exactly `x`: plain for 1e−4 ≤ |x| < 1e15, else in
/// scientific notation (`-1e200`, not two hundred digits).
pub fn exact(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e15).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}
