//! Hand gestures shared by the kittests: a drag in several moves, a mouse-wheel turn, a
//! number typed into a field, a text field's content replaced, a button that copies.
#![allow(dead_code)] // each test binary uses its own subset

use degrau::app::DegrauApp;
use eframe::egui::{self, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

/// Drags the widget labelled `label` by `by`, in `moves` moves as a hand would.
pub fn drag_by(h: &mut Harness<'_, DegrauApp>, label: &str, by: Vec2, moves: usize) {
    let from = h.get_by_label(label).rect().center();
    h.hover_at(from);
    h.run_steps(1);
    h.drag_at(from);
    h.run_steps(1);
    for k in 1..=moves {
        h.hover_at(from + by * (k as f32 / moves as f32));
        h.run_steps(1);
    }
    h.drop_at(from + by);
    h.run_steps(2);
}

/// One turn of the mouse wheel by `dy` points with the pointer at `at` (no frame is run).
pub fn wheel(h: &mut Harness<'_, DegrauApp>, at: Pos2, dy: f32) {
    h.hover_at(at);
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: Vec2::new(0.0, dy),
        modifiers: egui::Modifiers::NONE,
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
    });
}

/// Clicks the widget labelled `label` and runs one frame: the texts that frame put on the
/// clipboard.
pub fn click_and_copied(h: &mut Harness<'_, DegrauApp>, label: &str) -> Vec<String> {
    h.get_by_label(label).click();
    h.step();
    h.output()
        .platform_output
        .commands
        .iter()
        .filter_map(|c| match c {
            egui::OutputCommand::CopyText(t) => Some(t.clone()),
            _ => None,
        })
        .collect()
}

/// Every text painted in the last frame, with the rect it covers (tick labels and canvas
/// captions are painted, not widgets).
pub fn painted_texts(h: &Harness<'_, DegrauApp>) -> Vec<(String, egui::Rect)> {
    fn walk(shape: &egui::Shape, out: &mut Vec<(String, egui::Rect)>) {
        match shape {
            egui::Shape::Text(t) => out.push((
                t.galley.text().to_string(),
                t.galley.rect.translate(t.pos.to_vec2()),
            )),
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(s, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for clipped in &h.output().shapes {
        walk(&clipped.shape, &mut out);
    }
    out
}

/// The numbers painted inside `rect` (tick labels), with where they are; `decimal` is the
/// language's separator.
pub fn numbers_in(
    h: &Harness<'_, DegrauApp>,
    rect: egui::Rect,
    decimal: char,
) -> Vec<(f64, egui::Rect)> {
    painted_texts(h)
        .into_iter()
        .filter(|(_, r)| rect.contains(r.center()))
        .filter_map(|(t, r)| {
            t.trim()
                .replace(decimal, ".")
                .replace('\u{2212}', "-")
                .parse::<f64>()
                .ok()
                .map(|v| (v, r))
        })
        .collect()
}

/// Types `text` into the `nth` number field labelled `label` and presses Enter.
pub fn type_number(h: &mut Harness<'_, DegrauApp>, label: &str, nth: usize, text: &str) {
    h.get_all_by_role(egui::accesskit::Role::TextInput)
        .filter(|n| n.accesskit_node().label().as_deref() == Some(label))
        .nth(nth)
        .unwrap_or_else(|| panic!("no number field {label:?} number {nth}"))
        .focus();
    h.run_steps(1);
    replace_focused_text(h, text);
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
}

/// Replaces the text of the text field whose value ends with `ending` by `text` (no Enter).
pub fn retype_field_ending(h: &mut Harness<'_, DegrauApp>, ending: &str, text: &str) {
    h.get_all_by_role(egui::accesskit::Role::TextInput)
        .find(|n| n.value().is_some_and(|v| v.ends_with(ending)))
        .unwrap_or_else(|| panic!("no text field ending with {ending:?}"))
        .focus();
    h.run_steps(1);
    replace_focused_text(h, text);
    h.run_steps(1);
}

/// Selects all of the focused field's text and types `text` over it.
fn replace_focused_text(h: &mut Harness<'_, DegrauApp>, text: &str) {
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.event(egui::Event::Text(text.into()));
    h.run_steps(1);
}

/// Types `path` into the File field (replacing what is there) and presses Load.
pub fn load(h: &mut Harness<'_, DegrauApp>, path: &str) {
    let field = h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Step test file");
    field.focus();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Step test file")
        .type_text(path);
    h.run_steps(1);
    h.get_by_label("Load").click();
    h.run_steps(3);
}

/// Steps until `done` holds (jobs run on their own threads), at most 30 s.
pub fn wait_for(h: &mut Harness<'_, DegrauApp>, done: impl Fn(&Harness<'_, DegrauApp>) -> bool) {
    let start = std::time::Instant::now();
    while !done(h) {
        assert!(
            start.elapsed() < std::time::Duration::from_secs(30),
            "timed out"
        );
        std::thread::sleep(std::time::Duration::from_millis(5));
        h.run_steps(1);
    }
    h.run_steps(2);
}

/// The synthetic TCLab heater record of `tests/data/records/` (T1 against Q1).
pub const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

/// Opens the Identify mode, loads [`TCLAB`] (output T1, input Q1), fits `code` and waits
/// for the fit.
pub fn fit_tclab(h: &mut Harness<'_, DegrauApp>, code: &str) {
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    let settings = &mut h.state_mut().ident.settings;
    settings.y_col = "T1".into();
    settings.u_col = "Q1".into();
    settings.code = code.into();
    load(h, TCLAB);
    h.get_by_label("Fit").click();
    h.run_steps(1);
    let fitted = format!("Fitted {code}");
    wait_for(h, |h| h.query_by_label(&fitted).is_some());
}
