# openalea.mtg.mtg as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): the MTG, a multiscale tree graph (a tree at each scale, each vertex the
# complex of the components of the next scale), read from openalea.mtg's definition
# (src/openalea/mtg/mtg.py, CeCILL-C): the same vertex ids, properties and traversals, so
# that what a model computes from an MTG is what it computes with openalea.mtg.

# Index of this file:
#   [SECTION] the MTG: scales, vertices, edits
#   [SECTION] complexes and components
#   [SECTION] sub-MTGs, labels, the vertex as an object
#   [SECTION] AML's functions as methods
#   [SECTION] functions of MTGs

import re
import copy
import random
import warnings

from . import traversal
from . import algo
from .tree import PropertyTree, InvalidVertex




# [SECTION] the MTG: scales, vertices, edits
class MTG(PropertyTree):
    """A multiscale tree graph. Vertex 0 is the root, at scale 0; `edge_type` ('<' a
    successor, '+' a branch) and `label` are properties of every MTG."""

    def __init__(self, filename='', has_date=False, verbose=False):
        super().__init__()
        self.verbose = verbose
        self._scale = {0: 0}
        self._complex = {}
        self._components = {}
        self.add_property('edge_type')
        self.add_property('label')
        if filename:
            from .io import read_mtg_file
            read_mtg_file(filename, mtg=self, has_date=has_date, verbose=verbose)

    def __getitem__(self, vtx_id):
        if not self.has_vertex(vtx_id):
            raise IndexError('MTG index out of range')
        d = self.get_vertex_property(vtx_id)
        d.update({'vid': vtx_id, 'index': self.index(vtx_id), 'complex': self.complex(vtx_id),
                  'parent': self.parent(vtx_id), 'scale': self._scale.get(vtx_id)})
        return d

    def scale(self, vid):
        return self._scale.get(vid)

    def nb_scales(self):
        return len(set(self._scale.values()))

    def scales_iter(self):
        return iter(set(self._scale.values()))

    def scales(self):
        return list(self.scales_iter())

    def max_scale(self):
        return max(self.scales_iter())

    def nb_vertices(self, scale=-1):
        return len(self._scale) if scale < 0 else len(self.vertices(scale=scale))

    def vertices(self, scale=-1):
        return list(self.vertices_iter(scale=scale))

    def vertices_iter(self, scale=-1):
        if scale < 0:
            return iter(self._scale.keys())
        return (vid for vid, sid in self._scale.items() if sid == scale)

    def __iter__(self):
        return self.vertices_iter()

    def __contains__(self, vid):
        return self.has_vertex(vid)

    def has_vertex(self, vid):
        return vid in self._scale

    def is_valid(self):
        return True

    def iteredges(self, scale=-1):
        return self.iter_edges(scale)

    def iter_edges(self, scale=-1):
        if scale < 0:
            return ((v, k) for k, v in self._parent.items())
        return ((p, c) for c, p in self._parent.items() if self.scale(p) == scale)

    def edges(self, scale=-1):
        return list(self.iter_edges(scale=scale))

    def add_element(self, parent_id, edge_type='/', scale_id=None):
        raise NotImplementedError('MTG.add_element: openalea.mtg does not implement it either')

    def remove_vertex(self, vid, reparent_child=False):
        if reparent_child:
            new_parent = self.parent(vid)
            for cid in list(self.children_iter(vid)):
                self.replace_parent(cid, new_parent)
        if self.nb_components(vid) != 0:
            raise InvalidVertex('Can not remove vertex %d with components.Use remove_tree instead.' % vid)
        super().remove_vertex(vid, reparent_child=reparent_child)
        self._components.pop(vid, None)
        self._scale.pop(vid, None)
        if vid in self._complex:
            siblings = self._components[self._complex[vid]]
            if vid in siblings:
                siblings.remove(vid)
            del self._complex[vid]

    def clear(self):
        super().clear()
        self._scale.clear()
        self._scale[0] = 0
        self._complex.clear()
        self._components.clear()

    def clear_properties(self, exclude=[]):
        keep = set(exclude) | {'edge_type', 'label'}
        for k in set(self._properties) - keep:
            del self._properties[k]

    def copy(self):
        return copy.deepcopy(self)

    def roots_iter(self, scale=0):
        return (vid for vid in self.vertices_iter(scale=scale) if self.parent(vid) is None)

    def roots(self, scale=0):
        return list(self.roots_iter(scale=scale))

    def add_child(self, parent, child=None, **properties):
        child = super().add_child(parent, child, **properties)
        self._scale[child] = self._scale[parent]
        return child

    def insert_sibling(self, vtx_id1, vtx_id2=None, **properties):
        vtx_id2 = super().insert_sibling(vtx_id1, vtx_id2, **properties)
        self._scale[vtx_id2] = self._scale[vtx_id1]
        return vtx_id2

    def insert_parent(self, vtx_id, parent_id=None, **properties):
        parent_id = self._new_id(parent_id)
        self._scale[parent_id] = self.scale(vtx_id)
        return super().insert_parent(vtx_id, parent_id, **properties)

    def replace_parent(self, vtx_id, new_parent_id, **properties):
        if self.scale(vtx_id) != self.scale(new_parent_id):
            raise InvalidVertex('Can not replace vertex {} by vertex {} from a different scale'.format(vtx_id, new_parent_id))
        old_complex = self._complex.get(vtx_id)
        super().replace_parent(vtx_id, new_parent_id, **properties)
        if old_complex is not None:
            self.replace_parent(old_complex, self.complex(new_parent_id))

    # [SECTION] complexes and components
    def complex(self, vtx_id):
        """The vertex of the scale above that holds vtx_id (found through its ancestors)."""
        complex_id = self._complex.get(vtx_id)
        while complex_id is None:
            vtx_id = self.parent(vtx_id)
            if vtx_id is None:
                break
            complex_id = self._complex.get(vtx_id)
        return complex_id

    def complex_at_scale(self, vtx_id, scale):
        complex_id = vtx_id
        for _ in range(scale, self.scale(vtx_id)):
            complex_id = self.complex(complex_id)
        return complex_id

    def components_iter(self, vid):
        if vid in self._components:
            for v in self.component_roots_iter(vid):
                yield from traversal.pre_order(self, v, complex=vid)

    def components(self, vid):
        return list(self.components_iter(vid))

    def components_at_scale_iter(self, vid, scale):
        gen = (vid,)
        for _ in range(self.scale(vid), scale):
            gen = (c for vtx in gen for c in self.components_iter(vtx))
        return gen

    def components_at_scale(self, vid, scale):
        return list(self.components_at_scale_iter(vid, scale))

    def component_roots_iter(self, vtx_id):
        for ci in self._components.get(vtx_id, []):
            p = self.parent(ci)
            if p is None or self.complex(p) != vtx_id:
                yield ci

    def component_roots(self, vtx_id):
        return list(self.component_roots_iter(vtx_id))

    def component_roots_at_scale_iter(self, vtx_id, scale):
        cur = self.scale(vtx_id)
        if scale == -1 or scale == cur + 1:
            return self.component_roots_iter(vtx_id)
        if scale > cur + 1:
            gen = (vtx_id,)
            for _ in range(cur, scale):
                gen = (c for vtx in gen for c in self.component_roots_iter(vtx))
            return gen
        return iter([])

    def component_roots_at_scale(self, vtx_id, scale):
        return list(self.component_roots_at_scale_iter(vtx_id, scale))

    def nb_components(self, vid):
        return len(self.components(vid))

    def add_component(self, complex_id, component_id=None, **properties):
        component_id = self._new_id(component_id)
        self._add_vertex_properties(component_id, properties)
        self._components.setdefault(complex_id, []).append(component_id)
        self._complex[component_id] = complex_id
        self._scale[component_id] = self._scale[complex_id] + 1
        return component_id

    def add_child_and_complex(self, parent, child=None, complex=None, **properties):
        complex = self._new_id(complex)
        if child in self._children.get(parent, []):
            self._add_vertex_properties(child, properties)
        else:
            child = self.add_child(parent, child, **properties)
        self._scale[child] = self._scale[parent]
        parent_complex = self.complex(parent)
        if complex not in self._children.get(parent_complex, []):
            self.add_child(parent_complex, complex)
        self._scale[complex] = self._scale[parent_complex]
        self._components.setdefault(complex, []).append(child)
        self._complex[child] = complex
        return child, complex

    def __str__(self):
        return 'MTG : nb_vertices=%d, nb_scales=%d' % (self.nb_vertices(), self.nb_scales())

    def display(self, max_scale=0, display_id=True, display_scale=False, nb_tab=12, **kwds):
        from . import io
        print(str(self))
        print(io.display(self, max_scale=max_scale, display_id=display_id, display_scale=display_scale,
                         nb_tab=nb_tab, **kwds))

    def plot_property(self, prop, **kwds):
        """The property against each vertex's height (matplotlib), coloured by order."""
        import matplotlib
        import matplotlib.pyplot
        values = self.property(prop)
        colors, orders, heights = list(matplotlib.colors.cnames.keys()), algo.orders(self), algo.heights(self)
        for v in values:
            matplotlib.pyplot.plot(heights[v], values[v], 'o', color=colors[orders[v]])

    # [SECTION] sub-MTGs, labels, the vertex as an object
    def sub_mtg(self, vtx_id, copy=True):
        """The MTG below vtx_id, a copy renumbered from 0."""
        if not copy:
            raise NotImplementedError('MTG.sub_mtg(vtx_id, copy=False) (the MTG cut down in place) is not in '
                                      "Sprout's openalea.mtg: use the copy it returns by default")
        ids = {vtx_id: 0}
        g = MTG()
        for name in self.properties():
            g.add_property(name)
        below = traversal.iter_mtg2(self, vtx_id)
        next(below)
        for vid in below:
            v = g.add_component(ids[self.complex(vid)])
            ids[vid] = v
            pid = self.parent(vid)
            if pid in ids:
                g.add_child(ids[pid], child=v)
            g._add_vertex_properties(v, self.get_vertex_property(vid))
        return g

    def order(self, v1):
        edge_type = self.property('edge_type')
        n = 0
        while edge_type and v1 is not None:
            n += edge_type.get(v1) == '+'
            v1 = self.parent(v1)
        return n

    def edge_type(self, vid):
        return self.property('edge_type').get(vid, '')

    def label(self, vid):
        return self.property('label').get(vid, '')

    def class_name(self, vid):
        label = self.property('label').get(vid)
        m = re.match('[a-zA-Z]+', label) if label else None
        return m.group(0) if m else ''

    def index(self, vid):
        label = self.property('label').get(vid)
        m = re.search('[0-9]+$', label) if label else None
        return m.group(0) if m else vid

    def node(self, vid, klass=None):
        return (klass or _ProxyNode)(self, vid) if vid in self else None

    # [SECTION] AML's functions as methods
    def VtxList(self, Scale=-1):
        return self.vertices(scale=Scale)

    Label = label
    Class = class_name
    Index = index
    Scale = scale

    def ClassScale(self, c):
        for x in self.vertices_iter():
            if self.Class(x) == c:
                return self.scale(x)

    def EdgeType(self, v1, v2):
        if self.parent(v1) == v2:
            v1, v2 = v2, v1
        return self.property('edge_type').get(v2)

    def Defined(self, vid):
        return vid in self

    def Rank(self, v1, v2=None):
        return algo.rank(self, v1, v2)

    def Height(self, v1, v2=None):
        return algo.height(self, v1, v2)

    def AlgOrder(self, v1, v2):
        return algo.alg_order(self, v1, v2)

    def AlgRank(self, v1, v2):
        return algo.alg_rank(self, v1, v2)

    def AlgHeight(self, v1, v2):
        return algo.alg_height(self, v1, v2)

    def Father(self, v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None, Scale=-1):
        if EdgeType not in ['+', '<', '*']:
            raise Exception('Invalid argument %s. Value of EdgeType is "<", "+" or "*".' % EdgeType)
        if RestrictedTo not in ['SameComplex', 'SameAxis', 'NoRestriction']:
            raise Exception('Invalid argument %s. Value of RestrictedTo is SameComplex, SameAxis, NoRestriction .' % RestrictedTo)
        return algo.father(self, v, scale=Scale, EdgeType=EdgeType, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)

    def Successor(self, v, RestrictedTo='NoRestriction', ContainedIn=None):
        return algo.successor(self, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)

    def Predecessor(self, v, **kwds):
        return self.Father(v, EdgeType='<', **kwds)

    def Root(self, v, RestrictedTo='*', ContainedIn=None):
        return algo.root(self, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)

    def Complex(self, v, Scale=-1):
        if Scale == -1 or Scale == self.scale(v) - 1:
            return self.complex(v)
        return self.complex_at_scale(v, scale=Scale)

    def Sons(self, v, RestrictedTo='NoRestriction', EdgeType='*', Scale=-1, ContainedIn=None):
        return algo.sons(self, v, EdgeType=EdgeType, RestrictedTo=RestrictedTo, Scale=Scale, ContainedIn=ContainedIn)

    def Ancestors(self, v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None):
        return list(algo.full_ancestors(self, v, RestrictedTo=RestrictedTo, EdgeType=EdgeType, ContainedIn=ContainedIn))

    def Descendants(self, v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None):
        return list(algo.descendants(self, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn))

    def Extremities(self, v, RestrictedTo='NoRestriction', ContainedIn=None):
        return list(algo.extremities(self, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn))

    def Components(self, v, Scale=-1):
        scale = self.scale(v)
        if Scale == -1 or scale == Scale:
            return self.components(v)
        return self.components_at_scale(v, scale=Scale) if scale < Scale else []

    def ComponentRoots(self, v, Scale=-1):
        return self.component_roots_at_scale(v, scale=Scale)

    def Path(self, v1, v2):
        return list(algo.path(self, v1, v2)[0])

    def Axis(self, v, Scale=-1):
        return list(algo.axis(self, v, scale=Scale))

    def Trunk(self, v, Scale=-1):
        return list(algo.trunk(self, v, scale=Scale))


