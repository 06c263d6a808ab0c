# openalea.lpy as Sprout provides it to L-Py model files and scripts: what L-Py's package
# __init__.py gathers. Its parts: openalea.lpy._base (version, options, extern,
# defaultparameters), openalea.lpy.parameterset (ParameterSet), openalea.lpy._context
# (LsysContext and the control functions of a derivation), installed before this module
# (lpy/interpreter/interpreter.cpp); the classes of strings from Sprout's engine (_sprout_lpy);
# Lsystem and the matching classes added after it (lpy_lsystem.py, lpy_matching.py).

# Index of this file:
#   [SECTION] module classes, the embedded Python, warnings
#   [SECTION] functions on the current context
#   [SECTION] the plotter, scenes and the selection
#   [SECTION] the turtle of interpretation rules
#   [SECTION] makestring

import sys as _sys
from types import ModuleType  # in L-Py's namespace, as its __init__ imports it

from _sprout_lpy import Lstring, Module, ModuleClass
# The getters rules call at each match, in C++ (lpy/api/module.cpp): the running engine's value,
# or the current context's.
from _sprout_lpy import getIterationNb, getGroup, isForward, isFrameDisplayed, isAnimationEnabled, isSelectionAlwaysRequired
from _sprout_lpy import __lpy_module_class as _module_class, _class_count, _turtle_methods, _nsproduce
from openalea.lpy._base import *  # noqa: F401,F403
from openalea.lpy._base import __version_number__, __revision_str__  # noqa: F401
from openalea.lpy.parameterset import ParameterSet  # noqa: F401
from openalea.lpy._context import *  # noqa: F401,F403
import openalea.lpy._context as _cm

parameterset = _sys.modules['openalea.lpy.parameterset']
__version__ = _sys.modules['openalea.lpy.__version__']
_state = _cm._current._state  # the current context's (set again as it changes)


# [SECTION] module classes, the embedded Python, warnings
# (ModuleClassTable: lpy_strings.py.)
class _Embedded:
    """Modules compiled into Sprout that a model imports on demand (openalea.lpy.__lpyfuture__):
    a finder on sys.meta_path, and their loader, so that `import` and `importlib.reload` treat
    them as files."""

    sources = {}  # name: (source, file)
    # Packages (with modules of their own) used from the Python that runs Sprout where they
    # are installed there (a real openalea.mtg), Sprout's own otherwise.
    installed_first = ('openalea.mtg',)

    @classmethod
    def find_spec(cls, name, path=None, target=None):
        if name not in cls.sources:
            return None
        import importlib.util
        if name in cls.installed_first:
            import importlib.machinery, os
            folders = [os.path.join(p, *name.split('.')[:-1]) for p in _sys.path if isinstance(p, str)]
            real = importlib.machinery.PathFinder.find_spec(name, [f for f in folders if os.path.isdir(f)])
            if real is not None:
                return real
        return importlib.util.spec_from_loader(name, cls, origin=cls.sources[name][1], is_package=name in cls.installed_first)

    @staticmethod
    def create_module(spec):
        return None

    @classmethod
    def exec_module(cls, module):
        source, file = cls.sources[module.__name__]
        module.__file__ = file
        exec(compile(source, file, 'exec'), module.__dict__)


def _embed(name, source, file):
    """Makes `name` importable from `source` (lpy/interpreter/interpreter.cpp, at start)."""
    _Embedded.sources[name] = (source, file)
    if _Embedded not in _sys.meta_path:
        _sys.meta_path.append(_Embedded)


def _begin(ns, file, context=None):
    """A new run: the model's namespace and file in a context of its own (`context`: an
    Lsystem's), made current; nothing remembered from an earlier run."""
    # On-demand modules keep state of their own (__lpyfuture__'s kept strings): imported afresh.
    # (openalea.mtg keeps none: an MTG read before a run stays one of the same class.)
    for name in _Embedded.sources:
        if name == 'openalea.mtg' or name.startswith('openalea.mtg.'):
            continue
        _sys.modules.pop(name, None)
        globals().pop(name.rpartition('.')[2], None)
    return _cm._begin_context(ns, file, context)


def _warn(message):
    """A warning at the line of the model file that is running."""
    f = _sys._getframe(1)
    while f is not None and f.f_code.co_filename != _state.get('file'):
        f = f.f_back
    _state.setdefault('warnings', []).append((f.f_lineno if f is not None else 0, message))


