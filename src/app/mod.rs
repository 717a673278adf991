//! The egui desktop app: an s-plane on the left, the live step response on the right, the
//! system's numbers in a side panel and the metrics and y(t) in a bottom strip. Everything
//! it shows comes from the library ([`crate::lti`]); this module only lays out and edits.
//!
//! Every change to the system, whatever made it (a drag, a typed number, a menu), is one
//! undoable edit: the app compares the system before and after each frame and records the
//! state before an edit *session* (a drag or a focused text field counts as one).
//!
//! The session ([`Saved`]) is kept in the app's own state file ([`persist`]): every state
//! the app is given, from the file or from a caller, is checked field by field before it
//! reaches a view, and every change is handed to a saver thread that writes it within a
//! fraction of a second, frame or no frame.

pub mod analysis;
pub mod export;
pub mod field;
pub mod grid;
pub mod identify;
pub mod job;
pub mod look;
pub mod metrics_table;
pub mod persist;
pub mod presets;
pub mod splane;
pub mod state;
pub mod step_plot;
pub mod system_panel;

use eframe::egui::{self, Key, KeyboardShortcut, Modifiers, RichText, Ui};
use serde::{Deserialize, Serialize};

use analysis::Analysis;
use export::ExportState;
use presets::{Preset, presets};
use splane::SPlaneState;
use state::{History, RootId, System};
use step_plot::Markers;
use system_panel::PanelAction;

use crate::lti::StepInfoOptions;

/// Opens the Degrau window and blocks until it is closed.
pub fn run() -> eframe::Result {
    run_with(None)
}

/// Opens the window; with a step test (path and how to read it), in the identification
/// mode with that file loaded.
pub fn run_with(test: Option<identify::IdentSettings>) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Degrau")
            .with_inner_size([1360.0, 860.0])
            .with_min_inner_size([900.0, 600.0]),
        ..Default::default()
    };
    eframe::run_native(
        "Degrau",
        options,
        Box::new(move |_cc| {
            let mut app = DegrauApp::restore();
            if let Some(settings) = test {
                let path = settings.path.clone();
                app.ident.settings = settings;
                app.saved.mode = Mode::Identify;
                app.ident.load_path(&path);
            }
            Ok(Box::new(app))
        }),
    )
}

/// The two things the app does.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Mode {
    /// Place poles and zeros, watch the step response.
    #[default]
    Design,
    /// Fit a process model to a measured step test.
    Identify,
}

/// What is kept between runs (the state file of [`persist`]).
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub mode: Mode,
    pub ident: identify::IdentSettings,
    pub system: System,
    pub compare: Option<(String, System)>,
    pub splane: SPlaneState,
    pub markers: Markers,
    pub options: StepInfoOptions,
    pub phase_form: bool,
    pub dark: bool,
}

/// The app: saved state plus what is derived or transient.
pub struct DegrauApp {
    pub saved: Saved,
    pub history: History,
    pub analysis: Analysis,
    compare_analysis: Option<Analysis>,
    /// The response before the current/last edit session, drawn faintly.
    ghost: Option<Vec<[f64; 2]>>,
    /// The system as it was when the frame started.
    frame_start: System,
    /// True while an edit session is open (pointer held or a text field focused).
    editing: bool,
    presets: Vec<Preset>,
    export: ExportState,
    plot_rect: Option<egui::Rect>,
    /// The identification view (its settings live in `saved.ident`).
    pub ident: identify::Session,
    fonts_ready: bool,
    /// Writes the session to the state file after each change (none: not kept).
    saver: Option<persist::Saver>,
    /// Messages for the student (what could not be restored or saved), dismissable.
    pub notices: Vec<String>,
}

/// Adds egui's bundled monospace font (Hack) as a fallback of the proportional one, so
/// arrows, ○ and box-drawing characters in the text a student reads are drawn.
fn use_math_fallback_font(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    if let Some(family) = fonts.families.get_mut(&egui::FontFamily::Proportional)
        && !family.iter().any(|f| f == "Hack")
    {
        family.push("Hack".to_owned());
    }
    ctx.set_fonts(fonts);
}

const UNDO: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
const REDO: KeyboardShortcut =
    KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z);
const REDO_Y: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);

impl Default for DegrauApp {
    fn default() -> Self {
        Self::new(Saved::default())
    }
}

