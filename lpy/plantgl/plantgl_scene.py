# openalea.plantgl._scene, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): colours and materials, the scene objects a model builds for @g (kept with
# PlantGL's field names; Sprout draws them in lpy/plantgl/meshes.cpp), Scene, BoundingBox, and a
# Viewer whose calls do nothing (the light model is plantgl_light.py). Its own file: what a
# model stores, apart from the curves and grids it computes with.
#
# Index of this file:
#   [SECTION] Colours and materials
#   [SECTION] Scene objects
#   [SECTION] Scene and BoundingBox
#   [SECTION] Viewer
import math

from openalea.plantgl._vectors import Vector3
from openalea.plantgl._object import _SceneObject, with_defaults

try:
    from openalea.lpy import _warn
except ImportError:  # imported on its own
    def _warn(message):
        pass


# [SECTION] Colours and materials
class _Colour(tuple):
    """What PlantGL's Color3 and Color4 share: channels as 0..255, clamped ones as 0..1."""
    red = property(lambda s: s[0])
    green = property(lambda s: s[1])
    blue = property(lambda s: s[2])

    def clampedRed(self):
        return self[0] / 255.

    def clampedGreen(self):
        return self[1] / 255.

    def clampedBlue(self):
        return self[2] / 255.

    def getAverage(self):
        return (self[0] + self[1] + self[2]) / 3.

    def getAverageClamped(self):
        return self.getAverage() / 255.

    def interpolate(self, other, t=0.5):
        """The colour a fraction t of the way to `other`."""
        return type(self)(*[int(a + (b - a) * t) for a, b in zip(self, other)])

    def __repr__(self):
        return "%s(%s)" % (type(self).__name__, ",".join(str(c) for c in self))


class Color3(_Colour):
    def __new__(cls, r=0, g=0, b=0):
        if isinstance(r, (tuple, list)):
            r, g, b = r[:3]
        return tuple.__new__(cls, (int(r), int(g), int(b)))

    def toUint(self):
        return (self[0] << 16) | (self[1] << 8) | self[2]

    @staticmethod
    def fromUint(value):
        return Color3((value >> 16) & 255, (value >> 8) & 255, value & 255)


class Color4(_Colour):
    def __new__(cls, r=0, g=0, b=0, a=0):
        if isinstance(r, (tuple, list)):
            r, g, b, a = (list(r) + [0])[:4]
        return tuple.__new__(cls, (int(r), int(g), int(b), int(a)))

    alpha = property(lambda s: s[3])

    def clampedAlpha(self):
        return self[3] / 255.

    def getRGBAverage(self):
        return self.getAverage()

    # PlantGL's default packing (its eARGB channel positions, as they come out): red in the
    # lowest byte, then alpha, blue, green.
    def toUint(self):
        return (self[1] << 24) | (self[2] << 16) | (self[3] << 8) | self[0]

    @staticmethod
    def fromUint(value):
        return Color4(value & 255, (value >> 24) & 255, (value >> 16) & 255, (value >> 8) & 255)


for _name, _rgb in (('BLACK', (0, 0, 0)), ('WHITE', (255, 255, 255)), ('RED', (255, 0, 0)), ('GREEN', (0, 255, 0)),
                    ('BLUE', (0, 0, 255)), ('CYAN', (0, 255, 255)), ('YELLOW', (255, 255, 0))):
    setattr(Color3, _name, Color3(*_rgb))
    setattr(Color4, _name, Color4(*_rgb, 0))


class PglColorMap:
    """PlantGL's colour map (scenegraph/colormap.py): a value between `minvalue` and
    `maxvalue` made a Color4 by matplotlib's colour map `name`."""

    def __init__(self, minvalue=0, maxvalue=1, name='jet'):
        import matplotlib.pyplot as plt
        from matplotlib.colors import Normalize
        self.pltcolormap = plt.get_cmap(name)
        self.normalizer = Normalize(minvalue, maxvalue)

    def __call__(self, value):
        return self.__topglcolor__(self.normalizer(value))

    def __topglcolor__(self, normalizedindex):
        color = list(self.pltcolormap(normalizedindex))
        color[3] = 1. - color[3]
        return Color4([int(255 * c) for c in color])


