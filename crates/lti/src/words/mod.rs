//! The lti crate's words: every fact of its own (errors, metrics, stability, responses,
//! approximations, discrete models, loops) said in English and Brazilian Portuguese, with
//! the course notes' terms, and an example of each for the test that lists every message.

pub mod approx;
pub mod discrete;
pub mod expr;
pub mod feedback;
pub mod lti;
pub mod step;
