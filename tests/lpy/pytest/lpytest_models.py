#!/usr/bin/python3
"""L-Py's lpytest/ models (73 small models, many asserting in End() what their derivation
made), each run two ways as a user would: `sprout render FILE` in its folder, and
Lsystem(FILE).iterate() from Python after sprout.use_as_openalea() (issue 37).

    lpytest_models.py BUILD_DIR CORPUS_DIR [--at-least N]

Prints every model that fails either way, with its first line of error, and the counts;
exits 1 when fewer than N models run clean both ways.
"""
import argparse
import os
import subprocess
import sys
import tempfile

PY_RUN = r'''
import sys, sprout
sprout.use_as_openalea()
from openalea.lpy import Lsystem
l = Lsystem(sys.argv[1])
l.iterate()
'''


def first_error(out):
    lines = [l for l in out.decode(errors='replace').strip().splitlines() if l.strip()]
    return lines[-1][:200] if lines else 'no message'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('corpus')
    ap.add_argument('--at-least', type=int, default=0)
    ap.add_argument('--timeout', type=int, default=60)
    args = ap.parse_args()
    folder = os.path.join(args.corpus, 'lpy-tests', 'lpytest')
    if not os.path.isdir(folder):
        print('%s is not here: nothing to run' % folder)
        return 0
    sprout = os.path.join(os.path.abspath(args.build), 'sprout')
    env = dict(os.environ, PYTHONPATH=os.path.join(os.path.abspath(args.build), 'python'), PYTHONDONTWRITEBYTECODE='1')
    models = sorted(f for f in os.listdir(folder) if f.endswith('.lpy'))
    clean = {'render': 0, 'Lsystem': 0}
    both = 0
    with tempfile.TemporaryDirectory() as tmp:
        picture = os.path.join(tmp, 'model.png')
        for name in models:
            ok = True
            runs = {'render': [sprout, 'render', name, '-o', picture, '--size', '64x48'],
                    'Lsystem': [sys.executable, '-c', PY_RUN, name]}
            for how, cmd in runs.items():
                try:
                    p = subprocess.run(cmd, cwd=folder, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                       timeout=args.timeout)
                    if p.returncode == 0:
                        clean[how] += 1
                        continue
                    why = first_error(p.stdout)
                except subprocess.TimeoutExpired:
                    why = 'timed out after %d s' % args.timeout
                ok = False
                print('FAIL %s (%s): %s' % (name, how, why))
            both += ok
    print('lpytest/: %d of %d run clean through sprout render, %d through Lsystem(f).iterate(), %d both'
          % (clean['render'], len(models), clean['Lsystem'], both))
    if both < args.at_least:
        print('fewer than %d: a regression' % args.at_least)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
