"""openalea.lpy's strings (issue 51, helper h9): AxialTree and Lstring, AxialTreeIterator, a
string's tree through a ConsiderFilter, the patterns (LsysVar, PatternModule, PatternString) and
StringMatching, as L-Py's wrappers define them (src/wrapper/export_axialtree.cpp,
export_lstring.h, export_patternmodule.cpp, export_patternstring.cpp,
export_stringmatching.cpp). AxialTree's slices are not deleted here: L-Py's removeRange prints
its indices on the process's stdout."""
from lpy_api import case, declared, defined, lpy


# --- AxialTree, Lstring ------------------------------------------------------------------------


@case("AxialTree", "Lstring", "AxialTree.__str__", "AxialTree.__repr__", "AxialTree.__len__", "AxialTree.argSize",
      "AxialTree.empty", "AxialTree.__eq__", "AxialTree.__ne__")
def axial_tree_made():
    l = lpy()
    s = l.Lstring("A(1)[B(2,3)]C")
    t = l.AxialTree("A(1)[B(2,3)]C")
    return [str(s), repr(s), type(s).__name__, type(t).__name__, len(s), s.argSize(), s.empty(), l.AxialTree().empty(),
            s == t, s != t, s == l.AxialTree("A(2)"), str(l.AxialTree(l.ParamModule("D", 1))),
            str(l.AxialTree([l.ParamModule("E"), l.ParamModule("F", 2)])), str(l.AxialTree(("G", 7))),
            isinstance(s, l.AxialTree), str(l.Lstring())]


@case("AxialTree.__getitem__", "AxialTree.__setitem__", "AxialTree.__delitem__")
def axial_tree_items():
    l = lpy()
    s = l.AxialTree("A(1)B(2)C(3)D")
    out = [str(s[0]), type(s[1]).__name__, str(s[-1]), str(s[1:3]), type(s[1:3]).__name__, str(s[2:]), str(s[:2])]
    s[0] = l.ParamModule("X", 9)
    del s[1]
    out.append(str(s))
    m = s[0]
    m[0] = 10  # a module read from the string writes into it
    out.append(str(s))
    return out


@case("AxialTree.__getitem__")
def axial_tree_index_error():
    return lpy().AxialTree("A B")[5]


@case("AxialTree.append", "AxialTree.prepend", "AxialTree.insertAt", "AxialTree.__iadd__", "AxialTree.__add__",
      "AxialTree.__mul__", "AxialTree.__imul__", "AxialTree.clear")
def axial_tree_editing():
    l = lpy()
    s = l.AxialTree("A B")
    s.append("C(1)")
    s.append(l.ParamModule("D", 2))
    s.prepend("Z")
    s.insertAt(1, "Y(5)")
    out = [str(s)]
    s.insertAt(0, ("W", 3))  # L-Py sets the module there
    out.append(str(s))
    t = s + "E"
    t += l.ParamModule("F", 1)
    t += ("G", 2)
    out += [str(t), str(t + ("H",)), str(l.AxialTree("A[B]") * 2)]
    u = l.AxialTree("A B")
    u *= 3
    out.append(str(u))
    u.clear()
    out.append([str(u), len(u)])
    return out


@case("AxialTree.insertAt")
def axial_tree_insert_at_end():
    s = lpy().AxialTree("A B")
    s.insertAt(2, "C")
    return str(s)


@case("AxialTree.wellBracketed", "AxialTree.isAPath", "AxialTree.hasRequestModule", "AxialTree.count",
      "AxialTree.find", "AxialTree.str_slice")
def axial_tree_reading():
    l = lpy()
    s = l.AxialTree("A(1)[B(2)?P]A(1,2)A(3)C")
    return [s.wellBracketed(), l.AxialTree("A[B").wellBracketed(), s.isAPath(), l.AxialTree("A B").isAPath(),
            s.hasRequestModule(), l.AxialTree("A B").hasRequestModule(), s.count("A"), s.count("A", 1),
            s.count(l.ParamModule("A", 9)), s.find("A"), s.find("A", 1), s.find("C"), s.find("Q"), s.find("A", 1, 4),
            s.str_slice(1, 4), s.str_slice(2, 100)]


