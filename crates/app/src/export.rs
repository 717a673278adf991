//! Saving figures and data: the step plot or the whole window as PNG (from a screenshot of
//! the real window, taken once the dialog has closed) and the sampled curve as CSV. The
//! path is typed or chosen with a file dialog; a file that exists is overwritten only when
//! the student confirms; the outcome is reported in words, in the app's language.
//!
//! The window is a view like the modes': [`ExportState::show`] reads the state and returns
//! [`Command`]s, and [`ExportState::apply`] carries them out (the only place a file is
//! written); the app opens the file dialog when asked ([`Outcome::Browse`]).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, channel};

use eframe::egui::{self, ColorImage, Rect, Ui};

use crate::words::app::App as T;
use degrau_words::{Lang, Localize};

/// What went wrong while saving, in plain words.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("could not write {path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    #[error("could not encode the PNG {path}: {source}")]
    Png {
        path: String,
        source: png::EncodingError,
    },
    #[error("there is no curve to save: the system is not valid")]
    NoCurve,
    #[error("type a file name first")]
    NoPath,
}

/// The curve as CSV text: a header naming the columns and units, then `t,y` rows.
pub fn curve_csv(curve: &[[f64; 2]], compare: Option<&[[f64; 2]]>) -> String {
    let mut out = String::from(if compare.is_some() {
        "t_s,y,y_b\n"
    } else {
        "t_s,y\n"
    });
    for (i, p) in curve.iter().enumerate() {
        match compare.and_then(|c| c.get(i)) {
            Some(b) => out.push_str(&format!("{},{},{}\n", p[0], p[1], b[1])),
            None => out.push_str(&format!("{},{}\n", p[0], p[1])),
        }
    }
    out
}

/// Writes the curve as CSV.
pub fn save_csv(
    path: &Path,
    curve: &[[f64; 2]],
    compare: Option<&[[f64; 2]]>,
) -> Result<(), ExportError> {
    if curve.is_empty() {
        return Err(ExportError::NoCurve);
    }
    std::fs::write(path, curve_csv(curve, compare)).map_err(|source| ExportError::Io {
        path: path.display().to_string(),
        source,
    })
}

/// Encodes an RGBA image as PNG at `path`.
pub fn save_png(path: &Path, image: &ColorImage) -> Result<(), ExportError> {
    let name = path.display().to_string();
    let file = std::fs::File::create(path).map_err(|source| ExportError::Io {
        path: name.clone(),
        source,
    })?;
    let mut encoder = png::Encoder::new(
        std::io::BufWriter::new(file),
        image.size[0] as u32,
        image.size[1] as u32,
    );
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|source| ExportError::Png {
        path: name.clone(),
        source,
    })?;
    writer
        .write_image_data(image.as_raw())
        .map_err(|source| ExportError::Png { path: name, source })
}

impl Localize for ExportError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ExportError::Io { path, source } => {
                format!("{} {path}: {source}", T::CouldNotWrite.get(lang))
            }
            ExportError::Png { path, source } => {
                format!("{} {path}: {source}", T::CouldNotEncode.get(lang))
            }
            ExportError::NoCurve => T::NoCurve.get(lang).to_string(),
            ExportError::NoPath => T::NoPath.get(lang).to_string(),
        }
    }
}

/// Which figure a PNG export takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Figure {
    StepPlot,
    Window,
}

/// What a button of the window asks to save, to the typed path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ask {
    Png(Figure),
    Csv,
}

/// What the export window asks ([`ExportState::show`] returns them; [`ExportState::apply`]
/// carries them out, the only place a file is written).
#[must_use = "a command does nothing until it is applied"]
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    Open,
    /// The window's close button.
    Close,
    /// The path field's text.
    SetPath(String),
    /// Choose the path with the file dialog.
    Browse,
    /// Save to the typed path; a file that exists waits for [`Command::Overwrite`].
    Save(Ask),
    /// Save what waits for the student's word over the file that exists.
    Overwrite,
    /// Drop what waits for the student's word.
    Cancel,
}

/// What the export window asks of the app after a command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Choose the path with the file dialog (the app opens it).
    Browse,
}

