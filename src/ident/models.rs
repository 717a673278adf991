//! Process-model structures named as MATLAB's `procest`, with its parameters:
//!
//! G(s) = Kp · (1 + Tz·s) / [(1 + Tp1·s)(1 + Tp2·s)(1 + Tp3·s)] · e^{−Td·s}   (over s with `I`)
//!
//! or, underdamped (`U`), the pair (1 + Tp1 s)(1 + Tp2 s) replaced by 1 + 2·Zeta·Tw·s + (Tw·s)².
//! Codes: `P` + number of poles (1–3) + `D` (dead time Td) + `U` (underdamped pair, Tw and
//! Zeta; needs 2 or 3 poles) + `Z` (zero, Tz; a negative Tz is a right-half-plane zero) + `I`
//! (integrator), e.g. `P1D`, `P2DU`, `P2DUZ`, `P1DI`. Times in seconds; Kp in output units
//! per input unit (per second with an integrator).
//!
//! The measured output is modelled as y(t) = Y0 + Δu·g(t − t0) + Drift·(t − t0), where g is
//! the exact unit step response of G from [`crate::lti`], t0 the step instant and Δu its size.
//! Y0 (the operating point) is free or fixed; the linear drift term is optional.

use serde::{Deserialize, Serialize};

use crate::lti::{C64, LtiError, StepResponse, TransferFunction};

/// One parameter of a process model, with procest's name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Param {
    Kp,
    Tp1,
    Tp2,
    Tp3,
    Tw,
    Zeta,
    Td,
    Tz,
    Y0,
    Drift,
}

/// Every parameter, in display order.
pub const ALL_PARAMS: [Param; 10] = [
    Param::Kp,
    Param::Tp1,
    Param::Tp2,
    Param::Tp3,
    Param::Tw,
    Param::Zeta,
    Param::Td,
    Param::Tz,
    Param::Y0,
    Param::Drift,
];

impl Param {
    /// procest's name (`Kp`, `Tp1`, …, `Zeta`), plus `Y0` and `Drift`.
    pub fn name(self) -> &'static str {
        match self {
            Param::Kp => "Kp",
            Param::Tp1 => "Tp1",
            Param::Tp2 => "Tp2",
            Param::Tp3 => "Tp3",
            Param::Tw => "Tw",
            Param::Zeta => "Zeta",
            Param::Td => "Td",
            Param::Tz => "Tz",
            Param::Y0 => "Y0",
            Param::Drift => "Drift",
        }
    }

    /// Parses a name, case-insensitively (`kp`, `TD`, `zeta`).
    pub fn parse(name: &str) -> Option<Param> {
        ALL_PARAMS
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(name.trim()))
    }

    /// Unit, for people.
    pub fn unit(self) -> &'static str {
        match self {
            Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw | Param::Td | Param::Tz => "s",
            Param::Kp | Param::Zeta | Param::Y0 | Param::Drift => "",
        }
    }
}

/// What a parameter value must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Requirement {
    Finite,
    Positive,
    NotNegative,
    NotZero,
    /// A dead time cannot be negative.
    DelayNotNegative,
}

/// Errors in model codes and parameter values (`crate::text` says them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum ModelError {
    /// Not a procest code (P, the number of poles, then any of D, U, Z, I).
    BadCode(String),
    /// An underdamped pair (U) in a code with fewer than 2 poles.
    UnderdampedNeedsTwoPoles(String),
    /// The parameter `name` = `value` breaks `requirement`.
    BadValue {
        name: &'static str,
        value: f64,
        requirement: Requirement,
    },
    /// The model's response overflowed.
    Overflow,
    NotInModel(&'static str),
    /// The model is not a valid system.
    System(#[from] LtiError),
}

/// A model structure: procest's code plus what is done with Y0 and drift.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Structure {
    /// Number of poles besides an integrator: 1, 2 or 3.
    pub poles: u8,
    pub delay: bool,
    pub underdamped: bool,
    pub zero: bool,
    pub integrator: bool,
    /// Whether Y0 is estimated (else it is held at the value given).
    pub free_offset: bool,
    /// Whether a linear drift term is estimated.
    pub drift: bool,
}

