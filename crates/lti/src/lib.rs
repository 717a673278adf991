//! Continuous-time linear time-invariant systems, exactly: polynomials and their roots,
//! transfer functions with an optional transport delay, the closed-form step response,
//! the step metrics of MATLAB's `stepinfo` and the window that shows them ([`analyse`]), and
//! the text of y(t) as the course notes write it.
//!
//! Its modules depend on each other in one direction: [`number`] (numbers as text, from the
//! words' ground) is a leaf; [`response`] knows nothing of the metrics; [`metrics`] reads the
//! response; [`analysis`] puts the metrics and the window together; [`words`] says every
//! fact of the crate (its errors, metrics, approximations, loops) in English and Portuguese.
//!
//! Pure math: the crate depends on no GUI and no command line (Cargo keeps it so: it depends
//! only on `degrau-words`, nalgebra, serde and thiserror).

pub mod analysis;
pub mod approx;
pub mod bode;
pub mod control;
pub mod discrete;
pub mod divided;
pub mod expr;
pub mod feedback;
pub mod golden;
pub mod locus;
pub mod markov;
pub mod metrics;
pub use degrau_words::number;
pub mod parse;
pub mod poly;
pub mod response;
pub mod root_error;
pub mod tf;
pub mod words;

pub use analysis::{StepAnalysis, analyse};
pub use metrics::{StepInfo, StepInfoOptions};
pub use poly::C64;
pub use response::{Behaviour, StepResponse};
pub use tf::TransferFunction;

/// What can go wrong when a system is built or analysed: a typed fact, said in words (English
/// and Portuguese) by [`crate::words::lti`]; its `Display` is the English text.
#[derive(Debug, Clone, PartialEq)]
pub enum LtiError {
    /// A coefficient is NaN or infinite.
    NonFiniteCoefficient {
        what: Polynomial,
        /// Position of the coefficient, counted from 1 (the highest power first).
        index: usize,
    },
    /// Every coefficient is 0.
    ZeroPolynomial { what: Polynomial },
    /// A pole or zero (counted from 1) is NaN or infinite.
    NonFiniteRoot { what: RootRole, index: usize },
    /// A complex root whose conjugate is missing.
    UnpairedComplexRoot { what: RootRole, root: C64 },
    /// More zeros than poles.
    Improper {
        num_degree: usize,
        den_degree: usize,
    },
    /// No poles: a pure gain.
    NoPoles,
    /// The gain (or the static gain asked for) is zero or not finite.
    BadGain(f64),
    /// The gain k computed from normal numbers (num/den's leading coefficients, a model's
    /// Kp over its time constants, a static gain asked for) falls outside double precision's
    /// normal range.
    GainOutOfRange,
    /// The transport delay (s) is negative or not finite.
    BadDelay(f64),
    /// The step amplitude is zero or not finite.
    BadAmplitude(f64),
    /// The static gain G(0) is 0 or not finite, so no scaling of k sets it.
    DcGainNotScalable(f64),
    /// A closed loop was asked around a transport delay.
    DelayInLoop,
    /// The closed-loop gain Kp is not finite.
    BadLoopGain(f64),
    /// The closed loop's poles at this Kp cannot be computed right in double precision: a
    /// root of den + Kp·num is not one to rounding, or rounding hides its side of the
    /// imaginary axis.
    LoopPolesUnresolved { kp: f64 },
    /// The roots span too many decades for double precision.
    OutOfRange,
    /// A number typed is subnormal (0 < |x| < 2.2e-308).
    Subnormal { what: Quantity, value: f64 },
    /// A number computed from normal inputs fell below the normal range.
    Underflow { what: Quantity, value: f64 },
    /// The roots of a polynomial of this degree were not found.
    RootsDidNotConverge { degree: usize },
    /// More poles than [`tf::MAX_ORDER`].
    OrderTooHigh(usize),
    /// The settling band of [`StepInfoOptions`] is outside [1e-9, 1).
    BadSettlingBand(f64),
    /// The rise limits of [`StepInfoOptions`] are not 0 ≤ low < high ≤ 1.
    BadRiseLimits { low: f64, high: f64 },
}

impl std::fmt::Display for LtiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&degrau_words::Localize::text(self, degrau_words::Lang::En))
    }
}

impl std::error::Error for LtiError {}

/// Which polynomial an error is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Polynomial {
    Numerator,
    Denominator,
    /// A polynomial on its own (e.g. given to [`poly::roots`]).
    Alone,
}

/// Whether a root is a zero or a pole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RootRole {
    Zero,
    Pole,
}

/// The number an error about double precision's range is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// The step amplitude A.
    StepAmplitude,
    /// The gain k of k·Π(s − zᵢ)/Π(s − pⱼ).
    Gain,
    /// The final value A·G(0).
    FinalValue,
    /// The product A·k.
    AmplitudeTimesGain,
    /// Coefficient `index` (from 1, highest power first) of a polynomial.
    Coefficient { of: Polynomial, index: usize },
    /// A pole or zero, counted from 1 (its real or imaginary part).
    Root { role: RootRole, index: usize },
}

/// `-1+2j` style text for a complex number, with every digit ([`exact`]).
pub fn fmt_c(c: C64) -> String {
    complex_with(c, exact)
}

/// `-1+2j` style text for people: six significant digits ([`number::format_number`]).
pub fn fmt_c_rounded(c: C64) -> String {
    complex_with(c, number::format_number)
}

/// `-1+2j` style text, each part written by `number`.
fn complex_with(c: C64, number: fn(f64) -> String) -> String {
    if c.im == 0.0 {
        number(c.re)
    } else {
        let sign = if c.im < 0.0 { '-' } else { '+' };
        format!("{}{}{}j", number(c.re), sign, number(c.im.abs()))
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
