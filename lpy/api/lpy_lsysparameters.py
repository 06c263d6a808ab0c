# openalea.lpy.lsysparameters as Sprout provides it, after L-Py's lsysparameters and its editor's gui/plugins: the
# parameters L-Py's editor keeps in an INITIALISATION part (options, materials, scalars and graphical parameters by
# category, credits), read from an Lsystem's context, put into one, written as code (1.1, 1.2) and as L-Py's JSON.

# Index of this file:
#   [SECTION] scalars (L-Py's lsysparameters/scalar.py)
#   [SECTION] curves and patches: compared, written as code and as JSON
#   [SECTION] materials and textures
#   [SECTION] the managers of graphical parameters (L-Py's gui/plugins, without their editors)
#   [SECTION] L-Py's JSON layout (schema/lpy.json and the files it refers to)
#   [SECTION] the parameters

import json
import os
import re

import openalea.plantgl.all as pgl

__all__ = ['LsystemParameters', 'Category', 'BaseScalar', 'BoolScalar', 'IntegerScalar', 'FloatScalar',
           'CategoryScalar', 'ProduceScalar', 'scalar_from_json_rep', 'default_credits']

default_credits = dict.fromkeys('__authors__ __institutes__ __copyright__ __description__ __references__'.split(), '')
default_lpycode_version, default_lpyjson_version = 1.2, 1.0
_IDENT = re.compile(r'^[^\d\W]\w*\Z')  # a name, as the schemas' "pattern" says

# [SECTION] scalars (L-Py's lsysparameters/scalar.py)
class BaseScalar(object):
    """A value of the editor's panel: totuple() is how code 1.1 lists it, todict() its JSON."""
    targettype = None
    def __init__(self, name, value=None): self.name, self.value = name, value
    @classmethod
    def scalartype(cls): return cls.__name__.replace('Scalar', '')
    def isBool(self): return isinstance(self, BoolScalar)
    def isFloat(self): return isinstance(self, FloatScalar)
    def isCategory(self): return isinstance(self, CategoryScalar)
    def totuple(self): return (self.name, self.scalartype(), self.value)
    def todict(self, **extra): return dict(name=self.name, value=self.value, **extra)
    def __eq__(self, other): return type(self) == type(other) and self.totuple() == other.totuple()
    def __reduce__(self): return (self.__class__, self.totuple()[:1] + self.totuple()[2:])  # without the type
    def __repr__(self): return '%s(%s)' % (self.__class__.__name__, ','.join(map(repr, self.__reduce__()[1])))

class BoolScalar(BaseScalar):
    targettype = bool
    def __init__(self, name, value=True): BaseScalar.__init__(self, name, value)

class _NumberScalar(BaseScalar):
    def __init__(self, name, value, min, max):
        assert isinstance(value, (int, float)) and min <= value <= max, (name, value, min, max)
        BaseScalar.__init__(self, name, value)
        self.minvalue, self.maxvalue = min, max
    def totuple(self): return (self.name, self.scalartype(), self.value, self.minvalue, self.maxvalue)
    def todict(self, **extra): return BaseScalar.todict(self, type=self.scalartype(), min=self.minvalue,
                                                        max=self.maxvalue, **extra)

class IntegerScalar(_NumberScalar):
    targettype = int
    def __init__(self, name, value=1, min=0, max=100): _NumberScalar.__init__(self, name, value, min, max)

class FloatScalar(_NumberScalar):
    targettype = float
    def __init__(self, name, value=1., min=0., max=100., precision=2):
        _NumberScalar.__init__(self, name, value, min, max)
        self.precision = precision
    def totuple(self): return _NumberScalar.totuple(self) + (self.precision,)
    def todict(self, **extra): return _NumberScalar.todict(self, precision=self.precision, **extra)

class CategoryScalar(BaseScalar):  # a category's name in code 1.1's list of scalars
    targettype = str
    def totuple(self): return (self.name, 'Category')

_SCALAR_TYPES = {c.scalartype(): c for c in (BoolScalar, IntegerScalar, FloatScalar, CategoryScalar)}

def ProduceScalar(v):
    """A scalar from its tuple: (name, type name, value, ...), or the older (name, value, ...)."""
    v = list(v)
    if isinstance(v[1], str):
        return _SCALAR_TYPES[v[1]](*(v[:1] + v[2:]))
    if isinstance(v[1], bool) or v[1] is None:
        return CategoryScalar(v[0]) if v[1] is None else BoolScalar(v[0], v[1])
    return FloatScalar(v[0], float(v[1]), *v[2:]) if isinstance(v[1], float) or len(v) == 5 else IntegerScalar(*v)

