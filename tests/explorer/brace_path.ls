/* '{(0)' starts a path, a tube through the points F reaches; a '}' with no polygon open
   ends it. A '{' with no parameter is a polygon. */
derivation length: 1
axiom: {(0)A}[{.-f.+f.+f.}]
A --> F+(30)F+(30)F
// expect 1: {(0)F+(30)F+(30)F}[{.-f.+f.+f.}]
