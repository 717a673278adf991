//! An example of every fact of these words, for the test of both languages.

use super::*;

/// The name of a data note's variant. No wildcard: a new variant does not compile until it
/// is named here, and [`data_notes`] must then give an example of it (a test counts them).
fn data_note_id(n: &DataNote) -> &'static str {
    match n {
        DataNote::Utf16 => "Utf16",
        DataNote::Latin1 => "Latin1",
        DataNote::ReadAs { .. } => "ReadAs",
        DataNote::SamplingPeriodUnused { .. } => "SamplingPeriodUnused",
        DataNote::OutputOnlyLeft { .. } => "OutputOnlyLeft",
        DataNote::PastedTuy => "PastedTuy",
        DataNote::InputNotGuessed { .. } => "InputNotGuessed",
        DataNote::InputGuessed { .. } => "InputGuessed",
        DataNote::SeveralInputs { .. } => "SeveralInputs",
        DataNote::GeneratedTime { .. } => "GeneratedTime",
        DataNote::MissingValues { .. } => "MissingValues",
        DataNote::StepBetweenEqualTimes { .. } => "StepBetweenEqualTimes",
        DataNote::EqualTimes { .. } => "EqualTimes",
        DataNote::Window { .. } => "Window",
        DataNote::IndexIgnored { .. } => "IndexIgnored",
        DataNote::MoreEqualTimes { .. } => "MoreEqualTimes",
        DataNote::InputJoined { .. } => "InputJoined",
    }
}
#[cfg(test)]
const DATA_NOTE_VARIANTS: usize = 17;

fn named(position: usize, name: &str) -> Column {
    Column {
        position,
        name: Some(name.into()),
    }
}

fn unnamed(position: usize) -> Column {
    Column {
        position,
        name: None,
    }
}

fn data_notes() -> Vec<DataNote> {
    let two = ColumnList {
        shown: vec![named(2, "u1"), named(3, "u2")],
        more: 0,
    };
    vec![
        DataNote::Utf16,
        DataNote::Latin1,
        DataNote::ReadAs {
            separator: Separator::Semicolon,
            decimal_comma: true,
            header: HeaderFound::Row { line: 1 },
        },
        DataNote::SamplingPeriodUnused {
            sampling_period: 0.1,
            time: named(1, "t"),
        },
        DataNote::OutputOnlyLeft {
            output: named(3, "T1"),
        },
        DataNote::PastedTuy,
        DataNote::InputNotGuessed {
            columns: 300,
            limit: 256,
        },
        DataNote::InputGuessed { input: unnamed(2) },
        DataNote::SeveralInputs { columns: two },
        DataNote::GeneratedTime {
            sampling_period: 0.094,
        },
        DataNote::MissingValues {
            lines: vec![4, 5, 6],
            total: 3,
        },
        DataNote::StepBetweenEqualTimes {
            first: 2,
            second: 3,
            time: 0.0,
            before: 0.0,
            after: 50.0,
        },
        DataNote::EqualTimes {
            first: 7,
            second: 8,
            time: 1.5,
        },
        DataNote::Window {
            first: 37,
            last: 313,
            count: 384,
            start: 3.4,
            end: 29.3,
        },
        DataNote::IndexIgnored {
            columns: ColumnList {
                shown: vec![unnamed(1)],
                more: 0,
            },
        },
        DataNote::InputJoined { held_back: 1 },
        DataNote::MoreEqualTimes { pairs: 4 },
    ]
}

fn data_error_id(e: &DataError) -> &'static str {
    match e {
        DataError::Io { .. } => "Io",
        DataError::Binary { .. } => "Binary",
        DataError::Empty => "Empty",
        DataError::NoData { .. } => "NoData",
        DataError::TooFewSamples { .. } => "TooFewSamples",
        DataError::NotANumber { .. } => "NotANumber",
        DataError::TimeMissing { .. } => "TimeMissing",
        DataError::TimeNotIncreasing { .. } => "TimeNotIncreasing",
        DataError::Ragged { .. } => "Ragged",
        DataError::UnknownColumn { .. } => "UnknownColumn",
        DataError::NoSuchPosition { .. } => "NoSuchPosition",
        DataError::NoTime { .. } => "NoTime",
        DataError::SameColumn { .. } => "SameColumn",
        DataError::AmbiguousOutput { .. } => "AmbiguousOutput",
        DataError::NoOutput { .. } => "NoOutput",
        DataError::BadSamplingPeriod(_) => "BadSamplingPeriod",
        DataError::PasteColumns { .. } => "PasteColumns",
        DataError::NotAFile { .. } => "NotAFile",
        DataError::TooLarge { .. } => "TooLarge",
        DataError::TimeOverflow { .. } => "TimeOverflow",
        DataError::InputAfterOutput { .. } => "InputAfterOutput",
    }
}
#[cfg(test)]
const DATA_ERROR_VARIANTS: usize = 21;

