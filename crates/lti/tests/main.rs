//! The lti crate's integration tests, one binary (each file a module): they link the
//! crate and what it depends on, no GUI. The fixtures are the workspace's (`tests/data`,
//! `assets/`), two folders up.

mod exact;
mod lti_approx;
mod lti_bode;
mod lti_clusters;
mod lti_delay_loop;
mod lti_feedback;
mod lti_known_answers;
mod lti_locus;
mod lti_margins;
mod lti_nyquist;
mod lti_properties;
mod lti_python_control;
mod lti_tuning;
mod lti_zplane;
mod rng;
