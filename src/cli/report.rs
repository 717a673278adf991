//! The step report: one system from flags or a JSON line ([`SystemSpec`]), analysed once
//! ([`Analysis`]), and its JSON ([`Report`]).

use super::*;

/// One system and its step, from flags or from a JSON line: the JSON keys are the flags'
/// names with `_` for `-`, with roots as `[re, im]` pairs and coefficients as numbers.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SystemSpec {
    #[serde(default, deserialize_with = "pairs")]
    pub zeros: Option<Vec<C64>>,
    #[serde(default, deserialize_with = "pairs")]
    pub poles: Option<Vec<C64>>,
    pub gain: Option<f64>,
    pub num: Option<Vec<f64>>,
    pub den: Option<Vec<f64>>,
    pub dc_gain: Option<f64>,
    pub delay: Option<f64>,
    pub amplitude: Option<f64>,
    pub samples: Option<usize>,
}

/// Roots written as `[[re, im], …]`.
pub(super) fn pairs<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<Vec<C64>>, D::Error> {
    let roots: Option<Vec<[f64; 2]>> = Deserialize::deserialize(d)?;
    Ok(roots.map(|r| r.iter().map(|&[re, im]| C64::new(re, im)).collect()))
}

/// A system with its exact step response and metrics.
#[derive(Debug, Clone)]
pub struct Analysis {
    pub tf: TransferFunction,
    pub response: StepResponse,
    pub info: StepInfo,
    pub options: StepInfoOptions,
    /// y(t) over [0, auto horizon] when samples were asked for.
    pub samples: Option<Samples>,
}

impl SystemSpec {
    /// The transfer function, with the documented defaults: gain 1, delay 0.
    pub fn transfer_function(&self) -> Result<TransferFunction, CliError> {
        let tf = match (&self.poles, &self.num, &self.den) {
            (Some(_), Some(_), _) | (Some(_), _, Some(_)) => return Err(CliError::TwoDescriptions),
            (Some(poles), None, None) => {
                let zeros = self.zeros.as_deref().unwrap_or_default();
                TransferFunction::from_zpk(zeros, poles, self.gain.unwrap_or(1.0))?
            }
            (None, Some(num), Some(den)) => {
                if self.zeros.is_some() {
                    return Err(CliError::TwoDescriptions);
                }
                if self.gain.is_some() {
                    return Err(CliError::GainWithCoefficients);
                }
                TransferFunction::from_coeffs(num, den)?
            }
            (None, Some(_), None) => return Err(CliError::NumWithoutDen),
            (None, None, Some(_)) => return Err(CliError::DenWithoutNum),
            (None, None, None) if self.zeros.is_some() => return Err(CliError::ZerosWithoutPoles),
            (None, None, None) => return Err(CliError::NoSystem),
        };
        let tf = match self.dc_gain {
            Some(_) if self.gain.is_some() => return Err(CliError::GainAndDcGain),
            Some(k) => tf.with_dc_gain(k)?,
            None => tf,
        };
        Ok(tf.with_delay(self.delay.unwrap_or(0.0))?)
    }

    /// The step response (amplitude 1 unless given), its metrics and the asked samples.
    pub fn analyse(&self, options: &StepInfoOptions) -> Result<Analysis, CliError> {
        let sample_count = self.samples.map(check_samples).transpose()?;
        let tf = self.transfer_function()?;
        let response = StepResponse::new(&tf, self.amplitude.unwrap_or(1.0))?;
        let StepAnalysis { info, horizon } = analyse(&response, options);
        finite_metrics(&info)?;
        let samples = sample_count
            .map(|n| {
                let (t, y) = response.sample_uniform(0.0, horizon, n);
                Samples::checked(t, y)
            })
            .transpose()?;
        Ok(Analysis {
            tf,
            response,
            info,
            options: *options,
            samples,
        })
    }
}

