//! The app in a classroom, through egui_kittest: a small window (1000×650), a presentation
//! size for the projector, and Portuguese.

use crate::kit;

use degrau::app::{DegrauApp, Saved};
use degrau::text::Lang;
use degrau::text::app::App as T;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness(app: DegrauApp, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut DegrauApp| app.show(ui), app);
    h.run_steps(4);
    h
}

fn at_scale(scale: f32, size: [f32; 2]) -> Harness<'static, DegrauApp> {
    harness(
        DegrauApp::new(Saved {
            scale,
            ..Saved::default()
        }),
        size,
    )
}

/// The rect of the canvas named `name` (the s-plane and the step plot name themselves).
fn canvas(h: &Harness<'_, DegrauApp>, name: &str) -> egui::Rect {
    h.get_by_label(name).rect()
}

#[test]
fn at_1000_by_650_both_plots_are_visible_and_the_markers_bar_does_not_wrap_letters() {
    for scale in [1.0, 1.2] {
        let h = at_scale(scale, [1000.0, 650.0]);
        for name in ["s-plane", "step response"] {
            let r = canvas(&h, name);
            assert!(
                r.width() > 200.0 && r.height() > 200.0,
                "{name} at {scale}×: {r:?}"
            );
        }
        // A wrapped "Settling" would be several lines tall.
        let settling = h.get_by_label("Settling").rect();
        assert!(settling.height() < 30.0, "{settling:?}");
    }
}

/// The tick labels painted on the step plot: (x labels, y labels).
fn ticks(h: &Harness<'_, DegrauApp>, lang: Lang) -> (Vec<f64>, Vec<f64>) {
    let plot = canvas(h, lang.pick("step response", "resposta ao degrau"));
    let decimal = lang.decimal();
    let around = plot.expand(60.0);
    let numbers = kit::numbers_in(h, around, decimal);
    let x = numbers
        .iter()
        .filter(|(_, r)| r.center().y > plot.bottom() - 30.0)
        .map(|(v, _)| *v)
        .collect();
    let y = numbers
        .iter()
        .filter(|(_, r)| r.center().x < plot.left() + 60.0 && r.center().y < plot.bottom() - 30.0)
        .map(|(v, _)| *v)
        .collect();
    (x, y)
}

#[test]
fn the_step_plot_keeps_its_tick_labels_at_every_presentation_size() {
    // A window that holds the layout at 2× (a smaller one caps the size).
    for scale in [1.0, 1.2, 1.6, 2.0] {
        let h = at_scale(scale, [2000.0, 1300.0]);
        assert!((h.ctx.zoom_factor() - scale).abs() < 1e-3);
        let (x, y) = ticks(&h, Lang::En);
        assert!(x.len() >= 2, "x tick labels at {scale}×: {x:?}");
        assert!(y.len() >= 2, "y tick labels at {scale}×: {y:?}");
        // The default response runs from 0 to 0.04 and settles in about 4 s.
        assert!(y.iter().all(|v| (-0.01..=0.06).contains(v)), "{y:?}");
    }
}

#[test]
fn the_size_control_scales_and_is_remembered() {
    let mut h = at_scale(1.0, [2000.0, 1300.0]);
    h.get_by_label("A+").click();
    h.run_steps(3);
    h.get_by_label("A+").click();
    h.run_steps(3);
    let scale = h.state().saved.scale;
    assert!((scale - 1.4).abs() < 1e-4, "{scale}");
    assert!((h.ctx.zoom_factor() - 1.4).abs() < 1e-3);
    let json = serde_json::to_string(&h.state().saved).unwrap();
    let restored: Saved = serde_json::from_str(&json).unwrap();
    assert!((DegrauApp::new(restored).saved.scale - 1.4).abs() < 1e-4);
}

#[test]
fn in_portuguese_the_metrics_table_reads_in_portuguese() {
    let mut h = at_scale(1.0, [1360.0, 860.0]);
    h.get_by_label("Rise time");
    h.get_by_label("View").click();
    h.run_steps(2);
    h.get_by_label("Português").click();
    h.run_steps(3);
    assert_eq!(h.state().saved.lang, Lang::Pt);
    for name in [
        "Tempo de subida",
        "Tempo de acomodação",
        "Sobressinal",
        "Valor de pico",
    ] {
        h.get_by_label(name);
    }
    assert!(h.query_by_label("Rise time").is_none());
    // Numbers take the decimal comma, in the table and on the plot's axes.
    h.get_by_label("Polos");
    let (_, y) = ticks(&h, Lang::Pt);
    assert!(y.len() >= 2, "{y:?}");
    // ... and in G(s)'s coefficient fields, written again in the new language.
    assert_eq!(h.get_by_label("num").value().as_deref(), Some("0,5"));
}

