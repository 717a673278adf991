//! The Exercises mode through egui_kittest (issue 27, item 1): for every lettered part of
//! every exercise of the sheet, Degrau's exact answer typed into each field (found by its
//! label) is right on Check, and a wrong one is wrong, with the worked solution shown; in
//! Portuguese too for the exercises whose printed answers differ. The progress marks
//! survive a restart, a part's system opens in the Poles and zeros mode, and the mode's
//! layout holds at the classroom's sizes.

use crate::kit;

use degrau::app::exercises::answers::{field_label, verdict_line};
use degrau::app::exercises::list::entry;
use degrau::app::words::exercises::Exercises as T;
use degrau::app::{DegrauApp, Mode, Saved};
use degrau::lti::C64;
use degrau::text::Lang;
use degrau_exercise::{
    Choice, Exercise, Expected, Part, Question, StudentAnswer, TfAnswer, check, sheet, solution,
    typed_answer,
};
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness(app: DegrauApp, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

fn all() -> Vec<Exercise> {
    sheet().unwrap_or_else(|e| panic!("the sheet does not build: {e}"))
}

/// The app in the Exercises mode on the part `part`, in `lang`.
fn exercises_app(part: &str, lang: Lang) -> Harness<'static, DegrauApp> {
    let mut saved = Saved {
        mode: Mode::Exercises,
        lang,
        ..Saved::default()
    };
    saved.exercises.part = part.into();
    harness(DegrauApp::new(saved), [1600.0, 1200.0])
}

/// A wrong answer of the question's kind (checked wrong by the exercise crate first).
fn wrong(q: &Question, lang: Lang) -> String {
    let w = match &q.expected {
        Expected::Number { main, also, .. } => {
            let x = main.value;
            let mut w = if x.is_infinite() {
                7.0
            } else if x == 0.0 {
                0.5
            } else {
                3.0 * x
            };
            if also.iter().any(|a| (a.value - w).abs() < 0.05 * w.abs()) {
                w *= 1.5;
            }
            format!("{w}")
        }
        Expected::TransferFunction(TfAnswer::Fixed(_)) => {
            format!("3*({})", typed_answer(q, Lang::En))
        }
        Expected::TransferFunction(TfAnswer::ClosedLoopInK(_)) => "K/(s^2 + 0.3s + K)".into(),
        Expected::GainRange { main, .. } => {
            if main.high.is_finite() {
                format!("0 < K <= {}", main.high * 3.0)
            } else {
                format!("K > {}", main.low * 3.0 + 1.0)
            }
        }
        Expected::Region(r) => format!("ζ ≥ {}; σ ≥ {}", r.zeta_min * 0.5, r.sigma_min),
        Expected::ClosedForm { .. } => {
            let y = typed_answer(q, Lang::En);
            let y = y
                .trim_start_matches("y(t)")
                .trim_start()
                .trim_start_matches('=');
            format!("3*({y})")
        }
        Expected::Roots(roots) => {
            if roots.is_empty() {
                "-1".into()
            } else {
                let shifted: Vec<C64> = roots
                    .iter()
                    .map(|r| C64::new(3.0 * r.re - 1.0, r.im))
                    .collect();
                shifted
                    .iter()
                    .map(|r| format!("{}{:+}j", r.re, r.im))
                    .collect::<Vec<_>>()
                    .join("; ")
            }
        }
        Expected::Choice { options, right } => options
            .iter()
            .find(|c| *c != right)
            .map_or(Choice::No, |c| *c)
            .word(lang)
            .into(),
    };
    let v = check(q, &StudentAnswer::Text(w.clone()));
    assert!(
        !v.right && !v.unreadable,
        "{}: {w:?} is no wrong answer",
        q.id
    );
    w
}

/// Types `text` into the field of question `q` (found by its label).
fn type_into(h: &mut Harness<'_, DegrauApp>, q: &Question, lang: Lang, text: &str) {
    kit::type_number(h, &field_label(q, lang), 0, text);
}

/// Presses Check.
fn press_check(h: &mut Harness<'_, DegrauApp>, lang: Lang) {
    h.get_by_label(T::Check.get(lang)).click_accesskit();
    h.run_steps(2);
}

