//! The Challenges' views: on the left ([`list`]) the level, "New challenge" (a spinner and
//! Cancel while one is drawn) and the challenge handed out; in the centre ([`show`]) what
//! the student is told, the record opened in Identify, the answers (cause, final structure,
//! static gain), Check with a mark per answer, the evidence that gave the cause away, and
//! Degrau's own diagnosis, offered only after Check.

use eframe::egui::{self, RichText, Ui};

use degrau_ident::challenge::Level;
use degrau_ident::diagnose::{Cause, DiagnoseReport};
use degrau_ident::words::ident::{Naming, cause_name};
use degrau_ident::words::report::{diagnose_text, step_lines};
use degrau_ident::words::test_causes::{cause_lines, section, test_cause_name};
use degrau_words::{Lang, Localize};

use super::challenges::{ANSWERS, Current, Drawn, Field, Named};
use super::session::{Progress, Saved, Session};
use super::{ChallengeCommand as C, Command};
use crate::look::Look;
use crate::words::challenges::{Challenges as T, level};

/// The challenge's entry in the list (`"Challenge 3 (moderate)"`).
pub fn entry(current: &Current, lang: Lang) -> String {
    format!(
        "{} {} ({})",
        T::NumberLabel.get(lang),
        current.index + 1,
        level(current.level, lang)
    )
}

/// The Challenges' part of the left list.
pub fn list(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let ch = &kept.challenges;
    ui.heading(T::Heading.get(lang));
    super::weak(ui, T::Intro.get(lang), look);
    ui.horizontal_wrapped(|ui| {
        ui.label(T::LevelLabel.get(lang));
        for l in Level::ALL {
            if ui.selectable_label(ch.level == l, level(l, lang)).clicked() && ch.level != l {
                out.push(Command::Challenge(C::SetLevel(l)));
            }
        }
    });
    let drawing = session.board.drawing();
    let new = ui.add_enabled(!drawing, egui::Button::new(T::New.get(lang)));
    if new.on_hover_text(T::NewHelp.get(lang)).clicked() {
        out.push(Command::Challenge(C::New));
    }
    if drawing {
        spinner(ui, look, out);
    } else if let Some(c) = &ch.current
        && ui.selectable_label(ch.open, entry(c, lang)).clicked()
        && !ch.open
    {
        out.push(Command::Challenge(C::Open));
    }
}

/// The spinner and Cancel while a challenge is drawn.
fn spinner(ui: &mut Ui, look: &Look, out: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        ui.spinner();
        ui.label(T::Drawing.get(look.lang));
        if ui.button(T::Cancel.get(look.lang)).clicked() {
            out.push(Command::Challenge(C::Cancel));
        }
    });
}

/// The challenge in the centre.
pub fn show(ui: &mut Ui, session: &Session, kept: &Saved, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    let board = &session.board;
    ui.heading(T::Heading.get(lang));
    if board.drawing() {
        spinner(ui, look, out);
        return;
    }
    let (Some(current), Some(drawn)) = (&kept.challenges.current, &board.drawn) else {
        ui.add(egui::Label::new(T::Intro.get(lang)).wrap());
        return;
    };
    ui.label(RichText::new(entry(current, lang)).strong());
    if board.drawn_again {
        let notice = RichText::new(T::DrawnAgain.get(lang)).color(look.palette.warning);
        ui.add(egui::Label::new(notice).wrap());
    }
    ui.add(egui::Label::new(T::Task.get(lang)).wrap());
    ui.add_space(4.0);
    if ui.button(T::OpenRecord.get(lang)).clicked() {
        out.push(Command::Challenge(C::OpenRecord));
    }
    ui.separator();
    ui.label(RichText::new(T::Answers.get(lang)).strong());
    let checked = board.checked.as_ref();
    cause_field(ui, current, lang, out);
    mark(ui, checked.map(|c| c.grade.cause), None, look);
    text_field(
        ui,
        Field::Structure,
        &current.structure,
        T::Structure,
        lang,
        out,
    );
    mark(ui, checked.map(|c| c.grade.structure), None, look);
    text_field(ui, Field::Kp, &current.kp, T::Kp, lang, out);
    mark(
        ui,
        checked.map(|c| c.grade.kp),
        checked.and_then(|c| c.kp_problem.as_ref().map(|p| p.text(lang))),
        look,
    );
    ui.add_space(4.0);
    if ui
        .button(RichText::new(T::Check.get(lang)).strong())
        .on_hover_text(T::CheckHelp.get(lang))
        .clicked()
    {
        out.push(Command::Challenge(C::Check));
    }
    if checked.is_some() {
        after_check(ui, drawn, board.diagnosis_shown, look, out);
    }
}

