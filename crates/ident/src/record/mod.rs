//! The record, the first stage of identification: a measured test loaded from its file(s)
//! ([`data`], [`join`]), its time base ([`timebase`]), and prepared for fitting (the step,
//! the operating point, the window and filter: [`prepare`]).

pub mod data;
pub mod join;
pub mod prepare;
pub mod timebase;
