//! The words of `degrau loop --controller` and `degrau tune`: their refusals and the lines
//! of their reports, in English and Brazilian Portuguese. The controller's, the loop's and
//! the tuning rules' own words are the lti crate's ([`degrau_lti::words::control`]),
//! re-exported here.

pub use degrau_lti::words::control::*;

use crate::cli::loop_controller::ControllerLoopError;
use crate::cli::tune_plant::PlantError;
use crate::lti::control::{Action, LoopInput};

#[cfg(test)]
use super::Message;
use super::{Lang, Localize};

/// The action's name as written in a report: P, PI, PD, PID.
fn action_name(action: Action) -> String {
    action.key().to_uppercase()
}

/// What an action's flags are for: `--ti` needs integral action (pi, pid), …
fn actions_with(flag: &str) -> &'static str {
    match flag {
        "--ti" => "pi, pid",
        "--td" | "--n" => "pd, pid",
        _ => "p, pi, pd, pid",
    }
}

impl Localize for ControllerLoopError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ControllerLoopError::Missing { flag, action } => {
                let what = match *flag {
                    "--kc" => lang.pick(
                        "the controller gain Kc; --kp says the same",
                        "o ganho do controlador Kc; --kp diz o mesmo",
                    ),
                    "--ti" => lang.pick("the integral time Ti, s", "o tempo integral Ti, s"),
                    _ => lang.pick("the derivative time Td, s", "o tempo derivativo Td, s"),
                };
                let key = action.key();
                lang.pick(
                    format!("--controller {key} needs {flag} ({what})"),
                    format!("--controller {key} precisa de {flag} ({what})"),
                )
            }
            ControllerLoopError::Unused { flag, action } => {
                let (key, with) = (action.key(), actions_with(flag));
                lang.pick(
                    format!(
                        "{flag} is for a controller that has that action ({with}), not --controller {key}"
                    ),
                    format!(
                        "{flag} é de um controlador com essa ação ({with}), não de --controller {key}"
                    ),
                )
            }
            ControllerLoopError::Controller(e) => e.text(lang),
            ControllerLoopError::Loop(e) => e.text(lang),
            ControllerLoopError::BadTime(t) => lang.pick(
                format!(
                    "--at: each instant must be 0 or a positive number of seconds, not {}",
                    lang.num(*t, 6)
                ),
                format!(
                    "--at: cada instante deve ser 0 ou um número positivo de segundos, não {}",
                    lang.num(*t, 6)
                ),
            ),
            ControllerLoopError::TooManyTimes(n) => lang.pick(
                format!(
                    "--at gives {n} instants; at most {} are allowed",
                    crate::cli::MAX_SAMPLES
                ),
                format!(
                    "--at dá {n} instantes; o máximo é {}",
                    crate::cli::MAX_SAMPLES
                ),
            ),
        }
    }
}

/// What `degrau tune` takes, said after what the system has.
fn takes(lang: Lang) -> &'static str {
    lang.pick(
        "degrau tune takes a first- or second-order plant with a dead time (FOPTD, SOPTD): no zeros, one or two real stable poles",
        "degrau tune recebe uma planta de primeira ou segunda ordem com tempo morto (FOPTD, SOPTD): sem zeros, um ou dois polos reais estáveis",
    )
}

