#!/usr/bin/python3
"""The viewer's curve and material editors against the real L-Py (issue 52): every model of L-Py's
share/ (../shared/corpus/lpy) whose INITIALISATION part stores 2D curves, materials, patches
or scalars: each curve's point 1 moved as a drag in the editor moves it (sprout.set_lpy_curve:
the text rewritten in place, as L-Py Studio writes it), each material's ambient colour, diffuse,
specular and transparency set as the material editor sets them (sprout.set_lpy_material), each
NurbsPatch's point (1, 1) moved (sprout.set_lpy_patch), each Float scalar set to its middle and
each Integer written again (sprout.set_lpy_scalar); saved, then read back by Sprout and by the
reference L-Py (Lsystem(file): the curve and patch objects in the model's context have those
control points, to L-Py Studio's six digits; its turtle's materials and its scalar list those
values).

    lpy_curves_roundtrip.py REF_PYTHON --build BUILD

Not part of the README's test command or CI: ctest runs it under the label `reference` when
SPROUT_LPY_REFERENCE names the reference's python (../shared/tools/build-lpy-reference.sh).
"""
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CORPUS = os.path.join(os.path.dirname(ROOT), "shared", "corpus", "lpy")

# Run by the reference: each file's curves as its context holds them.
READ_BACK = r"""
import json, os, sys
real, sys.stdout = sys.stdout, sys.stderr  # what the models print is not the answer
from openalea.lpy import Lsystem
out = {}
for path, asked in json.loads(sys.stdin.read()).items():
    names, materials = asked['curves'], asked['materials']
    os.chdir(os.path.dirname(path))
    try:
        ctx = Lsystem(path).context()
        # The curve objects as the panel keeps them (a model may bind the name to something
        # made of the curve, a QuantisedFunction), else the name's value.
        kept = {}
        for key in ('__curves__', '__functions__'):
            for n, obj in (ctx[key] if key in ctx else []):
                kept[n] = obj
        out[path] = {n: [list(p) for p in (kept[n] if n in kept else ctx[n]).ctrlPointList] for n in names}
        for n in asked.get('patches', []):
            m = ctx[n].ctrlPointMatrix
            out[path]['patch ' + n] = [[list(m[i, j]) for j in range(m.getColumnNb())] for i in range(m.getRowNb())]
        for n in asked.get('scalars', []):  # as the model's scalar list has it (its code may assign the name again)
            for sc in ctx['__scalars__']:
                if sc[0] == n:
                    out[path]['scalar ' + n] = sc[2] if isinstance(sc[1], str) else sc[1]
        for i in materials:
            m = ctx.turtle.getMaterial(int(i))
            out[path]['material %s' % i] = dict(ambient=[m.ambient.red, m.ambient.green, m.ambient.blue], diffuse=m.diffuse,
                                                 specular=[m.specular.red, m.specular.green, m.specular.blue],
                                                 transparency=m.transparency)
    except Exception as e:
        out[path] = {'error': '%s: %s' % (type(e).__name__, e)}
real.write(json.dumps(out))
real.flush()
os._exit(0)
"""


