//! The egui desktop app, over the lti and ident crates (the only crate of the workspace that
//! links egui, eframe and rfd); its own words are in [`words`]. The top level is thin: one
//! [`Saved`] (what is kept between runs, with each mode's own: [`design::Saved`],
//! [`identify::Saved`]), the sessions of the modes (Design: [`design`]; Identify:
//! [`identify`]; least squares: [`lsq`]; Tune: [`tune`], its settings [`tune::Saved`];
//! Frequency: [`frequency`], its settings [`frequency::Saved`], its sources handed over from
//! the other modes before it draws; Exercises: [`exercises`], the sheet's guided exercises,
//! the student's progress kept as [`exercises::Saved`], a part's system loaded into Design,
//! and the hidden-effect challenges, drawn off the UI thread, their record loaded into
//! Identify),
//! the export window, the notices and the saver.
//!
//! Each frame the views draw from the sessions and return [`Command`]s (egui's own
//! `wrap_app.rs` pattern), and one function applies them: the menu's, the keys', the
//! notices' and what was dropped or pasted are applied before the mode draws; the mode's
//! jobs are polled, its views and the export window's draw, and their commands are applied
//! once after they have all drawn. What a mode's command asks of the app (open the fitted
//! model in Design, load a designed record, open a file dialog) comes back as further
//! commands, applied in turn. The derived data is brought up to date at once, so every
//! view of a frame shows one state; no view changes the state, writes a file or opens a
//! dialog while drawing ([`dialog`] opens them while commands are applied).
//!
//! Every change to the design system is one undoable edit (a drag is one edit; a typed
//! number is one edit when committed). The session ([`Saved`]) is kept in the app's own
//! state file ([`persist`]): every state the app is given is checked field by field before
//! it reaches a view, and it is handed to a saver thread only when something changed.
//!
//! The presentation size ([`Saved::scale`], 1×–2×) is egui's zoom factor, so text, markers
//! and line widths scale together; the language ([`Saved::lang`]) picks every label.

pub mod design;
pub mod dialog;
pub mod exercises;
pub mod export;
pub mod field;
pub mod frequency;
pub mod grid;
pub mod identify;
pub mod job;
pub mod look;
pub mod lsq;
mod menu;
pub mod persist;
pub mod plot_span;
mod state_file;
pub mod tune;
pub mod words;

use std::collections::VecDeque;
use std::time::Instant;

use eframe::egui::{self, Ui};
use serde::{Deserialize, Serialize};

use design::state::System;
use dialog::Pick;
use export::ExportState;
use look::{Look, clamp_scale};

use crate::words::app::{App as T, CodeKind, Notice};
use degrau_words::Lang;

/// Opens the Degrau window and blocks until it is closed.
pub fn run() -> eframe::Result {
    run_with(None, None)
}

/// Opens the window; with a step test (path and how to read it), in the identification
/// mode with that file loaded.
pub fn run_with(test: Option<identify::Saved>, lang: Option<Lang>) -> eframe::Result {
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
        Box::new(move |cc| {
            let mut app = DegrauApp::restore_opening(test);
            // The first frame is laid out at the presentation size already, so the panels'
            // first sizes are taken at it.
            cc.egui_ctx
                .set_zoom_factor(look::clamp_scale(app.saved.scale));
            if let Some(lang) = lang {
                app.saved.lang = lang;
            }
            Ok(Box::new(app))
        }),
    )
}

/// The app's modes (its tabs).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Mode {
    /// Place poles and zeros, watch the step response.
    #[default]
    Design,
    /// Fit a process model to a measured step test.
    Identify,
    /// Least squares on the samples: ARX, RLS, PRBS, validation.
    LeastSquares,
    /// From a process model to a controller: rules, drags, the loop's responses.
    Tune,
    /// The loop in frequency: Bode, margins, Nyquist, the sampled model on the z-plane.
    Frequency,
    /// Barbosa's exercise sheet as guided exercises: answers checked, solutions worked.
    Exercises,
}

