//! The closed loop in the Design mode, through egui_kittest: G(s) typed as coefficients,
//! the loop closed, a closed-loop pole dragged along its branch of the root locus (K and the
//! closed-loop step follow), a spec region shaded, and K found for an overshoot.

use crate::kit;

use degrau::app::DegrauApp;
use degrau::lti::C64;
use degrau::lti::locus::relative_residual;
use eframe::egui::{self, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

/// A tall window, so the whole system panel (the loop's part is at its end) is on screen.
fn harness() -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1500.0, 2600.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(3);
    h
}

/// The closed loop's analysis (the loop must be closed).
fn closed_loop(h: &Harness<'_, DegrauApp>) -> degrau::app::design::analysis::Analysis {
    h.state()
        .design
        .feedback
        .closed
        .clone()
        .expect("the closed loop")
}

/// The app with G(s) typed as tf(num, den).
fn typed(num: &str, den: &str) -> Harness<'static, DegrauApp> {
    let mut h = harness();
    kit::type_number(&mut h, "num", 0, num);
    kit::type_number(&mut h, "den", 0, den);
    h
}

fn click(h: &mut Harness<'_, DegrauApp>, label: &str) {
    h.get_by_label(label).click();
    h.run_steps(3);
}

/// Every closed-loop pole a root of den + Kp·num of the open loop.
#[track_caller]
fn assert_on_the_locus(h: &Harness<'_, DegrauApp>) {
    let g = h.state().system().transfer_function().unwrap();
    assert_on_the_shaped_locus(h, &g);
}

#[test]
fn dragging_a_closed_loop_pole_moves_k_and_the_closed_loop_step() {
    let mut h = harness();
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    let s = &h.state().design;
    assert!(h.state().saved.design.feedback.closed);
    assert_eq!(h.state().saved.design.feedback.kp, 1.0);
    let den = s
        .feedback
        .closed
        .as_ref()
        .unwrap()
        .tf
        .as_ref()
        .unwrap()
        .den();
    assert!((den[3] - 25.5).abs() < 1e-12, "the notes' FTMF: {den:?}");
    let before = s.feedback.closed.as_ref().unwrap().curve.clone();
    assert_on_the_locus(&h);
    // The upper pole of the pair (−0.99 + 2.01j) is on branch 1: drag it up its branch.
    let label = (1..=3)
        .map(|i| format!("closed-loop pole {i}"))
        .find(|l| {
            h.get_all_by_label(l).next().is_some_and(|n| {
                n.rect().center().y < h.get_by_label("s-plane").rect().center().y - 5.0
            })
        })
        .expect("a closed-loop pole above the real axis");
    kit::drag_by(&mut h, &label, Vec2::new(25.0, -60.0), 6);
    let s = &h.state().design;
    assert!(
        h.state().saved.design.feedback.kp > 5.0,
        "Kp followed the drag up the branch: {}",
        h.state().saved.design.feedback.kp
    );
    assert_eq!(
        h.state().system(),
        &degrau::app::design::state::System::default(),
        "the open loop stays"
    );
    assert_on_the_locus(&h);
    let after = &s.feedback.closed.as_ref().unwrap().curve;
    assert_ne!(&before, after, "the closed-loop step followed");
    let info = s.feedback.closed.as_ref().unwrap().info.as_ref().unwrap();
    let g = h.state().system().transfer_function().unwrap();
    let dc = h.state().saved.design.feedback.kp * g.dc_gain()
        / (1.0 + h.state().saved.design.feedback.kp * g.dc_gain());
    assert!(
        (info.steady_state.unwrap() - 2.0 * dc).abs() < 1e-9,
        "the closed loop's own final value"
    );
    // The Kp field shows the gain the drag set.
    let kp_text = h
        .get_all_by_role(egui::accesskit::Role::TextInput)
        .find(|n| n.accesskit_node().label().as_deref() == Some("Kp"))
        .and_then(|n| n.value())
        .unwrap();
    let shown: f64 = kp_text.parse().unwrap();
    assert!(
        (shown - h.state().saved.design.feedback.kp).abs()
            <= 1e-5 * h.state().saved.design.feedback.kp,
        "{kp_text}"
    );
}

