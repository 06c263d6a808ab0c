"""Differential cases of openalea.lpy's Lsystem, LsystemIterator, LsysRule, LpyDebugger,
LpyParsing, lstring2py and the enums eDirection and eRuleType (L-Py's src/wrapper/
export_lsystem.cpp, export_lsysrule.cpp, export_debugger.cpp, export_parser.cpp and
src/openalea/lpy/__init__.py): each builds its L-system from code and returns plain values."""
import os
import tempfile

from lpy_api import case

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


# -- Lsystem: files and settings ---------------------------------------------------------------
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


@case("Lsystem.read")
def lsystem_read_missing_file():
    from openalea.lpy import Lsystem

    return Lsystem().read("/no/such/dir/model.lpy")


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


# -- Lsystem: rules ------------------------------------------------------------------------
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


@case("Lsystem.productionRule", "Lsystem.interpretationRule")
def lsystem_rule_index_out_of_range():
    return lsystem(TWO_GROUPS).productionRule(1)


@case("Lsystem.productionRule")
def lsystem_group_index_out_of_range():
    return lsystem(TWO_GROUPS).productionRule(0, 2)


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


# -- Lsystem: deriving and drawing -------------------------------------------------------------
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


@case("Lsystem.stepInterpretation", "Lsystem.sceneInterpretation")
def lsystem_step_interpretation_plots():
    import openalea.lpy as lpy

    lsys = lsystem("Axiom: F F [+ F] X F\n")
    lsys.context().animation_timestep = 0
    plotter = Plotter()
    lpy.registerPlotter(plotter)
    try:
        lsys.stepInterpretation(lsys.axiom)
    finally:
        lpy.cleanPlotter()
    return [plotter.plotted, len(lsys.sceneInterpretation(lsys.axiom))]


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


