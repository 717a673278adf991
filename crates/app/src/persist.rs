//! The app's own state file (`state.json`): where it lives, how a saved session is restored
//! field by field (a bad field falls back to its default alone and is named), and a saver
//! thread that writes the file atomically soon after every change, whether or not the app
//! paints another frame.
//!
//! The file is in the platform's data directory (`$XDG_DATA_HOME/degrau`,
//! `~/Library/Application Support/Degrau`, `%APPDATA%\Degrau`), or in the directory named by
//! [`STATE_DIR_VAR`]. It is written as a temporary file in the same directory, flushed to
//! disk, then renamed over the old one, so a kill at any moment leaves either the old or the
//! new state whole. A file that cannot be restored whole is copied aside
//! (`state.json.bad-<unix seconds>`) before anything overwrites it.
//!
//! What could not be restored or saved is told as typed facts ([`problem`]), said in the
//! window's language by [`crate::words::persist`].

pub mod problem;

pub use problem::{
    ExperimentProblem, Field, FieldProblem, FileAction, Reason, SaveFailure, StateError, TestValue,
};

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use eframe::egui;
use serde::de::DeserializeOwned;
use serde_json::{Map, Value};

use super::Saved;
use super::design;
use super::design::plane::{SPlaneState, View};
use super::design::state::{self, RootRole, System};
use super::exercises;
use super::frequency;
use super::identify;
use super::look::clamp_scale;
use super::tune;
use degrau_ident::experiment::{Experiment, Offset};
use degrau_ident::fit::MAX_STARTS;
use degrau_ident::model::Structure;

/// The environment variable naming the directory of the state file (tests use a temporary
/// one).
pub const STATE_DIR_VAR: &str = "DEGRAU_STATE_DIR";
/// The state file's name in its directory.
pub const FILE_NAME: &str = "state.json";
/// Largest state file read (bytes); a bigger one is not a state the app wrote.
const MAX_STATE_BYTES: u64 = 16 << 20;
/// How long the saver waits for further changes before writing (a drag writes a few times
/// a second, not every frame).
pub const DEBOUNCE: Duration = Duration::from_millis(200);

/// The state file's path: in [`STATE_DIR_VAR`] if set, else in the platform data directory;
/// `None` when there is no home to put it in.
pub fn default_path() -> Option<PathBuf> {
    let var = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty());
    let dir = if let Some(dir) = var(STATE_DIR_VAR) {
        PathBuf::from(dir)
    } else if cfg!(windows) {
        PathBuf::from(var("APPDATA")?).join("Degrau")
    } else if cfg!(target_os = "macos") {
        PathBuf::from(var("HOME")?).join("Library/Application Support/Degrau")
    } else if let Some(data) = var("XDG_DATA_HOME") {
        PathBuf::from(data).join("degrau")
    } else {
        PathBuf::from(var("HOME")?).join(".local/share/degrau")
    };
    Some(dir.join(FILE_NAME))
}

/// A session restored from a file.
#[derive(Debug)]
pub struct Restored {
    pub saved: Saved,
    pub problems: Vec<FieldProblem>,
    /// Where the unreadable file was copied, when something could not be restored.
    pub backup: Option<PathBuf>,
    /// Why the file could not be copied aside, if it could not.
    pub backup_error: Option<String>,
}

/// Restores the session in `path` field by field; a missing file is a fresh start. When a
/// part could not be restored, the file is first copied aside.
pub fn restore(path: &Path) -> Restored {
    let (saved, problems) = match read(path) {
        Ok(None) => (Saved::default(), Vec::new()),
        Ok(Some(text)) => restore_text(&text),
        Err(e) => (Saved::default(), vec![whole_file(Reason::File(e))]),
    };
    let (mut backup, mut backup_error) = (None, None);
    if !problems.is_empty() && path.is_file() {
        match keep_aside(path) {
            Ok(p) => backup = Some(p),
            Err(e) => backup_error = Some(e.to_string()),
        }
    }
    Restored {
        saved,
        problems,
        backup,
        backup_error,
    }
}

