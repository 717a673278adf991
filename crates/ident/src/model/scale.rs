//! The internal units of identification, so that a record fits the same at any scale.
//!
//! A fit, a guess, a landscape and a residual analysis work on the record in its own units,
//! never in the file's: the output shifted by its level and divided by its spread, the step
//! Δu divided by its size, time counted from the step instant t0 in record lengths. A record
//! of temperatures near 1e-300 or 1e300, a step Δu of 1e-200, time in nanoseconds or in years:
//! the optimiser sees the same numbers (to rounding) as for a record of unit size, and every
//! result is scaled back at the end. [`Scale`] is that change of units, in one place:
//!
//! - output: y = level + unit·ỹ, with level the midpoint of the record's range and unit half
//!   the range (|level| for a flat record, 1 for an all-zero one);
//! - input: Δu = |Δu|·Δũ, so Δũ = ±1;
//! - time: t = t0 + T·t̃, with T the record's length after the step (at least one sampling
//!   period);
//! - parameters: Kp = K̃p·unit/|Δu| (divided by T as well with an integrator, whose Kp is per
//!   second), Y0 = level + unit·Ỹ0, Drift = D̃rift·unit/T, the time constants, Td and Tz by
//!   T, ζ unchanged;
//! - statistics: residuals by unit, the MSE by unit², its logarithm by 2·ln(unit), which stays
//!   finite where unit² does not (1e600).
//!
//! A value that cannot be scaled back (a gain of 1e600 output units per input unit) is not
//! representable in double precision; [`Scale::values_out`] refuses it with the parameter's
//! name and its order of magnitude.

use serde::{Deserialize, Serialize};

use crate::fit::FitData;
use crate::model::excitation::Excitation;
use crate::model::{Model, Param, Structure, Values};

/// The change of units between a record and the fit's internal, unit-sized units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Scale {
    /// Output level subtracted (output units): the midpoint of the record's range.
    pub y_level: f64,
    /// One internal output unit, in output units: half the record's range (positive).
    pub y_unit: f64,
    /// Size of the step |Δu| (input units, positive).
    pub du_unit: f64,
    /// Time origin (s): the step instant t0.
    pub t_origin: f64,
    /// One internal time unit (s): the record's length after the step (positive).
    pub t_unit: f64,
}

impl Default for Scale {
    /// The record's own units (nothing shifted or scaled).
    fn default() -> Self {
        Scale {
            y_level: 0.0,
            y_unit: 1.0,
            du_unit: 1.0,
            t_origin: 0.0,
            t_unit: 1.0,
        }
    }
}

/// A parameter whose value in the record's units is beyond double precision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unrepresentable {
    pub param: Param,
    /// log₁₀ of its magnitude (e.g. 600.3 for 2e600), when the magnitude is finite in logs.
    pub log10: f64,
}

