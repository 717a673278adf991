//! The ident crate's integration tests, one binary (each file a module): they link the
//! crate and what it depends on, no GUI. The fixtures are the workspace's (`tests/data`,
//! `assets/`), two folders up.

mod challenge_rates;
mod data_files;
mod data_fuzz;
mod data_loading;
mod diagnose_artefacts;
mod diagnose_closed_loop;
mod diagnose_generator;
mod diagnose_hidden;
mod diagnose_lookalikes;
mod diagnose_real;
mod diagnose_test_flaws;
mod draw;
mod ident_arx;
mod ident_excitation;
mod ident_hand;
mod ident_leci;
mod ident_memory;
mod ident_operating_point;
mod ident_scale;
#[path = "../../../tests/records/mod.rs"]
mod records;
mod wide;
