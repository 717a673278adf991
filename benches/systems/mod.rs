//! 2,000 random systems of orders 1–8 from a fixed seed (issue 22, item 18): the same
//! systems before and after a change, for `benches/step.rs` (the metrics in process) and
//! `benches/batch.rs` (`degrau step --batch` as a whole process, python-control beside it).
//!
//! Each system: an order n uniform in 1..=8; ⌊n/2⌋ or fewer lightly to well damped pairs
//! (ωn log-uniform in [0.1, 10] rad/s, ζ uniform in [0.05, 0.95]), the other poles real
//! (log-uniform in [−10, −0.1]); up to n − 1 real zeros (log-uniform moduli in [0.1, 10],
//! one in five in the right half plane); a static gain uniform in [0.5, 5]. Even lines give
//! the system as poles and zeros, odd ones as the coefficients of num and den, so the root
//! finding of the command line is timed too. Nothing is filtered: a random pole may fall
//! close to another (a cluster), as it would in a class's batch.

use degrau::lti::{C64, TransferFunction};

/// How many systems, and the seed they come from.
pub const COUNT: usize = 2000;
pub const SEED: u64 = 22_18;

/// One random system and the JSON line that gives it to `degrau step --batch`.
pub struct System {
    pub tf: TransferFunction,
    pub line: String,
}

/// SplitMix64: small, fixed, and the same on every machine.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Log-uniform in [lo, hi].
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.uniform(lo.ln(), hi.ln()).exp()
    }

    /// Uniform in 0..=n.
    fn up_to(&mut self, n: usize) -> usize {
        (self.next() % (n as u64 + 1)) as usize
    }
}

/// The poles, zeros and static gain of one random system.
fn draw(random: &mut Random) -> (Vec<C64>, Vec<C64>, f64) {
    let order = 1 + random.up_to(7);
    let pairs = random.up_to(order / 2);
    let mut poles = Vec::with_capacity(order);
    for _ in 0..pairs {
        let wn = random.log_uniform(0.1, 10.0);
        let zeta: f64 = random.uniform(0.05, 0.95);
        let (re, im) = (-zeta * wn, wn * (1.0 - zeta * zeta).sqrt());
        poles.extend([C64::new(re, im), C64::new(re, -im)]);
    }
    while poles.len() < order {
        poles.push(C64::new(-random.log_uniform(0.1, 10.0), 0.0));
    }
    let zeros = (0..random.up_to(order - 1))
        .map(|_| {
            let modulus = random.log_uniform(0.1, 10.0);
            let side = if random.unit() < 0.2 { 1.0 } else { -1.0 };
            C64::new(side * modulus, 0.0)
        })
        .collect();
    (poles, zeros, random.uniform(0.5, 5.0))
}

fn pairs(roots: &[C64]) -> String {
    let items: Vec<String> = roots
        .iter()
        .map(|r| format!("[{:?},{:?}]", r.re, r.im))
        .collect();
    format!("[{}]", items.join(","))
}

fn list(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
    format!("[{}]", items.join(","))
}

/// The systems, in order; the same on every run.
pub fn systems() -> Vec<System> {
    let mut random = Random(SEED);
    (0..COUNT)
        .map(|i| {
            let (poles, zeros, dc_gain) = draw(&mut random);
            let tf = TransferFunction::from_zpk(&zeros, &poles, 1.0)
                .and_then(|g| g.with_dc_gain(dc_gain))
                .expect("a valid random system");
            let line = if i % 2 == 0 {
                format!(
                    r#"{{"id":{i},"poles":{},"zeros":{},"dc_gain":{dc_gain:?}}}"#,
                    pairs(&poles),
                    pairs(&zeros)
                )
            } else {
                format!(
                    r#"{{"id":{i},"num":{},"den":{}}}"#,
                    list(&tf.num()),
                    list(&tf.den())
                )
            };
            System { tf, line }
        })
        .collect()
}

/// The batch input: one JSON line per system.
#[allow(dead_code)]
pub fn batch_input(systems: &[System]) -> String {
    systems.iter().map(|s| s.line.clone() + "\n").collect()
}
