//! The operating point means what it says: with `Offset::Auto` ("mean before the step") the
//! fit holds Y0 at the output measured at rest before the step, with `Offset::Free` it
//! estimates it, and the experiment says which it did (`OperatingPoint`).
//!
//! Records are simulated from the exact step response (P1D and P2, output far from zero,
//! noise 0.5 % of the step's effect, and 0.2–2 % white or coloured, quantised): the step between two samples in mid-record, and at the
//! first sample of a record that starts with it (the input before given). The TCLab records
//! in `tests/data/records` close the loop on the logs that raised the issue.

use degrau_ident::experiment::{EstimateReason, Experiment, Offset, OperatingPoint};
use degrau_ident::fit::{FitOptions, FitReport};
use degrau_ident::model::Param;
use degrau_ident::random::Lcg;
use degrau_ident::record::data::{LoadOptions, StepTest, load_file, load_str};
use degrau_lti::{C64, StepResponse, TransferFunction};

/// The true operating point of the simulated records.
const Y0: f64 = 250.0;
/// Step size Δu.
const DU: f64 = 10.0;
/// Sampling period (s).
const TS: f64 = 1.0;
/// Noise: 0.5 % of the step's effect Kp·Δu.
const NOISE: f64 = 0.005;

/// A simulated process: its structure code, transfer function and static gain.
struct Process {
    code: &'static str,
    g: TransferFunction,
    kp: f64,
}

fn p1d() -> Process {
    // 2·e^{−6s}/(15s + 1).
    let g = TransferFunction::from_zpk(&[], &[C64::new(-1.0 / 15.0, 0.0)], 2.0 / 15.0)
        .and_then(|g| g.with_delay(6.0))
        .unwrap();
    Process {
        code: "P1D",
        g,
        kp: 2.0,
    }
}

fn p2() -> Process {
    // 0.7/((8s + 1)(30s + 1)).
    let poles = [C64::new(-1.0 / 8.0, 0.0), C64::new(-1.0 / 30.0, 0.0)];
    let g = TransferFunction::from_zpk(&[], &poles, 0.7 / 240.0).unwrap();
    Process {
        code: "P2",
        g,
        kp: 0.7,
    }
}

/// A fast P1 without dead time: 2/(2s + 1), the output moves within the first sample.
fn fast_p1() -> Process {
    let g = TransferFunction::from_zpk(&[], &[C64::new(-0.5, 0.0)], 1.0).unwrap();
    Process {
        code: "P1",
        g,
        kp: 2.0,
    }
}

/// Measurement noise as real records have it: Gaussian (Box–Muller on the project's
/// seeded generator), coloured as an AR(1) process x_k = φ·x_{k−1} + e_k scaled to a
/// stationary standard deviation `sigma`, and read through an ADC of step `quantum`.
struct Noise {
    random: Lcg,
    sigma: f64,
    phi: f64,
    state: f64,
    quantum: f64,
}

impl Noise {
    fn new(seed: u64, sigma: f64, phi: f64, quantum: f64) -> Self {
        Self {
            random: Lcg(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1),
            sigma,
            phi,
            state: 0.0,
            quantum,
        }
    }

    /// `y` as measured.
    fn read(&mut self, y: f64) -> f64 {
        let innovation = self.sigma * (1.0 - self.phi * self.phi).sqrt();
        self.state = self.phi * self.state + innovation * self.random.gaussian();
        let measured = y + self.state;
        if self.quantum > 0.0 {
            (measured / self.quantum).round() * self.quantum
        } else {
            measured
        }
    }
}

/// `n` samples `TS` apart from t = 0 of the process stepped by `DU` at `t_step` from the
/// input `u_before`, as the loader reads a `t,u,y` file: the input column shows the new
/// level from the first sample at or after `t_step`.
fn record(process: &Process, t_step: f64, n: usize, seed: u64) -> StepTest {
    let sigma = NOISE * (process.kp * DU).abs();
    record_with(process, t_step, n, Noise::new(seed, sigma, 0.0, 0.0))
}

/// [`record`] with the given measurement noise.
fn record_with(process: &Process, t_step: f64, n: usize, mut noise: Noise) -> StepTest {
    let response = StepResponse::new(&process.g, DU).unwrap();
    let u_before = 20.0;
    let mut text = String::from("t,u,y\n");
    for k in 0..n {
        let t = k as f64 * TS;
        let u = if t >= t_step { u_before + DU } else { u_before };
        let y = noise.read(Y0 + response.value(t - t_step));
        text.push_str(&format!("{t},{u},{y}\n"));
    }
    load_str(&text, &LoadOptions::from_text("t", "y", "u", None, 0)).unwrap()
}

