//! The words of the state file: which part of a saved session could not be restored and
//! why, why the file could not be read or written, why the session could not be saved, and
//! what is wrong with a saved system, loop or step test, in English and in Brazilian
//! Portuguese. A system's own text of an io error is quoted as it is.

use degrau_words::{Lang, Localize, Message};

use crate::design::closed_loop::{KP_LIMIT, LoopProblem};
use crate::design::plane::View;
use crate::design::state::{MAX_ROOTS, Quantity, RootId, RootRole, SystemProblem};
use crate::field::LimitReason;
use crate::persist::problem::{
    ExperimentProblem, Field, FieldProblem, FileAction, Reason, SaveFailure, StateError, TestValue,
};
use degrau_ident::fit::MAX_STARTS;
use degrau_lti::feedback::PadeOrder;

/// A number as the program wrote it, with `lang`'s decimal separator.
fn number(x: impl std::fmt::Display, lang: Lang) -> String {
    lang.localize_number(&x.to_string())
}

/// A limit in scientific notation (`1e6`), with `lang`'s decimal separator.
fn limit(x: f64, lang: Lang) -> String {
    lang.localize_number(&format!("{x:e}"))
}

impl Localize for FileAction {
    fn text(&self, lang: Lang) -> String {
        match self {
            FileAction::LookAt => lang.pick("could not look at", "não foi possível examinar"),
            FileAction::Read => lang.pick("could not read", "não foi possível ler"),
            FileAction::Create => lang.pick("could not create", "não foi possível criar"),
            FileAction::Write => lang.pick("could not write", "não foi possível gravar"),
            FileAction::Replace => lang.pick("could not replace", "não foi possível substituir"),
        }
        .to_string()
    }
}

impl Localize for StateError {
    fn text(&self, lang: Lang) -> String {
        match self {
            StateError::Io { action, path, os } => {
                format!("{} {}: {os}", action.text(lang), path.display())
            }
            StateError::NotAFile(path) => format!(
                "{} {}",
                path.display(),
                lang.pick("is not a regular file", "não é um arquivo comum")
            ),
            StateError::TooLarge(path, bytes) => format!(
                "{} {}",
                path.display(),
                match lang {
                    Lang::En => format!("is {bytes} bytes, more than a saved session can be"),
                    Lang::Pt => format!("tem {bytes} bytes, mais do que uma sessão salva pode ter"),
                }
            ),
        }
    }
}

impl Localize for Field {
    fn text(&self, lang: Lang) -> String {
        match self {
            Field::WholeFile => lang.pick("the whole file", "o arquivo inteiro").to_string(),
            Field::WholeSession => lang
                .pick("the whole session", "a sessão inteira")
                .to_string(),
            Field::Path(path) => path.clone(),
        }
    }
}

impl Localize for Quantity {
    fn text(&self, lang: Lang) -> String {
        match self {
            Quantity::Sigma(root) => {
                format!("{}: σ", crate::words::design::root_label(*root, lang))
            }
            Quantity::Omega(root) => {
                format!("{}: ω", crate::words::design::root_label(*root, lang))
            }
            Quantity::Gain => lang.pick("gain", "ganho").to_string(),
            Quantity::Amplitude => lang
                .pick("step amplitude", "amplitude do degrau")
                .to_string(),
            Quantity::Delay => lang.pick("dead time", "tempo morto").to_string(),
        }
    }
}

