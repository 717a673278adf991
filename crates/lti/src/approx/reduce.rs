//! Reduced models of a system, the four approximations of the Tognetti notes:
//!
//! - **dominant poles** ([`dominant`]): keep the n poles nearest the imaginary axis (a
//!   conjugate pair stays whole), the zeros near them, and the static gain;
//! - **Taylor** ([`taylor`]): keep the n largest time constants; every neglected lag τ and
//!   every right-half-plane zero (−Ts + 1) becomes dead time, e^{−τs} ≈ 1/(τs + 1) and
//!   e^{−Ts} ≈ 1 − Ts;
//! - **Skogestad's half rule** ([`half_rule`]): as Taylor, but half of the largest
//!   neglected time constant goes to the smallest kept one and half to the dead time;
//! - **Padé moment matching** ([`moment_matching`]): G_{m,n}(s) = G(0)·(b_m s^m + … + 1) /
//!   (a_n s^n + … + 1) with G and its first m + n derivatives equal at s = 0.
//!
//! Conventions of the time-constant form: a real pole p < 0 is the lag (τs + 1), τ = −1/p;
//! a pair σ ± jω stands as one factor, ranked by its decay 1/|σ| and worth 2ζ/ωn = 2|σ|/|p|²
//! of dead time when neglected (its first moment); a left-half-plane real zero (Ts + 1)
//! (a lead) is first cancelled against the lag nearest it, (Ts + 1)/(τs + 1) ≈
//! 1/((τ − T)s + 1) (or the lead (T − τ)s + 1 when T > τ); complex zeros in the left half
//! plane stay. Poles and zeros at the origin always stay. Every method keeps the
//! low-frequency gain lim s^k·G(s) (the static gain G(0) when there is no integrator).

use serde::{Deserialize, Serialize};

use super::ApproxError;
use crate::{C64, TransferFunction};

/// A reduction method of the notes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Method {
    Dominant,
    Taylor,
    Skogestad,
    Pade,
}

impl Method {
    /// Every method, in the notes' order.
    pub const ALL: [Method; 4] = [
        Method::Dominant,
        Method::Taylor,
        Method::Skogestad,
        Method::Pade,
    ];

    /// The method's stable identifier (the CLI's `--method` value, the JSON's `method`).
    pub fn key(self) -> &'static str {
        match self {
            Method::Dominant => "dominant",
            Method::Taylor => "taylor",
            Method::Skogestad => "skogestad",
            Method::Pade => "pade",
        }
    }

    /// The target order the notes use: a pair for the dominant poles, a first order plus
    /// dead time for Taylor and Skogestad, G_{1,1} for Padé.
    pub fn default_reduction(self) -> Reduction {
        let (m, n) = match self {
            Method::Dominant => (0, 2),
            Method::Pade => (1, 1),
            Method::Taylor | Method::Skogestad => (0, 1),
        };
        Reduction { method: self, m, n }
    }
}

/// A reduction and its target: the model's order n (number of poles) and, for Padé, the
/// numerator degree m ≤ n (the other methods ignore m).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Reduction {
    pub method: Method,
    pub m: usize,
    pub n: usize,
}

/// The reduced model of `g`.
pub fn reduce(g: &TransferFunction, r: Reduction) -> Result<TransferFunction, ApproxError> {
    match r.method {
        Method::Dominant => dominant(g, r.n),
        Method::Taylor => taylor(g, r.n),
        Method::Skogestad => half_rule(g, r.n),
        Method::Pade => moment_matching(g, r.m, r.n),
    }
}

/// A real root, or a conjugate pair given by its upper member.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Factor {
    Real(f64),
    Pair(C64),
}

impl Factor {
    fn degree(self) -> usize {
        match self {
            Factor::Real(_) => 1,
            Factor::Pair(_) => 2,
        }
    }

    fn roots(self) -> Vec<C64> {
        match self {
            Factor::Real(r) => vec![C64::new(r, 0.0)],
            Factor::Pair(r) => vec![r, r.conj()],
        }
    }

    fn upper(self) -> C64 {
        match self {
            Factor::Real(r) => C64::new(r, 0.0),
            Factor::Pair(r) => r,
        }
    }

    /// Distance to the imaginary axis |σ| (1/s).
    fn decay(self) -> f64 {
        self.upper().re.abs()
    }