/// What the dialog was asked to save.
#[derive(Debug, Clone, PartialEq)]
enum Save {
    Png(Figure, PathBuf),
    Csv(PathBuf),
}

impl Save {
    fn path(&self) -> &Path {
        match self {
            Save::Png(_, p) | Save::Csv(p) => p,
        }
    }

    /// What `ask` saves to the typed `path`, with the figure's extension.
    fn of(ask: Ask, path: &str) -> Result<Self, ExportError> {
        Ok(match ask {
            Ask::Png(figure) => Save::Png(figure, with_extension(path, "png")?),
            Ask::Csv => Save::Csv(with_extension(path, "csv")?),
        })
    }
}

/// What happened, said in the dialog.
#[derive(Debug)]
enum Said {
    Taking,
    SavedPng(PathBuf),
    SavedCurve(PathBuf),
    Failed(ExportError),
}

impl Said {
    fn text(&self, lang: Lang) -> String {
        match self {
            Said::Taking => T::Taking.get(lang).to_string(),
            Said::SavedPng(p) => format!("{} {}", T::Saved.get(lang), p.display()),
            Said::SavedCurve(p) => format!("{} {}", T::SavedCurve.get(lang), p.display()),
            Said::Failed(e) => format!("{} {}", T::NotSaved.get(lang), e.text(lang)),
        }
    }
}

/// The curves a CSV export writes: the step response and the comparison's, if any.
#[derive(Debug, Clone, Copy)]
pub struct Curves<'a> {
    pub curve: &'a [[f64; 2]],
    pub compare: Option<&'a [[f64; 2]]>,
}

/// The export window's state. A PNG is taken on the first frame after the window has
/// closed (so the image never shows the dialog), and the window opens again to say how it
/// went; a file that exists is overwritten only once the student says so.
pub struct ExportState {
    pub open: bool,
    pub path: String,
    status: Option<Said>,
    /// A save waiting for "Overwrite".
    confirm: Option<Save>,
    /// A PNG to take once the window is closed.
    pending: Option<(Figure, PathBuf)>,
    results: (Sender<Said>, Receiver<Said>),
}

impl Default for ExportState {
    fn default() -> Self {
        Self {
            open: false,
            path: default_path("degrau_step.png"),
            status: None,
            confirm: None,
            pending: None,
            results: channel(),
        }
    }
}

fn default_path(name: &str) -> String {
    std::env::current_dir()
        .map(|d| d.join(name))
        .unwrap_or_else(|_| PathBuf::from(name))
        .display()
        .to_string()
}

impl ExportState {
    /// The status line now, in `lang` (for tests and the dialog).
    pub fn status(&self, lang: Lang) -> Option<String> {
        self.status.as_ref().map(|s| s.text(lang))
    }

    /// The path a save waits on for "Overwrite", if one does.
    pub fn waiting(&self) -> Option<&Path> {
        self.confirm.as_ref().map(Save::path)
    }

    /// Takes in the screenshots' outcomes (the window opens again to say them) and takes the
    /// PNG asked for last frame, now that the window is not drawn; `plot_rect` is where the
    /// step plot was drawn this frame. Whether a PNG is being taken (the window is not shown
    /// this frame).
    pub fn poll(&mut self, ctx: &egui::Context, plot_rect: Option<Rect>) -> bool {
        while let Ok(said) = self.results.1.try_recv() {
            self.status = Some(said);
            self.open = true;
        }
        match self.pending.take() {
            Some((figure, path)) => {
                self.take_png(ctx, figure, path, plot_rect);
                true
            }
            None => false,
        }
    }

    /// Draws the window, if it is open; returns what the student asked.
    pub fn show(&self, ctx: &egui::Context, lang: Lang) -> Vec<Command> {
        let mut out = Vec::new();
        // A closed window is not shown at all: egui keeps showing a window whose `open` is
        // false until its fade-out animation ends (at full opacity with `fade_out(false)`),
        // which put the dialog, "Taking the screenshot…", into "Save window as PNG".
        if !self.open {
            return out;
        }
        let mut open = true;
        egui::Window::new(T::ExportTitle.get(lang))
            .open(&mut open)
            .resizable(false)
            .show(ctx, |ui| self.contents(ui, lang, &mut out));
        if !open {
            out.push(Command::Close);
        }
        out
    }

