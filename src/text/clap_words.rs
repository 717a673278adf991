//! clap's refusals of a command line, in the student's language: a value that does not
//! parse (and what it must be), a choice not among the possible ones, an unknown flag or
//! subcommand, a missing or conflicting argument, a wrong count of values. clap's kinds of
//! error are few, so each has its own words here, in English and in Brazilian Portuguese;
//! help and version are printed by clap itself. A negative number after a flag that takes
//! none, which clap reads as a flag of its own, is said as what the flag's value must be.
//!
//! In English clap's own message is kept where it already says what is wrong; these words
//! replace it for a value that does not parse as a number and for a negative number.

use clap::error::{ContextKind, ContextValue, ErrorKind};

use super::Lang;
use super::cli::parse_words;
use crate::cli::fit::StartsError;
use crate::lti::parse::ParseError;

/// The words of clap's refusal `e` of the command line `args` in `lang`, with a last line
/// pointing to `--help`; `None` where clap's own message is printed (help, version, and in
/// English every refusal these words do not improve on).
pub fn refused_arguments(e: &clap::Error, args: &[String], lang: Lang) -> Option<String> {
    let words = match e.kind() {
        ErrorKind::ValueValidation => invalid_value(e, lang),
        ErrorKind::UnknownArgument => match negative_number(e, args) {
            Some((flag, value)) => Some(negative(args, &flag, &value, lang)),
            None if lang == Lang::Pt => unknown_argument(e),
            None => None,
        },
        _ if lang == Lang::En => None,
        ErrorKind::InvalidValue => Some(not_a_choice(e)),
        ErrorKind::InvalidSubcommand => Some(unknown_subcommand(e)),
        ErrorKind::MissingRequiredArgument => Some(format!(
            "faltam argumentos obrigatórios: {}",
            strings(e, ContextKind::InvalidArg).join(", ")
        )),
        ErrorKind::ArgumentConflict => Some(conflict(e)),
        ErrorKind::TooManyValues => Some(format!(
            "valor a mais '{}' para '{}'",
            string(e, ContextKind::InvalidValue).unwrap_or_default(),
            string(e, ContextKind::InvalidArg).unwrap_or_default()
        )),
        ErrorKind::TooFewValues | ErrorKind::WrongNumberOfValues => Some(format!(
            "'{}' precisa de {} valores, mas recebeu {}",
            string(e, ContextKind::InvalidArg).unwrap_or_default(),
            number(e, ContextKind::ExpectedNumValues)
                .or_else(|| number(e, ContextKind::MinValues))
                .map_or_else(|| "mais".to_string(), |n| n.to_string()),
            number(e, ContextKind::ActualNumValues).unwrap_or(0)
        )),
        ErrorKind::NoEquals => Some(format!(
            "'{}' pede um sinal de igual antes do valor (--opção=valor)",
            string(e, ContextKind::InvalidArg).unwrap_or_default()
        )),
        ErrorKind::InvalidUtf8 => Some("um argumento não é texto UTF-8 válido".to_string()),
        _ => None,
    }?;
    Some(format!(
        "{words}\n\n{}",
        lang.pick(
            "For more information, try '--help'.",
            "Para mais informações, use '--help'."
        )
    ))
}

/// The text of context `kind`, if it is one string.
fn string(e: &clap::Error, kind: ContextKind) -> Option<String> {
    match e.get(kind) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        Some(ContextValue::Strings(s)) => s.first().cloned(),
        _ => None,
    }
}

/// The texts of context `kind`.
fn strings(e: &clap::Error, kind: ContextKind) -> Vec<String> {
    match e.get(kind) {
        Some(ContextValue::String(s)) => vec![s.clone()],
        Some(ContextValue::Strings(s)) => s.clone(),
        _ => Vec::new(),
    }
}

fn number(e: &clap::Error, kind: ContextKind) -> Option<isize> {
    match e.get(kind) {
        Some(ContextValue::Number(n)) => Some(*n),
        _ => None,
    }
}

/// A value its parser refused: which flag, and why, from the parser's own error.
fn invalid_value(e: &clap::Error, lang: Lang) -> Option<String> {
    let arg = string(e, ContextKind::InvalidArg)?;
    let value = string(e, ContextKind::InvalidValue).unwrap_or_default();
    let source = std::error::Error::source(e)?;
    let why = if let Some(p) = source.downcast_ref::<ParseError>() {
        parse_words(p, lang)
    } else if let Some(n) = source.downcast_ref::<StartsError>() {
        super::Localize::text(n, lang)
    } else if let Some(n) = source.downcast_ref::<std::num::ParseIntError>() {
        whole_number(n, &value, lang)
    } else if let Some(_f) = source.downcast_ref::<std::num::ParseFloatError>() {
        lang.pick(
            format!("'{value}' is not a number"),
            format!("'{value}' não é um número"),
        )
    } else if lang == Lang::En {
        return None;
    } else {
        source.to_string()
    };
    Some(lang.pick(
        format!("invalid value '{value}' for '{arg}': {why}"),
        format!("valor inválido '{value}' para '{arg}': {why}"),
    ))
}

