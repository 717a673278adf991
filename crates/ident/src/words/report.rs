//! The fit and the diagnosis chain as people read them, written once for `degrau fit`,
//! `degrau diagnose` and the app's Identify panel: the parameter table, the fit's figures
//! and warnings, what a model's parameters mean (ωn, σ, ωd, poles, static gain), the chain
//! table (one row per model: RMSE, fit %, BIC change, Kp ± half its 95 % interval), each
//! step's cause, evidence and remedy, and the verdict.
//!
//! Numbers take the language's decimal separator; the tab-separated copy of the chain table
//! ([`chain_text`]) too, as a spreadsheet in that language reads it.

use crate::diagnose::{DiagnoseReport, Step};
use crate::fit::{FitReport, FitWarning};
use crate::model::{Model, Param, pair_poles};

use super::ident::{Naming, cause_name};
#[cfg(test)]
use degrau_words::Message;
use degrau_words::{Lang, Localize};

/// Columns of the chain table.
pub const CHAIN_COLUMNS: usize = 5;

/// The header of the chain table's Kp column: the same symbols in both languages.
pub const KP_INTERVAL: &str = "Kp ± 95 %";

degrau_words::phrases! {
    /// The fixed words of the fit and chain texts.
    pub enum ReportPhrase {
        Model => ("Model", "Modelo"),
        FitPercent => ("Fit %", "Ajuste %"),
        BicChange => ("BIC change", "Variação do BIC"),
        Parameter => ("Parameter", "Parâmetro"),
        Value => ("Value", "Valor"),
        Interval => ("95 % interval", "Intervalo de 95 %"),
        NoInterval => ("none", "nenhum"),
        Warning => ("Warning", "Atenção"),
        FinalRow => ("final fit", "ajuste final"),
        RobustRow => ("robust fit", "ajuste robusto"),
        WidenedRow => ("intervals", "intervalos"),
    }
}

/// `x` with `digits` significant digits in `lang`.
fn num(lang: Lang, x: f64, digits: i32) -> String {
    lang.num(x, digits)
}

/// Kp of a fit with half its 95 % interval: `1.002 ± 0.031`.
fn kp_cell(f: &FitReport, lang: Lang) -> String {
    let kp = f.model.get(Param::Kp);
    match f.interval(Param::Kp) {
        Some((a, b)) => format!("{} ± {}", num(lang, kp, 4), num(lang, 0.5 * (b - a), 2)),
        None => num(lang, kp, 4),
    }
}

/// The chain table's header.
pub fn chain_header(lang: Lang) -> [String; CHAIN_COLUMNS] {
    [
        ReportPhrase::Model.get(lang).to_string(),
        "RMSE".to_string(),
        ReportPhrase::FitPercent.get(lang).to_string(),
        ReportPhrase::BicChange.get(lang).to_string(),
        KP_INTERVAL.to_string(),
    ]
}

/// The chain table: its header, and one row per model (the start, then each step's, then
/// the final fit when it differs, [`DiagnoseReport::rows`]): model, RMSE, fit %, BIC change
/// (empty for the start and the final row), Kp ± half its 95 % interval.
pub fn chain_rows(
    d: &DiagnoseReport,
    lang: Lang,
) -> ([String; CHAIN_COLUMNS], Vec<[String; CHAIN_COLUMNS]>) {
    let chain = d.chain().len();
    let rows = d
        .rows()
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let delta = k
                .checked_sub(1)
                .filter(|_| k < chain)
                .and_then(|i| d.steps.get(i))
                .map_or(String::new(), |s| num(lang, s.gain.criterion_delta, 4));
            let name = f.model.structure.text(lang);
            [
                if k < chain {
                    name
                } else {
                    format!("{name}, {}", final_handling(d, lang))
                },
                num(lang, f.rmse, 4),
                num(lang, f.fit_percent, 4),
                delta,
                kp_cell(f, lang),
            ]
        })
        .collect();
    (chain_header(lang), rows)
}

/// What the final row's fit had done to it: `final fit (robust fit, Cauchy; intervals × 2.9)`.
fn final_handling(d: &DiagnoseReport, lang: Lang) -> String {
    use crate::diagnose::test_causes::Handling;
    let done: Vec<String> = d
        .test_causes
        .iter()
        .filter_map(|c| match c.handling {
            Handling::RobustLoss { loss } => Some(format!(
                "{}, {}",
                ReportPhrase::RobustRow.get(lang),
                loss.name()
            )),
            Handling::IntervalsWidened { factor } => Some(format!(
                "{} × {}",
                ReportPhrase::WidenedRow.get(lang),
                num(lang, factor, 3)
            )),
            _ => None,
        })
        .collect();
    let final_word = ReportPhrase::FinalRow.get(lang);
    if done.is_empty() {
        final_word.to_string()
    } else {
        format!("{final_word} ({})", done.join("; "))
    }
}