impl DegrauApp {
    /// An app showing `saved`, checked field by field as a restored file is (a bad field
    /// falls back to its default with a notice); nothing is written to disk.
    pub fn new(saved: Saved) -> Self {
        let (saved, problems) = match serde_json::to_value(&saved) {
            Ok(value) => persist::restore_value(&value),
            Err(e) => (
                Saved::default(),
                vec![persist::FieldProblem {
                    field: "the whole session".into(),
                    reason: e.to_string(),
                }],
            ),
        };
        let mut app = Self::unchecked(saved);
        app.notices.extend(restore_notice(&problems, None, None));
        app
    }

    /// The session kept in the state file at `path` (restored field by field; a file that
    /// could not be restored whole is copied aside first), saved there after every change.
    pub fn with_state_file(path: std::path::PathBuf) -> Self {
        let restored = persist::restore(&path);
        let mut app = Self::unchecked(restored.saved);
        app.notices.extend(restore_notice(
            &restored.problems,
            restored.backup.as_deref(),
            restored.backup_error.as_deref(),
        ));
        app.saver = Some(persist::Saver::spawn(path));
        app
    }

    /// The last session from the state file in its usual place ([`persist::default_path`]),
    /// or the built-in example.
    pub fn restore() -> Self {
        match persist::default_path() {
            Some(path) => Self::with_state_file(path),
            None => {
                let mut app = Self::default();
                app.notices.push(
                    "There is no home directory to keep the session in: it will not be saved."
                        .into(),
                );
                app
            }
        }
    }

    /// An app showing `saved` as it is (the callers check it first).
    fn unchecked(saved: Saved) -> Self {
        let saved_ident = saved.ident.clone();
        let analysis = Analysis::new(&saved.system, saved.options);
        let compare_analysis = saved
            .compare
            .as_ref()
            .map(|(_, s)| Analysis::new(s, saved.options));
        Self {
            frame_start: saved.system.clone(),
            saved,
            history: History::default(),
            analysis,
            compare_analysis,
            ghost: None,
            editing: false,
            presets: presets(),
            export: ExportState::default(),
            plot_rect: None,
            ident: identify::Session::with_settings(saved_ident),
            fonts_ready: false,
            saver: None,
            notices: Vec::new(),
        }
    }

    /// The state file the session is saved to, if it is saved.
    pub fn state_file(&self) -> Option<&std::path::Path> {
        self.saver.as_ref().map(|s| s.path())
    }

    /// The system being edited.
    pub fn system(&self) -> &System {
        &self.saved.system
    }

    /// Replaces the system as one undoable edit.
    pub fn set_system(&mut self, system: System) {
        self.history.record(&self.saved.system);
        self.ghost = Some(self.analysis.curve.clone());
        self.saved.system = system;
        self.frame_start = self.saved.system.clone();
        self.saved.splane.view = None;
        self.saved.splane.selected = None;
    }

    pub fn undo(&mut self) {
        if self.history.undo(&mut self.saved.system) {
            self.after_history_jump();
        }
    }

    pub fn redo(&mut self) {
        if self.history.redo(&mut self.saved.system) {
            self.after_history_jump();
        }
    }

    fn after_history_jump(&mut self) {
        self.ghost = Some(self.analysis.curve.clone());
        self.frame_start = self.saved.system.clone();
        self.editing = false;
        let (poles, zeros) = (self.saved.system.poles.len(), self.saved.system.zeros.len());
        if let Some(sel) = self.saved.splane.selected {
            let n = match sel.role {
                state::RootRole::Pole => poles,
                state::RootRole::Zero => zeros,
            };
            if sel.index >= n {
                self.saved.splane.selected = None;
            }
        }
    }

    /// Draws one frame into `ui` (the whole window), then hands the session to the saver if
    /// it changed.
    pub fn show(&mut self, ui: &mut Ui) {
        self.show_mode(ui);
        self.autosave(ui.ctx());
    }

