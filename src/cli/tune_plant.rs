//! The process model `degrau tune` tunes for: a first- or second-order plant with a dead
//! time (FOPTD K·e^{−θs}/(τs + 1), SOPTD K·e^{−θs}/((τ1·s + 1)(τ2·s + 1))), read from the
//! system flags of `degrau step` or from the JSON `degrau fit --json` wrote (a P1, P1D, P2
//! or P2D model: its Kp, Tp1, Tp2 and Td).

use std::path::Path;

use crate::lti::TransferFunction;
use crate::lti::control::{ModelError, ProcessModel};

use super::CliError;

/// Why a system or a fit is not a plant `degrau tune` takes (its words:
/// [`crate::text::control`]).
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::text::Localize::text(self, crate::text::Lang::En))]
pub enum PlantError {
    Cli(#[from] CliError),
    /// The system has zeros (how many).
    Zeros(usize),
    /// The system has this many poles (not one or two).
    Order(usize),
    /// A pair of complex poles (re, im).
    Complex(f64, f64),
    /// A pole at the origin or in the right half plane.
    NotStable(f64),
    /// The model's numbers, refused.
    Model(#[from] ModelError),
    /// The fit file could not be read (path, the system's words).
    Read(String, String),
    /// The fit file is not the JSON of `degrau fit --json` (path, serde_json's words).
    NotFitJson(String, String),
    /// The JSON has no `model` code and `params` object (path).
    NoModel(String),
    /// The fit's model is not P1, P1D, P2 or P2D (its code).
    ModelCode(String),
    /// The fit lacks a parameter, or it is not a number (its name).
    Param(&'static str),
}

/// The closest pole pair counted as real: |im| below this share of |re|.
const REAL_POLE: f64 = 1e-6;

/// The model of a system: no zeros, one or two real stable poles (a pair whose imaginary
/// parts are below 1e-6 of their real parts, as a double pole's computed roots may be,
/// counted as real), its static gain and dead time.
pub fn model_of_system(g: &TransferFunction) -> Result<ProcessModel, PlantError> {
    if !g.zeros().is_empty() {
        return Err(PlantError::Zeros(g.zeros().len()));
    }
    let poles = g.poles();
    if !(1..=2).contains(&poles.len()) {
        return Err(PlantError::Order(poles.len()));
    }
    let mut taus = Vec::with_capacity(2);
    for p in poles {
        if p.im.abs() > REAL_POLE * p.re.abs() {
            return Err(PlantError::Complex(p.re, p.im.abs()));
        }
        if p.re >= 0.0 {
            return Err(PlantError::NotStable(p.re));
        }
        taus.push(-1.0 / p.re);
    }
    let (k, theta) = (g.dc_gain(), g.delay());
    Ok(match taus[..] {
        [tau] => ProcessModel::foptd(k, tau, theta)?,
        [tau1, tau2, ..] => ProcessModel::soptd(k, tau1, tau2, theta)?,
        [] => return Err(PlantError::Order(0)),
    })
}

/// The model of the JSON `degrau fit --json` wrote to `path` (a P1, P1D, P2 or P2D fit),
/// and the fitted dead time when it was negative. A fit may place the step's effect up to a
/// sample before the step logged (the step fell between samples); a loop cannot have a
/// negative dead time, so it is tuned with θ = 0 and the caller says so.
pub fn model_of_fit_file(path: &Path) -> Result<(ProcessModel, Option<f64>), PlantError> {
    let name = path.display().to_string();
    let text =
        std::fs::read_to_string(path).map_err(|e| PlantError::Read(name.clone(), e.to_string()))?;
    let json: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| PlantError::NotFitJson(name.clone(), e.to_string()))?;
    let (Some(code), Some(params)) = (json["model"].as_str(), json["params"].as_object()) else {
        return Err(PlantError::NoModel(name));
    };
    let param = |key: &'static str| {
        params
            .get(key)
            .and_then(serde_json::Value::as_f64)
            .ok_or(PlantError::Param(key))
    };
    let fitted_delay = if code.ends_with('D') {
        param("Td")?
    } else {
        0.0
    };
    let negative = (fitted_delay < 0.0).then_some(fitted_delay);
    let theta = fitted_delay.max(0.0);
    let model = match code {
        "P1" | "P1D" => ProcessModel::foptd(param("Kp")?, param("Tp1")?, theta)?,
        "P2" | "P2D" => ProcessModel::soptd(param("Kp")?, param("Tp1")?, param("Tp2")?, theta)?,
        other => return Err(PlantError::ModelCode(other.to_string())),
    };
    Ok((model, negative))
}
