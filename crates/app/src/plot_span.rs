//! A shaded span of time with its label written in full. egui_plot cuts a span's own label
//! to the span's width ("rise ti…" over a narrow rise), so the span is drawn unnamed and its
//! label is a text item beside it, at a point of the curves (a point inside their own range,
//! so the label never widens the automatic bounds), listed in the legend by that name.

use eframe::egui::{Align2, Color32, RichText, TextStyle};
use egui_plot::{PlotPoint, PlotUi, Span, Text};

/// Shades `range` (seconds) with `fill` and writes `label` at `at`, anchored by `anchor`.
pub fn labelled_span(
    plot: &mut PlotUi<'_>,
    label: String,
    range: std::ops::RangeInclusive<f64>,
    fill: Color32,
    at: [f64; 2],
    anchor: Align2,
    color: Color32,
) {
    plot.span(Span::new("", range).fill(fill));
    plot.text(
        Text::new(
            label.clone(),
            PlotPoint::new(at[0], at[1]),
            RichText::new(label).text_style(TextStyle::Body),
        )
        .anchor(anchor)
        .color(color),
    );
}
