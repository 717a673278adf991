//! The Frequency mode through egui_kittest: the Bode readout of the default Design system
//! checked against a direct evaluation, the margins of the Tune loop (and ∞ where a loop
//! has no crossover), the z-plane at h = 0.1 s with H(z)'s poles e^{p·h}, a bad h refused,
//! the layout at the classroom's sizes and the settings kept across a restart.

use crate::kit;

use degrau::app::design::state::Root;
use degrau::app::frequency::{SourceKind, Tab};
use degrau::app::{DegrauApp, Mode, Saved};
use degrau::lti::bode::bode;
use degrau::lti::control::margins;
use degrau::lti::{C64, TransferFunction};
use degrau::text::Lang;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

fn harness(app: DegrauApp, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(3);
    h
}

/// The app in the Frequency mode with `saved`'s settings.
fn frequency_app(mut saved: Saved) -> Harness<'static, DegrauApp> {
    saved.mode = Mode::Frequency;
    harness(DegrauApp::new(saved), [1360.0, 860.0])
}

/// The numbers written in `text` (a decimal comma and − read as well).
fn numbers(text: &str) -> Vec<f64> {
    text.replace('\u{2212}', "-")
        .split(|c: char| c.is_whitespace() || "()°=:;".contains(c))
        .filter_map(|w| {
            w.trim_matches(|c: char| !(c.is_ascii_digit() || c == '-' || c == '.'))
                .parse::<f64>()
                .ok()
        })
        .collect()
}

/// The label that starts with `start`.
fn label_starting(h: &Harness<'_, DegrauApp>, start: &str) -> String {
    h.query_all_by_label_contains(start)
        .filter_map(|n| n.accesskit_node().value())
        .find(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("no label starting with {start:?}"))
}

/// Half a unit of the last of `digits` significant digits of `x`.
fn rounding(x: f64, digits: i32) -> f64 {
    if x == 0.0 {
        return 0.0;
    }
    0.5 * 10f64.powi(x.abs().log10().floor() as i32 - digits + 1)
}

fn design_tf(h: &Harness<'_, DegrauApp>) -> TransferFunction {
    h.state().design.analysis.tf.clone().expect("a system")
}

#[test]
fn hovering_the_bode_magnitude_reads_the_exact_values() {
    let mut h = frequency_app(Saved::default());
    h.get_by_label("Hover a plot to read ω, the magnitude and the phase.");
    let plot = h
        .get_by_role_and_label(egui::accesskit::Role::Canvas, "Bode magnitude")
        .rect();
    h.hover_at(plot.center() + egui::vec2(plot.width() * 0.1, 0.0));
    h.run_steps(2);
    let text = label_starting(&h, "ω = ");
    let v = numbers(&text);
    assert_eq!(v.len(), 4, "{text:?}: {v:?}");
    let (w, db, ratio, deg) = (v[0], v[1], v[2], v[3]);
    let exact = bode(&design_tf(&h), &[w]);
    let (edb, edeg) = (exact.mag_db[0], exact.phase_deg[0]);
    // The printed ω is rounded to 4 digits: the curve moves by at most 60 dB and 270° a
    // decade, 5e-4 of ω is 2.2e-4 decades.
    assert!((db - edb).abs() <= rounding(db, 4) + 0.02, "{text}: {edb}");
    assert!(
        (deg - edeg).abs() <= rounding(deg, 4) + 0.1,
        "{text}: {edeg}"
    );
    let eratio = 10f64.powf(edb / 20.0);
    assert!(
        (ratio - eratio).abs() <= rounding(ratio, 4) + 0.003 * eratio,
        "{text}: {eratio}"
    );
    assert!(text.contains("|G|") && text.contains("∠G"), "{text}");
    // The asymptotes in words: 0.5/25 is −33.98 dB, corners at √5 (a pair) and 5.
    h.get_by_label(
        "Low-frequency asymptote (type 0): 20·log10|K| = -33.9794 dB at ω = 1 rad/s, slope 0 dB/decade",
    );
    h.get_by_label(
        "Corner at ω = 2.23607 rad/s: the slope changes by -40 dB/decade, to -40 dB/decade",
    );
    h.get_by_label("Corner at ω = 5 rad/s: the slope changes by -20 dB/decade, to -60 dB/decade");
    // The phase plot reads the same way, at its own ω.
    let phase = h
        .get_by_role_and_label(egui::accesskit::Role::Canvas, "Bode phase")
        .rect();
    h.hover_at(phase.center() - egui::vec2(phase.width() * 0.2, 0.0));
    h.run_steps(2);
    let v = numbers(&label_starting(&h, "ω = "));
    assert!(v[0] < w, "further left is a lower ω: {} vs {w}", v[0]);
    let exact = bode(&design_tf(&h), &[v[0]]);
    assert!(
        (v[3] - exact.phase_deg[0]).abs() <= rounding(v[3], 4) + 0.1,
        "{v:?}"
    );
    // In Portuguese the numbers take the decimal comma.
    h.state_mut().saved.lang = Lang::Pt;
    h.run_steps(2);
    let text = label_starting(&h, "ω = ");
    assert!(text.contains(',') && !text.contains('.'), "{text}");
    let v = numbers(&text.replace(',', "."));
    let exact = bode(&design_tf(&h), &[v[0]]);
    assert!(
        (v[1] - exact.mag_db[0]).abs() <= rounding(v[1], 4) + 0.02,
        "{text}"
    );
}

