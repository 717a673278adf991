//! For every question of every part: Degrau's exact answer, typed in both languages, is
//! right; a wrong one is wrong; the sheet's printed answer is right unless its difference
//! is documented (and a documented difference must still differ).

use degrau_exercise::{
    Choice, Exercise, Expected, Lang, StudentAnswer, TfAnswer, check, sheet, solution, typed_answer,
};

fn all() -> Vec<Exercise> {
    match sheet() {
        Ok(s) => s,
        Err(e) => panic!("the sheet does not build: {e}"),
    }
}

fn text(t: &str) -> StudentAnswer {
    StudentAnswer::Text(t.to_string())
}

#[test]
fn thirteen_exercises_every_part_with_questions_and_a_solution() {
    let sheet = all();
    assert_eq!(sheet.len(), 13);
    let ids: Vec<&str> = sheet.iter().map(|e| e.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13"
        ]
    );
    let parts: Vec<String> = sheet
        .iter()
        .flat_map(|e| e.parts.iter().map(|p| p.id.clone()))
        .collect();
    assert_eq!(
        parts,
        [
            "1a", "1b", "2", "3a", "3b", "3c", "3d", "3e", "4", "5a", "5b", "5c", "6a", "6b", "6c",
            "7", "8a", "8b", "9", "10a", "10b", "10c", "10d", "10e", "10f", "10g", "11", "12",
            "13a", "13b"
        ]
    );
    let mut ids = std::collections::HashSet::new();
    for e in &sheet {
        for p in &e.parts {
            assert!(p.id.starts_with(&e.id), "{}", p.id);
            assert!(!p.questions.is_empty(), "{} has no questions", p.id);
            for lang in [Lang::En, Lang::Pt] {
                let steps = solution(p, lang);
                assert!(steps.len() >= 2, "{}: solution too short", p.id);
                assert!(steps.iter().all(|s| !s.line.trim().is_empty()));
            }
            assert!(!p.statement.en.is_empty() && !p.statement.pt.is_empty());
            for q in &p.questions {
                assert!(q.id.starts_with(&format!("{}.", p.id)), "{}", q.id);
                assert!(ids.insert(q.id.clone()), "duplicate id {}", q.id);
                assert!(!q.label.en.is_empty() && !q.label.pt.is_empty());
                assert_ne!(q.label.en, q.label.pt, "{}: label untranslated", q.id);
            }
        }
    }
}

#[test]
fn the_exact_answer_typed_in_either_language_is_right() {
    for e in all() {
        for p in &e.parts {
            for q in &p.questions {
                for lang in [Lang::En, Lang::Pt] {
                    let typed = typed_answer(q, lang);
                    let v = check(q, &text(&typed));
                    assert!(v.right, "{} ({lang:?}): {typed:?} → {}", q.id, v.message.en);
                    assert!(!v.message.pt.is_empty() && v.message.en != v.message.pt);
                }
            }
        }
    }
}

/// A wrong answer of the question's kind.
fn wrong(q: &degrau_exercise::Question) -> String {
    match &q.expected {
        Expected::Number { main, also, .. } => {
            let x = main.value;
            let mut w = if x.is_infinite() {
                7.0
            } else if x == 0.0 {
                0.5
            } else {
                1.37 * x + 0.1 * x.signum()
            };
            if also.iter().any(|a| (a.value - w).abs() < 0.05 * w.abs()) {
                w *= 1.5;
            }
            format!("{w}")
        }
        Expected::TransferFunction(TfAnswer::Fixed(_)) => {
            format!("2*({})", typed_answer(q, Lang::En))
        }
        Expected::TransferFunction(TfAnswer::ClosedLoopInK(_)) => "K/(s^2 + 0.3s + K)".into(),
        Expected::GainRange { main, .. } => {
            if main.high.is_finite() {
                format!("0 < K <= {}", main.high * 1.5)
            } else {
                format!("K > {}", main.low * 1.5)
            }
        }
        Expected::Region(r) => format!("ζ ≥ {}; σ ≥ {}", r.zeta_min * 0.5, r.sigma_min),
        Expected::ClosedForm { .. } => {
            let y = typed_answer(q, Lang::En);
            let y = y
                .trim_start_matches("y(t)")
                .trim_start()
                .trim_start_matches('=');
            format!("1.5*({y})")
        }
        Expected::Roots(roots) => {
            if roots.is_empty() {
                "-1".into()
            } else {
                roots
                    .iter()
                    .map(|r| format!("{}{:+}j", 2.0 * r.re - 1.0, r.im))
                    .collect::<Vec<_>>()
                    .join("; ")
            }
        }
        Expected::Choice { options, right } => options
            .iter()
            .find(|c| *c != right)
            .map_or(Choice::No, |c| *c)
            .id()
            .into(),
    }
}

