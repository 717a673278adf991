//! The fit's words: parameters, how it ended, its warnings, the filter, the guess handles.

use super::*;

/// What a parameter is, in words ("static gain Δy/Δu", "ganho estático Δy/Δu").
pub fn param_meaning(p: Param, lang: Lang) -> &'static str {
    let (en, pt) = match p {
        Param::Kp => ("static gain Δy/Δu", "ganho estático Δy/Δu"),
        Param::Tp1 => ("first time constant", "primeira constante de tempo"),
        Param::Tp2 => ("second time constant", "segunda constante de tempo"),
        Param::Tp3 => ("third time constant", "terceira constante de tempo"),
        Param::Tw => (
            "time constant of the underdamped pair, 1/ωn",
            "constante de tempo do par subamortecido, 1/ωn",
        ),
        Param::Zeta => ("damping ratio of the pair", "fator de amortecimento do par"),
        Param::Td => ("dead time", "tempo morto"),
        Param::Tz => (
            "time constant of the zero (negative: inverse response)",
            "constante de tempo do zero (negativa: resposta inversa)",
        ),
        Param::Y0 => (
            "output before the step (operating point)",
            "saída antes do degrau (ponto de operação)",
        ),
        Param::Drift => (
            "slope of a linear drift, output units per second",
            "inclinação de uma deriva linear, unidades da saída por segundo",
        ),
        Param::Ta => (
            "how long before the sample that first shows it each input change happened",
            "quanto antes da amostra que primeiro a mostra cada mudança da entrada ocorreu",
        ),
        Param::X1 | Param::X2 | Param::X3 => (
            "coefficient of the initial transient (the test was not at rest), output units",
            "coeficiente do transitório inicial (o ensaio não estava em repouso), unidades da saída",
        ),
    };
    lang.pick(en, pt)
}

/// A parameter's meaning as a fact, for the test of every message.
#[cfg(test)]
pub(super) struct Meaning(pub(super) Param);

#[cfg(test)]
impl Localize for Meaning {
    fn text(&self, lang: Lang) -> String {
        param_meaning(self.0, lang).to_string()
    }
}

impl Localize for Structure {
    /// The code plus what it does not say: `P2 + drift`, `P1D, Y0 held` (`Y0 fixo`).
    fn text(&self, lang: Lang) -> String {
        let mut l = self.code();
        if self.drift {
            l.push_str(lang.pick(" + drift", " + deriva"));
        }
        if self.transient {
            l.push_str(lang.pick(" + initial transient", " + transitório inicial"));
        }
        if !self.free_offset {
            l.push_str(lang.pick(", Y0 held", ", Y0 fixo"));
        }
        l
    }
}