impl Localize for SystemProblem {
    fn text(&self, lang: Lang) -> String {
        match self {
            SystemProblem::OutOfRange {
                what,
                value,
                limit: l,
            } => {
                let (what, value, l) = (what.text(lang), number(value, lang), limit(*l, lang));
                match lang {
                    Lang::En => format!("{what} = {value} is not a finite number within ±{l}"),
                    Lang::Pt => format!("{what} = {value} não é um número finito dentro de ±{l}"),
                }
            }
            SystemProblem::RealWithOmega { root, omega } => {
                let (root, omega) = (
                    crate::words::design::root_label(*root, lang),
                    number(omega, lang),
                );
                match lang {
                    Lang::En => format!("{root} is real but has ω = {omega}"),
                    Lang::Pt => format!("{root} é real mas tem ω = {omega}"),
                }
            }
            SystemProblem::NegativeOmega { root, omega } => {
                let (root, omega) = (
                    crate::words::design::root_label(*root, lang),
                    number(omega, lang),
                );
                match lang {
                    Lang::En => format!("{root} has ω = {omega} < 0"),
                    Lang::Pt => format!("{root} tem ω = {omega} < 0"),
                }
            }
            SystemProblem::TooMany { role, count } => {
                let roles = format!("{}s", crate::words::design::role_name(*role, lang));
                match lang {
                    Lang::En => format!("{count} {roles}, more than the {MAX_ROOTS} the app holds"),
                    Lang::Pt => {
                        format!("{count} {roles}, mais do que os {MAX_ROOTS} que o app comporta")
                    }
                }
            }
            SystemProblem::NegativeDelay(delay) => {
                let delay = number(delay, lang);
                match lang {
                    Lang::En => format!("dead time = {delay} s is negative"),
                    Lang::Pt => format!("tempo morto = {delay} s é negativo"),
                }
            }
        }
    }
}

impl Localize for LoopProblem {
    fn text(&self, lang: Lang) -> String {
        let l = limit(KP_LIMIT, lang);
        match (self, lang) {
            (LoopProblem::Gain(kp), Lang::En) => {
                format!("the gain Kp = {} is beyond ±{l}", number(kp, lang))
            }
            (LoopProblem::Gain(kp), Lang::Pt) => {
                format!("o ganho Kp = {} está além de ±{l}", number(kp, lang))
            }
            (LoopProblem::Pade(PadeOrder { m, n }), Lang::En) => {
                format!("the Padé order ({m}, {n}) is not one offered")
            }
            (LoopProblem::Pade(PadeOrder { m, n }), Lang::Pt) => {
                format!("a ordem de Padé ({m}, {n}) não é uma das oferecidas")
            }
            (LoopProblem::Controller(e), _) => e.text(lang),
        }
    }
}

/// The view's words: out of range, fitted to the roots again.
fn view_text(v: &View, lang: Lang) -> String {
    let (re, im, ppu) = (
        number(v.center_re, lang),
        number(v.center_im, lang),
        number(v.pixels_per_unit, lang),
    );
    match lang {
        Lang::En => format!(
            "the view (centre {re} + {im}j, {ppu} pixels per unit) is out of range; fitted to the roots"
        ),
        Lang::Pt => format!(
            "a vista (centro {re} + {im}j, {ppu} pixels por unidade) está fora do alcance; enquadrada nas raízes"
        ),
    }
}

impl Localize for TestValue {
    fn text(&self, lang: Lang) -> String {
        match self {
            TestValue::StepTime => lang.pick("the step time t0", "o instante do degrau t0"),
            TestValue::StepSize => lang.pick("the step size Δu", "o tamanho do degrau Δu"),
            TestValue::OperatingPoint => {
                lang.pick("the operating point y0", "o ponto de operação y0")
            }
            TestValue::WindowStart => lang.pick("the window start", "o início da janela"),
            TestValue::WindowEnd => lang.pick("the window end", "o fim da janela"),
        }
        .to_string()
    }
}

impl Localize for ExperimentProblem {
    fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (ExperimentProblem::NotFinite { what, value }, Lang::En) => {
                format!(
                    "{} = {} is not a finite number",
                    what.text(lang),
                    number(value, lang)
                )
            }
            (ExperimentProblem::NotFinite { what, value }, Lang::Pt) => {
                format!(
                    "{} = {} não é um número finito",
                    what.text(lang),
                    number(value, lang)
                )
            }
            (ExperimentProblem::ZeroStep, Lang::En) => "the step size Δu is 0".into(),
            (ExperimentProblem::ZeroStep, Lang::Pt) => "o tamanho do degrau Δu é 0".into(),
            (ExperimentProblem::EmptyWindow(a, b), Lang::En) => {
                format!(
                    "the window {}…{} is empty",
                    number(a, lang),
                    number(b, lang)
                )
            }
            (ExperimentProblem::EmptyWindow(a, b), Lang::Pt) => {
                format!(
                    "a janela {}…{} está vazia",
                    number(a, lang),
                    number(b, lang)
                )
            }
            (ExperimentProblem::Filter(fc), Lang::En) => {
                format!(
                    "the filter cut-off {} Hz is not a positive number",
                    number(fc, lang)
                )
            }
            (ExperimentProblem::Filter(fc), Lang::Pt) => format!(
                "a frequência de corte do filtro, {} Hz, não é um número positivo",
                number(fc, lang)
            ),
        }
    }
}