#[test]
fn an_overshoot_spec_shades_its_region() {
    let mut h = harness();
    let filled = |h: &Harness<'_, DegrauApp>| {
        h.output()
            .shapes
            .iter()
            .filter(|c| matches!(&c.shape, egui::Shape::Path(p) if p.closed && p.points.len() == 3 && p.fill != egui::Color32::TRANSPARENT))
            .count()
    };
    let none = filled(&h);
    click(&mut h, "Specs");
    click(&mut h, "overshoot");
    assert_eq!(h.state().saved.design.feedback.specs.overshoot, Some(10.0));
    assert_eq!(filled(&h), none + 2, "two wedges where ζ < ζ(10 %)");
    kit::type_number(&mut h, "Mp ≤", 0, "5");
    assert_eq!(h.state().saved.design.feedback.specs.overshoot, Some(5.0));
}

#[test]
fn typed_coefficients_and_k_found_for_an_overshoot() {
    let mut h = typed("1", "1 2 0");
    let g = h.state().system().transfer_function().unwrap();
    assert_eq!(
        g.den(),
        vec![1.0, 2.0, 0.0],
        "K/(s(s+2)) typed as tf(num, den)"
    );
    // Switching what the gain means keeps the system.
    let zpk = h.state().system().clone();
    click(&mut h, "static G(0)");
    click(&mut h, "k (MATLAB's zpk)");
    assert_eq!(
        h.state().system().transfer_function(),
        zpk.transfer_function()
    );
    click(&mut h, "Specs");
    click(&mut h, "overshoot");
    click(&mut h, "Find K");
    let s = &h.state().design;
    assert_eq!(format!("{:.2}", h.state().saved.design.feedback.kp), "2.86");
    assert!(
        h.state().saved.design.feedback.closed,
        "the answer's loop is shown"
    );
    h.get_by_label_contains("Kp = 2.8615");
    let os = s
        .feedback
        .closed
        .as_ref()
        .unwrap()
        .info
        .as_ref()
        .unwrap()
        .overshoot
        .unwrap();
    assert!((os - 10.0).abs() < 1e-6, "{os}");
    assert_on_the_locus(&h);
}

#[test]
fn the_locus_is_drawn_on_request_and_reads_k() {
    let mut h = harness();
    assert!(
        h.state().design.feedback.locus.is_none(),
        "no locus until asked"
    );
    click(&mut h, "Root locus");
    let s = &h.state().design;
    let locus = s.feedback.locus.as_ref().expect("the locus");
    assert!(
        (locus.crossings[0].k - 160.0).abs() < 1e-8,
        "Routh: K = 160"
    );
    assert_eq!(s.feedback.branches.len(), 3);
    // Hovering the locus reads K there.
    let plane = h.get_by_label("s-plane").rect();
    let far = locus.points.iter().find(|p| p.k > 50.0).unwrap().clone();
    let upper = *far.roots.iter().find(|r| r.im > 0.0).unwrap();
    let center = plane.center();
    let view = h.state().saved.design.splane.view.unwrap();
    let at = egui::pos2(
        center.x + ((upper.re - view.center_re) * view.pixels_per_unit) as f32,
        center.y - ((upper.im - view.center_im) * view.pixels_per_unit) as f32,
    );
    h.hover_at(at);
    h.run_steps(2);
    let readout = h.state().design.readout.clone().unwrap_or_default();
    assert!(readout.starts_with("K = "), "{readout}");
    let k: f64 = readout[4..].split(' ').next().unwrap().parse().unwrap();
    assert!((k - far.k).abs() < 0.2 * far.k, "{k} vs {}", far.k);
    click(&mut h, "complementary (K < 0)");
    assert!(!h.state().design.feedback.complementary_branches.is_empty());
}

#[test]
fn the_formulas_sit_beside_the_exact_metrics_and_the_inverse_places_a_pair() {
    let mut h = harness();
    click(&mut h, "Second-order formulas vs the exact response");
    // The notes' system: its dominant pair −1 ± 2j (ζ = 0.447, ωn = 2.236).
    let f = h
        .state()
        .design
        .feedback
        .formulas
        .clone()
        .expect("a dominant pair");
    assert!((f.pair.wn - 5f64.sqrt()).abs() < 1e-12);
    h.get_by_label("t_s ≈ 4/(ζωn)");
    // Mp = 10 % and t_s = 4 s (the defaults): ζ = 0.5912, ωn = 1.6918; placed in one click.
    click(&mut h, "Place on the s-plane");
    let g = h.state().system().transfer_function().unwrap();
    let zeta = degrau::lti::feedback::SecondOrder::damping_for_overshoot(10.0).unwrap();
    let wn = 4.0 / (zeta * 4.0);
    let den = g.den();
    assert!(
        (den[1] - 2.0 * zeta * wn).abs() < 1e-12 && (den[2] - wn * wn).abs() < 1e-12,
        "{den:?}"
    );
    // The exact overshoot of the canonical pair is the spec, to the formula's exactness.
    let f = h.state().design.feedback.formulas.clone().unwrap();
    assert!((f.overshoot.exact.unwrap() - 10.0).abs() < 1e-6);
}

