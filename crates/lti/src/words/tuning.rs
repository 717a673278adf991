//! The words of tuning and of the loop's frequency facts: the rules' names, their formulas
//! written out with their sources, a model refused ([`ModelError`]), why a rule gives no
//! controller ([`NotApplicable`]) and why the closed-loop roots could not be counted
//! ([`StabilityError`]), in English and Brazilian Portuguese (sintonia, ganho último,
//! período último, tempo integral, tempo derivativo, …).

use crate::control::Action;
use crate::control::frequency::StabilityError;
use crate::control::tuning::{Formula, ModelError, ModelKind, NotApplicable, Rule};

#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

impl Localize for Rule {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            Rule::ZieglerNicholsOpen => (
                "Ziegler–Nichols (reaction curve)",
                "Ziegler–Nichols (curva de reação)",
            ),
            Rule::ZieglerNicholsUltimate => (
                "Ziegler–Nichols (ultimate cycle)",
                "Ziegler–Nichols (ciclo último)",
            ),
            Rule::CohenCoon => (
                "Cohen–Coon (reaction curve)",
                "Cohen–Coon (curva de reação)",
            ),
            Rule::Imc => (
                "IMC (internal model control)",
                "IMC (controle por modelo interno)",
            ),
            Rule::Simc => ("SIMC (Skogestad's IMC)", "SIMC (IMC de Skogestad)"),
            Rule::Amigo => (
                "AMIGO (Åström–Hägglund's approximate M-constrained integral gain optimisation)",
                "AMIGO (otimização aproximada do ganho integral com restrição de M, de Åström–Hägglund)",
            ),
            Rule::Lambda => ("Lambda tuning", "Sintonia lambda"),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for ModelKind {
    fn text(&self, lang: Lang) -> String {
        let (en, pt) = match self {
            ModelKind::Foptd => (
                "first order with dead time",
                "primeira ordem com tempo morto",
            ),
            ModelKind::Soptd => (
                "second order with dead time",
                "segunda ordem com tempo morto",
            ),
        };
        lang.pick(en, pt).to_string()
    }
}

impl Localize for ModelError {
    fn text(&self, lang: Lang) -> String {
        let n = |x: f64| lang.num(x, 6);
        match *self {
            ModelError::Gain(x) => lang.pick(
                format!(
                    "the process gain K must be a finite number other than 0, not {}",
                    n(x)
                ),
                format!(
                    "o ganho do processo K deve ser um número finito diferente de 0, não {}",
                    n(x)
                ),
            ),
            ModelError::TimeConstant(x) => lang.pick(
                format!(
                    "a time constant must be a positive number of seconds, not {}",
                    n(x)
                ),
                format!(
                    "uma constante de tempo deve ser um número positivo de segundos, não {}",
                    n(x)
                ),
            ),
            ModelError::DeadTime(x) => lang.pick(
                format!(
                    "the dead time θ must be 0 or a positive number of seconds, not {}",
                    n(x)
                ),
                format!(
                    "o tempo morto θ deve ser 0 ou um número positivo de segundos, não {}",
                    n(x)
                ),
            ),
        }
    }
}

impl Localize for NotApplicable {
    fn text(&self, lang: Lang) -> String {
        match *self {
            NotApplicable::NoAction { rule, action } => lang.pick(
                format!("{} gives no {} controller", rule.text(lang), action_name(action)),
                format!("{} não dá um controlador {}", rule.text(lang), action_name(action)),
            ),
            NotApplicable::FirstOrderOnly { rule } => lang.pick(
                format!("{} is defined for a first-order model with dead time", rule.text(lang)),
                format!("{} é definido para um modelo de primeira ordem com tempo morto", rule.text(lang)),
            ),
            NotApplicable::NeedsDeadTime { rule } => lang.pick(
                format!("{} needs a dead time θ > 0 (its formulas divide by θ)", rule.text(lang)),
                format!("{} precisa de um tempo morto θ > 0 (suas fórmulas dividem por θ)", rule.text(lang)),
            ),
            NotApplicable::SimcFirstOrderPid => lang.pick(
                "SIMC gives a PI for a first-order model: its derivative time is the second time constant τ2".into(),
                "o SIMC dá um PI para um modelo de primeira ordem: seu tempo derivativo é a segunda constante de tempo τ2".into(),
            ),
            NotApplicable::ImcSecondOrderPi => lang.pick(
                "IMC gives a PID for a second-order model (Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2) cancel both lags); for a PI, reduce the model to first order first (SIMC's half rule does)".into(),
                "o IMC dá um PID para um modelo de segunda ordem (Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2) cancelam os dois atrasos); para um PI, reduza antes o modelo à primeira ordem (a regra da metade do SIMC faz isso)".into(),
            ),
            NotApplicable::LambdaMismatch { .. } => lang.pick(
                "Lambda tuning gives a PI for a first-order model and a PID for a second-order one".into(),
                "a sintonia lambda dá um PI para um modelo de primeira ordem e um PID para um de segunda ordem".into(),
            ),
            NotApplicable::NoPhaseCrossover => lang.pick(
                "the loop has no phase crossover (the phase never reaches −180°), so no ultimate gain".into(),
                "a malha não tem cruzamento de fase (a fase nunca chega a −180°), logo não há ganho último".into(),
            ),
            NotApplicable::NeedsTimeConstant { rule } => lang.pick(
                format!("{}: with no dead time the default τc = θ would be 0; give a closed-loop time constant τc > 0", rule.text(lang)),
                format!("{}: sem tempo morto o τc = θ padrão seria 0; informe uma constante de tempo de malha fechada τc > 0", rule.text(lang)),
            ),
            NotApplicable::BadTimeConstant(x) => lang.pick(
                format!("the closed-loop time constant must be a positive number of seconds, not {}", lang.num(x, 6)),
                format!("a constante de tempo de malha fechada deve ser um número positivo de segundos, não {}", lang.num(x, 6)),
            ),
            NotApplicable::Controller(e) => lang.pick(
                format!("the rule's numbers are not a usable controller: {}", e.text(lang)),
                format!("os números da regra não formam um controlador utilizável: {}", e.text(lang)),
            ),
        }
    }
}

impl Localize for StabilityError {
    fn text(&self, lang: Lang) -> String {
        match *self {
            StabilityError::Marginal { w } => lang.pick(
                format!("the closed loop has roots on the imaginary axis (near ω = {} rad/s): it is on the edge of stability", lang.num(w, 6)),
                format!("a malha fechada tem raízes no eixo imaginário (perto de ω = {} rad/s): está no limite da estabilidade", lang.num(w, 6)),
            ),
            StabilityError::Neutral { ratio } => lang.pick(
                format!("at high frequency |L| tends to {} ≥ 1 with a dead time: the loop has infinitely many roots at or beyond the imaginary axis", lang.num(ratio, 6)),
                format!("em alta frequência |L| tende a {} ≥ 1 com tempo morto: a malha tem infinitas raízes sobre ou além do eixo imaginário", lang.num(ratio, 6)),
            ),
            StabilityError::IllPosed => lang.pick(
                "1 + L(s) tends to 0 at high frequency: the loop is not well posed".into(),
                "1 + L(s) tende a 0 em alta frequência: a malha não é bem posta".into(),
            ),
            StabilityError::Unresolved { count } => lang.pick(
                format!("the closed-loop roots in the right half-plane could not be counted (the count came to {})", lang.num(count, 4)),
                format!("as raízes de malha fechada no semiplano direito não puderam ser contadas (a contagem deu {})", lang.num(count, 4)),
            ),
            StabilityError::Roots => lang.pick(
                "the roots of the loop's polynomials were not found".into(),
                "as raízes dos polinômios da malha não foram encontradas".into(),
            ),
        }
    }
}

/// P, PI, PD or PID.
fn action_name(action: Action) -> &'static str {
    match action {
        Action::P => "P",
        Action::PI => "PI",
        Action::PD => "PD",
        Action::PID => "PID",
    }
}

