//! The words of `degrau approx`'s own refusals; the approximations' words are the lti
//! crate's ([`degrau_lti::words::approx`]), re-exported here.

pub use degrau_lti::words::approx::*;

use crate::cli::approx::ApproxCliError;

#[cfg(test)]
use super::Message;
use super::{Lang, Localize};

impl Localize for ApproxCliError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ApproxCliError::Cli(e) => e.text(lang),
            ApproxCliError::Approx(e) => e.text(lang),
            ApproxCliError::BadOrder(text) => match lang {
                Lang::En => format!(
                    "--order {text:?}: give the model's order n (e.g. 2), or m,n for pade \
                     (e.g. 1,2)"
                ),
                Lang::Pt => format!(
                    "--order {text:?}: dê a ordem n do modelo (p. ex. 2), ou m,n para pade \
                     (p. ex. 1,2)"
                ),
            },
            ApproxCliError::Batch => lang
                .pick(
                    "--batch is for degrau step; degrau approx takes one system",
                    "--batch é de degrau step; degrau approx recebe um só sistema",
                )
                .into(),
        }
    }
}

/// An example of every refusal of `degrau approx`, for the test of the words.
#[cfg(test)]
pub fn cli_messages() -> Vec<Message> {
    [ApproxCliError::BadOrder("x".into()), ApproxCliError::Batch]
        .iter()
        .map(|e| Message::of(format!("approx::ApproxCliError::{e:?}"), e))
        .collect()
}