/// Whether a label reading exactly `text` is in the window.
fn shows(h: &Harness<'_, DegrauApp>, text: &str) -> bool {
    h.query_all_by_label(text).next().is_some()
}

/// Every part of exercise `id`: the exact answers right, then wrong ones wrong with the
/// worked solution shown.
fn exercise_checks(id: &str, lang: Lang) {
    let sheet = all();
    let exercise = sheet
        .iter()
        .find(|e| e.id == id)
        .unwrap_or_else(|| panic!("no exercise {id}"));
    for part in &exercise.parts {
        part_checks(part, lang);
    }
}

fn part_checks(part: &Part, lang: Lang) {
    let mut h = exercises_app(&part.id, lang);
    let first_step = solution(part, lang)
        .first()
        .map(|s| s.line.clone())
        .unwrap_or_else(|| panic!("{}: no solution", part.id));
    assert!(
        !shows(&h, &first_step),
        "{}: solution shown at first",
        part.id
    );
    // The exact answers: right.
    for q in &part.questions {
        type_into(&mut h, q, lang, &typed_answer(q, lang));
    }
    press_check(&mut h, lang);
    for q in &part.questions {
        let typed = typed_answer(q, lang);
        let v = check(q, &StudentAnswer::Text(typed.clone()));
        assert!(v.right, "{}: {typed:?}", q.id);
        let line = verdict_line(&v, lang);
        assert!(line.starts_with('●'));
        assert!(shows(&h, &line), "{}: {line:?} not on screen", q.id);
    }
    assert!(
        shows(&h, &entry(part, &h.state().saved.exercises)),
        "{}: the mark",
        part.id
    );
    assert!(entry(part, &h.state().saved.exercises).starts_with('●'));
    // Wrong answers: wrong, and the worked solution shown.
    for q in &part.questions {
        type_into(&mut h, q, lang, &wrong(q, lang));
    }
    press_check(&mut h, lang);
    for q in &part.questions {
        let v = check(q, &StudentAnswer::Text(wrong(q, lang)));
        let line = verdict_line(&v, lang);
        assert!(line.starts_with('×'));
        assert!(shows(&h, &line), "{}: {line:?} not on screen", q.id);
    }
    assert!(entry(part, &h.state().saved.exercises).starts_with('×'));
    assert!(
        shows(&h, &first_step),
        "{}: the solution's first step {first_step:?} not shown",
        part.id
    );
}

#[test]
fn exercise_1() {
    exercise_checks("1", Lang::En);
}
#[test]
fn exercise_2() {
    exercise_checks("2", Lang::En);
}
#[test]
fn exercise_3() {
    exercise_checks("3", Lang::En);
}
#[test]
fn exercise_3_in_portuguese() {
    exercise_checks("3", Lang::Pt);
}
#[test]
fn exercise_4() {
    exercise_checks("4", Lang::En);
}
#[test]
fn exercise_4_in_portuguese() {
    exercise_checks("4", Lang::Pt);
}
#[test]
fn exercise_5() {
    exercise_checks("5", Lang::En);
}
#[test]
fn exercise_6() {
    exercise_checks("6", Lang::En);
}
#[test]
fn exercise_7() {
    exercise_checks("7", Lang::En);
}
#[test]
fn exercise_8() {
    exercise_checks("8", Lang::En);
}
#[test]
fn exercise_8_in_portuguese() {
    exercise_checks("8", Lang::Pt);
}
#[test]
fn exercise_9() {
    exercise_checks("9", Lang::En);
}
#[test]
fn exercise_10() {
    exercise_checks("10", Lang::En);
}
#[test]
fn exercise_10_in_portuguese() {
    exercise_checks("10", Lang::Pt);
}
#[test]
fn exercise_11() {
    exercise_checks("11", Lang::En);
}
#[test]
fn exercise_12() {
    exercise_checks("12", Lang::En);
}
#[test]
fn exercise_13() {
    exercise_checks("13", Lang::En);
}

