#!/usr/bin/env python3
"""Writes the synthetic stand-ins in this folder (see SOURCES.md): records of the same format
and character as real lab records whose licence does not allow shipping them.

    python3 tests/data/records/make_synthetic.py

Deterministic (fixed seeds); the files are committed, so the tests need no Python.
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def p2_step(t, k, tau1, tau2):
    """Unit-step response of k/((tau1 s + 1)(tau2 s + 1)) at t >= 0."""
    if t <= 0:
        return 0.0
    return k * (1 - (tau1 * math.exp(-t / tau1) - tau2 * math.exp(-t / tau2)) / (tau1 - tau2))


def quantise(x, base, q):
    return base + q * round((x - base) / q)


def ar1(rng, n, sigma, phi):
    e, out = 0.0, []
    for _ in range(n):
        e = phi * e + math.sqrt(1 - phi * phi) * rng.gauss(0, sigma)
        out.append(e)
    return out


def tclab_step():
    """TCLab heater 1, 0 -> 50 % at t = 0 (t = 0 logged twice), 1 s, 0.32 °C resolution:
    the source's own least-squares model 0.69537/((19.689 s + 1)(141.41 s + 1)) from 20.911 °C,
    with coloured noise."""
    rng = random.Random(50)
    noise = ar1(rng, 800, 0.08, 0.6)
    rows = ["Time,T1,T2,Q1", "0.0,20.9,21.54,0.0"]
    for k in range(800):
        t = float(k)
        t1 = 20.9 if k == 0 else quantise(
            20.911 + 50 * p2_step(t, 0.69537, 19.689, 141.41) + noise[k], 20.9, 0.322)
        t2 = quantise(21.54 + 10.0 * (1 - math.exp(-t / 400.0)), 21.54, 0.322)
        rows.append(f"{t},{t1:.2f},{t2:.2f},50.0")
    return "\n".join(rows)


def tclab_dropouts():
    """TCLab, heater on at 50 % from the first row (no pre-step row), ~1 s with jitter,
    0.032 °C resolution, and 46 downward dropouts between 30 and 784 s (down to -14.6 °C)."""
    rng = random.Random(46)
    noise = ar1(rng, 801, 0.05, 0.5)
    drops = set(rng.sample(range(30, 785), 45)) | {640}
    rows = ["Time,T1,T2,Q1,Q2"]
    t = 0.0
    for k in range(801):
        t1 = 21.543 + 50 * p2_step(t, 0.76, 18.0, 150.0) + noise[k]
        if k in drops:
            t1 -= 14.6 if k == 640 else rng.uniform(1.2, 9.0)
        t1 = quantise(t1, 21.543, 0.0322)
        t2 = quantise(20.898 + 4.0 * (1 - math.exp(-t / 500.0)), 20.898, 0.0322)
        rows.append(f"{round(t, 2)},{t1:.3f},{t2:.3f},50.0,0.0")
        t += rng.choice([0.99, 1.0, 1.01])
    return "\n".join(rows) + "\n"


def pendulum():
    """A propeller pendulum driven by an amplitude-modulated PRBS (13 changes), Ts = 0.01 s,
    no time column: a lightly damped second order with a small square-law nonlinearity."""
    rng = random.Random(13)
    levels = [0.77618] + [round(rng.uniform(0.3, 1.6), 5) for _ in range(13)]
    change_at = sorted(rng.sample(range(200, 4900), 13))
    wn, zeta, h = 6.0, 0.12, 0.01
    x, v, seg = 0.0, 0.0, 0
    rows = ["y, u"]
    for k in range(5001):
        while seg < 13 and k >= change_at[seg]:
            seg += 1
        u = levels[seg]
        rows.append(f"{max(x, 0.0):.5f}, {u:.5f}")
        for _ in range(10):  # semi-implicit Euler, 1 ms steps
            a = wn * wn * (0.9 * u + 0.1 * u * u) - 2 * zeta * wn * v - wn * wn * x
            v += a * h / 10
            x += v * h / 10
    return "\n".join(rows) + "\n"


def sci(x):
    """Oscilloscope-style 4.262618E+0."""
    if x == 0:
        return "0.000000E+0"
    e = math.floor(math.log10(abs(x)))
    m = x / 10 ** e
    if round(abs(m), 6) >= 10:
        m, e = m / 10, e + 1
    return f"{m:.6f}E{'+' if e >= 0 else '-'}{abs(e)}"


def rlc():
    """An oscilloscope capture of a series RLC driven by a 5 V step: four metadata lines,
    wall-clock time stamps, 200 samples 3.3 us apart; V_C underdamped (zeta 0.25)."""
    rng = random.Random(7)
    lines = [
        "waveform,V_S,V_C,V_R",
        "t0,5/7/2021  09:33:31.638054,5/7/2021  09:33:31.638055,5/7/2021  09:33:31.638057",
        "delta t,3.300000E-6,3.300000E-6,3.300000E-6",
        "",
        "time,V_S,V_C,V_R",
    ]
    wn, zeta = 2 * math.pi * 8000.0, 0.25
    wd = wn * math.sqrt(1 - zeta * zeta)
    start_us = 638054.0
    for k in range(200):
        t = (k + 0.3) * 3.3e-6
        vs = 5.0 - 0.75 * math.exp(-t / 4e-6) + rng.gauss(0, 0.004)
        vc = 5.0 * (1 - math.exp(-zeta * wn * t) * (math.cos(wd * t)
                    + zeta / math.sqrt(1 - zeta * zeta) * math.sin(wd * t)))
        vc = 2.762514e-2 if k == 0 else vc + rng.gauss(0, 0.004)
        vr = vs - vc + rng.gauss(0, 0.004)
        stamp = f"5/7/2021  09:33:31.{int(start_us + k * 3.3):06d}"
        lines.append(f"{stamp},{sci(vs)},{sci(vc)},{sci(vr)}")
    return "\r\n".join(lines) + "\r\n"


def rc_ladder():
    """A two-stage RC ladder (R C = 0.05 s per stage) driven by a DAC square wave 1241 <-> 2482
    counts every 100 samples from sample 45, read by a 12-bit ADC every 8 ms; no header."""
    rng = random.Random(2)
    h, rc = 0.008, 0.05
    v1 = v2 = 1241.0
    rows = []
    for k in range(641):
        u = 1241 if k < 45 else (2482 if ((k - 45) // 100) % 2 == 0 else 1241)
        rows.append(f"{u},{int(round(v2 + rng.gauss(0, 9)))}")
        for _ in range(20):
            dt = h / 20
            i1, i2 = (u - v1) / rc, (v1 - v2) / rc
            v1 += dt * (i1 - i2)
            v2 += dt * i2
    return "\n".join(rows) + "\n"


def multistep_heater():
    """A heater driven through four steps of its power (20 -> 40 -> 60 -> 30 -> 45 %), each
    switched between two samples of a 1 s logger that logs the command it last saw: the
    first-order plant 0.8 e^{-4 s}/(40 s + 1) from 25 degC at rest, 0.05 degC white noise,
    600 rows `time (s),heater (%),temperature (degC)`."""
    rng = random.Random(4)
    kp, tau, td, y0 = 0.8, 40.0, 4.0, 25.0
    switches = [(0.0, 20.0), (50.4, 40.0), (200.7, 60.0), (350.2, 30.0), (480.5, 45.0)]

    def command(t):
        return [u for (ts, u) in switches if ts <= t][-1]

    def temperature(t):
        y = y0
        for (ts, u), (_, before) in zip(switches[1:], switches[:-1]):
            s = t - ts - td
            if s > 0:
                y += kp * (u - before) * (1 - math.exp(-s / tau))
        return y

    rows = ["time (s),heater (%),temperature (degC)"]
    for k in range(600):
        t = float(k)
        rows.append(f"{t:.0f},{command(t):.1f},{temperature(t) + rng.gauss(0, 0.05):.3f}")
    return "\n".join(rows) + "\n"


def sbhs():
    """IIT Bombay's Single Board Heater System, heater 30 -> 40 % with the fan at 50 %, not at
    rest before the step: 821 rows `sample heater% fan% temperature(degC) stamp(ms)`,
    whitespace-separated, no header, ~1 s irregular sampling (1.00 s with 10 ms jitter, a few
    odd intervals, one short one at the start), temperature quantised at 0.1 degC.

    The plant is the source's first order 0.23/(58 s + 1) (degC per %). Before the step the
    heater has been at 30 % for a while but the plate has not settled: the temperature is the
    free response of that same pole, rising from 29.3 degC toward 34.6 degC, the shape of the
    real record (29.3 -> 34.5 degC over the first 249 s), so a model with an initial transient
    can describe it. The step happens between two samples (248.6 s); the logger shows it at
    the next one (~249 s). White noise 0.12 degC (the real record's first differences spread
    +/-0.2 degC)."""
    rng = random.Random(11)
    kp, tau, y_rest, y_first = 0.23, 58.0, 34.6, 29.3
    t_step, u_before, u_after = 248.6, 30.0, 40.0
    stamp0 = 1412400132192.0
    odd = {1: 0.85, 2: 0.27, 3: 0.89, 130: 1.2, 131: 0.8, 420: 0.53, 421: 1.47}
    rows, t = [], 0.0
    for k in range(821):
        if k > 0:
            t += odd.get(k, 1.0 + rng.choice([-0.01, 0.0, 0.0, 0.0, 0.01]))
        y = y_rest - (y_rest - y_first) * math.exp(-t / tau)
        if t >= t_step:
            y += kp * (u_after - u_before) * (1 - math.exp(-(t - t_step) / tau))
        # The logger reads the heater command just before it samples the temperature.
        u = u_after if t >= t_step else u_before
        temp = round((y + rng.gauss(0, 0.12)) * 10) / 10
        stamp = stamp0 + round(t * 1000)
        rows.append(f"{k + 1:15.1f}{u:18.1f}{50.0:18.1f}{temp:18.1f}{stamp:18.1f}")
    return "\n".join(rows) + "\n"


FILES = {
    "tclab_step_q1_50_synthetic.csv": tclab_step,
    "tclab_step_q1_50_dropouts_synthetic.csv": tclab_dropouts,
    "pendulum_aprbs_synthetic.txt": pendulum,
    "rlc_step_underdamped_synthetic.csv": rlc,
    "rc2_square_wave_adc_synthetic.csv": rc_ladder,
    "multistep_heater_synthetic.csv": multistep_heater,
    "sbhs_step_not_at_rest_synthetic.txt": sbhs,
}

if __name__ == "__main__":
    for name, make in FILES.items():
        with open(os.path.join(HERE, name), "w", newline="") as f:
            f.write(make())
