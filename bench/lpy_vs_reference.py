#!/usr/bin/python3
"""Sprout against the real L-Py, timed (issue 41): every model of ../shared/corpus/lpy, both ways.

    bench/lpy_vs_reference.sh REF_PYTHON [--build build] [--only TEXT] [--runs 3] [--ways whole,inside]

- Whole process: `sprout render MODEL -o x.png --size 320x240` against L-Py deriving and building
  its scene with no picture (`Lsystem(f)`, `derive()`, `sceneInterpretation()`), each the best of
  `--runs` wall-clock runs.
- In one Python process: `sprout.open(f).derive()` against `Lsystem(f).derive()`, timed inside
  the process (the best of `--runs` in it, or of as many as fit in half a second, up to 50, for
  a model of a few milliseconds), so that start-up is left out.
Prints each model's times and ratios (L-Py's time over Sprout's: above 1, Sprout is faster), then
the median and the worst ratio of each way over the models both run. REF_PYTHON is the
reference's interpreter (../shared/tools/build-lpy-reference.sh). Not part of CI.
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CORPUS = os.path.join(os.path.dirname(ROOT), "shared", "corpus", "lpy")

INSIDE = r"""
import json, os, sys, time
path, runs, mode = sys.argv[1], int(sys.argv[2]), sys.argv[3]
sys.stdout, out = sys.stderr, sys.stdout
os.chdir(os.path.dirname(path))
if mode == 'sprout':
    sys.path.insert(0, os.path.join(sys.argv[4], 'python'))
    import sprout
    derive = lambda: sprout.open(path).derive()
else:
    from openalea.lpy import Lsystem
    derive = lambda: Lsystem(path).derive()
best, spent, k = None, 0.0, 0
while k < runs or (spent < 0.5 and k < 50):  # a model of a few milliseconds: more tries, its best
    t0 = time.perf_counter()
    derive()
    t = time.perf_counter() - t0
    best = t if best is None else min(best, t)
    spent, k = spent + t, k + 1
out.write(json.dumps(best))
out.flush()
os._exit(0)
"""


def timed(cmd, cwd, runs, timeout=120):
    """The best wall-clock time of `runs` runs, or None when one fails."""
    best = None
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    for _ in range(runs):
        # Waited for without a timeout (subprocess's timeout polls every 50 ms, which would
        # round every time up); a timer kills a run that takes too long.
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        killer = threading.Timer(timeout, p.kill)
        killer.start()
        code = p.wait()
        t = time.perf_counter() - t0
        killer.cancel()
        if code != 0:
            return None
        best = t if best is None else min(best, t)
    return best


def inside(python, path, runs, mode, build, timeout=300):
    cmd = [python, "-c", INSIDE, path, str(runs), mode, build]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(path), stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, timeout=timeout,
                           env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
        return json.loads(p.stdout.decode() or "null")
    except (subprocess.TimeoutExpired, ValueError):
        return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("reference")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", default="")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--ways", default="whole,inside", help="whole (process), inside (one Python process), or both")
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    sprout = os.path.join(build, "sprout")
    scene = ("import sys; from openalea.lpy import Lsystem; l = Lsystem(sys.argv[1]); s = l.derive(); "
             "l.sceneInterpretation(s)")
    models = [m for m in sorted(glob.glob(os.path.join(CORPUS, "**", "*.lpy"), recursive=True)) if args.only in m]
    whole, within = [], []
    print("%-58s %9s %9s %7s %9s %9s %7s" % ("model", "sprout s", "L-Py s", "ratio", "open s", "Lsystem s", "ratio"))
    with tempfile.TemporaryDirectory() as tmp:
        for m in models:
            cwd = os.path.dirname(m)
            s = l = si = li = None
            if "whole" in args.ways:
                s = timed([sprout, "render", m, "-o", os.path.join(tmp, "x.png"), "--size", "320x240"], cwd, args.runs)
                l = timed([args.reference, "-c", scene, m], cwd, args.runs)
            if "inside" in args.ways:
                si = inside(sys.executable, m, args.runs, "sprout", build)
                li = inside(args.reference, m, args.runs, "lpy", build)
            r1 = l / s if s and l else None
            r2 = li / si if si and li else None
            if r1:
                whole.append((r1, m, s, l))
            if r2:
                within.append((r2, m, si, li))
            fmt = lambda v, f="%9.3f": (f % v) if v else "%9s" % "-"
            print("%-58s %s %s %s %s %s %s" % (os.path.relpath(m, CORPUS)[-58:], fmt(s), fmt(l), fmt(r1, "%7.2f"), fmt(si), fmt(li),
                                                 fmt(r2, "%7.2f")))
            sys.stdout.flush()
    for name, rs in (("whole process", whole), ("in one Python process", within)):
        if rs:
            worst = min(rs)
            print("%s: %d models both run; median ratio %.2f, worst %.2f (%s); total %.2f s for Sprout, %.2f s for L-Py" % (
                name, len(rs), statistics.median(r[0] for r in rs), worst[0], os.path.relpath(worst[1], CORPUS),
                sum(r[2] for r in rs), sum(r[3] for r in rs)))


main()
