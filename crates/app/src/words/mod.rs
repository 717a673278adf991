//! The app's words: its labels, tooltips and panels' sentences in English and Brazilian
//! Portuguese (the facts of the lower crates are said by their own words), and the code a
//! student copies to MATLAB or python-control.

pub mod app;
pub mod challenges;
pub mod code;
pub mod design;
pub mod exercises;
pub mod frequency;
pub mod identify;
pub mod lsq_app;
pub mod persist;
pub mod tune;

/// Every message of the app: its labels' catalogues and an example of each fact its
/// panels say. A new catalogue or fact adds its line here.
pub fn messages() -> Vec<degrau_words::Message> {
    let mut all = Vec::new();
    all.extend(crate::field::FieldPhrase::messages());
    all.extend(crate::field::examples());
    all.extend(app::messages());
    all.extend(design::messages());
    all.extend(exercises::messages());
    all.extend(challenges::messages());
    all.extend(frequency::messages());
    all.extend(identify::messages());
    all.extend(lsq_app::messages());
    all.extend(persist::messages());
    all.extend(tune::messages());
    all
}

#[cfg(test)]
#[test]
fn every_message_is_in_both_languages() {
    degrau_words::assert_said_in_both(&messages());
}
