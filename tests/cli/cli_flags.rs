//! The command line's flags, tried as a fuzzer would: non-finite numbers in every numeric
//! flag of every subcommand, guesses that conflict with the model or with `--y0`, a start
//! count past the cap, odd counts and lists, and data files that are not regular files.
//! Each is refused with exit code 2 and words naming the flag or the conflict, never a
//! number printed with exit 0.

use crate::run;

use std::process::Command;

use run::{STEP, degrau, stderr};

/// Runs `args`, expects exit code 2 and an error containing every one of `words`.
fn refused(args: &[&str], words: &[&str]) {
    let out = degrau(args);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} printed a result");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for w in words {
        assert!(err.contains(w), "{args:?}: {err:?} lacks {w:?}");
    }
}

fn fit_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["fit", STEP];
    all.extend_from_slice(args);
    all.push("--json");
    let out = degrau(&all);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

#[test]
fn the_fixture_fits_to_its_known_parameters() {
    let j = fit_json(&["--model", "P1", "--y0", "50"]);
    let p = &j["params"];
    assert!((p["Kp"].as_f64().unwrap() - 2.0).abs() < 1e-4, "{p}");
    assert!((p["Tp1"].as_f64().unwrap() - 5.0).abs() < 1e-3, "{p}");
    assert_eq!(p["Y0"].as_f64().unwrap(), 50.0);
}

#[test]
fn non_finite_values_are_refused_in_every_numeric_flag() {
    let step = ["step", "--poles", "-1"];
    let step_flags = [
        "--gain",
        "--dc-gain",
        "--delay",
        "--amplitude",
        "--settling-threshold",
    ];
    let data_flags = ["--ts", "--t0", "--du", "--initial-input", "--filter"];
    for value in ["NaN", "inf", "-inf", "1e999"] {
        for flag in step_flags {
            let mut args = step.to_vec();
            args.extend([flag, value]);
            refused(&args, &[flag, "not a finite number"]);
        }
        for command in ["fit", "diagnose"] {
            for flag in data_flags {
                refused(
                    &[command, STEP, flag, value],
                    &[flag, "not a finite number"],
                );
            }
        }
        refused(
            &["open", STEP, "--ts", value],
            &["--ts", "not a finite number"],
        );
        refused(
            &["fit", STEP, "--guess", &format!("Kp={value}")],
            &["--guess", "finite"],
        );
        refused(
            &["fit", STEP, "--window", &format!("0,{value}")],
            &["--window"],
        );
        refused(&["fit", STEP, "--y0", value], &["--y0"]);
    }
    // The reproducer: `--t0 NaN` said "0 samples after the step".
    refused(&["fit", STEP, "--t0", "NaN", "--du", "1"], &["--t0", "NaN"]);
    refused(
        &["fit", STEP, "--t0", "two"],
        &["--t0", "is not a real number"],
    );
}

#[test]
fn huge_and_tiny_finite_steps_are_accepted_by_the_flags() {
    for du in ["1e200", "-1e-200", "1e-300"] {
        let out = degrau(&["fit", STEP, "--model", "P1", "--t0", "2", "--du", du]);
        assert!(
            !stderr(&out).contains("invalid value"),
            "{du}: {}",
            stderr(&out)
        );
    }
}

#[test]
fn a_y0_guess_conflicts_with_a_held_y0() {
    refused(
        &["fit", STEP, "--y0", "50", "--guess", "Y0=40"],
        &["--guess Y0=40 conflicts with --y0 50", "--y0 free"],
    );
    // Held automatically at the mean before the step (50): also not estimated.
    refused(
        &["fit", STEP, "--guess", "Y0=40"],
        &["Y0 is held at 50", "--y0 free"],
    );
    // Estimated: the guess is where it starts.
    let j = fit_json(&["--model", "P1", "--y0", "free", "--guess", "Y0=40"]);
    assert!((j["params"]["Y0"].as_f64().unwrap() - 50.0).abs() < 1e-3);
}