const TCLAB: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/records/tclab_step_q1_50_synthetic.csv"
);

/// The window sizes of issue 23 (a small laptop, a projector), in pixels.
const SIZES: [[f32; 2]; 2] = [[1000.0, 650.0], [1600.0, 900.0]];
/// The presentation sizes the layout is checked at.
const ZOOMS: [f32; 3] = [1.0, 1.3, 1.6];
/// Roles whose node shows words (a label, a button's, a field's).
const TEXT_ROLES: [egui::accesskit::Role; 8] = {
    use egui::accesskit::Role::*;
    [
        Label,
        Button,
        CheckBox,
        RadioButton,
        ComboBox,
        TextInput,
        DisclosureTriangle,
        Link,
    ]
};

/// One widget as laid out: its role, what it says, its rect cut by the scroll areas around
/// it (`None`: scrolled out of sight).
struct Placed {
    role: egui::accesskit::Role,
    name: String,
    rect: egui::Rect,
    shown: Option<egui::Rect>,
}

/// Every widget with a rect, with what a scroll area around it hides cut off (a container's
/// scroll bars give its viewport).
fn placed(h: &Harness<'_, DegrauApp>) -> Vec<Placed> {
    use egui_kittest::kittest::NodeT;
    fn bounds(node: &egui_kittest::Node<'_>) -> Option<egui::Rect> {
        node.accesskit_node().bounding_box()?;
        Some(node.rect())
    }
    /// `clip` cut to the viewport of the scroll bars that follow a scroll area's content.
    fn viewport(bars: &[egui_kittest::Node<'_>], clip: egui::Rect) -> egui::Rect {
        let mut clip = clip;
        for r in bars.iter().filter_map(bounds) {
            if r.height() > r.width() {
                clip.set_top(clip.top().max(r.top()));
                clip.set_bottom(clip.bottom().min(r.bottom()));
            } else {
                clip.set_left(clip.left().max(r.left()));
                clip.set_right(clip.right().min(r.right()));
            }
        }
        clip
    }
    fn walk(node: egui_kittest::Node<'_>, clip: egui::Rect, out: &mut Vec<Placed>) {
        let children: Vec<_> = node.children().collect();
        let is_bar = |n: &egui_kittest::Node<'_>| {
            n.accesskit_node().role() == egui::accesskit::Role::ScrollBar
        };
        for (i, child) in children.iter().enumerate() {
            // A scroll area's bars are the siblings right after its content.
            let bars: Vec<_> = children[i + 1..]
                .iter()
                .take_while(|n| is_bar(n))
                .cloned()
                .collect();
            let clip = if is_bar(child) {
                clip
            } else {
                viewport(&bars, clip)
            };
            let a = child.accesskit_node();
            if let Some(rect) = bounds(child)
                && a.role() != egui::accesskit::Role::TextRun
            {
                let name = a.label().or_else(|| a.value()).unwrap_or_else(|| {
                    child
                        .children()
                        .filter_map(|c| c.accesskit_node().value())
                        .collect::<Vec<_>>()
                        .join(" ")
                });
                let shown = rect.intersect(clip);
                out.push(Placed {
                    role: a.role(),
                    name,
                    rect,
                    shown: shown.is_positive().then_some(shown),
                });
            }
            walk(*child, clip, out);
        }
    }
    let mut out = Vec::new();
    walk(h.root(), egui::Rect::EVERYTHING, &mut out);
    out
}

