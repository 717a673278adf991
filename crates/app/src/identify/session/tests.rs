//! The session's unit tests: a column header's unit, the nearest sample, padded ranges.

use super::loading::unit_in;
use super::plots::{nearest, padded, range_of};

#[test]
fn units_come_from_the_header() {
    assert_eq!(unit_in("T1 (°C)").as_deref(), Some("°C"));
    assert_eq!(unit_in("level [m]").as_deref(), Some("m"));
    assert_eq!(unit_in("T1"), None);
    assert_eq!(unit_in("odd ()"), None);
}

#[test]
fn nearest_sample_in_time() {
    let p = [[0.0, 1.0], [1.0, 2.0], [3.0, 5.0]];
    assert_eq!(nearest(&p, -1.0), Some([0.0, 1.0]));
    assert_eq!(nearest(&p, 0.4), Some([0.0, 1.0]));
    assert_eq!(nearest(&p, 2.2), Some([3.0, 5.0]));
    assert_eq!(nearest(&p, 9.0), Some([3.0, 5.0]));
    assert_eq!(nearest(&[], 1.0), None);
}

#[test]
fn ranges_are_padded() {
    assert_eq!(padded((0.0, 10.0)), (-0.5, 10.5));
    assert_eq!(padded((2.0, 2.0)), (1.9, 2.1));
    assert_eq!(range_of([f64::NAN, 3.0, -1.0].into_iter()), (-1.0, 3.0));
}
