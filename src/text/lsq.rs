//! The words of `degrau arx`'s and `degrau rls`'s own refusals; the least squares' words are
//! the ident crate's ([`degrau_ident::words::lsq`]), re-exported here.

pub use degrau_ident::words::lsq::*;

use crate::cli::arx::LsqCliError;

use super::{Lang, Localize};

impl Localize for LsqCliError {
    fn text(&self, lang: Lang) -> String {
        match self {
            LsqCliError::Cli(e) => e.text(lang),
            LsqCliError::NoInput => lang
                .pick(
                    "the file has no input column: least squares needs u(k) (give it with --u-col)",
                    "o arquivo não tem coluna de entrada: mínimos quadrados precisam de u(k) (indique-a com --u-col)",
                )
                .into(),
            LsqCliError::Levels(text) => lang.pick(
                format!("--levels \"{text}\" must be two numbers, low then high, e.g. 0,1"),
                format!("--levels \"{text}\" deve ter dois números, o baixo e o alto, p. ex. 0,1"),
            ),
            LsqCliError::Lsq(e) => e.text(lang),
            LsqCliError::Discrete(e) => e.text(lang),
            LsqCliError::Prbs(e) => e.text(lang),
        }
    }
}
