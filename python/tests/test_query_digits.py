"""L-Py's query modules (?P ?H ?U ?L ?R ?F) read back with L-Py's digits (issue 51): the turtle
that fills them works in double precision with PlantGL's arithmetic (lpy/draw/frames.cpp), so
positions and frames match L-Py's to 1e-9. The models are written for these tests; the expected
numbers came from the reference L-Py + PlantGL (L-Py 4a365a3, PlantGL 6e01c6d, built by
../shared/tools/build-lpy-reference.sh), each model derived once and its modules' values
printed with repr(): see EXPECTED below. Sprout's single-precision turtle gave them to about
1e-7 only (the sixth digit of a printed value)."""
import pytest

import sprout

sprout.use_as_openalea()
from openalea.lpy import Lsystem  # noqa: E402

HEADER = """
derivation length: 1
production:
?P(x, y, z) --> P(x, y, z)
?H(x, y, z) --> H(x, y, z)
?U(x, y, z) --> U(x, y, z)
?L(x, y, z) --> L(x, y, z)
?R(x, y, z) --> R(x, y, z)
?F(p, h, u, l) --> Q(p[0], p[1], p[2], h[0], h[1], h[2], u[0], u[1], u[2], l[0], l[1], l[2])
endlsystem
"""
Q = "?P(0, 0, 0) ?H(0, 0, 0) ?U(0, 0, 0) ?L(0, 0, 0)"

MODELS = {
    # Turns by given and default angles, rolls, pitches, turning around.
    "turns": "Axiom: F(1.3) +(33.7) F(0.7) &(21.1) /(47.3) F(2.9) - ^ \\ F(0.37) | F(1.1) " + Q + " ?R(0, 0, 0)",
    # Tropism with elasticity before each step, branches, f, nF and a step backwards.
    "tropism": "Axiom: @Tp(0.3, -0.5, -1) @Ts(0.27) F(1) [+(30) F(2) ?P(0, 0, 0)] f(0.6) nF(2.5, 0.7) "
               "F(-0.8) &(40) F(1.2) " + Q,
    # The heading set (without and with an up), moves to points, pinpoints, lines to points,
    # rolled to vertical, the whole frame.
    "points": "Axiom: @R(0.3, 1, 0.2) F(1) ?P(0, 0, 0) ?H(0, 0, 0) @R(1, 0.5, 0.2, 0, 0.3, 1) F(0.8) " + Q +
              " @M(1.5, -0.7, 2.2) Pinpoint(0, 0, 5) F(1) ?P(0, 0, 0) PinpointRel(1, 2, 0.5) F(0.5) "
              "LineTo(2, 3, 1) ?P(0, 0, 0) ?H(0, 0, 0) OLineTo(-1, 0.5, 4) ?F @v " + Q +
              " MoveRel(0.2, 0.3, 0.4) ?P(0, 0, 0)",
    # Lines to points and by vectors, with a tropism (PlantGL's F, which they step with, bends).
    "lines": "Axiom: &(20) @Tp(0, -1, 0.2) @Ts(0.3) LineTo(1, 2, 3) ?P(0, 0, 0) ?H(0, 0, 0) OLineTo(-0.5, 1, 2) " + Q +
             " LineRel(0.5, -0.2, 1) ?P(0, 0, 0) OLineRel(0.1, 0.7, -0.4) ?F F(1) ?P(0, 0, 0)",
    # F and f along guides in the plane of the heading and up: a NURBS curve (PlantGL's
    # arc-length mapping of it), and a polyline's end (where a step leaves a polyline before its
    # end differs from L-Py's in the fifth digit: PlantGL maps its arc length to u by a sampled
    # function that Sprout does not reproduce).
    "guides": "from openalea.plantgl.all import NurbsCurve2D, Polyline2D\n"
              "Axiom: +(20) SetGuide(NurbsCurve2D([(0, 0, 1), (0.5, 1, 1), (1, 0.2, 1), (1.5, 1, 1)]), 2.5)"
              " F(0.3) F(0.6) ?P(0, 0, 0) ?H(0, 0, 0) F(1) " + Q +
              " SetGuide(Polyline2D([(0, 0), (1, 0.5), (2, 0.3)]), 3) F(0.4) F(0.7) f(1.1) F(1.5) " + Q,
}


def values(text):
    """Each module's name and values after one step, the query modules' answers among them."""
    lsys = Lsystem()
    lsys.setCode(text + HEADER)
    out = []
    lstring = lsys.derive()  # kept: L-Py's lstring must outlive the loop over its modules
    for m in lstring:
        if m.name in "PHULRQ" and len(m.name) == 1:
            out.append((m.name, [float(m[k]) for k in range(len(m))]))
    return out


