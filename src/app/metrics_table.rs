//! The bottom strip: the metrics table (with B's column when comparing) and y(t) in closed
//! form. A metric that does not exist says why, in words.

use eframe::egui::{self, Ui};

use crate::app::analysis::Analysis;
use crate::app::step_plot::definitions;
use crate::lti::number::format_number;
use crate::lti::number::sig;
use crate::lti::{Behaviour, StepInfo};

/// One row: name, definition (hover), and how to read the value from a `StepInfo`.
struct Row {
    name: &'static str,
    definition: String,
    value: fn(&StepInfo) -> Option<f64>,
    unit: &'static str,
}

fn rows(analysis: &Analysis) -> Vec<Row> {
    let d = definitions(&analysis.options);
    vec![
        Row { name: "Rise time", definition: d[0].1.clone(), value: |i| i.rise_time, unit: "s" },
        Row { name: "Settling time", definition: d[2].1.clone(), value: |i| i.settling_time, unit: "s" },
        Row { name: "Overshoot", definition: d[1].1.clone(), value: |i| i.overshoot, unit: "%" },
        Row { name: "Undershoot", definition: d[4].1.clone(), value: |i| i.undershoot, unit: "%" },
        Row { name: "Peak", definition: d[1].1.clone(), value: |i| i.peak, unit: "" },
        Row { name: "Peak time", definition: d[1].1.clone(), value: |i| i.peak_time, unit: "s" },
        Row { name: "Steady state", definition: d[3].1.clone(), value: |i| i.steady_state, unit: "" },
        Row {
            name: "Settling min",
            definition: "The smallest y once the response has risen (from the end of the rise on).".into(),
            value: |i| i.settling_min,
            unit: "",
        },
        Row {
            name: "Settling max",
            definition: "The largest y once the response has risen (the final value counts as the limit it approaches).".into(),
            value: |i| i.settling_max,
            unit: "",
        },
    ]
}

/// The text of one cell: the value with its unit, or why it does not exist.
pub fn cell_text(
    info: Option<&StepInfo>,
    row_name: &str,
    value: Option<f64>,
    unit: &str,
) -> String {
    let Some(info) = info else {
        return "—".into();
    };
    match value {
        Some(v) if unit.is_empty() => sig(v, 5),
        Some(v) => format!("{} {unit}", sig(v, 5)),
        None if info.behaviour != Behaviour::Settles => {
            format!("none: {}", info.behaviour.describe())
        }
        None if row_name == "Peak time" => {
            "none: monotone, the peak is the final value (reached only as t tends to ∞)".into()
        }
        None => "none".into(),
    }
}

/// Draws the strip.
pub fn show(
    ui: &mut Ui,
    analysis: &Analysis,
    compare: Option<(&str, &Analysis)>,
    phase_form: &mut bool,
) {
    ui.horizontal_top(|ui| {
        egui::Grid::new("metrics")
            .striped(true)
            .num_columns(3)
            .show(ui, |ui| {
                ui.strong("Metric");
                ui.strong("A (current)");
                if let Some((name, _)) = compare {
                    ui.strong(format!("B: {name}"));
                }
                ui.end_row();
                for row in rows(analysis) {
                    ui.label(row.name).on_hover_text(&row.definition);
                    let a = analysis.info.as_ref();
                    ui.label(cell_text(a, row.name, a.and_then(row.value), row.unit));
                    if let Some((_, b)) = compare {
                        let bi = b.info.as_ref();
                        ui.label(cell_text(bi, row.name, bi.and_then(row.value), row.unit));
                    }
                    ui.end_row();
                }
            });
        ui.separator();
        ui.vertical(|ui| {
            ui.horizontal(|ui| {
                ui.strong("Closed form");
                ui.checkbox(phase_form, "amplitude–phase form");
            });
            let text = if *phase_form {
                &analysis.expression_phase
            } else {
                &analysis.expression
            };
            if text.is_empty() {
                ui.weak("no system");
            } else {
                ui.add(
                    egui::Label::new(egui::RichText::new(text).monospace())
                        .wrap()
                        .selectable(true),
                );
            }
            if let Ok(tf) = analysis.tf.as_ref() {
                let dc = tf.dc_gain();
                let stability = match tf.stability() {
                    crate::lti::tf::Stability::Stable => "stable",
                    crate::lti::tf::Stability::MarginallyStable => "marginally stable",
                    crate::lti::tf::Stability::Unstable => "unstable",
                };
                ui.label(format!(
                    "DC gain {} · {stability} · step amplitude {}",
                    if dc.is_finite() {
                        format_number(dc)
                    } else {
                        "∞".into()
                    },
                    format_number(analysis.system.amplitude)
                ));
            }
        });
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_metrics_say_why() {
        let info = StepInfo::not_settling(0.0, Behaviour::Integrating);
        assert_eq!(
            cell_text(Some(&info), "Rise time", None, "s"),
            "none: does not settle: it ramps (integrator)"
        );
        let mut settled = StepInfo::not_settling(0.0, Behaviour::Settles);
        settled.peak_time = None;
        assert!(cell_text(Some(&settled), "Peak time", None, "s").contains("monotone"));
        assert_eq!(
            cell_text(Some(&settled), "Rise time", Some(0.43944491546), "s"),
            "0.43944 s"
        );
    }
}
