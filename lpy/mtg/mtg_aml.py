# openalea.mtg.aml as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): AML's functions on the active MTG (MTG(file) reads and activates one),
# read from openalea.mtg's definition (src/openalea/mtg/aml.py, CeCILL-C). Those openalea.mtg
# leaves unimplemented (dates, coordinates, the plant frame) raise its NotImplementedError.

import openalea.mtg.mtg as mtg
from openalea.mtg.io import read_mtg_file
import openalea.mtg.algo as algo

_g = None


def MTG(filename):
    """Reads an MTG file and makes its MTG the active one."""
    global _g
    _g = read_mtg_file(filename)
    return _g


def Activate(g):
    global _g
    _g = g
    return _g


def Active():
    return _g


def MTGRoot():
    return _g.root


def VtxList(Scale=-1):
    return _g.vertices(scale=Scale)


def Label(v):
    if isinstance(v, list):
        return [Class(x) + str(Index(x)) for x in v]
    return Class(v) + str(Index(v))


def Class(vid):
    """The first letter of the vertex's label (AML's one-letter classes)."""
    label = _g.property('label').get(vid, '')
    return label[0] if label else ''


def Index(vid):
    return _g.property('index').get(vid, vid)


def Scale(vid):
    return _g.scale(vid)


def Feature(vid, fname, date=None):
    return _g.property(fname).get(vid)


def ClassScale(c):
    for x in _g.vertices():
        if Class(x) == c:
            return Scale(x)


def EdgeType(v1, v2):
    return _g.EdgeType(v1, v2)


def Defined(vid):
    return vid in _g


def Order(v1, v2=None):
    return algo.order(_g, v1, v2)


def Rank(v1, v2=None):
    return algo.rank(_g, v1, v2)


def Height(v1, v2=None):
    return algo.height(_g, v1, v2)


def AlgOrder(v1, v2):
    return algo.alg_order(_g, v1, v2)


def AlgRank(v1, v2):
    return algo.alg_rank(_g, v1, v2)


def AlgHeight(v1, v2):
    return algo.alg_height(_g, v1, v2)


def Father(v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None, Scale=-1):
    return _g.Father(v, EdgeType=EdgeType, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn, Scale=Scale)


def Successor(v, RestrictedTo='NoRestriction', ContainedIn=None):
    return algo.successor(_g, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)


def Predecessor(v, **kwds):
    return Father(v, EdgeType='<', **kwds)


def Root(v, RestrictedTo='*', ContainedIn=None):
    return algo.root(_g, v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)


def Complex(v, Scale=-1):
    return _g.Complex(v, Scale=Scale)


def Location(v, Scale=-1, ContainedIn=None):
    return algo.location(_g, v, Scale=Scale, ContainedIn=ContainedIn)


def Sons(v, RestrictedTo='NoRestriction', EdgeType='*', Scale=-1, ContainedIn=None):
    return _g.Sons(v, RestrictedTo=RestrictedTo, EdgeType=EdgeType, Scale=Scale, ContainedIn=ContainedIn)


def Ancestors(v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None):
    return _g.Ancestors(v, EdgeType=EdgeType, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)


def Descendants(v, EdgeType='*', RestrictedTo='NoRestriction', ContainedIn=None):
    return _g.Descendants(v, EdgeType=EdgeType, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)


def Extremities(v, RestrictedTo='NoRestriction', ContainedIn=None):
    return _g.Extremities(v, RestrictedTo=RestrictedTo, ContainedIn=ContainedIn)


def Components(v, Scale=-1):
    return _g.Components(v, Scale=Scale)


def ComponentRoots(v, Scale=-1):
    return _g.component_roots_at_scale(v, scale=Scale)


def Path(v1, v2):
    return _g.Path(v1, v2)


def Axis(v, Scale=-1):
    return _g.Axis(v, Scale=Scale)


def Trunk(v, Scale=-1):
    return _g.Trunk(v, Scale=Scale)


def _not_implemented(name, nargs):
    def f(*args):
        raise NotImplementedError('Function not yet implemented')
    f.__name__ = name
    f.__doc__ = 'Not implemented in openalea.mtg either.'
    return f


for _name, _n in [('DateSample', 1), ('FirstDefinedFeature', 2), ('LastDefinedFeature', 2), ('NextDate', 1),
                  ('PreviousDate', 1), ('PlantFrame', 1), ('TopCoord', 2), ('RelTopCoord', 2), ('BottomCoord', 2),
                  ('RelBottomCoord', 2), ('Coord', 2), ('DressingData', 1), ('Plot', 1), ('BottomDiameter', 2),
                  ('TopDiameter', 2), ('Alpha', 2), ('Beta', 2), ('Length', 2), ('VirtualPattern', 1), ('PDir', 2),
                  ('SDir', 2)]:
    globals()[_name] = _not_implemented(_name, _n)
del _name, _n