#[test]
fn a_dead_time_is_closed_through_its_pade_approximant_said_approximate() {
    let mut h = harness();
    kit::type_number(&mut h, "Dead time θ", 0, "0.5");
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    h.get_by_label_contains(
        "replaced by its Padé (3, 3) approximant: the closed loop is approximate",
    );
    h.get_by_label_contains(
        "Root locus of the loop with the dead time replaced by its Padé approximant: approximate.",
    );
    // The curve's legend entry and the metrics column's heading.
    assert!(
        h.query_all_by_label("closed loop y(t), Padé approximate")
            .count()
            >= 2
    );
    let s = &h.state().design;
    assert_eq!(s.feedback.approximant.map(|a| (a.m, a.n)), Some((3, 3)));
    // Three poles of G and three of the approximant.
    assert_eq!(s.feedback.closed_poles.len(), 6);
    // Each is a root of 1 + Kp·G·Padé (3, 3), built here from G and the notes' formula.
    let g = h.state().system().transfer_function().unwrap();
    let (pn, pd) = degrau::lti::approx::pade_coefficients(0.5, 3, 3).unwrap();
    let mul = |a: &[f64], b: &[f64]| {
        let mut out = vec![0.0; a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] += x * y;
            }
        }
        out
    };
    let (num, den) = (mul(&g.num(), &pn), mul(&g.den(), &pd));
    for p in &s.feedback.closed_poles {
        let r = relative_residual(&num, &den, 1.0, *p);
        assert!(r < 1e-9, "pole {p}: residual {r}");
    }
    // Another order from the choice.
    click(&mut h, "Padé order (m, n) of the dead time");
    click(&mut h, "(1, 1)");
    assert_eq!(
        h.state().saved.design.feedback.pade,
        degrau::lti::feedback::PadeOrder { m: 1, n: 1 }
    );
    assert_eq!(h.state().design.feedback.closed_poles.len(), 4);
    h.get_by_label_contains("Padé (1, 1) approximant: the closed loop is approximate");
    // And in Portuguese.
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(3);
    h.get_by_label_contains(
        "substituído pela sua aproximação de Padé (1, 1): a malha fechada é aproximada",
    );
}

