# openalea.mtg.traversal as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): the orders in which an MTG's vertices are visited, read from openalea.mtg's
# definition (src/openalea/mtg/traversal.py, CeCILL-C). A vertex's children are visited
# branches ('+' edges) first and its successor ('<') last, as openalea.mtg visits them, so
# the vertex ids and the strings made from an MTG come out in openalea.mtg's order.

from collections import deque


def _ordered(tree, vid, keep):
    """The children of vid that `keep` keeps: branches first, then successors."""
    edge_type = tree.property('edge_type')
    plus, successors = [], []
    for v in tree.children_iter(vid):
        if keep(v):
            (successors if edge_type.get(v) == '<' else plus).append(v)
    return plus + successors


def pre_order(tree, vtx_id, complex=None, visitor_filter=None):
    """The tree below vtx_id, each vertex before its children (recursively)."""
    if complex is not None and tree.complex(vtx_id) != complex:
        return
    if visitor_filter and not visitor_filter.pre_order(vtx_id):
        return
    yield vtx_id
    for vid in _ordered(tree, vtx_id, lambda v: True):
        yield from pre_order(tree, vid, complex, visitor_filter)
    if visitor_filter:
        visitor_filter.post_order(vtx_id)


def pre_order_with_filter(tree, vtx_id, pre_order_filter=None, post_order_visitor=None):
    if pre_order_filter and not pre_order_filter(vtx_id):
        return
    yield vtx_id
    for vid in _ordered(tree, vtx_id, lambda v: True):
        yield from pre_order_with_filter(tree, vid, pre_order_filter, post_order_visitor)
    if post_order_visitor:
        post_order_visitor(vtx_id)


def pre_order2(tree, vtx_id, complex=None, visitor_filter=None):
    """pre_order without recursion (deep trees)."""
    if complex is not None and tree.complex(vtx_id) != complex:
        return
    def keep(v):
        if complex is not None and tree.complex(v) != complex:
            return False
        return not visitor_filter or visitor_filter.pre_order(tree, v)
    queue = deque([vtx_id])
    while queue:
        vid = queue.pop()
        yield vid
        queue.extend(reversed(_ordered(tree, vid, keep)))


def pre_order2_with_filter(tree, vtx_id, complex=None, pre_order_filter=None, post_order_visitor=None):
    def keep(v):
        if complex is not None and tree.complex(v) != complex:
            return False
        return not pre_order_filter or pre_order_filter(v)
    queue = deque([(vtx_id, list(reversed(_ordered(tree, vtx_id, keep))))])
    yield vtx_id
    while queue:
        vid, children = queue[-1]
        if children:
            child = children.pop()
            yield child
            queue.append((child, list(reversed(_ordered(tree, child, keep)))))
        else:
            queue.pop()
            if post_order_visitor:
                post_order_visitor(vid)


def pre_order_in_scale(tree, vtx_id, visitor_filter=None):
    queue = deque([vtx_id])
    while queue:
        vid = queue.pop()
        yield vid
        for c in tree.components_iter(vid):
            if not visitor_filter or visitor_filter.pre_order(c):
                queue.append(c)


def post_order(tree, vtx_id, complex=None, visitor_filter=None):
    """The tree below vtx_id, each vertex after its children."""
    if complex is not None and tree.complex(vtx_id) != complex:
        return
    if visitor_filter and not visitor_filter.pre_order(vtx_id):
        return
    for vid in tree.children_iter(vtx_id):
        yield from post_order(tree, vid, complex, visitor_filter)
    if visitor_filter:
        visitor_filter.post_order(vtx_id)
    yield vtx_id


def post_order2(tree, vtx_id, complex=None, pre_order_filter=None, post_order_visitor=None):
    """post_order without recursion, children in pre_order's order."""
    keep_filter = pre_order_filter or (lambda v: True)
    visit = post_order_visitor or (lambda v: None)
    def keep(v):
        return (complex is None or tree.complex(v) == complex) and keep_filter(v)
    visited = set()
    queue = [vtx_id]
    while queue:
        vid = queue[-1]
        for child in reversed(_ordered(tree, vid, keep)):
            if child not in visited:
                queue.append(child)
                break
        else:
            visit(vid)
            yield vid
            visited.add(vid)
            queue.pop()


