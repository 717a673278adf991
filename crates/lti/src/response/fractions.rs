//! From a transfer function to its step response's terms: the poles grouped into clusters,
//! their partial fractions, the geometry that bounds each term, and the checks that the
//! result is representable.

use super::*;

/// The time after which w·|q|·τ^j·e^{στ} stays below `eps` (σ < 0); infinite if σ ≥ 0.
pub(super) fn term_decay_time(magnitude: f64, j: usize, sigma: f64, eps: f64) -> f64 {
    if magnitude == 0.0 {
        return 0.0;
    }
    if sigma >= 0.0 {
        return f64::INFINITY;
    }
    let rate = -sigma;
    let j = j as f64;
    // h(τ) = ln|q| + j ln τ − rate τ − ln eps is concave; start where it decreases.
    let (log_magnitude, log_eps) = (magnitude.ln(), eps.ln());
    let h =
        |tau: f64| log_magnitude + if j > 0.0 { j * tau.ln() } else { 0.0 } - rate * tau - log_eps;
    let mut tau = if j > 0.0 { 2.0 * j / rate } else { 0.0 };
    for _ in 0..60 {
        let value = h(tau);
        if value <= 0.0 {
            return tau;
        }
        let slope = if j > 0.0 { j / tau } else { 0.0 } - rate;
        // Newton on a concave decreasing function steps past the root: a safe bound.
        tau -= value / slope;
    }
    tau
}

/// The final value theorem as a check of the partial fractions: the constant term (the
/// step's pole at the origin) must be A·G(0). It fails only when the poles span so many
/// decades that the products of the residue formula leave the range of f64 (s² + 1e200·s + 1
/// came out as y(t) = 0); the response is then refused rather than shown wrong.
pub(super) fn check_final_value(clusters: &[Cluster], expected: f64) -> Result<(), LtiError> {
    let constant: f64 = clusters
        .iter()
        .filter(|c| c.center == C64::new(0.0, 0.0))
        .map(|c| c.coeffs.first().map_or(0.0, |q| q.re))
        .sum();
    if (constant - expected).abs() <= 1e-6 * expected.abs() {
        Ok(())
    } else {
        Err(LtiError::OutOfRange)
    }
}

/// Refuses a final value A·G(0) that fell below the normal range of f64 (or to 0 without
/// a zero at the origin): the metrics are measured in units of it.
pub(super) fn check_representable(
    final_value: Option<f64>,
    tf: &TransferFunction,
    amplitude: f64,
) -> Result<(), LtiError> {
    let Some(value) = final_value else {
        return Ok(());
    };
    let lost = value.is_subnormal() || (value == 0.0 && tf.system_type() == 0);
    let scale = amplitude * tf.gain();
    if lost || !scale.is_normal() {
        return Err(LtiError::Underflow {
            what: if lost {
                Quantity::FinalValue
            } else {
                Quantity::AmplitudeTimesGain
            },
            value: if lost { value } else { scale },
        });
    }
    Ok(())
}

/// The poles' moduli and their distances, each |·| (a hypot) computed once for the whole
/// grouping rather than again for every pair at every tolerance tried.
pub(super) struct Geometry<'a> {
    poles: &'a [C64],
    norms: Vec<f64>,
    /// |pᵢ − pⱼ|, row-major.
    distances: Vec<f64>,
}

impl<'a> Geometry<'a> {
    pub(super) fn new(poles: &'a [C64]) -> Self {
        let n = poles.len();
        let mut distances = vec![0.0; n * n];
        for i in 0..n {
            for j in i + 1..n {
                let d = (poles[i] - poles[j]).norm();
                distances[i * n + j] = d;
                distances[j * n + i] = d;
            }
        }
        Self {
            poles,
            norms: poles.iter().map(|p| p.norm()).collect(),
            distances,
        }
    }

    pub(super) fn distance(&self, i: usize, j: usize) -> f64 {
        self.distances[i * self.poles.len() + j]
    }

    /// How far apart two poles are, relative to the larger modulus (0 when equal).
    pub(super) fn gap(&self, i: usize, j: usize) -> f64 {
        let d = self.distance(i, j);
        if d == 0.0 {
            0.0
        } else {
            d / self.norms[i].max(self.norms[j])
        }
    }

    /// Single-linkage labels: poles within `tolerance` (relative) of each other, directly or
    /// through a chain, share a label.
    pub(super) fn single_linkage(&self, tolerance: f64) -> Vec<usize> {
        let n = self.poles.len();
        let mut label: Vec<usize> = (0..n).collect();
        for i in 0..n {
            for j in (i + 1)..n {
                if self.gap(i, j) <= tolerance && label[i] != label[j] {
                    let (keep, drop) = (label[i], label[j]);
                    label
                        .iter_mut()
                        .filter(|l| **l == drop)
                        .for_each(|l| *l = keep);
                }
            }
        }
        label
    }