#[test]
fn guesses_the_model_lacks_and_duplicates_are_named() {
    refused(
        &["fit", STEP, "--model", "P1D", "--guess", "Tz=1"],
        &["--guess Tz=1", "P1D has no Tz", "Kp, Tp1, Td"],
    );
    refused(
        &["fit", STEP, "--model", "P1", "--guess", "Zeta=0.5"],
        &["has no Zeta"],
    );
    refused(
        &["fit", STEP, "--guess", "Drift=0.1"],
        &["no drift term", "--drift"],
    );
    refused(
        &["fit", STEP, "--guess", "Kp=1,kp=2"],
        &["Kp twice", "1 and 2"],
    );
    refused(&["fit", STEP, "--guess", ","], &["--guess is empty"]);
    let j = fit_json(&["--model", "P1", "--drift", "--guess", "Drift=0,Kp=1"]);
    assert!((j["params"]["Kp"].as_f64().unwrap() - 2.0).abs() < 1e-3);
}

#[test]
fn starts_are_capped() {
    refused(
        &["fit", STEP, "--starts", "100000"],
        &["100000 starts", "1000"],
    );
    refused(
        &["fit", STEP, "--starts", "0"],
        &["0 starts", "1 (the guess only)"],
    );
    refused(&["fit", STEP, "--starts", "-3"], &["--starts"]);
    let j = fit_json(&["--model", "P1", "--starts", "1000"]);
    assert_eq!(j["model"], "P1");
}

#[test]
fn odd_counts_and_lists_are_refused() {
    refused(
        &["step", "--poles", "-1", "--samples", "0"],
        &["samples must be between 2"],
    );
    refused(
        &["step", "--poles", "-1", "--samples", "1000001"],
        &["samples must be between 2 and 1000000"],
    );
    refused(
        &[
            "step",
            "--poles",
            "-1",
            "--samples",
            "99999999999999999999999",
        ],
        &["--samples"],
    );
    refused(
        &["step", "--poles", "-1", "--samples", "-5"],
        &["--samples"],
    );
    refused(&["step", "--poles", ""], &["no poles"]);
    refused(&["step", "--poles", ",,"], &["--poles"]);
    refused(&["step", "--num", "1", "--den", ""], &["--den is empty"]);
    refused(
        &["step", "--poles", "-1", "--rise-limits", ""],
        &["rise limits"],
    );
    refused(
        &["step", "--poles", "-1", "--rise-limits", "0.1,nan"],
        &["--rise-limits"],
    );
    refused(&["fit", STEP, "--window", "5,1"], &["--window"]);
    refused(&["fit", STEP, "--window", "5"], &["--window"]);
    refused(&["fit", STEP, "--window", ""], &["--window"]);
    refused(&["fit", STEP, "--model", ""], &[]);
    refused(&["fit", STEP, "--y-col", "0"], &["column 0"]);
    refused(&["fit", STEP, "--skip-rows", "100000"], &["no data"]);
    refused(&["fit", STEP, "--du", "0"], &["Δu"]);
    refused(&["fit", STEP, "--filter", "0"], &[]);
    refused(&["fit", STEP, "--filter", "-1"], &[]);
    refused(&["diagnose", STEP, "--start", "P0"], &[]);
}

#[test]
fn data_files_that_are_not_regular_files_are_refused() {
    let dir = env!("CARGO_TARGET_TMPDIR");
    refused(&["fit", dir], &["a directory, not a regular file"]);
    refused(&["diagnose", dir], &["a directory"]);
    #[cfg(target_os = "linux")]
    refused(&["fit", "/dev/zero"], &["a device", "not a regular file"]);
    #[cfg(unix)]
    {
        let fifo = std::path::Path::new(dir).join(format!("cli-flags-{}.fifo", std::process::id()));
        let made = Command::new("mkfifo").arg(&fifo).status();
        assert!(made.is_ok_and(|s| s.success()), "mkfifo {}", fifo.display());
        let path = fifo.display().to_string();
        // Before the fix this blocked for ever: no writer ever opens the FIFO.
        refused(&["fit", &path], &["a named pipe (FIFO)"]);
        std::fs::remove_file(&fifo).ok();
    }
}
