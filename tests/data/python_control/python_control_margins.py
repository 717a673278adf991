"""Writes python_control_margins.json beside this file: 100 random rational loops L(s)
(numerator degree below the denominator's, orders 1 to 5) and python-control's margins of
each, for the lti crate's test `lti_python_control` (crates/lti/tests/lti_python_control.rs).

Deterministic (numpy's default_rng with SEED); run it with python-control, numpy and scipy
installed to regenerate:  python3 tests/data/python_control/python_control_margins.py

The systems: poles real or in complex pairs (some lightly damped, ζ 0.01–0.1), some with an
integrator (one pole at 0), some with a right-half-plane pole or zero, magnitudes 0.1–10
rad/s; the gain's sign either, its magnitude 0.1–100 times the one that makes |L(0)| (or
the integrator's |s·L(s)| at s = 0) one. Non-finite numbers are written as the strings
"inf", "-inf" and "nan" (JSON has none).
"""

import json
import math
import os

import control
import numpy as np

SEED = 2026
COUNT = 100


def number(x):
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


def numbers(xs):
    return [number(x) for x in np.atleast_1d(xs)]


def roots(rng, n, rhp_chance, light_chance):
    """n roots: real ones and complex pairs, mostly in the left half plane."""
    out = []
    while len(out) < n:
        mag = 10 ** rng.uniform(-1, 1)
        sign = 1.0 if rng.random() < rhp_chance else -1.0
        if n - len(out) >= 2 and rng.random() < 0.5:
            zeta = rng.uniform(0.01, 0.1) if rng.random() < light_chance else rng.uniform(0.1, 0.95)
            re = sign * zeta * mag
            im = mag * math.sqrt(1 - zeta * zeta)
            out += [complex(re, im), complex(re, -im)]
        else:
            out.append(complex(sign * mag, 0.0))
    return out


def system(rng):
    n = int(rng.integers(1, 6))
    integrator = rng.random() < 0.25
    poles = roots(rng, n - 1 if integrator else n, 0.15, 0.3)
    if integrator:
        poles.append(0j)
    m = int(rng.integers(0, n))
    zeros = roots(rng, m, 0.2, 0.2)
    # |L| ≈ k at low frequency (beside the integrator's 1/ω).
    scale = np.prod([abs(p) for p in poles if p != 0]) / np.prod([abs(z) for z in zeros] or [1.0])
    k = (1 if rng.random() < 0.75 else -1) * 10 ** rng.uniform(-1, 2) * scale
    num = k * np.real(np.poly(zeros)) if zeros else np.array([k])
    den = np.real(np.poly(poles))
    return [float(c) for c in np.atleast_1d(num)], [float(c) for c in den]


def main():
    rng = np.random.default_rng(SEED)
    cases = []
    for _ in range(COUNT):
        num, den = system(rng)
        loop = control.tf(num, den)
        gm, pm, wcg, wcp = control.margin(loop)
        gms, pms, _, w180, wc, _ = control.stability_margins(loop, returnall=True)
        cases.append({
            "num": num,
            "den": den,
            "gm": number(gm),
            "pm": number(pm),
            "wcg": number(wcg),
            "wcp": number(wcp),
            "all_gm": numbers(gms),
            "all_wcg": numbers(w180),
            "all_pm": numbers(pms),
            "all_wcp": numbers(wc),
        })
    out = {
        "python_control": control.__version__,
        "numpy": np.__version__,
        "seed": SEED,
        "script": "tests/data/python_control/python_control_margins.py",
        "cases": cases,
    }
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "python_control_margins.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
