#!/usr/bin/python3
"""The PlantGL names L-Py models use, and whether Sprout's openalea.plantgl has each (issue 51).

    tests/reference/plantgl_names.py --build build [--corpus ../shared/corpus] [--doc DIR]
    tests/reference/plantgl_names.py --write REF_PYTHON [--corpus ...] [--doc DIR]

The models are the .lpy and .py files of ../shared/corpus/lpy (L-Py's share/) and lpy-tests (its
pytest suite), and the Python of L-Py's documentation (--doc: its doc/ folder, whose names are
kept in the data file, so a check without it still checks them). A name is used where a file
names it as a word outside comments and strings: a module of openalea.plantgl it imports, a
name it imports from one, a public name of openalea.plantgl.all (models have them all), and a
member `.m` of one of PlantGL's classes that the same file names.

PlantGL's names and its classes' members are those of the reference PlantGL (3.22.3), kept in
tests/reference/data/plantgl_reference_names.txt: `--write REF_PYTHON` makes that file with the
reference's python (built by ../shared/tools/build-lpy-reference.sh), from its dir()s, and adds
the names the documentation uses. Without --write, the names the corpora use now are found, and
each is looked up in Sprout's openalea.plantgl (sprout.use_as_openalea()); every one missing is
printed, and the exit status is 1 when any is. The ctest PlantGL.NamesModelsUseExist runs it.
"""
import argparse
import glob
import io
import json
import os
import re
import subprocess
import sys
import tokenize

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(HERE, "data", "plantgl_reference_names.txt")
DEFAULT_CORPUS = os.path.join(os.path.dirname(ROOT), "shared", "corpus")

# Words that are PlantGL names but, where the corpora use them, are something else: L-Py's own
# names that the model's namespace takes from openalea.lpy (imported before PlantGL's, and
# PlantGL's all has names of the same spelling that models never mean), and Python's.
NOT_PLANTGL = {
    'Debug', 'Viewer',  # Viewer: a GUI (a model's calls do nothing in Sprout, a NotImplemented-free stub)
}
# PlantGL names models use that Sprout leaves out, and why (printed, not counted as missing).
LEFT_OUT = {
    'qt': "PlantGL's Qt GUI (test_ui.py), not what an L-system derives or draws",
    'ProfileInterpolation': "PlantGL's fitting of sections (profile.cpp); lsystem10.lpy names it on a path its "
                            "METHOD parameter (2) never takes",
}
# Instances of PlantGL's classes that need arguments, for the members an instance has.
SAMPLES = {
    'NurbsCurve2D': "NurbsCurve2D([(0,0,1),(1,0,1),(1,1,1),(0,1,1)])", 'NurbsCurve': "NurbsCurve([(0,0,0,1),(1,0,0,1),(1,1,0,1)])",
    'BezierCurve2D': "BezierCurve2D([(0,0,1),(1,0,1),(1,1,1)])", 'BezierCurve': "BezierCurve([(0,0,0,1),(1,0,0,1)])",
    'Polyline2D': "Polyline2D([(0,0),(1,0)])", 'Polyline': "Polyline([(0,0,0),(1,0,0)])",
    'NurbsPatch': "NurbsPatch([[(0,0,0,1),(1,0,0,1)],[(0,1,0,1),(1,1,0,1)]], udegree=1, vdegree=1)",
    'BezierPatch': "BezierPatch([[(0,0,0,1),(1,0,0,1)],[(0,1,0,1),(1,1,0,1)]])",
    'Translated': "Translated((0,0,1), Sphere())", 'Scaled': "Scaled((1,1,2), Sphere())",
    'AxisRotated': "AxisRotated((0,0,1), 1, Sphere())", 'Oriented': "Oriented((1,0,0),(0,1,0), Sphere())",
    'EulerRotated': "EulerRotated(0, 0, 0, Sphere())", 'Shape': "Shape(Sphere())", 'Group': "Group([Sphere()])",
    'PointSet': "PointSet([(0,0,0)])", 'TriangleSet': "TriangleSet([(0,0,0),(1,0,0),(0,1,0)], [(0,1,2)])",
    'QuadSet': "QuadSet([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2,3)])",
    'Point3Grid': "Point3Grid((1,1,1), [(0,0,0),(1,1,1)])", 'ImageTexture': "ImageTexture('t.png')",
    'QuantisedFunction': "QuantisedFunction(NurbsCurve2D([(0,0,1),(0.5,1,1),(1,0,1)]))",
}
# Modules of openalea.plantgl that L-Py models import.
MODULE_RE = re.compile(r"\bopenalea\.plantgl((?:\.\w+)*)")
FROM_RE = re.compile(r"^\s*from\s+openalea\.plantgl((?:\.\w+)*)\s+import\s+(\(?[\w\s,]+\)?|\*)", re.M)


