# openalea.mtg.io as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): MTG files read and written (the MTG format: CODE, CLASSES, DESCRIPTION,
# FEATURES sections, then the MTG code, one vertex a line, tabs for branches), and an L-Py
# lstring made into an MTG and back (axialtree2mtg, mtg2axialtree, lpy2mtg, mtg2lpy). Read
# from openalea.mtg's definition (src/openalea/mtg/io.py, CeCILL-C): the same vertex ids,
# properties and text. MTG.write is in mtg_write.py (openalea.mtg._write), gathered here.

# Index of this file:
#   [SECTION] labels
#   [SECTION] the MTG code made into an MTG (multiscale_edit)
#   [SECTION] lstrings and MTGs
#   [SECTION] MTG files read (Reader)

import re
from string import Template
from warnings import warn

from .mtg import *
from .mtg import fat_mtg
from . import traversal
from .traversal import iter_mtg, iter_mtg_with_filter
from ._write import Writer, write_mtg, display, mtg_display

debug = 0
logger = None  # openalea.core's logger where it is installed: not in Sprout


def log(*args):
    """Prints its arguments when `debug` is set (openalea.mtg's trace of the reader)."""
    if debug:
        print('  '.join(map(str, args)))


# [SECTION] labels
def get_expr(s, expr):
    res = re.search(expr, s)
    return s[res.start():res.end()] if res else ''


def get_label(s):
    return get_expr(s, r'[a-zA-Z0-9]+')


def get_name(s):
    return get_expr(s, r'[a-zA-Z]+')


def get_index(s):
    return get_expr(s, r'[0-9]+')


def get_args(s):
    return get_expr(s, r'\([0-9,-\.\+]+\)')


def get_float(s):
    return float(get_expr(s, r'[0-9-\+]+'))


def replace_date(s, format):
    """Dates written with '/' rewritten with '-' (the '/' of the code is a decomposition)."""
    if format == 'DD/MM/YY':
        rawstr = r"(?P<day>3[01]|[1-9]|[0-2][0-9])/(?P<month>1[012]|0[1-9]|[1-9])/(?P<year>\d\d)"
    else:
        rawstr = r"(?P<day>3[01]|[0-2]{0,1}\d)/(?P<month>1[012]|0\d)/(?P<year>19\d\d|20\d\d)"
    return re.sub(rawstr, lambda m: '-'.join((m.group('day'), m.group('month'), m.group('year'))), s)


# [SECTION] the MTG code made into an MTG (multiscale_edit)
_TYPES = {'INT': int, 'REAL': float, 'ALPHA': str, 'DD/MM/YY': str, 'DD/MM/YYYY': str, 'STRING': str}


def _properties(name, class_type, vid=None, time=False):
    """A vertex's label, index and features, from `A1(x=2,y=3.5)`, each of its declared type."""
    args = {}
    parts = name.strip().split('(')
    if not time:
        label = get_label(name)
        index = get_index(label)
        if index.isdigit():
            args['index'] = int(index)
        args['label'] = label
    if len(parts) > 1:
        arg_string = parts[1].strip()[:-1]
        for arg in (arg_string.split(',') if arg_string else []):
            k, v = arg.split('=')
            klass = _TYPES[class_type[k]]
            try:
                args[k] = klass(v)
            except ValueError:
                if vid is not None and k == '_line':
                    continue
                where = 'of vertex %s ' % vid if vid is not None else ''
                print('Args ', v, where + 'of type ', k, 'is not of type ', str(klass))
    return args


def _add_dynamic_properties(mtg, vid, args):
    """A dated line (`*(Date=...)`) of a dynamic MTG: each property a list of (date, value)."""
    new_date = args.get('Date')
    if new_date is None:
        return
    old_date = mtg.property('Date')[vid]
    for prop in args:
        if prop == 'Date':
            continue
        old = mtg.property(prop).get(vid)
        if isinstance(old, list):
            old.append((new_date, args[prop]))
        elif old:
            mtg.property(prop)[vid] = [(old_date, old), (new_date, args[prop])]
        else:
            mtg.property(prop)[vid] = [(new_date, args[prop])]


