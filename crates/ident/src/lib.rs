//! Process identification from a measured open-loop step test: loading and preparing the
//! data, model structures named as MATLAB's procest (P1D, P2DU, …), fitting them,
//! diagnosing what a fitted model gets wrong, the hand methods of the notes and least
//! squares (ARX, RLS, PRBS); [`words`] says each of its facts in English and Portuguese.
//!
//! Pure: it stands on `degrau-lti` and `degrau-words` and knows nothing of the GUI or the
//! command line (Cargo keeps it so: no egui, eframe, rfd or clap among its dependencies).
//!
//! Its modules are the stages a record goes through, each importing only the ones before it:
//! [`record`] (loading, the time base, preparation) → [`model`] (the procest structures,
//! the input as the model sees it, internal units) → [`fit`] (the least-squares problem,
//! its solvers, the multi-start search, the report; rest, guesses, dragged handles, robust
//! fits) → [`diagnose`] (the loop, its causes and rules, the test's own flaws, residuals,
//! hold-out) → [`experiment`] (a record and a student's choices, fitted); beside them
//! [`hand`] (the notes' graphical methods) and [`lsq`] (ARX, RLS, PRBS, validation), on the
//! shared ground of [`stats`] and [`random`].

pub mod challenge;
pub mod diagnose;
pub mod experiment;
pub mod fit;
pub mod hand;
pub mod lsq;
pub mod model;
mod parallel;
pub mod random;
pub mod record;
pub mod stats;
pub mod words;
