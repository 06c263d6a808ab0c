# openalea.lpy as Sprout provides it to L-Py model files: the control functions of a
# derivation (from Sprout's engine, _sprout_lpy) and the `context()` that an
# INITIALISATION block writes its materials, options and parameters into.

# Index of this file:
#   [SECTION] module classes, the embedded Python, warnings
#   [SECTION] L-Py's options
#   [SECTION] LsysContext and the current context
#   [SECTION] the plotter and the selection
#   [SECTION] extern and defaultparameters
#   [SECTION] the turtle of interpretation rules
#   [SECTION] ParameterSet and makestring

import sys as _sys

from _sprout_lpy import (Lstring, Module, ModuleClass, Stop, forward, backward, isForward, useGroup,
                         getGroup, getIterationNb, nsproduce, isAnimationEnabled, isFrameDisplayed,
                         setSelectionAlwaysRequired, isSelectionAlwaysRequired, requestSelection)

from _sprout_lpy import __lpy_module_class as _module_class, _class_count, _turtle_methods

_state = {}


# [SECTION] module classes, the embedded Python, warnings
# (ModuleClassTable: lpy_strings.py.)
class _Embedded:
    """Modules compiled into Sprout that a model imports on demand (openalea.lpy.__lpyfuture__):
    a finder on sys.meta_path, and their loader, so that `import` and `importlib.reload` treat
    them as files."""

    sources = {}  # name: (source, file)

    @classmethod
    def find_spec(cls, name, path=None, target=None):
        if name not in cls.sources:
            return None
        import importlib.util
        return importlib.util.spec_from_loader(name, cls, origin=cls.sources[name][1])

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
    for name in _Embedded.sources:
        _sys.modules.pop(name, None)
        globals().pop(name.rpartition('.')[2], None)
    if context is None:
        context = LsysContext()
        _contexts.clear()
    context._state.update(ns=ns, file=file, warnings=[])
    context.makeCurrent()
    return context


def _warn(message):
    """A warning at the line of the model file that is running."""
    f = _sys._getframe(1)
    while f is not None and f.f_code.co_filename != _state.get('file'):
        f = f.f_back
    _state.setdefault('warnings', []).append((f.f_lineno if f is not None else 0, message))


# [SECTION] L-Py's options
# L-Py's options (src/cpp/lsyscontext.cpp): each with its values, by index, and its default.
_OPTIONS = [
    ('Module declaration', ['On the fly', 'Mandatory'], 0),
    ('Warning with sharp module', ['Disabled', 'Enabled'], 1),
    ('Compiler', ['Python', 'Python -OO', 'Cython'], 0),
    ('Optimization', ['Level 0', 'Level 1', 'Level 2'], 1),
    ('Module matching', ['Simple', 'Extension : *args', 'Extensions : *args and arg value constraints'], 2),
    ('Module inheritance', ['Disabled', 'Enabled'], 0),
    ('String matching', ['As String', 'As AxialTree', 'As Multi-level AxialTree', 'As Multiscale AxialTree'], 1),
    ('Early return when no matching', ['Disabled', 'Enabled'], 0),
    ('Axiom decomposition', ['Disabled', 'Enabled'], 0),
    ('Warning with Turtle inconsistency', ['Disabled', 'Enabled'], 1),
    ('Turtle Path Optimization', ['Disabled', 'Enabled'], 0),
    ('Turtle in Interpretation rules', ['Disabled', 'Enabled'], 1),
    ('Multicore parallel rewriting', ['Disabled', 'Enabled'], 0),
    ('Bracket mapping optimization', ['Disabled', 'On the fly', 'As preprocessing'], 0),
    ('Selection Always Required', ['Disabled', 'Enabled'], 0),
]


class _OptionValue:
    def __init__(self, name):
        self.name, self.comment = name, ''

    def activate(self):
        pass


