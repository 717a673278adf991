//! The unity-feedback loop of a controller around a plant with a true dead time,
//! y = G0(s)·e^{−θs}·v, v = Cr(s)·r − C(s)·y (+ d), computed without replacing the delay.
//!
//! The loop is a delay-differential system. It is solved by the method of steps: time is cut
//! into steps of h = θ/m, so that the plant's input on a step is the controller's output on
//! the step one dead time earlier, already known. On each step that known input is the
//! polynomial of degree [`DEGREE`] through its values at the step's Chebyshev–Lobatto nodes,
//! and the loop's states (plant and controller) are propagated *exactly* under it: the
//! matrix exponential of the states augmented with the polynomial's chain (Van Loan 1978),
//! computed once per node offset. The only error is the interpolation of a signal that is
//! analytic inside each step (its kinks fall on multiples of θ, which are step boundaries),
//! and h is chosen below the loop's fastest time constant, so that error is below 1e-8 of
//! the step's size (the tests compare with an independent integration).
//!
//! Written here rather than taken from a crate: no Rust crate integrates delay equations
//! with an exact propagator between delay intervals, and a general DDE solver would
//! interpolate the stiff controller filter as well.

use nalgebra::DMatrix;

use super::controller::Controller;
use crate::TransferFunction;

/// The degree of the polynomial standing in for the delayed input on a step.
pub const DEGREE: usize = 7;
/// Nodes per step.
const NODES: usize = DEGREE + 1;
/// The most steps a response is allowed (beyond it the loop's fastest time constant is too
/// short for the time asked).
pub const MAX_STEPS: usize = 400_000;

/// Which input steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum LoopInput {
    /// A unit step of the setpoint r at t = 0.
    Setpoint,
    /// A unit step of a load disturbance d at the plant's input (before the dead time) at
    /// t = 0, the setpoint at 0.
    Load,
}

impl LoopInput {
    /// `setpoint` or `load` (the command line and the JSON).
    pub fn key(self) -> &'static str {
        match self {
            LoopInput::Setpoint => "setpoint",
            LoopInput::Load => "load",
        }
    }

    /// The input named by [`Self::key`].
    pub fn from_key(key: &str) -> Option<Self> {
        [LoopInput::Setpoint, LoopInput::Load]
            .into_iter()
            .find(|i| i.key().eq_ignore_ascii_case(key.trim()))
    }

    /// The value the output should reach: the setpoint (1) or the undisturbed output (0).
    pub fn reference(self) -> f64 {
        match self {
            LoopInput::Setpoint => 1.0,
            LoopInput::Load => 0.0,
        }
    }
}

/// How long to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Horizon {
    /// Until the output and the plant's input have settled to 1e-7 of their size (or the
    /// loop is found not to settle).
    Auto,
    /// Up to this time (s).
    Until(f64),
}

/// Why a loop response cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{}", degrau_words::Localize::text(self, degrau_words::Lang::En))]
pub enum DelayLoopError {
    /// The plant's and the controller's direct feedthroughs make 1 + C(∞)·G0(∞) = 0 (or so
    /// small that the loop is not well posed).
    NotWellPosed,
    /// The time asked is not a positive finite number of seconds.
    BadHorizon(f64),
    /// More than [`MAX_STEPS`] steps would be needed: the loop's fastest time constant (s)
    /// is too short beside the time asked or the dead time.
    TooManySteps { fastest: f64 },
}

/// A realization (A, B, C, D) in observable canonical form, flat row-major.
#[derive(Debug, Clone)]
struct Realization {
    n: usize,
    a: DMatrix<f64>,
    /// One column per input.
    b: DMatrix<f64>,
    c: Vec<f64>,
    /// One entry per input.
    d: Vec<f64>,
}

