#!/usr/bin/env python3
"""Sprout's openalea.mtg (lpy/mtg/) against the real openalea.mtg, a checkout of its repository
(pure Python: its src/ is put on the path, where `import openalea.mtg` finds it before
Sprout's own). Both read every MTG file of the checkout's test/data and src/openalea/mtg/data,
and each file's MTG is compared: its vertices, scales, complexes, properties (their Python
values), traversals, AML's walks, the text write_mtg makes of it and the MTG read back from
that text; and an lstring made into an MTG and back. Prints each difference.

Usage: mtg_compare.py OPENALEA_MTG_CHECKOUT --build BUILD_DIR
(exits 77, skipped, when the checkout is not there)"""
import json
import os
import subprocess
import sys
from pathlib import Path

PROBE = r'''
import json, sys
import sprout; sprout.use_as_openalea()
import openalea.mtg as M
from openalea.mtg import algo, traversal
from openalea.mtg.io import read_mtg, read_mtg_file, write_mtg, axialtree2mtg, mtg2axialtree
from openalea.lpy import Lstring

def summary(g):
    r = {'n': len(g), 'scale': sorted(g._scale.items()), 'parent': sorted(g._parent.items()),
         'children': sorted(g._children.items()), 'complex': sorted(g._complex.items()),
         'props': {p: sorted((k, repr(v)) for k, v in g.property(p).items()) for p in sorted(g.property_names())},
         'iter_mtg': list(traversal.iter_mtg(g, g.root)), 'iter_mtg2': list(traversal.iter_mtg2(g, g.root)),
         'orders': sorted(algo.orders(g).items()), 'heights': sorted(algo.heights(g).items())}
    v = max(g.vertices())
    r['walks'] = [g.Ancestors(v), g.Axis(v), g.Trunk(v), g.Path(g.Root(v), v)]
    first = g.roots(scale=g.max_scale())[0]
    r['below'] = [sorted(g.Descendants(first)), sorted(g.Extremities(first))]
    r['components'] = [g.components(x) for x in g.vertices(scale=1)]
    return r

out = {'file': M.__file__}
for fn in sys.argv[1:]:
    try:
        g = read_mtg_file(fn, verbose=False)
        r = summary(g)
        reals = [p for p in sorted(g.property_names()) if p not in ('edge_type', 'label', 'index', '_line')
                 and g.property(p) and all(isinstance(x, float) for x in g.property(p).values())]
        r['write'] = write_mtg(g, properties=[(p, 'REAL') for p in reals], nb_tab=20)
        r['read_back'] = summary(read_mtg(r['write'], verbose=False))
    except Exception as e:
        r = 'error %s: %s' % (type(e).__name__, e)
    out[fn] = r
for text, scales in [('P U(1) I I [ + I I ] I U(2) I [ - I ] I', {'P': 1, 'U': 2, 'I': 3}),
                     ('A B [ B B [ B ] B ] B A B B', {'A': 1, 'B': 2}), ('I I [ I [ I ] I ] I', {'I': 1})]:
    g = axialtree2mtg(Lstring(text), scales, None, {k: [] for k in scales})
    out[text] = {'mtg': summary(g), 'back': str(mtg2axialtree(g, {k: [] for k in scales}))}
json.dump(out, sys.stdout, default=str)
'''


def run(build, extra_path, files):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(build / 'python')] + extra_path))
    r = subprocess.run([sys.executable, '-c', PROBE] + files, capture_output=True, text=True, env=env, timeout=1800)
    if r.returncode != 0:
        sys.exit('the probe failed:\n' + r.stderr[-3000:])
    return json.loads(r.stdout)


def main():
    if len(sys.argv) < 4 or sys.argv[2] != '--build':
        sys.exit(__doc__)
    checkout, build = Path(sys.argv[1]), Path(sys.argv[3])
    if not (checkout / 'src' / 'openalea' / 'mtg' / 'mtg.py').exists():
        print('no openalea.mtg checkout at %s: skipped' % checkout)
        return 77
    files = sorted(str(p) for d in ['test/data', 'src/openalea/mtg/data'] for p in (checkout / d).glob('*.mtg'))
    ours, real = run(build, [], files), run(build, [str(checkout / 'src')], files)
    if not ours.pop('file').startswith('<sprout>') or real.pop('file').startswith('<sprout>'):
        sys.exit('the probes did not import the two openalea.mtg (Sprout\'s, then the checkout\'s)')
    differences = 0
    for key in real:
        a, b = ours[key], real[key]
        if isinstance(a, dict) and isinstance(b, dict):
            bad = [part for part in b if a.get(part) != b[part]]
        else:
            bad = [] if a == b else ['outcome: Sprout %s, openalea.mtg %s' % (str(a)[:200], str(b)[:200])]
        if bad:
            differences += 1
            print('%s: differs in %s' % (Path(key).name if os.sep in key else repr(key), ', '.join(bad)))
    print('openalea.mtg: %d of %d cases the same in Sprout' % (len(real) - differences, len(real)))
    return 1 if differences else 0


if __name__ == '__main__':
    sys.exit(main())
