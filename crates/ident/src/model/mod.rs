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
//! The measured output is modelled as y(t) = Y0 + (g ∗ u)(t) + Drift·(t − t0) + x(t): the exact
//! response of G (from [`degrau_lti`]) to the input's deviation from its level before the first
//! change ([`Excitation`]: one ideal step Δu at t0, or the measured input held between its
//! samples), t0 the first change. Y0 (the operating point) is free or fixed; the linear drift
//! term is optional. Two more terms come from the test rather than the process:
//! - **the step instant** (`Ta`, s): a change first seen at a sample happened up to one
//!   sampling period earlier; a structure with `lead` moves every change earlier by Ta
//!   (0 ≤ Ta < Ts), or, with a dead time, lets Td go down to −Ts (the response starting
//!   before the sample that first shows the change);
//! - **the initial transient** (`X1`, `X2`, `X3`, output units): a test not at rest at its
//!   first change carries the free response of G's own poles, x(t) = Σ Xᵢ·φᵢ(t − ts), with
//!   φ the Newton basis of the poles' exponentials (e^{p₁τ}, the divided differences
//!   e^{pτ}[p₁, p₂], e^{pτ}[p₁, p₂, p₃]; e^{στ}cos ωdτ and e^{στ}sin(ωdτ)/ωd for an
//!   underdamped pair), which stays well conditioned when two poles meet; Xᵢ are the
//!   coefficients at the record's first sample ts (the first change for a typed step):
//!   taken from the first change, a fast mode extrapolated back over the samples before it
//!   grows as e^{|p|·t} and the fit loses itself (a 15 s lag 250 s back: 10⁷). An
//!   integrator's own mode is Y0 itself.
//!
//! Below it: the input as the model sees it ([`excitation`]), the internal units a record fits
//! in ([`scale`]) and the initial transient of a test not at rest (`transient`).

pub mod excitation;
pub mod scale;
pub(crate) mod transient;

use serde::{Deserialize, Serialize};

use crate::model::excitation::Excitation;
use crate::model::transient::Transient;
use degrau_lti::{C64, LtiError, StepInfo, StepInfoOptions, StepResponse, TransferFunction};

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
    /// How long before the sample that first shows it each input change happened (s).
    Ta,
    /// Coefficients of the initial transient (output units).
    X1,
    X2,
    X3,
}

/// How many parameters there are.
pub const PARAM_COUNT: usize = 14;

/// Every parameter, in display order.
pub const ALL_PARAMS: [Param; PARAM_COUNT] = [
    Param::Kp,
    Param::Tp1,
    Param::Tp2,
    Param::Tp3,
    Param::Tw,
    Param::Zeta,
    Param::Td,
    Param::Tz,
    Param::Ta,
    Param::X1,
    Param::X2,
    Param::X3,
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
            Param::Ta => "Ta",
            Param::X1 => "X1",
            Param::X2 => "X2",
            Param::X3 => "X3",
        }
    }

    /// Parses a name, case-insensitively (`kp`, `TD`, `zeta`).
    pub fn parse(name: &str) -> Option<Param> {
        ALL_PARAMS
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(name.trim()))
    }

    /// Whether the parameter is a time (s): a time constant, the dead time, the zero's, Ta.
    pub fn is_time(self) -> bool {
        matches!(
            self,
            Param::Tp1 | Param::Tp2 | Param::Tp3 | Param::Tw | Param::Td | Param::Tz | Param::Ta
        )
    }

    /// Unit, for people.
    pub fn unit(self) -> &'static str {
        if self.is_time() { "s" } else { "" }
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