impl Localize for Reason {
    fn text(&self, lang: Lang) -> String {
        let say = |en: String, pt: String| lang.pick(en, pt);
        match self {
            Reason::File(e) => e.text(lang),
            Reason::System(p) => p.text(lang),
            Reason::Placement(why) => why.text(lang),
            Reason::Options(e) => e.text(lang),
            Reason::Loop(p) => p.text(lang),
            Reason::View(v) => view_text(v, lang),
            Reason::Experiment(p) => p.text(lang),
            Reason::NotWritable => SaveFailure::NotWritable.text(lang),
            Reason::NotJson { line, column } => say(
                format!("not a saved session (not JSON: line {line}, column {column})"),
                format!("não é uma sessão salva (não é JSON: linha {line}, coluna {column})"),
            ),
            Reason::NotAnObject => lang
                .pick(
                    "not a saved session (not a JSON object)",
                    "não é uma sessão salva (não é um objeto JSON)",
                )
                .into(),
            Reason::ExpectedObject { found } => say(
                format!("expected an object, found {found}"),
                format!("esperava um objeto, encontrou {found}"),
            ),
            Reason::Unreadable { found } => say(
                format!("{found} is not a value this field holds"),
                format!("{found} não é um valor que este campo aceite"),
            ),
            Reason::Code(code) => say(
                format!("\"{code}\" is not a model code (P, 1 to 3 poles, then any of D, U, Z, I)"),
                format!(
                    "\"{code}\" não é um código de modelo (P, 1 a 3 polos, depois D, U, Z, I em qualquer combinação)"
                ),
            ),
            Reason::Starts(starts) => say(
                format!("{starts} starts, not 1 to {MAX_STARTS}"),
                format!("{starts} partidas, não de 1 a {MAX_STARTS}"),
            ),
            Reason::TuneModel(p) => p.text(lang),
            Reason::Controller(e) => e.text(lang),
            Reason::SamplingPeriod(h) => say(
                format!(
                    "the sampling period h = {} s is not a positive number",
                    number(h, lang)
                ),
                format!(
                    "o período de amostragem h = {} s não é um número positivo",
                    number(h, lang)
                ),
            ),
            Reason::Scale(s) => say(
                format!(
                    "the presentation size {} is not from 1 to 2",
                    number(s, lang)
                ),
                format!(
                    "o tamanho de apresentação {} não está entre 1 e 2",
                    number(s, lang)
                ),
            ),
        }
    }
}

impl Localize for FieldProblem {
    /// "field (reason)", as the notice lists them.
    fn text(&self, lang: Lang) -> String {
        format!("{} ({})", self.field.text(lang), self.reason.text(lang))
    }
}

impl Localize for SaveFailure {
    fn text(&self, lang: Lang) -> String {
        match self {
            SaveFailure::Stopped => lang
                .pick("the saver has stopped", "o gravador parou")
                .into(),
            SaveFailure::NotWritable => lang
                .pick(
                    "the session could not be written as JSON",
                    "a sessão não pôde ser escrita como JSON",
                )
                .into(),
            SaveFailure::File(e) => e.text(lang),
        }
    }
}

