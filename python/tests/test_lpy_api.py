"""L-Py's Python API on Sprout's engine (issue 37): `sprout.use_as_openalea()`, then
openalea.lpy's Lsystem, Lstring and their kin as L-Py's documentation teaches them. The models
here are written for these tests; the expected strings are worked out by hand from L-Py's
rules (derive(lstring, start, nb) calls Start at iteration 0 and End at the last)."""
import os
import pickle

import numpy as np
import pytest

import sprout

sprout.use_as_openalea()
from openalea.lpy import AxialTree, Lstring, Lsystem, LsysRule  # noqa: E402

GROWTH = """
extern(ANGLE=30)
log = []
def Start():
    log.append('Start')
def End():
    log.append('End')
Axiom: A(1)
derivation length: 4
production:
A(x) --> I(x) [+(ANGLE) B] A(x + 1)
B --> L
endlsystem
"""


def model(tmp_path, text, name="model.lpy"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_a_file_derives_with_parameters_that_override_the_model(tmp_path):
    lsys = Lsystem(model(tmp_path, GROWTH), {"ANGLE": 45})
    assert lsys.derivationLength == 4
    s = lsys.derive()
    assert str(s) == "I(1)[+(45)L]I(2)[+(45)L]I(3)[+(45)L]I(4)[+(45)B]A(5)"
    assert len(s) == 21 and s[0].name == "I" and s.count("L") == 3
    assert lsys.log == ["Start", "End"]
    assert lsys.getLastIterationNb() == 3


def test_derive_in_pieces_calls_start_and_end_once(tmp_path):
    lsys = Lsystem(model(tmp_path, GROWTH))
    s = lsys.derive(lsys.axiom, 0, 2)
    assert lsys.log == ["Start"]
    s = lsys.derive(s, 2, 2)
    assert lsys.log == ["Start", "End"]
    assert s == lsys.derive()
    assert s[-1].args == [5]


def test_lstrings_as_lpy_reads_them():
    a = AxialTree("F[F[F][G]][F]B[[[G]G]FF]")
    assert a.wellBracketed() and a.sons(0) == [2, 11, 13] and a.directSon(0) == 13
    assert a.parent(21) == 13 and a.sons(4) is None
    assert a[-3:] == AxialTree("FF]")
    s = Lstring("A(1)B")
    s += "C(2)"
    assert str(s) == "A(1)BC(2)" and s.find("C") == 2
    assert str(pickle.loads(pickle.dumps(s))) == "A(1)BC(2)"


def test_rules_added_from_python_and_one_rule_alone():
    lsys = Lsystem()
    lsys.derivationLength = 2
    lsys.axiom = AxialTree("F")
    lsys.addProductionRule("F --> F[+F]F")
    assert str(lsys.derive()) == "F[+F]F[+F[+F]F]F[+F]F"
    rule = LsysRule()
    rule.set("F --> F[+F]F")
    assert rule.isContextFree() and rule.match("FF", 0)[0] == 1
    assert str(rule.process("F")) == "F[+F]F"


def test_a_scene_renders_and_exports(tmp_path):
    text = GROWTH.replace("endlsystem", "interpretation:\nL --> F(0.3) ~l(1)\nB --> F\nendlsystem")
    lsys = Lsystem(model(tmp_path, text))
    scene = lsys.sceneInterpretation(lsys.derive())
    ids = sorted({shape.id for shape in scene})
    assert ids[:2] == [3, 8]  # the first two L (I draws nothing in L-Py)
    picture = scene.render(width=160, height=120)
    assert picture.shape == (120, 160, 4)
    # The plant: pixels far from the sky-and-ground background's colours.
    assert (np.abs(picture[..., :3].astype(int) - picture[0, 0, :3].astype(int)).sum(axis=2) > 120).sum() > 50
    out = tmp_path / "scene.obj"
    scene.export(str(out))
    assert out.stat().st_size > 1000
    assert scene._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"


def test_errors_name_the_file_and_the_line(tmp_path):
    with pytest.raises(ValueError) as missing:  # L-Py's LsysError
        Lsystem(str(tmp_path / "missing.lpy"))
    assert "missing.lpy" in str(missing.value)
    path = model(tmp_path, "Axiom: A(1)\nproduction:\nA(x) :\n    y = x / 0\n    produce A(y)\n", "bad.lpy")
    lsys = Lsystem(path)
    with pytest.raises(ZeroDivisionError) as e:
        lsys.derive()
    frames = [(os.path.basename(f.filename), f.lineno) for f in __import__("traceback").extract_tb(e.tb)]
    assert ("bad.lpy", 4) in frames
    with pytest.raises(SyntaxError) as syntax:
        Lsystem().set("Axiom: A(\n")
    assert syntax.value.lineno == 1


# Lsystem, LsysRule and LpyDebugger as L-Py's src/wrapper/export_lsystem.cpp, export_lsysrule.cpp
# and export_debugger.cpp define them (issue 51; tests/reference/lpy_api_cases/lsystem.py checks
# them against the real L-Py).
RULES = "Axiom: A(1) B\nderivation length: 3\nproduction:\nA(x) --> A(x + 1) C\nB --> B D\nC < D --> E\nendlsystem\n"


def test_lsystem_file_settings_and_early_return(tmp_path):
    path = model(tmp_path, RULES, "my.model.lpy")
    lsys = Lsystem(path)
    assert lsys.filename == path and lsys.context()["__name__"] == "my" and Lsystem().filename == ""
    assert (lsys.decompositionMaxDepth, lsys.interpretationMaxDepth) == (1, 1)
    lsys.early_return = True
    assert lsys.early_return
    assert str(lsys.derive()) == "A(4)CCCBDDD" and not lsys.early_return
    with pytest.raises(ValueError):
        Lsystem().read(str(tmp_path / "none.lpy"))


def test_lsystem_rules_partial_derivation_and_queries():
    from openalea.lpy import eForward

    lsys = Lsystem()
    lsys.setCode(RULES)
    assert [lsys.nbGroups(), lsys.nbTotalRules(), lsys.productionRule(2).name()] == [1, 3, "C < D"]
    assert lsys.get_rule_fonction_table()["__p_0_2_CD"] == "C < D"
    with pytest.raises(IndexError):
        lsys.productionRule(3)
    s = lsys.derive(1)
    assert str(lsys.partial_derivation(s, 1, 3)) == "CBDD"
    assert [str(x) for x in lsys.derivations(1, 3)] == ["A(2)CBD", "A(3)CCBDD", "A(4)CCCBDDD"]
    lsys.setCode("Axiom: F(2) ?P +(90) F(1) ?P\n")
    q = lsys.axiom
    lsys.turtle_interpretation(q)
    assert [round(c, 6) for c in q[1][0]] == [0, 0, 2] and str(eForward) == "eForward"


def test_lsysrule_alone_and_the_debugger():
    from openalea.lpy import ArgList, LpyDebugger

    rule = LsysRule()
    rule.set("A(x) < B(y) --> C(x+y) D")
    assert [rule.name(), rule.parameterNames(), rule.functionName()] == ["A(x) < B(y)", ["x", "y"], "__p_0_0_A_x_B_y_"]
    found = rule.match(Lstring("A(1)B(2)"), 1)
    assert found[0] == 2 and isinstance(found[1], ArgList) and list(found[1]) == [1, 2]
    out = Lstring("")
    assert rule.applyTo(out, found[1]) and str(out) == "C(3)D"
    with pytest.raises(ValueError):  # L-Py's binding passes no value from the list
        rule([1, 2])
    static = LsysRule()
    static.set("A(x) : produce B(2 * 3)")
    with pytest.raises(ValueError):
        static()

    class Told(LpyDebugger):
        log = []

        def total_match(self, beg, end, dest, n, rule, args):
            self.log.append((beg, rule.name(), rule.lineno, list(args)))

    lsys = Lsystem()
    lsys.setCode("Axiom: BA(2)C\nproduction:\nB --> D\nA(x) :\n    produce E(x)\nendlsystem\n")
    lsys.setDebugger(Told())
    assert str(lsys.derive(1)) == "DE(2)C" and Told.log == [(0, "B", 3, []), (1, "A(x)", 4, [2])]
