# openalea.lpy's names that need no L-system context, as L-Py defines them: its version
# (src/openalea/lpy/__version__.py), its options (src/cpp/lsysoptions.h, LsysContext::init_options
# in src/cpp/lsyscontext.cpp, src/wrapper/export_lsysoptions.cpp), `extern` and
# `defaultparameters` (src/openalea/lpy/defaultparameters.py), and the few helpers its
# __init__.py leaves in the package (`deprecated`, `determine_lpymodule_path`, `ModuleType`).
# Installed as openalea.lpy._base before openalea.lpy (lpy/interpreter/interpreter.cpp), which
# imports all of it; openalea.lpy.__version__ and openalea.lpy.defaultparameters are views of it.

# Index of this file:
#   [SECTION] version
#   [SECTION] options
#   [SECTION] extern and defaultparameters
#   [SECTION] helpers of __init__.py
#   [SECTION] the turtle's help

import sys as _sys
import types as _types
from types import ModuleType

__all__ = ['get_major', 'get_minor', 'get_revision', 'get_version_majorminor', 'version_string', 'LPY_VERSION_MAJOR',
           'LPY_VERSION_MINOR', 'LPY_VERSION_REV', 'LPY_VERSION_STR', 'LsysOptionValue', 'LsysOption', 'LsysOptions',
           'extern', 'defaultparameters', 'deprecated', 'determine_lpymodule_path', 'ModuleType', 'helpTurtle']


# [SECTION] version
# The L-Py this openalea.lpy follows: 3.15.1 (its functions read __version_number__, whatever
# they are given, as L-Py's do).
__version_number__ = 0x030F01
__revision_str__ = ""


def get_major(version):
    return (__version_number__ & 0xff0000) >> 16


def get_minor(version):
    return (__version_number__ & 0x00ff00) >> 8


def get_revision(version):
    return __version_number__ & 0x0000ff


def get_version_majorminor(version):
    return float(str(get_major(version)) + '.' + str(get_minor(version)))


def version_string(version, gitrev=''):
    num_version_str = str(get_major(version)) + '.' + str(get_minor(version)) + '.' + str(get_revision(version))
    if len(gitrev) > 0:
        gitrev = gitrev.split(':')[1][1:-1]
        num_version_str = num_version_str + '-r' + gitrev
    return num_version_str


LPY_VERSION_MAJOR = get_major(__version_number__)
LPY_VERSION_MINOR = get_minor(__version_number__)
LPY_VERSION_REV = get_revision(__version_number__)
LPY_VERSION_STR = version_string(__version_number__, __revision_str__)


# [SECTION] options
# The arguments L-Py's C++ takes, checked as Boost.Python converts them: a string, a flag (what
# has a truth value of its own: a number, None, a bool; not a string or a list), a count (an
# int, not a float; negative, an OverflowError).
def _text(value, what):
    if not isinstance(value, str):
        raise TypeError("%s: a string, not %s" % (what, type(value).__name__))
    return value


def _flag(value, what):
    if not hasattr(type(value), '__bool__'):
        raise TypeError("%s: True or False, not %s" % (what, type(value).__name__))
    return bool(value)


def _count(value, what):
    if not isinstance(value, int):
        raise TypeError("%s: an integer, not %s" % (what, type(value).__name__))
    if value < 0:
        raise OverflowError("can't convert negative value to unsigned int")
    return int(value)


_cython = []


def _cython_available():
    """Looked for once, as L-Py does at its import (a search of sys.path at each context was a
    third of a small model's Lsystem())."""
    if not _cython:
        import importlib.util
        try:
            _cython.append(importlib.util.find_spec('pyximport') is not None)
        except (ImportError, ValueError):
            _cython.append(False)
    return _cython[0]


