//! The notes' rules for the sampling period h (Tognetti's slides, "Escolha do tempo de
//! amostragem"), each judged for the source's numbers: h < 0.1·τ_max [Kalman & Bertram];
//! 0.2 < h/θ < 1 (FOPTD); 0.01 < h/τ < 0.05 [Åström & Wittenmark], τ the slowest time
//! constant; t_s/15 < h < t_s/6 [Isermann], t_s the 95 % settling time. τ_max = −1/Re p of
//! the slowest pole. A rule whose number the system does not have does not apply.

use degrau_lti::TransferFunction;

/// The numbers of the plant the rules read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Facts {
    /// The slowest time constant −1/Re p (none: a pole on or right of the imaginary axis,
    /// or no pole).
    pub tau_max: Option<f64>,
    /// The dead time θ (s).
    pub theta: f64,
    /// The 95 % settling time (s) of the step response (none: it does not settle).
    pub settling: Option<f64>,
}

impl Facts {
    /// The facts of `plant` with its 95 % settling time `settling`.
    pub fn of(plant: &TransferFunction, settling: Option<f64>) -> Self {
        let poles = plant.poles();
        let stable = !poles.is_empty() && poles.iter().all(|p| p.re < 0.0);
        let tau_max = stable.then(|| poles.iter().map(|p| -1.0 / p.re).fold(0.0, f64::max));
        Self {
            tau_max,
            theta: plant.delay(),
            settling: settling.filter(|t| t.is_finite() && *t > 0.0),
        }
    }
}

/// Which rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RuleKind {
    /// h < 0.1·τ_max.
    KalmanBertram,
    /// 0.2 < h/θ < 1.
    DeadTime,
    /// 0.01 < h/τ < 0.05.
    AstromWittenmark,
    /// t_s/15 < h < t_s/6.
    Isermann,
}

impl RuleKind {
    pub const ALL: [RuleKind; 4] = [
        RuleKind::KalmanBertram,
        RuleKind::DeadTime,
        RuleKind::AstromWittenmark,
        RuleKind::Isermann,
    ];
}

/// Why a rule does not apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Missing {
    /// No finite slowest time constant (an unstable or integrating pole, or no pole).
    TimeConstant,
    /// θ = 0.
    DeadTime,
    /// The step response does not settle.
    Settling,
}

/// A rule judged for one h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Judged {
    pub kind: RuleKind,
    /// The open interval of h the rule asks for (s), or why it does not apply.
    pub range: Result<(f64, f64), Missing>,
    /// Whether h is inside it (none: the rule does not apply).
    pub met: Option<bool>,
}

/// The interval of h `kind` asks for, with `facts`.
pub fn range(kind: RuleKind, facts: &Facts) -> Result<(f64, f64), Missing> {
    let tau = facts.tau_max.ok_or(Missing::TimeConstant);
    match kind {
        RuleKind::KalmanBertram => tau.map(|t| (0.0, 0.1 * t)),
        RuleKind::DeadTime if facts.theta > 0.0 => Ok((0.2 * facts.theta, facts.theta)),
        RuleKind::DeadTime => Err(Missing::DeadTime),
        RuleKind::AstromWittenmark => tau.map(|t| (0.01 * t, 0.05 * t)),
        RuleKind::Isermann => facts
            .settling
            .map(|ts| (ts / 15.0, ts / 6.0))
            .ok_or(Missing::Settling),
    }
}

/// Every rule judged for `h`.
pub fn judge(facts: &Facts, h: f64) -> Vec<Judged> {
    RuleKind::ALL
        .iter()
        .map(|&kind| {
            let range = range(kind, facts);
            Judged {
                kind,
                range,
                met: range.ok().map(|(lo, hi)| lo < h && h < hi),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn foptd() -> TransferFunction {
        // 1/(10s + 1)·e^{−2s}: τ = 10 s, θ = 2 s.
        TransferFunction::from_coeffs(&[1.0], &[10.0, 1.0])
            .and_then(|g| g.with_delay(2.0))
            .expect("a plant")
    }

    #[test]
    fn the_facts_of_a_foptd_are_its_tau_and_theta() {
        let f = Facts::of(&foptd(), Some(32.0));
        assert!((f.tau_max.expect("a tau") - 10.0).abs() < 1e-12);
        assert_eq!((f.theta, f.settling), (2.0, Some(32.0)));
    }

    #[test]
    fn each_rule_says_whether_h_meets_it() {
        // τ = 10, θ = 2, t_s = 32: KB h < 1; θ: 0.4 < h < 2; ÅW: 0.1 < h < 0.5;
        // Isermann: 2.133 < h < 5.333.
        let f = Facts::of(&foptd(), Some(32.0));
        let met = |h: f64| judge(&f, h).iter().map(|j| j.met).collect::<Vec<_>>();
        assert_eq!(
            met(0.45),
            vec![Some(true), Some(true), Some(true), Some(false)]
        );
        assert_eq!(
            met(3.0),
            vec![Some(false), Some(false), Some(false), Some(true)]
        );
        assert_eq!(
            met(0.05),
            vec![Some(true), Some(false), Some(false), Some(false)]
        );
        let (lo, hi) = range(RuleKind::Isermann, &f).expect("applies");
        assert!((lo - 32.0 / 15.0).abs() < 1e-12 && (hi - 32.0 / 6.0).abs() < 1e-12);
    }

    #[test]
    fn a_rule_without_its_number_does_not_apply() {
        // An integrator, no dead time, no settling.
        let g = TransferFunction::from_coeffs(&[1.0], &[1.0, 1.0, 0.0]).expect("a plant");
        let f = Facts::of(&g, None);
        assert_eq!(f.tau_max, None);
        let judged = judge(&f, 0.1);
        assert!(judged.iter().all(|j| j.met.is_none()));
        assert_eq!(judged[0].range, Err(Missing::TimeConstant));
        assert_eq!(judged[1].range, Err(Missing::DeadTime));
        assert_eq!(judged[3].range, Err(Missing::Settling));
    }
}