def _split_code(s, symbol_at_scale, class_type, has_date):
    """The code cut into one node a line, each starting with its edge ('/', '[', ']', '+', '<', '<<')."""
    symbols = ['/', '[', ']', '+', '<', '<<'] if symbol_at_scale else ['/', '\\', '[', ']', '+', '<', '<<']
    if has_date:
        s = replace_date(s, 'DD/MM/YY' if 'DD/MM/YY' in class_type.values() else 'DD/MM/YYYY')
    for edge in symbols:
        if edge != '/' or not symbol_at_scale:
            s = s.replace(edge, '\n%s' % edge)
        else:  # not the '/' of a date
            for klass in symbol_at_scale:
                s = s.replace('/%s' % klass, '\n/%s' % klass)
    s = s.replace('<\n<', '<<').replace(')(', ')\n(').replace(') (', ')\n(').replace('*(', '\n(')
    return symbols, [node for node in s.split('\n') if node]


class _Editor:
    """multiscale_edit's state: the vertex of the finest scale reached, the current vertex,
    the scale, the edge pending and the stack of branches."""

    def __init__(self, mtg):
        self.mtg = mtg
        self.vid = self.current = mtg.root
        self.stack = []
        self.pending = ''
        self.scale = 0

    def node(self, tag, args, symbol_at_scale, name):
        g = self.mtg
        if symbol_at_scale:
            new_scale = symbol_at_scale.get(get_name(name))
            if new_scale is None:
                raise KeyError('MTG code: the class %r of %r is not declared in CLASSES' % (get_name(name), name))
            if tag == '/' and new_scale <= self.scale:
                new_scale -= 1
                self.pending = '/'
            while new_scale < self.scale:
                self.scale -= 1
                self.current = g.complex(self.current)
        if tag in ['+', '<']:
            if g.scale(self.vid) == self.scale:
                self.vid = self.current = g.add_child(self.vid, edge_type=tag, **args)
                self.pending = ''
            else:
                self.current = g.add_component(g.complex(self.current), **args)
                self.pending = tag
        elif tag == '<<':
            self.successors(args)
        elif tag == '/':
            self.decompose(args)
        elif tag == '\\':
            self.scale -= 1
            self.current = g.complex(self.current)

    def successors(self, args):
        """`<<A5` after A2: A3, A4 and A5 added as successors."""
        g = self.mtg
        index, label = args['index'], args['label']
        previous = g.property('index')[self.current]
        self.pending = ''
        one = {}
        for i in range(previous + 1, index + 1):
            if i == index:
                one = args
            one['index'] = i
            one['label'] = label.replace(str(index), str(i))
            self.vid = self.current = g.add_child(self.vid, edge_type='<', **one)

    def decompose(self, args):
        g = self.mtg
        if g.scale(self.vid) == self.scale:
            self.vid = self.current = g.add_component(self.vid, **args)
            self.scale += 1
        elif g.scale(self.vid) > self.scale:
            self.scale += 1
            component = g.add_component(self.current, **args)
            if g.scale(self.vid) == self.scale and self.pending != '/':
                self.vid = self.current = g.add_child(self.vid, child=component, edge_type=self.pending)
            else:
                self.current = component
                if self.pending == '/':  # /P/P: a new vertex at a scale already reached
                    self.vid = self.current
                    self.scale = g.scale(self.vid)
        else:
            self.vid = self.current = g.add_component(self.current, **args)


