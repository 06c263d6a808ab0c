# openalea.plantgl._light, a part of Sprout's PlantGL (openalea.plantgl.all gathers the parts:
# plantgl.py; openalea.plantgl.light and .light.light are that module too): PlantGL's light
# module (its light/light.py, sky.py, sun.py, utils.py, read line by line) with the z-buffer it
# projects scenes with (ZBufferEngine: lpy/plantgl/zbuffer.cpp, through bind_light.cpp), and
# surface(). The light reaching each shape of a scene from a set of directions: the scene seen
# from each direction by an orthographic camera, each shape's pixels counted, times the pixel's
# area and the direction's weight. Its own file: the light model.
#
# Index of this file:
#   [SECTION] ZBufferEngine
#   [SECTION] Directions: the sky's turtle, the sun, azimuths and elevations
#   [SECTION] Interception
#   [SECTION] surface()
import math as _math
from math import radians, degrees, sin

from _sprout_lpy import _ZBuffer, _shape_mesh
from openalea.plantgl._vectors import Vector3, Matrix3, cross
from openalea.plantgl._scene import BoundingBox, PointSet


# [SECTION] ZBufferEngine
eDepthOnly, eColorBased, eIdBased, eIdAndColorBased = 0, 1, 2, 3
eOrientationBased, eColorAndOrientationBased, eIdAndOrientationBased, eIdAndColorAndOrientationBased = 4, 5, 6, 7
eNoCulling, eBackFaceCulling, eFrontFaceCulling, eBothFaceCulling = 0, 1, 2, 3
ePrimitiveIdBased, eShapeIdBased = 0, 1


class ZBufferEngine:
    """PlantGL's ZBufferEngine as its light module drives it: an id buffer seen through an
    orthographic camera (setOrthographicCamera, lookAt), filled by process(scene) with each
    shape's id, counted by idhistogram(). Sprout draws ids only (no colours, no culling), with
    shape ids (ePrimitiveIdBased is refused)."""

    def __init__(self, imageWidth=800, imageHeight=600, renderingStyle=eColorBased, backGroundColor=None,
                 defaultId=0xFFFFFFFF, multithreaded=True, faceculling=eNoCulling, idPolicy=eShapeIdBased):
        if idPolicy != eShapeIdBased:
            raise NotImplementedError("ZBufferEngine: Sprout counts shapes' ids only (eShapeIdBased), not primitives'")
        if faceculling != eNoCulling:
            raise NotImplementedError("ZBufferEngine: Sprout's z-buffer culls no faces (eNoCulling)")
        self._z = _ZBuffer(int(imageWidth), int(imageHeight), int(defaultId))
        self.renderingStyle, self.multithreaded, self._camera = renderingStyle, multithreaded, False

    def getRenderingStyle(self):
        return self.renderingStyle

    def setOrthographicCamera(self, left, right, bottom, top, near, far):
        self._z.setOrthographicCamera(float(left), float(right), float(bottom), float(top), float(near), float(far))
        self._camera = True

    def lookAt(self, eyePosition, center, up):
        self._z.lookAt(tuple(eyePosition), tuple(center), tuple(up))

    def process(self, scene):
        if not self._camera:
            raise NotImplementedError("ZBufferEngine: Sprout's z-buffer has an orthographic camera only (setOrthographicCamera)")
        self._z.process(scene if isinstance(scene, (list, tuple)) else [scene])

    def worldToRaster(self, position):
        return Vector3(*self._z.worldToRaster(tuple(position)))

    def idhistogram(self, solidangle=True):
        """[(id, pixels)]: an orthographic camera's pixels all count 1."""
        if not self.renderingStyle & eIdBased:
            return None
        return [(i, n) for i, n in self._z.idhistogram()]

    def periodizeBuffer(self, *args, **kwargs):
        raise NotImplementedError("ZBufferEngine.periodizeBuffer (an infinite canopy) is not in Sprout")


# [SECTION] Directions: the sky's turtle, the sun, azimuths and elevations
# PlantGL's light/sky.py: the 46 directions of the sky's turtle and their weights.
elevations = [9.23] * 10 + [10.81] * 5 + [26.57] * 5 + [31.08] * 10 + [47.41] * 5 + [52.62] * 5 + [69.16] * 5 + [90.0]
azimuths = [12.23, 59.77, 84.23, 131.77, 156.23, 203.77, 228.23, 275.77, 300.23, 347.77, 36.0, 108.0, 180.0, 252.0,
            324.0, 0.0, 72.0, 144.0, 216.0, 288.0, 23.27, 48.73, 95.27, 120.73, 167.27, 192.73, 239.27, 264.73, 311.27,
            336.73, 0.0, 72.0, 144.0, 216.0, 288.0, 36.0, 108.0, 180.0, 252.0, 324.0, 0.0, 72.0, 144.0, 216.0, 288.0,
            180.0]
