#!/usr/bin/python3
"""Sprout against the real cpfg (issue 50): every VLab object derived by both, the strings compared.

    tests/reference/cpfg_compare.py CPFG_BIN [--build build] [--objects DIR] [--only TEXT]
                                    [--at-least N] [--write-expected DIR] [--time]

CPFG_BIN is the folder of the reference cpfg (ROOT/bin after
`bash ../shared/tools/build-cpfg-reference.sh ROOT VLAB_GITDIR`, with WITH_ENVIRO=1 for the
environment programs). Each object (a folder with a `specifications`) is copied to a scratch
folder and run as its specifications' cpfg line says, with `-g -str out.str` added (cpfg's
window options -w/-wp/-wr/-wpr/-wt left out): that is cpfg's derived string, before
homomorphism. `sprout expand FOLDER` gives Sprout's. They are compared module by module,
numbers equal to 1e-5 (relative; 1e-9 absolute near zero). Prints a line per object and the
figures; exits 1 when fewer than --at-least objects give cpfg's string.

--write-expected DIR writes cpfg's strings as DIR/NAME.str (test data for
VlabObject.ManualObjectsDeriveCpfgsStrings, made by this script: see that folder's README);
--expected DIR compares with those instead of running cpfg (that test, without the reference).
--time prints both programs' times per object and the median ratio (bench/cpfg_vs_reference.sh).

Not part of the README's test command or CI: ctest runs it under the label `reference` when
SPROUT_CPFG_REFERENCE names the reference's bin folder.
"""
import argparse
import glob
import math
import os
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SHARED = os.path.join(os.path.dirname(ROOT), "shared")
WINDOW_OPTIONS = {"-w": 2, "-wp": 2, "-wr": 2, "-wpr": 2, "-wt": 1}

MODULE = re.compile(r"\s*([^\s(])(\(([^()]*)\))?")


def objects(folder):
    return sorted(os.path.dirname(p) for p in glob.glob(os.path.join(folder, "**", "specifications"), recursive=True))


def cpfg_line(folder):
    with open(os.path.join(folder, "specifications"), encoding="latin-1") as f:
        for line in f:
            words = line.split()
            if words and words[0] == "cpfg":
                return words[1:]
    return None


def modules(text):
    """A string as (symbol, [numbers]) pairs; whitespace (cpfg's wrapping) is not part of it."""
    out, i = [], 0
    text = text.strip()
    while i < len(text):
        m = MODULE.match(text, i)
        if not m or m.end() == i:
            break
        params = []
        if m.group(2) is not None and m.group(3).strip():
            for p in m.group(3).split(","):
                try:
                    params.append(float(p))
                except ValueError:
                    params.append(p.strip())
        out.append((m.group(1), params))
        i = m.end()
        while i < len(text) and text[i].isspace():
            i += 1
    return out


def close(a, b):
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    if a == b:  # infinities too
        return True
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= max(1e-9, 1e-5 * max(abs(a), abs(b)))


def first_difference(ours, theirs):
    a, b = modules(ours), modules(theirs)
    for i, (x, y) in enumerate(zip(a, b)):
        if x[0] != y[0] or len(x[1]) != len(y[1]) or not all(close(p, q) for p, q in zip(x[1], y[1])):
            return "module %d: sprout %s, cpfg %s" % (i + 1, show(x), show(y))
    if len(a) != len(b):
        return "sprout has %d modules, cpfg %d" % (len(a), len(b))
    return None


def show(m):
    return m[0] + ("(" + ",".join("%g" % p if isinstance(p, float) else p for p in m[1]) + ")" if m[1] else "")