def words_of(text):
    """The names and the attributes (`.name`) a file writes outside comments and strings."""
    names, attrs = set(), set()
    previous = None
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        tokens = None
    if tokens is None:  # L-Py's text that Python's tokenizer refuses: words, comments cut
        text = re.sub(r"#[^\n]*", "", text)
        for m in re.finditer(r"(\.?)\b([A-Za-z_]\w*)", text):
            (attrs if m.group(1) else names).add(m.group(2))
        return names, attrs
    for tok in tokens:
        if tok.type == tokenize.NAME:
            (attrs if previous == '.' else names).add(tok.string)
        if tok.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT, tokenize.COMMENT):
            previous = tok.string
    return names, attrs


DEFINES = [re.compile(r"^\s*(?:def|class)\s+(\w+)", re.M),                       # def f, class C
           re.compile(r"^\s*([\w\s,]+?)\s*=(?!=)", re.M),                       # x = ..., a, b = ...
           re.compile(r"\bfor\s+\(?([\w\s,]+?)\)?\s+in\b"),                     # for a, b in
           re.compile(r"\bimport\s+[\w.]+\s+as\s+(\w+)"),                         # import m as x
           re.compile(r"^\s*(?:import|from\s+[\w.]+\s+import)\s+([\w\s,]+)$", re.M),  # import x / from m import x
           re.compile(r"^\s*module\s+(.*)$", re.M),                                # L-Py's module declarations
           re.compile(r"\bdef\s+\w+\s*\(([^)]*)\)"),                              # a function's parameters
           re.compile(r"^[^#'\"=]*?\w\(([^)]*)\)\s*(?:<|>|:|-->)", re.M)]          # a rule header's parameters


def defined_in(text):
    """The names a file defines itself (which then are not PlantGL's where it uses them)."""
    out = set()
    for rx in DEFINES:
        for m in rx.finditer(text):
            out.update(w for w in re.findall(r"[A-Za-z_]\w*", re.sub(r"=[^,]*", "", m.group(1))))
    return out


def files(corpus, doc):
    out = []
    for sub in ("lpy", "lpy-tests"):
        for ext in ("lpy", "py"):
            out += sorted(glob.glob(os.path.join(corpus, sub, "**", "*." + ext), recursive=True))
    if doc:
        out += sorted(glob.glob(os.path.join(doc, "**", "*.rst"), recursive=True))
        out += sorted(glob.glob(os.path.join(doc, "**", "*.py"), recursive=True))
        out += sorted(glob.glob(os.path.join(doc, "**", "*.lpy"), recursive=True))
    return out


def doc_python(text):
    """The code of an .rst page: its literal blocks and `code::` blocks."""
    out, block, indent = [], False, None
    for line in text.splitlines():
        if block:
            if line.strip() == "":
                out.append("")
                continue
            lead = len(line) - len(line.lstrip())
            if indent is None:
                indent = lead
            if lead >= indent and lead > 0:
                out.append(line[indent:])
                continue
            block, indent = False, None
        if line.rstrip().endswith("::"):
            block = True
    return "\n".join(out)


def read(path):
    with open(path, "rb") as f:
        raw = f.read()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        text = raw.decode("latin-1")
    text = text.replace("\r", "")
    return doc_python(text) if path.endswith(".rst") else text