class _Option:
    """One of L-Py's options: its values, the one selected (by index)."""

    def __init__(self, state, name, values, default):
        self._state, self.name, self._values, self.default_value_id = state, name, values, default
        self.comment, self.category, self.__dict__['global'] = '', '', False

    @property
    def selection(self):
        return self._state['options'].get(self.name, self.default_value_id)

    @selection.setter
    def selection(self, index):
        self.setSelection(index)

    def setSelection(self, value):
        if isinstance(value, str):
            if value not in self._values:
                return False
            value = self._values.index(value)
        value = int(value)
        if not 0 <= value < len(self._values):
            return False
        self._state['options'][self.name] = value
        self._state['changes'] = self._state.get('changes', 0) + 1  # read again (Matcher::readOptions)
        return True

    def currentValue(self):
        return self._values[self.selection]

    def isToDefault(self):
        return self.selection == self.default_value_id

    def activateSelection(self):
        pass

    def activate(self, value):
        self.setSelection(value)

    def __len__(self):
        return len(self._values)

    def __getitem__(self, i):
        return _OptionValue(self._values[i])


class _Options:
    """A context's options as L-Py names them: setSelection(name, index or value name)."""

    def __init__(self, state):
        self._state = state
        self._all = [_Option(state, n, v, d) for n, v, d in _OPTIONS]

    def find(self, name):
        for option in self._all:
            if option.name == name:
                return option
        return None

    def setSelection(self, name, value):
        option = self.find(name)
        if option is None:
            _warn("option '%s' is not one of L-Py's: ignored" % name)
            return False
        return option.setSelection(value)

    def activateSelection(self):
        pass

    def __getitem__(self, key):
        if isinstance(key, int):
            return self._all[key]
        option = self.find(key)
        return None if option is None else option.selection

    def __len__(self):
        return len(self._all)


# [SECTION] LsysContext and the current context
class _Turtle:
    def __init__(self, state):
        self._state = state

    def setAngleIncrement(self, angle):
        self._state['angle'] = float(angle)

    def setMaterial(self, index, material):
        self._state['materials'][int(index)] = material

    def getMaterial(self, index):
        return self._state['materials'].get(int(index))

    def __getattr__(self, name):
        if name.startswith('_'):
            raise AttributeError(name)

        def ignored(*args, **kwargs):
            _warn("context().turtle.%s is not provided by Sprout: ignored" % name)
        return ignored


class LsysContext:
    """L-Py's LsysContext: a model's namespace (context['k'] = v), its options, the turtle's
    settings and materials. The current one is what a running model's context() gives;
    makeCurrent() and done() switch to it and back."""

    def __init__(self):
        self._state = dict(ns={}, file=None, materials={}, angle=None, warnings=[], options={}, timestep=None, scales={})
        self.turtle = _Turtle(self._state)
        self.options = _Options(self._state)

    def makeCurrent(self):
        global _state, _current
        _contexts.append(_current)
        _current, _state = self, self._state

    def done(self):
        global _state, _current
        previous = _contexts.pop() if _contexts else None
        _current = previous if previous is not None else LsysContext()
        _state = _current._state

    def isCurrent(self):
        return _current is self

    def __enter__(self):
        self.makeCurrent()
        return self

    def __exit__(self, *exc):
        self.done()

    @property
    def animation_timestep(self):
        return self._state.get('timestep')

    @animation_timestep.setter
    def animation_timestep(self, value):
        self._state['timestep'] = value

    def __setitem__(self, name, value):
        self._state['ns'][name] = value

    def __getitem__(self, name):
        return self._state['ns'][name]

    def __delitem__(self, name):
        del self._state['ns'][name]

    def __contains__(self, name):
        return name in self._state['ns']

    def get(self, name, default=None):
        return self._state['ns'].get(name, default)

    def globals(self):
        return self._state['ns']

    def getIterationNb(self):
        return getIterationNb()

    InitialisationFunctionName = '__initialiseContext__'

    def declare(self, names):
        """Declares modules ('A, B, C') for the strings this context reads."""
        from _sprout_lpy import _declare
        for name in str(names).split(','):
            name = name.strip().split('(')[0].strip()
            if name:
                _declare(name)
                self._state.setdefault('declared', []).append(name)

    def undeclare(self, names):
        declared = self._state.setdefault('declared', [])
        for name in str(names).split(','):
            name = name.strip()
            if name in declared:
                declared.remove(name)

    @staticmethod
    def currentContext():
        return _current

    def updateNamespace(self, values):
        self._state['ns'].update(values)

    def declaredModules(self):
        return list(self._state.get('declared', []))

    def setModuleScale(self, names, scale):
        for name in str(names).split(','):
            if name.strip():
                self._state['scales'][name.strip()] = int(scale)
                self._state['changes'] = self._state.get('changes', 0) + 1

    def __getattr__(self, name):
        if name.startswith('_'):
            raise AttributeError(name)

        def ignored(*args, **kwargs):
            _warn("context().%s is not provided by Sprout: ignored" % name)
        return ignored