#[test]
fn the_tune_loop_shows_its_margins() {
    let mut saved = Saved::default();
    saved.frequency.source = SourceKind::Tune;
    let h = frequency_app(saved);
    let (plant, c) = h.state().saved.tune.plant_and_controller().expect("a loop");
    let m = margins(&plant, &c);
    let gm = numbers(&label_starting(&h, "Gain margin GM = "));
    assert!(
        (gm[0] - m.gm).abs() <= rounding(m.gm, 4),
        "{gm:?} vs {}",
        m.gm
    );
    assert!((gm[1] - m.gm_db).abs() <= rounding(m.gm_db, 4), "{gm:?}");
    let w_pc = m.w_pc.expect("a phase crossover");
    assert!((gm[2] - w_pc).abs() <= rounding(w_pc, 4), "{gm:?}");
    let pm = numbers(&label_starting(&h, "Phase margin PM = "));
    assert!(
        (pm[0] - m.pm).abs() <= rounding(m.pm, 4),
        "{pm:?} vs {}",
        m.pm
    );
    let w_gc = m.w_gc.expect("a gain crossover");
    assert!((pm[1] - w_gc).abs() <= rounding(w_gc, 4), "{pm:?}");
    // K·e^{−2s}/(10s + 1) with SIMC's PI: L = 0.25·e^{−2s}/s, PM = 90° − 0.5 rad.
    assert!((m.pm - (90.0 - 0.5f64.to_degrees())).abs() < 1e-6);
    h.get_by_label("The closed loop is stable.");
    h.get_by_label("Controller C(s) =");
    h.get_by_label_contains("2.5 s + 0.25");
    h.get_by_label_contains("The loop stands a gain");
    h.get_by_label_contains("It stands a dead time");
    assert!(label_starting(&h, "Delay margin = ").contains(" s"));
}

#[test]
fn a_loop_without_a_crossover_says_infinity_in_words() {
    // The default system: 0.5/((s² + 2s + 5)(s + 5)), |G| < 1 everywhere.
    let h = frequency_app(Saved::default());
    h.get_by_label("Phase margin PM = ∞: |L| never crosses 1: no gain crossover");
    h.get_by_label_contains("The loop stands any extra dead time");
    // One pole: the phase never reaches −180°.
    let mut saved = Saved::default();
    saved.design.system.poles = vec![Root::real(-1.0)];
    saved.design.system.gain = 5.0;
    saved.lang = Lang::Pt;
    let h = frequency_app(saved);
    h.get_by_label("Margem de ganho GM = ∞: não há cruzamento de fase");
    h.get_by_label("A malha suporta qualquer ganho maior (não há cruzamento de fase).");
}