fn fit(experiment: &Experiment, test: &StepTest, code: &str) -> FitReport {
    experiment
        .fit(test, code, false, &[], &FitOptions::default(), &mut ())
        .unwrap()
        .1
}

fn estimated(report: &FitReport, p: Param) -> bool {
    report.params.iter().any(|e| e.param == p)
}

/// Auto holds Y0 at the mean of the samples strictly before the step (the sample at t0
/// comes after a step between samples), the fit's Y0 is exactly that, and it is the true
/// operating point to within the noise; Free estimates it.
#[test]
fn a_step_between_samples_holds_the_mean_before_it() {
    for (process, seed) in [(p1d(), 1), (p2(), 2)] {
        let test = record(&process, 40.5, 300, seed);
        let mut e = Experiment::new(&test, None, None, None).unwrap();
        assert_eq!((e.t0, e.du), (41.0, DU), "{}", process.code);
        let data = e.fit_data(&test).unwrap();
        let mean = test.output[..41].iter().sum::<f64>() / 41.0;
        let fact = e.operating_point_fact(&data);
        assert_eq!(
            fact,
            OperatingPoint::MeanBefore {
                y0: mean,
                samples: 41,
                wild: 0
            },
            "{}",
            process.code
        );
        let sigma = NOISE * process.kp * DU;
        assert!((mean - Y0).abs() < 4.0 * sigma / 41f64.sqrt(), "{mean}");
        let held = fit(&e, &test, process.code);
        assert!(!estimated(&held, Param::Y0), "{}", process.code);
        assert_eq!(held.model.get(Param::Y0), mean, "{}", process.code);
        assert!((held.model.get(Param::Kp) - process.kp).abs() < 0.02 * process.kp);

        e.offset = Offset::Free;
        assert_eq!(
            e.operating_point_fact(&data),
            OperatingPoint::Estimated {
                reason: EstimateReason::Asked
            }
        );
        let free = fit(&e, &test, process.code);
        assert!(estimated(&free, Param::Y0), "{}", process.code);
        assert_ne!(free.model.get(Param::Y0), mean);
        assert!((free.model.get(Param::Y0) - Y0).abs() < 3.0 * sigma);
    }
}

/// The same on records as messy as real ones: noise from 0.2 % to 2 % of the step's effect,
/// white or strongly coloured (φ = 0.8), read through an ADC, the step at varied instants
/// between samples. Auto holds Y0 at exactly the measured mean before the step, which is the
/// true operating point within what that noise allows of a mean of 41 samples.
#[test]
fn messy_records_hold_the_measured_mean_before_the_step() {
    let mut seed = 10;
    for process in [p1d(), p2()] {
        for (level, phi) in [(0.002, 0.0), (0.02, 0.0), (0.005, 0.8), (0.02, 0.8)] {
            for t_step in [40.15, 40.5, 40.9] {
                seed += 1;
                let effect = (process.kp * DU).abs();
                let noise = Noise::new(seed, level * effect, phi, 0.001 * effect);
                let test = record_with(&process, t_step, 300, noise);
                let e = Experiment::new(&test, None, None, None).unwrap();
                assert_eq!(e.t0, 41.0, "{} at {t_step}", process.code);
                let data = e.fit_data(&test).unwrap();
                let mean = test.output[..41].iter().sum::<f64>() / 41.0;
                assert_eq!(
                    e.operating_point_fact(&data),
                    OperatingPoint::MeanBefore {
                        y0: mean,
                        samples: 41,
                        wild: 0
                    }
                );
                // The standard deviation of a mean of 41 AR(1) samples is about
                // σ·√((1 + φ)/(1 − φ))/√41.
                let spread = level * effect * ((1.0 + phi) / (1.0 - phi)).sqrt() / 41f64.sqrt();
                assert!((mean - Y0).abs() < 4.0 * spread, "{mean} vs {Y0}");
                let held = fit(&e, &test, process.code);
                assert_eq!(held.model.get(Param::Y0), mean, "{}", process.code);
                let kp = held.model.get(Param::Kp);
                // Kp errs by the error of Y0 over the effect, plus the fit's own noise.
                let allowed = 4.0 * spread / effect + 4.0 * level;
                assert!(
                    (kp - process.kp).abs() < allowed * process.kp,
                    "{} level {level} φ {phi} at {t_step}: Kp {kp}",
                    process.code
                );
            }
        }
    }
}