def main():
    args = sys.argv[1:]
    if not args or not os.path.exists(args[0]):
        print("no reference L-Py (SPROUT_LPY_REFERENCE): skipped")
        return 77
    ref = args[0]
    build = args[args.index("--build") + 1] if "--build" in args else os.path.join(ROOT, "build")
    sys.path.insert(0, os.path.join(os.path.abspath(build), "python"))
    import sprout

    failures, expected, originals, checked = [], {}, {}, 0
    with tempfile.TemporaryDirectory() as tmp:
        for folder, _, files in sorted(os.walk(CORPUS)):
            for f in sorted(files):
                if not f.endswith(".lpy"):
                    continue
                with open(os.path.join(folder, f), encoding="utf-8", errors="surrogateescape") as fh:
                    text = fh.read()
                curves = sprout.lpy_curves(text)
                materials = [m for m in sprout.lpy_materials(text) if "texture" not in m]
                patches = sprout.lpy_patches(text)
                scalars = [x for x in sprout.lpy_scalars(text) if x["kind"] != "Bool"]
                if not curves and not materials and not patches and not scalars:
                    continue
                moved = text
                want = {}
                last = {c["name"]: c for c in curves}  # a name several panels set: the last, which the model uses
                for c in last.values():
                    pts = [list(p) for p in c["points"]]
                    pts[1][0] += 0.05
                    pts[1][1] -= 0.03
                    moved = sprout.set_lpy_curve(moved, c["name"], pts)
                    want[c["name"]] = pts
                # Sprout reads back the change, and the rest of the file is as it was outside the lists.
                again = {c["name"]: c["points"] for c in sprout.lpy_curves(moved)}
                for name, pts in want.items():
                    if any(abs(a - b) > 1e-6 * max(1.0, abs(b)) for p, q in zip(again.get(name, []), pts) for a, b in zip(p, q)):
                        failures.append("%s: Sprout reads %s back as %s" % (f, name, again.get(name)))
                last_material = {m["index"]: m for m in materials}  # set twice: the last, which the turtle keeps
                for m in last_material.values():
                    ambient = [(c + 37) % 256 for c in m["ambient"]]
                    most = 255.0 / max(ambient) if max(ambient) > 0 else 10.0  # PlantGL keeps ambient x diffuse in 255
                    d = min(m["diffuse"] + 0.5, most)
                    d = math.floor(d * 10 ** (5 - math.floor(math.log10(d)))) / 10 ** (5 - math.floor(math.log10(d)))  # %g's six digits, down
                    want_m = dict(ambient=ambient, diffuse=float("%g" % d),
                                  specular=[(c + 11) % 256 for c in m["specular"]], transparency=0.25)
                    for field, value in want_m.items():
                        moved = sprout.set_lpy_material(moved, m["index"], field, value)
                    want["material %d" % m["index"]] = want_m
                    read = [x for x in sprout.lpy_materials(moved) if x["index"] == m["index"]][-1]
                    if any(read[k] != v for k, v in want_m.items()):
                        failures.append("%s: Sprout reads material %d back as %s" % (f, m["index"], read))
                for pa in {q["name"]: q for q in patches}.values():  # a patch's point (1, 1) moved, as the surface editor moves it
                    rows = [[list(q) for q in row] for row in pa["points"]]
                    rows[1][1][0] += 0.05
                    rows[1][1][1] -= 0.03
                    rows[1][1][2] += 0.02
                    moved = sprout.set_lpy_patch(moved, pa["name"], rows)
                    want["patch " + pa["name"]] = rows
                for sc in scalars:  # a Float's slider moved to its middle; an Integer written again as it is
                    # (another whole number may take the model where L-Py itself fails: lsystem10's METHOD)
                    v = sc["value"] if sc["kind"] == "Integer" else float("%g" % round((sc["min"] + sc["max"]) / 2, 3))
                    moved = sprout.set_lpy_scalar(moved, sc["name"], v)
                    want["scalar " + sc["name"]] = v
                # Saved beside the model (its imports and files are its folder's).
                path = os.path.join(folder, ".sprout-roundtrip-" + f)
                with open(path, "w", encoding="utf-8", errors="surrogateescape") as fh:
                    fh.write(moved)
                expected[path] = want
                originals[path] = os.path.join(folder, f)
        try:
            def asked(want):
                return dict(curves=[n for n in want if not n.startswith(("material ", "patch ", "scalar "))],
                            materials=[int(n[9:]) for n in want if n.startswith("material ")],
                            patches=[n[6:] for n in want if n.startswith("patch ")],
                            scalars=[n[7:] for n in want if n.startswith("scalar ")])
            p = subprocess.run([ref, "-c", READ_BACK], input=json.dumps({k: asked(v) for k, v in expected.items()}),
                               capture_output=True, text=True, timeout=1800, env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
            got = json.loads(p.stdout or "{}")
            broken = [path for path, read in got.items() if "error" in read]
            # A model the reference cannot read as it is (Python 2's print...) is none of this test's.
            p = subprocess.run([ref, "-c", READ_BACK], input=json.dumps({originals[k]: asked(expected[k]) for k in broken}),
                               capture_output=True, text=True, timeout=1800, env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
            unreadable = {path for path in broken if "error" in json.loads(p.stdout or "{}").get(originals[path], {"error": 1})}
        finally:
            for path in expected:
                os.remove(path)
    for path, want in sorted(expected.items()):
        name = os.path.relpath(path, CORPUS).replace(".sprout-roundtrip-", "")
        read = got.get(path, {"error": "the reference gave nothing"})
        if path in unreadable:
            print("skipped %s: the reference L-Py cannot read the model as it is either" % name)
            continue
        if "error" in read:
            failures.append("%s: the reference L-Py could not read it: %s" % (name, read["error"]))
            continue
        for curve, pts in want.items():
            checked += 1
            if curve.startswith("patch "):
                got_p = read.get(curve, [])
                flat_got = [a for row in got_p for q in row for a in q]
                flat_want = [a for row in pts for q in row for a in q]
                if len(flat_got) != len(flat_want) or any(abs(a - b) > 1e-6 * max(1.0, abs(b)) for a, b in zip(flat_got, flat_want)):
                    failures.append("%s: %s is %s in L-Py, %s wanted" % (name, curve, got_p, pts))
                continue
            if curve.startswith("scalar "):
                if abs(read.get(curve, float("nan")) - pts) > 1e-9:
                    failures.append("%s: %s is %s in L-Py, %s wanted" % (name, curve, read.get(curve), pts))
                continue
            if curve.startswith("material "):
                got_m = read.get(curve, {})
                if any(abs(a - b) > 1e-6 for k, v in pts.items() for a, b in zip(got_m.get(k, []) if isinstance(v, list) else [got_m.get(k, -1)],
                                                                          v if isinstance(v, list) else [v])):
                    failures.append("%s: %s is %s in L-Py, %s wanted" % (name, curve, got_m, pts))
                continue
            ref_pts = read.get(curve, [])
            # A Polyline2D's points are pairs; a NURBS's (x, y, w).
            if len(ref_pts) != len(pts) or any(abs(a - b) > 1e-6 * max(1.0, abs(b))
                                               for p, q in zip(ref_pts, pts) for a, b in zip(p, q[:len(p)])):
                failures.append("%s: %s is %s in L-Py, %s wanted" % (name, curve, ref_pts, pts))
    for line in failures:
        print("FAIL " + line)
    def count(prefix):
        return sum(1 for path, want in expected.items() if path not in unreadable for n in want if n.startswith(prefix))
    materials, patches, scalars = count("material "), count("patch "), count("scalar ")
    print("%d curves, %d materials, %d patches and %d scalars of %d models changed, saved and read back by L-Py with the same "
          "numbers; %d failures" % (checked - materials - patches - scalars, materials, patches, scalars, len(expected), len(failures)))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
