//! The words of least squares on samples (`crate::lsq::arx`, `rls`, `prbs`, `validation`)
//! and of discrete models (`degrau_lti::discrete`): the labels of the tables and the refusals,
//! in English and Brazilian Portuguese with the notes' terms (mínimos quadrados, regressores,
//! função custo, estimador recursivo, fator de esquecimento, sinal PRBS, validação, …).

use crate::lsq::arx::{Cost, LsqError, Regressor};
use crate::lsq::prbs::{MAX_ORDER, MIN_ORDER, PrbsError};
use crate::lsq::validation::{MIN_PART, ValidationError};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// The labels of the least-squares tables (CLI and app).
    pub enum LsqPhrase {
        ArxHeading => ("Least squares (ARX)", "Mínimos quadrados (ARX)"),
        RlsHeading => ("Recursive least squares", "Mínimos quadrados recursivo"),
        PrbsHeading => ("PRBS test signal", "Sinal de teste PRBS"),
        DiscreteHeading => ("Discrete model (ZOH)", "Modelo discreto (ZOH)"),
        ContinuousHeading => ("Continuous model", "Modelo contínuo"),
        Orders => ("Orders", "Ordens"),
        Parameter => ("Parameter", "Parâmetro"),
        Value => ("Value", "Valor"),
        StandardError => ("Standard error", "Desvio padrão"),
        Regressors => ("Regressors φ(k)", "Regressores φ(k)"),
        Rows => ("Rows of Φ", "Linhas de Φ"),
        Cost => ("Cost J = Σe(k)²", "Função custo J = Σe(k)²"),
        FitPrediction => ("Fit % (one-step prediction)", "Ajuste % (predição um passo à frente)"),
        FitSimulation => ("Fit % (free simulation)", "Ajuste % (simulação livre)"),
        Aic => ("AIC", "AIC (critério de Akaike)"),
        OperatingPoint => ("Operating point (u0, y0)", "Ponto de operação (u0, y0)"),
        Constant => ("Constant term", "Termo constante"),
        SamplingPeriod => ("Sampling period h (s)", "Período de amostragem h (s)"),
        Candidates => ("Orders by AIC (best first)", "Ordens pelo AIC (melhor primeiro)"),
        Forgetting => ("Forgetting factor λ", "Fator de esquecimento λ"),
        InitialCovariance => ("Initial covariance P0 = α·I", "Covariância inicial P0 = α·I"),
        FinalEstimate => ("Final estimate θ", "Estimativa final θ"),
        Estimation => ("Estimation", "Estimação"),
        Validation => ("Validation", "Validação"),
        ResidualsWhite => ("Residuals white", "Resíduos brancos"),
        Yes => ("yes", "sim"),
        No => ("no", "não"),
        RegisterOrder => ("Register length n (bits)", "Comprimento do registrador n (bits)"),
        Clock => ("Clock period (samples per bit)", "Período do relógio (amostras por bit)"),
        Period => ("Period (samples)", "Período (amostras)"),
        Levels => ("Levels", "Níveis"),
        Samples => ("Samples", "Amostras"),
        Poles => ("Poles", "Polos"),
        DeadTime => ("Dead time θ (s)", "Tempo morto θ (s)"),
        Delay => ("Delay nk (samples)", "Atraso nk (amostras)"),
        StaticGain => ("Static gain", "Ganho estático"),
        ExactFit => ("exact fit", "ajuste exato"),
        FitUndefined => (
            "undefined: the output is constant over these samples",
            "indefinido: a saída é constante nessas amostras"
        ),
        FitDiverges => (
            "none: the model's output diverges beyond double precision",
            "nenhum: a saída do modelo diverge além da precisão dupla"
        ),
        BeyondDouble => (
            "beyond double precision in the record's units",
            "além da precisão dupla nas unidades do registro"
        ),
    }
}

/// A fit % as text: the number, or in words why there is none (a constant output, a model
/// whose output diverges).
pub fn percent(x: f64, lang: Lang) -> String {
    if x.is_finite() {
        lang.num(x, 4)
    } else if x.is_nan() {
        LsqPhrase::FitUndefined.get(lang).into()
    } else {
        LsqPhrase::FitDiverges.get(lang).into()
    }
}

/// J as text: the number, or its order of magnitude when it lies beyond double precision.
pub fn cost(c: &Cost, lang: Lang) -> String {
    match c.value() {
        Some(j) => lang.num(j, 6),
        None => format!(
            "{} ({})",
            lang.power_of_ten(c.log10(), 6),
            LsqPhrase::BeyondDouble.get(lang)
        ),
    }
}

/// A regressor as the notes write it: `1`, `−y(k−1)`, `u(k)`, `u(k−2)`.
pub fn regressor_symbol(r: Regressor) -> String {
    let lagged = |name: &str, lag: usize| {
        if lag == 0 {
            format!("{name}(k)")
        } else {
            format!("{name}(k−{lag})")
        }
    };
    match r {
        Regressor::Constant => "1".into(),
        Regressor::Output(i) => format!("−{}", lagged("y", i)),
        Regressor::Input(j) => lagged("u", j),
    }
}