/// num_k(s)/den(s) for each numerator, sharing den (descending powers; deg num ≤ deg den).
fn observable(nums: &[Vec<f64>], den: &[f64]) -> Realization {
    let lead = den[0];
    let n = den.len() - 1;
    let a_coef: Vec<f64> = den[1..].iter().map(|c| c / lead).collect();
    let mut a = DMatrix::zeros(n, n);
    for i in 0..n {
        a[(i, 0)] = -a_coef[i];
        if i + 1 < n {
            a[(i, i + 1)] = 1.0;
        }
    }
    let mut b = DMatrix::zeros(n, nums.len());
    let mut d = Vec::with_capacity(nums.len());
    for (k, num) in nums.iter().enumerate() {
        // Pad to n + 1 coefficients, divide by the leading coefficient of den.
        let mut padded = vec![0.0; n + 1 - num.len().min(n + 1)];
        padded.extend(num.iter().map(|c| c / lead));
        let feed = padded[0];
        for i in 0..n {
            b[(i, k)] = padded[i + 1] - feed * a_coef[i];
        }
        d.push(feed);
    }
    let mut c = vec![0.0; n];
    if n > 0 {
        c[0] = 1.0;
    }
    Realization { n, a, b, c, d }
}

/// The loop's linear part with the delayed input w as a known forcing:
/// s' = M·s + E·w + G, v = H·s + J·w + K0, y = Y·s + Dp·w (s: plant then controller states).
#[derive(Debug, Clone)]
struct LoopSystem {
    n: usize,
    m: DMatrix<f64>,
    e: Vec<f64>,
    g: Vec<f64>,
    h: Vec<f64>,
    j: f64,
    k0: f64,
    y: Vec<f64>,
    dp: f64,
    /// A constant in y (only without a delay, from a biproper plant: Dp·K0/(1 − J)).
    y0: f64,
}

impl LoopSystem {
    fn new(plant: &TransferFunction, controller: &Controller, input: LoopInput) -> Self {
        let p = observable(&[plant.num()], &plant.den());
        let (num_r, den_c) = controller.reference_coeffs();
        let (num_f, _) = controller.feedback_coeffs();
        let minus_f: Vec<f64> = num_f.iter().map(|c| -c).collect();
        let c = observable(&[num_r, minus_f], &den_c);
        let (np, nc) = (p.n, c.n);
        let n = np + nc;
        let r = match input {
            LoopInput::Setpoint => 1.0,
            LoopInput::Load => 0.0,
        };
        let d = 1.0 - r;
        let dp = p.d[0];
        let (dr, dy) = (c.d[0], c.d[1]);
        let mut m = DMatrix::zeros(n, n);
        m.view_mut((0, 0), (np, np)).copy_from(&p.a);
        m.view_mut((np, np), (nc, nc)).copy_from(&c.a);
        for i in 0..nc {
            for k in 0..np {
                m[(np + i, k)] = c.b[(i, 1)] * p.c[k];
            }
        }
        let mut e = vec![0.0; n];
        let mut g = vec![0.0; n];
        for (i, ei) in e.iter_mut().take(np).enumerate() {
            *ei = p.b[(i, 0)];
        }
        for i in 0..nc {
            e[np + i] = c.b[(i, 1)] * dp;
            g[np + i] = c.b[(i, 0)] * r;
        }
        let mut h: Vec<f64> = p.c.iter().map(|ck| dy * ck).collect();
        h.resize(np, 0.0);
        h.extend_from_slice(&c.c);
        let mut y = vec![0.0; n];
        y[..np].copy_from_slice(&p.c);
        Self {
            n,
            m,
            e,
            g,
            h,
            j: dy * dp,
            k0: dr * r + d,
            y,
            dp,
            y0: 0.0,
        }
    }

    /// Without a dead time the loop closes algebraically: w = v = (H·s + K0)/(1 − J).
    fn closed_without_delay(&self) -> Self {
        let q = 1.0 / (1.0 - self.j);
        let mut m = self.m.clone();
        let mut g = self.g.clone();
        for i in 0..self.n {
            for k in 0..self.n {
                m[(i, k)] += self.e[i] * self.h[k] * q;
            }
            g[i] += self.e[i] * self.k0 * q;
        }
        // y = Y·s + Dp·w with w = (H·s + K0)/(1 − J).
        let y = self
            .y
            .iter()
            .zip(&self.h)
            .map(|(yk, hk)| yk + self.dp * hk * q)
            .collect();
        Self {
            m,
            g,
            e: vec![0.0; self.n],
            y,
            dp: 0.0,
            y0: self.dp * self.k0 * q,
            h: self.h.iter().map(|x| x * q).collect(),
            j: 0.0,
            k0: self.k0 * q,
            n: self.n,
        }
    }
}

