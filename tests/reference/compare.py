#!/usr/bin/python3
"""Sprout against the real L-Py (issue 40): every model derived by both, the strings compared.

    tests/reference/compare.py REF_PYTHON [--build build] [--sets share,tests,own] [--only TEXT]
                                          [--jobs 2] [--report out.json] [--at-least PERCENT]

REF_PYTHON is the reference L-Py's interpreter (ROOT/venv/bin/python after
`bash ../shared/tools/build-lpy-reference.sh ROOT PLANTGL_GITDIR LPY_GITDIR`). Each model is
derived by tests/reference/lpy_derive.py in a process of its own, twice by L-Py (a model whose
string changes from run to run in L-Py itself is set apart) and once by Sprout's openalea.lpy,
with Python's and numpy's random seeded alike. Strings are compared module by module with
numbers equal to 1e-9 (relative; --tolerance); where they differ, both derive again one step at a time and
the first step and module that differ are named. The scenes' shape counts are compared too.

Sets: share (../shared/corpus/lpy, L-Py's share/), tests (../shared/corpus/lpy-tests), own
(Sprout's tests/lpy/models and presets). Prints a line per model that is not the same and the
figures per set; exits 1 when a set's share of same strings is under --at-least.
Not part of the README's test command or CI: ctest runs it under the label `reference` when
SPROUT_LPY_REFERENCE names the reference's python.
"""
import argparse
import concurrent.futures
import glob
import json
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SHARED = os.path.join(os.path.dirname(ROOT), "shared")
DERIVE = os.path.join(HERE, "lpy_derive.py")


def models(sets):
    found = []
    if "share" in sets:
        found += [("share", p) for p in sorted(glob.glob(os.path.join(SHARED, "corpus", "lpy", "**", "*.lpy"), recursive=True))]
    if "tests" in sets:
        found += [("tests", p) for p in sorted(glob.glob(os.path.join(SHARED, "corpus", "lpy-tests", "**", "*.lpy"), recursive=True))]
    if "own" in sets:
        own = glob.glob(os.path.join(ROOT, "tests", "lpy", "models", "*.lpy")) + glob.glob(os.path.join(ROOT, "presets", "**", "*.lpy"), recursive=True)
        found += [("own", p) for p in sorted(own)]
    return found


def derive(python, path, build=None, steps=False, timeout=120):
    cmd = [python, DERIVE, path] + (["--sprout", build] if build else []) + (["--steps"] if steps else [])
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", PYTHONHASHSEED="0")
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout, env=env, cwd=os.path.dirname(path))
    except subprocess.TimeoutExpired:
        return {"ok": False, "error": "timed out after %d s" % timeout}
    lines = p.stdout.decode(errors="replace").strip().splitlines()
    try:
        return json.loads(lines[-1])
    except (IndexError, ValueError):
        tail = p.stderr.decode(errors="replace").strip().splitlines()[-1:] or ["no output"]
        return {"ok": False, "error": "exit %d: %s" % (p.returncode, tail[0][:200])}


# A PlantGL vector is one token (its components compared at its own scale); a number another;
# an object written with its address (`<...QuantisedFunction object at 0x7f...>`) another.
TOKEN = re.compile(r"Vector[234]\([^()]*\)|<[\w.]*?(\w+) object at 0x[0-9a-f]+>|\d+\.\d*(?:[eE][-+]?\d+)?|\d+(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|.", re.S)


TOLERANCE = 1e-9  # relative, with 1 as the least scale (--tolerance)


def tokens(s):
    return [m.group(0) for m in TOKEN.finditer(s)]


def same_vector(a, b):
    """Vectors as PlantGL writes them (6 significant digits each): equal when each component is
    within the tolerance of the vector's size (both turtles work in double precision: the
    written digits are the same but where a rounding falls between them)."""
    try:
        x = [float(v) for v in a[a.index("(") + 1:-1].split(",")]
        y = [float(v) for v in b[b.index("(") + 1:-1].split(",")]
    except ValueError:
        return False
    if a[:7] != b[:7] or len(x) != len(y):
        return False
    scale = max([1.0] + [abs(v) for v in x + y])
    for u, v in zip(x, y):
        m = max(abs(u), abs(v))
        digit = 10 ** (math.floor(math.log10(m)) - 5) if m > 0 else 0.0
        if abs(u - v) > max(TOLERANCE * scale, 1.01 * digit if TOLERANCE >= 1e-6 else 0.0):
            return False
    return True


def same_token(x, y):
    if x == y:
        return True
    if x.startswith("Vector") and y.startswith("Vector"):
        return same_vector(x, y)
    if x.startswith("<") and y.startswith("<"):  # objects: their class, not their address
        return TOKEN.match(x).group(1) == TOKEN.match(y).group(1)
    return is_number(x) and is_number(y) and same_number(x, y)


def is_number(t):
    return t[0].isdigit() or (t[0] == "." and len(t) > 1)


def same_number(a, b):
    try:
        x, y = float(a), float(b)
    except ValueError:
        return a == b
    return abs(x - y) <= TOLERANCE * max(1.0, abs(x), abs(y))