def tocolorlist(values, name='jet'):
    cm = PglColorMap(min(values), max(values), name)
    return list(map(cm, values))


class Material(_SceneObject):
    """PlantGL's Material: the colour a surface shows is ambient x diffuse."""

    def __init__(self, *args, **kwargs):
        names = ['ambient', 'diffuse', 'specular', 'emission', 'shininess', 'transparency']
        args = list(args)
        self.name = args.pop(0) if args and isinstance(args[0], str) else kwargs.pop('name', '')
        values = dict(ambient=Color3(80, 80, 80), diffuse=2.0, specular=Color3(0, 0, 0), emission=Color3(0, 0, 0),
                      shininess=0.2, transparency=0.0)
        for n, v in zip(names, args):
            values[n] = v
        values.update(kwargs)
        self.ambient = Color3(values['ambient'])
        self.diffuse = float(values['diffuse'])
        self.specular = Color3(values['specular'])
        self.emission = Color3(values['emission'])
        self.shininess = float(values['shininess'])
        self.transparency = float(values['transparency'])
        # PlantGL's constructor: the diffuse factor no more than keeps ambient x diffuse in 255.
        for c in self.ambient:
            if self.diffuse * c > 255:
                self.diffuse = min(self.diffuse, 255.0 / c)

    def diffuseColor(self):
        return Color3(*[min(255, int(math.floor(c * self.diffuse))) for c in self.ambient])

    def isSimilar(self, other):
        return all(getattr(self, f) == getattr(other, f, None) for f in _material_defaults)

    def isTexture(self):
        return False


_material_defaults = dict(ambient=Color3(80, 80, 80), diffuse=2.0, specular=Color3(0, 0, 0), emission=Color3(0, 0, 0),
                          shininess=0.2, transparency=0.0)
with_defaults(Material, _material_defaults)
Material.DEFAULT_MATERIAL = Material('DEFAULT_MATERIAL')


# [SECTION] Scene objects
class _Geometry(_SceneObject):
    """PlantGL scene objects a model may build for @g: kept (with PlantGL's field names), not
    drawn by Sprout (a warning names the module that carries them)."""
    _fields = ()

    _defaults = {}

    _vector_defaults = ()

    def __init__(self, *args, **kwargs):
        # Written into the instance's dict directly: models make these by the thousand a step.
        d = self.__dict__
        d['args'], d['kwargs'], d['name'] = args, kwargs, ''
        d.update(zip(self._fields, args))
        d.update(kwargs)
        # PlantGL's defaults: numbers are the class's; a vector, a copy of its own each.
        for field in self._vector_defaults:
            if field not in d:
                d[field] = Vector3(self._defaults[field])

    def apply(self, action):
        """PlantGL's actions (a Discretizer...): action.process(self)."""
        return action.process(self)


