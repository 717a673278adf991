//! Flaws of the test alone on records built here (a P1 process, the CSV text read as
//! `degrau diagnose` reads it): each flaw is named among the test's causes, no structure
//! is bought for it, and the gain is the process's own.

use degrau_ident::challenge::solve::diagnosis;
use degrau_ident::diagnose::DiagnoseReport;
use degrau_ident::diagnose::test_causes::{TestCauseKind, TestEvidence};
use degrau_ident::model::Param;
use degrau_ident::random::Lcg;

/// A first-order process of lag `tau` from `y0`, sampled every `h` s for `n` samples, the
/// input from `u0` changed at each (instant, Δu, that change's own gain), with white noise
/// of `sd`, written as a CSV.
fn p1_record(
    tau: f64,
    y0: f64,
    u0: f64,
    changes: &[(f64, f64, f64)],
    sampling: (f64, usize),
    sd: f64,
) -> String {
    p1_record_coloured(tau, y0, u0, changes, sampling, (sd, 0.0))
}

/// [`p1_record`] with AR(1) noise of standard deviation `sd` and lag-one correlation `rho`.
fn p1_record_coloured(
    tau: f64,
    y0: f64,
    u0: f64,
    changes: &[(f64, f64, f64)],
    (h, n): (f64, usize),
    (sd, rho): (f64, f64),
) -> String {
    let mut rng = Lcg(0x7E57_F1A5);
    let mut csv = String::from("t,u,y\n");
    let mut e = 0.0;
    for k in 0..n {
        let t = h * k as f64;
        let mut u = u0;
        e = rho * e + (1.0 - rho * rho).sqrt() * sd * rng.gaussian();
        let mut y = y0 + e;
        for &(tc, du, gain) in changes.iter().filter(|c| c.0 <= t) {
            u += du;
            y += gain * du * (1.0 - (-(t - tc) / tau).exp());
        }
        csv.push_str(&format!("{t:.1},{u:.5},{y:.5}\n"));
    }
    csv
}

/// [`p1_record`] from a process still answering an earlier change `(before, du)`: made
/// `before` s ahead of the record, of the same gain as the first change.
fn p1_not_at_rest(
    tau: f64,
    earlier: (f64, f64),
    changes: &[(f64, f64, f64)],
    sampling: (f64, usize),
    sd: f64,
) -> String {
    let gain = changes[0].2;
    let plain = p1_record(tau, 0.0, 23.23, changes, sampling, sd);
    let mut csv = String::from("t,u,y\n");
    for line in plain.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let tail = gain * earlier.1 * (1.0 - (-(v[0] + earlier.0) / tau).exp());
        csv.push_str(&format!(
            "{:.1},{:.5},{:.5}\n",
            v[0],
            v[1],
            20.0 + v[2] + tail
        ));
    }
    csv
}

/// No structural cause named, and the final gain within 5 % of the process's `kp`.
fn no_structure_and_its_gain(r: &DiagnoseReport, kp: f64) {
    assert_eq!(r.steps.first().map(|s| s.cause), None, "{:?}", r.steps);
    let got = r.final_fit.model.get(Param::Kp);
    assert!(
        (got / kp - 1.0).abs() < 0.05,
        "Kp {got}, the process's {kp}"
    );
}

fn named(r: &DiagnoseReport, kind: TestCauseKind) -> bool {
    r.test_causes.iter().any(|c| c.kind == kind)
}

#[test]
fn a_gain_that_differs_up_and_down_is_named_though_a_joint_p1_bends_its_lag() {
    // Up with gain −2.8, back down with −1.5, each held over eight lags of 17 s: a joint P1
    // through both compromises with a lag near 67 s, under which neither change looks held.
    let changes = [(20.05, 8.53, -2.8), (167.75, -8.53, -1.5)];
    let csv = p1_record(17.0, 98.7, 57.17, &changes, (0.1, 3156), 0.05);
    let r = diagnosis(&csv).expect("the record is diagnosed");
    assert!(
        named(&r, TestCauseKind::Nonlinearity),
        "{:?}",
        r.test_causes
    );
    no_structure_and_its_gain(&r, -2.8);
}

#[test]
fn a_test_not_at_rest_is_no_nonlinearity_when_its_first_window_is_short() {
    // τ 7 s; the record starts 4 s after an earlier change of half the step, 13.6 s before
    // the first of two changes of the same gain: the first window holds only the last 4.5 s
    // of that motion, too little for its own rest test, and fitted from rest its gain was
    // 6 % off the second's.
    let changes = [(13.65, -3.695, -3.75), (70.15, 3.695, -3.75)];
    let csv = p1_not_at_rest(7.0, (4.0, -1.85), &changes, (0.1, 1268), 0.012);
    let r = diagnosis(&csv).expect("the record is diagnosed");
    assert!(named(&r, TestCauseKind::NotAtRest), "{:?}", r.test_causes);
    assert!(
        !named(&r, TestCauseKind::Nonlinearity),
        "{:?}",
        r.test_causes
    );
    no_structure_and_its_gain(&r, -3.75);
}

#[test]
fn a_motion_small_against_the_range_is_not_at_rest_when_the_transient_explains_it() {
    // τ 19 s, an earlier change of a quarter of the step 17 s before the record, the step
    // 15 s in: the output falls by under 5 % of the record's range before it, four times
    // the noise; left to the model's loop, it bought a zero.
    let changes = [(15.05, -9.38, 1.637)];
    let csv = p1_not_at_rest(19.0, (17.0, -2.2), &changes, (0.1, 1900), 0.135);
    let r = diagnosis(&csv).expect("the record is diagnosed");
    let motion = r.test_causes.iter().find_map(|c| match &c.evidence {
        TestEvidence::NotAtRest { motion } => Some(*motion),
        _ => None,
    });
    let motion = motion.unwrap_or_else(|| panic!("not named: {:?}", r.test_causes));
    let ys: Vec<f64> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(2).unwrap().parse().unwrap())
        .collect();
    let range = ys.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - ys.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(
        motion.change.abs() < 0.05 * range,
        "{motion:?} range {range}"
    );
    no_structure_and_its_gain(&r, 1.637);
}

