//! The Identify mode's own words: every label, button, hint and status of the app's
//! identification views, in English and Brazilian Portuguese (the glossary's terms: ensaio ao
//! degrau, ponto de operação, período de amostragem, estimativa inicial, ajuste, resíduos,
//! filtro passa-baixa, frequência de corte, estrutura do modelo, função de custo, …).
//!
//! A phrase with numbers or names in it is a template: each `{}` is filled in order by
//! [`fill`], so each language keeps its own word order.

use degrau_words::{Lang, Message};

degrau_words::phrases! {
    /// The identification views' phrases.
    pub enum Phrase {
        StepTest => ("Step test", "Ensaio ao degrau"),
        FileField => ("Step test file", "Arquivo do ensaio ao degrau"),
        Load => ("Load", "Carregar"),
        Example => ("Example", "Exemplo"),
        ExampleHelp => (
            "The LECI step test of the course notes",
            "O ensaio ao degrau do LECI, das notas de aula"
        ),
        Open => ("Open…", "Abrir…"),
        HowToRead => ("How to read the file", "Como ler o arquivo"),
        TimeColumn => ("Time column", "Coluna de tempo"),
        OutputColumn => ("Output column", "Coluna de saída"),
        InputColumn => ("Input column", "Coluna de entrada"),
        SamplingPeriod => ("Sampling period (s)", "Período de amostragem (s)"),
        InitialInput => ("Input before the record", "Entrada antes do registro"),
        InputFile => ("Input's own file", "Arquivo próprio da entrada"),
        InputFileHint => (
            "optional: a file of time and input, joined on time",
            "opcional: um arquivo de tempo e entrada, unido pelo tempo"
        ),
        ColumnHint => ("automatic; or a name or a number", "automática; ou um nome ou um número"),
        DetectedColumn => ("read: {}", "lida: {}"),
        GiveSamplingPeriod => (
            "give it (files without a time column)",
            "informar (arquivos sem coluna de tempo)"
        ),
        GiveInitialInput => (
            "give it (the step came at the first sample)",
            "informar (o degrau veio na primeira amostra)"
        ),
        DropOrPaste => (
            "Drop a file on the window, or paste two or three columns (Ctrl+V).",
            "Solte um arquivo na janela, ou cole duas ou três colunas (Ctrl+V)."
        ),
        LoadedFrom => ("Loaded {} samples from {}.", "{} amostras carregadas de {}."),
        PastedData => ("pasted data", "dados colados"),
        TheExample => ("the LECI example of the course notes", "o exemplo do LECI das notas de aula"),
        LoadedExample => (
            "Loaded the LECI example of the course notes: {} samples, a step of Δu = {} at t0 = {} s from y0 = {}.",
            "Exemplo do LECI das notas de aula carregado: {} amostras, um degrau de Δu = {} em t0 = {} s a partir de y0 = {}."
        ),
        StepMissing => (
            "{}. Set t0 and Δu below (now t0 = {}, Δu = 1).",
            "{}. Defina t0 e Δu abaixo (agora t0 = {}, Δu = 1)."
        ),
        KeptChoices => (
            "Read with the choices typed for it: {}.",
            "Lido com as escolhas digitadas para ele: {}."
        ),
        ClearedChoices => (
            "The choices made on the previous file were not carried over ({}): this file is read with its own columns.",
            "As escolhas feitas no arquivo anterior não foram mantidas ({}): este arquivo é lido com as suas próprias colunas."
        ),
        NotLoaded => ("Not loaded ({}): {}.", "Não carregado ({}): {}."),
        PasteRefused => (
            "The pasted text is not a step test: {}.",
            "O texto colado não é um ensaio ao degrau: {}."
        ),
        ExampleRefused => ("The example did not load: {}.", "O exemplo não carregou: {}."),
        KeptBefore => ("What was loaded before is kept.", "O que estava carregado antes foi mantido."),
        StepTime => ("Step time t0 (s)", "Instante do degrau t0 (s)"),
        StepSize => ("Step size Δu", "Amplitude do degrau Δu"),
        OperatingPoint => ("Operating point Y0", "Ponto de operação Y0"),
        MeanBefore => ("mean before the step", "média antes do degrau"),
        Estimate => ("estimate", "estimar"),
        Typed => ("typed", "digitado"),
        TypedY0 => ("Y0 held at", "Y0 mantido em"),
        HeldAt => ("Y0 held at {}.", "Y0 mantido em {}."),
        NoSampleBefore => (
            "No sample before the step: Y0 is estimated with the other parameters instead.",
            "Nenhuma amostra antes do degrau: Y0 é estimado com os demais parâmetros."
        ),
        EstimatedY0 => (
            "Y0 is estimated with the other parameters.",
            "Y0 é estimado com os demais parâmetros."
        ),
        Window => ("Window (s)", "Janela (s)"),
        KeepOnly => ("keep only", "manter só"),
        WindowFrom => ("from", "de"),
        WindowTo => ("to", "até"),
        Filter => ("Low-pass filter", "Filtro passa-baixa"),
        FilterOn => ("first order (EWMA)", "primeira ordem (EWMA)"),
        CutOff => ("cut-off (Hz)", "frequência de corte (Hz)"),
        ModelStructure => ("Model structure", "Estrutura do modelo"),
        Drift => ("drift", "deriva"),
        DriftHelp => (
            "Add a linear drift term Drift·(t − t0)",
            "Acrescenta um termo de deriva linear Drift·(t − t0)"
        ),
        AutoGuess => ("Automatic guess", "Estimativa inicial automática"),
        AutoGuessHelp => ("Read the guesses off the curve again", "Lê de novo as estimativas na curva"),
        GuessOf => ("{} guess", "{} (estimativa inicial)"),
        FittedStartOf => ("{} fitted (the next fit starts here)", "{} ajustado (o próximo ajuste parte daqui)"),
        Multistart => ("multi-start", "vários inícios"),
        MultistartHelp => (
            "Run from the guess and from spread-out starts, keep the best result that is not an alias",
            "Parte da estimativa inicial e de inícios espalhados, e fica com o melhor resultado que não é um alias"
        ),
        Starts => ("starts", "inícios"),
        Fit => ("Fit", "Ajustar"),
        Cancel => ("Cancel", "Cancelar"),
        Fitting => ("Fitting…", "Ajustando…"),
        Cancelling => ("Cancelling…", "Cancelando…"),
        FitProgress => (
            "start {}/{} · iteration {} · MSE {} (best {})",
            "início {}/{} · iteração {} · MSE {} (melhor {})"
        ),
        FitDone => ("{} · {} start(s), {} iterations", "{} · {} início(s), {} iterações"),
        FromDiagnosis => ("from the diagnosis: {} · {} iterations", "do diagnóstico: {} · {} iterações"),
        FitFailed => ("The fit did not run: {}", "O ajuste não rodou: {}"),
        Fitted => ("Fitted {}", "{} ajustado"),
        Parameter => ("Parameter", "Parâmetro"),
        Value => ("Value", "Valor"),
        Interval95 => ("95 % interval", "Intervalo de 95 %"),
        NoInterval => ("none", "nenhum"),
        Warning => ("Warning: {}", "Aviso: {}"),
        ShowOnSPlane => ("Show on the s-plane", "Mostrar no plano s"),
        CostLandscape => ("Cost landscape…", "Mapa da função de custo…"),
        CopyMatlab => ("Copy as MATLAB", "Copiar como MATLAB"),
        CopyPython => ("Copy as python-control", "Copiar como python-control"),
        CopyHelp => (
            "The fitted transfer function as code, to the clipboard",
            "A função de transferência ajustada como código, para a área de transferência"
        ),
        WhatIsWrong => ("What does the model get wrong?", "O que o modelo erra?"),
        ExtendOnce => ("Extend with the leading cause", "Estender pela causa principal"),
        ExtendOnceHelp => (
            "Name what the model gets wrong and extend it once",
            "Diz o que o modelo erra e o estende uma vez"
        ),
        WholeLoop => ("Run the whole loop", "Rodar o ciclo inteiro"),
        WholeLoopHelp => (
            "Extend until no extension pays for itself",
            "Estende até que nenhuma extensão compense"
        ),
        RunningLoop => ("Running the loop…", "Rodando o ciclo…"),
        LookingForCause => ("Looking for the leading cause…", "Procurando a causa principal…"),
        DiagnoseProgress => (
            "extension {} of at most {} · {} fits so far",
            "extensão {} de no máximo {} · {} ajustes até agora"
        ),
        RowHelp => ("Show this model's curve and residuals", "Mostra a curva e os resíduos deste modelo"),
        CopyTable => ("Copy the table", "Copiar a tabela"),
        NothingLoaded => (
            "Load a step test: File → Open a step test…, type its path on the right, drop it here, paste columns, or press Example for the LECI test of the course notes.",
            "Carregue um ensaio ao degrau: Arquivo → Abrir um ensaio ao degrau…, digite o caminho à direita, solte-o aqui, cole colunas, ou aperte Exemplo para o ensaio do LECI das notas de aula."
        ),
        NothingToShow => (
            "The chosen window and filter leave nothing to show.",
            "A janela e o filtro escolhidos não deixam nada para mostrar."
        ),
        MeasuredAndModel => ("Measured output and model", "Saída medida e modelo"),
        PlotName => ("plot of the measured output", "gráfico da saída medida"),
        Measured => ("measured", "medido"),
        StepAt => ("step at t0 = {} s", "degrau em t0 = {} s"),
        Evidence => ("evidence", "evidência"),
        ModelFitting => ("model (fitting…)", "modelo (ajustando…)"),
        ModelFitted => ("fitted model", "modelo ajustado"),
        ModelGuess => ("model (guess)", "modelo (estimativa inicial)"),
        ModelOfRow => ("model {} of the chain", "modelo {} da cadeia"),
        Residuals => ("Residuals y − ŷ", "Resíduos y − ŷ"),
        Residual => ("residual", "resíduo"),
        ZeroLine => ("no error", "erro nulo"),
        MeasuredMarkers => ("Measured characteristics:", "Características medidas:"),
        Rise => ("Rise", "Subida"),
        Peak => ("Peak", "Pico"),
        Settling => ("Settling", "Acomodação"),
        FinalLevel => ("Final level", "Valor final"),
        SettlingBand => ("±{} % band", "faixa de ±{} %"),
        OvershootWithinNoise => (
            "overshoot within the noise (±{})",
            "sobressinal dentro do ruído (±{})"
        ),
        FinalValueHandle => ("final value handle", "alça do valor final"),
        DeadTimeHandle => ("dead time handle", "alça do tempo morto"),
        TimeConstantHandle => ("time constant handle", "alça da constante de tempo"),
        FirstPeakHandle => ("first peak handle", "alça do primeiro pico"),
        FinalValueHelp => (
            "Drag up or down: the final value sets the static gain Kp.",
            "Arraste para cima ou para baixo: o valor final define o ganho estático Kp."
        ),
        DeadTimeHelp => (
            "Drag left or right: where the response starts sets the dead time Td.",
            "Arraste para os lados: onde a resposta começa define o tempo morto Td."
        ),
        TimeConstantHelp => (
            "Drag left or right: the 63.2 % time sets the time constants.",
            "Arraste para os lados: o instante de 63,2 % define as constantes de tempo."
        ),
        FirstPeakHelp => (
            "Drag: the peak's height sets ζ (overshoot), its time sets ωd (peak time).",
            "Arraste: a altura do pico define ζ (sobressinal), o instante define ωd (tempo de pico)."
        ),
        StepLine => ("step time line", "linha do instante do degrau"),
        StepLineHelp => ("Drag left or right: the step time t0.", "Arraste para os lados: o instante do degrau t0."),
        Drive => ("Input that drove the test", "Entrada que excitou o ensaio"),
        DriveMeasured => ("measured input", "entrada medida"),
        DriveStep => ("one ideal step", "um degrau ideal"),
        DriveHelp => (
            "The measured input: the model is driven by the input column, every change of it used. One ideal step: Δu at t0, typed (the model of a single step test).",
            "Entrada medida: o modelo é excitado pela coluna de entrada, com todas as suas mudanças. Um degrau ideal: Δu em t0, digitados (o modelo de um único ensaio ao degrau)."
        ),
        BetweenSamples => ("Between samples", "Entre amostras"),
        HoldZoh => ("held (zero-order hold)", "mantida (segurador de ordem zero)"),
        HoldFoh => ("straight line (first-order hold)", "reta (segurador de primeira ordem)"),
        HoldHelp => (
            "Held: a logged actuator command, constant until the next sample. Straight line: an analog input that was sampled.",
            "Mantida: um comando de atuador registrado, constante até a próxima amostra. Reta: uma entrada analógica que foi amostrada."
        ),
        NoInputToUse => (
            "The file has no input that changes: one ideal step is the only choice.",
            "O arquivo não tem entrada que muda: um degrau ideal é a única escolha."
        ),
        ChangesUsed => ("{} input changes used.", "{} mudanças da entrada usadas."),
        OneChangeUsed => ("1 input change used.", "1 mudança da entrada usada."),
        ChangeLead => (
            "Each change may have come up to {} s before the sample that first shows it: the fit estimates when (Ta, or Td down to −{} s).",
            "Cada mudança pode ter ocorrido até {} s antes da amostra que primeiro a mostra: o ajuste estima quando (Ta, ou Td até −{} s)."
        ),
        InputPlot => ("Input u(t) as the model sees it", "Entrada u(t) como o modelo a vê"),
        InputCurve => ("input", "entrada"),
        ChangeMark => ("change {} at t = {} s (Δu = {})", "mudança {} em t = {} s (Δu = {})"),
        ChangeSpan => ("change {} happened in ({} s, {} s]", "a mudança {} ocorreu em ({} s, {} s]"),
        ChangeInstantExact => ("change {} at t = {} s, an exact instant", "mudança {} em t = {} s, um instante exato"),
        StepWindow => ("step {}", "degrau {}"),
        StepWindowLabel => ("step {} window, {} s to {} s", "janela do degrau {}, de {} s a {} s"),
        PerStep => ("Each step on its own", "Cada degrau isolado"),
        PerStepHelp => (
            "Each input change fitted on its own window, beside the joint fit: a linear process gives the same values within their intervals.",
            "Cada mudança da entrada ajustada na sua própria janela, ao lado do ajuste conjunto: um processo linear dá os mesmos valores dentro dos seus intervalos."
        ),
        FitEachStep => ("Fit each step", "Ajustar cada degrau"),
        PerStepRunning => ("Fitting step {} of {}…", "Ajustando o degrau {} de {}…"),
        PerStepCancelled => ("The per-step fits were cancelled.", "Os ajustes por degrau foram cancelados."),
        ChangeHeader => ("Change", "Mudança"),
        FromHeader => ("from", "a partir de"),
        JointFit => ("joint fit", "ajuste conjunto"),
        StepRow => ("step {}", "degrau {}"),
        StepRowMoving => ("step {} (output still moving)", "degrau {} (saída ainda em movimento)"),
        NoStepFit => ("no fit: {}", "sem ajuste: {}"),
        StepDiffers => (
            "Step {} (t = {} s) gives {} = {}, beyond the joint fit's {}: beyond both 95 % intervals and what the record resolves. A first hint that the process is not linear.",
            "O degrau {} (t = {} s) dá {} = {}, além do {} do ajuste conjunto: além dos dois intervalos de 95 % e do que o registro resolve. Um primeiro indício de que o processo não é linear."
        ),
        StepNotHeld => (
            "Step {} (t = {} s) was held less than 3 time constants beyond its dead time: its own values rest on the tail of the response before it, and are not compared.",
            "O degrau {} (t = {} s) foi mantido menos de 3 constantes de tempo além do seu tempo morto: os seus valores dependem da cauda da resposta anterior e não são comparados."
        ),
        StepsAgree => (
            "Every step agrees with the joint fit, within the 95 % intervals or within what the record resolves (5 %, and a sampling period for Td): nothing here says the process is not linear.",
            "Todos os degraus concordam com o ajuste conjunto, dentro dos intervalos de 95 % ou do que o registro resolve (5 %, e um período de amostragem para Td): nada aqui indica que o processo não é linear."
        ),
        StepsUnknown => (
            "Some values have no interval: whether the steps agree cannot be said from them.",
            "Alguns valores não têm intervalo: não dá para dizer por eles se os degraus concordam."
        ),
        HandlesOnLargest => (
            "The handles act on the largest change (step {}, t = {} s), as if it were one step from where the model stands then.",
            "As alças agem sobre a maior mudança (degrau {}, t = {} s), como se fosse um degrau a partir de onde o modelo está nesse instante."
        ),
        DiagnosisCancelled => ("The diagnosis was cancelled.", "O diagnóstico foi cancelado."),
        LandscapeTitle => ("Cost landscape", "Mapa da função de custo"),
        FitFirst => (
            "Fit a model first: the landscape is drawn around the fit.",
            "Ajuste um modelo antes: o mapa é desenhado em torno do ajuste."
        ),
        Spread => ("spread ×", "abrangência ×"),
        RowOf => ("row {} of {}", "linha {} de {}"),
        Compute => ("Compute", "Calcular"),
        LandscapeSummary => (
            "log10 MSE over {} × {}; {} local minima on the grid; lowest MSE on the grid {}",
            "log10 do MSE sobre {} × {}; {} mínimos locais na grade; menor MSE na grade {}"
        ),
        OptimiserPath => ("optimiser path", "caminho do otimizador"),
        LocalMinima => ("local minima", "mínimos locais"),
        TheFit => ("fit", "ajuste"),
    }
}

