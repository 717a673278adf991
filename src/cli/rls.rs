//! `degrau rls FILE --na N --nb N --nk N --lambda L --p0 A`: recursive least squares on the
//! samples of a record, with the parameter trajectory (`trajectory` in the JSON, one θ per
//! row of Φ) and the last estimate (`final`), plus the ARX keys of the last model. Its
//! standard errors are σ̂·√(P_N)ᵢᵢ, σ̂² = J/(N − p): P_N is σ̂⁻²·cov(θ̂) at λ = 1 (the notes:
//! "P_k é proporcional à matriz de covariância das estimativas").

use std::io::{self, Write};

use clap::Args;
use serde::Serialize;

use crate::ident::lsq::arx::Offset;
use crate::ident::lsq::rls::{RlsOptions, rls_arx};
use crate::ident::lsq::validation::score_arx;
use crate::text::Lang;
use crate::text::lsq::LsqPhrase;

use super::CliError;
use super::arx::{
    ArxJson, Figures, LsqCliError, OrderArgs, ValidationJson, columns, estimation_end,
    write_figures, write_validation,
};
use super::fit::DataArgs;

/// `degrau rls` options.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Examples:
  degrau rls tclab_step_q1_50.csv --y-col T1 --u-col Q1 --na 1 --nb 1 --nk 4 --json
  degrau rls prbs.csv --na 2 --nb 2 --lambda 0.98 --p0 1000")]
pub struct RlsArgs {
    #[command(flatten)]
    pub data: DataArgs,
    #[command(flatten)]
    pub orders: OrderArgs,
    /// Forgetting factor λ in (0, 1] (1: the notes' form, every sample weighs the same).
    #[arg(long, default_value_t = 1.0, value_parser = super::finite_f64)]
    pub lambda: f64,
    /// P0 = α·I: large α, little trust in the initial θ (zeros).
    #[arg(long, default_value_t = 1e6, value_parser = super::finite_f64)]
    pub p0: f64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The RLS JSON: the ARX keys of the last model, its trajectory and last θ.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RlsJson {
    #[serde(flatten)]
    pub model: ArxJson,
    pub lambda: f64,
    pub p0: f64,
    /// θ after each row of Φ.
    pub trajectory: Vec<Vec<f64>>,
    #[serde(rename = "final")]
    pub last: Vec<f64>,
}

/// `degrau rls`.
pub fn run_rls(args: &RlsArgs, lang: Lang) -> Result<(), LsqCliError> {
    let (time, u, y) = columns(&args.data)?;
    let offset: Offset = args.orders.offset.into();
    let end = estimation_end(&time, args.orders.validate)?;
    let options = RlsOptions {
        alpha: args.p0,
        lambda: args.lambda,
        theta0: None,
    };
    let orders = args.orders.orders();
    let fit = rls_arx(&time[..end], &u[..end], &y[..end], orders, offset, &options)?;
    let figures = Figures {
        model: &fit.model,
        offset,
        regression: &fit.regression,
        estimate: &fit.run.estimate,
        scores: &fit.scores,
        aic: fit.aic,
    };
    let validation = args
        .orders
        .validate
        .map(|_| ValidationJson::from(&score_arx(&fit.model, &time, &u, &y, end)));
    let mut out = io::stdout().lock();
    let written = if args.json {
        let mut model = ArxJson::new(&figures);
        model.validation = validation;
        super::write_json_line(
            &mut out,
            &RlsJson {
                model,
                lambda: args.lambda,
                p0: args.p0,
                trajectory: fit.run.trajectory.clone(),
                last: fit.run.last.clone(),
            },
        )
    } else {
        (|| {
            writeln!(out, "{}", LsqPhrase::RlsHeading.get(lang))?;
            writeln!(
                out,
                "{}: {}; {}: {}",
                LsqPhrase::Forgetting.get(lang),
                lang.num(args.lambda, 6),
                LsqPhrase::InitialCovariance.get(lang),
                lang.num(args.p0, 6)
            )?;
            write_figures(&mut out, &figures, lang)?;
            if let Some(v) = &validation {
                write_validation(&mut out, v, lang)?;
            }
            Ok(())
        })()
    };
    written.map_err(|e| LsqCliError::Cli(CliError::WriteOutput(e)))
}
