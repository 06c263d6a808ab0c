#!/usr/bin/python3
"""Sprout's openalea.plantgl against the reference PlantGL (issue 51): the same Python run by both,
the values compared (tests/reference/plantgl_cases.py: cardinal splines, curves' members,
vectors and matrices, bounding boxes, surfaces, the light model and its z-buffer).

    tests/reference/plantgl_differential.py REF_PYTHON [--build build] [--only TEXT]

REF_PYTHON is the reference's python (../shared/tools/build-lpy-reference.sh); `none` or a
path that is not there skips (exit 77). Numbers are compared to each case's relative tolerance
(a dict's keys must be the same), exceptions by their type. Prints every case that differs
and the count; exits 1 when any differs. The ctest Reference.PlantGLComputesWhatPlantGLComputes
runs it under the label `reference`.
"""
import argparse
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from plantgl_cases import CASES  # noqa: E402

RUNNER = r'''
import json, sys
if sys.argv[1] == "sprout":
    import sprout
    sprout.use_as_openalea()
from openalea.plantgl.all import *

def plain(v, depth=0):
    if depth > 8:
        return repr(v)
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return v
    if isinstance(v, (int, float)):
        return float(v)
    if isinstance(v, dict):
        return {"__dict__": sorted([[plain(k, depth + 1), plain(x, depth + 1)] for k, x in v.items()], key=repr)}
    try:
        return [plain(x, depth + 1) for x in v]
    except TypeError:
        return repr(v)

out = []
for code in json.load(sys.stdin):
    scope = {}
    exec("from openalea.plantgl.all import *", scope)
    try:
        exec(code, scope)
        out.append(plain(scope.get("result")))
    except Exception as e:
        out.append({"__raise__": type(e).__name__, "message": str(e)})
print(json.dumps(out))
'''


def run(python, which, codes, build):
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    if which == "sprout":
        env["PYTHONPATH"] = os.path.join(build, "python")
    p = subprocess.run([python, "-c", RUNNER, which], input=json.dumps(codes), capture_output=True, text=True,
                       env=env, timeout=1800)
    if p.returncode != 0:
        sys.exit("%s's PlantGL did not run the cases:\n%s" % (which, p.stderr[-3000:]))
    return json.loads(p.stdout.strip().splitlines()[-1])


def differs(a, b, tol, where="result"):
    """Where a and b differ beyond `tol` (relative, with an absolute floor of tol), or None."""
    if isinstance(a, float) and isinstance(b, float):
        if math.isnan(a) and math.isnan(b):
            return None
        if abs(a - b) <= tol * max(1.0, abs(a), abs(b)):
            return None
        return "%s: %r against %r" % (where, a, b)
    if isinstance(a, dict) and isinstance(b, dict):
        if "__raise__" in a or "__raise__" in b:
            return None if a.get("__raise__") == b.get("__raise__") else "%s: %r against %r" % (where, a, b)
        ka, kb = [k for k, _ in a["__dict__"]], [k for k, _ in b["__dict__"]]
        if ka != kb:
            return "%s: keys %r against %r" % (where, ka, kb)
        for (k, x), (_, y) in zip(a["__dict__"], b["__dict__"]):
            d = differs(x, y, tol, "%s[%r]" % (where, k))
            if d:
                return d
        return None
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return "%s: %d items against %d" % (where, len(a), len(b))
        for i, (x, y) in enumerate(zip(a, b)):
            d = differs(x, y, tol, "%s[%d]" % (where, i))
            if d:
                return d
        return None
    return None if a == b else "%s: %r against %r" % (where, a, b)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("reference")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", default="")
    ap.add_argument("--show", action="store_true", help="print both values of every case")
    args = ap.parse_args()
    if not os.path.isfile(args.reference):
        print("no reference PlantGL (%s): skipped" % args.reference)
        return 77
    cases = [c for c in CASES if args.only in c[0]]
    codes = [c[1] for c in cases]
    ref = run(args.reference, "reference", codes, args.build)
    own = run("/usr/bin/python3", "sprout", codes, args.build)
    bad = 0
    for (name, _, tol), r, s in zip(cases, ref, own):
        d = differs(r, s, tol)
        if args.show:
            print("%s\n  reference: %s\n  sprout:    %s" % (name, json.dumps(r)[:1500], json.dumps(s)[:1500]))
        if d:
            bad += 1
            print("DIFFERS %s: %s" % (name, d[:1500]))
    print("%d of %d cases give the reference PlantGL's values" % (len(cases) - bad, len(cases)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