@case("AxialTree.roots", "AxialTree.parent", "AxialTree.children", "AxialTree.lateral_children",
      "AxialTree.direct_child", "AxialTree.endBracket", "AxialTree.beginBracket", "AxialTree.father",
      "AxialTree.sons", "AxialTree.lateralSons", "AxialTree.directSon")
def axial_tree_navigation():
    l = lpy()
    s = l.AxialTree("A[B[C]D]E[F]G")
    out = [s.roots(), l.AxialTree("[A][B]C").roots(), l.AxialTree("").roots()]
    for i in range(len(s)):
        if s[i].name not in "[]":
            out.append([i, s.parent(i), s.children(i), s.lateral_children(i), s.direct_child(i),
                        s.children(i, "<"), s.children(i, "+")])
    out += [s.endBracket(1), s.endBracket(1, True), s.endBracket(2), s.beginBracket(5), s.beginBracket(7),
            s.beginBracket(7, True), s.endBracket(len(s))]
    return out


@case("AxialTree.children")
def axial_tree_children_bad_edge():
    return lpy().AxialTree("A[B]C").children(0, "x")


@case("AxialTree.parent")
def axial_tree_parent_out_of_range():
    return lpy().AxialTree("A B").parent(7)


@case("AxialTree.complex", "AxialTree.components", "AxialTree.components_at_scale", "AxialTree.successor_at_scale",
      "AxialTree.predecessor_at_scale", "AxialTree.successor_at_level", "AxialTree.predecessor_at_level")
def axial_tree_scales():
    l = lpy()
    p, u = declared("P", []), declared("U", [])
    p.scale, u.scale = 1, 2
    s = l.AxialTree("P U I I U I P U I")
    return [p.scale, u.scale, s.complex(2), s.complex(2, 1), s.components(0), s.components_at_scale(0, 2),
            s.successor_at_scale(1, 2), s.predecessor_at_scale(4, 2), s.successor_at_level(1, 2),
            s.predecessor_at_level(7, 1), s.complex(1), s.complex(0), s.components(1), s.successor_at_scale(0, 1)]


@case("AxialTree.node", "NodeModule", "NodeModule.position", "NodeModule.isValid", "NodeModule.isRoot",
      "NodeModule.parent", "NodeModule.children", "NodeModule.lateral_children", "NodeModule.direct_child",
      "NodeModule.father", "NodeModule.sons", "NodeModule.lateralSons", "NodeModule.directSon")
def axial_tree_nodes():
    s = lpy().AxialTree("A(1)[B(2)]C(3)")
    a, b, c = s.node(0), s.node(2), s.node(4)
    kids = a.children()
    return [type(a).__name__, str(a), a.position(), a.isValid(), a.isRoot(), b.isRoot(), str(b.parent()),
            [str(k) for k in kids], [str(k) for k in a.lateral_children()], str(a.direct_child()), c.children(),
            a.parent(), b.parent().position(), [k.position() for k in kids]]


@case("AxialTree.__iter__", "AxialTreeIterator", "AxialTreeIterator.next", "AxialTreeIterator.__next__",
      "AxialTreeIterator.current", "AxialTreeIterator.__length_hint__", "AxialTreeIterator.toEndBracket",
      "AxialTreeIterator.__iter__")
def axial_tree_iterator():
    l = lpy()
    s = l.AxialTree("A[B C]D E")
    out = [[str(m) for m in s], type(iter(s)).__name__]
    it = l.AxialTreeIterator(s)
    out += [str(it.next()), str(it.current()), it.__length_hint__(), str(it.next()), str(it.toEndBracket()),
            str(next(it)), iter(it) is not None]
    return out


