//! Reading students' answers: decimal commas, units, infinity, and refusals without panics.

use degrau_exercise::{StudentAnswer, check, sheet};

#[test]
fn nothing_typed_anywhere_is_refused_without_panic() {
    let sheet = sheet().unwrap_or_default();
    for e in &sheet {
        for p in &e.parts {
            for q in &p.questions {
                for t in [
                    "", "   ", "abc", "1,2,3", "((", "K <", "∞∞", "1e999", "-", "j",
                ] {
                    let v = check(q, &StudentAnswer::Text(t.into()));
                    assert!(!v.right || t == "-", "{}: {t:?} taken as right", q.id);
                }
                let v = check(
                    q,
                    &StudentAnswer::Coefficients {
                        num: vec![1.0],
                        den: vec![1.0, 2.0],
                    },
                );
                let _ = v.right;
                let v = check(q, &StudentAnswer::Number(f64::NAN));
                assert!(!v.right, "{}: NaN taken as right", q.id);
            }
        }
    }
}

/// Random texts built from the characters answers use: never a panic, and the verdict
/// always has a message in both languages.
#[test]
fn random_texts_never_panic() {
    let sheet = sheet().unwrap_or_default();
    let alphabet: Vec<char> = "0123456789.,;:+-−*/^()[]{}<>=≤≥±%∞ sStTkKjJeEpiπζσθinfxyz°²·"
        .chars()
        .collect();
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..400 {
        let len = (next() % 24) as usize;
        let text: String = (0..len)
            .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
            .collect();
        for e in &sheet {
            for p in &e.parts {
                for q in &p.questions {
                    let v = check(q, &StudentAnswer::Text(text.clone()));
                    assert!(!v.message.en.is_empty() && !v.message.pt.is_empty());
                }
            }
        }
    }
    let deep = "(".repeat(5000) + "s" + &")".repeat(5000);
    for e in &sheet {
        for p in &e.parts {
            for q in &p.questions {
                assert!(!check(q, &StudentAnswer::Text(deep.clone())).right);
            }
        }
    }
}

#[test]
fn the_words_are_said_in_both_languages() {
    degrau_words::assert_said_in_both(&degrau_exercise::words::Phrase::messages());
}