/// The cause's combo: the model's causes, then the test's, in words, `none` last.
fn cause_field(ui: &mut Ui, current: &Current, lang: Lang, out: &mut Vec<Command>) {
    let chosen = Named::of_id(&current.cause);
    let shown = chosen.map_or(T::ChooseCause.get(lang), |n| answer_name(n, lang));
    egui::ComboBox::from_label(T::Cause.get(lang))
        .selected_text(shown)
        // Tall enough for most of the twenty causes (the rest scroll into view).
        .height(560.0)
        .show_ui(ui, |ui| {
            let mut group = None;
            for n in ANSWERS {
                let this = matches!(n, Named::Test(_));
                if group.is_some_and(|g| g != this) || n == Named::Model(Cause::None) {
                    ui.separator();
                }
                group = Some(this);
                if ui
                    .selectable_label(chosen == Some(n), answer_name(n, lang))
                    .clicked()
                    && chosen != Some(n)
                {
                    out.push(Command::Challenge(C::Type(Field::Cause, n.id().into())));
                }
            }
        });
}

/// A cause a student can name, in a few words.
pub fn answer_name(n: Named, lang: Lang) -> &'static str {
    match n {
        Named::Model(c) => cause_name(c, Naming::Words, lang),
        Named::Test(k) => test_cause_name(k, Naming::Words, lang),
    }
}

/// A labelled text field; a change is a [`C::Type`].
fn text_field(ui: &mut Ui, field: Field, text: &str, label: T, lang: Lang, out: &mut Vec<Command>) {
    let name = ui.add(egui::Label::new(label.get(lang)).wrap());
    let mut text = text.to_string();
    let edit = egui::TextEdit::singleline(&mut text)
        .id_salt(("challenge answer", format!("{field:?}")))
        .desired_width(160.0);
    if ui.add(edit).labelled_by(name.id).changed() {
        out.push(Command::Challenge(C::Type(field, text)));
    }
}

/// The mark of one answer after Check (● right, × wrong), and why the text was refused.
fn mark(ui: &mut Ui, right: Option<bool>, why: Option<String>, look: &Look) {
    let Some(right) = right else {
        return;
    };
    ui.add(egui::Label::new(
        RichText::new(verdict(right, look.lang)).color(if right {
            look.palette.main
        } else {
            look.palette.error
        }),
    ));
    if let Some(why) = why {
        super::weak(ui, why, look);
    }
}

/// One answer's verdict: the Exercises' mark and the word (`"● right"`).
pub fn verdict(right: bool, lang: Lang) -> String {
    let (p, w) = if right {
        (Progress::Right, T::Right)
    } else {
        (Progress::Wrong, T::Wrong)
    };
    format!("{} {}", p.symbol(), w.get(lang))
}

/// After Check: the evidence for the true cause, and Degrau's diagnosis behind a button.
fn after_check(ui: &mut Ui, drawn: &Drawn, shown: bool, look: &Look, out: &mut Vec<Command>) {
    let lang = look.lang;
    ui.separator();
    ui.label(RichText::new(T::Evidence.get(lang)).strong());
    let Some(report) = &drawn.report else {
        super::weak(ui, T::NoDiagnosis.get(lang), look);
        return;
    };
    for line in evidence(report, &drawn.challenge.causes, lang) {
        ui.add(egui::Label::new(line).wrap());
    }
    ui.add_space(4.0);
    if !shown {
        if ui.button(T::ShowDiagnosis.get(lang)).clicked() {
            out.push(Command::Challenge(C::ShowDiagnosis));
        }
        return;
    }
    ui.separator();
    ui.label(RichText::new(T::Diagnosis.get(lang)).strong());
    ui.add(egui::Label::new(RichText::new(diagnose_text(report, lang)).monospace()).wrap());
}

/// The evidence the diagnosis gives for the key's causes: each step naming one (its cause
/// and evidence, as the Identify mode shows a step), and each flaw of the test the key
/// names (what the test got wrong, with what Degrau did about it); every test cause when
/// the key names nothing.
pub fn evidence(report: &DiagnoseReport, causes: &[String], lang: Lang) -> Vec<String> {
    let named = |id: &str| causes.iter().any(|k| k == id);
    let mut lines: Vec<String> = report
        .steps
        .iter()
        .filter(|s| !s.removed && (named(s.cause.id()) || s.paired.is_some_and(|p| named(p.id()))))
        .flat_map(|s| {
            let [cause, evidence, _] = step_lines(s, Naming::Words, lang);
            [cause, evidence]
        })
        .collect();
    for c in report.test_causes.iter().filter(|c| named(c.kind.id())) {
        let [name, evidence, done, _] = cause_lines(c, Naming::Words, lang);
        lines.extend([name, evidence, done]);
    }
    if lines.is_empty() {
        lines.push(T::NoEvidence.get(lang).to_string());
    }
    if named(Cause::None.id()) {
        lines.extend(section(&report.test_causes, lang));
    }
    lines
}