class _ProxyNode:
    """A vertex as an object (MTG.node): its properties as attributes, the MTG's methods on it."""

    def __init__(self, g, vid):
        self.__dict__['_g'] = g
        self.__dict__['_vid'] = vid

    def __setattr__(self, name, value):
        if name not in self._g.property_names():
            self._g.add_property(name)
        self._g.property(name)[self._vid] = value

    def __getattr__(self, name):
        if name in self._g.property_names():
            return self._g.property(name).get(self._vid)
        raise AttributeError(name)

    def __eq__(self, other):
        return self._vid == other._vid

    def __hash__(self):
        return hash(self._vid)

    def __str__(self):
        return '_ProxyNode(%d)' % self._vid

    __repr__ = __str__

    def properties(self):
        return self._g.get_vertex_property(self._vid)


def _proxy(name, wrap):
    method = getattr(MTG, name)
    def f(self, *args, **kwds):
        result = method(self._g, self._vid, *args, **kwds)
        if wrap == 'node':
            return None if result is None else self.__class__(self._g, result)
        if wrap == 'list':
            return [self.__class__(self._g, v) for v in result]
        if wrap == 'tuple':
            return tuple(self.__class__(self._g, v) for v in result)
        return result
    f.__name__ = name
    f.__doc__ = method.__doc__
    setattr(_ProxyNode, name, f)