#[test]
fn the_loop_is_still_closed_with_its_gain_after_a_restart() {
    use degrau::app::persist::FILE_NAME;
    let dir = std::env::temp_dir().join(format!("degrau-app-loop-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(FILE_NAME);
    let mut h = Harness::builder()
        .with_size([1500.0, 2600.0])
        .build_ui_state(
            |ui, app: &mut DegrauApp| app.show(ui),
            DegrauApp::with_state_file(path.clone()),
        );
    h.run_steps(3);
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    kit::type_number(&mut h, "Kp", 0, "4");
    click(&mut h, "Specs");
    click(&mut h, "overshoot");
    let kept = h.state().saved.design.feedback.clone();
    assert!(kept.closed && kept.kp == 4.0 && kept.specs.overshoot == Some(10.0));
    // The saver thread writes it; poll the file for up to 2 s.
    let start = std::time::Instant::now();
    loop {
        let on_disk = std::fs::read_to_string(&path)
            .ok()
            .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok());
        if on_disk.is_some_and(|v| v["feedback"]["kp"] == 4.0 && v["feedback"]["closed"] == true) {
            break;
        }
        assert!(
            start.elapsed() < std::time::Duration::from_secs(2),
            "not saved"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    drop(h);
    let restored = DegrauApp::with_state_file(path.clone());
    assert!(restored.notices.is_empty(), "{:?}", restored.notices);
    assert_eq!(restored.saved.design.feedback, kept);
    // The restored session shows the closed loop at once: 0.5·4 added to 25.
    let den = restored
        .design
        .feedback
        .closed
        .as_ref()
        .expect("closed")
        .tf
        .as_ref()
        .unwrap()
        .den();
    assert!((den[3] - 27.0).abs() < 1e-12, "{den:?}");
    // A gain beyond the limits in the file falls back to the defaults, named.
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    v["feedback"]["kp"] = serde_json::json!(1e300);
    std::fs::write(&path, v.to_string()).unwrap();
    let bad = DegrauApp::with_state_file(path.clone());
    assert_eq!(bad.saved.design.feedback, Default::default());
    assert!(
        bad.notices
            .iter()
            .any(|n| format!("{n:?}").contains("feedback")),
        "{:?}",
        bad.notices
    );
    drop((restored, bad));
    std::fs::remove_dir_all(&dir).ok();
}

/// With the loop closed, the "Previous" curve is the closed loop before the gain changed
/// (issue 23, item 3: it showed the open loop from the last edit of the system, two edits
/// old, while Kp moved the closed loop).
#[test]
fn the_previous_curve_follows_the_loop_gain() {
    let mut h = harness();
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    kit::type_number(&mut h, "Kp", 0, "2");
    h.run_steps(2);
    let at_two = h
        .state()
        .design
        .feedback
        .closed
        .as_ref()
        .expect("the closed loop at Kp = 2")
        .curve
        .clone();
    kit::type_number(&mut h, "Kp", 0, "5");
    h.run_steps(2);
    assert_eq!(h.state().saved.design.feedback.kp, 5.0);
    assert_eq!(h.state().design.ghost.as_ref(), Some(&at_two));
}

/// One name, one thing (issue 23, item 9): the loop's gain is Kp, the error constants are
/// the notes' K_p, K_v, K_a; the plot's legend reads in Portuguese word order ("faixa de
/// ±2 %", not the calque "±2 % faixa").
#[test]
fn the_error_constants_and_the_legend_read_as_the_notes_write_them() {
    let mut h = harness();
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    h.get_by_label_contains("error constants of Kp·G: position K_p = ");
    assert!(h.query_by_label_contains("position Kp =").is_none());
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(3);
    h.get_by_label_contains("posição K_p = ");
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|p| p.0).collect();
    assert!(painted.iter().any(|t| t == "faixa de ±2 %"), "{painted:?}");
    assert!(
        painted.iter().any(|t| t == "passagem por 90 %"),
        "{painted:?}"
    );
    assert!(
        !painted.iter().any(|t| t.ends_with("% faixa")),
        "{painted:?}"
    );
}

/// Typed coefficients stay as the student typed them (issue 23, item 14: "7.5 19 8.5 1"
/// was rewritten "1 2.5333333 …", monic); the system is the one typed, and a later change
/// of the system writes the fields afresh.
#[test]
fn typed_coefficients_stay_as_typed() {
    let mut h = typed("3", "7.5 19 8.5 1");
    h.run_steps(3);
    let value = |h: &Harness<'_, DegrauApp>, label: &str| {
        h.get_all_by_role(egui::accesskit::Role::TextInput)
            .find(|n| n.accesskit_node().label().as_deref() == Some(label))
            .and_then(|n| n.value())
            .unwrap_or_default()
    };
    assert_eq!(value(&h, "den"), "7.5 19 8.5 1");
    assert_eq!(value(&h, "num"), "3");
    let g = h.state().system().transfer_function().unwrap();
    assert!((g.dc_gain() - 3.0).abs() < 1e-12, "G(0) = 3/1");
    click(&mut h, "Undo");
    assert_ne!(
        value(&h, "den"),
        "7.5 19 8.5 1",
        "the undone system's own coefficients"
    );
}

/// With the loop closed, the metrics and the closed form describe the closed loop beside
/// the open loop (issue 23, item 8: "does not settle: it ramps (integrator)" stood alone
/// beside a closed-loop curve with 10 % overshoot).
#[test]
fn the_closed_loop_has_its_own_metrics_and_closed_form() {
    let mut h = typed("1", "1 2 0");
    click(&mut h, "Specs");
    click(&mut h, "overshoot");
    click(&mut h, "Find K");
    let closed = closed_loop(&h);
    let os = closed
        .info
        .as_ref()
        .and_then(|i| i.overshoot)
        .expect("an overshoot");
    assert!((os - 10.0).abs() < 1e-6, "{os}");
    // The column's heading, beside the curve's legend entry.
    assert!(h.query_all_by_label("closed loop y(t)").count() >= 2);
    let cell = degrau::app::design::metrics_table::cell_text(
        &closed,
        degrau::text::step::Metric::Overshoot,
        degrau::text::Lang::En,
    );
    assert!(h.query_all_by_label(&cell).count() >= 1, "{cell}");
    h.get_by_label_contains("closed loop y(t): y(t) = ");
    // The open loop's own column still says why it has no overshoot: it ramps.
    let open = degrau::app::design::metrics_table::cell_text(
        &h.state().design.analysis,
        degrau::text::step::Metric::Overshoot,
        degrau::text::Lang::En,
    );
    assert!(h.query_all_by_label(&open).count() >= 1, "{open}");
    assert_ne!(open, cell);
}

/// With the loop closed, only the closed loop's rise and peak carry text on the plot
/// (issue 23, item 6: the open and closed loops' labels printed over each other).
#[test]
fn only_the_closed_loops_markers_are_labelled() {
    let mut h = harness();
    let count = |h: &Harness<'_, DegrauApp>, start: &str| {
        kit::painted_texts(h)
            .into_iter()
            .filter(|(t, _)| t.trim_start().starts_with(start))
            .count()
    };
    // The label on the plot and its legend entry.
    let open = count(&h, "rise time");
    assert!(open >= 1);
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    h.run_steps(2);
    let closed = closed_loop(&h);
    let tr = closed
        .info
        .as_ref()
        .and_then(|i| i.rise_time)
        .expect("a rise");
    let label = format!("rise time {} s", degrau::text::Lang::En.num(tr, 4));
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|p| p.0).collect();
    assert_eq!(count(&h, "rise time"), open, "not doubled: {painted:?}");
    assert!(
        painted.iter().any(|t| t.trim() == label),
        "{label} in {painted:?}"
    );
}

