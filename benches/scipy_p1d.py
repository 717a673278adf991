"""scipy's least_squares on a FOPDT (P1D) driven by a measured input: the comparison of the
fit bench (benches/fit.rs), run in the same session.

Usage: python3 benches/scipy_p1d.py RECORD.csv KP TP1 TD Y0

The record is a CSV with columns t, u, y (uniform sampling). The model is exact for an
input held between samples (zero-order hold): y = Y0 + Kp·(u − u0) through 1/(Tp1·s + 1)
and a dead time Td split into whole samples and a fraction (the modified z-transform),
simulated with scipy.signal.lfilter (vectorised). One start from the guess given, the
default trust-region reflective method with bounds, the Jacobian by 2-point differences.
Prints the time of the least_squares call alone (best of 3, in-process) and the result.
"""

import sys
import time

import numpy as np
from scipy.optimize import least_squares
from scipy.signal import lfilter


def simulate(p, t, du, ts):
    kp, tp1, td, y0 = p
    a = np.exp(-ts / tp1)
    whole = int(np.floor(td / ts))
    frac = td / ts - whole
    # Modified z-transform of Kp/(Tp1 s + 1)·e^{-Td s} behind a zero-order hold:
    # b1 = Kp(1 − a^{1−frac}), b2 = Kp(a^{1−frac} − a).
    m = np.exp(-(1.0 - frac) * ts / tp1)
    b = np.array([0.0, kp * (1.0 - m), kp * (m - a)])
    shifted = np.concatenate([np.zeros(whole), du[: len(du) - whole]]) if whole > 0 else du
    return y0 + lfilter(b, [1.0, -a], shifted)


def main():
    path = sys.argv[1]
    guess = np.array([float(v) for v in sys.argv[2:6]])
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    t, u, y = data[:, 0], data[:, 1], data[:, 2]
    ts = float(np.median(np.diff(t)))
    du = u - u[0]
    duration = t[-1] - t[0]

    def residuals(p):
        return simulate(p, t, du, ts) - y

    lower = [-np.inf, 1e-3 * ts, 0.0, -np.inf]
    upper = [np.inf, 100 * duration, 0.95 * duration, np.inf]
    guess = np.clip(guess, lower, upper)
    best = np.inf
    for _ in range(3):
        start = time.perf_counter()
        result = least_squares(residuals, guess, bounds=(lower, upper))
        best = min(best, time.perf_counter() - start)
    rmse = np.sqrt(np.mean(result.fun**2))
    print(f"seconds {best:.6f}")
    print(
        "params Kp {:.6g} Tp1 {:.6g} Td {:.6g} Y0 {:.6g}; rmse {:.4g}; nfev {}".format(
            *result.x, rmse, result.nfev
        )
    )


if __name__ == "__main__":
    main()