#[test]
fn a_wrong_answer_is_wrong() {
    for e in all() {
        for p in &e.parts {
            for q in &p.questions {
                let w = wrong(q);
                let v = check(q, &text(&w));
                assert!(!v.right, "{}: {w:?} was taken as right", q.id);
                assert!(
                    !v.unreadable,
                    "{}: {w:?} unreadable: {}",
                    q.id, v.message.en
                );
                assert!(
                    v.message.en.contains(&v.expected.en),
                    "{}: {}",
                    q.id,
                    v.message.en
                );
            }
        }
    }
}

#[test]
fn the_sheets_answers_are_reproduced_or_their_difference_documented() {
    let mut undocumented = Vec::new();
    let mut stale = Vec::new();
    let mut printed = 0;
    for e in all() {
        for p in &e.parts {
            for q in &p.questions {
                let Some(sheet) = &q.sheet else {
                    assert!(
                        q.difference.is_none(),
                        "{}: a difference without a sheet answer",
                        q.id
                    );
                    continue;
                };
                printed += 1;
                let v = check(q, &text(sheet));
                assert!(
                    !v.unreadable,
                    "{}: the sheet's {sheet:?} is unreadable: {}",
                    q.id, v.message.en
                );
                match (&q.difference, v.right) {
                    (None, false) => undocumented.push(format!(
                        "{}: sheet {sheet:?}, Degrau {}",
                        q.id, v.expected.en
                    )),
                    (Some(_), true) => stale.push(format!("{}: sheet {sheet:?} is right", q.id)),
                    (Some(d), false) => {
                        assert!(
                            v.message.en.contains(&d.en),
                            "{}: the note is not said",
                            q.id
                        );
                        assert!(
                            v.message.pt.contains(&d.pt),
                            "{}: the note is not said",
                            q.id
                        );
                    }
                    (None, true) => {}
                }
            }
        }
    }
    assert!(
        undocumented.is_empty(),
        "undocumented differences: {undocumented:#?}"
    );
    assert!(
        stale.is_empty(),
        "documented differences that are none: {stale:#?}"
    );
    assert!(printed >= 60, "only {printed} printed answers recorded");
}

/// The list of every question with Degrau's answer and the sheet's (for the report:
/// `cargo test -p degrau-exercise -- --nocapture report`).
#[test]
fn report() {
    for e in all() {
        for p in &e.parts {
            for q in &p.questions {
                let v = check(q, &text(q.sheet.as_deref().unwrap_or("")));
                println!(
                    "{:10} Degrau: {:40} also: {:30} sheet: {:28} {}",
                    q.id,
                    v.expected.en,
                    v.formula.as_ref().map_or("", |f| f.en.as_str()),
                    q.sheet.as_deref().unwrap_or("—"),
                    if q.difference.is_some() {
                        "DIFFERS"
                    } else {
                        ""
                    }
                );
            }
        }
    }
}

/// Every worked solution in both languages (for review: `-- --nocapture solutions`).
#[test]
fn solutions() {
    for e in all() {
        for p in &e.parts {
            for lang in [Lang::En, Lang::Pt] {
                println!("— {} ({lang:?}) {}", p.id, p.statement.get(lang));
                for s in solution(p, lang) {
                    println!("    {}", s.line);
                }
            }
        }
    }
}

/// A few verdicts in full (for review: `-- --nocapture verdicts`).
#[test]
fn verdicts() {
    let sheet = all();
    for (id, typed) in [
        ("6a.ts", "0,666 s"),
        ("6a.tr", "0.158"),
        ("4.wn", "6.2"),
        ("8b.K", "86,25"),
        ("10f.K_range", "K > 0.03"),
        ("10f.K_range", "K > 0,0136"),
        ("3d.y", "1/20 - (1/2 t - 1/20) e^{-10t}"),
        ("10d.T", "10K/(s^2+0.3s+10K)"),
        ("8a.region", "θ ≤ 66,4°; σ ≥ 40"),
        ("5a.poles", "-80 ± j208,7"),
        ("1a.ts", "abc"),
    ] {
        let q = degrau_exercise::find_question(&sheet, id).unwrap_or_else(|| panic!("{id}"));
        let v = check(q, &text(typed));
        println!(
            "{id} {typed:?}: right={} | {} | {}",
            v.right, v.message.en, v.message.pt
        );
    }
}
