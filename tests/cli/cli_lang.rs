//! `--lang pt` on every command, through the binary: the human output and the errors in
//! Brazilian Portuguese with decimal commas and the same numbers as in English; `--json`
//! byte-identical in both languages.

use crate::run;

use run::{STEP, degrau, stderr, stdout};

const LECI: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/leci_step.csv");

/// The text output of `args` in `lang`, which must succeed.
fn text_in(lang: &str, args: &[&str]) -> String {
    let mut all = args.to_vec();
    all.extend(["--lang", lang]);
    let out = degrau(&all);
    assert!(out.status.success(), "{all:?}: {}", stderr(&out));
    stdout(&out)
}

/// The numbers of a text, in order, with `decimal` as the decimal separator (a separator
/// counts only between digits, so "a, b" and "[1; 2]" stay lists).
fn numbers(text: &str, decimal: char) -> Vec<f64> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < chars.len() {
        let starts = chars[k].is_ascii_digit()
            && (k == 0 || !(chars[k - 1].is_alphanumeric() || chars[k - 1] == '_'));
        if !starts {
            k += 1;
            continue;
        }
        let negative = k > 0 && chars[k - 1] == '-';
        let mut s = String::from(if negative { "-" } else { "" });
        while k < chars.len() {
            let c = chars[k];
            let next_digit = chars.get(k + 1).is_some_and(|d| d.is_ascii_digit());
            let exponent = c == 'e'
                && chars
                    .get(k + 1)
                    .is_some_and(|d| d.is_ascii_digit() || *d == '-');
            if c.is_ascii_digit() {
                s.push(c);
            } else if c == decimal && next_digit {
                s.push('.');
            } else if exponent {
                s.push('e');
                if chars[k + 1] == '-' {
                    s.push('-');
                    k += 1;
                }
            } else {
                break;
            }
            k += 1;
        }
        if let Ok(x) = s.parse() {
            out.push(x);
        }
    }
    out
}

#[test]
fn step_speaks_portuguese_with_decimal_commas() {
    let pt = text_in("pt", &["step", "--num", "5", "--den", "1,5"]);
    // 5/(s+5): rise time ln 9 / 5 = 0.439445 s, 2 % settling time ln 50 / 5 = 0.782404 s.
    for words in [
        "Sistema",
        "Polos",
        "Ganho estático",
        "Estabilidade",
        "Tempo de subida",
        "0,43944 s",
        "Tempo de acomodação",
        "0,7824 s",
        "Sobressinal",
        "Regime permanente",
        "Resposta ao degrau (forma fechada exata):",
        "y(t) = 1 − e^{−5t}",
    ] {
        assert!(pt.contains(words), "missing {words:?} in\n{pt}");
    }
    assert!(!pt.contains("Rise time"), "{pt}");
    let en = text_in("en", &["step", "--num", "5", "--den", "1,5"]);
    assert!(en.contains("Rise time") && en.contains("0.43944 s"), "{en}");
    assert_eq!(numbers(&en, '.'), numbers(&pt, ','));
}

#[test]
fn fit_speaks_portuguese_with_the_same_numbers() {
    let args = ["fit", STEP, "--model", "P1", "--y0", "50", "--t0", "2"];
    let en = text_in("en", &args);
    let pt = text_in("pt", &args);
    assert!(en.contains("Model P1 fitted to"), "{en}");
    assert!(pt.contains("Modelo P1 ajustado a"), "{pt}");
    assert!(pt.contains("Ganho estático Kp = Δy/Δu = 2"), "{pt}");
    assert!(pt.contains("Parâmetro") && pt.contains("ajuste"), "{pt}");
    let (a, b) = (numbers(&en, '.'), numbers(&pt, ','));
    assert_eq!(a, b, "\n{en}\n{pt}");
    // The fitted time constant is the fixture's 5 s, written with a comma when not whole.
    assert!(a.iter().any(|x| (x - 5.0).abs() < 1e-3), "{a:?}");
}

#[test]
fn diagnose_speaks_portuguese_with_the_same_numbers() {
    let args = [
        "diagnose", LECI, "--t0", "5", "--du", "10", "--y0", "50", "--start", "P2U",
    ];
    let en = text_in("en", &args);
    let pt = text_in("pt", &args);
    assert!(
        en.contains("dead_time: The model moves before the data does"),
        "{en}"
    );
    assert!(
        pt.contains("dead_time: O modelo se move antes dos dados"),
        "{pt}"
    );
    assert!(
        pt.contains("Ajuste %") && pt.contains("Variação do BIC"),
        "{pt}"
    );
    assert!(
        pt.contains("Correção: acrescentar um tempo morto Td"),
        "{pt}"
    );
    assert!(pt.contains("Ganho estático Kp"), "{pt}");
    assert_eq!(numbers(&en, '.'), numbers(&pt, ','), "\n{en}\n{pt}");
}

#[test]
fn json_is_the_same_in_every_language() {
    let cases: [&[&str]; 3] = [
        &["step", "--num", "5", "--den", "1,5", "--json"],
        &["fit", STEP, "--model", "P1D", "--json"],
        &["diagnose", STEP, "--start", "P1", "--json"],
    ];
    for args in cases {
        let en = degrau(&[args, &["--lang", "en"]].concat());
        let pt = degrau(&[args, &["--lang", "pt"]].concat());
        assert!(en.status.success(), "{args:?}: {}", stderr(&en));
        assert!(!en.stdout.is_empty());
        assert_eq!(en.stdout, pt.stdout, "{args:?}");
        assert_eq!(
            degrau(args).stdout,
            en.stdout,
            "{args:?}: English is the default"
        );
    }
}

