//! The file dialogs: what each is for ([`Pick`]) and the path chosen (the app turns it into
//! the command the choice makes). They are opened only while the app applies its commands,
//! never while a view draws.

use std::path::PathBuf;

use crate::words::app::App as T;
use degrau_words::Lang;

/// A file the student is asked to choose.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pick {
    /// A step test for the Identify mode, from the File menu (any file).
    AnyTest,
    /// A step test, from the Identify mode's panel (tables only).
    StepTest,
    /// The file that holds the test's input.
    InputFile,
    /// Where the designed PRBS test is written.
    PrbsCsv,
    /// Where the export window saves.
    ExportPath,
}

/// The file kinds a step test or an input is read from.
const TABLES: [&str; 4] = ["csv", "tsv", "txt", "dat"];

/// Opens the dialog (its kinds of file named in `lang`); the path chosen, none when it was
/// cancelled.
pub fn choose(pick: Pick, lang: Lang) -> Option<PathBuf> {
    let dialog = rfd::FileDialog::new();
    match pick {
        Pick::AnyTest => dialog.pick_file(),
        Pick::StepTest => dialog
            .add_filter(T::StepTestFiles.get(lang), &TABLES)
            .pick_file(),
        Pick::InputFile => dialog
            .add_filter(T::InputFiles.get(lang), &TABLES)
            .pick_file(),
        Pick::PrbsCsv => dialog.set_file_name("prbs_test.csv").save_file(),
        Pick::ExportPath => dialog.set_file_name("degrau_step.png").save_file(),
    }
}
