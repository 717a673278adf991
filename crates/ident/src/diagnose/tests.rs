use super::extension::*;
use super::judge::*;
use super::step::*;
use super::*;
use crate::fit::{FitOptions, FitReport, fit};
use crate::model::excitation::Excitation;
use crate::model::{Model, Param, Structure, Values};

fn model(code: &str, params: &[(Param, f64)]) -> Model {
    let mut v = Values::default();
    params.iter().for_each(|&(p, x)| v.set(p, x));
    Model::new(Structure::parse(code).unwrap(), v)
}

/// A P1 record (Kp 2, τ 10 s, Y0 50, step at 20.4 s between samples), noise ± 0.02.
fn p1_record() -> FitData {
    let times: Vec<f64> = (0..=150).map(f64::from).collect();
    let input = Excitation::step(20.4, 1.0);
    let truth = model(
        "P1",
        &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
    );
    let mut rng = crate::random::Lcg(5);
    let y = truth
        .simulate(&input, &times)
        .unwrap()
        .into_iter()
        .map(|v| v + 0.02 * rng.symmetric())
        .collect();
    FitData { times, y, input }
}

fn fitted(data: &FitData, code: &str, params: &[(Param, f64)]) -> FitReport {
    let m = model(code, params);
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    fit(data, m.structure, m.values, &options, &mut ()).unwrap()
}

/// `r` with a drift term, refitted on `data` from its values and `drift` (one start).
fn refitted_with_drift(data: &FitData, r: &FitReport, drift: f64) -> FitReport {
    let mut s = r.model.structure;
    s.drift = true;
    let mut v = r.model.values;
    v.set(Param::Drift, drift);
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    fit(data, s, v, &options, &mut ()).unwrap()
}

#[test]
fn the_backward_look_takes_out_a_drift_that_no_longer_pays() {
    let data = p1_record();
    let current = fitted(
        &data,
        "P1",
        &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
    );
    let with_drift = refitted_with_drift(&data, &current, 1e-4);
    let (e, step) = backward_step(&data, &with_drift, Extension::Pole).expect("taken out");
    assert_eq!(e, Extension::Drift);
    assert!(step.removed && step.cause == Cause::Drift);
    assert!(!step.fit.model.structure.drift);
    let Evidence::NoLongerPays { param, .. } = step.evidence else {
        panic!("{:?}", step.evidence)
    };
    assert_eq!(param, Param::Drift);
    // The term just paid for is never taken out in the same step.
    assert!(backward_step(&data, &with_drift, Extension::Drift).is_none());
    // A P1 without the drift has nothing to take out.
    assert!(backward_step(&data, &current, Extension::Pole).is_none());
}

#[test]
fn a_gain_measured_only_with_a_drift_is_said_and_a_settled_one_is_not() {
    let data = p1_record();
    let settled = fitted(
        &data,
        "P1",
        &[(Param::Kp, 2.0), (Param::Tp1, 10.0), (Param::Y0, 50.0)],
    );
    assert!(!settled.kp_correlations.is_empty());
    assert_eq!(gain_trade(&settled), None, "{:?}", settled.kp_correlations);
    // The same record from 2 s before the step to 15 s after it (1.5 τ): nothing before
    // the step pins a drift, and the drift and the gain trade.
    let keep: Vec<bool> = data
        .times
        .iter()
        .map(|&t| (18.0..=35.0).contains(&t))
        .collect();
    let short = data.keeping(&keep);
    let with_drift = refitted_with_drift(&short, &settled, 0.0);
    let trade = gain_trade(&with_drift).expect("trades");
    assert!(matches!(trade.with, Param::Drift | Param::Tp1), "{trade:?}");
    assert!(trade.correlation.abs() >= TRADE_CORRELATION);
    // As correlated, but the gain pinned within 1 %: measured, nothing to say.
    let mut tight = with_drift.clone();
    let kp = tight.model.get(Param::Kp);
    for e in tight.params.iter_mut().filter(|e| e.param == Param::Kp) {
        e.ci95 = Some((0.99 * kp, 1.01 * kp));
    }
    assert_eq!(gain_trade(&tight), None);
}

#[test]
fn a_dead_time_at_or_below_zero_is_no_dead_time() {
    let data = p1_record();
    let current = fitted(
        &data,
        "P1D",
        &[
            (Param::Kp, 2.0),
            (Param::Tp1, 10.0),
            (Param::Y0, 50.0),
            (Param::Td, 0.0),
        ],
    );
    let mut negative = current.clone();
    negative.model.values.set(Param::Td, -0.2);
    assert!(no_longer_pays(&negative, Param::Td, -50.0));
    let mut positive = current.clone();
    positive.model.values.set(Param::Td, 1.5);
    assert!(!no_longer_pays(&positive, Param::Td, -50.0));
    assert!(no_longer_pays(&positive, Param::Td, -5.0));
}

#[test]
fn a_lag_slower_than_the_record_is_refused_and_a_ringing_is_not() {
    // 100 s after the step at 20 s.
    let times: Vec<f64> = (0..=120).map(f64::from).collect();
    let data = FitData {
        y: vec![0.0; times.len()],
        times,
        input: Excitation::step(20.0, 1.0),
    };
    let p1 = model("P1", &[(Param::Tp1, 10.0)]);
    let slow = model("P2", &[(Param::Tp1, 10.0), (Param::Tp2, 900.0)]);
    assert!(beyond_record(&data, &p1, &slow));
    // A slow zero as well: SBHS's P2Z with Tz = 758 s and a pole of 8,464 s.
    let zero = model("P1Z", &[(Param::Tp1, 10.0), (Param::Tz, -300.0)]);
    assert!(beyond_record(&data, &p1, &zero));
    let second = model("P2", &[(Param::Tp1, 10.0), (Param::Tp2, 40.0)]);
    assert!(!beyond_record(&data, &p1, &second));
    // A lightly damped pair: its envelope Tw/ζ = 200 s outlasts the record, but the
    // ringing shows its period; Tw = 10 s is what counts.
    let ringing = model("P2U", &[(Param::Tw, 10.0), (Param::Zeta, 0.05)]);
    assert!(!beyond_record(&data, &p1, &ringing));
    // A start already slower than the record is not refused its own lag.
    let long = model("P1", &[(Param::Tp1, 300.0)]);
    let longer = model("P2", &[(Param::Tp1, 300.0), (Param::Tp2, 20.0)]);
    assert!(!beyond_record(&data, &long, &longer));
}
