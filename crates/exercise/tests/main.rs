//! The exercise crate's tests, one binary: every part of the sheet checked both ways, the
//! sheet's printed answers reproduced or documented, and known closed forms.

mod answers;
mod closed_forms;
mod differences;
mod input;
