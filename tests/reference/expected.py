#!/usr/bin/python3
"""Writes the `# expect N: STRING` lines of Sprout's own L-Py test models (tests/lpy/models)
from what the real L-Py derives (issue 40), so that ctest checks Sprout against L-Py without
the reference being there.

    tests/reference/expected.py REF_PYTHON [--check]

REF_PYTHON is the reference L-Py's interpreter (ROOT/venv/bin/python after
`bash ../shared/tools/build-lpy-reference.sh ROOT PLANTGL_GITDIR LPY_GITDIR`: L-Py 3.15.4 with
PlantGL 3.22.3). For each line `# expect N: ...` of a model, L-Py derives N steps with the
model's derivation length set to N (`Lsystem(f)`, `derivationLength = N`, `derive()`: its End
hook runs after step N, as `sprout expand -n N` runs it), Python's and numpy's random seeded
with 0, and the line is rewritten with `str()` of L-Py's string. A model L-Py cannot run keeps
its lines (listed). With --check nothing is written: the lines that would change are listed and
the exit status is 1 when there are any.
"""
import glob
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = os.path.join(os.path.dirname(HERE), "lpy", "models")
EXPECT = re.compile(r"^# expect (\d+): (.*)$")

DERIVE = r"""
import json, os, random, sys
sys.stdout, out = sys.stderr, sys.stdout
path, steps = sys.argv[1], [int(s) for s in sys.argv[2:]]
os.chdir(os.path.dirname(path))
from openalea.lpy import Lsystem
result = {}
for n in steps:
    random.seed(0)
    try:
        import numpy
        numpy.random.seed(0)
    except ImportError:
        pass
    try:
        l = Lsystem(path)
        l.derivationLength = n
        result[n] = str(l.derive())
    except BaseException as e:
        result[n] = None
        result["error"] = "%s: %s" % (type(e).__name__, e)
out.write(json.dumps(result))
out.flush()
os._exit(0)
"""


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    python, check = sys.argv[1], "--check" in sys.argv
    changed = failed = 0
    for path in sorted(glob.glob(os.path.join(MODELS, "*.lpy"))):
        lines = open(path).read().split("\n")
        steps = sorted({int(m.group(1)) for m in map(EXPECT.match, lines) if m})
        if not steps:
            continue
        got = {}
        for n in steps:  # a process each: L-Py's module classes and aliases are the process's
            p = subprocess.run([python, "-c", DERIVE, path, str(n)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, env=dict(os.environ, QT_QPA_PLATFORM="offscreen"), timeout=120)
            try:
                got.update(json.loads(p.stdout.decode() or "{}"))
            except ValueError:
                got["error"] = "no output"
        if "error" in got or not got:
            failed += 1
            print("%s: L-Py cannot run it (%s): its lines are kept" % (os.path.basename(path), got.get("error", "no output")))
            continue
        for i, line in enumerate(lines):
            m = EXPECT.match(line)
            if not m:
                continue
            want = got.get(m.group(1))
            if want is None or want == m.group(2):
                continue
            changed += 1
            print("%s, %s steps:\n  was    %s\n  L-Py   %s" % (os.path.basename(path), m.group(1), m.group(2)[:200], want[:200]))
            lines[i] = "# expect %s: %s" % (m.group(1), want)
        if not check:
            with open(path, "w") as f:
                f.write("\n".join(lines))
    print("%d lines %s from L-Py; %d models L-Py cannot run" % (changed, "differ" if check else "rewritten", failed))
    return 1 if check and changed else 0


sys.exit(main())
