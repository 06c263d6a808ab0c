# openalea.plantgl._patches, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): NURBS patches and volumes (NurbsPatch, NurbsPatch3D), PlantGL's interface
# evaluated in C++ (lpy/plantgl/curves.cpp through bind_curves.cpp). Its own file: surfaces and
# volumes, apart from the curves (plantgl_curves.py) they are made with.
from _sprout_lpy import _PglPatch, _pgl_iso_points, _pgl_uniform_knots, _pgl_volume_point
from openalea.plantgl import _vectors
from openalea.plantgl._vectors import _Vec, Vector2, Vector3, cross
from openalea.plantgl._object import _SceneObject
from openalea.plantgl._curves import NurbsCurve, Point4Matrix, RealArray, _default_knots

_of2, _of3 = Vector2._of, Vector3._of


class NurbsPatch(_SceneObject):
    """A NURBS surface; control points (x, y, z, w) in rows along u."""
    _kind = 'surface'
    DEFAULT_CCW, DEFAULT_STRIDE, DEFAULT_NURBS_DEGREE = True, 30, 3

    def __init__(self, ctrlPointMatrix, udegree=3, vdegree=3, *args, **kwargs):
        if isinstance(udegree, (list, tuple)):  # the form (ctrl, uknots, vknots, udegree, vdegree)
            self.uknotList, self.vknotList = list(udegree), list(vdegree)
            udegree, vdegree = (list(args) + [3, 3])[:2]
        else:
            self.uknotList = kwargs.get('uknotList')
            self.vknotList = kwargs.get('vknotList')
        self.ctrlPointMatrix = [[tuple(p) for p in row] for row in ctrlPointMatrix]
        self.udegree, self.vdegree = int(udegree), int(vdegree)
        # PlantGL fills in the uniform clamped knots where none are given.
        # (Not where the degree is too high for the points: Sprout draws such a patch at the
        # degree the points allow, with that degree's knots.)
        rows = self.ctrlPointMatrix
        if not self.uknotList and rows and 1 <= self.udegree < len(rows):
            self.uknotList = RealArray(_pgl_uniform_knots(len(rows), self.udegree))
        if not self.vknotList and rows and rows[0] and all(1 <= self.vdegree < len(r) for r in rows):
            self.vknotList = RealArray(_pgl_uniform_knots(len(rows[0]), self.vdegree))
        self.ustride, self.vstride = kwargs.get('ustride', 30), kwargs.get('vstride', 30)
        self.ccw = kwargs.get('ccw', True)
        self.name = ''

    def _knots(self, which):
        """The knots along u or v: the patch's, or the uniform clamped ones."""
        knots = self.uknotList if which == 'u' else self.vknotList
        if knots:
            return list(knots)
        n = len(self.ctrlPointMatrix) if which == 'u' else len(self.ctrlPointMatrix[0])
        return _pgl_uniform_knots(n, self.udegree if which == 'u' else self.vdegree)

    firstUKnot = property(lambda self: self._knots('u')[self.udegree])
    lastUKnot = property(lambda self: self._knots('u')[len(self.ctrlPointMatrix)])
    firstVKnot = property(lambda self: self._knots('v')[self.vdegree])
    lastVKnot = property(lambda self: self._knots('v')[len(self.ctrlPointMatrix[0])])

    def isUDegreeToDefault(self):
        return self.udegree == 3

    def isVDegreeToDefault(self):
        return self.vdegree == 3

    def isUStrideToDefault(self):
        return self.ustride == 30

    def isVStrideToDefault(self):
        return self.vstride == 30

    def isCCWToDefault(self):
        return self.ccw is True

    def isUKnotListToDefault(self):
        return _default_knots(self.uknotList, len(self.ctrlPointMatrix), self.udegree)

    def isVKnotListToDefault(self):
        return _default_knots(self.vknotList, len(self.ctrlPointMatrix[0]), self.vdegree)

    def setUKnotListToDefault(self):
        self.uknotList = _pgl_uniform_knots(len(self.ctrlPointMatrix), self.udegree)
        return True

    def setVKnotListToDefault(self):
        self.vknotList = _pgl_uniform_knots(len(self.ctrlPointMatrix[0]), self.vdegree)
        return True

    def apply(self, action):
        return action.process(self)

    def __repr__(self):
        """As PlantGL writes a patch (its np_repr): what is not the default after the points."""
        rows, cols = len(self.ctrlPointMatrix), len(self.ctrlPointMatrix[0]) if self.ctrlPointMatrix else 0
        text = "NurbsPatch(" + repr(Point4Matrix(self.ctrlPointMatrix))
        for name, degree, knots, n in (("u", self.udegree, self.uknotList, rows), ("v", self.vdegree, self.vknotList, cols)):
            if degree != 3:
                text += ", %sdegree = %d" % (name, degree)
        for name, degree, knots, n in (("u", self.udegree, self.uknotList, rows), ("v", self.vdegree, self.vknotList, cols)):
            if not _default_knots(knots, n, degree):
                text += ", %sknotList = %r" % (name, RealArray(knots))
        for name, stride in (("u", self.ustride), ("v", self.vstride)):
            if stride != 30:
                text += ", %sstride = %d" % (name, stride)
        return text + ")"

    __str__ = __repr__

    # As each row were a NurbsCurve along v, its points at v the control points of one along u
    # (weight 1), evaluated in C++ (lpy/plantgl/curves.cpp) by an evaluator kept on the patch
    # while its rows hold the same points and no vector has changed in place.
    def _native(self):
        rows, uk, vk = self.ctrlPointMatrix, self.uknotList, self.vknotList
        key = (_vectors._changes[0], self.udegree, self.vdegree, tuple(map(tuple, rows)),
               None if uk is None else tuple(uk), None if vk is None else tuple(vk))
        cache = self.__dict__.get('_sprout_native_cache')
        if cache is not None and cache[0] == key:
            return cache[1]
        native = _PglPatch(rows, int(self.udegree), int(self.vdegree), uk or None, vk or None)
        if all(isinstance(q, (_Vec, tuple)) for row in rows for q in row):
            self.__dict__['_sprout_native_cache'] = (key, native)
        return native

    def __getstate__(self):  # pickled and copied without its evaluator
        state = dict(self.__dict__)
        state.pop('_sprout_native_cache', None)
        return state

    def getPointAt(self, u, v):
        return _of3(self._native().point(u, v))

    def _grid(self, n):
        """The points at (i / n, j / n), i outer, as tuples: the drawing's (lpy/plantgl/meshes.cpp)."""
        return self._native().grid(n)

    def getUTangentAt(self, u, v):
        """dS/du: the derivative of the iso-v section (PlantGL's, not normalised)."""
        return self.getIsoVSectionAt(v).getTangentAt(u)

    def getVTangentAt(self, u, v):
        return self.getIsoUSectionAt(u).getTangentAt(v)

    def getNormalAt(self, u, v):
        return cross(self.getUTangentAt(u, v), self.getVTangentAt(u, v)).normed()

    def getIsoUSectionAt(self, u):
        """The curve along v at u: each column's control points taken along u at u, in
        homogeneous coordinates (PlantGL's), with the patch's v knots and degree."""
        points = _pgl_iso_points(self.ctrlPointMatrix, self.udegree, self._knots('u'), u, True)
        return NurbsCurve(points, self.vdegree, self._knots('v'), self.vstride)

    def getIsoVSectionAt(self, v):
        """The curve along u at v."""
        points = _pgl_iso_points(self.ctrlPointMatrix, self.vdegree, self._knots('v'), v, False)
        return NurbsCurve(points, self.udegree, self._knots('u'), self.ustride)


