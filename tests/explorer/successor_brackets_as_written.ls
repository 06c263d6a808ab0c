/* A successor that closes the branch it stands in and opens another (the string stays
   balanced): read as written. */
derivation length: 2
axiom: #(1)[A(2)]
A(n) : n > 1 --> F(n)A(n-1)
A(n) : n <= 1 --> ]f(2)[+F(1)
// warning 6: ']' closes a branch this successor did not open: read as written, as L-system Explorer reads it
// expect 1: #(1)[F(2)A(1)]
// expect 2: #(1)[F(2)]f(2)[+F(1)]
