# openalea.lpy's Lsystem as L-Py defines it (src/cpp/lsystem.h, src/wrapper/export_lsystem.cpp,
# src/openalea/lpy/__init__.py), on Sprout's engine: `_Session` (lpy/api/session.cpp) holds a
# model's translation, namespace and engine between calls; this class gives it L-Py's API.

# Index of this file:
#   [SECTION] files, materials and scenes
#   [SECTION] Lsystem
#   [SECTION] LsystemIterator

import io as _io
import os as _os

from _sprout_lpy import _Session, Lstring
import openalea.lpy as _lpy
from openalea.lpy import LsysContext  # noqa: F401

__all__ = ['Lsystem', 'LsysContext', 'LsystemIterator', 'AxialTree', 'ParamModule', 'eForward', 'eBackward',
           'eProduction', 'eDecomposition', 'eInterpretation']

from _sprout_lpy import AxialTree, ParamModule  # noqa: E402

eForward, eBackward = 0, 1
eProduction, eDecomposition, eInterpretation = 0, 1, 2


# [SECTION] files, materials and scenes
def _read(filename):
    """A model file's text, as L-Py's Python reads it: by its coding cookie, otherwise UTF-8
    with any other byte read as Latin-1 (lpy/translate/encoding.cpp), any line ends."""
    from _sprout_lpy import _model_text
    with open(filename, 'rb') as f:
        text = _model_text(f.read())
    return text.replace('\r\n', '\n').replace('\r', '\n')


def _material(colour):
    from openalea.plantgl.all import Material
    r, g, b, a = colour
    return Material((r, g, b), diffuse=1, transparency=1 - a / 255.0)


def _scene(parts):
    """A PlantGL Scene from what Sprout's turtle drew (lpy/api/session.cpp sceneOf): a shape per
    cylinder, surface or sphere, with the id of the module that drew it."""
    from openalea.plantgl.all import (Scene, Shape, Translated, Oriented, Cylinder, Cone, Frustum, Sphere, Scaled,
                                      TriangleSet, Polyline, Vector3)
    scene = Scene()
    for part in parts:
        kind, ident = part[0], part[1]
        if kind == 'cylinder':
            # PlantGL's shapes for an F: a Cylinder, a Cone (a radius of 0 at one end), a
            # Frustum, a Polyline for a width of 0; placed by Translated(Oriented(...)) unless
            # the turtle stands at the origin, heading up.
            a, b, r0, r1, colour = Vector3(*part[2]), Vector3(*part[3]), part[4], part[5], part[6]
            axis = b - a
            height = sum(c * c for c in axis) ** 0.5
            if r0 <= 1e-9 and r1 <= 1e-9:
                scene.append(Shape(Polyline([a, b]), _material(colour), ident))
                continue
            if abs(r0 - r1) < 1e-9:
                g = Cylinder(r0, height)
            elif r1 <= 1e-9:
                g = Cone(r0, height)
            elif r0 <= 1e-9:  # a cone upside down: its base at the F's end, turned over
                geometry = Translated(b, _along(-axis, Cone(r1, height), Oriented, Vector3))
                geometry.direction = axis
                scene.append(Shape(geometry, _material(colour), ident))
                continue
            else:
                g = Frustum(r0, height, r1 / r0)
            upright = height > 0 and abs(axis[2] - height) < 1e-6 * max(1.0, height)
            if sum(c * c for c in a) < 1e-12 and upright:
                geometry = g
            else:
                geometry = Translated(a, _along(axis, g, Oriented, Vector3))
            geometry.direction = axis
        elif kind == 'sphere':
            geometry = Translated(Vector3(*part[2]), Sphere(part[4]))
            colour = part[5]
        elif kind == 'surface':
            geometry = Translated(Vector3(*part[2]), Scaled((part[4],) * 3, TriangleSet([], [])))
            colour = part[5]
        else:
            geometry = _drawn_mesh(TriangleSet, Vector3, part[2], part[3])
            colour = part[4]
        scene.append(Shape(geometry, _material(colour), ident))
    return scene


