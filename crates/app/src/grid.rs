//! Grid lines and tick labels at 1-2-5 steps for the plots. egui_plot's default spacer steps
//! by powers of ten, so a plot a little too short for labels every unit jumps to labels every
//! ten units and may show a single "0" (the residual plot did); 1-2-5 steps keep several
//! labelled ticks at any height.
//!
//! Every grid here is capped: whatever the view (huge, tiny, non-finite bounds), at most
//! [`MAX_LINES`] lines per step size are generated in a frame, so a bad view can never
//! make a frame unbounded.

use std::ops::RangeInclusive;

use egui_plot::{GridInput, GridMark};

/// Most grid lines (and so labels) of one step size drawn in a frame.
pub const MAX_LINES: usize = 200;

/// The multiples k·`step` in [`lo`, `hi`], counted by an integer so that no float
/// increment can stall; empty when the range or step is not finite or would need more
/// than [`MAX_LINES`] lines.
pub fn multiples(lo: f64, hi: f64, step: f64) -> impl Iterator<Item = f64> {
    let ok = lo.is_finite() && hi.is_finite() && step.is_finite() && step > 0.0 && lo <= hi;
    let first = if ok { (lo / step).ceil() } else { 0.0 };
    let last = if ok { (hi / step).floor() } else { -1.0 };
    let count = last - first + 1.0;
    let count = if count.is_finite() && count >= 1.0 && count <= MAX_LINES as f64 {
        count as usize
    } else {
        0
    };
    (0..count).map(move |i| (first + i as f64) * step)
}

/// The smallest of 1, 2, 5 × 10ᵏ at or above `x` (> 0), for grid steps here and on the
/// s-plane; a mantissa a rounding error above 1, 2 or 5 (0.2 = 2.0000000000000004 × 0.1)
/// stays there.
pub fn nice_step(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    let m = x / p;
    let nice = if m <= 1.0 + 1e-9 {
        1.0
    } else if m <= 2.0 + 1e-9 {
        2.0
    } else if m <= 5.0 + 1e-9 {
        5.0
    } else {
        10.0
    };
    nice * p
}

/// The three step sizes (fine, medium, coarse) for the visible range, nested so that every
/// coarser line is also a finer one: 1-2-10, 2-10-20 or 5-10-50 (× 10ᵏ).
fn steps(input: GridInput) -> [f64; 3] {
    let base = input.base_step_size.abs();
    let fine = if base.is_finite() && base > 0.0 {
        nice_step(base)
    } else {
        1.0
    };
    let mantissa = (fine / 10f64.powf(fine.log10().floor())).round();
    let medium = if mantissa == 2.0 {
        5.0 * fine
    } else {
        2.0 * fine
    };
    [fine, medium, 10.0 * fine]
}

/// A grid spacer at 1-2-5 steps, capped at [`MAX_LINES`] marks per step size.
pub fn one_two_five() -> Box<dyn Fn(GridInput) -> Vec<GridMark>> {
    Box::new(marks)
}

/// The marks of the three nested step sizes, each value once with its coarsest step.
fn marks(input: GridInput) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    let sizes = steps(input);
    let mut all: Vec<GridMark> = sizes
        .iter()
        .flat_map(|&step_size| {
            multiples(lo, hi, step_size).map(move |value| GridMark { value, step_size })
        })
        .collect();
    all.sort_by(|a, b| a.value.total_cmp(&b.value));
    let eps = 0.1 * sizes[0];
    let mut out: Vec<GridMark> = Vec::with_capacity(all.len());
    for mark in all {
        match out.last_mut() {
            Some(last) if (last.value - mark.value).abs() < eps => {
                if mark.step_size > last.step_size {
                    *last = mark;
                }
            }
            _ => out.push(mark),
        }
    }
    out
}

