//! What an extension gains on a staircase. When the output's resolution q is coarse against
//! its noise (σ < q/2, the `quantisation` cause's staircase), rounding does not average out:
//! the error follows the signal, a level held for long is read with a bias of up to q/2,
//! and an extension (a drift tilting through the levels, a zero or a pair bending to them)
//! lowers the residuals by more than the BIC's penalty although the model lacks nothing.
//! Neither the BIC nor its correlation-corrected form knows this, so the gain is judged
//! against its null: the current model's own response with white noise σ, rounded to the
//! same grid, fitted with the current structure and with the candidate's, [`REPLICATES`]
//! times. The extension is kept only when it gains more than every replicate's, by the BIC
//! threshold. A parametric bootstrap, made only on a staircase and only for the step about
//! to be taken (2 × [`REPLICATES`] fits of one start).

use crate::diagnose::judge::{BIC_THRESHOLD, judged_change};
use crate::diagnose::test_causes::{FittedRecord, TestEvidence, quantisation};
use crate::fit::{FitData, FitOptions, FitReport, fit};
use crate::random::Lcg;

/// Records simulated under the null.
pub const REPLICATES: usize = 3;

/// A record's staircase: its resolution and the noise under it (output units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Staircase {
    pub resolution: f64,
    pub noise: f64,
    /// Where the grid's levels sit: level = offset + k·resolution.
    pub offset: f64,
}

impl Staircase {
    /// The staircase of `data` fitted by `fit`: `None` unless its resolution is named and
    /// the noise under it is below half a step. The replicates carry the cause's noise (the
    /// residuals' robust scale), which reads low where most samples sit on their level: a
    /// null with less noise rounds more regularly and lets an extension gain more, so the
    /// test errs towards no structure on a staircase, never towards invented structure.
    pub fn of(data: &FitData, fit: &FitReport) -> Option<Self> {
        let cause = quantisation(&FittedRecord::new(data, fit)?)?;
        match cause.evidence {
            TestEvidence::Quantisation {
                resolution,
                noise,
                kp_floor: Some(_),
                ..
            } if resolution > 0.0 && noise.is_finite() => {
                let y0 = *data.y.first()?;
                Some(Self {
                    resolution,
                    noise,
                    offset: y0 - resolution * (y0 / resolution).round(),
                })
            }
            _ => None,
        }
    }

    /// `y` rounded to the staircase's grid.
    fn round(&self, y: f64) -> f64 {
        let q = self.resolution;
        self.offset + q * ((y - self.offset) / q).round()
    }

    /// Whether `candidate` gains more over `current` on `data` than the staircase alone lets
    /// it gain: its corrected BIC change below −[`BIC_THRESHOLD`] (on a staircase the plain
    /// BIC, which the loop lets decide when the residuals are far from white, is no judge:
    /// the rounding keeps them so) and below every null replicate's by [`BIC_THRESHOLD`].
    /// A replicate that cannot be simulated or fitted does not count; none at all keeps
    /// the extension (as without this test).
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
        let options = FitOptions {
            starts: 1,
            screen: true,
            ..FitOptions::default()
        };
        let Ok(clean) = current.model.simulate(&data.input, &data.times) else {
            return true;
        };
        let mut rng = Lcg(0x5EED_57A1);
        let nulls: Vec<FitData> = (0..REPLICATES)
            .map(|_| {
                let y = clean
                    .iter()
                    .map(|c| self.round(c + self.noise * rng.gaussian()))
                    .collect();
                FitData { y, ..data.clone() }
            })
            .collect();
        // Each replicate's two fits, independent: spread over the cores.
        let jobs: Vec<(usize, &FitReport)> = (0..REPLICATES)
            .flat_map(|k| [(k, current), (k, candidate)])
            .collect();
        let fits = crate::parallel::map(&jobs, |&(k, r)| {
            fit(
                &nulls[k],
                r.model.structure,
                r.model.values,
                &options,
                &mut (),
            )
            .ok()
        });
        fits.chunks(2)
            .zip(&nulls)
            .filter_map(|(pair, null)| match pair {
                [Some(under), Some(extended)] => Some(judged_change(null, under, extended)),
                _ => None,
            })
            .all(|null| real < null - BIC_THRESHOLD)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::{DiagnoseOptions, Ending, diagnose};
    use crate::model::excitation::Excitation;
    use crate::model::{Model, Param, Structure, Values};

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

    #[test]
    fn the_grid_is_the_records_own() {
        let data = record(1.5, 0.15, 0.0);
        let stair = staircase_of(&data).expect("a staircase");
        assert!((stair.resolution - 1.5).abs() < 1e-9, "{stair:?}");
        for y in &data.y {
            assert!((stair.round(*y) - y).abs() < 1e-9, "{y}");
        }
    }
}
