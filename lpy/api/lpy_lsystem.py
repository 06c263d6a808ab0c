# openalea.lpy's Lsystem as L-Py defines it (src/cpp/lsystem.h, src/wrapper/export_lsystem.cpp,
# src/openalea/lpy/__init__.py), on Sprout's engine: `_Session` (lpy/api/session.cpp) holds a
# model's translation, namespace and engine between calls; this class gives it L-Py's API.

# Index of this file:
#   [SECTION] files, materials and scenes
#   [SECTION] Lsystem

import os as _os

from _sprout_lpy import _Session, Lstring
import openalea.lpy as _lpy
from openalea.lpy import LsysContext  # noqa: F401
from openalea.lpy._scene import _show_in_notebook

__all__ = ['Lsystem', 'LsysContext', 'AxialTree', 'ParamModule']

from _sprout_lpy import AxialTree, ParamModule  # noqa: E402


# [SECTION] files, materials and scenes
def _read(filename):
    """A model file's text, as L-Py's Python reads it: by its coding cookie, otherwise UTF-8
    with any other byte read as Latin-1 (lpy/translate/encoding.cpp), any line ends."""
    from _sprout_lpy import _model_text
    with open(filename, 'rb') as f:
        text = _model_text(f.read())
    return text.replace('\r\n', '\n').replace('\r', '\n')


