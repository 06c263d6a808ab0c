# openalea.lpy's names for strings and modules, as L-Py defines them (src/wrapper/
# export_moduleclass.cpp, export_module.cpp, export_axialtree.cpp, export_consider.cpp,
# export_patternmodule.cpp, export_patternstring.cpp; src/openalea/lpy/__init__.py): the
# classes of lpy/api/types*.cpp under their names (AxialTree, Lstring, ParamModule,
# NodeModule...), the predefined module classes by name (F, Left, newmodule...), ModuleClass's
# table and documentation, the enums ModuleCategory and eConsiderMethod, ConsiderFilter, and
# the patterns: LsysVar, PatternString, and what AxialTree matches with them.

# Index of this file:
#   [SECTION] enums
#   [SECTION] predefined module classes
#   [SECTION] ModuleClassTable
#   [SECTION] ConsiderFilter
#   [SECTION] patterns
#   [SECTION] AxialTree's patterns

import builtins as _builtins
from types import ModuleType
import keyword as _keyword

from _sprout_lpy import (AxialTree, _Lstring as Lstring, Module, ParamModule, NodeModule, ModuleClass, PackedArgs,
                         AxialTreeIterator, _written, _declare, _class_count, __lpy_module_class as _module_class)

__all__ = ['AxialTree', 'Lstring', 'Module', 'ParamModule', 'NodeModule', 'ModuleClass', 'PackedArgs',
           'AxialTreeIterator', 'ModuleType', 'ModuleCategory', 'eConsiderMethod', 'eConsider', 'eIgnore',
           'ConsiderFilter', 'ModuleClassTable', 'LsysVar', 'PatternString', 'ArgList']


# [SECTION] enums
class _Enum(int):
    """An enum as Boost.Python gives it: an int with a name; the class keeps `names` (name: value)
    and `values` (int: value)."""

    names, values = {}, {}

    def __new__(cls, value, name=None):
        if name is None:
            return cls.values[int(value)]
        self = int.__new__(cls, value)
        self._name = name
        return self

    @property
    def name(self):
        return self._name

    def __repr__(self):
        return 'openalea.lpy.__lpy_kernel__.%s.%s' % (type(self).__name__, self._name)

    def __str__(self):
        return self._name

    def __reduce__(self):
        return (type(self), (int(self),))


def _enum(name, items, left_out=()):
    """`left_out`: values L-Py's C++ has that its Python enum does not name."""
    cls = type(name, (_Enum,), {'__module__': 'openalea.lpy.__lpy_kernel__', 'names': {}, 'values': {}})
    for k, n in enumerate(items):
        if n in left_out:
            continue
        v = _Enum.__new__(cls, k, n)
        setattr(cls, n, v)
        cls.names[n] = v
        cls.values[k] = v
    return cls


ModuleCategory = _enum('ModuleCategory', ['None', 'Structure', 'Rotation', 'Position', 'Scale', 'Primitive', 'Width',
                                          'Color', 'Tropism', 'Request', 'Texture', 'StringManipulation',
                                          'PatternMatching', 'UserDefined'], left_out=('Texture',))
eConsiderMethod = _enum('eConsiderMethod', ['eConsider', 'eIgnore'])
eConsider, eIgnore = eConsiderMethod.eConsider, eConsiderMethod.eIgnore

