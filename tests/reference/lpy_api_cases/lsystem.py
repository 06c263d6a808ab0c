"""Differential cases of openalea.lpy's Lsystem (its rules as LsysRule objects), LsystemIterator,
LpyDebugger and the enums eDirection and eRuleType (L-Py's src/wrapper/export_lsystem.cpp,
export_debugger.cpp and src/openalea/lpy/__init__.py): each builds its L-system from code and
returns plain values. A case uses nothing that crashes the real L-Py (a missing file's read, a
rule index out of range, stepInterpretation without a display, lstring breakpoints, a debugger
that overrides nothing): the compare runs all cases in one process."""
# Index of this file:
#   [SECTION] Lsystem: files and settings
#   [SECTION] Lsystem: rules
#   [SECTION] Lsystem: deriving and drawing
#   [SECTION] debugger
#   [SECTION] the enums
#   [SECTION] more of Lsystem

import os
import tempfile

from lpy_api import case

UI_ONLY = {
    "Lsystem.stepInterpretation": "draws in L-Py's viewer module by module and shows each module in its status bar "
                                  "(the real L-Py crashes without a display); Sprout gives the scenes to a registered "
                                  "plotter, and raises NotImplementedError without one",
}

MODEL = """
Axiom: A(1) B
derivation length: 3
production:
A(x) --> A(x + 1) C
B --> B D
C < D --> E
interpretation:
E --> F
endlsystem
"""

TWO_GROUPS = """
Axiom: A
derivation length: 2
production:
A --> AB
group 1:
B --> C
decomposition:
maximum depth: 2
C --> DD
group 0:
interpretation:
A --> F
endlsystem
"""


def lsystem(code=MODEL):
    from openalea.lpy import Lsystem

    lsys = Lsystem()
    lsys.setCode(code)
    return lsys


def written(tmpdir, text, name="model.lpy"):
    path = os.path.join(tmpdir, name)
    with open(path, "w") as f:
        f.write(text)
    return path


class Plotter:
    """What openalea.lpy.registerPlotter takes: records the scenes and the files saved."""

    def __init__(self):
        self.plotted, self.saved = [], []

    def plot(self, scene):
        self.plotted.append(len(scene))

    def save(self, name, format):
        self.saved.append((os.path.basename(name), format))

    def selection(self):
        return []

    def waitSelection(self, txt):
        return None


# [SECTION] Lsystem: files and settings
@case("Lsystem.filename", "Lsystem.read")
def lsystem_filename_of_a_file():
    from openalea.lpy import Lsystem

    with tempfile.TemporaryDirectory() as d:
        path = written(d, MODEL, "my.model.lpy")
        lsys = Lsystem(path)
        again = Lsystem()
        again.read(path)
        return [lsys.filename == path, again.filename == path, lsys.context()["__name__"], str(lsys.derive()),
                Lsystem().filename]


@case("Lsystem.filename")
def lsystem_filename_set():
    lsys = lsystem()
    lsys.filename = "some/where/plant.v2.lpy"
    lsys.setCode(MODEL)  # a new code keeps the file
    return [lsys.filename, lsys.context()["__name__"]]


@case("Lsystem.derivationLength", "Lsystem.decompositionMaxDepth", "Lsystem.interpretationMaxDepth")
def lsystem_lengths_and_depths():
    from openalea.lpy import Lsystem

    fresh = Lsystem()
    lsys = lsystem(TWO_GROUPS + "\n")
    before = [fresh.derivationLength, fresh.decompositionMaxDepth, fresh.interpretationMaxDepth,
              lsys.derivationLength, lsys.decompositionMaxDepth, lsys.interpretationMaxDepth]
    lsys.derivationLength, lsys.decompositionMaxDepth, lsys.interpretationMaxDepth = 5, 1, 3
    return before + [lsys.derivationLength, lsys.decompositionMaxDepth, lsys.interpretationMaxDepth]


@case("Lsystem.decompositionMaxDepth", "Lsystem.derive")
def lsystem_decomposition_depth_used():
    code = "Axiom: A\nderivation length: 1\nproduction:\nA --> B\ndecomposition:\nmaximum depth: 3\nB --> CB\nendlsystem\n"
    lsys = lsystem(code)
    deep = str(lsys.derive())
    lsys.decompositionMaxDepth = 1
    return [deep, str(lsys.derive())]