# -- debugger ------------------------------------------------------------------------------------
DEBUGGED = """
Axiom: BAABAC
production:
B --> D
C : pass
A :
    if 1 / 0: produce E
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
    had = [lsys.hasDebugger(), lsys.getDebugger() is d]
    out = str(lsys.derive(1))
    lsys.clearDebugger()
    return [out, d.log, had, lsys.hasDebugger(), lsys.getDebugger()]


@case("LpyDebugger.alwaysStop", "LpyDebugger.insertCodeBreakPointAt", "LpyDebugger.insertLstringBreakPointAt")
def debugger_breakpoints_filter():
    lsys = lsystem(DEBUGGED)
    d = told_debugger()
    d.alwaysStop = False
    d.insertCodeBreakPointAt(5)  # the line of C's rule
    lsys.setDebugger(d)
    lsys.derive(1)
    return [d.alwaysStop, d.log]


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


@case("LpyDebugger.removeCodeBreakPointAt")
def debugger_remove_missing_breakpoint():
    from openalea.lpy import LpyDebugger

    return LpyDebugger().removeCodeBreakPointAt(2)


@case("LpyDebugger.total_match", "LpyDebugger.identity", "LpyDebugger.begin")
def debugger_base_does_nothing():
    lsys = lsystem(DEBUGGED.replace("    if 1 / 0: produce E\n", "    produce E\n"))
    from openalea.lpy import LpyDebugger

    lsys.setDebugger(LpyDebugger())
    return str(lsys.derive(1))


@case("LpyDebugger.error_match")
def debugger_base_keeps_the_error():
    from openalea.lpy import LpyDebugger

    lsys = lsystem(DEBUGGED)
    lsys.setDebugger(LpyDebugger())
    return str(lsys.derive(1))


# -- the enums -----------------------------------------------------------------------------------
@case("eDirection", "eDirection.eForward", "eDirection.eBackward", "eDirection.name", "eDirection.names",
      "eDirection.values", "eForward", "eBackward")
def enum_direction():
    from openalea.lpy import eBackward, eDirection, eForward

    return [int(eForward), int(eBackward), str(eForward), repr(eBackward), eForward.name, sorted(eDirection.names),
            sorted(eDirection.values), eDirection(1) is eBackward, eForward == 0, isinstance(eForward, int)]


@case("eRuleType", "eRuleType.eProduction", "eRuleType.eDecomposition", "eRuleType.eInterpretation",
      "eRuleType.name", "eRuleType.names", "eRuleType.values")
def enum_rule_type():
    from openalea.lpy import eInterpretation, eRuleType

    return [[int(v), str(v), v.name] for k, v in sorted(eRuleType.values.items())] + [
        sorted(eRuleType.names), eRuleType.eInterpretation is eInterpretation]


# -- LsysRule ------------------------------------------------------------------------------------
def rule(code, *init):
    from openalea.lpy import LsysRule

    r = LsysRule(*init)
    r.set(code)
    return r


@case("LsysRule", "LsysRule.set", "LsysRule.name", "LsysRule.__str__", "LsysRule.definition", "LsysRule.nbParameters",
      "LsysRule.parameterNames", "LsysRule.nbContexts", "LsysRule.isContextFree", "LsysRule.forwardCompatible",
      "LsysRule.backwardCompatible", "LsysRule.hasQuery", "LsysRule.isCompiled", "LsysRule.static",
      "LsysRule.codelength", "LsysRule.lineno", "LsysRule.id", "LsysRule.groupId", "LsysRule.functionName")
def rule_read_alone():
    out = []
    for code in ("A(x) < B(y) --> C(x+y)", "A(x) << B(y) > C : produce D(y)", "A(x,y) >> B --> C", "?P(p) F(l) --> F(l)",
                 "X --> Y Z", "X(a) :\n    if a > 1:\n        produce Y\n    else:\n        produce Z(a)\n"):
        r = rule(code)
        out.append([r.name(), str(r), r.definition(), r.nbParameters(), r.parameterNames(), r.nbContexts(), r.isContextFree(),
                    r.forwardCompatible(), r.backwardCompatible(), r.hasQuery(), r.isCompiled(), r.static, r.codelength,
                    r.lineno, r.id, r.groupId, r.functionName()])
    return out


@case("LsysRule", "LsysRule.id", "LsysRule.groupId", "LsysRule.functionName", "LsysRule.clear")
def rule_ids():
    from openalea.lpy import LsysRule

    r = rule("A --> B", 3, 2, "d")
    out = [r.id, r.groupId, r.functionName()]
    r.id, r.groupId = 5, 1
    out += [r.id, r.groupId, r.functionName()]
    r.clear()
    return out + [r.id, r.groupId, r.name(), str(r), r.isCompiled(), LsysRule().isCompiled(), str(LsysRule())]


@case("LsysRule.__call__", "LsysRule.static", "LsysRule.__static_production__")
def rule_called():
    r = rule("A(x) < B(y) --> C(x+y) D")
    s = rule("X --> Y(1) Z")
    t = rule("A(x) : produce")
    return [str(r([1, 2])), str(s()), s.static, str(s.__static_production__), r.static, t([3])]


@case("LsysRule.__call__")
def rule_called_with_too_few():
    return str(rule("A(x) < B(y) --> C(x+y)")([1]))


@case("LsysRule.set")
def rule_without_delimiter():
    return rule("A B C")


@case("LsysRule.set")
def rule_with_two_predecessors():
    return rule("A > B > C --> D")


@case("LsysRule.match", "LsysRule.reverse_match")
def rule_matched():
    from openalea.lpy import Lstring

    r = rule("A(x) < B(y) --> C(x+y)")
    s = Lstring("A(1)B(2)B(3)")
    return [r.match(s, 1), r.match(s, 2), r.match(s, 0), r.reverse_match(s, 1), r.reverse_match(s), r.match(s, -2),
            rule("B(y) --> C").match(s)]


@case("LsysRule.match")
def rule_match_out_of_range():
    from openalea.lpy import Lstring

    return rule("A --> B").match(Lstring("A A"), 7)


@case("LsysRule.process", "LsysRule.applyTo")
def rule_processed():
    from openalea.lpy import Lstring

    r = rule("A(x) --> A(x+1) B")
    s = Lstring("C")
    applied = r.applyTo(s, [4])
    return [str(r.process("A(1) C A(2)")), str(rule("B --> *").process("ABAB")), applied, str(s),
            rule("A(x) : pass").applyTo(s, [1]), str(s)]


@case("LsysRule.compile", "LsysRule.recompile", "LsysRule.function", "LsysRule.code")
def rule_compiled():
    from openalea.lpy import LsysRule

    r = LsysRule()
    before = [r.isCompiled(), r.function()]
    r.set("A(x) --> B(x)")
    f = r.function()
    r.recompile()
    return before + [r.isCompiled(), callable(f), r.code().split("\n")[0]]


@case("LsysRule.predecessor", "LsysRule.leftContext", "LsysRule.newLeftContext", "LsysRule.rightContext",
      "LsysRule.newRightContext")
def rule_patterns():
    r = rule("A(x) < B(y)  C >> D(z) --> E")
    q = rule("A << B > C(a, b) --> E")
    return [[str(p()) for p in (r.leftContext, r.newLeftContext, r.predecessor, r.newRightContext, r.rightContext)],
            [str(p()) for p in (q.leftContext, q.newLeftContext, q.predecessor, q.newRightContext, q.rightContext)]]


@case("LsysRule.consider", "LsysRule.ignore", "LsysRule.considerFilter")
def rule_consider():
    from openalea.lpy import Lstring

    r = rule("A < B --> C")
    s = Lstring("A X B")
    plain = r.match(s, 2)
    r.ignore("X")
    ignoring = r.match(s, 2)
    r.consider("A B")
    return [plain, ignoring, r.match(s, 2), r.considerFilter is not None]


# -- LpyParsing, lstring2py ------------------------------------------------------------------------
@case("LpyParsing", "LpyParsing.InitialisationBeginTag", "LpyParsing.VersionTag", "LpyParsing.formats",
      "LpyParsing.DefaultFormat", "LpyParsing.isSupportedFormat", "LpyParsing.getFormatVersion",
      "LpyParsing.isFormatDefined")
def parsing_constants():
    from openalea.lpy import LpyParsing as P

    return [P.InitialisationBeginTag, P.VersionTag, P.formats, P.DefaultFormat, P.isSupportedFormat(1.0),
            P.isSupportedFormat(1.1), P.isSupportedFormat(0.5),
            P.getFormatVersion("# -*- lpy version: 1.1 -*-\nAxiom: A"), P.getFormatVersion("Axiom: A"),
            P.getFormatVersion("# -*- lpy version: 2.5 -*-"), P.getFormatVersion("# -*- lpy version: 1.2x -*-\n"),
            P.isFormatDefined("# -*- lpy version: 1.0 -*-\n"), P.isFormatDefined(" # -*- lpy version: 1.0 -*-\n"),
            P.isFormatDefined("# -*- lpy version: 1.0 -*-")]


@case("LpyParsing.lstring2py", "lstring2py")
def parsing_lstring2py():
    from openalea.lpy import LpyParsing, lstring2py

    from openalea.lpy import AxialTree, ParamModule

    names = {"ParamModule": ParamModule}  # what a model's namespace holds (L-Py's ids need none)
    text = "F(1)+(30)[F(2, 3)]f"
    return [str(AxialTree(eval(lstring2py(text), names))), len(eval(LpyParsing.lstring2py("F[+F]"), names))]
