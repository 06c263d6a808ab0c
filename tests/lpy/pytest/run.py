#!/usr/bin/python3
"""L-Py's own pytest suite, unmodified, against Sprout (issue 37).

    run.py BUILD_DIR CORPUS_DIR [--at-least N] [--list]

CORPUS_DIR holds `lpy-tests` (L-Py's test folder) and `lpy` (L-Py's share/ folder, which
some tests open as ../share). Each test file runs in a pytest of its own (a file that hangs
or crashes costs only its own tests), in a folder laid out as L-Py's sources are (test/ and
share/ side by side), with this folder's conftest.py loaded (`-p conftest`): it calls
sprout.use_as_openalea(), so `from openalea.lpy import *` gives Sprout's.

Prints every test that fails and the count passed of all; exits 1 when fewer than N pass.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))


def run_file(path, test_dir, env, timeout):
    """(passed, [(test, why)]) for one test file."""
    with tempfile.NamedTemporaryFile(suffix='.xml', delete=False) as f:
        report = f.name
    name = os.path.basename(path)
    try:
        cmd = [sys.executable, '-m', 'pytest', '-q', '-p', 'no:cacheprovider', '-p', 'conftest',
               '--junitxml', report, name]
        try:
            proc = subprocess.run(cmd, cwd=test_dir, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  timeout=timeout)
        except subprocess.TimeoutExpired:
            return 0, [(name, 'timed out after %d s' % timeout)]
        try:
            root = ET.parse(report).getroot()
        except (ET.ParseError, FileNotFoundError):
            tail = proc.stdout.decode(errors='replace').strip().splitlines()[-1:] or ['no output']
            return 0, [(name, 'pytest ended without a report (exit %d): %s' % (proc.returncode, tail[0]))]
        passed, failed = 0, []
        for case in root.iter('testcase'):
            problem = next((c for c in case if c.tag in ('failure', 'error')), None)
            skipped = next((c for c in case if c.tag == 'skipped'), None)
            test = '%s::%s' % (name, case.get('name'))
            if problem is not None:
                why = (problem.get('message') or problem.text or '').strip().splitlines()
                failed.append((test, why[0][:200] if why else problem.tag))
            elif skipped is not None:
                failed.append((test, 'skipped: ' + (skipped.get('message') or '')[:200]))
            else:
                passed += 1
        if passed == 0 and not failed:
            failed.append((name, 'no test ran: ' + (proc.stdout.decode(errors='replace').strip().splitlines() or [''])[-1][:200]))
        return passed, failed
    finally:
        if os.path.exists(report):
            os.unlink(report)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('corpus')
    ap.add_argument('--at-least', type=int, default=0)
    ap.add_argument('--timeout', type=int, default=120)
    ap.add_argument('--total', type=int, default=153, help="the suite's count of tests")
    args = ap.parse_args()
    tests = os.path.join(args.corpus, 'lpy-tests')
    if not os.path.isdir(tests):
        print('%s is not here: nothing to run' % tests)
        return 0
    work = tempfile.mkdtemp(prefix='sprout-lpy-pytest-')
    # test/ a folder of links (a link to the folder would make `..` the corpus's parent).
    os.mkdir(os.path.join(work, 'test'))
    for name in os.listdir(tests):
        os.symlink(os.path.abspath(os.path.join(tests, name)), os.path.join(work, 'test', name))
    if os.path.isdir(os.path.join(args.corpus, 'lpy')):
        os.symlink(os.path.abspath(os.path.join(args.corpus, 'lpy')), os.path.join(work, 'share'))
    env = dict(os.environ)
    env['PYTHONPATH'] = os.pathsep.join([os.path.join(os.path.abspath(args.build), 'python'), HERE])
    env['PYTHONDONTWRITEBYTECODE'] = '1'  # nothing written into the corpus
    env.setdefault('MPLBACKEND', 'Agg')
    try:
        return run_all(args, tests, work, env)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def run_all(args, tests, work, env):
    passed, failures = 0, []
    test_dir = os.path.join(work, 'test')
    for name in sorted(os.listdir(tests)):
        if name.startswith('test_') and name.endswith('.py'):
            p, f = run_file(os.path.join(tests, name), test_dir, env, args.timeout)
            passed += p
            failures += f
    for test, why in failures:
        print('FAIL %s: %s' % (test, why))
    print("L-Py's pytest suite on Sprout: %d of %d pass" % (passed, args.total))
    if passed < args.at_least:
        print('fewer than %d: a regression' % args.at_least)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