# L-Py's options of a context, in its order: (name, comment, category, global, default,
# [(value, comment)]). The Compiler has Cython only where pyximport is installed, as in L-Py;
# 'Multicore parallel rewriting' is L-Py's only where it is built with MULTICORE_ENABLED (not by
# default), so not here.
def _option_table():
    dis, en = 'Disabled', 'Enabled'
    return [
        ('Module declaration', 'Specify if module declaration is mandatory.', 'Compilation', True, 0,
         [('On the fly', 'Module declaration is made on the fly when parsing string.'),
          ('Mandatory', 'Module declaration is mandatory before use in string.')]),
        ('Warning with sharp module', 'Set whether a warning is made when sharp symbol is met when parsing (compatibility with cpfg).',
         'Compilation', False, 1, [(dis, 'Disable Warning.'), (en, 'Enable Warning.')]),
        ('Compiler', 'Specify the compiler to use', 'Compilation', True, 0,
         [('Python', 'Use python compiler.'), ('Python -OO', 'Use python compiler.')]
         + ([('Cython', 'Use Cython compiler.')] if _cython_available() else [])),
        ('Optimization', 'Specify the level of optimization to use', 'Compilation', False, 1,
         [('Level %d' % i, 'Use Level %d.' % i) for i in range(3)]),
        ('Module matching', 'Specify the way modules are matched to rules pattern', 'Matching', True, 2,
         [('Simple', "Simple module matching : Same name and same number of arguments . '*' module allowed."),
          ('Extension : *args', 'Add matching rule that * module can match any module and allow *args to match a number of module arguments'),
          ('Extensions : *args and arg value constraints', 'With * module and *args. A module argument can also be set to a given value adding thus a new matching constraint.')]),
        ('Module inheritance', 'Specify if modules inheritance is taken into account in rules pattern matching', 'Matching', True, 0,
         [(dis, 'Modules with different names are considered as different even if they inherit from each other.'),
          (en, 'A module inheriting from a second one can be used for application of the first one if number of parameters are also compatible.')]),
        ('String matching', 'Specify the way strings are matched to rules pattern', 'Matching', True, 1,
         [('As String', 'String is considered as a simple string.'),
          ('As AxialTree', 'String is considered as an axial tree and some modules can be skipped according to tree connectivity.'),
          ('As Multi-level AxialTree', 'String is considered as a multi level axial tree and some modules can be skipped according to module level. Level are not ordered.'),
          ('As Multiscale AxialTree', 'String is considered as a multi scale axial tree and some modules can be skipped according to module scale.')]),
        ('Early return when no matching', 'Set whether the L-systems end prematurely if no matching has occured in the last iteration.',
         'Processing', False, 0, [(dis, 'Disable early return.'), (en, 'Enable early return.')]),
        ('Axiom decomposition', 'Set whether the axiom is immediatly decomposed.', 'Processing', False, 0,
         [(dis, 'Disable early return.'), (en, 'Enable early return.')]),
        ('Warning with Turtle inconsistency', 'Set whether a warning/error is raised when an invalid value is found during turtle processing.',
         'Processing', False, 1, [(dis, 'Disable warnings/errors.'), (en, 'Enable warnings/errors.')]),
        ('Turtle Path Optimization', 'Set whether the Turtle use a cache with the path.', 'Processing', False, 1,
         [(dis, 'Disable Cache.'), (en, 'Enable Cache.')]),
        ('Turtle in Interpretation rules', 'Set whether the Turtle is given in the interpretation rules.', 'Processing', False, 1,
         [(dis, 'Disable.'), (en, 'Enable.')]),
        ('Bracket mapping optimization', 'Specify the level of optimization of mapping brackets for lstring traversal.', 'Processing', False, 0,
         [(dis, 'Disable brackets mapping optimization.'), ('On the fly', 'Enable brackets mapping on the fly.'),
          ('As preprocessing', 'Compute brackets mapping as preprocessing of each step.')]),
        ('Selection Always Required', 'Set whether selection check in GUI is required or not. Selection is then transform in X module in the Lstring.',
         'Interaction', False, 0, [(dis, 'Disable Selection Check.'), (en, 'Enable Selection Check.')]),
    ]


class LsysOptionValue:
    """One value of an option (L-Py's LsysOptionValue): its name and comment."""

    name = comment = ''

    def __init__(self, name, comment=''):
        self.name, self.comment = name, comment

    def activate(self):
        """L-Py's calls the setting's function with this value and leaves the option's selection
        as it is; Sprout's engine reads its settings from the selections, so nothing changes."""