/// What is wrong with the layout now, one line each.
fn layout_problems(h: &Harness<'_, DegrauApp>) -> Vec<String> {
    let window = h.ctx.content_rect().expand(0.5);
    let all = placed(h);
    let mut problems = Vec::new();
    // A splitter is the invisible strip that resizes a panel.
    for w in all
        .iter()
        .filter(|w| w.role != egui::accesskit::Role::Splitter)
    {
        if let Some(r) = w.shown
            && !window.contains_rect(r)
        {
            problems.push(format!(
                "{:?} {:?} at {r:?} is outside the window {window:?}",
                w.role, w.name
            ));
        }
    }
    // The handles on a canvas (an s-plane's poles) are markers, not text: an open-loop pole
    // under its closed-loop one is the plot's business.
    let canvases: Vec<egui::Rect> = all
        .iter()
        .filter(|w| w.role == egui::accesskit::Role::Canvas)
        .map(|w| w.rect)
        .collect();
    let texts: Vec<&Placed> = all
        .iter()
        .filter(|w| TEXT_ROLES.contains(&w.role) && w.shown.is_some())
        .filter(|w| !canvases.iter().any(|c| c.contains(w.rect.center())))
        .collect();
    for (i, a) in texts.iter().enumerate() {
        for b in &texts[i + 1..] {
            let (ra, rb) = (a.shown.unwrap_or(a.rect), b.shown.unwrap_or(b.rect));
            let cut = ra.intersect(rb);
            let nested = ra.expand(0.5).contains_rect(rb) || rb.expand(0.5).contains_rect(ra);
            if cut.width() > 1.0 && cut.height() > 1.0 && !nested {
                problems.push(format!(
                    "{:?} {:?} at {ra:?} overlaps {:?} {:?} at {rb:?}",
                    a.role, a.name, b.role, b.name
                ));
            }
        }
    }
    problems.extend(words_on_plots(h, &canvases));
    for plot in all
        .iter()
        .filter(|w| w.role == egui::accesskit::Role::Canvas)
    {
        let r = plot.shown.unwrap_or(egui::Rect::NOTHING);
        if !(r.width() >= 220.0 && r.height() >= 220.0) {
            problems.push(format!(
                "the plot {:?} is shown at {:?} (under 220 points)",
                plot.name, plot.shown
            ));
        }
    }
    problems
}

/// The texts painted on a plot (captions, status, marker labels, the s-plane's ticks): each
/// whole inside what it is clipped to, none over another.
fn words_on_plots(h: &Harness<'_, DegrauApp>, canvases: &[egui::Rect]) -> Vec<String> {
    fn walk(
        shape: &egui::Shape,
        clip: egui::Rect,
        out: &mut Vec<(String, egui::Rect, egui::Rect)>,
    ) {
        match shape {
            egui::Shape::Text(t) if !t.galley.text().trim().is_empty() => out.push((
                t.galley.text().to_string(),
                t.galley.rect.translate(t.pos.to_vec2()),
                clip,
            )),
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(s, clip, out)),
            _ => {}
        }
    }
    let mut texts = Vec::new();
    for c in &h.output().shapes {
        walk(&c.shape, c.clip_rect, &mut texts);
    }
    let on_plot = |r: &egui::Rect| canvases.iter().position(|c| c.contains(r.center()));
    let texts: Vec<_> = texts
        .into_iter()
        .filter_map(|(t, r, clip)| on_plot(&r).map(|k| (t, r, clip, k)))
        .collect();
    let mut problems = Vec::new();
    for (t, r, clip, _) in &texts {
        if !clip.expand(1.0).contains_rect(*r) {
            problems.push(format!(
                "the text {t:?} on a plot at {r:?} is cut by its edge {clip:?}"
            ));
        }
    }
    for (i, (ta, ra, _, ka)) in texts.iter().enumerate() {
        for (tb, rb, _, kb) in &texts[i + 1..] {
            let cut = ra.intersect(*rb);
            if ka == kb && cut.width() > 1.0 && cut.height() > 1.0 {
                problems.push(format!(
                    "on a plot, {ta:?} at {ra:?} is over {tb:?} at {rb:?}"
                ));
            }
        }
    }
    problems
}

/// Shows `h` as a window of `size` pixels at the presentation size `zoom` in `lang`: the
/// harness takes its size in points, so it is given the pixels over the zoom drawn at, until
/// the zoom (capped by the window) holds still.
fn present(h: &mut Harness<'_, DegrauApp>, size: [f32; 2], zoom: f32, lang: Lang) {
    h.state_mut().saved.scale = zoom;
    h.state_mut().saved.lang = lang;
    for _ in 0..4 {
        let drawn = h.ctx.zoom_factor();
        h.set_size(egui::vec2(size[0], size[1]) / drawn);
        h.run_steps(3);
    }
    let window = h.ctx.content_rect().size() * h.ctx.zoom_factor();
    assert!(
        (window - egui::vec2(size[0], size[1])).length() < 2.0,
        "the harness shows a window of {window:?} pixels for {size:?} at {zoom}×"
    );
}