def scalar_from_json_rep(rep):
    rep = dict(rep)
    kind = rep.pop('type', None) or {bool: 'Bool', int: 'Integer', float: 'Float'}[type(rep['value'])]
    return _SCALAR_TYPES[kind](**rep)

# [SECTION] curves and patches: compared, written as code and as JSON
# Per PlantGL type: the field of its points (the depth of lists above the points, a point's size, the JSON's
# array type, None: plain lists) and the fields its JSON keeps (schema/curve.json, patch.json).
_SHAPES = {
    'Polyline2D': ('pointList', 1, 2, 'Point2Array', ()),
    'NurbsCurve2D': ('ctrlPointList', 1, 3, 'Point3Array', ('degree', 'knotList')),
    'BezierCurve2D': ('ctrlPointList', 1, 3, 'Point3Array', ()),
    'NurbsPatch': ('ctrlPointMatrix', 2, 4, 'Point4Matrix', ('udegree', 'vdegree', 'uknotList', 'vknotList',
                                                             'ustride', 'vstride')),
    'NurbsPatch3D': ('ctrlPointMatrix', 3, 4, None, ('udegree', 'vdegree', 'wdegree', 'uknotList', 'vknotList',
                                                     'wknotList', 'ustride', 'vstride', 'wstride'))}

def _plain(v):  # a value as numbers and lists (PlantGL's vectors, colours and arrays unwrapped)
    return v if v is None or isinstance(v, (bool, str, int, float)) else [_plain(x) for x in v]

def _close(a, b):
    """Whether two fields are alike: numbers to 1e-5 (L-Py's code writes 6 digits), sequences item by item."""
    if a is None or b is None or isinstance(a, (bool, str)) or isinstance(b, (bool, str)):
        return a == b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b) <= 1e-5 * max(1.0, abs(a), abs(b))
    if not hasattr(a, '__iter__') or not hasattr(b, '__iter__'):
        return True  # other objects: not compared (as L-Py)
    return len(list(a)) == len(list(b)) and all(_close(x, y) for x, y in zip(a, b))

def _shape_fields(obj, for_code):
    """(type name, points, {field: value}): the fields unlike those of the object made of the points alone."""
    kind = type(obj).__name__
    points, names = _plain(getattr(obj, _SHAPES[kind][0])), _SHAPES[kind][4] + (('stride', 'width') * for_code)
    try:
        default = type(obj)(points)
    except (ValueError, TypeError, IndexError):
        default = None
    fields = {name: _plain(getattr(obj, name, None)) for name in names}
    return kind, points, {k: v for k, v in fields.items() if v is not None and (
        default is None or not _close(v, _plain(getattr(default, k, None))))}

def _code(v, leaf='(%s)'):
    """A value as Python: numbers (integral ones as integers), lists whose innermost lists are `leaf` (tuples)."""
    if isinstance(v, list):
        return (leaf if all(isinstance(x, (int, float)) for x in v) else '[%s]') % ', '.join(_code(x, leaf) for x in v)
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return repr(int(v)) if float(v).is_integer() and abs(v) < 1e15 else repr(float(v))
    return repr(v)

def _object_from_json(rep):
    args = {k: v['data'] if isinstance(v, dict) else v for k, v in rep.items()
            if k not in ('name', 'type', 'id', 'is_function')}
    obj = getattr(pgl, rep['type'])(args.pop(_SHAPES[rep['type']][0]), **args)
    obj.name = rep.get('name', '')
    return obj

# [SECTION] materials and textures
# PlantGL lowers a material's diffuse so that no channel of ambient x diffuse passes 255; Sprout's Material
# keeps what it is given: materials are compared and written here as PlantGL has them.
_MATERIAL_DEFAULTS = {'ambient': (80, 80, 80), 'diffuse': 2.0, 'specular': (0, 0, 0), 'emission': (0, 0, 0),
                      'shininess': 0.2, 'transparency': 0.0}

def _is_texture(app):
    return hasattr(app, 'image')

def _material_fields(mat):
    f = {k: getattr(mat, k, d) for k, d in _MATERIAL_DEFAULTS.items()}
    f.update((k, tuple(int(c) for c in f[k])) for k in ('ambient', 'specular', 'emission'))
    f['diffuse'] = min([float(f['diffuse'])] + [255.0 / c for c in f['ambient'] if c > 0])
    return f

def _image_file(image):
    """ImageTexture(name, filename)'s file, or ImageTexture(filename)'s, whose one argument Sprout keeps as name."""
    args = getattr(image, 'args', ())
    return getattr(image, 'filename', None) or (args[0] if len(args) == 1 else getattr(image, 'name', ''))