fn data_errors() -> Vec<DataError> {
    let named_columns = Columns::Named(ColumnList {
        shown: vec![named(1, "t"), named(2, "u"), named(3, "y")],
        more: 2,
    });
    vec![
        DataError::Io {
            path: "step.csv".into(),
            kind: std::io::ErrorKind::NotFound,
            reason: "No such file or directory (os error 2)".into(),
        },
        DataError::Binary { line: 3 },
        DataError::Empty,
        DataError::NoData { lines: 4 },
        DataError::TooFewSamples {
            line: 3,
            found: 2,
            needed: 3,
        },
        DataError::NotANumber {
            line: 5,
            column: named(2, "y"),
            text: "abc".into(),
        },
        DataError::TimeMissing {
            line: 6,
            column: unnamed(1),
        },
        DataError::TimeNotIncreasing {
            line: 7,
            time: 0.5,
            previous: 0.6,
            first_column_assumed: true,
        },
        DataError::Ragged {
            line: 9,
            found: 2,
            expected: 3,
            reference: 1,
        },
        DataError::UnknownColumn {
            line: 1,
            role: Role::Output,
            name: "T9".into(),
            available: named_columns.clone(),
        },
        DataError::NoSuchPosition {
            line: 1,
            role: Role::Input,
            position: 7,
            available: Columns::Unnamed { count: 3 },
        },
        DataError::NoTime {
            line: 1,
            available: named_columns.clone(),
        },
        DataError::SameColumn {
            line: 1,
            first: Role::Time,
            second: Role::Output,
            column: named(1, "t"),
        },
        DataError::AmbiguousOutput {
            line: 1,
            candidates: ColumnList {
                shown: vec![named(2, "T1"), named(3, "T2")],
                more: 0,
            },
        },
        DataError::NoOutput {
            line: 1,
            available: named_columns,
        },
        DataError::BadSamplingPeriod(-1.0),
        DataError::PasteColumns { line: 1, found: 5 },
        DataError::NotAFile {
            path: "/tmp".into(),
            kind: FileKind::Directory,
        },
        DataError::TooLarge {
            what: Source::File,
            size: 1 << 31,
        },
        DataError::TimeOverflow {
            sampling_period: 1e308,
            rows: 10,
        },
        DataError::InputAfterOutput {
            input_start: 12.5,
            output_end: 10.0,
        },
    ]
}

fn evidence_id(e: &Evidence) -> &'static str {
    match e {
        Evidence::DeadTime { .. } => "DeadTime",
        Evidence::Offset { .. } => "Offset",
        Evidence::Oscillation { .. } => "Oscillation",
        Evidence::ExtraPole { .. } => "ExtraPole",
        Evidence::Zero { .. } => "Zero",
        Evidence::InverseResponse { .. } => "InverseResponse",
        Evidence::Integrator { .. } => "Integrator",
        Evidence::Drift { .. } => "Drift",
        Evidence::NoLongerPays { .. } => "NoLongerPays",
        Evidence::None => "None",
    }
}
#[cfg(test)]
const EVIDENCE_VARIANTS: usize = 10;

fn evidence() -> Vec<Evidence> {
    let bias = Bias {
        start: 5.0,
        end: 6.76,
        n: 12,
        mean: -0.31,
        same_sign: 0.92,
    };
    vec![
        Evidence::DeadTime {
            bias,
            td: 1.76,
            changes: 1,
        },
        Evidence::DeadTime {
            bias,
            td: 0.008,
            changes: 266,
        },
        Evidence::Offset {
            bias,
            y0_held: 20.9,
            y0_estimated: 21.3,
        },
        Evidence::Oscillation {
            period: Some(6.5),
            omega_d: Some(0.95),
            zeta: 0.19,
        },
        Evidence::ExtraPole {
            bias,
            added: Some((Param::Tp2, 12.0)),
        },
        Evidence::Zero {
            overshoot: 0.12,
            peak_time: Some(8.0),
            underdamped: false,
            tz: 3.0,
        },
        Evidence::InverseResponse {
            undershoot: 0.08,
            dip_time: Some(1.2),
            tz: -0.7,
        },
        Evidence::Integrator {
            slope: 0.2,
            per_time_constant: 0.4,
            trend_z: Some(5.1),
        },
        Evidence::Drift {
            tail: Some((0.01, 4.2)),
            drift: 0.012,
        },
        Evidence::NoLongerPays {
            param: Param::Drift,
            value: 0.0002,
            ci95: Some((-0.001, 0.0014)),
            criterion_delta: -3.2,
        },
        Evidence::None,
    ]
}