# From the reference L-Py (see the docstring): repr() of each value.
EXPECTED = {
    'guides': [
        ('P', [0.6611830611702688, -0.20024545472992483, 0.55016986521695]),
        ('H', [0.4174612370903599, -0.31079190239654175, 0.8538937339808302]),
        ('P', [0.8859044992551641, -0.5309754714957355, 1.4588431182136574]),
        ('H', [0.48402196356869576, -0.2992867268770692, 0.8222835240343291]),
        ('U', [0.8750558489508564, 0.16554526135305273, -0.4548318674636215]),
        ('L', [0.0, -0.9396926207855205, -0.3420201433267344]),
        ('P', [2.824841246072566, -1.5294121470223854, 4.20202533896879]),
        ('H', [0.30301001295913327, -0.3259408777134417, 0.8955152015917416]),
        ('U', [0.9529873724486102, 0.1036355280617183, -0.28473627320182227]),
        ('L', [0.0, -0.9396926207855205, -0.3420201433267344]),
    ],
    'lines': [
        ('P', [1.0517384000748877, -0.07094391772202191, 3.5900993437990225]),
        ('H', [-0.3420201433267344, 0.0, 0.9396926207855205]),
        ('P', [-0.8059781390338128, -0.5369098110705786, 2.0360742774372476]),
        ('H', [-0.7532035700213489, -0.1889239649805281, -0.630073104935555]),
        ('U', [-0.5890216154897838, 0.6201024923859065, 0.5181953641461801]),
        ('L', [-0.2928103799268396, -0.7614332763892204, 0.5783437101017672]),
        ('P', [-0.40475200328406974, -1.1215130630352586, 2.92334910846969]),
        ('Q', [
            -0.13011357931185813, -0.9577077470729392, 2.1765281429494765, 0.33805653086953646, 0.20163040572142593,
            -0.9192730614050795, -0.26166942371109514, 0.9584030135197401, 0.11398586039936742, -0.9040170875769757,
            -0.20201198767621167, -0.37675490999315264
        ]),
        ('P', [0.22776375147370603, -1.3313568010103782, 1.3207768936944981]),
    ],
    'points': [
        ('P', [0.28221626051507914, 0.9407208683835973, 0.1881441736767194]),
        ('H', [0.28221626051507914, 0.9407208683835973, 0.1881441736767194]),
        ('P', [0.9865769855755782, 1.2929012309138468, 0.32901631868881925]),
        ('H', [0.8804509063256238, 0.4402254531628119, 0.1760901812651248]),
        ('U', [-0.2598753487034132, 0.15741021121463886, 0.9058512154804689]),
        ('L', [-0.37106036920720603, 0.8433190209254683, -0.2529957062776405]),
        ('P', [1.0388434035739906, -0.484793588334529, 3.060825646661884]),
        ('P', [2.0, 3.0, 1.0000000000000004]),
        ('H', [0.43643578047198484, 0.8728715609439694, 0.2182178902359925]),
        ('Q', [
            -1.0, 0.49999999999999956, 3.9999999999999987, -0.6092076990801715, -0.5076730825668097,
            0.6092076990801711, -0.4706185706041751, -0.3437850147108805, -0.7571060828632428, -0.593798856707523,
            0.7479393112428866, 0.029483902661549072
        ]),
        ('P', [-1.0, 0.49999999999999956, 3.9999999999999987]),
        ('H', [-0.6092076990801715, -0.5076730825668097, 0.6092076990801711]),
        ('U', [0.4680063181279422, 0.3900052651066185, 0.7930107057167914]),
        ('L', [0.6401843996644799, -0.7682212795973759, 0.0]),
        ('P', [-0.8, 0.7999999999999996, 4.399999999999999]),
    ],
    'tropism': [
        ('P', [0.9484076357414409, -2.4593195862537414, 0.765915332029834]),
        ('P', [1.4197718911122086, -3.5296265281772268, 0.10322125257682348]),
        ('H', [0.018186452125576055, -0.9997607893838282, 0.012149772413891313]),
        ('U', [0.921965820496252, 0.012067200998286787, -0.38708320616727887]),
        ('L', [-0.38684399800922, -0.018241345089992034, -0.9219647360574865]),
    ],
    'turns': [
        ('P', [-1.1615472723588627, -2.3207326850529517, 3.556065567174984]),
        ('H', [-0.16103634083649948, -0.5906490181164298, -0.7906965500924406]),
        ('U', [0.5201236282447343, -0.7316602237510997, 0.4406185746448087]),
        ('L', [0.838772143237675, 0.34030435550928073, -0.4250343954903991]),
        ('R', [-0.838772143237675, -0.34030435550928073, 0.4250343954903991]),
    ],
}


@pytest.mark.parametrize("name", sorted(MODELS))
def test_query_modules_read_back_lpys_digits(name):
    got = values(MODELS[name])
    want = EXPECTED[name]
    assert [n for n, _ in got] == [n for n, _ in want]
    for (n, xs), (_, ys) in zip(got, want):
        assert len(xs) == len(ys), n
        for x, y in zip(xs, ys):
            assert abs(x - y) <= 1e-9 * max(1.0, abs(y)), (n, xs, ys)