    /// Whether some group's partial fractions amplify rounding by more than
    /// [`AMPLIFICATION_LIMIT`]: Π_{p outside}|p|/|c − p| (c the group's centre, p ≠ 0), how
    /// much larger than the final value the group's terms are.
    pub(super) fn amplifies(&self, partition: &Partition) -> bool {
        partition.groups().enumerate().any(|(g, group)| {
            // A lone pole is its own centre: its distances are already known.
            let center = mean(group.iter().map(|&i| self.poles[i]));
            let from_center = |j: usize| match group[..] {
                [i] => self.distance(i, j),
                _ => (center - self.poles[j]).norm(),
            };
            let log: f64 = partition
                .groups()
                .enumerate()
                .filter(|&(h, _)| h != g)
                .flat_map(|(_, members)| members.iter().copied())
                .filter(|&j| self.norms[j] > 0.0)
                .map(|j| (self.norms[j] / from_center(j)).ln())
                .sum();
            log.exp() > AMPLIFICATION_LIMIT
        })
    }
}

/// The poles grouped by label: the indices of each group in a row, the groups in order of
/// their first member, each group's members in their own order.
pub(super) struct Partition {
    index: Vec<usize>,
    /// Where each group starts in `index`, and its end.
    bounds: Vec<usize>,
}

impl Partition {
    pub(super) fn new(label: &[usize]) -> Self {
        let mut index = Vec::with_capacity(label.len());
        let mut bounds = vec![0];
        for (i, &l) in label.iter().enumerate() {
            if index.iter().all(|&k| label[k] != l) {
                index.extend((i..label.len()).filter(|&k| label[k] == l));
                bounds.push(index.len());
            }
        }
        Self { index, bounds }
    }

    pub(super) fn groups(&self) -> impl Iterator<Item = &[usize]> {
        self.bounds.windows(2).map(|w| &self.index[w[0]..w[1]])
    }
}

pub(super) fn mean(poles: impl ExactSizeIterator<Item = C64>) -> C64 {
    let n = poles.len();
    poles.sum::<C64>() / n as f64
}

/// Groups the poles of Y(s) into clusters: single linkage at [`MERGE_RELATIVE`], then at the
/// next larger gap while some group's partial fractions would amplify rounding by more than
/// [`AMPLIFICATION_LIMIT`] (ten poles 2 % apart: about 1e8), up to [`MAX_MERGE_GAP`].
///
/// Closeness is relative to the poles' own modulus only. A tolerance relative to the fastest
/// pole merged the step's pole at the origin with a slow pole (s² + 1e7·s + 1: 0 and −1e−7
/// next to −1e7); the origin is never within a relative gap below 1 of another pole, so it
/// stays alone (or with the integrators exactly at 0).
pub(super) fn group_poles(poles: &[C64]) -> Partition {
    let geometry = Geometry::new(poles);
    let mut tolerance = MERGE_RELATIVE;
    loop {
        let label = geometry.single_linkage(tolerance);
        let groups = Partition::new(&label);
        if !geometry.amplifies(&groups) {
            return groups;
        }
        let next = (0..poles.len())
            .flat_map(|i| (i + 1..poles.len()).map(move |j| (i, j)))
            .filter(|&(i, j)| label[i] != label[j])
            .map(|(i, j)| geometry.gap(i, j))
            .fold(f64::INFINITY, f64::min);
        if next > MAX_MERGE_GAP {
            return groups;
        }
        tolerance = next;
    }
}

/// One group as a cluster of Y(s) = scale·Π(s − z)/Π(s − p): `None` for the mirror image of
/// a complex group (its partner above the axis stands for both).
pub(super) fn make_cluster<'a>(
    group: &[C64],
    others: impl Iterator<Item = &'a C64> + Clone,
    zeros: &[C64],
    scale: f64,
) -> Option<Cluster> {
    let m = group.len();
    let repeated = group.iter().all(|&p| p == group[0]);
    let self_conjugate = group.iter().any(|p| p.im <= 0.0) && group.iter().any(|p| p.im >= 0.0);
    let center = if repeated {
        group[0]
    } else {
        mean(group.iter().copied())
    };
    let (center, weight) = if self_conjugate {
        (C64::new(center.re, 0.0), 1.0)
    } else if center.im > 0.0 {
        (center, 2.0)
    } else {
        return None;
    };
    let norms = |q: &[C64]| q.iter().map(|q| q.norm()).collect();
    let (coeffs, bound, spread) = if repeated {
        let coeffs = taylor_to_powers(divided::rational(&vec![center; m], scale, zeros, others));
        let bound = norms(&coeffs);
        (coeffs, bound, None)
    } else {
        let value = divided::rational(group, scale, zeros, others.clone());
        let at_center = divided::rational(&vec![center; m], scale, zeros, others);
        let bound = norms(&taylor_to_powers(value.clone()));
        let spread = Spread::new(group.to_vec(), center, value);
        (taylor_to_powers(at_center), bound, Some(spread))
    };
    let d1 = differentiate(center, &coeffs);
    let d2 = differentiate(center, &d1);
    Some(Cluster {
        center,
        multiplicity: m,
        weight,
        coeffs,
        bound,
        d1,
        d2,
        frequency: group.iter().map(|p| p.im.abs()).fold(0.0, f64::max),
        spread,
    })
}

