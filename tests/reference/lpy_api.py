#!/usr/bin/python3
"""openalea.lpy's API, Sprout's against the real L-Py's (issue 51), name by name.

    lpy_api.py inventory [--sprout BUILD]          this interpreter's openalea.lpy: its public
                                                   names and its classes' members, as JSON
    lpy_api.py cases [--sprout BUILD]              runs the differential cases (lpy_api_cases/)
                                                   in this interpreter, their results as JSON
    lpy_api.py compare REF_PYTHON --build BUILD [--at-least 95] [--write-reference FILE]
                                                   both sides' names and cases, compared
    lpy_api.py check --build BUILD --reference FILE [--at-least-names N --at-least-members M]
                                                   Sprout's names against a kept inventory
                                                   (no reference needed)
    lpy_api.py docs --build BUILD --reference FILE [--write PAGE]
                                                   the side-by-side page of the docs

Public names are dir(openalea.lpy) without a leading underscore; a public class is one of them
that is a class, and its public members are dir(cls) without a leading underscore (for a class
built on int, an enum, less int's own). A member is "checked" when every differential case that
names it gives the same result in both (or, for what the reference crashes on, a case marked
@defined gives in Sprout what L-Py's definition says); UI-only names (a case file's UI_ONLY) must exist in
Sprout and raise NotImplementedError there, and are counted apart.

REF_PYTHON is the reference L-Py's interpreter (ROOT/venv/bin/python after
`bash ../shared/tools/build-lpy-reference.sh ROOT PLANTGL_GITDIR LPY_GITDIR`). Not part of the
README's test command or CI: ctest runs `compare` under the label `reference` when
SPROUT_LPY_REFERENCE names that python, and `check` (against tests/data/lpy-api-reference.json,
written by `compare --write-reference` from the reference) always.
"""
import importlib.util
import io
import json
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "lpy_api_cases")
# Exceptions that are the same error told by Boost.Python and by Python.
SAME_ERROR = {"ArgumentError": "TypeError"}


def load_lpy(sprout_build):
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    if sprout_build:
        sys.path.insert(0, os.path.join(os.path.abspath(sprout_build), "python"))
        import sprout

        sprout.use_as_openalea()
    import openalea.lpy

    return openalea.lpy


def inventory(lpy):
    names = sorted(n for n in dir(lpy) if not n.startswith("_"))
    classes = {}
    for n in names:
        obj = getattr(lpy, n)
        if isinstance(obj, type):
            own = set(dir(obj))
            if issubclass(obj, int):
                own -= set(dir(int))
            classes[n] = sorted(m for m in own if not m.startswith("_"))
    return {"names": names, "classes": classes}


# --- the cases -------------------------------------------------------------------------------

_registered = []


def case(*covers):
    """Marks a function of a case file as a differential case naming the members it checks
    ("Lstring.replace", "newmodule")."""

    def mark(f):
        _registered.append((f.__module__ + "." + f.__name__, covers, f))
        return f

    return mark


_defined = []


def defined(*covers, expect, source):
    """Marks a case for members the reference cannot run (it crashes the process on them): only
    Sprout runs it, and its result must be `expect`, read from L-Py's definition (`source`:
    where in L-Py's sources)."""

    def mark(f):
        _defined.append((f.__module__ + "." + f.__name__, covers, f, expect, source))
        return f

    return mark


def lpy():
    """openalea.lpy, whichever this interpreter has (for the case files)."""
    import openalea.lpy as l

    return l


def declared(name, params):
    """A module class of the process with declared parameter names (for the case files). L-Py's
    table forgets a class declared there once Python holds it no more: a case keeps what this
    gives."""
    c = lpy().ModuleClassTable.get().declare(name)
    c.parameterNames = params
    return c


ADDRESS = re.compile(r" at 0x[0-9a-fA-F]+")


def canon(v, depth=0):
    if depth > 20:
        return "..."
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, int):
        return int(v)
    if isinstance(v, float):
        return v if math.isfinite(v) else repr(v)
    if isinstance(v, (list, tuple)):
        return [canon(x, depth + 1) for x in v]
    if isinstance(v, dict):
        return {str(k): canon(x, depth + 1) for k, x in sorted(v.items(), key=lambda kv: str(kv[0]))}
    if isinstance(v, (set, frozenset)):
        return sorted((canon(x, depth + 1) for x in v), key=repr)
    return {"type": type(v).__name__, "str": ADDRESS.sub("", str(v))}


