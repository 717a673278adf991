//! Independent pieces of work (the fits of a diagnosis' candidates, each from its own start)
//! spread over the machine's cores, results kept in the items' order so that what is chosen
//! from them is the same as one by one.
//!
//! Written here rather than taken from rayon: one scoped map over a slice is all the
//! diagnosis needs, and rayon's pool would add a dependency (and its build time) for it.
//! A map inside a map (a fit's starts inside the diagnosis's candidates) runs on the thread
//! it is called from: the cores are already busy, and more threads would only contend.

use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

thread_local! {
    /// Whether this thread is one of a [`map`]'s workers.
    static INSIDE: Cell<bool> = const { Cell::new(false) };
}

/// Marks this thread a worker while alive, and restores what it was (even on a panic).
struct Worker(bool);

impl Worker {
    fn enter() -> Self {
        Self(INSIDE.replace(true))
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        INSIDE.set(self.0);
    }
}

/// `f` applied to every item, on up to as many threads as the machine has cores (one
/// thread for one item, or a machine that reports a single core): the results in the
/// items' order. Items are handed out one at a time, so long and short pieces balance.
pub fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let workers = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(items.len());
    if workers <= 1 || INSIDE.get() {
        return items.iter().map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let work = || {
        let _worker = Worker::enter();
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(item) = items.get(i) else { break };
            done.push((i, f(item)));
        }
        done
    };
    let mut results: Vec<(usize, R)> = std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..workers).map(|_| scope.spawn(work)).collect();
        let mut all = work();
        for h in helpers {
            // A piece that panicked panics here too, as it would have one by one.
            all.extend(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        all
    });
    results.sort_by_key(|(i, _)| *i);
    results.into_iter().map(|(_, r)| r).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_keep_the_items_order_whatever_finishes_first() {
        let items: Vec<u64> = (0..50).collect();
        let out = map(&items, |&k| {
            // Uneven work: later items finish first.
            std::thread::sleep(std::time::Duration::from_micros(50 * (50 - k)));
            k * k
        });
        assert_eq!(out, items.iter().map(|k| k * k).collect::<Vec<_>>());
        assert!(map(&Vec::<u64>::new(), |&k| k).is_empty());
    }

    #[test]
    fn a_map_inside_a_map_runs_on_its_callers_thread() {
        let outer: Vec<u64> = (0..4).collect();
        let out = map(&outer, |&k| {
            let me = std::thread::current().id();
            let inner: Vec<u64> = (0..8).collect();
            let threads = map(&inner, |_| std::thread::current().id());
            (threads.iter().all(|t| *t == me), k)
        });
        assert!(out.iter().all(|(same, _)| *same), "{out:?}");
        assert_eq!(out.iter().map(|(_, k)| *k).collect::<Vec<_>>(), outer);
        // The caller's thread is no worker once the map is over.
        assert!(!INSIDE.get());
    }
}
