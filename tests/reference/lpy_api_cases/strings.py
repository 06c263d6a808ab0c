"""openalea.lpy's strings and modules (issue 51, helper h9): AxialTree and Lstring, its iterator,
Module / ParamModule / NodeModule, ModuleClass and its table, the predefined module classes,
ModuleCategory, eConsiderMethod and ConsiderFilter, PackedArgs, the patterns (LsysVar,
PatternModule, PatternString) and StringMatching, as L-Py's wrappers define them
(src/wrapper/export_axialtree.cpp, export_lstring.h, export_module.cpp, export_moduleclass.cpp,
export_nodemodule.cpp, export_patternmodule.cpp, export_patternstring.cpp,
export_stringmatching.cpp, export_consider.cpp). AxialTree's slices are not deleted here:
L-Py's removeRange prints its indices on the process's stdout."""
from lpy_api import case


def lpy():
    import openalea.lpy as l

    return l


def declared(name, params):
    """A module class of the process with declared parameter names. L-Py's table forgets a
    class declared there once Python holds it no more: a case keeps what this gives."""
    l = lpy()
    c = l.ModuleClassTable.get().declare(name)
    c.parameterNames = params
    return c


# --- predefined module classes, ModuleClass, its table --------------------------------------


@case("F", "f", "Left", "Right", "SB", "EB", "Cut", "SetGuide", "Sweep", "Tropism", "Label", "newmodule", "new",
      "GetPos", "MouseIns", "X", "IncWidth", "SetColor", "Frame", "PglShape", "ModuleClass.name", "ModuleClass.aliases")
def predefined_classes_by_name():
    l = lpy()
    out = []
    for n in ["F", "f", "Left", "Right", "SB", "EB", "Cut", "SetGuide", "Sweep", "Tropism", "Label", "newmodule", "new",
              "GetPos", "MouseIns", "X", "IncWidth", "SetColor", "Frame", "PglShape"]:
        c = getattr(l, n)
        out.append([n, type(c).__name__, c.name, sorted(c.aliases)])
    return out


PREDEFINED_NAMES = ["SB", "EB", "Cut", "any", "F", "f", "nF", "Left", "Right", "Up", "Down", "RollL",
                    "RollR", "iRollL", "iRollR", "TurnAround", "RollToVert", "RollToHorizontal", "SetHead", "EulerAngles",
                    "Pinpoint", "PinpointRel", "MoveTo", "MoveRel", "LineTo", "LineRel", "OLineTo", "OLineRel",
                    "IncWidth", "DecWidth", "SetWidth", "IncColor", "DecColor", "SetColor", "InterpolateColors",
                    "TextureBaseColor", "InterpolateTextureBaseColors", "Sphere", "Circle", "Box", "Quad", "Label",
                    "StartGC", "EndGC", "BP", "EP", "PP", "SetContour", "SectionResolution", "SetGuide", "EndGuide",
                    "PositionOnGuide", "Sweep", "PglShape", "Frame", "Arrow", "SetScale", "MultScale", "DivScale",
                    "Elasticity", "Tropism", "LeftReflection", "UpReflection", "HeadingReflection",
                    "StartScreenProjection", "EndScreenProjection", "TextureScale", "TextureUScale", "TextureVScale",
                    "TextureVCoeff", "TextureTranslation", "TextureRotation", "TextureTransformation", "GetPos",
                    "GetHead", "GetUp", "GetLeft", "GetRight", "GetFrame", "X", "MouseIns", "x", "repexp", "all", "or",
                    "GetIterator", "new", "newmodule", "GetModule"]


@case(*PREDEFINED_NAMES)
def every_predefined_name():
    """Each name a predefined module class has in openalea.lpy, and what it names. Not here:
    `None` and `surface` (Sprout names its None module 'None', L-Py ''; Sprout's `~` and
    `surface` are one class, L-Py's two)."""
    l = lpy()
    return [[n, type(getattr(l, n)).__name__, getattr(l, n).name] for n in PREDEFINED_NAMES]


@case("ArgList", "ArgList.append", "ArgList.extend")
def arg_list():
    a = lpy().ArgList()
    a.append(1)
    a.extend([2, "x"])
    return [str(a), repr(a), len(a), a[2], list(a), str(lpy().ArgList(2, 0))]


