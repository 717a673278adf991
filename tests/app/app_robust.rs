//! The app cannot freeze and loses nothing (issue 8), through egui_kittest: an absurd pole
//! typed in and the s-plane fitted to it, a restored view that is infinite or huge, a state
//! file with one bad field, and an edit that is on disk without any further frame.
//!
//! "Keeps painting" is checked as a person would see it: frames complete, each draws a
//! bounded number of shapes, and the app still answers (undo, a drag, a button).

use crate::kit;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use degrau::app::design::plane::View;
use degrau::app::design::state::{ROOT_LIMIT, Root, System};
use degrau::app::identify;
use degrau::app::persist::FILE_NAME;
use degrau::app::{DegrauApp, Saved};
use eframe::egui::{self, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

/// Most shapes one frame may draw: the s-plane grid is capped at 200 lines a direction, and
/// the default app draws far fewer than this; an unbounded grid drew millions.
const MAX_SHAPES: usize = 5000;

fn harness(app: DegrauApp) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

/// A fresh empty directory for one test's state file.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("degrau-app-robust-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Runs `frames` frames and checks that each one completes with a bounded drawing.
fn keeps_painting(h: &mut Harness<'_, DegrauApp>, frames: usize) {
    for _ in 0..frames {
        h.step();
        let shapes = h.output().shapes.len();
        assert!(
            shapes > 0 && shapes <= MAX_SHAPES,
            "a frame drew {shapes} shapes"
        );
    }
}

/// The view the s-plane shows now (set by the last frame).
fn view(h: &Harness<'_, DegrauApp>) -> View {
    h.state()
        .saved
        .design
        .splane
        .view
        .expect("the s-plane has a view")
}

#[test]
fn a_pole_typed_far_away_and_fit_keep_the_app_painting() {
    let mut h = harness(DegrauApp::default());
    kit::type_number(&mut h, "σ", 1, "-1e30");
    assert_eq!(h.state().system(), &System::default(), "-1e30 is refused");
    h.get_by_label_contains("is below the smallest allowed value");
    kit::type_number(&mut h, "σ", 1, "-1e6");
    let pole = h.state().system().poles[1];
    assert_eq!(pole.re, -ROOT_LIMIT, "the limit itself is accepted");
    h.get_by_label("Fit").click();
    keeps_painting(&mut h, 5);
    assert!(view(&h).is_sane(), "{:?}", view(&h));
    // The fitted view still shows the far pole.
    let pole2 = h.get_by_label("pole 2").rect().center();
    let canvas = h.get_by_label("pole 1").rect().center();
    assert!(pole2.x < canvas.x, "pole 2 is left of pole 1 on screen");
    // Usable: undo brings the example back, and its pole can be dragged.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    keeps_painting(&mut h, 2);
    assert_eq!(h.state().system(), &System::default());
    h.get_by_label("Fit").click();
    keeps_painting(&mut h, 2);
    kit::drag_by(&mut h, "pole 2", Vec2::new(30.0, 0.0), 4);
    keeps_painting(&mut h, 2);
    assert!(
        h.state().system().poles[1].re > -5.0,
        "the drag moved pole 2"
    );
}

#[test]
fn absurd_roots_zoom_and_pan_keep_frames_bounded() {
    let mut saved = Saved::default();
    saved.design.system = System {
        poles: vec![Root::pair(-1e30, 1e30), Root::real(1e300)],
        ..System::default()
    };
    // Roots made beyond the limit are clamped to it when made, and a pair at the corner
    // (|s| = 1.41e6) is beyond what the app holds: the system falls back whole, named.
    assert_eq!(
        saved.design.system.poles,
        [Root::pair(-ROOT_LIMIT, ROOT_LIMIT), Root::real(ROOT_LIMIT)]
    );
    let mut h = harness(DegrauApp::new(saved));
    keeps_painting(&mut h, 3);
    assert_eq!(h.state().system(), &System::default());
    h.get_by_label_contains("system.poles");
    // A pole at the limit, then zoomed all the way in and out and panned far away.
    h.state_mut().saved.design.system.poles[1] = Root::real(-ROOT_LIMIT);
    h.state_mut().saved.design.splane.view = None;
    keeps_painting(&mut h, 2);
    let canvas = h.get_by_label("pole 1").rect().center();
    for scroll in [3000.0, -3000.0] {
        for _ in 0..40 {
            kit::wheel(&mut h, canvas, scroll);
            keeps_painting(&mut h, 1);
            assert!(view(&h).is_sane(), "{:?}", view(&h));
        }
    }
    let far = canvas + Vec2::new(-200.0, 0.0);
    for _ in 0..3 {
        h.hover_at(canvas);
        h.run_steps(1);
        h.drag_at(canvas);
        h.run_steps(1);
        h.hover_at(far);
        keeps_painting(&mut h, 1);
        h.drop_at(far);
        keeps_painting(&mut h, 1);
        assert!(view(&h).is_sane(), "{:?}", view(&h));
    }
}

#[test]
fn a_restored_infinite_view_keeps_painting_and_is_fitted_again() {
    let mut saved = Saved::default();
    saved.design.splane.view = Some(View {
        center_re: f64::NEG_INFINITY,
        center_im: f64::NAN,
        pixels_per_unit: f64::INFINITY,
    });
    let mut h = harness(DegrauApp::new(saved));
    keeps_painting(&mut h, 5);
    assert!(view(&h).is_sane(), "{:?}", view(&h));
    h.get_by_label_contains("splane.view");
    h.get_by_label("pole 1");
}

#[test]
fn a_state_file_with_a_huge_view_starts_and_paints() {
    let dir = temp_dir("huge-view");
    let path = dir.join(FILE_NAME);
    // What the unbounded fit used to save after σ = −1e30: every start froze on it.
    let mut saved = Saved::default();
    saved.design.splane.view = Some(View {
        center_re: -5e29,
        center_im: 0.0,
        pixels_per_unit: 1e-6,
    });
    std::fs::write(&path, serde_json::to_string(&saved).expect("json")).expect("write");
    let mut h = harness(DegrauApp::with_state_file(path.clone()));
    keeps_painting(&mut h, 5);
    assert!(view(&h).is_sane(), "{:?}", view(&h));
    h.get_by_label_contains("splane.view");
    assert_eq!(h.state().system(), &System::default());
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}

/// Polls `path` for up to 2 s until `done` holds for its parsed JSON.
fn on_disk_soon(path: &Path, done: impl Fn(&serde_json::Value) -> bool) -> serde_json::Value {
    let start = Instant::now();
    loop {
        let value = std::fs::read_to_string(path)
            .ok()
            .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok());
        if let Some(v) = value.filter(&done) {
            return v;
        }
        assert!(
            start.elapsed() < Duration::from_secs(2),
            "{} does not hold the change after 2 s",
            path.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn a_state_file_with_one_bad_field_restores_the_rest_and_names_it() {
    let dir = temp_dir("bad-field");
    let path = dir.join(FILE_NAME);
    let mut saved = Saved {
        dark: true,
        ..Saved::default()
    };
    saved.design.phase_form = true;
    saved.design.system.gain = 3.0;
    saved.design.system.poles[1] = Root::real(-7.0);
    saved.ident.code = "P1D".into();
    let mut value = serde_json::to_value(&saved).expect("json");
    value["system"]["amplitude"] = serde_json::json!("two");
    let text = serde_json::to_string_pretty(&value).expect("json");
    std::fs::write(&path, &text).expect("write");

    let mut h = harness(DegrauApp::with_state_file(path.clone()));
    let s = h.state();
    assert_eq!(s.system().gain, 3.0);
    assert_eq!(s.system().poles[1], Root::real(-7.0));
    assert_eq!(s.system().amplitude, System::default().amplitude);
    assert!(s.saved.dark && s.saved.design.phase_form);
    assert_eq!(s.ident.settings.code, "P1D");
    h.get_by_label_contains("system.amplitude");
    // The file as it was is kept aside, and the state file is rewritten whole.
    let backups: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().contains(".bad-"))
        .collect();
    assert_eq!(backups.len(), 1, "{backups:?}");
    assert_eq!(std::fs::read_to_string(&backups[0]).expect("backup"), text);
    let rewritten = on_disk_soon(&path, |v| v["system"]["amplitude"].is_number());
    assert_eq!(rewritten["system"]["gain"], 3.0);
    // The notice goes when dismissed.
    h.get_by_label("Dismiss").click();
    h.run_steps(2);
    assert!(h.query_by_label_contains("system.amplitude").is_none());
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_edit_followed_by_no_frame_is_on_disk_within_a_second() {
    let dir = temp_dir("prompt");
    let path = dir.join(FILE_NAME);
    let mut h = harness(DegrauApp::with_state_file(path.clone()));
    on_disk_soon(&path, |v| {
        v["system"]["zeros"]
            .as_array()
            .is_some_and(|z| z.is_empty())
    });
    h.get_by_label("+ real zero").click();
    h.run_steps(1);
    assert_eq!(h.state().system().zeros.len(), 1, "the click made the edit");
    // No further frame: the saver thread alone must write it.
    let v = on_disk_soon(&path, |v| {
        v["system"]["zeros"]
            .as_array()
            .is_some_and(|z| z.len() == 1)
    });
    let restored = DegrauApp::with_state_file(path.clone());
    assert_eq!(restored.system(), h.state().system());
    assert!(restored.notices.is_empty(), "{:?}", restored.notices);
    assert_eq!(
        v["system"]["zeros"][0]["re"],
        h.state().system().zeros[0].re
    );
    let others: Vec<String> = std::fs::read_dir(&dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n != FILE_NAME)
        .collect();
    assert!(others.is_empty(), "no temporary or backup file: {others:?}");
    drop((h, restored));
    std::fs::remove_dir_all(&dir).ok();
}

/// The record and flags of `degrau open FILE --time-col … --initial-input …` parsed as the
/// command line parses them.
fn open_flags(args: &[&str]) -> degrau::app::identify::Saved {
    use clap::Parser;
    let mut line = vec!["degrau", "open"];
    line.extend_from_slice(args);
    match degrau::cli::Cli::try_parse_from(line)
        .expect("the flags parse")
        .command
    {
        Some(degrau::cli::Command::Open(open)) => open.settings(),
        other => panic!("not open: {other:?}"),
    }
}

/// `degrau open` after a session on another record (issue 23, item 1): the flags given on
/// the command line win over the saved session. The last session loaded its own record and
/// then cleared the new one's column choices as left over from it ("several columns could
/// be the output"), kept the old record plotted under the new path and its structure's
/// guess under the new structure's name. `--initial-input` reaches the app too.
#[test]
fn flags_on_the_command_line_win_over_the_saved_session() {
    let dir = temp_dir("open-flags");
    let path = dir.join(FILE_NAME);
    let records = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/records/");
    let saved = Saved {
        mode: degrau::app::Mode::Identify,
        ident: identify::Saved {
            path: format!("{records}multistep_heater_synthetic.csv"),
            code: "P2DZ".into(),
            initial_input: "3".into(),
            ..identify::Saved::default()
        },
        ..Saved::default()
    };
    std::fs::write(&path, serde_json::to_string(&saved).expect("json")).expect("write");

    let sbhs = format!("{records}sbhs_step_not_at_rest_synthetic.txt");
    let flags = ["--time-col", "1", "--y-col", "4", "--u-col", "2"];
    let mut args = vec![sbhs.as_str()];
    args.extend(flags);
    let h = harness(DegrauApp::opening(path.clone(), open_flags(&args)));
    let ident = &h.state().ident;
    let loaded = ident.loaded.as_ref().expect("the new record is loaded");
    let rows = std::fs::read_to_string(&sbhs)
        .expect("sbhs")
        .lines()
        .count();
    assert_eq!(loaded.test.time.len(), rows);
    // Not the saved record's P2DZ: the structure SBHS's own shape suggests (a heater).
    assert_eq!(loaded.structure.code(), "P1D");
    assert_eq!(ident.settings.code, "P1D");
    assert_eq!(ident.settings.y_col, "4");
    assert_eq!(
        loaded.experiment.initial_input, None,
        "no setting of the last record"
    );
    assert!(h.query_by_label_contains("could be the output").is_none());
    drop(h);

    let daisy = format!("{records}daisy_heating_system.dat");
    let h = harness(DegrauApp::opening(
        path,
        open_flags(&[
            &daisy,
            "--time-col",
            "1",
            "--y-col",
            "3",
            "--u-col",
            "2",
            "--initial-input",
            "6",
        ]),
    ));
    let loaded = h.state().ident.loaded.as_ref().expect("DaISy is loaded");
    assert_eq!(loaded.experiment.initial_input, Some(6.0));
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}

/// The structure shown in the "Model structure" box.
fn shown_structure(h: &Harness<'_, DegrauApp>) -> Vec<String> {
    h.get_all_by_role(egui::accesskit::Role::ComboBox)
        .filter(|n| n.accesskit_node().label().as_deref() == Some("Model structure"))
        .filter_map(|n| n.value())
        .collect()
}

/// Issue 23, item 11: a record opened without `--model` starts on the structure its shape
/// suggests, its guess drawn from it: a first-order heater on P1D (not an oscillating P2DU
/// guess), an underdamped response on P2DU; `--model` still wins.
#[test]
fn a_record_opened_without_a_model_starts_on_the_structure_its_shape_suggests() {
    use degrau::ident::model::excitation::Excitation;
    use degrau::ident::model::{Model, Param, Structure, Values};
    let dir = temp_dir("suggested");
    let state = dir.join(FILE_NAME);
    let records = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/records/");
    let heater = format!("{records}tclab_step_q1_50_synthetic.csv");
    let heater_flags = ["--time-col", "Time", "--y-col", "T1", "--u-col", "Q1"];
    // An underdamped response written as a logger would: ζ 0.3, a step at 5 s, far from 0.
    let mut v = Values::default();
    for (p, x) in [
        (Param::Kp, 2.0),
        (Param::Tw, 1.5),
        (Param::Zeta, 0.3),
        (Param::Y0, 20.0),
    ] {
        v.set(p, x);
    }
    let times: Vec<f64> = (0..400).map(|k| 0.1 * k as f64).collect();
    let y = Model::new(Structure::parse("P2U").expect("a code"), v)
        .simulate(&Excitation::step(5.0, 3.0), &times)
        .expect("a response");
    let ringing = dir.join("ringing.csv");
    let mut text = String::from("t,u,y\n");
    for (t, y) in times.iter().zip(&y) {
        let u = if *t >= 5.0 { 3.0 } else { 0.0 };
        text.push_str(&format!("{t},{u},{y}\n"));
    }
    std::fs::write(&ringing, text).expect("write");
    let ringing = ringing.display().to_string();
    let ringing_flags = ["--time-col", "t", "--y-col", "y", "--u-col", "u"];
    for (file, flags, model, expected) in [
        (&heater, heater_flags, None, "P1D"),
        (&ringing, ringing_flags, None, "P2DU"),
        (&heater, heater_flags, Some("P2"), "P2"),
    ] {
        let mut args = vec![file.as_str()];
        args.extend(flags);
        if let Some(m) = model {
            args.extend(["--model", m]);
        }
        let h = harness(DegrauApp::opening(state.clone(), open_flags(&args)));
        let loaded = h.state().ident.loaded.as_ref().expect("loaded");
        assert_eq!(loaded.structure.code(), expected, "{file} {model:?}");
        assert_eq!(shown_structure(&h), [expected], "{file} {model:?}");
        drop(h);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Every structure the diagnosis can end on: 1 to 3 poles, with any of D, U (two poles or
/// more), Z and I.
fn every_structure() -> Vec<String> {
    let mut codes = Vec::new();
    for poles in 1..=3 {
        for letters in 0..16u8 {
            let mut code = format!("P{poles}");
            for (bit, letter) in ['D', 'U', 'Z', 'I'].into_iter().enumerate() {
                if letters & (1 << bit) != 0 {
                    code.push(letter);
                }
            }
            if degrau::ident::model::Structure::parse(&code).is_ok() {
                codes.push(code);
            }
        }
    }
    codes
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(96))]
    /// Whatever the app can reach, it saves and restores with no notice (issue 23, item 2: a
    /// diagnosis ending on P3Z was refused on the next start): every structure, with or
    /// without drift, in every mode, language, presentation size and theme.
    #[test]
    fn every_reachable_state_round_trips(
        structure in proptest::sample::select(every_structure()),
        drift: bool,
        mode in proptest::sample::select(vec![
            degrau::app::Mode::Design,
            degrau::app::Mode::Identify,
            degrau::app::Mode::LeastSquares,
        ]),
        pt: bool,
        dark: bool,
        scale in proptest::sample::select(vec![1.0f32, 1.2, 1.3, 1.4, 1.6, 1.8, 2.0]),
    ) {
        let saved = Saved {
            ident: identify::Saved { code: structure.clone(), drift, ..identify::Saved::default() },
            mode,
            lang: if pt { degrau::text::Lang::Pt } else { degrau::text::Lang::En },
            dark,
            scale,
            ..Saved::default()
        };
        let text = serde_json::to_string(&saved).expect("json");
        let (restored, problems) = degrau::app::persist::restore_text(&text);
        proptest::prop_assert!(problems.is_empty(), "{problems:?}");
        proptest::prop_assert_eq!(serde_json::to_string(&restored).expect("json"), text);
    }
}

/// No approximation, and every one the comparison table lists for a third-order system
/// with a dead time (every reduction and every stand-in for the delay).
fn approximations() -> Vec<Option<degrau::lti::approx::Approximation>> {
    use degrau::lti::{C64, TransferFunction};
    let poles = [
        C64::new(-1.0, 2.0),
        C64::new(-1.0, -2.0),
        C64::new(-5.0, 0.0),
    ];
    let g = TransferFunction::from_zpk(&[], &poles, 0.5)
        .and_then(|g| g.with_delay(0.3))
        .expect("a system");
    let mut all = vec![None];
    all.extend(
        degrau::lti::approx::Approximation::catalogue(&g)
            .into_iter()
            .map(Some),
    );
    all
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
    /// The Design mode's reachable states round-trip too, and the app starts on them with no
    /// notice: a dead time or none, either gain form, any step amplitude, the loop open or
    /// closed at any gain the field accepts, the locus and its complement, every input and
    /// Padé order offered, either form of y(t), every approximation with its table or not.
    #[test]
    fn every_reachable_design_state_round_trips(
        delay in proptest::sample::select(vec![0.0, 0.3, 2.0]),
        static_gain: bool,
        amplitude in proptest::sample::select(vec![1.0, 2.0, -4.0, 0.01]),
        closed: bool,
        kp in proptest::sample::select(vec![0.1, 1.0, 37.5, -2.0, 1e6]),
        locus: bool,
        complementary: bool,
        input in proptest::sample::select(vec![
            degrau::lti::feedback::Input::Impulse,
            degrau::lti::feedback::Input::Step,
            degrau::lti::feedback::Input::Ramp,
            degrau::lti::feedback::Input::Parabola,
        ]),
        pade in proptest::sample::select(degrau::lti::feedback::PadeOrder::offered()),
        phase_form: bool,
        pt: bool,
        approx in proptest::sample::select(approximations()),
        approx_table: bool,
    ) {
        let mut saved = Saved {
            mode: degrau::app::Mode::Design,
            lang: if pt { degrau::text::Lang::Pt } else { degrau::text::Lang::En },
            ..Saved::default()
        };
        let design = &mut saved.design;
        design.system.delay = delay;
        design.system.amplitude = amplitude;
        if static_gain {
            design.system.gain_mode = degrau::app::design::state::GainMode::Static;
        }
        design.phase_form = phase_form;
        (design.approx, design.approx_table) = (approx, approx_table);
        let feedback = &mut design.feedback;
        feedback.closed = closed;
        feedback.kp = kp;
        feedback.locus = locus;
        feedback.complementary = complementary;
        feedback.input = input;
        feedback.pade = pade;
        let text = serde_json::to_string(&saved).expect("json");
        let (restored, problems) = degrau::app::persist::restore_text(&text);
        proptest::prop_assert!(problems.is_empty(), "{problems:?}");
        proptest::prop_assert_eq!(serde_json::to_string(&restored).expect("json"), text.clone());
        let dir = temp_dir("design-state");
        let path = dir.join(FILE_NAME);
        std::fs::write(&path, &text).expect("write");
        let h = harness(DegrauApp::with_state_file(path));
        let notice = h.query_by_label_contains("could not be restored").is_none()
            && h.query_by_label_contains("não pôde ser restaurad").is_none();
        // The approximation chosen is the one shown again.
        let shown = h.state().design.approx.choice;
        proptest::prop_assert_eq!(shown, approx);
        drop(h);
        std::fs::remove_dir_all(&dir).ok();
        proptest::prop_assert!(notice, "a notice on {text}");
    }
}

/// A session saved on a structure the menu does not list starts again on it, with no
/// notice, and the structure box shows it.
#[test]
fn a_diagnosis_ending_on_p3z_starts_again_on_it() {
    let dir = temp_dir("p3z");
    let path = dir.join(FILE_NAME);
    let saved = Saved {
        mode: degrau::app::Mode::Identify,
        ident: identify::Saved {
            example: true,
            code: "P3Z".into(),
            ..identify::Saved::default()
        },
        ..Saved::default()
    };
    std::fs::write(&path, serde_json::to_string(&saved).expect("json")).expect("write");
    let h = harness(DegrauApp::with_state_file(path));
    assert!(h.query_by_label_contains("could not be restored").is_none());
    assert_eq!(h.state().ident.settings.code, "P3Z");
    let loaded = h
        .state()
        .ident
        .loaded
        .as_ref()
        .expect("the example is loaded");
    assert_eq!(loaded.structure.code(), "P3Z");
    assert_eq!(shown_structure(&h), ["P3Z"]);
    drop(h);
    std::fs::remove_dir_all(&dir).ok();
}
