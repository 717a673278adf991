#!/usr/bin/env python3
"""Reliability fuzzer for the `degrau` command line: mutated data files and odd arguments.

Not part of `cargo test` (it takes minutes); run it by hand against a built binary:

    python3 scripts/fuzz_cli.py target/debug/degrau --files 600 --args 300

It mutates the repo's data fixtures (and ../shared/data when present), runs `degrau fit` and
`degrau diagnose` on each mutant, runs `degrau step`/`fit` with odd arguments, and sorts every
run into one outcome:

- ok: exit 0 and a JSON object whose numbers are all finite;
- refused: a non-zero exit with a message on stderr and no panic;
- PANIC: the process panicked (Rust's "panicked at" on stderr) or died of a signal;
- HANG: it did not finish within the time limit;
- SUSPECT: exit 0 but the JSON holds NaN, inf or nulls where a fit reports numbers.

It prints a table of outcomes and the first few reproducers of every bad outcome. The seed
makes runs repeatable.
"""

import argparse
import glob
import json
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

ODD_NUMBERS = [
    "nan", "NaN", "inf", "-inf", "1e308", "-1e308", "1e-320", "0", "-0", "1e400",
    "9" * 400, "0x10", "1,5", "", " ", "--", "1e", "e5", "+-1", "1.2.3",
]


def seeds():
    files = sorted(glob.glob(os.path.join(REPO, "tests", "data", "*")))
    files += [os.path.join(REPO, "assets", "leci_step.csv")]
    files += sorted(glob.glob(os.path.join(REPO, "..", "shared", "data", "real", "*.csv")))
    files += sorted(glob.glob(os.path.join(REPO, "..", "shared", "data", "real", "*.txt")))
    out = []
    for f in files:
        if os.path.isfile(f) and os.path.getsize(f) < 2_000_000:
            with open(f, "rb") as fh:
                out.append((os.path.basename(f), fh.read()))
    return out


