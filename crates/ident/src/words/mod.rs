//! The ident crate's words: every fact of its own (the loader's notes, the experiment, model
//! codes and parameters, the fit's report and warnings, the diagnosis's causes and evidence,
//! the test's flaws, the hand methods, least squares) said in English and Brazilian
//! Portuguese with the course notes' terms, and an example of each for the test that lists
//! every message.

pub mod hand;
pub mod ident;
pub mod lsq;
pub mod operating_point;
pub mod report;
pub mod steps;
pub mod test_causes;

/// Every message of the ident crate: the loader's, the fit's, the diagnosis's and the
/// test causes', the hand methods' and least squares', an example of each. A new catalogue or fact adds its line here.
#[cfg(test)]
pub fn messages() -> Vec<degrau_words::Message> {
    let mut all = Vec::new();
    all.extend(ident::messages());
    all.extend(report::messages());
    all.extend(steps::messages());
    all.extend(test_causes::messages());
    all.extend(operating_point::messages());
    all.extend(hand::messages());
    all.extend(lsq::messages());
    all
}

#[cfg(test)]
#[test]
fn every_message_is_in_both_languages() {
    degrau_words::assert_said_in_both(&messages());
}
