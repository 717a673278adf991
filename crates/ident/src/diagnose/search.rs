//! The cheapest way to the best fit of each of many candidates: all their starts screened a
//! few iterations on the reduced record, the leaders of each carried to convergence.

use super::judge::{aliased, beyond_record, bic};
use crate::diagnose::tracker::Tracker;
use crate::fit::{FitData, FitOptions, FitReport, Termination, search_fit};
use crate::model::{Structure, Values};

/// Each job's structure fitted from its start (one start, on the record's reduction for a
/// long record), spread over the cores ([`crate::parallel`]); for each key, in the order the
/// keys first come, the fit with the lowest cost that is not an alias, leans on no lag
/// beyond the record, and is finite.
///
/// The starts are screened first: each key's first runs [`SCREEN_ITERATIONS`] iterations,
/// its others [`PRE_SCREEN_ITERATIONS`], of which the [`PRE_SCREEN_KEPT`] lowest go on to
/// the whole screen; then only the [`KEPT_PER_KEY`] lowest of each key go on to convergence,
/// of the `leaders` keys whose best screened fit has the lowest BIC. When none of those ends
/// acceptable the next ones go on, until one ends where a rejected one ended
/// ([`same_optimum`]: the key's starts share that basin). Starts in the same basin agree
/// long before they converge, and one that is far behind after the screen does not
/// overtake the leaders.
pub(super) fn best_fits<K: Copy + PartialEq + Sync + Send>(
    data: &FitData,
    current: &FitReport,
    jobs: &[(K, Structure, Values)],
    leaders: usize,
    tracker: &Tracker,
) -> Vec<(K, FitReport)> {
    let full = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    let screen = FitOptions {
        max_iterations: SCREEN_ITERATIONS,
        screen: true,
        ..full
    };
    let pre_screen = FitOptions {
        max_iterations: PRE_SCREEN_ITERATIONS,
        ..screen
    };
    let screen_rest = FitOptions {
        max_iterations: SCREEN_ITERATIONS - PRE_SCREEN_ITERATIONS,
        ..screen
    };
    let fit_with = |options: &FitOptions, s: Structure, g: Values| {
        if tracker.cancelled() {
            return None;
        }
        let r = search_fit(data, s, g, options);
        tracker.fitted();
        r.ok().filter(|r| r.ln_mse.is_finite())
    };
    // Each key's first start runs the whole screen, its others a short one, all at once;
    // then each key's leading few of those go on to the whole screen.
    let first_of_key: Vec<bool> = (0..jobs.len())
        .map(|i| !jobs[..i].iter().any(|j| j.0 == jobs[i].0))
        .collect();
    let all: Vec<usize> = (0..jobs.len()).collect();
    let mut screened = crate::parallel::map(&all, |&i| {
        let options = if first_of_key[i] {
            &screen
        } else {
            &pre_screen
        };
        fit_with(options, jobs[i].1, jobs[i].2)
    });
    let later: Vec<usize> = all.into_iter().filter(|&i| !first_of_key[i]).collect();
    let going_on = pre_screen_leaders(jobs, &screened, &later);
    let fits = crate::parallel::map(&going_on, |&i| {
        let r = screened[i].as_ref()?;
        fit_with(&screen_rest, r.model.structure, r.model.values)
    });
    for (&i, r) in going_on.iter().zip(fits) {
        if r.is_some() {
            screened[i] = r;
        }
    }
    let acceptable = |r: &FitReport| !aliased(r) && !beyond_record(data, &current.model, &r.model);
    let mut keys: Vec<K> = Vec::new();
    jobs.iter().for_each(|(k, _, _)| {
        if !keys.contains(k) {
            keys.push(*k);
        }
    });
    // Per key, its screened fits from the lowest cost.
    let mut queues: Vec<Vec<FitReport>> = keys
        .iter()
        .map(|key| {
            let mut q: Vec<FitReport> = jobs
                .iter()
                .zip(&screened)
                .filter(|((k, _, _), _)| k == key)
                .filter_map(|(_, r)| r.clone())
                .collect();
            q.sort_by(|a, b| a.ln_mse.total_cmp(&b.ln_mse));
            q.reverse();
            q
        })
        .collect();
    if leaders < keys.len() {
        // Only the keys whose best screened fit has the lowest BICs go on.
        let lead = |i: usize| queues[i].last().map_or(f64::INFINITY, bic);
        let mut order: Vec<usize> = (0..keys.len()).collect();
        order.sort_by(|&a, &b| lead(a).total_cmp(&lead(b)));
        order[leaders..].iter().for_each(|&i| queues[i].clear());
    }
    let mut best: Vec<Option<FitReport>> = vec![None; keys.len()];
    let mut rejected: Vec<Vec<f64>> = vec![Vec::new(); keys.len()];
    loop {
        let round: Vec<(usize, FitReport)> = queues
            .iter_mut()
            .enumerate()
            .filter(|(i, _)| best[*i].is_none())
            .flat_map(|(i, q)| {
                let take = q.len().min(KEPT_PER_KEY);
                q.split_off(q.len() - take)
                    .into_iter()
                    .rev()
                    .map(move |r| (i, r))
            })
            .collect();
        if round.is_empty() {
            break;
        }
        // Each goes on from where its screen left it (one that converged there is only
        // polished, and given its intervals).
        let finished = crate::parallel::map(&round, |(_, r)| {
            fit_with(&full, r.model.structure, r.model.values)
        });
        for ((i, _), r) in round.iter().zip(finished) {
            let Some(r) = r else { continue };
            if !acceptable(&r) {
                // A start that ends where a rejected one ended: the key's starts share one
                // basin, and the rest of its queue would end there too.
                if rejected[*i].iter().any(|&b| same_optimum(b, bic(&r))) {
                    queues[*i].clear();
                }
                rejected[*i].push(bic(&r));
                continue;
            }
            if best[*i].as_ref().is_none_or(|b| r.ln_mse < b.ln_mse) {
                best[*i] = Some(r);
            }
        }
    }
    keys.into_iter()
        .zip(best)
        .filter_map(|(k, r)| Some((k, r?)))
        .collect()
}