for _name, _wrap in [('scale', ''), ('edge_type', ''), ('index', ''), ('parent', 'node'), ('children', 'list'),
                     ('nb_children', ''), ('siblings', 'list'), ('nb_siblings', ''), ('complex', 'node'),
                     ('components', 'list'), ('nb_components', ''), ('complex_at_scale', 'node'),
                     ('components_at_scale', 'list'), ('component_roots', 'list'),
                     ('component_roots_at_scale', 'list'), ('add_child', 'node'), ('add_child_and_complex', 'tuple'),
                     ('insert_parent', 'node'), ('insert_sibling', 'node'), ('add_component', 'node'),
                     ('remove_vertex', ''), ('remove_tree', 'list')]:
    _proxy(_name, _wrap)


# [SECTION] functions of MTGs
def fat_mtg(slim_mtg, preserve_order=False):
    """The edges between complexes that their components imply, added at every scale."""
    edge_type = slim_mtg.property('edge_type')
    for scale in range(slim_mtg.max_scale() - 1, 0, -1):
        _compute_missing_edges(slim_mtg, scale, edge_type)
    return slim_mtg


def _compute_missing_edges(mtg, scale, edge_type_property=None):
    for vid in mtg.roots(scale=scale):
        components = mtg._components.get(vid)
        if components is None:
            if mtg.verbose:
                print('ERROR: Missing component for vertex %d' % vid)
            continue
        cid = components[0]
        if mtg.parent(cid) is None:
            continue
        parent_id = mtg.complex(mtg.parent(cid))
        if parent_id is None:
            if mtg.verbose:
                print('ERROR: Missing parent for vertex %d' % cid)
            continue
        if edge_type_property:
            mtg.add_child(parent_id, child=vid, edge_type=edge_type_property.get(cid))
        else:
            mtg.add_child(parent_id, child=vid)
    return True