impl Structure {
    /// Parses a procest code such as `P2DU` (letters after the digit in any order).
    pub fn parse(code: &str) -> Result<Self, ModelError> {
        let bad = || ModelError::BadCode(code.to_string());
        let upper = code.trim().to_ascii_uppercase();
        let mut chars = upper.chars();
        if chars.next() != Some('P') {
            return Err(bad());
        }
        let poles = chars
            .next()
            .and_then(|c| c.to_digit(10))
            .filter(|n| (1..=3).contains(n))
            .ok_or_else(bad)? as u8;
        let mut s = Structure {
            poles,
            delay: false,
            underdamped: false,
            zero: false,
            integrator: false,
            free_offset: true,
            drift: false,
        };
        for c in chars {
            let flag = match c {
                'D' => &mut s.delay,
                'U' => &mut s.underdamped,
                'Z' => &mut s.zero,
                'I' => &mut s.integrator,
                _ => return Err(bad()),
            };
            if *flag {
                return Err(bad());
            }
            *flag = true;
        }
        if s.underdamped && s.poles < 2 {
            return Err(ModelError::UnderdampedNeedsTwoPoles(code.to_string()));
        }
        Ok(s)
    }

    /// The canonical code, letters in the order D, U, Z, I (`P2DUZ`, `P1DI`).
    pub fn code(&self) -> String {
        let mut c = format!("P{}", self.poles);
        for (on, letter) in [
            (self.delay, 'D'),
            (self.underdamped, 'U'),
            (self.zero, 'Z'),
            (self.integrator, 'I'),
        ] {
            if on {
                c.push(letter);
            }
        }
        c
    }

    /// The code plus what it does not say, in English (`P2 + drift`, `P1D, Y0 held`): kept
    /// for the app; `crate::text::Localize` says it in either language.
    pub fn label(&self) -> String {
        crate::text::Localize::text(self, crate::text::Lang::En)
    }

    /// The parameters of the transfer function and of the output model, in order.
    pub fn params(&self) -> Vec<Param> {
        let mut p = vec![Param::Kp];
        if self.underdamped {
            p.extend([Param::Tw, Param::Zeta]);
            if self.poles == 3 {
                p.push(Param::Tp3);
            }
        } else {
            p.extend(
                [Param::Tp1, Param::Tp2, Param::Tp3]
                    .into_iter()
                    .take(self.poles as usize),
            );
        }
        if self.delay {
            p.push(Param::Td);
        }
        if self.zero {
            p.push(Param::Tz);
        }
        if self.free_offset {
            p.push(Param::Y0);
        }
        if self.drift {
            p.push(Param::Drift);
        }
        p
    }

    /// Number of estimated parameters.
    pub fn len(&self) -> usize {
        self.params().len()
    }

    /// True when there is nothing to estimate (never: Kp is always there).
    pub fn is_empty(&self) -> bool {
        false
    }
}

/// Values of every parameter (those not in the structure are ignored).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Values([f64; 10]);

impl Default for Values {
    fn default() -> Self {
        let mut v = Values([0.0; 10]);
        v.set(Param::Kp, 1.0);
        v.set(Param::Tp1, 1.0);
        v.set(Param::Tp2, 0.5);
        v.set(Param::Tp3, 0.25);
        v.set(Param::Tw, 1.0);
        v.set(Param::Zeta, 0.5);
        v
    }
}

impl Values {
    pub fn get(&self, p: Param) -> f64 {
        self.0[p as usize]
    }

    pub fn set(&mut self, p: Param, value: f64) {
        self.0[p as usize] = value;
    }

    /// The values of `params`, in order.
    pub fn vector(&self, params: &[Param]) -> Vec<f64> {
        params.iter().map(|&p| self.get(p)).collect()
    }

    /// Sets `params` from a vector, in order.
    pub fn with_vector(mut self, params: &[Param], x: &[f64]) -> Self {
        for (&p, &v) in params.iter().zip(x) {
            self.set(p, v);
        }
        self
    }
}

/// A model: a structure with parameter values.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Model {
    pub structure: Structure,
    pub values: Values,
}

/// Where the step happened and how large it was.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepSetup {
    /// Step instant t0 (s).
    pub t0: f64,
    /// Step size Δu (input units).
    pub du: f64,
}

impl Model {
    pub fn new(structure: Structure, values: Values) -> Self {
        Self { structure, values }
    }

    pub fn get(&self, p: Param) -> f64 {
        self.values.get(p)
    }

