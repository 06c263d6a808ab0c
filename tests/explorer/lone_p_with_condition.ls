/* A production for the module P with cpfg's "no condition" star and a statement block:
   'P :' here is not a label. */
z = 0
#define STEP 3
axiom: PAPB
A -> F(1)
B -> F(2)
P : * {z = z+STEP} -> @m(0,0,z)
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// warning 8: the block changes the variable 'z': in Sprout the change is seen by this production only (each time from 0), not by the next ones
// n: 1
// expect 1: @m(0,0,3)F(1)@m(0,0,3)F(2)
