/* mathjs's functions in expressions: fix rounds towards zero, mod takes the divisor's
   sign, cbrt, square, cube, log10, log2, hypot. */
n=1
axiom: A(-2.7)
A(x) -> B(fix(x),mod(x-0.3,2),cbrt(8),square(3),cube(2),log10(100),log2(8),hypot(3,4))
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// expect 1: B(-2,1,2,9,8,2,3,5)