/// Of the starts `picked` (all but each key's first), those of each key whose short screen
/// ([`PRE_SCREEN_ITERATIONS`]) ended unfinished with the lowest costs, [`PRE_SCREEN_KEPT`]
/// per key: they go on to the whole screen.
pub(super) fn pre_screen_leaders<K: Copy + PartialEq>(
    jobs: &[(K, Structure, Values)],
    screened: &[Option<FitReport>],
    picked: &[usize],
) -> Vec<usize> {
    let unfinished = |i: usize| {
        screened[i]
            .as_ref()
            .filter(|r| r.termination == Termination::IterationLimit)
            .map(|r| r.ln_mse)
    };
    let mut going_on = Vec::new();
    for (k, &i) in picked.iter().enumerate() {
        let Some(cost) = unfinished(i) else { continue };
        let ahead = picked[..k]
            .iter()
            .chain(&picked[k + 1..])
            .filter(|&&j| jobs[j].0 == jobs[i].0)
            .filter(|&&j| unfinished(j).is_some_and(|c| c < cost || (c == cost && j < i)))
            .count();
        if ahead < PRE_SCREEN_KEPT {
            going_on.push(i);
        }
    }
    going_on
}

/// Iterations of the short screen of a key's later starts ([`best_fits`]): a start far
/// behind its key's others after these is not taken further.
pub(super) const PRE_SCREEN_ITERATIONS: usize = 3;

/// A key's later starts that go on from the short screen to the whole one.
pub(super) const PRE_SCREEN_KEPT: usize = 1;

/// Whether two converged fits of one structure, of BICs `a` and `b`, are the same optimum:
/// BICs within [`SAME_OPTIMUM`] (a tenth of a unit of N·ln MSE: far below any difference the
/// loop judges by, far above what two converged runs into one basin differ by).
pub(super) fn same_optimum(a: f64, b: f64) -> bool {
    (a - b).abs() <= SAME_OPTIMUM
}

/// See [`same_optimum`].
pub(super) const SAME_OPTIMUM: f64 = 0.1;

/// Pairs of extensions taken on to convergence after the screen (those whose best screened
/// fit has the lowest BIC): the pair search only needs its winner.
pub(super) const PAIRS_TAKEN_ON: usize = 2;

/// Iterations the whole screen runs before the leaders are picked ([`best_fits`]): every
/// candidate's first start, and those of its others that lead after the short screen.
pub(super) const SCREEN_ITERATIONS: usize = 6;

/// Screened starts of each candidate taken on to convergence at a time ([`best_fits`]): the
/// leader alone, since starts in the same basin agree after the screen; the next one goes
/// on only when the leader ends unacceptable (an alias, a lag beyond the record).
pub(super) const KEPT_PER_KEY: usize = 1;