/// Chebyshev–Lobatto node offsets on [0, h]: h·(1 − cos(πi/p))/2.
fn node_offsets(h: f64) -> [f64; NODES] {
    std::array::from_fn(|i| {
        h * (1.0 - (std::f64::consts::PI * i as f64 / DEGREE as f64).cos()) / 2.0
    })
}

/// The augmented matrix of Van Loan: states, the chain ξ0' = ξ1, …, ξp' = 0 whose ξ0 drives
/// the states through E (ξ(0) = e_j gives ξ0 = τ^j/j!), and a constant 1 driving G.
fn augmented(sys: &LoopSystem) -> DMatrix<f64> {
    let n = sys.n;
    let size = n + NODES + 1;
    let mut aug = DMatrix::zeros(size, size);
    aug.view_mut((0, 0), (n, n)).copy_from(&sys.m);
    for i in 0..n {
        aug[(i, n)] = sys.e[i];
        aug[(i, size - 1)] = sys.g[i];
    }
    for k in 0..DEGREE {
        aug[(n + k, n + k + 1)] = 1.0;
    }
    aug
}

/// The exact propagation over τ: s(τ) = Φ·s0 + Σ_j Γj·c_j + g, the c_j the forcing's
/// coefficients in the basis τ^j/j!.
#[derive(Debug, Clone)]
struct Propagator {
    phi: DMatrix<f64>,
    /// n × NODES: column j the response to τ^j/j!.
    gamma: DMatrix<f64>,
    g: Vec<f64>,
}

fn propagator(aug: &DMatrix<f64>, n: usize, tau: f64) -> Propagator {
    let ex = (aug * tau).exp();
    let size = aug.nrows();
    Propagator {
        phi: ex.view((0, 0), (n, n)).into_owned(),
        gamma: ex.view((0, n), (n, NODES)).into_owned(),
        g: (0..n).map(|i| ex[(i, size - 1)]).collect(),
    }
}

/// The map from the forcing's node values to its coefficients in the basis τ^j/j!.
fn coefficient_map(nodes: &[f64; NODES]) -> DMatrix<f64> {
    let mut v = DMatrix::zeros(NODES, NODES);
    for (i, &t) in nodes.iter().enumerate() {
        let mut term = 1.0;
        for j in 0..NODES {
            v[(i, j)] = term;
            term *= t / (j + 1) as f64;
        }
    }
    // The Vandermonde matrix at distinct nodes is invertible.
    v.try_inverse()
        .unwrap_or_else(|| DMatrix::zeros(NODES, NODES))
}

/// Per node: s_i = Φ_i·s0 + Q_i·w_nodes + g_i, each matrix flat row-major.
#[derive(Debug, Clone)]
struct NodeMaps {
    phi: Vec<Vec<f64>>,
    q: Vec<Vec<f64>>,
    g: Vec<Vec<f64>>,
}

fn row_major(m: &DMatrix<f64>) -> Vec<f64> {
    (0..m.nrows())
        .flat_map(|r| (0..m.ncols()).map(move |c| m[(r, c)]))
        .collect()
}

fn node_maps(sys: &LoopSystem, nodes: &[f64; NODES]) -> NodeMaps {
    let aug = augmented(sys);
    let vinv = coefficient_map(nodes);
    let mut maps = NodeMaps {
        phi: Vec::new(),
        q: Vec::new(),
        g: Vec::new(),
    };
    for &tau in nodes.iter() {
        let p = propagator(&aug, sys.n, tau);
        maps.q.push(row_major(&(&p.gamma * &vinv)));
        maps.phi.push(row_major(&p.phi));
        maps.g.push(p.g);
    }
    maps
}