#[test]
fn a_pi_controller_in_the_loop_adds_its_integrator_and_zero_and_k_is_kc() {
    let mut h = harness();
    click(&mut h, "Close the loop: unity feedback around Kp·G(s)");
    let before = h
        .state()
        .design
        .feedback
        .open_loop
        .clone()
        .unwrap()
        .unwrap();
    click(&mut h, "PI");
    kit::type_number(&mut h, "Ti", 0, "2");
    let feedback = &h.state().saved.design.feedback;
    assert_eq!(feedback.controller.action, degrau::lti::control::Action::PI);
    assert_eq!(feedback.controller.ti, 2.0);
    // The open loop is (1 + 1/(2s))·G: one pole more (at the origin) and a zero at −0.5.
    let g = h
        .state()
        .design
        .feedback
        .open_loop
        .clone()
        .unwrap()
        .unwrap();
    assert_eq!(g.order(), before.order() + 1);
    assert!(g.poles().iter().any(|p| p.norm() == 0.0));
    assert!(
        g.zeros()
            .iter()
            .any(|z| (z.re + 0.5).abs() < 1e-12 && z.im == 0.0)
    );
    let s = C64::new(0.3, 0.7);
    let expected = before.eval(s) * (1.0 + 1.0 / (2.0 * s));
    assert!((g.eval(s) - expected).norm() < 1e-12 * expected.norm());
    // The integrator makes the loop type 1: no steady-state error to a step.
    let constants = h.state().design.feedback.constants.unwrap();
    assert_eq!(constants.system_type, 1);
    assert_on_the_shaped_locus(&h, &g);
    // A typed Ti of 0 is refused and the PI stays.
    kit::type_number(&mut h, "Ti", 0, "0");
    assert_eq!(h.state().saved.design.feedback.controller.ti, 2.0);
}

/// Every closed-loop pole a root of den + Kp·num of the open loop g (shaped by the
/// controller when it is not P).
#[track_caller]
fn assert_on_the_shaped_locus(h: &Harness<'_, DegrauApp>, g: &degrau::lti::TransferFunction) {
    let kp = h.state().saved.design.feedback.kp;
    let poles = &h.state().design.feedback.closed_poles;
    assert_eq!(poles.len(), g.order());
    for p in poles {
        let r = relative_residual(&g.num(), &g.den(), kp, *p);
        assert!(r < 1e-9, "pole {p} at Kp {kp}: residual {r}");
    }
}