@case("Lsystem.early_return")
def lsystem_early_return_flag():
    lsys = lsystem()
    before = lsys.early_return
    lsys.early_return = True
    during = lsys.early_return
    lsys.derive()
    return [before, during, lsys.early_return]


@case("Lsystem.early_return", "Lsystem.getLastIterationNb")
def lsystem_early_return_from_end_each():
    code = """
seen = []
def EndEach():
    seen.append(lsys_early())
    if getIterationNb() == 1:
        Stop()
        seen.append(lsys_early())
Axiom: A
derivation length: 5
production:
A --> AB
endlsystem
"""
    lsys = lsystem(code)
    lsys.context()["lsys_early"] = lambda: lsys.early_return
    out = lsys.derive()
    return [str(out), lsys.getLastIterationNb(), lsys.seen, lsys.early_return]


# [SECTION] Lsystem: rules
@case("Lsystem.nbGroups", "Lsystem.nbProductionRules", "Lsystem.nbDecompositionRules", "Lsystem.nbInterpretationRules",
      "Lsystem.nbTotalRules", "Lsystem.empty", "Lsystem.isCompiled")
def lsystem_rule_counts():
    from openalea.lpy import Lsystem

    lsys = lsystem(TWO_GROUPS)
    fresh = Lsystem()
    return [lsys.nbGroups(), lsys.nbProductionRules(), lsys.nbProductionRules(1), lsys.nbDecompositionRules(1),
            lsys.nbInterpretationRules(), lsys.nbTotalRules(), lsys.empty(), lsys.isCompiled(),
            fresh.empty(), fresh.nbGroups(), fresh.isCompiled(), lsystem("Axiom: A\n").empty()]


@case("Lsystem.productionRule", "Lsystem.decompositionRule", "Lsystem.interpretationRule", "LsysRule.name",
      "LsysRule.id", "LsysRule.groupId")
def lsystem_rules_as_objects():
    lsys = lsystem(TWO_GROUPS)
    rules = [lsys.productionRule(0), lsys.productionRule(0, 1), lsys.decompositionRule(0, 1),
             lsys.interpretationRule(0, 0), lsys.productionRule(-1, -1)]
    return [[r.name(), r.id, r.groupId] for r in rules]


@case("Lsystem.productionRule", "LsysRule.static", "LsysRule.name", "LsysRule.functionName", "LsysRule.parameterNames",
      "LsysRule.predecessor", "Lsystem.get_rule_fonction_table")
def lsystem_static_rules():
    lsys = lsystem("Axiom: A(1)\nproduction:\nA(x) --> B\nB(x, y) < C(z) --> D(1)\nX(a) --> Y(a)\n")
    rules = [lsys.productionRule(i) for i in range(3)]
    return [[r.name(), r.functionName(), r.static, r.nbParameters(), r.parameterNames(), str(r.predecessor())] for r in rules] + [
        lsys.get_rule_fonction_table(), str(lsys)]


@case("Lsystem.get_rule_fonction_table", "LsysRule.functionName")
def lsystem_rule_function_table():
    return lsystem(MODEL).get_rule_fonction_table()


@case("Lsystem.addRule", "Lsystem.addProductionRule", "Lsystem.addDecompositionRule",
      "Lsystem.addInterpretationRule", "eRuleType", "eProduction", "eDecomposition", "eInterpretation")
def lsystem_rules_added():
    from openalea.lpy import eDecomposition, eProduction

    lsys = lsystem("Axiom: A\nderivation length: 2\nproduction:\nA --> AB\nendlsystem\n")
    lsys.addProductionRule("B --> C")
    lsys.addRule("C --> D", eProduction)
    lsys.addRule("D --> EE", eDecomposition)
    lsys.addInterpretationRule("E --> F")
    return [str(lsys.derive()), lsys.nbProductionRules(), lsys.nbDecompositionRules(), lsys.nbInterpretationRules(),
            str(lsys.interpret(lsys.derive()))]


@case("Lsystem.__str__", "Lsystem.code", "Lsystem.clear")
def lsystem_listing():
    lsys = lsystem(MODEL)
    listing = str(lsys)
    lsys.clear()
    return [listing, lsys.code().split("\n")[:4], lsys.derivationLength, lsys.empty(), lsys.filename]


