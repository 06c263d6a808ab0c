/* A polygon opened by one production and closed by another ('{' and '}' after the arrow
   are modules, not blocks). */
derivation length: 2
axiom: [A][B]
p1: A -> [&FA{.].
p2: B -> B&.F.}
// expect 1: [[&FA{.].][B&.F.}]
// expect 2: [[&F[&FA{.].{.].][B&.F.}&.F.}]
