//! "What the test got wrong" in the Identify mode, through egui_kittest: the SBHS heater
//! record (a synthetic stand-in, see tests/data/records/SOURCES.md) is still rising before
//! its step; after the whole loop the panel names `not_at_rest` apart from the chain, with
//! its evidence, what Degrau did and the remedy, and its interval is shaded on the output
//! plot (an accessible mark over the span, at the span's times on the plot's axis).

use crate::kit;

use kit::{load, wait_for};

use degrau::app::DegrauApp;
use degrau::app::identify::plot::main_plot_id;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SBHS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/sbhs_step_not_at_rest_synthetic.txt"
);

/// The app with the SBHS record loaded as a student reads it: time from the sample column
/// (one a second), output the temperature, input the heater, start model P1.
fn sbhs_p1() -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size([1360.0, 860.0])
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), DegrauApp::default());
    h.run_steps(2);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    let settings = &mut h.state_mut().ident.settings;
    settings.time_col = "1".into();
    settings.y_col = "4".into();
    settings.u_col = "2".into();
    settings.code = "P1".into();
    settings.multistart = false;
    load(&mut h, SBHS);
    h
}

/// Steps until `done` holds, at most 3 min: the whole loop on 821 samples with an initial
/// transient takes about 15 s in the debug build, several times that on a busy machine
/// (the kit's `wait_for` gives up at 30 s). Not a timing assert: only a hang fails.
fn wait_long(h: &mut Harness<'_, DegrauApp>, done: impl Fn(&Harness<'_, DegrauApp>) -> bool) {
    let start = std::time::Instant::now();
    while !done(h) {
        assert!(start.elapsed().as_secs() < 180, "the loop never ended");
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    eprintln!("the loop took {:?}", start.elapsed());
    h.run_steps(2);
}

fn plot_x(h: &Harness<'_, DegrauApp>, t: f64) -> f32 {
    let memory = egui_plot::PlotMemory::load(&h.ctx, main_plot_id()).expect("the plot drew");
    memory
        .transform()
        .position_from_point(&egui_plot::PlotPoint::new(t, 0.0))
        .x
}

#[test]
fn the_sbhs_record_is_not_at_rest_and_its_interval_is_shaded() {
    let mut h = sbhs_p1();
    h.get_by_label_contains("Loaded 821 samples");
    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| !h.state().ident.is_fitting());
    h.get_by_label("Run the whole loop").click_accesskit();
    h.run_steps(1);
    wait_long(&mut h, |h| !h.state().ident.is_diagnosing());
    // The two questions stay apart.
    h.get_by_label("What does the model get wrong?");
    h.get_by_label("What the test got wrong");
    // Named in the student's words, not by the CLI's identifier (issue 23, item 9).
    h.get_by_label("Not at rest before the step");
    let ids: Vec<String> = h
        .query_all_by_label_contains("not_at_rest:")
        .filter_map(|n| n.value())
        .filter(|v| !v.contains("sbhs_step_not_at_rest"))
        .collect();
    assert!(ids.is_empty(), "{ids:?}");
    // In Portuguese the chain's causes are named in Portuguese too ("extra_pole:" before).
    h.state_mut().saved.lang = degrau::text::Lang::Pt;
    h.run_steps(2);
    let chain = h.state().ident.diagnosis.clone().expect("a chain");
    if chain
        .steps
        .iter()
        .any(|s| s.cause == degrau::ident::diagnose::Cause::ExtraPole)
    {
        h.get_by_label_contains("Polo a mais");
    }
    assert!(h.query_by_label_contains("extra_pole").is_none());
    h.state_mut().saved.lang = degrau::text::Lang::En;
    h.run_steps(2);
    h.get_by_label_contains("Before the first input change (t = 1 … 250 s, 250 samples)");
    h.get_by_label_contains("What Degrau did: Degrau estimated an initial transient");
    h.get_by_label_contains("What to do: Wait for steady state before the step");
    // The verdict's structure keeps no invented drift, offset or integrator.
    let d = h.state().ident.diagnosis.clone().expect("a diagnosis");
    assert!(
        !d.final_fit.model.structure.integrator,
        "{:?}",
        d.final_fit.model
    );
    assert!(
        !d.final_fit.model.structure.drift,
        "{:?}",
        d.final_fit.model
    );
    // The interval shaded on the output plot: its mark spans t = 1 … 250 s on the axis.
    let mark = h.get_by_label("Not at rest: t = 1 … 250 s");
    let rect = mark.rect();
    assert!((rect.left() - plot_x(&h, 1.0)).abs() < 1.5, "{rect:?}");
    assert!((rect.right() - plot_x(&h, 250.0)).abs() < 1.5, "{rect:?}");
    // The span's label is painted on the plot in the student's words, short (a sentence
    // per region ran over the others at the plot's top edge, issue 23, item 6).
    let painted: Vec<String> = kit::painted_texts(&h).into_iter().map(|p| p.0).collect();
    assert!(painted.iter().any(|t| t == "Not at rest"), "{painted:?}");
}

/// The measured curve's overshoot is read beyond what the noise explains (issue 23, item
/// 12): SBHS's heater does not overshoot, and its raw samples' 13.7 % (16.9 % with another
/// model) is said to be within the noise, the model shown or not.
#[test]
fn a_noisy_heater_has_no_measured_overshoot() {
    let mut h = sbhs_p1();
    h.get_by_label_contains("Loaded 821 samples");
    let painted = |h: &Harness<'static, DegrauApp>| -> Vec<String> {
        kit::painted_texts(h).into_iter().map(|p| p.0).collect()
    };
    let before = painted(&h);
    assert!(
        before
            .iter()
            .any(|t| t.starts_with("overshoot within the noise")),
        "{before:?}"
    );
    assert!(
        !before.iter().any(|t| t.starts_with("Overshoot ")),
        "{before:?}"
    );
    h.get_by_label("Fit").click();
    h.run_steps(1);
    wait_for(&mut h, |h| !h.state().ident.is_fitting());
    h.run_steps(2);
    let after = painted(&h);
    assert!(
        after
            .iter()
            .any(|t| t.starts_with("overshoot within the noise")),
        "{after:?}"
    );
}
