//! The figure a part is read off (exercises 2, 4 and 9), rebuilt: the sheet's figures are
//! not in its text, so [`System::Figure`] carries the curve they show, and [`scene`] lays it
//! out as a student would draw it on paper: the exact step response of the curve times the
//! step's amplitude, over a span that shows it settle, and each reading the sheet takes off
//! it marked with dashed guides from the axes and labelled with its value in the student's
//! language. No transfer function is shown: the figure must not give the answer away.
//!
//! Pure: no egui here; [`super::figure_view`] draws the scene, built again each frame the
//! part is shown (a few hundred samples of a second-order response: microseconds).

use degrau_exercise::text::num;
use degrau_exercise::{Lang, Part, Reading, System, Unit};
use degrau_lti::{StepInfoOptions, StepResponse, analyse};

/// Points of the drawn curve.
pub const SAMPLES: usize = 600;
/// The fraction of its final value a first-order response has reached at t = τ.
pub const AT_TAU: f64 = 0.632;
/// Room left above the highest point (a fraction of the y span): the labels above the peak.
const HEADROOM: f64 = 0.2;
/// Room left below the lowest point (a fraction of the y span).
const FOOTROOM: f64 = 0.05;
/// The time axis's name (notation: the same in both languages).
pub const T_AXIS: &str = "t (s)";

/// What the figure shows, in plot coordinates, its words in one language.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The exact response, (t, y) from the step to [`Scene::t_end`].
    pub curve: Vec<[f64; 2]>,
    /// The span shown (seconds from the step): the lti's window of the response, which
    /// shows its settling and its peak.
    pub t_end: f64,
    /// The y range shown: the curve's, with room above for the labels.
    pub y_range: (f64, f64),
    /// The output: `y(t)`, or `x(t)` for a displacement.
    pub output: &'static str,
    /// The output's axis name: `y(t)`, or `x(t) (m)` for a displacement.
    pub y_axis: String,
    pub marks: Vec<Mark>,
}

/// One reading marked on the figure.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// An instant read on the t axis (t_p, τ): a dashed guide from the axis up to the
    /// curve's point (t, y), labelled at the axis.
    Instant { t: f64, y: f64, label: Label },
    /// A value read on the y axis at the curve's point (t, y) (y(t_p), 0.632·y(∞)): a
    /// dashed guide from the axis across to the point, labelled beside the point.
    Value { t: f64, y: f64, label: Label },
    /// The final value: a dashed line across the figure, labelled at its right end.
    Level { y: f64, label: Label },
    /// A difference of two values at the instant t (the overshoot x(t_p) − x(∞)): a double
    /// arrow from `from` to `to`, labelled above its top.
    Gap {
        t: f64,
        from: f64,
        to: f64,
        label: Label,
    },
}

impl Mark {
    /// The mark's label.
    pub fn label(&self) -> &Label {
        match self {
            Mark::Instant { label, .. }
            | Mark::Value { label, .. }
            | Mark::Level { label, .. }
            | Mark::Gap { label, .. } => label,
        }
    }
}

/// A mark's words and where they go: beside the point `at`, on its `side`.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub text: String,
    pub at: [f64; 2],
    pub side: Side,
}

/// Where a label sits from its point (the view keeps a few points away from it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    AboveRight,
    BelowRight,
    AboveLeft,
}

