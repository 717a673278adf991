"""python-control's step_info on the systems of a `degrau step --batch` input: the
comparison of benches/batch.rs (issue 22, item 18), run in the same session.

Usage: python3 benches/step_info_control.py BATCH.jsonl

Each line gives "poles" (with "zeros" and "dc_gain") or "num" and "den", as the batch does.
The systems are built first (control.tf); only step_info(sys) is timed, each system once,
the whole set twice (the best of the two); a system step_info fails on (an IndexError on
some responses) is timed all the same. Prints the time per system in seconds, how many
systems were timed and how many step_info failed on, on one line: "SECONDS COUNT FAILED".
"""

import json
import sys
import time

import control
import numpy as np


def system(request):
    if "num" in request:
        return control.tf(request["num"], request["den"])
    poles = [complex(re, im) for re, im in request["poles"]]
    zeros = [complex(re, im) for re, im in request.get("zeros", [])]
    num = np.real(np.poly(zeros)) if zeros else np.array([1.0])
    den = np.real(np.poly(poles))
    gain = request.get("dc_gain", 1.0) * den[-1] / num[-1]
    return control.tf(gain * num, den)


def main():
    with open(sys.argv[1]) as f:
        systems = [system(json.loads(line)) for line in f if line.strip()]
    best = float("inf")
    for _ in range(2):
        failed = 0
        start = time.perf_counter()
        for g in systems:
            try:
                control.step_info(g)
            except (IndexError, ValueError):
                failed += 1
        best = min(best, time.perf_counter() - start)
    print(f"{best / len(systems)} {len(systems)} {failed}")


if __name__ == "__main__":
    main()
