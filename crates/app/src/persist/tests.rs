//! The state file's unit tests: a session round-trips, a bad field falls back alone and is
//! named, a bad file is kept aside, the saver writes atomically.

use super::*;
use crate::design::state::Root;
use degrau_words::{Lang, Localize};

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("degrau-persist-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_session_round_trips_with_no_problem() {
    let mut saved = Saved::default();
    saved.design.system.poles.push(Root::real(-7.5));
    saved.dark = true;
    saved.design.splane.view = Some(View {
        center_re: -2.0,
        center_im: 0.5,
        pixels_per_unit: 40.0,
    });
    let text = serde_json::to_string(&saved).unwrap();
    let (back, problems) = restore_text(&text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(serde_json::to_string(&back).unwrap(), text);
}

#[test]
fn each_bad_field_falls_back_alone() {
    let mut saved = Saved::default();
    saved.design.system.gain = 3.0;
    saved.dark = true;
    saved.ident.code = "P1D".into();
    let mut value = serde_json::to_value(&saved).unwrap();
    value["system"]["poles"] = serde_json::json!("three");
    value["splane"]["view"] =
        serde_json::json!({"center_re": -5e29, "center_im": 0.0, "pixels_per_unit": 1e-300});
    value["ident"]["starts"] = serde_json::json!(100000);
    value["options"] = serde_json::json!({"settling_threshold": 7.0, "rise_limits": [0.1, 0.9]});
    let (back, problems) = restore_value(&value);
    let mut fields: Vec<&str> = problems
        .iter()
        .filter_map(|p| match &p.field {
            Field::Path(path) => Some(path.as_str()),
            _ => None,
        })
        .collect();
    fields.sort_unstable();
    assert_eq!(
        fields,
        ["ident.starts", "options", "splane.view", "system.poles"],
        "{problems:?}"
    );
    assert_eq!(back.design.system.poles, System::default().poles);
    assert_eq!(
        back.design.system.gain, 3.0,
        "the rest of the system is kept"
    );
    assert!(back.dark);
    assert_eq!(back.ident.code, "P1D");
    assert_eq!(back.ident.starts, identify::Saved::default().starts);
    assert_eq!(
        back.design.splane.view, None,
        "an absurd view is fitted again"
    );
}

#[test]
fn not_json_is_one_problem_with_defaults() {
    let (back, problems) = restore_text("{\"dark\": tru");
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].field, Field::WholeFile);
    assert!(!back.dark);
}

#[test]
fn a_bad_file_is_kept_aside_and_a_missing_one_is_a_fresh_start() {
    let dir = temp_dir("aside");
    let path = dir.join(FILE_NAME);
    let fresh = restore(&path);
    assert!(fresh.problems.is_empty() && fresh.backup.is_none());
    std::fs::write(&path, "{\"dark\": true, \"mode\": 12}").unwrap();
    let r = restore(&path);
    assert!(r.saved.dark);
    assert_eq!(r.problems[0].field, Field::Path("mode".into()));
    let backup = r.backup.expect("a backup");
    assert_eq!(
        std::fs::read_to_string(&backup).unwrap(),
        "{\"dark\": true, \"mode\": 12}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_saver_writes_atomically_and_flushes_on_drop() {
    let dir = temp_dir("saver");
    let path = dir.join("nested").join(FILE_NAME);
    let mut saver = Saver::spawn(path.clone());
    assert!(saver.offer("{\"a\": 1}".into(), None));
    assert!(saver.offer("{\"a\": 2}".into(), None));
    drop(saver);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "{\"a\": 2}");
    let leftovers: Vec<_> = std::fs::read_dir(path.parent().unwrap())
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name())
        .filter(|n| n != FILE_NAME)
        .collect();
    assert!(
        leftovers.is_empty(),
        "no temporary file left: {leftovers:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_directory_as_the_state_file_is_refused_in_words() {
    let dir = temp_dir("notafile");
    let r = restore(&dir);
    assert_eq!(r.problems.len(), 1);
    assert_eq!(
        r.problems[0].reason,
        Reason::File(StateError::NotAFile(dir.clone()))
    );
    let said = r.problems[0].text(Lang::En);
    assert!(said.contains("not a regular file"), "{said}");
    assert!(
        r.problems[0]
            .text(Lang::Pt)
            .contains("não é um arquivo comum")
    );
    assert!(r.backup.is_none(), "nothing to copy");
    std::fs::remove_dir_all(&dir).ok();
}
