//! The words of controllers and their loop with a true dead time: the controller's
//! parameters refused ([`ControllerError`]), the loop's refusals and the names of its
//! responses and metrics, in English and Brazilian Portuguese (controlador, sintonia,
//! perturbação de carga, tempo integral, tempo derivativo, …).

use crate::control::{ControllerError, DelayLoopError, RowError};

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

impl Localize for RowError {
    fn text(&self, lang: Lang) -> String {
        match self {
            RowError::NotApplicable(e) => e.text(lang),
            RowError::Loop(e) => e.text(lang),
            RowError::Model(e) => e.text(lang),
        }
    }
}

degrau_words::phrases! {
    /// The names of a controller's parts, the loop's responses and their metrics (the CLI's
    /// `degrau tune` and `degrau loop --controller`, the app's Tune mode).
    pub enum ControlWord {
        Controller => ("Controller", "Controlador"),
        Tuning => ("Tuning", "Sintonia"),
        Rule => ("Rule", "Regra"),
        Formula => ("Formula", "Fórmula"),
        Source => ("Source", "Fonte"),
        Gain => ("Controller gain Kc", "Ganho do controlador Kc"),
        IntegralTime => ("Integral time Ti (s)", "Tempo integral Ti (s)"),
        DerivativeTime => ("Derivative time Td (s)", "Tempo derivativo Td (s)"),
        Filter => ("Derivative filter N", "Filtro derivativo N"),
        SetpointWeight => ("Setpoint weight b", "Peso da referência b"),
        IdealForm => ("ideal (ISA) form: Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N))", "forma ideal (ISA): Kc·(1 + 1/(Ti·s) + Td·s/(1 + Td·s/N))"),
        ParallelForm => ("parallel form: Kp + Ki/s + Kd·s/(1 + Tf·s)", "forma paralela: Kp + Ki/s + Kd·s/(1 + Tf·s)"),
        SetpointResponse => ("Setpoint step response", "Resposta ao degrau de referência"),
        LoadResponse => ("Load disturbance response (step at the plant's input)", "Resposta à perturbação de carga (degrau na entrada da planta)"),
        FinalValue => ("Final value", "Valor final"),
        Overshoot => ("Overshoot (%)", "Sobressinal (%)"),
        Peak => ("Peak", "Pico"),
        PeakDeviation => ("Peak deviation", "Desvio máximo"),
        PeakTime => ("Peak time (s)", "Tempo de pico (s)"),
        SettlingTime => ("Settling time, 2 % (s)", "Tempo de acomodação, 2 % (s)"),
        Iae => ("IAE, integral of |e|", "IAE, integral de |e|"),
        Itae => ("ITAE, integral of t·|e|", "ITAE, integral de t·|e|"),
        MaxSensitivity => ("Maximum sensitivity Ms", "Sensibilidade máxima Ms"),
        ExactDelay => ("exact dead time (no Padé)", "atraso exato (sem Padé)"),
        NotSettled => ("did not settle: the loop is unstable or too slow", "não acomodou: a malha é instável ou lenta demais"),
        NoIntegralAction => ("none: the error does not vanish without integral action", "não há: o erro não se anula sem ação integral"),
        Unstable => ("unstable", "instável"),
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
    .chain(ControlWord::messages())
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