weights = ([0.02013846416430755] * 10 + [0.023124393865618653] * 5 + [0.029825786654911167] * 5
           + [0.03828923988020318] * 10 + [0.0470922662962344] * 5 + [0.051959000044448256] * 5
           + [0.05421450172832646] * 5 + [0.04851833940010471])


def sky_turtle():
    return list(zip(elevations, azimuths, weights))


def soc_sky_sources(ghi=1):
    return [(el, az, w * ghi) for el, az, w in sky_turtle()]


def to_horizontal_irradiance(normal_irradiance, elevation):
    if elevation <= 0:
        return 0
    return normal_irradiance * sin(radians(elevation))


def to_normal_irradiance(horizontal_irradiance, elevation):
    if elevation <= 0:
        return horizontal_irradiance
    return horizontal_irradiance / sin(radians(elevation))


def azel2vect(az, el, north=0):
    """The direction light comes along from azimuth `az` and elevation `el` (degrees, azimuths
    clockwise from the north, `north` the angle from X+ to the north, counter-clockwise)."""
    azimuth = radians(- north - az)
    zenith = radians(90 - el)
    v = -Vector3(Vector3.Spherical(1., azimuth, zenith))
    v.normalize()
    return v


def elaz2vect(el, az, north=0):
    return azel2vect(az, el, north)


def vect2azel(vector, north=0):
    x, y, z = tuple(-Vector3(vector))
    r = _math.sqrt(x * x + y * y + z * z)
    phi, theta = _math.acos(z / r), _math.atan2(y, x)  # Vector3.Spherical(v)
    return (- north - degrees(theta), 90 - degrees(phi))


def vect2elaz(vector, north=0):
    az, el = vect2azel(vector, north)
    return (el, az)


def estimate_dir_vectors(directions, north=0, horizontal=False):
    """[(direction vector, irradiance)] of [(elevation, azimuth, irradiance)]."""
    results = []
    for el, az, irr in directions:
        direction = azel2vect(az, el, north)
        if horizontal:
            irr = to_horizontal_irradiance(irr, el)
        results.append((direction, irr))
    return results


def getProjectionMatrix(forward, up=Vector3(0, 0, 1)):
    """The matrix taking world coordinates to the frame whose z is `forward` (normalised in
    place, as PlantGL does) and whose y is `up` made orthogonal to it."""
    forward.normalize()
    up.normalize()
    side = cross(up, forward)
    side.normalize()
    up = cross(forward, side)
    up.normalize()
    return Matrix3(side, up, forward).inverse()


def projectedBBox(bbx, direction, up):
    """The bounding box of `bbx`'s corners in the frame of getProjectionMatrix(direction, up)."""
    from itertools import product
    proj = getProjectionMatrix(direction, up)
    pts = [proj * Vector3(*pt) for pt in product([bbx.getXMin(), bbx.getXMax()], [bbx.getYMin(), bbx.getYMax()],
                                                  [bbx.getZMin(), bbx.getZMax()])]
    return BoundingBox(PointSet(pts))


# PlantGL's light/sun.py (NOAA's formulas).
def day_of_year(dt):
    return dt.timetuple().tm_yday


def solar_declination(gamma):
    return (0.006918 - 0.399912 * _math.cos(gamma) + 0.070257 * _math.sin(gamma) - 0.006758 * _math.cos(2 * gamma)
            + 0.000907 * _math.sin(2 * gamma) - 0.002697 * _math.cos(3 * gamma) + 0.00148 * _math.sin(3 * gamma))


def equation_of_time(gamma):
    return (229.18 * (0.000075 + 0.001868 * _math.cos(gamma) - 0.032077 * _math.sin(gamma)
                      - 0.014615 * _math.cos(2 * gamma) - 0.040849 * _math.sin(2 * gamma)))


def solar_hour_angle(solar_time_minutes):
    return _math.radians((solar_time_minutes / 4.0) - 180.0)