class LsysOption:
    """An option (L-Py's LsysOption): its values by index, the one selected (`selection`), its
    default. An option of a context keeps its selection in the context, where Sprout's engine
    reads it."""

    name = comment = category = ''
    default_value_id = 0

    def __init__(self, name, comment='', category=''):
        self.name, self.comment, self.category = _text(name, 'LsysOption(name)'), _text(comment, 'LsysOption(comment)'), \
            _text(category, 'LsysOption(category)')
        self.default_value_id = 0
        setattr(self, 'global', False)
        self._values, self._store = [], {}

    def _select(self, index):
        self._store[self.name] = index
        on_change = self.__dict__.get('_changed')
        if on_change is not None:
            on_change(self.name, index)

    @property
    def selection(self):
        return self._store.get(self.name, self.default_value_id)

    @selection.setter
    def selection(self, index):
        if not self.setSelection(int(index)):
            raise ValueError("Invalid Option Value")

    def setSelection(self, value):
        if isinstance(value, str):
            names = [v.name for v in self._values]
            if value not in names:
                return False
            value = names.index(value)
        elif isinstance(value, bool) or not isinstance(value, int):
            raise TypeError("LsysOption.setSelection(value): a value's name or its index")
        if not 0 <= value < len(self._values):
            if value < 0:
                raise OverflowError("can't convert negative value to unsigned int")
            return False
        self._select(value)
        return True

    def activate(self, value):
        return self.setSelection(str(value))

    def activateSelection(self):
        return True

    def currentValue(self):
        if not 0 <= self.selection < len(self._values):
            raise IndexError("LsysOption.currentValue(): the option has no value %d" % self.selection)
        return self._values[self.selection].name

    def isToDefault(self):
        return self.selection == self.default_value_id

    def __len__(self):
        return len(self._values)

    def __getitem__(self, index):
        if not isinstance(index, int):
            raise TypeError("LsysOption[index]: an integer, not %s" % type(index).__name__)
        if index < 0:
            index += len(self._values)
        if not 0 <= index < len(self._values):
            raise IndexError("Out of range index.")
        return self._values[index]


setattr(LsysOption, 'global', False)  # a keyword of Python's: read with getattr(option, 'global')


class LsysOptions:
    """A context's options (L-Py's LsysOptions), by index (options[i]) or by name (find)."""

    def __init__(self, store=None, changed=None):
        # A context's options are built when first asked for: most models never ask, and
        # building L-Py's table cost a small model's Lsystem() a fifth of its time.
        self._store, self._changed = store, changed

    @property
    def _all(self):
        built = self.__dict__.get('_built')
        if built is None:
            built = self._built = []
            if self._store is not None:
                for name, comment, category, is_global, default, values in _option_table():
                    option = LsysOption(name, comment, category)
                    option._values = [LsysOptionValue(v, c) for v, c in values]
                    option.default_value_id, option._store = default, self._store
                    setattr(option, 'global', is_global)
                    option._changed = self._changed
                    built.append(option)
        return built

    def find(self, name):
        _text(name, 'LsysOptions.find(name)')
        for option in self._all:
            if option.name == name:
                return option
        return None

    def setSelection(self, name, value):
        if isinstance(value, float) or not isinstance(value, (str, int)):
            raise TypeError("LsysOptions.setSelection(name, value): a value's name or its index")
        option = self.find(name)
        return False if option is None else option.setSelection(value)

    def activate(self, name, value):
        option = self.find(name)
        return False if option is None else option.activate(value)

    def activateSelection(self, name):
        return self.find(name) is not None

    def __getitem__(self, index):
        if not isinstance(index, int):
            raise TypeError("LsysOptions[index]: an integer, not %s (find(name) gives an option by its name)" % type(index).__name__)
        if index < 0:
            index += len(self._all)
        if not 0 <= index < len(self._all):
            raise IndexError("Out of range index.")
        return self._all[index]

    def __len__(self):
        return len(self._all)


# [SECTION] extern and defaultparameters
def get_caller_frame():
    import inspect
    return inspect.getouterframes(inspect.currentframe())[2][0]