    /// Draws the frame of the current mode.
    fn show_mode(&mut self, ui: &mut Ui) {
        if !self.fonts_ready {
            use_math_fallback_font(ui.ctx());
            self.fonts_ready = true;
        }
        let theme = if self.saved.dark {
            egui::Theme::Dark
        } else {
            egui::Theme::Light
        };
        if ui.ctx().theme() != theme {
            ui.ctx().set_theme(theme);
        }
        self.keyboard(ui);
        self.frame_start = self.saved.system.clone();

        egui::Panel::top("menu").show(ui, |ui| self.menu_bar(ui));
        if !self.notices.is_empty() {
            egui::Panel::top("notices").show(ui, |ui| self.show_notices(ui));
        }
        self.dropped_and_pasted(ui);
        if self.saved.mode == Mode::Identify {
            self.identify(ui);
            return;
        }
        let action = egui::Panel::right("system")
            .resizable(true)
            .default_size(330.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .show(ui, |ui| {
                        system_panel::show(
                            ui,
                            &mut self.saved.system,
                            &mut self.saved.splane.selected,
                            &self.analysis,
                            &self.presets,
                            self.saved.compare.is_some(),
                        )
                    })
                    .inner
            })
            .inner;
        egui::Panel::bottom("metrics")
            .resizable(true)
            .default_size(230.0)
            .show(ui, |ui| {
                let compare = compare_pair(&self.saved.compare, &self.compare_analysis);
                metrics_table::show(ui, &self.analysis, compare, &mut self.saved.phase_form);
            });
        let half = (ui.available_width() * 0.45).max(250.0);
        egui::Panel::left("s-plane")
            .resizable(true)
            .default_size(half)
            .show(ui, |ui| self.splane_panel(ui));
        egui::CentralPanel::default().show(ui, |ui| self.plot_panel(ui));

