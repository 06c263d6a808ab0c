# openalea.mtg.tree as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): a rooted tree of integer vertex ids (Tree) and one with a property dict
# per property name (PropertyTree), read from openalea.mtg's definition
# (src/openalea/mtg/tree.py, CeCILL-C): the same ids, the same errors.

from copy import deepcopy

from .traversal import *


class GraphError(Exception):
    """An operation the graph refuses."""


class InvalidVertex(GraphError, KeyError):
    """A vertex that is not in the graph, or that cannot take the operation."""


class Tree:
    """A rooted tree: each vertex's parent and its ordered children."""

    def __init__(self, root=0, tree=None):
        self._root = root
        self._id = root
        self._parent = {root: None}
        self._children = {}

    def __len__(self):
        return self.nb_vertices()

    def nb_vertices(self):
        return len(self._parent)

    def vertices_iter(self):
        return iter(self._parent.keys())

    def vertices(self):
        return list(self.vertices_iter())

    def __iter__(self):
        return self.vertices_iter()

    def has_vertex(self, vid):
        return vid in self._parent

    def __contains__(self, vid):
        return self.has_vertex(vid)

    def is_valid(self):
        return True

    def iteredges(self):
        return ((parent, child) for child, parent in self._parent.items())

    def remove_vertex(self, vid, reparent_child=False):
        if vid == self.root:
            raise InvalidVertex('Removing the root node %d is forbidden.' % vid)
        if reparent_child:
            new_parent = self.parent(vid)
            for cid in list(self.children(vid)):
                self.replace_parent(cid, new_parent)
        if self.nb_children(vid) != 0:
            raise InvalidVertex('Can not remove vertex %d  with children. Use remove_tree instead.' % vid)
        p = self.parent(vid)
        if p is not None:
            self._children[p].remove(vid)
            del self._parent[vid]
        self._children.pop(vid, None)

    def clear(self):
        self._root = 0
        self._id = 0
        self._parent.clear()
        self._children.clear()
        self._parent[self._root] = None

    def set_root(self, vtx_id):
        self._root = vtx_id
        if vtx_id not in self._parent:
            self._parent[vtx_id] = None

    def get_root(self):
        return self._root

    root = property(get_root, set_root)

    def parent(self, vtx_id):
        return self._parent.get(vtx_id)

    def children_iter(self, vtx_id):
        return iter(self._children.get(vtx_id, []))

    def children(self, vtx_id):
        return self._children.get(vtx_id, [])

    def nb_children(self, vtx_id):
        return len(self.children(vtx_id))

    def siblings_iter(self, vtx_id):
        parent = self.parent(vtx_id)
        if parent is None:
            return iter([])
        return (vid for vid in self._children[parent] if vid != vtx_id)

    def siblings(self, vtx_id):
        return list(self.siblings_iter(vtx_id))

    def nb_siblings(self, vtx_id):
        n = self.nb_children(self.parent(vtx_id))
        return n - 1 if n > 0 else 0

    def is_leaf(self, vtx_id):
        return self.nb_children(vtx_id) == 0

    def _new_id(self, vid):
        if vid is None:
            self._id += 1
            vid = self._id
        return vid

    def add_child(self, parent, child=None, **properties):
        child = self._new_id(child)
        self._children.setdefault(parent, []).append(child)
        self._parent[child] = parent
        return child

    def insert_sibling(self, vtx_id1, vtx_id2=None, **properties):
        vtx_id2 = self._new_id(vtx_id2)
        parent = self.parent(vtx_id1)
        siblings = self._children[parent]
        siblings.insert(siblings.index(vtx_id1), vtx_id2)
        self._parent[vtx_id2] = parent
        return vtx_id2

    def insert_parent(self, vtx_id, parent_id=None, **properties):
        parent_id = self._new_id(parent_id)
        old_parent = self.parent(vtx_id)
        self.add_child(parent_id, vtx_id)
        if old_parent is not None:
            children = self._children[old_parent]
            children[children.index(vtx_id)] = parent_id
            self._parent[parent_id] = old_parent
        return parent_id

    def replace_parent(self, vtx_id, new_parent_id, **properties):
        if new_parent_id not in self:
            raise InvalidVertex(new_parent_id)
        old_parent = self.parent(vtx_id)
        self.add_child(new_parent_id, vtx_id)
        if old_parent is not None:
            self._children[old_parent].remove(vtx_id)

    def __str__(self):
        return 'Tree : nb_vertices=%d' % self.nb_vertices()

    def sub_tree(self, vtx_id, copy=True):
        if not copy:
            bunch = set(pre_order(self, vtx_id))
            for vid in list(self):
                if vid not in bunch:
                    self.remove_vertex(vid)
            self._root = vtx_id
            self._parent[self._root] = None
            return self
        ids = {vtx_id: 0}
        tree = Tree()
        below = pre_order(self, vtx_id)
        next(below)
        for vid in below:
            ids[vid] = tree.add_child(ids[self.parent(vid)])
        return tree

    def insert_sibling_tree(self, vid, tree):
        ids = {tree.root: self.insert_sibling(vid)}
        for v in pre_order(tree, tree.root):
            if v != tree.root:
                ids[v] = self.add_child(ids[tree.parent(v)])
        return ids

    def add_child_tree(self, parent, tree):
        ids = {tree.root: self.add_child(parent)}
        for v in pre_order(tree, tree.root):
            if v != tree.root:
                ids[v] = self.add_child(ids[tree.parent(v)])
        return ids

    def remove_tree(self, vtx_id):
        removed = []
        for vid in list(post_order(self, vtx_id)):
            self.remove_vertex(vid)
            removed.append(vid)
        return removed

    def copy(self):
        return deepcopy(self)


