//! The Exercises session without egui: every part's system loads into the Design mode, a
//! Check marks the answers and opens the solution when one is wrong, typing clears the last
//! Check, a kept state naming unknown ids is pruned, and a kept challenge is checked.

use degrau_exercise::{Lang, find_question, typed_answer};

use super::commands::{Command, Outcome};
use super::load::design_load;
use super::session::{Answer, Progress, Saved, Session, progress, prune, the_sheet};

fn sheet() -> &'static [degrau_exercise::Exercise] {
    the_sheet().unwrap_or_else(|e| panic!("the sheet does not build: {e}"))
}

#[test]
fn every_parts_system_loads_into_the_design_mode() {
    for part in sheet().iter().flat_map(|e| &e.parts) {
        let load = design_load(&part.system).unwrap_or_else(|e| panic!("{}: {e:?}", part.id));
        let loop_part = matches!(part.system, degrau_exercise::System::Loop { .. });
        assert_eq!(load.loop_gain.is_some(), loop_part, "{}", part.id);
        let tf = load.system.transfer_function();
        assert!(tf.is_ok(), "{}: {tf:?}", part.id);
    }
}

#[test]
fn opening_a_part_asks_the_app_to_load_it() {
    let mut session = Session::default();
    let mut kept = Saved::default();
    let out = session.apply(&mut kept, Command::OpenInDesign("8b".into()));
    assert!(matches!(out, Some(Outcome::Load(l)) if l.loop_gain.is_some()));
    assert_eq!(
        session.apply(&mut kept, Command::OpenInDesign("99z".into())),
        None
    );
}

#[test]
fn check_marks_the_answers_and_a_wrong_one_opens_the_solution() {
    let mut session = Session::default();
    let mut kept = Saved::default();
    let part = degrau_exercise::find_part(sheet(), "1a").expect("1a");
    for q in &part.questions {
        let text = typed_answer(q, Lang::Pt);
        let _ = session.apply(
            &mut kept,
            Command::Type {
                question: q.id.clone(),
                text,
            },
        );
    }
    let _ = session.apply(&mut kept, Command::Check("1a".into()));
    assert_eq!(progress(part, &kept), Progress::Right);
    assert!(!session.solution_shown("1a"));
    let q = &part.questions[0];
    let _ = session.apply(
        &mut kept,
        Command::Type {
            question: q.id.clone(),
            text: "abc".into(),
        },
    );
    assert!(
        session.verdict(&q.id).is_none(),
        "typing clears the last Check"
    );
    let _ = session.apply(&mut kept, Command::Check("1a".into()));
    assert_eq!(progress(part, &kept), Progress::Wrong);
    assert!(session.verdict(&q.id).is_some_and(|v| v.unreadable));
    assert!(session.solution_shown("1a"));
    // A question the sheet does not have is not kept.
    let _ = session.apply(
        &mut kept,
        Command::Type {
            question: "99z.K".into(),
            text: "1".into(),
        },
    );
    assert!(!kept.answers.contains_key("99z.K"));
}

#[test]
fn unknown_ids_are_pruned() {
    let mut kept = Saved {
        part: "99z".into(),
        ..Saved::default()
    };
    kept.answers.insert("99z.K".into(), Answer::default());
    kept.answers.insert("1a.x".into(), Answer::default());
    let known = sheet()[0].parts[0].questions[0].id.clone();
    kept.answers.insert(known.clone(), Answer::default());
    prune(&mut kept, sheet());
    assert_eq!(kept.part, "1a");
    let left: Vec<&String> = kept.answers.keys().collect();
    assert_eq!(left, [&known]);
    assert!(find_question(sheet(), &known).is_some());
}

#[test]
fn a_kept_challenge_is_checked_on_restore() {
    use degrau_ident::challenge::Level;
    let mut value = serde_json::to_value(crate::Saved::default()).expect("JSON");
    value["exercises"]["challenges"] = serde_json::json!({
        "seed": 7, "level": "subtle", "next": 3, "open": true,
        "current": {"seed": 7, "index": 2, "level": "subtle",
                    "cause": "gremlins", "structure": "P2", "kp": "1,5", "checked": true}
    });
    let (restored, problems) = crate::persist::restore_value(&value);
    assert!(problems.is_empty(), "{problems:?}");
    let kept = &restored.exercises.challenges;
    assert_eq!(
        (kept.seed, kept.level, kept.next),
        (Some(7), Level::Subtle, 3)
    );
    let current = kept.current.as_ref().expect("the challenge kept");
    assert_eq!((current.index, current.kp.as_str()), (2, "1,5"));
    assert!(current.cause.is_empty() && !current.checked, "{current:?}");
    // An unreadable one is reported and dropped.
    value["exercises"]["challenges"]["level"] = serde_json::json!("extreme");
    let (restored, problems) = crate::persist::restore_value(&value);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(
        restored.exercises.challenges,
        super::challenges::Kept::default()
    );
}