def _similar_appearances(a, b):
    if _is_texture(a) or _is_texture(b):
        return _is_texture(a) and _is_texture(b) and _image_file(a.image) == _image_file(b.image)
    return _close(list(_material_fields(a).values()), list(_material_fields(b).values()))

def _appearance_code(app, index, ind, reference_dir):
    var = app.name if _IDENT.match(app.name) else 'Color_%d' % index
    if _is_texture(app):
        filename = _image_file(app.image)
        if reference_dir and os.path.isabs(filename):
            filename = os.path.relpath(filename, os.path.abspath(reference_dir))
        color = getattr(app, 'baseColor', None)
        txt = ind + '%s_image = pgl.ImageTexture(%r, %r)\n' % (var, var + '_image', filename)
        txt += ind + '%s = pgl.Texture2D(image=%s_image%s)\n' % (var, var, '' if color is None else
                                                                 ', baseColor=' + _code(_plain(color)))
    else:
        args = [repr(app.name)] + ['%s=%s' % (k, _code(_plain(v))) for k, v in _material_fields(app).items()
                                   if not _close(v, _MATERIAL_DEFAULTS[k])]
        txt = ind + '%s = pgl.Material(%s)\n' % (var, ', '.join(args))
    return txt + ind + '%s.name = %r\n' % (var, app.name) + ind + 'context.turtle.setMaterial(%d, %s)\n' % (index, var)

def _appearance_json(app, index):
    res = {'name': app.name, 'type': 'Texture2D' if _is_texture(app) else 'Material', 'index': index}
    if not _is_texture(app):
        return dict(res, **{k: _plain(v) for k, v in _material_fields(app).items()})
    res['image'] = {'type': 'ImageTexture', 'filename': _image_file(app.image)}
    return dict(res, **({'baseColor': _plain(app.baseColor)} if getattr(app, 'baseColor', None) is not None else {}))

def _appearance_from_json(rep):
    if rep['type'] == 'Texture2D':
        image = pgl.ImageTexture(rep['name'] + '_image', rep['image']['filename'])
        app = pgl.Texture2D(image=image, **({'baseColor': tuple(rep['baseColor'])} if 'baseColor' in rep else {}))
    else:
        app = pgl.Material(rep['name'], **{k: tuple(v) if isinstance(v, list) else v
                                           for k, v in rep.items() if k in _MATERIAL_DEFAULTS})
    app.name = rep['name']
    return app

# [SECTION] the managers of graphical parameters (L-Py's gui/plugins, without their editors)
class AbstractObjectManager(object):
    """Names, makes and writes one type of graphical parameter (typename)."""
    is_function = None  # what its JSON says of is_function (None: nothing, not a curve)
    writing = 'import openalea.plantgl.all as pgl'
    def __init__(self, typename, make_default): self.typename, self._make_default = typename, make_default
    def setName(self, obj, name): obj.name = name
    def getName(self, obj): return obj.name
    def getObjectForLsysContext(self, obj): return obj
    def writeObjectToLsysContext(self, obj): return obj.name
    def createDefaultObject(self, subtype=None): return self._make_default(subtype)
    def initWriting(self, indentation): return indentation + self.writing + '\n'

    def writeObject(self, obj, indentation):
        kind, points, fields = _shape_fields(obj, True)
        args = ', '.join([_code(points)] + ['%s=%s' % (k, _code(v, '[%s]')) for k, v in fields.items()])
        code = '%s.%s(%s)' % ('pglnp' if kind == 'NurbsPatch3D' else 'pgl', kind, args)
        return '%s%s = %s\n%s%s.name = %r\n' % (indentation, obj.name, code, indentation, obj.name, obj.name)

    def to_json(self, obj):
        kind, points, fields = _shape_fields(obj, False)
        pfield, arraytype = _SHAPES[kind][0], _SHAPES[kind][3]
        res = {'name': obj.name, 'type': kind, pfield: {'type': arraytype, 'data': points} if arraytype else points}
        res.update((k, {'type': 'RealArray', 'data': v} if isinstance(v, list) else v) for k, v in fields.items())
        return dict(res, **({'is_function': self.is_function} if self.is_function is not None else {}))

class FunctionManager(AbstractObjectManager):  # functions y = f(x): curves the model gets as QuantisedFunction
    is_function = True
    def getObjectForLsysContext(self, obj): return pgl.QuantisedFunction(obj)
    def writeObjectToLsysContext(self, obj): return 'pgl.QuantisedFunction(%s)' % obj.name

