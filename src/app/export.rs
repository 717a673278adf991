//! Saving figures and data: the step plot or the whole window as PNG (from a screenshot of
//! the real window) and the sampled curve as CSV. The path is typed or chosen with a file
//! dialog; the outcome is reported in words.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, channel};

use eframe::egui::{self, ColorImage, Rect, Ui};

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

/// Which figure a PNG export takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Figure {
    StepPlot,
    Window,
}

/// The export window's state.
pub struct ExportState {
    pub open: bool,
    pub path: String,
    pub status: Option<String>,
    results: (Sender<String>, Receiver<String>),
}

impl Default for ExportState {
    fn default() -> Self {
        Self {
            open: false,
            path: default_path("degrau_step.png"),
            status: None,
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
    /// Shows the window; `plot_rect` is where the step plot was drawn last frame.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        plot_rect: Option<Rect>,
        curve: &[[f64; 2]],
        compare: Option<&[[f64; 2]]>,
    ) {
        while let Ok(message) = self.results.1.try_recv() {
            self.status = Some(message);
        }
        let mut open = self.open;
        egui::Window::new("Export")
            .open(&mut open)
            .resizable(false)
            .show(ctx, |ui| {
                self.contents(ui, plot_rect, curve, compare);
            });
        self.open = open;
    }

    fn contents(
        &mut self,
        ui: &mut Ui,
        plot_rect: Option<Rect>,
        curve: &[[f64; 2]],
        compare: Option<&[[f64; 2]]>,
    ) {
        ui.horizontal(|ui| {
            ui.label("File");
            ui.add(egui::TextEdit::singleline(&mut self.path).desired_width(360.0));
            if ui.button("Browse…").clicked()
                && let Some(p) = rfd::FileDialog::new()
                    .set_file_name("degrau_step.png")
                    .save_file()
            {
                self.path = p.display().to_string();
            }
        });
        ui.horizontal(|ui| {
            if ui.button("Save step plot as PNG").clicked() {
                self.request_png(ui.ctx(), Figure::StepPlot, plot_rect);
            }
            if ui.button("Save window as PNG").clicked() {
                self.request_png(ui.ctx(), Figure::Window, None);
            }
            if ui.button("Save curve as CSV").clicked() {
                let path = with_extension(&self.path, "csv");
                self.status = Some(
                    match path.and_then(|p| save_csv(&p, curve, compare).map(|_| p)) {
                        Ok(p) => format!("Saved the curve to {}", p.display()),
                        Err(e) => format!("Not saved: {e}"),
                    },
                );
            }
        });
        if let Some(status) = &self.status {
            ui.label(status);
        }
    }

    fn request_png(&mut self, ctx: &egui::Context, figure: Figure, plot_rect: Option<Rect>) {
        let path = match with_extension(&self.path, "png") {
            Ok(p) => p,
            Err(e) => {
                self.status = Some(format!("Not saved: {e}"));
                return;
            }
        };
        let region = match figure {
            Figure::StepPlot => plot_rect,
            Figure::Window => None,
        };
        let pixels_per_point = ctx.pixels_per_point();
        let sender = self.results.0.clone();
        let repaint = ctx.clone();
        self.status = Some("Taking the screenshot…".into());
        ctx.request_screenshot(move |image: Arc<ColorImage>| {
            let cropped = match region {
                Some(r) => image.region(&r, Some(pixels_per_point)),
                None => (*image).clone(),
            };
            let message = match save_png(&path, &cropped) {
                Ok(()) => format!("Saved {}", path.display()),
                Err(e) => format!("Not saved: {e}"),
            };
            let _ = sender.send(message);
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