    /// The transfer function G(s) (delay included, no offset or drift).
    pub fn transfer_function(&self) -> Result<TransferFunction, ModelError> {
        let s = &self.structure;
        let v = &self.values;
        let check = |p: Param, positive: bool| -> Result<f64, ModelError> {
            let x = v.get(p);
            if !x.is_finite() {
                return Err(ModelError::BadValue {
                    name: p.name(),
                    value: x,
                    requirement: Requirement::Finite,
                });
            }
            if positive && x <= 0.0 {
                return Err(ModelError::BadValue {
                    name: p.name(),
                    value: x,
                    requirement: Requirement::Positive,
                });
            }
            Ok(x)
        };
        let kp = check(Param::Kp, false)?;
        let mut poles: Vec<C64> = Vec::new();
        let mut gain = kp;
        if s.underdamped {
            let tw = check(Param::Tw, true)?;
            let zeta = check(Param::Zeta, false)?;
            if zeta < 0.0 {
                return Err(ModelError::BadValue {
                    name: "Zeta",
                    value: zeta,
                    requirement: Requirement::NotNegative,
                });
            }
            poles.extend(pair_poles(tw, zeta));
            gain /= tw * tw;
            if s.poles == 3 {
                let tp3 = check(Param::Tp3, true)?;
                poles.push(C64::new(-1.0 / tp3, 0.0));
                gain /= tp3;
            }
        } else {
            for p in [Param::Tp1, Param::Tp2, Param::Tp3]
                .into_iter()
                .take(s.poles as usize)
            {
                let tp = check(p, true)?;
                poles.push(C64::new(-1.0 / tp, 0.0));
                gain /= tp;
            }
        }
        if s.integrator {
            poles.push(C64::new(0.0, 0.0));
        }
        let mut zeros = Vec::new();
        if s.zero {
            let tz = check(Param::Tz, false)?;
            if tz != 0.0 {
                zeros.push(C64::new(-1.0 / tz, 0.0));
                gain *= tz;
            }
        }
        if gain == 0.0 {
            return Err(ModelError::BadValue {
                name: "Kp",
                value: kp,
                requirement: Requirement::NotZero,
            });
        }
        let tf = TransferFunction::from_zpk(&zeros, &poles, gain)?;
        if s.delay {
            let td = check(Param::Td, false)?;
            if td < 0.0 {
                return Err(ModelError::BadValue {
                    name: "Td",
                    value: td,
                    requirement: Requirement::DelayNotNegative,
                });
            }
            return Ok(tf.with_delay(td)?);
        }
        Ok(tf)
    }

    /// The model's output at each instant, for a step of `setup.du` at `setup.t0`.
    pub fn simulate(&self, setup: &StepSetup, times: &[f64]) -> Result<Vec<f64>, ModelError> {
        let mut out = vec![0.0; times.len()];
        self.simulate_into(setup, times, &mut out)?;
        Ok(out)
    }

    /// [`Self::simulate`] into a buffer; uniform time grids use the fast recurrence.
    pub fn simulate_into(
        &self,
        setup: &StepSetup,
        times: &[f64],
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        self.simulator(setup)?.fill(times, out);
        Ok(())
    }

    /// The model's response prepared once, to be evaluated on many pieces of a record.
    pub fn simulator(&self, setup: &StepSetup) -> Result<Simulator, ModelError> {
        Ok(Simulator {
            response: StepResponse::new(&self.transfer_function()?, setup.du)?,
            t0: setup.t0,
            y0: self.values.get(Param::Y0),
            drift: if self.structure.drift {
                self.values.get(Param::Drift)
            } else {
                0.0
            },
        })
    }

    /// The damped natural frequency ωd of the underdamped pair (rad/s), if oscillatory.
    pub fn damped_frequency(&self) -> Option<f64> {
        if !self.structure.underdamped {
            return None;
        }
        let (tw, zeta) = (self.values.get(Param::Tw), self.values.get(Param::Zeta));
        (tw > 0.0 && (0.0..1.0).contains(&zeta)).then(|| (1.0 - zeta * zeta).sqrt() / tw)
    }
}

/// A model's output for one step, ready to be evaluated at any instants (see
/// [`Model::simulator`]): a long record is simulated piece by piece with one set-up.
#[derive(Debug, Clone)]
pub struct Simulator {
    response: StepResponse,
    t0: f64,
    y0: f64,
    drift: f64,
}