def sun_position(dt, latitude, longitude):
    """(elevation, azimuth) in degrees of the sun at `dt` (a timezone-aware datetime)."""
    from datetime import timezone
    if dt.tzinfo is None:
        raise ValueError("Datetime must be timezone-aware.")
    dt_utc = dt.astimezone(timezone.utc)
    gamma = 2 * _math.pi * (day_of_year(dt_utc) - 1) / 365
    decl = solar_declination(gamma)
    e = equation_of_time(gamma)
    local_offset = dt.utcoffset().total_seconds() / 3600.0
    minutes = dt.hour * 60 + dt.minute + dt.second / 60
    h = solar_hour_angle(minutes + e + 4 * longitude - 60 * local_offset)
    lat = _math.radians(latitude)
    elevation = _math.asin(_math.sin(lat) * _math.sin(decl) + _math.cos(lat) * _math.cos(decl) * _math.cos(h))
    azimuth = _math.atan2(-_math.sin(h), _math.cos(lat) * _math.tan(decl) - _math.sin(lat) * _math.cos(h))
    return _math.degrees(elevation), (_math.degrees(azimuth) + 360) % 360


SOLAR_CONSTANT = 1361


def relative_optical_air_mass(elevation):
    if elevation <= 0.1:
        return 40
    elevation = max(elevation, 0.1)
    return 1.0 / (_math.sin(_math.radians(elevation)) + 0.50572 * (elevation + 6.07995) ** (-1.6364))


def direct_normal_irradiance(elevation, tau=0.7):
    assert tau >= 0.0 and tau <= 1.0, "Tau must be in [0, 1]"
    if elevation <= 0:
        return 0.0
    return SOLAR_CONSTANT * tau ** (relative_optical_air_mass(elevation) ** 0.678)


def direct_horizontal_irradiance(elevation, tau=0.7):
    assert tau >= 0.0 and tau <= 1.0, "Tau must be in [0, 1]"
    return to_horizontal_irradiance(direct_normal_irradiance(elevation, tau), elevation)


def diffuse_horizontal_irradiance(elevation, tau=0.7):
    assert tau >= 0.0 and tau <= 1.0, "Tau must be in [0, 1]"
    if elevation <= 0:
        return 0.0
    m = relative_optical_air_mass(elevation)
    diffuse_ratio = 0.271 - 0.294 * tau ** (m ** 0.576) * sin(radians(elevation))
    return SOLAR_CONSTANT * max(min(diffuse_ratio, 1.0), 0.0)


def total_horizontal_irradiance(elevation, tau=0.7):
    assert tau >= 0.0 and tau <= 1.0, "Tau must be in [0, 1]"
    dhi = min(max(diffuse_horizontal_irradiance(elevation, tau), 0.0), SOLAR_CONSTANT)
    return direct_horizontal_irradiance(elevation, tau) + dhi


def sun_sources(dates, latitude, longitude, irradiance, tau=0.7):
    """[(elevation, azimuth, weight)] of the sun at each of `dates` where it is above the
    horizon, `irradiance` shared in proportion to each one's direct horizontal irradiance.
    (PlantGL 3.22's own sun_sources names a `tau` it never defines, and raises NameError; this
    is the computation it spells out, with its default atmosphere, tau = 0.7.)"""
    sources = []
    for dt in dates:
        elevation, azimuth = sun_position(dt, latitude, longitude)
        if elevation > 0:
            ghi, dhi = total_horizontal_irradiance(elevation, tau), diffuse_horizontal_irradiance(elevation, tau)
            sources.append((elevation, azimuth, ghi - dhi))
    total = sum(direct for _, _, direct in sources)
    return [(el, az, direct * irradiance / total) for el, az, direct in sources]


# [SECTION] Interception
eShapeBased, eTriangleBased = range(2)
eOpenGLProjection, eZBufferProjection, eTriangleProjection, eCaribu = range(4)
MethodNames = {eOpenGLProjection: "OpenGL Projection", eZBufferProjection: "Z-Buffer Projection",
               eTriangleProjection: "Triangle Projection", eCaribu: "Caribu"}


def caribu_available():
    try:
        import openalea.caribu  # noqa: F401
        return True
    except ImportError:
        return False


def available_projection_methods(primitive=eShapeBased):
    """The methods Sprout has: the z-buffer's projection."""
    return [eZBufferProjection]


def diffuseInterception(scene, ghi, screenresolution=None):
    """The light each shape intercepts from the sky's turtle (46 directions), `ghi` shared by
    their weights: {shape id: light}."""
    return directionalInterception(scene, directions=soc_sky_sources(ghi), screenresolution=screenresolution)


