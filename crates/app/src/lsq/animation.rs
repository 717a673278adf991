//! Recursive least squares run sample by sample for the app to animate, with no egui in it:
//! the rows of Φ of the ARX orders on the record, the estimate ([`Rls`]) after the rows taken
//! in so far, θ_k and e_k at each of them, and the batch solution on the same rows (what RLS
//! ends at with λ = 1 and a large α).
//!
//! While running, [`Animation::tick`] takes [`Animation::per_frame`] rows each frame, so any
//! record plays in about [`FRAMES`] frames; Step takes one row, Reset starts again.

use degrau_ident::lsq::arx::{
    ArxModel, ArxOrders, LeastSquares, LsqError, Offset, Regression, arx_regression, least_squares,
    sampling_period,
};
use degrau_ident::lsq::rls::{Rls, RlsOptions};

use super::samples::Samples;

/// About this many frames play a whole record.
pub const FRAMES: usize = 240;

/// An RLS run in progress.
#[derive(Debug, Clone)]
pub struct Animation {
    pub orders: ArxOrders,
    pub regression: Regression,
    /// The operating point (u0, y0) the rows are deviations from.
    pub offset: (f64, f64),
    /// The batch least-squares solution on the same rows.
    pub batch: Result<LeastSquares, LsqError>,
    rls: Rls,
    /// θ_k after each row taken in.
    pub trajectory: Vec<Vec<f64>>,
    /// e_k = y(k) − φ(k)ᵀθ_{k−1} of each row taken in.
    pub errors: Vec<f64>,
    pub running: bool,
    ts: f64,
}

impl Animation {
    /// A fresh run of `orders` on `samples`.
    pub fn new(
        samples: &Samples,
        orders: ArxOrders,
        offset: Offset,
        options: &RlsOptions,
    ) -> Result<Self, LsqError> {
        let (regression, op) =
            arx_regression(&samples.time, &samples.u, &samples.y, orders, offset)?;
        if regression.phi.nrows() == 0 {
            return Err(LsqError::TooFewSamples {
                rows: 0,
                parameters: regression.regressors.len(),
            });
        }
        let rls = Rls::new(regression.phi.ncols(), options)?;
        Ok(Self {
            orders,
            batch: least_squares(&regression),
            regression,
            offset: op,
            rls,
            trajectory: Vec::new(),
            errors: Vec::new(),
            running: false,
            ts: sampling_period(&samples.time),
        })
    }

    /// The rows of Φ.
    pub fn rows(&self) -> usize {
        self.regression.phi.nrows()
    }

    /// Rows taken in so far.
    pub fn taken(&self) -> usize {
        self.trajectory.len()
    }

    pub fn finished(&self) -> bool {
        self.taken() >= self.rows()
    }

    /// Rows taken per frame while running.
    pub fn per_frame(&self) -> usize {
        self.rows().div_ceil(FRAMES).max(1)
    }

    /// Takes in the next row, if any.
    pub fn step(&mut self) {
        let r = self.taken();
        if r >= self.rows() {
            self.running = false;
            return;
        }
        let phi: Vec<f64> = self.regression.phi.row(r).iter().copied().collect();
        let e = self.rls.update(&phi, self.regression.y[r]);
        self.errors.push(e);
        self.trajectory.push(self.rls.theta().to_vec());
        if self.finished() {
            self.running = false;
        }
    }

    /// One frame of a running animation; whether it is still running.
    pub fn tick(&mut self) -> bool {
        if self.running {
            for _ in 0..self.per_frame() {
                self.step();
            }
        }
        self.running
    }

    /// Runs to the end at once.
    pub fn run_to_end(&mut self) {
        while !self.finished() {
            self.step();
        }
    }

    /// θ_k now (θ0 before any row).
    pub fn theta(&self) -> &[f64] {
        self.rls.theta()
    }

    /// The sample index k of the last row taken in.
    pub fn last_sample(&self) -> Option<usize> {
        self.taken()
            .checked_sub(1)
            .map(|r| self.regression.first + r)
    }

    /// The ARX model of θ_k now.
    pub fn model(&self) -> ArxModel {
        ArxModel::from_theta(self.orders, self.theta(), self.offset, self.ts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stepping_to_the_end_reaches_the_batch_solution() {
        let n = 300;
        let time: Vec<f64> = (0..n).map(|k| 0.5 * k as f64).collect();
        let u: Vec<f64> = (0..n)
            .map(|k| 40.0 + if (k / 7) % 3 == 0 { 5.0 } else { -2.0 })
            .collect();
        let mut y = vec![80.0; n];
        for k in 2..n {
            y[k] = 80.0
                + 0.9 * (y[k - 1] - 80.0)
                + 0.25 * (u[k - 1] - 40.0)
                + 0.02 * (((k * 37) % 11) as f64 - 5.0);
        }
        let samples = Samples { time, u, y };
        let mut a = Animation::new(
            &samples,
            ArxOrders::new(1, 1, 1),
            Offset::Initial,
            &RlsOptions::default(),
        )
        .unwrap();
        a.running = true;
        let mut frames = 0;
        while a.tick() {
            frames += 1;
        }
        assert!(frames <= FRAMES);
        assert!(a.finished());
        let batch = a.batch.clone().unwrap();
        for (x, b) in a.theta().iter().zip(&batch.theta) {
            assert!((x - b).abs() < 1e-6, "{x} vs {b}");
        }
    }
}