/// `template` with each `{}` replaced by the next of `args` (in order; missing ones empty).
pub fn fill(template: &str, args: &[String]) -> String {
    let mut out = String::with_capacity(template.len() + 16);
    let mut args = args.iter();
    let mut pieces = template.split("{}");
    if let Some(first) = pieces.next() {
        out.push_str(first);
    }
    for piece in pieces {
        if let Some(a) = args.next() {
            out.push_str(a);
        }
        out.push_str(piece);
    }
    out
}

impl Phrase {
    /// The template in `lang`, filled with `args`.
    pub fn with(self, lang: Lang, args: &[String]) -> String {
        fill(self.get(lang), args)
    }
}

/// Every phrase, for [`super::every_message`].
pub fn messages() -> Vec<Message> {
    Phrase::messages()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn templates_fill_in_order() {
        let args = ["35".to_string(), "x.csv".to_string()];
        assert_eq!(
            Phrase::LoadedFrom.with(Lang::En, &args),
            "Loaded 35 samples from x.csv."
        );
        assert_eq!(
            Phrase::LoadedFrom.with(Lang::Pt, &args),
            "35 amostras carregadas de x.csv."
        );
        assert_eq!(fill("{} and {}", &["a".into()]), "a and ");
    }

    #[test]
    fn both_languages_have_the_same_placeholders() {
        for p in Phrase::ALL {
            let count = |l: Lang| p.get(l).matches("{}").count();
            assert_eq!(count(Lang::En), count(Lang::Pt), "{p:?}");
        }
    }
}