_MANAGERS = {
    'Curve2D': AbstractObjectManager('Curve2D', lambda subtype: {'Polyline': pgl.Polyline2D, 'BezierCurve':
        pgl.BezierCurve2D}.get(subtype, pgl.NurbsCurve2D)([(-0.5 + i / 3., 0, 1) for i in range(4)])),
    'Function': FunctionManager('Function', lambda s: pgl.NurbsCurve2D([(i / 3., 0, 1) for i in range(4)])),
    'NurbsPatch': AbstractObjectManager('NurbsPatch', lambda s: pgl.NurbsPatch(
        [[(0, i / 3. - 0.5, j / 3. - 0.5, 1) for j in range(4)] for i in range(4)], ustride=10, vstride=10)),
    'NurbsPatch3D': AbstractObjectManager('NurbsPatch3D', lambda s: pgl.NurbsPatch3D.default())}
_MANAGERS['Curve2D'].is_function = False
_MANAGERS['NurbsPatch3D'].writing = 'import openalea.plantgl.scenegraph.nurbspatch_nd as pglnp'
scalartypemap = {int: 'Integer', float: 'Float', bool: 'Bool'}
graphictypemap = {pgl.NurbsCurve2D: 'Curve2D', pgl.BezierCurve2D: 'Curve2D', pgl.Polyline2D: 'Curve2D',
                  pgl.NurbsPatch: 'NurbsPatch', pgl.NurbsPatch3D: 'NurbsPatch3D'}

# [SECTION] L-Py's JSON layout (schema/lpy.json and the files it refers to)
def _need(ok, where, what):
    if not ok:
        raise ValueError('%s %s' % (where, what))

def _check(v, spec, where='L-Py parameters'):
    """Checks v as spec says, in the terms of L-Py's schemas: a set (one of its values), a kind ('name', 'string',
    'boolean', 'number', 'integer'), a tuple (kind, minimum, maximum), a list [item spec, least count, most
    count], a dict {property: spec} (a required one ends in '!'; '...': others allowed), or a function (v, where)."""
    if callable(spec):
        return spec(v, where)
    if isinstance(spec, set):
        return _need(v in spec, where, '%r is not one of %s' % (v, sorted(spec)))
    if isinstance(spec, list):
        item, least, most = (spec + [0, None])[:3]
        _need(isinstance(v, list) and least <= len(v) <= (most or len(v)), where, 'is not %d items or more' % least)
        return [_check(x, item, '%s[%d]' % (where, i)) for i, x in enumerate(v)]
    if isinstance(spec, dict):
        _need(isinstance(v, dict), where, 'is not an object')
        props = {k.rstrip('!'): s for k, s in spec.items() if k != '...'}
        required = {k[:-1] for k in spec if k.endswith('!')}
        _need(required <= set(v), where, 'lacks %s' % sorted(required - set(v)))
        _need('...' in spec or set(v) <= set(props), where, 'should not have %s' % sorted(set(v) - set(props)))
        return [_check(v[k], s, where + '.' + k) for k, s in props.items() if k in v]
    kind, lo, hi = spec if isinstance(spec, tuple) else (spec, None, None)
    if kind in ('name', 'string', 'boolean'):
        ok = isinstance(v, bool) if kind == 'boolean' else isinstance(v, str) and (kind == 'string' or _IDENT.match(v))
    else:
        ok = isinstance(v, (int, float)) and not isinstance(v, bool) and (kind == 'number' or float(v).is_integer())
        ok = ok and (lo is None or v >= lo) and (hi is None or v <= hi)
    _need(ok, where, '%r is not a %s%s' % (v, kind, '' if lo is None and hi is None else ' in [%s, %s]' % (lo, hi)))

def _item_spec(kind):  # a curve's or a patch's JSON (schema/curve.json, patch.json)
    pfield, depth, size, arraytype, names = _SHAPES[kind]
    points = ['number', size, size]
    for _ in range(depth):
        points = [points, 2]
    spec = {'name!': 'name', 'type!': {kind}, 'id': 'integer',
            pfield + '!': {'type!': {arraytype}, 'data!': points, 'id': 'integer'} if arraytype else points}
    spec.update((n, _REAL if n.endswith('knotList') else ('number', 1, None)) for n in names)
    return dict(spec, is_function='boolean') if 'Patch' not in kind else spec