# [SECTION] Lsystem: deriving and drawing
@case("Lsystem.derivations", "LsystemIterator", "Lsystem.derive")
def lsystem_derivations():
    lsys = lsystem()
    return [[str(s) for s in lsys.derivations()], [str(s) for s in lsys.derivations(2)],
            [str(s) for s in lsys.derivations(1, 3)], [str(s) for s in lsys.derivations(0, 3, 2)],
            [str(s) for s in lsys]]


@case("LsystemIterator", "LsystemIterator.next")
def lsystem_iterator_by_hand():
    from openalea.lpy import LsystemIterator

    lsys = lsystem()
    it = LsystemIterator(lsys, 1, 2)
    first = it.next()
    second = next(it)
    try:
        next(it)
        over = "no end"
    except StopIteration:
        over = "StopIteration"
    return [str(first), str(second), over, it.start, it.stop, it.step, it.currentstep]


@case("LsystemIterator")
def lsystem_iterator_start_after_stop():
    from openalea.lpy import LsystemIterator

    return LsystemIterator(lsystem(), 3, 1)


@case("Lsystem.partial_derivation")
def lsystem_partial_derivation():
    lsys = lsystem(MODEL)
    s = lsys.derive(1)
    return [str(s), str(lsys.partial_derivation(s, 1, 3)), str(lsys.partial_derivation(s, 0, 2)),
            str(lsys.partial_derivation(s, 2, 10))]


@case("Lsystem.turtle_interpretation")
def lsystem_turtle_interpretation_fills_queries():
    from openalea.lpy import Lstring

    lsys = lsystem("Axiom: F(2) ?P +(90) F(1) ?P\n")
    s = lsys.axiom
    lsys.turtle_interpretation(s)
    return [[round(c, 9) for c in (s[1][0].x, s[1][0].y, s[1][0].z)], [round(c, 9) for c in (s[4][0].x, s[4][0].y, s[4][0].z)],
            lsys.turtle_interpretation(Lstring("F"))]


@case("Lsystem.record", "Lsystem.plot")
def lsystem_record_with_a_plotter():
    import openalea.lpy as lpy

    lsys = lsystem()
    plotter = Plotter()
    lpy.registerPlotter(plotter)
    try:
        lsys.record("frame_", 2)
        lsys.record("img", 1, 2, "jpg")
    finally:
        lpy.cleanPlotter()
    return [plotter.saved, plotter.plotted, lsys.getLastIterationNb()]


@case("Lsystem.isRunning", "Lsystem.forceRelease")
def lsystem_running():
    code = "seen = []\ndef EndEach():\n    seen.append(me().isRunning())\nAxiom: A\nderivation length: 2\nproduction:\nA --> AB\nendlsystem\n"
    lsys = lsystem(code)
    lsys.context()["me"] = lambda: lsys
    lsys.derive()
    return [lsys.isRunning(), lsys.seen, lsys.forceRelease(), lsys.isRunning()]


@case("Lsystem.derive")
def lsystem_derive_again_inside_its_run():
    code = "def EndEach():\n    me().derive()\nAxiom: A\nderivation length: 1\nproduction:\nA --> AB\nendlsystem\n"
    lsys = lsystem(code)
    lsys.context()["me"] = lambda: lsys
    return str(lsys.derive())


@case("Lsystem.__getattr__", "Lsystem.__setattr__")
def lsystem_names_of_the_model():
    lsys = lsystem("size = 3\nAxiom: A\n")
    lsys.size = 4
    lsys.colour = "red"
    return [lsys.size, lsys.context()["size"], lsys.context()["colour"], "colour" in lsys.context()]


@case("Lsystem.__getattr__")
def lsystem_missing_name():
    return lsystem().no_such_name


# [SECTION] debugger
DEBUGGED = """
Axiom: BAABAC
production:
B --> D
C : pass
A(x) :
    produce E
A :
    if len(str(A)) > 1000: produce E
endlsystem
"""