impl Simulator {
    /// The output at each instant of `times` into `out` (both cut to the shorter); uniform
    /// time grids use the fast recurrence.
    pub fn fill(&self, times: &[f64], out: &mut [f64]) {
        let n = times.len().min(out.len());
        let (times, out) = (&times[..n], &mut out[..n]);
        let (t0, y0, drift) = (self.t0, self.y0, self.drift);
        let first = times.iter().position(|&t| t >= t0).unwrap_or(n);
        for (o, &t) in out.iter_mut().zip(times).take(first) {
            *o = y0 + drift * (t - t0);
        }
        let after = &times[first..];
        if let Some(uniform) = uniform_grid(after) {
            let (_, values) =
                self.response
                    .sample_uniform(uniform.0 - t0, uniform.1 - t0, after.len());
            for ((o, &t), v) in out[first..].iter_mut().zip(after).zip(values) {
                *o = y0 + v + drift * (t - t0);
            }
        } else {
            for (o, &t) in out[first..].iter_mut().zip(after) {
                *o = y0 + self.response.value(t - t0) + drift * (t - t0);
            }
        }
    }
}

/// Poles of 1/(1 + 2ζ·Tw·s + Tw²s²): (−ζ ± √(ζ²−1))/Tw, without cancellation.
pub fn pair_poles(tw: f64, zeta: f64) -> [C64; 2] {
    let wn = 1.0 / tw;
    if zeta < 1.0 {
        let wd = wn * (1.0 - zeta * zeta).sqrt();
        [C64::new(-zeta * wn, wd), C64::new(-zeta * wn, -wd)]
    } else {
        let fast = -wn * (zeta + (zeta * zeta - 1.0).sqrt());
        // Product of the roots is wn²: the slow one from it, no cancellation.
        [C64::new(fast, 0.0), C64::new(wn * wn / fast, 0.0)]
    }
}