    fn contents(&self, ui: &mut Ui, lang: Lang, out: &mut Vec<Command>) {
        ui.horizontal(|ui| {
            let name = ui.label(T::FileLabel.get(lang));
            let mut path = self.path.clone();
            let edited = ui
                .add(egui::TextEdit::singleline(&mut path).desired_width(360.0))
                .labelled_by(name.id)
                .changed();
            if edited {
                out.push(Command::SetPath(path));
            }
            if ui.button(T::Browse.get(lang)).clicked() {
                out.push(Command::Browse);
            }
        });
        ui.horizontal_wrapped(|ui| {
            for (text, ask) in [
                (T::SavePlotPng, Ask::Png(Figure::StepPlot)),
                (T::SaveWindowPng, Ask::Png(Figure::Window)),
                (T::SaveCsv, Ask::Csv),
            ] {
                if ui.button(text.get(lang)).clicked() {
                    out.push(Command::Save(ask));
                }
            }
        });
        if let Some(path) = self.waiting() {
            ui.horizontal_wrapped(|ui| {
                ui.label(format!("{} {}", path.display(), T::Exists.get(lang)));
                if ui.button(T::Overwrite.get(lang)).clicked() {
                    out.push(Command::Overwrite);
                }
                if ui.button(T::Cancel.get(lang)).clicked() {
                    out.push(Command::Cancel);
                }
            });
        }
        if let Some(status) = &self.status {
            ui.add(egui::Label::new(status.text(lang)).wrap());
        }
    }

    /// Carries out one command: a CSV is written here, a PNG is asked for the next frame
    /// (after the window has closed), a file that exists waits for the student's word.
    pub fn apply(&mut self, command: Command, curves: Curves<'_>) -> Option<Outcome> {
        match command {
            Command::Open => self.open = true,
            Command::Close => self.open = false,
            Command::SetPath(path) => self.path = path,
            Command::Browse => return Some(Outcome::Browse),
            Command::Save(ask) => match Save::of(ask, &self.path) {
                Ok(save) if save.path().exists() => self.confirm = Some(save),
                Ok(save) => self.save(save, curves),
                Err(e) => self.status = Some(Said::Failed(e)),
            },
            Command::Overwrite => {
                if let Some(save) = self.confirm.take() {
                    self.save(save, curves);
                }
            }
            Command::Cancel => self.confirm = None,
        }
        None
    }

    fn save(&mut self, save: Save, curves: Curves<'_>) {
        match save {
            Save::Csv(path) => {
                self.status = Some(match save_csv(&path, curves.curve, curves.compare) {
                    Ok(()) => Said::SavedCurve(path),
                    Err(e) => Said::Failed(e),
                });
            }
            Save::Png(figure, path) => {
                // Close the window first; the PNG is taken on the next frame.
                self.open = false;
                self.status = Some(Said::Taking);
                self.pending = Some((figure, path));
            }
        }
    }

    fn take_png(
        &mut self,
        ctx: &egui::Context,
        figure: Figure,
        path: PathBuf,
        plot_rect: Option<Rect>,
    ) {
        let region = match figure {
            Figure::StepPlot => plot_rect,
            Figure::Window => None,
        };
        let pixels_per_point = ctx.pixels_per_point();
        let sender = self.results.0.clone();
        let repaint = ctx.clone();
        ctx.request_screenshot(move |image: Arc<ColorImage>| {
            // Within the image: a region past its edge would index beyond its pixels.
            let [w, h] = image.size;
            let whole = Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(w as f32, h as f32) / pixels_per_point,
            );
            let cropped = match region.map(|r| r.intersect(whole)) {
                Some(r) if r.is_positive() => image.region(&r, Some(pixels_per_point)),
                _ => (*image).clone(),
            };
            let said = match save_png(&path, &cropped) {
                Ok(()) => Said::SavedPng(path),
                Err(e) => Said::Failed(e),
            };
            let _ = sender.send(said);
            repaint.request_repaint();
        });
    }
}

