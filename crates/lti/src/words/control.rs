//! The words of controllers and their loop with a true dead time: the controller's
//! parameters refused ([`ControllerError`]), the loop's refusals and the names of its
//! responses and metrics, in English and Brazilian Portuguese (controlador, sintonia,
//! perturbação de carga, tempo integral, tempo derivativo, …).

use crate::control::{ControllerError, DelayLoopError};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

impl Localize for ControllerError {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match *self {
            ControllerError::Gain(x) => lang.pick(
                format!(
                    "the controller gain Kc must be a finite number other than 0, not {}",
                    n(x)
                ),
                format!(
                    "o ganho do controlador Kc deve ser um número finito diferente de 0, não {}",
                    n(x)
                ),
            ),
            ControllerError::IntegralTime(x) => lang.pick(
                format!(
                    "the integral time Ti must be a positive number of seconds, not {}",
                    n(x)
                ),
                format!(
                    "o tempo integral Ti deve ser um número positivo de segundos, não {}",
                    n(x)
                ),
            ),
            ControllerError::DerivativeTime(x) => lang.pick(
                format!(
                    "the derivative time Td must be 0 or a positive number of seconds, not {}",
                    n(x)
                ),
                format!(
                    "o tempo derivativo Td deve ser 0 ou um número positivo de segundos, não {}",
                    n(x)
                ),
            ),
            ControllerError::Filter(x) => lang.pick(
                format!(
                    "the derivative filter N must be a positive number, not {}",
                    n(x)
                ),
                format!(
                    "o filtro derivativo N deve ser um número positivo, não {}",
                    n(x)
                ),
            ),
            ControllerError::SetpointWeight(x) => lang.pick(
                format!(
                    "the setpoint weight b must be between 0 and 1, not {}",
                    n(x)
                ),
                format!(
                    "o peso da referência b deve estar entre 0 e 1, não {}",
                    n(x)
                ),
            ),
        }
    }
}

impl Localize for DelayLoopError {
    fn text(&self, lang: Lang) -> String {
        match *self {
            DelayLoopError::NotWellPosed => lang.pick(
                "the loop is not well posed: 1 + C·G is 0 at high frequency (the controller's and the plant's direct feedthroughs cancel)".into(),
                "a malha não é bem posta: 1 + C·G é 0 em alta frequência (as transmissões diretas do controlador e da planta se anulam)".into(),
            ),
            DelayLoopError::BadHorizon(t) => lang.pick(
                format!("the time to compute must be a positive number of seconds, not {}", lang.num(t, 6)),
                format!("o tempo a calcular deve ser um número positivo de segundos, não {}", lang.num(t, 6)),
            ),
            DelayLoopError::TooManySteps { fastest } => lang.pick(
                format!(
                    "the loop's fastest time constant ({} s) is too short beside the time asked: more than 400000 steps would be needed",
                    lang.num(fastest, 4)
                ),
                format!(
                    "a constante de tempo mais rápida da malha ({} s) é curta demais para o tempo pedido: seriam precisos mais de 400000 passos",
                    lang.num(fastest, 4)
                ),
            ),
        }
    }
}

/// Every message of the controllers and their loop, for the words' test.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    [
        ControllerError::Gain(0.0),
        ControllerError::IntegralTime(-1.0),
        ControllerError::DerivativeTime(-2.0),
        ControllerError::Filter(0.0),
        ControllerError::SetpointWeight(1.5),
    ]
    .iter()
    .map(|e| Message::of(format!("{e:?}"), e))
    .chain(
        [
            DelayLoopError::NotWellPosed,
            DelayLoopError::BadHorizon(-1.0),
            DelayLoopError::TooManySteps { fastest: 1e-6 },
        ]
        .iter()
        .map(|e| Message::of(format!("{e:?}"), e)),
    )
    .collect()
}
