#!/usr/bin/python3
"""Explosive growth refused (issue 39): each input as `sprout expand` whole processes, the time
and peak memory until the refusal, against deriving step 1 of the same file in the same run
(the ratio: how many first steps the refusal costs). Best of 3 wall-clock runs each.

    bench/refuse_bench.py [build/sprout]
"""
import os, resource, subprocess, sys, tempfile, time

SPROUT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/sprout")
INPUTS = [
    ("parametric .lsys, triples (n: 60)", "boom.lsys", "n: 60\naxiom: A(1)\nA(x) -> A(x+1)A(x*2)A(x)\n", []),
    ("D0L .lsys, x10 (n: 40)", "d0l.lsys", "n: 40\naxiom: F\nF -> FFFFFFFFFF\n", []),
    ("cpfg decomposition doubling for 40 passes", "dec.l",
     "derivation length: 30\nAxiom: A\nA --> AB\ndecomposition:\nmaximum depth: 40\nB --> BB\n", []),
    ("L-Py A --> AA (derivation length 40)", "aa.lpy", "Axiom: A\nderivation length: 40\nproduction:\nA --> AA\nendlsystem\n", []),
    ("L-Py Python body, lists as parameters (64 MB budget)", "lists.lpy",
     "Axiom: A([1.0] * 20)\nderivation length: 40\nproduction:\nA(x) :\n    y = list(x)\n    produce A(x) A(y)\nendlsystem\n",
     ["--max-memory", "64"]),
    ("L-Py Python body, produce A(x+1) A(x*2) (derivation length 40)", "body.lpy",
     "Axiom: A(1)\nderivation length: 40\nproduction:\nA(x) :\n    y = x * 2\n    produce A(x+1) A(y)\nendlsystem\n", []),
]


def run(args):
    """(seconds, peak resident MB of that child, exit status, last line of stderr)"""
    t0 = time.perf_counter()
    p = subprocess.Popen([SPROUT] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    seconds = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    lines = err.strip().splitlines()
    return seconds, usage.ru_maxrss / 1024, p.returncode, (lines[-1] if lines else "")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        print("%-62s %9s %9s %12s %s" % ("input", "refused", "peak MB", "1 step", "ratio"))
        for label, name, text, extra in INPUTS:
            path = os.path.join(tmp, name)
            with open(path, "w") as f:
                f.write(text)
            best, peak, message = 1e9, 0.0, ""
            for _ in range(3):
                s, mb, code, last = run(["expand", path] + extra)
                if code == 0:
                    sys.exit("%s: not refused" % label)
                best, peak, message = min(best, s), max(peak, mb), last
            one = min(run(["expand", path, "-n", "1"] + extra)[0] for _ in range(3))
            print("%-62s %8.2fs %9.0f %11.3fs %6.1fx" % (label, best, peak, one, best / one))
            print("    %s" % message[:160])


main()