    /// Distance to the origin |r| (rad/s).
    fn magnitude(self) -> f64 {
        self.upper().norm()
    }

    /// Σ −1/r over the factor's roots (s): the τ of a lag, 2ζ/ωn of a stable pair; the dead
    /// time its normalised factor 1/(1 − s/r) is worth to first order.
    fn first_moment(self) -> f64 {
        self.roots().iter().map(|&r| (-1.0 / r).re).sum()
    }
}

/// The roots at the origin (counted) and the others as factors.
fn split(roots: &[C64]) -> (usize, Vec<Factor>) {
    let mut origin = 0;
    let mut factors = Vec::new();
    for &r in roots {
        if r.re == 0.0 && r.im == 0.0 {
            origin += 1;
        } else if r.im == 0.0 {
            factors.push(Factor::Real(r.re));
        } else if r.im > 0.0 {
            factors.push(Factor::Pair(r));
        }
    }
    (origin, factors)
}

use crate::tf::product_neg_nonzero as nonzero_product;

/// The low-frequency gain lim_{s→0} s^k·G(s)/s^j (k poles and j zeros at the origin): the
/// static gain G(0) of a system without roots at the origin.
pub fn low_frequency_gain(g: &TransferFunction) -> f64 {
    times_over(
        g.gain(),
        nonzero_product(g.zeros()),
        nonzero_product(g.poles()),
    )
}

/// a·b/c, with a·b first unless it leaves the normal range (a gain of 2.2e-308 times a
/// product of 2e-10 lost 8 digits as a subnormal before the division brought it back).
fn times_over(a: f64, b: f64, c: f64) -> f64 {
    let first = a * b;
    if first.is_normal() {
        first / c
    } else {
        a * (b / c)
    }
}

/// The model with these zeros, poles and dead time whose low-frequency gain is `k_low`.
fn assemble(
    zeros: &[C64],
    poles: &[C64],
    k_low: f64,
    delay: f64,
) -> Result<TransferFunction, ApproxError> {
    let gain = times_over(k_low, nonzero_product(poles), nonzero_product(zeros));
    Ok(TransferFunction::from_zpk(zeros, poles, gain)?.with_delay(delay)?)
}

/// A target order between 1 and the system's order (`equal_allowed`: the order itself).
fn check_target(g: &TransferFunction, n: usize, equal_allowed: bool) -> Result<(), ApproxError> {
    let order = g.order();
    if n == 0 {
        Err(ApproxError::OrderZero)
    } else if n > order || (n == order && !equal_allowed) {
        Err(ApproxError::NotLower { asked: n, order })
    } else {
        Ok(())
    }
}

/// The ranking methods need every pole out of the right half plane.
fn check_no_rhp_pole(g: &TransferFunction) -> Result<(), ApproxError> {
    match g.poles().iter().find(|p| p.re > 0.0) {
        Some(&p) => Err(ApproxError::UnstablePole(p)),
        None => Ok(()),
    }
}

/// The dominant-pole model of order n: the n poles nearest the imaginary axis (ties: the
/// nearest the origin; a pair cut in two is kept whole, so the order may be n + 1), every
/// zero slower than the geometric mean of the fastest kept and the slowest left-out pole's
/// magnitudes (slowest first, never more zeros than poles), the dead time, and the
/// low-frequency gain. The notes' fifth order 1/(2(s + 10)(s² + 14s + 50)(s² + 6s + 18))
/// gives (1/1000)/(s² + 6s + 18).
pub fn dominant(g: &TransferFunction, n: usize) -> Result<TransferFunction, ApproxError> {
    check_target(g, n, false)?;
    check_no_rhp_pole(g)?;
    let (origin_poles, mut poles) = split(g.poles());
    poles.sort_by(|a, b| {
        a.decay()
            .total_cmp(&b.decay())
            .then(a.magnitude().total_cmp(&b.magnitude()))
    });
    let mut kept_poles = vec![C64::new(0.0, 0.0); origin_poles];
    let (mut fastest_kept, mut slowest_left) = (0.0f64, f64::INFINITY);
    for f in poles {
        if kept_poles.len() < n {
            kept_poles.extend(f.roots());
            fastest_kept = fastest_kept.max(f.magnitude());
        } else {
            slowest_left = slowest_left.min(f.magnitude());
        }
    }
    if kept_poles.len() >= g.order() {
        // The pair cut in two, kept whole, leaves nothing out.
        return Err(ApproxError::NotLower {
            asked: kept_poles.len(),
            order: g.order(),
        });
    }
    let boundary = (fastest_kept * slowest_left).sqrt();
    let (origin_zeros, mut zeros) = split(g.zeros());
    zeros.sort_by(|a, b| a.magnitude().total_cmp(&b.magnitude()));
    let mut kept_zeros = vec![C64::new(0.0, 0.0); origin_zeros.min(kept_poles.len())];
    for z in zeros {
        if z.magnitude() < boundary && kept_zeros.len() + z.degree() <= kept_poles.len() {
            kept_zeros.extend(z.roots());
        }
    }
    assemble(&kept_zeros, &kept_poles, low_frequency_gain(g), g.delay())
}