/// The roots written as "0.9048; 0.8 + 0.1j; 0.8 − 0.1j".
fn roots_written(text: &str) -> Vec<C64> {
    let list = text.split_once(':').map_or(text, |(_, l)| l);
    list.split("; ")
        .map(|r| {
            let r = r.trim().replace('\u{2212}', "-");
            match r.split_once(" + ").or_else(|| r.split_once(" - ")) {
                Some((re, im)) => {
                    let sign = if r.contains(" - ") { -1.0 } else { 1.0 };
                    let im: f64 = im.trim_end_matches('j').parse().expect("im");
                    C64::new(re.parse().expect("re"), sign * im)
                }
                None => C64::new(r.parse().expect("a real root"), 0.0),
            }
        })
        .collect()
}

#[test]
fn the_z_plane_lists_the_poles_e_to_the_p_h() {
    let mut h = frequency_app(Saved::default());
    h.get_by_label("z-plane (sampled)").click();
    h.run_steps(3);
    assert_eq!(h.state().saved.frequency.tab, Tab::ZPlane);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "0.2");
    assert_eq!(h.state().saved.frequency.h, 0.2);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "0.1");
    assert_eq!(h.state().saved.frequency.h, 0.1);
    // A new h samples again; the loop's Bode and margins are not computed again.
    assert_eq!(h.state().frequency.computations, 1);
    let shown = roots_written(&label_starting(&h, "Poles of H(z):"));
    let tf = design_tf(&h);
    assert_eq!(shown.len(), tf.poles().len());
    for p in tf.poles() {
        let want = (p * 0.1).exp();
        assert!(
            shown.iter().any(|z| (z - want).norm() < 1e-5),
            "e^(0.1·{p}) = {want} not in {shown:?}"
        );
    }
    label_starting(&h, "Zeros of H(z): ");
    h.get_by_role_and_label(egui::accesskit::Role::Canvas, "z-plane");
    h.get_by_label_contains("[Kalman & Bertram]: h < ");
    h.get_by_label_contains("(FOPTD): does not apply (there is no dead time");
    h.get_by_label("d2c back: G(s) =");
}

#[test]
fn a_bad_sampling_period_is_refused_and_the_old_one_stays() {
    let mut saved = Saved::default();
    saved.frequency.tab = Tab::ZPlane;
    saved.frequency.h = 0.5;
    let mut h = frequency_app(saved);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "0");
    h.get_by_label_contains(
        "Refused: the sampling period h must be a positive number of seconds, not 0",
    );
    assert_eq!(h.state().saved.frequency.h, 0.5);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "-1");
    assert_eq!(h.state().saved.frequency.h, 0.5);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "abc");
    h.get_by_label("\"abc\" is not a number");
    assert_eq!(h.state().saved.frequency.h, 0.5);
    assert!(label_starting(&h, "Poles of H(z):").len() > 15);
}

#[test]
fn the_loop_is_computed_only_when_its_source_changes() {
    let mut h = frequency_app(Saved::default());
    h.run_steps(5);
    assert_eq!(h.state().frequency.computations, 1);
    h.get_by_label("Tuning: the loop L(s) = C(s)·G(s)").click();
    h.run_steps(3);
    assert_eq!(h.state().saved.frequency.source, SourceKind::Tune);
    assert_eq!(h.state().frequency.computations, 2);
    // No fit yet: the Identify source is greyed and says so.
    h.get_by_label("Identify: the fitted model G(s) (no fitted model yet)");
}

