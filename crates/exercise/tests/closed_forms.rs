//! Known closed forms the sheet's answers rest on, against the numbers Degrau computes.

use degrau_exercise::{Expected, sheet};
use degrau_lti::feedback::SecondOrder;

fn number(id: &str) -> f64 {
    let sheet = sheet().unwrap_or_default();
    for e in &sheet {
        for p in &e.parts {
            if let Some(q) = p.questions.iter().find(|q| q.id == id)
                && let Expected::Number { main, .. } = &q.expected
            {
                return main.value;
            }
        }
    }
    panic!("no number question {id}")
}

#[test]
fn first_order_rise_and_settling_times() {
    for (part, tau) in [("1a", 0.2), ("1b", 0.1)] {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b;
        assert!(close(number(&format!("{part}.tau")), tau));
        assert!(close(number(&format!("{part}.tr")), tau * 9f64.ln()));
        assert!(close(number(&format!("{part}.ts")), tau * 50f64.ln()));
    }
}

#[test]
fn second_order_overshoot_formula() {
    // 6a: ωn² = 120, 2ζωn = 12: the exact overshoot is the formula's.
    let wn = 120f64.sqrt();
    let zeta = 6.0 / wn;
    let mp = 100.0 * (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    assert!((number("6a.Mp") - mp).abs() < 1e-6 * mp);
    assert!((number("6a.zeta") - zeta).abs() < 1e-12);
    assert!(
        (number("6a.tp") - std::f64::consts::PI / (wn * (1.0 - zeta * zeta).sqrt())).abs() < 1e-9
    );
    let pair = SecondOrder { zeta, wn };
    assert!((pair.overshoot() - mp).abs() < 1e-9);
}

#[test]
fn error_constants_of_exercise_11() {
    assert_eq!(number("11.type"), 1.0);
    assert_eq!(number("11.Kp"), f64::INFINITY);
    assert_eq!(number("11.Kv"), 0.5);
    assert_eq!(number("11.Ka"), 0.0);
    assert_eq!(number("11.ess_ramp"), 2.0);
    assert_eq!(number("11.ess_parabola"), f64::INFINITY);
}
