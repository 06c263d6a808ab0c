#!/usr/bin/env python3
"""Derives L-Py models the way a user of L-Py's Python API does, in whichever `openalea.lpy`
this interpreter has: the real L-Py (the reference built by ../shared/tools/build-lpy-reference.sh)
or Sprout's (with --sprout BUILD_DIR: `sprout.use_as_openalea()`). One model a call, so that a
model that hangs or crashes costs only itself (tests/reference/compare.py runs it per model).

    lpy_derive.py MODEL.lpy [--sprout BUILD_DIR] [--steps]

Prints one JSON object: ok, error, final (str(Lsystem(f).derive())), shapes (the number of
shapes of sceneInterpretation(final)), and with --steps each step's string, derived one step
at a time (derive(s, i, 1)). Python's and numpy's random are seeded with 0 before the model is
read, on both sides alike.
"""
import json
import os
import random
import sys
import time
import traceback


def main():
    args = sys.argv[1:]
    path = os.path.abspath(args[0])
    steps = "--steps" in args
    if "--sprout" in args:
        build = os.path.abspath(args[args.index("--sprout") + 1])
        sys.path.insert(0, os.path.join(build, "python"))
        import sprout
        sprout.use_as_openalea()
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    out = {"ok": False}
    # Output of the model's own prints goes to stderr: stdout carries the JSON only.
    real_stdout = sys.stdout
    sys.stdout = sys.stderr
    try:
        from openalea.lpy import Lsystem

        os.chdir(os.path.dirname(path))
        sys.path.insert(0, os.path.dirname(path))

        def seed():
            random.seed(0)
            try:
                import numpy
                numpy.random.seed(0)
            except ImportError:
                pass

        seed()
        t0 = time.perf_counter()
        lsys = Lsystem(path)
        final = lsys.derive()
        out["seconds"] = time.perf_counter() - t0
        out["final"] = str(final)
        out["length"] = len(final)
        try:
            out["shapes"] = len(lsys.sceneInterpretation(final))
        except Exception as e:  # the scene is a second question: the string stands without it
            out["shapes_error"] = "%s: %s" % (type(e).__name__, e)
        out["ok"] = True
        if steps:
            seed()
            lsys = Lsystem(path)
            s = lsys.axiom
            every = [str(s)]
            for i in range(lsys.derivationLength):
                s = lsys.derive(s, i, 1)
                every.append(str(s))
            out["steps"] = every
    except BaseException as e:  # SystemExit included: a model's end is a result here
        out["error"] = "%s: %s" % (type(e).__name__, str(e).strip().splitlines()[0] if str(e).strip() else "")
        out["trace"] = traceback.format_exc()[-2000:]
    sys.stdout = real_stdout
    sys.stdout.write(json.dumps(out) + "\n")
    sys.stdout.flush()
    os._exit(0)  # no interpreter teardown: some models leave threads or Qt objects behind


main()