impl Localize for Termination {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Termination::Gradient => (
                "converged: the gradient vanished",
                "convergiu: o gradiente se anulou",
            ),
            Termination::SmallStep => (
                "converged: the steps became negligible",
                "convergiu: os passos ficaram desprezíveis",
            ),
            Termination::SmallCostChange => (
                "converged: the cost stopped decreasing",
                "convergiu: o custo parou de diminuir",
            ),
            Termination::IterationLimit => (
                "stopped at the iteration limit (not converged)",
                "parou no limite de iterações (não convergiu)",
            ),
            Termination::Cancelled => ("cancelled", "cancelado"),
            Termination::NoImprovement => (
                "stopped: no step lowered the cost from the start (not converged)",
                "parou: nenhum passo baixou o custo a partir do início (não convergiu)",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for FitWarning {
    fn text(&self, lang: Lang) -> String {
        match self {
            FitWarning::AtBound { param, bound } => {
                let b = full(lang, *bound);
                lang.pick(
                    format!(
                        "{param} stopped at its bound {b}: the optimum may lie beyond it, or the \
                         model does not need this parameter"
                    ),
                    format!(
                        "{param} parou no seu limite {b}: o ótimo pode estar além dele, ou o \
                         modelo não precisa deste parâmetro"
                    ),
                )
            }
            FitWarning::OverdampedUnderdamped { zeta } => {
                let z = d4(lang, *zeta);
                lang.pick(
                    format!(
                        "Zeta = {z} ≥ 1 in an underdamped model: the pair is not oscillatory; an \
                         overdamped structure (two real poles) says the same with a clearer \
                         meaning"
                    ),
                    format!(
                        "Zeta = {z} ≥ 1 num modelo subamortecido: o par não oscila; uma estrutura \
                         sobreamortecida (dois polos reais) diz o mesmo com um sentido mais claro"
                    ),
                )
            }
            FitWarning::Alias {
                omega_d,
                nyquist,
                between_samples,
            } => {
                let (w, ny) = (d4(lang, *omega_d), d4(lang, *nyquist));
                let pct = format!("{:.0}", 100.0 * between_samples);
                lang.pick(
                    format!(
                        "alias: the model oscillates at ωd = {w} rad/s, but samples every Ts can \
                         only show up to π/Ts = {ny} rad/s; between the samples the model swings \
                         by {pct} % of the step's effect. Its samples may match the data while \
                         the model is wrong: start from a better guess (the oscillation period of \
                         the data) or use several starts"
                    ),
                    format!(
                        "alias: o modelo oscila em ωd = {w} rad/s, mas amostras a cada Ts só \
                         mostram até π/Ts = {ny} rad/s; entre as amostras o modelo oscila {pct} % \
                         do efeito do degrau. Suas amostras podem coincidir com os dados e o \
                         modelo estar errado: parta de uma estimativa melhor (o período de \
                         oscilação dos dados) ou use vários pontos de partida"
                    ),
                )
            }
            FitWarning::NotIdentifiable { param } => lang.pick(
                format!(
                    "{param} is not identifiable from this data (the fit does not depend on it): \
                     no interval can be given"
                ),
                format!(
                    "{param} não é identificável a partir destes dados (o ajuste não depende \
                     dele): não se pode dar um intervalo"
                ),
            ),
            FitWarning::CombinationNotIdentifiable => lang
                .pick(
                    "a combination of the parameters is not identifiable from this data (the fit \
                     does not depend on it): no interval can be given",
                    "uma combinação dos parâmetros não é identificável a partir destes dados (o \
                     ajuste não depende dela): não se pode dar um intervalo",
                )
                .into(),
            FitWarning::LagsNotResolved { larger, smaller } => lang.pick(
                format!(
                    "{larger} and {smaller} cannot be told apart from this data: two equal time \
                     constants explain it as well. Their intervals are read together (the range \
                     of each wherever the other may be); a larger step or a longer record \
                     separates them"
                ),
                format!(
                    "{larger} e {smaller} não se distinguem com estes dados: duas constantes de \
                     tempo iguais os explicam igualmente bem. Seus intervalos são lidos juntos \
                     (a faixa de cada uma onde quer que a outra esteja); um degrau maior ou um \
                     registro mais longo as separa"
                ),
            ),
            FitWarning::NotConverged => lang
                .pick(
                    "the optimiser did not converge: the values are not an optimum",
                    "o otimizador não convergiu: os valores não são um ótimo",
                )
                .into(),
            FitWarning::NoImprovement => lang
                .pick(
                    "the optimiser found no step that lowers the cost from the start: the values \
                     are the start's, not an optimum; try another guess or more starts",
                    "o otimizador não achou passo que baixe o custo a partir do início: os \
                     valores são os da partida, não um ótimo; tente outra estimativa ou mais \
                     pontos de partida",
                )
                .into(),
            FitWarning::Unrepresentable { statistic, log10 } => {
                let e = lang.localize_number(&format!("{log10:.1}"));
                let shown = if *log10 > 0.0 { "inf" } else { "0" };
                lang.pick(
                    format!(
                        "the {statistic} is about 1e{e} in the data's units, beyond double \
                         precision, so it shows as {shown}; the RMSE, fit % and AIC are exact"
                    ),
                    format!(
                        "o {statistic} é cerca de 1e{e} nas unidades dos dados, além da precisão \
                         dupla, e aparece como {shown}; o RMSE, o ajuste % e o AIC são exatos"
                    ),
                )
            }
            FitWarning::GainUndetermined { low, high } => {
                let (lo, hi) = (full(lang, *low), full(lang, *high));
                lang.pick(
                    format!(
                        "the 95 % interval of Kp, [{lo}, {hi}], contains 0: this record does \
                         not determine the gain, not even its sign. A larger step, a longer \
                         record or a test in open loop may"
                    ),
                    format!(
                        "o intervalo de 95 % de Kp, [{lo}; {hi}], contém 0: este registro não \
                         determina o ganho, nem mesmo o seu sinal. Um degrau maior, um registro \
                         mais longo ou um ensaio em malha aberta podem determinar"
                    ),
                )
            }
        }
    }
}

impl Localize for Ewma {
    /// α, RC, RC/Ts and the lag, then the notes' warning when Ts > RC/5.
    fn text(&self, lang: Lang) -> String {
        let (a, rc, ratio, lag) = (
            d4(lang, self.alpha),
            d4(lang, self.rc),
            d4(lang, self.ratio()),
            d4(lang, self.lag()),
        );
        let line = lang.pick(
            format!(
                "α = {a}, RC = {rc} s, RC/Ts = {ratio}; the filter delays the output by RC = {lag} s"
            ),
            format!("α = {a}, RC = {rc} s, RC/Ts = {ratio}; o filtro atrasa a saída em RC = {lag} s"),
        );
        if !self.too_coarse() {
            return line;
        }
        let (ts, rc5) = (full(lang, self.ts), d4(lang, self.rc / 5.0));
        let warning = lang.pick(
            format!(
                "Warning: the sampling period Ts = {ts} s is more than RC/5 = {rc5} s (RC/Ts = \
                 {ratio}, expected ≥ 5): this digital filter behaves quite differently from the \
                 RC filter it imitates; use a lower cut-off or faster sampling"
            ),
            format!(
                "Atenção: o período de amostragem Ts = {ts} s é maior que RC/5 = {rc5} s (RC/Ts \
                 = {ratio}, esperado ≥ 5): este filtro digital se comporta bem diferente do \
                 filtro RC que imita; use uma frequência de corte menor ou amostragem mais rápida"
            ),
        );
        format!("{line}. {warning}")
    }
}

// ---------------------------------------------------------------------------------------
// The guess handles

/// The accessible label of a guess handle ("dead time handle").
pub fn handle_label(h: Handle, lang: Lang) -> &'static str {
    let (en, pt) = match h {
        Handle::FinalValue => ("final value handle", "alça do valor final"),
        Handle::DeadTime => ("dead time handle", "alça do tempo morto"),
        Handle::TimeConstant => ("time constant handle", "alça da constante de tempo"),
        Handle::FirstPeak => ("first peak handle", "alça do primeiro pico"),
    };
    lang.pick(en, pt)
}

/// What dragging a guess handle changes, for a tooltip.
pub fn handle_help(h: Handle, lang: Lang) -> &'static str {
    let (en, pt) = match h {
        Handle::FinalValue => (
            "Drag up or down: the final value sets the static gain Kp.",
            "Arraste para cima ou para baixo: o valor final define o ganho estático Kp.",
        ),
        Handle::DeadTime => (
            "Drag left or right: where the response starts sets the dead time Td.",
            "Arraste para a esquerda ou a direita: onde a resposta começa define o tempo morto \
             Td.",
        ),
        Handle::TimeConstant => (
            "Drag left or right: the 63.2 % time sets the time constants.",
            "Arraste para a esquerda ou a direita: o instante de 63,2 % define as constantes de \
             tempo.",
        ),
        Handle::FirstPeak => (
            "Drag: the peak's height sets ζ (overshoot), its time sets ωd (peak time).",
            "Arraste: a altura do pico define ζ (sobressinal), seu instante define ωd (tempo de \
             pico).",
        ),
    };
    lang.pick(en, pt)
}
