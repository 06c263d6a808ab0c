"""A model's namespace as L-Py gives it, and model files in any encoding L-Py reads (issue 51).
L-Py runs `from openalea.lpy import *` and `from openalea.plantgl.all import *` in a model's
namespace (lsyscontext.cpp, namespaceInitialisation), so a model uses sqrt and pi without
importing them: PlantGL's scenegraph exports them. The strings expected were given by the
reference L-Py 3.15.4 on the same files."""
import math
import subprocess
from pathlib import Path

import sprout

sprout.use_as_openalea()
from openalea.lpy import Lsystem  # noqa: E402

SPROUT = Path(sprout.__file__).resolve().parents[2] / 'sprout'  # build/sprout beside build/python

NAMES = b"""Axiom: A(2)
derivation length: 2
production:
A(x) --> F(sqrt(x)) A(x * pi)
endlsystem
"""
# Written in Latin-1: accents in comments, one in a rule's line.
LATIN1 = (b"# Mod\xe8le \xe9crit en Latin-1 : une tige qui pousse\nfrom math import sqrt\n\nAxiom: A(1)\n\n"
          b"derivation length: 3\nproduction:\n\n# r\xe8gle de croissance\nA(x) --> F(x) A(x*2) # double\n\nendlsystem\n")
# A Latin-1 string literal, read by the file's coding cookie.
COOKIE = (b"# -*- coding: latin-1 -*-\n# Mod\xe8le\nname = \"caf\xe9\"\nAxiom: A(len(name))\nderivation length: 1\n"
          b"production:\nA(x) --> B(x, name == 'caf\\u00e9')\nendlsystem\n")
# UTF-8 with one Latin-1 byte in a comment: the UTF-8 literal stays UTF-8.
MIXED = (b"# commentaire \xe9crit en Latin-1\nname = \"caf\xc3\xa9\"\nAxiom: A(len(name))\nderivation length: 1\n"
         b"production:\nA(x) --> B(x, name == 'caf\\u00e9')\nendlsystem\n")
EXPECTED = {'names': 'F(1.4142135623730951)F(2.5066282746310002)A(19.739208802178716)',
            'latin1': 'F(1)F(2)F(4)A(8)', 'cookie': 'B(4,True)', 'mixed': 'B(4,True)'}


def files(tmp_path):
    out = {}
    for name, data in [('names', NAMES), ('latin1', LATIN1), ('cookie', COOKIE), ('mixed', MIXED)]:
        out[name] = tmp_path / (name + '.lpy')
        out[name].write_bytes(data)
    return out


def test_the_namespace_holds_what_lpy_and_plantgl_export():
    ns = {}
    exec('from openalea.lpy import *\nfrom openalea.plantgl.all import *', ns)
    assert ns['sqrt'] is math.sqrt and ns['pi'] == math.pi
    assert ns['deepcopy']([1, [2]]) == [1, [2]] and ns['pj']('a', 'b') == 'a/b'
    assert ns['pgl'].__name__ == 'openalea.plantgl.all' and ns['ModuleType'] is type(math)
    assert ns['warnings'].__name__ == 'warnings' and ns['importlib'].__name__ == 'importlib'


def test_models_derive_as_lpy_derives_them_from_a_script(tmp_path):
    for name, path in files(tmp_path).items():
        assert str(Lsystem(str(path)).derive()) == EXPECTED[name], name


def test_models_derive_as_lpy_derives_them_in_the_program(tmp_path):
    if not SPROUT.exists():
        return
    for name, path in files(tmp_path).items():
        r = subprocess.run([str(SPROUT), 'expand', str(path)], capture_output=True, text=True, timeout=60)
        assert r.returncode == 0, r.stderr
        assert r.stdout.strip() == EXPECTED[name], name