impl Scale {
    /// The units of `data` (finite, validated samples assumed), `None` when they cannot be
    /// formed: a step of zero or non-finite size, a record without a positive length, or a
    /// range beyond double precision.
    pub fn of(data: &FitData, sampling_period: f64) -> Option<Scale> {
        let (lo, hi) = data
            .y
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &y| {
                (lo.min(y), hi.max(y))
            });
        // Halves first: (hi − lo) overflows for a range wider than 1.8e308.
        let y_level = 0.5 * lo + 0.5 * hi;
        let half_range = 0.5 * hi - 0.5 * lo;
        let y_unit = [half_range, y_level.abs(), 1.0]
            .into_iter()
            .find(|u| is_positive_finite(*u))?;
        let du_unit = data.input.du_scale().abs();
        let t_origin = data.input.t0();
        let last = data.times.last().copied().unwrap_or(t_origin);
        let t_unit = [last - t_origin, sampling_period]
            .into_iter()
            .filter(|t| is_positive_finite(*t))
            .fold(f64::NAN, f64::max);
        (is_positive_finite(du_unit) && is_positive_finite(t_unit) && t_origin.is_finite())
            .then_some(Scale {
                y_level,
                y_unit,
                du_unit,
                t_origin,
                t_unit,
            })
    }

    /// The record in internal units: times from t0 in record lengths, the output about its
    /// level in half-ranges, the step ±1.
    pub fn data_in(&self, data: &FitData) -> FitData {
        FitData {
            times: data.times.iter().map(|&t| self.time_in(t)).collect(),
            y: data.y.iter().map(|&y| self.output_in(y)).collect(),
            input: self.input_in(&data.input),
        }
    }

    /// The input in internal units: instants from t0 in record lengths, its deviation in
    /// units of its largest (so the largest is ±1).
    pub fn input_in(&self, input: &Excitation) -> Excitation {
        input.rescaled(self.t_origin, self.t_unit, self.du_unit)
    }

    /// An instant in internal units.
    pub fn time_in(&self, t: f64) -> f64 {
        (t - self.t_origin) / self.t_unit
    }

    /// An internal instant in seconds.
    pub fn time_out(&self, t: f64) -> f64 {
        self.t_origin + t * self.t_unit
    }

    /// An output value in internal units.
    pub fn output_in(&self, y: f64) -> f64 {
        (y - self.y_level) / self.y_unit
    }

    /// A difference of outputs (a residual, a standard deviation) in output units.
    pub fn output_difference_out(&self, e: f64) -> f64 {
        e * self.y_unit
    }

    /// A mean squared error in (output units)²: infinite or zero where unit² is out of range
    /// (see [`Scale::ln_mse_out`] for its logarithm, which is always finite).
    pub fn mse_out(&self, mse: f64) -> f64 {
        mse * self.y_unit * self.y_unit
    }

    /// ln of a mean squared error in (output units)², from the internal MSE (floored at the
    /// smallest normal number, so an exact fit gives a finite value).
    pub fn ln_mse_out(&self, mse: f64) -> f64 {
        mse.max(f64::MIN_POSITIVE).ln() + 2.0 * self.y_unit.ln()
    }

    /// Physical = internal × factor (plus the level for Y0), for each parameter.
    fn factor(&self, p: Param, structure: Structure) -> f64 {
        match p {
            Param::Kp if structure.integrator => self.y_unit / self.du_unit / self.t_unit,
            Param::Kp => self.y_unit / self.du_unit,
            Param::Zeta => 1.0,
            // The transient's basis (model/mod.rs): X1 multiplies a unitless mode; X2 a first
            // divided difference or sin(ωτ)/ω (time); X3 a second divided difference
            // (time²), or the third pole's own mode beside a pair (unitless).
            Param::Y0 | Param::X1 => self.y_unit,
            Param::X2 => self.y_unit / self.t_unit,
            Param::X3 if structure.underdamped => self.y_unit,
            Param::X3 => self.y_unit / (self.t_unit * self.t_unit),
            Param::Drift => self.y_unit / self.t_unit,
            _ => self.t_unit, // the times (Param::is_time)
        }
    }

    /// One parameter value in internal units.
    pub fn value_in(&self, p: Param, structure: Structure, x: f64) -> f64 {
        match p {
            Param::Y0 => self.output_in(x),
            // Kp·(unit/|Δu|)⁻¹ written so it underflows or overflows only when the result does.
            Param::Kp if structure.integrator => x * self.du_unit / self.y_unit * self.t_unit,
            Param::Kp => x * self.du_unit / self.y_unit,
            Param::Drift => x / self.y_unit * self.t_unit,
            _ => x / self.factor(p, structure),
        }
    }

    /// One internal parameter value in the record's units (possibly not finite: see
    /// [`Scale::values_out`]).
    pub fn value_out(&self, p: Param, structure: Structure, x: f64) -> f64 {
        match p {
            Param::Y0 => self.y_level + x * self.y_unit,
            Param::Kp if structure.integrator => x * self.y_unit / self.du_unit / self.t_unit,
            Param::Kp => x * self.y_unit / self.du_unit,
            Param::Drift => x * self.y_unit / self.t_unit,
            _ => x * self.factor(p, structure),
        }
    }

    /// Every parameter value in internal units.
    pub fn values_in(&self, structure: Structure, v: &Values) -> Values {
        map_values(v, |p, x| self.value_in(p, structure, x))
    }

    /// Every parameter of `structure` in the record's units; the first one that is not
    /// representable is refused (the others of [`Values`] are scaled as they come).
    pub fn values_out(&self, structure: Structure, v: &Values) -> Result<Values, Unrepresentable> {
        let out = map_values(v, |p, x| self.value_out(p, structure, x));
        match structure
            .params()
            .into_iter()
            .find(|&p| !out.get(p).is_finite() || (out.get(p) == 0.0 && v.get(p) != 0.0))
        {
            Some(param) => Err(Unrepresentable {
                param,
                log10: self.log10_out(param, structure, v.get(param)),
            }),
            None => Ok(out),
        }
    }

    /// log₁₀|x in the record's units|, computed in logarithms so that it is finite even when
    /// the value is not.
    pub fn log10_out(&self, p: Param, structure: Structure, x: f64) -> f64 {
        let factor_log10 = match p {
            Param::Kp if structure.integrator => {
                self.y_unit.log10() - self.du_unit.log10() - self.t_unit.log10()
            }
            Param::Kp => self.y_unit.log10() - self.du_unit.log10(),
            Param::Drift => self.y_unit.log10() - self.t_unit.log10(),
            _ => self.factor(p, structure).log10(),
        };
        x.abs().log10() + factor_log10
    }

    /// Whether one internal unit of every parameter of `structure` is representable in the
    /// record's units (a gain of 1e600 output units per input unit is not).
    pub fn check(&self, structure: Structure) -> Result<(), Unrepresentable> {
        match structure.params().into_iter().find(|&p| {
            let v = self.value_out(p, structure, 1.0);
            !v.is_finite() || (p != Param::Y0 && !v.is_normal())
        }) {
            Some(param) => Err(Unrepresentable {
                param,
                log10: self.log10_out(param, structure, 1.0),
            }),
            None => Ok(()),
        }
    }

    /// A model in internal units.
    pub fn model_in(&self, m: &Model) -> Model {
        Model::new(m.structure, self.values_in(m.structure, &m.values))
    }

    /// An internal model in the record's units, if representable.
    pub fn model_out(&self, m: &Model) -> Result<Model, Unrepresentable> {
        Ok(Model::new(
            m.structure,
            self.values_out(m.structure, &m.values)?,
        ))
    }
}