_REAL = {'type!': {'RealArray'}, 'data!': ['number', 2], 'id': 'integer'}
_ITEMS = {kind: _item_spec(kind) for kind in _SHAPES}
_COLOR, _INDEX = ('integer', 0, 255), ('integer', 0, None)
_MATERIAL = {'name!': 'name', 'id': _INDEX, 'type!': {'Material'}, 'index!': _INDEX, 'ambient': [_COLOR, 3, 3],
             'specular': [_COLOR, 3, 3], 'emission': [_COLOR, 3, 3], 'diffuse': ('number', 0, 3),
             'transparency': ('number', 0, 1), 'shininess': ('number', 0, 1)}
_TEXTURE = {'name!': 'name', 'id': _INDEX, 'type!': {'Texture2D'}, 'index!': _INDEX, 'baseColor': [_COLOR, 4, 4],
            'image!': {'name': 'name', 'id': _INDEX, 'type!': {'ImageTexture'}, 'filename!': 'string', '...': True},
            '...': True}
_SCALAR_NUMBER = {'name!': 'name', 'type!': {'Integer', 'Float'}, 'value!': 'number', 'min!': 'number',
                  'max!': 'number', 'precision': ('number', 0, None)}
_CATEGORY = {'name!': 'string', 'enabled!': 'boolean', '...': True,
             'items!': [lambda v, w: _check(v, _ITEMS.get(v.get('type'), {'type!': set(_SHAPES), '...': True})
                                            if isinstance(v, dict) else {}, w)],
             'scalars!': [lambda v, w: _check(v, _SCALAR_NUMBER if isinstance(v, dict) and 'type' in v
                                              else {'name!': 'name', 'value!': 'boolean'}, w)]}
_LPY = {'schema!': {'lpy'}, 'version!': 'string', 'options': {'animation_timestep': ('number', 0, None), '...': True},
        'parameters': [_CATEGORY], '...': True,
        'materials': [lambda v, w: _check(v, _TEXTURE if isinstance(v, dict) and v.get('type') == 'Texture2D'
                                          else _MATERIAL, w)],
        'credits': {'...': True, **dict.fromkeys(('authors', 'institutes', 'copyright', 'description', 'references'),
                                                 'string')}}

# [SECTION] the parameters
class Category:
    """A panel of L-Py's editor: its info (name, enabled...), items {name: (manager, object)}, scalars by name."""
    def __init__(self, info, items=None, scalars=None, **params):
        self.info = {'name': info, 'enabled': True} if isinstance(info, str) else dict({'enabled': True}, **info)
        self.__dict__.update(params)
        self.items, self.scalars = {m.getName(o): (m, o) for m, o in (items or [])}, {}
        self.add_scalars(scalars or [])

    def update_scalar(self, name, value): self.scalars[name].value = value
    def add_item(self, manager, value): self.items[manager.getName(value)] = (manager, value)
    def add_items(self, pairs): self.items.update((m.getName(v), (m, v)) for m, v in pairs)
    def add_scalar(self, value):
        value.category = self.info['name']
        self.scalars[value.name] = value
    def add_scalars(self, values):
        for v in values:
            self.add_scalar(v)
    def update_item(self, name, value):
        self.items[name][0].setName(value, name)
        self.items[name] = (self.items[name][0], value)

def _succeeds(check, *args):
    try:
        check(*args)
        return True
    except Exception:
        return False