fn prepare_errors() -> Vec<PrepareError> {
    vec![
        PrepareError::BadRange {
            first: 0,
            last: 3,
            count: 10,
        },
        PrepareError::TooFewInWindow { kept: 2, needed: 3 },
        PrepareError::BadTimeRange {
            start: 5.0,
            end: 1.0,
        },
        PrepareError::BadCutoff(0.0),
        PrepareError::BadSamplingPeriod(0.0),
    ]
}

fn model_errors() -> Vec<ModelError> {
    vec![
        ModelError::BadCode("Q3".into()),
        ModelError::UnderdampedNeedsTwoPoles("P1U".into()),
        ModelError::BadValue {
            name: "Tp1",
            value: -1.0,
            requirement: Requirement::Positive,
        },
        ModelError::BadValue {
            name: "Kp",
            value: f64::INFINITY,
            requirement: Requirement::Finite,
        },
        ModelError::Overflow,
        ModelError::NotInModel("Tz"),
        ModelError::System(LtiError::NoPoles),
    ]
}

fn fit_errors() -> Vec<FitError> {
    vec![
        FitError::TooFewSamples { n: 2, p: 4 },
        FitError::BadStep(0.0),
        FitError::BadGuess(ModelError::NotInModel("Tz")),
        FitError::NonFiniteData,
        FitError::BadStepTime(f64::NAN),
        FitError::NonFiniteCost,
        FitError::Unrepresentable {
            param: "Kp",
            log10: 320.4,
        },
    ]
}

fn experiment_errors() -> Vec<ExperimentError> {
    vec![
        ExperimentError::NoStep,
        ExperimentError::BadStep(0.0),
        ExperimentError::Prepare(PrepareError::BadCutoff(-1.0)),
        ExperimentError::Model(ModelError::Overflow),
        ExperimentError::Fit(FitError::NonFiniteCost),
    ]
}

fn fit_warnings() -> Vec<FitWarning> {
    vec![
        FitWarning::AtBound {
            param: "Td".into(),
            bound: 0.0,
        },
        FitWarning::OverdampedUnderdamped { zeta: 1.2 },
        FitWarning::Alias {
            omega_d: 40.0,
            nyquist: 31.4,
            between_samples: 0.3,
        },
        FitWarning::NotIdentifiable { param: "Tz".into() },
        FitWarning::CombinationNotIdentifiable,
        FitWarning::LagsNotResolved {
            larger: "Tp1".into(),
            smaller: "Tp2".into(),
        },
        FitWarning::NotConverged,
        FitWarning::NoImprovement,
        FitWarning::Unrepresentable {
            statistic: "MSE".into(),
            log10: 600.3,
        },
        FitWarning::GainUndetermined {
            low: -140.0,
            high: 109.0,
        },
    ]
}

fn prepare_error_id(e: &PrepareError) -> &'static str {
    match e {
        PrepareError::BadRange { .. } => "BadRange",
        PrepareError::TooFewInWindow { .. } => "TooFewInWindow",
        PrepareError::BadTimeRange { .. } => "BadTimeRange",
        PrepareError::BadCutoff(_) => "BadCutoff",
        PrepareError::BadSamplingPeriod(_) => "BadSamplingPeriod",
    }
}

fn model_error_id(e: &ModelError) -> &'static str {
    match e {
        ModelError::BadCode(_) => "BadCode",
        ModelError::UnderdampedNeedsTwoPoles(_) => "UnderdampedNeedsTwoPoles",
        ModelError::BadValue { .. } => "BadValue",
        ModelError::Overflow => "Overflow",
        ModelError::NotInModel(_) => "NotInModel",
        ModelError::System(_) => "System",
    }
}

fn fit_error_id(e: &FitError) -> &'static str {
    match e {
        FitError::TooFewSamples { .. } => "TooFewSamples",
        FitError::BadStep(_) => "BadStep",
        FitError::BadGuess(_) => "BadGuess",
        FitError::NonFiniteData => "NonFiniteData",
        FitError::BadStepTime(_) => "BadStepTime",
        FitError::NonFiniteCost => "NonFiniteCost",
        FitError::Unrepresentable { .. } => "Unrepresentable",
    }
}