/// The chain table as tab-separated text, for a spreadsheet or a report.
pub fn chain_text(d: &DiagnoseReport, lang: Lang) -> String {
    let (header, rows) = chain_rows(d, lang);
    let mut out = String::new();
    for row in std::iter::once(&header).chain(&rows) {
        out.push_str(&row.join("\t"));
        out.push('\n');
    }
    out
}

/// The chain table with aligned columns, as `degrau diagnose` prints it.
fn chain_table(d: &DiagnoseReport, lang: Lang) -> Vec<String> {
    let (header, rows) = chain_rows(d, lang);
    let all: Vec<&[String; CHAIN_COLUMNS]> = std::iter::once(&header).chain(&rows).collect();
    let width = |c: usize| all.iter().map(|r| r[c].chars().count()).max().unwrap_or(0);
    let widths: Vec<usize> = (0..CHAIN_COLUMNS).map(width).collect();
    all.iter()
        .map(|r| {
            let mut line = format!("{:<w$}", r[0], w = widths[0]);
            for c in 1..CHAIN_COLUMNS - 1 {
                line.push_str(&format!("  {:>w$}", r[c], w = widths[c]));
            }
            line.push_str(&format!("  {}", r[CHAIN_COLUMNS - 1]));
            line.trim_end().to_string()
        })
        .collect()
}

/// A step's cause in words: `dead_time: The model moves before the data does: …` (named
/// as `naming` says: `Dead time: …` in the app).
pub fn cause_line(step: &Step, naming: Naming, lang: Lang) -> String {
    let name = |c| cause_name(c, naming, lang);
    if step.removed {
        return format!(
            "{} {}: {}",
            name(step.cause),
            lang.pick("taken out", "retirado"),
            lang.pick(
                "the term no longer pays once the later ones are in.",
                "o termo não compensa mais com os seguintes incluídos."
            )
        );
    }
    match step.paired {
        Some(p) => format!(
            "{} + {}: {} {}",
            name(step.cause),
            cause_name(p, naming, lang).to_lowercase(),
            step.cause.text(lang),
            p.text(lang)
        ),
        None => format!("{}: {}", name(step.cause), step.cause.text(lang)),
    }
}

/// A step's remedy and gain: `Remedy: add a dead time Td. RMSE 0.9 → 0.3 (3× lower); fit …`.
pub fn remedy_line(step: &Step, lang: Lang) -> String {
    let g = &step.gain;
    let remedy = if step.removed {
        lang.pick("take the term out again", "retirar o termo de novo")
            .to_string()
    } else {
        super::ident::remedy(step.cause, lang).to_string()
    };
    let (before, after, ratio, fb, fa) = (
        num(lang, g.rmse_before, 4),
        num(lang, g.rmse_after, 4),
        num(lang, g.rmse_ratio, 3),
        num(lang, g.fit_percent_before, 4),
        num(lang, g.fit_percent_after, 4),
    );
    lang.pick(
        format!("Remedy: {remedy}. RMSE {before} → {after} ({ratio}× lower); fit {fb} % → {fa} %."),
        format!(
            "Correção: {remedy}. RMSE {before} → {after} ({ratio}× menor); ajuste {fb} % → {fa} %."
        ),
    )
}

/// A step as the app shows the selected one: its cause, its evidence, its remedy and gain.
pub fn step_lines(step: &Step, naming: Naming, lang: Lang) -> [String; 3] {
    [
        cause_line(step, naming, lang),
        step.evidence.text(lang),
        remedy_line(step, lang),
    ]
}

/// The static gain of the final model with its interval.
pub fn static_gain_line(d: &DiagnoseReport, lang: Lang) -> String {
    let (k, ci) = d.static_gain;
    let interval = ci.map_or(String::new(), |ci| {
        format!(", 95 % {}", interval(lang, ci, 5))
    });
    let line = format!(
        "{} Kp = Δy/Δu = {}{interval}",
        lang.pick("Static gain", "Ganho estático"),
        num(lang, k, 5)
    );
    match &d.gain_trade {
        Some(t) => format!("{line}. {}", trade_words(t, lang)),
        None => line,
    }
}

