//! The Nyquist plot's geometry, with no egui: the curve cut where |L| is too large to draw
//! (a near-integrator's branch would stretch the axes past reading), and the window that
//! keeps the −1 point readable.

/// Points with |L| above this are left out of the drawing.
pub const CLIP: f64 = 1e6;
/// The part of the curve the default window is sized to: |L| ≤ this.
pub const NEAR: f64 = 4.0;
/// The smallest default window: [−2, 1] × [−1.5, 1.5].
pub const SMALLEST: ([f64; 2], [f64; 2]) = ([-2.0, -1.5], [1.0, 1.5]);

/// The pieces of `curve` (x, y) with |L| ≤ [`CLIP`], each drawn as one line.
pub fn pieces(curve: &[[f64; 2]]) -> Vec<Vec<[f64; 2]>> {
    let mut out: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut current = Vec::new();
    for &p in curve {
        let drawn = p[0].is_finite() && p[1].is_finite() && p[0].hypot(p[1]) <= CLIP;
        if drawn {
            current.push(p);
        } else if !current.is_empty() {
            out.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out
}

/// The default window (min, max): the smallest one, grown to hold the points of `curve`
/// (and their mirror) with |L| ≤ [`NEAR`], with a margin.
pub fn window(curve: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    holding(curve, NEAR)
}

/// The window of the whole curve drawn (|L| ≤ [`CLIP`]), −1 and the unit circle included.
pub fn whole(curve: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    holding(curve, CLIP)
}

/// The smallest window grown to hold the points (and their mirror) with |L| ≤ `radius`.
fn holding(curve: &[[f64; 2]], radius: f64) -> ([f64; 2], [f64; 2]) {
    let (mut min, mut max) = SMALLEST;
    for p in curve.iter().filter(|p| p[0].hypot(p[1]) <= radius) {
        min[0] = min[0].min(p[0]);
        max[0] = max[0].max(p[0]);
        let y = p[1].abs();
        min[1] = min[1].min(-y);
        max[1] = max[1].max(y);
    }
    let pad = 0.05 * (max[0] - min[0]).max(max[1] - min[1]);
    ([min[0] - pad, min[1] - pad], [max[0] + pad, max[1] + pad])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_huge_branch_is_cut_out() {
        let curve = [
            [1.0, 0.0],
            [1e7, 0.0],
            [f64::NAN, 0.0],
            [0.5, 0.5],
            [0.1, 0.1],
        ];
        let p = pieces(&curve);
        assert_eq!(p, vec![vec![[1.0, 0.0]], vec![[0.5, 0.5], [0.1, 0.1]]]);
    }

    #[test]
    fn the_window_holds_minus_one_and_the_near_curve() {
        let (min, max) = window(&[[0.2, -0.1]]);
        assert!(min[0] < -2.0 && max[0] > 1.0 && min[1] < -1.5 && max[1] > 1.5);
        let (min, max) = window(&[[-3.5, -1.0], [100.0, 0.0]]);
        assert!(min[0] < -3.5 && max[0] < 2.0, "{min:?} {max:?}");
        let (_, max) = whole(&[[-3.5, -1.0], [100.0, 0.0], [1e7, 0.0]]);
        assert!(max[0] > 100.0 && max[0] < 200.0, "{max:?}");
    }
}
