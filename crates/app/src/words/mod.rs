//! The app's words: its labels, tooltips and panels' sentences in English and Brazilian
//! Portuguese (the facts of the lower crates are said by their own words), and the code a
//! student copies to MATLAB or python-control.

pub mod app;
pub mod code;
pub mod design;
pub mod identify;
pub mod lsq_app;
