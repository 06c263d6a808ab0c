# openalea.lpy's LsysContext and the functions that act on the current one, as L-Py defines
# them (src/cpp/lsyscontext.h/.cpp, src/wrapper/export_lsyscontext.cpp). A context holds a
# namespace (context['k'] = v), its options, the turtle's settings and materials, its declared
# modules and the control of a derivation (direction, group of rules, frame display, selection,
# early return). While Sprout's engine runs the model of the current context, that control is
# the engine's (_sprout_lpy._control; the engine takes it from the context when it starts and
# gives it back when it stops); otherwise each context keeps its own.
# Installed as openalea.lpy._context before openalea.lpy (lpy/interpreter/interpreter.cpp),
# which imports LsysContext and gives the functions on the current context. openalea.lpy._state
# is the current context's state, which the engine reads (options, materials, scales).

# Index of this file:
#   [SECTION] the current context
#   [SECTION] LsysContext

import sys as _sys

from _sprout_lpy import _control, _nsproduce, _declare, ModuleClass, Lstring
from openalea.lpy._base import LsysOptions, _text, _flag, _count

__all__ = ['LsysContext']

INITIALISATION_TAG = '###### INITIALISATION ######'
DEFAULT_TIMESTEP = 0.05
GEOM_EPSILON = 1e-5


# [SECTION] the current context
_stack = []  # the contexts made current before, for done()
_current = None
_global = None
_default = None


def _switch(context):
    global _current
    _current = context
    lpy = _sys.modules.get('openalea.lpy')
    if lpy is not None:
        lpy._state = context._state


def _begin_context(ns, file, context=None):
    """A new run: the model's namespace and file in a context of its own (`context`: an
    Lsystem's), made current."""
    if context is None:
        context = LsysContext(_ns=ns)
        del _stack[:]
    context._state.update(ns=ns, file=file, warnings=[])
    context.makeCurrent()
    return context


def _warn(message):
    lpy = _sys.modules.get('openalea.lpy')
    if lpy is not None:
        lpy._warn(message)


def _predefined(name):
    from openalea.lpy._base import _PREDEFINED
    return any(name == row[0] or name in row[1].split(', ') for row in _PREDEFINED)


def _running():
    return _control('iteration') is not None


def _module_names(text):
    """The names of a module list ('A, B(x, y), C'): each name before its parameters."""
    names, depth, word = [], 0, ''
    if str(text).count('(') != str(text).count(')'):
        raise SyntaxError("Invalid syntax in module declaration: Wait for ')'.")
    for ch in str(text) + ',':
        if ch == '(':
            depth += 1
        elif ch == ')':
            depth -= 1
        elif ch == ',' and depth == 0:
            if word.strip():
                names.append(word.strip())
            word = ''
            continue
        if depth == 0 and ch != ')':
            word += ch
    return [n.split('=')[0].strip() for n in names if n.split('=')[0].strip()]


class _Turtle:
    """The turtle's settings a model gives its context (context().turtle): the angle and the
    materials, which Sprout's turtle draws with."""

    def __init__(self, state):
        self._state = state

    def setAngleIncrement(self, angle):
        self._state['angle'] = float(angle)

    def setMaterial(self, index, material):
        self._state['materials'][int(index)] = material

    def getMaterial(self, index):
        return self._state['materials'].get(int(index))

    def getScene(self):
        return self._state.get('scene')

    def __getattr__(self, name):
        if name.startswith('_'):
            raise AttributeError(name)

        def ignored(*args, **kwargs):
            _warn("context().turtle.%s is not provided by Sprout: ignored" % name)
        return ignored


