//! Two real lags the record cannot tell apart. A model with lags a ≥ b depends on them only
//! through (1 + a·s)(1 + b·s), which is even in their half-difference: the response is the
//! same function of (m, q), m = (a + b)/2 and q = ((a − b)/2)², smooth across a = b, where
//! the lags themselves are a fold (their two Jacobian columns equal, the usual s²(JᵀJ)⁻¹
//! singular, and near it every interval absurdly wide). The fit reads the covariance in
//! (m, q) instead, and the lags' 95 % intervals as their ranges over the 95 % region of
//! (m, q) with q ≥ 0 (real lags); this module owns that projection. Pure: no fitting here.

/// The least relative step of the squared half-difference q, in units of m² (a second
/// derivative at the fold: the step of the half-difference is about ε^¼ of m there).
pub const Q_STEP: f64 = 1e-6;

/// How many points of the region's boundary are read for the lags' ranges: the extremes
/// are found within (π/n)² of the ellipse's size.
const BOUNDARY_POINTS: usize = 2880;

/// (m, q) of two lags: their mean and their squared half-difference.
pub fn mean_and_square(a: f64, b: f64) -> (f64, f64) {
    let half = (a - b) / 2.0;
    ((a + b) / 2.0, half * half)
}

/// The lags (larger, smaller) of (m, q), q ≥ 0.
pub fn lags_of(m: f64, q: f64) -> (f64, f64) {
    let half = q.max(0.0).sqrt();
    (m + half, m - half)
}

/// The 95 % ranges of the larger and of the smaller lag: their least and greatest values
/// over {v : (v − v̂)ᵀ C⁻¹ (v − v̂) ≤ t²} ∩ {q ≥ 0}, v = (m, q), `c` the covariance of
/// (m, q) and `t` the one-parameter quantile (so that the range of any linear function of
/// (m, q) is its usual t·σ interval). Both lags are monotone in m and in q (the larger
/// rises with both, the smaller rises with m and falls with q), so their extremes lie on
/// the region's border: the ellipse's arc with q ≥ 0, sampled, and the segment of q = 0
/// inside it, exact. `None` when the covariance is not one (not finite, a negative
/// variance).
pub fn lag_ranges(
    (m, q): (f64, f64),
    c: [[f64; 2]; 2],
    t: f64,
) -> Option<((f64, f64), (f64, f64))> {
    let (cmm, cmq, cqq) = (c[0][0], c[0][1], c[1][1]);
    if !(cmm >= 0.0 && cqq >= 0.0 && [cmm, cmq, cqq, m, q, t].iter().all(|v| v.is_finite())) {
        return None;
    }
    // Cholesky factor of C (its second pivot floored at 0 when C is singular).
    let l11 = cmm.sqrt();
    let l21 = if l11 > 0.0 { cmq / l11 } else { 0.0 };
    let l22 = (cqq - l21 * l21).max(0.0).sqrt();
    let mut larger = (f64::INFINITY, f64::NEG_INFINITY);
    let mut smaller = larger;
    let mut take = |mv: f64, qv: f64| {
        let (a, b) = lags_of(mv, qv);
        larger = (larger.0.min(a), larger.1.max(a));
        smaller = (smaller.0.min(b), smaller.1.max(b));
    };
    take(m, q);
    for k in 0..BOUNDARY_POINTS {
        let phi = std::f64::consts::TAU * k as f64 / BOUNDARY_POINTS as f64;
        let (cos, sin) = (phi.cos(), phi.sin());
        let qv = q + t * (l21 * cos + l22 * sin);
        if qv >= 0.0 {
            take(m + t * l11 * cos, qv);
        }
    }
    for mv in equal_lags_within(m, q, (l11, l21, l22), t) {
        take(mv, 0.0);
    }
    Some((larger, smaller))
}