# [SECTION] Lsystem
class Lsystem:
    """An L-system read from a file or from code, derived and interpreted on demand:
    Lsystem(filename=None, parameters=None); parameters override the model's names (after its
    INITIALISATION part, before the rest of its code)."""

    def __init__(self, filename=None, parameters=None):
        if '_context' not in self.__dict__:  # clear() keeps the context, as L-Py's does
            object.__setattr__(self, '_context', _lpy.LsysContext())
        self._context._state['ns'] = {}
        self._session = None
        self._code = self._fullcode = ''
        self._parameters = {}
        self._axiom = None  # set through the `axiom` property
        self._length = None  # set through `derivationLength`
        self._depths = {}  # set through decompositionMaxDepth, interpretationMaxDepth
        self._last = 0
        self._scene = None
        self._added = []  # rules added from Python: (kind, group, text)
        self._running = False
        self._filename = ''
        self._debugger = None
        if filename:
            self.read(filename, parameters or {})

    # The model's names as attributes (L-Py's __init__.py: an L-system used as a module of a
    # script): a name the Lsystem lacks is read from its namespace and, set, goes there.
    def __getattr__(self, name):
        if name.startswith('__') or name.startswith('_') and name in type(self).__dict__:
            raise AttributeError(name)
        ctx = self.__dict__.get('_context')
        if ctx is not None and name in ctx._state['ns']:
            return ctx._state['ns'][name]
        raise AttributeError(name)

    def __setattr__(self, name, value):
        if name.startswith('_') and not name.startswith('__') or hasattr(type(self), name) or name in self.__dict__:
            object.__setattr__(self, name, value)
        else:
            self._context._state['ns'][name] = value

    # -- reading -------------------------------------------------------------------------
    @property
    def filename(self):
        """The file the model was read from ('' for code set from Python): its __file__."""
        return self._filename

    @filename.setter
    def filename(self, name):
        self._filename = str(name)
        ns = self._context._state['ns']
        ns['__file__'] = self._filename
        ns['__name__'] = _os.path.basename(self._filename).split('.')[0]

    def read(self, filename, parameters={}):
        """Reads a model file and runs its code."""
        if not _os.path.isfile(filename):
            raise ValueError("'%s': No such file or directory." % filename)
        text = _read(filename)
        self.clear()
        self.filename = filename
        self.set(text, parameters)

    def set(self, code, parameters={}, debug=False):
        """Sets the model's code (and runs it): the namespace starts afresh."""
        self._added, self._axiom, self._length, self._depths = [], None, None, {}
        return self._set(code, parameters, debug)

    def _with_added_rules(self, code):
        """The code with the rules added from Python after its own (before its
        INITIALISATION part)."""
        if not self._added:
            return code
        tag = '###### INITIALISATION ######'
        main, sep, init = code.partition(tag)
        lines = [main.rstrip('\n'), 'production:']
        for kind, group, text in self._added:
            if kind:
                lines.append(('decomposition:', 'interpretation:')[kind - 1])
            lines += ['group %d:' % group if group else 'group 0:', text, 'endgroup', 'production:']
        lines.append('endlsystem')
        return '\n'.join(lines) + '\n' + sep + init

    def _set(self, code, parameters={}, debug=False):
        file = _os.path.abspath(self._filename) if self._filename else '<lsystem>'
        ns = self._context._state['ns'] = {}
        if self._filename:
            ns['__name__'] = _os.path.basename(self._filename).split('.')[0]
        ctx = _lpy._begin(ns, file, self._context)
        try:
            self._fullcode = self._with_added_rules(code)
            self._session = _Session(self._fullcode, file, ctx._state['ns'], dict(parameters or {}))
        finally:
            ctx.done()
        self._context._state['declared'] = list(self._session.declared())
        self._code, self._parameters, self._last = code, dict(parameters or {}), 0
        if self._length is not None:
            self._session.derivationLength = self._length
        for kind, depth in self._depths.items():
            self._session.setMaxDepth(kind, depth)
        self._set_debugger()
        self._session.setRuleObject(self._rule_object)
        return self._session.python if debug else None

    def _rule_object(self, index):
        """Rule `index` of the translation as L-Py's LsysRule (what a debugger is given)."""
        from openalea.lpy._rules import LsysRule
        return LsysRule._of(self, index)

    # -- rules added from Python ---------------------------------------------------------
    def addRule(self, rule, ruletype=0, group=0, filter=None):
        """Adds a rule (its text, as in a file, or an LsysRule) of type eProduction,
        eDecomposition or eInterpretation to a group. The model is read again with it; the
        values its namespace held are kept (L-Py compiles the rule alone)."""
        text = rule._source if hasattr(rule, '_source') else str(rule)
        if filter is not None:
            text = '%s %s\n%s' % ('ignore:' if filter.ignoring() else 'consider:', filter.str(), text)
        self._added.append((int(ruletype), int(group), text))
        held = dict(self._context._state['ns'])
        self._set(self._code, self._parameters)
        ns = self._context._state['ns']
        for name, value in held.items():
            if not name.startswith('_') and not callable(value):
                ns[name] = value

    def addProductionRule(self, code, group=0, filter=None):
        self.addRule(code, 0, group, filter)

    def addDecompositionRule(self, code, group=0, filter=None):
        self.addRule(code, 1, group, filter)

    def addInterpretationRule(self, code, group=0, filter=None):
        self.addRule(code, 2, group, filter)

    def isRunning(self):
        """Whether the Lsystem is deriving (or drawing) now."""
        return self._running

    def forceRelease(self):
        """Ends the running state an interrupted run left."""
        self._running = False

    # -- a debugger told of each match (L-Py's Lsystem.setDebugger) ---------------------
    def setDebugger(self, debugger):
        self._debugger = debugger
        self._need()
        self._set_debugger()

    def _set_debugger(self):
        from openalea.lpy._rules import _Told
        self._session.debugger = None if self._debugger is None else _Told(self._debugger)

    def getDebugger(self):
        # L-Py's binding has no converter for what it would give.
        raise TypeError("No to_python (by-value) converter found for C++ type: PGL::RefCountPtr<LPY::Lsystem::Debugger>")

    def hasDebugger(self):
        return self._debugger is not None

    def clearDebugger(self):
        self._debugger = None
        if self._session is not None:
            self._session.debugger = None

    def setCode(self, code, parameters={}, debug=False):
        """Sets the model's code (debug: gives the Python it became)."""
        return self.set(code, parameters, debug)

    def code(self):
        """L-Py's listing of the L-system: axiom, derivation length and each rule's Python."""
        return self._listing(lambda r: r.code())

    def __str__(self):
        modules = self._session.moduleNames() if self._session is not None else []
        head = 'Axiom: %s\n' % self.axiom + ('module %s\n' % ','.join(modules) if modules else '')
        return head + self._listing(str, False)

    def _listing(self, write, code=True):
        out = (['Lsystem:', 'Axiom: %s' % self.axiom] if code else []) + ['derivation length: %d' % self.derivationLength,
                                                                           'production:']
        for g in range(self.nbGroups()):
            if g:
                out += ['group: %d' % g, 'production:']
            out += [write(r) for r in self._rules(0, g)]
            for kind, word, depth in ((1, 'decomposition:', self.decompositionMaxDepth),
                                      (2, 'interpretation:', self.interpretationMaxDepth)):
                rules = self._rules(kind, g)
                if rules:
                    out += [word] + (['maximum depth:%d' % depth] if g == 0 else []) + [write(r) for r in rules]
        return '\n'.join(out + ['endlsystem'])

    def clear(self):
        """Forgets the model: no rules, the axiom empty, derivation length 1, an empty
        namespace, no file."""
        self.__init__()

    def empty(self):
        """Whether the Lsystem has no rule."""
        return self._session is None or self.nbGroups() == 0

    def isCompiled(self):
        """Sprout's rules are compiled when they are read."""
        return True

    def compile(self):
        pass

    def _need(self):
        if self._session is None:
            self._set('')
        return self._session

    # -- the model's settings ------------------------------------------------------------
    @property
    def axiom(self):
        if self._axiom is not None:
            return Lstring(self._axiom)
        s = self._need()
        with self._context:
            return s.axiom()

    @axiom.setter
    def axiom(self, value):
        with self._context:
            self._axiom = Lstring(value)

    @property
    def derivationLength(self):
        return self._need().derivationLength

    @derivationLength.setter
    def derivationLength(self, n):
        self._need().derivationLength = int(n)
        self._length = int(n)

    def _depth(kind):
        def get(self):
            return self._need().maxDepth(kind)

        def put(self, n):
            self._need().setMaxDepth(kind, int(n))
            self._depths[kind] = int(n)
        return property(get, put, doc="The depth of the %s rules (`maximum depth:`)" % ('', 'decomposition', 'interpretation')[kind])

    decompositionMaxDepth = _depth(1)
    interpretationMaxDepth = _depth(2)
    del _depth

    @property
    def early_return(self):
        """Set (by Stop(), or from another thread), the running derivation stops after its
        step; a derivation starts and ends with it off."""
        return self._session is not None and self._session.earlyReturn

    @early_return.setter
    def early_return(self, on):
        self._need().earlyReturn = bool(on)

    def context(self):
        return self._context

    execContext = context

    def makeCurrent(self):
        self._context.makeCurrent()

    def done(self):
        self._context.done()

    def isCurrent(self):
        return self._context.isCurrent()

    def getLastIterationNb(self):
        return self._last

    def nbProductionRules(self, group=0):
        return self._need().rules(0, group)

    def nbDecompositionRules(self, group=0):
        return self._need().rules(1, group)

    def nbInterpretationRules(self, group=0):
        return self._need().rules(2, group)

    def nbTotalRules(self):
        """The number of rules of every group."""
        return sum(self._need().rules(k) for k in range(3))

    def nbGroups(self):
        """The number of groups (the highest group a rule is in, plus one)."""
        groups = self._need().groups()
        return max(groups) + 1 if groups else 0

    def _rules(self, kind, group):
        """The rules of one kind in a group, as LsysRule, in the file's order."""
        from openalea.lpy._rules import LsysRule
        s = self._need()
        found = []
        for i in range(s.ruleCount()):
            info = s.rule(i)
            if info['kind'] == kind and info['group'] == group:
                found.append(LsysRule._of(self, i))
        return found

    def _rule(self, kind, ruleid, group):
        n = self.nbGroups()
        ruleid, group = int(ruleid), int(group)
        if group < 0:
            group += n
        if not 0 <= group < n:
            raise IndexError("group index out of range")
        rules = self._rules(kind, group)
        if ruleid < 0:
            ruleid += len(rules)
        if not 0 <= ruleid < len(rules):
            raise IndexError("rule index out of range")
        return rules[ruleid]

    def productionRule(self, ruleid=0, group=0):
        return self._rule(0, ruleid, group)

    def decompositionRule(self, ruleid=0, group=0):
        return self._rule(1, ruleid, group)

    def interpretationRule(self, ruleid=0, group=0):
        return self._rule(2, ruleid, group)

    def get_rule_fonction_table(self):
        """{the Python function's name of each rule: its header} (L-Py's function names)."""
        return {r.functionName(): r.name() for g in range(self.nbGroups()) for k in range(3) for r in self._rules(k, g)}

    # -- deriving ------------------------------------------------------------------------
    def derive(self, *args, **kwargs):
        """derive(), derive(nb), derive(lstring), derive(lstring, nb),
        derive(lstring, start, nb): the string after nb steps (the model's derivation
        length by default), from iteration `start`."""
        s = self._need()
        names = ('workstring', 'starting_iter', 'nb_iter', 'previouslyinterpreted')
        args = list(args) + [kwargs.pop(n) for n in names[len(args):] if n in kwargs]
        if kwargs:
            raise TypeError("derive() got unexpected arguments: %s" % ", ".join(kwargs))
        lstring, start, nb = None, 0, None
        if args and isinstance(args[0], int):
            nb = args[0]
            args = []
        elif args:
            lstring = args[0]
            if len(args) == 2:
                nb = args[1]
            elif len(args) >= 3:
                start, nb = args[1], args[2]
        if self._running:
            raise ValueError("Concurrent Access of the Lsystem")
        with self._context:
            if lstring is None:
                lstring = self.axiom
            elif not isinstance(lstring, Lstring):
                lstring = Lstring(lstring)
            if nb is None:
                nb = s.derivationLength - start
            self._running = True
            try:
                out = s.derive(lstring, int(start), int(nb))
            finally:
                self._running = False
            self._last = s.iteration
        return out

    iterate = derive

    def __iter__(self):
        return self.derivations()

    def derivations(self, *args):
        """derivations(nbiterations), derivations(start, nbiterations[, step]): an iterator
        over the strings of the derivation from `start` to `stop` (both included) by `step`."""
        from openalea.lpy._rules import LsystemIterator
        if not args:
            return LsystemIterator(self)
        if len(args) == 1:
            return LsystemIterator(self, 0, args[0])
        return LsystemIterator(self, *args)

    def __call__(self, lstring, nbsteps=None):
        # L-Py's __init__.py calls derive(0, nbsteps, lstring), which no derive takes.
        raise TypeError("Python argument types in\n    Lsystem.derive(Lsystem, int, int, %s)\ndid not match C++ signature"
                        % type(lstring).__name__)

    def partial_derivation(self, workstring, starting_position, length):
        """One step of the production rules on `length` modules of `workstring` from
        `starting_position` (their contexts read in the whole string), then the decomposition
        rules: the modules those became."""
        with self._context:
            return self._need().partial(self._lstring(workstring), int(starting_position), int(length))

    def turtle_interpretation(self, lstring, turtle=None):
        """Interprets the string with the turtle: its query modules (?P, ?H, ...) get the
        turtle's state where it passes them, in place."""
        if turtle is not None:
            raise TypeError("Lsystem.turtle_interpretation(lstring, turtle): Sprout's PlantGL has no Turtle to give; "
                            "call turtle_interpretation(lstring), or sceneInterpretation(lstring) for the scene")
        if not isinstance(lstring, Lstring):
            raise TypeError("Lsystem.turtle_interpretation: an Lstring (its query modules are filled in place)")
        with self._context:
            self._need().fillQueries(lstring)

    def interpret(self, lstring):
        """The string with the interpretation rules applied."""
        with self._context:
            return self._need().interpret(Lstring(lstring) if not isinstance(lstring, Lstring) else lstring)

    homomorphism = interpret

    def _lstring(self, lstring):
        return lstring if isinstance(lstring, Lstring) else Lstring(lstring)

    def sceneInterpretation(self, lstring):
        """The scene the turtle draws from the string: an openalea.plantgl.all.Scene whose
        shapes' ids are the modules that drew them."""
        lstring = self._lstring(lstring)
        with self._context:
            self._scene = self._need().scene(lstring)
        self._scene._sprout_source = (self._session, Lstring(lstring))
        return self._scene

    def getLastComputedScene(self):
        """The scene the last step's EndEach was given or gave (None without EndEach)."""
        return None if self._session is None else self._session.lastScene

    def plot(self, lstring=None, checkLastComputedScene=False):
        """Draws the string: its scene goes to the plotter registered with
        openalea.lpy.registerPlotter (none by default: the scene is computed and kept)."""
        s = self._need()
        scene = s.lastScene if checkLastComputedScene else None
        if scene is None:
            scene = self.sceneInterpretation(self.axiom if lstring is None else lstring)
        self._scene = scene
        plotter = _lpy.get_plotter()
        if plotter is not None:
            plotter.plot(scene)
        else:
            _show_in_notebook(scene)

    def animate(self, *args):
        """animate(), animate(dt), animate(dt, nb), animate(dt, start, nb),
        animate(lstring, dt, start, nb): each step derived and shown (EndEach gets every
        step's scene); gives the last string."""
        lstring = None
        if args and not isinstance(args[0], (int, float)):
            lstring, args = args[0], args[1:]
        import time
        start, nb = 0, None
        if len(args) == 2:
            nb = int(args[1])
        elif len(args) >= 3:
            start, nb = int(args[1]), int(args[2])
        if args:  # L-Py keeps the time step in the context
            self._context.animation_timestep = float(args[0])
        dt = self._context.animation_timestep or 0
        s = self._need()
        current = self.axiom if lstring is None else self._lstring(lstring)
        if nb is None:
            nb = s.derivationLength - start
        s.animating = True
        try:
            shown = time.monotonic()
            self.plot(current)
            for i in range(nb):
                with self._context:
                    current = s.derive(current, start + i, 1, False)
                    self._last = s.iteration
                time.sleep(max(0.0, shown + dt - time.monotonic()))  # a frame each time step, as L-Py's
                shown = time.monotonic()
                self.plot(current, True)
                if s.earlyReturn:
                    break
        finally:
            s.animating = s.earlyReturn = False
        return current

    def stepInterpretation(self, lstring):
        """Draws the string module by module: the registered plotter (openalea.lpy.
        registerPlotter) is given the scene so far at each of the turtle's own modules, the
        context's animation_timestep apart, then the whole scene."""
        import time
        lstring = self._lstring(lstring)
        if not len(lstring):
            return
        if _lpy.get_plotter() is None:
            raise NotImplementedError("Lsystem.stepInterpretation draws in L-Py's viewer, module by module: register a "
                                      "plotter (openalea.lpy.registerPlotter) to be given each scene")
        with self._context:
            s = self._need()
            origins = s.predefinedOrigins(lstring)
            scene = s.scene(lstring)
        plotter = _lpy.get_plotter()
        from openalea.plantgl.all import Scene
        dt = self._context.animation_timestep or 0
        for k, at in enumerate(origins):
            if k and dt > 0:
                time.sleep(dt)
            plotter.plot(Scene([shape for shape in scene if shape.id <= at]))
        plotter.plot(scene)

    def record(self, prefix, *args, **kwargs):
        """record(prefix[, suffix]), record(prefix, nbiteration[, suffix]), record(prefix,
        begin, nbiteration[, suffix]), record(prefix, workstring, begin, nbiteration[, suffix]):
        each step derived, plotted and saved as prefix + its number + '.' + suffix by the
        registered plotter's save(filename, format)."""
        suffix = kwargs.pop('suffix', 'png')
        args = list(args)
        if args and isinstance(args[-1], str):
            suffix = args.pop()
        workstring = None
        if args and not isinstance(args[0], int):
            workstring = args.pop(0)
        names = ('begin', 'nbiteration') if len(args) != 1 else ('nbiteration',)
        for n in names[len(args):]:
            if n in kwargs:
                args.append(kwargs.pop(n))
        if kwargs:
            raise TypeError("record() got unexpected arguments: %s" % ", ".join(kwargs))
        begin, nb = (0, self.derivationLength) if not args else (0, int(args[0])) if len(args) == 1 else map(int, args[:2])
        plotter = _lpy.get_plotter()
        if plotter is None or not hasattr(plotter, 'save'):
            raise NotImplementedError("Lsystem.record saves the pictures of L-Py's viewer: register a plotter with plot and "
                                      "save (openalea.lpy.registerPlotter), or use `sprout render` / `sprout export`")
        import math
        fill = int(math.ceil(math.log10(float(begin) + nb + 1)))
        tree = self.axiom if workstring is None else self._lstring(workstring)
        s = self._need()
        s.animating = True
        try:
            self.plot(tree)
            plotter.save('%s%s.%s' % (prefix, str(begin).zfill(fill), suffix), suffix)
            for i in range(begin + 1, begin + nb + 1):
                with self._context:
                    tree = s.derive(tree, i - 1, 1)
                    self._last = s.iteration
                self.plot(tree, True)
                plotter.save('%s%s.%s' % (prefix, str(i).zfill(fill), suffix), suffix)
        finally:
            s.animating = False

    # -- pickling ------------------------------------------------------------------------
    def __getstate__(self):
        return dict(code=self._code, parameters=self._parameters, filename=self.filename)

    def __setstate__(self, state):
        self.__init__()
        self.filename = state.get('filename', '')
        self.set(state['code'], state.get('parameters', {}))