/// The typed path with the figure's extension (replacing another one).
fn with_extension(path: &str, extension: &str) -> Result<PathBuf, ExportError> {
    let trimmed = path.trim();
    if trimmed.is_empty() {
        return Err(ExportError::NoPath);
    }
    Ok(PathBuf::from(trimmed).with_extension(extension))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_has_a_header_and_one_row_per_sample() {
        let text = curve_csv(&[[0.0, 0.0], [0.5, 0.25]], None);
        assert_eq!(text, "t_s,y\n0,0\n0.5,0.25\n");
        let with_b = curve_csv(&[[0.0, 0.0]], Some(&[[0.0, 1.0]]));
        assert_eq!(with_b, "t_s,y,y_b\n0,0,1\n");
    }

    #[test]
    fn png_round_trip_writes_a_file() {
        let dir = std::env::temp_dir().join(format!("degrau-png-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("x.png");
        let image = ColorImage::new([3, 2], vec![egui::Color32::RED; 6]);
        save_png(&path, &image).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn empty_path_and_curve_are_refused_in_words() {
        assert!(matches!(
            with_extension("  ", "csv"),
            Err(ExportError::NoPath)
        ));
        assert!(matches!(
            save_csv(Path::new("/tmp/x.csv"), &[], None),
            Err(ExportError::NoCurve)
        ));
    }

    /// A temporary directory of its own for one test.
    fn temp_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("degrau-export-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    const CURVES: Curves<'static> = Curves {
        curve: &[[0.0, 0.0], [1.0, 0.5]],
        compare: None,
    };

    #[test]
    fn a_csv_is_written_by_apply_and_an_existing_file_waits_for_overwrite() {
        let dir = temp_dir("apply");
        let path = dir.join("curve.csv");
        let mut export = ExportState::default();
        let apply = |e: &mut ExportState, c| e.apply(c, CURVES);
        assert_eq!(apply(&mut export, Command::Open), None);
        assert!(export.open);
        let typed = dir.join("curve.png").display().to_string();
        assert_eq!(apply(&mut export, Command::SetPath(typed)), None);
        assert_eq!(apply(&mut export, Command::Save(Ask::Csv)), None);
        assert_eq!(
            std::fs::read_to_string(&path).unwrap(),
            "t_s,y\n0,0\n1,0.5\n"
        );
        assert!(
            export
                .status(Lang::En)
                .unwrap()
                .starts_with("Saved the curve to")
        );

        std::fs::write(&path, "kept\n").unwrap();
        assert_eq!(apply(&mut export, Command::Save(Ask::Csv)), None);
        assert_eq!(export.waiting(), Some(path.as_path()));
        assert_eq!(apply(&mut export, Command::Cancel), None);
        assert_eq!(export.waiting(), None);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "kept\n");
        assert_eq!(apply(&mut export, Command::Save(Ask::Csv)), None);
        assert_eq!(apply(&mut export, Command::Overwrite), None);
        assert!(
            std::fs::read_to_string(&path)
                .unwrap()
                .starts_with("t_s,y\n")
        );

        assert_eq!(apply(&mut export, Command::Browse), Some(Outcome::Browse));
        assert_eq!(apply(&mut export, Command::Close), None);
        assert!(!export.open);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_png_closes_the_window_and_waits_for_the_next_frame() {
        let dir = temp_dir("png");
        let mut export = ExportState {
            open: true,
            path: dir.join("plot").display().to_string(),
            ..ExportState::default()
        };
        assert_eq!(
            export.apply(Command::Save(Ask::Png(Figure::StepPlot)), CURVES),
            None
        );
        assert!(!export.open, "closed before the screenshot");
        assert_eq!(
            export.pending,
            Some((Figure::StepPlot, dir.join("plot.png"))),
            "taken on the next frame"
        );
        assert!(!dir.join("plot.png").exists(), "nothing written yet");
        assert_eq!(
            export.status(Lang::Pt).as_deref(),
            Some("Capturando a tela…")
        );
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_save_without_a_path_says_so_in_the_window_language() {
        let mut export = ExportState {
            path: "  ".into(),
            ..ExportState::default()
        };
        assert_eq!(export.apply(Command::Save(Ask::Csv), CURVES), None);
        assert_eq!(
            export.status(Lang::Pt).as_deref(),
            Some("Não salvo: digite primeiro um nome de arquivo")
        );
    }
}
