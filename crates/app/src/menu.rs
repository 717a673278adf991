//! The top level's own views: the menu bar (modes, File, Edit, View, the presentation size
//! and the language), the keys that act on every mode (undo, redo) and the notices. Each
//! reads the app and returns [`Command`]s, applied by [`DegrauApp`]'s `apply`.

use eframe::egui::{self, Key, KeyboardShortcut, Modifiers, RichText, Ui};

use crate::design::{self, state::System};
use crate::look::{Look, SCALE_RANGE};
use crate::words::app::{App as T, CodeKind};
use crate::{Command, DegrauApp, Mode};
use degrau_words::{Lang, Localize};

const UNDO: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
const REDO: KeyboardShortcut =
    KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z);
const REDO_Y: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);
/// How long a confirmation stays in the menu bar (s).
const CONFIRMATION_SECONDS: f64 = 4.0;
/// The presentation sizes the menu offers.
const SCALES: [f32; 6] = [1.0, 1.2, 1.4, 1.6, 1.8, 2.0];

impl DegrauApp {
    /// Undo and redo (both modes' menus and keys act on the design system), then the
    /// Design mode's own keys.
    pub(crate) fn keyboard(&mut self, ui: &mut Ui) -> Vec<Command> {
        // Ctrl+Z matches Ctrl+Shift+Z too in egui's logical matching: consume redo first.
        let redo = ui.input_mut(|i| i.consume_shortcut(&REDO) || i.consume_shortcut(&REDO_Y));
        let undo = ui.input_mut(|i| i.consume_shortcut(&UNDO));
        let mut out = Vec::new();
        if redo {
            out.push(Command::Design(design::Command::Redo));
        } else if undo {
            out.push(Command::Design(design::Command::Undo));
        }
        if self.saved.mode == Mode::Design {
            out.extend(
                design::keyboard(ui, &self.saved.design)
                    .into_iter()
                    .map(Command::Design),
            );
        }
        out
    }

    pub(crate) fn menu_bar(&self, ui: &mut Ui, look: &Look) -> Vec<Command> {
        let lang = look.lang;
        let mut out = Vec::new();
        let history = &self.design.history;
        let kept = &self.saved.design;
        egui::MenuBar::new().ui(ui, |ui| {
            let mut mode = self.saved.mode;
            // Five modes and the rest of the bar in a 1000-point window in Portuguese: the
            // tabs sit a little closer than egui's spacing.
            let spacing = ui.spacing().item_spacing.x;
            ui.spacing_mut().item_spacing.x = spacing / 2.0;
            ui.selectable_value(&mut mode, Mode::Design, T::ModeDesign.get(lang));
            ui.selectable_value(&mut mode, Mode::Identify, T::ModeIdentify.get(lang));
            ui.selectable_value(
                &mut mode,
                Mode::LeastSquares,
                crate::words::lsq_app::Phrase::ModeName.get(lang),
            );
            ui.selectable_value(
                &mut mode,
                Mode::Tune,
                crate::words::tune::Tune::ModeName.get(lang),
            );
            ui.selectable_value(
                &mut mode,
                Mode::Frequency,
                crate::words::frequency::Frequency::ModeName.get(lang),
            );
            ui.selectable_value(
                &mut mode,
                Mode::Exercises,
                crate::words::exercises::Exercises::ModeName.get(lang),
            );
            if mode != self.saved.mode {
                out.push(Command::SetMode(mode));
            }
            ui.spacing_mut().item_spacing.x = spacing;
            ui.separator();
            ui.menu_button(T::File.get(lang), |ui| {
                let mut item = |ui: &mut Ui, text: T, enabled: bool, command: Command| {
                    if ui
                        .add_enabled(enabled, egui::Button::new(text.get(lang)))
                        .clicked()
                    {
                        out.push(command);
                        ui.close();
                    }
                };
                item(ui, T::OpenTest, true, Command::OpenTestFile);
                item(
                    ui,
                    T::Export,
                    true,
                    Command::Export(crate::export::Command::Open),
                );
                let has_tf = self.design.analysis.tf.is_ok();
                item(
                    ui,
                    T::CopyMatlab,
                    has_tf,
                    Command::CopyCode(CodeKind::Matlab),
                );
                item(
                    ui,
                    T::CopyPython,
                    has_tf,
                    Command::CopyCode(CodeKind::PythonControl),
                );
                item(
                    ui,
                    T::Reset,
                    true,
                    Command::Design(design::Command::SetSystem(System::default())),
                );
            });
            ui.menu_button(T::Edit.get(lang), |ui| {
                let undo = egui::Button::new(T::Undo.get(lang))
                    .shortcut_text(ui.ctx().format_shortcut(&UNDO));
                if ui.add_enabled(history.can_undo(), undo).clicked() {
                    out.push(Command::Design(design::Command::Undo));
                    ui.close();
                }
                let redo = egui::Button::new(T::Redo.get(lang))
                    .shortcut_text(ui.ctx().format_shortcut(&REDO));
                if ui.add_enabled(history.can_redo(), redo).clicked() {
                    out.push(Command::Design(design::Command::Redo));
                    ui.close();
                }
                let delete = egui::Button::new(T::DeleteSelected.get(lang))
                    .shortcut_text(T::DeleteKey.get(lang));
                if let Some(id) = kept.splane.selected
                    && ui.add(delete).clicked()
                {
                    out.push(Command::Design(design::Command::RemoveRoot(id)));
                    ui.close();
                }
            });
            ui.menu_button(T::View.get(lang), |ui| {
                let mut dark = self.saved.dark;
                if ui.checkbox(&mut dark, T::DarkTheme.get(lang)).changed() {
                    out.push(Command::SetDark(dark));
                }
                let mut grid = kept.splane.damping_grid;
                if ui.checkbox(&mut grid, T::DampingLines.get(lang)).changed() {
                    out.push(Command::Design(design::Command::SetDampingGrid(grid)));
                }
                let mut snap = kept.splane.snap;
                if ui.checkbox(&mut snap, T::SnapRoots.get(lang)).changed() {
                    out.push(Command::Design(design::Command::SetSnap(snap)));
                }
                if ui.button(T::FitSPlane.get(lang)).clicked() {
                    out.push(Command::Design(design::Command::SetView(None)));
                    ui.close();
                }
                ui.separator();
                ui.label(T::PresentationSize.get(lang));
                for scale in SCALES {
                    let text = format!("{}×", lang.num(scale as f64, 2));
                    let on = (self.saved.scale - scale).abs() < 0.05;
                    if ui.selectable_label(on, text).clicked() {
                        out.push(Command::SetScale(scale));
                        ui.close();
                    }
                }
                ui.separator();
                ui.label(T::Language.get(lang));
                for l in Lang::ALL {
                    if ui.selectable_label(l == lang, l.name()).clicked() {
                        out.push(Command::SetLang(l));
                        ui.close();
                    }
                }
            });
            if ui
                .add_enabled(history.can_undo(), egui::Button::new(T::Undo.get(lang)))
                .clicked()
            {
                out.push(Command::Design(design::Command::Undo));
            }
            if ui
                .add_enabled(history.can_redo(), egui::Button::new(T::Redo.get(lang)))
                .clicked()
            {
                out.push(Command::Design(design::Command::Redo));
            }
            ui.separator();
            out.extend(self.size_and_language(ui, look));
            if let Some((text, _)) = self.confirmation_now(ui.ctx()) {
                ui.label(RichText::new(text.get(lang)).color(look.palette.main));
            }
        });
        out
    }

