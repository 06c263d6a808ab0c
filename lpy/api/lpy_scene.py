# The scenes of openalea.lpy's Lsystem (lpy/api/lpy_lsystem.py) as PlantGL's: what Sprout's
# turtle drew (lpy/api/session.cpp sceneOf) made into a Scene of PlantGL's shapes with the ids
# of the modules that drew them; a scene shown in a notebook.

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
            # PlantGL's turtle's: its leaf 'l' scaled, turned to the turtle's frame
            # (Oriented(up, -left): the leaf along the heading) and placed (pglturtledrawer.cpp).
            h, up = Vector3(*part[3]), Vector3(*part[6])
            geometry = Translated(Vector3(*part[2]), Oriented(up, h ^ up, Scaled(Vector3(part[4], part[4], part[4]),
                                                                                  _leaf(TriangleSet))))
            colour = part[5]
        else:
            geometry = _drawn_mesh(TriangleSet, Vector3, part[2], part[3])
            colour = part[4]
        scene.append(Shape(geometry, _material(colour), ident))
    return scene


def _leaf(TriangleSet):
    """PlantGL's turtle's surface 'l' (PglTurtle::defaultValue): six triangles in the y-z plane,
    from 0 to 1 along z, a quarter wide on each side."""
    points = [(0, 0, 0.5), (0, 0, 0), (0, -0.25, 1. / 3), (0, -0.25, 2. / 3), (0, 0, 1), (0, 0.25, 2. / 3), (0, 0.25, 1. / 3)]
    return TriangleSet(points, [(0, 2, 1), (0, 3, 2), (0, 4, 3), (0, 5, 4), (0, 6, 5), (0, 1, 6)])


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