def directInterception(scene, dates, irradiance, latitude=43.36, longitude=3.52, screenresolution=None):
    """The light each shape intercepts from the sun at each of `dates` (timezone-aware)."""
    return directionalInterception(scene, sun_sources(dates, latitude, longitude, irradiance),
                                   screenresolution=screenresolution)


def totalInterception(scene, ghi, dhi, dates, latitude=43.36, longitude=3.52, screenresolution=None):
    directions = soc_sky_sources(dhi) + sun_sources(dates, latitude, longitude, ghi - dhi)
    return directionalInterception(scene, directions=directions, screenresolution=screenresolution)


def directionalInterception(scene, directions, north=0, horizontal=False, method=eZBufferProjection,
                            primitive=eShapeBased, **args):
    """{shape id: light} from [(elevation, azimuth, irradiance)]."""
    return directionalInterception_from_dir_vectors(scene, estimate_dir_vectors(directions, north, horizontal), method,
                                                    primitive, **args)


def directionalInterception_from_dir_vectors(scene, directions, method=eZBufferProjection, primitive=eShapeBased,
                                             **args):
    if method != eZBufferProjection:
        raise NotImplementedError("directionalInterception: Sprout projects with the z-buffer only "
                                  "(eZBufferProjection), not with %s" % MethodNames.get(method, method))
    return directionalInterception_zbuffer_from_dir_vectors(scene, directions, primitive=primitive, **args)


def directionalInterception_zbuffer(scene, directions, north=0, horizontal=False, screenresolution=None,
                                    multithreaded=True, infinitize=None, primitive=eShapeBased):
    return directionalInterception_zbuffer_from_dir_vectors(scene, estimate_dir_vectors(directions, north, horizontal),
                                                            screenresolution, multithreaded, infinitize, primitive)


def directionalInterception_zbuffer_from_dir_vectors(scene, directions, screenresolution=None, multithreaded=True,
                                                     infinitize=None, primitive=eShapeBased):
    """PlantGL's: for each direction, the scene's bounding box seen along it fixes an image of
    pixels `screenresolution` wide (a hundredth of the box's largest side by default); each
    shape's pixels times a pixel's area times the direction's weight."""
    if primitive != eShapeBased:
        raise NotImplementedError("directionalInterception: Sprout counts shapes (eShapeBased), not triangles")
    if infinitize is not None:
        raise NotImplementedError("directionalInterception: an infinite canopy (infinitize) is not in Sprout")
    bbox = BoundingBox(scene)
    d_factor = max(bbox.getXRange(), bbox.getYRange(), bbox.getZRange())
    shapeLight = {}
    if screenresolution is None:
        screenresolution = d_factor / 100
    pixsize = screenresolution * screenresolution
    for direction, wg in directions:
        direction = Vector3(direction)
        up = direction.anOrthogonalVector()
        pjbbx = projectedBBox(bbox, direction, up)
        worldWidth, worldheight = pjbbx.getXRange(), pjbbx.getYRange()
        w = max(2, int(_math.ceil(worldWidth / screenresolution)) + 1)
        h = max(2, int(_math.ceil(worldheight / screenresolution)) + 1)
        worldWidth, worldheight = w * screenresolution, h * screenresolution
        z = ZBufferEngine(w, h, renderingStyle=eIdBased, idPolicy=eShapeIdBased)
        z.multithreaded = multithreaded
        z.setOrthographicCamera(-worldWidth / 2., worldWidth / 2., -worldheight / 2., worldheight / 2., d_factor,
                                3 * d_factor)
        eyepos = bbox.getCenter() - direction * d_factor * 2
        z.lookAt(eyepos, bbox.getCenter(), up)
        z.process(scene)
        for shid, val in z.idhistogram(False) or ():
            shapeLight[shid] = shapeLight.get(shid, 0) + val * pixsize * wg
    return shapeLight


def scene_irradiance(scene, directions, north=0, horizontal=False, scene_unit='m', method=eZBufferProjection,
                     primitive=eShapeBased, **args):
    """{'area': {id: m2}, 'irradiance': {id: light per m2}, 'interception': {id: light}} (a
    pandas DataFrame where pandas is installed, as PlantGL gives it)."""
    assert method in [eZBufferProjection, eTriangleProjection, eCaribu, eOpenGLProjection], "Unknown method for projection"
    interception = directionalInterception(scene=scene, directions=directions, north=north, horizontal=horizontal,
                                           method=method, primitive=primitive, **args)
    return _format_irradiance(scene, interception, primitive, scene_unit)