/// A parameter's name for a regressor: `a1`, `b2`, `c` (the constant); `b` indices count
/// from 1 after the delay nk, as MATLAB's.
pub fn parameter_name(r: Regressor, nk: usize) -> String {
    match r {
        Regressor::Constant => "c".into(),
        Regressor::Output(i) => format!("a{i}"),
        Regressor::Input(j) => format!("b{}", j + 1 - nk.min(j)),
    }
}

impl Localize for LsqError {
    fn text(&self, lang: Lang) -> String {
        match self {
            LsqError::LengthMismatch { u, y } => lang.pick(
                format!("the input has {u} samples and the output {y}: they must match"),
                format!("a entrada tem {u} amostras e a saída {y}: devem ser iguais"),
            ),
            LsqError::NonFinite => lang
                .pick(
                    "a sample is not a finite number",
                    "uma amostra não é um número finito",
                )
                .into(),
            LsqError::BadRegressors => lang
                .pick(
                    "no regressor to estimate (na + nb must be at least 1, and y(k) cannot explain itself)",
                    "nenhum regressor a estimar (na + nb deve ser ao menos 1, e y(k) não pode explicar a si mesma)",
                )
                .into(),
            LsqError::TooFewSamples { rows, parameters } => lang.pick(
                format!(
                    "{rows} rows of Φ for {parameters} parameters: use a longer record or lower orders"
                ),
                format!(
                    "{rows} linhas de Φ para {parameters} parâmetros: use um registro mais longo ou ordens menores"
                ),
            ),
            LsqError::Singular { index } => {
                let i = index + 1;
                lang.pick(
                    format!(
                        "Φ'Φ is singular: regressor {i} repeats the ones before it (the input does not excite enough, or the orders are too high)"
                    ),
                    format!(
                        "Φ'Φ é singular: o regressor {i} repete os anteriores (a entrada não excita o suficiente, ou as ordens são altas demais)"
                    ),
                )
            }
            LsqError::ConstantOutput => lang
                .pick(
                    "the output never changes: there is nothing to identify, and no fit % to give",
                    "a saída nunca muda: não há o que identificar, nem ajuste % a dar",
                )
                .into(),
            LsqError::LagBeyondRecord { lag, samples } => lang.pick(
                format!(
                    "the longest lag, max(na, nk + nb − 1) = {lag} samples, leaves no row of Φ in a record of {samples} samples: use a smaller delay or lower orders"
                ),
                format!(
                    "o maior atraso, max(na, nk + nb − 1) = {lag} amostras, não deixa nenhuma linha de Φ num registro de {samples} amostras: use um atraso menor ou ordens menores"
                ),
            ),
            LsqError::Unrepresentable { regressor, log10 } => {
                let r = regressor_symbol(*regressor);
                let e = lang.localize_number(&format!("{log10:.1}"));
                lang.pick(
                    format!(
                        "the parameter of {r} (or its standard error) is about 1e{e} in the record's units, beyond double precision: express u or y in other units"
                    ),
                    format!(
                        "o parâmetro de {r} (ou seu desvio padrão) é cerca de 1e{e} nas unidades do registro, além da precisão dupla: expresse u ou y em outras unidades"
                    ),
                )
            }
            LsqError::BadForgetting(l) => {
                let l = lang.num(*l, 6);
                lang.pick(
                    format!("the forgetting factor λ = {l} must be in (0, 1]"),
                    format!("o fator de esquecimento λ = {l} deve estar em (0, 1]"),
                )
            }
            LsqError::BadCovariance(a) => {
                let a = lang.num(*a, 6);
                lang.pick(
                    format!("the initial covariance α = {a} must be a positive number"),
                    format!("a covariância inicial α = {a} deve ser um número positivo"),
                )
            }
            LsqError::CovarianceOverflow { alpha, lambda, row } => {
                let (a, l) = (lang.num(*alpha, 6), lang.num(*lambda, 6));
                lang.pick(
                    format!(
                        "the covariance P left double precision's range at row {row} of Φ (P₀ = α·I with α = {a}, divided by λ = {l} at every row): take λ closer to 1 or a smaller α"
                    ),
                    format!(
                        "a covariância P saiu da faixa da precisão dupla na linha {row} de Φ (P₀ = α·I com α = {a}, dividida por λ = {l} a cada linha): use λ mais perto de 1 ou um α menor"
                    ),
                )
            }
            LsqError::BadInitialTheta { expected, got } => lang.pick(
                format!("the initial θ has {got} values; the model has {expected} parameters"),
                format!("o θ inicial tem {got} valores; o modelo tem {expected} parâmetros"),
            ),
            LsqError::BadSplit => lang.pick(
                format!(
                    "the split must leave at least {MIN_PART} samples for estimation and {MIN_PART} for validation (a fraction between 0 and 1, or a time inside the record)"
                ),
                format!(
                    "a divisão deve deixar ao menos {MIN_PART} amostras para estimação e {MIN_PART} para validação (uma fração entre 0 e 1, ou um instante dentro do registro)"
                ),
            ),
            LsqError::Discrete(e) => e.text(lang),
        }
    }
}