/// What is kept between runs (the state file of [`persist`]). The Design mode's part is
/// at the top level of the file (`system`, `compare`, `splane`, …) as it always was.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub mode: Mode,
    pub ident: identify::Saved,
    #[serde(flatten)]
    pub design: design::Saved,
    /// The Tune mode's model, controller, τc and rule.
    pub tune: tune::Saved,
    /// The Frequency mode's source, tab, sampling period and Nyquist zoom.
    pub frequency: frequency::Saved,
    /// The Exercises mode's part open and the answers typed, with their last Check.
    pub exercises: exercises::Saved,
    pub dark: bool,
    /// The language of every label.
    pub lang: Lang,
    /// The presentation size, within [`SCALE_RANGE`].
    pub scale: f32,
}

impl Default for Saved {
    fn default() -> Self {
        Self {
            mode: Mode::default(),
            ident: identify::Saved::default(),
            design: design::Saved::default(),
            tune: tune::Saved::default(),
            frequency: frequency::Saved::default(),
            exercises: exercises::Saved::default(),
            dark: false,
            lang: Lang::default(),
            scale: 1.0,
        }
    }
}

/// What the app is asked to do: a change the top level makes (the menu, the notices, the
/// keys, a file dropped or text pasted, a file dialog), or a mode's or the export window's
/// command. Every change goes through [`DegrauApp`]'s `apply`, once per frame.
#[must_use = "a command does nothing until it is applied"]
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    SetMode(Mode),
    SetDark(bool),
    SetLang(Lang),
    SetScale(f32),
    Dismiss(usize),
    /// Choose a step test with the file dialog and open it in the Identify mode.
    OpenTestFile,
    /// The design system as code, to the clipboard.
    CopyCode(CodeKind),
    /// A file dropped on the window: loaded as a step test in the Identify mode.
    LoadPath(String),
    /// Columns pasted as text (or a designed record): loaded as the Identify mode's test.
    LoadText(String),
    /// A file dialog; what is chosen in it is applied as the command it makes.
    Pick(Pick),
    Export(export::Command),
    Design(design::Command),
    Identify(identify::Command),
    Lsq(lsq::Command),
    Tune(tune::Command),
    Frequency(frequency::Command),
    Exercises(exercises::Command),
}

/// What the Identify mode asks of the app after a command.
fn after_identify(outcome: identify::Outcome) -> Vec<Command> {
    match outcome {
        identify::Outcome::ShowOnSPlane { tf, du } => vec![
            Command::Design(design::Command::SetSystem(System::from_transfer_function(
                &tf, du,
            ))),
            Command::SetMode(Mode::Design),
        ],
        identify::Outcome::Tune { model, code } => vec![
            Command::Tune(tune::Command::Receive { model, code }),
            Command::SetMode(Mode::Tune),
        ],
        identify::Outcome::Pick(pick) => vec![Command::Pick(pick)],
    }
}

/// What the Exercises mode asks of the app: a part's system loaded into the Design mode
/// (a loop closed around its gain K with a P controller, specs shaded), then shown.
fn after_exercises(outcome: exercises::Outcome) -> Vec<Command> {
    match outcome {
        exercises::Outcome::Load(load) => {
            let mut out = vec![Command::Design(design::Command::SetSystem(load.system))];
            if let Some(k) = load.loop_gain {
                out.extend([
                    Command::Design(design::Command::SetLoopController(
                        design::closed_loop::ControllerShape::default(),
                    )),
                    Command::Design(design::Command::SetKp(k)),
                ]);
            }
            out.push(Command::Design(design::Command::SetLoopClosed(
                load.loop_gain.is_some(),
            )));
            if let Some(specs) = load.specs {
                out.push(Command::Design(design::Command::SetSpecs(specs)));
            }
            out.push(Command::SetMode(Mode::Design));
            out
        }
        exercises::Outcome::Record(csv) => vec![
            Command::SetMode(Mode::Identify),
            Command::Identify(identify::Command::LoadText(csv)),
        ],
    }
}