/// A fast output has already moved at the first sample after a step between samples: that
/// sample is not part of the level before the step.
#[test]
fn the_sample_at_t0_after_a_step_between_samples_is_not_at_rest() {
    let process = fast_p1();
    let test = record(&process, 40.5, 120, 3);
    let e = Experiment::new(&test, None, None, None).unwrap();
    let data = e.fit_data(&test).unwrap();
    let moved = test.output[41] - Y0;
    // 2·10·(1 − e^{−0.25}) = 4.4 above the operating point, against a noise of 0.1.
    assert!(moved > 4.0, "{moved}");
    let Some(y0) = e.operating_point(&data) else {
        panic!("Y0 is held")
    };
    assert!((y0 - Y0).abs() < 0.1, "{y0}");
}

/// A record that starts with the step (the input before it given): no sample is before the
/// step, the one at the step instant is still at rest, and Y0 is held there.
#[test]
fn a_step_at_the_first_sample_holds_the_level_at_the_step() {
    for (process, seed) in [(p1d(), 4), (p2(), 5)] {
        let test = record(&process, 0.0, 300, seed);
        let mut e = Experiment::new(&test, None, None, Some(20.0)).unwrap();
        assert_eq!((e.t0, e.du), (0.0, DU), "{}", process.code);
        let data = e.fit_data(&test).unwrap();
        let first = test.output[0];
        assert_eq!(
            e.operating_point_fact(&data),
            OperatingPoint::AtStep { y0: first }
        );
        let sigma = NOISE * process.kp * DU;
        assert!((first - Y0).abs() < 4.0 * sigma);
        let held = fit(&e, &test, process.code);
        assert!(!estimated(&held, Param::Y0));
        assert_eq!(held.model.get(Param::Y0), first, "{}", process.code);
        assert!((held.model.get(Param::Kp) - process.kp).abs() < 0.03 * process.kp);

        e.offset = Offset::Free;
        let free = fit(&e, &test, process.code);
        assert!(estimated(&free, Param::Y0), "{}", process.code);
    }
}

/// A step instant before the first sample kept leaves nothing measured: Y0 is estimated,
/// and the experiment says why.
#[test]
fn no_sample_at_or_before_the_step_estimates_y0() {
    let test = record(&p1d(), 40.5, 300, 6);
    let mut e = Experiment::new(&test, None, None, None).unwrap();
    e.window = Some((50.0, 299.0));
    let data = e.fit_data(&test).unwrap();
    assert_eq!(
        e.operating_point_fact(&data),
        OperatingPoint::Estimated {
            reason: EstimateReason::NoSampleBeforeStep
        }
    );
    assert_eq!(e.operating_point(&data), None);
    assert!(e.structure("P1D", false, &data).unwrap().free_offset);
    // A given value is held whatever the data.
    e.offset = Offset::Fixed(251.0);
    assert_eq!(
        e.operating_point_fact(&data),
        OperatingPoint::Given { y0: 251.0 }
    );
}

fn records(name: &str) -> String {
    format!(
        "{}/tests/data/records/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/../..")
    )
}

/// The TCLab log that raised the issue writes t = 0 twice, the heater off then on: Y0 is
/// held at the first row's 20.9 °C (it was fitted free at 17.95), with or without the
/// initial input 0.
#[test]
fn tclab_holds_y0_at_its_first_samples_level() {
    let options = LoadOptions::from_text("", "T1", "Q1", None, 0);
    let test = load_file(records("tclab_step_q1_50_synthetic.csv"), &options).unwrap();
    for initial_input in [None, Some(0.0)] {
        let e = Experiment::new(&test, None, None, initial_input).unwrap();
        let data = e.fit_data(&test).unwrap();
        assert_eq!(
            e.operating_point_fact(&data),
            OperatingPoint::MeanBefore {
                y0: 20.9,
                samples: 1,
                wild: 0
            }
        );
        let report = fit(&e, &test, "P1");
        assert_eq!(report.model.get(Param::Y0), 20.9);
    }
}

/// Kantor's TCLab step, the heater at 100 % from the first row: with the initial input 0
/// the step is at the first sample and Y0 is held at its 23.48 °C.
#[test]
fn tclab_heater_on_from_the_first_row_holds_y0_at_that_row() {
    let options = LoadOptions::from_text("Time", "T1", "Q1", None, 0);
    let test = load_file(records("tclab_step_q1_100_spikes.csv"), &options).unwrap();
    let e = Experiment::new(&test, None, None, Some(0.0)).unwrap();
    let data = e.fit_data(&test).unwrap();
    assert_eq!(
        e.operating_point_fact(&data),
        OperatingPoint::AtStep { y0: 23.48 }
    );
    assert_eq!(fit(&e, &test, "P1D").model.get(Param::Y0), 23.48);
}