def _along(axis, g, Oriented, Vector3):
    """`g` (made along z) turned to `axis`, as PlantGL's turtle turns it: Oriented(up, -left),
    its z the heading; the turtle's up is not in what Sprout's turtle gives, so the one nearest
    the first turtle's (x) stands for it (a cylinder's eight sides turn about its axis)."""
    h = Vector3(axis)
    h.normalize()
    up = Vector3(1, 0, 0) - h * h.x
    if up.normalize() < 1e-9:
        up = Vector3(0, 1, 0) - h * h.y
        up.normalize()
    return Oriented(up, h ^ up, g)


_DrawnMesh = None


def _drawn_mesh(TriangleSet, Vector3, points, faces):
    """The turtle's triangles in a scene: a TriangleSet whose pointList and indexList are read
    from their packed form (float x, y, z; uint32 indices) when the model first asks for them."""
    global _DrawnMesh
    if _DrawnMesh is None:
        import array

        class _DrawnMesh(TriangleSet):
            def __init__(self, points, faces):
                self.kwargs, self.name, self._packed = {}, '', (points, faces)

            def __getattr__(self, name):  # only for what is not there yet
                packed = self.__dict__.get('_packed')
                if name not in ('pointList', 'indexList', 'args') or packed is None:
                    raise AttributeError(name)
                xyz, ids = array.array('f'), array.array('I')
                xyz.frombytes(packed[0])
                ids.frombytes(packed[1])
                self.pointList = [Vector3(xyz[i], xyz[i + 1], xyz[i + 2]) for i in range(0, len(xyz), 3)]
                self.indexList = [(ids[i], ids[i + 1], ids[i + 2]) for i in range(0, len(ids), 3)]
                self.args, self._packed = (self.pointList, self.indexList), None
                return getattr(self, name)
        _DrawnMesh.__name__ = _DrawnMesh.__qualname__ = 'TriangleSet'  # as PlantGL names it (and @g draws it)
    return _DrawnMesh(points, faces)


def _show_in_notebook(scene):
    """In Jupyter, plot() shows the scene's picture (L-Py shows it in its viewer)."""
    import sys
    if 'IPython' not in sys.modules:
        return
    try:
        from IPython import get_ipython
        from IPython.display import display
        if get_ipython() is not None and getattr(get_ipython(), 'kernel', None) is not None:
            display(scene)
    except ImportError:
        pass


