//! The answer key of `degrau exercise`: the JSON a teacher keeps, `generator_version`,
//! `seed`, `level`, `start` and one entry per record (`file`, `causes`, `structure`, `kp`,
//! `kp_tolerance`).

use serde::{Deserialize, Serialize};

use crate::ident::challenge::{Challenge, GENERATOR_VERSION, START, logger::significant};

/// The key file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Key {
    pub generator_version: u32,
    pub seed: u64,
    pub level: String,
    /// The model the records are meant to be fitted from.
    #[serde(default = "default_start")]
    pub start: String,
    pub records: Vec<KeyRecord>,
}

fn default_start() -> String {
    START.to_string()
}

/// One record's answer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeyRecord {
    pub file: String,
    /// Cause ids as `degrau diagnose` writes them (any one is right), or `["none"]`.
    pub causes: Vec<String>,
    pub structure: String,
    pub kp: f64,
    /// Relative.
    pub kp_tolerance: f64,
}

impl KeyRecord {
    /// The entry of `challenge`, written as `file`; the gain with the CSV's significant
    /// digits, so that the key's bytes are the same on every machine.
    pub fn new(file: String, challenge: &Challenge) -> Self {
        Self {
            file,
            causes: challenge.causes.clone(),
            structure: challenge.structure.clone(),
            kp: significant(challenge.kp).parse().unwrap_or(challenge.kp),
            kp_tolerance: challenge.kp_tolerance,
        }
    }

    /// The causes as one label (`dead_time/extra_pole`): the key of the summary per cause.
    pub fn label(&self) -> String {
        self.causes.join("/")
    }
}

impl Key {
    pub fn new(seed: u64, level: &str, records: Vec<KeyRecord>) -> Self {
        Self {
            generator_version: GENERATOR_VERSION,
            seed,
            level: level.to_string(),
            start: START.to_string(),
            records,
        }
    }

    /// The record named `file`.
    pub fn record(&self, file: &str) -> Option<&KeyRecord> {
        self.records.iter().find(|r| r.file == file)
    }
}
