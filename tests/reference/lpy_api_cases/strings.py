"""openalea.lpy's modules (issue 51, helper h9): Module / ParamModule / NodeModule, ModuleClass
and its table, the predefined module classes, ModuleCategory, eConsiderMethod and ConsiderFilter,
PackedArgs, ArgList, as L-Py's wrappers define them (src/wrapper/export_module.cpp,
export_moduleclass.cpp, export_nodemodule.cpp, export_consider.cpp); its strings and patterns
are strings_axialtree.py's."""
from lpy_api import case, declared, lpy


# --- in a model (first: a reference L-Py that raised in a module's constructor may crash in a
# model's rules) ------------------------------------------------------------------------------


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


@case("None", "surface")
def none_and_surface_in_a_model():
    """A successor's None stays a module, printed as nothing; surface stays surface."""
    l = lpy()
    ls = l.Lsystem()
    ls.set("Axiom: A\nderivation length: 2\nproduction:\nA --> B ~l(3) surface('l', 2) None C\nB --> None\nendlsystem\n")
    s = ls.derive()
    return [str(s), len(s)]


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


@case("ModuleClass", "ModuleClass.get", "ModuleClass.issubclass", "ModuleClass.scale", "ModuleClass.category",
      "ModuleClass.DEFAULT_SCALE", "ModuleClass.bases")
def module_class_members():
    l = lpy()
    a, b = declared("Base1", []), declared("Derived1", [])
    b.bases = [a]
    return [l.ModuleClass.get("F").name, l.ModuleClass.get("+").name, l.ModuleClass.get("Left").name,
            b.issubclass(a), a.issubclass(b), [x.name for x in b.bases], l.ModuleClass.DEFAULT_SCALE == l.F.scale,
            l.F.category == l.F.scale]


@case("ModuleClassTable", "ModuleClassTable.find", "ModuleClassTable.getNames", "ModuleClassTable.getClasses", "ModuleClassTable.size",
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


# --- the members each class inherits, on an object of that class -----------------------------


def tried(f):
    try:
        return f()
    except Exception as e:  # an error is a result too: its kind, told the same way by both
        return ["raises", {"ArgumentError": "TypeError"}.get(type(e).__name__, type(e).__name__)]


def text(v):
    return v if v is None or isinstance(v, (bool, int, float, list, str)) else str(v)


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


@case(*["NodeModule." + m for m in MODULE_MEMBERS + ["append", "prepend", "match", "components",
                                                       "components_at_scale"]])
def node_module_members():
    """(Not NodeModule.complex: L-Py's crashes the process now and then on a string without scales.)"""
    s = lpy().AxialTree("A(1,2)[B]C")
    n = s.node(0)
    out = module_members(n)
    out += [text(tried(f)) for f in [n.components, lambda: n.components_at_scale(1), lambda: n.match("A", 2)]]
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


@case("ModuleClass.__call__", "ParamModule.__eq__")
def module_classes_called():
    l = lpy()
    return [str(l.F()), str(l.F(1, 2)), l.F(1) == l.ParamModule("F", 1), str(l.SB()), str(l.GetPos()), str(l.X(2)),
            text(tried(lambda: l.newmodule())), text(tried(lambda: l.newmodule(3)))]


# --- None and surface: L-Py's None module is named '' (its alias None), surface a class apart from ~


@case("None", "surface", "ModuleClass.name", "ModuleClass.aliases")
def none_and_surface():
    l = lpy()
    none, surface = getattr(l, "None"), l.surface
    read = []
    for t in ["A None B", "A surface B", "A ~l B", 'A surface("l",2) ~(2)']:
        kept = l.Lstring(t)  # kept while its modules are read (the reference's iterator holds no string)
        read.append([str(kept), [kept[i].name for i in range(len(kept))]])
    return [none.name, sorted(none.aliases), surface.name, sorted(surface.aliases), read,
            str(l.Module("None")), l.Module("None").isNull(), len(l.Lstring("None"))]


@case("ModuleClassTable.remove")
def table_remove():
    l = lpy()
    t = l.ModuleClassTable.get()
    c = t.declare("Zq")
    out = [c.name, t.remove("Zq"), t.find("Zq"), t.remove("Zq"), "Zq" in t.getNames()]
    e = t.declare("Zr")
    out += [t.remove(e), t.find("Zr"), "Zr" in t.getNames(), t.remove("NoSuchName"), text(tried(lambda: t.remove(3)))]
    again = t.declare("Zq")
    return out + [again.name, again.id != c.id, t.find("Zq") is not None]


@case("ModuleClass.getReferenceCount")
def class_reference_count():
    """The handles Python holds on a declared class that no string uses (L-Py's also counts
    C++ holders: a predefined class's own pointer, modules)."""
    t = lpy().ModuleClassTable.get()
    c = t.declare("Zt")
    one = c.getReferenceCount()
    d = t.find("Zt")
    two = [c.getReferenceCount(), d.getReferenceCount()]
    del d
    return [one, two, c.getReferenceCount()]
