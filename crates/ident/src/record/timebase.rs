//! The record's time base, read the same way by every stage: its sampling period (the median
//! positive spacing), the samples before an instant, and the samples the output rests on
//! before a step.

/// The median spacing of positive time steps, `None` with fewer than two distinct times
/// (linear time: a selection, not a sort, for records of millions of samples).
pub fn sampling_period(time: &[f64]) -> Option<f64> {
    let mut steps: Vec<f64> = time
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 0.0)
        .collect();
    if steps.is_empty() {
        return None;
    }
    let middle = steps.len() / 2;
    let (_, median, _) = steps.select_nth_unstable_by(middle, f64::total_cmp);
    Some(*median)
}

/// How many samples come before the step at `t0` (see the module docs for a repeated t0).
pub fn samples_before(time: &[f64], t0: f64) -> usize {
    time.iter()
        .enumerate()
        .take_while(|&(k, &t)| t < t0 || (t == t0 && time.get(k + 1) == Some(&t0)))
        .count()
}

/// How many leading samples of `times` (of `n` outputs) are at rest before a step at `t0`,
/// and whether the only one is the sample at t0 itself (the rule of [`crate::fit::guess::rest_level`]).
pub(crate) fn rest_samples(times: &[f64], t0: f64, n: usize) -> Option<(usize, bool)> {
    match samples_before(times, t0).min(n) {
        0 if times.first() == Some(&t0) && n > 0 => Some((1, true)),
        0 => None,
        k => Some((k, false)),
    }
}