/// The step metrics, refused when one is not a finite number (a response whose terms
/// overflow near 1.8e308 gave "Undershoot inf %", "Peak inf").
pub(crate) fn finite_metrics(info: &StepInfo) -> Result<(), CliError> {
    let finite = Metric::ALL
        .iter()
        .all(|m| m.value(info).is_none_or(f64::is_finite));
    if finite {
        Ok(())
    } else {
        Err(CliError::ResponseBeyondRange)
    }
}

pub(super) fn check_samples(n: usize) -> Result<usize, CliError> {
    if (2..=MAX_SAMPLES).contains(&n) {
        Ok(n)
    } else {
        Err(CliError::Samples(n))
    }
}

/// Evenly spaced samples of y(t), times in seconds from the step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Samples {
    pub t: Vec<f64>,
    pub y: Vec<f64>,
}

impl Samples {
    /// The samples, refused when one is not a finite number (a response beyond double
    /// precision's range, which would print as NaN, inf or null).
    pub(crate) fn checked(t: Vec<f64>, y: Vec<f64>) -> Result<Self, CliError> {
        if t.iter().chain(&y).all(|x| x.is_finite()) {
            Ok(Self { t, y })
        } else {
            Err(CliError::ResponseBeyondRange)
        }
    }
}

/// The JSON report of one system: `--json` prints it, `--batch` prints one per line.
/// A metric that does not exist is `null`, and so is an infinite `dc_gain`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    pub rise_time: Option<f64>,
    pub settling_time: Option<f64>,
    pub peak: Option<f64>,
    pub peak_time: Option<f64>,
    pub overshoot: Option<f64>,
    pub undershoot: Option<f64>,
    pub steady_state: Option<f64>,
    pub settling_min: Option<f64>,
    pub settling_max: Option<f64>,
    pub dc_gain: Option<f64>,
    pub poles: Vec<[f64; 2]>,
    pub zeros: Vec<[f64; 2]>,
    /// y(t) with oscillations as e^{σt}[cos ωt + β sin ωt].
    pub expression: String,
    /// y(t) with oscillations as R e^{σt} sin(ωt + φ).
    pub expression_amplitude_phase: String,
    pub behaviour: Behaviour,
    pub stability: &'static str,
    pub gain: f64,
    pub delay: f64,
    pub amplitude: f64,
    pub order: usize,
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<Samples>,
}

impl Report {
    pub fn new(a: &Analysis) -> Self {
        let info = &a.info;
        let dc_gain = a.tf.dc_gain();
        Self {
            rise_time: info.rise_time,
            settling_time: info.settling_time,
            peak: info.peak,
            peak_time: info.peak_time,
            overshoot: info.overshoot,
            undershoot: info.undershoot,
            steady_state: info.steady_state,
            settling_min: info.settling_min,
            settling_max: info.settling_max,
            dc_gain: dc_gain.is_finite().then_some(dc_gain),
            poles: as_pairs(a.tf.poles()),
            zeros: as_pairs(a.tf.zeros()),
            expression: expression(&a.response, OscillationForm::CosSin),
            expression_amplitude_phase: expression(&a.response, OscillationForm::AmplitudePhase),
            behaviour: a.response.behaviour(),
            stability: stability_key(a.tf.stability()),
            gain: a.tf.gain(),
            delay: a.tf.delay(),
            amplitude: a.response.amplitude(),
            order: a.tf.order(),
            num: a.tf.num(),
            den: a.tf.den(),
            samples: a.samples.clone(),
        }
    }
}

/// `[re, im]` pairs, with −0 written as 0.
pub(super) fn as_pairs(roots: &[C64]) -> Vec<[f64; 2]> {
    roots.iter().map(|r| [r.re + 0.0, r.im + 0.0]).collect()
}

pub(super) fn stability_key(s: Stability) -> &'static str {
    match s {
        Stability::Stable => "stable",
        Stability::MarginallyStable => "marginally_stable",
        Stability::Unstable => "unstable",
    }
}