# [SECTION] LsysContext
class LsysContext:
    """Lsystem Execution Context (L-Py's LsysContext)."""

    InitialisationFunctionName = '__initialiseContext__'

    def __init__(self, *, _ns=None, _kind='local'):
        self._kind = _kind
        self._state = dict(ns={} if _ns is None else _ns, file=None, materials={}, angle=None, warnings=[], options={},
                           timestep=DEFAULT_TIMESTEP, scales={}, declared=[], production=[])
        # The control of a derivation, shared with the engine that runs this context's model
        # (lpy/interpreter/interpreter.cpp's EngineScope): it takes it, and gives it back.
        self._control = self._state['control'] = dict(forward=True, group=0, frame=False, selectionAlways=False,
                                                      selectionRequested=False, stop=False, iteration=0, animating=False)
        self._turtle = _Turtle(self._state)
        self._options = LsysOptions(self._state['options'], self._option_changed)
        if _ns is None and _kind == 'local':
            self._initialise_namespace()

    def _option_changed(self, name, index):
        self._state['changes'] = self._state.get('changes', 0) + 1  # read again (Matcher::readOptions)
        if name == 'Selection Always Required':
            self._set('selectionAlways', bool(index))

    def _initialise_namespace(self):
        ns = self.globals()
        if '__builtins__' not in ns and '__builtins__' not in self._state['ns']:
            ns['__builtins__'] = __builtins__
        if 'nproduce' not in self:
            exec("from openalea.lpy import *\nfrom openalea.plantgl.all import *\n", ns, ns)

    # -- the control of a derivation: the engine's while it runs this context's model -------
    # What a model sets or reads while the engine runs it stays in the context after the run.
    def _get(self, name):
        if self is _current:
            value = _control(name)
            if value is not None:
                self._control[name] = value
        return self._control[name]

    def _set(self, name, value):
        if self is _current:
            _control(name, value)
        self._control[name] = value

    def backward(self):
        self._set('forward', False)

    def forward(self):
        self._set('forward', True)

    def isForward(self):
        return self._get('forward')

    def stop(self):
        self._set('stop', True)

    def useGroup(self, gid):
        self._set('group', _count(gid, 'useGroup(gid)'))

    def getGroup(self):
        return self._get('group')

    def frameDisplay(self, enabled=True):
        self._set('frame', _flag(enabled, 'frameDisplay(enabled)'))

    def isFrameDisplayed(self):
        return self._get('frame')

    def isSelectionAlwaysRequired(self):
        return self._get('selectionAlways')

    def setSelectionAlwaysRequired(self, enabled):
        enabled = _flag(enabled, 'setSelectionAlwaysRequired(enabled)')
        if self._get('selectionAlways') != enabled:
            self._set('selectionAlways', enabled)
            self._state['options']['Selection Always Required'] = int(enabled)

    def requestSelection(self, message):
        self._control['message'] = _text(message, 'requestSelection(message)')
        self._set('selectionRequested', True)
        self.frameDisplay(True)

    def getIterationNb(self):
        return self._get('iteration')

    def isAnimationEnabled(self):
        return self._get('animating')

    def nproduce(self, lstring):
        """Adds modules to the production under way (an Lstring, a list of modules, or their
        text)."""
        if isinstance(lstring, str):
            lstring = Lstring(lstring)
        if not isinstance(lstring, (Lstring, list)):
            raise TypeError("LsysContext.nproduce(lstring): an Lstring, a list of modules or their text")
        if self is _current and _running():
            _nsproduce(lstring)
        else:
            for module in Lstring(lstring) if isinstance(lstring, list) else lstring:
                self._state['production'].append(module)

    # L-Py's buffer of what nproduce gave outside a rule, read and set from Python.
    @property
    def __production_buffer__(self):
        return Lstring(list(self._state['production']))

    @__production_buffer__.setter
    def __production_buffer__(self, lstring):
        self._state['production'] = list(Lstring(lstring) if not isinstance(lstring, Lstring) else lstring)

    # -- settings ------------------------------------------------------------------------
    @property
    def turtle(self):
        return self._turtle

    @property
    def options(self):
        return self._options

    @property
    def animation_timestep(self):
        return self._state['timestep']

    @animation_timestep.setter
    def animation_timestep(self, value):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise TypeError("animation_timestep: a number, not %s" % type(value).__name__)
        self._state['timestep'] = float(value)

    def is_animation_timestep_to_default(self):
        return abs(self._state['timestep'] - DEFAULT_TIMESTEP) < GEOM_EPSILON

    def __str__(self):
        return "<LsysContext instance at 0x%x with %d declared modules>" % (id(self), len(self._state['declared']))

    __repr__ = __str__

    def clear(self):
        """Back to a fresh context's control, no declared module, the namespace afresh."""
        self._control.update(forward=True, group=0, selectionAlways=False, selectionRequested=False, iteration=0,
                             animating=False, stop=False)
        del self._state['declared'][:]
        self._state['scales'].clear()
        self.clearNamespace()

    def empty(self):
        return not self._state['declared']

    # -- modules -------------------------------------------------------------------------
    def declare(self, modules):
        """Declares modules ('A, B(x, y)') for the strings this context reads."""
        for name in _module_names(_text(modules, 'declare(modules)')):
            _declare(name)
            self._state['declared'].append(name)

    def undeclare(self, modules):
        """Undeclares modules. As in L-Py, a string read in this context declared the modules it
        named on the fly (Sprout does not list those): a module of the model's Sprout knows is
        undeclared silently; a predefined module or a name no module has is an error."""
        for name in _module_names(_text(modules, 'undeclare(modules)')):
            if name in self._state['declared']:
                self._state['declared'].remove(name)
            elif ModuleClass.get(name) is None or _predefined(name):
                raise ValueError("Cannot undeclare module '%s'. Not declared in this scope." % name)

    def isDeclared(self, module):
        return _text(module, 'isDeclared(module)') in self._state['declared']

    def declaredModules(self):
        return [ModuleClass.get(name) for name in self._state['declared']]

    def setModuleScale(self, modules, scale):
        if not isinstance(scale, int):
            raise TypeError("setModuleScale(modules, scale): the scale is an integer, not %s" % type(scale).__name__)
        for name in _module_names(_text(modules, 'setModuleScale(modules)')):
            self._state['scales'][name] = int(scale)
            self._state['changes'] = self._state.get('changes', 0) + 1

    # -- the namespace -------------------------------------------------------------------
    def locals(self):
        return self._state['ns']

    def globals(self):
        if self._kind == 'global':
            return _sys.modules['__main__'].__dict__
        return self._state['ns']

    def getNamespace(self, d):
        if not isinstance(d, dict):
            raise TypeError("getNamespace(d): a dict, not %s" % type(d).__name__)
        d.update(self.locals())

    def updateNamespace(self, d):
        if not isinstance(d, dict):
            raise TypeError("updateNamespace(d): a dict, not %s" % type(d).__name__)
        self.locals().update(d)

    def clearNamespace(self):
        self.locals().clear()
        if self._kind != 'global':
            self._initialise_namespace()

    def __contains__(self, name):
        _text(name, 'a name of the context')
        return name in self.locals() or name in self.globals()

    has_key = __contains__

    def get(self, name, defaultvalue):  # both needed, as L-Py's (a C++ default Boost.Python does not see)
        if _text(name, 'a name of the context') in self.locals():
            return self.locals()[name]
        return self.globals().get(name, defaultvalue)

    def __getitem__(self, name):
        if name not in self:
            raise KeyError(name)
        return self.get(name, None)

    def __setitem__(self, name, value):
        self.locals()[_text(name, 'a name of the context')] = value

    def __delitem__(self, name):
        if _text(name, 'a name of the context') in self.locals():
            del self.locals()[name]
        else:
            del self.globals()[name]

    def evaluate(self, code):
        """The value of a Python expression in the context's namespace (None for no code)."""
        if not _text(code, 'evaluate(code)'):
            return None
        with _Maintained(self):
            return eval(compile(code, '<string>', 'eval'), self.globals(), {})

    def compile(self, code, *more):
        """compile(code) runs the code in the namespace; compile(name, code) runs it and gives
        the value it left under `name` (None for no code)."""
        if more:
            name, code = _text(code, 'compile(name, code)'), _text(more[0], 'compile(name, code)')
            if not code:
                return None
            exec(code, self.globals(), self.locals())
            return self.get(name, None)
        with _Maintained(self):
            exec(_text(code, 'compile(code)'), self.globals(), self.locals())

    # -- the functions of a model ----------------------------------------------------------
    def _call(self, name):
        with _Maintained(self):
            return self.get(name, None)() if name in self else None

    def start(self):
        return self._call('Start')

    def end(self):
        return self._call('End')

    def startEach(self):
        return self._call('StartEach')

    def endEach(self):
        return self._call('EndEach')

    def postDraw(self):
        self._call('PostDraw')

    def setStart(self, func):
        self['Start'] = func

    def setEnd(self, func):
        self['End'] = func

    def setStartEach(self, func):
        self['StartEach'] = func

    def setEndEach(self, func):
        self['EndEach'] = func

    def setPostDraw(self, func):
        self['PostDraw'] = func

    def initialise(self):
        """Calls the namespace's __initialiseContext__(context): True if there is one."""
        with _Maintained(self):
            return self._initialise()

    def _initialise(self):
        if LsysContext.InitialisationFunctionName not in self:
            return False
        self.get(LsysContext.InitialisationFunctionName, None)(self)
        return True

    def initialiseFrom(self, code):
        """Runs the INITIALISATION part of a model's code, then initialise(): where the part
        begins, or None without one."""
        with _Maintained(self):
            pos = _text(code, 'initialiseFrom(code)').find(INITIALISATION_TAG)
            if pos < 0:
                return None
            self.compile(code[pos:])
            self._initialise()
            return pos

    # -- the current context -------------------------------------------------------------
    def makeCurrent(self):
        if self is _current:
            import warnings
            warnings.warn("Multiple activation of same context!", Warning, stacklevel=2)
        _stack.append(_current)
        _switch(self)

    def isCurrent(self):
        return self is _current

    def done(self):
        if self is _current and _stack:
            _switch(_stack.pop())
        elif self is not _default:
            raise ValueError("Not current context trying to be done.")

    # Sprout's: `with context:` makes it current for the block unless it is (L-Py's
    # ContextMaintainer, which its Lsystem's methods use).
    def __enter__(self):
        made = self is not _current
        self.__dict__.setdefault('_made', []).append(made)
        if made:
            self.makeCurrent()
        return self

    def __exit__(self, *exc):
        if self._made.pop() and self is _current:
            self.done()

    @staticmethod
    def currentContext():
        return _current

    @staticmethod
    def current():
        return _current

    @staticmethod
    def globalContext():
        return _global

    @staticmethod
    def defaultContext():
        global _default
        if _default is None:
            _default = LsysContext()
        return _default

    @staticmethod
    def default():
        return LsysContext.defaultContext()


class _Maintained:
    """L-Py's ContextMaintainer: the context made current for a block unless it is."""

    def __init__(self, context):
        self.context, self.made = context, not context.isCurrent()

    def __enter__(self):
        if self.made:
            self.context.makeCurrent()

    def __exit__(self, *exc):
        if self.made and self.context.isCurrent():
            self.context.done()


_global = LsysContext(_kind='global')
_current = _global
