//! The step response of a system with distinct poles in 768-bit arithmetic (astro-float):
//! the plain residue formula y(t) = A·k·[Π(−z)/Π(−p) + Σᵢ Π(pᵢ − z)/(pᵢ·Π_{j≠i}(pᵢ − pⱼ))·
//! e^{pᵢt}], an independent reference for the library's closed form and for c2d's samples,
//! where the cancellation of the residues (~1/δ^{m−1} for poles δ apart, ~1/t^r near t = 0
//! for a relative degree r) leaves well over 100 bits. It shares nothing with the library.
#![allow(dead_code)] // each test binary uses its own subset

use astro_float::{BigFloat, Consts, Radix, RoundingMode};
use degrau_lti::C64;

const BITS: usize = 768;
const RM: RoundingMode = RoundingMode::ToEven;

#[derive(Clone)]
pub struct Big {
    re: BigFloat,
    im: BigFloat,
}

impl Big {
    pub fn new(c: C64) -> Self {
        Self {
            re: BigFloat::from_f64(c.re, BITS),
            im: BigFloat::from_f64(c.im, BITS),
        }
    }
    pub fn add(&self, o: &Self) -> Self {
        Self {
            re: self.re.add(&o.re, BITS, RM),
            im: self.im.add(&o.im, BITS, RM),
        }
    }
    pub fn sub(&self, o: &Self) -> Self {
        Self {
            re: self.re.sub(&o.re, BITS, RM),
            im: self.im.sub(&o.im, BITS, RM),
        }
    }
    pub fn mul(&self, o: &Self) -> Self {
        Self {
            re: self
                .re
                .mul(&o.re, BITS, RM)
                .sub(&self.im.mul(&o.im, BITS, RM), BITS, RM),
            im: self
                .re
                .mul(&o.im, BITS, RM)
                .add(&self.im.mul(&o.re, BITS, RM), BITS, RM),
        }
    }
    pub fn div(&self, o: &Self) -> Self {
        let n =
            o.re.mul(&o.re, BITS, RM)
                .add(&o.im.mul(&o.im, BITS, RM), BITS, RM);
        let conj = Self {
            re: o.re.clone(),
            im: o.im.neg(),
        };
        let p = self.mul(&conj);
        Self {
            re: p.re.div(&n, BITS, RM),
            im: p.im.div(&n, BITS, RM),
        }
    }
    /// e^{self·t}.
    pub fn exp_times(&self, t: f64, cc: &mut Consts) -> Self {
        let t = BigFloat::from_f64(t, BITS);
        let a = self.re.mul(&t, BITS, RM).exp(BITS, RM, cc);
        let w = self.im.mul(&t, BITS, RM);
        Self {
            re: a.mul(&w.cos(BITS, RM, cc), BITS, RM),
            im: a.mul(&w.sin(BITS, RM, cc), BITS, RM),
        }
    }
}

pub fn to_f64(x: &BigFloat, cc: &mut Consts) -> f64 {
    let text = x.format(Radix::Dec, RM, cc).expect("a decimal form");
    text.parse().expect("a decimal number")
}

/// The step response of A·k·Π(s − z)/Π(s − p), distinct poles, in high precision.
pub struct Reference {
    /// (pole, A·k·Π(p − z)/(p·Π(p − q))) per pole, conjugates included.
    residues: Vec<(Big, Big)>,
    constant: Big,
    cc: Consts,
}

impl Reference {
    pub fn new(zeros: &[C64], poles: &[C64], scale: f64) -> Self {
        let one = Big::new(C64::new(1.0, 0.0));
        let zero = Big::new(C64::new(0.0, 0.0));
        let k = Big::new(C64::new(scale, 0.0));
        let product = |s: &Big, roots: &[C64], skip: Option<usize>| {
            roots
                .iter()
                .enumerate()
                .filter(|&(i, _)| Some(i) != skip)
                .fold(one.clone(), |acc, (_, &r)| acc.mul(&s.sub(&Big::new(r))))
        };
        let constant = k
            .mul(&product(&zero, zeros, None))
            .div(&product(&zero, poles, None));
        let residues = (0..poles.len())
            .map(|i| {
                let p = Big::new(poles[i]);
                let r = k
                    .mul(&product(&p, zeros, None))
                    .div(&p.mul(&product(&p, poles, Some(i))));
                (p, r)
            })
            .collect();
        Self {
            residues,
            constant,
            cc: Consts::new().expect("constants"),
        }
    }

    pub fn final_value(&mut self) -> f64 {
        let c = self.constant.re.clone();
        to_f64(&c, &mut self.cc)
    }

    pub fn value(&mut self, t: f64) -> f64 {
        let mut sum = self.constant.clone();
        for (p, r) in &self.residues {
            sum = sum.add(&r.mul(&p.exp_times(t, &mut self.cc)));
        }
        to_f64(&sum.re, &mut self.cc)
    }

    /// The first instant in [a, b] where y crosses `level` (y(a), y(b) on either side),
    /// by bisection to the last bit.
    pub fn crossing(&mut self, level: f64, mut a: f64, mut b: f64) -> f64 {
        let below_at_a = self.value(a) < level;
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            if (self.value(m) < level) == below_at_a {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    }
}