class LocalsRetriever:
    """Calls a function and keeps its local variables (L-Py's defaultparameters.LocalsRetriever)."""

    def __init__(self, func):
        self.mylocals, self.depth, self.func = {}, 0, func

    def _mytracer(self, frame, event, arg):
        if event == 'call':
            self.depth += 1
            if self.depth == 1:
                return self._mytracer
        elif event == 'return':
            self.depth -= 1
            self.mylocals.update(frame.f_locals)

    def __call__(self, *args, **kwds):
        old = _sys.gettrace()
        _sys.settrace(self._mytracer)
        try:
            res = self.func(*args, **kwds)
        finally:
            _sys.settrace(old)
        return self.mylocals, res


def defaultparameters(function):
    """L-Py's @defaultparameters: the function's local variables become the caller's names where
    they are not set yet (at once for a function without parameters, else at each call)."""
    import inspect
    if len(inspect.signature(function).parameters) == 0:
        params, _ = LocalsRetriever(function)()
        caller = _sys._getframe(1).f_locals
        for k, v in params.items():
            caller.setdefault(k, v)
        return function

    def wrapper(*args, **kwargs):
        params, res = LocalsRetriever(function)(*args, **kwargs)
        caller = _sys._getframe(1).f_locals
        for k, v in params.items():
            caller.setdefault(k, v)
        return res
    return wrapper


def extern(*paramstocheck, **params):
    """L-Py's extern: extern(a=1) gives a the value 1 unless the caller has it (Lsystem(file,
    {'a': 2})); extern('b') requires b. Both are listed in the caller's __externs__."""
    caller = _sys._getframe(1).f_locals
    for key, val in params.items():
        caller.setdefault(key, val)
        caller.setdefault('__externs__', set()).add(key)
    for val in paramstocheck:
        assert type(val) == str
        if val not in caller:
            raise NameError(val, 'should be provided by external parameters.')
        caller.setdefault('__externs__', set()).add(val)


# [SECTION] helpers of __init__.py
def deprecated(func):
    """PlantGL's decorator that __init__.py imports: the function warns (DeprecationWarning) at
    each call."""
    def newFunc(*args, **kwargs):
        import warnings
        warnings.warn("Call to deprecated function %s." % func.__name__, category=DeprecationWarning)
        return func(*args, **kwargs)
    newFunc.__deprecated__ = True
    newFunc.__name__ = func.__name__
    newFunc.__doc__ = func.__doc__
    newFunc.__dict__.update(func.__dict__)
    return newFunc


def determine_lpymodule_path(fn):
    """The file of an .lpy model named as a module ('package.model'): model.lpy in the
    package's folders (ModuleNotFoundError if none has it)."""
    if fn.endswith('.lpy'):
        fn = fn[:-4]
    splittedfn = fn.split('.')
    package, modfname = '.'.join(splittedfn[:-1]), splittedfn[-1] + '.lpy'
    import importlib
    from os.path import join, exists
    paths = importlib.import_module(package).__path__
    for p in paths:
        fnpath = join(p, modfname)
        if exists(fnpath):
            return fnpath
    raise ModuleNotFoundError(fn)


# [SECTION] the turtle's help
# L-Py's predefined modules in the order it makes them (src/cpp/predefinedmodules.cpp): name,
# aliases (', ' between two), category (PredefinedModuleClass::eCategory) and documentation.
_CATEGORIES = ['None', 'Structure', 'Rotation', 'Position', 'Scale', 'Primitive', 'Width', 'Color', 'Tropism', 'Request',
               'Texture', 'String Manipulation', 'Pattern Matching', 'User Defined']
