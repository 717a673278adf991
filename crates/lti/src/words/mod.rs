//! The lti crate's words: every fact of its own (errors, metrics, stability, responses,
//! approximations, discrete models, loops) said in English and Brazilian Portuguese, with
//! the course notes' terms, and an example of each for the test that lists every message.

pub mod approx;
pub mod bode;
pub mod control;
pub mod discrete;
pub mod expr;
pub mod feedback;
pub mod lti;
pub mod step;
pub mod tuning;

/// Every message of the lti crate: its catalogues' phrases and an example of each fact it
/// says (errors, metrics, approximations, loops, discrete models, y(t)). A new catalogue or fact adds its line here.
#[cfg(test)]
pub fn messages() -> Vec<degrau_words::Message> {
    let mut all = Vec::new();
    all.extend(lti::messages());
    all.extend(step::messages());
    all.extend(feedback::messages());
    all.extend(approx::messages());
    all.extend(bode::messages());
    all.extend(discrete::messages());
    all.extend(expr::messages());
    all.extend(control::messages());
    all.extend(tuning::messages());
    all
}

#[cfg(test)]
#[test]
fn every_message_is_in_both_languages() {
    degrau_words::assert_said_in_both(&messages());
}