def multiscale_edit(s, symbol_at_scale={}, class_type={}, has_date=False, mtg=None):
    """The MTG of the code `s` (the brackets form of the MTG code): `symbol_at_scale` the
    scale of each class, `class_type` the type of each feature."""
    mtg = mtg if mtg else MTG()
    mtg.add_property('index')
    for k in class_type:
        mtg.add_property(k)
    symbols, nodes = _split_code(s, symbol_at_scale, class_type, has_date)
    edit = _Editor(mtg)
    for node in nodes:
        if node.startswith('<<'):
            tag, name = '<<', node[2:]
        elif node.startswith('(') and has_date:
            tag, name = '*', node
        else:
            tag, name = node[0], node[1:]
            if tag not in symbols:
                raise ValueError('MTG code: %r is not an edge (one of %s) before %r' % (tag, ' '.join(symbols), name))
        if tag == '[':
            edit.stack.append(edit.vid)
        elif tag == ']':
            if not edit.stack:
                raise ValueError('MTG code: a ] closes no branch')
            edit.vid = edit.current = edit.stack.pop()
            edit.scale = mtg.scale(edit.vid)
        elif tag == '*':
            _add_dynamic_properties(mtg, edit.vid, _properties(name, class_type, vid=edit.vid, time=True))
        else:
            if class_type:
                args = _properties(name, class_type, vid=edit.vid)
            else:
                args = {'label': get_label(name)}
                if get_index(name).isdigit():
                    args['index'] = int(get_index(name))
            edit.node(tag, args, symbol_at_scale, name)
    return fat_mtg(mtg)


# [SECTION] lstrings and MTGs
def _module_parameter(module, p):
    """(True, value) when the module has a parameter named p (L-Py's hasParameter)."""
    if hasattr(module, 'hasParameter'):
        return (True, module.getParameter(p)) if module.hasParameter(p) else (False, None)
    try:
        return True, getattr(module, p)
    except (AttributeError, IndexError):
        return False, None


def _module_properties(module, label, names):
    params = {'label': label}
    for p in names:
        found, value = _module_parameter(module, p)
        if found:
            params[p] = value
        elif module.argSize() == 1:  # a parameter set's attribute
            pset = getattr(module.args[0], '__dict__', {})
            if p in pset:
                params[p] = pset[p]
    return params


def axialtree2mtg(tree, scale, scene, parameters=None):
    """The MTG of an lstring: each module named in `scale` a vertex at its scale (others
    left out), with the parameters `parameters` names for it as properties; `scene`'s shapes
    (their ids the modules' positions) as the property 'geometry'. '_axial_id' is each
    vertex's position in the lstring."""
    geoms = scene.todict() if scene else {}
    mtg = MTG()
    if scene:
        mtg.add_property('geometry')
    mtg.add_property('_axial_id')
    parameters = parameters or {}
    for label in parameters:
        for p in parameters[label]:
            if p not in mtg.property_names():
                mtg.add_property(p)
    vid = current = mtg.root
    stack = [vid]
    pending = ''
    max_scale = max(scale.values())
    for aid, module in enumerate(tree):
        label = module.name
        if label == '[':
            stack.append(vid)
            pending = '+'
            continue
        if label == ']':
            vid = current = stack.pop()
            pending = ''
            continue
        if label not in scale and label not in parameters:
            continue
        _scale = scale[label]
        params = _module_properties(module, label, parameters.get(label, []))
        if mtg.scale(vid) == mtg.scale(current) == _scale:
            edge = '+' if pending == '+' and current == stack[-1] else '<'
            vid = current = mtg.add_child(vid, edge_type=edge, **params)
            pending = ''
        elif mtg.scale(vid) < max_scale:
            vid = current = mtg.add_component(vid, **params)
        elif mtg.scale(current) < _scale:
            current = mtg.add_component(current, **params)
            if mtg.scale(vid) == _scale:
                params['edge_type'] = '+' if pending == '+' else '<'
                vid = mtg.add_child(vid, child=current, **params)
                pending = ''
        else:
            while mtg.scale(current) >= _scale:
                current = mtg.complex(current)
            current = mtg.add_component(current, **params)
            pending = ''
        mtg.property('_axial_id')[current] = aid
        if aid in geoms:
            for shape in geoms[aid]:
                shape.id = current
            mtg.property('geometry')[current] = geoms[aid]
    return fat_mtg(mtg)


