/* cpfg's global blocks, over several lines: not run, said once each. */
#define r 0.9
a = 0
dist = 15
view = {position: [1, 2, 0]}
lsystem: 1
derivation length: 2
EndEach: {
        a = (a + 10)%360; dist = 1.2 * dist;
        view.position = [dist, 2, 0]; }
axiom: A(1)
A(l) -> F(l)A(l*r)
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// warning 5: 'view' is another L-system tool's view setting: Sprout leaves it out
// warning 8: 'EndEach:' blocks are not run (this one sets a, dist, view): the rules use the values set before the axiom
// expect 2: F(1)F(0.9)A(0.81)
