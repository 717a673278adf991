//! Degrau: open-loop step-response analysis and process identification for control students.
//!
//! - [`lti`]: exact transfer-function math, step responses and step metrics (no GUI).
//! - [`ident`]: measured step tests, process models and their fitting (no GUI).
//! - [`app`]: the egui desktop app, which only calls the library.
//! - [`cli`]: the headless command line of the `degrau` binary.
//! - [`text`]: the words of every fact and label, in English and Portuguese.

pub use degrau_app as app;
pub use degrau_ident as ident;
pub use degrau_lti as lti;
pub use degrau_words::phrases;

pub mod cli;
pub mod text;
