//! The words of `degrau hand`'s own refusals; the hand methods' words are the ident
//! crate's ([`degrau_ident::words::hand`]), re-exported here.

pub use degrau_ident::words::hand::*;

use crate::cli::hand::HandCliError;

use super::{Lang, Localize};

impl Localize for HandCliError {
    fn text(&self, lang: Lang) -> String {
        match self {
            HandCliError::Cli(e) => e.text(lang),
            HandCliError::Hand(e) => e.text(lang),
        }
    }
}
