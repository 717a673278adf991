//! The app's tests, one binary (each file a module): kittest drives the window's widgets
//! without a GPU, as a student would, in both languages and at the class's sizes.

mod app;
mod app_approx;
mod app_challenges;
mod app_classroom;
mod app_commands;
mod app_design;
mod app_exercises;
mod app_frequency;
mod app_hand;
mod app_identify;
mod app_identify_session;
mod app_loop;
mod app_lsq;
mod app_multistep;
mod app_robust;
mod app_test_causes;
mod app_tune;
#[path = "../kit/mod.rs"]
mod kit;
#[path = "../run/mod.rs"]
mod run;