def mtg2axialtree(g, parameters=None, axial_tree=None):
    """The lstring of an MTG: a module per vertex named by its class, with the properties
    `parameters` names for it as arguments (those it lacks left out); a branch ('+' or
    '/' edge) in brackets."""
    edge_type = g.properties().get('edge_type', {})
    parameters = parameters or {}
    tree = axial_tree
    if tree is None:
        import openalea.lpy as lpy
        tree = lpy.AxialTree()

    def pre(vid, tree=tree):
        if vid == g.root:
            return True
        if edge_type.get(vid, '/') in ('+', '/'):
            tree += '['
        name = g.class_name(vid)
        if not name:
            return False
        args = [name]
        params = parameters.get(name, [])
        if 'parameter_set' in params and len(params) == 1:
            from openalea.lpy.parameterset import ParameterSet
            exclude = ['geometry', 'label', 'edge_type', '_axial_id']
            pset = dict((p, g.property(p)[vid]) for p in g.property_names()
                        if p not in exclude and g.property(p).get(vid) is not None)
            args.append(ParameterSet(**pset))
        else:
            args += [g.property(p)[vid] for p in params if g.property(p).get(vid) is not None]
        tree += tuple(args)
        return True

    def post(vid, tree=tree):
        if edge_type.get(vid, '/') in ('+', '/'):
            tree += ']'

    for _ in traversal.iter_mtg2_with_filter(g, next(g.roots_iter(scale=0)), pre, post):
        pass
    return tree


def read_lsystem_string(string, symbol_at_scale, functional_symbol={}, mtg=None):
    """openalea.mtg's reader of cpfg-era strings with PlantGL's turtle: not in Sprout's."""
    raise NotImplementedError('read_lsystem_string (a cpfg string walked by PlantGL\'s turtle) is not in '
                              'Sprout\'s openalea.mtg: make the MTG with axialtree2mtg, or install openalea.mtg')


def mtg2mss(name, mtg, scene, envelop_type='CvxHull'):
    """The multiscale structure of openalea.fractalysis (which it needs, as openalea.mtg does)."""
    from openalea.fractalysis.light import ssFromDict
    layers = [dict((vid, mtg.components(vid)) for vid in mtg.vertices_iter(scale=scale))
              for scale in range(1, mtg.nb_scales() - 1)]
    return ssFromDict(name, scene, layers, envelop_type)


def lpy2mtg(axial_tree, lsystem, scene=None):
    """axialtree2mtg with the scales and parameter names the Lsystem's modules declare."""
    lsystem.makeCurrent()
    parameters, scales = {}, {}
    for m in lsystem.context().declaredModules():
        parameters[m.name] = list(m.parameterNames)
        if 'parameter_set' in m.parameterNames and len(m.parameterNames) == 1 and axial_tree.count(m.name) > 0:
            pset = axial_tree[axial_tree.find(m.name + '(p)')].args[0]
            parameters[m.name] = list(pset.__dict__.keys())
        scales[m.name] = m.scale
    if scene is None:
        scene = lsystem.sceneInterpretation(axial_tree)
    lsystem.done()
    return axialtree2mtg(axial_tree, scales, scene, parameters)


def mtg2lpy(g, lsystem, axial_tree=None):
    """mtg2axialtree with the parameter names the Lsystem's modules declare."""
    lsystem.makeCurrent()
    parameters = dict((m.name, list(m.parameterNames)) for m in lsystem.context().declaredModules())
    lsystem.done()
    return mtg2axialtree(g, parameters, axial_tree)


# [SECTION] MTG files read (Reader)
from ._read import Reader  # noqa: E402 (the reader needs multiscale_edit above)


def read_mtg(s, mtg=None, has_date=False, verbose=True):
    """The MTG of a text in the MTG format."""
    return Reader(s, mtg=mtg, has_date=has_date, verbose=verbose).parse()


def read_mtg_file(fn, mtg=None, has_date=False, verbose=True):
    """The MTG of an MTG file."""
    with open(fn) as f:
        txt = f.read()
    return read_mtg(txt, mtg=mtg, has_date=has_date, verbose=verbose)
