//! Expressions a student types, read once and evaluated many times in complex arithmetic:
//! a transfer function `10/(s+2)`, `10K/(s^2 + 0,3s + 10K)`, a closed form
//! `1 - e^{-5t}`, `1/20 + (t/2 - 1/20)·exp(-10t)`, a number `15/4`.
//!
//! This module owns that syntax (lti's [`degrau_lti::parse`] reads numbers and lists of
//! roots, not expressions, and no other crate reads expressions):
//! - numbers with a decimal point, or a decimal comma between two digits (`0,3`), and an
//!   exponent (`2.5e-3`);
//! - the variables `s`, `t`, `K` (or `k`) and `a`; `j` (or `i`) the imaginary unit; `e` and
//!   `pi`/`π` the constants;
//! - `+ - * / ^` (also `−`, `·`, `×`, and superscript powers `s²`), brackets `()`, `[]`,
//!   `{}`; a product may be implicit (`10K`, `2s`, `(s+1)(s+2)`, `t e^{-t}`);
//! - the functions `exp`, `sin`, `cos`, `tan`, `sqrt`, `ln`, `log` (natural), with or
//!   without brackets around a tight product (`sin 2t`);
//! - an exponent binds a sign and a tight product (`e^-5t` is e^(−5t)); `-s^2` is −(s²).
//!
//! A leading `y(t) =`, `G(s) =` (anything up to the last `=`) is ignored.

use degrau_lti::C64;

/// Why a text is not an expression: a typed fact, said by [`crate::words`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ExprError {
    #[error("empty expression")]
    Empty,
    #[error("unexpected character {0:?}")]
    Character(char),
    #[error("unknown name {0:?}")]
    Name(String),
    #[error("a bracket is not closed or not opened")]
    Bracket,
    #[error("the expression ends too early or has something left over")]
    Syntax,
    #[error("the variable {0} is not part of this answer")]
    Variable(char),
    #[error("the expression is too long or too deeply bracketed")]
    TooLong,
}

/// The most tokens an expression may have.
const MAX_TOKENS: usize = 400;
/// The deepest nesting of brackets accepted.
const MAX_DEPTH: usize = 32;

/// The variables an expression may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    S,
    T,
    K,
    A,
}