impl Formula {
    /// The equations alone, e.g. "Kc = τ/(K(τc + θ)), Ti = τ" (decimals in `lang`'s way).
    pub fn equations(&self, lang: Lang) -> String {
        lang.localize_number(equations(self))
    }

    /// Where the formula is published.
    pub fn source(&self, lang: Lang) -> String {
        let seborg = |table: &str| {
            lang.pick(
                format!("Seborg, Edgar, Mellichamp & Doyle, Process Dynamics and Control, Table {table}"),
                format!("Seborg, Edgar, Mellichamp & Doyle, Process Dynamics and Control, Tabela {table}"),
            )
        };
        match self.rule {
            Rule::ZieglerNicholsOpen => format!(
                "Ziegler & Nichols (1942), Trans. ASME 64:759–768; {}",
                seborg("12.6")
            ),
            Rule::ZieglerNicholsUltimate => format!(
                "Ziegler & Nichols (1942), Trans. ASME 64:759–768; {}",
                seborg("12.7")
            ),
            Rule::CohenCoon => format!(
                "Cohen & Coon (1953), Trans. ASME 75:827–834; {}",
                seborg("12.6")
            ),
            Rule::Imc => format!(
                "Rivera, Morari & Skogestad (1986), Ind. Eng. Chem. Process Des. Dev. 25:252–265; {}",
                seborg("12.1")
            ),
            Rule::Simc => lang.pick(
                "Skogestad (2003), J. Process Control 13:291–309, equations (27)–(28) and the half rule",
                "Skogestad (2003), J. Process Control 13:291–309, equações (27)–(28) e a regra da metade",
            ).into(),
            Rule::Amigo => lang.pick(
                "Åström & Hägglund (2004), J. Process Control 14:635–650; Advanced PID Control (2006), §7.6".into(),
                "Åström & Hägglund (2004), J. Process Control 14:635–650; Advanced PID Control (2006), seção 7.6".into(),
            ),
            Rule::Lambda => lang.pick(
                "Dahlin (1968), Instruments and Control Systems 41:77–83; Åström & Hägglund, Advanced PID Control (2006), §7.5".into(),
                "Dahlin (1968), Instruments and Control Systems 41:77–83; Åström & Hägglund, Advanced PID Control (2006), seção 7.5".into(),
            ),
        }
    }

