//! The ident crate's words: every fact of its own (the loader's notes, the experiment, model
//! codes and parameters, the fit's report and warnings, the diagnosis's causes and evidence,
//! the test's flaws, the hand methods, least squares) said in English and Brazilian
//! Portuguese with the course notes' terms, and an example of each for the test that lists
//! every message.

pub mod hand;
pub mod ident;
pub mod lsq;
pub mod operating_point;
pub mod report;
pub mod steps;
pub mod test_causes;