def run_cases(lpy):
    sys.modules["lpy_api"] = sys.modules[__name__]
    out = {}
    for f in sorted(os.listdir(CASES)):
        if not f.endswith(".py"):
            continue
        spec = importlib.util.spec_from_file_location("lpy_api_cases_" + f[:-3], os.path.join(CASES, f))
        mod = importlib.util.module_from_spec(spec)
        try:
            spec.loader.exec_module(mod)
        except Exception as e:  # a case file that cannot load is every one of its cases failing
            out["file:" + f] = {"covers": [], "raises": type(e).__name__, "message": str(e)}
    ui = ui_only()
    for name, covers, f in _registered:
        real_stdout = sys.stdout
        sys.stdout = io.StringIO()
        try:
            out[name] = {"covers": list(covers), "value": canon(f())}
        except Exception as e:
            out[name] = {"covers": list(covers), "raises": type(e).__name__, "message": str(e)[:300]}
        finally:
            sys.stdout = real_stdout
    for name, covers, f, expect, source in (_defined if "sprout" in sys.modules else []):
        real_stdout = sys.stdout
        sys.stdout = io.StringIO()
        try:
            out["defined:" + name] = {"covers": list(covers), "value": canon(f()), "expect": canon(expect), "source": source}
        except Exception as e:
            out["defined:" + name] = {"covers": list(covers), "raises": type(e).__name__, "message": str(e)[:300],
                                      "expect": canon(expect), "source": source}
        finally:
            sys.stdout = real_stdout
    for name in ui:  # each must exist, and raise NotImplementedError where it is Sprout's
        obj, ok = lpy, True
        for part in name.split("."):
            if not hasattr(obj, part):
                ok = False
                break
            obj = getattr(obj, part)
        out["ui:" + name] = {"covers": [name], "exists": ok}
    return out


def ui_only():
    """The UI-only names: each case file's top-level UI_ONLY = {"Name.member": "why"}."""
    import ast

    found = {}
    for f in sorted(os.listdir(CASES)):
        if f.endswith(".py"):
            for node in ast.parse(open(os.path.join(CASES, f)).read()).body:
                if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "UI_ONLY" for t in node.targets):
                    found.update(ast.literal_eval(node.value))
    return found


# --- both sides ------------------------------------------------------------------------------


def run_side(python, mode, build=None):
    cmd = [python, os.path.abspath(__file__), mode] + (["--sprout", build] if build else [])
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", PYTHONDONTWRITEBYTECODE="1")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=1800)
    if p.returncode != 0:
        sys.exit("%s %s failed:\n%s" % (python, mode, p.stderr[-3000:]))
    return json.loads(p.stdout)


def same(a, b, tol=1e-9):
    if isinstance(a, float) or isinstance(b, float):
        if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
            return a == b or abs(a - b) <= tol * max(abs(a), abs(b), 1e-300)
        return False
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y, tol) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k], tol) for k in a)
    return a == b


def case_agrees(ref, mine):
    if "raises" in ref or "raises" in mine:
        r, m = ref.get("raises"), mine.get("raises")
        return r is not None and m is not None and SAME_ERROR.get(r, r) == SAME_ERROR.get(m, m)
    return same(ref.get("value"), mine.get("value"))


def counts(ref_inv, mine_inv):
    mine_names = set(mine_inv["names"])
    names = [n for n in ref_inv["names"]]
    have = [n for n in names if n in mine_names]
    members, have_members = [], []
    for cls, ms in ref_inv["classes"].items():
        mine_ms = set(mine_inv.get("members_of", {}).get(cls, mine_inv["classes"].get(cls, [])))
        for m in ms:
            members.append(cls + "." + m)
            if m in mine_ms:
                have_members.append(cls + "." + m)
    return names, have, members, have_members