/// The problems of `h`'s mode at every size, zoom and language, each line saying where.
pub(crate) fn problems_everywhere(
    h: &mut Harness<'_, DegrauApp>,
    mode: &str,
    canvases: usize,
) -> Vec<String> {
    problems_everywhere_with(h, mode, canvases, |_, _| Vec::new())
}

/// The labels of `names` not drawn whole inside the window, each as a problem.
pub(crate) fn not_on_screen(h: &Harness<'_, DegrauApp>, names: &[String]) -> Vec<String> {
    let window = h.ctx.content_rect().expand(0.5);
    names
        .iter()
        .filter(|name| {
            !h.query_all_by_label(name)
                .any(|n| window.contains_rect(n.rect()))
        })
        .map(|name| format!("{name:?} is not on screen"))
        .collect()
}

/// Fails with every layout problem listed.
pub(crate) fn assert_no_problems(problems: &[String]) {
    assert!(
        problems.is_empty(),
        "{} layout problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// [`problems_everywhere`] with the mode's own checks (`more`: its problems in a language).
pub(crate) fn problems_everywhere_with(
    h: &mut Harness<'_, DegrauApp>,
    mode: &str,
    canvases: usize,
    more: impl Fn(&Harness<'_, DegrauApp>, Lang) -> Vec<String>,
) -> Vec<String> {
    let mut out = Vec::new();
    for size in SIZES {
        for zoom in ZOOMS {
            for lang in Lang::ALL {
                present(h, size, zoom, lang);
                let window = h.ctx.content_rect().size();
                let at = format!(
                    "{mode}, {}×{} at {zoom}× (drawn at {:.2}×, {:.0}×{:.0} points), {}",
                    size[0],
                    size[1],
                    h.ctx.zoom_factor(),
                    window.x,
                    window.y,
                    lang.name()
                );
                let mut problems = layout_problems(h);
                problems.extend(more(h, lang));
                let plots = h.query_all_by_role(egui::accesskit::Role::Canvas).count();
                if plots < canvases {
                    problems.push(format!(
                        "{plots} plots name themselves, {canvases} expected"
                    ));
                }
                for name in [T::View.get(lang), T::Language.get(lang)] {
                    let shown = placed(h).into_iter().any(|w| {
                        w.name == name
                            && w.shown
                                .is_some_and(|r| h.ctx.content_rect().expand(0.5).contains_rect(r))
                    });
                    if !shown {
                        problems.push(format!("the menu bar's {name:?} cannot be reached"));
                    }
                }
                out.extend(problems.into_iter().map(|p| format!("{at}: {p}")));
            }
        }
    }
    out
}

/// Design with the loop closed, Skogestad's approximation and every method compared.
fn design_with_every_panel() -> Harness<'static, DegrauApp> {
    let mut saved = Saved::default();
    saved.design.feedback.closed = true;
    let mut h = harness(DegrauApp::new(saved), [1600.0, 900.0]);
    h.get_by_label("Skogestad").click_accesskit();
    h.run_steps(3);
    h.get_by_label("Compare every method").click_accesskit();
    h.run_steps(3);
    assert!(
        h.state().design.approx.table.is_some(),
        "the table of every method"
    );
    h
}

/// Identify with the TCLab record fitted and diagnosed (the chain table shown).
fn identify_with_a_diagnosis() -> Harness<'static, DegrauApp> {
    let mut h = harness(DegrauApp::default(), [1600.0, 900.0]);
    h.get_by_label("Identify a step test").click();
    h.run_steps(2);
    let settings = &mut h.state_mut().ident.settings;
    settings.y_col = "T1".into();
    settings.u_col = "Q1".into();
    settings.code = "P1".into();
    kit::load(&mut h, TCLAB);
    h.get_by_label("Fit").click_accesskit();
    h.run_steps(1);
    kit::wait_for(&mut h, |h| h.query_by_label("Fitted P1").is_some());
    h.get_by_label("Run the whole loop").click_accesskit();
    h.run_steps(1);
    kit::wait_for(&mut h, |h| !h.state().ident.is_diagnosing());
    assert!(h.state().ident.diagnosis.is_some(), "a diagnosis to show");
    h
}

/// Issue 23's layout: at 1000×650 and 1600×900, at 1×, 1.3× and 1.6×, in both languages,
/// with every panel of each mode open: no widget outside the window, no two texts over one
/// another (a label inside its own button is fine), every plot at least 220 points each
/// way, and the View menu and the language selector on screen.
///
/// What cannot fit degrades: a size the window cannot hold is drawn at the largest it does
/// (1000×650 stays at 1×, 1600×900 at 1.6× is drawn at 1.38×: the messages say "drawn at");
/// with an approximation shown in a window under 760 points tall the metrics table folds
/// into the approximation's words; the step plot's controls scroll sideways. Markers and
/// legend entries on a plot are checked as painted words, not as widgets; the Identify
/// mode's input and residual strips are not held to 220 points (its main plot is).
#[test]
fn every_mode_fits_every_classroom_size() {
    let mut problems = Vec::new();
    let mut design = design_with_every_panel();
    problems.extend(problems_everywhere(&mut design, "Design", 4));
    // An unstable system says so on the step plot, whole.
    let mut saved = Saved::default();
    saved.design.system.poles[0].re = 1.0;
    let mut unstable = harness(DegrauApp::new(saved), [1600.0, 900.0]);
    assert!(unstable.state().system().has_rhp_pole());
    problems.extend(problems_everywhere(&mut unstable, "Design, unstable", 2));
    let mut identify = identify_with_a_diagnosis();
    problems.extend(problems_everywhere(&mut identify, "Identify", 1));
    identify.state_mut().saved.mode = degrau::app::Mode::LeastSquares;
    problems.extend(problems_everywhere(&mut identify, "Least squares", 1));
    assert_no_problems(&problems);
}
/// At 1000×650 the step plot's controls are one line scrolled sideways: its scroll bar must
/// not take the clicks on the line (it took the lower half of each toggle).
#[test]
fn the_one_line_markers_bar_takes_a_click_at_1000_by_650() {
    let mut h = at_scale(1.0, [1000.0, 650.0]);
    let before = h.state().saved.design.markers.rise;
    h.get_by_label("Rise").click();
    h.run_steps(2);
    assert_ne!(
        h.state().saved.design.markers.rise,
        before,
        "the Rise toggle took the click"
    );
}

/// In Portuguese every number painted on a plot takes the decimal comma: the Identify
/// mode's three plots as well as the step plot (their ticks read "0.5" before; the
/// least-squares plots share the same axes, `grid::app_axes`).
#[test]
fn in_portuguese_no_plot_paints_a_decimal_point() {
    // A small output (0 to 0.04): every plot's ticks have decimals.
    let dir = std::env::temp_dir().join(format!("degrau-classroom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("small.csv");
    let mut text = String::from("t,u,y\n");
    for k in 0..200 {
        let t = 0.1 * k as f64;
        let (u, y) = if t < 2.0 {
            (0.0, 0.0)
        } else {
            (1.0, 0.04 * (1.0 - (-(t - 2.0) / 3.0).exp()))
        };
        text.push_str(&format!("{t},{u},{y}\n"));
    }
    std::fs::write(&file, text).expect("write");
    let mode = degrau::app::Mode::Identify;
    let app = DegrauApp::new(Saved {
        mode,
        lang: Lang::Pt,
        ident: degrau::app::identify::Saved {
            path: file.display().to_string(),
            time_col: "t".into(),
            y_col: "y".into(),
            u_col: "u".into(),
            ..Default::default()
        },
        ..Saved::default()
    });
    let h = harness(app, [1600.0, 900.0]);
    let pointed: Vec<String> = kit::painted_texts(&h)
        .into_iter()
        .map(|(t, _)| t.trim().replace('\u{2212}', "-"))
        .filter(|t| t.contains('.') && t.parse::<f64>().is_ok())
        .collect();
    assert!(pointed.is_empty(), "{mode:?}: {pointed:?}");
    let commas = kit::painted_texts(&h)
        .into_iter()
        .filter(|(t, _)| t.trim().replace(',', ".").parse::<f64>().is_ok() && t.contains(','))
        .count();
    assert!(commas > 0, "{mode:?}: no decimal tick at all");
    std::fs::remove_dir_all(&dir).ok();
}
