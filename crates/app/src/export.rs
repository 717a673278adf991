//! Saving figures and data: the step plot or the whole window as PNG (from a screenshot of
//! the real window, taken once the dialog has closed) and the sampled curve as CSV. The
//! path is typed or chosen with a file dialog; a file that exists is overwritten only when
//! the student confirms; the outcome is reported in words, in the app's language.

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
}

/// What happened, said in the dialog.
#[derive(Debug)]
enum Outcome {
    Taking,
    SavedPng(PathBuf),
    SavedCurve(PathBuf),
    Failed(ExportError),
}

impl Outcome {
    fn text(&self, lang: Lang) -> String {
        match self {
            Outcome::Taking => T::Taking.get(lang).to_string(),
            Outcome::SavedPng(p) => format!("{} {}", T::Saved.get(lang), p.display()),
            Outcome::SavedCurve(p) => format!("{} {}", T::SavedCurve.get(lang), p.display()),
            Outcome::Failed(e) => format!("{} {}", T::NotSaved.get(lang), e.text(lang)),
        }
    }
}

/// The export window's state. A PNG is taken on the first frame after the window has
/// closed (so the image never shows the dialog), and the window opens again to say how it
/// went; a file that exists is overwritten only once the student says so.
pub struct ExportState {
    pub open: bool,
    pub path: String,
    status: Option<Outcome>,
    /// A save waiting for "Overwrite".
    confirm: Option<Save>,
    /// A PNG to take once the window is closed.
    pending: Option<(Figure, PathBuf)>,
    results: (Sender<Outcome>, Receiver<Outcome>),
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

    /// Shows the window; `plot_rect` is where the step plot was drawn this frame.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        plot_rect: Option<Rect>,
        curve: &[[f64; 2]],
        compare: Option<&[[f64; 2]]>,
        lang: Lang,
    ) {
        while let Ok(outcome) = self.results.1.try_recv() {
            self.status = Some(outcome);
            self.open = true;
        }
        if let Some((figure, path)) = self.pending.take() {
            // The window was not drawn this frame: the screenshot shows the app alone.
            self.take_png(ctx, figure, path, plot_rect);
            return;
        }
        // A closed window is not shown at all: egui keeps showing a window whose `open` is
        // false until its fade-out animation ends (at full opacity with `fade_out(false)`),
        // which put the dialog, "Taking the screenshot…", into "Save window as PNG".
        if !self.open {
            return;
        }
        let mut open = self.open;
        egui::Window::new(T::ExportTitle.get(lang))
            .open(&mut open)
            .resizable(false)
            .show(ctx, |ui| {
                self.contents(ui, curve, compare, lang);
            });
        self.open = open && self.open;
    }

    fn contents(
        &mut self,
        ui: &mut Ui,
        curve: &[[f64; 2]],
        compare: Option<&[[f64; 2]]>,
        lang: Lang,
    ) {
        ui.horizontal(|ui| {
            let name = ui.label(T::FileLabel.get(lang));
            ui.add(egui::TextEdit::singleline(&mut self.path).desired_width(360.0))
                .labelled_by(name.id);
            if ui.button(T::Browse.get(lang)).clicked()
                && let Some(p) = rfd::FileDialog::new()
                    .set_file_name("degrau_step.png")
                    .save_file()
            {
                self.path = p.display().to_string();
            }
        });
        let mut asked = None;
        ui.horizontal_wrapped(|ui| {
            if ui.button(T::SavePlotPng.get(lang)).clicked() {
                asked =
                    Some(with_extension(&self.path, "png").map(|p| Save::Png(Figure::StepPlot, p)));
            }
            if ui.button(T::SaveWindowPng.get(lang)).clicked() {
                asked =
                    Some(with_extension(&self.path, "png").map(|p| Save::Png(Figure::Window, p)));
            }
            if ui.button(T::SaveCsv.get(lang)).clicked() {
                asked = Some(with_extension(&self.path, "csv").map(Save::Csv));
            }
        });
        match asked {
            Some(Ok(save)) if save.path().exists() => self.confirm = Some(save),
            Some(Ok(save)) => self.save(ui.ctx(), save, curve, compare),
            Some(Err(e)) => self.status = Some(Outcome::Failed(e)),
            None => {}
        }
        if let Some(save) = self.confirm.clone() {
            ui.horizontal_wrapped(|ui| {
                ui.label(format!("{} {}", save.path().display(), T::Exists.get(lang)));
                if ui.button(T::Overwrite.get(lang)).clicked() {
                    self.confirm = None;
                    self.save(ui.ctx(), save, curve, compare);
                }
                if ui.button(T::Cancel.get(lang)).clicked() {
                    self.confirm = None;
                }
            });
        }
        if let Some(status) = &self.status {
            ui.add(egui::Label::new(status.text(lang)).wrap());
        }
    }

    fn save(
        &mut self,
        ctx: &egui::Context,
        save: Save,
        curve: &[[f64; 2]],
        compare: Option<&[[f64; 2]]>,
    ) {
        match save {
            Save::Csv(path) => {
                self.status = Some(match save_csv(&path, curve, compare) {
                    Ok(()) => Outcome::SavedCurve(path),
                    Err(e) => Outcome::Failed(e),
                });
            }
            Save::Png(figure, path) => {
                // Close the window first; the PNG is taken on the next frame.
                self.open = false;
                self.status = Some(Outcome::Taking);
                self.pending = Some((figure, path));
                ctx.request_repaint();
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
            let outcome = match save_png(&path, &cropped) {
                Ok(()) => Outcome::SavedPng(path),
                Err(e) => Outcome::Failed(e),
            };
            let _ = sender.send(outcome);
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
}