/// The file's text; `None` when there is no file. A FIFO or device is refused before it is
/// opened (opening one could block), and so is a file past [`MAX_STATE_BYTES`].
fn read(path: &Path) -> Result<Option<String>, StateError> {
    let meta = match std::fs::metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(StateError::io(FileAction::LookAt, path, &e)),
    };
    if !meta.is_file() {
        return Err(StateError::NotAFile(path.to_path_buf()));
    }
    if meta.len() > MAX_STATE_BYTES {
        return Err(StateError::TooLarge(path.to_path_buf(), meta.len()));
    }
    let bytes = std::fs::read(path).map_err(|e| StateError::io(FileAction::Read, path, &e))?;
    Ok(Some(String::from_utf8_lossy(&bytes).into_owned()))
}

fn whole_file(reason: Reason) -> FieldProblem {
    FieldProblem {
        field: Field::WholeFile,
        reason,
    }
}

/// Copies `path` to `path.bad-<unix seconds>` (with `-2`, `-3`… if taken).
fn keep_aside(path: &Path) -> std::io::Result<PathBuf> {
    let seconds = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let base = format!("{}.bad-{seconds}", path.display());
    let target = (1..)
        .map(|n| match n {
            1 => PathBuf::from(&base),
            n => PathBuf::from(format!("{base}-{n}")),
        })
        .find(|p| !p.exists())
        .unwrap_or_else(|| PathBuf::from(&base));
    std::fs::copy(path, &target)?;
    Ok(target)
}

/// Restores a session from the text of a state file, field by field.
pub fn restore_text(text: &str) -> (Saved, Vec<FieldProblem>) {
    match serde_json::from_str::<Value>(text) {
        Ok(value) => restore_value(&value),
        Err(e) => (
            Saved::default(),
            vec![whole_file(Reason::NotJson {
                line: e.line(),
                column: e.column(),
            })],
        ),
    }
}

/// Restores a session from a JSON value, field by field: each top-level field (and each
/// field of the system, the s-plane state and the identification settings) is read and
/// checked on its own; a bad one falls back to its default and is reported.
pub fn restore_value(value: &Value) -> (Saved, Vec<FieldProblem>) {
    let mut problems = Vec::new();
    let Some(obj) = value.as_object() else {
        return (Saved::default(), vec![whole_file(Reason::NotAnObject)]);
    };
    let d = Saved::default();
    let mut f = Fields::new(Some(obj), "", &mut problems);
    let system = restore_system(f.nested("system"), d.design.system);
    let design = design::Saved {
        compare: f.checked("compare", d.design.compare, |c| {
            c.as_ref().map_or(Ok(()), |(_, s)| {
                s.check().map_err(Reason::System)?;
                s.placement().map_err(Reason::Placement)
            })
        }),
        splane: restore_splane(f.nested("splane"), d.design.splane),
        markers: f.take("markers", d.design.markers),
        options: f.checked("options", d.design.options, |o| {
            o.check().map_err(Reason::Options)
        }),
        phase_form: f.take("phase_form", d.design.phase_form),
        feedback: f.checked("feedback", d.design.feedback, |l| {
            l.validate().map_err(Reason::Loop)
        }),
        approx: f.take("approx", d.design.approx),
        approx_table: f.take("approx_table", d.design.approx_table),
        system,
    };
    let mut saved = Saved {
        mode: f.take("mode", d.mode),
        ident: restore_ident(f.nested("ident"), d.ident),
        tune: restore_tune(f.nested("tune"), d.tune),
        frequency: restore_frequency(f.nested("frequency"), d.frequency),
        exercises: restore_exercises(f.nested("exercises"), d.exercises),
        design,
        dark: f.take("dark", d.dark),
        lang: f.take("lang", d.lang),
        scale: f.checked("scale", d.scale, |s| {
            if clamp_scale(*s) == *s {
                Ok(())
            } else {
                Err(Reason::Scale(*s))
            }
        }),
    };
    // A selection that names no root of the restored system is dropped (nothing to tell).
    if let Some(id) = saved.design.splane.selected
        && saved.design.system.root(id).is_none()
    {
        saved.design.splane.selected = None;
    }
    (saved, problems)
}

