//! The file dialogs: what each is for ([`Pick`]) and the command its choice makes. They are
//! opened only while the app applies its commands, never while a view draws.

use std::path::PathBuf;

use crate::identify::commands::Choice;
use crate::words::app::App as T;
use crate::{Command, export, identify, lsq};
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

/// Opens the dialog (its kinds of file named in `lang`); the command the choice makes, none
/// when it was cancelled.
pub fn choose(pick: Pick, lang: Lang) -> Option<Command> {
    let dialog = rfd::FileDialog::new();
    Some(match pick {
        Pick::AnyTest => Command::Identify(identify::Command::Open(text(dialog.pick_file()?))),
        Pick::StepTest => {
            let chosen = dialog
                .add_filter(T::StepTestFiles.get(lang), &TABLES)
                .pick_file()?;
            Command::Identify(identify::Command::Open(text(chosen)))
        }
        Pick::InputFile => {
            let chosen = dialog
                .add_filter(T::InputFiles.get(lang), &TABLES)
                .pick_file()?;
            Command::Identify(identify::Command::SetChoice(
                Choice::InputFile,
                text(chosen),
            ))
        }
        Pick::PrbsCsv => {
            let chosen = dialog.set_file_name("prbs_test.csv").save_file()?;
            Command::Lsq(lsq::Command::ExportPrbs(chosen))
        }
        Pick::ExportPath => {
            let chosen = dialog.set_file_name("degrau_step.png").save_file()?;
            Command::Export(export::Command::SetPath(text(chosen)))
        }
    })
}

/// A chosen path as the text the fields and the loader take.
fn text(path: PathBuf) -> String {
    path.display().to_string()
}