def simple_tree(tree, vtx_id, nb_children=3, nb_vertices=20):
    pending = [vtx_id]
    while nb_vertices > 0:
        n = min(nb_children, nb_vertices)
        vid = pending.pop(0)
        for _ in range(n):
            pending.append(tree.add_child(vid))
            nb_vertices -= 1
    return tree


def random_tree(mtg, root, nb_children=3, nb_vertices=20):
    from random import randint
    pending = [root]
    while nb_vertices > 0:
        n = min(nb_children() if callable(nb_children) else randint(1, nb_children), nb_vertices)
        vid = pending.pop(randint(0, len(pending) - 1))
        for i in range(n):
            pending.append(mtg.add_child(vid, edge_type='<' if i == n / 2 else '+'))
            nb_vertices -= 1
    return pending[-1]


def random_mtg(tree, nb_scales):
    """An MTG of nb_scales scales over tree: at each coarser scale, a random part of the
    vertices of the scale below starts a complex."""
    n = len(tree)
    colors = {nb_scales - 1: tree.vertices()}
    for s in range(nb_scales - 2, 0, -1):
        n = random.randint(1, n)
        chosen = sorted(random.sample(colors[s + 1], n))
        if tree.root not in chosen:
            chosen.insert(0, tree.root)
        colors[s] = chosen
    return colored_tree(tree, colors)[0]