_PREDEFINED = [
('', 'None', 0, 'None Module.'),
    ('[', 'SB', 1, 'Push the state in the stack.'),
    (']', 'EB', 1, 'Pop last state from turtle stack and make it the its current state.'),
    ('=]', '', 12, 'Match exactly a closing bracket'),
    ('F', '', 5, "Move forward and draw. Params: 'length , topradius'."),
    ('f', '', 5, "Move forward and without draw. Params: 'length'."),
    ('nF', '', 5, "Produce a n steps path of a given length and varying radius. Params : 'length, dlength [, radius = 1, radiusvariation = None]'."),
    ('X', 'MouseIns', 11, 'Module inserted just before module selected by user in visualisation.'),
    ('%', 'Cut', 11, 'Cut the remainder of the current branch in the string.'),
    ('*', 'any', 12, 'Used to match any module in rules predecessor. First argument will become name of the module.'),
    ('x', 'repexp, all', 12, 'Used to specify matching of a repetition of modules.'),
    ('or', '||', 12, 'Used to specify an alternative matching of modules.'),
    ('?P', 'GetPos', 9, "Request position vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle)."),
    ('?H', 'GetHead', 9, "Request heading vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle)."),
    ('?U', 'GetUp', 9, "Request up vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle)."),
    ('?L', 'GetLeft', 9, "Request left vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle)."),
    ('?R', 'GetRight', 9, "Request right vector information. Params : 'x,y,z' or 'v' (optional, default=Vector3, filled by Turtle)."),
    ('?F', 'GetFrame', 9, "Request turtle frame information. Params : 'p,h,u,l' (optional, filled by Turtle)."),
    ('@Gc', 'StartGC', 5, 'Start a new generalized cylinder.'),
    ('@Ge', 'EndGC', 5, 'Pop generalized cylinder from the stack and render it.'),
    ('{', 'BP', 5, 'Start a new polygon.'),
    ('}', 'EP', 5, 'Pop a polygon from the stack and render it. Params : concavetest (default=False).'),
    ('.', 'PP', 5, 'Add a point for polygon.'),
    ('@M', 'MoveTo', 3, "Set the turtle position. Params : 'x, y, z' or 'v' (optionals, default = None for not changing specific coordinates)."),
    ('MoveRel', '', 3, "Move relatively from current the turtle position. Params : 'x, y, z' or 'v'(optionals, default = 0)."),
    ('LineTo', '', 5, "Trace line to (x,y,z) without changing the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0)."),
    ('OLineTo', '', 5, "Trace line toward (x,y,z) and change the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0)."),
    ('Pinpoint', '', 2, "Orient turtle toward (x,y,z) . Params : 'x, y, z' or 'v' (optionals, default = 0)."),
    ('LineRel', '', 5, "Trace line to pos+(x,y,z) without changing the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter'(optionals, default = 0)."),
    ('OLineRel', '', 5, "Trace line toward pos+(x,y,z) and change the orientation. Params : 'x, y, z, topdiameter' or 'v, topdiameter' (optionals, default = 0)."),
    ('PinpointRel', '', 2, "Orient turtle toward pos+(x,y,z) . Params : 'x, y, z' or 'v' (optionals, default = 0)."),
    ('@R', 'SetHead', 2, "Set the turtle Heading and Up vector. Params: 'hx, hy, hz, ux, uy, uz' or 'h,v' (optionals, default=0,0,1, 1,0,0)."),
    ('EulerAngles', '', 2, "Set the orientation of the turtle from the absolute euler angles. Params: 'azimuth, elevation, roll' (optionals, default=180,90,0)."),
    ('+', 'Left', 2, "Turn left  around Up vector. Params : 'angle' (optional, in degrees)."),
    ('-', 'Right', 2, "Turn right around Up vector. Params : 'angle' (optional, in degrees)."),
    ('^', 'Up', 2, "Pitch up around Left vector. Params : 'angle' (optional, in degrees)."),
    ('&', 'Down', 2, "Pitch down around Left vector. Params : 'angle' (optional, in degrees)."),
    ('/', 'RollL', 2, "Roll left  around Heading vector. Params : 'angle' (optional, in degrees)."),
    ('\\', 'RollR', 2, "Roll right  around Heading vector. Params : 'angle' (optional, in degrees)."),
    ('iRollL', '', 2, "Roll left intrinsically around Heading vector. Params : 'angle' (optional, in degrees)."),
    ('iRollR', '', 2, "Roll right intrinsically around Heading vector. Params : 'angle' (optional, in degrees)."),
    ('|', 'TurnAround', 2, 'Turn around 180deg the Up vector.'),
    ('@v', 'RollToVert', 2, 'Roll to Vertical : Roll the turtle around the H axis so that H and U lie in a common vertical plane with U closest to up'),
    ('@h', 'RollToHorizontal', 2, 'Roll to Horizontal : Roll the turtle so that H lie in the horizontal plane'),
    ('@O', 'Sphere', 5, "Draw a sphere. Params : 'radius' (optional, should be positive, default = line width)."),
    ('@B', 'Box', 5, "Draw a box. Params : 'length','topradius'."),
    ('@b', 'Quad', 5, "Draw a quad. Params : 'length','topradius'."),
    ('@o', 'Circle', 5, "Draw a circle. Params : 'radius' (optional, should be positive, default = line width)."),
    ('@L', 'Label', 5, "Draw a text label. Params : 'text','size'."),
    ('_', 'IncWidth', 6, "Increase the current line width or set it if a parameter is given. Params : 'width' (optional)."),
    ('!', 'DecWidth', 6, "Decrease the current line width or set it if a parameter is given. Params : 'width' (optional)."),
    ('SetWidth', '', 6, "Set current line width. Params : 'width'."),
    (';', 'IncColor', 7, "Increase the current material index or set it if a parameter is given. Params : 'index' (optional, positive int)."),
    (',', 'DecColor', 7, "Decrease the current material index or set it if a parameter is given. Params : 'index' (optional, positive int)."),
    ('SetColor', '', 7, "Set the current material. Params : 'index' (positive int) or 'r,g,b[,a]' or 'material'."),
    ('InterpolateColors', '', 7, "Set the current material. Params : 'index1', 'index2', 'alpha' ."),
    ('TextureBaseColor', '', 10, "Set the base color of the texture. Params : 'index' (positive int) or 'r,g,b[,a]' or 'material'."),
    ('InterpolateTextureBaseColors', '', 10, "Set the base color of the texture from interpolation of 2 predefined material. Params : 'index1', 'index2', 'alpha' ."),
    ('@Dd', 'DivScale', 4, "Divides the current turtle scale by a scale factor, Params : 'scale_factor' (optional, default = 1.0)."),
    ('@Di', 'MultScale', 4, "Multiplies the current turtle scale by a scale factor, Params : 'scale_factor' (optional, default = 1.0)."),
    ('@D', 'SetScale', 4, "Set the current turtle scale, Params : 'scale' (optional, default = 1.0)."),
    ('surface', '', 5, "Draw the predefined surface at the turtle's current location and orientation. Params : 'surface_name' (by default, 'l' exists), 'scale_factor' (optional, default= 1.0, should be positive)."),
    ('~', '', 5, "Draw the predefined surface at the turtle's current location and orientation. Params : 'surface_name' (by default, 'l' exists), 'scale_factor' (optional, default= 1.0, should be positive)."),
    ('@g', 'PglShape', 5, "Draw a geometry at the turtle's current location and orientation. Params : 'geometric_model', 'scale_factor' (optional, should be positive) or 'shape' or 'scene' or 'material'."),
    ('Frame', '', 5, "Draw the current turtle frame as 3 arrows (red=heading,blue=up,green=left). Params : 'size' (should be positive), 'cap_heigth_ratio' (in [0,1]), 'cap_radius_ratio' (should be positive)."),
    ('Arrow', '', 5, "Draw an arrow. Params : 'size' (should be positive), 'cap_heigth_ratio' (in [0,1]), 'cap_radius_ratio' (should be positive)."),
    ('@Ts', 'Elasticity', 8, "Set Branch Elasticity. Params : 'elasticity' (optional, default= 0.0, should be between [0,1])."),
    ('@Tp', 'Tropism', 8, "Set Tropism. Params : 'tropism' (optional, Vector3, default= (1,0,0))."),
    ('SetContour', '', 5, "Set Cross Section of Generalized Cylinder. Params : 'Curve2D [, ccw]'."),
    ('SectionResolution', '', 5, "Set Resolution of Section of Cylinder. Params : 'resolution' (int)."),
    ('SetGuide', '', 5, "Set Guide for turtle tracing. Params : 'Curve[2D|3D], length [,yorientation, ccw]'."),
    ('EndGuide', '', 5, 'End Guide for turtle tracing.'),
    ('Sweep', '', 5, "Produce a sweep surface. Params : 'path, section, length, dlength [, radius = 1, radiusvariation = None]'."),
    ('PositionOnGuide', '', 5, 'Set position on Guide for turtle tracing.'),
    ('TextureScale', '', 10, "Set the scale coefficient for texture application. Params : 'uscale, vscale' (default = 1,1) or 'scale'."),
    ('TextureUScale', '', 10, "Set the u-scale coefficient for texture application. Params : 'uscale' (default = 1)."),
    ('TextureVScale', 'TextureVCoeff', 10, "Set the v-scale coefficient for texture application. Params : 'vscale' (default = 1)."),
    ('TextureTranslation', '', 10, "Set the translation for texture application. Params : 'utranslation, vtranslation' (default = 0,0) or 'translation'."),
    ('TextureRotation', '', 10, "Set the rotation for texture application. Params : 'angle, urotcenter, vrotcenter' (default = 0,0.5,0.5) or 'angle, rotcenter'."),
    ('TextureTransformation', '', 10, "Set the transformation for texture application. Params : 'uscale, vscale, utranslation, vtranslation, angle, urotcenter, vrotcenter' (default = 1,1,0,0,0,0.5,0.5) or 'scale, translation, angle, rotcenter'."),
    ('LeftReflection', '', 2, 'The turtle change the left vector to have a symmetric behavior.'),
    ('UpReflection', '', 2, 'The turtle change the up vector to have a symmetric behavior.'),
    ('HeadingReflection', '', 2, 'The turtle change the heading vector to have a symmetric behavior.'),
    ('@2D', 'StartScreenProjection', 3, 'The turtle will create geometry in the screen coordinates system.'),
    ('@3D', 'EndScreenProjection', 3, 'The turtle will create geometry in the world system (default behaviour).'),
    ('?I', 'GetIterator', 12, 'Request an iterator over the current Lstring.'),
    ('$', 'GetModule', 12, 'Request a module of the current Lstring.'),
    ('new', 'newmodule', 11, 'Create a new module whose name is given by first argument.'),
]


