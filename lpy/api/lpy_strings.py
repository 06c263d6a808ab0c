# openalea.lpy's names for strings and modules, as L-Py defines them (src/wrapper/
# export_moduleclass.cpp, export_module.cpp, export_axialtree.cpp, export_consider.cpp,
# export_patternmodule.cpp, export_patternstring.cpp; src/openalea/lpy/__init__.py): the
# classes of lpy/api/types*.cpp under their names (AxialTree, Lstring, ParamModule,
# NodeModule...), the predefined module classes by name (F, Left, newmodule...), ModuleClass's
# table and documentation, the enums ModuleCategory and eConsiderMethod, ConsiderFilter. The
# patterns (LsysVar, PatternString, what AxialTree matches) are lpy_patterns.py's.

# Index of this file:
#   [SECTION] enums
#   [SECTION] predefined module classes
#   [SECTION] ModuleClassTable
#   [SECTION] ConsiderFilter

from types import ModuleType
import keyword as _keyword

from _sprout_lpy import (AxialTree, _Lstring as Lstring, Module, ParamModule, NodeModule, ModuleClass, PackedArgs,
                         AxialTreeIterator, _written, _declare, _class_count, _forget, _forget_class, _named,
                         __lpy_module_class as _module_class)

Lstring.__module__ = 'openalea.lpy'  # where pickle finds it (_sprout_lpy.Lstring is AxialTree)

__all__ = ['AxialTree', 'Lstring', 'Module', 'ParamModule', 'NodeModule', 'ModuleClass', 'PackedArgs',
           'AxialTreeIterator', 'ModuleType', 'ModuleCategory', 'eConsiderMethod', 'eConsider', 'eIgnore',
           'ConsiderFilter', 'ModuleClassTable']  # ArgList: lpy_matching.py


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
    file's functions call none of Python's)."""
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

    def size(self):  # L-Py's counts its names (aliases included), not its classes
        return len(self.getNames())

    def empty(self):
        return self.size() == 0

    def getClasses(self):
        return [_module_class(i) for i in range(_class_count()) if _named(i)]

    def getNames(self):
        names = []
        for c in self.getClasses():
            names += [c.name] + list(c.aliases)
        return names

    def find(self, name):
        if isinstance(name, int):
            return _module_class(name) if 0 <= name < _class_count() and _named(name) else None
        return ModuleClass.get(name)

    def declare(self, what):
        if isinstance(what, ModuleClass):
            return False
        return _module_class(_declare(what))

    def remove(self, what):
        """The name is found no more (a class's own name gives way to its first alias), or
        every name of a class: L-Py's ModuleClassTable::remove. False when nothing was."""
        if isinstance(what, ModuleClass):
            return _forget_class(what.id)
        if not isinstance(what, str):
            raise TypeError("ModuleClassTable.remove(name or ModuleClass), not %s" % type(what).__name__)
        return _forget(what)


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
