/* L-system Explorer's modules of more than one character: home, contours and their use,
   radius spline, moves without drawing. */
derivation length: 1
axiom: C F
C --> [@H(1)@Cs(8,1)@Cn(8).f@Ct(1,3)@Cm(3)@Ce('ctr')]@#('ctr')@Gr(30,2,-30,2)
// n: 1
// expect 1: [@H(1)@Cs(8,1)@Cn(8).f@Ct(1,3)@Cm(3)@Ce('ctr')]@#('ctr')@Gr(30,2,-30,2)F
