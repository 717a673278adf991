//! The bottom strip: the metrics table (with B's column when comparing) and y(t) in closed
//! form. A metric that does not exist says why, in words (from [`degrau_lti::words::step`]).

use eframe::egui::{self, Ui};

use crate::look::Look;
use crate::words::design::Design as P;
use degrau_lti::expr::OscillationForm;
use degrau_lti::words::step::{Metric, stability};

use super::analysis::Analysis;
use super::commands::Command;
use super::session::{Saved, Session};

/// The text of one cell: the value with its unit, or why it does not exist ("—" without a
/// response).
pub fn cell_text(analysis: &Analysis, metric: Metric, lang: degrau_words::Lang) -> String {
    match &analysis.info {
        Some(info) => metric.cell(info, lang),
        None => "—".into(),
    }
}

/// Draws the strip; the closed form's toggle is its only command.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let analysis = &session.analysis;
    let compare = session.compare(kept);
    // With the loop closed, the closed loop is described beside the open loop: a table and
    // a closed form of the open loop alone said "it ramps" beside a curve that settles.
    let closed = closed_loop(session, kept, lang);
    let mut out = Vec::new();
    ui.horizontal_top(|ui| {
        egui::Grid::new("metrics")
            .striped(true)
            .num_columns(4)
            .show(ui, |ui| {
                ui.strong(P::MetricHeading.get(lang));
                ui.strong(P::CurrentColumn.get(lang));
                if let Some((name, _)) = &closed {
                    ui.strong(name);
                }
                if let Some((name, _)) = compare {
                    ui.strong(format!("B: {}", super::presets::compare_name(name, lang)));
                }
                ui.end_row();
                for metric in Metric::ALL {
                    ui.label(metric.name(lang))
                        .on_hover_text(metric.definition(&analysis.options, lang));
                    ui.label(cell_text(analysis, metric, lang));
                    if let Some((_, c)) = &closed {
                        ui.label(cell_text(c, metric, lang));
                    }
                    if let Some((_, b)) = compare {
                        ui.label(cell_text(b, metric, lang));
                    }
                    ui.end_row();
                }
            });
        ui.separator();
        ui.vertical(|ui| {
            ui.horizontal_wrapped(|ui| {
                ui.strong(P::ClosedForm.get(lang));
                let mut phase = kept.phase_form;
                if ui.checkbox(&mut phase, P::PhaseForm.get(lang)).changed() {
                    out.push(Command::SetPhaseForm(phase));
                }
            });
            let form = if kept.phase_form {
                OscillationForm::AmplitudePhase
            } else {
                OscillationForm::CosSin
            };
            let text = analysis.expression(form, lang);
            if text.is_empty() {
                ui.weak(P::NoSystemShort.get(lang));
            } else {
                closed_form(
                    ui,
                    &text,
                    closed.as_ref().map(|_| P::CurrentColumn.get(lang)),
                );
            }
            if let Some((name, c)) = &closed {
                let text = c.expression(form, lang);
                if !text.is_empty() {
                    closed_form(ui, &text, Some(name));
                }
            }
            if let Ok(tf) = analysis.tf.as_ref() {
                let dc = tf.dc_gain();
                ui.add(
                    egui::Label::new(format!(
                        "{} {} · {} · {} {}",
                        P::DcGain.get(lang),
                        if dc.is_finite() {
                            lang.num(dc, 6)
                        } else {
                            "∞".into()
                        },
                        stability(tf.stability(), lang),
                        P::StepAmplitudeLower.get(lang),
                        lang.num(analysis.system.amplitude, 6)
                    ))
                    .wrap(),
                );
            }
        });
    });
    out
}

/// The closed loop's name and analysis, when the loop is closed and has one.
fn closed_loop<'a>(
    session: &'a Session,
    kept: &Saved,
    lang: degrau_words::Lang,
) -> Option<(String, &'a Analysis)> {
    let c = session
        .feedback
        .closed
        .as_ref()
        .filter(|_| kept.feedback.closed)?;
    let approximate = session.feedback.approximant.is_some();
    let name = degrau_lti::words::feedback::Loop::closed_loop_curve(approximate).get(lang);
    Some((name.to_string(), c))
}

/// One closed form, selectable, after its name when there are two.
fn closed_form(ui: &mut Ui, text: &str, name: Option<&str>) {
    let text = match name {
        Some(name) => format!("{name}: {text}"),
        None => text.to_string(),
    };
    ui.add(
        egui::Label::new(egui::RichText::new(text).monospace())
            .wrap()
            .selectable(true),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::state::System;
    use degrau_lti::StepInfoOptions;
    use degrau_words::Lang;

    #[test]
    fn cells_read_in_both_languages() {
        let a = Analysis::new(&System::default(), StepInfoOptions::default());
        let en = cell_text(&a, Metric::RiseTime, Lang::En);
        let pt = cell_text(&a, Metric::RiseTime, Lang::Pt);
        assert!(en.ends_with(" s") && en.contains('.'), "{en}");
        assert_eq!(pt, en.replace('.', ","));
    }
}
