//! Divided differences through the Opitz matrix, the stable way to evaluate a cluster of
//! nearly equal poles.
//!
//! For nodes x₁…x_m, the lower bidiagonal Opitz matrix J (x_i on the diagonal, 1 below it)
//! carries every divided difference of a function f in f(J): f(J)_{j,i} = f[x_i…x_j]
//! (Opitz 1964). Two cases are needed:
//! - a rational f = k·Π(s − z)/Π(s − p) with no pole among the nodes: the first column of
//!   f(J) is built factor by factor, a bidiagonal product for each zero and a bidiagonal
//!   forward substitution for each pole. No truncation, no cancellation beyond the
//!   problem's own (no 1/δ terms: every division is by a distance to a pole *outside*);
//! - the exponential e^{sτ} over nodes close to a centre c: e^{cτ}·exp(τ·(J − cI)), the
//!   Taylor series on τ scaled until ‖τ(x − c)‖ ≤ 1/2, then squared back (McCurdy, Ng &
//!   Parlett 1984, "Accurate computation of divided differences of the exponential
//!   function"). For real nodes every entry is positive, so the squarings cannot cancel.
//!
//! Nodes equal to each other are allowed (confluent divided differences: derivatives).

use super::poly::C64;

/// Taylor terms beyond the nilpotent part once ‖τ·d‖ ≤ [`SCALED_NORM`]: the remainder is
/// below (1/2)^19/19!·e^{1/2} < 1e-22 of the result.
const EXTRA_TERMS: usize = 19;
/// The Taylor series runs on τ/2^s with τ·max|x − c|/2^s at most this.
const SCALED_NORM: f64 = 0.5;
/// More squarings than this (τ·|x − c| > 2^60) are never needed: such a term has long
/// decayed below any representable number or is outside the range of f64 anyway.
const MAX_SQUARINGS: u32 = 60;

const ZERO: C64 = C64::new(0.0, 0.0);

/// f[x₁…x_k] for k = 1…m, f(s) = scale·Π(s − zᵢ)/Π(s − pⱼ): the first column of f(J).
/// No pole may equal a node. The zeros are applied first, then the poles in their order
/// (for a single node: the residue k·Π(x − z)·Π 1/(x − p), in that order).
pub fn rational<'a>(
    nodes: &[C64],
    scale: f64,
    zeros: &[C64],
    poles: impl IntoIterator<Item = &'a C64>,
) -> Vec<C64> {
    let mut v = vec![ZERO; nodes.len()];
    if let Some(first) = v.first_mut() {
        *first = C64::new(scale, 0.0);
    }
    zeros.iter().for_each(|&z| times_linear(&mut v, nodes, z));
    poles
        .into_iter()
        .for_each(|&p| over_linear(&mut v, nodes, p));
    v
}

/// v ← (J − zI)·v: the divided differences of (s − z)·f from those of f (Leibniz).
pub fn times_linear(v: &mut [C64], nodes: &[C64], z: C64) {
    for k in (0..v.len()).rev() {
        let below = if k > 0 { v[k - 1] } else { ZERO };
        v[k] = (nodes[k] - z) * v[k] + below;
    }
}

/// v ← (J − pI)⁻¹·v: the divided differences of f/(s − p) from those of f.
fn over_linear(v: &mut [C64], nodes: &[C64], p: C64) {
    let mut previous = ZERO;
    for (k, value) in v.iter_mut().enumerate() {
        previous = (*value - previous) * (C64::new(1.0, 0.0) / (nodes[k] - p));
        *value = previous;
    }
}

/// A lower triangular m×m matrix, row-major, full storage (m ≤ 31).
#[derive(Debug, Clone, PartialEq)]
pub struct Lower {
    m: usize,
    a: Vec<C64>,
}

impl Lower {
    fn identity(m: usize) -> Self {
        let mut a = vec![ZERO; m * m];
        (0..m).for_each(|i| a[i * m + i] = C64::new(1.0, 0.0));
        Self { m, a }
    }

    fn at(&self, j: usize, i: usize) -> C64 {
        self.a[j * self.m + i]
    }