def run_cpfg(bin_dir, folder, timeout=300):
    words = cpfg_line(folder)
    if words is None:
        return None, "no cpfg line", 0.0
    args, i = [], 0
    while i < len(words):
        if words[i] in WINDOW_OPTIONS:
            i += 1 + WINDOW_OPTIONS[words[i]]
            continue
        args.append(words[i])
        i += 1
    # An environment program of the object's own (`executable: ./obcheck ...`) that is not built
    # in its folder: cpfg runs without it and its ?E keep their values, not the object's string.
    if "-e" in args and args.index("-e") + 1 < len(args):
        try:
            with open(os.path.join(folder, args[args.index("-e") + 1]), encoding="latin-1") as f:
                for line in f:
                    if line.startswith("executable:"):
                        program = line.split(":", 1)[1].split()
                        if program and program[0].startswith("./") and not os.path.exists(os.path.join(folder, program[0])):
                            return None, "its environment program %s is the object's own C, not built" % program[0], 0.0
        except OSError:
            pass
    scratch = tempfile.mkdtemp(prefix="cpfg-ref-")
    try:
        work = os.path.join(scratch, "object")
        shutil.copytree(folder, work)
        env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))
        start = time.perf_counter()
        try:
            p = subprocess.run([os.path.join(bin_dir, "cpfg"), "-g", "-str", os.path.join(work, "out.str")] + args,
                               cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, "timed out", 0.0
        seconds = time.perf_counter() - start
        out = os.path.join(work, "out.str")
        if not os.path.exists(out):
            tail = p.stdout.decode(errors="replace").strip().splitlines()[-1:] or ["no output"]
            return None, "cpfg wrote no string: " + tail[0], seconds
        with open(out, encoding="latin-1") as f:
            return f.read(), None, seconds
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def run_sprout(build, folder, timeout=300):
    start = time.perf_counter()
    try:
        p = subprocess.run([os.path.join(build, "sprout"), "expand", folder], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timed out", 0.0
    seconds = time.perf_counter() - start
    if p.returncode != 0:
        lines = [l for l in p.stderr.decode(errors="replace").splitlines() if "warning" not in l]
        return None, (lines[:1] or ["exit %d" % p.returncode])[0], seconds
    return p.stdout.decode(errors="replace"), None, seconds


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cpfg_bin")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--objects", default=os.path.join(SHARED, "corpus", "vlab-manuals"))
    ap.add_argument("--only", default="")
    ap.add_argument("--at-least", type=int, default=0)
    ap.add_argument("--write-expected", default="")
    ap.add_argument("--time", action="store_true")
    ap.add_argument("--repeat", type=int, default=3, help="with --time: the best of this many runs of each")
    ap.add_argument("--expected", default="", help="compare with the strings kept in this folder instead of running cpfg")
    a = ap.parse_args()
    if a.expected and not os.path.isdir(a.objects):
        print("no %s: skipped" % a.objects)
        return 77
    if not a.expected and not os.path.exists(os.path.join(a.cpfg_bin, "cpfg")):
        print("no reference cpfg (SPROUT_CPFG_REFERENCE): skipped")
        return 77
    same, refused, ratios = 0, 0, []
    found = [f for f in objects(a.objects) if a.only in f]
    if a.expected:
        found = [f for f in found if os.path.exists(os.path.join(a.expected, os.path.basename(f) + ".str"))]
    for folder in found:
        name = os.path.relpath(folder, a.objects)
        if a.expected:
            with open(os.path.join(a.expected, os.path.basename(folder) + ".str"), encoding="latin-1") as f:
                theirs, why, t_cpfg = f.read(), None, 0.0
        else:
            theirs, why, t_cpfg = run_cpfg(a.cpfg_bin, folder)
        if theirs is None:
            refused += 1
            print("%-40s cpfg refuses it (%s)" % (name, why))
            continue
        if a.write_expected:
            with open(os.path.join(a.write_expected, os.path.basename(folder) + ".str"), "w") as f:
                f.write(theirs)
        ours, why, t_sprout = run_sprout(a.build, folder)
        timing = ""
        if a.time and ours is not None:
            for _ in range(max(0, a.repeat - 1)):  # the best of several runs, both programs alike
                t_cpfg = min(t_cpfg, run_cpfg(a.cpfg_bin, folder)[2] or t_cpfg)
                t_sprout = min(t_sprout, run_sprout(a.build, folder)[2] or t_sprout)
            ratios.append(t_cpfg / max(t_sprout, 1e-6))
            timing = "  cpfg %.3f s, sprout %.3f s (%.2fx)" % (t_cpfg, t_sprout, ratios[-1])
        if ours is None:
            print("%-40s sprout: %s" % (name, why))
            continue
        diff = first_difference(ours, theirs)
        if diff is None:
            same += 1
            print("%-40s same%s" % (name, timing))
        else:
            print("%-40s differs: %s%s" % (name, diff, timing))
    derived = len(found) - refused
    print("\n%d objects, cpfg derives %d; Sprout gives cpfg's string on %d" % (len(found), derived, same))
    if ratios:
        print("median time ratio cpfg/sprout: %.2fx (over %d objects)" % (statistics.median(ratios), len(ratios)))
    return 0 if same >= a.at_least else 1


if __name__ == "__main__":
    sys.exit(main())
