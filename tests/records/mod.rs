//! The records of `tests/data/records` with the flags a student types to read each of them
//! (`degrau diagnose FILE --time-col … --y-col … --u-col …`), shared by the tests and the
//! benches (`#[path]`), so that both read every record the same way.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// How the CLI is told to read a record: (file, time column, output, input, sampling
/// period, rows skipped, input before the record); an empty column is the automatic choice.
pub type Flags = (
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    Option<f64>,
    usize,
    Option<f64>,
);

/// Every record of `tests/data/records`, with the flags a student gives the CLI.
pub const RECORDS: [Flags; 13] = [
    (
        "apmonitor_arduino_1st_order_SISO_data.csv",
        "time",
        "temperature",
        "voltage",
        None,
        0,
        None,
    ),
    (
        "daisy_heating_system.dat",
        "1",
        "3",
        "2",
        None,
        0,
        Some(6.0),
    ),
    (
        "ecam_tclab_Open_loop_experiment_on_DV_2022-03-22-20h49.txt",
        "t",
        "PV",
        "DV",
        None,
        0,
        None,
    ),
    (
        "ecam_tclab_Open_loop_experiment_on_MV_2022-03-01-09h52.txt",
        "t",
        "PV",
        "MV",
        None,
        0,
        None,
    ),
    ("enclosure_heater_doublet.csv", "1", "4", "2", None, 0, None),
    (
        "multistep_heater_synthetic.csv",
        "time (s)",
        "temperature (degC)",
        "heater (%)",
        None,
        0,
        None,
    ),
    (
        "pendulum_aprbs_synthetic.txt",
        "",
        "y",
        "u",
        Some(0.01),
        0,
        None,
    ),
    (
        "rc2_square_wave_adc_synthetic.csv",
        "",
        "2",
        "1",
        Some(0.008),
        0,
        None,
    ),
    (
        "rlc_step_underdamped_synthetic.csv",
        "",
        "V_C",
        "V_S",
        Some(3.3e-6),
        4,
        None,
    ),
    (
        "sbhs_step_not_at_rest_synthetic.txt",
        "1",
        "4",
        "2",
        None,
        0,
        None,
    ),
    (
        "tclab_step_q1_100_spikes.csv",
        "Time",
        "T1",
        "Q1",
        None,
        0,
        Some(0.0),
    ),
    (
        "tclab_step_q1_50_dropouts_synthetic.csv",
        "Time",
        "T1",
        "Q1",
        None,
        0,
        Some(0.0),
    ),
    (
        "tclab_step_q1_50_synthetic.csv",
        "Time",
        "T1",
        "Q1",
        None,
        0,
        None,
    ),
];

/// The path of record `name`.
pub fn path(name: &str) -> PathBuf {
    // The workspace's root: the crate's own folder, or the one above `crates/` for the
    // tests of a lower crate.
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let root = crate_dir
        .ancestors()
        .find(|d| d.join("tests/data/records").is_dir())
        .unwrap_or(crate_dir);
    root.join("tests/data/records").join(name)
}
