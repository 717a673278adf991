//! The causes a diagnosis names: what a fitted model lacks (a dead time, an offset, an
//! oscillation, one more pole, a zero, an inverse response, an integrator, a drift), each
//! with the stable identifier graders read. The test's own flaws are
//! [`crate::diagnose::test_causes::TestCauseKind`].

use serde::{Deserialize, Serialize};

/// A named cause, with a stable identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Cause {
    DeadTime,
    Offset,
    Oscillation,
    ExtraPole,
    Zero,
    InverseResponse,
    Integrator,
    Drift,
    None,
}

impl Cause {
    /// The stable identifier graders read (`dead_time`, `offset`, …, `none`).
    pub fn id(self) -> &'static str {
        match self {
            Cause::DeadTime => "dead_time",
            Cause::Offset => "offset",
            Cause::Oscillation => "oscillation",
            Cause::ExtraPole => "extra_pole",
            Cause::Zero => "zero",
            Cause::InverseResponse => "inverse_response",
            Cause::Integrator => "integrator",
            Cause::Drift => "drift",
            Cause::None => "none",
        }
    }
}
