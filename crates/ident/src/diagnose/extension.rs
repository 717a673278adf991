//! The structural extensions a diagnosis tries (a dead time, a free offset, an underdamped
//! pair, one more pole, a zero, an integrator, a drift, and their pairs), the cause each
//! names, the starts each is fitted from (warm from the current fit and fresh from the
//! extended structure's guess), and the candidates kept.

use super::cause::Cause;
use super::explain::characteristic_time;
use super::judge::bic;
use super::search::{PAIRS_TAKEN_ON, best_fits};
use crate::diagnose::drift_evidence::read_drift;
use crate::diagnose::offset_evidence::offset_shown;
use crate::diagnose::tracker::Tracker;
use crate::fit::guess::{auto_guess, features};
use crate::fit::{FitData, FitOptions, FitReport, fit};
use crate::model::{Model, Param, Structure, Values};

/// An underdamped pair fitted with ζ at or above this is taken as two real poles.
pub(super) const OVERDAMPED_ZETA: f64 = 0.98;

/// A structural change to try.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Extension {
    Delay,
    FreeOffset,
    Underdamped,
    Pole,
    Zero,
    Integrator,
    Drift,
}

pub(super) const EXTENSIONS: [Extension; 7] = [
    Extension::Delay,
    Extension::FreeOffset,
    Extension::Underdamped,
    Extension::Pole,
    Extension::Zero,
    Extension::Integrator,
    Extension::Drift,
];

impl Extension {
    /// The extended structure, if this structure can take the extension.
    pub(super) fn apply(self, s: Structure) -> Option<Structure> {
        let mut e = s;
        match self {
            Extension::Delay if !s.delay => e.delay = true,
            Extension::FreeOffset if !s.free_offset => e.free_offset = true,
            Extension::Underdamped if !s.underdamped => {
                e.underdamped = true;
                e.poles = s.poles.max(2);
            }
            Extension::Pole if s.poles < 3 => e.poles += 1,
            Extension::Zero if !s.zero => e.zero = true,
            Extension::Integrator if !s.integrator => e.integrator = true,
            // A test not at rest has its initial transient: a drift would absorb the same
            // motion before the step (an artefact of the test), not a trend of the process.
            Extension::Drift if !s.drift && !s.transient => e.drift = true,
            _ => return None,
        }
        Some(e)
    }

    /// The structure without this extension's term and the parameter whose null value (0)
    /// says the term is not needed, for the terms the backward look may take out again: a
    /// dead time, a zero and a drift (an offset, an integrator, a pole or a pair have no
    /// null value that leaves the same model).
    pub(super) fn removed(self, s: Structure) -> Option<(Structure, Param)> {
        let mut r = s;
        let param = match self {
            Extension::Delay if s.delay => {
                r.delay = false;
                Param::Td
            }
            Extension::Zero if s.zero => {
                r.zero = false;
                Param::Tz
            }
            Extension::Drift if s.drift => {
                r.drift = false;
                Param::Drift
            }
            _ => return None,
        };
        Some((r, param))
    }

    pub(super) fn cause(self, fitted: &Values) -> Cause {
        match self {
            Extension::Delay => Cause::DeadTime,
            Extension::FreeOffset => Cause::Offset,
            Extension::Underdamped => Cause::Oscillation,
            Extension::Pole => Cause::ExtraPole,
            Extension::Zero if fitted.get(Param::Tz) < 0.0 => Cause::InverseResponse,
            Extension::Zero => Cause::Zero,
            Extension::Integrator => Cause::Integrator,
            Extension::Drift => Cause::Drift,
        }
    }
}

/// Extensions tried in pairs: the dynamic ones (an offset, an integrator or a drift in a
/// pair would only absorb what the first named alone could not).
pub(super) const PAIRED: [Extension; 4] = [
    Extension::Delay,
    Extension::Underdamped,
    Extension::Pole,
    Extension::Zero,
];