def helpTurtle(command=None):
    """L-Py's helpTurtle(): every predefined module by category, with its aliases and what it
    does; helpTurtle(name): the documentation of that module ('' for none)."""
    if command is not None:
        _text(command, 'helpTurtle(module)')
        for name, alias, category, doc in _PREDEFINED:
            if command == name or command in alias.split(', '):
                return doc
        from _sprout_lpy import ModuleClass
        found = ModuleClass.get(command)  # a module of the model's: its documentation, if any
        return '' if found is None else str(getattr(found, 'documentation', ''))
    out, previous = [], 0
    for name, alias, category, doc in sorted(_PREDEFINED, key=lambda row: row[2]):
        if category != previous:
            out.append(_CATEGORIES[category] + '\n')
            previous = category
        out.append(name + (' ( ' + alias + ' )' if alias else '') + ' : ' + doc + '\n')
    return ''.join(out)


# The modules of L-Py's package that are parts of this one.
def _view(name, names):
    """A module of L-Py's package that Sprout keeps here (openalea.lpy.__version__, ...)."""
    view = _types.ModuleType(name)
    view.__file__ = '<sprout>/' + name.replace('.', '/') + '.py'
    for n in names:
        setattr(view, n, globals()[n])
    _sys.modules[name] = view
    return view


_view('openalea.lpy.__version__', ['__version_number__', '__revision_str__', 'get_major', 'get_minor', 'get_revision',
                                   'get_version_majorminor', 'version_string', 'LPY_VERSION_MAJOR', 'LPY_VERSION_MINOR',
                                   'LPY_VERSION_REV', 'LPY_VERSION_STR'])
_view('openalea.lpy.defaultparameters', ['get_caller_frame', 'LocalsRetriever', 'defaultparameters', 'extern']).__all__ = [
    'defaultparameters', 'extern']