_geometry_fields = {
    'Sphere': ('radius', 'slices', 'stacks'), 'Box': ('size',), 'Cylinder': ('radius', 'height', 'solid', 'slices'),
    'Cone': ('radius', 'height', 'solid', 'slices'), 'Frustum': ('radius', 'height', 'taper', 'solid', 'slices'),
    'Disc': ('radius', 'slices'), 'Paraboloid': ('radius', 'height', 'shape', 'solid', 'slices', 'stacks'),
    'Scaled': ('scale', 'geometry'), 'Translated': ('translation', 'geometry'),
    'AxisRotated': ('axis', 'angle', 'geometry'), 'EulerRotated': ('azimuth', 'elevation', 'roll', 'geometry'),
    'Oriented': ('primary', 'secondary', 'geometry'), 'Shape': ('geometry', 'appearance', 'id'),
    'QuadSet': ('pointList', 'indexList'), 'TriangleSet': ('pointList', 'indexList'), 'Polyline': ('pointList',),
    'BezierPatch': ('ctrlPointMatrix',), 'Extrusion': ('axis', 'crossSection', 'scale'), 'Revolution': ('profile',),
    'Swung': ('profileList', 'angleList'), 'Group': ('geometryList',), 'Text': ('string', 'position'), 'Font': (),
    'Texture2D': ('image', 'transformation', 'baseColor'), 'Texture2DTransformation': (),
    'PointSet': ('pointList', 'colorList'),
    'AsymmetricHull': ('negXRadius', 'posXRadius', 'negYRadius', 'posYRadius', 'negXHeight', 'posXHeight', 'negYHeight',
                       'posYHeight', 'bottom', 'top', 'bottomShape', 'topShape', 'slices', 'stacks'),
}
# PlantGL's defaults of the fields (its DEFAULT_* constants): what a field left out reads.
_NOID = 4294967295  # Shape::NOID
_mesh_defaults = dict(ccw=True, solid=False, normalPerVertex=True, colorPerVertex=True, skeleton=None, normalList=None,
                      colorList=None, texCoordList=None, normalIndexList=None, colorIndexList=None,
                      texCoordIndexList=None)
_geometry_defaults = {
    'Sphere': dict(radius=0.5, slices=8, stacks=8), 'Box': dict(size=Vector3(0.5, 0.5, 0.5)),
    'Cylinder': dict(radius=0.5, height=1.0, solid=True, slices=8), 'Cone': dict(radius=0.5, height=1.0, solid=True, slices=8),
    'Frustum': dict(radius=0.5, height=1.0, taper=0.5, solid=True, slices=8), 'Disc': dict(radius=0.5, slices=8),
    'Paraboloid': dict(radius=0.5, height=1.0, shape=2.0, solid=True, slices=8, stacks=8),
    'Scaled': dict(scale=Vector3(1, 1, 1)), 'Translated': dict(translation=Vector3(0, 0, 0)),
    'AxisRotated': dict(axis=Vector3(0, 0, 1), angle=0.0), 'EulerRotated': dict(azimuth=0.0, elevation=0.0, roll=0.0),
    'Oriented': dict(primary=Vector3(1, 0, 0), secondary=Vector3(0, 1, 0)), 'Shape': dict(id=_NOID, parentId=_NOID),
    'Polyline': dict(width=1, colorList=None), 'PointSet': dict(width=1, colorList=None),
    'Texture2D': dict(transformation=None),
    'TriangleSet': dict(_mesh_defaults), 'QuadSet': dict(_mesh_defaults),
    'AsymmetricHull': dict(negXRadius=0.5, posXRadius=0.5, negYRadius=0.5, posYRadius=0.5, negXHeight=0.0,
                           posXHeight=0.0, negYHeight=0.0, posYHeight=0.0, bottom=Vector3(0, 0, -0.5),
                           top=Vector3(0, 0, 0.5), bottomShape=2.0, topShape=2.0, slices=4, stacks=4),
}


class Mesh(_Geometry):
    """PlantGL's meshes (TriangleSet, QuadSet, FaceSet): their points and faces read as given
    (vectors made when asked)."""

    def pointAt(self, i, j=None):
        """Point i, or the j-th point of face i."""
        return Vector3(self.pointList[i] if j is None else self.pointList[self.indexList[i][j]])

    def indexAt(self, i):
        return tuple(self.indexList[i])

    def indexListSize(self):
        return len(self.indexList)

    def faceSize(self, i):
        return len(self.indexList[i])

    def faceCenter(self, i):
        pts = [Vector3(self.pointList[k]) for k in self.indexList[i]]
        return sum(pts[1:], pts[0]) / len(pts)

    def normalAt(self, i):
        return Vector3(self.normalList[i])

    def colorAt(self, i):
        return self.colorList[i]

    def texCoordAt(self, i):
        return self.texCoordList[i]