fn restore_system(mut f: Fields<'_>, d: System) -> System {
    let fallback = d.clone();
    let system = System {
        poles: f.checked("poles", d.poles, |l| {
            state::check_roots(RootRole::Pole, l).map_err(Reason::System)
        }),
        zeros: f.checked("zeros", d.zeros, |l| {
            state::check_roots(RootRole::Zero, l).map_err(Reason::System)
        }),
        gain: f.checked("gain", d.gain, |g| {
            state::check_gain(*g).map_err(Reason::System)
        }),
        gain_mode: f.take("gain_mode", d.gain_mode),
        delay: f.checked("delay", d.delay, |t| {
            state::check_delay(*t).map_err(Reason::System)
        }),
        amplitude: f.checked("amplitude", d.amplitude, |a| {
            state::check_amplitude(*a).map_err(Reason::System)
        }),
    };
    // Roots each within range but too far apart for the exact response fall back whole.
    match system.placement() {
        Ok(()) => system,
        Err(why) => {
            f.problems.push(FieldProblem {
                field: f.name("poles"),
                reason: Reason::Placement(why),
            });
            fallback
        }
    }
}

fn restore_splane(mut f: Fields<'_>, d: SPlaneState) -> SPlaneState {
    let mut s = d;
    s.view = f.checked("view", s.view, |v| v.as_ref().map_or(Ok(()), check_view));
    s.damping_grid = f.take("damping_grid", s.damping_grid);
    s.snap = f.take("snap", s.snap);
    s.selected = f.take("selected", s.selected);
    s
}

/// A restored view must already be sane: one that is not is fitted to the roots again.
fn check_view(v: &View) -> Result<(), Reason> {
    if v.is_sane() {
        Ok(())
    } else {
        Err(Reason::View(*v))
    }
}

fn restore_ident(mut f: Fields<'_>, d: identify::Saved) -> identify::Saved {
    identify::Saved {
        path: f.take("path", d.path),
        example: f.take("example", d.example),
        experiment: f.checked("experiment", d.experiment, |e| {
            e.as_ref()
                .map_or(Ok(()), |e| check_experiment(e).map_err(Reason::Experiment))
        }),
        time_col: f.take("time_col", d.time_col),
        y_col: f.take("y_col", d.y_col),
        u_col: f.take("u_col", d.u_col),
        sampling_period: f.take("sampling_period", d.sampling_period),
        initial_input: f.take("initial_input", d.initial_input),
        u_path: f.take("u_path", d.u_path),
        // Any structure: the diagnosis ends on ones the menu does not list (P3Z, P3DU…).
        code: f.checked("code", d.code, |c| {
            Structure::parse(c)
                .map(|_| ())
                .map_err(|_| Reason::Code(c.clone()))
        }),
        drift: f.take("drift", d.drift),
        method: f.take("method", d.method),
        multistart: f.take("multistart", d.multistart),
        starts: f.checked("starts", d.starts, |&n| {
            if (1..=MAX_STARTS).contains(&n) {
                Ok(())
            } else {
                Err(Reason::Starts(n))
            }
        }),
    }
}

/// The Tune mode's settings: a model that is a model, a controller whose every number is
/// usable (Ti and Td included, whatever the action), a positive τc.
fn restore_tune(mut f: Fields<'_>, d: tune::Saved) -> tune::Saved {
    tune::Saved {
        model: f.checked("model", d.model, |m| m.check().map_err(Reason::TuneModel)),
        received: f.take("received", d.received),
        controller: f.checked("controller", d.controller, |c| {
            c.check().map_err(Reason::Controller)
        }),
        tc: f.checked("tc", d.tc, |t| {
            t.map_or(Ok(()), |t| {
                tune::session::check_tc(t).map_err(Reason::TuneModel)
            })
        }),
        rule: f.take("rule", d.rule),
    }
}

/// The Frequency mode's settings: a sampling period that is a positive number of seconds.
fn restore_frequency(mut f: Fields<'_>, d: frequency::Saved) -> frequency::Saved {
    frequency::Saved {
        source: f.take("source", d.source),
        tab: f.take("tab", d.tab),
        h: f.checked("h", d.h, |&h| {
            frequency::session::check_period(h).map_err(|_| Reason::SamplingPeriod(h))
        }),
        whole_curve: f.take("whole_curve", d.whole_curve),
    }
}