/// The response of a loop to a unit step of its input: the output y and the plant's input
/// v at the nodes of every step, and what is needed to evaluate y anywhere.
#[derive(Debug, Clone)]
pub struct LoopResponse {
    pub input: LoopInput,
    /// θ (s).
    pub delay: f64,
    /// The step h (s): θ/m, or the loop's fastest time constant's share without a delay.
    pub step: f64,
    /// Node offsets within a step (s).
    offsets: [f64; NODES],
    /// y at the nodes, NODES per step.
    y: Vec<f64>,
    /// v (the controller's output plus the load) at the nodes, NODES per step.
    v: Vec<f64>,
    /// The states at each step's start, n per step.
    starts: Vec<f64>,
    /// Steps per dead time (0 without a delay).
    per_delay: usize,
    sys: LoopSystem,
    /// y(∞) (NaN when the loop has no steady state).
    pub final_value: f64,
    /// v(∞) (NaN when the loop has no steady state).
    pub final_input: f64,
    /// Whether y and v settled within the time computed (for [`Horizon::Auto`]).
    pub settled: bool,
}

/// The loop's steady state (y(∞), v(∞)) from the constant terms of its polynomials, NaN
/// when 1 + L(s) vanishes at s = 0 (a closed-loop pole at the origin).
fn steady_state(plant: &TransferFunction, c: &Controller, input: LoopInput) -> (f64, f64) {
    let at0 = |p: &[f64]| p.last().copied().unwrap_or(0.0);
    let (ng, dg) = (at0(&plant.num()), at0(&plant.den()));
    let (nr, dc) = {
        let (num, den) = c.reference_coeffs();
        (at0(&num), at0(&den))
    };
    let nf = at0(&c.feedback_coeffs().0);
    let den = dc * dg + nf * ng;
    if den == 0.0 {
        return (f64::NAN, f64::NAN);
    }
    match input {
        LoopInput::Setpoint => (nr * ng / den, nr * dg / den),
        LoopInput::Load => (ng * dc / den, dc * dg / den),
    }
}

/// The fastest rate (1/s) among the plant's and the controller's poles.
fn fastest_rate(plant: &TransferFunction, c: &Controller) -> f64 {
    let mut rate = plant.poles().iter().map(|p| p.norm()).fold(0.0, f64::max);
    let p = c.parallel();
    if p.tf > 0.0 {
        rate = rate.max(1.0 / p.tf);
    }
    rate
}

/// The unit-step response of the loop around `plant` (its dead time included exactly).
pub fn loop_response(
    plant: &TransferFunction,
    controller: &Controller,
    input: LoopInput,
    horizon: Horizon,
) -> Result<LoopResponse, DelayLoopError> {
    if let Horizon::Until(t) = horizon
        && !(t.is_finite() && t > 0.0)
    {
        return Err(DelayLoopError::BadHorizon(t));
    }
    let open = LoopSystem::new(plant, controller, input);
    if (1.0 - open.j).abs() < 1e-9 {
        return Err(DelayLoopError::NotWellPosed);
    }
    let theta = plant.delay();
    let rate = fastest_rate(plant, controller);
    let (sys, step, per_delay) = if theta > 0.0 {
        let h_max = if rate > 0.0 {
            (1.0 / rate).min(theta / 4.0)
        } else {
            theta / 4.0
        };
        let m = (theta / h_max).ceil().max(1.0) as usize;
        (open, theta / m as f64, m)
    } else {
        let closed = open.closed_without_delay();
        let rho = closed
            .m
            .complex_eigenvalues()
            .iter()
            .map(|z| z.norm())
            .fold(rate, f64::max);
        (closed, if rho > 0.0 { 1.0 / rho } else { 1.0 }, 0)
    };
    let (final_value, final_input) = steady_state(plant, controller, input);
    let limit = match horizon {
        Horizon::Until(t) => t,
        Horizon::Auto => auto_limit(plant, controller, step),
    };
    if limit / step > MAX_STEPS as f64
        && let Horizon::Until(_) = horizon
    {
        return Err(DelayLoopError::TooManySteps {
            fastest: 1.0 / rate.max(1e-300),
        });
    }
    let offsets = node_offsets(step);
    let maps = node_maps(&sys, &offsets);
    let mut response = LoopResponse {
        input,
        delay: theta,
        step,
        offsets,
        y: Vec::new(),
        v: Vec::new(),
        starts: Vec::new(),
        per_delay,
        sys,
        final_value,
        final_input,
        settled: false,
    };
    response.run(&maps, horizon, limit);
    Ok(response)
}

