//! "What the test got wrong" in the Identify mode, kept apart from the chain ("what the
//! model gets wrong"): each cause of the diagnosis's test with its name, evidence, what
//! Degrau did and the remedy, in the panel; on the output plot each cause's interval
//! shaded, the outliers marked as points and the clipped spans shaded, with an accessible
//! mark over each shaded span (its label says the cause and the interval). The words are
//! the text layer's ([`degrau_ident::words::test_causes`]), the same the CLI prints.

use eframe::egui::{self, Align2, Id, Rect, Sense, Ui};
use egui_plot::{MarkerShape, PlotPoint, PlotTransform, PlotUi, Points};

use crate::look::Look;
use degrau_ident::diagnose::test_causes::{TestCause, TestEvidence};
use degrau_ident::words::ident::Naming;
use degrau_ident::words::test_causes::{TestCausePhrase, cause_lines, span_words, test_cause_name};
use degrau_words::Localize;

use super::session::Session;

/// The causes of the test the diagnosis found (none before it ran).
fn causes(session: &Session) -> &[TestCause] {
    session
        .diagnosis
        .as_ref()
        .map_or(&[], |d| d.test_causes.as_slice())
}

/// The panel's section: its heading and each cause in words, or that none was found.
pub fn section(ui: &mut Ui, session: &Session, look: &Look) {
    let lang = look.lang;
    ui.heading(TestCausePhrase::Heading.get(lang));
    let causes = causes(session);
    if causes.is_empty() {
        ui.label(TestCausePhrase::NothingFound.get(lang));
    }
    for c in causes {
        let [name, evidence, done, remedy] = cause_lines(c, Naming::Words, lang);
        ui.strong(name);
        ui.label(evidence);
        ui.label(done);
        ui.label(remedy);
    }
}

/// The shaded spans of a cause on the output plot: its interval, and for a saturation each
/// clipped span.
fn spans(c: &TestCause) -> Vec<(f64, f64)> {
    match &c.evidence {
        TestEvidence::Saturation { spans, .. } => spans.clone(),
        _ => c.interval.into_iter().collect(),
    }
}

/// Draws every cause on the output plot: shaded spans labelled with the cause's name at
/// `top`, the outliers as crosses on the measured points.
pub fn shade(
    plot: &mut PlotUi<'_>,
    session: &Session,
    measured: &[[f64; 2]],
    top: f64,
    look: &Look,
) {
    let palette = &look.palette;
    for c in causes(session) {
        let clipped = matches!(c.evidence, TestEvidence::Saturation { .. });
        let fill = if clipped {
            palette.error
        } else {
            palette.warning
        }
        .gamma_multiply(0.18);
        for (a, b) in spans(c) {
            crate::plot_span::labelled_span(
                plot,
                test_cause_name(c.kind, Naming::Words, look.lang).to_string(),
                a..=b,
                fill,
                [a, top],
                Align2::LEFT_TOP,
                palette.warning,
            );
        }
        if let TestEvidence::Outliers { times, .. } = &c.evidence {
            let points: Vec<[f64; 2]> = times
                .iter()
                .filter_map(|&t| super::session::nearest_point(measured, t))
                .collect();
            plot.points(
                Points::new(test_cause_name(c.kind, Naming::Words, look.lang), points)
                    .color(palette.error)
                    .shape(MarkerShape::Cross)
                    .radius(5.0),
            );
        }
    }
}

/// An accessible mark over each shaded span, a strip at the plot's bottom, labelled
/// `not_at_rest: t = 0 … 248 s`.
pub fn marks(ui: &mut Ui, session: &Session, transform: &PlotTransform, look: &Look) {
    let frame: Rect = *transform.frame();
    let x = |t: f64| transform.position_from_point(&PlotPoint::new(t, 0.0)).x;
    for (k, c) in causes(session).iter().enumerate() {
        for (j, (a, b)) in spans(c).into_iter().enumerate() {
            let (left, right) = (x(a).max(frame.left()), x(b).min(frame.right()));
            if right <= left {
                continue;
            }
            let rect = Rect::from_x_y_ranges(left..=right, frame.bottom() - 16.0..=frame.bottom());
            let name = test_cause_name(c.kind, Naming::Words, look.lang);
            let label = format!("{name}: {}", span_words((a, b), look.lang));
            let response = ui.interact(rect, Id::unique(("test cause span", k, j)), Sense::hover());
            response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, &label));
            response.on_hover_text(c.evidence.text(look.lang));
        }
    }
}
