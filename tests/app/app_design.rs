//! The Design mode's fields, y range and hover, through egui_kittest: what a student types,
//! what the plot shows and what it reads out.

use crate::kit;

use degrau::app::DegrauApp;
use degrau::app::design::state::System;
use eframe::egui::{self, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

fn harness(app: DegrauApp) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

#[test]
fn a_pole_typed_as_1e300_is_refused_with_why_and_changes_nothing() {
    let mut h = harness(DegrauApp::default());
    let panel = h.get_by_label("System").rect();
    let plane = h.get_by_label("s-plane").rect();
    for (field, nth, text) in [("σ", 1, "-1e300"), ("σ", 0, "1e300"), ("±jω", 0, "1e300")] {
        kit::type_number(&mut h, field, nth, text);
        assert_eq!(h.state().system(), &System::default(), "{field} = {text}");
        h.get_by_label_contains("beyond what the exact response can show");
        assert_eq!(
            h.get_by_label("System").rect(),
            panel,
            "the panel keeps its place"
        );
        assert_eq!(h.get_by_label("s-plane").rect(), plane);
        // Fix the entry so the next one is refused on its own.
        kit::type_number(
            &mut h,
            field,
            nth,
            if field == "σ" && nth == 1 {
                "-5"
            } else if field == "σ" {
                "-1"
            } else {
                "2"
            },
        );
    }
    assert!(!h.state().design.history.can_undo(), "nothing was applied");
    // A root 1e13 times slower than the fastest is refused too, naming the spread.
    kit::type_number(&mut h, "σ", 1, "-5e-13");
    assert_eq!(h.state().system(), &System::default());
    h.get_by_label_contains("1e12 times faster");
}

#[test]
fn a_decimal_comma_is_accepted_in_the_gain() {
    let mut h = harness(DegrauApp::default());
    kit::type_number(&mut h, "Gain", 0, "2,5");
    assert_eq!(h.state().system().gain, 2.5);
    kit::type_number(&mut h, "Dead time θ", 0, "0,25");
    assert_eq!(h.state().system().delay, 0.25);
    // One undo per committed field.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().system().delay, 0.0);
    assert_eq!(h.state().system().gain, 2.5);
}

#[test]
fn the_ghost_does_not_set_the_y_range() {
    let mut h = harness(DegrauApp::default());
    h.get_by_label("Example").click();
    h.run_steps(2);
    h.get_by_label("Fifth order vs its dominant pair −3 ± 3j")
        .click();
    h.run_steps(4);
    assert!(
        h.state().design.ghost.is_some(),
        "the default system is the ghost"
    );
    let plot = h.get_by_label("step response").rect();
    let y: Vec<f64> = kit::numbers_in(&h, plot.expand(60.0), '.')
        .into_iter()
        .filter(|(_, r)| r.center().x < plot.left() + 60.0 && r.center().y < plot.bottom() - 30.0)
        .map(|(v, _)| v)
        .collect();
    // Both current curves end at 2·0.5/9000 = 1.1e-4; the ghost reaches 0.04.
    assert!(y.len() >= 2, "{y:?}");
    assert!(
        y.iter().all(|v| v.abs() < 5e-4),
        "the y range follows the current curves: {y:?}"
    );
}

/// The hover label's lines "t = …" and "y(t) = …", as numbers.
fn hover_reading(h: &Harness<'_, DegrauApp>) -> Option<(f64, f64)> {
    let text = h
        .get_all_by_role(egui::accesskit::Role::Label)
        .filter_map(|n| {
            n.accesskit_node()
                .label()
                .or_else(|| n.value())
                .map(|l| l.to_string())
        })
        .find(|l| l.starts_with("t = ") && l.contains("y(t) = "))?;
    let value = |key: &str| -> Option<f64> {
        let line = text.lines().find(|l| l.starts_with(key))?;
        line[key.len()..].trim_end_matches(" s").trim().parse().ok()
    };
    Some((value("t = ")?, value("y(t) = ")?))
}

#[test]
fn hovering_the_plot_reads_the_curve_at_the_cursor_t() {
    let mut h = harness(DegrauApp::default());
    let plot = h.get_by_label("step response").rect();
    let response = h
        .state()
        .design
        .analysis
        .response
        .clone()
        .expect("a response");
    // Well above the curve, where the cursor's own y is far from it.
    for fraction in [0.2f32, 0.45, 0.7] {
        let at = Pos2::new(plot.left() + fraction * plot.width(), plot.top() + 20.0);
        h.hover_at(at);
        h.run_steps(2);
        let (t, y) = hover_reading(&h).expect("a hover label");
        // Within one pixel of t on either side.
        let horizon = h.state().design.analysis.horizon;
        let dt = horizon / plot.width() as f64;
        let (a, b) = (response.value((t - dt).max(0.0)), response.value(t + dt));
        let (lo, hi) = (a.min(b), a.max(b));
        let tolerance = 1e-4 * response.value(horizon).abs();
        assert!(
            y >= lo - tolerance && y <= hi + tolerance,
            "hover at t = {t}: y = {y}, the curve is between {lo} and {hi}"
        );
    }
}

fn open_menu_item(h: &mut Harness<'_, DegrauApp>, menu: &str, item: &str) {
    h.get_by_label(menu).click();
    h.run_steps(2);
    h.get_by_label(item).click();
    h.run_steps(3);
}

#[test]
fn copy_as_code_puts_the_system_on_the_clipboard_and_says_so() {
    let mut h = harness(DegrauApp::default());
    h.get_by_label("File").click();
    h.run_steps(2);
    let copied = kit::click_and_copied(&mut h, "Copy as MATLAB code");
    // 0.5/((s² + 2s + 5)(s + 5)) = 0.5/(s³ + 7s² + 15s + 25), driven by the notes' step
    // of 2 (MATLAB's step(G) is a unit step: its peak was half the app's).
    assert_eq!(
        copied,
        ["G = tf([0.5], [1 7 15 25]);\nA = 2;  % the step's amplitude\nstep(A*G)\nstepinfo(A*G)"]
    );
    h.run_steps(2);
    h.get_by_label("Copied the system as MATLAB code");
}

#[test]
fn saving_over_a_file_asks_first_and_a_png_waits_for_the_dialog_to_close() {
    let dir = std::env::temp_dir().join(format!("degrau-overwrite-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    std::fs::write(&path, "kept\n").unwrap();
    let mut h = harness(DegrauApp::default());
    open_menu_item(&mut h, "File", "Export…");
    kit::retype_field_ending(&mut h, "degrau_step.png", path.to_str().unwrap());
    h.run_steps(1);
    h.get_by_label("Save curve as CSV").click();
    h.run_steps(2);
    h.get_by_label_contains("already exists. Overwrite it?");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "kept\n", "not yet");
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "kept\n");
    h.get_by_label("Save curve as CSV").click();
    h.run_steps(2);
    h.get_by_label("Overwrite").click();
    h.run_steps(2);
    assert!(
        std::fs::read_to_string(&path)
            .unwrap()
            .starts_with("t_s,y\n")
    );
    // A PNG to a new file: the dialog closes first, so the screenshot cannot show it.
    let png = dir.join("plot.png");
    kit::retype_field_ending(&mut h, "curve.csv", png.to_str().unwrap());
    h.run_steps(1);
    h.get_by_label("Save step plot as PNG").click();
    h.step(); // the frame the click is read in, the last with the dialog
    for _ in 0..3 {
        h.step();
        // Nothing of it is painted either (issue 23, item 15: egui kept drawing a window
        // closed through `open` during its fade-out, and the PNG showed it).
        let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|p| p.0).collect();
        assert!(
            !painted
                .iter()
                .any(|t| t.contains("Taking the screenshot") || t == "Save window as PNG"),
            "{painted:?}"
        );
    }
    assert!(
        h.query_by_label("Save step plot as PNG").is_none(),
        "the export window is closed while the screenshot is taken"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The closed form speaks the student's language (issue 23, item 9): in Portuguese a dead
/// time reads "para t ≥ 0,5 (y = 0 antes de 0,5)", its numbers with the decimal comma.
#[test]
fn the_closed_form_is_written_in_portuguese() {
    let mut h = harness(DegrauApp::default());
    let mut system = h.state().system().clone();
    system.delay = 0.5;
    h.state_mut().set_system(system);
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(3);
    h.get_by_label_contains("para t ≥ 0,5 (y = 0 antes de 0,5)");
    assert!(h.query_by_label_contains("for t ≥").is_none());
    assert!(h.query_by_label_contains("before 0").is_none());
}

/// G(s) with a dead time is drawn as the fraction times the delay (issue 23, item 7: the
/// delay sat after the denominator, "5 / s + 2 · e^(−0.5 s)"), its numbers with the
/// language's separator (item 9).
#[test]
fn a_dead_time_multiplies_the_whole_fraction() {
    let mut h = harness(DegrauApp::default());
    h.state_mut().set_system(System {
        zeros: vec![],
        poles: vec![degrau::app::design::state::Root::real(-2.0)],
        gain: 5.0,
        delay: 0.5,
        ..System::default()
    });
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(3);
    let g = h
        .get_all_by_role(egui::accesskit::Role::Label)
        .filter_map(|n| n.value())
        .find(|v| v.contains('─'))
        .expect("G(s) as a fraction");
    let lines: Vec<&str> = g.lines().collect();
    assert_eq!(lines.len(), 3, "{g}");
    assert_eq!(lines[0].trim(), "5", "{g}");
    assert!(lines[1].ends_with("─ · e^(−0,5 s)"), "{g}");
    assert_eq!(lines[2].trim(), "s + 2", "{g}");
}

/// "Save step plot as PNG" crops to the plot with its title, axes and ticks (issue 23,
/// item 15: the plot's frame alone had none of them).
#[test]
fn the_plot_region_holds_its_title_axes_and_ticks() {
    let h = harness(DegrauApp::default());
    let region = h.state().plot_rect().expect("the plot was drawn");
    let painted = kit::painted_texts(&h);
    for text in ["Step response y(t), A = 2", "t (s)", "y(t)"] {
        let (_, rect) = painted
            .iter()
            .find(|(t, _)| t == text)
            .unwrap_or_else(|| panic!("{text:?} not painted"));
        assert!(
            region.expand(0.5).contains_rect(*rect),
            "{text:?} {rect:?} outside {region:?}"
        );
    }
    // A tick label of each axis too.
    let ticks = painted
        .iter()
        .filter(|(t, r)| t.parse::<f64>().is_ok() && region.contains_rect(*r))
        .count();
    assert!(ticks >= 4, "{ticks} tick labels inside");
}