def told_debugger():
    from openalea.lpy import LpyDebugger

    class Told(LpyDebugger):
        def __init__(self):
            LpyDebugger.__init__(self)
            self.log = []

        def begin(self, src, direction):
            self.log.append(("begin", str(src), str(direction)))

        def end(self, result):
            self.log.append(("end", str(result)))

        def total_match(self, pos_beg, pos_end, dest, prod_length, rule, args):
            self.log.append(("total", pos_beg, pos_end, str(dest), prod_length, rule.name(), rule.lineno, list(args)))

        def partial_match(self, pos_beg, pos_end, dest, rule, args):
            self.log.append(("partial", pos_beg, pos_end, str(dest), rule.name()))

        def error_match(self, pos_beg, pos_end, dest, rule, args, trace):
            self.log.append(("error", pos_beg, pos_end, rule.name(), trace[0].__name__))
            return True

        def identity(self, pos, dest):
            self.log.append(("identity", pos, str(dest)))

    return Told()


@case("LpyDebugger", "LpyDebugger.begin", "LpyDebugger.end", "LpyDebugger.total_match", "LpyDebugger.partial_match",
      "LpyDebugger.error_match", "LpyDebugger.identity", "Lsystem.setDebugger", "Lsystem.getDebugger",
      "Lsystem.hasDebugger", "Lsystem.clearDebugger", "eDirection", "eForward")
def debugger_told_of_each_match():
    lsys = lsystem(DEBUGGED)
    d = told_debugger()
    lsys.setDebugger(d)
    had = lsys.hasDebugger()
    out = str(lsys.derive(1))
    lsys.clearDebugger()
    return [out, d.log, had, lsys.hasDebugger()]


@case("Lsystem.getDebugger")
def debugger_given_back():
    lsys = lsystem(DEBUGGED)
    lsys.setDebugger(told_debugger())
    return lsys.getDebugger()


@case("eDirection", "eBackward")
def enum_made_from_a_number():
    from openalea.lpy import eBackward, eDirection

    made = eDirection(1)
    return [repr(made), str(eDirection(5)), made == eBackward, made is eBackward, int(made)]


@case("eDirection.name")
def enum_made_has_no_name():
    from openalea.lpy import eDirection

    return eDirection(1).name


@case("LpyDebugger.alwaysStop", "LpyDebugger.insertCodeBreakPointAt")
def debugger_breakpoints_filter():
    lsys = lsystem(DEBUGGED)
    d = told_debugger()
    d.alwaysStop = False
    d.insertCodeBreakPointAt(5)  # the line of C's rule
    lsys.setDebugger(d)
    lsys.derive(1)
    return [d.alwaysStop, d.log]


@case("LpyDebugger.insertLstringBreakPointAt", "LpyDebugger.removeLstringBreakPointAt",
      "LpyDebugger.hasLstringBreakPointAt", "LpyDebugger.alwaysStop")
def debugger_lstring_breakpoints():
    """Positions of the string being derived: L-Py's hold an iterator into it, so they are set
    once the step has begun (from begin on, the reference crashes); has... tells nothing."""
    d = told_debugger()
    inner = d.total_match

    def total_match(pos_beg, pos_end, dest, prod_length, rule, args):
        inner(pos_beg, pos_end, dest, prod_length, rule, args)
        if pos_beg == 0:
            d.alwaysStop = False
            d.insertLstringBreakPointAt(3)
            d.insertLstringBreakPointAt(4)
            d.log.append(("has", d.hasLstringBreakPointAt(3)))
            d.removeLstringBreakPointAt(4)
            try:
                d.removeLstringBreakPointAt(4)
            except Exception as e:
                d.log.append(("raised", type(e).__name__, str(e)))

    d.total_match = total_match
    lsys = lsystem("Axiom: A B C D E\nderivation length: 1\nproduction:\nA --> A\nC --> C\nE --> E\nendlsystem\n")
    lsys.setDebugger(d)
    out = str(lsys.derive(1))
    return [out, d.log]


@case("LpyDebugger.insertCodeBreakPointAt", "LpyDebugger.removeCodeBreakPointAt", "LpyDebugger.hasCodeBreakPointAt",
      "LpyDebugger.clearBreakPoints", "LpyDebugger.clearCodeBreakPoints", "LpyDebugger.clearLstringBreakPoints",
      "LpyDebugger.clearPyError", "LpyDebugger.alwaysStop")
