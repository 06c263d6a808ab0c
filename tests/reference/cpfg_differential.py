#!/usr/bin/python3
"""Sprout against the real cpfg on small L-system files (issue 50): differential testing of cpfg's
language, construct by construct, so that VLab objects nobody here has seen derive cpfg's string.

    tests/reference/cpfg_differential.py CPFG_BIN [--build build] [--random N] [--seed S]
                                         [--only TEXT] [--keep DIR] [--list] [--verbose]

Writes small cpfg `.l` files: the hand-written cases of tests/reference/cpfg_cases.py (one or
more for each construct of the CPFG manual and of cpfg's grammar, lsys_input.l/.y, and
derivation, generate.c) and N random ones (random_lsystem below: parametric modules of 0..3
parameters, conditions, left and right contexts with branches, ignore:/consider:, multi-module
predecessors, pre- and post-condition blocks with if/while/do, Start:/StartEach:/EndEach:
globals, arrays, #define constants and macros, cut %, decomposition with maximum depth,
sub-L-systems ?(k,s) ... $, stochastic productions with seed:, ring L-systems, expressions with
every operator and function). Each is run by both:

    cpfg -g -m t.map -str out.str t.l t.v      (in a scratch folder; t.map 768 zero bytes,
                                                t.v `angle factor: 8`; cpfg's exit status is
                                                0 even when it fails: out.str must exist)
    build/sprout expand t.l

and the strings compared module by module, numbers equal to 1e-5 relative (cpfg_compare.py's
first_difference). Prints a line for each case that differs (or that only one of them derives)
and the figures; exits 1 when any case differs or Sprout refuses what cpfg derives. --keep DIR
writes each such case there as NAME.l with cpfg's and Sprout's strings beside it (NAME.cpfg,
NAME.sprout); --verbose prints them. A random case is named random-SEED-K: `--random N --seed
SEED --only random-SEED-K` (K < N) runs it again alone.

Where cpfg itself fails (a crash, an error of its own on a valid file, or a 64-bit bug) the case
is noted as `cpfg fails` and not counted: Sprout does not copy cpfg's crashes.

A tool, not part of CI or the README's test command: it needs the reference cpfg (CPFG_BIN is
ROOT/bin of `bash ../shared/tools/build-cpfg-reference.sh ROOT VLAB_GITDIR`; its vlabcpp must be
on the PATH, which this script arranges).
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from cpfg_compare import first_difference  # noqa: E402
from cpfg_cases import CASES  # noqa: E402

VIEW = "angle factor: 8\n"


def run_cpfg(bin_dir, folder, timeout=20):
    """cpfg's string for folder/t.l, or (None, why)."""
    out = os.path.join(folder, "out.str")
    if os.path.exists(out):
        os.remove(out)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))
    try:
        p = subprocess.run([os.path.join(bin_dir, "cpfg"), "-g", "-m", "t.map", "-str", "out.str", "t.l", "t.v"],
                           cwd=folder, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timed out"
    text = p.stdout.decode(errors="replace")
    if not os.path.exists(out) or p.returncode < 0:
        lines = [l for l in text.strip().splitlines() if l.strip()]
        why = "signal %d" % -p.returncode if p.returncode < 0 else (lines[-1] if lines else "no output")
        return None, why
    with open(out, encoding="latin-1") as f:
        return f.read(), text


def run_sprout(build, folder, timeout=20):
    try:
        p = subprocess.run([os.path.join(build, "sprout"), "expand", os.path.join(folder, "t.l")],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timed out"
    err = p.stderr.decode(errors="replace")
    if p.returncode != 0:
        lines = [l for l in err.splitlines() if "warning" not in l]
        return None, (lines[:1] or ["exit %d" % p.returncode])[0]
    return p.stdout.decode(errors="replace"), err


def run_case(bin_dir, build, name, text, files=None):
    """('same' | 'differs' | 'cpfg fails' | 'sprout refuses' | 'both fail', detail, cpfg, sprout)."""
    folder = tempfile.mkdtemp(prefix="cpfg-diff-")
    try:
        with open(os.path.join(folder, "t.l"), "w") as f:
            f.write(text)
        with open(os.path.join(folder, "t.v"), "w") as f:
            f.write(VIEW)
        with open(os.path.join(folder, "t.map"), "wb") as f:
            f.write(bytes(768))
        for fname, content in (files or {}).items():
            with open(os.path.join(folder, fname), "w") as f:
                f.write(content)
        theirs, cpfg_log = run_cpfg(bin_dir, folder)
        ours, sprout_log = run_sprout(build, folder)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    if theirs is None and ours is None:
        return "both fail", "cpfg: %s; sprout: %s" % (cpfg_log, sprout_log), None, None
    if theirs is None:
        return "cpfg fails", cpfg_log, None, ours
    if ours is None:
        return "sprout refuses", sprout_log, theirs, None
    diff = first_difference(ours, theirs)
    return ("same", "", theirs, ours) if diff is None else ("differs", diff, theirs, ours)


# [random L-systems] ------------------------------------------------------------------------

class Gen:
    """One random cpfg L-system: symbols of fixed arity (sometimes one letter with two arities)."""

    def __init__(self, rng):
        self.r = rng
        letters = rng.sample("ABCDEGHIJKLMNOPRSTUVWXY", rng.randint(2, 5))
        self.arity = {}
        for c in letters:
            self.arity[c] = [rng.choice([0, 0, 1, 1, 2, 3])]
            if rng.random() < 0.1:
                self.arity[c].append((self.arity[c][0] + 1) % 3)
        self.turtle = ["F", "+", "-", "/", "&", "f"]
        self.globals = []
        self.arrays = []
        self.defines = []
        self.macros = []

    # expressions over the names in scope
    def expr(self, names, depth=0):
        r = self.r
        if depth > 3 or r.random() < 0.3:
            k = r.random()
            if names and k < 0.55:
                return r.choice(names)
            if self.defines and k < 0.6:
                return r.choice(self.defines)
            if self.arrays and k < 0.65:
                a, dims = r.choice(self.arrays)
                return a + "".join("[%s]" % self.index(names, d) for d in dims)
            return r.choice(["0", "1", "2", "3", "0.5", "1.5", "10", "2.25", "7", "0.1", ".5", "1.5e2", "3."])
        op = r.random()
        a = self.expr(names, depth + 1)
        b = self.expr(names, depth + 1)
        if op < 0.45:
            o = r.choice(["+", "-", "*", "/", "+", "-", "*", "^", "<", ">", "<=", ">=", "==", "!=", "&&", "||"])
            if o == "^":
                return "%s^%s" % (self.small(a), r.choice(["2", "0.5", "3", "-1"]))
            if o == "/":
                return "%s/(%s)" % (a, r.choice([b, "2", "4"]))
            return "%s %s %s" % (a, o, b) if r.random() < 0.5 else "(%s %s %s)" % (a, o, b)
        if op < 0.55:
            return "-%s" % self.atom(a)
        if op < 0.6:
            return "!%s" % self.atom(a)
        if op < 0.7:
            c = self.expr(names, depth + 1)
            return "(%s ? %s : %s)" % (a, b, c)
        if op < 0.9:
            f = r.choice(["sin", "cos", "floor", "ceil", "trunc", "fabs", "sign", "sqrt", "exp", "log", "atan", "tan",
                          "asin", "acos"])
            if f == "sqrt":
                return "sqrt(fabs(%s))" % a
            if f == "log":
                return "log(fabs(%s)+1)" % a
            if f == "exp":
                return "exp(%s/(fabs(%s)+10))" % (self.atom(a), self.atom(a))
            if f in ("asin", "acos"):
                return "%s(sin(%s))" % (f, a)
            if f == "atan2":
                return "atan2(%s, %s)" % (a, b)
            return "%s(%s)" % (f, a)
        if self.macros and op < 0.95:
            m, n = r.choice(self.macros)
            return "%s(%s)" % (m, ", ".join(self.expr(names, depth + 2) for _ in range(n)))
        return "(%s)" % a

    def atom(self, e):
        return e if e.replace(".", "").replace("_", "").isalnum() else "(%s)" % e

    def small(self, e):
        return "(fabs(%s)+1)" % e if self.r.random() < 0.7 else self.atom(e)

    def index(self, names, size):
        return "floor(fabs(%s))%%%d" % (self.expr(names, 3), size) if self.r.random() < 0.5 else str(self.r.randrange(size))

    def cond(self, names):
        r = self.r
        a, b = self.expr(names, 2), self.expr(names, 2)
        o = r.choice(["<", ">", "<=", ">=", "==", "!="])
        c = "%s %s %s" % (a, o, b)
        if r.random() < 0.3:
            c = "%s %s %s" % (c, r.choice(["&&", "||"]), self.expr(names, 2))
        return c

    def module(self, names, letters=None):
        r = self.r
        c = r.choice(letters or list(self.arity))
        n = r.choice(self.arity[c])
        if n == 0:
            return c
        return "%s(%s)" % (c, ",".join(self.expr(names, 1) for _ in range(n)))

    def formal(self, used, letters=None, exact=None):
        r = self.r
        c = exact or r.choice(letters or list(self.arity))
        n = r.choice(self.arity.get(c, [0]))
        if n == 0:
            return c, []
        ps = []
        for _ in range(n):
            v = "v%d" % len(used)
            used.append(v)
            ps.append(v)
        return "%s(%s)" % (c, ",".join(ps)), ps

    def successor(self, names, length, cut=False, sub=None):
        r = self.r
        out = []
        for _ in range(length):
            k = r.random()
            if k < 0.12:
                out.append(r.choice(self.turtle) + (("(%s)" % self.expr(names, 2)) if r.random() < 0.3 else ""))
            elif k < 0.25:
                inner = self.successor(names, r.randint(1, 2), cut)
                out.append("[" + inner + "]")
            elif cut and k < 0.3:
                out.append("%")
            elif sub and k < 0.35:
                out.append("?(%d,1)%s$" % (sub[0], self.module(names, sub[1])))
            else:
                out.append(self.module(names))
        return "".join(out) or "*"

    def axiom(self):
        parts = []
        for c in list(self.arity) * 2:
            n = self.arity[c][0]
            parts.append(c if n == 0 else "%s(%s)" % (c, ",".join(self.r.choice(["0", "1", "2", "3", "0.5", "-1"])
                                                            for _ in range(n))))
            if self.r.random() < 0.3:
                parts.append("[" + self.module([]) + "]")
        self.r.shuffle(parts)
        return "".join(parts)


def random_lsystem(seed):
    r = random.Random(seed)
    g = Gen(r)
    lines = []
    if r.random() < 0.3:
        g.defines = ["K%d" % i for i in range(r.randint(1, 2))]
        for d in g.defines:
            lines.append("#define %s %s" % (d, r.choice(["2", "0.5", "3", "(1+2)", "-1"])))
    if r.random() < 0.2:
        g.macros = [("M", 2)]
        lines.append("#define M(a,b) ((a)*2-(b))")
    lines.append("Lsystem: 1")
    stochastic = r.random() < 0.25
    if stochastic:
        lines.append("seed: %d" % r.randint(1, 1000))
    lines.append("derivation length: %d" % r.randint(1, 5))
    if r.random() < 0.1:
        lines.append("ring lsystem")
    if r.random() < 0.2:
        letters = r.sample(list(g.arity) + ["F", "+", "-"], 2)
        lines.append("ignore: " + " ".join(letters))
    elif r.random() < 0.1:
        letters = r.sample(list(g.arity), min(2, len(g.arity)))
        lines.append("consider: " + " ".join(letters + (["[", "]"] if r.random() < 0.3 else [])))
    if r.random() < 0.2:
        g.arrays = [("arr", [3]), ("mat", [2, 2])][: r.randint(1, 2)]
        defs = []
        for a, dims in g.arrays:
            size = 1
            for d in dims:
                size *= d
            defs.append("array %s%s = {%s};" % (a, "".join("[%d]" % d for d in dims),
                                                 ", ".join(r.choice(["1", "2", "0.5", "-3"]) for _ in range(size))))
        lines.append("define: { %s }" % " ".join(defs))
    if r.random() < 0.3:
        g.globals = ["gx", "gy"][: r.randint(1, 2)]
        lines.append("Start: { %s }" % " ".join("%s = %s;" % (v, g.expr([], 2)) for v in g.globals))
        blocks = ["StartEach", "EndEach"]
        r.shuffle(blocks)
        for b in blocks[: r.randint(0, 2)]:
            v = r.choice(g.globals)
            lines.append("%s: { %s = %s; }" % (b, v, g.expr(g.globals, 2)))
    lines.append("Axiom: " + g.axiom())
    sub = None
    if r.random() < 0.15:
        sub = (2, [r.choice(list(g.arity))])
    rules = []
    letters = list(g.arity)
    for _ in range(r.randint(1, 6)):
        used = []
        pred, ps = g.formal(used)
        if r.random() < 0.1:
            p2, _ = g.formal(used)
            pred += p2
        left = right = ""
        if r.random() < 0.3:
            left = "".join(g.formal(used)[0] for _ in range(r.randint(1, 2))) + " < "
        if r.random() < 0.3:
            parts = []
            for _ in range(r.randint(1, 2)):
                f = g.formal(used)[0]
                parts.append("[" + f + "]" if r.random() < 0.2 else f)
            right = " > " + "".join(parts)
        names = used + g.globals
        cond = ""
        pre = post = ""
        if r.random() < 0.2:
            loc = "t%d" % len(rules)
            kind = r.random()
            if kind < 0.5:
                pre = "{ %s = %s; } " % (loc, g.expr(names, 2))
            elif kind < 0.75:
                pre = "{ if (%s) { %s = 1; } else { %s = 2; } } " % (g.cond(names), loc, loc)
            else:
                pre = "{ %s = 0; while (%s < 3) { %s = %s + 1; } } " % (loc, loc, loc, loc)
            names = names + [loc]
        if g.globals and r.random() < 0.15:
            v = r.choice(g.globals)
            post = " { %s = %s + 1; }" % (v, v)
        if r.random() < 0.4 or pre or post:
            cond = " : " + pre + (g.cond(names) if r.random() < 0.7 else "*") + post
        succ = g.successor(names, r.randint(0, 4), cut=r.random() < 0.15, sub=sub)
        prob = " : %s" % r.choice(["1", "2", "0.5", "3"]) if stochastic and r.random() < 0.8 else ""
        rules.append("%s%s%s%s --> %s%s" % (left, pred, right, cond, succ, prob))
    lines.extend(rules)
    if r.random() < 0.15:
        lines.append("decomposition")
        if r.random() < 0.5:
            lines.append("maximum depth: %d" % r.randint(1, 3))
        for _ in range(r.randint(1, 2)):
            used = []
            pred, ps = g.formal(used, letters)
            lines.append("%s --> %s" % (pred, g.successor(used, r.randint(1, 2))))
    if r.random() < 0.2:
        lines.append("homomorphism")
        used = []
        pred, ps = g.formal(used, letters)
        lines.append("%s --> F%s" % (pred, g.successor(used, 1)))
    lines.append("endlsystem")
    if sub:
        lines.append("")
        lines.append("Lsystem: 2")
        lines.append("derivation length: 1")
        lines.append("Axiom: " + g.axiom())
        used = []
        pred, ps = g.formal(used, sub[1])
        lines.append("%s --> %s" % (pred, g.successor(used, r.randint(1, 3))))
        lines.append("endlsystem")
    return "\n".join(lines) + "\n"


# [main] ------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cpfg_bin")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--random", type=int, default=0, help="this many random L-systems after the hand-written cases")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--only", default="")
    ap.add_argument("--keep", default="")
    ap.add_argument("--list", action="store_true", help="print every case's outcome, not only the differences")
    ap.add_argument("--verbose", action="store_true", help="print each differing case's text and both strings")
    a = ap.parse_args()
    if not os.path.exists(os.path.join(a.cpfg_bin, "cpfg")):
        print("no reference cpfg in %s: skipped" % a.cpfg_bin)
        return 77
    cases = [(name, text, files) for name, text, files in CASES]
    cases += [("random-%d-%d" % (a.seed, k), random_lsystem(a.seed * 100003 + k), None) for k in range(a.random)]
    counts = {}
    for name, text, files in cases:
        if a.only and a.only not in name:
            continue
        outcome, detail, theirs, ours = run_case(a.cpfg_bin, a.build, name, text, files)
        counts[outcome] = counts.get(outcome, 0) + 1
        if outcome != "same" or a.list:
            print("%-28s %s%s" % (name, outcome, ": " + detail if detail else ""))
        if outcome in ("differs", "sprout refuses") and a.verbose:
            print(text)
            print("  cpfg:   %s" % (theirs or "").strip()[:600])
            print("  sprout: %s" % (ours or "").strip()[:600])
        if a.keep and outcome in ("differs", "sprout refuses"):
            os.makedirs(a.keep, exist_ok=True)
            with open(os.path.join(a.keep, name + ".l"), "w") as f:
                f.write(text)
            for ext, s in (("cpfg", theirs), ("sprout", ours)):
                if s is not None:
                    with open(os.path.join(a.keep, name + "." + ext), "w") as f:
                        f.write(s)
    print("\n" + ", ".join("%s %d" % (k, v) for k, v in sorted(counts.items())))
    return 1 if counts.get("differs") or counts.get("sprout refuses") else 0


if __name__ == "__main__":
    sys.exit(main())