/// The scene of `part`'s figure in `lang`; `None` when the part is not read off a figure or
/// its curve cannot be drawn (a response that does not settle or is beyond double precision:
/// none of the sheet's, whose figures the exercise crate checks).
pub fn scene(part: &Part, lang: Lang) -> Option<Scene> {
    let System::Figure {
        curve,
        amplitude,
        readings,
    } = &part.system
    else {
        return None;
    };
    let response = StepResponse::new(curve, *amplitude).ok()?;
    let final_value = response.final_value()?;
    let t_end = analyse(&response, &StepInfoOptions::default()).horizon;
    if !(t_end.is_finite() && t_end > 0.0) {
        return None;
    }
    let (t, y) = response.sample_uniform(0.0, t_end, SAMPLES);
    let curve: Vec<[f64; 2]> = t.into_iter().zip(y).map(|(t, y)| [t, y]).collect();
    let output = Output::of(readings);
    let read = |key: &str| readings.iter().find(|r| r.key == key);
    let mut marks = Vec::new();
    for r in readings {
        marks.extend(marks_of(
            r,
            &read,
            &response,
            final_value,
            output,
            t_end,
            lang,
        ));
    }
    let ys = curve
        .iter()
        .map(|p| p[1])
        .chain(marks.iter().flat_map(mark_heights));
    let (lo, hi) = ys.fold((0.0f64, 0.0f64), |(lo, hi), y| (lo.min(y), hi.max(y)));
    let span = hi - lo;
    let finite = curve.iter().flatten().all(|v| v.is_finite());
    if !(finite && span.is_finite() && span > 0.0) {
        return None;
    }
    Some(Scene {
        curve,
        t_end,
        y_range: (lo - FOOTROOM * span, hi + HEADROOM * span),
        output: output.name(),
        y_axis: output.axis(),
        marks,
    })
}

/// The heights a mark reaches.
fn mark_heights(mark: &Mark) -> Vec<f64> {
    match mark {
        Mark::Instant { y, .. } | Mark::Value { y, .. } | Mark::Level { y, .. } => vec![*y],
        Mark::Gap { from, to, .. } => vec![*from, *to],
    }
}

/// The output the figure plots: y(t), or a displacement x(t) in metres.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Output {
    Y,
    Displacement,
}

impl Output {
    /// A displacement when a reading is in metres (exercise 9's x(∞) and overshoot).
    fn of(readings: &[Reading]) -> Self {
        if readings.iter().any(|r| r.unit == Unit::Metre) {
            Output::Displacement
        } else {
            Output::Y
        }
    }

    /// `y` or `x`.
    fn symbol(self) -> &'static str {
        match self {
            Output::Y => "y",
            Output::Displacement => "x",
        }
    }

    /// `y(t)` or `x(t)`.
    fn name(self) -> &'static str {
        match self {
            Output::Y => "y(t)",
            Output::Displacement => "x(t)",
        }
    }

    /// The y axis's name, with the unit of a displacement.
    fn axis(self) -> String {
        match self {
            Output::Y => self.name().into(),
            Output::Displacement => format!("{} ({})", self.name(), Unit::Metre.symbol()),
        }
    }
}

/// "name = value unit" with the language's decimal separator.
fn equals(name: &str, value: f64, unit: Unit, lang: Lang) -> String {
    format!("{name} = {} {}", num(lang, value), unit.symbol())
        .trim_end()
        .to_string()
}