/// What the least-squares mode asks of the app after a command.
fn after_lsq(outcome: lsq::Outcome) -> Vec<Command> {
    match outcome {
        lsq::Outcome::UseRecord(csv) => vec![Command::LoadText(csv)],
        lsq::Outcome::Pick(pick) => vec![Command::Pick(pick)],
    }
}

/// The app: saved state, the mode sessions, the notices and the saver.
pub struct DegrauApp {
    pub saved: Saved,
    /// The Design mode's history and derived data (its state is `saved.design`).
    pub design: design::Session,
    /// The Identify mode's session (its settings are saved as `saved.ident`).
    pub ident: identify::Session,
    /// The least-squares mode's session (on the Identify mode's record).
    pub lsq: lsq::Session,
    /// The Tune mode's derived data (its settings are `saved.tune`).
    pub tune: tune::Session,
    /// The Frequency mode's derived data (its settings are `saved.frequency`).
    pub frequency: frequency::Session,
    /// The Exercises mode's sheet and last Check (its progress is `saved.exercises`).
    pub exercises: exercises::Session,
    /// Messages for the student (what could not be restored or saved), dismissable.
    pub notices: Vec<Notice>,
    export: ExportState,
    plot_rect: Option<egui::Rect>,
    fonts_ready: bool,
    /// The zoom factor the app last set (a different one was set by egui's own keys).
    zoom_set: f32,
    /// A short confirmation ("Copied …") and when it was given (seconds of egui time).
    confirmation: Option<(T, f64)>,
    /// Writes the session to the state file after each change (none: not kept).
    saver: Option<persist::Saver>,
    /// Something was changed since the session was last handed to the saver.
    dirty: bool,
    last_offer: Option<Instant>,
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

impl Default for DegrauApp {
    fn default() -> Self {
        Self::new(Saved::default())
    }
}

impl DegrauApp {
    /// An app showing `saved` as it is (the callers check it first).
    fn unchecked(mut saved: Saved) -> Self {
        let ident = identify::Session::with_settings(saved.ident.clone());
        let tune = tune::Session::new(&saved.tune);
        let exercises = exercises::Session::restored(&mut saved.exercises);
        Self {
            design: design::Session::new(&saved.design),
            saved,
            ident,
            lsq: lsq::Session::default(),
            tune,
            frequency: frequency::Session::default(),
            exercises,
            notices: Vec::new(),
            export: ExportState::default(),
            plot_rect: None,
            fonts_ready: false,
            zoom_set: 1.0,
            confirmation: None,
            saver: None,
            dirty: true,
            last_offer: None,
        }
    }

    /// The system being edited.
    pub fn system(&self) -> &System {
        &self.saved.design.system
    }

    /// What every view is drawn with this frame.
    pub fn look(&self) -> Look {
        Look::new(self.saved.lang, self.saved.dark, self.saved.scale)
    }

    /// Replaces the system as one undoable edit.
    pub fn set_system(&mut self, system: System) {
        self.design
            .apply(&mut self.saved.design, design::Command::SetSystem(system));
        self.dirty = true;
    }

    pub fn undo(&mut self) {
        self.design
            .apply(&mut self.saved.design, design::Command::Undo);
        self.dirty = true;
    }

    pub fn redo(&mut self) {
        self.design
            .apply(&mut self.saved.design, design::Command::Redo);
        self.dirty = true;
    }

    /// Where the step plot was drawn in the last Design frame (the PNG export's region).
    pub fn plot_rect(&self) -> Option<egui::Rect> {
        self.plot_rect
    }

    /// The root currently selected on the s-plane.
    pub fn selected(&self) -> Option<design::state::RootId> {
        self.saved.design.splane.selected
    }