class Transformed(_Geometry):
    """PlantGL's transformed geometries (Translated, Oriented, Scaled, ...): `geometry` inside."""


# PlantGL's kinds of geometry (isACurve, isASurface, isAVolume) and its explicit ones.
_kinds = dict([(n, 'volume') for n in ('Sphere', 'Box', 'Cylinder', 'Cone', 'Frustum', 'Paraboloid', 'AsymmetricHull',
                                       'Revolution', 'Swung', 'Extrusion')]
              + [(n, 'surface') for n in ('Disc', 'TriangleSet', 'QuadSet', 'BezierPatch')] + [('Polyline', 'curve')])
_explicit = ('TriangleSet', 'QuadSet', 'PointSet', 'Polyline')
_transforms = ('Scaled', 'Translated', 'AxisRotated', 'EulerRotated', 'Oriented')
for _name, _f in _geometry_fields.items():
    _base = Transformed if _name in _transforms else Mesh if _name in ('TriangleSet', 'QuadSet') else _Geometry
    _d = _geometry_defaults.get(_name, {})
    _members = {'_fields': _f, '_defaults': _d, '_kind': _kinds.get(_name, ''), '_explicit': _name in _explicit,
                '_vector_defaults': tuple(k for k, v in _d.items() if isinstance(v, Vector3))}
    _members.update((k, v) for k, v in _d.items() if not isinstance(v, Vector3))
    globals()[_name] = with_defaults(type(_name, (_base,), _members), _d)
del _name, _f, _base, _d, _members


class ImageTexture(_Geometry):
    """PlantGL's ImageTexture: ImageTexture(filename, ...) or ImageTexture(name, filename, ...),
    then repeatS, repeatT, mipmaping."""
    _defaults = dict(mipmaping=True, repeatS=True, repeatT=True)

    def __init__(self, *args, **kwargs):
        args = list(args)
        name = args.pop(0) if len(args) >= 2 and isinstance(args[1], str) else kwargs.pop('name', '')
        _Geometry.__init__(self, **kwargs)
        self.name = name
        for field, value in zip(('filename', 'repeatS', 'repeatT', 'mipmaping'), args):
            self.__dict__[field] = value
        self.__dict__.setdefault('filename', '')

    def isTexture(self):
        return True


with_defaults(ImageTexture, ImageTexture._defaults)
ImageTexture.DEFAULT_MIPMAPING = True
for _k, _v in ImageTexture._defaults.items():
    setattr(ImageTexture, _k, _v)


def _texture_is_texture(self):
    return True


Texture2D.isTexture = _texture_is_texture
# (no baseColor unless one is given: L-Py's parameter code tells a texture's colour by it)
Texture2D.DEFAULT_BASECOLOR = Color4(255, 255, 255, 0)


def _shape_init(self, *args, **kwargs):
    """A Shape without an id gets its own, as PlantGL's (its address, on 32 bits)."""
    _Geometry.__init__(self, *args, **kwargs)
    if self.id == _NOID:
        self.id = id(self) & 0xFFFFFFFF
    if 'appearance' not in self.__dict__:
        self.appearance = Material.DEFAULT_MATERIAL
    if not self.name:
        _shape_set_computed_name(self)


def _shape_set_computed_name(self):
    """PlantGL's: the shape, and its geometry and appearance where they have no name, named
    after its id."""
    for part, prefix in ((getattr(self, 'geometry', None), 'GEOMID'), (getattr(self, 'appearance', None), 'APPID')):
        if isinstance(part, _SceneObject) and not part.isNamed():
            part.name = "%s_%d_%d" % (prefix, self.id, id(part) & 0xFFFFFFFF)
    self.name = "SHAPEID_%d_%d" % (self.id, id(self) & 0xFFFFFFFF)


Shape.setComputedName = _shape_set_computed_name
Shape.NOID = _NOID


