"""Differential cases of openalea.lpy's LsysRule, ArgList, LpyParsing and lstring2py (L-Py's
src/wrapper/export_lsysrule.cpp and export_parser.cpp): rules read, matched and applied on their
own; each case returns plain values. (Lsystem's cases, and its rules as objects, are in
lsystem.py.)"""
from lpy_api import case


# -- LsysRule ------------------------------------------------------------------------------------
_context = []


def rule(code, *init):
    """A rule read alone, in a context made current (L-Py compiles a rule in the current
    context, which must hold L-Py's names)."""
    from openalea.lpy import LsysContext, LsysRule

    if not _context:
        _context.append(LsysContext())
    _context[0].makeCurrent()
    try:
        r = LsysRule(*init)
        r.set(code)
    finally:
        _context[0].done()  # (the real L-Py hangs at exit with a context left current)
    return r


@case("LsysRule", "LsysRule.set", "LsysRule.name", "LsysRule.__str__", "LsysRule.nbParameters",
      "LsysRule.parameterNames", "LsysRule.nbContexts", "LsysRule.isContextFree", "LsysRule.forwardCompatible",
      "LsysRule.backwardCompatible", "LsysRule.hasQuery", "LsysRule.isCompiled", "LsysRule.static",
      "LsysRule.codelength", "LsysRule.lineno", "LsysRule.id", "LsysRule.groupId", "LsysRule.functionName")
def rule_read_alone():
    out = []
    for code in ("A(x) < B(y) --> C(x+y)", "A(x) << B(y) > C : produce D(y)", "A(x,y) >> B --> C", "?P(p) F(l) --> F(l)",
                 "X --> Y Z", "X(a) :\n    if a > 1:\n        produce Y\n    else:\n        produce Z(a)\n"):
        r = rule(code)
        out.append([r.name(), str(r), r.nbParameters(), r.parameterNames(), r.nbContexts(), r.isContextFree(),
                    r.forwardCompatible(), r.backwardCompatible(), r.hasQuery(), r.isCompiled(), r.static, r.codelength,
                    r.lineno, r.id, r.groupId, r.functionName()])
    return out


@case("LsysRule.definition")
def rule_definition():
    return rule("A --> B").definition()


@case("LsysRule.set", "LsysRule.static", "LsysRule.compile")
def rule_static_with_variables():
    return rule("A(x) --> B(1)")


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
    t = rule("A : produce B(2 * 3) C")
    u = rule("A : pass")
    return [str(s()), str(s([])), s.static, str(s.__static_production__), r.static, str(r.__static_production__),
            str(t()), t.static, u(), u([])]


@case("LsysRule.__call__")
def rule_called_with_values():
    return str(rule("A(x) < B(y) --> C(x+y)")([1, 2]))


@case("LsysRule.__call__")
def rule_called_without_values():
    return str(rule("A(x) < B(y) --> C(x+y)")())


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


@case("LsysRule.process", "LsysRule.applyTo", "ArgList", "ArgList.append", "ArgList.extend")
def rule_processed():
    from openalea.lpy import ArgList, Lstring

    r = rule("A(x) --> A(x+1) B")
    s = Lstring("C")
    values = ArgList()
    values.append(4)
    applied = r.applyTo(s, values)
    more = ArgList(2, 0)
    more.extend([7])
    return [str(r.process("A(1) C A(2)")), str(rule("B --> *").process("ABAB")), str(rule("B : pass").process("ABAB")),
            applied, str(s), rule("A : pass").applyTo(s, ArgList()), str(s), str(more), len(more), more[2], 7 in more]


@case("LsysRule.applyTo")
def rule_applied_to_a_list():
    from openalea.lpy import Lstring

    return rule("A(x) --> A(x+1) B").applyTo(Lstring("C"), [4])


@case("LsysRule.match", "ArgList")
def rule_match_gives_an_arglist():
    from openalea.lpy import Lstring

    found = rule("A(x) --> B(x)").match(Lstring("A(3)"))
    return [found[0], str(found[1]), repr(found[1]), list(found[1]), type(found[1]).__name__]


@case("LsysRule.compile", "LsysRule.recompile", "LsysRule.function", "LsysRule.code")
def rule_compiled():
    from openalea.lpy import LsysRule

    r = LsysRule()
    before = [r.isCompiled(), r.function()]
    r.set("A(x) --> B(x)")
    f = r.function()
    r.recompile()
    return before + [r.isCompiled(), callable(f), r.code().split(" :")[0]]  # (L-Py's body names its own production ids)


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
