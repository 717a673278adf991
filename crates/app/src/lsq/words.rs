//! Small shared pieces of the least-squares views: numbers as the tables write them, the
//! section names, and the plot every section draws its curves on.

use eframe::egui::TextStyle;
use egui_plot::{Legend, Plot};

use crate::words::lsq_app::Phrase;
use degrau_words::Lang;

use super::commands::Section;

/// Significant digits of a number in a table.
pub const DIGITS: i32 = 5;

/// A number in a table, [`DIGITS`] significant digits in the language's separator.
pub fn num(x: f64, lang: Lang) -> String {
    lang.num(x, DIGITS)
}

/// A fit % with one decimal place's worth of digits, or a dash when it is undefined.
pub fn percent(x: f64, lang: Lang) -> String {
    if x.is_finite() {
        format!("{} %", lang.localize_number(&format!("{x:.1}")))
    } else {
        "—".into()
    }
}

/// θ written as the notes write it, `[0, 0.9, 0.3]`: [`DIGITS`] significant digits, and 0
/// for a value below 1e-12 of the largest (the rounding of an exact 0).
pub fn vector(theta: &[f64], lang: Lang) -> String {
    let scale = theta.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let shown: Vec<String> = theta
        .iter()
        .map(|&v| {
            let v = if v.abs() <= 1e-12 * scale { 0.0 } else { v };
            num(v, lang)
        })
        .collect();
    let separator = lang.pick(", ", "; ");
    format!("[{}]", shown.join(separator))
}

/// The cost J, 0 when below 1e-12 of YᵀY (`scale`): the rounding of an exact fit.
pub fn cost(j: f64, scale: f64, lang: Lang) -> String {
    num(if j.abs() <= 1e-12 * scale { 0.0 } else { j }, lang)
}

/// The name of a section's tab.
pub fn section(s: Section, lang: Lang) -> &'static str {
    match s {
        Section::Arx => Phrase::TabArx,
        Section::Example => Phrase::TabExample,
        Section::Rls => Phrase::TabRls,
        Section::Prbs => Phrase::TabPrbs,
        Section::Validation => Phrase::TabValidation,
        Section::Advisor => Phrase::TabAdvisor,
    }
    .get(lang)
}

/// (x, y) pairs of two columns.
pub fn pairs(x: &[f64], y: &[f64]) -> Vec<[f64; 2]> {
    x.iter().zip(y).map(|(&a, &b)| [a, b]).collect()
}

/// A plot against time with its legend, `height` px tall (at least 160).
pub fn time_plot(id: &str, height: f32, lang: Lang) -> Plot<'static> {
    crate::grid::app_axes(Plot::new(id), lang)
        .height(height.max(160.0))
        .x_axis_label("t (s)")
        .legend(
            Legend::default()
                .position(egui_plot::Corner::RightBottom)
                .text_style(TextStyle::Body),
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_read_as_the_notes_write_them() {
        assert_eq!(vector(&[2.0e-17, 0.9, 0.3], Lang::En), "[0, 0.9, 0.3]");
        assert_eq!(vector(&[-0.05, 1.05], Lang::Pt), "[-0,05; 1,05]");
        assert_eq!(percent(87.26, Lang::Pt), "87,3 %");
        assert_eq!(percent(f64::NAN, Lang::En), "—");
    }
}
