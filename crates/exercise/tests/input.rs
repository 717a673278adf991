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
