//! The app and its state file: an app made from a saved session (checked field by field,
//! what could not be restored told in a notice), from the file in its usual place or named,
//! with the step test of the command line in place of the saved one; and the saver it hands
//! the session to after each change, whose failures become a notice.

use std::time::Instant;

use eframe::egui;

use crate::persist::{self, SaveFailure};
use crate::words::app::Notice;
use crate::{DegrauApp, Mode, Saved, identify};

impl DegrauApp {
    /// An app showing `saved`, checked field by field as a restored file is (a bad field
    /// falls back to its default with a notice); nothing is written to disk.
    pub fn new(saved: Saved) -> Self {
        let (saved, problems) = match serde_json::to_value(&saved) {
            Ok(value) => persist::restore_value(&value),
            Err(_) => (
                Saved::default(),
                vec![persist::FieldProblem {
                    field: persist::Field::WholeSession,
                    reason: persist::Reason::NotWritable,
                }],
            ),
        };
        let mut app = Self::unchecked(saved);
        app.notices.extend(restore_notice(&problems, None, None));
        app
    }

    /// The session kept in the state file at `path` (restored field by field; a file that
    /// could not be restored whole is copied aside first), saved there after every change.
    pub fn with_state_file(path: std::path::PathBuf) -> Self {
        Self::from_state_file(path, None)
    }

    /// [`Self::with_state_file`] with the step test named on the command line (`degrau
    /// open FILE` and its flags) in place of the saved one: the flags win over the last
    /// session, which would otherwise load its own record first and then clear the new
    /// record's column choices as left over from it.
    pub fn opening(path: std::path::PathBuf, test: identify::Saved) -> Self {
        Self::from_state_file(path, Some(test))
    }

    fn from_state_file(path: std::path::PathBuf, test: Option<identify::Saved>) -> Self {
        let mut restored = persist::restore(&path);
        if let Some(test) = test {
            restored.saved.ident = test;
            restored.saved.mode = Mode::Identify;
            // What could not be restored of the last record's settings is replaced whole.
            restored
                .problems
                .retain(|p| !matches!(&p.field, persist::Field::Path(f) if f.starts_with("ident")));
        }
        let mut app = Self::unchecked(restored.saved);
        app.notices.extend(restore_notice(
            &restored.problems,
            restored.backup.as_deref(),
            restored.backup_error.as_deref(),
        ));
        app.saver = Some(persist::Saver::spawn(path));
        app
    }

    /// The last session from the state file in its usual place ([`persist::default_path`]),
    /// or the built-in example.
    pub fn restore() -> Self {
        Self::restore_opening(None)
    }

    /// [`Self::restore`], with the step test named on the command line in place of the
    /// saved one ([`Self::opening`]).
    pub fn restore_opening(test: Option<identify::Saved>) -> Self {
        match persist::default_path() {
            Some(path) => Self::from_state_file(path, test),
            None => {
                let mut saved = Saved::default();
                if let Some(test) = test {
                    saved.ident = test;
                    saved.mode = Mode::Identify;
                }
                let mut app = Self::new(saved);
                app.notices.push(Notice::NoHome);
                app
            }
        }
    }

    /// The state file the session is saved to, if it is saved.
    pub fn state_file(&self) -> Option<&std::path::Path> {
        self.saver.as_ref().map(|s| s.path())
    }

    /// Hands the session to the saver when something changed (during a drag at most once
    /// per [`persist::DEBOUNCE`]), and shows a notice when writing failed.
    pub(crate) fn autosave(&mut self, ctx: &egui::Context) {
        let Some(saver) = self.saver.as_mut() else {
            return;
        };
        let recent = self
            .last_offer
            .is_some_and(|t| t.elapsed() < persist::DEBOUNCE);
        let dragging = ctx.input(|i| i.pointer.any_down());
        let failure = if self.dirty && !(dragging && recent) {
            self.saved.ident = self.ident.settings_to_save();
            self.dirty = false;
            self.last_offer = Some(Instant::now());
            serde_json::to_string_pretty(&self.saved)
                .map_err(|_| SaveFailure::NotWritable)
                .and_then(|json| {
                    saver
                        .offer(json, Some(ctx))
                        .then_some(())
                        .ok_or(SaveFailure::Stopped)
                })
                .err()
        } else {
            if self.dirty {
                ctx.request_repaint_after(persist::DEBOUNCE);
            }
            None
        };
        let failure = failure.or_else(|| saver.take_error().map(SaveFailure::File));
        if let Some(reason) = failure {
            let notice = Notice::SaveFailed(reason);
            if !self.notices.contains(&notice) {
                self.notices.push(notice);
            }
        }
    }
}

/// The notice of what could not be restored, naming each field, if anything.
fn restore_notice(
    problems: &[persist::FieldProblem],
    backup: Option<&std::path::Path>,
    backup_error: Option<&str>,
) -> Option<Notice> {
    if problems.is_empty() {
        return None;
    }
    Some(Notice::NotRestored {
        fields: problems.to_vec(),
        backup: backup.map(|p| p.display().to_string()),
        backup_error: backup_error.map(str::to_string),
    })
}
