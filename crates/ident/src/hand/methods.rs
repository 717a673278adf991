//! Each hand method's construction on a [`Reading`] (formulas in the parent module's doc).

use super::curve::line_fit;
use super::{
    DeadTimeFrom, HandError, HandMethod, HandWarning, Overrides, Read, Reading, SecondOrder, Shape,
    THREE_POINT_ZETA, Tangent,
};

/// The band of the set-of-points method (% of the change).
const POINTS_BAND: (f64, f64) = (10.0, 90.0);

/// The first departure: the share of the change (%) the curve must leave y0 by, at least.
const DEPARTURE_PERCENT: f64 = 2.0;

pub(super) fn read(
    reading: &Reading,
    method: HandMethod,
    overrides: &Overrides,
) -> Result<Read, HandError> {
    match method {
        HandMethod::Tangent => tangent_method(reading, overrides),
        HandMethod::SixtyThree => sixty_three(reading, overrides),
        HandMethod::Broida => two_points(reading, (28.0, 40.0), |t1, t2| {
            (5.5 * (t2 - t1), 2.8 * t1 - 1.8 * t2)
        }),
        HandMethod::Smith => two_points(reading, (28.3, 63.2), |t1, t2| {
            let tau = 1.5 * (t2 - t1);
            (tau, t2 - tau)
        }),
        HandMethod::Points => points(reading),
        HandMethod::ThreePoint => three_points(reading),
    }
}

/// The tangent at the steepest rise, or at the student's point.
fn tangent(reading: &Reading, overrides: &Overrides) -> Result<Tangent, HandError> {
    let curve = &reading.curve;
    let sign = if curve.rising { 1.0 } else { -1.0 };
    let line = match overrides.tangent_time {
        Some(t) => curve.line_at(t).filter(|l| l.slope * sign > 0.0),
        None => curve.steepest(sign),
    }
    .ok_or(HandError::NoSteepestRise)?;
    Ok(Tangent {
        t: line.x,
        y: line.y,
        slope: line.slope,
        t_initial: line.at_level(reading.y0),
        t_final: line.at_level(reading.y_final),
    })
}

fn first_order(reading: &Reading, tau: f64, theta: f64) -> Result<Read, HandError> {
    if !(tau > 0.0 && tau.is_finite()) {
        return Err(HandError::NoTimeConstant { tau });
    }
    Ok(Read {
        theta,
        shape: Shape::First { tau },
        construction: reading.construction(),
        warnings: Vec::new(),
    })
}

fn tangent_method(reading: &Reading, overrides: &Overrides) -> Result<Read, HandError> {
    let line = tangent(reading, overrides)?;
    let mut read = first_order(
        reading,
        line.t_final - line.t_initial,
        line.t_initial - reading.t0,
    )?;
    read.construction.tangent = Some(line);
    Ok(read)
}

fn sixty_three(reading: &Reading, overrides: &Overrides) -> Result<Read, HandError> {
    let t63 = reading.level_time(63.2)?;
    let (start, line, departure) = match overrides.dead_time_from {
        DeadTimeFrom::Tangent => {
            let line = tangent(reading, overrides)?;
            (line.t_initial, Some(line), None)
        }
        DeadTimeFrom::FirstDeparture => {
            let change = (reading.y_final - reading.y0).abs();
            let percent = DEPARTURE_PERCENT.max(300.0 * reading.curve.noise / change);
            let d = reading.level_time(percent)?;
            (d.t, None, Some(d))
        }
    };
    let mut read = first_order(reading, t63.t - start, start - reading.t0)?;
    read.construction.tangent = line;
    read.construction.levels.extend(departure);
    read.construction.levels.push(t63);
    Ok(read)
}

/// A two-point method: `rule` turns the two times (s, from t0) into (τ, θ).
fn two_points(
    reading: &Reading,
    (p1, p2): (f64, f64),
    rule: impl Fn(f64, f64) -> (f64, f64),
) -> Result<Read, HandError> {
    let (a, b) = (reading.level_time(p1)?, reading.level_time(p2)?);
    let (tau, theta) = rule(a.t - reading.t0, b.t - reading.t0);
    let mut read = first_order(reading, tau, theta)?;
    read.construction.levels = vec![a, b];
    Ok(read)
}

fn points(reading: &Reading) -> Result<Read, HandError> {
    let (low, high) = POINTS_BAND;
    let change = reading.y_final - reading.y0;
    let used: Vec<(f64, f64)> = reading
        .curve
        .points()
        .filter(|&(_, y)| {
            let z = 100.0 * (y - reading.y0) / change;
            (low..=high).contains(&z)
        })
        .collect();
    let ts: Vec<f64> = used.iter().map(|p| p.0 - reading.t0).collect();
    let logs: Vec<f64> = used
        .iter()
        .map(|p| (1.0 - (p.1 - reading.y0) / change).ln())
        .collect();
    let line = line_fit(&ts, &logs).ok_or(HandError::LevelNotReached { percent: high })?;
    let tau = -1.0 / line.slope;
    let mut read = first_order(reading, tau, line.at_zero() * tau)?;
    read.construction.points = used;
    read.construction.levels = vec![reading.level_time(low)?, reading.level_time(high)?];
    Ok(read)
}