@case("AxialTree.match", "AxialTree.reverse_match", "AxialTree.leftmatch", "AxialTree.rightmatch")
def axial_tree_matching():
    s = lpy().AxialTree("A(1)B(2)[C(3)]D(4)")
    t = lpy().AxialTree("A B C D")
    right = [[s.rightmatch(p, i) for i in range(len(s))] for p in ["A(x)", "B(x)", "C(x)", "D(x)", "B(x)D(y)",
                                                                   "[C(x)]D(y)", "B(x)[C(y)]"]]
    left = [[s.leftmatch(p, i) for i in range(len(s))] for p in ["A(x)", "B(x)", "C(x)", "A(x)B(y)"]]
    flat = [[t.rightmatch(p, i) for i in range(len(t))] + [t.leftmatch(p, i) for i in range(len(t))]
            for p in ["A", "B C", "A B"]]
    return right + left + flat + [s.match("A(x)", 0), s.match("A(x)B(y)", 0), s.match("B(y)", 0), s.match("B(y)", 1),
            s.match("A(x,y)", 0), s.match("A(1)", 0), s.match("A(2)", 0), s.reverse_match("A(x)B(y)", 1),
            s.reverse_match("B(y)", 0), s.rightmatch("D(x)", 3), s.rightmatch("C(x)", 3), s.leftmatch("B(x)", 6),
            s.leftmatch("A(x)B(x)", 6), s.leftmatch("C(x)", 6)]


@case("AxialTree.replace", "AxialTree.find")
def axial_tree_replace():
    l = lpy()
    s = l.AxialTree("A(1)B(2)A(3)C")
    return [str(s.replace("A(x)", "Z")), str(s.replace(l.PatternModule("A(x)"), ("Y", 0))),
            str(s.replace("A(x)B(y)", l.AxialTree("Q R"))), str(s.replace(l.PatternModule("C"), l.ParamModule("K", 5))),
            str(s), s.find(l.PatternModule("A(x)")), s.find(l.PatternModule("C")), s.find(l.PatternModule("A(x)"), 1)]


# --- patterns ---------------------------------------------------------------------------------


@case("PatternModule", "PatternModule.varnames", "PatternModule.getVarNb", "PatternModule.args",
      "PatternModule.argSize", "PatternModule.name", "PatternModule.__len__", "PatternModule.__getitem__")
def pattern_module():
    l = lpy()
    p = l.PatternModule("A(x,1,y)")
    q = l.PatternModule("B(a,*rest)")
    return [str(p), p.varnames(), p.getVarNb(), [str(a) for a in p.args], p.argSize(), p.name, len(p), str(p[0]),
            type(p[0]).__name__, str(q), q.varnames(), str(l.PatternModule("C")), l.PatternModule("C").varnames(),
            type(p).__name__]


@case("PatternModule")
def pattern_module_of_two():
    return str(lpy().PatternModule("A B"))


@case("PatternModule.matchingMethod", "PatternModule.eSimple", "PatternModule.eWithStar",
      "PatternModule.eWithStarNValueConstraint")
def pattern_module_matching_method():
    P = lpy().PatternModule
    return [int(P.eSimple), int(P.eWithStar), int(P.eWithStarNValueConstraint), int(P.matchingMethod)]


@case("LsysVar", "LsysVar.varname", "LsysVar.isArgs", "LsysVar.isKwds", "LsysVar.value", "LsysVar.name")
def lsys_var():
    L = lpy().LsysVar
    out = []
    for n in ["x", "*args", "**kw"]:
        v = L(n)
        out.append([str(v), repr(v), v.varname(), v.isArgs(), v.isKwds(), v.value(), v.name])
    v = L("x")
    v.name = "y"
    out.append([str(v), v.varname()])
    return out


@case("PatternString", "PatternString.varnames", "PatternString.getVarNb", "PatternString.__len__",
      "PatternString.__str__", "PatternString.__getitem__")
def pattern_string():
    l = lpy()
    p = l.PatternString("A(x) B(y,z) C")
    return [str(p), len(p), p.varnames(), p.getVarNb(), str(p[1]), type(p[1]).__name__, str(l.PatternString())]


@case("StringMatching", "StringMatching.begin", "StringMatching.end", "StringMatching.append",
      "StringMatching.addIdentity", "StringMatching.const_iterator")