/// The pair of extensions whose refit has the lowest BIC, started from each one's starts.
/// A pair whose structure is `reached`'s also starts from it.
pub(super) fn best_pair(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    reached: Option<&Model>,
    tracker: &Tracker,
) -> Option<((Extension, Extension), FitReport)> {
    let paired: Vec<Extension> = PAIRED.into_iter().filter(|e| allowed.contains(e)).collect();
    let pairs: Vec<((Extension, Extension), Structure)> = paired
        .iter()
        .enumerate()
        .flat_map(|(i, &e1)| paired[i + 1..].iter().map(move |&e2| (e1, e2)))
        .filter_map(|(e1, e2)| {
            let s = e1
                .apply(current.model.structure)
                .and_then(|s| e2.apply(s))?;
            Some(((e1, e2), s))
        })
        .collect();
    // The pairs' automatic guesses (a regression each) on every core; both members' fresh
    // starts begin with the pair's own guess (no pair holds a free offset: one Y0).
    let held = held_y0(current, Extension::Delay);
    let guesses = crate::parallel::map(&pairs, |&(_, s)| extended_guess(data, s, held));
    let mut jobs = Vec::new();
    for (&((e1, e2), s), &auto) in pairs.iter().zip(&guesses) {
        let mut starts = fresh_starts_from(data, auto, e1, held);
        starts.extend(fresh_starts_from(data, auto, e2, held));
        starts.extend(warm_starts(data, current, e1));
        starts.extend(warm_starts(data, current, e2));
        starts.extend(reached_start(reached, s));
        // One run of a start is enough.
        let mut distinct: Vec<Values> = Vec::with_capacity(starts.len());
        starts.into_iter().for_each(|g| {
            if !distinct.contains(&g) {
                distinct.push(g);
            }
        });
        jobs.extend(distinct.into_iter().map(|g| ((e1, e2), s, g)));
    }
    let (pair, r) = best_fits(data, current, &jobs, PAIRS_TAKEN_ON, tracker)
        .into_iter()
        .reduce(|best, next| {
            if bic(&next.1) < bic(&best.1) {
                next
            } else {
                best
            }
        })?;
    on_every_sample(data, (pair.0, r)).map(|(_, r)| (pair, r))
}

/// The single extensions of one fit on one record ([`candidates`], every one allowed),
/// fitted once, when first asked for: the disturbance test asks whether one of them explains
/// the record as well as a disturbance would ([`StartExtensions::reach`]), and the loop's
/// first step chooses among the same fits when the record and the start it was asked on are
/// still the loop's ([`Extensions`]).
pub struct StartExtensions<'a> {
    data: &'a FitData,
    current: &'a FitReport,
    found: std::sync::OnceLock<Vec<(Extension, FitReport)>>,
}

impl<'a> StartExtensions<'a> {
    pub fn new(data: &'a FitData, current: &'a FitReport) -> Self {
        Self {
            data,
            current,
            found: std::sync::OnceLock::new(),
        }
    }

    pub(super) fn get(&self) -> &[(Extension, FitReport)] {
        self.found.get_or_init(|| {
            candidates(self.data, self.current, &EXTENSIONS, None, &Tracker::none())
        })
    }

    /// Whether the best of the extensions explains the record with a BIC at most `bound`
    /// (refitted on every sample when found on a long record's reduction).
    pub fn reach(&self, bound: f64) -> bool {
        self.get()
            .iter()
            .min_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)))
            .cloned()
            .and_then(|winner| on_every_sample(self.data, winner))
            .is_some_and(|(_, r)| bic(&r) <= bound)
    }

    /// The extensions fitted, if any were asked for.
    pub fn fitted(self) -> Option<Extensions> {
        self.found.into_inner().map(Extensions)
    }
}

/// The single extensions of the loop's start, fitted before the loop ([`StartExtensions`]).
#[derive(Debug, Clone)]
pub struct Extensions(pub(super) Vec<(Extension, FitReport)>);

/// Every extension of `current` that can be fitted, with its refit (on the record's
/// reduction for a long record, [`search_fit`](crate::fit::search_fit)); aliased fits, lags beyond the record and
/// "pairs" fitted overdamped left out. An extension whose structure is `reached`'s also
/// starts from it.
pub(super) fn candidates(
    data: &FitData,
    current: &FitReport,
    allowed: &[Extension],
    reached: Option<&Model>,
    tracker: &Tracker,
) -> Vec<(Extension, FitReport)> {
    let extended: Vec<(Extension, Structure)> = allowed
        .iter()
        .filter_map(|&e| Some((e, e.apply(current.model.structure)?)))
        .collect();
    // The starts (each an automatic guess: a regression) on every core.
    let starts = crate::parallel::map(&extended, |&(e, s)| {
        let mut all = starts(data, current, e, s);
        all.extend(reached_start(reached, s));
        all
    });
    let jobs: Vec<(Extension, Structure, Values)> = extended
        .iter()
        .zip(starts)
        .flat_map(|(&(e, s), starts)| starts.into_iter().map(move |g| (e, s, g)))
        .collect();
    best_fits(data, current, &jobs, usize::MAX, tracker)
        .into_iter()
        .filter(|(e, r)| kept_candidate(data, current, *e, r))
        .collect()
}

