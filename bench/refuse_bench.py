#!/usr/bin/python3
"""Explosive growth refused (issue 39): each input as whole `sprout expand` or `sprout render`
processes, the time and peak memory until the refusal, against deriving step 1 of the same
file in the same run (the ratio: how many first steps the refusal costs; for the forest, one
plant of it). Best of 3 wall-clock runs each.

    bench/refuse_bench.py [build/sprout]
"""
import os, resource, subprocess, sys, tempfile, time

SPROUT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/sprout")
# (label, {file: text}, the refused command, the one-step command); {d} is the folder of the files.
def expand(name, extra=()):
    return (["expand", "{d}/" + name] + list(extra), ["expand", "{d}/" + name, "-n", "1"] + list(extra))


def render(name, extra=(), one=None):
    picture = ["-o", "{d}/out.png", "--size", "64x48"]
    return (["render", "{d}/" + name] + picture + list(extra), one or ["render", "{d}/" + name, "-n", "1"] + picture + list(extra))


BODY = "Axiom: A(1)\nderivation length: %d\nproduction:\nA(x) :\n    y = x * 2\n    produce A(x+1) A(y)\nendlsystem\n"
INPUTS = [
    ("parametric .lsys, triples (n: 60)", {"boom.lsys": "n: 60\naxiom: A(1)\nA(x) -> A(x+1)A(x*2)A(x)\n"}, *expand("boom.lsys")),
    ("D0L .lsys, x10 (n: 40)", {"d0l.lsys": "n: 40\naxiom: F\nF -> FFFFFFFFFF\n"}, *expand("d0l.lsys")),
    ("cpfg decomposition doubling for 40 passes",
     {"dec.l": "derivation length: 30\nAxiom: A\nA --> AB\ndecomposition:\nmaximum depth: 40\nB --> BB\n"}, *expand("dec.l")),
    ("L-Py A --> AA (derivation length 40)", {"aa.lpy": "Axiom: A\nderivation length: 40\nproduction:\nA --> AA\nendlsystem\n"},
     *expand("aa.lpy")),
    ("L-Py Python body, lists as parameters (64 MB budget)",
     {"lists.lpy": "Axiom: A([1.0] * 20)\nderivation length: 40\nproduction:\nA(x) :\n    y = list(x)\n    produce A(x) A(y)\nendlsystem\n"},
     *expand("lists.lpy", ["--max-memory", "64"])),
    ("L-Py Python body, produce A(x+1) A(x*2) (derivation length 40)", {"body.lpy": BODY % 40}, *expand("body.lpy")),
    ("the same, over the limit only at its last step (length 26)", {"last.lpy": BODY % 26}, *expand("last.lpy")),
    ("drawing 16.7 M segments, 256 MB budget (render)", {"segments.lsys": "n: 24\naxiom: F\nF -> FF\n"},
     *render("segments.lsys", ["--max-memory", "256"])),
    ("cpfg homomorphism A --> F+F-F at n 24, 64 MB budget (render)",
     {"homomorphism.l": "derivation length: 24\nAxiom: A\nA --> AA\nhomomorphism:\nA --> F+F-F\nendlsystem\n"},
     *render("homomorphism.l", ["--max-memory", "64"])),
    ("forest of 16 plants of 1 M segments, 256 MB budget (render)",
     {"small.lsys": "n: 20\naxiom: F\nF -> FF\n",
      "many.forest": "scene: forest\ngrid: 4 4\nspacing: 40\nseed: 2\nspecies: {d}/small.lsys 1\n",
      "one.forest": "scene: forest\ngrid: 1 1\nspacing: 40\nseed: 2\nspecies: {d}/small.lsys 1\n"},
     *render("many.forest", ["--max-memory", "256"], ["render", "{d}/one.forest", "-o", "{d}/out.png", "--size", "64x48"])),
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
        print("%-66s %9s %9s %12s %s" % ("input", "refused", "peak MB", "1 step", "ratio"))
        for label, files, refused, one_step in INPUTS:
            for name, text in files.items():
                with open(os.path.join(tmp, name), "w") as f:
                    f.write(text.replace("{d}", tmp))
            refused = [a.replace("{d}", tmp) for a in refused]
            one_step = [a.replace("{d}", tmp) for a in one_step]
            best, peak, message = 1e9, 0.0, ""
            for _ in range(3):
                s, mb, code, last = run(refused)
                if code == 0:
                    sys.exit("%s: not refused" % label)
                best, peak, message = min(best, s), max(peak, mb), last
            one = min(run(one_step)[0] for _ in range(3))
            print("%-66s %8.2fs %9.0f %11.3fs %6.1fx" % (label, best, peak, one, best / one))
            print("    %s" % message.replace(tmp + "/", "")[:200])


main()
