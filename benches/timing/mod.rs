//! Plain timing shared by the benches that read a whole run's seconds (not criterion).

use std::time::Instant;

/// Seconds of the fastest of `runs` runs of `f`.
pub fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    (0..runs)
        .map(|_| {
            let clock = Instant::now();
            std::hint::black_box(f());
            clock.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}
