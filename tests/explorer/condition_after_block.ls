/* A condition after the statement block, with a ':' before it, and the block on the
   indented line after the production's first line. */
#define R 2
n=2
axiom: C(1,1)
p1: C(a,s) :
    { s = s*R; }: a == 1 and s < 3 -> C(1,s)F(s)
// warning 4: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// expect 1: C(1,2)F(2)
// expect 2: C(1,2)F(2)