fn experiment_error_id(e: &ExperimentError) -> &'static str {
    match e {
        ExperimentError::NoStep => "NoStep",
        ExperimentError::BadStep(_) => "BadStep",
        ExperimentError::Prepare(_) => "Prepare",
        ExperimentError::Model(_) => "Model",
        ExperimentError::Fit(_) => "Fit",
    }
}

fn fit_warning_id(w: &FitWarning) -> &'static str {
    match w {
        FitWarning::AtBound { .. } => "AtBound",
        FitWarning::OverdampedUnderdamped { .. } => "OverdampedUnderdamped",
        FitWarning::Alias { .. } => "Alias",
        FitWarning::NotIdentifiable { .. } => "NotIdentifiable",
        FitWarning::CombinationNotIdentifiable => "CombinationNotIdentifiable",
        FitWarning::LagsNotResolved { .. } => "LagsNotResolved",
        FitWarning::NotConverged => "NotConverged",
        FitWarning::NoImprovement => "NoImprovement",
        FitWarning::Unrepresentable { .. } => "Unrepresentable",
        FitWarning::GainUndetermined { .. } => "GainUndetermined",
    }
}

/// Examples of every variant, one message each, with its id.
fn examples<T: Localize>(kind: &str, all: Vec<T>, id: fn(&T) -> &'static str) -> Vec<Message> {
    all.iter()
        .map(|x| Message::of(format!("ident::{kind}::{}", id(x)), x))
        .collect()
}