/// An example of every reason a field of a saved session is reset for.
pub fn reasons() -> Vec<Reason> {
    let root = RootId {
        role: RootRole::Pole,
        index: 1,
    };
    let path = std::path::PathBuf::from("state.json");
    let too_many = SystemProblem::TooMany {
        role: RootRole::Zero,
        count: 40,
    };
    vec![
        Reason::File(StateError::NotAFile(path.clone())),
        Reason::File(StateError::TooLarge(path.clone(), 1 << 30)),
        Reason::NotJson {
            line: 1,
            column: 12,
        },
        Reason::NotAnObject,
        Reason::ExpectedObject { found: "3".into() },
        Reason::Unreadable {
            found: "\"two\"".into(),
        },
        Reason::NotWritable,
        Reason::System(SystemProblem::OutOfRange {
            what: Quantity::Sigma(root),
            value: f64::NAN,
            limit: 1e6,
        }),
        Reason::System(SystemProblem::OutOfRange {
            what: Quantity::Omega(root),
            value: 2e6,
            limit: 1e6,
        }),
        Reason::System(SystemProblem::RealWithOmega { root, omega: 1.5 }),
        Reason::System(SystemProblem::NegativeOmega { root, omega: -1.5 }),
        Reason::System(too_many),
        Reason::System(SystemProblem::NegativeDelay(-0.5)),
        Reason::Placement(LimitReason::RootSpread),
        Reason::Options(degrau_lti::LtiError::BadSettlingBand(7.0)),
        Reason::Loop(LoopProblem::Gain(1e300)),
        Reason::Loop(LoopProblem::Pade(PadeOrder { m: 9, n: 1 })),
        Reason::Loop(LoopProblem::Controller(
            degrau_lti::control::ControllerError::IntegralTime(0.0),
        )),
        Reason::View(View {
            center_re: -5e29,
            center_im: 0.0,
            pixels_per_unit: 1e-300,
        }),
        Reason::Experiment(ExperimentProblem::ZeroStep),
        Reason::Experiment(ExperimentProblem::EmptyWindow(3.5, 1.0)),
        Reason::Experiment(ExperimentProblem::Filter(-1.0)),
        Reason::Code("Q9".into()),
        Reason::Starts(100_000),
        Reason::Scale(3.5),
        Reason::TuneModel(crate::tune::model::ModelProblem::Delay(-1.0)),
        Reason::Controller(degrau_lti::control::ControllerError::IntegralTime(0.0)),
        Reason::SamplingPeriod(-0.1),
    ]
}

/// Every message of the state file's words: each reason, each field, each quantity and
/// test value, each file action and each save failure.
pub fn messages() -> Vec<Message> {
    let mut all: Vec<Message> = reasons()
        .iter()
        .map(|r| Message::of(format!("persist::Reason::{r:?}"), r))
        .collect();
    let quantities = [Quantity::Gain, Quantity::Amplitude, Quantity::Delay];
    all.extend(
        quantities
            .iter()
            .map(|q| Message::of(format!("persist::{q:?}"), q)),
    );
    let values = [
        TestValue::StepTime,
        TestValue::StepSize,
        TestValue::OperatingPoint,
        TestValue::WindowStart,
        TestValue::WindowEnd,
    ];
    all.extend(values.iter().map(|v| {
        let p = ExperimentProblem::NotFinite {
            what: *v,
            value: f64::INFINITY,
        };
        Message::of(format!("persist::{p:?}"), &p)
    }));
    let actions = [
        FileAction::LookAt,
        FileAction::Read,
        FileAction::Create,
        FileAction::Write,
        FileAction::Replace,
    ];
    all.extend(actions.iter().map(|&action| {
        let e = StateError::Io {
            action,
            path: "state.json".into(),
            os: "No space left on device (os error 28)".into(),
        };
        Message::of(format!("persist::{e:?}"), &e)
    }));
    all.extend(
        [Field::WholeFile, Field::WholeSession]
            .iter()
            .map(|f| Message::of(format!("persist::{f:?}"), f)),
    );
    all.extend(
        [SaveFailure::Stopped, SaveFailure::NotWritable]
            .iter()
            .map(|f| Message::of(format!("persist::{f:?}"), f)),
    );
    all
}