    /// The visible presentation-size control (A− size A+) and the language switch.
    fn size_and_language(&self, ui: &mut Ui, look: &Look) -> Vec<Command> {
        let lang = look.lang;
        let mut out = Vec::new();
        let scale = self.saved.scale;
        let step = 0.2;
        if ui
            .add_enabled(scale > *SCALE_RANGE.start() + 1e-3, egui::Button::new("A−"))
            .on_hover_text(T::Smaller.get(lang))
            .clicked()
        {
            out.push(Command::SetScale(scale - step));
        }
        // The size drawn at: less than the one asked for when the window is too small.
        let capped = self.zoom_set < scale - 1e-3;
        let hint = if capped {
            T::SizeCapped
        } else {
            T::PresentationSize
        };
        ui.label(format!("{}×", lang.num(self.zoom_set as f64, 2)))
            .on_hover_text(hint.get(lang));
        if ui
            .add_enabled(scale < *SCALE_RANGE.end() - 1e-3, egui::Button::new("A+"))
            .on_hover_text(T::Larger.get(lang))
            .clicked()
        {
            out.push(Command::SetScale(scale + step));
        }
        // As wide as the longest language's name, not egui's 100 points.
        let name_width = Lang::ALL
            .iter()
            .map(|l| {
                ui.painter()
                    .layout_no_wrap(
                        l.name().to_string(),
                        egui::TextStyle::Button.resolve(ui.style()),
                        egui::Color32::PLACEHOLDER,
                    )
                    .size()
                    .x
            })
            .fold(0.0, f32::max);
        egui::ComboBox::from_id_salt("language")
            .width(name_width + ui.spacing().icon_width + ui.spacing().button_padding.x * 2.0)
            .selected_text(lang.name())
            .show_ui(ui, |ui| {
                for l in Lang::ALL {
                    if ui.selectable_label(l == lang, l.name()).clicked() {
                        out.push(Command::SetLang(l));
                    }
                }
            })
            .response
            .on_hover_text(T::Language.get(lang));
        out
    }

    /// The confirmation to show now, if one was given in the last few seconds.
    fn confirmation_now(&self, ctx: &egui::Context) -> Option<(T, f64)> {
        let (text, when) = self.confirmation?;
        let left = CONFIRMATION_SECONDS - (ctx.input(|i| i.time) - when);
        if left > 0.0 {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(left));
            Some((text, when))
        } else {
            None
        }
    }

    /// The notices, each with a button to dismiss it.
    pub(crate) fn show_notices(&self, ui: &mut Ui, look: &Look) -> Vec<Command> {
        let mut out = Vec::new();
        for (i, notice) in self.notices.iter().enumerate() {
            ui.horizontal_wrapped(|ui| {
                if ui.button(T::Dismiss.get(look.lang)).clicked() {
                    out.push(Command::Dismiss(i));
                }
                ui.add(
                    egui::Label::new(
                        RichText::new(notice.text(look.lang)).color(look.palette.warning),
                    )
                    .wrap(),
                );
            });
        }
        out
    }
}
