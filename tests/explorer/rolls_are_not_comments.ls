/* '//' glued to a module is two rolls; after a space it starts a comment. */
n=1; delta=30
axiom: i
i -> F[//&&l][//^^l]F // the internode and two leaves
l -> +F
// warning 2: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// expect 2: F[//&&+F][//^^+F]F