        self.apply(action);
        self.close_edit_session(ui);
        self.refresh();
        let compare_curve = self.compare_analysis.as_ref().map(|a| a.curve.as_slice());
        self.export.show(
            ui.ctx(),
            self.plot_rect,
            &self.analysis.curve,
            compare_curve,
        );
    }

    fn menu_bar(&mut self, ui: &mut Ui) {
        egui::MenuBar::new().ui(ui, |ui| {
            ui.selectable_value(&mut self.saved.mode, Mode::Design, "Poles and zeros");
            ui.selectable_value(&mut self.saved.mode, Mode::Identify, "Identify a step test");
            ui.separator();
            ui.menu_button("File", |ui| {
                if ui.button("Open a step test…").clicked() {
                    self.saved.mode = Mode::Identify;
                    if let Some(p) = rfd::FileDialog::new().pick_file() {
                        self.ident.load_path(&p.display().to_string());
                    }
                    ui.close();
                }
                if ui.button("Export…").clicked() {
                    self.export.open = true;
                    ui.close();
                }
                if ui.button("Reset to the built-in example").clicked() {
                    self.set_system(System::default());
                    ui.close();
                }
            });
            ui.menu_button("Edit", |ui| {
                if ui
                    .add_enabled(
                        self.history.can_undo(),
                        egui::Button::new("Undo").shortcut_text(ui.ctx().format_shortcut(&UNDO)),
                    )
                    .clicked()
                {
                    self.undo();
                    ui.close();
                }
                if ui
                    .add_enabled(
                        self.history.can_redo(),
                        egui::Button::new("Redo").shortcut_text(ui.ctx().format_shortcut(&REDO)),
                    )
                    .clicked()
                {
                    self.redo();
                    ui.close();
                }
                if ui
                    .add_enabled(
                        self.saved.splane.selected.is_some(),
                        egui::Button::new("Delete selected root").shortcut_text("Delete"),
                    )
                    .clicked()
                {
                    self.delete_selected();
                    ui.close();
                }
            });
            ui.menu_button("View", |ui| {
                ui.checkbox(&mut self.saved.dark, "Dark theme");
                ui.checkbox(
                    &mut self.saved.splane.damping_grid,
                    "Constant ζ and ωn lines",
                );
                ui.checkbox(&mut self.saved.splane.snap, "Snap roots to the grid");
                if ui.button("Fit the s-plane to the roots").clicked() {
                    self.saved.splane.view = None;
                    ui.close();
                }
            });
            if ui
                .add_enabled(self.history.can_undo(), egui::Button::new("Undo"))
                .clicked()
            {
                self.undo();
            }
            if ui
                .add_enabled(self.history.can_redo(), egui::Button::new("Redo"))
                .clicked()
            {
                self.redo();
            }
        });
    }

    fn splane_panel(&mut self, ui: &mut Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut self.saved.splane.damping_grid, "ζ / ωn grid");
            ui.checkbox(&mut self.saved.splane.snap, "Snap");
            if ui
                .button("Fit")
                .on_hover_text("Fit the view to the roots")
                .clicked()
            {
                self.saved.splane.view = None;
            }
            if self.saved.system.has_rhp_pole() {
                ui.label(
                    RichText::new("Unstable: a pole is in the right half plane")
                        .color(ui.visuals().error_fg_color)
                        .strong(),
                );
            }
        });
        let readout = self
            .saved
            .splane
            .readout
            .clone()
            .unwrap_or_else(|| "Drag a pole (×) or zero (o); right-click to add; scroll to zoom; drag the background to pan.".into());
        ui.weak(readout);
        splane::show(ui, &mut self.saved.system, &mut self.saved.splane);
    }

    fn plot_panel(&mut self, ui: &mut Ui) {
        step_plot::controls(ui, &mut self.saved.markers, &mut self.saved.options);
        if let Err(reason) = &self.analysis.tf {
            ui.label(
                RichText::new(format!("No step response: {reason}"))
                    .color(ui.visuals().error_fg_color),
            );
        }
        self.plot_rect = Some(ui.available_rect_before_wrap());
        let compare = compare_pair(&self.saved.compare, &self.compare_analysis);
        step_plot::show(
            ui,
            &self.analysis,
            compare,
            self.ghost.as_deref(),
            &self.saved.markers,
        );
    }

    fn apply(&mut self, action: PanelAction) {
        match action {
            PanelAction::None => {}
            PanelAction::LoadPreset(i) => {
                if let Some(p) = self.presets.get(i) {
                    let (system, compare) = (
                        p.system.clone(),
                        p.compare.as_ref().map(|(n, s)| (n.to_string(), s.clone())),
                    );
                    self.set_system(system);
                    self.saved.compare = compare;
                }
            }
            PanelAction::CompareWithCurrent => {
                self.saved.compare = Some(("kept".into(), self.saved.system.clone()));
            }
            PanelAction::StopComparing => self.saved.compare = None,
        }
    }

    fn keyboard(&mut self, ui: &mut Ui) {
        let typing = ui.ctx().memory(|m| m.focused().is_some());
        // Ctrl+Z matches Ctrl+Shift+Z too in egui's logical matching: consume redo first.
        let redo = ui.input_mut(|i| i.consume_shortcut(&REDO) || i.consume_shortcut(&REDO_Y));
        let undo = ui.input_mut(|i| i.consume_shortcut(&UNDO));
        if redo {
            self.redo();
        } else if undo {
            self.undo();
        }
        if typing {
            return;
        }
        let Some(id) = self.saved.splane.selected else {
            return;
        };
        if ui.input(|i| i.key_pressed(Key::Delete) || i.key_pressed(Key::Backspace)) {
            self.delete_selected();
            return;
        }
        let step = self
            .saved
            .splane
            .view
            .map_or(0.1, |v| grid::nice_step(70.0 / v.pixels_per_unit) / 10.0);
        let (dx, dy) = ui.input(|i| {
            let mut d = (0.0, 0.0);
            if i.key_pressed(Key::ArrowLeft) {
                d.0 -= step;
            }
            if i.key_pressed(Key::ArrowRight) {
                d.0 += step;
            }
            if i.key_pressed(Key::ArrowUp) {
                d.1 += step;
            }
            if i.key_pressed(Key::ArrowDown) {
                d.1 -= step;
            }
            d
        });
        if (dx, dy) != (0.0, 0.0)
            && let Some(root) = self.saved.system.root_mut(id)
        {
            let (re, im) = (root.re + dx, root.im + dy);
            root.move_to(re, im);
        }
    }

    fn delete_selected(&mut self) {
        if let Some(id) = self.saved.splane.selected.take() {
            let before = self.saved.system.clone();
            if self.saved.system.remove(id) {
                self.history.record(&before);
                self.ghost = Some(self.analysis.curve.clone());
                self.frame_start = self.saved.system.clone();
            }
        }
    }

    /// Records the state before an edit session and closes the session when the pointer is
    /// released and no field has focus.
    fn close_edit_session(&mut self, ui: &Ui) {
        let changed = self.saved.system != self.frame_start;
        if changed && !self.editing {
            self.history.record(&self.frame_start);
            self.ghost = Some(self.analysis.curve.clone());
            self.editing = true;
        }
        let busy = ui.input(|i| i.pointer.any_down()) || ui.ctx().memory(|m| m.focused().is_some());
        if !busy && !changed {
            self.editing = false;
        }
    }

    fn refresh(&mut self) {
        self.analysis
            .refresh(&self.saved.system, self.saved.options);
        match (&self.saved.compare, &mut self.compare_analysis) {
            (Some((_, s)), Some(a)) => a.refresh(s, self.saved.options),
            (Some((_, s)), None) => {
                self.compare_analysis = Some(Analysis::new(s, self.saved.options))
            }
            (None, _) => self.compare_analysis = None,
        }
    }

    /// The identification mode: its session polled, its views drawn, their commands applied.
    fn identify(&mut self, ui: &mut Ui) {
        if !self.ident.has_waker() {
            let ctx = ui.ctx().clone();
            self.ident
                .set_waker(std::sync::Arc::new(move || ctx.request_repaint()));
        }
        if self.ident.poll() {
            ui.ctx().request_repaint();
        }
        let look = look::Look::new(crate::text::Lang::En, self.saved.dark, 1.0);
        for command in identify::show(ui, &self.ident, &look) {
            if let Some(identify::Outcome::ShowOnSPlane { tf, du }) = self.ident.apply(command) {
                self.show_model(&tf, du);
            }
        }
    }

    /// Opens a fitted model in the pole-zero view, stepped by the test's Δu.
    fn show_model(&mut self, tf: &crate::lti::TransferFunction, du: f64) {
        self.set_system(System::from_transfer_function(tf, du));
        self.saved.mode = Mode::Design;
    }

    /// Files dropped on the window load as step tests; text pasted in the identification
    /// mode (outside a text field) loads as columns.
    fn dropped_and_pasted(&mut self, ui: &Ui) {
        let dropped: Vec<String> = ui.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().display().to_string())
                .collect()
        });
        if let Some(path) = dropped.first() {
            self.saved.mode = Mode::Identify;
            self.ident.load_path(path);
        }
        let typing = ui.ctx().memory(|m| m.focused().is_some());
        if self.saved.mode == Mode::Identify && !typing {
            let pasted: Option<String> = ui.input(|i| {
                i.events.iter().find_map(|e| match e {
                    egui::Event::Paste(text) => Some(text.clone()),
                    _ => None,
                })
            });
            if let Some(text) = pasted {
                self.ident.load_text(&text);
            }
        }
    }

    /// The notices, each with a button to dismiss it.
    fn show_notices(&mut self, ui: &mut Ui) {
        let mut dismissed = None;
        for (i, text) in self.notices.iter().enumerate() {
            ui.horizontal_wrapped(|ui| {
                if ui.button("Dismiss").clicked() {
                    dismissed = Some(i);
                }
                ui.label(RichText::new(text).color(ui.visuals().warn_fg_color));
            });
        }
        if let Some(i) = dismissed {
            self.notices.remove(i);
        }
    }

    /// Hands the session to the saver (it writes only when it changed) and shows a notice
    /// when writing failed.
    fn autosave(&mut self, ctx: &egui::Context) {
        let Some(saver) = self.saver.as_mut() else {
            return;
        };
        self.saved.ident = self.ident.settings_to_save();
        let offered = serde_json::to_string_pretty(&self.saved)
            .map_err(|e| e.to_string())
            .and_then(|json| {
                saver
                    .offer(json, Some(ctx))
                    .then_some(())
                    .ok_or_else(|| "the saver has stopped".to_string())
            });
        let failure = offered.err().or_else(|| saver.take_error());
        if let Some(reason) = failure {
            let text = format!("Could not save the session: {reason}");
            if !self.notices.contains(&text) {
                self.notices.push(text);
            }
        }
    }

    /// The root currently selected on the s-plane.
    pub fn selected(&self) -> Option<RootId> {
        self.saved.splane.selected
    }
}

/// The comparison system's name and analysis, when comparing.
fn compare_pair<'a>(
    saved: &'a Option<(String, System)>,
    analysis: &'a Option<Analysis>,
) -> Option<(&'a str, &'a Analysis)> {
    match (saved, analysis) {
        (Some((name, _)), Some(a)) => Some((name.as_str(), a)),
        _ => None,
    }
}

/// The notice of what could not be restored, naming each field, if anything.
fn restore_notice(
    problems: &[persist::FieldProblem],
    backup: Option<&std::path::Path>,
    backup_error: Option<&str>,
) -> Option<String> {
    if problems.is_empty() {
        return None;
    }
    let parts: Vec<String> = problems
        .iter()
        .map(|p| format!("{} ({})", p.field, p.reason))
        .collect();
    let mut text = format!(
        "Part of the last session could not be restored and was reset to its default: {}.",
        parts.join("; ")
    );
    if let Some(path) = backup {
        text.push_str(&format!(
            " The file as it was is kept as {}.",
            path.display()
        ));
    }
    if let Some(reason) = backup_error {
        text.push_str(&format!(" It could not be kept aside: {reason}."));
    }
    Some(text)
}

impl eframe::App for DegrauApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }
}