impl Localize for PlantError {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        let takes = takes(lang);
        match self {
            PlantError::Cli(e) => e.text(lang),
            PlantError::Zeros(count) => lang.pick(
                format!("{takes}; this system has {count} zero(s)"),
                format!("{takes}; este sistema tem {count} zero(s)"),
            ),
            PlantError::Order(count) => lang.pick(
                format!("{takes}; this system has {count} poles"),
                format!("{takes}; este sistema tem {count} polos"),
            ),
            PlantError::Complex(re, im) => lang.pick(
                format!("{takes}; this system has complex poles {} ± j{}", n(*re), n(*im)),
                format!("{takes}; este sistema tem polos complexos {} ± j{}", n(*re), n(*im)),
            ),
            PlantError::NotStable(re) => lang.pick(
                format!("{takes}; this system has a pole at s = {}", n(*re)),
                format!("{takes}; este sistema tem um polo em s = {}", n(*re)),
            ),
            PlantError::Model(e) => e.text(lang),
            PlantError::Read(path, why) => lang.pick(
                format!("cannot read {path}: {why}"),
                format!("não foi possível ler {path}: {why}"),
            ),
            PlantError::NotFitJson(path, why) => lang.pick(
                format!("{path} is not the JSON of degrau fit --json: {why}"),
                format!("{path} não é o JSON de degrau fit --json: {why}"),
            ),
            PlantError::NoModel(path) => lang.pick(
                format!("{path} is not the JSON of degrau fit --json: it has no \"model\" and \"params\""),
                format!("{path} não é o JSON de degrau fit --json: não tem \"model\" e \"params\""),
            ),
            PlantError::ModelCode(code) => lang.pick(
                format!("the fit's model is {code}; degrau tune takes a P1, P1D, P2 or P2D fit (a first- or second-order plant with real poles)"),
                format!("o modelo do ajuste é {code}; degrau tune recebe um ajuste P1, P1D, P2 ou P2D (planta de primeira ou segunda ordem com polos reais)"),
            ),
            PlantError::Param(name) => lang.pick(
                format!("the fit has no number for its parameter {name}"),
                format!("o ajuste não tem um número para o seu parâmetro {name}"),
            ),
        }
    }
}

crate::phrases! {
    /// Why a metric of a loop's response is absent.
    pub enum Absent {
        NotSettled => (
            "none: did not settle (the loop is unstable or too slow)",
            "não há: não acomodou (a malha é instável ou lenta demais)"
        ),
        NoIntegralAction => (
            "none: the error does not vanish without integral action",
            "não há: o erro não se anula sem ação integral"
        ),
        NoChange => ("none: the output does not move", "não há: a saída não se move"),
    }
}

/// "Controller PI, ideal (ISA) form: Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N))".
pub fn controller_heading(action: Action, lang: Lang) -> String {
    format!(
        "{} {}, {}",
        ControlWord::Controller.get(lang),
        action_name(action),
        ControlWord::IdealForm.get(lang)
    )
}

/// The parallel form's gains, written: Kp, Ki (1/s), Kd (s), Tf (s).
pub fn parallel_line(gains: [String; 4], lang: Lang) -> String {
    let [kp, ki, kd, tf] = gains;
    let form = ControlWord::ParallelForm.get(lang);
    lang.pick(
        format!(
            "  The same in the {form}, with Kp = {kp}, Ki = {ki} 1/s, Kd = {kd} s, Tf = {tf} s"
        ),
        format!("  O mesmo na {form}, com Kp = {kp}, Ki = {ki} 1/s, Kd = {kd} s, Tf = {tf} s"),
    )
}

/// The dead time (written, s) kept in the loop as it is.
pub fn exact_delay_line(delay: &str, lang: Lang) -> String {
    let exact = ControlWord::ExactDelay.get(lang);
    lang.pick(
        format!("Dead time e^(−θs), θ = {delay} s, kept in the loop: {exact}"),
        format!("Tempo morto e^(−θs), θ = {delay} s, mantido na malha: {exact}"),
    )
}

/// The heading of the response reported.
pub fn response_heading(input: LoopInput, lang: Lang) -> String {
    let name = match input {
        LoopInput::Setpoint => ControlWord::SetpointResponse,
        LoopInput::Load => ControlWord::LoadResponse,
    };
    format!("{}:", name.get(lang))
}

/// "1.2 at t = 5 s" (both written).
pub fn at_time(value: &str, time: &str, lang: Lang) -> String {
    lang.pick(
        format!("{value} at t = {time} s"),
        format!("{value} em t = {time} s"),
    )
}

