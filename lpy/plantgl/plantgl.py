# openalea.plantgl.all: the part of PlantGL that L-Py model files use, as Sprout provides it.
# Its names come from the parts, each a file of its own that lpy/interpreter/interpreter.cpp installs as a
# private module before this one (in this order: each imports from those above it):
#
#   _vectors   vectors, Matrix3, cross, dot, angle...             plantgl_vectors.py
#   _object    what every scene object has (names, ids...)        plantgl_object.py
#   _arrays    point arrays, RealArray, Point4Matrix              plantgl_arrays.py
#   _scene     colours, materials, the scene objects for @g,      plantgl_scene.py
#              Scene, BoundingBox, the Viewer (does nothing)
#   _curves    point arrays, NURBS / Bezier curves, polylines,    plantgl_curves.py
#              QuantisedFunction, Discretizer, NurbsPatch
#   _patches   NurbsPatch, NurbsPatch3D                          plantgl_patches.py
#   _grids     Grid3Indexing, Point3Grid (space colonisation)     plantgl_grids.py
#   _light     the light model (diffuseInterception...),          plantgl_light.py
#              ZBufferEngine, surface()
#
# and openalea.plantgl.scenegraph.cspline (plantgl_cspline.py), installed before this module,
# kept here as `cspline` and as NurbsCurve.CSpline, as PlantGL's scenegraph package keeps it.
# (@g's shapes are meshed in C++: lpy/plantgl/meshes.cpp.)
# The aliases openalea.plantgl.math, .scenegraph, .light, .light.light are this module (lpy/interpreter/interpreter.cpp).
from openalea.plantgl._vectors import *
from openalea.plantgl._vectors import _Vec, _math
from openalea.plantgl._scene import *
from openalea.plantgl._scene import _warn, _Geometry, _geometry_fields, _Viewer
from openalea.plantgl._arrays import *
from openalea.plantgl._curves import *
from openalea.plantgl._curves import _Points
from openalea.plantgl._curves import _pgl_uniform_knots as _uniform_clamped_knots
from openalea.plantgl._patches import *
from openalea.plantgl._grids import *
from openalea.plantgl._light import *
import sys as _sys
cspline = _sys.modules['openalea.plantgl.scenegraph.cspline']
NurbsCurve.CSpline = staticmethod(cspline.cspline)


# What the parts define belongs to this module, as when it was one file: a model printing
# type(v) sees openalea.plantgl.all.Vector3, and pickle finds the classes here.
def _adopt(obj):
    if isinstance(obj, (staticmethod, classmethod)):
        obj = obj.__func__
    if isinstance(obj, property):
        for f in (obj.fget, obj.fset, obj.fdel):
            if f is not None:
                _adopt(f)
        return
    if isinstance(obj, (type, type(_adopt))) and obj.__module__.startswith('openalea.plantgl._'):
        obj.__module__ = __name__
        if isinstance(obj, type):
            for member in list(vars(obj).values()):
                _adopt(member)


for _v in list(globals().values()):
    _adopt(_v)
del _adopt, _v


def pgl_support_extension(name):
    """Whether PlantGL was built with an optional extension (CGAL, Qt, ...): Sprout's PlantGL
    has none of them."""
    return False


class Sequencer:
    """PlantGL's Sequencer: touch() (or a call) waits until `timeStep` seconds have passed since
    the last touch (PlantGL counts the processor's clock; Sprout, the wall clock)."""

    def __init__(self, timestep=0.01):
        self.timeStep, self._time = float(timestep), None

    def touch(self, next_timestep=None):
        import time
        now = time.monotonic()
        if self._time is not None and now - self._time < self.timeStep:
            time.sleep(self.timeStep - (now - self._time))
        self._time = time.monotonic()
        if next_timestep is not None:
            self.timeStep = float(next_timestep)

    __call__ = touch

    def elapsedTime(self):
        import time
        return time.monotonic() - self._time if self._time is not None else 0.0

    def ok(self):
        return self._time is None or self.elapsedTime() >= self.timeStep

    def sleep(self, t):
        import time
        time.sleep(max(0.0, float(t)))




# Names PlantGL's `all` gives beside its own, that a model's namespace holds (L-Py runs
# `from openalea.plantgl.all import *` in it): its modules import them and export them with
# theirs: sqrt and pi (scenegraph's nurbsshape: models take them for granted), deepcopy
# (algo), pj (all itself), the modules importlib, warnings and openalea, and pgl (this
# module: light's `import openalea.plantgl.all as pgl`).
from math import sqrt, pi
from copy import deepcopy
from os.path import join as pj
import importlib
import warnings
import openalea
pgl = light = lg = utils = _sys.modules[__name__]
PGL_VERSION, PGL_VERSION_STR = 201986, '3.21.2'  # what the reference PlantGL 3.22.3 says of itself