# [SECTION] Lsystem
class Lsystem:
    """An L-system read from a file or from code, derived and interpreted on demand:
    Lsystem(filename=None, parameters=None); parameters override the model's names (after its
    INITIALISATION part, before the rest of its code)."""

    _own = ('_context', '_session', '_code', '_parameters', '_axiom', '_length', '_last', '_scene', '_added', '_running',
            'filename')

    def __init__(self, filename=None, parameters=None):
        self._context = _lpy.LsysContext()
        self._session = None
        self._code = ''
        self._parameters = {}
        self._axiom = None  # set through the `axiom` property
        self._length = None  # set through `derivationLength`
        self._last = 0
        self._scene = None
        self._added = []  # rules added from Python: (kind, group, text)
        self._running = False
        self.filename = ''
        if filename:
            self.read(filename, parameters or {})

    # The model's names as attributes (an L-system used as a module of a script).
    def __getattr__(self, name):
        if name.startswith('__') or name in Lsystem._own:
            raise AttributeError(name)
        ns = self.__dict__.get('_context')._state['ns'] if '_context' in self.__dict__ else {}
        if name in ns:
            return ns[name]
        raise AttributeError("'Lsystem' object has no attribute '%s'" % name)

    def __setattr__(self, name, value):
        if name in Lsystem._own or name.startswith('_') or isinstance(getattr(type(self), name, None), property):
            object.__setattr__(self, name, value)
        elif name in self._context._state['ns']:
            self._context._state['ns'][name] = value
        else:
            object.__setattr__(self, name, value)

    # -- reading -------------------------------------------------------------------------
    def read(self, filename, parameters={}):
        """Reads a model file and runs its code."""
        text = _read(filename)
        self.filename = filename
        self.set(text, parameters)

    def set(self, code, parameters={}, debug=False):
        """Sets the model's code (and runs it): the namespace starts afresh."""
        self._added, self._axiom, self._length = [], None, None
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
        file = _os.path.abspath(self.filename) if self.filename else '<lsystem>'
        self._context._state['ns'] = {}
        ctx = _lpy._begin(self._context._state['ns'], file, self._context)
        try:
            self._session = _Session(self._with_added_rules(code), file, ctx._state['ns'], dict(parameters or {}))
        finally:
            ctx.done()
        self._context._state['declared'] = list(self._session.declared())
        self._code, self._parameters, self._last = code, dict(parameters or {}), 0
        if self._length is not None:
            self._session.derivationLength = self._length
        return self._session.python if debug else None

    # -- rules added from Python ---------------------------------------------------------
    def addRule(self, rule, kind=0, group=0):
        """Adds a rule (its text, as in a file) of kind 0 production, 1 decomposition, 2
        interpretation, to a group; the model is read again with it."""
        self._added.append((int(kind), int(group), str(rule)))
        self._set(self._code, self._parameters)

    def addProductionRule(self, rule, group=0):
        self.addRule(rule, 0, group)

    def addDecompositionRule(self, rule, group=0):
        self.addRule(rule, 1, group)

    def addInterpretationRule(self, rule, group=0):
        self.addRule(rule, 2, group)

    def isRunning(self):
        return self._running

    # -- a debugger told of each match (L-Py's Lsystem.setDebugger) ---------------------
    def setDebugger(self, debugger):
        self._need().debugger = debugger

    def getDebugger(self):
        return self._need().debugger

    def hasDebugger(self):
        return self._need().debugger is not None

    def clearDebugger(self):
        self._need().debugger = None

    def setCode(self, code, parameters={}, debug=False):  # noqa: D102
        return self.set(code, parameters, debug)

    def code(self):
        return self._code

    def clear(self):
        self.__init__()

    def empty(self):
        return self._session is None

    def isCompiled(self):
        return self._session is not None

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

    def setAxiom(self, value):
        self.axiom = value

    @property
    def derivationLength(self):
        return self._need().derivationLength

    @derivationLength.setter
    def derivationLength(self, n):
        self._need().derivationLength = int(n)
        self._length = int(n)

    def setDerivationLength(self, n):
        self.derivationLength = n

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
        return sum(self._need().rules(k) for k in range(3))

    def nbGroups(self):
        return max(self._need().groups() or [0]) + 1

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
            raise RuntimeError("this Lsystem is deriving already: it cannot derive again from inside its own run")
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
        return LsystemIterator(self)

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
        return self._scene

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
        start, nb = 0, None
        if len(args) == 2:
            nb = int(args[1])
        elif len(args) >= 3:
            start, nb = int(args[1]), int(args[2])
        s = self._need()
        current = self.axiom if lstring is None else self._lstring(lstring)
        if nb is None:
            nb = s.derivationLength - start
        s.animating = True
        try:
            self.plot(current)
            for i in range(nb):
                with self._context:
                    current = s.derive(current, start + i, 1)
                    self._last = s.iteration
                self.plot(current, True)
        finally:
            s.animating = False
        return current

    def record(self, *args, **kwargs):
        raise NotImplementedError("Lsystem.record: use `sprout render` or `sprout export` for pictures and videos")

    # -- pickling ------------------------------------------------------------------------
    def __getstate__(self):
        return dict(code=self._code, parameters=self._parameters, filename=self.filename)

    def __setstate__(self, state):
        self.__init__()
        self.filename = state.get('filename', '')
        self.set(state['code'], state.get('parameters', {}))

    def __str__(self):
        return self._code


# [SECTION] LsystemIterator
class LsystemIterator:
    """The strings of an Lsystem's derivation, step by step (L-Py's LsystemIterator)."""

    def __init__(self, lsystem, start=0, stop=None, step=1):
        assert step >= 1 and start >= 0
        self.lsystem, self.start, self.step = lsystem, start, step
        self.stop = lsystem.derivationLength if stop is None else stop
        self.currentstep = -1
        self.axiom = None

    def __next__(self):
        if self.currentstep == -1:
            self.axiom = self.lsystem.axiom
            if self.start != 0:
                self.axiom = self.lsystem.derive(self.axiom, 0, self.start)
            self.currentstep = self.start
            return self.axiom
        if self.currentstep + self.step > self.stop:
            raise StopIteration()
        self.axiom = self.lsystem.derive(self.axiom, self.currentstep, self.step)
        self.currentstep += self.step
        return self.axiom

    next = __next__

    def __iter__(self):
        return self
