//! The least-squares mode's own words: the tabs, buttons, hints and notes of the app's ARX,
//! example, RLS, PRBS and validation views, in English and Brazilian Portuguese (the notes'
//! terms: mínimos quadrados, regressores, predição um passo à frente, simulação livre, fator
//! de esquecimento, estimação e validação, ruído). The tables' own labels are
//! [`degrau_ident::words::lsq`]'s, shared with the command line.
//!
//! A phrase with numbers or names in it is a template: each `{}` is filled in order by
//! [`crate::words::identify::fill`], so each language keeps its own word order.

use crate::lsq::designer::DesignError;
use degrau_words::Message;
use degrau_words::{Lang, Localize};

degrau_words::phrases! {
    /// The least-squares views' phrases.
    pub enum Phrase {
        ModeName => ("Least squares on samples", "Mínimos quadrados"),
        TabArx => ("ARX model", "Modelo ARX"),
        TabExample => ("Notes' example", "Exemplo das notas"),
        TabRls => ("Recursive (RLS)", "Recursivo (MQR)"),
        TabPrbs => ("PRBS test", "Ensaio PRBS"),
        TabValidation => ("Validation", "Validação"),
        NoRecord => (
            "No record: load a test in the Identify mode (or design a PRBS test and use it as the record).",
            "Nenhum registro: carregue um ensaio no modo Identificar (ou projete um ensaio PRBS e use-o como registro)."
        ),
        ArxEquation => (
            "y(k) + a1·y(k−1) + … + a_na·y(k−na) = b1·u(k−nk) + … + b_nb·u(k−nk−nb+1); θ = argmin J by QR.",
            "y(k) + a1·y(k−1) + … + a_na·y(k−na) = b1·u(k−nk) + … + b_nb·u(k−nk−nb+1); θ = argmin J por QR."
        ),
        OffsetInitial => ("deviations from the start", "desvios do início"),
        OffsetConstant => ("a constant regressor", "um regressor constante"),
        OffsetNone => ("as recorded", "como registrado"),
        Fit => ("Fit", "Ajustar"),
        PressFit => ("The orders changed: press Fit.", "As ordens mudaram: pressione Ajustar."),
        Estimate => ("Estimate θ", "Estimativa θ"),
        TwoFits => ("Prediction and simulation", "Predição e simulação"),
        WhichIsWhich => (
            "One-step prediction: each ŷ(k) from the measured past outputs. Free simulation: from the input alone, the model's own past outputs fed back. The simulation's fit % is what the model can do on its own; other tools often report the prediction's.",
            "Predição um passo à frente: cada ŷ(k) a partir das saídas passadas medidas. Simulação livre: só a partir da entrada, com as saídas passadas do próprio modelo. O ajuste % da simulação é o que o modelo faz sozinho; outras ferramentas costumam dar o da predição."
        ),
        D2c => ("The ARX model as G(s) (d2c)", "O modelo ARX como G(s) (d2c)"),
        ContinuousFit => ("The continuous fit (Identify mode)", "O ajuste contínuo (modo Identificar)"),
        ContinuousFitPercent => ("Its fit % on these samples: {}", "O seu ajuste % nestas amostras: {}"),
        NoContinuousFit => (
            "None yet: fit a model in the Identify mode to compare it here.",
            "Nenhum ainda: ajuste um modelo no modo Identificar para compará-lo aqui."
        ),
        AicNote => (
            "Every row on the same rows of Φ; the lowest AIC balances J against the number of parameters.",
            "Todas as linhas sobre as mesmas linhas de Φ; o menor AIC equilibra J e o número de parâmetros."
        ),
        PredictionShort => ("prediction", "predição"),
        SimulationShort => ("simulation", "simulação"),
        FitThese => ("Fit {}, {}, {}", "Ajustar {}, {}, {}"),
        Current => ("(shown)", "(exibido)"),
        PhiAndY => ("Regressor matrix Φ and Y", "Matriz de regressores Φ e Y"),
        FirstRows => ("The first {} of {} rows.", "As primeiras {} de {} linhas."),
        ArxPlot => (
            "Measured output, ARX prediction and simulation, continuous fit",
            "Saída medida, predição e simulação ARX, ajuste contínuo"
        ),
        Measured => ("measured", "medido"),
        Prediction => ("ARX one-step prediction", "predição ARX um passo à frente"),
        Simulation => ("ARX free simulation", "simulação livre ARX"),
        ContinuousCurve => ("continuous fit", "ajuste contínuo"),
        ExampleHeading => ("The notes' least-squares example", "O exemplo de mínimos quadrados das notas"),
        ExampleData => (
            "Three samples: u = [0, 1, 2], y = [0, 0.9, 2.1]; signals taken as 0 before k = 0. Choose a model:",
            "Três amostras: u = [0, 1, 2], y = [0, 0,9, 2,1]; sinais tomados como 0 antes de k = 0. Escolha um modelo:"
        ),
        ExampleSolve => (
            "θ = (Φ'Φ)⁻¹Φ'Y, computed by QR; J = Σe(k)² with E = Y − Φθ.",
            "θ = (Φ'Φ)⁻¹Φ'Y, calculado por QR; J = Σe(k)² com E = Y − Φθ."
        ),
        ExampleAll => ("The three models", "Os três modelos"),
        ExamplePlot => ("y(k) and each model's Φθ", "y(k) e o Φθ de cada modelo"),
        Model => ("Model", "Modelo"),
        Cost => ("Cost J = Σe(k)²", "Função custo J = Σe(k)²"),
        RlsEquations => (
            "Each sample: e_k = y(k) − φ'θ_{k−1};  P_k = (P_{k−1} − P_{k−1}φφ'P_{k−1}/(λ + φ'P_{k−1}φ))/λ;  θ_k = θ_{k−1} + P_kφ·e_k.",
            "A cada amostra: e_k = y(k) − φ'θ_{k−1};  P_k = (P_{k−1} − P_{k−1}φφ'P_{k−1}/(λ + φ'P_{k−1}φ))/λ;  θ_k = θ_{k−1} + P_kφ·e_k."
        ),
        Run => ("Run", "Executar"),
        Pause => ("Pause", "Pausar"),
        Step => ("Step", "Passo"),
        Reset => ("Reset", "Reiniciar"),
        RlsPress => (
            "Press Run to watch θ_k sample by sample, or Step for one sample.",
            "Pressione Executar para ver θ_k amostra a amostra, ou Passo para uma amostra."
        ),
        RlsProgress => ("{} of {} samples taken in.", "{} de {} amostras processadas."),
        Batch => ("batch θ", "θ em lote"),
        BatchOf => ("{} batch", "{} em lote"),
        RlsDone => (
            "Every sample taken in: with λ = 1 and a large α, θ_k ends at the batch solution.",
            "Todas as amostras processadas: com λ = 1 e α grande, θ_k termina na solução em lote."
        ),
        RlsPlot => (
            "Parameter trajectories θ_k (dashed: the batch solution)",
            "Trajetórias dos parâmetros θ_k (tracejado: a solução em lote)"
        ),
        PrbsNote => (
            "A maximal-length PRBS as MATLAB's idinput: each bit held for the clock period; one period is (2^n − 1) bits.",
            "Um PRBS de comprimento máximo como o idinput do MATLAB: cada bit mantido pelo período do relógio; um período tem (2^n − 1) bits."
        ),
        Length => ("Length N (samples)", "Comprimento N (amostras)"),
        Low => ("Low level", "Nível baixo"),
        High => ("High level", "Nível alto"),
        Periods => ("Periods", "Períodos"),
        PrbsModel => ("The process it is applied to", "O processo em que é aplicado"),
        FromCode => ("a procest model", "um modelo do procest"),
        FromDesign => ("the Design mode's G(s)", "a G(s) do modo Projeto"),
        ModelCode => ("Model code", "Código do modelo"),
        NoDesign => (
            "The Design mode has no valid G(s).",
            "O modo Projeto não tem uma G(s) válida."
        ),
        NoisePercent => ("Noise (% of the output's range)", "Ruído (% da faixa da saída)"),
        Seed => ("Seed", "Semente"),
        Register => (
            "Register of {} bits: {} bits per period × {} samples per bit = {} samples per period; {} samples in all.",
            "Registrador de {} bits: {} bits por período × {} amostras por bit = {} amostras por período; {} amostras no total."
        ),
        NoiseStd => ("Noise standard deviation: {}", "Desvio padrão do ruído: {}"),
        ExportCsv => ("Export CSV…", "Exportar CSV…"),
        UseAsRecord => ("Use as record", "Usar como registro"),
        Saved => ("Saved {}.", "Salvo {}."),
        NotSaved => ("Could not save {}: {}.", "Não foi possível salvar {}: {}."),
        Used => (
            "Loaded as the record of the Identify mode and of this mode.",
            "Carregado como o registro do modo Identificar e deste modo."
        ),
        NoDesignedTest => ("No test designed.", "Nenhum ensaio projetado."),
        PrbsInput => ("Input u (PRBS)", "Entrada u (PRBS)"),
        PrbsOutput => ("Simulated output y, with noise", "Saída simulada y, com ruído"),
        ValidationNote => (
            "Estimate on the samples before the split, validate on the samples after it (the simulation runs from the start, its state carried across).",
            "Estime com as amostras antes da divisão, valide com as amostras depois dela (a simulação corre desde o início, com o estado levado através da divisão)."
        ),
        SplitAt => ("Split by", "Dividir por"),
        SplitFraction => ("fraction of the samples", "fração das amostras"),
        SplitTime => ("time", "instante"),
        EstimationShare => ("Share used to estimate", "Fração usada na estimação"),
        SplitTimeField => ("Split time", "Instante da divisão"),
        ArxOrders => ("ARX orders: na = {}, nb = {}, nk = {}.", "Ordens ARX: na = {}, nb = {}, nk = {}."),
        LagsOutside => ("lags outside 99 %", "atrasos fora de 99 %"),
        RunsZ => ("runs z", "z das sequências"),
        ResidualStd => ("residual std", "desvio padrão dos resíduos"),
        ArxName => ("ARX model", "modelo ARX"),
        RlsName => ("RLS (final θ)", "MQR (θ final)"),
        ContinuousName => ("continuous {}", "contínuo {}"),
        ChecksNote => (
            "Fit % on each part; the residual checks on the validation part (for ARX and RLS the one-step prediction errors, white for a right model).",
            "Ajuste % em cada parte; as verificações dos resíduos na parte de validação (para ARX e MQR os erros de predição um passo à frente, brancos para um modelo certo)."
        ),
        ContinuousValidation => ("The continuous model", "O modelo contínuo"),
        ValidateContinuous => (
            "Fit the Identify mode's model on the estimation part",
            "Ajustar o modelo do modo Identificar na parte de estimação"
        ),
        Validating => ("Fitting on the estimation part…", "Ajustando na parte de estimação…"),
        Cancel => ("Cancel", "Cancelar"),
        ValidationPlot => (
            "Measured output and the models estimated before the split",
            "Saída medida e os modelos estimados antes da divisão"
        ),
        SimulationOf => ("{} simulation", "simulação {}"),
        SplitLine => ("split", "divisão"),
        TabAdvisor => ("Sampling advisor", "Escolha da amostragem"),
        AdvisorHeading => (
            "The notes' rules for the sampling period and the step's amplitude",
            "As regras das notas para o período de amostragem e a amplitude do degrau"
        ),
        NoAdvice => (
            "No record or model: load a test in the Identify mode; its model (the fit, or the guess read off the curve) gives the time scales.",
            "Nenhum registro ou modelo: carregue um ensaio no modo Identificar; o seu modelo (o ajuste, ou a estimativa lida na curva) dá as escalas de tempo."
        ),
        AdviceFromFit => ("Time scales of the fitted {}.", "Escalas de tempo do {} ajustado."),
        AdviceFromGuess => (
            "Time scales of the {} guess read off the curve (fit it in the Identify mode for better ones).",
            "Escalas de tempo da estimativa inicial {} lida na curva (ajuste-a no modo Identificar para melhores)."
        ),
        Rule => ("Rule", "Regra"),
        RecordValue => ("This record", "Este registro"),
        Holds => ("Holds", "Vale"),
        RuleTenth => ("h < 0.1·τmax (Kalman and Bertram)", "h < 0,1·τmax (Kalman e Bertram)"),
        RuleDeadTime => ("0.2 < h/θ < 1 (FOPTD)", "0,2 < h/θ < 1 (FOPTD, primeira ordem com tempo morto)"),
        RuleTimeConstant => (
            "0.01 < h/τ < 0.05 (Åström and Wittenmark)",
            "0,01 < h/τ < 0,05 (Åström e Wittenmark)"
        ),
        RuleSettling => ("t_s/15 < h < t_s/6 (Isermann)", "t_s/15 < h < t_s/6 (Isermann, t_s de 95 %)"),
        RuleAmplitude => ("step's effect / noise > 6", "efeito do degrau / ruído > 6"),
        TooSlow => ("no: sampled too slowly", "não: amostragem lenta demais"),
        TooFast => ("no: sampled too fast", "não: amostragem rápida demais"),
        TooSmall => ("no: the step is too small for the noise", "não: o degrau é pequeno demais para o ruído"),
        AdvisorNote => (
            "The effect is |K·Δu| (static gain times the largest input change); the noise is read from the output's first differences. Most lab records break one rule or another harmlessly; an effect under {} times the noise leaves the parameters uncertain.",
            "O efeito é |K·Δu| (ganho estático vezes a maior mudança da entrada); o ruído é lido das primeiras diferenças da saída. A maioria dos registros de laboratório viola uma ou outra regra sem dano; um efeito abaixo de {} vezes o ruído deixa os parâmetros incertos."
        ),
        AdvisorPlot => ("The record's samples", "As amostras do registro"),
        Samples => ("samples", "amostras"),
        BadSettings => (
            "Give at least one period and a noise level of 0 % or more.",
            "Informe ao menos um período e um nível de ruído de 0 % ou mais."
        ),
    }
}

impl Phrase {
    /// The phrase with its `{}` filled by `args`, in order.
    pub fn with(self, lang: Lang, args: &[String]) -> String {
        crate::words::identify::fill(self.get(lang), args)
    }
}

impl Localize for DesignError {
    fn text(&self, lang: Lang) -> String {
        match self {
            DesignError::Prbs(e) => e.text(lang),
            DesignError::Model(e) => e.text(lang),
            DesignError::Discrete(e) => e.text(lang),
            DesignError::NoDesignSystem => Phrase::NoDesign.get(lang).to_string(),
            DesignError::BadSettings => Phrase::BadSettings.get(lang).to_string(),
        }
    }
}

/// Every phrase, and an example of every [`DesignError`] of this mode's own.
pub fn messages() -> Vec<Message> {
    let mut all = Phrase::messages();
    for e in [DesignError::NoDesignSystem, DesignError::BadSettings] {
        all.push(Message::of(format!("DesignError::{e:?}"), &e));
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_languages_have_the_same_placeholders() {
        for p in Phrase::ALL {
            let count = |l: Lang| p.get(l).matches("{}").count();
            assert_eq!(count(Lang::En), count(Lang::Pt), "{p:?}");
        }
    }
}