Shape.__init__ = _shape_init


# [SECTION] Scene and BoundingBox
class Scene(list):
    """PlantGL's Scene: a list of shapes (`sc += Shape(...)`), kept, not drawn by Sprout."""

    def __init__(self, shapes=()):
        list.__init__(self, shapes if isinstance(shapes, (list, tuple)) else [])
        if isinstance(shapes, str):
            self.read(shapes)

    def read(self, filename, format=''):
        """PlantGL's text files (.geom) read into the scene (lpy/plantgl/plantgl_geomfile.py);
        its binary ones (.bgeom) and other formats are not."""
        import os
        ext = os.path.splitext(str(filename))[1].lower()
        if ext != '.geom':
            raise NotImplementedError("Scene(%r): Sprout's PlantGL reads PlantGL's text scenes (.geom), not %s"
                                      % (filename, ext or 'a file without an extension'))
        from openalea.plantgl._geomfile import read
        self.extend(read(filename))
        return True

    def save(self, filename, format=''):
        """PlantGL's text file (.geom, as PlantGL writes it: lpy/plantgl/plantgl_geomfile.py),
        or a model (.obj, .ply, .glb, .gltf, .stl, .svg) by Sprout's exporters for a scene an
        Lsystem made; PlantGL's binary .bgeom is not written."""
        import os
        ext = os.path.splitext(str(filename))[1].lower()
        if ext == '.geom':
            from openalea.plantgl._geomfile import write
            return write(self, filename)
        if ext not in ('.obj', '.ply', '.glb', '.gltf', '.stl', '.svg'):
            raise NotImplementedError("Scene.save(%r): Sprout writes .geom, .obj, .ply, .glb, .gltf, .stl or .svg, not "
                                      "%s" % (filename, ext or 'a format without an extension'))
        return self.export(filename)

    def merge(self, other):
        self.extend(other)
        return self

    def find(self, id):
        """The shape whose id is `id` (an IndexError where none is, as PlantGL's)."""
        for shape in self:
            if getattr(shape, 'id', None) == id:
                return shape
        raise IndexError('')

    def findSceneObject(self, id):
        return self.find(id)

    def deepcopy(self):
        import copy
        return copy.deepcopy(self)

    def isValid(self):
        return all(getattr(sh, 'isValid', lambda: True)() for sh in self)

    def apply(self, action):
        return all(action.process(sh) is not False for sh in self)

    def getPglId(self):
        return id(self)

    getId = getPglId

    def __iadd__(self, o):
        if isinstance(o, (list, tuple)):
            self.extend(o)
        else:
            self.append(o)
        return self

    def add(self, shape):
        self.append(shape)

    # A scene an Lsystem made (sceneInterpretation): a picture and a model by Sprout's renderer
    # and exporters, when the `sprout` module is there (a script or a notebook): it hands its
    # maker of plants down (_sprout_lpy._scene_plant), as this module is below it.
    def _plant(self):
        made = getattr(self, '_sprout_source', None)
        if made is None:
            raise ValueError("only a scene made by Lsystem.sceneInterpretation is drawn by Sprout")
        from _sprout_lpy import _scene_plant
        maker = _scene_plant()
        if maker is None:
            raise ValueError("a scene is drawn by Sprout's Python module (the sprout package) only")
        return maker(*made)

    def render(self, **kwargs):
        """The scene's picture: numpy (height, width, 4), as sprout.Plant.render."""
        return self._plant().render(**kwargs)

    def export(self, path, **kwargs):
        """Writes the scene as a model (.obj, .ply, .glb, .gltf, .stl, .svg), as sprout.Plant.export."""
        return self._plant().export(path, **kwargs)

    def _repr_png_(self):
        if getattr(self, '_sprout_source', None) is None:
            return None
        return self._plant().png()

    def todict(self):
        """The shapes by id."""
        out = {}
        for shape in self:
            out.setdefault(getattr(shape, 'id', None), []).append(shape)
        return out


