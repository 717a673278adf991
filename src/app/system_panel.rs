//! The side panel: the system as numbers a student can type or drag (gain and what it
//! means, dead time, step amplitude, every pole and zero), presets, and the transfer
//! function as MATLAB would print it.

use eframe::egui::{self, DragValue, RichText, Ui};

use crate::app::analysis::Analysis;
use crate::app::presets::Preset;
use crate::app::state::{
    AMPLITUDE_LIMIT, DELAY_LIMIT, GAIN_LIMIT, GainMode, MAX_ROOTS, ROOT_LIMIT, Root, RootId,
    RootKind, RootRole, System,
};
use crate::lti::poly::format_poly;

/// What the panel asks the app to do beyond editing the system in place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PanelAction {
    None,
    LoadPreset(usize),
    CompareWithCurrent,
    StopComparing,
}

/// Draws the panel; edits `system` in place and returns a request for the app.
pub fn show(
    ui: &mut Ui,
    system: &mut System,
    selected: &mut Option<RootId>,
    analysis: &Analysis,
    presets: &[Preset],
    comparing: bool,
) -> PanelAction {
    let mut action = PanelAction::None;
    ui.heading("System");
    egui::ComboBox::from_label("Example")
        .selected_text("Load an example…")
        .show_ui(ui, |ui| {
            for (i, p) in presets.iter().enumerate() {
                if ui.selectable_label(false, p.name).clicked() {
                    action = PanelAction::LoadPreset(i);
                }
            }
        });
    ui.horizontal(|ui| {
        if !comparing
            && ui
                .button("Compare: keep this as B")
                .on_hover_text("Freeze the current system as B and overlay it while you edit.")
                .clicked()
        {
            action = PanelAction::CompareWithCurrent;
        }
        if comparing && ui.button("Stop comparing").clicked() {
            action = PanelAction::StopComparing;
        }
    });
    ui.separator();
    gain_delay_amplitude(ui, system);
    ui.separator();
    root_list(ui, system, selected, RootRole::Pole);
    ui.separator();
    root_list(ui, system, selected, RootRole::Zero);
    ui.separator();
    transfer_function(ui, analysis);
    action
}

fn gain_delay_amplitude(ui: &mut Ui, system: &mut System) {
    egui::Grid::new("system numbers")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("Gain means").on_hover_text(
            "k: the k of k·Π(s − z_i)/Π(s − p_j), as MATLAB's zpk. Static gain: G(0), the notes' \
             \"ganho estático\", kept fixed while you move roots.",
        );
            ui.horizontal(|ui| {
                ui.radio_value(&mut system.gain_mode, GainMode::Zpk, "k (zpk)");
                ui.radio_value(&mut system.gain_mode, GainMode::Static, "static G(0)");
            });
            ui.end_row();
            number_row(
                ui,
                "Gain",
                DragValue::new(&mut system.gain)
                    .speed(0.01)
                    .range(-GAIN_LIMIT..=GAIN_LIMIT)
                    .max_decimals(6),
            );
            number_row(
                ui,
                "Dead time θ (s)",
                DragValue::new(&mut system.delay)
                    .speed(0.01)
                    .range(0.0..=DELAY_LIMIT)
                    .max_decimals(6),
            );
            number_row(
                ui,
                "Step amplitude A",
                DragValue::new(&mut system.amplitude)
                    .speed(0.01)
                    .range(-AMPLITUDE_LIMIT..=AMPLITUDE_LIMIT)
                    .max_decimals(6),
            );
        });
}

/// A number typed in a field, read as the command line reads its numbers (− as a minus),
/// refused unless finite: "inf", "NaN" or "1e400" keep the field's value.
pub fn finite_number(text: &str) -> Option<f64> {
    crate::lti::parse::parse_real(text).ok()
}

/// A labelled number in a grid row (the label names the field for screen readers and tests).
fn number_row(ui: &mut Ui, label: &str, value: DragValue<'_>) {
    let name = ui.label(label);
    ui.add(value.custom_parser(finite_number))
        .labelled_by(name.id);
    ui.end_row();
}

