//! Process identification from a measured open-loop step test: loading and preparing the
//! data, model structures named as MATLAB's procest (P1D, P2DU, …), fitting them,
//! diagnosing what a fitted model gets wrong, the hand methods of the notes and least
//! squares (ARX, RLS, PRBS); [`words`] says each of its facts in English and Portuguese.
//!
//! Pure: it stands on `degrau-lti` and `degrau-words` and knows nothing of the GUI or the
//! command line (Cargo keeps it so: no egui, eframe, rfd or clap among its dependencies).

pub mod arx;
pub mod data;
pub mod diagnose;
pub mod drift_evidence;
pub mod excitation;
pub mod experiment;
pub mod fit;
pub mod guess;
pub mod hand;
pub mod handles;
pub mod holdout;
pub mod join;
pub mod lag_pair;
pub mod landscape;
pub mod models;
mod parallel;
pub mod per_step;
pub mod prbs;
pub mod prepare;
pub mod random;
pub mod reduce;
pub mod residuals;
pub mod rest;
pub mod rls;
pub mod robust;
pub mod scale;
pub mod staircase;
pub mod stats;
pub mod test_causes;
pub mod timebase;
pub mod tracker;
mod transient;
pub mod validation;
pub mod words;