# [SECTION] functions on the current context (src/wrapper/export_lsyscontext.cpp)
def context():
    """Return the current L-system context of execution. Rather use execContext."""
    return _cm._current


def execContext():
    """Return the current L-system context of execution."""
    return _cm._current


def backward():
    _cm._current.backward()


def forward():
    _cm._current.forward()


def useGroup(gid):
    _cm._current.useGroup(gid)


def frameDisplay(enabled=True):
    _cm._current.frameDisplay(enabled)


def setSelectionAlwaysRequired(enabled):
    _cm._current.setSelectionAlwaysRequired(enabled)


def requestSelection(message):
    _cm._current.requestSelection(message)


def declare(modules):
    _cm._current.declare(modules)


def undeclare(modules):
    _cm._current.undeclare(modules)


def isDeclared(module):
    """As L-Py's: asks the current context, and gives None (its C++ function returns void)."""
    _cm._current.isDeclared(module)


def Stop():
    _cm._current.stop()


def nsproduce(lstring):
    """Adds modules (a list, an Lstring or a string of them) to the production under way."""
    if isinstance(lstring, str):
        lstring = Lstring(lstring)
    if type(lstring) is list and _cm._running():  # in a rule: straight to the engine
        return _nsproduce(lstring)
    _cm._current.nproduce(lstring)


def pproduce(*args, **kwargs):
    """L-Py's produce of a parametric successor (`$` successors its parser compiles): Sprout's
    translation writes those as plain produce statements, and has no such successor."""
    if not args:
        raise TypeError("pproduce(id, *args): the successor's id and its values")
    raise IndexError("pproduce(%r, ...): no parametric successor has this id (Sprout translates `produce` "
                     "statements into modules directly)" % (args[0],))


def _in_context(pid, left, parameters):
    if not _cm._running():
        raise ValueError("Cannot call %s" % ("InLeftContext" if left else "InRightContext"))
    from _sprout_lpy import __lpy_in_context as test
    return test(int(pid), left, parameters)


def pInLeftContext(patternid, parameters=None):
    """Whether the pattern `patternid` of the model (an InLeftContext of a rule's body) matches
    on the left of the rule's match; its values go into `parameters`."""
    return _in_context(patternid, True, {} if parameters is None else parameters)


def pInRightContext(patternid, parameters=None):
    return _in_context(patternid, False, {} if parameters is None else parameters)


def _in_context_of(pattern, left, parameters):
    if not _cm._running():
        raise ValueError("Cannot call %s" % ("inLeftContext" if left else "inRightContext"))
    from _sprout_lpy import _in_context_text
    return _in_context_text(str(pattern), left, {} if parameters is None else parameters)


def inLeftContext(pattern, parameters=None):
    """In a rule's body: whether `pattern` ('A(x)', a PatternString) matches on the left of the
    rule's match (from where the header's context, or the last such test, ended); its values go
    into `parameters`. A pattern written in the call is read with the file; one made at run
    time is read when first tested."""
    return _in_context_of(pattern, True, parameters)


def inRightContext(pattern, parameters=None):
    """inLeftContext's twin, on the right of the rule's match."""
    return _in_context_of(pattern, False, parameters)


# [SECTION] the plotter, scenes and the selection
_plotter = None


def registerPlotter(plotter):
    """plot(), Lsystem.plot and animate give their scenes to plotter.plot(scene); the
    selection is plotter.selection()."""
    global _plotter
    _plotter = plotter


def cleanPlotter():
    global _plotter
    _plotter = None


def get_plotter():
    return _plotter


def _selection():
    """The positions the registered plotter's selection() gives (none without one)."""
    if _plotter is None or not hasattr(_plotter, 'selection'):
        return None
    return _plotter.selection()


_drawer = None


def _scene_of(lstring, context=None):
    """The PlantGL scene the turtle draws from a string, without interpretation rules, with the
    turtle's settings and materials of `context` (by default none: the turtle's defaults)."""
    global _drawer
    if not isinstance(lstring, Lstring):
        raise TypeError("a scene is drawn from an Lstring (or AxialTree), not from %s" % type(lstring).__name__)
    if _drawer is None:
        from openalea.lpy._lsystem import Lsystem
        _drawer = Lsystem()
        _drawer._need()
    own = _drawer.context()._state
    kept = dict(angle=own['angle'], materials=dict(own['materials']))
    if context is not None:
        own.update(angle=context._state['angle'], materials=dict(context._state['materials']))
    try:
        return _drawer.sceneInterpretation(lstring)
    finally:
        own.update(kept)