/// The sheet's printed answer that differs (exercise 8b's K = 86,25): wrong, and the
/// message says why; the solution lists the difference.
#[test]
fn the_sheets_printed_answer_is_explained_where_it_differs() {
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "8b").expect("8b");
    let q = part.question("8b.K").expect("8b.K");
    let printed = q.sheet.clone().expect("printed");
    let mut h = exercises_app("8b", Lang::Pt);
    type_into(&mut h, q, Lang::Pt, &printed);
    press_check(&mut h, Lang::Pt);
    let v = check(q, &StudentAnswer::Text(printed));
    assert!(!v.right);
    let difference = q.difference.as_ref().expect("difference").get(Lang::Pt);
    assert!(v.message.pt.contains(difference));
    assert!(shows(&h, &verdict_line(&v, Lang::Pt)));
    assert!(shows(&h, T::SheetDiffers.get(Lang::Pt)));
}

/// The marks and the answers typed are kept in the state file; a restored state that
/// names parts and questions the sheet does not have drops them.
#[test]
fn progress_survives_a_restart() {
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "1a")
        .expect("1a")
        .clone();
    let mut h = exercises_app("1a", Lang::En);
    for q in &part.questions {
        type_into(&mut h, q, Lang::En, &typed_answer(q, Lang::En));
    }
    press_check(&mut h, Lang::En);
    let mark = entry(&part, &h.state().saved.exercises);
    assert!(mark.starts_with('●'), "{mark}");
    let kept = h.state().saved.exercises.clone();
    let dir = std::env::temp_dir().join(format!("degrau-exercises-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let path = dir.join("state.json");
    let json = serde_json::to_string_pretty(&h.state().saved).expect("JSON");
    degrau::app::persist::write_atomically(&path, json.as_bytes()).expect("written");
    let h2 = harness(DegrauApp::with_state_file(path), [1600.0, 1000.0]);
    assert_eq!(h2.state().saved.mode, Mode::Exercises);
    assert_eq!(h2.state().saved.exercises, kept);
    assert!(h2.state().notices.is_empty());
    assert!(shows(&h2, &mark), "the mark {mark:?} after the restart");
    for q in &part.questions {
        let v = check(q, &StudentAnswer::Text(typed_answer(q, Lang::En)));
        let line = verdict_line(&v, Lang::En);
        assert!(shows(&h2, &line), "{line:?} after the restart");
    }
    let _ = std::fs::remove_dir_all(&dir);
    // Unknown ids are dropped, an unknown part opens the first.
    let mut value = serde_json::to_value(Saved::default()).expect("JSON");
    value["exercises"]["part"] = serde_json::json!("99z");
    value["exercises"]["answers"] = serde_json::json!({
        "99z.K": {"text": "1", "right": true},
        "1a.tau": {"text": "0,5", "right": false},
        "1b.x": 3
    });
    let (restored, _) = degrau::app::persist::restore_value(&value);
    assert_eq!(restored.exercises.part, "1a");
    let ids: Vec<&String> = restored.exercises.answers.keys().collect();
    assert!(
        ids.iter()
            .all(|id| degrau_exercise::find_question(&sheet, id).is_some()),
        "{ids:?}"
    );
    assert!(!ids.iter().any(|id| id.starts_with("99z")));
}

/// The G(s) fraction the Design mode draws.
fn design_fraction(h: &Harness<'_, DegrauApp>) -> String {
    h.get_all_by_role(egui::accesskit::Role::Label)
        .filter_map(|n| n.value())
        .find(|v| v.contains('─'))
        .expect("G(s) as a fraction")
}

/// "Open in Poles and zeros" loads the part's transfer function (1a), or its loop with the
/// compensator pole in G(s) and the gain K as Kp (8b).
#[test]
fn a_parts_system_opens_in_the_design_mode() {
    let sheet = all();
    for (id, lang) in [("1a", Lang::En), ("8b", Lang::Pt)] {
        let part = degrau_exercise::find_part(&sheet, id).expect("part");
        let mut h = exercises_app(id, lang);
        h.get_by_label(&degrau::app::words::exercises::open_in_design(lang))
            .click_accesskit();
        h.run_steps(3);
        assert_eq!(h.state().saved.mode, Mode::Design, "{id}");
        let g = design_fraction(&h);
        let tf = h.state().design.analysis.tf.clone().expect("a G(s)");
        let s = C64::new(0.7, 1.3);
        let (want, kp) = match &part.system {
            degrau_exercise::System::Tf { tf, .. } => (tf.eval(s), None),
            degrau_exercise::System::Loop {
                plant,
                controller: degrau_exercise::Controller::Pole { a },
                gain,
            } => (plant.eval(s) / (s + *a), Some(*gain)),
            other => panic!("{id}: {other:?}"),
        };
        assert!((tf.eval(s) - want).norm() < 1e-9 * want.norm(), "{id}: {g}");
        let feedback = &h.state().saved.design.feedback;
        assert_eq!(feedback.closed, kp.is_some(), "{id}");
        if let Some(k) = kp {
            assert!(
                (feedback.kp - k).abs() < 1e-9 * k,
                "{id}: Kp {}",
                feedback.kp
            );
        }
    }
}

/// Issue 23's layout for this mode: 1000×650 and 1600×900 at 1×, 1.3× and 1.6× in both
/// languages, with a part checked wrong and its solution shown: nothing outside the window,
/// no two texts over one another, the part's buttons and the list on screen.
#[test]
fn the_exercises_mode_fits_every_classroom_size() {
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "8b")
        .expect("8b")
        .clone();
    let mut h = exercises_app("8b", Lang::En);
    for q in &part.questions {
        type_into(&mut h, q, Lang::En, &wrong(q, Lang::En));
    }
    press_check(&mut h, Lang::En);
    let problems =
        crate::app_classroom::problems_everywhere_with(&mut h, "Exercises", 0, |h, lang| {
            let names = [
                degrau::app::words::exercises::open_in_design(lang),
                T::SheetHeading.get(lang).to_string(),
                entry(&part, &h.state().saved.exercises),
            ];
            let mut missing = crate::app_classroom::not_on_screen(h, &names);
            if !shows(h, T::Check.get(lang)) {
                missing.push("no Check button".into());
            }
            missing
        });
    crate::app_classroom::assert_no_problems(&problems);
}

