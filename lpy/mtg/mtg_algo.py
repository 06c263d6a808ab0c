# openalea.mtg.algo as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): the walks of an MTG that AML's functions and models use (ancestors,
# descendants, axes, orders, heights...), read from openalea.mtg's definition
# (src/openalea/mtg/algo.py, CeCILL-C).

from collections import deque

from . import traversal
from .tree import InvalidVertex


def _in_complex(g, v, ci):
    return ci is None or g.complex_at_scale(v, scale=g.scale(ci)) == ci


def ancestors(g, vid, **kwds):
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    v = vid
    while v is not None:
        if rt == 'SameComplex' and g.complex(v) != g.complex(vid):
            break
        if ci and not _in_complex(g, v, ci):
            break
        yield v
        v = g.parent(v)


def path(g, vid1, vid2=None):
    """The vertices from vid1 down to vid2 (one is the other's ancestor) and the direction."""
    if vid2 is None:
        return ancestors(g, vid1), 1
    sign = 1
    chain = list(ancestors(g, vid2))
    if vid1 in chain:
        index = chain.index(vid1)
    else:
        chain = list(ancestors(g, vid1))
        if vid2 not in chain:
            return iter([]), 0
        index, sign = chain.index(vid2), -1
    return reversed(chain[:index + 1]), sign


def edge_type(g, v):
    return g.property('edge_type').get(v)


def topological_path(g, v1, v2=None, edge=None):
    p, sign = path(g, v1, v2)
    if sign == 0:
        return None
    if edge is None:
        return sum(1 for v in p), sign
    return sum(1 for v in p if g.edge_type(v) == edge), sign


def order(g, v1, v2=None):
    return topological_path(g, v1, v2, '+')[0]


def alg_rank(g, v1, v2=None):
    p, sign = path(g, v1, v2)
    count = 0
    for v in p:
        if edge_type(g, v) != '<':
            break
        count += 1
    return count * sign


def rank(g, v1, v2=None):
    return abs(alg_rank(g, v1, v2))


def height(g, v1, v2=None):
    return topological_path(g, v1, v2)[0] - 1


def alg_order(g, v1, v2=None):
    p, s = topological_path(g, v1, v2, '+')
    return p * s


def alg_height(g, v1, v2=None):
    p, s = topological_path(g, v1, v2)
    return p * s


def father(g, vid, scale=-1, **kwds):
    et = kwds.get('EdgeType', '*')
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    current = g.scale(vid)
    if scale <= 0 or scale == current:
        p = g.parent(vid)
    elif scale < current:
        vid = g.complex_at_scale(vid, scale)
        p = g.parent(vid)
    else:
        vid = next(g.component_roots_at_scale_iter(vid, scale=scale))
        p = g.parent(vid)
    if et != '*' and types.get(vid) != et:
        return None
    if rt == 'SameComplex' and g.complex(p) != g.complex(vid):
        return None
    if rt == 'SameAxis' and types.get(vid) == '+':
        return None
    if ci is not None:
        c_scale = g.scale(ci)
        if g.complex_at_scale(vid, scale=c_scale) != g.complex_at_scale(p, scale=c_scale) != ci:
            return None
    return p


def successor(g, vid, **kwds):
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    son = next((v for v in g.children_iter(vid) if types.get(v) == '<'), None)
    if son is None:
        return None
    if rt == 'SameComplex' and g.complex(son) != g.complex(vid):
        return None
    if ci is not None:
        c_scale = g.scale(ci)
        if g.complex_at_scale(vid, scale=c_scale) != g.complex_at_scale(son, scale=c_scale) != ci:
            return None
    return son


def predecessor(g, vid, **kwds):
    return father(g, vid, **kwds)


def root(g, vid, RestrictedTo='NoRestriction', ContainedIn=None):
    current = vid
    for v in ancestors(g, vid):
        if RestrictedTo == 'SameComplex' and g.complex(v) != g.complex(vid):
            break
        current = v
    return current


def location(g, vid, **kwds):
    scale = kwds.get('Scale')
    if not scale or scale < 0:
        scale = g.max_scale()
    return father(g, vid, scale=scale, ContainedIn=kwds.get('ContainedIn'))


def sons(g, vid, **kwds):
    et, ci, scale = kwds.get('EdgeType', '*'), kwds.get('ContainedIn'), kwds.get('Scale')
    types = g.property('edge_type')
    vid = vertex_at_scale(g, vid, scale if scale and scale > 0 else g.scale(vid))
    children = g.children_iter(vid)
    if et != '*':
        children = (v for v in children if types[v] == et)
    if ci is not None:
        children = (v for v in children if _in_complex(g, v, ci))
    return list(children)


def full_ancestors(g, v1, **kwds):
    et = kwds.get('EdgeType', '*')
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    v = v1
    while v is not None:
        if et != '*' and types.get(v) != et:
            break
        if rt == 'SameComplex' and g.complex(v) != g.complex(v1):
            break
        if rt == 'SameAxis' and types.get(v) == '+':
            break
        if ci and not _in_complex(g, v, ci):
            break
        yield v
        v = g.parent(v)