impl Var {
    fn letter(self) -> char {
        match self {
            Var::S => 's',
            Var::T => 't',
            Var::K => 'K',
            Var::A => 'a',
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Func {
    Exp,
    Sin,
    Cos,
    Tan,
    Sqrt,
    Ln,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

#[derive(Debug, Clone, PartialEq)]
enum Node {
    Num(C64),
    Var(Var),
    Neg(Box<Node>),
    Bin(Op, Box<Node>, Box<Node>),
    Call(Func, Box<Node>),
}

/// A parsed expression.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    root: Node,
}

/// Values of the variables for one evaluation (unset ones are refused by [`Expr::uses`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Env {
    pub s: C64,
    pub t: f64,
    pub k: f64,
    pub a: f64,
}

impl Expr {
    /// Reads `text` (anything up to the last `=` ignored).
    pub fn parse(text: &str) -> Result<Self, ExprError> {
        let body = text.rsplit(['=', '≈']).next().unwrap_or(text);
        let tokens = tokenize(body)?;
        if tokens.is_empty() {
            return Err(ExprError::Empty);
        }
        // A typed answer is short; a bound keeps the recursive reading's depth small.
        let mut depth = 0usize;
        let mut deepest = 0usize;
        for t in &tokens {
            match t {
                Token::Open => depth += 1,
                Token::Close => depth = depth.saturating_sub(1),
                _ => {}
            }
            deepest = deepest.max(depth);
        }
        if tokens.len() > MAX_TOKENS || deepest > MAX_DEPTH {
            return Err(ExprError::TooLong);
        }
        let mut parser = Parser { tokens, at: 0 };
        let root = parser.sum()?;
        if parser.at != parser.tokens.len() {
            return Err(match parser.tokens[parser.at] {
                Token::Close => ExprError::Bracket,
                _ => ExprError::Syntax,
            });
        }
        Ok(Self { root })
    }

    /// Refuses a variable outside `allowed`.
    pub fn uses_only(&self, allowed: &[Var]) -> Result<(), ExprError> {
        let mut found = Vec::new();
        collect(&self.root, &mut found);
        match found.into_iter().find(|v| !allowed.contains(v)) {
            Some(v) => Err(ExprError::Variable(v.letter())),
            None => Ok(()),
        }
    }

    /// The value for these variables.
    pub fn eval(&self, env: &Env) -> C64 {
        eval(&self.root, env)
    }
}

fn collect(node: &Node, out: &mut Vec<Var>) {
    match node {
        Node::Num(_) => {}
        Node::Var(v) => out.push(*v),
        Node::Neg(a) | Node::Call(_, a) => collect(a, out),
        Node::Bin(_, a, b) => {
            collect(a, out);
            collect(b, out);
        }
    }
}

fn eval(node: &Node, env: &Env) -> C64 {
    match node {
        Node::Num(x) => *x,
        Node::Var(Var::S) => env.s,
        Node::Var(Var::T) => C64::new(env.t, 0.0),
        Node::Var(Var::K) => C64::new(env.k, 0.0),
        Node::Var(Var::A) => C64::new(env.a, 0.0),
        Node::Neg(a) => -eval(a, env),
        Node::Call(f, a) => {
            let x = eval(a, env);
            match f {
                Func::Exp => x.exp(),
                Func::Sin => x.sin(),
                Func::Cos => x.cos(),
                Func::Tan => x.tan(),
                Func::Sqrt => x.sqrt(),
                Func::Ln => x.ln(),
            }
        }
        Node::Bin(op, a, b) => {
            let (x, y) = (eval(a, env), eval(b, env));
            match op {
                Op::Add => x + y,
                Op::Sub => x - y,
                Op::Mul => x * y,
                Op::Div => x / y,
                Op::Pow => power(x, y),
            }
        }
    }
}

/// x^y, exact for small integer powers (s² of a negative real stays real).
fn power(x: C64, y: C64) -> C64 {
    if y.im == 0.0 && y.re.fract() == 0.0 && y.re.abs() <= 64.0 {
        x.powi(y.re as i32)
    } else if x.im == 0.0 && x.re > 0.0 {
        (y * x.re.ln()).exp()
    } else {
        x.powc(y)
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Token {
    Num(f64),
    Var(Var),
    Imag,
    Func(Func),
    Op(Op),
    Open,
    Close,
}

fn tokenize(text: &str) -> Result<Vec<Token>, ExprError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit()
            || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
        {
            let (x, next) = number(&chars, i)?;
            out.push(Token::Num(x));
            i = next;
        } else if c.is_alphabetic() && !"²³".contains(c) {
            let start = i;
            while i < chars.len() && chars[i].is_alphabetic() && !"²³".contains(chars[i]) {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            words(&word, &mut out)?;
        } else {
            let token = match c {
                '+' => Token::Op(Op::Add),
                '-' | '−' | '–' => Token::Op(Op::Sub),
                '*' | '·' | '×' | '⋅' => Token::Op(Op::Mul),
                '/' | '÷' => Token::Op(Op::Div),
                '^' => Token::Op(Op::Pow),
                '(' | '[' | '{' => Token::Open,
                ')' | ']' | '}' => Token::Close,
                '²' | '³' => {
                    out.push(Token::Op(Op::Pow));
                    Token::Num(if c == '²' { 2.0 } else { 3.0 })
                }
                other => return Err(ExprError::Character(other)),
            };
            out.push(token);
            i += 1;
        }
    }
    Ok(out)
}

/// A number starting at `i`: digits, one decimal point or a comma between two digits, an
/// exponent `e±d` only when digits follow it.
fn number(chars: &[char], mut i: usize) -> Result<(f64, usize), ExprError> {
    let mut text = String::new();
    let digit = |k: usize| chars.get(k).is_some_and(char::is_ascii_digit);
    let mut separator = false;
    while i < chars.len() {
        let c = chars[i];
        if c.is_ascii_digit() {
            text.push(c);
        } else if (c == '.' || (c == ',' && i > 0 && digit(i - 1) && digit(i + 1))) && !separator {
            separator = true;
            text.push('.');
        } else {
            break;
        }
        i += 1;
    }
    if matches!(chars.get(i), Some('e' | 'E')) {
        let sign = matches!(chars.get(i + 1), Some('+' | '-'));
        let first = if sign { i + 2 } else { i + 1 };
        if digit(first) {
            text.push('e');
            if sign {
                text.push(chars[i + 1]);
            }
            i = first;
            while digit(i) {
                text.push(chars[i]);
                i += 1;
            }
        }
    }
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok((x, i)),
        _ => Err(ExprError::Syntax),
    }
}

/// A run of letters: a function or constant name, else single-letter variables side by side
/// (`Ks` is K·s, `te` is t·e).
fn words(word: &str, out: &mut Vec<Token>) -> Result<(), ExprError> {
    let func = match word.to_lowercase().as_str() {
        "exp" => Some(Func::Exp),
        "sin" | "sen" => Some(Func::Sin),
        "cos" => Some(Func::Cos),
        "tan" | "tg" => Some(Func::Tan),
        "sqrt" | "raiz" => Some(Func::Sqrt),
        "ln" | "log" => Some(Func::Ln),
        _ => None,
    };
    if let Some(f) = func {
        out.push(Token::Func(f));
        return Ok(());
    }
    if matches!(word, "pi" | "π") {
        out.push(Token::Num(std::f64::consts::PI));
        return Ok(());
    }
    for c in word.chars() {
        out.push(match c {
            's' => Token::Var(Var::S),
            't' => Token::Var(Var::T),
            'K' | 'k' => Token::Var(Var::K),
            'a' => Token::Var(Var::A),
            'j' | 'i' => Token::Imag,
            'e' => Token::Num(std::f64::consts::E),
            'π' => Token::Num(std::f64::consts::PI),
            _ => return Err(ExprError::Name(word.to_string())),
        });
    }
    Ok(())
}

struct Parser {
    tokens: Vec<Token>,
    at: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }

    fn sum(&mut self) -> Result<Node, ExprError> {
        let mut left = self.product()?;
        while let Some(Token::Op(op @ (Op::Add | Op::Sub))) = self.peek().cloned() {
            self.at += 1;
            let right = self.product()?;
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn starts_primary(&self) -> bool {
        matches!(
            self.peek(),
            Some(Token::Num(_) | Token::Var(_) | Token::Imag | Token::Func(_) | Token::Open)
        )
    }

    fn product(&mut self) -> Result<Node, ExprError> {
        let mut left = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(Token::Op(op @ (Op::Mul | Op::Div))) => {
                    let op = *op;
                    self.at += 1;
                    op
                }
                _ if self.starts_primary() => Op::Mul,
                _ => break,
            };
            let right = self.unary()?;
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<Node, ExprError> {
        match self.peek() {
            Some(Token::Op(Op::Sub)) => {
                self.at += 1;
                Ok(Node::Neg(Box::new(self.unary()?)))
            }
            Some(Token::Op(Op::Add)) => {
                self.at += 1;
                self.unary()
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Result<Node, ExprError> {
        let base = self.primary()?;
        if let Some(Token::Op(Op::Pow)) = self.peek() {
            self.at += 1;
            let exponent = self.tight()?;
            return Ok(Node::Bin(Op::Pow, Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    /// A sign and primaries side by side (an exponent, a function's bare argument).
    fn tight(&mut self) -> Result<Node, ExprError> {
        let negative = match self.peek() {
            Some(Token::Op(Op::Sub)) => {
                self.at += 1;
                true
            }
            Some(Token::Op(Op::Add)) => {
                self.at += 1;
                false
            }
            _ => false,
        };
        let bracketed = matches!(self.peek(), Some(Token::Open));
        let mut node = self.primary()?;
        // `e^-5t` chains t; `e^{-t}[cos 2t]` does not chain the bracket after the group.
        while !bracketed
            && matches!(
                self.peek(),
                Some(Token::Num(_) | Token::Var(_) | Token::Imag)
            )
        {
            let next = self.primary()?;
            node = Node::Bin(Op::Mul, Box::new(node), Box::new(next));
        }
        Ok(if negative {
            Node::Neg(Box::new(node))
        } else {
            node
        })
    }

    fn primary(&mut self) -> Result<Node, ExprError> {
        let token = self.peek().cloned().ok_or(ExprError::Syntax)?;
        self.at += 1;
        match token {
            Token::Num(x) => Ok(Node::Num(C64::new(x, 0.0))),
            Token::Var(v) => Ok(Node::Var(v)),
            Token::Imag => Ok(Node::Num(C64::new(0.0, 1.0))),
            Token::Open => {
                let inner = self.sum()?;
                match self.peek() {
                    Some(Token::Close) => {
                        self.at += 1;
                        Ok(inner)
                    }
                    _ => Err(ExprError::Bracket),
                }
            }
            Token::Func(f) => {
                let argument = if matches!(self.peek(), Some(Token::Open)) {
                    self.power()?
                } else {
                    self.tight()?
                };
                Ok(Node::Call(f, Box::new(argument)))
            }
            Token::Close => Err(ExprError::Bracket),
            Token::Op(_) => Err(ExprError::Syntax),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at_t(text: &str, t: f64) -> f64 {
        let env = Env {
            t,
            ..Env::default()
        };
        Expr::parse(text)
            .map(|e| e.eval(&env).re)
            .unwrap_or(f64::NAN)
    }

    fn at_s(text: &str, s: C64, k: f64) -> C64 {
        let env = Env {
            s,
            k,
            ..Env::default()
        };
        Expr::parse(text)
            .map(|e| e.eval(&env))
            .unwrap_or(C64::new(f64::NAN, 0.0))
    }

    #[test]
    fn closed_forms_in_every_spelling() {
        let t: f64 = 0.3;
        let y = 1.0 - (-5.0 * t).exp();
        for text in [
            "1 - e^{-5t}",
            "1-exp(-5*t)",
            "y(t) = 1 − e^(−5t)",
            "1 - e^-5t",
            "1 - 1·e^{-5t}",
        ] {
            assert!((at_t(text, t) - y).abs() < 1e-12, "{text}");
        }
        let y = 0.05 + (t / 2.0 - 0.05) * (-10.0 * t).exp();
        for text in [
            "1/20 + (1/2*t - 1/20)*exp(-10*t)",
            "1/20+(t/2-1/20)e^{-10t}",
            "0,05 + (0,5t - 0,05) e^{-10t}",
        ] {
            assert!((at_t(text, t) - y).abs() < 1e-12, "{text}");
        }
        let y = 1.0 - (-t).exp() * ((2.0 * t).cos() - 0.5 * (2.0 * t).sin());
        for text in [
            "1 - e^{-t}[cos(2t) - 1/2 sin(2t)]",
            "1 − e^{−t}[cos 2t − (1/2) sin 2t]",
            "-exp(-t)*cos(2*t)+1/2*exp(-t)*sin(2*t)+1",
        ] {
            assert!((at_t(text, t) - y).abs() < 1e-12, "{text}");
        }
    }

    #[test]
    fn transfer_functions_with_a_gain() {
        let s = C64::new(0.4, 1.3);
        let k = 0.7;
        let g = C64::new(10.0 * k, 0.0) / (s * s + s * 0.3 + 10.0 * k);
        for text in [
            "10K/(s^2+0.3s+10K)",
            "10*K/(s²+0,3*s+10*K)",
            "(10 k)/(s s + 0.3 s + 10 k)",
        ] {
            assert!((at_s(text, s, k) - g).norm() < 1e-12, "{text}");
        }
        let g = (s + 2.0) / (s * (s + 4.0));
        assert!((at_s("(s+2)/(s(s+4))", s, k) - g).norm() < 1e-12);
        assert!((at_s("-s^2", s, k) + s * s).norm() < 1e-12);
        assert!((at_s("2e-3s", s, k) - s * 2e-3).norm() < 1e-15);
    }

    #[test]
    fn bad_expressions_are_refused() {
        assert_eq!(Expr::parse("  "), Err(ExprError::Empty));
        assert_eq!(Expr::parse("(s+1"), Err(ExprError::Bracket));
        assert_eq!(Expr::parse("s+1)"), Err(ExprError::Bracket));
        assert_eq!(Expr::parse("1+"), Err(ExprError::Syntax));
        assert!(matches!(Expr::parse("x+1"), Err(ExprError::Name(_))));
        assert!(matches!(
            Expr::parse("1 $ 2"),
            Err(ExprError::Character('$'))
        ));
        let e = Expr::parse("K/(s+1)").map(|e| e.uses_only(&[Var::S]));
        assert_eq!(e, Ok(Err(ExprError::Variable('K'))));
    }
}