/// (first, last) when the instants are evenly spaced to 1e-9 of the spacing, plus the
/// rounding of instants of their size (and there are ≥ 3).
pub(crate) fn uniform_grid(times: &[f64]) -> Option<(f64, f64)> {
    let n = times.len();
    if n < 3 {
        return None;
    }
    let (first, last) = (times[0], times[n - 1]);
    let dt = (last - first) / (n - 1) as f64;
    if dt <= 0.0 {
        return None;
    }
    let tolerance =
        1e-9 * dt.max(last.abs() * 1e-7) + 8.0 * f64::EPSILON * first.abs().max(last.abs());
    times
        .iter()
        .enumerate()
        .all(|(i, &t)| (t - (first + dt * i as f64)).abs() <= tolerance)
        .then_some((first, last))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_parse_and_print_canonically() {
        for code in [
            "P1", "P1D", "P2", "P2D", "P2U", "P2DU", "P2Z", "P2DZ", "P2DUZ", "P3", "P3D", "P1I",
            "P1DI",
        ] {
            assert_eq!(Structure::parse(code).unwrap().code(), code);
        }
        assert_eq!(Structure::parse("p2udz").unwrap().code(), "P2DUZ");
        assert!(matches!(
            Structure::parse("P1U"),
            Err(ModelError::UnderdampedNeedsTwoPoles(_))
        ));
        assert!(Structure::parse("P4").is_err());
        assert!(Structure::parse("P2DD").is_err());
        assert!(Structure::parse("Q1").is_err());
        let p = Structure::parse("P2DU").unwrap().params();
        assert_eq!(
            p,
            vec![Param::Kp, Param::Tw, Param::Zeta, Param::Td, Param::Y0]
        );
    }

    fn model(code: &str, set: &[(Param, f64)]) -> Model {
        let mut v = Values::default();
        for &(p, x) in set {
            v.set(p, x);
        }
        Model::new(Structure::parse(code).unwrap(), v)
    }

    #[test]
    fn p1d_matches_its_closed_form() {
        let m = model(
            "P1D",
            &[
                (Param::Kp, 2.0),
                (Param::Tp1, 3.0),
                (Param::Td, 0.5),
                (Param::Y0, 10.0),
            ],
        );
        let setup = StepSetup { t0: 1.0, du: 4.0 };
        let times: Vec<f64> = (0..50).map(|k| 0.2 * k as f64).collect();
        let y = m.simulate(&setup, &times).unwrap();
        for (t, y) in times.iter().zip(y) {
            let tau = t - 1.5;
            let exact = if tau < 0.0 {
                10.0
            } else {
                10.0 + 8.0 * (1.0 - (-tau / 3.0).exp())
            };
            assert!((y - exact).abs() < 1e-12, "t={t}: {y} vs {exact}");
        }
    }

    #[test]
    fn p2du_matches_the_notes_formula() {
        // The LECI notes' subamort_tmorto with Gdc 1.0021, θ 1.759, ζ 0.1948, ωn 0.9659.
        let (gdc, theta, zeta, wn) = (1.0021, 1.759, 0.1948, 0.9659);
        let m = model(
            "P2DU",
            &[
                (Param::Kp, gdc),
                (Param::Tw, 1.0 / wn),
                (Param::Zeta, zeta),
                (Param::Td, theta),
                (Param::Y0, 50.0),
            ],
        );
        let setup = StepSetup { t0: 5.0, du: 10.0 };
        let times = [5.0, 6.0254, 8.0762, 10.1271, 20.3812, 39.8641];
        let y = m.simulate(&setup, &times).unwrap();
        let wd = wn * (1.0f64 - zeta * zeta).sqrt();
        let phi = (1.0f64 - zeta * zeta).sqrt().atan2(zeta);
        for (t, y) in times.iter().zip(y) {
            let tt = t - 5.0 - theta;
            let dy = if tt > 0.0 {
                10.0 * (gdc
                    - gdc / (1.0 - zeta * zeta).sqrt()
                        * (-zeta * wn * tt).exp()
                        * (wd * tt + phi).sin())
            } else {
                0.0
            };
            assert!((y - (50.0 + dy)).abs() < 1e-11, "t={t}");
        }
    }

    #[test]
    fn integrator_zero_and_drift() {
        // P1I: Kp/(s(1+Tp1 s)), du = 1: y = Kp(t − Tp1(1 − e^{−t/Tp1})).
        let m = model(
            "P1I",
            &[(Param::Kp, 0.5), (Param::Tp1, 2.0), (Param::Y0, 0.0)],
        );
        let setup = StepSetup { t0: 0.0, du: 1.0 };
        let y = m.simulate(&setup, &[4.0]).unwrap()[0];
        assert!((y - 0.5 * (4.0 - 2.0 * (1.0 - (-2f64).exp()))).abs() < 1e-12);
        // P2Z with Tz < 0 dips first (inverse response).
        let m = model(
            "P2Z",
            &[
                (Param::Kp, 1.0),
                (Param::Tp1, 1.0),
                (Param::Tp2, 0.5),
                (Param::Tz, -2.0),
                (Param::Y0, 0.0),
            ],
        );
        let y = m.simulate(&setup, &[0.1, 20.0]).unwrap();
        assert!(y[0] < 0.0 && (y[1] - 1.0).abs() < 1e-6);
        let mut s = Structure::parse("P1").unwrap();
        s.drift = true;
        let mut m = model(
            "P1",
            &[(Param::Kp, 1.0), (Param::Tp1, 1.0), (Param::Y0, 1.0)],
        );
        m.structure = s;
        m.values.set(Param::Drift, 0.1);
        let y = m
            .simulate(&StepSetup { t0: 1.0, du: 1.0 }, &[0.0, 11.0])
            .unwrap();
        assert!((y[0] - 0.9).abs() < 1e-12);
        assert!((y[1] - (1.0 + 1.0 - (-10f64).exp() + 1.0)).abs() < 1e-12);
    }

    #[test]
    fn bad_values_are_refused_in_words() {
        let m = model("P1", &[(Param::Tp1, -1.0)]);
        let e = m.transfer_function().unwrap_err().to_string();
        assert!(e.contains("Tp1") && e.contains("positive"), "{e}");
        let m = model("P2U", &[(Param::Zeta, f64::NAN)]);
        assert!(m.transfer_function().is_err());
    }

    #[test]
    fn overdamped_pair_is_accurate() {
        let [a, b] = pair_poles(1.0, 1e4);
        assert!((a.re * b.re - 1.0).abs() < 1e-12);
        assert!((b.re + 1.0 / (2e4)).abs() < 1e-12);
    }
}