    /// self·(h·N), N = diag(d) + subdiagonal of ones.
    fn times_opitz(&self, d: &[C64], h: f64) -> Self {
        let m = self.m;
        let mut a = vec![ZERO; m * m];
        for j in 0..m {
            for i in 0..=j {
                let right = if i < j { self.at(j, i + 1) } else { ZERO };
                a[j * m + i] = (self.at(j, i) * d[i] + right) * h;
            }
        }
        Self { m, a }
    }

    fn squared(&self) -> Self {
        let m = self.m;
        let mut a = vec![ZERO; m * m];
        for j in 0..m {
            for i in 0..=j {
                a[j * m + i] = (i..=j).map(|k| self.at(j, k) * self.at(k, i)).sum();
            }
        }
        Self { m, a }
    }

    /// row·self: the row vector r (length m) times this matrix.
    pub fn row_times(&self, row: &[C64], out: &mut [C64]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = (i..self.m).map(|j| row[j] * self.at(j, i)).sum();
        }
    }

    fn last_row(&self) -> Vec<C64> {
        self.a[(self.m - 1) * self.m..].to_vec()
    }
}

/// row ← row·(Σ_{n ≤ count} (δN)ⁿ/n!), N = diag(d) + subdiagonal of ones: the Taylor series
/// of exp(δN) on the row (each term a bidiagonal product, O(m)), which carries an advance
/// kept over h to one over h + δ, exp((h + δ)N) = exp(hN)·exp(δN), with the terms
/// [`advance_terms`] counts for |δ|·max|d| ≤ [`SCALED_NORM`]. `term` is scratch of the
/// row's length.
fn carry(row: &mut [C64], term: &mut [C64], d: &[C64], delta: f64, count: usize) {
    term.copy_from_slice(row);
    for n in 1..=count {
        let h = delta / n as f64;
        for i in 0..term.len() {
            let below = term.get(i + 1).copied().unwrap_or(ZERO);
            term[i] = (term[i] * d[i] + below) * h;
        }
        row.iter_mut().zip(term.iter()).for_each(|(r, t)| *r += t);
    }
}

/// Spacings whose exp(hN) a [`RowAdvance`] keeps.
const KEPT_SPACINGS: usize = 4;
/// Terms of the row series past which a [`RowAdvance`] with room keeps the new spacing's own
/// matrix (a term costs a few products, a matrix hundreds).
const CARRY_TERMS: usize = 4;

/// The advance of a row vector over spacings h, row ← row·exp(hN) (N = diag(d) + subdiagonal
/// of ones): exp(hN) kept for the last few distinct spacings, and a spacing near a kept one
/// carried by the row's own series ([`carry`]), so that a uniform clock costs one
/// matrix, and a jittered one (a logger's irregular instants) a handful.
#[derive(Debug, Clone)]
pub struct RowAdvance {
    d: Vec<C64>,
    radius: f64,
    kept: Vec<(f64, Lower)>,
    oldest: usize,
    term: Vec<C64>,
    next: Vec<C64>,
    /// [`advance_terms`] for |δ| up to 2^e, by e: a jittered clock asks for every instant,
    /// and its offsets fall in a few binades (the bound grows with |δ|, so a binade's top
    /// counts enough terms for all of it).
    counts: Vec<(i32, usize)>,
}

impl RowAdvance {
    /// For nodes `d` within `radius` of the centre.
    pub fn new(d: &[C64], radius: f64) -> Self {
        Self {
            d: d.to_vec(),
            radius,
            kept: Vec::with_capacity(KEPT_SPACINGS),
            oldest: 0,
            term: vec![ZERO; d.len()],
            next: vec![ZERO; d.len()],
            counts: Vec::new(),
        }
    }

    /// row ← row·exp(h·N).
    pub fn advance(&mut self, row: &mut [C64], h: f64) {
        let nearest = self
            .kept
            .iter()
            .enumerate()
            .map(|(k, (kept, _))| (k, h - kept))
            .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
            .filter(|(_, delta)| row_advance_fits(*delta, self.radius))
            .map(|(k, delta)| (k, delta, self.terms_for(row.len(), delta)));
        // A new spacing gets its own matrix while there is room, or when none kept reaches.
        let room = self.kept.len() < KEPT_SPACINGS;
        let (k, delta, count) = match nearest {
            Some(near) if near.2 <= CARRY_TERMS || !room => near,
            _ => (self.keep(h), 0.0, 0),
        };
        self.kept[k].1.row_times(row, &mut self.next);
        row.copy_from_slice(&self.next);
        carry(row, &mut self.term, &self.d, delta, count);
    }

