//! Initial guesses a student drags on the plot: where each handle of a model sits, and what
//! moving it does to the parameters.
//! - **final value**: scales Kp so the model passes through the handle at the end of the record;
//! - **dead time**: the start of the response, t0 + Td;
//! - **time constant**: the 63.2 % point of the response; moving it stretches every time
//!   constant alike (exactly Tp1 for a first-order model);
//! - **first peak** (underdamped models): its height sets ζ through the overshoot,
//!   e^{−ζπ/√(1−ζ²)}, its time sets ωd = π/(t_peak − t0 − Td).

use crate::model::excitation::Excitation;
use crate::model::{Model, Param};

/// The draggable handles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Handle {
    FinalValue,
    DeadTime,
    TimeConstant,
    FirstPeak,
}

/// The handles a model offers.
pub fn handles(model: &Model) -> Vec<Handle> {
    let s = &model.structure;
    let mut out = vec![Handle::FinalValue];
    if s.delay {
        out.push(Handle::DeadTime);
    }
    if s.underdamped {
        out.push(Handle::FirstPeak);
    } else {
        out.push(Handle::TimeConstant);
    }
    out
}

/// Samples of the model over [t0, t_end] for locating handles.
fn curve(model: &Model, setup: &Excitation, t_end: f64) -> Option<(Vec<f64>, Vec<f64>)> {
    let n = 1500;
    let times: Vec<f64> = (0..=n)
        .map(|k| setup.t0() + (t_end - setup.t0()) * k as f64 / n as f64)
        .collect();
    let y = model.simulate(setup, &times).ok()?;
    Some((times, y))
}

/// Where a handle sits (t, y), for a record ending at `t_end`.
pub fn position(
    model: &Model,
    setup: &Excitation,
    t_end: f64,
    handle: Handle,
) -> Option<(f64, f64)> {
    let y0 = model.get(Param::Y0);
    let td = delay_of(model);
    match handle {
        Handle::FinalValue => Some((t_end, *model.simulate(setup, &[t_end]).ok()?.first()?)),
        Handle::DeadTime => Some((setup.t0() + td, y0)),
        Handle::TimeConstant => {
            let (t, y) = curve(model, setup, t_end)?;
            let target = y0 + 0.632 * (model.get(Param::Kp) * setup.du());
            let rising = model.get(Param::Kp) * setup.du() > 0.0;
            let k = y
                .iter()
                .position(|&v| if rising { v >= target } else { v <= target })?;
            Some((t[k], target))
        }
        Handle::FirstPeak => {
            let (t, y) = curve(model, setup, t_end)?;
            let sign = (model.get(Param::Kp) * setup.du()).signum();
            let k = (1..y.len() - 1)
                .find(|&k| sign * (y[k] - y[k - 1]) > 0.0 && sign * (y[k + 1] - y[k]) <= 0.0)?;
            Some((t[k], y[k]))
        }
    }
}

/// The model after dragging `handle` to (t, y).
pub fn drag(
    model: &Model,
    setup: &Excitation,
    t_end: f64,
    handle: Handle,
    (t, y): (f64, f64),
) -> Model {
    let mut m = *model;
    let y0 = model.get(Param::Y0);
    let td = delay_of(model);
    match handle {
        Handle::FinalValue => {
            if let Some((_, y_now)) = position(model, setup, t_end, handle) {
                let (now, wanted) = (y_now - y0, y - y0);
                if now != 0.0 && wanted != 0.0 {
                    m.values.set(Param::Kp, model.get(Param::Kp) * wanted / now);
                }
            }
        }
        Handle::DeadTime => m.values.set(Param::Td, (t - setup.t0()).max(0.0)),
        Handle::TimeConstant => {
            if let Some((t_now, _)) = position(model, setup, t_end, handle) {
                let (now, wanted) = (t_now - setup.t0() - td, t - setup.t0() - td);
                if now > 0.0 && wanted > 0.0 {
                    for p in [Param::Tp1, Param::Tp2, Param::Tp3, Param::Tw, Param::Tz] {
                        m.values.set(p, model.get(p) * wanted / now);
                    }
                }
            }
        }
        Handle::FirstPeak => {
            let y_final = y0 + model.get(Param::Kp) * setup.du();
            let overshoot = ((y - y_final) / (y_final - y0)).clamp(1e-4, 0.99);
            let l = overshoot.ln();
            let zeta = -l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
            let tp = t - setup.t0() - td;
            if tp > 0.0 {
                let wd = std::f64::consts::PI / tp;
                m.values.set(Param::Zeta, zeta);
                m.values.set(Param::Tw, (1.0 - zeta * zeta).sqrt() / wd);
            }
        }
    }
    m
}

/// The model's Td as the handles place it (negative for a lead), 0 without a delay.
fn delay_of(model: &Model) -> f64 {
    if model.structure.delay {
        model.get(Param::Td)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Structure, Values};

    fn model(code: &str, set: &[(Param, f64)]) -> Model {
        Model::new(Structure::parse(code).unwrap(), Values::from_pairs(set))
    }

    #[test]
    fn first_order_handles_are_exact() {
        let m = model(
            "P1D",
            &[
                (Param::Kp, 2.0),
                (Param::Tp1, 3.0),
                (Param::Td, 1.0),
                (Param::Y0, 5.0),
            ],
        );
        let setup = Excitation::step(2.0, 1.0);
        assert_eq!(
            handles(&m),
            vec![Handle::FinalValue, Handle::DeadTime, Handle::TimeConstant]
        );
        let (t, y) = position(&m, &setup, 40.0, Handle::TimeConstant).unwrap();
        assert!((t - 6.0).abs() < 0.05, "{t}");
        assert!((y - (5.0 + 0.632 * 2.0)).abs() < 1e-12);
        let moved = drag(&m, &setup, 40.0, Handle::DeadTime, (4.5, 5.0));
        assert!((moved.get(Param::Td) - 2.5).abs() < 1e-12);
        let moved = drag(&m, &setup, 40.0, Handle::FinalValue, (40.0, 9.0));
        let (_, y_end) = position(&moved, &setup, 40.0, Handle::FinalValue).unwrap();
        assert!(
            (y_end - 9.0).abs() < 1e-12,
            "the model passes through the handle"
        );
        assert!((moved.get(Param::Kp) - 4.0).abs() < 1e-4);
        let moved = drag(&m, &setup, 40.0, Handle::TimeConstant, (t + 3.0, y));
        assert!(
            (moved.get(Param::Tp1) - 6.0).abs() < 0.1,
            "{}",
            moved.get(Param::Tp1)
        );
    }

    #[test]
    fn the_peak_handle_sets_zeta_and_wd() {
        let m = model(
            "P2DU",
            &[
                (Param::Kp, 1.0),
                (Param::Tw, 1.0),
                (Param::Zeta, 0.5),
                (Param::Td, 0.0),
                (Param::Y0, 0.0),
            ],
        );
        let setup = Excitation::step(0.0, 1.0);
        // Target: 25 % overshoot at t = 2 s.
        let moved = drag(&m, &setup, 30.0, Handle::FirstPeak, (2.0, 1.25));
        let (t, y) = position(&moved, &setup, 30.0, Handle::FirstPeak).unwrap();
        assert!((t - 2.0).abs() < 0.03, "{t}");
        assert!((y - 1.25).abs() < 1e-3, "{y}");
    }
}
