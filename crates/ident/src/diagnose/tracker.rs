//! How far a diagnosis has gone, and whether it should stop: what the app's progress figure
//! reads while the loop runs off the UI thread. The diagnosis counts its fits and the
//! extension it is looking for; a student's cancel ends it at its next fit.

use std::sync::atomic::{AtomicUsize, Ordering};

/// A diagnosis' progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DiagnoseProgress {
    /// The extension being looked for (1 = the first); 0 while the test's own causes are read.
    pub extension: usize,
    /// The most extensions the loop makes.
    pub max_steps: usize,
    /// Fits made so far.
    pub fits: usize,
}

/// Where a diagnosis reports its progress and learns that it was cancelled.
pub struct Tracker<'a> {
    report: Option<&'a (dyn Fn(DiagnoseProgress) + Sync)>,
    cancelled: Option<&'a (dyn Fn() -> bool + Sync)>,
    extension: AtomicUsize,
    max_steps: usize,
    fits: AtomicUsize,
}

impl<'a> Tracker<'a> {
    /// A diagnosis nobody watches.
    pub fn none() -> Self {
        Self::new(None, None, 0)
    }

    /// Reports to `report`, stops when `cancelled` says so; `max_steps` as the loop's.
    pub fn new(
        report: Option<&'a (dyn Fn(DiagnoseProgress) + Sync)>,
        cancelled: Option<&'a (dyn Fn() -> bool + Sync)>,
        max_steps: usize,
    ) -> Self {
        Self {
            report,
            cancelled,
            extension: AtomicUsize::new(0),
            max_steps,
            fits: AtomicUsize::new(0),
        }
    }

    /// The loop starts looking for extension `k` (1-based).
    pub fn extension(&self, k: usize) {
        self.extension.store(k, Ordering::Relaxed);
        self.send();
    }

    /// One more fit made.
    pub fn fitted(&self) {
        self.fits.fetch_add(1, Ordering::Relaxed);
        self.send();
    }

    /// Whether the student cancelled.
    pub fn cancelled(&self) -> bool {
        self.cancelled.is_some_and(|c| c())
    }

    /// The progress so far.
    pub fn progress(&self) -> DiagnoseProgress {
        DiagnoseProgress {
            extension: self.extension.load(Ordering::Relaxed),
            max_steps: self.max_steps,
            fits: self.fits.load(Ordering::Relaxed),
        }
    }

    fn send(&self) {
        if let Some(report) = self.report {
            report(self.progress());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::{DiagnoseOptions, diagnose_tracked};
    use crate::fit::guess::auto_guess;
    use crate::fit::{FitData, FitOptions, fit};
    use crate::model::excitation::Excitation;
    use crate::model::{Model, Param, Structure, Values};
    use crate::random::Lcg;
    use std::sync::Mutex;

    /// A P2 step test (Kp 2, lags 10 s and 3 s, from 5) with 0.5 % noise, and its P1 fit.
    fn p2_record_and_p1_fit() -> (FitData, crate::fit::FitReport) {
        let mut v = Values::default();
        for (p, x) in [
            (Param::Kp, 2.0),
            (Param::Tp1, 10.0),
            (Param::Tp2, 3.0),
            (Param::Y0, 5.0),
        ] {
            v.set(p, x);
        }
        let input = Excitation::step(5.0, 1.0);
        let times: Vec<f64> = (0..300).map(|k| 0.25 * k as f64).collect();
        let model = Model::new(Structure::parse("P2").expect("a code"), v);
        let mut y = model.simulate(&input, &times).expect("a model");
        let mut noise = Lcg(11);
        y.iter_mut().for_each(|v| *v += 0.01 * noise.symmetric());
        let data = FitData { times, y, input };
        let p1 = Structure::parse("P1").expect("a code");
        let start = fit(
            &data,
            p1,
            auto_guess(&data, p1, None),
            &FitOptions::default(),
            &mut (),
        );
        (data, start.expect("a P1 fit"))
    }

    #[test]
    fn a_diagnosis_reports_each_extension_and_its_fits_and_stops_when_cancelled() {
        let (data, start) = p2_record_and_p1_fit();
        let options = DiagnoseOptions::default();
        let seen = Mutex::new(Vec::new());
        let report = |p: DiagnoseProgress| seen.lock().map(|mut s| s.push(p)).unwrap_or(());
        let tracker = Tracker::new(Some(&report), None, options.max_steps);
        let chain = diagnose_tracked(&data, start.clone(), &options, &tracker);
        let seen = seen.into_inner().unwrap_or_default();
        assert_eq!(
            chain.steps.first().map(|s| s.cause.id()),
            Some("extra_pole")
        );
        // One extension looked for per step made, and one more that found nothing.
        let last = seen.last().copied().expect("progress was reported");
        assert_eq!(last.extension, chain.steps.len() + 1);
        assert_eq!(last.max_steps, 4);
        assert!(seen.windows(2).all(|w| w[1].fits >= w[0].fits));
        assert!(last.fits >= 2 * chain.steps.len(), "{last:?}");

        let stop = || true;
        let cancelled = Tracker::new(None, Some(&stop), options.max_steps);
        let chain = diagnose_tracked(&data, start, &options, &cancelled);
        assert!(chain.steps.is_empty());
        assert_eq!(cancelled.progress().fits, 0);
    }

    #[test]
    fn reports_each_fit_and_extension_and_answers_cancel() {
        let seen = Mutex::new(Vec::new());
        let report = |p: DiagnoseProgress| seen.lock().map(|mut s| s.push(p)).unwrap_or(());
        let stop = || true;
        let t = Tracker::new(Some(&report), Some(&stop), 4);
        t.extension(1);
        t.fitted();
        t.fitted();
        t.extension(2);
        assert!(t.cancelled());
        let seen = seen.into_inner().unwrap_or_default();
        assert_eq!(seen.len(), 4);
        assert_eq!(
            seen[3],
            DiagnoseProgress {
                extension: 2,
                max_steps: 4,
                fits: 2
            }
        );
        assert!(!Tracker::none().cancelled());
    }
}