def load_reference():
    """{'all': set, 'modules': {module: set}, 'classes': {class: set}, 'doc': [used lines]}."""
    ref = {'all': set(), 'modules': {}, 'classes': {}, 'doc': []}
    with open(DATA, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            kind, _, rest = line.partition(" ")
            if kind == "all":
                ref['all'].update(rest.split())
            elif kind == "module":
                name, _, members = rest.partition(" ")
                ref['modules'][name] = set(members.split())
            elif kind == "class":
                name, _, members = rest.partition(" ")
                ref['classes'][name] = set(members.split())
            elif kind == "doc":
                ref['doc'].append(rest)
    return ref


def used(ref, paths):
    """The uses found: {("module", m), ("from", m, name), ("name", n), ("member", cls, m)}:
    each with the files that make it."""
    found = {}

    def add(key, path):
        found.setdefault(key, set()).add(os.path.basename(path))

    for path in paths:
        text = read(path)
        names, attrs = words_of(text)
        if "plantgl" not in text and not path.endswith(".lpy"):
            continue  # a .py that does not use PlantGL: a model's helper without it
        for m in MODULE_RE.finditer(text):
            module = "openalea.plantgl" + m.group(1)
            if module in ref['modules']:
                add(("module", module), path)
        for m in FROM_RE.finditer(text):
            module = "openalea.plantgl" + m.group(1)
            if m.group(2).strip() == "*" or module not in ref['modules']:
                continue
            for name in re.split(r"[\s,()]+", m.group(2)):
                if name and name in ref['modules'][module]:
                    add(("from", module, name), path)
        classes = set()
        imported = set()
        for m in FROM_RE.finditer(text):
            imported.update(re.split(r"[\s,()]+", m.group(2)))
        for name in (names & ref['all']) - (defined_in(text) - imported):
            if name in NOT_PLANTGL or name.startswith("_"):
                continue
            add(("name", name), path)
            if name in ref['classes']:
                classes.add(name)
        for cls in classes:
            for member in attrs & ref['classes'][cls]:
                if not member.startswith("_"):
                    add(("member", cls, member), path)
    return found


def sprout_has(build, keys):
    """Which of `keys` Sprout's openalea.plantgl lacks (run in a python of its own)."""
    probe = r'''
import json, sys, importlib
import sprout
sprout.use_as_openalea()
import openalea.plantgl.all as pgl
missing = []
for key in json.load(sys.stdin):
    try:
        if key[0] == "module":
            importlib.import_module(key[1])
        elif key[0] == "from":
            if not hasattr(importlib.import_module(key[1]), key[2]): missing.append(key)
        elif key[0] == "name":
            if not hasattr(pgl, key[1]): missing.append(key)
        elif key[0] == "member":
            cls = getattr(pgl, key[1])
            if not hasattr(cls, key[2]):
                try:  # an instance's own field: a sample made as models make one
                    sample = eval(SAMPLES.get(key[1], key[1] + "()"), vars(pgl))
                except Exception:
                    sample = None
                if not hasattr(sample, key[2]): missing.append(key)
    except Exception as e:
        missing.append(key)
        print("%s: %s: %s" % (".".join(key[1:]), type(e).__name__, e), file=sys.stderr)
print(json.dumps(missing))
'''
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    probe = "SAMPLES = %r\n" % SAMPLES + probe
    out = subprocess.run([sys.executable, "-c", probe], input=json.dumps([list(k) for k in keys]), env=env,
                         capture_output=True, text=True, timeout=600)
    if out.returncode != 0:
        sys.exit("Sprout's openalea.plantgl did not load:\n" + out.stderr[-3000:])
    sys.stdout.write(out.stderr)
    return [tuple(k) for k in json.loads(out.stdout.strip().splitlines()[-1])]


def sprout_members(build, classes):
    """{class: the members Sprout's class and an instance of it have} (None: no such class)."""
    probe = "SAMPLES = %r\n" % SAMPLES + r'''
import json, sys
import sprout
sprout.use_as_openalea()
import openalea.plantgl.all as pgl
out = {}
for name in json.load(sys.stdin):
    cls = getattr(pgl, name, None)
    if cls is None:
        out[name] = None
        continue
    members = set(dir(cls))
    try:
        members |= set(dir(eval(SAMPLES.get(name, name + "()"), vars(pgl))))
    except Exception:
        pass
    out[name] = sorted(m for m in members if not m.startswith("_"))
print(json.dumps(out))
'''
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    out = subprocess.run([sys.executable, "-c", probe], input=json.dumps(sorted(classes)), env=env, capture_output=True,
                         text=True, timeout=600)
    if out.returncode != 0:
        sys.exit("Sprout's openalea.plantgl did not load:\n" + out.stderr[-3000:])
    return json.loads(out.stdout.strip().splitlines()[-1])


def write(ref_python, corpus, doc):
    dump = r'''
import json, inspect, importlib
import openalea.plantgl.all as pgl
out = {'all': sorted(n for n in dir(pgl) if not n.startswith('_')), 'modules': {}, 'classes': {}}
for name in ['openalea.plantgl', 'openalea.plantgl.all', 'openalea.plantgl.math', 'openalea.plantgl.scenegraph',
             'openalea.plantgl.algo', 'openalea.plantgl.light', 'openalea.plantgl.light.light',
             'openalea.plantgl.scenegraph.cspline', 'openalea.plantgl.scenegraph.interpolated_profile',
             'openalea.plantgl.scenegraph.nurbspatch_nd', 'openalea.plantgl.codec']:
    try:
        out['modules'][name] = sorted(n for n in dir(importlib.import_module(name)) if not n.startswith('_'))
    except Exception:
        pass
for n in out['all']:
    v = getattr(pgl, n)
    if inspect.isclass(v):
        out['classes'][n] = sorted(m for m in dir(v) if not m.startswith('_'))
print(json.dumps(out))
'''
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    out = subprocess.run([ref_python, "-c", dump], capture_output=True, text=True, env=env, timeout=600)
    if out.returncode != 0:
        sys.exit("the reference PlantGL did not load:\n" + out.stderr[-3000:])
    data = json.loads(out.stdout.strip().splitlines()[-1])
    ref = {'all': set(data['all']), 'modules': {k: set(v) for k, v in data['modules'].items()},
           'classes': {k: set(v) for k, v in data['classes'].items()}, 'doc': []}
    doc_uses = sorted(used(ref, files(corpus, doc)[len(files(corpus, None)):]).keys()) if doc else []
    os.makedirs(os.path.dirname(DATA), exist_ok=True)
    with open(DATA, "w", encoding="utf-8") as f:
        f.write("# PlantGL's public names, from the reference PlantGL 3.22.3 (plantgl 6e01c6d), written by\n"
                "# tests/reference/plantgl_names.py --write: `all` its openalea.plantgl.all, `module` a module's\n"
                "# names, `class` a class's members; `doc` a use found in L-Py's doc/ (lpy 4a365a3).\n")
        for i in range(0, len(data['all']), 12):
            f.write("all " + " ".join(data['all'][i:i + 12]) + "\n")
        for name, members in sorted(data['modules'].items()):
            if name not in ('openalea.plantgl.all',):
                f.write("module %s %s\n" % (name, " ".join(members)))
        for name, members in sorted(data['classes'].items()):
            f.write("class %s %s\n" % (name, " ".join(members)))
        for key in doc_uses:
            f.write("doc " + " ".join(key) + "\n")
    print("wrote %s: %d names, %d classes, %d uses in the documentation" % (DATA, len(ref['all']), len(ref['classes']),
                                                                          len(doc_uses)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--corpus", default=DEFAULT_CORPUS)
    ap.add_argument("--doc", default=None, help="L-Py's doc/ folder")
    ap.add_argument("--write", metavar="REF_PYTHON")
    ap.add_argument("--list", action="store_true", help="print every use with the files that make it")
    args = ap.parse_args()
    if not os.path.isdir(os.path.join(args.corpus, "lpy")):
        print("no corpus at %s: skipped" % args.corpus)
        return 77
    if args.write:
        write(args.write, args.corpus, args.doc)
        return 0
    ref = load_reference()
    found = used(ref, files(args.corpus, args.doc))
    for line in ref['doc']:
        found.setdefault(tuple(line.split()), set()).add("(L-Py's doc)")
    keys = sorted(found)
    missing = set(sprout_has(args.build, keys))
    kinds = {}
    for key in [k for k in keys if k[1] in LEFT_OUT]:
        print("%-8s %-50s left out: %s" % (key[0], ".".join(key[1:]), LEFT_OUT[key[1]]))
    keys = [k for k in keys if k[1] not in LEFT_OUT]
    missing = {k for k in missing if k[1] not in LEFT_OUT}
    for key in keys:
        total, have = kinds.get(key[0], (0, 0))
        kinds[key[0]] = (total + 1, have + (key not in missing))
        if args.list or key in missing:
            print("%-8s %-50s %s%s" % (key[0], ".".join(key[1:]), "MISSING " if key in missing else "",
                                       ", ".join(sorted(found[key])[:4])))
    for kind, (total, have) in sorted(kinds.items()):
        print("%s: %d of %d in Sprout's openalea.plantgl" % (kind, have, total))
    # Every member of the classes the models use, whether or not they call it (a measure, not
    # a check: PlantGL's members of its GUI, its actions and its C++ plumbing are among them).
    used_classes = {k[1] for k in keys if k[0] == "name" and k[1] in ref['classes']}
    own = sprout_members(args.build, used_classes)
    total = have = 0
    for cls in sorted(used_classes):
        theirs = ref['classes'][cls]
        ours = set(own.get(cls) or ())
        total, have = total + len(theirs), have + len(theirs & ours)
        if args.list:
            print("class %-20s %3d of %3d  lacks: %s" % (cls, len(theirs & ours), len(theirs), " ".join(sorted(theirs - ours))))
    print("all members of the %d classes models use: %d of %d in Sprout's (a measure)" % (len(used_classes), have, total))
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