impl Spread {
    /// The divided-difference form of distinct `nodes` around `center`, from the
    /// differences `value` = R[x₁…x_k] of the rest of Y(s).
    pub(super) fn new(nodes: Vec<C64>, center: C64, value: Vec<C64>) -> Self {
        let offsets: Vec<C64> = nodes.iter().map(|&x| x - center).collect();
        let mut first = value.clone();
        divided::times_linear(&mut first, &nodes, C64::new(0.0, 0.0));
        let mut second = first.clone();
        divided::times_linear(&mut second, &nodes, C64::new(0.0, 0.0));
        Spread {
            radius: offsets.iter().map(|d| d.norm()).fold(0.0, f64::max),
            growth: offsets
                .iter()
                .map(|d| d.re)
                .fold(f64::NEG_INFINITY, f64::max),
            offsets,
            nodes,
            differences: [value, first, second],
        }
    }
}

/// q_j = v_{m−1−j}/j! from divided differences v_k = f[x₁…x_{k+1}] (Taylor coefficients
/// when the nodes are equal): the coefficients of τ^j.
pub(super) fn taylor_to_powers(mut v: Vec<C64>) -> Vec<C64> {
    v.reverse();
    let mut factorial = 1.0;
    for (j, q) in v.iter_mut().enumerate().skip(1) {
        factorial *= j as f64;
        *q /= factorial;
    }
    v
}

/// The clusters of Y(s) = scale·Π(s − z)/Π(s − p) (the step's pole included in `poles`).
pub(super) fn partial_fractions(poles: &[C64], zeros: &[C64], scale: f64) -> Vec<Cluster> {
    let partition = group_poles(poles);
    // The poles group after group: each group a slice, the others what is around it.
    let ordered: Vec<C64> = partition.index.iter().map(|&i| poles[i]).collect();
    partition
        .bounds
        .windows(2)
        .filter_map(|w| {
            let others = ordered[..w[0]].iter().chain(&ordered[w[1]..]);
            make_cluster(&ordered[w[0]..w[1]], others, zeros, scale)
        })
        .collect()
}

/// Polynomial factor of d/dτ[e^{cτ}·P(τ)] = e^{cτ}·(c·P + P').
pub(super) fn differentiate(center: C64, p: &[C64]) -> Vec<C64> {
    (0..p.len())
        .map(|j| {
            let from_derivative = p
                .get(j + 1)
                .map_or(C64::new(0.0, 0.0), |&q| q * (j + 1) as f64);
            center * p[j] + from_derivative
        })
        .collect()
}

/// Classifies the long-run behaviour from the uncancelled poles.
pub(super) fn classify(tf: &TransferFunction) -> Behaviour {
    let poles = tf.uncancelled_poles();
    if poles.iter().any(|p| p.re > 0.0) {
        return Behaviour::Unstable;
    }
    let on_axis: Vec<C64> = poles
        .iter()
        .copied()
        .filter(|p| p.re == 0.0 && p.im != 0.0)
        .collect();
    // "Repeated" to [`REPEATED_AXIS_RELATIVE`]:
    // j(1 ± 1e-9) from the roots of (s² + 1)² is one double pair there, so y grows as t·sin t.
    let repeated_axis = on_axis.iter().enumerate().any(|(i, p)| {
        on_axis[i + 1..]
            .iter()
            .any(|q| (p - q).norm() <= REPEATED_AXIS_RELATIVE * p.norm().max(q.norm()))
    });
    if repeated_axis {
        Behaviour::Unstable
    } else if poles.iter().any(|p| p.re == 0.0 && p.im == 0.0) {
        Behaviour::Integrating
    } else if !on_axis.is_empty() {
        Behaviour::Oscillating
    } else {
        Behaviour::Settles
    }
}