/// `csv`'s output column rounded to multiples of `quantum` (a coarse converter).
fn rounded(csv: &str, quantum: f64) -> String {
    csv.lines()
        .enumerate()
        .map(|(k, line)| match (k, line.rsplit_once(',')) {
            (0, _) | (_, None) => format!("{line}\n"),
            (_, Some((head, y))) => {
                let y: f64 = y.parse().unwrap();
                format!("{head},{:.6}\n", quantum * (y / quantum).round())
            }
        })
        .collect()
}

#[test]
fn a_coarse_staircase_buys_no_structure_and_keeps_its_gain() {
    // P1 records read through a converter of 6–10 % of the effect, the noise 1–5 % of the
    // quantum (a staircase, white or coloured), one or two changes between samples, far
    // from zero: least
    // squares bent a pole and a zero to the rounding (4 of 200 clear challenges did), which
    // the samples read within their quanta do not pay for; and read so, the gain is the
    // process's within 1.5 %, and several times nearer on average than least squares'.
    let mut misses = Vec::new();
    let mut offs = Vec::new();
    for i in 0..8u64 {
        let mut rng = Lcg(0x57A1_C0A5 + i);
        let mut range = |a: f64, b: f64| a + (b - a) * rng.unit();
        let tau = range(5.0, 30.0);
        let h = (tau / range(40.0, 150.0) * 10.0).round() / 10.0;
        let gain = range(0.5, 3.0) * if i % 3 == 0 { -1.0 } else { 1.0 };
        let du = range(2.0, 10.0) * if i % 4 == 1 { -1.0 } else { 1.0 };
        let effect = (gain * du).abs();
        let quantum = range(0.06, 0.10) * effect;
        let sd = range(0.01, 0.05) * quantum;
        let (y0, u0) = (range(-300.0, 300.0), range(0.0, 80.0));
        let t1 = 1.5 * tau + 0.37 * h;
        let mut changes = vec![(t1, du, gain)];
        if i % 2 == 1 {
            changes.push((t1 + 8.0 * tau + 0.61 * h, -du, gain));
        }
        let length = t1 + 8.0 * tau * changes.len() as f64;
        // Every third record's noise coloured (AR(1), ρ 0.3–0.7).
        let rho = if i % 3 == 2 { range(0.3, 0.7) } else { 0.0 };
        let sampling = (h, (length / h) as usize);
        let csv = p1_record_coloured(tau, y0, u0, &changes, sampling, (sd, rho));
        let r = diagnosis(&rounded(&csv, quantum)).unwrap();
        let kp = r.final_fit.model.get(Param::Kp);
        let causes: Vec<&str> = r.steps.iter().map(|s| s.cause.id()).collect();
        let within = r.test_causes.iter().find_map(|c| match c.evidence {
            TestEvidence::Quantisation { within_quanta, .. } => within_quanta,
            _ => None,
        });
        let off = |k: f64| (k / gain - 1.0).abs();
        offs.push((off(kp), within.map_or(f64::INFINITY, off)));
        let bad = !causes.is_empty()
            || !named(&r, TestCauseKind::Quantisation)
            || off(kp) > 0.05
            || !within.is_some_and(|w| off(w) < 0.015);
        if bad {
            misses.push(format!(
                "#{i}: {causes:?} Kp {kp}, within the quanta {within:?} (true {gain}) q \
                 {quantum} sd {sd}"
            ));
        }
    }
    assert!(misses.is_empty(), "{}", misses.join("\n"));
    // Measured: 0.3 % against 1.5 % on average.
    let mean = |pick: fn(&(f64, f64)) -> f64| offs.iter().map(pick).sum::<f64>() / 8.0;
    let (least_squares, within) = (mean(|o| o.0), mean(|o| o.1));
    assert!(
        within < 0.5 * least_squares,
        "{within} against {least_squares}"
    );
}

#[test]
fn a_level_before_the_step_off_by_its_own_noise_is_no_offset() {
    // Stepped and stepped back, the record at rest after the return five times as long as
    // before the step: the mean of the 136 samples before the step, lifted by 2.7 of its
    // standard errors (as chance lifts one record in 140), is no operating point off.
    let (sd, before) = (0.023, 136.0);
    let lift = 2.7 * sd / f64::sqrt(before);
    let changes = [(13.63, 7.94, -0.87), (81.83, -7.94, -0.87)];
    let csv = p1_record(7.1, 70.03, 22.8, &changes, (0.1, 1460), sd);
    let lifted: String = csv
        .lines()
        .enumerate()
        .map(|(k, line)| match line.rsplit_once(',') {
            Some((head, y)) if k > 0 && k <= before as usize => {
                format!("{head},{:.5}\n", y.parse::<f64>().unwrap() + lift)
            }
            _ => format!("{line}\n"),
        })
        .collect();
    let r = diagnosis(&lifted).unwrap();
    let causes: Vec<&str> = r.steps.iter().map(|s| s.cause.id()).collect();
    assert!(causes.is_empty(), "{causes:?}");
    let kp = r.final_fit.model.get(Param::Kp);
    assert!((kp / -0.87 - 1.0).abs() < 0.01, "{kp}");
}