    /// Draws one frame into `ui` (the whole window), applies what the views asked for,
    /// then hands the session to the saver if it changed.
    pub fn show(&mut self, ui: &mut Ui) {
        self.prepare(ui.ctx());
        // Whatever changed the state outside a command (a test, a restored file) is
        // analysed before anything draws.
        self.design.refresh(&self.saved.design);
        self.tune.refresh(&self.saved.tune);
        let look = self.look();
        let mut commands = self.keyboard(ui);
        commands.extend(
            egui::Panel::top("menu")
                .show(ui, |ui| self.menu_bar(ui, &look))
                .inner,
        );
        if !self.notices.is_empty() {
            commands.extend(
                egui::Panel::top("notices")
                    .show(ui, |ui| self.show_notices(ui, &look))
                    .inner,
            );
        }
        commands.extend(self.dropped_and_pasted(ui));
        // The menu, the keys, the notices and what was dropped or pasted are the frame's
        // input: applied before the mode draws, so a mode chosen in the menu is the one
        // drawn this frame.
        self.apply(ui.ctx(), commands);
        let look = self.look();
        let mut commands = self.show_mode(ui, &look);
        // A PNG asked for last frame is taken now, with the export window not drawn.
        if !self.export.poll(ui.ctx(), self.plot_rect) {
            commands.extend(
                self.export
                    .show(ui.ctx(), look.lang)
                    .into_iter()
                    .map(Command::Export),
            );
        }
        self.apply(ui.ctx(), commands);
        // A job that ended may have changed what is kept (a diagnosis adopts its model).
        if self.ident.settings_to_save() != self.saved.ident {
            self.dirty = true;
        }
        self.autosave(ui.ctx());
    }

    /// The mode: its jobs polled (what finished taken in), then its views drawn from its
    /// session. Returns what the views asked.
    fn show_mode(&mut self, ui: &mut Ui, look: &Look) -> Vec<Command> {
        match self.saved.mode {
            Mode::Identify => {
                self.poll_identify(ui.ctx());
                identify::show(ui, &self.ident, look)
                    .into_iter()
                    .map(Command::Identify)
                    .collect()
            }
            Mode::LeastSquares => {
                self.poll_lsq(ui.ctx());
                let design = self.design.analysis.tf.as_ref().ok();
                lsq::show(ui, &self.lsq, design, look)
                    .into_iter()
                    .map(Command::Lsq)
                    .collect()
            }
            Mode::Tune => tune::show(ui, &self.tune, &self.saved.tune, look)
                .into_iter()
                .map(Command::Tune)
                .collect(),
            Mode::Frequency => {
                self.frequency
                    .sync(&self.saved.frequency, self.frequency_sources());
                frequency::show(ui, &self.frequency, &self.saved.frequency, look)
                    .into_iter()
                    .map(Command::Frequency)
                    .collect()
            }
            Mode::Exercises => {
                self.poll_challenge(ui.ctx());
                self.exercises.sync(&mut self.saved.exercises);
                exercises::show(ui, &self.exercises, &self.saved.exercises, look)
                    .into_iter()
                    .map(Command::Exercises)
                    .collect()
            }
            Mode::Design => {
                let shown = design::show(ui, &self.design, &self.saved.design, look);
                self.plot_rect = shown.plot_rect;
                shown.commands.into_iter().map(Command::Design).collect()
            }
        }
    }

    /// The transfer functions the Frequency mode can show, from the other modes.
    fn frequency_sources(&self) -> frequency::Sources {
        let alone = |plant: degrau_lti::TransferFunction| frequency::Source {
            plant,
            controller: None,
        };
        frequency::Sources {
            design: self.design.analysis.tf.clone().ok().map(alone),
            tune: self
                .saved
                .tune
                .plant_and_controller()
                .map(|(plant, c)| frequency::Source {
                    plant,
                    controller: Some(c),
                }),
            fitted: self
                .ident
                .fitted_transfer_function()
                .map(|(tf, _)| alone(tf)),
        }
    }

