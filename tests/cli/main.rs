//! The command line's tests, one binary (each file a module): each runs the `degrau` binary
//! as a user would and reads what it prints, in both languages and as JSON.

mod cli;
mod cli_approx;
mod cli_bode;
mod cli_diagnose;
mod cli_exercise;
mod cli_fit;
mod cli_flags;
mod cli_fuzz;
mod cli_hand;
mod cli_lang;
mod cli_loop;
mod cli_lsq;
mod cli_margins;
mod cli_multistep;
mod cli_step_large;
mod cli_test_causes;
mod cli_tune;
#[path = "../../crates/lti/tests/exact/mod.rs"]
mod exact;
mod lti_discrete;
#[path = "../run/mod.rs"]
mod run;
