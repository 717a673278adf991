//! Messy generated step tests for the detectors' unit tests: a first order with dead time
//! far from zero (Y0 50, u0 30), steps between samples, a jittered clock, Gaussian noise as
//! a share of the step's effect, optional quantisation, per-step gains (a nonlinearity) and
//! an input that ramps, overshoots or wobbles instead of stepping. The plant is integrated
//! on a fine grid from the input it actually received; the logger shows the input at each
//! sample (zero-order hold).

use crate::fit::{FitData, FitOptions, FitReport, fit};
use crate::model::excitation::{Excitation, Hold};
use crate::model::{Param, Structure, Values};
use crate::random::Lcg;

use super::FittedRecord;

/// How the actuator moved on each change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Ideal,
    /// A straight line over `duration` seconds.
    Ramp(f64),
    /// Past the new level by `fraction` of the change, decaying with time constant `decay`.
    Overshoot {
        fraction: f64,
        decay: f64,
    },
    /// ± `amplitude` (a share of the change) about the new level, of `period`, for four
    /// periods.
    Wobble {
        amplitude: f64,
        period: f64,
    },
}

#[derive(Debug, Clone)]
pub struct Messy {
    pub kp: f64,
    pub tau: f64,
    pub td: f64,
    pub y0: f64,
    pub u0: f64,
    /// (instant, Δu, gain of this change).
    pub steps: Vec<(f64, f64, f64)>,
    pub h: f64,
    pub n: usize,
    /// Noise standard deviation as a share of the largest change's effect.
    pub noise: f64,
    pub quantum: Option<f64>,
    pub shape: Shape,
    pub seed: u64,
}

impl Default for Messy {
    fn default() -> Self {
        Self {
            kp: 1.2,
            tau: 20.0,
            td: 3.0,
            y0: 50.0,
            u0: 30.0,
            steps: vec![(40.37, 10.0, 1.2)],
            h: 1.0,
            n: 300,
            noise: 0.005,
            quantum: None,
            shape: Shape::Ideal,
            seed: 7,
        }
    }
}

/// A generated record and the fit of the true structure (P1D, Y0 free, step instants
/// estimated) to it.
pub struct MessyRecord {
    pub data: FitData,
    pub u: Vec<f64>,
    pub fit: FitReport,
}

impl MessyRecord {
    pub fn record(&self) -> FittedRecord<'_> {
        FittedRecord::new(&self.data, &self.fit).expect("the fit simulates")
    }
}

fn shape_at(shape: Shape, s: f64) -> f64 {
    if s < 0.0 {
        return 0.0;
    }
    match shape {
        Shape::Ideal => 1.0,
        Shape::Ramp(d) => (s / d).min(1.0),
        Shape::Overshoot { fraction, decay } => 1.0 + fraction * (-s / decay).exp(),
        Shape::Wobble { amplitude, period } if s < 4.0 * period => {
            1.0 + amplitude * (std::f64::consts::TAU * s / period).sin()
        }
        Shape::Wobble { .. } => 1.0,
    }
}

pub fn messy(m: Messy) -> MessyRecord {
    let mut rng = Lcg(m.seed);
    let times: Vec<f64> = (0..m.n)
        .map(|k| k as f64 * m.h + 0.02 * m.h * rng.symmetric())
        .collect();
    let input = |t: f64| {
        m.u0 + m
            .steps
            .iter()
            .map(|&(ts, du, _)| du * shape_at(m.shape, t - ts))
            .sum::<f64>()
    };
    // What drives the plant: each change through its own gain.
    let drive = |t: f64| {
        m.steps
            .iter()
            .map(|&(ts, du, k)| k * du * shape_at(m.shape, t - ts - m.td))
            .sum::<f64>()
    };
    let effect = m
        .steps
        .iter()
        .map(|&(_, du, k)| (k * du).abs())
        .fold(0.0, f64::max);
    let fine = 40;
    let mut x = 0.0;
    let mut t = times[0];
    let mut y = Vec::with_capacity(m.n);
    for &ti in &times {
        let dt = (ti - t) / fine as f64;
        for _ in 0..fine {
            let w = drive(t + 0.5 * dt);
            x += (w - x) * (1.0 - (-dt / m.tau).exp());
            t += dt;
        }
        let v = m.y0 + x + m.noise * effect * rng.gaussian();
        y.push(m.quantum.map_or(v, |q| q * (v / q).round()));
    }
    let u: Vec<f64> = times.iter().map(|&t| input(t)).collect();
    let excitation = Excitation::measured(&times, &u, None, Hold::Zoh).expect("the input changes");
    let data = FitData {
        times,
        y,
        input: excitation,
    };
    let structure = Structure {
        lead: true,
        ..Structure::parse("P1D").expect("a code")
    };
    let mut guess = Values::default();
    for (p, v) in [
        (Param::Kp, m.kp),
        (Param::Tp1, m.tau),
        (Param::Td, m.td),
        (Param::Y0, m.y0),
    ] {
        guess.set(p, v);
    }
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let fit = fit(&data, structure, guess, &options, &mut ()).expect("the truth fits");
    MessyRecord { data, u, fit }
}