def _turtle_of(turtle):
    if not isinstance(turtle, _cm._Turtle):
        raise TypeError("the turtle is a context's (LsysContext.turtle): Sprout's openalea.plantgl has no PglTurtle "
                        "to interpret a string with, got %s" % type(turtle).__name__)
    return turtle


def generateScene(lstring, turtle=None):
    """The scene of a string drawn by a turtle: a context's turtle (its settings and
    materials), or a turtle of its own."""
    if turtle is None:
        return _scene_of(lstring)
    return _scene_of(lstring, _owner_of(_turtle_of(turtle)))


def _owner_of(turtle):
    owner = LsysContext.__new__(LsysContext)
    owner._state = turtle._state
    return owner


def plot(lstring, turtle=None):
    """Draws a string with the current context's turtle (or `turtle`): its scene goes to the
    registered plotter (registerPlotter), or is shown in Jupyter."""
    scene = _scene_of(lstring, _owner_of(_turtle_of(turtle)) if turtle is not None else context())
    if _plotter is not None:
        _plotter.plot(scene)
    else:  # L-Py shows it in PlantGL's viewer; Sprout in Jupyter, as Lsystem.plot does
        from openalea.lpy._lsystem import _show_in_notebook
        _show_in_notebook(scene)


def turtle_interpretation(lstring, turtle, matching=None):
    """The string interpreted by a context's turtle, from its start: turtle.getScene() is the
    scene it drew."""
    if not isinstance(lstring, Lstring):
        raise TypeError("turtle_interpretation(lstring, turtle): an Lstring, not %s" % type(lstring).__name__)
    t = _turtle_of(turtle)
    if not lstring.wellBracketed():
        raise ValueError("Ill-formed string: unmatched brackets")
    t._state['scene'] = _scene_of(lstring, _owner_of(t))


def turtle_partial_interpretation(lstring, turtle):
    """The string interpreted by a context's turtle, its shapes added to what it drew before."""
    if not isinstance(lstring, Lstring):
        raise TypeError("turtle_partial_interpretation(lstring, turtle): an Lstring, not %s" % type(lstring).__name__)
    t = _turtle_of(turtle)
    scene = _scene_of(lstring, _owner_of(t))
    before = t._state.get('scene')
    if before is not None:
        for shape in scene:
            before.append(shape)
        scene = before
    t._state['scene'] = scene


# [SECTION] the turtle of interpretation rules
class _InterpretationTurtle:
    """The `turtle` of interpretation rules and of StartInterpretation(turtle), as far as Sprout
    draws: each drawing call (turtle.left(60), turtle.F(1), turtle.sphere(0.5), named as L-Py's
    PglTurtle names them) puts its module into the interpreted string where the rule runs, so
    the turtle draws it there; the parameters a model gives it (add_parameter) follow the
    turtle's branches: '[' keeps them, ']' brings them back."""

    # PglTurtle's methods, and the module each one is (lpy/translate/turtle_vocabulary.hpp).
    _modules = dict(_turtle_methods())

    def __init__(self):
        object.__setattr__(self, '_params', {})
        object.__setattr__(self, '_pystack', [])

    def add_parameter(self, name, value=None):
        self._params[name] = value

    def remove_parameter(self, name):
        self._params.pop(name, None)

    def clear_parameters(self):
        self._params.clear()

    def _push(self):
        self._pystack.append(dict(self._params))

    def _pop(self):
        if self._pystack:
            object.__setattr__(self, '_params', self._pystack.pop())

    def __getattr__(self, name):
        params = object.__getattribute__(self, '_params')
        if name in params:
            return params[name]
        module = _InterpretationTurtle._modules.get(name)
        if module is None:
            raise AttributeError("the turtle has no '%s' (Sprout's turtle of interpretation rules: "
                                 "PglTurtle's drawing calls and the parameters added to it)" % name)
        cls = ModuleClass.get(module)
        return lambda *args: _nsproduce([cls(*args)])

    def __setattr__(self, name, value):
        if name in self._params:
            self._params[name] = value
        else:
            object.__setattr__(self, name, value)


# [SECTION] makestring
def makestring(text):
    return Lstring(text)
