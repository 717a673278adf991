//! The words of controllers and their loop with a true dead time: the controller's
//! parameters refused ([`ControllerError`]), the loop's refusals and the names of its
//! responses and metrics, in English and Brazilian Portuguese (controlador, sintonia,
//! perturbação de carga, tempo integral, tempo derivativo, …).

use crate::control::ControllerError;

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
    .collect()
}