/// A part read off a figure lists the figure's readings (the sheet's figure is not in its
/// text), in the student's language; a click on a part in the list opens it.
#[test]
fn a_figures_readings_are_listed_and_the_list_opens_a_part() {
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "2").expect("2");
    let degrau_exercise::System::Figure { readings, .. } = &part.system else {
        panic!("2 is read off a figure");
    };
    let mut h = exercises_app("1a", Lang::Pt);
    h.get_by_label(&entry(part, &h.state().saved.exercises))
        .click_accesskit();
    h.run_steps(2);
    assert_eq!(h.state().saved.exercises.part, "2");
    assert!(shows(&h, part.statement.get(Lang::Pt)));
    for r in readings {
        let value = degrau_exercise::text::num(Lang::Pt, r.value);
        let line = format!("• {} = {value} {}", r.label.get(Lang::Pt), r.unit.symbol());
        assert!(shows(&h, line.trim_end()), "{line:?} not listed");
    }
}

/// The painted texts of the last frame reading exactly `text`, with where they are.
fn painted(h: &Harness<'_, DegrauApp>, text: &str) -> Vec<egui::Rect> {
    kit::painted_texts(h)
        .into_iter()
        .filter(|(t, _)| t == text)
        .map(|(_, r)| r)
        .collect()
}