# [SECTION] predefined module classes
# L-Py's predefined modules (src/cpp/predefinedmodules.cpp): their names and aliases, their
# documentation, their category, in the order of L-Py's ids.
_PREDEFINED = [
    (['', 'None'], 'None Module.', 'None'),
    (['[', 'SB'], 'Push the state in the stack.', 'Structure'),
    ([']', 'EB'], 'Pop last state from turtle stack and make it the its current state.', 'Structure'),
    (['=]'], 'Match exactly a closing bracket', 'PatternMatching'),
    (['F'], "Move forward and draw. Params: 'length , topradius'.", 'Primitive'),
    (['f'], "Move forward and without draw. Params: 'length'.", 'Primitive'),
    (['nF'], "Produce a n steps path of a given length and varying radius. Params : 'length, dlength [, radius = 1, radiusvariation = None]'.", 'Primitive'),
    (['X', 'MouseIns'], 'Module inserted just before module selected by user in visualisation.', 'StringManipulation'),
    (['%', 'Cut'], 'Cut the remainder of the current branch in the string.', 'StringManipulation'),
    (['*', 'any'], 'Used to match any module in rules predecessor. First argument will become name of the module.', 'PatternMatching'),
    (['x', 'repexp', 'all'], 'Used to specify matching of a repetition of modules.', 'PatternMatching'),
    (['or', '||'], 'Used to specify an alternative matching of modules.', 'PatternMatching'),
    (['?P', 'GetPos'], "Request position vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle).", 'Request'),
    (['?H', 'GetHead'], "Request heading vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle).", 'Request'),
    (['?U', 'GetUp'], "Request up vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle).", 'Request'),
    (['?L', 'GetLeft'], "Request left vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle).", 'Request'),
    (['?R', 'GetRight'], "Request right vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle).", 'Request'),
    (['?F', 'GetFrame'], "Request turtle frame information. Params : 'p,h,u,l' (optional, filled by Turtle).", 'Request'),
    (['@Gc', 'StartGC'], 'Start a new generalized cylinder.', 'Primitive'),
    (['@Ge', 'EndGC'], 'Pop generalized cylinder from the stack and render it.', 'Primitive'),
    (['{', 'BP'], 'Start a new polygon.', 'Primitive'),
    (['}', 'EP'], 'Pop a polygon from the stack and render it. Params : concavetest (default=False).', 'Primitive'),
    (['.', 'PP'], 'Add a point for polygon.', 'Primitive'),
    (['@M', 'MoveTo'], "Set the turtle position. Params : 'x, y, z' or 'v' (optionals, default = None for not changing specific coordinates).", 'Position'),
    (['MoveRel'], "Move relatively from current the turtle position. Params : 'x, y, z' or 'v'(optionals, default = 0).", 'Position'),
    (['LineTo'], "Trace line to (x,y,z) without changing the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0).", 'Primitive'),
    (['OLineTo'], "Trace line toward (x,y,z) and change the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0).", 'Primitive'),
    (['Pinpoint'], "Orient turtle toward (x,y,z) . Params : 'x, y, z' or 'v' (optionals, default = 0).", 'Rotation'),
    (['LineRel'], "Trace line to pos+(x,y,z) without changing the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter'(optionals, default = 0).", 'Primitive'),
    (['OLineRel'], "Trace line toward pos+(x,y,z) and change the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0).", 'Primitive'),
    (['PinpointRel'], "Orient turtle toward pos+(x,y,z) . Params : 'x, y, z' or 'v' (optionals, default = 0).", 'Rotation'),
    (['@R', 'SetHead'], "Set the turtle Heading and Up vector. Params: 'hx, hy, hz, ux, uy, uz' or 'h,v' (optionals, default=0,0,1, 1,0,0).", 'Rotation'),
    (['EulerAngles'], "Set the orientation of the turtle from the absolute euler angles. Params: 'azimuth, elevation, roll' (optionals, default=180,90,0).", 'Rotation'),
    (['+', 'Left'], "Turn left  around Up vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['-', 'Right'], "Turn right around Up vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['^', 'Up'], "Pitch up around Left vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['&', 'Down'], "Pitch down around Left vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['/', 'RollL'], "Roll left  around Heading vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['\\', 'RollR'], "Roll right  around Heading vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['iRollL'], "Roll left intrinsically around Heading vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['iRollR'], "Roll right intrinsically around Heading vector. Params : 'angle' (optional, in degrees).", 'Rotation'),
    (['|', 'TurnAround'], 'Turn around 180deg the Up vector.', 'Rotation'),
    (['@v', 'RollToVert'], 'Roll to Vertical : Roll the turtle around the H axis so that H and U lie in a common vertical plane with U closest to up', 'Rotation'),
    (['@h', 'RollToHorizontal'], 'Roll to Horizontal : Roll the turtle so that H lie in the horizontal plane', 'Rotation'),
    (['@O', 'Sphere'], "Draw a sphere. Params : 'radius' (optional, should be positive, default = line width).", 'Primitive'),
    (['@B', 'Box'], "Draw a box. Params : 'length','topradius'.", 'Primitive'),
    (['@b', 'Quad'], "Draw a quad. Params : 'length','topradius'.", 'Primitive'),
    (['@o', 'Circle'], "Draw a circle. Params : 'radius' (optional, should be positive, default = line width).", 'Primitive'),
    (['@L', 'Label'], "Draw a text label. Params : 'text','size'.", 'Primitive'),
    (['_', 'IncWidth'], "Increase the current line width or set it if a parameter is given. Params : 'width' (optional).", 'Width'),
    (['!', 'DecWidth'], "Decrease the current line width or set it if a parameter is given. Params : 'width' (optional).", 'Width'),
    (['SetWidth'], "Set current line width. Params : 'width'.", 'Width'),
    ([';', 'IncColor'], "Increase the current material index or set it if a parameter is given. Params : 'index' (optional, positive int).", 'Color'),
    ([',', 'DecColor'], "Decrease the current material index or set it if a parameter is given. Params : 'index' (optional, positive int).", 'Color'),
    (['SetColor'], "Set the current material. Params : 'index' (positive int) or 'r,g,b[,a]' or 'material'.", 'Color'),
    (['InterpolateColors'], "Set the current material. Params : 'index1', 'index2', 'alpha' .", 'Color'),
    (['TextureBaseColor'], "Set the base color of the texture. Params : 'index' (positive int) or 'r,g,b[,a]' or 'material'.", 'Texture'),
    (['InterpolateTextureBaseColors'], "Set the base color of the texture from interpolation of 2 predefined material. Params : 'index1', 'index2', 'alpha' .", 'Texture'),
    (['@Dd', 'DivScale'], "Divides the current turtle scale by a scale factor, Params : 'scale_factor' (optional, default = 1.0).", 'Scale'),
    (['@Di', 'MultScale'], "Multiplies the current turtle scale by a scale factor, Params : 'scale_factor' (optional, default = 1.0).", 'Scale'),
    (['@D', 'SetScale'], "Set the current turtle scale, Params : 'scale' (optional, default = 1.0).", 'Scale'),
    (['surface'], "Draw the predefined surface at the turtle's current location and orientation. Params : 'surface_name' (by default, 'l' exists), 'scale_factor' (optional, default= 1.0, should be positive).", 'Primitive'),
    (['~'], "Draw the predefined surface at the turtle's current location and orientation. Params : 'surface_name' (by default, 'l' exists), 'scale_factor' (optional, default= 1.0, should be positive).", 'Primitive'),
    (['@g', 'PglShape'], "Draw a geometry at the turtle's current location and orientation. Params : 'geometric_model', 'scale_factor' (optional, should be positive) or 'shape' or 'scene' or 'material'.", 'Primitive'),
    (['Frame'], "Draw the current turtle frame as 3 arrows (red=heading,blue=up,green=left). Params : 'size' (should be positive), 'cap_heigth_ratio' (in [0,1]), 'cap_radius_ratio' (should be positive).", 'Primitive'),
    (['Arrow'], "Draw an arrow. Params : 'size' (should be positive), 'cap_heigth_ratio' (in [0,1]), 'cap_radius_ratio' (should be positive).", 'Primitive'),
    (['@Ts', 'Elasticity'], "Set Branch Elasticity. Params : 'elasticity' (optional, default= 0.0, should be between [0,1]).", 'Tropism'),
    (['@Tp', 'Tropism'], "Set Tropism. Params : 'tropism' (optional, Vector3, default= (1,0,0)).", 'Tropism'),
    (['SetContour'], "Set Cross Section of Generalized Cylinder. Params : 'Curve2D [, ccw]'.", 'Primitive'),
    (['SectionResolution'], "Set Resolution of Section of Cylinder. Params : 'resolution' (int).", 'Primitive'),
    (['SetGuide'], "Set Guide for turtle tracing. Params : 'Curve[2D|3D], length [,yorientation, ccw]'.", 'Primitive'),
    (['EndGuide'], 'End Guide for turtle tracing.', 'Primitive'),
    (['Sweep'], "Produce a sweep surface. Params : 'path, section, length, dlength [, radius = 1, radiusvariation = None]'.", 'Primitive'),
    (['PositionOnGuide'], 'Set position on Guide for turtle tracing.', 'Primitive'),
    (['TextureScale'], "Set the scale coefficient for texture application. Params : 'uscale, vscale' (default = 1,1) or 'scale'.", 'Texture'),
    (['TextureUScale'], "Set the u-scale coefficient for texture application. Params : 'uscale' (default = 1).", 'Texture'),
    (['TextureVScale', 'TextureVCoeff'], "Set the v-scale coefficient for texture application. Params : 'vscale' (default = 1).", 'Texture'),
    (['TextureTranslation'], "Set the translation for texture application. Params : 'utranslation, vtranslation' (default = 0,0) or 'translation'.", 'Texture'),
    (['TextureRotation'], "Set the rotation for texture application. Params : 'angle, urotcenter, vrotcenter' (default = 0,0.5,0.5) or 'angle, rotcenter'.", 'Texture'),
    (['TextureTransformation'], "Set the transformation for texture application. Params : 'uscale, vscale, utranslation, vtranslation, angle, urotcenter, vrotcenter' (default = 1,1,0,0,0,0.5,0.5) or 'scale, translation, angle, rotcenter'.", 'Texture'),
    (['LeftReflection'], 'The turtle change the left vector to have a symmetric behavior.', 'Rotation'),
    (['UpReflection'], 'The turtle change the up vector to have a symmetric behavior.', 'Rotation'),
    (['HeadingReflection'], 'The turtle change the heading vector to have a symmetric behavior.', 'Rotation'),
    (['@2D', 'StartScreenProjection'], 'The turtle will create geometry in the screen coordinates system.', 'Position'),
    (['@3D', 'EndScreenProjection'], 'The turtle will create geometry in the world system (default behaviour).', 'Position'),
    (['?I', 'GetIterator'], 'Request an iterator over the current Lstring.', 'PatternMatching'),
    (['$', 'GetModule'], 'Request a module of the current Lstring.', 'PatternMatching'),
    (['new', 'newmodule'], 'Create a new module whose name is given by first argument.', 'StringManipulation'),
]

_DOCUMENTATION = {}
for _names, _doc, _cat in _PREDEFINED:
    for _n in _names:
        _DOCUMENTATION[_n] = _doc


def _documentation(mclass):
    return _DOCUMENTATION.get(mclass.name, '') if mclass.isPredefined() else ''


def _predefined():
    out = []
    for names, doc, cat in _PREDEFINED:
        for n in names:
            c = ModuleClass.get(n)
            if c is not None and c.isPredefined():
                out.append(c)
                break
    return out


class _ClassProperty:
    def __init__(self, get):
        self._get = get

    def __get__(self, obj, cls=None):
        return self._get()


ModuleClass.documentation = property(_documentation)
ModuleClass.predefinedClasses = _ClassProperty(_predefined)


def _export_predefined(scope):
    """Each predefined module class under each of its names that reads as a variable's (L-Py's
    export_moduleclass.cpp), `newmodule` among them; `any` and `all` too, as in L-Py (this
    file's functions call Python's through _builtins)."""
    for names, doc, cat in _PREDEFINED:
        c = None
        for n in names:
            c = c or ModuleClass.get(n)
        if c is None:
            continue
        for n in names:
            if n.isidentifier() or _keyword.iskeyword(n):
                scope[n] = c
                __all__.append(n)


_export_predefined(globals())


class ArgList(list):
    """The values a pattern bound (L-Py's ArgList, a vector of Python objects): ArgList(size, obj)."""

    def __init__(self, size=0, obj=None):
        list.__init__(self, [obj] * size)


# [SECTION] ModuleClassTable
class ModuleClassTable:
    """L-Py's table of module classes: every class the process knows, with its aliases."""

    _table = None

    @staticmethod
    def get():
        if ModuleClassTable._table is None:
            ModuleClassTable._table = ModuleClassTable()
        return ModuleClassTable._table

    mandatory_declaration = False

    def size(self):
        return len(self.getClasses())

    def empty(self):
        return self.size() == 0

    def getClasses(self):
        return [_module_class(i) for i in range(_class_count())]

    def getNames(self):
        names = []
        for c in self.getClasses():
            names += [c.name] + list(c.aliases)
        return names

    def find(self, name):
        if isinstance(name, int):
            return _module_class(name) if 0 <= name < _class_count() else None
        return ModuleClass.get(name)

    def declare(self, what):
        if isinstance(what, ModuleClass):
            return False
        return _module_class(_declare(what))


# [SECTION] ConsiderFilter
def _class_of(what):
    if isinstance(what, ModuleClass):
        return what
    if isinstance(what, Module):
        return what.mclass
    return _module_class(_declare(str(what)))


class ConsiderFilter:
    """Filter on the module to consider in the context of the rules (L-Py's ConsiderFilter):
    the classes named in `modules`, considered or ignored."""

    def __init__(self, modules, method=eConsider):
        self._method = eConsiderMethod(int(method), None) if not isinstance(method, eConsiderMethod) else method
        self._keyword = {}
        if isinstance(modules, (list, tuple)):
            for c in modules:
                self._keyword[c.id] = c
        elif modules:
            for m in AxialTree(modules):
                self._keyword[m.mclass.id] = m.mclass

    def isIgnored(self, module):
        if not self._keyword:
            return False
        c = _class_of(module)
        if self._method == eIgnore:
            return c.id in self._keyword
        return c.id not in self._keyword and c.name not in ('[', ']', '=]')

    def isConsidered(self, module):
        return not self.isIgnored(module)

    def ignoring(self):
        return self._method == eIgnore

    def keyword(self):
        return ' '.join(self._keyword[k].name for k in sorted(self._keyword))

    def str(self):
        if not self._keyword:
            return ''
        return ('consider: ' if self._method == eConsider else 'ignore: ') + self.keyword()

    @staticmethod
    def consider(modules):
        return ConsiderFilter(modules, eConsider)

    @staticmethod
    def ignore(modules):
        return ConsiderFilter(modules, eIgnore)

    @staticmethod
    def ignorePredefined():
        return ConsiderFilter([c for c in _predefined() if c.name not in ('', 'None', '[', ']')], eIgnore)


# [SECTION] patterns
def _namespace():
    import openalea.lpy as lpy
    ns = lpy._state.get('ns')
    return ns if ns is not None else {}


def _parse_variable(text):
    """A pattern's parameter read as a variable ('x', '*args', '**kw', '-', 'x if x > 1'), or None."""
    import re
    m = re.match(r'^\s*(\*{0,2}[A-Za-z_]\w*|-)\s*(?:if\s+(.+?))?\s*$', text)
    return (m.group(1), m.group(2) or '') if m else None


class LsysVar:
    """A variable of a pattern (L-Py's LsysVar): its name ('x', '*args', '**kw', '-' unnamed),
    or a value the module's parameter must equal, or a condition it must meet."""

    def __init__(self, name):
        self.name, self._value, self._condition, self._text = str(name), None, None, ''

    @property
    def name(self):
        return self._name

    @name.setter
    def name(self, value):
        self._name = str(value)

    @classmethod
    def _of_value(cls, value):
        v = cls('')
        v._value, v._condition = value, 'value'
        return v

    def _set_condition(self, text):
        self._text = text
        self._value = eval('lambda %s : %s' % (self.varname(), text), _namespace())
        self._condition = 'function'

    def __str__(self):
        if self._condition == 'function':
            return self.name + ' if ' + self._text
        if self._condition == 'value':
            return str(self._value)
        return self.name

    __repr__ = __str__

    def varname(self):
        n = self.name
        return n[2:] if n.startswith('**') else n[1:] if n.startswith('*') else n

    def isArgs(self):
        return self.name.startswith('*') and not self.name.startswith('**')

    def isKwds(self):
        return self.name.startswith('**')

    def value(self):
        return self._value

    def _named(self):
        return bool(self.name) and self.name[0] != '-' and self.name not in ('*-', '**-')

    def _accepts(self, v):
        if self._condition == 'value':
            return v == self._value
        if self._condition == 'function':
            return bool(self._value(v))
        return True


def _pattern_args(argtexts):
    out = []
    for k, text in enumerate(argtexts):
        var = _parse_variable(text)
        if var is None:
            out.append(LsysVar._of_value(eval(text, _namespace())))
            continue
        v = LsysVar(var[0])
        if var[1]:
            v._set_condition(var[1])
        if (v.isKwds() and k != len(argtexts) - 1) or (v.isArgs() and k < len(argtexts) - 2):
            raise ValueError("Invalid syntax : invalid variable name '%s'" % text)
        out.append(v)
    return out


def _match_module(pattern, module, bound):
    """MatchingEngine::module_match as L-Py's default method (eWithStarNValueConstraint) reads
    it: the same class (`*` any), as many parameters (more with *args), values and conditions
    met; the variables' values appended to `bound`."""
    pvars = list(pattern.args)
    values = list(module.args)
    if pattern.name == '*':
        if not pvars:
            return True
        values = [module.name] + values
    elif pattern.mclass != module.mclass:
        return False
    kw = pvars.pop() if pvars and pvars[-1].isKwds() else None
    star = pvars.pop() if pvars and pvars[-1].isArgs() else None
    if len(values) < len(pvars) or (star is None and len(values) != len(pvars)):
        return False
    for var, v in zip(pvars, values):
        if not var._accepts(v):
            return False
        if var._named():
            bound.append(v)
    if star is not None and star._named():
        bound.append(values[len(pvars):])
    if kw is not None and kw._named():
        bound.append({})
    return True


class PatternString(AxialTree):
    """A string of patterns (L-Py's PatternString): modules whose parameters are variables."""

    def __init__(self, text='', lineno=-1):
        AxialTree.__init__(self)
        if isinstance(text, PatternString):
            AxialTree.append(self, text)
        elif isinstance(text, Module):
            AxialTree.append(self, text)
        elif text:
            for name, args in _written(str(text)):
                AxialTree.append(self, _lpy().PatternModule(name + ('(%s)' % ','.join(args) if args else '')))

    def __getitem__(self, i):
        m = AxialTree.__getitem__(self, i)
        return m if isinstance(i, slice) else _lpy().PatternModule(m)

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    def __repr__(self):
        return 'PatternString(%s)' % str(self)

    def varnames(self):
        out = []
        for m in self:
            out += m.varnames()
        return out

    def getVarNb(self):
        return sum(m.getVarNb() for m in self)


def _lpy():
    import openalea.lpy
    return openalea.lpy


# [SECTION] AxialTree's patterns
def _pattern_string(p):
    if isinstance(p, PatternString):
        return list(p)
    if isinstance(p, _lpy().PatternModule):
        return [p]
    return list(PatternString(p))


def _exact(s, patterns, at):
    """string_exact_match: the patterns, one module each, from position `at` on; the end, or -1."""
    if at < 0 or at + len(patterns) > len(s):
        return -1
    for k, p in enumerate(patterns):
        if not _match_module(p, s[at + k], []):
            return -1
    return at + len(patterns)


def _position(s, pos):
    n = len(s)
    if pos < 0:
        pos += n
    if pos < 0 or pos > n:
        raise IndexError('index out of range')
    return pos


def _tree_match(self, pattern, pos):
    return _exact(self, _pattern_string(pattern), _position(self, pos)) >= 0


def _tree_reverse_match(self, pattern, pos):
    pos = _position(self, pos)
    if pos >= len(self):
        return False
    ps = _pattern_string(pattern)
    return _exact(self, ps, pos - len(ps) + 1) >= 0


def _tree_rightmatch(self, pattern, pos):
    """A right context: the modules after `pos`, branches the pattern does not open passed
    over, a ']' of the string the end of what follows (a ']' of the pattern: the rest of the
    branch passed over)."""
    ps = _pattern_string(pattern)
    j = _position(self, pos) + 1
    for p in ps:
        if p.name == '[':
            if j >= len(self) or self[j].name != '[':
                return False
            j += 1
            continue
        if p.name == ']':
            e = self.endBracket(j, True) if j < len(self) else None
            if e is None:
                return False
            j = e + 1
            continue
        while j < len(self) and self[j].name == '[':
            e = self.endBracket(j)
            if e is None:
                return False
            j = e + 1
        if j >= len(self) or self[j].name == ']' or not _match_module(p, self[j], []):
            return False
        j += 1
    return True


def _tree_leftmatch(self, pattern, pos):
    """A left context: the modules before `pos` towards the root, branches passed over."""
    ps = _pattern_string(pattern)
    j = _position(self, pos) - 1
    for p in reversed(ps):
        while j >= 0 and self[j].name in '[]':
            if self[j].name == ']':
                b = self.beginBracket(j)
                if b is None:
                    return False
                j = b
            j -= 1
        if j < 0 or not _match_module(p, self[j], []):
            return False
        j -= 1
    return True


def _tree_find(self, pattern, start=0, end=2147483647):
    if isinstance(pattern, _lpy().PatternModule):
        a, b = _position(self, start), len(self) if end == 2147483647 else _position(self, end)
        for i in range(a, b):
            if self[i].name == pattern.name and len(self[i]) == len(pattern):
                return i
        return None
    return _find_name(self, pattern, start, end)


def _replacement(b):
    if isinstance(b, tuple):
        return AxialTree([ParamModule(b)])
    if isinstance(b, Module):
        return AxialTree([b])
    return AxialTree(b)


def _tree_replace(self, a, b):
    by = _replacement(b)
    out = AxialTree()
    if isinstance(a, _lpy().PatternModule):
        for m in self:
            out += by if _match_module(a, m, []) else AxialTree([m])
        return out
    ps, i = _pattern_string(a), 0
    while i < len(self):
        e = _exact(self, ps, i) if ps else -1
        if e > i:
            out += by
            i = e
        else:
            out.append(self[i])
            i += 1
    return out


_find_name = AxialTree.find
AxialTree.match = _tree_match
AxialTree.reverse_match = _tree_reverse_match
AxialTree.leftmatch = _tree_leftmatch
AxialTree.rightmatch = _tree_rightmatch
AxialTree.find = _tree_find
AxialTree.replace = _tree_replace
