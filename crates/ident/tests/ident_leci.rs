//! The LECI step test of the notes (Tôrres): P2DU from the automatic guess and from the
//! notes' bad guess, against the notes' answer Gdc 1.0021, θ 1.759 s, ζ 0.1948, ωn 0.9659.

use degrau_ident::fit::guess::auto_guess;
use degrau_ident::fit::{FitData, FitOptions, FitReport, FitWarning, Method, fit};
use degrau_ident::model::excitation::Excitation;
use degrau_ident::model::{Model, Param, Structure, Values};

fn leci() -> FitData {
    let text = std::fs::read_to_string(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/assets/leci_step.csv"
    ))
    .expect("the LECI data of the notes");
    let (times, y): (Vec<f64>, Vec<f64>) = text
        .lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let mut f = l.split(',').map(|v| v.trim().parse::<f64>().unwrap());
            (f.next().unwrap(), f.next().unwrap())
        })
        .unzip();
    FitData {
        times,
        y,
        input: Excitation::step(5.0, 10.0),
    }
}

/// P2DU with Y0 held at the notes' 50.
fn structure() -> Structure {
    let mut s = Structure::parse("P2DU").unwrap();
    s.free_offset = false;
    s
}

/// P2DU values from the gain, the dead time, ζ and ωn (Tw = 1/ωn), Y0 at the notes' 50.
fn p2du(kp: f64, td: f64, zeta: f64, wn: f64) -> Values {
    let mut v = Values::default();
    v.set(Param::Kp, kp);
    v.set(Param::Td, td);
    v.set(Param::Zeta, zeta);
    v.set(Param::Tw, 1.0 / wn);
    v.set(Param::Y0, 50.0);
    v
}

fn notes_answer() -> Values {
    p2du(1.0021, 1.759, 0.1948, 0.9659)
}

fn mse(data: &FitData, v: Values) -> f64 {
    let y = Model::new(structure(), v)
        .simulate(&data.input, &data.times)
        .unwrap();
    data.y
        .iter()
        .zip(y)
        .map(|(a, b)| (a - b).powi(2))
        .sum::<f64>()
        / data.y.len() as f64
}

/// The structure of [`structure`] fitted to `data` from `guess`.
fn fit_p2du(data: &FitData, guess: Values, options: &FitOptions) -> FitReport {
    fit(data, structure(), guess, options, &mut ()).unwrap()
}

/// `r` fits `data` at least as well as the notes' answer (to 1e-9).
fn no_worse_than_the_notes(data: &FitData, r: &FitReport) {
    let notes = mse(data, notes_answer());
    assert!(
        r.mse <= notes * (1.0 + 1e-9),
        "MSE {} vs the notes' {}",
        r.mse,
        notes
    );
}

#[test]
fn p2du_from_the_automatic_guess_matches_the_notes() {
    let data = leci();
    let guess = auto_guess(&data, structure(), Some(50.0));
    let one = FitOptions {
        starts: 1,
        ..Default::default()
    };
    let r = fit_p2du(&data, guess, &one);
    no_worse_than_the_notes(&data, &r);
    let m = &r.model;
    assert!((m.get(Param::Kp) - 1.0021).abs() < 0.01 * 1.0021, "{m:?}");
    assert!((m.get(Param::Td) - 1.759).abs() < 0.02 * 1.759);
    assert!((m.get(Param::Zeta) - 0.1948).abs() < 0.02 * 0.1948 + 0.002);
    assert!((1.0 / m.get(Param::Tw) - 0.9659).abs() < 0.02 * 0.9659);
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
    let (lo, hi) = r.interval(Param::Kp).unwrap();
    assert!(lo < m.get(Param::Kp) && m.get(Param::Kp) < hi);
}

fn bad_guess() -> Values {
    p2du(10.0, 1.0, 0.1, 20.0)
}

#[test]
fn from_the_bad_guess_multi_start_finds_the_same_optimum() {
    let data = leci();
    let r = fit_p2du(&data, bad_guess(), &FitOptions::default());
    no_worse_than_the_notes(&data, &r);
    assert!((1.0 / r.model.get(Param::Tw) - 0.9659).abs() < 0.02);
}

#[test]
fn from_the_bad_guess_a_single_start_flags_the_alias() {
    let data = leci();
    for method in [Method::NelderMead, Method::LevenbergMarquardt] {
        let options = FitOptions {
            method,
            starts: 1,
            ..Default::default()
        };
        let r = fit_p2du(&data, bad_guess(), &options);
        let wn = 1.0 / r.model.get(Param::Tw);
        let notes = mse(&data, notes_answer());
        let found_optimum = (wn - 0.9659).abs() < 0.02 && r.mse <= notes * (1.0 + 1e-6);
        let flagged = r
            .warnings
            .iter()
            .any(|w| matches!(w, FitWarning::Alias { .. }));
        assert!(
            found_optimum || flagged,
            "{method:?}: ωn {wn}, MSE {}, warnings {:?}",
            r.mse,
            r.warnings
        );
        eprintln!(
            "{method:?}: ωn = {wn:.4}, ζ = {:.4}, MSE = {:.4}, alias flagged: {flagged}",
            r.model.get(Param::Zeta),
            r.mse
        );
    }
}

/// The automatic guess reads the oscillation off the curve: ωn and ζ near the notes' answer,
/// so the student sees a guess that already looks like the data (35 coarse samples).
#[test]
fn the_automatic_guess_reads_the_oscillation() {
    let data = leci();
    let g = auto_guess(&data, structure(), Some(50.0));
    let wn = 1.0 / g.get(Param::Tw);
    let zeta = g.get(Param::Zeta);
    assert!((wn - 0.9659).abs() < 0.15 * 0.9659, "ωn {wn}");
    assert!((zeta - 0.1948).abs() < 0.05, "ζ {zeta}");
    assert!(
        (g.get(Param::Kp) - 1.0021).abs() < 0.02,
        "{}",
        g.get(Param::Kp)
    );
}

/// A poor fit (P2U, no dead time: RMSE 1.58) has large residuals, where Gauss–Newton steps
/// overshoot and zigzag; the damping must still converge, to the optimum Nelder–Mead finds.
#[test]
fn levenberg_marquardt_converges_on_a_poor_fit() {
    use degrau_ident::fit::Termination;
    let data = leci();
    let mut s = Structure::parse("P2U").unwrap();
    s.free_offset = false;
    let mut guess = auto_guess(&data, s, Some(50.0));
    guess.set(Param::Y0, 50.0);
    let single = |method| FitOptions {
        method,
        starts: 1,
        ..FitOptions::default()
    };
    let lm = fit(
        &data,
        s,
        guess,
        &single(Method::LevenbergMarquardt),
        &mut (),
    )
    .unwrap();
    let nm = fit(&data, s, guess, &single(Method::NelderMead), &mut ()).unwrap();
    assert_ne!(
        lm.termination,
        Termination::IterationLimit,
        "{}",
        lm.iterations
    );
    assert!(lm.iterations < 60, "{} iterations", lm.iterations);
    assert!(
        (lm.mse - nm.mse).abs() < 1e-6 * nm.mse,
        "{} vs {}",
        lm.mse,
        nm.mse
    );
    assert!((lm.mse - 2.49501).abs() < 1e-5, "{}", lm.mse);
}