/// Errors in model codes and parameter values (`crate::words` says them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
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
    /// Whether the input changes' instants are estimated within their sampling interval
    /// (`Ta`, or a `Td` down to −Ts with a dead time).
    #[serde(default)]
    pub lead: bool,
    /// Whether an initial transient is estimated (the test was not at rest).
    #[serde(default)]
    pub transient: bool,
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
            lead: false,
            transient: false,
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
    /// for the app; `degrau_words::Localize` says it in either language.
    pub fn label(&self) -> String {
        degrau_words::Localize::text(self, degrau_words::Lang::En)
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
        if self.lead && !self.delay {
            p.push(Param::Ta);
        }
        p.extend(self.transient_params());
        if self.free_offset {
            p.push(Param::Y0);
        }
        if self.drift {
            p.push(Param::Drift);
        }
        p
    }

    /// The initial transient's coefficients (X1… one per pole, none without `transient`).
    pub fn transient_params(&self) -> Vec<Param> {
        let count = if self.transient {
            self.poles as usize
        } else {
            0
        };
        [Param::X1, Param::X2, Param::X3][..count].to_vec()
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

/// Values of every parameter (those not in the structure are ignored). Saved as a list in
/// [`ALL_PARAMS`]'s declaration order; a shorter list (saved before a parameter was added)
/// reads with the missing ones at 0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "Vec<f64>", into = "Vec<f64>")]
pub struct Values([f64; PARAM_COUNT]);

impl From<Vec<f64>> for Values {
    fn from(v: Vec<f64>) -> Self {
        let mut out = [0.0; PARAM_COUNT];
        for (o, x) in out.iter_mut().zip(v) {
            *o = x;
        }
        Values(out)
    }
}

impl From<Values> for Vec<f64> {
    fn from(v: Values) -> Self {
        v.0.to_vec()
    }
}

impl Default for Values {
    fn default() -> Self {
        let mut v = Values([0.0; PARAM_COUNT]);
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
    /// The given parameters at their values, every other at 0.
    pub fn from_pairs(pairs: &[(Param, f64)]) -> Self {
        let mut v = Self::default();
        pairs.iter().for_each(|&(p, x)| v.set(p, x));
        v
    }

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
        if kp == 0.0 {
            return Err(ModelError::BadValue {
                name: "Kp",
                value: kp,
                requirement: Requirement::NotZero,
            });
        }
        if !gain.is_normal() {
            // Kp over the time constants' product left the range of a double (Kp = 2 over
            // time constants of 1e300 s, or Tp1 = 5e-324 s).
            return Err(degrau_lti::LtiError::GainOutOfRange.into());
        }
        let tf = TransferFunction::from_zpk(&zeros, &poles, gain)?;
        if s.delay {
            let td = check(Param::Td, false)?;
            if td < 0.0 && !s.lead {
                return Err(ModelError::BadValue {
                    name: "Td",
                    value: td,
                    requirement: Requirement::DelayNotNegative,
                });
            }
            // A negative Td (with `lead`) is the step instant, not the process: G has none.
            return Ok(tf.with_delay(td.max(0.0))?);
        }
        Ok(tf)
    }

    /// How far the model moves the input's changes in time (s): the dead time, less the
    /// step-instant lead (Ta, or the negative part of Td).
    pub fn input_shift(&self) -> f64 {
        let s = &self.structure;
        let td = if s.delay {
            self.values.get(Param::Td)
        } else {
            0.0
        };
        let ta = if s.lead && !s.delay {
            self.values.get(Param::Ta)
        } else {
            0.0
        };
        td - ta
    }

    /// The settling time of G's step response into a band of ± `threshold` of its final
    /// value (s from the step, dead time included; MATLAB's stepinfo, 0.02 its default),
    /// exact; `None` when it does not settle (an integrator, an undamped pair) or G cannot
    /// be formed. It does not depend on the step's size or sign: a unit step is used.
    pub fn settling_time(&self, threshold: f64) -> Option<f64> {
        let options = StepInfoOptions {
            settling_threshold: threshold,
            ..StepInfoOptions::default()
        };
        let tf = self.transfer_function().ok()?;
        let response = StepResponse::new(&tf, 1.0).ok()?;
        StepInfo::of_response(&response, &options).settling_time
    }

    /// The settling time into stepinfo's default band (± 2 % of the final value, s from the
    /// step, dead time included): the one rule identification reads a settled response by
    /// ([`Self::settling_time`] for another band).
    pub fn settling(&self) -> Option<f64> {
        self.settling_time(StepInfoOptions::default().settling_threshold)
    }

    /// The dead time of G (s): Td when the structure has one and it is positive, else 0.
    pub fn dead_time(&self) -> f64 {
        if self.structure.delay {
            self.values.get(Param::Td).max(0.0)
        } else {
            0.0
        }
    }

    /// The model's output at each instant of `times` (ascending) for the input `input`.
    pub fn simulate(&self, input: &Excitation, times: &[f64]) -> Result<Vec<f64>, ModelError> {
        let mut out = vec![0.0; times.len()];
        self.simulate_into(input, times, &mut out)?;
        Ok(out)
    }

    /// [`Self::simulate`] into a buffer.
    pub fn simulate_into(
        &self,
        input: &Excitation,
        times: &[f64],
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        self.simulator(input)?.fill(times, out);
        Ok(())
    }

    /// The model's response to `input` prepared once, to be evaluated on many pieces of a
    /// record.
    pub fn simulator(&self, input: &Excitation) -> Result<Simulator, ModelError> {
        // G carries the dead time; the steps carry the lead (what is left of the shift).
        let tf = self.transfer_function()?;
        let lead = (self.input_shift() - tf.delay()).min(0.0);
        let ramps = input.shifted_ramps(lead);
        let ramp = if ramps.is_empty() {
            None
        } else {
            Some(StepResponse::new(&integrated(&tf)?, 1.0)?)
        };
        Ok(Simulator {
            response: StepResponse::new(&tf, 1.0)?,
            steps: input.shifted_steps(lead),
            ramp,
            ramps,
            t0: input.t0(),
            origin: input.start.map_or(input.t0(), |s| s.min(input.t0())),
            y0: self.values.get(Param::Y0),
            drift: if self.structure.drift {
                self.values.get(Param::Drift)
            } else {
                0.0
            },
            transient: Transient::of(self),
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

/// G(s)/s (with G's dead time): its step response is G's response to a unit ramp.
fn integrated(g: &TransferFunction) -> Result<TransferFunction, ModelError> {
    let mut poles = g.poles().to_vec();
    poles.push(C64::new(0.0, 0.0));
    Ok(TransferFunction::from_zpk(g.zeros(), &poles, g.gain())?.with_delay(g.delay())?)
}

/// A model's output for one input, ready to be evaluated at any instants (see
/// [`Model::simulator`]): a long record is simulated piece by piece with one set-up.
#[derive(Debug, Clone)]
pub struct Simulator {
    /// G's unit step response, with its dead time.
    response: StepResponse,
    /// The input's steps, moved earlier by the step-instant lead: (instant, size).
    steps: Vec<(f64, f64)>,
    /// G(s)/s's unit step response, for the slope changes of a first-order hold.
    ramp: Option<StepResponse>,
    ramps: Vec<(f64, f64)>,
    /// The first change's instant (s): the origin of the drift.
    t0: f64,
    /// The origin of the transient (s): the record's first instant, else the first change.
    origin: f64,
    y0: f64,
    drift: f64,
    transient: Option<Transient>,
}

impl Simulator {
    /// The output at each instant of `times` (ascending) into `out` (both cut to the
    /// shorter). One ideal step on a uniform grid uses the step response's own recurrence;
    /// anything else the exact superposition of [`StepResponse::superpose`], which advances
    /// a running state from instant to instant (one exponential per distinct spacing).
    pub fn fill(&self, times: &[f64], out: &mut [f64]) {
        let n = times.len().min(out.len());
        let (times, out) = (&times[..n], &mut out[..n]);
        match (self.steps.as_slice(), &self.ramp) {
            ([(s, a)], None) => self.one_step(*s, *a, times, out),
            _ => {
                self.response.superpose(&self.steps, times, out);
                if let Some(ramp) = &self.ramp {
                    let mut extra = vec![0.0; n];
                    ramp.superpose(&self.ramps, times, &mut extra);
                    out.iter_mut().zip(&extra).for_each(|(o, e)| *o += e);
                }
            }
        }
        let (t0, y0, drift) = (self.t0, self.y0, self.drift);
        for (o, &t) in out.iter_mut().zip(times) {
            *o += y0 + drift * (t - t0);
        }
        if let Some(x) = &self.transient {
            x.add_to(times, self.origin, out);
        }
    }

    /// The forced response (what the input drives, proportional to the gain) from the
    /// output `values` this simulator filled at `times`: Y0, the drift's line and the initial
    /// transient are taken out in place, the transient from its `basis` on `times` when
    /// given ([`Simulator::transient_basis`]), else evaluated.
    pub fn forced_from(&self, times: &[f64], values: &mut [f64], basis: Option<&[Vec<f64>]>) {
        let (t0, y0, drift) = (self.t0, self.y0, self.drift);
        for (v, &t) in values.iter_mut().zip(times) {
            *v -= y0 + drift * (t - t0);
        }
        let Some(x) = &self.transient else { return };
        let n = times.len().min(values.len());
        match basis.filter(|b| b.len() == x.coefficients().len()) {
            Some(basis) => {
                for (column, coefficient) in basis.iter().zip(x.coefficients()) {
                    values[..n]
                        .iter_mut()
                        .zip(column)
                        .for_each(|(v, phi)| *v -= coefficient * phi);
                }
            }
            None => {
                let mut free = vec![0.0; n];
                x.add_to(&times[..n], self.origin, &mut free);
                values.iter_mut().zip(&free).for_each(|(v, f)| *v -= f);
            }
        }
    }

    /// The initial transient's basis at `times`: one column per coefficient (X1's first),
    /// the output's derivative along it; none without a transient.
    pub fn transient_basis(&self, times: &[f64]) -> Vec<Vec<f64>> {
        let Some(x) = &self.transient else {
            return Vec::new();
        };
        let mut columns = vec![vec![0.0; times.len()]; x.coefficients().len()];
        x.basis_into(times, self.origin, &mut columns);
        columns
    }

    /// The first change's instant (s), the origin of the drift's line.
    pub fn drift_origin(&self) -> f64 {
        self.t0
    }

    /// a·g(t − s) into `out`, 0 before s.
    fn one_step(&self, s: f64, a: f64, times: &[f64], out: &mut [f64]) {
        let n = times.len();
        let first = times.iter().position(|&t| t >= s).unwrap_or(n);
        out[..first].iter_mut().for_each(|o| *o = 0.0);
        let after = &times[first..];
        if let Some(uniform) = uniform_grid(after) {
            let (_, values) =
                self.response
                    .sample_uniform(uniform.0 - s, uniform.1 - s, after.len());
            for (o, v) in out[first..].iter_mut().zip(values) {
                *o = a * v;
            }
        } else {
            // Advances a running state: no exponential per instant.
            self.response.superpose(&[(s, a)], after, &mut out[first..]);
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
        Model::new(Structure::parse(code).unwrap(), Values::from_pairs(set))
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
        let setup = Excitation::step(1.0, 4.0);
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
        let setup = Excitation::step(5.0, 10.0);
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
        let setup = Excitation::step(0.0, 1.0);
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
            .simulate(&Excitation::step(1.0, 1.0), &[0.0, 11.0])
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
