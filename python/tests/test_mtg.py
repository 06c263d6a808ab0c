"""openalea.mtg as L-Py models use it (issue 51): Sprout's own where the real one is not
installed (lpy/mtg/). The expected vertices, properties and texts below were worked out by hand
and checked against openalea.mtg itself (its repository's src/, pure Python, run on the same
inputs beside Sprout's openalea.lpy): they agree to the last id and digit. The models' strings
and MTGs are also those the reference L-Py 3.15.4 gives with that openalea.mtg."""
import pytest

import sprout

sprout.use_as_openalea()
from openalea.lpy import Lsystem  # noqa: E402
from openalea.mtg import MTG  # noqa: E402
from openalea.mtg import algo, traversal  # noqa: E402
from openalea.mtg.io import axialtree2mtg, mtg2axialtree, read_mtg, read_mtg_file, write_mtg  # noqa: E402

# A plant (P) of axes (A) of internodes (E); a branch A2 on E2; features of three types.
TEXT = """CODE:\tFORM-A

CLASSES:
SYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION
$\t0\tFREE\tFREE\tIMPLICIT
P\t1\tFREE\tFREE\tEXPLICIT
A\t2\tFREE\tFREE\tEXPLICIT
E\t3\tFREE\tFREE\tEXPLICIT

DESCRIPTION:
LEFT\tRIGHT\tRELTYPE\tMAX
A\tA\t+\t?
A\tA\t<\t?
E\tE\t<\t?
E\tE\t+\t?

FEATURES:
NAME\tTYPE
length\tREAL
nb\tINT
kind\tALPHA

MTG:
ENTITY-CODE\t\tlength\tnb\tkind
/P1/A1/E1\t\t2.5\t3\ttrunk
^<E2\t\t1.25\t\t
\t+A2/E1\t0.75\t1\tshoot
\t^<E2\t0.5\t\t
^<E3\t\t4.0\t2\t
"""


def test_an_mtg_file_is_read_vertex_by_vertex_with_its_features_typed():
    g = read_mtg(TEXT)
    assert len(g) == 9 and g.nb_scales() == 4 and g.max_scale() == 3
    assert sorted(g._scale.items()) == [(0, 0), (1, 1), (2, 2), (3, 3), (4, 3), (5, 2), (6, 3), (7, 3), (8, 3)]
    assert sorted(g._parent.items()) == [(0, None), (4, 3), (5, 2), (6, 4), (7, 6), (8, 4)]
    assert sorted(g._complex.items()) == [(1, 0), (2, 1), (3, 2), (5, 1), (6, 5)]
    assert [g.label(v) for v in range(1, 9)] == ['P1', 'A1', 'E1', 'E2', 'A2', 'E1', 'E2', 'E3']
    assert [g.class_name(v) for v in (1, 2, 8)] == ['P', 'A', 'E']
    assert sorted(g.property('edge_type').items()) == [(4, '<'), (5, '+'), (6, '+'), (7, '<'), (8, '<')]
    assert sorted(g.property('length').items()) == [(3, 2.5), (4, 1.25), (6, 0.75), (7, 0.5), (8, 4.0)]
    assert sorted(g.property('nb').items()) == [(3, 3), (6, 1), (8, 2)]
    assert all(type(v) is int for v in g.property('nb').values())
    assert sorted(g.property('kind').items()) == [(3, 'trunk'), (6, 'shoot')]
    assert sorted(g.property('_line').items()) == [(3, 24), (4, 25), (6, 26), (7, 27), (8, 28)]


def test_the_walks_of_an_mtg():
    g = read_mtg(TEXT)
    assert list(traversal.iter_mtg2(g, 0)) == list(range(9))
    assert algo.orders(g) == {0: 0, 1: 0, 2: 0, 3: 0, 4: 0, 5: 1, 6: 1, 7: 1, 8: 0}
    assert algo.heights(g) == {0: 0, 1: 0, 2: 0, 3: 0, 4: 1, 5: 1, 6: 2, 7: 3, 8: 2}
    assert g.Sons(3) == [4] and g.Ancestors(7) == [7, 6, 4, 3] and g.Axis(7) == [6, 7]
    assert g.Trunk(7) == [3, 4, 8] and g.Descendants(3) == [3, 4, 6, 7, 8] and sorted(g.Extremities(3)) == [7, 8]
    assert g.Path(3, 7) == [3, 4, 6, 7] and g.Father(6) == 4 and g.Successor(3) == 4
    assert g.components(2) == [3, 4, 8] and g.components_at_scale(1, 3) == [3, 4, 8, 6, 7]
    assert g.complex(6) == 5 and g.Complex(6, Scale=1) == 1 and g.roots(scale=3) == [3]
    node = g.node(6)
    assert node.length == 0.75 and node.parent().label == 'E2' and [c.label for c in node.children()] == ['E2']
    assert g.order(7) == 1 and g.Rank(8) == 2 and g.Height(7) == 3