fn three_points(reading: &Reading) -> Result<Read, HandError> {
    let [l15, l45, l75] = [15.0, 45.0, 75.0].map(|p| reading.level_time(p));
    let (l15, l45, l75) = (l15?, l45?, l75?);
    let (t1, t2, t3) = (l15.t - reading.t0, l45.t - reading.t0, l75.t - reading.t0);
    let x = (t2 - t1) / (t3 - t1);
    let zeta = (0.0805 - 5.547 * (0.475 - x).powi(2)) / (x - 0.356);
    if !(zeta > 0.0 && zeta.is_finite() && x.is_finite()) {
        return Err(HandError::ThreePointShape { x });
    }
    let f2 = if zeta < 1.0 {
        0.708 * 2.811f64.powf(zeta)
    } else {
        2.6 * zeta - 0.60
    };
    let omega_n = f2 / (t3 - t1);
    let theta = t2 - 0.922 * 1.66f64.powf(zeta) / omega_n;
    let root = (zeta * zeta - 1.0).sqrt();
    let (tau1, tau2) = if zeta >= 1.0 {
        (Some((zeta + root) / omega_n), Some((zeta - root) / omega_n))
    } else {
        (None, None)
    };
    let mut warnings = Vec::new();
    let (low, high) = THREE_POINT_ZETA;
    if !(low..=high).contains(&zeta) {
        warnings.push(HandWarning::DampingOutsideRange { zeta });
    }
    let mut construction = reading.construction();
    construction.levels = vec![l15, l45, l75];
    Ok(Read {
        theta,
        shape: Shape::Second(SecondOrder {
            zeta,
            omega_n,
            tau1,
            tau2,
        }),
        construction,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::super::{LevelTime, Overrides, Record, estimate};
    use super::*;

    /// The level-time pairs of a construction as (percent, t − t0).
    fn relative(levels: &[LevelTime], t0: f64) -> Vec<(f64, f64)> {
        levels.iter().map(|l| (l.percent, l.t - t0)).collect()
    }

    /// K e^{−θs}/(τs + 1) from y0, sampled every h from 0, the step at t0.
    fn fopdt(k: f64, tau: f64, theta: f64, t0: f64, h: f64, n: usize) -> Record {
        let times: Vec<f64> = (0..n).map(|i| i as f64 * h).collect();
        let y: Vec<f64> = times
            .iter()
            .map(|&t| {
                let s = t - t0 - theta;
                100.0
                    + if s > 0.0 {
                        2.0 * k * (1.0 - (-s / tau).exp())
                    } else {
                        0.0
                    }
            })
            .collect();
        Record::new(&times, &y, t0, 2.0, 100.0).unwrap()
    }

    #[test]
    fn smith_reads_its_two_levels_and_broida_its_constants() {
        let r = fopdt(1.5, 10.0, 2.0, 1.05, 0.01, 15000);
        let e = estimate(&r, HandMethod::Smith, &Overrides::default()).unwrap();
        let levels = relative(&e.construction.levels, 1.05);
        // 28.3 % at θ + τ/3·… : t = θ − τ ln(1 − p).
        for (p, t) in levels {
            let exact = 2.0 - 10.0 * (1.0 - p / 100.0).ln();
            assert!((t - exact).abs() < 1e-3, "{p}: {t} vs {exact}");
        }
        let b = estimate(&r, HandMethod::Broida, &Overrides::default()).unwrap();
        // Broida's rounded constants: τ·5.5·ln(0.72/0.60) and θ + τ(2.8 ln(1/0.72) − 1.8 ln(1/0.6)).
        let tau = 10.0 * 5.5 * (0.72f64 / 0.60).ln();
        let theta = 2.0 + 10.0 * (2.8 * (1.0 / 0.72f64).ln() - 1.8 * (1.0 / 0.6f64).ln());
        assert!((b.tau.unwrap() - tau).abs() < 2e-3, "{b:?}");
        assert!((b.theta - theta).abs() < 2e-3, "{b:?}");
    }

    #[test]
    fn a_first_order_curve_has_no_three_point_damping() {
        let r = fopdt(1.0, 10.0, 2.0, 0.0, 0.01, 15000);
        assert!(matches!(
            estimate(&r, HandMethod::ThreePoint, &Overrides::default()),
            Err(HandError::ThreePointShape { .. })
        ));
    }

    #[test]
    fn the_student_moves_the_tangent_and_the_levels() {
        let r = fopdt(1.0, 10.0, 2.0, 0.0, 0.01, 6000);
        let at = Overrides {
            tangent_time: Some(12.0),
            ..Overrides::default()
        };
        let e = estimate(&r, HandMethod::Tangent, &at).unwrap();
        let line = e.construction.tangent.unwrap();
        assert!((line.t - 12.0).abs() < 0.01);
        // The tangent of the exponential at s = t − θ: slope e^{−s/τ}·K·Δu/τ.
        let s = line.t - 2.0;
        assert!((line.slope - 2.0 * (-s / 10.0).exp() / 10.0).abs() < 1e-4);
        let low = Overrides {
            y_final: Some(101.0),
            ..Overrides::default()
        };
        let e = estimate(&r, HandMethod::Smith, &low).unwrap();
        assert!((e.k - 0.5).abs() < 1e-12);
        assert!(matches!(
            estimate(
                &r,
                HandMethod::Tangent,
                &Overrides {
                    y0: Some(f64::NAN),
                    ..Overrides::default()
                }
            ),
            Err(HandError::BadOverride(_))
        ));
    }
}