/// Taylor's model of order n: the n largest time constants kept, every neglected one and
/// every right-half-plane zero added to the dead time. The notes:
/// K(−0.1s + 1)/((5s + 1)(3s + 1)(0.5s + 1)) → K e^{−3.6s}/(5s + 1).
pub fn taylor(g: &TransferFunction, n: usize) -> Result<TransferFunction, ApproxError> {
    lags_to_delay(g, n, false)
}

/// Skogestad's half rule to order n: as [`taylor`], but half of the largest neglected time
/// constant is added to the smallest kept one and half to the dead time (when both are real
/// lags; a pair neglected or kept last takes Taylor's rule). The notes:
/// K(−0.1s + 1)/((5s + 1)(3s + 1)(0.5s + 1)) → K e^{−2.1s}/(6.5s + 1).
pub fn half_rule(g: &TransferFunction, n: usize) -> Result<TransferFunction, ApproxError> {
    lags_to_delay(g, n, true)
}

/// A pole factor as the time-constant form sees it: a lag τ (s) or a pair.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Lag {
    Real(f64),
    Pair(C64),
}

impl Lag {
    /// The time constant it is ranked by: τ, or 1/|σ| for a pair.
    fn rank(self) -> f64 {
        match self {
            Lag::Real(tau) => tau,
            Lag::Pair(r) => 1.0 / r.re.abs(),
        }
    }

    fn degree(self) -> usize {
        match self {
            Lag::Real(_) => 1,
            Lag::Pair(_) => 2,
        }
    }

    /// The dead time it is worth when neglected (s).
    fn worth(self) -> f64 {
        match self {
            Lag::Real(tau) => tau,
            Lag::Pair(r) => Factor::Pair(r).first_moment(),
        }
    }

    fn roots(self) -> Vec<C64> {
        match self {
            Lag::Real(tau) => vec![C64::new(-1.0 / tau, 0.0)],
            Lag::Pair(r) => vec![r, r.conj()],
        }
    }
}

/// What the zeros leave: the zeros kept, the dead time they add, whether any was approximated.
struct ZerosDone {
    kept: Vec<C64>,
    delay: f64,
    approximated: bool,
}

