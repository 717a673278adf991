//! The Frequency mode's session: the settings it keeps between runs ([`Saved`]: the source,
//! the tab, the sampling period h and the Nyquist zoom) and what is derived from the source
//! (the Bode diagram, the margins, the Nyquist curve, the sampled model), recomputed only
//! when the source's transfer function, its controller or h changed. No egui here: the views
//! read a session and return [`Command`]s, and [`Session::apply`] is the only place the
//! settings change. The sources' transfer functions come from the other modes, handed over
//! by the app before the mode draws ([`Sources`], [`Session::sync`]).

use serde::{Deserialize, Serialize};

use degrau_lti::control::Controller;
use degrau_lti::{LtiError, TransferFunction};

use super::commands::{Command, SourceKind, Tab};
use super::derived::{LoopData, SampledData};

/// The sampling period the z-plane starts with (s).
pub const DEFAULT_PERIOD: f64 = 0.1;

/// What the Frequency mode keeps between runs (the state file's `frequency`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Saved {
    pub source: SourceKind,
    pub tab: Tab,
    /// The sampling period h (s) of the z-plane.
    pub h: f64,
    /// The Nyquist plot shows the whole curve (else a window around −1).
    pub whole_curve: bool,
}

impl Default for Saved {
    fn default() -> Self {
        Self {
            source: SourceKind::default(),
            tab: Tab::default(),
            h: DEFAULT_PERIOD,
            whole_curve: false,
        }
    }
}

/// Checks a sampling period: a positive finite number of seconds.
pub fn check_period(h: f64) -> Result<(), Refusal> {
    if h.is_finite() && h > 0.0 {
        Ok(())
    } else {
        Err(Refusal::Period(h))
    }
}

/// An entry refused, said until the next accepted change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Refusal {
    /// A sampling period that is not a positive number of seconds.
    Period(f64),
}

/// One source as the other modes hand it over: the plant and, for a loop, its controller.
#[derive(Debug, Clone, PartialEq)]
pub struct Source {
    pub plant: TransferFunction,
    /// The controller of the loop L = C·G (none: L = G).
    pub controller: Option<Controller>,
}

/// The three sources this frame (none: that mode has no transfer function now).
#[derive(Debug, Clone, Default)]
pub struct Sources {
    pub design: Option<Source>,
    pub tune: Option<Source>,
    pub fitted: Option<Source>,
}

impl Sources {
    pub fn get(&self, kind: SourceKind) -> Option<&Source> {
        match kind {
            SourceKind::Design => self.design.as_ref(),
            SourceKind::Tune => self.tune.as_ref(),
            SourceKind::Fitted => self.fitted.as_ref(),
        }
    }
}

/// The Frequency mode's derived data.
#[derive(Debug, Default)]
pub struct Session {
    /// The sources handed over last.
    pub sources: Sources,
    /// The source shown (none: the chosen mode has no transfer function).
    pub source: Option<Source>,
    /// The loop's Bode diagram, margins and Nyquist curve, or why there is no loop (none:
    /// no source).
    pub loop_data: Option<Result<LoopData, LtiError>>,
    /// The plant sampled at h (none: no source).
    pub sampled: Option<SampledData>,
    /// The last entry refused.
    pub refusal: Option<Refusal>,
    /// How many times the loop's data was computed (a test sees it is not every frame).
    pub computations: usize,
    /// The period `sampled` was computed at.
    sampled_at: Option<f64>,
}

impl Session {
    /// Takes the sources of this frame and brings the derived data up to date (only what
    /// changed is computed again).
    pub fn sync(&mut self, kept: &Saved, sources: Sources) {
        self.sources = sources;
        self.refresh(kept);
    }

    /// Recomputes what the chosen source or h changed (else nothing).
    pub fn refresh(&mut self, kept: &Saved) {
        let source = self.sources.get(kept.source).cloned();
        if source != self.source {
            self.loop_data = source
                .as_ref()
                .map(|s| super::derived::loop_data(&s.plant, s.controller.as_ref()));
            self.sampled = None;
            self.sampled_at = None;
            self.computations += 1;
            self.source = source;
        }
        if self.sampled_at != Some(kept.h) {
            self.sampled = self
                .source
                .as_ref()
                .map(|s| super::derived::sampled(&s.plant, kept.h));
            self.sampled_at = Some(kept.h);
        }
    }

    /// Applies one command to `kept`, then brings the derived data up to date.
    pub fn apply(&mut self, kept: &mut Saved, command: Command) {
        self.refusal = None;
        match command {
            Command::SetSource(s) => kept.source = s,
            Command::SetTab(t) => kept.tab = t,
            Command::SetPeriod(h) => match check_period(h) {
                Ok(()) => kept.h = h,
                Err(r) => self.refusal = Some(r),
            },
            Command::SetWholeCurve(w) => kept.whole_curve = w,
        }
        self.refresh(kept);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sources() -> Sources {
        let plant = TransferFunction::from_coeffs(&[1.0], &[10.0, 1.0])
            .and_then(|g| g.with_delay(2.0))
            .expect("a plant");
        Sources {
            design: Some(Source {
                plant,
                controller: None,
            }),
            ..Sources::default()
        }
    }

    #[test]
    fn a_bad_period_is_refused_and_the_old_one_kept() {
        let mut kept = Saved::default();
        let mut s = Session::default();
        s.sync(&kept, sources());
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            s.apply(&mut kept, Command::SetPeriod(bad));
            assert_eq!(kept.h, DEFAULT_PERIOD);
            assert!(matches!(s.refusal, Some(Refusal::Period(_))));
        }
        s.apply(&mut kept, Command::SetPeriod(0.5));
        assert_eq!((kept.h, s.refusal), (0.5, None));
        assert_eq!(s.sampled.as_ref().map(|d| d.h), Some(0.5));
    }

    #[test]
    fn the_loop_is_computed_only_when_the_source_changes() {
        let mut kept = Saved::default();
        let mut s = Session::default();
        s.sync(&kept, sources());
        s.sync(&kept, sources());
        s.apply(&mut kept, Command::SetPeriod(0.2));
        s.apply(&mut kept, Command::SetTab(Tab::Nyquist));
        assert_eq!(s.computations, 1);
        // The Tune source is not there: nothing to show, and it says so.
        s.apply(&mut kept, Command::SetSource(SourceKind::Tune));
        assert!(s.source.is_none() && s.loop_data.is_none() && s.sampled.is_none());
        assert_eq!(s.computations, 2);
    }
}