    /// What the formula's letters are, and the defaults, in `lang`.
    fn note(&self, lang: Lang) -> String {
        match (self.rule, self.kind) {
            (Rule::ZieglerNicholsOpen, ModelKind::Foptd) => lang.pick("a = Kθ/τ", "a = Kθ/τ").to_string() + lang.pick(", from the model", ", do modelo"),
            (Rule::ZieglerNicholsOpen, ModelKind::Soptd) => lang.pick(
                "a = Kθ′/τ′, θ′ and τ′ read from the tangent at the inflection of the step response",
                "a = Kθ′/τ′, θ′ e τ′ lidos da tangente no ponto de inflexão da resposta ao degrau",
            ).into(),
            (Rule::ZieglerNicholsUltimate, _) => lang.pick(
                "Kcr, the ultimate gain, and Pcr, the ultimate period, exact with the dead time",
                "Kcr, o ganho último, e Pcr, o período último, exatos com o tempo morto",
            ).into(),
            (Rule::CohenCoon, _) => lang.pick("with r = θ/τ", "com r = θ/τ").into(),
            (Rule::Imc, _) => lang.pick("τc = θ by default", "τc = θ por padrão").into(),
            (Rule::Simc, ModelKind::Soptd) if self.action == Action::PI => lang.pick(
                "the half rule: τ1 + τ2/2 and θ + τ2/2 in place of τ1 and θ; τc = θ by default",
                "a regra da metade: τ1 + τ2/2 e θ + τ2/2 no lugar de τ1 e θ; τc = θ por padrão",
            ).into(),
            (Rule::Simc, ModelKind::Soptd) => lang.pick(
                "in the series form; τc = θ by default",
                "na forma série; τc = θ por padrão",
            ).into(),
            (Rule::Simc, _) => lang.pick("τc = θ by default", "τc = θ por padrão").into(),
            (Rule::Amigo, _) => lang.pick("for a first-order model with dead time", "para um modelo de primeira ordem com tempo morto").into(),
            (Rule::Lambda, ModelKind::Foptd) => lang.pick("λ = τ by default", "λ = τ por padrão").into(),
            (Rule::Lambda, ModelKind::Soptd) => lang.pick("λ = τ1 by default", "λ = τ1 por padrão").into(),
        }
    }
}

/// "PI: Kc = τ/(K(τc + θ)), Ti = τ (τc = θ by default)".
impl Localize for Formula {
    fn text(&self, lang: Lang) -> String {
        format!(
            "{}: {} ({})",
            action_name(self.action),
            self.equations(lang),
            self.note(lang)
        )
    }
}

