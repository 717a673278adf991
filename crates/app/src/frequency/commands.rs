//! What the Frequency views ask for: every change to the mode's settings is one
//! [`Command`], returned by a view while it draws and applied by
//! [`super::session::Session::apply`] once per frame, after the views.

use super::session::{SourceKind, Tab};

/// One change to the Frequency mode's settings.
#[must_use = "a command does nothing until the session applies it"]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    /// Which system (or loop) the mode shows.
    SetSource(SourceKind),
    SetTab(Tab),
    /// A sampling period typed (s); refused, with the reason shown, unless positive.
    SetPeriod(f64),
    /// The Nyquist plot's bounds: the whole curve, or the window around −1.
    SetWholeCurve(bool),
}