#[test]
fn errors_are_said_in_portuguese() {
    let missing = degrau(&["fit", "no_such_file.csv", "--lang", "pt"]);
    assert_eq!(missing.status.code(), Some(2));
    let err = stderr(&missing);
    assert!(
        err.starts_with("erro: no_such_file.csv: não foi possível ler"),
        "{err}"
    );
    let bad_value = degrau(&["step", "--poles", "-1", "--delay", "nan", "--lang", "pt"]);
    assert_eq!(bad_value.status.code(), Some(2));
    let err = stderr(&bad_value);
    assert!(
        err.starts_with("erro: valor inválido 'nan' para '--delay <SECONDS>'"),
        "{err}"
    );
    // --lang may come before the subcommand too.
    let no_system = degrau(&["--lang", "pt", "step"]);
    assert_eq!(no_system.status.code(), Some(2));
    assert!(
        stderr(&no_system).contains("erro: nenhum sistema dado"),
        "{}",
        stderr(&no_system)
    );
    let y0 = degrau(&["fit", STEP, "--y0", "x", "--lang", "pt"]);
    assert!(
        stderr(&y0).contains("--y0 deve ser auto, free ou um número"),
        "{}",
        stderr(&y0)
    );
    // The same errors in English by default.
    let missing = degrau(&["fit", "no_such_file.csv"]);
    assert!(
        stderr(&missing).starts_with("error: no_such_file.csv: could not read"),
        "{}",
        stderr(&missing)
    );
}

#[test]
fn numbers_are_read_with_either_separator() {
    // A digit inside a name (Tp1, P2DU) is not a number.
    assert_eq!(numbers("Kp 1.5, Tp1 2 s", '.'), [1.5, 2.0]);
    assert_eq!(numbers("Kp 1,5; Tp1 2 s", ','), [1.5, 2.0]);
    assert_eq!(numbers("-1e-5 and 3e2", '.'), [-1e-5, 300.0]);
}

/// Every kind of refusal clap makes is said in Portuguese under `--lang pt` (issue 22,
/// item 11), and a negative number says what the flag takes, in both languages.
#[test]
fn the_argument_parser_refuses_in_portuguese() {
    let cases: [(&[&str], &str); 9] = [
        (
            &["prbs", "--n", "1e3", "--lang", "pt"],
            "valor inválido '1e3' para '--n <N>': '1e3' não é um número inteiro",
        ),
        (
            &["prbs", "--n", "-1", "--lang", "pt"],
            "--n recebe um número inteiro a partir de 0, não -1",
        ),
        (
            &["fit", "--lang", "pt"],
            "faltam argumentos obrigatórios: <FILE>",
        ),
        (&["frob", "--lang", "pt"], "subcomando desconhecido 'frob'"),
        (
            &["fit", STEP, "--method", "foo", "--lang", "pt"],
            "valor inválido 'foo' para '--method <METHOD>': os valores possíveis são lm, nelder-mead",
        ),
        (
            &["fit", STEP, "--tempo", "3", "--lang", "pt"],
            "argumento inesperado '--tempo'",
        ),
        (
            &["prbs", "--n", "10", "--n", "5", "--lang", "pt"],
            "não pode ser dado mais de uma vez",
        ),
        (
            &["prbs", "--n", "10", "--ts", "-1", "--lang", "pt"],
            "--ts não aceita valor negativo, e foi dado -1",
        ),
        (&["fit", STEP, "--json=3", "--lang", "pt"], "erro:"),
    ];
    for (args, words) in cases {
        let out = degrau(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(err.starts_with("erro: "), "{args:?}: {err}");
        assert!(err.contains(words), "{args:?}: {err}");
        assert!(
            err.contains("Para mais informações, use '--help'."),
            "{err}"
        );
        for english in [
            "error:",
            "invalid value",
            "unexpected",
            "required",
            "For more",
        ] {
            assert!(!err.contains(english), "{args:?}: {err}");
        }
    }
    let negative = stderr(&degrau(&["prbs", "--n", "-1"]));
    assert!(
        negative.starts_with("error: --n takes a whole number from 0 up, not -1"),
        "{negative}"
    );
    let digits = stderr(&degrau(&["prbs", "--n", "1e3"]));
    assert!(digits.contains("'1e3' is not a whole number"), "{digits}");
}

/// A one-column file has no time column: the message says so and names `--ts` (issue 22,
/// item 12), whichever flags were guessed; a missing file's reason is in the language asked.
#[test]
fn a_one_column_file_asks_for_the_sampling_period() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/one_column.txt");
    for args in [
        vec!["fit", file],
        vec!["hand", file, "--y-col", "1"],
        vec!["fit", file, "--time-col", "1", "--y-col", "1"],
    ] {
        let err = stderr(&degrau(&args));
        assert!(
            err.contains("the file has one column, the output, and no time column")
                && err.contains("--ts"),
            "{args:?}: {err}"
        );
        assert!(!err.contains("same column"), "{err}");
    }
    let pt = stderr(&degrau(&["fit", file, "--lang", "pt"]));
    assert!(
        pt.contains("nenhuma coluna de tempo: dê o período de amostragem com --ts"),
        "{pt}"
    );
    let fitted = degrau(&["fit", file, "--ts", "0.5", "--t0", "0.9", "--du", "1"]);
    assert_eq!(fitted.status.code(), Some(0), "{}", stderr(&fitted));
    let missing = stderr(&degrau(&["fit", "no_such_file.csv", "--lang", "pt"]));
    assert!(missing.contains("esse arquivo não existe"), "{missing}");
}