/// What a gain that trades with another term means: measured only together with it.
fn trade_words(t: &crate::diagnose::GainTrade, lang: Lang) -> String {
    let (name, r) = (t.with.name(), num(lang, t.correlation, 3));
    lang.pick(
        format!(
            "The record does not separate Kp from {name} (their estimates are correlated \
             {r}): the gain is measured only together with {name}, and the interval is the \
             range the record allows; a longer record, settled before and after each change, \
             would separate them."
        ),
        format!(
            "O registro não separa Kp de {name} (as estimativas têm correlação {r}): o ganho \
             só é medido junto com {name}, e o intervalo é a faixa que o registro permite; um \
             registro mais longo, acomodado antes e depois de cada variação, os separaria."
        ),
    )
}

/// The whole diagnosis as `degrau diagnose` prints it: what the test got wrong, then what
/// the model gets wrong (the table, then each step's cause, evidence and remedy), the
/// verdict, the line naming the structure and the artefacts, and the static gain.
pub fn diagnose_text(d: &DiagnoseReport, lang: Lang) -> String {
    let mut lines = super::test_causes::section(&d.test_causes, lang);
    lines.push(String::new());
    lines.push(format!(
        "{}:",
        super::test_causes::TestCausePhrase::ModelHeading.get(lang)
    ));
    lines.extend(chain_table(d, lang));
    for (k, s) in d.steps.iter().enumerate() {
        lines.push(String::new());
        let [cause, evidence, remedy] = step_lines(s, Naming::Id, lang);
        lines.push(format!("{}. {cause}", k + 1));
        lines.push(format!("   {evidence}"));
        lines.push(format!("   {remedy}"));
    }
    lines.push(String::new());
    if let Some(v) = &d.verdict {
        lines.push(v.text(lang));
    }
    lines.push(super::test_causes::verdict_line(d, lang));
    lines.push(static_gain_line(d, lang));
    lines.join("\n")
}

/// An interval `[a, b]` (`[a; b]` in Portuguese, whose numbers have commas).
fn interval(lang: Lang, (a, b): (f64, f64), digits: i32) -> String {
    let sep = lang.pick(", ", "; ");
    format!("[{}{sep}{}]", num(lang, a, digits), num(lang, b, digits))
}

/// The parameter table: its header (parameter, value, 95 % interval) and one row per
/// estimated parameter, the value with its unit.
pub fn param_rows(report: &FitReport, lang: Lang) -> ([String; 3], Vec<[String; 3]>) {
    let header = [
        ReportPhrase::Parameter.get(lang).to_string(),
        ReportPhrase::Value.get(lang).to_string(),
        ReportPhrase::Interval.get(lang).to_string(),
    ];
    let rows = report
        .params
        .iter()
        .map(|e| {
            let unit = e.param.unit();
            let value = num(lang, e.value, 6);
            [
                e.param.name().to_string(),
                if unit.is_empty() {
                    value
                } else {
                    format!("{value} {unit}")
                },
                e.ci95
                    .map_or(ReportPhrase::NoInterval.get(lang).to_string(), |ci| {
                        interval(lang, ci, 6)
                    }),
            ]
        })
        .collect();
    (header, rows)
}

/// The fit's figures on one line: `MSE … · RMSE … · fit … % · AIC … · N = …`.
pub fn figures_line(r: &FitReport, lang: Lang) -> String {
    format!(
        "MSE {} · RMSE {} · {} {} % · AIC {} · N = {}",
        num(lang, r.mse, 6),
        num(lang, r.rmse, 6),
        lang.pick("fit", "ajuste"),
        num(lang, r.fit_percent, 6),
        num(lang, r.aic, 6),
        r.n
    )
}

/// How the fit ended: `converged: … · 16 start(s), 42 iterations`.
pub fn status_line(r: &FitReport, lang: Lang) -> String {
    let (s, i) = (r.starts, r.iterations);
    format!(
        "{} · {}",
        r.termination.text(lang),
        lang.pick(
            format!("{s} start(s), {i} iterations"),
            format!("{s} ponto(s) de partida, {i} iterações"),
        )
    )
}

/// A warning as a line: `Warning: Td stopped at its bound 0: …`.
pub fn warning_line(w: &FitWarning, lang: Lang) -> String {
    format!("{}: {}", ReportPhrase::Warning.get(lang), w.text(lang))
}

