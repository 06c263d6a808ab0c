# openalea.plantgl._geomfile, a part of Sprout's PlantGL imported when a scene is saved to or
# read from PlantGL's text files (.geom): Scene.save and Scene(file) of plantgl_scene.py.
# Written as PlantGL's printer writes them (src/cpp/plantgl/algo/codec/printer.cpp): each
# shape's geometry and appearance named at the top level (an appearance shared by shapes once),
# then the Shape naming them; nested objects written in place, without a name; a field only
# where it is not its default; angles in degrees. Numbers are written in full (PlantGL writes
# six digits) so that Sprout reads back what it wrote. Read as PlantGL's parser reads them
# (scne_parser.yy): `Type [Name] { Field value ... }`, a value a number, True/False, "text",
# <x, y[, z[, w]]>, [ list ], an object in place or the name of one before; # starts a comment.
# What is read: the objects Sprout's PlantGL has (plantgl_scene.py); another type is an error
# at its line. PlantGL's binary files (.bgeom) are neither written nor read.
import re as _re

from openalea.plantgl import _scene
from openalea.plantgl._vectors import Vector2, Vector3, Vector4, _Vec

_ANGLES = {'AxisRotated': ('angle',), 'EulerRotated': ('azimuth', 'elevation', 'roll')}
_COLOURS = ('ambient', 'specular', 'emission')
# PlantGL's constants for degrees (src/cpp/plantgl/math/util_math.h: GEOM_DEG, GEOM_RAD): an
# angle read is the same number as PlantGL reads.
_DEG, _RAD = 57.295779513, 0.01745329252
_MATERIAL = ('ambient', 'diffuse', 'specular', 'emission', 'shininess', 'transparency')


# [SECTION] writing
def _number(v):
    if isinstance(v, bool):
        return 'True' if v else 'False'
    if isinstance(v, int):
        return str(v)
    r = repr(float(v))
    return r[:-2] if r.endswith('.0') else r


def _is_point(v):
    return isinstance(v, _Vec) or (isinstance(v, tuple) and 2 <= len(v) <= 4 and
                                   all(isinstance(c, (int, float)) and not isinstance(c, bool) for c in v))


def _value(v, indent, field=''):
    """A field's value as PlantGL writes it; an index list's items as [i,j,k]."""
    pad = '    ' * indent
    if isinstance(v, (bool, int, float)):
        return _number(v)
    if isinstance(v, str):
        return '"%s"' % v.replace('"', '\\"')
    if isinstance(v, (_scene._Geometry, _scene.Material)):
        return _object(v, '', indent)
    if _is_point(v):
        return '<%s>' % ','.join(_number(c) for c in tuple(v))
    if field.lower().endswith('indexlist'):
        rows = ['%s    [%s]' % (pad, ','.join(str(int(c)) for c in row)) for row in v]
    else:
        rows = [pad + '    ' + _value(x, indent + 1) for x in v]
    return '[ \n%s\n%s]' % (', \n'.join(rows), pad)


def _fields(obj):
    """(field, value) of an object that are not its defaults, in its class's order."""
    kind = type(obj).__name__
    if isinstance(obj, _scene.Material):
        return [(f, getattr(obj, f)) for f in _MATERIAL if getattr(obj, f) != _scene._material_defaults[f]]
    defaults = _scene._geometry_defaults.get(kind, {})
    names = list(obj._fields) + [f for f in defaults if f not in obj._fields]
    out = []
    for f in names:
        v = obj.__dict__.get(f, defaults.get(f))
        if v is None or (f in defaults and _same(v, defaults[f])):
            continue
        if f in _ANGLES.get(kind, ()):
            v = v * _DEG
        out.append((f, v))
    return out


def _same(a, b):
    try:
        return a == b or (_is_point(a) and _is_point(b) and tuple(a) == tuple(b))
    except (TypeError, ValueError):
        return False


def _object(obj, name, indent):
    pad = '    ' * indent
    lines = ['%s %s{ ' % (type(obj).__name__, name + ' ' if name else '')]
    for f, v in _fields(obj):
        lines.append('%s    %s %s' % (pad, f[0].upper() + f[1:], _value(v, indent + 1, f)))
    return '\n'.join(lines) + '\n%s}' % pad


def write(scene, filename):
    """The scene as PlantGL's text file, written whole or not at all."""
    import os
    import tempfile
    parts, names = [], {}

    def named(obj, prefix, shape):
        if id(obj) in names:
            return names[id(obj)], False
        name = obj.name if getattr(obj, 'name', '') else '%s_%d_%d' % (prefix, shape.id, id(obj) & 0xFFFFFFFF)
        names[id(obj)] = name
        return name, True

    for shape in scene:
        geometry = getattr(shape, 'geometry', None)
        appearance = getattr(shape, 'appearance', None)
        fields = ['    Id  %d' % int(shape.id)]
        for obj, prefix, field in ((geometry, 'GEOMID', 'Geometry'), (appearance, 'APPID', 'Appearance')):
            if obj is None:
                continue
            name, new = named(obj, prefix, shape)
            if new:
                parts.append(_object(obj, name, 0) + '\n\n')
            fields.append('    %s  %s' % (field, name))
        name = shape.name if getattr(shape, 'name', '') else 'SHAPEID_%d_%d' % (shape.id, id(shape) & 0xFFFFFFFF)
        parts.append('Shape %s { \n%s\n}\n\n' % (name, '\n'.join(fields)))
    folder = os.path.dirname(os.path.abspath(str(filename)))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix='.sprout-', suffix='.geom')
    try:
        with os.fdopen(fd, 'w') as f:
            f.write('\n'.join(parts))
        os.replace(tmp, str(filename))
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return True