def string_matching():
    sm = lpy().StringMatching()
    sm.addIdentity(2)
    sm.append(1, 3)
    sm.append(2, 1)
    sm.addIdentity(1)
    it = sm.begin()
    out = [it.values()]
    for k in range(8):
        out.append(it.nextValues())
    e = sm.end()
    out.append(e.values())
    it2 = sm.begin()
    it2.increment()
    out += [it2.original(), it2.target(), it2.next(), type(it2).__name__]
    return out


def tried(f):
    try:
        return f()
    except Exception as e:  # an error is a result too: its kind, told the same way by both
        return ["raises", {"ArgumentError": "TypeError"}.get(type(e).__name__, type(e).__name__)]


def text(v):
    return v if v is None or isinstance(v, (bool, int, float, list, str)) else str(v)


def string_members(s, patterns):
    """What a string's members give on `s` (AxialTree's members; `patterns`: its own too)."""
    out = [text(tried(f)) for f in [
        s.argSize, s.empty, s.wellBracketed, s.isAPath, s.hasRequestModule, s.roots, lambda: s.parent(2),
        lambda: s.children(0), lambda: s.lateral_children(0), lambda: s.direct_child(0), lambda: s.father(2),
        lambda: s.sons(0), lambda: s.lateralSons(0), lambda: s.directSon(0), lambda: s.endBracket(1),
        lambda: s.beginBracket(4), lambda: s.complex(2), lambda: s.components(0), lambda: s.components_at_scale(0, 1),
        lambda: s.successor_at_scale(0, 1), lambda: s.predecessor_at_scale(2, 1), lambda: s.successor_at_level(0, 1),
        lambda: s.predecessor_at_level(2, 1)]]
    if patterns:
        out += [text(tried(f)) for f in [
            lambda: s.count("A"), lambda: s.find("B"), lambda: s.str_slice(0, 3), lambda: s.node(2),
            lambda: s.match("A(x)", 0), lambda: s.reverse_match("A(x)", 0), lambda: s.leftmatch("A(x)", 2),
            lambda: s.rightmatch("E", 0), lambda: s.replace("E", "Q")]]
    s.append("F")
    s.prepend("G")
    s.insertAt(1, "H")
    out.append(str(s))
    s.clear()
    out.append([str(s), len(s)])
    return out


STRING_MEMBERS = ["argSize", "empty", "wellBracketed", "isAPath", "hasRequestModule", "roots", "parent", "children",
                  "lateral_children", "direct_child", "father", "sons", "lateralSons", "directSon", "endBracket",
                  "beginBracket", "complex", "components", "components_at_scale", "successor_at_scale",
                  "predecessor_at_scale", "successor_at_level", "predecessor_at_level", "append", "prepend",
                  "insertAt", "clear"]


PATTERN_MEMBERS = ["count", "find", "str_slice", "node", "match", "reverse_match", "leftmatch", "rightmatch", "replace"]


@case(*["Lstring." + m for m in STRING_MEMBERS + PATTERN_MEMBERS])
def lstring_members():
    return string_members(lpy().Lstring("A(1)[B(2)[C]D]E"), True)


@case(*["PatternString." + m for m in STRING_MEMBERS])
def pattern_string_members():
    return string_members(lpy().PatternString("A(x)[B(y)[C]D]E"), False)


# --- edges ------------------------------------------------------------------------------------


@case("AxialTree.__getitem__", "AxialTree.str_slice", "AxialTree.insertAt", "AxialTree.__mul__")
def axial_tree_positions():
    l = lpy()
    s = l.AxialTree("A B C D")
    out = [text(tried(f)) for f in [lambda: s[5:], lambda: s[-2:], lambda: s[1:-1], lambda: s[3:1], lambda: s[4:],
                                    lambda: s[-6:], lambda: s[::2], lambda: s.str_slice(-2, 4),
                                    lambda: s.str_slice(2, 1), lambda: l.AxialTree("")[0:0], lambda: s * 0,
                                    lambda: s * -1, lambda: s[-5]]]
    s.insertAt(-1, "E")
    out.append(str(s))
    return out