/// The longest an automatic horizon runs: 400 times the loop's slowest time scale (the
/// dead time, the plant's time constants, Ti), within [`MAX_STEPS`].
fn auto_limit(plant: &TransferFunction, c: &Controller, step: f64) -> f64 {
    let slow_pole = plant
        .poles()
        .iter()
        .filter(|p| p.norm() > 0.0)
        .map(|p| 1.0 / p.norm())
        .fold(0.0, f64::max);
    let ti = if c.action.integral() { c.ti } else { 0.0 };
    let scale = plant.delay() + slow_pole + ti + step;
    (400.0 * scale).min(step * MAX_STEPS as f64)
}

impl LoopResponse {
    fn run(&mut self, maps: &NodeMaps, horizon: Horizon, limit: f64) {
        let n = self.sys.n;
        let mut s = vec![0.0; n];
        let mut si = vec![0.0; n];
        let mut w = [0.0; NODES];
        let mut monitor = Settling::new(self.final_value, self.final_input, self.delay);
        let mut j = 0usize;
        loop {
            let t0 = j as f64 * self.step;
            if t0 >= limit {
                break;
            }
            self.fill_forcing(j, &mut w);
            self.starts.extend_from_slice(&s);
            for i in 0..NODES {
                if i == 0 {
                    si.copy_from_slice(&s);
                } else {
                    apply(&maps.phi[i], &s, &maps.q[i], &w, &maps.g[i], &mut si);
                }
                let y = dot(&self.sys.y, &si) + self.sys.dp * w[i] + self.sys.y0;
                let v = self.v_of(&si, w[i]);
                self.y.push(y);
                self.v.push(v);
                monitor.see(t0 + self.offsets[i], y, v);
            }
            s.copy_from_slice(&si);
            j += 1;
            if horizon == Horizon::Auto && monitor.done(t0 + self.step) {
                self.settled = true;
                break;
            }
            if monitor.diverged() {
                break;
            }
        }
        if horizon != Horizon::Auto {
            self.settled = monitor.quiet_since.is_some();
        }
    }

    /// The plant's input v at a state, given the delayed input w there.
    fn v_of(&self, s: &[f64], w: f64) -> f64 {
        if self.per_delay == 0 {
            // Without a delay H, K0 already carry 1/(1 − J): v = H·s + K0.
            dot(&self.sys.h, s) + self.sys.k0
        } else {
            dot(&self.sys.h, s) + self.sys.j * w + self.sys.k0
        }
    }

    /// The delayed input on step j: v on step j − m (0 before t = 0 and without a delay).
    fn fill_forcing(&self, j: usize, w: &mut [f64; NODES]) {
        if self.per_delay > 0 && j >= self.per_delay {
            let k = (j - self.per_delay) * NODES;
            w.copy_from_slice(&self.v[k..k + NODES]);
        } else {
            *w = [0.0; NODES];
        }
    }

    /// The time computed up to (s).
    pub fn end(&self) -> f64 {
        self.steps() as f64 * self.step
    }

    /// Number of steps computed.
    pub fn steps(&self) -> usize {
        self.y.len() / NODES
    }

    /// The node times and outputs (for plots: about 28 points per step, denser where the
    /// nodes cluster at the steps' ends).
    pub fn samples(&self) -> (Vec<f64>, Vec<f64>) {
        let t = (0..self.steps())
            .flat_map(|j| {
                let t0 = j as f64 * self.step;
                self.offsets.iter().map(move |o| t0 + o)
            })
            .collect();
        (t, self.y.clone())
    }