@case("newmodule", "ModuleClass.__call__")
def newmodule_names_the_module():
    l = lpy()
    m = l.newmodule("Apex", 1, 2.5)
    return [str(m), type(m).__name__, m.name, len(m), str(l.F(1)), str(l.Left()), type(l.F(2)).__name__]


@case("ModuleClass.documentation", "ModuleClass.isPredefined", "ModuleClass.predefinedClasses")
def module_class_documentation():
    l = lpy()
    names = [c.name for c in l.ModuleClass.predefinedClasses]
    stem = declared("Stem", [])
    return [l.F.documentation, l.Left.documentation, l.SetGuide.documentation, l.newmodule.documentation,
            l.F.isPredefined(), stem.isPredefined(), stem.documentation, "F" in names, "+" in names, "Stem" in names]


@case("ModuleClass.parameterNames", "ModuleClass.hasParameter", "ModuleClass.getParameterPosition",
      "ModuleClass.getNamedParameterNb", "ModuleClassTable.declare", "ModuleClassTable.get")
def module_class_parameters():
    c = declared("Leaf", ["length", "angle"])
    return [c.parameterNames, c.hasParameter("angle"), c.hasParameter("width"), c.getParameterPosition("angle"),
            c.getParameterPosition("width"), c.getNamedParameterNb(), lpy().F.parameterNames]


@case("ModuleClass.get", "ModuleClass.issubclass", "ModuleClass.scale", "ModuleClass.category",
      "ModuleClass.DEFAULT_SCALE", "ModuleClass.bases")
def module_class_members():
    l = lpy()
    a, b = declared("Base1", []), declared("Derived1", [])
    b.bases = [a]
    return [l.ModuleClass.get("F").name, l.ModuleClass.get("+").name, l.ModuleClass.get("Left").name,
            b.issubclass(a), a.issubclass(b), [x.name for x in b.bases], l.ModuleClass.DEFAULT_SCALE == l.F.scale,
            l.F.category == l.F.scale]


@case("ModuleClassTable.find", "ModuleClassTable.getNames", "ModuleClassTable.getClasses", "ModuleClassTable.size",
      "ModuleClassTable.empty")
def module_class_table():
    t = lpy().ModuleClassTable.get()
    names = t.getNames()
    return [t.find("F").name, t.find("Left").name, "F" in names, "Left" in names, "+" in names, t.empty(),
            t.size() == len(t.getClasses()), t.size() > 80]


@case("ModuleCategory", "ModuleCategory.Structure", "ModuleCategory.Rotation", "ModuleCategory.UserDefined",
      "ModuleCategory.PatternMatching", "ModuleCategory.names", "ModuleCategory.values", "ModuleCategory.name")
def module_category_enum():
    C = lpy().ModuleCategory
    return [int(C.Structure), int(C.Rotation), int(C.UserDefined), int(C.PatternMatching), C.Structure.name,
            sorted(C.names), sorted(C.values), str(C.Request)]


@case("eConsiderMethod", "eConsider", "eIgnore", "eConsiderMethod.eConsider", "eConsiderMethod.eIgnore")
def consider_method_enum():
    l = lpy()
    return [int(l.eConsider), int(l.eIgnore), l.eConsiderMethod.eIgnore == l.eIgnore, sorted(l.eConsiderMethod.names)]


@case("ModuleType")
def module_type_is_pythons():
    import types

    return lpy().ModuleType is types.ModuleType


# --- Module, ParamModule ---------------------------------------------------------------------


@case("ParamModule", "ParamModule.argSize", "ParamModule.empty", "ParamModule.hasArg", "ParamModule.__len__",
      "ParamModule.__tuple__", "ParamModule.args", "Module.name", "Module.mclass")
def param_module_values():
    l = lpy()
    m = l.ParamModule("A", 1, 2.5, "x")
    e = l.ParamModule("B")
    t = l.ParamModule(("C", 4, 5))
    return [str(m), m.argSize(), m.empty(), m.hasArg(), len(m), m.__tuple__(), m.args, e.empty(), e.hasArg(), str(t),
            m.name, m.mclass.name, type(m).__name__, str(l.ParamModule(l.F, (3,))), str(l.ParamModule(["D", 1]))]


