// No derivation length: L-system Explorer derives once.
axiom: F
F -> F+F
// dialect: L-system Explorer
// n: 1
// expect 1: F+F