impl Localize for PrbsError {
    fn text(&self, lang: Lang) -> String {
        match self {
            PrbsError::BadOrder(n) => lang.pick(
                format!("a register of {n} bits is not offered: use {MIN_ORDER} to {MAX_ORDER}"),
                format!(
                    "um registrador de {n} bits não é oferecido: use de {MIN_ORDER} a {MAX_ORDER}"
                ),
            ),
            PrbsError::BadClock => lang
                .pick(
                    "the clock period must be at least 1 sample",
                    "o período do relógio deve ser ao menos 1 amostra",
                )
                .into(),
            PrbsError::BadLevels { low, high } => {
                let (lo, hi) = (lang.num(*low, 6), lang.num(*high, 6));
                lang.pick(
                    format!(
                        "the levels {lo} and {hi} must be two different finite numbers, each 0 or at least 2.2e-308 in size (the smallest normal double)"
                    ),
                    format!(
                        "os níveis {lo} e {hi} devem ser dois números finitos diferentes, cada um 0 ou de tamanho ao menos 2,2e-308 (o menor double normal)"
                    ),
                )
            }
            PrbsError::BadLength(n) => lang.pick(
                format!(
                    "{n} samples cannot be generated: at least 1, at most 10 000 000, and covered by a register of at most {MAX_ORDER} bits"
                ),
                format!(
                    "não é possível gerar {n} amostras: ao menos 1, no máximo 10 000 000, e cobertas por um registrador de no máximo {MAX_ORDER} bits"
                ),
            ),
            PrbsError::BadSimulation => lang
                .pick(
                    "the sampling period must be positive and the noise level not negative",
                    "o período de amostragem deve ser positivo e o nível de ruído não negativo",
                )
                .into(),
            PrbsError::TimeBeyondRange { samples, ts } => {
                let ts = lang.num(*ts, 6);
                lang.pick(
                    format!(
                        "{samples} samples every {ts} s end beyond double precision (about 1.8e308 s): use a smaller sampling period"
                    ),
                    format!(
                        "{samples} amostras a cada {ts} s terminam além da precisão dupla (cerca de 1,8e308 s): use um período de amostragem menor"
                    ),
                )
            }
            PrbsError::OutputBeyondRange => lang
                .pick(
                    "the simulated output goes beyond double precision (about 1.8e308): use a smaller gain, levels or --noise",
                    "a saída simulada vai além da precisão dupla (cerca de 1,8e308): use ganho, níveis ou --noise menores",
                )
                .into(),
            PrbsError::Model(e) => e.text(lang),
        }
    }
}

impl Localize for ValidationError {
    fn text(&self, lang: Lang) -> String {
        match self {
            ValidationError::Lsq(e) => e.text(lang),
            ValidationError::Fit(e) => e.text(lang),
        }
    }
}

/// An example of every phrase and error, for the test of both languages.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let mut all = LsqPhrase::messages();
    let lsq = [
        LsqError::LengthMismatch { u: 3, y: 4 },
        LsqError::NonFinite,
        LsqError::BadRegressors,
        LsqError::TooFewSamples {
            rows: 2,
            parameters: 4,
        },
        LsqError::Singular { index: 1 },
        LsqError::ConstantOutput,
        LsqError::LagBeyondRecord {
            lag: 100_000_002,
            samples: 762,
        },
        LsqError::Unrepresentable {
            regressor: Regressor::Input(1),
            log10: 600.3,
        },
        LsqError::BadForgetting(1.5),
        LsqError::BadCovariance(-1.0),
        LsqError::CovarianceOverflow {
            alpha: 1e6,
            lambda: 1e-300,
            row: 2,
        },
        LsqError::BadInitialTheta {
            expected: 3,
            got: 2,
        },
        LsqError::BadSplit,
    ];
    let prbs = [
        PrbsError::BadOrder(40),
        PrbsError::BadClock,
        PrbsError::BadLevels {
            low: 1.0,
            high: 1.0,
        },
        PrbsError::BadLength(0),
        PrbsError::BadSimulation,
        PrbsError::TimeBeyondRange {
            samples: 10,
            ts: 1e308,
        },
        PrbsError::OutputBeyondRange,
    ];
    all.extend(
        lsq.iter()
            .map(|e| Message::of(format!("lsq::LsqError::{e:?}"), e)),
    );
    all.extend(
        prbs.iter()
            .map(|e| Message::of(format!("lsq::PrbsError::{e:?}"), e)),
    );
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regressors_read_as_the_notes_write_them() {
        assert_eq!(regressor_symbol(Regressor::Output(2)), "−y(k−2)");
        assert_eq!(regressor_symbol(Regressor::Input(0)), "u(k)");
        assert_eq!(regressor_symbol(Regressor::Constant), "1");
        assert_eq!(parameter_name(Regressor::Input(3), 2), "b2");
        assert_eq!(parameter_name(Regressor::Output(1), 1), "a1");
    }
}