def sprout_members_of(python, build, classes):
    """Members of the reference's classes on Sprout's objects of the same names, class or not."""
    code = ("import sys, json; sys.path.insert(0, %r); import sprout; sprout.use_as_openalea();"
            "import openalea.lpy as l; cls = json.loads(sys.stdin.read());"
            "print(json.dumps({c: sorted(m for m in ms if hasattr(getattr(l, c), m)) for c, ms in cls.items() if hasattr(l, c)}))"
            % os.path.join(os.path.abspath(build), "python"))
    p = subprocess.run([python, "-c", code], input=json.dumps(classes), capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        sys.exit(p.stderr[-3000:])
    return json.loads(p.stdout)


def report(ref_inv, mine_inv, at_least, ref_cases=None, mine_cases=None):
    names, have, members, have_members = counts(ref_inv, mine_inv)
    missing = [n for n in names if n not in set(have)]
    missing_m = [m for m in members if m not in set(have_members)]
    print("names:   %d of %d (%.1f%%)" % (len(have), len(names), 100.0 * len(have) / max(1, len(names))))
    print("members: %d of %d (%.1f%%)" % (len(have_members), len(members), 100.0 * len(have_members) / max(1, len(members))))
    if missing:
        print("missing names: " + " ".join(missing))
    if missing_m:
        print("missing members: " + " ".join(missing_m))
    ok = 100.0 * len(have) / max(1, len(names)) >= at_least and 100.0 * len(have_members) / max(1, len(members)) >= at_least
    if ref_cases is not None:
        agree, differ, checked, failed = 0, [], set(), set()
        ui = ui_only()
        for name, ref in ref_cases.items():
            if name.startswith("ui:"):
                continue
            mine = mine_cases.get(name, {"raises": "missing"})
            if case_agrees(ref, mine):
                agree += 1
                checked.update(ref["covers"])
            else:
                differ.append(name)
                failed.update(ref["covers"])
                print("DIFFERS %s\n  L-Py:   %s\n  Sprout: %s" % (name, json.dumps({k: v for k, v in ref.items() if k != "covers"})[:400],
                                                             json.dumps({k: v for k, v in mine.items() if k != "covers"})[:400]))
        # Cases read from L-Py's definition, for what the reference crashes on: Sprout's alone.
        by_definition = {n: c for n, c in mine_cases.items() if n.startswith("defined:")}
        for name, mine in sorted(by_definition.items()):
            if "raises" not in mine and same(mine["value"], mine["expect"]):
                checked.update(mine["covers"])
            else:
                differ.append(name)
                failed.update(mine["covers"])
                print("DIFFERS FROM L-PY'S DEFINITION %s (%s)\n  expected: %s\n  Sprout:   %s"
                      % (name, mine["source"], json.dumps(mine["expect"])[:400],
                         json.dumps({k: v for k, v in mine.items() if k in ("value", "raises", "message")})[:400]))
        for name in ui:
            entry = mine_cases.get("ui:" + name, {})
            if not entry.get("exists"):
                differ.append("ui:" + name)
                print("UI-ONLY NAME MISSING %s" % name)
        checked -= failed
        api = set(names) | set(members)
        unchecked = sorted(api - checked - set(ui))
        if unchecked:
            print("not checked by a case: " + " ".join(unchecked))
        print("differential cases: %d of %d agree" % (agree, len(ref_cases) - sum(1 for n in ref_cases if n.startswith("ui:"))))
        print("cases from L-Py's definition (the reference crashes on them): %d of %d agree"
              % (sum(1 for n in by_definition if n not in differ), len(by_definition)))
        print("names and members checked by a case: %d of %d (%.1f%%); UI-only: %d"
              % (len(checked & api), len(api), 100.0 * len(checked & api) / max(1, len(api)), len(set(ui) & api)))
        ok = ok and not differ
    return ok


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    mode = args[0]

    def opt(flag, default=None):
        return args[args.index(flag) + 1] if flag in args else default

    if mode in ("inventory", "cases"):
        real = sys.stdout
        sys.stdout = sys.stderr  # what importing prints is not the JSON
        lpy = load_lpy(opt("--sprout"))
        result = inventory(lpy) if mode == "inventory" else run_cases(lpy)
        sys.stdout = real
        print(json.dumps(result))
        return 0
    build = opt("--build", "build")
    if mode == "compare":
        ref_python = args[1]
        if not os.path.exists(ref_python):
            print("no reference L-Py (SPROUT_LPY_REFERENCE): skipped")
            return 77
        ref_inv = run_side(ref_python, "inventory")
        mine_inv = run_side(sys.executable, "inventory", build)
        mine_inv["members_of"] = sprout_members_of(sys.executable, build, ref_inv["classes"])
        if opt("--write-reference"):
            with open(opt("--write-reference"), "w") as f:
                json.dump(ref_inv, f, indent=1, sort_keys=True)
                f.write("\n")
        ref_cases = run_side(ref_python, "cases")
        mine_cases = run_side(sys.executable, "cases", build)
        return 0 if report(ref_inv, mine_inv, float(opt("--at-least", "95")), ref_cases, mine_cases) else 1
    if mode == "check":
        with open(opt("--reference")) as f:
            ref_inv = json.load(f)
        mine_inv = run_side(sys.executable, "inventory", build)
        mine_inv["members_of"] = sprout_members_of(sys.executable, build, ref_inv["classes"])
        names, have, members, have_members = counts(ref_inv, mine_inv)
        report(ref_inv, mine_inv, 0)
        need_n, need_m = int(opt("--at-least-names", "0")), int(opt("--at-least-members", "0"))
        return 0 if len(have) >= need_n and len(have_members) >= need_m else 1
    if mode == "docs":
        import lpy_api_docs

        with open(opt("--reference")) as f:
            ref_inv = json.load(f)
        mine_inv = run_side(sys.executable, "inventory", build)
        mine_inv["members_of"] = sprout_members_of(sys.executable, build, ref_inv["classes"])
        page = lpy_api_docs.page(ref_inv, mine_inv, ui_only())
        if opt("--write"):
            with open(opt("--write"), "w") as f:
                f.write(page)
            return 0
        target = opt("--check")
        if target:
            if open(target).read() != page:
                print("%s is not what the two dir()s give: run lpy_api.py docs --build BUILD --reference FILE --write %s" % (target, target))
                return 1
            return 0
        sys.stdout.write(page)
        return 0
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())