/// The Exercises mode's progress: each answer read on its own (an unreadable one is
/// reported and dropped), the Challenges' state as a whole, then what names no part or question of the sheet is dropped.
fn restore_exercises(mut f: Fields<'_>, d: exercises::Saved) -> exercises::Saved {
    let part = f.take("part", d.part);
    let mut each = f.nested("answers");
    let answers = each
        .keys()
        .into_iter()
        .filter_map(|id| {
            let answer = each.take::<Option<exercises::session::Answer>>(&id, None)?;
            Some((id, answer))
        })
        .collect();
    let challenges = f.take("challenges", d.challenges);
    let mut kept = exercises::Saved {
        part,
        answers,
        challenges,
    };
    if let Ok(sheet) = exercises::session::the_sheet() {
        exercises::session::prune(&mut kept, sheet);
    }
    kept
}

/// The choices on a test: every number finite, Δu ≠ 0, a window with start < end and a
/// filter cut-off > 0.
fn check_experiment(e: &Experiment) -> Result<(), ExperimentProblem> {
    let finite = |what, value: f64| {
        if value.is_finite() {
            Ok(())
        } else {
            Err(ExperimentProblem::NotFinite { what, value })
        }
    };
    finite(TestValue::StepTime, e.t0)?;
    finite(TestValue::StepSize, e.du)?;
    if e.du == 0.0 {
        return Err(ExperimentProblem::ZeroStep);
    }
    if let Offset::Fixed(y0) = e.offset {
        finite(TestValue::OperatingPoint, y0)?;
    }
    if let Some((a, b)) = e.window {
        finite(TestValue::WindowStart, a)?;
        finite(TestValue::WindowEnd, b)?;
        if a >= b {
            return Err(ExperimentProblem::EmptyWindow(a, b));
        }
    }
    if let Some(fc) = e.filter_hz
        && !(fc.is_finite() && fc > 0.0)
    {
        return Err(ExperimentProblem::Filter(fc));
    }
    Ok(())
}

/// The fields of one JSON object being restored, with where to report problems.
struct Fields<'a> {
    obj: Option<&'a Map<String, Value>>,
    prefix: String,
    problems: &'a mut Vec<FieldProblem>,
}

impl<'a> Fields<'a> {
    fn new(
        obj: Option<&'a Map<String, Value>>,
        prefix: &str,
        problems: &'a mut Vec<FieldProblem>,
    ) -> Self {
        Self {
            obj,
            prefix: prefix.to_string(),
            problems,
        }
    }

    fn name(&self, field: &str) -> Field {
        Field::Path(format!("{}{field}", self.prefix))
    }

    /// The field, or `default` when it is missing (a file from another version) or bad.
    fn take<T: DeserializeOwned>(&mut self, field: &str, default: T) -> T {
        self.checked(field, default, |_| Ok(()))
    }

    /// The field if it reads as a `T` and passes `check`; else `default`, and the problem
    /// is reported. A missing field is not a problem.
    fn checked<T: DeserializeOwned>(
        &mut self,
        field: &str,
        default: T,
        check: impl Fn(&T) -> Result<(), Reason>,
    ) -> T {
        let Some(value) = self.obj.and_then(|o| o.get(field)) else {
            return default;
        };
        let read = T::deserialize(value)
            .map_err(|_| Reason::Unreadable {
                found: problem::quoted(value),
            })
            .and_then(|t| check(&t).map(|()| t));
        match read {
            Ok(t) => t,
            Err(reason) => {
                self.problems.push(FieldProblem {
                    field: self.name(field),
                    reason,
                });
                default
            }
        }
    }

    /// The names of the object's fields.
    fn keys(&self) -> Vec<String> {
        self.obj
            .map_or_else(Vec::new, |o| o.keys().cloned().collect())
    }

    /// The fields of the nested object `field`; one that is not an object is reported and
    /// restores as all defaults.
    fn nested(&mut self, field: &str) -> Fields<'_> {
        let value = self.obj.and_then(|o| o.get(field));
        let obj = match value {
            Some(Value::Object(o)) => Some(o),
            Some(other) => {
                self.problems.push(FieldProblem {
                    field: self.name(field),
                    reason: Reason::ExpectedObject {
                        found: problem::quoted(other),
                    },
                });
                None
            }
            None => None,
        };
        let prefix = format!("{}{field}.", self.prefix);
        Fields::new(obj, &prefix, self.problems)
    }
}

