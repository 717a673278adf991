//! What an extension gains on a staircase. When the output's resolution q is coarse against
//! its noise (σ < q/2, the `quantisation` cause's staircase), rounding does not average out:
//! the error follows the signal, a level held for long is read with a bias of up to q/2,
//! and an extension (a drift tilting through the levels, a zero or a pair bending to them)
//! lowers the squared residuals by more than the BIC's penalty although the model lacks
//! nothing. Neither the BIC nor its correlation-corrected form knows this, so on a
//! staircase the extension is judged again on what the samples say once each is read as
//! lying anywhere within its quantum: the current model and the candidate are refitted by
//! the interval-censored likelihood ([`censored_fit`], Y0 free, since the level before the
//! step is itself rounded) and the candidate is kept only when it raises that likelihood by
//! more than the BIC's penalty and [`BIC_THRESHOLD`]. A model that lacks nothing already
//! puts the signal within nearly every quantum and leaves an extension nothing to gain; a
//! real dead time or pole moves where the levels change, and pays.
//!
//! (Before, the gain was judged against records simulated from the least-squares model and
//! rounded to the grid; that model's level before the step sits on a grid level, which the
//! truth's seldom does, so those records never showed the tension that buys an extension on
//! the real one.)

use crate::diagnose::judge::{BIC_THRESHOLD, judged_change};
use crate::diagnose::test_causes::{FittedRecord, TestEvidence, quantisation};
use crate::fit::censored::censored_fit;
use crate::fit::{FitData, FitReport};

/// A record's staircase: its resolution (output units), under noise below half of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Staircase {
    pub resolution: f64,
}

impl Staircase {
    /// The staircase of `data` fitted by `fit`: `None` unless its resolution is named and
    /// the noise under it (the residuals' robust scale) is below half a step.
    pub fn of(data: &FitData, fit: &FitReport) -> Option<Self> {
        let cause = quantisation(&FittedRecord::new(data, fit)?)?;
        match cause.evidence {
            TestEvidence::Quantisation {
                resolution,
                noise,
                kp_floor: Some(_),
                ..
            } if resolution > 0.0 && noise.is_finite() => Some(Self { resolution }),
            _ => None,
        }
    }

    /// Whether `candidate` gains more over `current` on `data` than the staircase alone lets
    /// it gain: its corrected BIC change below −[`BIC_THRESHOLD`] (on a staircase the plain
    /// BIC, which the loop lets decide when the residuals are far from white, is no judge:
    /// the rounding keeps them so), and its BIC change on the censored likelihood below
    /// −[`BIC_THRESHOLD`] too. A model that cannot be refitted so keeps the extension (as
    /// without this test).
    pub fn beyond_rounding(
        &self,
        data: &FitData,
        current: &FitReport,
        candidate: &FitReport,
    ) -> bool {
        let real = judged_change(data, current, candidate);
        if real.is_nan() || real >= -BIC_THRESHOLD {
            return false;
        }
        self.censored_change(data, current, candidate)
            .is_none_or(|change| change < -BIC_THRESHOLD)
    }

    /// The BIC change from `from` to `to` on the censored likelihood: both refitted by
    /// [`censored_fit`] with Y0 free, −2·Δ(Σ ln P) + Δp·ln N. `None` when either cannot be
    /// refitted.
    pub fn censored_change(&self, data: &FitData, from: &FitReport, to: &FitReport) -> Option<f64> {
        let fits = crate::parallel::map(&[from, to], |r| {
            let mut structure = r.model.structure;
            structure.free_offset = true;
            censored_fit(data, self.resolution, structure, r.model.values)
        });
        let [Some(a), Some(b)] = &fits[..] else {
            return None;
        };
        let extra = to.params.len() as f64 - from.params.len() as f64;
        let n = data.y.len() as f64;
        Some(2.0 * (a.log_likelihood - b.log_likelihood) + extra * n.ln())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::{DiagnoseOptions, Ending, diagnose};
    use crate::fit::{FitOptions, fit};
    use crate::model::excitation::Excitation;
    use crate::model::{Model, Param, Structure, Values};
    use crate::random::Lcg;

    /// A step of Kp 2, τ 10 s (with `delay` s of dead time), Δu 5 from y0 20, over 600
    /// samples with white noise of `noise`, rounded to `q`.
    fn record(q: f64, noise: f64, delay: f64) -> FitData {
        let s = Structure::parse("P1D").unwrap();
        let mut v = Values::default();
        v.set(Param::Kp, 2.0);
        v.set(Param::Tp1, 10.0);
        v.set(Param::Td, delay);
        v.set(Param::Y0, 20.0);
        let input = Excitation::step(20.1, 5.0);
        let times: Vec<f64> = (0..600).map(|k| 0.3 * k as f64).collect();
        let clean = Model::new(s, v).simulate(&input, &times).unwrap();
        let mut rng = Lcg(11);
        let y = clean
            .iter()
            .map(|c| q * ((c + noise * rng.gaussian()) / q).round())
            .collect();
        FitData { times, y, input }
    }

    /// The staircase of `data` under a P1 fitted from its automatic guess.
    fn staircase_of(data: &FitData) -> Option<Staircase> {
        let s = Structure::parse("P1").unwrap();
        let guess = crate::fit::guess::auto_guess(data, s, None);
        let start = fit(data, s, guess, &FitOptions::default(), &mut ()).unwrap();
        Staircase::of(data, &start)
    }

    /// The diagnosis from P1: the chain's causes and how the loop ended.
    fn chain(data: &FitData) -> (Vec<&'static str>, Ending) {
        let p1 = Structure::parse("P1").unwrap();
        let r = diagnose(data, p1, None, &DiagnoseOptions::default()).unwrap();
        let ending = r.verdict.map(|v| v.ending).unwrap();
        (r.steps.iter().map(|s| s.cause.id()).collect(), ending)
    }

    #[test]
    fn a_staircase_buys_no_structure_and_a_real_dead_time_still_pays() {
        // q = 1.5 is 15 % of the 10-unit effect, the noise 0.15 a tenth of it: a staircase,
        // on which a P1 start gained a zero by the plain BIC; the verdict says why it ends.
        let data = record(1.5, 0.15, 0.0);
        assert!(staircase_of(&data).is_some());
        assert_eq!(chain(&data), (vec![], Ending::WithinRounding));
        // A dead time of 4 s (13 samples) on the same staircase is no rounding.
        let data = record(1.5, 0.15, 4.0);
        assert!(staircase_of(&data).is_some());
        assert_eq!(chain(&data).0, ["dead_time"]);
    }
}
