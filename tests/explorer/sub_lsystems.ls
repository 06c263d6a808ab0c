/* Sub-L-systems: after the main L-system's 'endlsystem', 'lsystem: 2' defines productions
   that rewrite what stands between '$(2)' and '$' (its own axiom is not used). */
lsystem: 1
derivation length: 3
axiom: A
A --> F[$(2)A$]A
endlsystem

lsystem: 2
axiom: B
A --> +FA
endlsystem
// warning 10: a sub-L-system's productions are used; its other lines are not
// expect 1: F[$(2)A$]A
// expect 2: F[$(2)+FA$]F[$(2)A$]A
// expect 3: F[$(2)+F+FA$]F[$(2)+FA$]F[$(2)A$]A