    /// [`advance_terms`] for an offset δ, counted at the top of its binade and kept.
    fn terms_for(&mut self, m: usize, delta: f64) -> usize {
        if delta == 0.0 {
            return 0;
        }
        let binade = delta.abs().log2().floor() as i32 + 1;
        if let Some(&(_, count)) = self.counts.iter().find(|(e, _)| *e == binade) {
            return count;
        }
        let count = advance_terms(m, self.radius, 2f64.powi(binade));
        self.counts.push((binade, count));
        count
    }

    /// Keeps exp(hN) in place of the oldest kept spacing: its index.
    fn keep(&mut self, h: f64) -> usize {
        let matrix = exp_matrix(&self.d, self.radius, h);
        if self.kept.len() < KEPT_SPACINGS {
            self.kept.push((h, matrix));
            return self.kept.len() - 1;
        }
        let k = self.oldest;
        self.kept[k] = (h, matrix);
        self.oldest = (k + 1) % KEPT_SPACINGS;
        k
    }
}

/// Terms of [`carry`]'s series for `m` nodes within `radius`: where the bound of the
/// n-th term falls under 1e-18 (relative to the row). N = D + L, D diagonal (|d| ≤ radius), L
/// the subdiagonal of ones: a product of n factors with k of L's shifts every entry k places,
/// so only k < m survive, and ‖(δN)ⁿ/n!‖ ≤ Σ_{k<m} (|δ|·radius)^{n−k}/(n−k)! · |δ|^k/k!. Past
/// n = m − 1 each bound is at most |δ|·radius ≤ 1/2 of the one before, so the rest of the
/// series is under the last. A clock's rounding needs no term; a jitter of a tenth of the
/// spacing a handful.
fn advance_terms(m: usize, radius: f64, delta: f64) -> usize {
    let (u, v) = (delta.abs() * radius, delta.abs());
    if m == 0 || (u + v) < 1e-16 {
        return 0;
    }
    // q[k] = v^k/k! (k < m) and p[i] = u^i/i!, built as n grows (m ≤ 31: on the stack).
    let mut q = [0.0; 32];
    let mut p = [0.0; 64];
    if m > q.len() || terms(m) >= p.len() {
        return terms(m);
    }
    let last = terms(m);
    q[0] = 1.0;
    p[0] = 1.0;
    for k in 1..m {
        q[k] = q[k - 1] * v / k as f64;
    }
    for n in 1..=last {
        p[n] = p[n - 1] * u / n as f64;
        let bound: f64 = (0..m.min(n + 1)).map(|k| p[n - k] * q[k]).sum();
        if n + 1 >= m && bound <= 1e-18 {
            return n;
        }
    }
    terms(m)
}

/// Whether an advance by δ can be carried by [`advance_row`] over nodes within `radius`.
pub fn row_advance_fits(delta: f64, radius: f64) -> bool {
    delta.abs() * radius <= SCALED_NORM
}

/// How many halvings bring τ·radius to at most [`SCALED_NORM`].
fn squarings(tau: f64, radius: f64) -> u32 {
    let x = tau.abs() * radius;
    if x <= SCALED_NORM || !x.is_finite() {
        0
    } else {
        ((x / SCALED_NORM).log2().ceil() as u32).min(MAX_SQUARINGS)
    }
}

fn terms(m: usize) -> usize {
    m + EXTRA_TERMS
}

/// exp(τ·N) for N = diag(d) + subdiagonal of ones, |d_i| ≤ `radius`: entry (j, i) is
/// e^{uτ}[d_i…d_j].
pub fn exp_matrix(d: &[C64], radius: f64, tau: f64) -> Lower {
    let m = d.len();
    let s = squarings(tau, radius);
    let h = tau / 2f64.powi(s as i32);
    let mut sum = Lower::identity(m);
    let mut term = Lower::identity(m);
    for n in 1..=terms(m) {
        term = term.times_opitz(d, h / n as f64);
        sum.a.iter_mut().zip(&term.a).for_each(|(s, t)| *s += t);
    }
    (0..s).fold(sum, |acc, _| acc.squared())
}