class PropertyTree(Tree):
    """A Tree with properties: for each name, a dict from vertex to value."""

    def __init__(self, *args, **kwds):
        super().__init__(*args, **kwds)
        self._properties = {}
        self._graph_properties = {}

    def remove_vertex(self, vid, reparent_child=False):
        super().remove_vertex(vid, reparent_child=reparent_child)
        self._remove_vertex_properties(vid)

    def add_child(self, parent, child=None, **properties):
        child = super().add_child(parent, child)
        self._add_vertex_properties(child, properties)
        return child

    def insert_sibling(self, vtx_id1, vtx_id2=None, **properties):
        vtx_id2 = super().insert_sibling(vtx_id1, vtx_id2)
        self._add_vertex_properties(vtx_id2, properties)
        return vtx_id2

    def insert_parent(self, vtx_id, parent_id=None, **properties):
        parent_id = super().insert_parent(vtx_id, parent_id)
        self._add_vertex_properties(parent_id, properties)
        return parent_id

    def sub_tree(self, vtx_id, copy=True):
        if not copy:
            bunch = set(pre_order(self, vtx_id))
            for vid in set(self) - bunch:
                self._remove_vertex_properties(vid)
                pid = self.parent(vid)
                if pid is not None:
                    self._children[pid].remove(vid)
                    del self._parent[vid]
                for cid in self.children(vid):
                    self._parent[cid] = None
                self._children.pop(vid, None)
            self.root = vtx_id
            return self
        tree = self.__class__()
        for name in self.properties():
            tree.add_property(name)
        ids = {vtx_id: tree.root}
        tree._add_vertex_properties(tree.root, self.get_vertex_property(vtx_id))
        below = pre_order(self, vtx_id)
        next(below)
        for vid in below:
            ids[vid] = v = tree.add_child(ids[self.parent(vid)])
            tree._add_vertex_properties(v, self.get_vertex_property(vid))
        return tree

    def _copy_properties(self, tree, ids):
        for tid, vid in ids.items():
            for name in tree.properties():
                v = tree.property(name).get(tid)
                if v is not None:
                    self.property(name)[vid] = v
        return ids

    def insert_sibling_tree(self, vid, tree):
        return self._copy_properties(tree, super().insert_sibling_tree(vid, tree))

    def add_child_tree(self, parent, tree):
        return self._copy_properties(tree, super().add_child_tree(parent, tree))

    def remove_tree(self, vtx_id):
        vids = super().remove_tree(vtx_id)
        for vid in vids:
            self._remove_vertex_properties(vid)
        return vids

    def property_names(self):
        return list(self._properties.keys())

    def property_names_iter(self):
        return iter(self._properties.keys())

    def property(self, name):
        return self._properties.setdefault(name, {})

    def add_property(self, property_name):
        self._properties[property_name] = {}

    def remove_property(self, property_name):
        del self._properties[property_name]

    def properties(self):
        return self._properties

    def _add_vertex_properties(self, vid, properties):
        for name in properties:
            if name not in self._properties:
                self.add_property(name)
            self._properties[name][vid] = properties[name]

    def _remove_vertex_properties(self, vid):
        for p in self._properties.values():
            p.pop(vid, None)

    def get_vertex_property(self, vid):
        p = self._properties
        return dict((name, p[name][vid]) for name in p if vid in p[name])

    def graph_properties(self):
        return self._graph_properties