def mutate(data: bytes, rng: random.Random) -> bytes:
    lines = data.split(b"\n")
    kind = rng.randrange(12)
    if kind == 0 and data:
        return data[: rng.randrange(len(data))]
    if kind == 1 and data:
        b = bytearray(data)
        for _ in range(rng.randint(1, 20)):
            b[rng.randrange(len(b))] = rng.randrange(256)
        return bytes(b)
    if kind == 2:
        i = rng.randrange(len(lines))
        lines.insert(i, rng.choice([b"nan,nan,nan", b"1e308,1e308", b";;;;", b"\t\t", b"#",
                                    b"x" * 5000, b"1" * 5000, b",".join([b"1"] * 2000)]))
        return b"\n".join(lines)
    if kind == 3 and len(lines) > 2:
        i = rng.randrange(1, len(lines))
        return b"\n".join(lines[:i] + lines[i:][::-1])
    if kind == 4:
        word = rng.choice(ODD_NUMBERS).encode()
        b = bytearray(data)
        for _ in range(rng.randint(1, 5)):
            if not b:
                break
            i = rng.randrange(len(b))
            b[i:i + rng.randint(1, 6)] = word
        return bytes(b)
    if kind == 5:
        return data.replace(b",", rng.choice([b";", b"\t", b" ", b",,", b""]))
    if kind == 6:
        return data.replace(b".", rng.choice([b",", b"", b".."]))
    if kind == 7:
        return rng.choice([b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff", b"\x00"]) + data
    if kind == 8 and len(lines) > 3:
        k = rng.randrange(1, len(lines))
        return b"\n".join(rng.sample(lines, k))
    if kind == 9:
        scale = rng.choice(["1e200", "1e-200", "1e150", "-1e150", "1e300"])
        out = []
        for line in lines:
            cells = line.split(b",")
            new = []
            for c in cells:
                try:
                    new.append(repr(float(c) * float(scale)).encode())
                except ValueError:
                    new.append(c)
            out.append(b",".join(new))
        return b"\n".join(out)
    if kind == 10:
        return b"\r\n".join(lines) if rng.random() < 0.5 else b"\r".join(lines)
    return b"\n".join(line + b"," + str(rng.random()).encode() for line in lines)


def run(cmd, timeout):
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return "HANG", ""
    err = p.stderr.decode("utf-8", "replace")
    if "panicked at" in err or p.returncode < 0:
        return "PANIC", err[-400:]
    if p.returncode != 0:
        return ("refused" if err.strip() else "PANIC"), err[-200:]
    out = p.stdout.decode("utf-8", "replace")
    try:
        doc = json.loads(out)
    except ValueError:
        return "SUSPECT", "stdout is not JSON: " + out[:200]
    bad = suspicious(doc)
    return ("SUSPECT", bad) if bad else ("ok", "")


FIT_NUMBERS = {"mse", "rmse", "fit_percent", "aic"}


def suspicious(doc, path=""):
    if isinstance(doc, dict):
        for k, v in doc.items():
            overflow_said = k == "mse" and any(
                "beyond double precision" in w for w in doc.get("warnings", []))
            if k in FIT_NUMBERS and v is None and not overflow_said:
                return f"{path}.{k} is null"
            bad = suspicious(v, f"{path}.{k}")
            if bad:
                return bad
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            bad = suspicious(v, f"{path}[{i}]")
            if bad:
                return bad
    elif isinstance(doc, str) and doc.lower() in ("nan", "inf", "-inf", "infinity"):
        return f"{path} = {doc}"
    return None


FLAG_SETS = [[], ["--t0", "5", "--du", "10"], ["--y-col", "T1", "--u-col", "Q1"],
             ["--initial-input", "0"], ["--initial-input", "0", "--y-col", "T1", "--u-col", "Q1"],
             ["--ts", "1", "--t0", "3", "--du", "1"], ["--t0", "1", "--du", "1"]]


def viable(binary, corpus, tmp, timeout):
    """Each seed with the first flag set that fits its unmutated file (so mutants test more
    than the refusal of a missing step)."""
    out = []
    for name, data in corpus:
        path = os.path.join(tmp, "seed_" + name)
        with open(path, "wb") as fh:
            fh.write(data)
        flags = next((f for f in FLAG_SETS
                      if run([binary, "fit", path, "--json", "--model", "P1", "--starts", "1"]
                             + f, timeout)[0] == "ok"), [])
        out.append((name, data, flags))
    print(f"seeds: {len(out)}, with flags that fit: {sum(1 for o in out if o[2])}")
    return out


def fuzz_files(binary, n, rng, timeout, tmp):
    results = []
    corpus = viable(binary, seeds(), tmp, timeout)
    for i in range(n):
        name, data, flags = rng.choice(corpus)
        mutant = mutate(data, rng)
        path = os.path.join(tmp, f"m{i}_{name}")
        with open(path, "wb") as fh:
            fh.write(mutant)
        sub = "diagnose" if i % 4 == 0 else "fit"
        model = rng.choice(["P1", "P1D", "P2", "P2DU", "P1I"])
        cmd = [binary, sub, path, "--json"] + flags
        cmd += ["--start", model] if sub == "diagnose" else ["--model", model, "--starts", "4"]
        outcome, detail = run(cmd, timeout)
        results.append((outcome, " ".join(cmd), detail))
        if outcome not in ("ok", "refused"):
            keep = os.path.join(tmp, "keep")
            os.makedirs(keep, exist_ok=True)
            os.replace(path, os.path.join(keep, os.path.basename(path)))
        else:
            os.remove(path)
    return results


STEP_FLAGS = ["--poles", "--zeros", "--gain", "--num", "--den", "--dc-gain", "--delay",
              "--amplitude", "--settling-threshold", "--rise-limits", "--samples"]
FIT_FLAGS = ["--t0", "--du", "--y0", "--ts", "--window", "--filter", "--starts", "--guess",
             "--initial-input", "--skip-rows", "--y-col", "--u-col", "--time-col", "--model"]


def odd_value(rng):
    return rng.choice(ODD_NUMBERS + [
        "-1,-1.0001", "-1+2j,-1-2j", "1,2,3", "-1e30", "1e30,-1e30", "0,0", "1,0",
        "Kp=1,Kp=2", "Y0=40", "Zeta=nan", "P9", "P2DUZI", "1e6", "100000", "-3", "0.5,0.1",
        "-1e-300", "3e-324", "1,1,1,1,1,1,1,1,1,1,1,1,1", ",", ";", "j", "-j",
    ])


def fuzz_args(binary, n, rng, timeout):
    results = []
    leci = os.path.join(REPO, "assets", "leci_step.csv")
    for i in range(n):
        if i % 2 == 0:
            cmd = [binary, "step", "--json"]
            base = rng.choice([["--poles", "-1,-2"], ["--num", "1", "--den", "1,3,2"], []])
            cmd += base
            for _ in range(rng.randint(1, 4)):
                cmd += [rng.choice(STEP_FLAGS), odd_value(rng)]
        else:
            cmd = [binary, "fit", leci, "--json", "--t0", "5", "--du", "10"]
            for _ in range(rng.randint(1, 3)):
                cmd += [rng.choice(FIT_FLAGS), odd_value(rng)]
        outcome, detail = run(cmd, timeout)
        results.append((outcome, " ".join(cmd), detail))
    return results


def summarise(title, results):
    counts = {}
    for outcome, _, _ in results:
        counts[outcome] = counts.get(outcome, 0) + 1
    print(f"{title}: {len(results)} runs: " +
          ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    reasons = {}
    for outcome, _, detail in results:
        if outcome == "refused":
            text = detail.strip().splitlines()[-1] if detail.strip() else ""
            text = text.split(": ", 1)[-1] if "/" in text.split(": ", 1)[0] else text
            key = " ".join(text.split()[:7])
            reasons[key] = reasons.get(key, 0) + 1
    for key, count in sorted(reasons.items(), key=lambda kv: -kv[1])[:8]:
        print(f"  refused {count}: {key} …")
    for bad in ("PANIC", "HANG", "SUSPECT"):
        shown = [r for r in results if r[0] == bad][:5]
        for _, cmd, detail in shown:
            print(f"  {bad}: {cmd}\n      {detail.strip()[:300]}")
    return counts


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--files", type=int, default=400)
    ap.add_argument("--args", type=int, default=300)
    ap.add_argument("--seed", type=int, default=8)
    ap.add_argument("--timeout", type=float, default=30.0)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    with tempfile.TemporaryDirectory() as tmp:
        files = fuzz_files(a.binary, a.files, rng, a.timeout, tmp)
        args = fuzz_args(a.binary, a.args, rng, a.timeout)
        c1 = summarise("mutated files", files)
        c2 = summarise("odd arguments", args)
        keep = os.path.join(tmp, "keep")
        if os.path.isdir(keep) and os.listdir(keep):
            dest = os.path.join(REPO, "target", "fuzz-keep")
            os.makedirs(dest, exist_ok=True)
            for f in os.listdir(keep):
                os.replace(os.path.join(keep, f), os.path.join(dest, f))
            print(f"bad mutants kept in {dest}")
    bad = sum(c.get(k, 0) for c in (c1, c2) for k in ("PANIC", "HANG"))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
