//! What the Frequency views ask for: every change to the mode's settings is one
//! [`Command`], returned by a view while it draws and applied by
//! [`super::session::Session::apply`] once per frame, after the views.

use serde::{Deserialize, Serialize};

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

/// Which system the mode shows.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum SourceKind {
    /// The Design mode's G(s); the loop is L = G.
    #[default]
    Design,
    /// The Tune mode's loop L = C·G.
    Tune,
    /// The Identify mode's fitted model; the loop is L = G.
    Fitted,
}

impl SourceKind {
    pub const ALL: [SourceKind; 3] = [SourceKind::Design, SourceKind::Tune, SourceKind::Fitted];
}

/// The tab shown in the centre.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Tab {
    #[default]
    Bode,
    Nyquist,
    ZPlane,
}

impl Tab {
    pub const ALL: [Tab; 3] = [Tab::Bode, Tab::Nyquist, Tab::ZPlane];
}