/// A candidate's own conditions: a pair that oscillates, a drift the record shows, an
/// operating point off the held one beyond its noise ([`offset_shown`]), a finite BIC.
pub(super) fn kept_candidate(
    data: &FitData,
    current: &FitReport,
    e: Extension,
    r: &FitReport,
) -> bool {
    let own = match e {
        Extension::Underdamped => oscillates(r),
        Extension::Drift => drift_shown(data, &current.model, r),
        Extension::FreeOffset => offset_shown(data, &current.model, r),
        _ => true,
    };
    own && bic(r).is_finite()
}

/// Whether a fit with a drift term shows it where only a drift explains it
/// ([`read_drift`]: on the stretches where no input change is still answered, the same
/// slope whatever the change, in a straight line).
pub(super) fn drift_shown(data: &FitData, current: &Model, r: &FitReport) -> bool {
    read_drift(data, current, r).is_some_and(|d| d.shows(r.model.get(Param::Drift)))
}

/// `reached`'s values, as a start of an extension of structure `s`, when `s` is its
/// structure.
fn reached_start(reached: Option<&Model>, s: Structure) -> Option<Values> {
    reached.filter(|m| m.structure == s).map(|m| m.values)
}

/// `model` with its underdamped pair as two real poles: Tp1, Tp2 = Tw·(ζ ± √(ζ² − 1)) for
/// ζ ≥ 1, a double pole at Tw below (a pair whose ζ's interval reaches 1); a third pole
/// stays where it is. The same model for a structure without a pair.
pub(super) fn real_poles(model: &Model) -> Model {
    let mut m = *model;
    if !m.structure.underdamped {
        return m;
    }
    let (tw, zeta) = (m.get(Param::Tw), m.get(Param::Zeta));
    let root = (zeta * zeta - 1.0).max(0.0).sqrt();
    m.structure.underdamped = false;
    m.values.set(Param::Tp1, tw * (zeta + root));
    m.values.set(Param::Tp2, tw * (zeta - root));
    m
}

/// Whether a fitted pair oscillates: ζ below [`OVERDAMPED_ZETA`], and its 95 % interval
/// below 1. A "pair" fitted with ζ ≥ 1 is two real poles, and one whose interval reaches 1
/// cannot be told from them (a dead time and two close poles make an S-shape a pair with
/// ζ ≈ 0.85 also draws): that is the extra-pole extension, not an oscillation, and must not
/// take its name.
pub(super) fn oscillates(r: &FitReport) -> bool {
    r.model.get(Param::Zeta) < OVERDAMPED_ZETA
        && r.interval(Param::Zeta).is_none_or(|(_, hi)| hi < 1.0)
}

/// Scale (issue 10): on a long record the candidates are fitted on its reduction
/// ([`search_fit`](crate::fit::search_fit), statistics standing for the whole record's) and only the chosen one is
/// refitted on every sample, from its optimum; a record [`crate::fit::reduce`] leaves as it is
/// keeps its fit.
pub(super) fn on_every_sample(
    data: &FitData,
    (extension, r): (Extension, FitReport),
) -> Option<(Extension, FitReport)> {
    full_fit(data, r).map(|full| (extension, full))
}

/// A fit found on the record's reduction ([`search_fit`](crate::fit::search_fit)) refitted on every sample from its
/// optimum; the fit itself when the record is not reduced.
pub(super) fn full_fit(data: &FitData, r: FitReport) -> Option<FitReport> {
    if crate::fit::reduce::reduce(&data.times, &data.input).is_none() {
        return Some(r);
    }
    let options = FitOptions {
        starts: 1,
        ..FitOptions::default()
    };
    fit(data, r.model.structure, r.model.values, &options, &mut ()).ok()
}

/// The starts of an extension: a few warm ones from the current fit, and the extended
/// structure's automatic guess.
pub(super) fn starts(
    data: &FitData,
    current: &FitReport,
    extension: Extension,
    s: Structure,
) -> Vec<Values> {
    let mut starts = warm_starts(data, current, extension);
    starts.extend(fresh_starts(data, current, extension, s));
    starts
}