@case("ParamModule.__getitem__", "ParamModule.__setitem__", "ParamModule.__delitem__", "ParamModule.append",
      "ParamModule.prepend")
def param_module_editing():
    m = lpy().ParamModule("A", 1, 2, 3, 4)
    out = [m[0], m[-1], m[1:3], m[2:]]
    m[1] = 20
    del m[0]
    m.append(5)
    m.prepend(0)
    out.append(str(m))
    del m[1:3]
    out.append(str(m))
    return out


@case("ParamModule.__getitem__")
def param_module_index_error():
    return lpy().ParamModule("A", 1)[3]


@case("ParamModule.__eq__", "ParamModule.__ne__", "ParamModule.match", "Module.__eq__")
def param_module_comparisons():
    l = lpy()
    a = l.ParamModule("A", 1)
    return [a == l.ParamModule("A", 1), a == l.ParamModule("A", 2), a != l.ParamModule("A", 2), a == "A", a == "B",
            a.match("A", 1), a.match("A", 2), l.Module("A") == l.Module("A"), l.Module("A") == l.Module("B")]


@case("ParamModule.getParameter", "ParamModule.setParameter",
      "ParamModule.hasParameter", "ParamModule.getParameterPosition", "ParamModule.getNamedParameterNb",
      "ParamModule.getNamedParameters", "ParamModule.__getattr__", "ParamModule.__setattr__")
def param_module_named_parameters():
    seg = declared("Seg", ["length", "width"])
    m = lpy().ParamModule("Seg", 1.5, 0.2)
    out = [seg.name, m.getParameter("width"), m.hasParameter("length"), m.hasParameter("x"),
           m.getParameterPosition("width"), m.getNamedParameterNb(), m.length]
    m.setParameter("length", 3)
    m.width = 0.5
    m.note = "kept"
    d = {}
    m.getNamedParameters(d)
    out += [str(m), d, m.note]
    m3 = lpy().ParamModule("Seg", 9, 1, 2)  # named parameters are the last ones
    out += [m3.getParameterPosition("length"), m3.length]
    return out


@case("ParamModule.getParameter")
def param_module_unknown_parameter():
    seg = declared("Seg", ["length", "width"])
    return [seg.name, lpy().ParamModule("Seg", 1, 2).getParameter("height")]


@case("ParamModule.getParameter")
def param_module_parameter_without_value():
    seg = declared("Seg", ["length", "width"])
    return [seg.name, lpy().ParamModule("Seg", 1).getParameter("width")]


@case("ParamModule.getParameterNames")
def param_module_parameter_names():
    """L-Py binds it with a return type its Boost.Python cannot convert: a TypeError."""
    seg = declared("Seg", ["length", "width"])
    return [seg.name, lpy().ParamModule("Seg", 1, 2).getParameterNames()]


@case("ParamModule.__setattr__", "ParamModule.args", "Module.name")
def param_module_setattr_keeps_the_module():
    l = lpy()
    m = l.ParamModule("A", 1)
    m.args = [7, 8]
    m.name = "B"
    b = l.Module("C")
    b.name = "D"
    return [str(m), m.args, m.name, m.__dict__, str(b)]


@case("ParamModule.__getattr__")
def param_module_missing_attribute():
    return lpy().ParamModule("A", 1).height


@case("PackedArgs")
def packed_args_unpacked():
    l = lpy()
    return [str(l.ParamModule("A", 1, l.PackedArgs([2, 3]))), str(l.newmodule("B", l.PackedArgs([4])))]


@case("Module", "Module.isLeftBracket", "Module.isRightBracket", "Module.isBracket", "Module.isRequest",
      "ParamModule.isLeftBracket", "ParamModule.isRightBracket", "ParamModule.isBracket", "ParamModule.isRequest",
      "ParamModule.isNull", "ParamModule.isCut", "ParamModule.isinstance", "ParamModule.scale",
      "Module.isNull", "Module.isCut", "Module.isinstance", "Module.scale", "Module.__str__", "Module.__repr__")
