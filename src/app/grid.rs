//! Grid lines and tick labels at 1-2-5 steps for the plots. egui_plot's default spacer steps
//! by powers of ten, so a plot a little too short for labels every unit jumps to labels every
//! ten units and may show a single "0" (the residual plot did); 1-2-5 steps keep several
//! labelled ticks at any height.

use std::ops::RangeInclusive;

use egui_plot::{GridInput, GridMark, uniform_grid_spacer};

/// The smallest of 1, 2, 5 × 10ᵏ at or above `x` (> 0), for grid steps here and on the
/// s-plane; a mantissa a rounding error above 1, 2 or 5 (0.2 = 2.0000000000000004 × 0.1)
/// stays there.
pub fn nice_step(x: f64) -> f64 {
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

/// A grid spacer at 1-2-5 steps.
pub fn one_two_five() -> Box<dyn Fn(GridInput) -> Vec<GridMark>> {
    uniform_grid_spacer(steps)
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
}
