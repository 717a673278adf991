//! Least squares on a sampled record, the notes' second way to a model: ARX models by batch
//! least squares ([`arx`]) and recursively ([`rls`]), the PRBS test that excites them
//! ([`prbs`]), and estimation on one part of a record with validation on the other
//! ([`validation`]).

pub mod arx;
pub mod prbs;
pub mod rls;
pub mod validation;