def module_kinds():
    l = lpy()
    out = []
    for text in ["[", "]", "?P", "*", "%", "F", "A"]:
        m = l.ParamModule(text)
        out.append([text, m.isLeftBracket(), m.isRightBracket(), m.isBracket(), m.isRequest(), m.isNull(), m.isCut()])
    bare = l.Module("Bud")
    out += [str(bare), repr(bare), type(bare).__name__, bare.name, l.ParamModule("F", 1).isinstance(l.F),
            l.ParamModule("F", 1).isinstance(l.Left), l.ParamModule("F").scale() == l.ModuleClass.DEFAULT_SCALE]
    return out


@case("Module.isConsidered", "Module.isIgnored", "ConsiderFilter", "ConsiderFilter.isConsidered",
      "ConsiderFilter.isIgnored", "ConsiderFilter.ignoring", "ConsiderFilter.keyword", "ConsiderFilter.str",
      "ConsiderFilter.consider", "ConsiderFilter.ignore")
def consider_filters():
    l = lpy()
    c = l.ConsiderFilter("A B")
    i = l.ConsiderFilter.ignore("F")
    a, f, br = l.ParamModule("A", 1), l.ParamModule("F"), l.ParamModule("[")
    return [c.isConsidered("A"), c.isConsidered("C"), c.isIgnored("C"), c.isIgnored(br), c.ignoring(),
            sorted(c.str().split()),
            sorted(c.keyword().split()), i.ignoring(), i.isIgnored(f), i.isIgnored(a), i.isConsidered(l.F), i.str(),
            a.isConsidered(c), f.isConsidered(c), f.isIgnored(i), l.ConsiderFilter.consider("A").str(),
            l.ConsiderFilter("").str()]


@case("Module.isConsidered")
def module_considered_without_filter():
    return lpy().ParamModule("A").isConsidered(None)


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


# --- the members each class inherits, on an object of that class -----------------------------


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


def module_members(m):
    l = lpy()
    return [text(tried(f)) for f in [
        m.argSize, m.empty, m.hasArg, lambda: m.args, m.isBracket, m.isLeftBracket, m.isRightBracket, m.isCut,
        m.isNull, m.isRequest, lambda: m.mclass.name, lambda: m.name, lambda: m.scale() == l.ModuleClass.DEFAULT_SCALE,
        lambda: m.isinstance(l.F), lambda: m.isConsidered(l.ConsiderFilter("A")),
        lambda: m.isIgnored(l.ConsiderFilter("A")), lambda: m.getNamedParameterNb(), lambda: m.hasParameter("x"),
        lambda: m.getParameterPosition("x"), lambda: m.getParameter("x"), lambda: m.setParameter("x", 1),
        lambda: m.getParameterNames(), lambda: m.getNamedParameters({})]] + [str(m)]


MODULE_MEMBERS = ["argSize", "empty", "hasArg", "args", "isBracket", "isLeftBracket", "isRightBracket", "isCut",
                  "isNull", "isRequest", "mclass", "name", "scale", "isinstance", "isConsidered", "isIgnored",
                  "getNamedParameterNb", "hasParameter", "getParameterPosition", "getParameter", "setParameter",
                  "getParameterNames", "getNamedParameters"]


@case(*["ParamModule." + m for m in MODULE_MEMBERS])
def param_module_members():
    return module_members(lpy().ParamModule("A", 1, 2))


@case(*["NodeModule." + m for m in MODULE_MEMBERS + ["append", "prepend", "match", "complex", "components",
                                                       "components_at_scale"]])
def node_module_members():
    s = lpy().AxialTree("A(1,2)[B]C")
    n = s.node(0)
    out = module_members(n)
    out += [text(tried(f)) for f in [n.complex, n.components, lambda: n.components_at_scale(1), lambda: n.match("A", 2)]]
    n.append(3)
    n.prepend(0)
    return out + [str(n), str(s)]


@case(*["PatternModule." + m for m in MODULE_MEMBERS + ["append", "prepend"]])
def pattern_module_members():
    p = lpy().PatternModule("A(x,y)")
    out = module_members(p)
    p.append(lpy().LsysVar("z"))
    p.prepend(lpy().LsysVar("w"))
    return out + [str(p), p.varnames()]