_contexts = []  # the contexts made current before, for done()
_current = LsysContext()
_state = _current._state
_Context = LsysContext


def context():
    return _current


execContext = context
getContext = context


def frameDisplay(*args):
    pass


# [SECTION] the plotter and the selection
_plotter = None


def registerPlotter(plotter):
    """Lsystem.plot and animate give their scenes to plotter.plot(scene)."""
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


# [SECTION] extern and defaultparameters
def extern(*names, **defaults):
    """L-Py's extern (openalea.lpy.defaultparameters): extern(a=1) gives a the value 1 unless
    the caller set it (Lsystem(file, {'a': 2})); extern('b') requires b to be set. Both are
    listed in the model's __externs__."""
    ns = _sys._getframe(1).f_globals
    externs = ns.setdefault('__externs__', set())
    for k, v in defaults.items():
        ns.setdefault(k, v)
        externs.add(k)
    for k in names:
        if not isinstance(k, str):
            raise TypeError("extern(): a name is a string")
        if k not in ns:
            raise NameError(k, 'should be provided by external parameters.')
        externs.add(k)


def defaultparameters(function):
    """L-Py's @defaultparameters: the function's local variables become the model's names
    where they are not set yet."""
    import inspect
    ns = _sys._getframe(1).f_globals
    found = {}

    def tracer(frame, event, arg):
        if event == 'return' and frame.f_code is function.__code__:
            found.update(frame.f_locals)
        return tracer if frame.f_code is function.__code__ else None

    def run(*args, **kwargs):
        old = _sys.gettrace()
        _sys.settrace(tracer)
        try:
            return function(*args, **kwargs)
        finally:
            _sys.settrace(old)
            for k, v in found.items():
                ns.setdefault(k, v)

    if len(inspect.signature(function).parameters) == 0:
        run()
        return function
    return run


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
        return lambda *args: nsproduce([cls(*args)])

    def __setattr__(self, name, value):
        if name in self._params:
            self._params[name] = value
        else:
            object.__setattr__(self, name, value)


# [SECTION] ParameterSet and makestring
class ParameterSet:
    def __init__(self, **kwargs):
        self.__dict__.update(kwargs)

    def set(self, **kwargs):
        self.__dict__.update(kwargs)

    def setdefault(self, **kwargs):
        for k, v in kwargs.items():
            self.__dict__.setdefault(k, v)

    def hasattr(self, name):
        return name in self.__dict__

    def get(self, name, default=None):
        return self.__dict__.get(name, default)

    def parameter_names(self):
        return list(self.__dict__.keys())

    def rename(self, old, new):
        self.__dict__[new] = self.__dict__.pop(old)

    def copy(self, deep=True):
        import copy
        return copy.deepcopy(self) if deep else copy.copy(self)

    def __contains__(self, name):
        return name in self.__dict__

    def __repr__(self):  # as L-Py writes it: ParameterSet(length=2,width=0.1)
        return "%s(%s)" % (type(self).__name__, ",".join("%s=%r" % kv for kv in self.__dict__.items()))


def makestring(text):
    return Lstring(text)