/// Why `value` is not the whole number a flag takes.
fn whole_number(e: &std::num::ParseIntError, value: &str, lang: Lang) -> String {
    use std::num::IntErrorKind;
    match e.kind() {
        IntErrorKind::Empty => lang.pick(
            "a whole number is needed here".to_string(),
            "aqui é preciso um número inteiro".to_string(),
        ),
        IntErrorKind::PosOverflow | IntErrorKind::NegOverflow => lang.pick(
            format!("{value} is too large for this flag"),
            format!("{value} é grande demais para esta opção"),
        ),
        _ if value.starts_with('-') => lang.pick(
            format!("'{value}' is negative: this flag takes a whole number from 0 up"),
            format!("'{value}' é negativo: esta opção recebe um número inteiro a partir de 0"),
        ),
        _ => lang.pick(
            format!("'{value}' is not a whole number: write it in digits only, like 1000"),
            format!("'{value}' não é um número inteiro: escreva-o só com algarismos, como 1000"),
        ),
    }
}

/// An unknown "argument" that is a negative number, with the flag just before it.
fn negative_number(e: &clap::Error, args: &[String]) -> Option<(String, String)> {
    let value = string(e, ContextKind::InvalidArg)?;
    value.strip_prefix('-')?.parse::<f64>().ok()?;
    let at = args.iter().position(|a| *a == value)?;
    let flag = args.get(at.checked_sub(1)?)?;
    flag.starts_with("--")
        .then(|| (flag.clone(), value.clone()))
}

/// A negative number after `flag`: what the flag takes. A flag that takes a negative value
/// reads a leading hyphen as part of it, so one that reads it as a flag takes none: a count
/// takes a whole number from 0 up, anything else a value that is not negative.
fn negative(args: &[String], flag: &str, value: &str, lang: Lang) -> String {
    if counts(args, flag) {
        return lang.pick(
            format!("{flag} takes a whole number from 0 up, not {value}"),
            format!("{flag} recebe um número inteiro a partir de 0, não {value}"),
        );
    }
    lang.pick(
        format!("{flag} takes no negative value, and {value} was given"),
        format!("{flag} não aceita valor negativo, e foi dado {value}"),
    )
}

/// Whether `flag` of the subcommand named in `args` takes an unsigned whole number.
fn counts(args: &[String], flag: &str) -> bool {
    use clap::CommandFactory;
    let command = crate::cli::Cli::command();
    let long = flag.trim_start_matches('-');
    let sub = args
        .iter()
        .skip(1)
        .find_map(|a| command.find_subcommand(a.as_str()));
    let id = |p: clap::builder::ValueParser| p.type_id();
    let unsigned = [
        id(clap::value_parser!(usize).into()),
        id(clap::value_parser!(u64).into()),
        id(clap::value_parser!(u32).into()),
        id(clap::value_parser!(u8).into()),
    ];
    sub.into_iter()
        .flat_map(|s| s.get_arguments())
        .chain(command.get_arguments())
        .find(|a| a.get_long() == Some(long))
        .is_some_and(|a| unsigned.contains(&a.get_value_parser().type_id()))
}

fn unknown_argument(e: &clap::Error) -> Option<String> {
    let arg = string(e, ContextKind::InvalidArg)?;
    let tip = string(e, ContextKind::SuggestedArg)
        .map(|s| format!("\n\n  dica: existe uma opção parecida: '{s}'"))
        .unwrap_or_default();
    Some(format!("argumento inesperado '{arg}'{tip}"))
}

fn not_a_choice(e: &clap::Error) -> String {
    let arg = string(e, ContextKind::InvalidArg).unwrap_or_default();
    let value = string(e, ContextKind::InvalidValue).unwrap_or_default();
    let possible = strings(e, ContextKind::ValidValue).join(", ");
    if value.is_empty() {
        return format!("'{arg}' pede um valor, e nenhum foi dado (valores possíveis: {possible})");
    }
    format!("valor inválido '{value}' para '{arg}': os valores possíveis são {possible}")
}

fn unknown_subcommand(e: &clap::Error) -> String {
    use clap::CommandFactory;
    let name = string(e, ContextKind::InvalidSubcommand).unwrap_or_default();
    let known: Vec<String> = crate::cli::Cli::command()
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect();
    let tip = string(e, ContextKind::SuggestedSubcommand)
        .map(|s| format!("; talvez '{s}'"))
        .unwrap_or_default();
    format!(
        "subcomando desconhecido '{name}'{tip}; os subcomandos são {}",
        known.join(", ")
    )
}

fn conflict(e: &clap::Error) -> String {
    let arg = string(e, ContextKind::InvalidArg).unwrap_or_default();
    let prior = strings(e, ContextKind::PriorArg);
    match prior.as_slice() {
        [] => format!("o argumento '{arg}' não pode ser usado aqui"),
        [p] if *p == arg => format!("o argumento '{arg}' não pode ser dado mais de uma vez"),
        _ => format!(
            "o argumento '{arg}' não pode ser usado com '{}'",
            prior.join("', '")
        ),
    }
}
