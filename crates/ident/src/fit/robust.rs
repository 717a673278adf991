//! Fitting against outliers: a robust loss (Huber or Cauchy, the two the TCLab course
//! compares) minimised by iteratively reweighted least squares on the existing
//! Levenberg–Marquardt ([`fit_weighted`]): each round weighs every sample by the loss's
//! weight of how far its residual stands off its neighbours' ([`off_neighbours`]), on the
//! robust scale of those (1.4826·MAD), and refits from the last optimum, until the
//! parameters settle. Judged off the neighbours, not on the raw residual: a model's smooth
//! misfit is no reason to down-weight the samples where it misfits. Written here because IRLS is a loop of a
//! few lines around the fit the crate already has.
//!
//! Huber's weight is 1 within k·s and k·s/|r| beyond (k = 1.345: 95 % efficiency on Gaussian
//! noise); Cauchy's is 1/(1 + (r/(c·s))²) (c = 2.385, the same efficiency).

use serde::{Deserialize, Serialize};

use crate::fit::{FitData, FitError, FitOptions, FitReport, fit_weighted};
use crate::model::{Structure, Values};
use crate::stats::robust_scale;

/// The robust loss a fit uses against outliers (the TCLab course compares them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Loss {
    Huber,
    Cauchy,
}

impl Loss {
    /// Its author's name, the same in every language.
    pub fn name(self) -> &'static str {
        match self {
            Loss::Huber => "Huber",
            Loss::Cauchy => "Cauchy",
        }
    }
}

/// Huber's tuning constant (in robust standard deviations).
pub const HUBER_K: f64 = 1.345;
/// Cauchy's tuning constant (in robust standard deviations).
pub const CAUCHY_C: f64 = 2.385;
/// Rounds of reweighting at most.
const ROUNDS: usize = 8;
/// A sample standing off its neighbours by more than this many robust scales counts as
/// down-weighted (set aside: its weight under 0.2); nearer ones keep most of theirs.
const SET_ASIDE: f64 = 5.0;

/// A robust fit: the report (its statistics weighted) and the samples it set aside
/// (indices into the record: standing off their neighbours by more than [`SET_ASIDE`]
/// robust scales).
#[derive(Debug, Clone, PartialEq)]
pub struct RobustFit {
    pub report: FitReport,
    pub loss: Loss,
    pub down_weighted: Vec<usize>,
}

/// The loss's weight of each residual on the scale `scale` (output units).
pub fn weights(loss: Loss, residuals: &[f64], scale: f64) -> Vec<f64> {
    if scale.is_nan() || scale <= 0.0 {
        return vec![1.0; residuals.len()];
    }
    residuals
        .iter()
        .map(|r| {
            let u = (r / scale).abs();
            match loss {
                Loss::Huber if u <= HUBER_K => 1.0,
                Loss::Huber => HUBER_K / u,
                Loss::Cauchy => 1.0 / (1.0 + (u / CAUCHY_C).powi(2)),
            }
        })
        .collect()
}

/// Half the width of the running median an outlier is judged against (samples each side).
const NEIGHBOURS: usize = 3;

/// Each residual less the median of its neighbourhood (itself and [`NEIGHBOURS`] each side):
/// how far it stands off its neighbours. A wild sample stands off; a model's smooth misfit
/// (a slow approach it does not follow, a bend) moves its neighbours with it and does not,
/// so the weights fall on wild samples only and never reshape the fit to the misfit.
pub fn off_neighbours(r: &[f64]) -> Vec<f64> {
    let mut window = [0.0; 2 * NEIGHBOURS + 1];
    (0..r.len())
        .map(|i| {
            let lo = i.saturating_sub(NEIGHBOURS);
            let hi = (i + NEIGHBOURS + 1).min(r.len());
            let w = &mut window[..hi - lo];
            w.copy_from_slice(&r[lo..hi]);
            let mid = w.len() / 2;
            r[i] - *w.select_nth_unstable_by(mid, f64::total_cmp).1
        })
        .collect()
}

