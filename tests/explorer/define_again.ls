/* cpfg's #define is the C preprocessor's: the same value again is nothing, another value
   replaces the first with a warning. */
#define S 0.5
#define S 0.5
#define T 1
#define T 2
n=1
axiom: A(1)
A(x) -> F(x*S)A(x*T)
// warning 6: 'T' is defined again with another value: the last one is used
// warning 7: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// expect 1: F(0.5)A(2)
// expect 2: F(0.5)F(1)A(4)