fn root_list(ui: &mut Ui, system: &mut System, selected: &mut Option<RootId>, role: RootRole) {
    let title = match role {
        RootRole::Pole => "Poles",
        RootRole::Zero => "Zeros",
    };
    ui.horizontal(|ui| {
        ui.strong(title);
        let name = role.name();
        let room = system.has_room(role);
        let full = format!("At most {MAX_ROOTS} {name}s (real or pairs)");
        let add = |ui: &mut Ui, text: String| {
            ui.add_enabled(room, egui::Button::new(text).small())
                .on_disabled_hover_text(&full)
                .clicked()
        };
        if add(ui, format!("+ real {name}")) {
            let re = next_free_real(system.roots(role));
            *selected = Some(system.add(role, Root::real(re)));
        }
        if add(ui, format!("+ {name} pair")) {
            let re = next_free_real(system.roots(role));
            *selected = Some(system.add(role, Root::pair(re, 1.0)));
        }
    });
    if system.roots(role).is_empty() {
        ui.weak(match role {
            RootRole::Pole => "none: add at least one pole",
            RootRole::Zero => "none",
        });
    }
    let mut remove = None;
    let mut toggle = None;
    egui::Grid::new(("roots", role))
        .num_columns(5)
        .show(ui, |ui| {
            for index in 0..system.roots(role).len() {
                let id = RootId { role, index };
                let is_selected = *selected == Some(id);
                let name = ui.selectable_label(is_selected, format!("{} ", id.label()));
                if name.clicked() {
                    *selected = Some(id);
                }
                let Some(root) = system.root_mut(id) else {
                    continue;
                };
                ui.add(
                    DragValue::new(&mut root.re)
                        .speed(0.02)
                        .range(-ROOT_LIMIT..=ROOT_LIMIT)
                        .custom_parser(finite_number)
                        .max_decimals(6)
                        .prefix("σ "),
                )
                .labelled_by(name.id);
                if root.kind == RootKind::Pair {
                    ui.add(
                        DragValue::new(&mut root.im)
                            .speed(0.02)
                            .range(0.0..=ROOT_LIMIT)
                            .custom_parser(finite_number)
                            .max_decimals(6)
                            .prefix("± j"),
                    )
                    .labelled_by(name.id);
                } else {
                    ui.label("");
                }
                let toggle_text = if root.kind == RootKind::Pair {
                    "make real"
                } else {
                    "make pair"
                };
                if ui
                    .small_button(toggle_text)
                    .on_hover_text(
                        "Split a pair into two real roots, or make a real root a complex pair",
                    )
                    .clicked()
                {
                    toggle = Some(id);
                }
                if ui
                    .small_button("delete")
                    .on_hover_text(format!("Delete {}", id.label()))
                    .clicked()
                {
                    remove = Some(id);
                }
                ui.end_row();
            }
        });
    if let Some(id) = toggle {
        system.toggle_pair(id, 1.0);
    }
    if let Some(id) = remove {
        system.remove(id);
        *selected = None;
    }
}

/// A real part left of the existing roots, so a new root does not sit on another.
fn next_free_real(roots: &[Root]) -> f64 {
    let leftmost = roots.iter().map(|r| r.re).fold(0.0, f64::min);
    (leftmost - 1.0).floor()
}

fn transfer_function(ui: &mut Ui, analysis: &Analysis) {
    ui.strong("G(s)");
    match &analysis.tf {
        Ok(tf) => {
            let num = format_poly(&tf.num());
            let den = format_poly(&tf.den());
            let delay = if tf.delay() > 0.0 {
                format!(" · e^(−{} s)", tf.delay())
            } else {
                String::new()
            };
            ui.monospace(format!(
                "{num}\n{}\n{den}{delay}",
                "─".repeat(num.len().max(den.len()).min(40))
            ));
            let dc = tf.dc_gain();
            let dc_text = if dc.is_finite() {
                crate::lti::number::format_number(dc)
            } else {
                "∞ (integrator)".into()
            };
            ui.label(format!(
                "Order {} · relative degree {} · static gain G(0) = {dc_text}",
                tf.order(),
                tf.relative_degree()
            ));
        }
        Err(reason) => {
            ui.label(
                RichText::new(format!("No system: {reason}")).color(ui.visuals().error_fg_color),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::finite_number;

    #[test]
    fn only_finite_numbers_are_read() {
        assert_eq!(finite_number(" −1e3 "), Some(-1000.0));
        for bad in ["inf", "-inf", "NaN", "1e400", "", "abc"] {
            assert_eq!(finite_number(bad), None, "{bad}");
        }
    }
}