/// The ends of the segment q = 0 inside the region (equal lags the record allows), in m:
/// v = v̂ + t·L·w with |w| ≤ 1 and q = 0 fixes w₁·l21 + w₂·l22 = −q̂/t; m = m̂ + t·l11·w₁.
fn equal_lags_within(m: f64, q: f64, (l11, l21, l22): (f64, f64, f64), t: f64) -> Vec<f64> {
    let target = -q / t;
    let norm = (l21 * l21 + l22 * l22).sqrt();
    if norm.is_nan() || norm <= 0.0 || target.abs() > norm {
        return Vec::new();
    }
    // The chord of the unit circle on the line w·(l21, l22) = target: its point nearest the
    // origin and its half-length along the line's direction (−l22, l21)/norm.
    let (n1, n2) = (l21 / norm, l22 / norm);
    let along = (1.0 - (target / norm).powi(2)).max(0.0).sqrt();
    let (c1, d1) = (n1 * target / norm, -n2);
    [c1 + along * d1, c1 - along * d1]
        .into_iter()
        .map(|w1| m + t * l11 * w1)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn lags_round_trip_through_mean_and_square() {
        for (a, b) in [(3.0, 1.0), (2.0, 2.0), (10.0, 0.5)] {
            let (m, q) = mean_and_square(a, b);
            let (x, y) = lags_of(m, q);
            assert!(close(x, a, 1e-15) && close(y, b, 1e-15), "{a} {b}: {x} {y}");
        }
        // (1 + a s)(1 + b s) = 1 + 2m s + (m² − q) s².
        let (m, q) = mean_and_square(3.0, 1.0);
        assert!(close(2.0 * m, 4.0, 1e-15) && close(m * m - q, 3.0, 1e-15));
    }

    #[test]
    fn well_resolved_lags_get_the_delta_method_intervals() {
        // Lags 4 and 2 (m = 3, q = 1) known to about 1e-4: the ranges are the linearised
        // intervals of a = m + √q and b = m − √q, t·√(gᵀCg) with g = (1, ±1/(2√q)).
        let (m, q) = (3.0, 1.0);
        let c = [[1e-8, 2e-9], [2e-9, 4e-8]];
        let t = 1.96;
        let ((alo, ahi), (blo, bhi)) = lag_ranges((m, q), c, t).unwrap();
        let sd = |s: f64| (c[0][0] + 2.0 * s * 0.5 * c[0][1] + 0.25 * c[1][1]).sqrt();
        let (ha, hb) = (t * sd(1.0), t * sd(-1.0));
        assert!(
            close(ahi - 4.0, ha, 1e-3) && close(4.0 - alo, ha, 1e-3),
            "{alo} {ahi} {ha}"
        );
        assert!(
            close(bhi - 2.0, hb, 1e-3) && close(2.0 - blo, hb, 1e-3),
            "{blo} {bhi} {hb}"
        );
    }

    #[test]
    fn at_the_fold_the_ranges_open_by_the_root_of_q() {
        // Equal lags m̂ = 5; m alone known to ±0.1, q to ±0.36 (t·σ), uncorrelated: the
        // region is m = 5 + 0.1 cos φ, q = 0.36 sin φ (sin φ ≥ 0) and the segment q = 0,
        // m ∈ [4.9, 5.1]. The larger lag's greatest is max 5 + 0.1 cos φ + 0.6 √sin φ
        // (read here on a fine grid), its least 4.9 (equal lags at the segment's left end);
        // the smaller's least is min 5 + 0.1 cos φ − 0.6 √sin φ, its greatest 5.1.
        let t = 2.0;
        let c = [[(0.1 / t) * (0.1 / t), 0.0], [0.0, (0.36 / t) * (0.36 / t)]];
        let ((alo, ahi), (blo, bhi)) = lag_ranges((5.0, 0.0), c, t).unwrap();
        let grid = |sign: f64| {
            (0..=1_000_000).map(move |k| {
                let phi = std::f64::consts::PI * k as f64 / 1e6;
                5.0 + 0.1 * phi.cos() + sign * 0.6 * phi.sin().max(0.0).sqrt()
            })
        };
        let top = grid(1.0).fold(f64::NEG_INFINITY, f64::max);
        let bottom = grid(-1.0).fold(f64::INFINITY, f64::min);
        assert!(top > 5.6 && close(ahi, top, 1e-5), "{ahi} {top}");
        assert!(bottom < 4.4 && close(blo, bottom, 1e-5), "{blo} {bottom}");
        assert!(close(alo, 4.9, 1e-12), "{alo}");
        assert!(close(bhi, 5.1, 1e-12), "{bhi}");
        // With m exact, the ends are exactly m̂ ± √(t·σq).
        let c = [[0.0, 0.0], [0.0, (0.36 / t) * (0.36 / t)]];
        let ((alo, ahi), (blo, bhi)) = lag_ranges((5.0, 0.0), c, t).unwrap();
        assert!(
            close(ahi, 5.6, 1e-12) && close(blo, 4.4, 1e-12),
            "{ahi} {blo}"
        );
        assert!(
            close(alo, 5.0, 1e-12) && close(bhi, 5.0, 1e-12),
            "{alo} {bhi}"
        );
    }

    #[test]
    fn the_equal_lags_segment_is_where_the_ellipse_meets_q_zero() {
        // A correlated C; the segment's ends lie on the ellipse: (v − v̂)ᵀC⁻¹(v − v̂) = t².
        let c: [[f64; 2]; 2] = [[0.04, 0.01], [0.01, 0.09]];
        let (m, q, t) = (2.0, 0.2, 1.5);
        let l11 = c[0][0].sqrt();
        let l21 = c[0][1] / l11;
        let l22 = (c[1][1] - l21 * l21).sqrt();
        let ends = equal_lags_within(m, q, (l11, l21, l22), t);
        assert_eq!(ends.len(), 2);
        let det = c[0][0] * c[1][1] - c[0][1] * c[0][1];
        for e in ends {
            let (dm, dq) = (e - m, -q);
            let form = (c[1][1] * dm * dm - 2.0 * c[0][1] * dm * dq + c[0][0] * dq * dq) / det;
            assert!(close(form, t * t, 1e-12), "{form}");
        }
        // An ellipse that does not reach q = 0 has no segment.
        assert!(equal_lags_within(m, 10.0, (l11, l21, l22), t).is_empty());
    }

    #[test]
    fn a_covariance_that_is_none_gives_no_ranges() {
        assert!(lag_ranges((1.0, 0.0), [[-1.0, 0.0], [0.0, 1.0]], 2.0).is_none());
        assert!(lag_ranges((1.0, 0.0), [[f64::NAN, 0.0], [0.0, 1.0]], 2.0).is_none());
    }
}
