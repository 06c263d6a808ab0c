derivation length: 1
axiom: F[+A[-A]
A -> F
// dialect: L-system Explorer (cpfg family)
// warning 2: this '[' is never closed with ']': the branch ends at the end of the axiom
// expect 0: F[+A[-A]]
// expect 1: F[+F[-F]]