def test_an_mtg_written_is_the_mtg_format_and_reads_back():
    g = read_mtg(TEXT)
    text = write_mtg(g, properties=[('length', 'REAL'), ('nb', 'INT'), ('kind', 'ALPHA')], nb_tab=3)
    assert text.endswith(
        "MTG :\nENTITY-CODE\t\t\tlength\tnb\tkind\n/P1\t\t\t\t\t\n^/A1\t\t\t\t\t\n^/E1\t\t\t2.5\t3\ttrunk\n"
        "^<E2\t\t\t1.25\t\t\n\t+A2\t\t\t\t\n\t^/E1\t\t0.75\t1\tshoot\n\t^<E2\t\t0.5\t\t\n^<E3\t\t\t4.0\t2\t\n")
    assert "CLASSES :\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n$\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE" in text
    assert "FEATURES :\nNAME\tTYPE\nlength\tREAL\nnb\tINT\nkind\tALPHA\n" in text
    back = read_mtg(text)
    assert sorted(back._parent.items()) == sorted(g._parent.items())
    assert sorted(back._complex.items()) == sorted(g._complex.items())
    for name in ('label', 'edge_type', 'length', 'nb', 'kind'):
        assert back.property(name) == g.property(name), name


def test_an_mtg_built_by_hand():
    g = MTG()
    plant = g.add_component(g.root, label='P1')
    a = g.add_component(plant, label='A1')
    b = g.add_child(a, edge_type='<', label='A2')
    c = g.add_child(a, edge_type='+', label='A3', length=2.0)
    assert (plant, a, b, c) == (1, 2, 3, 4)
    assert g.scale(c) == 2 and g.complex(c) == plant and g.children(a) == [3, 4]
    assert list(traversal.pre_order(g, a)) == [2, 4, 3]  # branches before the successor
    assert g[4]['length'] == 2.0 and g[4]['parent'] == 2 and g[4]['scale'] == 2
    with pytest.raises(IndexError):
        g[99]
    with pytest.raises(KeyError):  # InvalidVertex: openalea.mtg's GraphError and KeyError
        g.remove_vertex(g.root)


MODEL = """
module P : scale = 1
module U(n) : scale = 2
module I(length, radius) : scale = 3
Axiom: P U(1) I(1.5, 0.25) A
derivation length: 2
production:
A --> [ + I(0.5, 0.125) ] I(2.0, 0.2) U(2) I(0.75, 0.1) A
endlsystem
"""
PARAMETERS = {'P': [], 'U': ['n'], 'I': ['length', 'radius']}


def test_an_lstring_made_into_an_mtg_and_back(tmp_path):
    path = tmp_path / 'multiscale.lpy'
    path.write_text(MODEL)
    s = Lsystem(str(path)).derive()
    assert str(s) == ('PU(1)I(1.5,0.25)[+I(0.5,0.125)]I(2.0,0.2)U(2)I(0.75,0.1)'
                      '[+I(0.5,0.125)]I(2.0,0.2)U(2)I(0.75,0.1)A')
    g = axialtree2mtg(s, {'P': 1, 'U': 2, 'I': 3}, None, PARAMETERS)
    assert sorted(g._scale.items()) == [(0, 0), (1, 1), (2, 2), (3, 3), (4, 3), (5, 3), (6, 2), (7, 3), (8, 3),
                                        (9, 3), (10, 2), (11, 3)]
    assert sorted(g._parent.items()) == [(0, None), (4, 3), (5, 3), (6, 2), (7, 5), (8, 7), (9, 7), (10, 6), (11, 9)]
    assert sorted(g.property('edge_type').items()) == [(4, '+'), (5, '<'), (6, '<'), (7, '<'), (8, '+'), (9, '<'),
                                                       (10, '<'), (11, '<')]
    assert sorted(g.property('length').items()) == [(3, 1.5), (4, 0.5), (5, 2.0), (7, 0.75), (8, 0.5), (9, 2.0),
                                                    (11, 0.75)]
    assert sorted(g.property('radius').items()) == [(3, 0.25), (4, 0.125), (5, 0.2), (7, 0.1), (8, 0.125), (9, 0.2),
                                                    (11, 0.1)]
    assert sorted(g.property('n').items()) == [(2, 1), (6, 2), (10, 2)]
    assert sorted(g.property('_axial_id').items()) == [(1, 0), (2, 1), (3, 2), (4, 5), (5, 7), (6, 8), (7, 9),
                                                       (8, 12), (9, 14), (10, 15), (11, 16)]
    # Back: each decomposition and branch in brackets, as openalea.mtg writes them.
    assert str(mtg2axialtree(g, PARAMETERS)) == (
        '[P[U(1)[I(1.5,0.25)[I(0.5,0.125)]I(2.0,0.2)U(2)I(0.75,0.1)[I(0.5,0.125)]I(2.0,0.2)U(2)I(0.75,0.1)]]]')