/// The equations of a formula, with decimal points.
fn equations(f: &Formula) -> &'static str {
    use {Action::*, ModelKind::*, Rule::*};
    match (f.rule, f.action, f.kind) {
        (ZieglerNicholsOpen, P, _) => "Kc = 1/a",
        (ZieglerNicholsOpen, PI, _) => "Kc = 0.9/a, Ti = θ/0.3 = 3.33θ",
        (ZieglerNicholsOpen, _, _) => "Kc = 1.2/a, Ti = 2θ, Td = θ/2",
        (ZieglerNicholsUltimate, P, _) => "Kc = 0.5·Kcr",
        (ZieglerNicholsUltimate, PI, _) => "Kc = 0.45·Kcr, Ti = Pcr/1.2",
        (ZieglerNicholsUltimate, _, _) => "Kc = 0.6·Kcr, Ti = Pcr/2, Td = Pcr/8",
        (CohenCoon, P, _) => "Kc = (τ/(Kθ))·(1 + r/3)",
        (CohenCoon, PI, _) => "Kc = (τ/(Kθ))·(0.9 + r/12), Ti = θ(30 + 3r)/(9 + 20r)",
        (CohenCoon, _, _) => {
            "Kc = (τ/(Kθ))·(4/3 + r/4), Ti = θ(32 + 6r)/(13 + 8r), Td = 4θ/(11 + 2r)"
        }
        (Imc, PI, Foptd) => "Kc = τ/(K(τc + θ)), Ti = τ",
        (Imc, _, Foptd) => "Kc = (τ + θ/2)/(K(τc + θ/2)), Ti = τ + θ/2, Td = τθ/(2τ + θ)",
        (Imc, _, Soptd) => "Kc = (τ1 + τ2)/(K(τc + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2)",
        (Simc, _, Foptd) => "Kc = τ/(K(τc + θ)), Ti = min(τ, 4(τc + θ))",
        (Simc, PI, Soptd) => "Kc = τ1/(K(τc + θ)), Ti = min(τ1, 4(τc + θ))",
        (Simc, _, Soptd) => "Kc = τ1/(K(τc + θ)), Ti = min(τ1, 4(τc + θ)), Td = τ2",
        (Amigo, PI, _) => {
            "Kc = 0.15/K + (0.35 − θτ/(θ + τ)²)·τ/(Kθ), Ti = 0.35θ + 13θτ²/(τ² + 12θτ + 7θ²)"
        }
        (Amigo, _, _) => {
            "Kc = (0.2 + 0.45τ/θ)/K, Ti = θ(0.4θ + 0.8τ)/(θ + 0.1τ), Td = 0.5θτ/(0.3θ + τ)"
        }
        (Lambda, _, Foptd) => "Kc = τ/(K(λ + θ)), Ti = τ",
        (Lambda, _, Soptd) => "Kc = (τ1 + τ2)/(K(λ + θ)), Ti = τ1 + τ2, Td = τ1τ2/(τ1 + τ2)",
    }
}

/// Every message of tuning and the loop's frequency facts, for the words' test.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    use crate::control::ControllerError;
    use crate::control::tuning::formula;
    let mut all: Vec<Message> = Rule::ALL
        .iter()
        .map(|r| Message::of(format!("Rule::{r:?}"), r))
        .collect();
    for kind in [ModelKind::Foptd, ModelKind::Soptd] {
        all.push(Message::of(format!("ModelKind::{kind:?}"), &kind));
        for rule in Rule::ALL {
            for action in Action::ALL {
                match formula(rule, action, kind) {
                    Ok(f) => {
                        all.push(Message::of(format!("{f:?}"), &f));
                        all.push(Message::said(format!("{f:?}.source"), |l| f.source(l)));
                    }
                    Err(e) => all.push(Message::of(format!("{e:?}"), &e)),
                }
            }
        }
    }
    let facts: Vec<Box<dyn Localize>> = vec![
        Box::new(ModelError::Gain(0.0)),
        Box::new(ModelError::TimeConstant(-1.0)),
        Box::new(ModelError::DeadTime(f64::NAN)),
        Box::new(NotApplicable::NeedsDeadTime { rule: Rule::Amigo }),
        Box::new(NotApplicable::NoPhaseCrossover),
        Box::new(NotApplicable::NeedsTimeConstant { rule: Rule::Imc }),
        Box::new(NotApplicable::BadTimeConstant(-1.0)),
        Box::new(NotApplicable::Controller(ControllerError::Gain(
            f64::INFINITY,
        ))),
        Box::new(StabilityError::Marginal { w: 0.84 }),
        Box::new(StabilityError::Neutral { ratio: 1.5 }),
        Box::new(StabilityError::IllPosed),
        Box::new(StabilityError::Unresolved { count: 0.5 }),
        Box::new(StabilityError::Roots),
    ];
    all.extend(
        facts
            .iter()
            .enumerate()
            .map(|(i, f)| Message::of(format!("tuning fact {i}"), f.as_ref())),
    );
    all
}
