/* A #define that goes on over the next lines with '\', and a function-like one. */
#define BOX [F(1)+(90)F(1) \
   +(90)F(1)]
#define outside(y) \
   ((y < 0) or (y > 2))
derivation length: 1
axiom: BOX A(1)
A(y) : outside(y) --> F
A(y) : !outside(y) --> A(y+2)
// expect 0: [F(1)+(90)F(1)+(90)F(1)]A(1)
// expect 1: [F(1)+(90)F(1)+(90)F(1)]A(3)
// expect 2: [F(1)+(90)F(1)+(90)F(1)]F