def debugger_code_breakpoints():
    from openalea.lpy import LpyDebugger

    d = LpyDebugger()
    out = [d.alwaysStop]
    d.insertCodeBreakPointAt(3)
    d.insertCodeBreakPointAt(7)
    out += [d.hasCodeBreakPointAt(3), d.hasCodeBreakPointAt(4)]
    d.removeCodeBreakPointAt(3)
    out += [d.hasCodeBreakPointAt(3), d.hasCodeBreakPointAt(7)]
    d.clearCodeBreakPoints()
    out += [d.hasCodeBreakPointAt(7), d.clearBreakPoints(), d.clearLstringBreakPoints(), d.clearPyError()]
    return out


@case("LpyDebugger.error_match")
def debugger_not_asked_of_errors():
    lsys = lsystem(DEBUGGED.replace("if len(str(A)) > 1000", "if 1 / 0"))
    d = told_debugger()
    lsys.setDebugger(d)
    try:
        lsys.derive(1)
        return "no error"
    except ZeroDivisionError:
        return d.log


@case("LpyDebugger.removeCodeBreakPointAt")
def debugger_remove_missing_breakpoint():
    from openalea.lpy import LpyDebugger

    return LpyDebugger().removeCodeBreakPointAt(2)


# [SECTION] the enums
@case("eDirection", "eDirection.eForward", "eDirection.eBackward", "eDirection.name", "eDirection.names",
      "eDirection.values", "eForward", "eBackward")
def enum_direction():
    from openalea.lpy import eBackward, eDirection, eForward

    return [int(eForward), int(eBackward), str(eForward), repr(eBackward), eForward.name, sorted(eDirection.names),
            sorted(eDirection.values), eDirection.values[1] is eBackward, eForward == 0, isinstance(eForward, int)]


@case("eRuleType", "eRuleType.eProduction", "eRuleType.eDecomposition", "eRuleType.eInterpretation",
      "eRuleType.name", "eRuleType.names", "eRuleType.values")
def enum_rule_type():
    from openalea.lpy import eInterpretation, eRuleType

    return [[int(v), str(v), v.name] for k, v in sorted(eRuleType.values.items())] + [
        sorted(eRuleType.names), eRuleType.eInterpretation is eInterpretation]


# [SECTION] more of Lsystem
@case("Lsystem", "Lsystem.axiom", "Lsystem.setCode", "Lsystem.set", "Lsystem.compile", "Lsystem.context", "Lsystem.execContext",
      "Lsystem.makeCurrent", "Lsystem.isCurrent", "Lsystem.done", "Lsystem.iterate", "Lsystem.homomorphism",
      "Lsystem.interpret")
def lsystem_basics():
    from openalea.lpy import Lsystem

    lsys = Lsystem()
    given = lsys.setCode(MODEL)
    out = [given, str(lsys.axiom), lsys.compile(), type(lsys.context()) is type(lsys.execContext()), lsys.isCurrent()]
    lsys.makeCurrent()
    out.append(lsys.isCurrent())
    lsys.done()
    out.append(lsys.isCurrent())
    lsys.axiom = "A(7) D"
    derived = lsys.iterate(2)
    out += [str(lsys.axiom), str(derived), str(lsys.homomorphism(derived)), str(lsys.interpret(derived))]
    lsys.set("Axiom: B\n")
    return out + [str(lsys.axiom), lsys.derivationLength]


@case("Lsystem.sceneInterpretation", "Lsystem.getLastComputedScene")
def lsystem_scenes():
    lsys = lsystem("Axiom: F F [+ F] X F(2)\n")
    scene = lsys.sceneInterpretation(lsys.axiom)
    return [len(scene), lsys.getLastComputedScene() is None, sorted(sh.id for sh in scene)]


@case("Lsystem.getLastComputedScene")
def lsystem_last_scene_of_end_each():
    code = "def EndEach(lstring, scene):\n    pass\nAxiom: F\nderivation length: 2\nproduction:\nF --> FF\n"
    lsys = lsystem(code)
    lsys.derive()
    scene = lsys.getLastComputedScene()
    return [scene is None, len(scene) if scene is not None else None]


@case("Lsystem.animate", "Lsystem.plot")
def lsystem_animated_with_a_plotter():
    import openalea.lpy as lpy

    lsys = lsystem("Axiom: F\nderivation length: 3\nproduction:\nF --> F F\n")
    plotter = Plotter()
    lpy.registerPlotter(plotter)
    try:
        last = lsys.animate(0.001)
        lsys.plot(last)
    finally:
        lpy.cleanPlotter()
    return [str(last), plotter.plotted, lsys.getLastIterationNb()]