class BoundingBox:
    """PlantGL's BoundingBox: BoundingBox(lower, upper), or BoundingBox(x) of a scene, a shape,
    a geometry or a PointSet: the bounds of its points (PlantGL bounds each primitive by its
    formula; Sprout by its mesh, lpy/plantgl/meshes.cpp, the same for unrotated spheres, boxes,
    cylinders, cones and frusta, and for point and face sets)."""

    def __init__(self, lower=(0, 0, 0), upper=None):
        if upper is None and not _is_point(lower):
            lower, upper = _bounds_of(lower)
        elif upper is None:
            upper = lower
        self.lowerLeftCorner, self.upperRightCorner = Vector3(*tuple(lower)[:3]), Vector3(*tuple(upper)[:3])

    def getXMin(self):
        return self.lowerLeftCorner.x

    def getYMin(self):
        return self.lowerLeftCorner.y

    def getZMin(self):
        return self.lowerLeftCorner.z

    def getXMax(self):
        return self.upperRightCorner.x

    def getYMax(self):
        return self.upperRightCorner.y

    def getZMax(self):
        return self.upperRightCorner.z

    def getXRange(self):
        return self.upperRightCorner.x - self.lowerLeftCorner.x

    def getYRange(self):
        return self.upperRightCorner.y - self.lowerLeftCorner.y

    def getZRange(self):
        return self.upperRightCorner.z - self.lowerLeftCorner.z

    def getLowerLeftCorner(self):
        return Vector3(self.lowerLeftCorner)

    def getUpperRightCorner(self):
        return Vector3(self.upperRightCorner)

    def getCenter(self):
        return (self.lowerLeftCorner + self.upperRightCorner) / 2

    def getSize(self):
        return (self.upperRightCorner - self.lowerLeftCorner) / 2

    def contains(self, p):
        p = tuple(p)
        return all(self.lowerLeftCorner[k] <= p[k] <= self.upperRightCorner[k] for k in range(3))

    def extend(self, other):
        """This box grown to hold `other` (a box or a point)."""
        lo, hi = (other.lowerLeftCorner, other.upperRightCorner) if isinstance(other, BoundingBox) else (other, other)
        self.lowerLeftCorner = Vector3(*[min(a, b) for a, b in zip(self.lowerLeftCorner, tuple(lo))])
        self.upperRightCorner = Vector3(*[max(a, b) for a, b in zip(self.upperRightCorner, tuple(hi))])
        return self

    def __add__(self, other):
        return BoundingBox(self.lowerLeftCorner, self.upperRightCorner).extend(other)

    def __repr__(self):
        return "BoundingBox(%r,%r)" % (self.lowerLeftCorner, self.upperRightCorner)


def _is_point(v):
    try:
        return len(v) == 3 and all(isinstance(c, (int, float)) for c in v)
    except TypeError:
        return False


def _bounds_of(obj):
    """The lower and upper corners of what `obj` draws."""
    if type(obj).__name__ == 'PointSet':
        pts = [tuple(p) for p in getattr(obj, 'pointList', ())]
        if not pts:
            raise ValueError("BoundingBox: an empty PointSet has no bounds")
        return [min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]
    from _sprout_lpy import _mesh_bounds
    bounds = _mesh_bounds(obj)
    if bounds is None:
        raise ValueError("BoundingBox: %s draws nothing to bound" % type(obj).__name__)
    return bounds


# [SECTION] Viewer
eStatic, eAnimatedPrimitives, eAnimatedScene = 0, 1, 2


class _Viewer:
    class _Any:
        def __getattr__(self, name):
            return _Viewer._Any()

        def __call__(self, *args, **kwargs):
            _warn("Viewer: Sprout has no PlantGL viewer; the call does nothing")
            return None

    def __getattr__(self, name):
        return _Viewer._Any()


Viewer = _Viewer()