/// `plot` with the app's axes: 1-2-5 grid steps on y and tick labels with the decimals their
/// steps need, in `lang`'s numbers (0,5 in Portuguese) on both axes.
pub fn app_axes(plot: egui_plot::Plot<'_>, lang: degrau_words::Lang) -> egui_plot::Plot<'_> {
    plot.y_grid_spacer(one_two_five())
        .x_axis_formatter(move |m, r| lang.localize_number(&tick_label(m, r)))
        .y_axis_formatter(move |m, r| lang.localize_number(&tick_label(m, r)))
}

/// A tick label with as many decimals as its step needs (0.5 → "0.5", not egui_plot's "0").
pub fn tick_label(mark: GridMark, _range: &RangeInclusive<f64>) -> String {
    let decimals = (-mark.step_size.log10() - 1e-9).ceil().max(0.0) as usize;
    format!("{:.*}", decimals, mark.value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_go_one_two_five() {
        assert_eq!(nice_step(0.7), 1.0);
        assert_eq!(nice_step(1.0), 1.0);
        assert_eq!(nice_step(1.3), 2.0);
        assert_eq!(nice_step(3.0), 5.0);
        assert_eq!(nice_step(6.0), 10.0);
        assert!((nice_step(0.031) - 0.05).abs() < 1e-15);
        assert_eq!(nice_step(0.2), 0.2, "a rounding error above 2 stays at 2");
        let at = |base: f64| {
            steps(GridInput {
                bounds: (-5.0, 5.0),
                base_step_size: base,
            })
        };
        assert_eq!(at(0.08), [0.1, 0.2, 1.0]);
        assert_eq!(at(1.5), [2.0, 10.0, 20.0]);
        assert_eq!(at(4.0), [5.0, 10.0, 50.0]);
        let label =
            |value: f64, step_size: f64| tick_label(GridMark { value, step_size }, &(0.0..=1.0));
        assert_eq!(label(0.5, 0.5), "0.5");
        assert_eq!(label(-0.4, 0.2), "-0.4");
        assert_eq!(label(0.3, 0.1), "0.3");
        assert_eq!(label(0.05, 0.05), "0.05");
        assert_eq!(label(20.0, 10.0), "20");
    }

    #[test]
    fn multiples_are_counted_and_capped() {
        let v: Vec<f64> = multiples(-0.25, 1.0, 0.5).collect();
        assert_eq!(v, vec![0.0, 0.5, 1.0]);
        // A range where k += 1 would not change k (k ≈ 5e21; the ±2e8 is below the
        // precision of 5e29) gives one line rather than an endless loop.
        assert_eq!(multiples(-5e29 - 2e8, -5e29 + 2e8, 1e8).count(), 1);
        assert_eq!(multiples(0.0, 1e6, 1.0).count(), 0, "over the cap");
        assert_eq!(multiples(0.0, 199.0, 1.0).count(), MAX_LINES);
        assert_eq!(multiples(f64::NEG_INFINITY, 1.0, 1.0).count(), 0);
        assert_eq!(multiples(0.0, 1.0, 0.0).count(), 0);
        assert_eq!(multiples(0.0, f64::NAN, 1.0).count(), 0);
    }

    #[test]
    fn plot_marks_stay_bounded_for_any_bounds() {
        for (bounds, base) in [
            ((-1e300, 1e300), 0.0),
            ((f64::NEG_INFINITY, f64::INFINITY), f64::NAN),
            ((1e30, 1e30 + 1e15), 1e-3),
            ((0.0, 10.0), 1e-12),
        ] {
            let m = marks(GridInput {
                bounds,
                base_step_size: base,
            });
            assert!(m.len() <= 3 * MAX_LINES, "{bounds:?}: {}", m.len());
        }
        let m = marks(GridInput {
            bounds: (-0.05, 2.05),
            base_step_size: 0.08,
        });
        let values: Vec<f64> = m.iter().map(|m| m.value).collect();
        assert_eq!(values.len(), 21, "0, 0.1, …, 2 once each: {values:?}");
        assert_eq!(m[10].step_size, 1.0, "1 carries the coarse step");
        assert_eq!(m[2].step_size, 0.2);
        assert_eq!(m[1].step_size, 0.1);
    }
}
