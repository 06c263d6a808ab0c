# openalea.plantgl._object, a part of Sprout's PlantGL (openalea.plantgl.all gathers the parts:
# plantgl.py): what every PlantGL scene object has (its SceneObject and Geometry members: a
# name, ids, deepcopy, validity, what kind of geometry it is), and the DEFAULT_* constants and
# is<Field>ToDefault() methods each class has for its fields. The scene objects (plantgl_scene.py)
# and the curves and patches (plantgl_curves.py) take them from here.
import copy as _copy
import re as _re


class _SceneObject:
    """PlantGL's SceneObject: a name (empty until set), its ids, deepcopy, isValid."""

    _kind = ''  # 'curve', 'surface', 'volume' or '' (PlantGL's isACurve / isASurface / isAVolume)
    _explicit = False  # PlantGL's isExplicit: made of points given (meshes, point sets, polylines)

    def getName(self):
        return self.__dict__.get('name', '')

    def setName(self, name):
        self.name = str(name)

    def isNamed(self):
        return bool(self.__dict__.get('name', ''))

    def getObjectId(self):
        return id(self)

    getPglId = getObjectId

    def getPglReferenceCount(self):
        import sys
        return sys.getrefcount(self) - 2

    def isValid(self):
        return True

    def deepcopy(self):
        return _copy.deepcopy(self)

    def recast(self):
        return self

    def isACurve(self):
        return self._kind == 'curve'

    def isASurface(self):
        return self._kind == 'surface'

    def isAVolume(self):
        return self._kind == 'volume'

    def isExplicit(self):
        return self._explicit


# Fields PlantGL spells its own way: (its DEFAULT_ constant, the word in is<Word>ToDefault).
_SPELLED = {'ccw': ('DEFAULT_CCW', 'CCW'), 'colorPerVertex': ('DEFAULT_COLORPERVERTEX', 'ColorPerVertex'),
            'normalPerVertex': ('DEFAULT_NORMALPERVERTEX', 'NormalPerVertex')}


def _constant_name(field):
    """PlantGL's DEFAULT_ constant of a field: negXRadius -> DEFAULT_NEG_X_RADIUS."""
    if field in _SPELLED:
        return _SPELLED[field][0]
    return "DEFAULT_" + _re.sub(r"(?<!^)(?=[A-Z])", "_", field).upper()


def with_defaults(cls, defaults):
    """`cls` given PlantGL's DEFAULT_* constants and is<Field>ToDefault() methods of `defaults`
    ({field: value})."""
    for field, value in defaults.items():
        setattr(cls, _constant_name(field), value)

        def is_default(self, field=field, value=value):
            return getattr(self, field, value) == value

        word = _SPELLED[field][1] if field in _SPELLED else field[0].upper() + field[1:]
        is_default.__name__ = "is%sToDefault" % word
        setattr(cls, is_default.__name__, is_default)
    return cls