/// The marks of one reading (none for a reading the figure does not show, such as
/// exercise 9's force step).
fn marks_of<'a>(
    r: &Reading,
    read: &dyn Fn(&str) -> Option<&'a Reading>,
    response: &StepResponse,
    final_value: f64,
    output: Output,
    t_end: f64,
    lang: Lang,
) -> Vec<Mark> {
    let o = output.symbol();
    let label = |text: String, at: [f64; 2], side: Side| Label { text, at, side };
    let instant = |t: f64, name: &str| Mark::Instant {
        t,
        y: response.value(t),
        label: label(equals(name, t, r.unit, lang), [t, 0.0], Side::AboveRight),
    };
    let peak_time = read("tp").map(|tp| tp.value);
    match r.key.as_str() {
        "tp" => vec![instant(r.value, "t_p")],
        "tau" => {
            let y = response.value(r.value);
            // What the student computes to find τ: 0.632 of the final value read.
            let level = AT_TAU * read("y_final").map_or(final_value, |f| f.value);
            let name = format!("{}·{o}(∞)", num(lang, AT_TAU));
            vec![
                instant(r.value, "τ"),
                Mark::Value {
                    t: r.value,
                    y,
                    label: label(
                        equals(&name, level, Unit::None, lang),
                        [r.value, y],
                        Side::BelowRight,
                    ),
                },
            ]
        }
        "y_peak" => peak_time.map_or_else(Vec::new, |tp| {
            let y = response.value(tp);
            vec![Mark::Value {
                t: tp,
                y,
                label: label(
                    equals(&format!("{o}(t_p)"), r.value, r.unit, lang),
                    [tp, y],
                    Side::AboveRight,
                ),
            }]
        }),
        "y_final" | "x_final" => vec![Mark::Level {
            y: final_value,
            label: label(
                equals(&format!("{o}(∞)"), r.value, r.unit, lang),
                [t_end, final_value],
                Side::AboveLeft,
            ),
        }],
        "x_over" => peak_time.map_or_else(Vec::new, |tp| {
            let y = response.value(tp);
            vec![Mark::Gap {
                t: tp,
                from: final_value,
                to: y,
                label: label(
                    equals(&format!("{o}(t_p) − {o}(∞)"), r.value, r.unit, lang),
                    [tp, y],
                    Side::AboveRight,
                ),
            }]
        }),
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use degrau_lti::StepInfo;

    fn part(id: &str) -> Part {
        let sheet = super::super::session::the_sheet()
            .unwrap_or_else(|e| panic!("the sheet does not build: {e}"));
        degrau_exercise::find_part(sheet, id)
            .unwrap_or_else(|| panic!("no part {id}"))
            .clone()
    }

    fn reading(part: &Part, key: &str) -> f64 {
        let System::Figure { readings, .. } = &part.system else {
            panic!("{} is not read off a figure", part.id);
        };
        readings
            .iter()
            .find(|r| r.key == key)
            .unwrap_or_else(|| panic!("{}: no reading {key}", part.id))
            .value
    }

    fn info(part: &Part) -> StepInfo {
        let System::Figure {
            curve, amplitude, ..
        } = &part.system
        else {
            panic!("{} is not read off a figure", part.id);
        };
        let r = StepResponse::new(curve, *amplitude).expect("a response");
        StepInfo::of_response(&r, &StepInfoOptions::default())
    }

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    fn scene_of(id: &str, lang: Lang) -> (Part, Scene) {
        let p = part(id);
        let s = scene(&p, lang).unwrap_or_else(|| panic!("{id}: no figure"));
        (p, s)
    }

    fn instants(s: &Scene) -> Vec<(f64, f64)> {
        s.marks
            .iter()
            .filter_map(|m| match m {
                Mark::Instant { t, y, .. } => Some((*t, *y)),
                _ => None,
            })
            .collect()
    }

    fn level(s: &Scene) -> f64 {
        s.marks
            .iter()
            .find_map(|m| match m {
                Mark::Level { y, .. } => Some(*y),
                _ => None,
            })
            .expect("a final value marked")
    }

    /// The common checks: the span shows the settling, the curve ends on the final value
    /// marked, every mark within the y range.
    fn settles_in_view(p: &Part, s: &Scene, final_key: &str) {
        let i = info(p);
        let ts = i.settling_time.expect("settles");
        assert!(s.t_end >= ts, "{}: span {} < t_s {ts}", p.id, s.t_end);
        let y_final = i.steady_state.expect("a final value");
        assert!(close(level(s), y_final, 1e-12));
        assert!(close(level(s), reading(p, final_key), 1e-6), "{}", p.id);
        let last = s.curve.last().expect("points")[1];
        assert!(close(last, y_final, 0.02), "{}: ends at {last}", p.id);
        assert_eq!(s.curve.len(), SAMPLES);
        let (lo, hi) = s.y_range;
        for m in &s.marks {
            for y in mark_heights(m) {
                assert!(lo < y && y < hi, "{}: {m:?} outside {lo}..{hi}", p.id);
            }
        }
    }

    #[test]
    fn exercise_2_marks_tau_at_63_percent_of_the_final_value() {
        let (p, s) = scene_of("2", Lang::En);
        settles_in_view(&p, &s, "y_final");
        let [(t, y)] = instants(&s)[..] else {
            panic!("one instant: {:?}", s.marks);
        };
        assert_eq!(t, reading(&p, "tau"));
        let y_final = reading(&p, "y_final");
        assert!(close(y, AT_TAU * y_final, 1e-3), "y(τ) = {y}");
        assert!(close(y, (1.0 - (-1f64).exp()) * y_final, 1e-9));
        assert_eq!(s.y_axis, "y(t)");
        let texts: Vec<&str> = s.marks.iter().map(|m| m.label().text.as_str()).collect();
        assert!(texts.contains(&"τ = 0.25 s"), "{texts:?}");
        assert!(texts.contains(&"0.632·y(∞) = 0.316"), "{texts:?}");
        assert!(texts.contains(&"y(∞) = 0.5"), "{texts:?}");
    }

    #[test]
    fn exercise_4_marks_the_peak_and_the_final_value() {
        let (p, s) = scene_of("4", Lang::En);
        settles_in_view(&p, &s, "y_final");
        let [(tp, y)] = instants(&s)[..] else {
            panic!("one instant: {:?}", s.marks);
        };
        assert_eq!(tp, reading(&p, "tp"));
        let i = info(&p);
        let peak = i.peak.expect("a peak");
        assert!(close(y, peak, 1e-6), "y(t_p) = {y}, peak {peak}");
        assert!(close(tp, i.peak_time.expect("t_p"), 1e-6));
        assert!(close(y, reading(&p, "y_peak"), 1e-6));
        assert!(s.curve.iter().all(|q| q[1] <= y * (1.0 + 1e-9)));
        let value = s.marks.iter().find_map(|m| match m {
            Mark::Value { t, y, .. } => Some((*t, *y)),
            _ => None,
        });
        assert_eq!(value, Some((tp, y)), "y(t_p) read at the peak");
        assert!(s.t_end >= 2.5 * tp);
    }

    #[test]
    fn exercise_9_marks_a_displacement_its_overshoot_and_peak_time() {
        let (p, s) = scene_of("9", Lang::En);
        settles_in_view(&p, &s, "x_final");
        assert_eq!(s.y_axis, "x(t) (m)");
        let [(tp, y)] = instants(&s)[..] else {
            panic!("one instant: {:?}", s.marks);
        };
        assert_eq!(tp, reading(&p, "tp"));
        let i = info(&p);
        assert!(close(y, i.peak.expect("a peak"), 1e-6));
        let gap = s.marks.iter().find_map(|m| match m {
            Mark::Gap { t, from, to, .. } => Some((*t, *from, *to)),
            _ => None,
        });
        let Some((t, from, to)) = gap else {
            panic!("the overshoot marked: {:?}", s.marks);
        };
        assert_eq!((t, to), (tp, y));
        assert!(
            close(to - from, reading(&p, "x_over"), 1e-6),
            "{}",
            to - from
        );
        // x(t) is 10 N times the curve: x(∞) = 0.03 m.
        assert!(close(from, 0.03, 1e-9));
        let texts: Vec<&str> = s.marks.iter().map(|m| m.label().text.as_str()).collect();
        assert!(texts.contains(&"x(∞) = 0.03 m"), "{texts:?}");
        assert!(texts.contains(&"x(t_p) − x(∞) = 0.003 m"), "{texts:?}");
        assert!(texts.contains(&"t_p = 2 s"), "{texts:?}");
        assert!(!texts.iter().any(|t| t.contains('f')), "no force mark");
    }

    #[test]
    fn labels_take_the_languages_decimal_separator() {
        for id in ["2", "4", "9"] {
            let (_, pt) = scene_of(id, Lang::Pt);
            let (_, en) = scene_of(id, Lang::En);
            assert_eq!(pt.marks.len(), en.marks.len());
            for m in &pt.marks {
                let text = &m.label().text;
                assert!(!text.contains('.'), "{id}: {text:?}");
            }
            for m in &en.marks {
                assert!(!m.label().text.contains(','), "{id}: {:?}", m.label());
            }
            assert!(
                pt.marks.iter().any(|m| m.label().text.contains(',')),
                "{id}: a decimal comma somewhere"
            );
        }
        let (_, s) = scene_of("4", Lang::Pt);
        let texts: Vec<&str> = s.marks.iter().map(|m| m.label().text.as_str()).collect();
        assert_eq!(texts, ["t_p = 0,0551 s", "y(t_p) = 0,944", "y(∞) = 0,75"]);
    }

    #[test]
    fn parts_without_a_figure_have_no_scene() {
        assert_eq!(scene(&part("1a"), Lang::En), None);
        assert_eq!(scene(&part("8b"), Lang::Pt), None);
    }
}