def traverse_tree(tree, vtx_id, visitor):
    yield visitor.pre_order(vtx_id)
    for v in tree.children_iter(vtx_id):
        yield from traverse_tree(tree, v, visitor)
    yield visitor.post_order(vtx_id)


class Visitor:
    """What traverse_tree calls before and after a vertex's children."""

    def pre_order(self, vtx_id):
        pass

    def post_order(self, vtx_id):
        pass


def iter_scale(g, vtx_id, visited):
    """vtx_id's complexes not yet visited, the coarsest first, then vtx_id."""
    if vtx_id is not None and vtx_id not in visited:
        yield from iter_scale(g, g._complex.get(vtx_id), visited)
        visited[vtx_id] = True
        yield vtx_id


def iter_scale2(g, vtx_id, complex_id, visited):
    if (vtx_id is not None and vtx_id not in visited
            and g.complex_at_scale(vtx_id, g.scale(complex_id)) == complex_id):
        yield from iter_scale2(g, g._complex.get(vtx_id), complex_id, visited)
        visited[vtx_id] = True
        yield vtx_id


def iter_mtg(mtg, vtx_id):
    """Every vertex of the MTG below vtx_id, each complex just before its first component."""
    visited = {vtx_id: True}
    yield vtx_id
    while mtg._components.get(vtx_id):
        vtx_id = mtg._components[vtx_id][0]
    for vid in pre_order2(mtg, vtx_id):
        yield from iter_scale(mtg, vid, visited)


def iter_mtg2(mtg, vtx_id):
    """iter_mtg over every tree of the finest scale that vtx_id holds."""
    visited = {vtx_id: True}
    complex_id = vtx_id
    yield vtx_id
    for root in mtg.component_roots_at_scale_iter(complex_id, mtg.max_scale()):
        for vid in pre_order2(mtg, root):
            yield from iter_scale2(mtg, vid, complex_id, visited)


def iter_mtg_with_filter(mtg, vtx_id, pre_order_filter=None, post_order_visitor=None):
    visited = {}
    cid = mtg.complex(vtx_id)
    if cid is not None:
        visited[cid] = True
    while mtg._components.get(vtx_id):
        vtx_id = mtg._components[vtx_id][0]
    for vid in pre_order_with_filter(mtg, vtx_id, pre_order_filter, post_order_visitor):
        yield from iter_scale(mtg, vid, visited)


def iter_mtg2_with_filter(mtg, vtx_id, pre_order_filter=None, post_order_visitor=None):
    """iter_mtg2 calling pre_order_filter on each vertex as it is given and
    post_order_visitor once all below it at its scale have been (mtg2axialtree's brackets)."""
    pre = pre_order_filter or (lambda v: True)
    post = post_order_visitor or (lambda v: None)
    visited = {vtx_id: True}
    complex_id = vtx_id
    max_scale = mtg.max_scale()
    pre(vtx_id)
    yield vtx_id
    queue = [vtx_id]
    for root in mtg.component_roots_at_scale_iter(complex_id, max_scale):
        for vid in pre_order2_with_filter(mtg, root, post_order_visitor=post):
            for node in iter_scale2(mtg, vid, complex_id, visited):
                scale = mtg.scale(node)
                if scale != max_scale:
                    _close_coarser(mtg, queue, node, scale, post)
                pre(node)
                yield node
        while len(queue) > 1:
            post(queue.pop())


def _close_coarser(mtg, queue, node, scale, post):
    """The coarser vertices left behind by `node` closed (post-visited), as openalea.mtg does."""
    prev_scale = mtg.scale(queue[-1])
    if prev_scale < scale:
        queue.append(node)
    elif prev_scale == scale:
        if mtg.parent(node) != queue[-1]:
            post(queue[-1])
            queue[-1] = node
        else:
            queue.append(node)
    else:
        prev = queue.pop()
        while mtg.scale(prev) > scale:
            post(prev)
            prev = queue.pop()
        if mtg.parent(node) != prev:
            post(prev)
        queue.append(node)


def topological_sort(g, vtx_id, visited=None):
    if visited is None:
        visited = {}
    yield vtx_id
    visited[vtx_id] = True
    for vid in g.out_neighbors(vtx_id):
        if vid not in visited:
            yield from topological_sort(g, vid, visited)