@case("Lstring", "AxialTree.__eq__")
def lstring_compared():
    l = lpy()
    s = l.Lstring("A(1)B")
    return [s == "A(1)B", s == "A(1) B", s == "A(2)B", s == l.AxialTree("A(1)B"), s == 3, s == [l.ParamModule("A", 1),
            l.ParamModule("B")], s != "A(1)B", l.Lstring("A", None) == "A", str(l.Lstring(l.AxialTree("C D")))]


@case("AxialTree.__iter__", "AxialTreeIterator.next")
def axial_tree_iterator_in_a_branch():
    l = lpy()
    s = l.AxialTree("A[B C]D")
    from_bracket, inside = s[1:], s[2:]  # kept: L-Py's iterator reads the string it was given
    it = l.AxialTreeIterator(from_bracket)  # from a '[': its branch, then what follows
    out = []
    try:
        while True:
            out.append(str(it.next()))
    except StopIteration:
        out.append("stop")
    it2 = l.AxialTreeIterator(inside)  # inside a branch: to its ']'
    out2 = [str(m) for m in it2]
    return [out, out2, [m.name for m in s if m.isBracket()]]


@case("AxialTree.roots", "AxialTree.parent", "AxialTree.children", "AxialTree.lateral_children",
      "AxialTree.direct_child", "ConsiderFilter")
def axial_tree_through_a_filter():
    """The tree's members passing over the modules a ConsiderFilter ignores."""
    l = lpy()
    s = l.AxialTree("I A[I B[C]I D]I E[F]G I")
    out = []
    for f in [l.ConsiderFilter("I", l.eIgnore), l.ConsiderFilter("A B E G"), l.ConsiderFilter.ignore("A I")]:
        row = [s.roots(f), l.AxialTree("[I A][B]C").roots(f), l.AxialTree("I [A] B").roots(f)]
        for i in range(len(s)):
            if s[i].name not in "[]":
                row.append([i, s.parent(i, f), s.children(i, f), s.lateral_children(i, f), s.direct_child(i, f),
                            s.children(i, "<", f), s.children(i, "+", f)])
        out.append(row)
    return out


# --- NodeModule.complex, from L-Py's definition: the reference crashes the process on it -----


def _lpy_complex(scales, pos, scale):
    """L-Py's LPY::complex (src/cpp/axialtree_manip.h), written out for a string without
    brackets (each module's parent is the one before it): up through the parents while their
    scale is below `scale`; the first one at `scale`, else none. A class without a scale has
    L-Py's ModuleClass::DEFAULT_SCALE, INT_MAX."""
    if pos == 0 or not scales[pos] < scale:
        return None
    pos -= 1
    while pos >= 0 and scales[pos] < scale:
        pos -= 1
    return pos if pos >= 0 and scales[pos] == scale else None


_MAX = 2 ** 31 - 1
_SCALES = [1, 2, _MAX, _MAX, 2, _MAX, 1, 2, _MAX]  # P U I I U I P U I, P at scale 1 and U at 2


def _up(scale):  # up_scale (src/cpp/module.h): scale + 1 in a C++ int, INT_MAX + 1 wrapping
    return scale + 1 if scale < _MAX else -2 ** 31


@defined("NodeModule.complex",
         expect=[[i, _lpy_complex(_SCALES, i, _up(_SCALES[i]))] + [_lpy_complex(_SCALES, i, sc) for sc in (0, 1, 2, 3)]
                 for i in range(9)],
         source="src/cpp/nodemodule.h: complex(scale) is LPY::complex(pos, scale), complex() is complex(scale() + 1)")
def node_complex():
    l = lpy()
    p, u = declared("P", []), declared("U", [])
    p.scale, u.scale = 1, 2
    s = l.AxialTree("P U I I U I P U I")

    def at(n):
        return None if n is None else n.position()

    return [[i, at(s.node(i).complex())] + [at(s.node(i).complex(sc)) for sc in (0, 1, 2, 3)] for i in range(len(s))]
