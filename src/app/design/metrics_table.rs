//! The bottom strip: the metrics table (with B's column when comparing) and y(t) in closed
//! form. A metric that does not exist says why, in words (from [`crate::text::step`]).

use eframe::egui::{self, Ui};

use crate::app::look::Look;
use crate::lti::expr::OscillationForm;
use crate::text::design::Design as P;
use crate::text::step::{Metric, stability};

use super::analysis::Analysis;
use super::commands::Command;
use super::session::{Kept, Session};

/// The text of one cell: the value with its unit, or why it does not exist ("—" without a
/// response).
pub fn cell_text(analysis: &Analysis, metric: Metric, lang: crate::text::Lang) -> String {
    match &analysis.info {
        Some(info) => metric.cell(info, lang),
        None => "—".into(),
    }
}

/// Draws the strip; the closed form's toggle is its only command.
pub fn show(ui: &mut Ui, session: &Session, kept: &Kept, look: &Look) -> Vec<Command> {
    let lang = look.lang;
    let analysis = &session.analysis;
    let compare = session.compare(kept);
    let mut out = Vec::new();
    ui.horizontal_top(|ui| {
        egui::Grid::new("metrics")
            .striped(true)
            .num_columns(3)
            .show(ui, |ui| {
                ui.strong(P::MetricHeading.get(lang));
                ui.strong(P::CurrentColumn.get(lang));
                if let Some((name, _)) = compare {
                    ui.strong(format!("B: {}", super::presets::compare_name(name, lang)));
                }
                ui.end_row();
                for metric in Metric::ALL {
                    ui.label(metric.name(lang))
                        .on_hover_text(metric.definition(&analysis.options, lang));
                    ui.label(cell_text(analysis, metric, lang));
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
                ui.add(
                    egui::Label::new(egui::RichText::new(&text).monospace())
                        .wrap()
                        .selectable(true),
                );
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::design::state::System;
    use crate::lti::StepInfoOptions;
    use crate::text::Lang;

    #[test]
    fn cells_read_in_both_languages() {
        let a = Analysis::new(&System::default(), StepInfoOptions::default());
        let en = cell_text(&a, Metric::RiseTime, Lang::En);
        let pt = cell_text(&a, Metric::RiseTime, Lang::Pt);
        assert!(en.ends_with(" s") && en.contains('.'), "{en}");
        assert_eq!(pt, en.replace('.', ","));
    }
}