def first_difference(a, b):
    """None when the strings hold the same modules (numbers to the tolerance), else (offset in a, a's
    text there, b's text there)."""
    ta, tb = tokens(a), tokens(b)
    offset = 0
    for i in range(min(len(ta), len(tb))):
        x, y = ta[i], tb[i]
        if not same_token(x, y):
            return offset, a[offset:offset + 60], "".join(tb[i:i + 30])[:60]
        offset += len(x)
    if len(ta) != len(tb):
        return offset, a[offset:offset + 60], "".join(tb[min(len(ta), len(tb)):])[:60]
    return None


def module_index(s, offset):
    """The module at `offset` of an L-Py string, counted from 0 (a name followed by its
    parentheses is one module; letters are one module each: an approximation for messages)."""
    count, depth = 0, 0
    for ch in s[:offset]:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif depth == 0:
            count += 1
    return count


def compare(args, entry):
    group, path = entry
    ref1 = derive(args.reference, path)
    if not ref1.get("ok"):
        mine = derive(sys.executable, path, args.build)
        return {"set": group, "model": path, "status": "lpy-fails" if mine.get("ok") else "both-fail", "why": ref1.get("error")}
    ref2 = derive(args.reference, path)
    mine = derive(sys.executable, path, args.build)
    r = {"set": group, "model": path, "lpy_seconds": ref1.get("seconds"), "sprout_seconds": mine.get("seconds")}
    if not ref2.get("ok") or ref1["final"] != ref2["final"]:  # L-Py's own variation: any change at all
        r["status"] = "lpy-varies"
        return r
    if not mine.get("ok"):
        r.update(status="sprout-fails", why=mine.get("error"))
        return r
    r["shapes"] = [ref1.get("shapes"), mine.get("shapes")]
    diff = first_difference(ref1["final"], mine["final"])
    if diff is None:
        r["status"] = "same" if ref1["final"] == mine["final"] else "same-values"
        return r
    r["status"] = "differs"
    r["final"] = {"module": module_index(ref1["final"], diff[0]), "lpy": diff[1], "sprout": diff[2],
                  "lengths": [ref1.get("length"), mine.get("length")]}
    # Where they part: one step at a time on both sides.
    a, b = derive(args.reference, path, steps=True), derive(sys.executable, path, args.build, steps=True)
    if a.get("steps") and b.get("steps"):
        for k, (x, y) in enumerate(zip(a["steps"], b["steps"])):
            d = first_difference(x, y)
            if d is not None:
                r["step"] = {"step": k, "module": module_index(x, d[0]), "lpy": d[1], "sprout": d[2]}
                break
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("reference")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--sets", default="share,tests,own")
    ap.add_argument("--only", default="")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--report", default="")
    ap.add_argument("--at-least", type=float, default=0.0)
    ap.add_argument("--tolerance", type=float, default=1e-9)
    args = ap.parse_args()
    global TOLERANCE
    TOLERANCE = args.tolerance
    if not os.access(args.reference, os.X_OK):
        print("no reference L-Py at %s: build it with ../shared/tools/build-lpy-reference.sh (skipped)" % args.reference)
        return 77
    entries = [e for e in models(args.sets.split(",")) if args.only in e[1]]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda e: compare(args, e), entries))
    low = False
    for group in args.sets.split(","):
        rs = [r for r in results if r["set"] == group]
        if not rs:
            continue
        base = os.path.join(SHARED, "corpus") if group != "own" else ROOT
        for r in rs:
            name = os.path.relpath(r["model"], base)
            if r["status"] in ("same",):
                continue
            line = "%-6s %-12s %s" % (group, r["status"], name)
            if r.get("why"):
                line += ": " + r["why"]
            if r["status"] == "differs":
                f = r["final"]
                line += "\n         final string, module %d: L-Py %r, Sprout %r (lengths %s)" % (f["module"], f["lpy"], f["sprout"], f["lengths"])
                if r.get("step"):
                    s = r["step"]
                    line += "\n         first at step %d, module %d: L-Py %r, Sprout %r" % (s["step"], s["module"], s["lpy"], s["sprout"])
            if r.get("shapes") and r["shapes"][0] != r["shapes"][1] and r["status"] != "differs":
                line += "  (shapes: L-Py %s, Sprout %s)" % tuple(r["shapes"])
            print(line)
        derived = [r for r in rs if r["status"] in ("same", "same-values", "differs", "sprout-fails")]
        same = [r for r in derived if r["status"] in ("same", "same-values")]
        written = [r for r in derived if r["status"] == "same"]
        shapes = [r for r in same if r.get("shapes") and r["shapes"][0] == r["shapes"][1]]
        pct = 100.0 * len(same) / max(1, len(derived))
        print("%s: %d models; L-Py derives %d the same way each run (%d vary, %d fail in L-Py); Sprout gives L-Py's string for %d "
              "(%.1f%%), written as L-Py writes it for %d; the same number of shapes for %d; Sprout fails on %d"
              % (group, len(rs), len(derived), sum(r["status"] == "lpy-varies" for r in rs),
                 sum(r["status"] in ("lpy-fails", "both-fail") for r in rs), len(same), pct, len(written), len(shapes),
                 sum(r["status"] == "sprout-fails" for r in rs)))
        low |= pct < args.at_least
    if args.report:
        with open(args.report, "w") as f:
            json.dump(results, f, indent=1)
    return 1 if low else 0


sys.exit(main())
