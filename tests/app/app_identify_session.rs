//! The identification session without egui: loading, what a change invalidates, the chain
//! rows, the readouts, and the outcome handed to the app.

use std::time::{Duration, Instant};

use degrau::app::identify::Session;
use degrau::app::identify::commands::{Choice, Command, Outcome};
use degrau::app::identify::session::{LoadError, LoadMessage, Shown, Status};
use degrau::ident::model::Param;

const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

/// Polls until the session's jobs are done, at most 30 s.
fn settle(s: &mut Session) {
    let start = Instant::now();
    while s.poll() {
        assert!(start.elapsed() < Duration::from_secs(30), "timed out");
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn example_fitted() -> Session {
    let mut s = Session::default();
    s.apply(Command::LoadExample);
    s.apply(Command::Fit);
    settle(&mut s);
    assert!(s.report.is_some(), "{:?}", s.status);
    s
}

#[test]
fn the_example_loads_with_the_notes_setup() {
    let mut s = Session::default();
    s.apply(Command::LoadExample);
    assert!(matches!(
        s.message,
        Some(LoadMessage::Example { samples: 35, .. })
    ));
    assert_eq!(s.held_operating_point(), Some(50.0));
    assert_eq!(s.shown().map(|x| x.1), Some(Shown::Guess));
    assert_eq!(s.plots().measured.len(), 35);
    assert!(!s.plots().model.is_empty() && s.plots().residuals.len() == 35);
}

#[test]
fn the_plots_are_recomputed_only_when_an_input_changed() {
    let mut s = Session::default();
    s.apply(Command::LoadExample);
    let before = s.plots().model.as_ptr();
    s.apply(Command::SetMultistart(false));
    s.poll();
    assert_eq!(s.plots().model.as_ptr(), before, "recomputed for nothing");
    s.apply(Command::SetGuess(Param::Kp, 2.0));
    assert_ne!(s.plots().model.as_ptr(), before);
    let m = s.shown_model().unwrap();
    let t = s.plots().model[400][0];
    let y = m.simulate(&s.setup().unwrap(), &[t]).unwrap()[0];
    assert_eq!(s.plots().model[400][1], y);
}

#[test]
fn a_new_test_drops_the_fit_and_its_status() {
    let mut s = example_fitted();
    assert!(matches!(s.status, Status::Fitted { .. }));
    s.settings.y_col = "T1".into();
    s.settings.u_col = "Q1".into();
    s.apply(Command::SetPath(TCLAB.into()));
    s.apply(Command::LoadPath);
    assert!(s.report.is_none() && s.fitted.is_none() && s.diagnosis.is_none());
    assert_eq!(s.status, Status::Idle);
    assert_eq!(s.shown().map(|x| x.1), Some(Shown::Guess));
    assert_eq!(s.plots().measured.len(), 801);
}

#[test]
fn a_new_choice_on_the_test_drops_the_fit() {
    let mut s = example_fitted();
    s.apply(Command::SetStepTime(5.5));
    assert!(s.report.is_none());
    assert_eq!(s.status, Status::Idle);
    let mut s = example_fitted();
    s.apply(Command::SetCode("P1D".into()));
    assert!(s.report.is_none());
    assert_eq!(s.shown_model().unwrap().structure.code(), "P1D");
    let mut s = example_fitted();
    s.apply(Command::SetFilter(Some(0.5)));
    assert!(s.report.is_none());
}

#[test]
fn a_failed_load_keeps_the_test_and_says_why() {
    let mut s = Session::default();
    s.apply(Command::LoadExample);
    s.apply(Command::SetChoice(Choice::InitialInput, "zero".into()));
    s.apply(Command::Open(TCLAB.into()));
    match &s.message {
        Some(LoadMessage::Failed {
            error: LoadError::Choice { choice, .. },
            kept: true,
            ..
        }) => assert_eq!(*choice, Choice::InitialInput),
        other => panic!("{other:?}"),
    }
    assert_eq!(s.loaded.as_ref().unwrap().test.time.len(), 35);
}

#[test]
fn the_fitted_model_goes_to_the_s_plane_with_its_step() {
    let mut s = example_fitted();
    let kp = s.report.as_ref().unwrap().model.get(Param::Kp);
    match s.apply(Command::ShowOnSPlane) {
        Some(Outcome::ShowOnSPlane { tf, du }) => {
            assert_eq!(du, 10.0);
            assert!((tf.dc_gain() - kp).abs() < 1e-9 * kp.abs());
        }
        other => panic!("{other:?}"),
    }
    assert!(Session::default().apply(Command::ShowOnSPlane).is_none());
}

/// The file dialogs are the app's: the session asks for them and opens none.
#[test]
fn the_file_dialogs_are_asked_of_the_app() {
    use degrau::app::dialog::Pick;
    let mut s = Session::default();
    assert!(matches!(
        s.apply(Command::BrowseTest),
        Some(Outcome::Pick(Pick::StepTest))
    ));
    assert!(matches!(
        s.apply(Command::BrowseInputFile),
        Some(Outcome::Pick(Pick::InputFile))
    ));
    assert!(s.loaded.is_none() && s.settings.u_path.is_empty());
}

#[test]
fn a_chain_row_is_shown_and_a_row_out_of_range_is_ignored() {
    let mut s = Session::default();
    s.settings.y_col = "T1".into();
    s.settings.u_col = "Q1".into();
    s.settings.code = "P1".into();
    s.load_path(TCLAB);
    s.apply(Command::Fit);
    settle(&mut s);
    s.apply(Command::Diagnose { whole: true });
    settle(&mut s);
    let d = s.diagnosis.clone().expect("a chain");
    s.apply(Command::SelectStep(0));
    assert_eq!(s.shown(), Some((d.start.model, Shown::ChainRow(0))));
    s.apply(Command::SelectStep(d.steps.len() + 5));
    assert_eq!(s.selected_step, Some(0));
}

#[test]
fn readouts_take_the_curves_values() {
    let mut s = Session::default();
    s.apply(Command::LoadExample);
    let first = s.plots().measured[0];
    let second = s.plots().measured[1];
    let between = first[0] + 0.4 * (second[0] - first[0]);
    assert_eq!(s.nearest_sample(between), Some(first));
    let m = s.shown_model().unwrap();
    let exact = m.simulate(&s.setup().unwrap(), &[12.345]).unwrap()[0];
    assert_eq!(s.model_value(12.345), Some(exact));
}
