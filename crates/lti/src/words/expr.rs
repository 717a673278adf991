//! The words around y(t) in closed form ([`crate::expr`]): where a delayed response holds,
//! and the note on a form written with repeated poles in place of a cluster of distinct
//! ones, in English and Brazilian Portuguese (the numbers come already written).

use degrau_words::Lang;
#[cfg(test)]
use degrau_words::Message;

/// "for t ≥ θ (y = 0 before θ)", with θ as written.
pub fn after_the_delay(delay: &str, lang: Lang) -> String {
    lang.pick(
        format!("for t ≥ {delay} (y = 0 before {delay})"),
        format!("para t ≥ {delay} (y = 0 antes de {delay})"),
    )
}

/// A cluster of distinct `poles` written as one pole of multiplicity `k` at `at`.
pub fn cluster(poles: &[String], k: usize, at: &str, lang: Lang) -> String {
    lang.pick(
        format!("the poles {} as a {k}-fold pole at {at}", poles.join(", ")),
        format!(
            "os polos {} como um polo de multiplicidade {k} em {at}",
            poles.join("; ")
        ),
    )
}

/// The note after a form written with repeated poles (the `clusters` as [`cluster`] says
/// them): how far it is from the exact y(t), `error` as written, or that it drifts away
/// when the error is unbounded.
pub fn approximation_note(clusters: &[String], error: Option<&str>, lang: Lang) -> String {
    let size = match error {
        Some(e) => lang.pick(
            format!("differs from the exact y(t) by up to {e}"),
            format!("difere do y(t) exato em até {e}"),
        ),
        None => lang
            .pick(
                "drifts away from the exact y(t) as t grows",
                "afasta-se do y(t) exato à medida que t cresce",
            )
            .to_string(),
    };
    lang.pick(
        format!(
            " [written with {}; this form {size}, while the curve and the metrics use the \
             exact response]",
            clusters.join(" and ")
        ),
        format!(
            " [escrita com {}; esta forma {size}, enquanto a curva e as métricas usam a \
             resposta exata]",
            clusters.join(" e ")
        ),
    )
}

/// An example of each, for the test of every message.
#[cfg(test)]
pub fn messages() -> Vec<Message> {
    let poles = ["-1".to_string(), "-1.0001".to_string()];
    let pair = |lang| cluster(&poles, 2, "-1.00005", lang);
    vec![
        Message::said("expr::after_the_delay", |lang| after_the_delay("0.5", lang)),
        Message::said("expr::cluster", pair),
        Message::said("expr::approximation_note", |lang| {
            approximation_note(&[pair(lang)], Some("1e-9"), lang)
        }),
        Message::said("expr::approximation_note::drifts", |lang| {
            approximation_note(&[pair(lang)], None, lang)
        }),
    ]
}