/// What a model's parameters mean: ωn, σ and ωd (or the two real poles) of an underdamped
/// pair, the real poles from the time constants, and the static gain.
pub fn derived(model: &Model, lang: Lang) -> Vec<String> {
    let s = model.structure;
    let n = |x: f64| num(lang, x, 4);
    let mut out = Vec::new();
    if s.underdamped {
        let (tw, zeta) = (model.get(Param::Tw), model.get(Param::Zeta));
        let [p, q] = pair_poles(tw, zeta);
        out.push(format!(
            "ωn = 1/Tw = {} rad/s · σ = ζωn = {} 1/s",
            n(1.0 / tw),
            n(zeta / tw)
        ));
        if zeta < 1.0 {
            out.push(format!(
                "ωd = {} rad/s · {} {} ± {}j",
                n(p.im),
                lang.pick("poles", "polos"),
                n(p.re),
                n(p.im)
            ));
        } else {
            out.push(lang.pick(
                format!("overdamped: poles {} and {}", n(p.re), n(q.re)),
                format!("sobreamortecido: polos {} e {}", n(p.re), n(q.re)),
            ));
        }
    }
    let poles: Vec<String> = [Param::Tp1, Param::Tp2, Param::Tp3]
        .into_iter()
        .filter(|p| s.params().contains(p))
        .map(|p| {
            let pole = n(-1.0 / model.get(p));
            lang.pick(
                format!("{pole} (from {})", p.name()),
                format!("{pole} (de {})", p.name()),
            )
        })
        .collect();
    if !poles.is_empty() {
        out.push(format!(
            "{}: {}",
            lang.pick("Real poles", "Polos reais"),
            poles.join("; ")
        ));
    }
    out.push(format!(
        "{} Kp = Δy/Δu = {}",
        lang.pick("Static gain", "Ganho estático"),
        num(lang, model.get(Param::Kp), 5)
    ));
    out
}

/// The fit as `degrau fit` prints it: the model and how the fit ended, the parameter
/// table, what the parameters mean, the figures and the warnings.
pub fn fit_lines(r: &FitReport, lang: Lang) -> Vec<String> {
    let (s, i) = (r.n, r.method.name());
    let mut lines = vec![format!(
        "{} {} {} ({i}, {})",
        ReportPhrase::Model.get(lang),
        r.model.structure.code(),
        lang.pick(
            format!("fitted to {s} samples"),
            format!("ajustado a {s} amostras")
        ),
        status_line(r, lang)
    )];
    let (header, rows) = param_rows(r, lang);
    let width = |c: usize| {
        std::iter::once(&header)
            .chain(&rows)
            .map(|row| row[c].chars().count())
            .max()
            .unwrap_or(0)
    };
    let (w0, w1) = (width(0), width(1));
    for row in std::iter::once(&header).chain(&rows) {
        lines.push(format!("  {:<w0$}  {:>w1$}  {}", row[0], row[1], row[2]));
    }
    lines.extend(derived(&r.model, lang));
    lines.push(figures_line(r, lang));
    lines.extend(r.warnings.iter().map(|w| warning_line(w, lang)));
    lines
}