@case("ModuleCategory.None", "ModuleCategory.Color", "ModuleCategory.Position", "ModuleCategory.Primitive",
      "ModuleCategory.Request", "ModuleCategory.Scale", "ModuleCategory.StringManipulation", "ModuleCategory.Tropism",
      "ModuleCategory.Width", "eConsiderMethod.name", "eConsiderMethod.names", "eConsiderMethod.values")
def enum_values():
    l = lpy()
    C = l.ModuleCategory
    return [[n, int(getattr(C, n)), getattr(C, n).name, str(getattr(C, n))] for n in sorted(C.names)] + [
        l.eIgnore.name, sorted(l.eConsiderMethod.names), sorted(l.eConsiderMethod.values), repr(l.eConsider)]


@case("ConsiderFilter.ignorePredefined", "ModuleClass.id", "ModuleClassTable.mandatory_declaration",
      "PatternModule.eMatchingMethod")
def other_members():
    l = lpy()
    f = l.ConsiderFilter.ignorePredefined()
    E = l.PatternModule.eMatchingMethod
    return [f.ignoring(), f.isIgnored("F"), f.isIgnored("+"), f.isIgnored("A"), f.isIgnored("["), f.isIgnored("]"),
            isinstance(l.F.id, int), l.F.id == l.ModuleClass.get("F").id, l.F.id != l.f.id,
            l.ModuleClassTable.get().mandatory_declaration, [int(E.eSimple), int(E.eWithStarNValueConstraint)],
            sorted(E.names)]


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


@case("ParamModule", "ParamModule.__getitem__", "ParamModule.__delitem__")
def param_module_made_and_sliced():
    l = lpy()
    out = [text(tried(f)) for f in [lambda: l.ParamModule("A(1,2+3)"), lambda: l.ParamModule("B(1, 'x')").args,
                                    lambda: l.ParamModule("A", 1, 2, 3, 4, 5), lambda: l.ParamModule("A", 1, 2, 3, 4, 5, 6),
                                    lambda: l.ParamModule("A", 1)[0:0], lambda: l.ParamModule("A", 1, 2)[-1:],
                                    lambda: l.ParamModule("A", 1, 2)[0:9], lambda: l.ParamModule("A")[0:1],
                                    lambda: l.ParamModule(("A",)), lambda: l.ParamModule(()), lambda: l.ParamModule([]),
                                    lambda: l.ParamModule("A", 1, 2).__tuple__(), lambda: l.ParamModule("A")[-1]]]
    m = l.ParamModule("A", 1, 2, 3)
    del m[-1]
    out.append(str(m))
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


@case("ModuleClass.__call__", "ParamModule.__eq__")
def module_classes_called():
    l = lpy()
    return [str(l.F()), str(l.F(1, 2)), l.F(1) == l.ParamModule("F", 1), str(l.SB()), str(l.GetPos()), str(l.X(2)),
            text(tried(lambda: l.newmodule())), text(tried(lambda: l.newmodule(3)))]


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


# --- in a model ------------------------------------------------------------------------------


MODEL = """
module A(x, y)
module B
Axiom: A(1, 2)[B]A(3, 4)
derivation length: 1
production:
$A(a) :
  kids = a.children() or []
  produce B(a.x, a.y, a.getParameterPosition('y'), a.hasParameter('z'), len(kids), a.isRoot(), a.position())
B --> newmodule('C', 9)
endlsystem
"""


@case("NodeModule", "NodeModule.children", "NodeModule.isRoot", "NodeModule.position", "ParamModule.__getattr__",
      "ParamModule.getParameterPosition", "ParamModule.hasParameter", "newmodule")
def modules_in_a_rule():
    l = lpy()
    ls = l.Lsystem()
    ls.set(MODEL)
    return str(ls.derive())


@case("ModuleClass.parameterNames", "ModuleClass.getNamedParameterNb", "ParamModule.getParameter")
def declared_module_parameters():
    l = lpy()
    ls = l.Lsystem()
    ls.set(MODEL)
    s = ls.axiom
    a = s[0]
    return [a.mclass.parameterNames, a.mclass.getNamedParameterNb(), a.getParameter("y"), type(s).__name__,
            str(s), type(ls.derive()).__name__]