    /// The node times and outputs of step j.
    pub(super) fn step_nodes(&self, j: usize) -> (f64, &[f64; NODES], &[f64]) {
        (
            j as f64 * self.step,
            &self.offsets,
            &self.y[j * NODES..(j + 1) * NODES],
        )
    }

    /// y(t), exact to the interpolation of the delayed input (t in [0, [`Self::end`]];
    /// 0 before 0, the last value after the end). At a step boundary the value is the
    /// right limit.
    pub fn value(&self, t: f64) -> f64 {
        if t.is_nan() || t <= 0.0 {
            return if t == 0.0 {
                self.y.first().copied().unwrap_or(0.0)
            } else {
                0.0
            };
        }
        let steps = self.steps();
        if steps == 0 {
            return 0.0;
        }
        let j = ((t / self.step).floor() as usize).min(steps - 1);
        let tau = (t - j as f64 * self.step).min(self.step);
        let n = self.sys.n;
        let mut w = [0.0; NODES];
        self.fill_forcing(j, &mut w);
        let aug = augmented(&self.sys);
        let p = propagator(&aug, self.sys.n, tau);
        let coeffs = &coefficient_map(&self.offsets) * nalgebra::DVector::from_column_slice(&w);
        let gc = &p.gamma * &coeffs;
        let state = &p.phi * nalgebra::DVector::from_column_slice(&self.starts[j * n..(j + 1) * n])
            + gc
            + nalgebra::DVector::from_vec(p.g);
        let mut y = self.sys.y0 + dot(&self.sys.y, state.as_slice());
        if self.per_delay > 0 && self.sys.dp != 0.0 {
            let mut wt = 0.0;
            let mut term = 1.0;
            for (jj, c) in coeffs.iter().enumerate() {
                wt += c * term;
                term *= tau / (jj + 1) as f64;
            }
            y += self.sys.dp * wt;
        }
        y
    }
}

/// Watches the nodes for the output and the plant's input settling (within 1e-7 of their
/// largest excursion for a window of max(2θ, t/4)) or diverging.
#[derive(Debug, Clone)]
struct Settling {
    y_final: f64,
    v_final: f64,
    delay: f64,
    y_size: f64,
    v_size: f64,
    quiet_since: Option<f64>,
}

impl Settling {
    fn new(y_final: f64, v_final: f64, delay: f64) -> Self {
        Self {
            y_final,
            v_final,
            delay,
            y_size: 0.0,
            v_size: 0.0,
            quiet_since: None,
        }
    }

    fn see(&mut self, t: f64, y: f64, v: f64) {
        self.y_size = self.y_size.max(y.abs());
        self.v_size = self.v_size.max(v.abs());
        let quiet = self.y_final.is_finite()
            && (y - self.y_final).abs() <= 1e-7 * self.y_size.max(1e-300)
            && (v - self.v_final).abs() <= 1e-7 * self.v_size.max(1e-300);
        if !quiet {
            self.quiet_since = None;
        } else if self.quiet_since.is_none() {
            self.quiet_since = Some(t);
        }
    }

    fn done(&self, t: f64) -> bool {
        self.quiet_since
            .is_some_and(|since| t - since >= (2.0 * self.delay).max(t / 4.0) && t > 0.0)
    }

    fn diverged(&self) -> bool {
        !(self.y_size < 1e12 && self.v_size < 1e12)
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// out = Φ·s + Q·w + g (Φ, Q flat row-major).
fn apply(phi: &[f64], s: &[f64], q: &[f64], w: &[f64; NODES], g: &[f64], out: &mut [f64]) {
    let n = s.len();
    for (r, o) in out.iter_mut().enumerate() {
        *o = g[r] + dot(&phi[r * n..(r + 1) * n], s) + dot(&q[r * NODES..(r + 1) * NODES], w);
    }
}