#[test]
fn the_frequency_settings_survive_a_restart() {
    let mut h = frequency_app(Saved::default());
    h.get_by_label("Tuning: the loop L(s) = C(s)·G(s)").click();
    h.run_steps(2);
    h.get_by_label("z-plane (sampled)").click();
    h.run_steps(2);
    kit::type_number(&mut h, "Sampling period h (s)", 0, "0,25");
    let kept = h.state().saved.frequency;
    assert_eq!(
        (kept.source, kept.tab, kept.h),
        (SourceKind::Tune, Tab::ZPlane, 0.25)
    );
    let dir = std::env::temp_dir().join(format!("degrau-frequency-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let path = dir.join("state.json");
    let json = serde_json::to_string_pretty(&h.state().saved).expect("JSON");
    degrau::app::persist::write_atomically(&path, json.as_bytes()).expect("written");
    let h2 = harness(DegrauApp::with_state_file(path), [1360.0, 860.0]);
    assert_eq!(h2.state().saved.mode, Mode::Frequency);
    assert_eq!(h2.state().saved.frequency, kept);
    assert!(h2.state().notices.is_empty());
    let _ = std::fs::remove_dir_all(&dir);
    // A saved h that is no period falls back alone.
    let mut value = serde_json::to_value(Saved::default()).expect("JSON");
    value["frequency"]["h"] = serde_json::json!(-2.0);
    value["frequency"]["tab"] = serde_json::json!("Nyquist");
    let (restored, problems) = degrau::app::persist::restore_value(&value);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(restored.frequency.h, 0.1);
    assert_eq!(restored.frequency.tab, Tab::Nyquist);
}

/// The words each tab must show on screen, in `lang` (their start).
fn key_labels(tab: Tab, lang: Lang) -> Vec<&'static str> {
    let mut labels = vec![lang.pick("Stability margins", "Margens de estabilidade")];
    labels.extend(match tab {
        Tab::Bode => vec![lang.pick("Hover a plot", "Passe o ponteiro")],
        Tab::ZPlane => vec![
            lang.pick("Sampling period h (s)", "Período de amostragem h (s)"),
            lang.pick("Poles of H(z):", "Polos de H(z):"),
        ],
        Tab::Nyquist => vec!["N = ", lang.pick("Whole curve", "Curva inteira")],
    });
    labels
}

/// The key labels of `tab` that are not whole inside the window.
fn missing_labels(h: &Harness<'_, DegrauApp>, tab: Tab, lang: Lang) -> Vec<String> {
    let window = h.ctx.content_rect().expand(0.5);
    key_labels(tab, lang)
        .into_iter()
        .filter(|start| {
            !h.query_all_by_label_contains(start)
                .any(|n| window.contains_rect(n.rect()))
        })
        .map(|start| format!("{start:?} is not on screen"))
        .collect()
}

/// The classroom's layout (1000×650 and 1600×900, 1× to 1.6×, both languages) of each tab,
/// for the Tune loop and the Design system: nothing outside the window or over another
/// text, every plot at least 220 points, the tab's key labels on screen.
#[test]
fn the_frequency_mode_fits_every_classroom_size() {
    let mut problems = Vec::new();
    let cases = [
        (Tab::Bode, 2, SourceKind::Tune),
        (Tab::Bode, 2, SourceKind::Design),
        (Tab::ZPlane, 2, SourceKind::Tune),
        (Tab::Nyquist, 1, SourceKind::Tune),
    ];
    for (tab, canvases, source) in cases {
        let mut saved = Saved {
            mode: Mode::Frequency,
            ..Default::default()
        };
        saved.frequency.tab = tab;
        saved.frequency.source = source;
        let mut h = harness(DegrauApp::new(saved), [1600.0, 900.0]);
        problems.extend(crate::app_classroom::problems_everywhere_with(
            &mut h,
            &format!("Frequency, {tab:?}, {source:?}"),
            canvases,
            |h, lang| missing_labels(h, tab, lang),
        ));
    }
    crate::app_classroom::assert_no_problems(&problems);
}

/// Z of the Nyquist verdict "… → Z = N + P = 2 closed-loop poles …".
fn nyquist_z(text: &str) -> i64 {
    let after = text.split("Z = N + P = ").nth(1).expect("a verdict");
    after
        .split_whitespace()
        .next()
        .and_then(|z| z.parse().ok())
        .expect("Z")
}

#[test]
fn the_nyquist_verdict_agrees_with_the_direct_count() {
    use degrau::lti::control::Action;
    use degrau::lti::control::frequency::closed_loop_unstable_roots;
    let cases = [
        (Action::PI, 2.5, true),
        (Action::PI, 40.0, false),
        (Action::P, 40.0, false),
    ];
    for (action, kc, stable) in cases {
        let mut saved = Saved::default();
        saved.frequency.source = SourceKind::Tune;
        saved.frequency.tab = Tab::Nyquist;
        saved.tune.controller.action = action;
        saved.tune.controller.kc = kc;
        let mut h = frequency_app(saved);
        let verdict = label_starting(&h, "N = ");
        let z = nyquist_z(&verdict);
        let (plant, c) = h.state().saved.tune.plant_and_controller().expect("a loop");
        let direct = closed_loop_unstable_roots(&plant, &c).expect("a count");
        assert_eq!(z, direct as i64, "{verdict}");
        assert_eq!(z == 0, stable, "{verdict}");
        let end = if stable { ": stable" } else { ": unstable" };
        assert!(verdict.ends_with(end), "{verdict}");
        let counted = label_starting(
            &h,
            "Counted directly from the closed-loop characteristic equation:",
        );
        assert!(counted.ends_with(end), "{counted}");
        assert!(counted.contains(&format!(": {direct} roots")), "{counted}");
        h.get_by_role_and_label(egui::accesskit::Role::Canvas, "Nyquist diagram");
        h.get_by_label("Controller C(s) =");
        if action == Action::P {
            h.get_by_label("40\n──\n1");
        }
        // The whole curve, then back to the window around −1.
        h.get_by_label("Whole curve").click();
        h.run_steps(2);
        assert!(h.state().saved.frequency.whole_curve);
        h.get_by_label("Whole curve").click();
        h.run_steps(2);
        assert!(!h.state().saved.frequency.whole_curve);
    }
}

#[test]
fn a_fitted_model_is_a_source_once_there_is_one() {
    let mut h = harness(DegrauApp::default(), [1360.0, 860.0]);
    kit::fit_tclab(&mut h, "P1D");
    let (fitted, _) = h.state().ident.fitted_transfer_function().expect("a fit");
    h.get_by_label("Frequency").click();
    h.run_steps(3);
    h.get_by_label("Identify: the fitted model G(s)").click();
    h.run_steps(3);
    assert_eq!(h.state().saved.frequency.source, SourceKind::Fitted);
    let shown = h.state().frequency.source.clone().expect("a source");
    assert_eq!(shown.plant, fitted);
    assert!(shown.controller.is_none());
    label_starting(&h, "Gain margin GM = ");
    h.get_by_label_contains(&format!("e^(−{}", Lang::En.num(fitted.delay(), 6)));
}

#[test]
fn the_bode_axis_is_written_in_decades_of_omega() {
    let h = frequency_app(Saved::default());
    let phase = h
        .get_by_role_and_label(egui::accesskit::Role::Canvas, "Bode phase")
        .rect();
    // The tick labels are painted just under the plot's frame.
    let below = egui::Rect::from_min_max(
        egui::pos2(phase.left(), phase.bottom()),
        egui::pos2(phase.right(), phase.bottom() + 14.0),
    );
    let ticks: Vec<f64> = kit::numbers_in(&h, below, '.')
        .into_iter()
        .map(|(v, _)| v)
        .collect();
    // The default system's corners are √5 and 5: two decades either side, 0.01 to 1000.
    assert!(ticks.len() >= 4, "{ticks:?}");
    for t in &ticks {
        let decade = t.log10();
        assert!(
            (decade - decade.round()).abs() < 1e-9,
            "{t} is not a decade: {ticks:?}"
        );
    }
    assert_eq!(ticks, vec![0.01, 0.1, 1.0, 10.0, 100.0, 1000.0]);
}