def colored_tree(tree, colors):
    """The MTG whose finest scale is tree, each scale s's complexes starting at the vertices
    colors[s]; and the map from its finest vertices' ids to tree's."""
    nb_scales = max(colors.keys()) + 1
    ids, count = {}, 1
    for scale in range(1, nb_scales):
        ids[scale] = {}
        for v in colors[scale]:
            ids[scale][v] = count
            count += 1
    g = MTG()
    index = ids[1]
    for v in colors[1]:
        g.add_component(g.root, index[v])
    for scale in range(2, nb_scales):
        previous, index = index, ids[scale]
        for v in colors[scale]:
            complex_id, component_id = previous.get(v), index.get(v)
            if complex_id:
                g.add_component(complex_id, component_id)
            elif component_id:
                g._scale[component_id] = scale
    finest = tree.max_scale() if isinstance(tree, MTG) else None
    for k, v in tree._parent.items():
        if v is not None and (finest is None or tree.scale(v) == finest):
            g._parent[index[k]] = index[v]
    for parent, children in tree._children.items():
        if finest is None or tree.scale(parent) == finest:
            g._children[index[parent]] = [index[c] for c in children]
    for pname, prop in tree.properties().items():
        values = g._properties.setdefault(pname, {})
        for v, value in prop.items():
            if finest is None or tree.scale(v) == finest:
                values[index[v]] = value
    return fat_mtg(g), dict(zip(index.values(), index.keys()))


def display_tree(tree, vid, tab='', labels={}, edge_type={}):
    labels = labels or tree.property('label')
    edge_type = edge_type or tree.property('edge_type')
    yield tab + edge_type.get(vid, '/') + labels.get(vid, str(vid))
    for v in tree.children_iter(vid):
        more = '\t' if edge_type.get(v) == '+' else ''
        yield from display_tree(tree, v, tab + more, edge_type=edge_type, labels=labels)


def display_mtg(mtg, vid):
    label, edge_type = mtg.property('label'), mtg.property('edge_type')
    current, tab = vid, 0
    for vtx in traversal.iter_mtg2(mtg, vid):
        et = '/'
        if vtx != current:
            s1, s2 = mtg.scale(current), mtg.scale(vtx)
            if s1 >= s2:
                et = '^' + edge_type[vtx]
                if s1 == s2 and mtg.parent(vtx) != current:
                    tab = -1
                elif s1 > s2:
                    v = current
                    for _ in range(s1 - s2):
                        v = mtg.complex(v)
                    if mtg.parent(vtx) != v:
                        tab -= 1
            else:
                tab += 1
            yield tab * '\t' + et + label.get(vtx, str(vtx))
        current = vtx