/// Writes `contents` to `path` atomically: a temporary file in the same directory, flushed
/// to disk, then renamed over `path` (and the directory flushed, where that is possible).
pub fn write_atomically(path: &Path, contents: &[u8]) -> Result<(), StateError> {
    let io = |action, path: &Path, e: std::io::Error| StateError::io(action, path, &e);
    let dir = path.parent().unwrap_or_else(|| Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| io(FileAction::Create, dir, e))?;
    let name = path
        .file_name()
        .map_or_else(|| FILE_NAME.into(), |n| n.to_string_lossy().into_owned());
    let temp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let written = std::fs::File::create(&temp).and_then(|mut file| {
        file.write_all(contents)?;
        file.sync_all()
    });
    if let Err(e) = written {
        std::fs::remove_file(&temp).ok();
        return Err(io(FileAction::Write, &temp, e));
    }
    if let Err(e) = std::fs::rename(&temp, path) {
        std::fs::remove_file(&temp).ok();
        return Err(io(FileAction::Replace, path, e));
    }
    // The rename is durable once the directory is flushed (Unix; elsewhere it cannot be
    // opened and the rename stands as it is).
    if let Ok(d) = std::fs::File::open(dir) {
        d.sync_all().ok();
    }
    Ok(())
}

/// A snapshot for the saver and the context to wake if writing it fails.
struct Snapshot {
    json: String,
    ctx: Option<egui::Context>,
}

/// Saves snapshots of the session on its own thread: each is written (atomically) at most
/// [`DEBOUNCE`] after it was offered, later snapshots replacing earlier ones still waiting.
/// Dropping the saver writes what is waiting and joins the thread.
pub struct Saver {
    path: PathBuf,
    tx: Option<Sender<Snapshot>>,
    errors: Receiver<StateError>,
    thread: Option<JoinHandle<()>>,
    /// The last snapshot offered, so an unchanged session is not sent again.
    last: Option<String>,
}

impl Saver {
    /// Starts the saver thread for the file at `path`.
    pub fn spawn(path: PathBuf) -> Self {
        let (tx, rx) = mpsc::channel::<Snapshot>();
        let (error_tx, errors) = mpsc::channel();
        let target = path.clone();
        let thread = std::thread::Builder::new()
            .name("degrau state saver".into())
            .spawn(move || save_loop(&target, &rx, &error_tx))
            .ok();
        Self {
            path,
            tx: thread.is_some().then_some(tx),
            errors,
            thread,
            last: None,
        }
    }

    /// The file being written.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Hands the session's JSON to the saver when it differs from the last one offered.
    /// Returns false when there is no saver thread (it could not start or has stopped).
    pub fn offer(&mut self, json: String, ctx: Option<&egui::Context>) -> bool {
        if self.last.as_deref() == Some(json.as_str()) {
            return true;
        }
        let Some(tx) = &self.tx else {
            return false;
        };
        let sent = tx
            .send(Snapshot {
                json: json.clone(),
                ctx: ctx.cloned(),
            })
            .is_ok();
        if sent {
            self.last = Some(json);
        } else {
            self.tx = None;
        }
        sent
    }

    /// The latest failure to write, if any happened since the last call.
    pub fn take_error(&self) -> Option<StateError> {
        self.errors.try_iter().last()
    }
}

impl Drop for Saver {
    fn drop(&mut self) {
        // Closing the channel makes the thread write what is waiting and stop.
        self.tx = None;
        if let Some(thread) = self.thread.take() {
            thread.join().ok();
        }
    }
}

/// The saver thread: wait for a snapshot, let later ones replace it for up to [`DEBOUNCE`],
/// write the latest, repeat until the app drops its end.
fn save_loop(path: &Path, rx: &Receiver<Snapshot>, errors: &Sender<StateError>) {
    while let Ok(mut latest) = rx.recv() {
        let deadline = Instant::now() + DEBOUNCE;
        let mut open = true;
        loop {
            match rx.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
                Ok(newer) => latest = newer,
                Err(RecvTimeoutError::Timeout) => break,
                Err(RecvTimeoutError::Disconnected) => {
                    open = false;
                    break;
                }
            }
        }
        if let Err(e) = write_atomically(path, latest.json.as_bytes()) {
            errors.send(e).ok();
            if let Some(ctx) = &latest.ctx {
                ctx.request_repaint();
            }
        }
        if !open {
            return;
        }
    }
}

#[cfg(test)]
mod tests;