class LsystemParameters:
    """A model's parameters: LsystemParameters(lsystem) reads an Lsystem's; LsystemParameters(file), a JSON file."""
    def __init__(self, lsystem_or_filename=None):
        self.clear()
        if hasattr(lsystem_or_filename, 'context'):  # an Lsystem
            self.retrieve_from(lsystem_or_filename)
        elif lsystem_or_filename is not None:  # a JSON file, or its name
            self.load(lsystem_or_filename)

    def clear(self):
        self.execOptions, self.animation_timestep, self.color_list = {}, None, {}
        self.categories, self.credits, self.default_category_name = {}, dict(default_credits), 'default'

    def is_valid(self): return _succeeds(self.check_validity)
    def is_similar(self, other): return _succeeds(self.check_similarity, other)

    def check_validity(self):
        assert isinstance(self.execOptions, dict) and isinstance(self.credits, dict) and (
            self.animation_timestep is None or self.animation_timestep > 0)
        assert all(isinstance(v, (pgl.Material, pgl.Texture2D)) for v in self.color_list.values())
        for c in self.categories.values():
            assert isinstance(c.info, dict) and 'name' in c.info, c
            assert all(isinstance(s, BaseScalar) for s in c.scalars.values()), c
            assert all(getattr(m, 'typename', None) in _MANAGERS for m, v in c.items.values()), c

    def check_similarity(self, other):
        """Raises ValueError at the first difference with `other`."""
        for att in ('execOptions', 'credits', 'animation_timestep', 'default_category_name'):
            if getattr(self, att) != getattr(other, att):
                raise ValueError(att, getattr(self, att), getattr(other, att))
        self.check_similar_colors(other)
        self.check_similar_parameters(other)

    def check_similar_parameters(self, other):
        if len(self.categories) != len(other.categories):
            raise ValueError('categories', list(self.categories), list(other.categories))
        for cat1, cat2 in zip(self.categories.values(), other.categories.values()):
            if cat1.info != cat2.info or len(cat1.items) != len(cat2.items) or len(cat1.scalars) != len(cat2.scalars):
                raise ValueError('category', cat1.info, cat2.info)
            for (m1, v1), (m2, v2) in zip(cat1.items.values(), cat2.items.values()):
                if m1.typename != m2.typename or type(v1) != type(v2):
                    raise ValueError('type', (m1.typename, v1), (m2.typename, v2))
                for att, value in vars(v1).items():
                    if not att.startswith('_') and not _close(value, getattr(v2, att, None)):
                        raise ValueError(att, value, getattr(v2, att, None))
            for s1, s2 in zip(cat1.scalars.values(), cat2.scalars.values()):
                if s1.scalartype() != s2.scalartype() or s1.value != s2.value:
                    raise ValueError('scalars', s1, s2)

    def check_similar_colors(self, other):
        if set(self.color_list) != set(other.color_list):
            raise ValueError('colors', sorted(self.color_list), sorted(other.color_list))
        for i, v1 in self.color_list.items():
            if type(v1) != type(other.color_list[i]) or not _similar_appearances(v1, other.color_list[i]):
                raise ValueError('color', i, v1, other.color_list[i])

    # Types, options, colors, categories and parameters, as L-Py names them.
    def get_available_scalar_types(self): return list(scalartypemap.values())
    def get_graphicalparameter_managers(self): return _MANAGERS
    def get_available_graphical_types(self): return list(_MANAGERS)
    def get_available_parameter_types(self): return self.get_available_scalar_types() + list(_MANAGERS)
    def set_option(self, name, value): self.execOptions[name] = value
    def get_option(self, name): return self.execOptions[name]
    def get_options(self): return self.execOptions
    def unset_color(self, index): del self.color_list[index]
    def get_color(self, index): return self.color_list.get(index)
    def get_colors(self): return self.color_list
    def set_defaut_category(self, name): self.default_category_name = name
    def get_categories(self): return self.categories
    def get_category_names(self): return self.categories.keys()
    def get_category_info(self, name=None): return self.get_category(name).info
    def get_category_graphicalparameters(self, name=None): return list(self.get_category(name).items.values())
    def get_category_scalars(self, name=None): return list(self.get_category(name).scalars.values())
    def get_scalars(self): return [s for c in self.categories.values() for s in c.scalars.values()]
    def update_scalar(self, name, value, category=None): self.get_category(category).update_scalar(name, value)
    def add_function(self, name, value=None, category=None): return self._add(name, value, 'Function', category)
    def add_curve(self, name, value=None, category=None): return self._add(name, value, 'Curve2D', category)
    def add_patch(self, name, value=None, category=None): return self._add(name, value, 'NurbsPatch', category)

    def get_category_parameters(self, name=None):
        return self.get_category_graphicalparameters(name) + self.get_category_scalars(name)

    def update_graphicalparameter(self, name, value, category=None):
        self.get_category(category).update_item(name, value)

    def get_category(self, name=None):  # made if it is not there
        name = self.default_category_name if name is None else name
        return self.categories.setdefault(name, Category(name))

    def add_category(self, name, **params):
        self.categories[name] = Category(name, **params)
        return self

    def get_scalar_list(self):  # as code 1.1 lists them: each category's name (a CategoryScalar), its scalars
        return [s for c in self.categories.values() if c.scalars
                for s in [CategoryScalar(c.info['name'])] + list(c.scalars.values())]

    def set_color(self, index, value, name=None):
        assert isinstance(value, (pgl.Material, pgl.Texture2D)), value
        self.color_list[index] = value
        if name is not None or not getattr(value, 'name', ''):
            value.name = 'Color_%d' % index if name is None else name

    def add(self, name, value, ptype=None, category=None, **params):
        """A scalar or a graphical parameter, by the type of its value unless ptype names it."""
        ptype = ptype or scalartypemap.get(type(value), graphictypemap.get(type(value), type(value)))
        if ptype in _MANAGERS:
            self.add_graphicalparameter(name, value, ptype, category)
        else:
            self.add_scalar(name, value, ptype, category, **params)

    def add_scalar(self, name, value, ptype=None, category=None, **params):
        ptype = ptype or scalartypemap[type(value)]
        if ptype not in scalartypemap.values():
            raise TypeError(ptype)
        scalar = ProduceScalar((name, ptype, value))
        scalar.__dict__.update(params)
        self.get_category(category).add_scalar(scalar)
        return self

    def add_graphicalparameter(self, name, value, ptype=None, category=None):
        manager = _MANAGERS[ptype or graphictypemap[type(value)]]
        value = manager.createDefaultObject() if value is None else value
        manager.setName(value, name)
        self.get_category(category).add_item(manager, value)
        return (manager, value)

    def _add(self, name, value, ptype, category):
        self.add_graphicalparameter(name, value, ptype, category)
        return self

    # -- an L-system's context -----------------------------------------------------------------------
    def retrieve_from(self, lsystem): self.retrieve_from_env(lsystem.context())
    def apply_to(self, lsystem): self.apply_to_env(lsystem.context())

    def retrieve_from_env(self, context):
        """What an INITIALISATION part (code 1.1 or 1.2) or apply_to put into the context."""
        ts, category = context.animation_timestep, vars(context).get('default_category')
        self.animation_timestep = None if context.is_animation_timestep_to_default() else ts
        self.default_category_name = category if isinstance(category, str) else self.default_category_name
        options = [context.options[i] for i in range(len(context.options))]
        self.execOptions = {o.name: o.selection for o in options if not o.isToDefault()}
        self.color_list.update(sorted(getattr(context.turtle, '_state', {}).get('materials', {}).items()))  # Sprout's
        self.credits.update((key, str(context.get(key, ''))) for key in default_credits)
        for panel in context.get('__parameterset__', []):
            info, objects, scalars = (list(panel) + [[]])[:3]  # code 1.1 has no scalars there
            info = {'name': info, 'enabled': True} if isinstance(info, str) else dict(info)
            info['enabled'] = info.pop('active', info.get('enabled', True))  # code 1.1 says 'active'
            category = self.categories.setdefault(info['name'], Category(info))
            category.add_items([(_MANAGERS[typename], obj) for typename, obj in objects])
            category.add_scalars(map(scalar_from_json_rep, scalars))
        version, current = context.get('__lpy_code_version__', None), self.default_category_name
        for sc in context.get('__scalars__', []) if version is None or version <= 1.1 else []:
            current = sc[0] if sc[1] in ('Category', None) else current
            if sc[1] not in ('Category', None):
                self.get_category(current).add_scalar(ProduceScalar(sc))

    def apply_to_env(self, context):
        context['__lpy_code_version__'] = default_lpycode_version
        if self.animation_timestep is not None:
            context.animation_timestep = self.animation_timestep
        if self.default_category_name != 'default':
            context.default_category = self.default_category_name
        for name, value in self.execOptions.items():
            context.options.setSelection(name, value)
        for i, cmat in self.color_list.items():
            context.turtle.setMaterial(i, cmat)
        context['__parameterset__'] = [(c.info, [(m.typename, o) for m, o in c.items.values()],
                                        [s.todict() for s in c.scalars.values()]) for c in self.categories.values()]
        for category in [c for c in self.categories.values() if c.info.get('enabled', True)]:
            for name, (manager, obj) in category.items.items():
                context[name] = manager.getObjectForLsysContext(obj)
            for scalar in category.scalars.values():
                context[scalar.name] = scalar.value

    # -- the code of an INITIALISATION part ----------------------------------------------------------
    def generate_py_code(self, indentation='', reference_dir=None, version=default_lpycode_version):
        """The INITIALISATION part that sets these parameters, in code format 1.1 or 1.2."""
        assert version in (1.1, 1.2)
        ind, body = indentation + '\t', ''
        if self.animation_timestep is not None:
            body += ind + 'context.animation_timestep = %r\n' % self.animation_timestep
        if self.default_category_name != 'default':
            body += ind + 'context.default_category = %r\n' % self.default_category_name
        body += ''.join(ind + 'context.options.setSelection(%r, %r)\n' % o for o in self.execOptions.items())
        body += ind + 'import openalea.plantgl.all as pgl\n' if self.color_list else ''
        for i, cmat in self.color_list.items():
            cmat.name = cmat.name or 'Color_%d' % i
            body += _appearance_code(cmat, i, ind, reference_dir)
        body += self._parameters_code(ind, version, bool(self.color_list))
        code = indentation + 'def __initialiseContext__(context):\n' + body if body else ''
        code += ''.join(indentation + '%s = %r\n' % (k, str(v)) for k, v in self.credits.items() if v)
        return '###### INITIALISATION ######\n\n__lpy_code_version__ = %s\n\n%s' % (version, code) if code else ''

    def _parameters_code(self, ind, version, pgl_imported):
        txt, written = '', {'import openalea.plantgl.all as pgl'} if pgl_imported else set()
        if any(c.items or c.scalars for c in self.categories.values()):
            for panelid, category in enumerate(self.categories.values()):
                for manager, obj in category.items.values():
                    txt += manager.initWriting(ind) if manager.writing not in written else ''
                    written.add(manager.writing)
                    txt += manager.writeObject(obj, ind)
                items = ', '.join('(%r, %s)' % (m.typename, m.getName(o)) for m, o in category.items.values())
                scalars = ', [%s]' % ', '.join(repr(s.todict()) for s in category.scalars.values())
                txt += ind + 'category_%d = (%r, [%s]%s)\n' % (panelid, category.info, items, scalars * (version > 1.1))
            txt += ind + 'parameterset = [%s]\n' % ', '.join('category_%d' % i for i in range(len(self.categories)))
            txt += ind + 'context["__parameterset__"] = parameterset\n'
            for category in [c for c in self.categories.values() if c.info.get('enabled', True)]:
                txt += ''.join(ind + 'context[%r] = %s\n' % (m.getName(o), m.writeObjectToLsysContext(o))
                               for m, o in category.items.values())
                if version > 1.1:
                    txt += ''.join(ind + 'context[%r] = %r\n' % (s.name, s.value) for s in category.scalars.values())
        if version == 1.1 and self.get_scalars():
            txt += ind + 'scalars = [%s]\n' % ', '.join(repr(s.totuple()) for s in self.get_scalar_list())
            txt += ind + 'context["__scalars__"] = scalars\n'
            txt += ind + 'for s in scalars:\n' + ind + '\tif not s[1] == "Category": context[s[0]] = s[2]\n'
        return txt

    # -- JSON ----------------------------------------------------------------------------------------
    def generate_json_parameter_dict(self):
        parameters = [dict(c.info, scalars=[s.todict() for s in c.scalars.values()],
                           items=[m.to_json(o) for m, o in c.items.values()]) for c in self.categories.values()]
        options = dict(self.execOptions)
        if self.animation_timestep is not None:
            options.update(animation_timestep=self.animation_timestep, default_category=self.default_category_name)
        materials = [_appearance_json(c, i) for i, c in self.color_list.items()]
        result = dict(schema='lpy', version=str(default_lpyjson_version), options=options, materials=materials,
                      parameters=parameters, credits={k: v for k, v in self.credits.items() if v != ''})
        _check(result, _LPY)
        return result

    @staticmethod
    def is_valid_schema(obj):
        """Whether obj (a dict, or its JSON text) is laid out as L-Py's schema 'lpy' says."""
        try:
            _check(json.loads(obj) if isinstance(obj, str) else obj, _LPY)
            return True
        except ValueError as e:
            print('L-Py schema validation failed:', e)
            return False

    def retrieve_from_json_dict(self, obj):
        if not LsystemParameters.is_valid_schema(obj):
            return False
        self.credits.update(obj.get('credits', {}))
        self.execOptions = dict(obj.get('options', {}))
        self.animation_timestep = self.execOptions.pop('animation_timestep', self.animation_timestep)
        self.default_category_name = self.execOptions.pop('default_category', self.default_category_name)
        self.color_list = {rep['index']: _appearance_from_json(rep) for rep in obj.get('materials', [])}
        for panel in obj.get('parameters', []):
            info = {k: v for k, v in panel.items() if k not in ('items', 'scalars')}
            items = [(_MANAGERS['Function' if rep.get('is_function') else graphictypemap[type(value)]], value)
                     for rep, value in ((rep, _object_from_json(rep)) for rep in panel['items'])]
            self.categories[info['name']] = Category(info, items, map(scalar_from_json_rep, panel['scalars']))
        return True

    def loads(self, text): return self.retrieve_from_json_dict(json.loads(text))
    def dumps(self): return json.dumps(self.generate_json_parameter_dict(), indent=4)
    def dump(self, file): json.dump(self.generate_json_parameter_dict(), file, indent=4)

    def load(self, file):
        if isinstance(file, str):
            with open(file) as f:
                return self.load(f)
        return self.retrieve_from_json_dict(json.load(file))