/// Right-half-plane zeros become dead time; left-half-plane real zeros (leads) cancel against
/// the nearest real lag of `lags` (changed in place); the other zeros stay.
fn zeros_to_delay(zeros: &[Factor], lags: &mut Vec<Lag>) -> ZerosDone {
    let mut done = ZerosDone {
        kept: Vec::new(),
        delay: 0.0,
        approximated: false,
    };
    for &z in zeros {
        let root = z.upper();
        if root.re > 0.0 {
            // (1 − s/z) ≈ e^{−s/z}: the first moment of the factor, negated.
            done.delay -= z.first_moment();
            done.approximated = true;
            continue;
        }
        let Factor::Real(r) = z else {
            done.kept.extend(z.roots());
            continue;
        };
        let lead = -1.0 / r;
        let nearest = lags
            .iter()
            .enumerate()
            .filter_map(|(i, l)| match l {
                Lag::Real(tau) => Some((i, (tau / lead).ln().abs())),
                Lag::Pair(_) => None,
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i);
        let Some(i) = nearest else {
            done.kept.push(C64::new(r, 0.0));
            continue;
        };
        done.approximated = true;
        let Lag::Real(tau) = lags[i] else { continue };
        let net = tau - lead;
        if net > 0.0 {
            lags[i] = Lag::Real(net);
        } else {
            lags.remove(i);
            if net < 0.0 {
                done.kept.push(C64::new(1.0 / net, 0.0));
            }
        }
    }
    done
}

/// Taylor's rule (`half`: Skogestad's half rule) to order n.
fn lags_to_delay(
    g: &TransferFunction,
    n: usize,
    half: bool,
) -> Result<TransferFunction, ApproxError> {
    check_target(g, n, true)?;
    check_no_rhp_pole(g)?;
    let (origin_poles, poles) = split(g.poles());
    let mut lags: Vec<Lag> = poles
        .iter()
        .map(|&f| match f {
            Factor::Real(r) => Lag::Real(-1.0 / r),
            Factor::Pair(r) => Lag::Pair(r),
        })
        .collect();
    let (origin_zeros, zeros) = split(g.zeros());
    let ZerosDone {
        kept: mut kept_zeros,
        mut delay,
        approximated,
    } = zeros_to_delay(&zeros, &mut lags);
    delay += g.delay();
    lags.sort_by(|a, b| b.rank().total_cmp(&a.rank()));
    let mut count = origin_poles;
    let mut kept: Vec<Lag> = Vec::new();
    let mut neglected: Vec<Lag> = Vec::new();
    for lag in lags {
        if count < n {
            count += lag.degree();
            kept.push(lag);
        } else {
            neglected.push(lag);
        }
    }
    if neglected.is_empty() && !approximated {
        return Err(ApproxError::NothingToApproximate);
    }
    delay += neglected.iter().map(|l| l.worth()).sum::<f64>();
    if half
        && let (Some(Lag::Real(largest)), Some(Lag::Real(smallest))) =
            (neglected.first().copied(), kept.last_mut())
    {
        *smallest += largest / 2.0;
        delay -= largest / 2.0;
    }
    let mut pole_roots = vec![C64::new(0.0, 0.0); origin_poles];
    pole_roots.extend(kept.iter().flat_map(|l| l.roots()));
    kept_zeros.extend(std::iter::repeat_n(C64::new(0.0, 0.0), origin_zeros));
    assemble(&kept_zeros, &pole_roots, low_frequency_gain(g), delay)
}

/// Padé's moment matching G_{m,n} (m ≤ n): the model G(0)·(b_m s^m + … + b_1 s + 1) /
/// (a_n s^n + … + a_1 s + 1) whose value and first m + n derivatives at s = 0 equal G's,
/// dead time included (e^{−θs} = 1 − θs + …), so the model has none. Poles and zeros at the
/// origin are taken out first and put back (they count in m and n). The notes:
/// 2/((10s + 1)(s + 1)) → G_{1,1} = 2(−0.909s + 1)/(10.09s + 1).
pub fn moment_matching(
    g: &TransferFunction,
    m: usize,
    n: usize,
) -> Result<TransferFunction, ApproxError> {
    if n == 0 || m > n {
        return Err(ApproxError::PadeOrder { m, n });
    }
    let (origin_poles, poles) = split(g.poles());
    let (origin_zeros, zeros) = split(g.zeros());
    if origin_poles > n || origin_zeros > m {
        return Err(ApproxError::OriginRoots { m, n });
    }
    let (mr, nr) = (m - origin_zeros, n - origin_poles);
    let c = series(&zeros, &poles, g.delay(), mr + nr + 1);
    let (b, a) = pade_from_series(&c, mr, nr).ok_or(ApproxError::Singular { m, n })?;
    let descending = |ascending: &[f64], origin: usize| {
        let mut d: Vec<f64> = ascending.iter().rev().copied().collect();
        d.extend(std::iter::repeat_n(0.0, origin));
        d
    };
    let shape = TransferFunction::from_coeffs(
        &descending(&b, origin_zeros),
        &descending(&a, origin_poles),
    )?;
    assemble(shape.zeros(), shape.poles(), low_frequency_gain(g), 0.0)
}

/// The first `count` Taylor coefficients at s = 0 of Π(1 − s/z)/Π(1 − s/p)·e^{−θs}.
fn series(zeros: &[Factor], poles: &[Factor], delay: f64, count: usize) -> Vec<f64> {
    let one = C64::new(1.0, 0.0);
    let mut c = vec![C64::new(0.0, 0.0); count];
    c[0] = one;
    let times = |c: &mut Vec<C64>, factor: &dyn Fn(usize) -> C64| {
        let f: Vec<C64> = (0..count).map(factor).collect();
        *c = (0..count)
            .map(|k| (0..=k).map(|i| c[i] * f[k - i]).sum())
            .collect();
    };
    for z in zeros.iter().flat_map(|z| z.roots()) {
        times(&mut c, &|i| match i {
            0 => one,
            1 => -one / z,
            _ => C64::new(0.0, 0.0),
        });
    }
    for p in poles.iter().flat_map(|p| p.roots()) {
        times(&mut c, &|i| (one / p).powu(i as u32));
    }
    if delay != 0.0 {
        let mut term = one;
        let terms: Vec<C64> = (0..count)
            .map(|i| {
                if i > 0 {
                    term *= -delay / i as f64;
                }
                term
            })
            .collect();
        times(&mut c, &|i| terms[i]);
    }
    c.into_iter().map(|x| x.re).collect()
}

/// The Padé approximant [m/n] of the power series `c` (c₀ = 1): its numerator b and
/// denominator a in ascending powers, a₀ = 1; `None` when the equations are singular. The
/// series is rescaled to a time unit where its coefficients are of order one first.
pub fn pade_from_series(c: &[f64], m: usize, n: usize) -> Option<(Vec<f64>, Vec<f64>)> {
    let scale = (1..c.len())
        .map(|i| c[i].abs().powf(1.0 / i as f64))
        .fold(0.0f64, f64::max);
    let scale = if scale.is_finite() && scale > 0.0 {
        scale
    } else {
        1.0
    };
    let d: Vec<f64> = c
        .iter()
        .enumerate()
        .map(|(i, &x)| x / scale.powi(i as i32))
        .collect();
    let at = |k: isize| if k < 0 { 0.0 } else { d[k as usize] };
    // Σ_{j=1..n} a_j d_{k−j} = −d_k for k = m+1 … m+n.
    let matrix: Vec<Vec<f64>> = (0..n)
        .map(|r| {
            (0..n)
                .map(|col| at((m + 1 + r) as isize - (col + 1) as isize))
                .collect()
        })
        .collect();
    let rhs: Vec<f64> = (0..n).map(|r| -at((m + 1 + r) as isize)).collect();
    let mut a = vec![1.0];
    a.extend(solve(matrix, rhs)?);
    let b: Vec<f64> = (0..=m)
        .map(|i| {
            (0..=i.min(n))
                .map(|j| a[j] * at(i as isize - j as isize))
                .sum()
        })
        .collect();
    let unscale = |v: Vec<f64>| -> Vec<f64> {
        v.into_iter()
            .enumerate()
            .map(|(i, x)| x * scale.powi(i as i32))
            .collect()
    };
    Some((unscale(b), unscale(a)))
}

/// x with A·x = b, by Gaussian elimination with partial pivoting; `None` when a pivot is
/// below 1e-12 of the matrix's largest entry.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    let largest = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if n == 0 {
        return Some(Vec::new());
    }
    if !(largest.is_finite() && largest > 0.0) {
        return None;
    }
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() <= 1e-12 * largest {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            let f = a[row][col] / a[col][col];
            let (above, below) = a.split_at_mut(row);
            for (x, p) in below[0][col..].iter_mut().zip(&above[col][col..]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_series_of_a_lag_is_geometric() {
        // 1/(1 + 2s) = 1 − 2s + 4s² − 8s³.
        let c = series(&[], &[Factor::Real(-0.5)], 0.0, 4);
        assert_eq!(c, vec![1.0, -2.0, 4.0, -8.0]);
    }

    #[test]
    fn pade_of_a_geometric_series_is_the_lag_itself() {
        let c = [1.0, -2.0, 4.0, -8.0, 16.0];
        let (b, a) = pade_from_series(&c, 0, 1).unwrap();
        assert!((b[0] - 1.0).abs() < 1e-15 && (a[1] - 2.0).abs() < 1e-15);
        // [1/1] of the same series: the zero cancels (b₁ = 0).
        let (b, a) = pade_from_series(&c, 1, 1).unwrap();
        assert!(b[1].abs() < 1e-14 && (a[1] - 2.0).abs() < 1e-14);
    }

    #[test]
    fn a_singular_system_is_refused() {
        assert_eq!(
            solve(vec![vec![1.0, 2.0], vec![2.0, 4.0]], vec![1.0, 1.0]),
            None
        );
    }
}