/// Every phrase of this module, for the test of both languages.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    ReportPhrase::messages()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{Estimate, Method, Termination};
    use crate::model::{Structure, Values};

    fn report() -> FitReport {
        let structure = Structure::parse("P2DU").unwrap();
        let mut values = Values::default();
        for (p, v) in [
            (Param::Kp, 1.0021),
            (Param::Tw, 1.0 / 0.9659),
            (Param::Zeta, 0.1948),
            (Param::Td, 1.759),
            (Param::Y0, 50.0),
        ] {
            values.set(p, v);
        }
        let model = Model::new(structure, values);
        FitReport {
            params: structure
                .params()
                .iter()
                .map(|&p| Estimate {
                    param: p,
                    value: values.get(p),
                    ci95: Some((values.get(p) - 0.01, values.get(p) + 0.01)),
                    bounds: None,
                })
                .collect(),
            model,
            method: Method::LevenbergMarquardt,
            n: 35,
            mse: 0.0123,
            ln_mse: 0.0123f64.ln(),
            rmse: 0.0123f64.sqrt(),
            fit_percent: 97.25,
            aic: -150.5,
            iterations: 12,
            termination: Termination::SmallStep,
            warnings: vec![FitWarning::NotConverged],
            starts: 16,
            path: Vec::new(),
            units: Default::default(),
            kp_correlations: Vec::new(),
        }
    }

    #[test]
    fn derived_poles_of_an_overdamped_pair_and_of_time_constants() {
        // Tw = 1 s, ζ = 1.25: s = −(ζ ± √(ζ² − 1))/Tw = −0.5 and −2.
        let mut v = Values::default();
        for (p, x) in [(Param::Kp, 2.0), (Param::Tw, 1.0), (Param::Zeta, 1.25)] {
            v.set(p, x);
        }
        let pair = Model::new(Structure::parse("P2U").unwrap(), v);
        let en = derived(&pair, Lang::En).join("\n");
        assert!(
            en.contains("ωn = 1/Tw = 1 rad/s · σ = ζωn = 1.25 1/s"),
            "{en}"
        );
        assert!(
            en.contains("overdamped: poles -0.5 and -2")
                || en.contains("overdamped: poles -2 and -0.5"),
            "{en}"
        );
        // P2 with Tp1 = 4 s, Tp2 = 0.5 s: poles −1/4 and −2.
        let mut v = Values::default();
        for (p, x) in [(Param::Kp, 0.8), (Param::Tp1, 4.0), (Param::Tp2, 0.5)] {
            v.set(p, x);
        }
        let lags = Model::new(Structure::parse("P2").unwrap(), v);
        let pt = derived(&lags, Lang::Pt).join("\n");
        assert!(
            pt.contains("Polos reais: -0,25 (de Tp1); -2 (de Tp2)"),
            "{pt}"
        );
        assert!(pt.contains("Ganho estático Kp = Δy/Δu = 0,8"), "{pt}");
    }

    #[test]
    fn the_fit_text_has_the_same_numbers_in_both_languages() {
        let r = report();
        let en = fit_lines(&r, Lang::En).join("\n");
        let pt = fit_lines(&r, Lang::Pt).join("\n");
        assert!(en.contains("Model P2DU fitted to 35 samples"), "{en}");
        assert!(pt.contains("Modelo P2DU ajustado a 35 amostras"), "{pt}");
        assert!(en.contains("1.0021") && pt.contains("1,0021"), "{en}\n{pt}");
        // ωn = 0.9659 rad/s and ζ = 0.1948: ωd = ωn √(1 − ζ²) = 0.9474 rad/s.
        assert!(en.contains("ωd = 0.9474 rad/s"), "{en}");
        assert!(pt.contains("ωd = 0,9474 rad/s"), "{pt}");
        assert!(pt.contains("Atenção: o otimizador não convergiu"), "{pt}");
        assert_eq!(en.lines().count(), pt.lines().count());
    }

    #[test]
    fn a_gain_that_trades_with_a_drift_says_so_in_both_languages() {
        let mut d = chain();
        assert!(!static_gain_line(&d, Lang::En).contains("does not separate"));
        d.gain_trade = Some(crate::diagnose::GainTrade {
            with: Param::Drift,
            correlation: -0.968,
        });
        let en = static_gain_line(&d, Lang::En);
        assert!(en.starts_with("Static gain Kp = Δy/Δu = 1.0021, 95 % [0.98647, 1.0178]. The record does not separate Kp from Drift (their estimates are correlated -0.968)"), "{en}");
        let pt = static_gain_line(&d, Lang::Pt);
        assert!(
            pt.contains("O registro não separa Kp de Drift (as estimativas têm correlação -0,968)"),
            "{pt}"
        );
    }

    #[test]
    fn a_term_taken_out_says_so_in_both_languages() {
        use crate::diagnose::{Cause, Evidence};
        let mut step = chain().steps[0].clone();
        step.cause = Cause::Drift;
        step.removed = true;
        step.evidence = Evidence::NoLongerPays {
            param: Param::Drift,
            value: 0.0002,
            ci95: Some((-0.001, 0.0014)),
            criterion_delta: 4.5,
        };
        let [cause, evidence, remedy] = step_lines(&step, Naming::Id, Lang::En);
        assert!(cause.starts_with("drift taken out"), "{cause}");
        assert!(
            evidence.contains("Drift = 0.0002 [-0.001, 0.0014] no longer pays"),
            "{evidence}"
        );
        assert!(
            remedy.starts_with("Remedy: take the term out again"),
            "{remedy}"
        );
        let [cause, evidence, remedy] = step_lines(&step, Naming::Id, Lang::Pt);
        assert!(cause.starts_with("drift retirado"), "{cause}");
        assert!(evidence.contains("não compensa"), "{evidence}");
        assert!(remedy.starts_with("Correção: retirar o termo"), "{remedy}");
        step.evidence = Evidence::NoLongerPays {
            param: Param::Td,
            value: -0.24,
            ci95: None,
            criterion_delta: -30.0,
        };
        assert!(step.evidence.text(Lang::En).contains("no dead time"));
    }

    fn chain() -> DiagnoseReport {
        use crate::diagnose::{Bias, Cause, Ending, Evidence, Gain, Verdict};
        let start = report();
        let mut end = report();
        end.rmse = 0.05;
        let step = Step {
            cause: Cause::DeadTime,
            paired: None,
            evidence: Evidence::DeadTime {
                bias: Bias {
                    start: 5.0,
                    end: 6.759,
                    n: 2,
                    mean: -0.8786,
                    same_sign: 1.0,
                },
                td: 1.759,
                changes: 1,
            },
            interval: Some((5.0, 6.759)),
            gain: Gain {
                rmse_before: start.rmse,
                rmse_after: end.rmse,
                rmse_ratio: start.rmse / end.rmse,
                fit_percent_before: 51.65,
                fit_percent_after: 87.51,
                criterion_delta: -91.18,
            },
            fit: end.clone(),
            removed: false,
        };
        DiagnoseReport {
            start,
            steps: vec![step],
            final_fit: end,
            adequate: true,
            verdict: Some(Verdict {
                ending: Ending::Adequate,
                whiteness: None,
                structure: None,
                artefacts: Default::default(),
            }),
            static_gain: (1.0021, Some((0.98647, 1.0178))),
            gain_trade: None,
            test_causes: Vec::new(),
        }
    }

    #[test]
    fn the_chain_table_is_one_row_per_model_in_either_language() {
        let d = chain();
        let (head, rows) = chain_rows(&d, Lang::Pt);
        assert_eq!(head[0], "Modelo");
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0][3], "", "the start has no BIC change");
        assert_eq!(rows[1][3], "-91,18");
        // Kp 1.0021 with its interval ±0.01: four digits, then two for the half-width.
        assert_eq!(rows[1][4], "1,002 ± 0,01");
        let en = chain_text(&d, Lang::En);
        assert!(
            en.starts_with("Model\tRMSE\tFit %\tBIC change\tKp ± 95 %\n"),
            "{en}"
        );
        assert_eq!(en.lines().count(), 3);
        let text = diagnose_text(&d, Lang::Pt);
        assert!(
            text.contains("1. dead_time: O modelo se move antes dos dados"),
            "{text}"
        );
        assert!(text.contains("Adequado:"), "{text}");
        assert!(text.contains("95 % [0,98647; 1,0178]"), "{text}");
    }

    #[test]
    fn a_final_fit_with_widened_intervals_is_a_row_of_its_own() {
        use crate::diagnose::test_causes::{Handling, TestCause, TestCauseKind, TestEvidence};
        let mut d = chain();
        assert_eq!(
            chain_rows(&d, Lang::En).1.len(),
            2,
            "the same fit: no extra row"
        );
        d.final_fit.widen_intervals(3.0);
        d.test_causes.push(TestCause {
            kind: TestCauseKind::ColouredNoise,
            evidence: TestEvidence::ColouredNoise {
                lag1: 0.8,
                widening: 3.0,
            },
            interval: None,
            handling: Handling::IntervalsWidened { factor: 3.0 },
        });
        let (_, rows) = chain_rows(&d, Lang::En);
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[2][0], "P2DU, final fit (intervals × 3)");
        assert_eq!(rows[2][3], "", "the final row is no step");
        // ±0.01 widened three times: the Kp the verdict quotes, with its interval.
        assert_eq!(rows[2][4], "1.002 ± 0.03");
        let (_, pt) = chain_rows(&d, Lang::Pt);
        assert!(
            pt[2][0].ends_with("ajuste final (intervalos × 3)"),
            "{}",
            pt[2][0]
        );
    }

    #[test]
    fn a_parameter_interval_keeps_its_two_numbers_apart() {
        let (_, rows) = param_rows(&report(), Lang::Pt);
        assert_eq!(rows[0][0], "Kp");
        assert_eq!(rows[0][2], "[0,9921; 1,0121]");
    }
}