class NurbsPatch3D(_SceneObject):
    """A NURBS volume (PlantGL's nurbspatch_nd.NurbsPatch3D): control points (x, y, z, w) in a
    grid [u][v][w]; getPointAt(u, v, w) maps the parameter cube into space."""
    _kind = 'volume'

    def __init__(self, ctrlPointMatrix, udegree=3, vdegree=3, wdegree=3, uknotList=None, vknotList=None, wknotList=None,
                 ustride=30, vstride=30, wstride=30):
        pts = [[[tuple(p) for p in row] for row in plane] for plane in ctrlPointMatrix]
        dims = (len(pts), len(pts[0]), len(pts[0][0]))
        self.udegree, self.vdegree, self.wdegree = int(udegree), int(vdegree), int(wdegree)
        for degree, dim in zip((self.udegree, self.vdegree, self.wdegree), dims):
            if not 1 <= degree < dim:
                raise ValueError("NurbsPatch3D: each degree from 1 to its count of control points - 1")
        self.ctrlPointMatrix = pts
        self.uknotList = list(uknotList) if uknotList is not None else _pgl_uniform_knots(dims[0], self.udegree)
        self.vknotList = list(vknotList) if vknotList is not None else _pgl_uniform_knots(dims[1], self.vdegree)
        self.wknotList = list(wknotList) if wknotList is not None else _pgl_uniform_knots(dims[2], self.wdegree)
        self.ustride, self.vstride, self.wstride = ustride, vstride, wstride
        self.name = ''

    @staticmethod
    def default():
        """The unit cube, degree 1 in each direction."""
        return NurbsPatch3D([[[(i, j, k, 1) for k in (0, 1)] for j in (0, 1)] for i in (0, 1)], 1, 1, 1)

    firstUKnot = property(lambda self: self.uknotList[0])
    lastUKnot = property(lambda self: self.uknotList[-1])
    firstVKnot = property(lambda self: self.vknotList[0])
    lastVKnot = property(lambda self: self.vknotList[-1])
    firstWKnot = property(lambda self: self.wknotList[0])
    lastWKnot = property(lambda self: self.wknotList[-1])

    def isValid(self):
        return True

    def getPointAt(self, u, v, w):
        """de Boor along w on the homogeneous points of each line, then along v, then along u
        (lpy/plantgl/curves.cpp's NurbsVolume)."""
        return _of3(_pgl_volume_point(self.ctrlPointMatrix, (self.udegree, self.vdegree, self.wdegree),
                                      (self.uknotList, self.vknotList, self.wknotList), u, v, w))