fn map_values(v: &Values, f: impl Fn(Param, f64) -> f64) -> Values {
    let mut out = *v;
    for p in crate::model::ALL_PARAMS {
        out.set(p, f(p, v.get(p)));
    }
    out
}

fn is_positive_finite(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(scale_y: f64, scale_t: f64, du: f64) -> FitData {
        let times: Vec<f64> = (0..11).map(|k| scale_t * (5.0 + k as f64)).collect();
        let y = (0..11).map(|k| scale_y * (3.0 + 0.1 * k as f64)).collect();
        FitData {
            times,
            y,
            input: Excitation::step(6.0 * scale_t, du),
        }
    }

    #[test]
    fn units_are_the_level_the_half_range_the_step_and_the_length() {
        let d = data(1.0, 1.0, -2.0);
        let s = Scale::of(&d, 1.0).unwrap();
        assert!((s.y_level - 3.5).abs() < 1e-15 && (s.y_unit - 0.5).abs() < 1e-15);
        assert_eq!((s.du_unit, s.t_origin, s.t_unit), (2.0, 6.0, 9.0));
        let n = s.data_in(&d);
        assert_eq!(n.input, Excitation::step(0.0, -1.0));
        assert!((n.y[0] + 1.0).abs() < 1e-15 && (n.y[10] - 1.0).abs() < 1e-15);
        assert!((n.times[10] - 1.0).abs() < 1e-15);
    }

    #[test]
    fn an_initial_transient_is_the_same_curve_in_either_units() {
        // X2 multiplies a mode in seconds, X3 one in s² (or a unitless one beside a pair):
        // scaled as the output alone, the model in the record's units was another curve.
        let d = data(3.0, 40.0, 2.0);
        let s = Scale::of(&d, 40.0).unwrap();
        let n = s.data_in(&d);
        for code in ["P2", "P3", "P2U", "P3U"] {
            let mut st = Structure::parse(code).unwrap();
            st.transient = true;
            let mut v = Values::default();
            for (p, x) in [
                (Param::Kp, 1.5),
                (Param::Tp1, 50.0),
                (Param::Tp2, 20.0),
                (Param::Tp3, 8.0),
                (Param::Tw, 30.0),
                (Param::Zeta, 0.4),
                (Param::Y0, 10.0),
                (Param::X1, 2.0),
                (Param::X2, -0.05),
                (Param::X3, 0.003),
            ] {
                v.set(p, x);
            }
            let model = Model::new(st, v);
            let outside = model.simulate(&d.input, &d.times).unwrap();
            let inside = s.model_in(&model).simulate(&n.input, &n.times).unwrap();
            for (a, b) in outside.iter().zip(&inside) {
                assert!((s.output_in(*a) - b).abs() < 1e-12, "{code}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn values_round_trip_and_extremes_are_refused_by_name() {
        let mut st = Structure::parse("P2DZI").unwrap();
        st.drift = true;
        let mut v = Values::default();
        for (p, x) in [
            (Param::Kp, -2.5),
            (Param::Tp1, 4.0),
            (Param::Td, 0.7),
            (Param::Tz, -1.5),
            (Param::Y0, 10.0),
            (Param::Drift, 0.01),
        ] {
            v.set(p, x);
        }
        for (ky, kt, du) in [(1.0, 1.0, 1.0), (1e300, 1e100, 1e5), (1e-300, 1e-200, 1e-7)] {
            let s = Scale::of(&data(ky, kt, du), kt).unwrap();
            let mut phys = v;
            phys.set(Param::Kp, v.get(Param::Kp) * ky / du / kt);
            phys.set(Param::Y0, v.get(Param::Y0) * ky);
            phys.set(Param::Drift, v.get(Param::Drift) * ky / kt);
            for p in [Param::Tp1, Param::Td, Param::Tz] {
                phys.set(p, v.get(p) * kt);
            }
            let back = s.values_out(st, &s.values_in(st, &phys)).unwrap();
            for p in st.params() {
                let (a, b) = (back.get(p), phys.get(p));
                assert!((a - b).abs() <= 1e-14 * b.abs(), "{p:?}: {a} vs {b}");
            }
        }
        let s = Scale::of(&data(1e300, 1.0, 1e-300), 1.0).unwrap();
        let mut big = v;
        big.set(Param::Kp, 1.0);
        let e = s
            .values_out(Structure::parse("P1").unwrap(), &big)
            .unwrap_err();
        assert_eq!(e.param, Param::Kp);
        // Kp = 1 internal = half the range 0.5e300 per 1e-300 input units: 5e599.
        assert!(
            (e.log10 - (599.0 + 5f64.log10())).abs() < 1e-9,
            "{}",
            e.log10
        );
        assert!((s.ln_mse_out(1.0) - 2.0 * s.y_unit.ln()).abs() < 1e-12);
        assert!(s.mse_out(1.0).is_infinite());
    }

    #[test]
    fn a_flat_or_zero_record_still_has_units() {
        let mut d = data(1.0, 1.0, 1.0);
        d.y = vec![5.0; 11];
        assert_eq!(Scale::of(&d, 1.0).unwrap().y_unit, 5.0);
        d.y = vec![0.0; 11];
        assert_eq!(Scale::of(&d, 1.0).unwrap().y_unit, 1.0);
        d.input = Excitation::step(d.input.t0(), 0.0);
        assert!(Scale::of(&d, 1.0).is_none());
    }
}