/// The note of a fit whose dead time came out negative (`td` written, s).
pub fn negative_delay_note(td: &str, lang: Lang) -> String {
    match lang {
        Lang::En => format!(
            "note: the fit's dead time is {td} s, below 0 (the step's effect began between samples, before the step logged); a loop has no negative dead time, so it is tuned with θ = 0"
        ),
        Lang::Pt => format!(
            "nota: o tempo morto do ajuste é {td} s, abaixo de 0 (o efeito do degrau começou entre amostras, antes do degrau registrado); uma malha não tem tempo morto negativo, então a sintonia usa θ = 0"
        ),
    }
}

/// The closed loop's stability and its maximum sensitivity (`ms`, `w` as text).
pub fn stability_line(unstable: Option<usize>, ms: Option<(String, String)>, lang: Lang) -> String {
    match (unstable, ms, lang) {
        (Some(0), Some((ms, w)), Lang::En) => format!(
            "Closed loop: stable (no root in the right half-plane); Ms = {ms}, the peak of |1/(1 + L(jω))|, at ω = {w} rad/s"
        ),
        (Some(0), Some((ms, w)), Lang::Pt) => format!(
            "Malha fechada: estável (nenhuma raiz no semiplano direito); Ms = {ms}, o pico de |1/(1 + L(jω))|, em ω = {w} rad/s"
        ),
        (Some(0), None, _) => lang
            .pick(
                "Closed loop: stable (no root in the right half-plane)",
                "Malha fechada: estável (nenhuma raiz no semiplano direito)",
            )
            .to_string(),
        (Some(n), _, Lang::En) => {
            format!("Closed loop: unstable, {n} roots in the right half-plane")
        }
        (Some(n), _, Lang::Pt) => {
            format!("Malha fechada: instável, {n} raízes no semiplano direito")
        }
        (None, _, _) => lang
            .pick(
                "Closed loop: at the limit of stability (a root on the imaginary axis)",
                "Malha fechada: no limite da estabilidade (uma raiz no eixo imaginário)",
            )
            .to_string(),
    }
}

/// Whether the response settled, computed up to `end` (written, s).
pub fn settled_line(settled: bool, end: &str, lang: Lang) -> String {
    match (settled, lang) {
        (true, Lang::En) => format!("Settled: yes (computed up to t = {end} s)"),
        (true, Lang::Pt) => format!("Acomodou: sim (calculada até t = {end} s)"),
        (false, _) => format!(
            "{} ({})",
            ControlWord::NotSettled.get(lang),
            lang.pick(
                format!("computed up to t = {end} s"),
                format!("calculada até t = {end} s")
            )
        ),
    }
}

crate::phrases! {
    /// The words of `degrau tune`'s report: its headings and its table's columns (the
    /// symbols Kc, Ti, Td, IAE and Ms are the same in both languages).
    pub enum TuneWord {
        Model => ("Model", "Modelo"),
        RuleColumn => ("rule", "regra"),
        OvershootColumn => ("overshoot %", "sobressinal %"),
        SettlingColumn => ("settling (s)", "acomodação (s)"),
        PeakDeviationColumn => ("peak dev.", "desvio máx."),
        AtColumn => ("at (s)", "em (s)"),
        SetpointColumns => ("setpoint step", "degrau de referência"),
        LoadColumns => ("load step at the plant's input", "degrau de carga na entrada da planta"),
        Formulas => ("Formulas and sources:", "Fórmulas e fontes:"),
    }
}

/// The controller every rule gives: its action, the ideal form, N and b.
pub fn tune_controller_line(action: Action, lang: Lang) -> String {
    format!(
        "{}, N = {}, b = 1",
        controller_heading(action, lang),
        lang.num(crate::lti::control::controller::DEFAULT_FILTER, 6)
    )
}

/// How each rule's loop is judged.
pub fn tune_loop_line(lang: Lang) -> String {
    let exact = ControlWord::ExactDelay.get(lang);
    lang.pick(
        format!("Each loop closed around the plant with its dead time, {exact}: unit steps of the setpoint and of a load at the plant's input"),
        format!("Cada malha fechada em torno da planta com o seu tempo morto, {exact}: degraus unitários da referência e de uma carga na entrada da planta"),
    )
}