FROM_MTG = """
from openalea.mtg.io import read_mtg_file, axialtree2mtg, mtg2axialtree
sizes = []
def End(lstring):
    g = axialtree2mtg(lstring, {'E': 1}, None, {'E': ['length']})
    sizes.append((len(g), sorted(g.property('length').values())))
module E(length)
Axiom: Init
derivation length: 2
production:
Init:
    g = read_mtg_file(MTGFILE)
    nsproduce(mtg2axialtree(g, {'E': ['length']}))
# The axis below each E, walked from the node a $ binds.
$E(it):
    total, n = 0, it
    while n is not None:
        total += n[0]
        n = n.direct_child()
    produce E(total)
endlsystem
"""


def test_a_model_makes_its_axiom_from_an_mtg_file_and_walks_it(tmp_path):
    mtgfile = tmp_path / 'plant.mtg'
    mtgfile.write_text(TEXT)
    path = tmp_path / 'from_mtg.lpy'
    path.write_text(FROM_MTG)
    lsys = Lsystem(str(path), {'MTGFILE': str(mtgfile)})
    s = lsys.derive()
    # Each vertex a module of its class (P and A without parameters), each decomposition and
    # branch in brackets, closed as openalea.mtg closes them (A2's after E3: the coarser scale
    # is closed by the next vertex of a coarser scale, or at the end); then the sums along
    # each axis: E1 2.5 + 1.25, A2's E1 0.75 + 0.5.
    assert str(s) == '[P[A[E(3.75)E(1.25)[A[E(1.25)E(0.5)]E(4.0)]]]]'
    assert lsys.sizes == [(6, [0.5, 1.25, 1.25, 3.75, 4.0])]


def test_amls_functions_on_the_active_mtg(tmp_path):
    from openalea.mtg import aml
    path = tmp_path / 'plant.mtg'
    path.write_text(TEXT)
    g = aml.MTG(str(path))
    assert aml.Active() is g and aml.VtxList(Scale=3) == [3, 4, 6, 7, 8]
    assert aml.Label(aml.VtxList(Scale=3)) == ['E1', 'E2', 'E1', 'E2', 'E3']
    assert (aml.Class(5), aml.Index(5), aml.Feature(6, 'length'), aml.ClassScale('E')) == ('A', 2, 0.75, 3)
    assert (aml.Father(7), aml.Sons(3), aml.Location(5), aml.Order(7), aml.Rank(8), aml.Height(7)) == (6, [4], 4, 1, 2, 3)
    assert aml.Components(1, Scale=3) == [3, 4, 8, 6, 7] and aml.ComponentRoots(1, Scale=3) == [3]
    with pytest.raises(NotImplementedError):
        aml.Coord(1, 2)


def test_an_mtg_as_a_dataframe():
    pd = pytest.importorskip('pandas')
    from openalea.mtg.dataframe import to_dataframe
    df = to_dataframe(read_mtg(TEXT))
    assert isinstance(df, pd.DataFrame) and len(df) == 9
    assert df.loc[6, 'length'] == 0.75 and df.loc[6, 'kind'] == 'shoot' and df.loc[6, 'parent'] == 4
    assert df.loc[6, 'complex'] == 5 and df.loc[6, 'scale'] == 3 and df.loc[6, 'order'] == 1


def test_a_tuple_added_to_an_lstring_is_a_module():
    # L-Py's AxialTree += ('A', x, ...): the module A(x, ...) (mtg2axialtree builds strings so);
    # 'A(1,2.5)[Bz]' is the reference L-Py's.
    from openalea.lpy import AxialTree
    s = AxialTree()
    s += ('A', 1, 2.5)
    s += '['
    s += ('Bz',)
    s += ']'
    assert str(s) == 'A(1,2.5)[Bz]' and len(s) == 4 and s[0][1] == 2.5 and s[2].name == 'Bz'