def _format_irradiance(scene, interception, primitive, scene_unit='m'):
    try:
        import pandas

        def convert(a):
            res = pandas.DataFrame(a)
            res.fillna(0, inplace=True)
            return res
    except ImportError:
        def convert(a):
            return a
    units = {'mm': 0.001, 'cm': 0.01, 'dm': 0.1, 'm': 1, 'dam': 10, 'hm': 100, 'km': 1000}
    conv_unit2 = units[scene_unit] ** 2
    byid = {}
    for sh in scene:
        byid.setdefault(getattr(sh, 'id', None), []).append(sh)
    surfaces = dict([(sid, conv_unit2 * sum([surface(sh.geometry) for sh in shapes])) for sid, shapes in byid.items()])
    irradiance = {sid: conv_unit2 * value / surfaces[sid] for sid, value in interception.items()}
    if conv_unit2 != 1:
        interception = {sid: conv_unit2 * value for sid, value in interception.items()}
    return convert({'area': surfaces, 'irradiance': irradiance, 'interception': interception})


# [SECTION] surface()
_TWO_PI = 6.2831853072  # PlantGL's GEOM_TWO_PI


def _triangle_area(a, b, c):
    u, v = Vector3(b) - Vector3(a), Vector3(c) - Vector3(a)
    return abs(cross(u, v)) / 2


def surface(obj, *points):
    """PlantGL's surface(): a triangle's area (three points), or a shape's: the formulas of
    PlantGL's SurfComputer for its spheres, boxes, cylinders, cones, frusta and discs (through
    translations and rotations), the area of its triangles for any other."""
    if points:
        return _triangle_area(obj, *points[:2])
    name = type(obj).__name__
    if name == 'Shape':
        return surface(obj.geometry)
    if name in ('Scene', 'Group') or isinstance(obj, (list, tuple)):
        items = obj.geometryList if name == 'Group' else obj
        return sum(surface(o) for o in items)
    if name in ('Translated', 'AxisRotated', 'EulerRotated', 'Oriented'):
        return surface(obj.geometry)
    formula = _surface_formulas.get(name)
    if formula is not None:
        return formula(obj)
    mesh = _shape_mesh(obj)
    if mesh is None:
        return 0.0
    pts = mesh[0]
    return sum(_triangle_area(pts[i], pts[j], pts[k]) for i, j, k in mesh[1])


def _field(obj, name, default):
    return float(getattr(obj, name, default))


def _solid(obj):
    return bool(getattr(obj, 'solid', True))


# PlantGL's SurfComputer's formulas as it writes them, with its GEOM_TWO_PI (a Disc's is its
# perimeter, 2 pi r).
def _cone_surface(obj):
    r, h = _field(obj, 'radius', 0.5), _field(obj, 'height', 1)
    if not _solid(obj):
        return _TWO_PI * r * _math.sqrt(r * r + h * h) / 2
    return _TWO_PI * r * (r + _math.sqrt(r * r + h * h)) / 2


def _cylinder_surface(obj):
    r, h = _field(obj, 'radius', 0.5), _field(obj, 'height', 1)
    return _TWO_PI * r * h if not _solid(obj) else _TWO_PI * r * (r + h)


def _frustum_surface(obj):
    r, h, taper = _field(obj, 'radius', 0.5), _field(obj, 'height', 1), _field(obj, 'taper', 0.5)
    rtaper = abs(1 - taper)
    if not rtaper > 1e-5:
        return _cylinder_surface(obj)
    top, cone_h, hdif = r * taper, h / rtaper, (h * taper) / rtaper
    side = r * _math.sqrt(r * r + cone_h * cone_h) - top * _math.sqrt(top * top + hdif * hdif)
    return _TWO_PI * (side if not _solid(obj) else r + top + side) / 2


def _box_surface(obj):
    x, y, z = tuple(Vector3(getattr(obj, 'size', (0.5, 0.5, 0.5))))
    return 8 * (x * y + x * z + y * z)


_surface_formulas = {
    'Sphere': lambda o: _TWO_PI * 2 * _field(o, 'radius', 0.5) ** 2,
    'Disc': lambda o: _TWO_PI * _field(o, 'radius', 0.5),
    'Box': _box_surface, 'Cone': _cone_surface, 'Cylinder': _cylinder_surface, 'Frustum': _frustum_surface,
}