/// The current values with the new parameter set to a few plausible values.
pub(super) fn warm_starts(
    data: &FitData,
    current: &FitReport,
    extension: Extension,
) -> Vec<Values> {
    let v = current.model.values;
    let s = current.model.structure;
    let t_char = characteristic_time(current, data);
    let with = |pairs: &[(Param, f64)]| {
        let mut w = v;
        for &(p, x) in pairs {
            w.set(p, x);
        }
        w
    };
    match extension {
        Extension::Delay => [0.1, 0.3, 0.7]
            .iter()
            .map(|f| with(&[(Param::Td, f * t_char)]))
            .collect(),
        Extension::FreeOffset | Extension::Integrator => vec![v],
        Extension::Drift => vec![with(&[(Param::Drift, 0.0)])],
        Extension::Underdamped => {
            let period = features(data, Some(v.get(Param::Y0))).period;
            let wd = period.map_or(1.0 / t_char, |p| std::f64::consts::TAU / p);
            [0.15, 0.4]
                .iter()
                .map(|&z: &f64| {
                    with(&[
                        (Param::Zeta, z),
                        (Param::Tw, (1.0 - z * z).sqrt() / wd),
                        (Param::Tp3, 0.3 * t_char),
                    ])
                })
                .collect()
        }
        Extension::Pole => {
            let next = match s.poles {
                1 => Param::Tp2,
                _ => Param::Tp3,
            };
            let td = if s.delay { v.get(Param::Td) } else { 0.0 };
            [0.15, 0.5]
                .iter()
                .flat_map(|f| {
                    let added = f * t_char;
                    // The new lag takes part of the old one and of the dead time.
                    [
                        with(&[(next, added)]),
                        with(&[
                            (next, added),
                            (Param::Tp1, (v.get(Param::Tp1) - added).max(0.1 * t_char)),
                            (Param::Td, (td - added).max(0.0)),
                        ]),
                    ]
                })
                .collect()
        }
        Extension::Zero => [-1.0, -0.3, 0.7, 2.5]
            .iter()
            .map(|f| with(&[(Param::Tz, f * t_char)]))
            .collect(),
    }
}

/// Starts read off the data rather than the current fit, which may have collapsed where the
/// structure could not follow the curve (a P2 on an overshoot fits two tiny lags): the extended
/// structure's automatic guess, with Y0 at the current value, or read off the first samples
/// when the offset is the extension; for a zero, the guess with Tz spread over multiples of
/// the 63 % time on the side the curve points at (an overshoot: Tz above the lags; a dip first:
/// Tz < 0).
pub(super) fn fresh_starts(
    data: &FitData,
    current: &FitReport,
    extension: Extension,
    s: Structure,
) -> Vec<Values> {
    let held_y0 = held_y0(current, extension);
    fresh_starts_from(data, extended_guess(data, s, held_y0), extension, held_y0)
}

/// The Y0 an extension's fresh starts hold: the current one, unless the offset is the
/// extension.
pub(super) fn held_y0(current: &FitReport, extension: Extension) -> Option<f64> {
    (extension != Extension::FreeOffset).then(|| current.model.get(Param::Y0))
}

/// The automatic guess of the extended structure `s` with Y0 held at `held_y0` (the
/// costliest part of a fresh start: a regression over a grid of lags).
pub(super) fn extended_guess(data: &FitData, s: Structure, held_y0: Option<f64>) -> Values {
    let mut auto = auto_guess(data, s, held_y0);
    if let Some(y0) = held_y0 {
        auto.set(Param::Y0, y0);
    }
    auto
}

/// [`fresh_starts`] from the extended structure's guess `auto`.
pub(super) fn fresh_starts_from(
    data: &FitData,
    auto: Values,
    extension: Extension,
    held_y0: Option<f64>,
) -> Vec<Values> {
    if extension != Extension::Zero {
        return vec![auto];
    }
    let f = features(data, held_y0);
    let t63 = f.t63.unwrap_or(data.duration() / 3.0);
    let mut factors = vec![];
    if f.overshoot > 0.0 {
        factors.extend([1.0, 2.0, 4.0]);
    }
    if f.t_dip.is_some() {
        factors.extend([-0.3, -1.0]);
    }
    let mut starts = vec![auto];
    starts.extend(factors.iter().map(|k| {
        let mut v = auto;
        v.set(Param::Tz, k * t63);
        v
    }));
    starts
}
