/* L-system Explorer passes over a line it cannot read (here what remains of a comment
   that was broken in two): so does Sprout, with a warning. */
n=2
/
*axiom: F
*/
axiom: X
X --> F[+X]
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// warning 4: not a rule, a setting or a statement: left out, as L-system Explorer leaves it out
// warning 5: not a rule, a setting or a statement: left out, as L-system Explorer leaves it out
// warning 6: not a rule, a setting or a statement: left out, as L-system Explorer leaves it out
// expect 2: F[+F[+X]]