    /// The Challenges' draw: a challenge drawn is taken in (and kept), and frames are asked
    /// while one is drawn.
    fn poll_challenge(&mut self, ctx: &egui::Context) {
        let board = &mut self.exercises.board;
        if !board.has_waker() {
            let ctx = ctx.clone();
            board.set_waker(std::sync::Arc::new(move || ctx.request_repaint()));
        }
        if board.poll(&mut self.saved.exercises.challenges) {
            self.dirty = true;
            ctx.request_repaint();
        } else if board.drawing() {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    /// The Identify mode's jobs: what finished is taken in, and frames are asked while one
    /// runs.
    fn poll_identify(&mut self, ctx: &egui::Context) {
        if !self.ident.has_waker() {
            let ctx = ctx.clone();
            self.ident
                .set_waker(std::sync::Arc::new(move || ctx.request_repaint()));
        }
        if self.ident.poll() {
            ctx.request_repaint();
        }
    }

    /// The least-squares mode: the Identify mode's record and fit taken in, the background
    /// validation polled and the RLS animation advanced (frames asked only while it runs).
    fn poll_lsq(&mut self, ctx: &egui::Context) {
        if !self.lsq.has_waker() {
            let ctx = ctx.clone();
            self.lsq
                .set_waker(std::sync::Arc::new(move || ctx.request_repaint()));
        }
        if self.ident.poll() {
            ctx.request_repaint();
        }
        let design = self.design.analysis.tf.as_ref().ok();
        self.lsq.sync(&self.ident, design);
        if self.lsq.poll() | self.lsq.tick() {
            ctx.request_repaint();
        }
    }

    /// Fonts, theme and the presentation size, before anything is laid out.
    fn prepare(&mut self, ctx: &egui::Context) {
        if !self.fonts_ready {
            use_math_fallback_font(ctx);
            self.fonts_ready = true;
        }
        let theme = if self.saved.dark {
            egui::Theme::Dark
        } else {
            egui::Theme::Light
        };
        if ctx.theme() != theme {
            ctx.set_theme(theme);
        }
        // egui's own Ctrl+plus / Ctrl+minus change the zoom: that is the presentation size.
        let zoom = ctx.zoom_factor();
        if (zoom - self.zoom_set).abs() > 1e-3 {
            self.saved.scale = clamp_scale(zoom);
            self.dirty = true;
        }
        self.saved.scale = clamp_scale(self.saved.scale);
        // A small window keeps its menu and plots: the zoom is capped to what it holds.
        let window = ctx.content_rect().size() * zoom;
        let fitted = look::fitted_zoom(self.saved.scale, [window.x, window.y]);
        if (zoom - fitted).abs() > 1e-3 {
            ctx.set_zoom_factor(fitted);
        }
        self.zoom_set = fitted;
    }

    /// Applies the frame's commands, in order (what one asks next is done before the
    /// next), and asks for the next frame to show them.
    pub fn apply(&mut self, ctx: &egui::Context, commands: Vec<Command>) {
        let mut changed = false;
        let mut queue: VecDeque<Command> = commands.into();
        while let Some(command) = queue.pop_front() {
            changed |= !matches!(command, Command::Design(design::Command::Readout(_)));
            for next in self.apply_one(ctx, command).into_iter().rev() {
                queue.push_front(next);
            }
        }
        if changed {
            self.dirty = true;
            ctx.request_repaint();
        }
    }

    /// Carries out one command; returns what it asks the app to do next.
    fn apply_one(&mut self, ctx: &egui::Context, command: Command) -> Vec<Command> {
        match command {
            Command::SetMode(mode) => self.saved.mode = mode,
            Command::SetDark(dark) => self.saved.dark = dark,
            Command::SetLang(lang) => self.saved.lang = lang,
            Command::SetScale(scale) => self.saved.scale = clamp_scale(scale),
            Command::Dismiss(i) => {
                if i < self.notices.len() {
                    self.notices.remove(i);
                }
            }
            Command::OpenTestFile => {
                return vec![
                    Command::SetMode(Mode::Identify),
                    Command::Pick(Pick::AnyTest),
                ];
            }
            Command::CopyCode(kind) => self.copy_code(ctx, kind),
            Command::LoadPath(path) => {
                return vec![
                    Command::SetMode(Mode::Identify),
                    Command::Identify(identify::Command::Open(path)),
                ];
            }
            Command::LoadText(text) => {
                return vec![Command::Identify(identify::Command::LoadText(text))];
            }
            Command::Pick(pick) => {
                let chosen = dialog::choose(pick, self.saved.lang);
                return chosen.map(|path| picked(pick, path)).into_iter().collect();
            }
            Command::Export(c) => {
                let curves = export::Curves {
                    curve: &self.design.analysis.curve,
                    compare: self
                        .design
                        .compare_analysis
                        .as_ref()
                        .map(|a| a.curve.as_slice()),
                };
                return match self.export.apply(c, curves) {
                    Some(export::Outcome::Browse) => vec![Command::Pick(Pick::ExportPath)],
                    None => Vec::new(),
                };
            }
            Command::Design(c) => self.design.apply(&mut self.saved.design, c),
            Command::Identify(c) => {
                return self.ident.apply(c).map_or_else(Vec::new, after_identify);
            }
            Command::Tune(c) => self.tune.apply(&mut self.saved.tune, c),
            Command::Frequency(c) => self.frequency.apply(&mut self.saved.frequency, c),
            Command::Exercises(c) => {
                return self
                    .exercises
                    .apply(&mut self.saved.exercises, c)
                    .map_or_else(Vec::new, after_exercises);
            }
            Command::Lsq(c) => {
                let design = self.design.analysis.tf.as_ref().ok();
                return self
                    .lsq
                    .apply(c, &self.ident, design)
                    .map_or_else(Vec::new, after_lsq);
            }
        }
        Vec::new()
    }

    /// The design system as code for `kind`, to the clipboard, with a confirmation.
    fn copy_code(&mut self, ctx: &egui::Context, kind: CodeKind) {
        let Ok(tf) = &self.design.analysis.tf else {
            return;
        };
        let (num, den) = (tf.num(), tf.den());
        let a = self.saved.design.system.amplitude;
        let code = match kind {
            CodeKind::Matlab => crate::words::code::matlab(&num, &den, tf.delay(), a),
            CodeKind::PythonControl => {
                crate::words::code::python_control(&num, &den, tf.delay(), a)
            }
        };
        ctx.copy_text(code);
        let when = ctx.input(|i| i.time);
        self.confirmation = Some((kind.copied(), when));
    }

    /// A file dropped on the window loads as a step test; text pasted in the identification
    /// mode (outside a text field) loads as columns.
    fn dropped_and_pasted(&self, ui: &Ui) -> Vec<Command> {
        let dropped = ui.input(|i| {
            i.raw
                .dropped_files
                .first()
                .map(|f| f.path().display().to_string())
        });
        let mut out: Vec<Command> = dropped.into_iter().map(Command::LoadPath).collect();
        let typing = ui.ctx().memory(|m| m.focused().is_some());
        if self.saved.mode == Mode::Identify && !typing {
            let pasted = ui.input(|i| {
                i.events.iter().find_map(|e| match e {
                    egui::Event::Paste(text) => Some(text.clone()),
                    _ => None,
                })
            });
            out.extend(pasted.map(Command::LoadText));
        }
        out
    }
}

impl eframe::App for DegrauApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }
}

/// The command a file chosen in the dialog `pick` makes.
fn picked(pick: Pick, path: std::path::PathBuf) -> Command {
    let text = path.display().to_string();
    match pick {
        Pick::AnyTest | Pick::StepTest => Command::Identify(identify::Command::Open(text)),
        Pick::InputFile => Command::Identify(identify::Command::SetChoice(
            identify::commands::Choice::InputFile,
            text,
        )),
        Pick::PrbsCsv => Command::Lsq(lsq::Command::ExportPrbs(path)),
        Pick::ExportPath => Command::Export(export::Command::SetPath(text)),
    }
}