/// The τc (or λ for Lambda tuning) a rule used, written.
pub fn time_constant_line(rule: crate::lti::control::Rule, tc: &str, lang: Lang) -> String {
    let name = if rule == crate::lti::control::Rule::Lambda {
        "λ"
    } else {
        "τc"
    };
    lang.pick(
        format!("{name} = {tc} s used here"),
        format!("{name} = {tc} s usado aqui"),
    )
}

/// SIMC's series form (Kc, Ti, Td written).
pub fn series_line(values: [String; 3], lang: Lang) -> String {
    let [kc, ti, td] = values;
    lang.pick(
        format!(
            "in the series form Kc·(1 + 1/(Ti·s))·(1 + Td·s): Kc = {kc}, Ti = {ti} s, Td = {td} s"
        ),
        format!("na forma série Kc·(1 + 1/(Ti·s))·(1 + Td·s): Kc = {kc}, Ti = {ti} s, Td = {td} s"),
    )
}

/// An example of every message of `degrau loop --controller` and `degrau tune`, for the
/// test of the words.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all: Vec<Message> = [
        ControllerLoopError::Missing {
            flag: "--kc",
            action: Action::P,
        },
        ControllerLoopError::Missing {
            flag: "--ti",
            action: Action::PI,
        },
        ControllerLoopError::Missing {
            flag: "--td",
            action: Action::PID,
        },
        ControllerLoopError::Unused {
            flag: "--ti",
            action: Action::PD,
        },
        ControllerLoopError::BadTime(-1.0),
        ControllerLoopError::TooManyTimes(2_000_000),
    ]
    .iter()
    .map(|e| Message::of(format!("control::{e:?}"), e))
    .collect();
    all.extend(
        [
            PlantError::Zeros(1),
            PlantError::Order(3),
            PlantError::Complex(-1.0, 2.0),
            PlantError::NotStable(0.0),
            PlantError::Read("a.json".into(), "No such file".into()),
            PlantError::NotFitJson("a.json".into(), "EOF".into()),
            PlantError::NoModel("a.json".into()),
            PlantError::ModelCode("P2DU".into()),
            PlantError::Param("Tp1"),
        ]
        .iter()
        .map(|e| Message::of(format!("control::{e:?}"), e)),
    );
    all.extend(Absent::messages());
    all.extend(TuneWord::messages());
    all.push(Message::said("control::tune_controller_line", |l| {
        tune_controller_line(Action::PID, l)
    }));
    all.push(Message::said("control::tune_loop_line", tune_loop_line));
    all.push(Message::said("control::time_constant_line", |l| {
        time_constant_line(crate::lti::control::Rule::Simc, "2", l)
    }));
    all.push(Message::said("control::series_line", |l| {
        series_line(["1".into(), "2".into(), "3".into()], l)
    }));
    all.push(Message::said("control::controller_heading", |l| {
        controller_heading(Action::PI, l)
    }));
    all.push(Message::said("control::parallel_line", |l| {
        parallel_line(["1".into(), "2".into(), "3".into(), "4".into()], l)
    }));
    all.push(Message::said("control::exact_delay_line", |l| {
        exact_delay_line("2", l)
    }));
    all.push(Message::said("control::response_heading", |l| {
        response_heading(LoopInput::Load, l)
    }));
    all.push(Message::said("control::at_time", |l| at_time("1", "2", l)));
    for (id, roots, ms) in [
        (
            "control::stable_line",
            Some(0),
            Some(("1.6".to_string(), "0.3".to_string())),
        ),
        ("control::stable_line_no_ms", Some(0), None),
        ("control::unstable_line", Some(2), None),
        ("control::marginal_line", None, None),
    ] {
        all.push(Message::said(id, |l| stability_line(roots, ms.clone(), l)));
    }
    all.push(Message::said("control::negative_delay_note", |l| {
        negative_delay_note("-0.57", l)
    }));
    all.push(Message::said("control::settled_line", |l| {
        settled_line(true, "10", l)
    }));
    all.push(Message::said("control::not_settled_line", |l| {
        settled_line(false, "10", l)
    }));
    all
}