# [SECTION] reading
_TOKEN = _re.compile(r'\s+|#[^\n]*|"(?:[^"\\]|\\.)*"|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[A-Za-z_][A-Za-z0-9_.]*|[{}\[\]<>,]')


class GeomError(ValueError):
    pass


def _tokens(text, filename):
    out, pos, line = [], 0, 1
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise GeomError('%s:%d: %r is not PlantGL\'s text format' % (filename, line, text[pos]))
        t = m.group(0)
        if not (t[0].isspace() or t[0] == '#'):
            out.append((t, line))
        line += t.count('\n')
        pos = m.end()
    return out


class _Reader:
    def __init__(self, text, filename):
        self.toks, self.i, self.file, self.named = _tokens(text, filename), 0, filename, {}

    def error(self, message):
        line = self.toks[min(self.i, len(self.toks) - 1)][1] if self.toks else 1
        raise GeomError('%s:%d: %s' % (self.file, line, message))

    def peek(self, k=0):
        return self.toks[self.i + k][0] if self.i + k < len(self.toks) else None

    def take(self, expected=None):
        t = self.peek()
        if t is None:
            self.error('the file ends inside an object')
        if expected is not None and t != expected:
            self.error('%r where %r was expected' % (t, expected))
        self.i += 1
        return t

    def value(self):
        t = self.peek()
        if t is None:
            self.error('the file ends where a value was expected')
        if t == '<':
            self.take()
            cs = [self.number()]
            while self.peek() == ',':
                self.take()
                cs.append(self.number())
            self.take('>')
            return tuple(cs)
        if t == '[':
            self.take()
            items = []
            while self.peek() != ']':
                items.append(self.value())
                if self.peek() == ',':
                    self.take()
            self.take(']')
            return items
        if t[0] == '"':
            self.take()
            return _re.sub(r'\\(.)', r'\1', t[1:-1])
        if t in ('True', 'False', 'TRUE', 'FALSE', 'true', 'false'):
            self.take()
            return t.lower() == 'true'
        if t[0] in '+-.0123456789':
            return self.number()
        if self.peek(1) == '{' or (self.peek(2) == '{' and self.peek(1) not in ('<', '[', '{')):
            return self.object()
        self.take()
        if t not in self.named:
            self.error('%r names no object before it' % t)
        return self.named[t]

    def number(self):
        t = self.take()
        try:
            return int(t) if _re.fullmatch(r'[-+]?\d+', t) else float(t)
        except ValueError:
            self.error('%r is not a number' % t)

    def object(self):
        kind = self.take()
        name = self.take() if self.peek() != '{' else ''
        self.take('{')
        fields = {}
        while self.peek() != '}':
            field = self.take()
            if not _re.fullmatch(r'[A-Za-z_]\w*', field):
                self.error('%r where a field name was expected' % field)
            fields[field[0].lower() + field[1:]] = self.value()
        self.take('}')
        obj = self.make(kind, fields)
        if name:
            obj.name = name
            self.named[name] = obj
        return obj

    def make(self, kind, fields):
        if kind == 'Material':
            for f in _COLOURS:
                if isinstance(fields.get(f), (int, float)):
                    fields[f] = (fields[f],) * 3
            unknown = set(fields) - set(_MATERIAL)
            if unknown:
                self.error('Material has no field %s' % ', '.join(sorted(unknown)))
            return _scene.Material(**fields)
        cls = getattr(_scene, kind, None)
        if kind not in _scene._geometry_fields or cls is None:
            self.error("%s: a type of object Sprout's PlantGL does not read" % kind)
        for f in _ANGLES.get(kind, ()):
            if f in fields:
                fields[f] = fields[f] * _RAD
        for f, v in list(fields.items()):
            if isinstance(v, tuple) and all(isinstance(c, (int, float)) for c in v):
                fields[f] = (Vector2, Vector3, Vector4)[len(v) - 2](*v) if 2 <= len(v) <= 4 else v
        if kind == 'Shape':
            return _scene.Shape(fields.pop('geometry', None), fields.pop('appearance', _scene.Material.DEFAULT_MATERIAL),
                                int(fields.pop('id', _scene._NOID)), **fields)
        return cls(**fields)


def read(filename):
    """The shapes of PlantGL's text file, in its order; a geometry alone at the top level that
    no shape names becomes a shape of the default material, as PlantGL makes it."""
    with open(str(filename), encoding='utf-8', errors='replace') as f:
        text = f.read()
    reader = _Reader(text, str(filename))
    top, used = [], set()
    while reader.peek() is not None:
        obj = reader.object()
        top.append(obj)
        if isinstance(obj, _scene.Shape):
            used.update({id(getattr(obj, 'geometry', None)), id(getattr(obj, 'appearance', None))})
    shapes = []
    for obj in top:
        if isinstance(obj, _scene.Shape):
            shapes.append(obj)
        elif isinstance(obj, _scene._Geometry) and id(obj) not in used:
            shapes.append(_scene.Shape(obj, _scene.Material.DEFAULT_MATERIAL))
    return shapes