/// The last row of exp(τ·N): e^{uτ}[d_k…d_m] for k = 1…m. A row-vector Taylor series
/// (O(m²)) when τ·radius is small, the full matrix with squarings otherwise.
pub fn exp_last_row(d: &[C64], radius: f64, tau: f64) -> Vec<C64> {
    let m = d.len();
    if m == 0 {
        return Vec::new();
    }
    if squarings(tau, radius) > 0 {
        return exp_matrix(d, radius, tau).last_row();
    }
    let mut term = vec![ZERO; m];
    term[m - 1] = C64::new(1.0, 0.0);
    let mut sum = term.clone();
    for n in 1..=terms(m) {
        let h = tau / n as f64;
        for i in 0..m {
            let right = if i + 1 < m { term[i + 1] } else { ZERO };
            term[i] = (term[i] * d[i] + right) * h;
        }
        sum.iter_mut().zip(&term).for_each(|(s, t)| *s += t);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64) -> C64 {
        C64::new(re, 0.0)
    }

    #[test]
    fn two_node_exponential_difference() {
        // e^{uτ}[a, b] = (e^{bτ} − e^{aτ})/(b − a), well separated so the formula is exact.
        let d = [c(-0.3), c(0.4)];
        for tau in [0.1, 1.0, 7.0, 40.0] {
            let row = exp_last_row(&d, 0.4, tau);
            let exact = ((0.4 * tau).exp() - (-0.3 * tau).exp()) / 0.7;
            assert!((row[0].re - exact).abs() < 1e-14 * exact, "τ={tau}");
            assert!((row[1].re - (0.4 * tau).exp()).abs() < 1e-14 * row[1].re);
        }
    }

    #[test]
    fn confluent_nodes_give_derivatives() {
        // e^{uτ}[0, 0, 0] = τ²/2.
        let row = exp_last_row(&[c(0.0); 3], 0.0, 3.0);
        assert!((row[0].re - 4.5).abs() < 1e-15);
        assert!((row[1].re - 3.0).abs() < 1e-15);
    }

    #[test]
    fn an_advance_carried_by_the_row_series_is_the_advance_itself() {
        // Two advances, h then h + δ (the second carried from the first's matrix by the row
        // series, or a new matrix), against the last row of exp((2h + δ)N): a clock's
        // rounding, a jitter and a δ as large as the series allows, on spread and meeting
        // nodes.
        let nodes: [&[C64]; 3] = [
            &[c(-0.004), c(0.004)],
            &[c(-0.2), c(0.05), c(0.15)],
            &[c(0.0); 3],
        ];
        for d in nodes {
            let radius = d.iter().map(|x| x.norm()).fold(0.0, f64::max);
            for (h, delta) in [
                (2.4, 3e-16),
                (2.4, 0.7),
                (2.4, -1.1),
                (10.0, 2.0),
                (1.0, 3.0),
            ] {
                let mut advance = RowAdvance::new(d, radius);
                let mut row = vec![ZERO; d.len()];
                row[d.len() - 1] = c(1.0);
                advance.advance(&mut row, h);
                advance.advance(&mut row, h + delta);
                let direct = exp_matrix(d, radius, 2.0 * h + delta).last_row();
                for (a, b) in row.iter().zip(&direct) {
                    let tolerance = 1e-14 * b.norm().max(1.0);
                    assert!((a - b).norm() <= tolerance, "{d:?} {delta}: {a} vs {b}");
                }
            }
        }
    }

    #[test]
    fn row_and_squared_matrix_agree() {
        let d = [c(-0.01), c(0.002), C64::new(0.003, 0.004), c(0.005)];
        let direct = exp_last_row(&d, 0.01, 30.0);
        let squared = exp_matrix(&d, 0.01, 30.0).last_row();
        for (a, b) in direct.iter().zip(&squared) {
            assert!((a - b).norm() < 1e-13 * b.norm(), "{a} vs {b}");
        }
    }

    #[test]
    fn rational_differences_of_a_simple_pole() {
        // (1/(s − p))[x₁…x_k] = (−1)^{k−1}... = 1/Π(x_i − p) up to sign: here 1/((x₁−p)(x₂−p)).
        let nodes = [c(-1.0), c(-1.5)];
        let v = rational(&nodes, 1.0, &[], &[c(-3.0)]);
        assert!((v[0].re - 0.5).abs() < 1e-16);
        assert!((v[1].re + 1.0 / (2.0 * 1.5)).abs() < 1e-16);
    }
}