def axis(g, vtx_id, scale=-1, **kwds):
    """The axis vtx_id is on: from its first vertex (a branch's or the root's) along '<' edges."""
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    kwds['EdgeType'] = '<'
    for v in ancestors(g, vtx_id, **kwds):
        if rt == 'SameComplex' and g.complex(v) != g.complex(vtx_id):
            break
        if ci and not _in_complex(g, v, ci):
            break
        if types.get(v) == '+':
            break
    return local_axis(g, v, scale=scale, **kwds)


def descendants(g, vtx_id, scale=-1, **kwds):
    et = kwds.get('EdgeType', '*')
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    vtx_id = vertex_at_scale(g, vtx_id, scale)
    complex = g.complex(vtx_id)

    def keep(v):
        if et in ['<', '+'] and et != types.get(v, et):
            return False
        if rt == 'SameComplex' and g.complex(v) != complex:
            return False
        if rt == 'SameAxis' and types.get(v) == '+':
            return False
        return not ci or _in_complex(g, v, ci)
    return traversal.pre_order2_with_filter(g, vtx_id, pre_order_filter=keep)


def extremities(g, vid, **kwds):
    vertices = set(descendants(g, vid, **kwds))
    for v in vertices:
        if g.is_leaf(v) or not any(c in vertices for c in g.children_iter(v)):
            yield v


def local_axis(g, vtx_id, scale=-1, **kwds):
    rt, ci = kwds.get('RestrictedTo', 'NoRestriction'), kwds.get('ContainedIn')
    types = g.property('edge_type')
    vtx_id = vertex_at_scale(g, vtx_id, scale)
    v = vtx_id
    while v is not None:
        yield v
        following = None
        for c in g.children_iter(v):
            if types.get(c) == '<':
                following = c
                if rt == 'SameComplex' and g.complex(c) != g.complex(vtx_id):
                    following = None
                if ci and not _in_complex(g, c, ci):
                    following = None
        v = following


def vertex_at_scale(g, vtx_id, scale):
    if scale is None or scale <= 0:
        return vtx_id
    current = g.scale(vtx_id)
    if scale < current:
        return g.complex_at_scale(vtx_id, scale=scale)
    if scale > current:
        return next(g.component_roots_at_scale_iter(vtx_id, scale=scale))
    return vtx_id


def trunk(g, vtx_id, scale=-1, **kwds):
    kwds['EdgeType'] = '<'
    vtx_id = vertex_at_scale(g, vtx_id, scale)
    v = root(g, vtx_id, RestrictedTo=kwds.get('RestrictedTo', 'NoRestriction'), ContainedIn=kwds.get('ContainedIn'))
    return local_axis(g, v, scale, **kwds)


def union(g1, g2, vid1=None, vid2=None, edge_type='<'):
    """g2 (below vid2) joined to a copy of g1 at vid1."""
    v1 = vid1 if vid1 is not None else g1.root
    if v1 not in g1:
        raise InvalidVertex(v1)
    v2 = vid2 if vid2 is not None else g2.root
    if v2 not in g2:
        raise InvalidVertex(v2)
    g = g1.sub_mtg(g1.root)
    ids = {}
    below = traversal.iter_mtg2(g2, v2)
    if v1 == g1.root and v2 == g2.root:
        ids[v2] = v1
        next(below)
    else:
        v2 = next(below)
        v = g.add_child(v1)
        ids[v2] = v
        g._add_vertex_properties(v, g2.get_vertex_property(v2))
        g.node(v).edge_type = edge_type
    for vid in below:
        v = g.add_component(ids[g2.complex(vid)])
        ids[vid] = v
        pid = g2.parent(vid)
        if pid is not None:
            g.add_child(ids[pid], child=v)
        g._add_vertex_properties(v, g2.get_vertex_property(vid))
    return g


def split(g, scale=1):
    return [g.sub_mtg(vid) for vid in g.component_roots_at_scale(g.root, scale=scale)]


def _per_vertex(g, scale, first, step):
    values = {}
    def walk(vertices):
        for vid in vertices:
            pid = g.parent(vid)
            values[vid] = step(vid, first if pid is None else values[pid])
    if scale <= 0:
        walk(traversal.iter_mtg2(g, g.root))
    else:
        for rid in g.roots_iter(scale=scale):
            walk(traversal.pre_order2(g, rid))
    return values


def orders(g, scale=-1):
    """Each vertex's order: the number of '+' edges from its root."""
    return _per_vertex(g, scale, 0, lambda v, p: p + 1 if g.edge_type(v) == '+' else p)


def heights(g, scale=-1):
    """Each vertex's height: the number of edges from its root."""
    return _per_vertex(g, scale, -1, lambda v, p: p + 1)


def lookForCommonAncestor(g, commonAncestors, currentNode):
    while currentNode is not None:
        if currentNode in commonAncestors:
            for _ in range(list(commonAncestors).index(currentNode)):
                commonAncestors.popleft()
            return
        currentNode = g.parent(currentNode)


def lowestCommonAncestor(g, nodes):
    if len(nodes) <= 1:
        return None
    common = deque(g.Ancestors(nodes[0]))
    for node in nodes[1:]:
        if not common:
            break
        lookForCommonAncestor(g, common, node)
    return common[0] if common else None