/// Exercise 4 is read off a figure: its part draws the figure (the plot names itself) with
/// each reading marked and labelled on it in the student's language (a decimal comma in
/// Portuguese), and nothing on screen gives the answer away (no G(s), no ωn or K).
#[test]
fn a_figure_part_draws_its_figure_with_the_readings_marked() {
    use degrau::app::exercises::figure;
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "4").expect("4");
    for lang in Lang::ALL {
        let h = exercises_app("4", lang);
        let canvas = h.get_by_label(T::FigureName.get(lang)).rect();
        assert!(
            canvas.width() > 400.0 && canvas.height() >= 220.0,
            "{lang:?}: the figure at {canvas:?}"
        );
        assert!(shows(&h, T::FigureTitle.get(lang)));
        let scene = figure::scene(part, lang).expect("a figure");
        assert_eq!(scene.marks.len(), 3, "t_p, y(t_p) and y(∞)");
        for m in &scene.marks {
            let text = &m.label().text;
            let at = painted(&h, text);
            assert!(
                at.iter().any(|r| canvas.expand(1.0).contains_rect(*r)),
                "{lang:?}: {text:?} not on the figure ({at:?}, figure {canvas:?})"
            );
        }
        let want = match lang {
            Lang::Pt => ["t_p = 0,0551 s", "y(t_p) = 0,944", "y(∞) = 0,75"],
            _ => ["t_p = 0.0551 s", "y(t_p) = 0.944", "y(∞) = 0.75"],
        };
        for text in want {
            assert!(!painted(&h, text).is_empty(), "{lang:?}: {text:?}");
        }
        // The answer stays hidden: not the curve's transfer function, nor ωn, nor K.
        let degrau_exercise::System::Figure { curve, .. } = &part.system else {
            panic!("4 is read off a figure");
        };
        let g = degrau_exercise::text::tf(lang, curve);
        let hidden: Vec<String> = ["4.wn", "4.K"]
            .iter()
            .map(|id| {
                let q = part.question(id).expect("question");
                let Expected::Number { main, .. } = &q.expected else {
                    panic!("{id} is a number");
                };
                degrau_exercise::text::num(lang, main.value)
            })
            .collect();
        for (text, _) in kit::painted_texts(&h) {
            assert!(!text.contains(g.as_str()), "{lang:?}: {text:?} shows G(s)");
            for answer in &hidden {
                assert!(!text.contains(answer.as_str()), "{lang:?}: {text:?}");
            }
        }
    }
}

/// Exercise 4 at every classroom size, zoom and language: the figure keeps 220 points, its
/// labels stay whole and apart, the readings and Check are there; at 1000×650 asked at 1.6×
/// (drawn at 1×, the size the window holds) the readings and Check scroll into view.
#[test]
fn a_figure_part_fits_every_classroom_size() {
    let sheet = all();
    let part = degrau_exercise::find_part(&sheet, "4").expect("4").clone();
    let degrau_exercise::System::Figure { readings, .. } = &part.system else {
        panic!("4 is read off a figure");
    };
    let lines = |lang: Lang| -> Vec<String> {
        readings
            .iter()
            .map(|r| {
                let value = degrau_exercise::text::num(lang, r.value);
                format!("• {} = {value} {}", r.label.get(lang), r.unit.symbol())
                    .trim_end()
                    .to_string()
            })
            .collect()
    };
    let mut h = exercises_app("4", Lang::En);
    for q in &part.questions {
        type_into(&mut h, q, Lang::En, &typed_answer(q, Lang::En));
    }
    let problems =
        crate::app_classroom::problems_everywhere_with(&mut h, "Exercise 4", 1, |h, lang| {
            let mut missing = Vec::new();
            for line in lines(lang) {
                if !shows(h, &line) {
                    missing.push(format!("{line:?} is not listed"));
                }
            }
            if !shows(h, T::Check.get(lang)) {
                missing.push("no Check button".into());
            }
            missing
        });
    crate::app_classroom::assert_no_problems(&problems);
    for lang in Lang::ALL {
        h.state_mut().saved.scale = 1.6;
        h.state_mut().saved.lang = lang;
        // The harness takes points: pixels over the zoom drawn at, until it holds still.
        for _ in 0..4 {
            let drawn = h.ctx.zoom_factor();
            h.set_size(egui::vec2(1000.0, 650.0) / drawn);
            h.run_steps(3);
        }
        assert!(
            (h.ctx.zoom_factor() - 1.0).abs() < 1e-3,
            "1000×650 holds 1×"
        );
        let window = h.ctx.content_rect();
        let mut names = lines(lang);
        names.push(T::Check.get(lang).to_string());
        for name in names {
            h.get_by_label(&name).scroll_to_me();
            h.run_steps(4);
            let r = h.get_by_label(&name).rect();
            assert!(window.contains_rect(r), "{lang:?}: {name:?} at {r:?}");
        }
        h.get_by_label(T::Check.get(lang)).click_accesskit();
        h.run_steps(2);
        assert!(
            part.questions.iter().all(|q| h
                .state()
                .exercises
                .verdict(&q.id)
                .is_some_and(|v| v.right)),
            "{lang:?}: Check checked the part"
        );
    }
}
