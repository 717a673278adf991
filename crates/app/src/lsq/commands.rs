//! What the least-squares views ask of their session ([`Command`]), and what the session asks
//! of the app in return ([`Outcome`]). A view never changes the session while it draws: it
//! returns commands, applied once per frame before the next is drawn.

use degrau_ident::lsq::arx::{ArxOrders, Offset};
use degrau_ident::lsq::validation::Split;

use super::designer::PrbsSettings;

/// The parts of the mode, in the order of the notes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Section {
    /// ARX least squares on the record (Φ, θ, J, AIC, prediction and simulation, d2c).
    #[default]
    Arx,
    /// The notes' three-sample example, with its regressors.
    Example,
    /// Recursive least squares, animated sample by sample.
    Rls,
    /// A PRBS test designed, simulated on a model, exported or used as the record.
    Prbs,
    /// Estimation on one part of the record, validation on the other.
    Validation,
    /// The notes' sampling and amplitude rules with the record's numbers.
    Advisor,
}

impl Section {
    pub const ALL: [Section; 6] = [
        Section::Arx,
        Section::Example,
        Section::Rls,
        Section::Prbs,
        Section::Validation,
        Section::Advisor,
    ];
}

/// The three models of the notes' example, each with its regressors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ExampleModel {
    /// y(k) = θ0.
    Constant,
    /// y(k) = θ0 + θ1·u(k).
    Line,
    /// y(k) = θ0 + θ1·u(k) + θ2·u(k−1).
    #[default]
    TwoInputs,
}

impl ExampleModel {
    pub const ALL: [ExampleModel; 3] = [
        ExampleModel::Constant,
        ExampleModel::Line,
        ExampleModel::TwoInputs,
    ];
}

/// What a view asks of the least-squares session.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    SetSection(Section),
    /// The ARX orders (the fit shown no longer describes them until Fit).
    SetOrders(ArxOrders),
    SetOffset(Offset),
    /// Fit the ARX model of the orders, with the AIC grid.
    Fit,
    /// Fit the orders of a row of the AIC table.
    FitOrders(ArxOrders),
    SetExample(ExampleModel),
    /// The forgetting factor λ, in (0, 1].
    SetLambda(f64),
    /// P0 = α·I.
    SetAlpha(f64),
    RlsRun,
    RlsPause,
    RlsStep,
    RlsReset,
    SetPrbs(PrbsSettings),
    /// Choose where the designed record is written, with the file dialog.
    BrowsePrbsExport,
    /// Write the designed record as CSV (time, u, y) to this path.
    ExportPrbs(std::path::PathBuf),
    /// Load the designed record in the Identify mode.
    UsePrbs,
    SetSplit(Split),
    /// Fit the continuous model of the Identify mode on the estimation part (in the
    /// background).
    ValidateContinuous,
    CancelContinuous,
}

/// What the session asks of the app after a command.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Load this CSV text (time, u, y) as the Identify mode's record.
    UseRecord(String),
    /// Choose a file with the file dialog (the app opens it).
    Pick(crate::dialog::Pick),
}