/// Fits `structure` to `data` under `loss` from `start` (usually the least-squares optimum).
pub fn robust_fit(
    data: &FitData,
    structure: Structure,
    start: Values,
    loss: Loss,
) -> Result<RobustFit, FitError> {
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let mut w = vec![1.0; data.y.len()];
    let mut report = fit_weighted(data, structure, start, &options, &w)?;
    let mut set_aside = Vec::new();
    for _ in 0..ROUNDS {
        let Ok(r) = report.residuals(data) else {
            break;
        };
        let local = off_neighbours(&r);
        let scale = robust_scale(&local);
        w = weights(loss, &local, scale);
        set_aside = (0..local.len())
            .filter(|&i| local[i].abs() > SET_ASIDE * scale)
            .collect();
        let next = fit_weighted(data, structure, report.model.values, &options, &w)?;
        let settled = structure.params().iter().all(|&p| {
            let (a, b) = (report.model.get(p), next.model.get(p));
            (a - b).abs() <= 1e-6 * (a.abs() + b.abs()).max(1e-300)
        });
        report = next;
        if settled {
            break;
        }
    }
    Ok(RobustFit {
        report,
        loss,
        down_weighted: set_aside,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::fit;
    use crate::model::excitation::Excitation;
    use crate::model::{Model, Param};

    /// A P1 fitted as P1 to a P2's slow approach: its smooth misfit is large against the
    /// noise, and one wild sample. Least squares and the robust fit give the same gain: the
    /// misfit's samples are not down-weighted, only the wild one.
    #[test]
    fn a_smooth_misfit_is_not_down_weighted() {
        let mut truth = Values::default();
        truth.set(Param::Kp, 0.56);
        truth.set(Param::Tp1, 150.0);
        truth.set(Param::Tp2, 15.0);
        truth.set(Param::Y0, 40.0);
        let times: Vec<f64> = (0..480).map(f64::from).collect();
        let input = Excitation::step(10.0, 40.0);
        let clean = Model::new(Structure::parse("P2").unwrap(), truth)
            .simulate(&input, &times)
            .unwrap();
        let mut rng = crate::random::Lcg(2);
        let mut y: Vec<f64> = clean.iter().map(|c| c + 0.03 * rng.symmetric()).collect();
        y[40] -= 0.5;
        let data = FitData { times, y, input };
        let s = Structure::parse("P1").unwrap();
        let ls = fit(&data, s, truth, &FitOptions::default(), &mut ()).unwrap();
        let r = robust_fit(&data, s, ls.model.values, Loss::Cauchy).unwrap();
        let (a, b) = (ls.model.get(Param::Kp), r.report.model.get(Param::Kp));
        assert!((a - b).abs() < 0.002 * a, "least squares {a}, robust {b}");
        assert_eq!(r.down_weighted, vec![40]);
    }

    #[test]
    fn weights_follow_their_loss() {
        let w = weights(Loss::Huber, &[0.5, -2.69, 13.45], 1.0);
        assert_eq!(w[0], 1.0);
        assert!((w[1] - 0.5).abs() < 1e-12 && (w[2] - 0.1).abs() < 1e-12);
        let c = weights(Loss::Cauchy, &[CAUCHY_C], 1.0);
        assert!((c[0] - 0.5).abs() < 1e-12);
    }

    /// A P1 with ten wild samples: least squares is pulled off, the robust fits are not, and
    /// the wild samples are the ones down-weighted.
    #[test]
    fn spikes_do_not_pull_a_robust_fit() {
        let s = Structure::parse("P1").unwrap();
        let mut truth = Values::default();
        truth.set(Param::Kp, 2.0);
        truth.set(Param::Tp1, 5.0);
        truth.set(Param::Y0, 10.0);
        let times: Vec<f64> = (0..300).map(|k| 0.2 * k as f64).collect();
        let input = Excitation::step(6.0, 1.0);
        let clean = Model::new(s, truth).simulate(&input, &times).unwrap();
        let wild: Vec<usize> = (0..10).map(|k| 40 + 25 * k).collect();
        let mut rng = crate::random::Lcg(13);
        let y: Vec<f64> = clean
            .iter()
            .enumerate()
            .map(|(i, c)| c + 0.005 * rng.symmetric() - if wild.contains(&i) { 1.5 } else { 0.0 })
            .collect();
        let data = FitData { times, y, input };
        let ls = fit(&data, s, truth, &FitOptions::default(), &mut ()).unwrap();
        assert!((ls.model.get(Param::Kp) - 2.0).abs() > 0.02);
        for loss in [Loss::Huber, Loss::Cauchy] {
            let r = robust_fit(&data, s, ls.model.values, loss).unwrap();
            let kp = r.report.model.get(Param::Kp);
            assert!((kp - 2.0).abs() < 0.01, "{loss:?}: Kp {kp}");
            assert_eq!(r.down_weighted, wild, "{loss:?}");
        }
    }
}