/// Every message of this module: an example of every variant of every fact.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = examples("DataNote", data_notes(), data_note_id);
    all.extend(examples("DataError", data_errors(), data_error_id));
    all.extend(examples("Evidence", evidence(), evidence_id));
    all.extend(examples("PrepareError", prepare_errors(), prepare_error_id));
    all.extend(examples("ModelError", model_errors(), model_error_id));
    all.extend(examples("FitError", fit_errors(), fit_error_id));
    all.extend(examples(
        "ExperimentError",
        experiment_errors(),
        experiment_error_id,
    ));
    all.extend(examples("FitWarning", fit_warnings(), fit_warning_id));
    let requirements = [
        Requirement::Finite,
        Requirement::Positive,
        Requirement::NotNegative,
        Requirement::NotZero,
        Requirement::DelayNotNegative,
    ];
    all.extend(
        requirements
            .iter()
            .map(|r| Message::of(format!("ident::Requirement::{r:?}"), r)),
    );
    for place in [Where::Cli, Where::App] {
        all.push(Message {
            id: format!("ident::ExperimentError::NoStep::{place:?}"),
            en: experiment_error(&ExperimentError::NoStep, Lang::En, place),
            pt: experiment_error(&ExperimentError::NoStep, Lang::Pt, place),
        });
    }
    let terminations = [
        Termination::Gradient,
        Termination::SmallStep,
        Termination::SmallCostChange,
        Termination::IterationLimit,
        Termination::Cancelled,
        Termination::NoImprovement,
    ];
    all.extend(
        terminations
            .iter()
            .map(|t| Message::of(format!("ident::Termination::{t:?}"), t)),
    );
    let causes = [
        Cause::DeadTime,
        Cause::Offset,
        Cause::Oscillation,
        Cause::ExtraPole,
        Cause::Zero,
        Cause::InverseResponse,
        Cause::Integrator,
        Cause::Drift,
        Cause::None,
    ];
    for c in causes {
        all.push(Message::of(format!("ident::Cause::{c:?}"), &c));
        all.push(Message::of(format!("ident::Remedy::{c:?}"), &Remedy(c)));
    }
    for h in [
        Handle::FinalValue,
        Handle::DeadTime,
        Handle::TimeConstant,
        Handle::FirstPeak,
    ] {
        all.push(Message::said(format!("ident::Handle::{h:?}"), |lang| {
            format!("{} / {}", handle_label(h, lang), handle_help(h, lang))
        }));
    }
    for p in crate::model::ALL_PARAMS {
        all.push(Message::of(format!("ident::Param::{p:?}"), &Meaning(p)));
    }
    let whiteness = Some(Whiteness {
        outside: 3,
        lags: 40,
        runs_z: -2.5,
    });
    for ending in [
        Ending::Adequate,
        Ending::NotWhite,
        Ending::WithinRounding,
        Ending::StepLimit,
    ] {
        all.push(Message::of(
            format!("ident::Verdict::{ending:?}"),
            &Verdict {
                ending,
                whiteness,
                structure: None,
                artefacts: Default::default(),
            },
        ));
    }
    for kind in [
        FileKind::Directory,
        FileKind::NamedPipe,
        FileKind::Device,
        FileKind::Socket,
        FileKind::Special,
    ] {
        all.push(Message::of(format!("ident::FileKind::{kind:?}"), &kind));
    }
    for source in [Source::File, Source::Data, Source::Text, Source::Paste] {
        all.push(Message::of(format!("ident::Source::{source:?}"), &source));
    }
    for separator in [
        Separator::Semicolon,
        Separator::Tab,
        Separator::Comma,
        Separator::Whitespace,
    ] {
        all.push(Message::of(
            format!("ident::Separator::{separator:?}"),
            &separator,
        ));
    }
    all.push(Message::of(
        "ident::Structure",
        &Structure {
            poles: 2,
            delay: true,
            underdamped: false,
            zero: false,
            integrator: false,
            free_offset: false,
            drift: true,
            lead: false,
            transient: false,
        },
    ));
    all.push(Message::of("ident::Ewma", &Ewma::new(0.6, 0.094)));
    all
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::data::{LoadOptions, load_str};
    use std::collections::BTreeSet;

    fn distinct<T>(all: &[T], id: fn(&T) -> &'static str) -> usize {
        all.iter().map(id).collect::<BTreeSet<_>>().len()
    }

    #[test]
    fn every_variant_has_an_example() {
        assert_eq!(distinct(&data_notes(), data_note_id), DATA_NOTE_VARIANTS);
        assert_eq!(distinct(&data_errors(), data_error_id), DATA_ERROR_VARIANTS);
        assert_eq!(distinct(&evidence(), evidence_id), EVIDENCE_VARIANTS);
        assert_eq!(distinct(&prepare_errors(), prepare_error_id), 5);
        assert_eq!(distinct(&model_errors(), model_error_id), 6);
        assert_eq!(distinct(&fit_errors(), fit_error_id), 7);
        assert_eq!(distinct(&experiment_errors(), experiment_error_id), 5);
        assert_eq!(distinct(&fit_warnings(), fit_warning_id), 10);
    }

    #[test]
    fn lines_are_listed_briefly() {
        assert_eq!(lines_text(&[4], 1, Lang::En), "line 4");
        assert_eq!(lines_text(&[4, 9, 12], 3, Lang::En), "lines 4, 9 and 12");
        assert_eq!(lines_text(&[4, 9, 12], 3, Lang::Pt), "linhas 4, 9 e 12");
        assert_eq!(lines_text(&[4], 2, Lang::En), "lines 4 and 1 more");
        let many: Vec<usize> = (1..=8).collect();
        assert_eq!(
            lines_text(&many, 20, Lang::En),
            "lines 1, 2, 3, 4, 5, 6, 7, 8 and 12 more"
        );
    }

    #[test]
    fn columns_are_listed_with_how_many_more() {
        let list = ColumnList {
            shown: (1..=20).map(|k| named(k, &k.to_string())).collect(),
            more: 5,
        };
        let text = available(&Columns::Named(list), Lang::En);
        assert!(text.ends_with("20 \"20\", … and 5 more"), "{text}");
    }

    #[test]
    fn a_note_reads_the_same_numbers_in_both_languages() {
        let t = load_str(
            "t;y\n0;1,5\n1;2,5\n2;3,5\n",
            &LoadOptions {
                sampling_period: Some(0.25),
                ..LoadOptions::default()
            },
        )
        .unwrap();
        let en: Vec<String> = t.notes.iter().map(|n| n.text(Lang::En)).collect();
        let pt: Vec<String> = t.notes.iter().map(|n| n.text(Lang::Pt)).collect();
        assert!(
            en.iter().any(|n| n.contains("(0.25 s) was not used")),
            "{en:?}"
        );
        assert!(
            pt.iter().any(|n| n.contains("(0,25 s) não foi usado")),
            "{pt:?}"
        );
        assert!(pt[0].starts_with("lido como separado por ponto e vírgula com vírgula decimal"));
    }

    #[test]
    fn errors_display_their_english_words() {
        let e = DataError::BadSamplingPeriod(-0.5);
        assert_eq!(e.to_string(), e.text(Lang::En));
        assert!(e.text(Lang::Pt).contains("-0,5"));
    }

    #[test]
    fn no_step_names_the_place_to_give_what_is_missing() {
        let e = ExperimentError::NoStep;
        assert!(!e.to_string().contains("--"));
        assert!(experiment_error(&e, Lang::Pt, Where::Cli).contains("--initial-input"));
        assert!(experiment_error(&e, Lang::En, Where::App).contains("Input before the record"));
    }
}
