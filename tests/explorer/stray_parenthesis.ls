/* A '(' that follows no module is passed over, as L-system Explorer does. */
n=1
axiom: U F
U -> @Cs(0,1)(@m(-1,0,0).@m(1,0,0).@Ce(1)
// warning 2: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// warning 4: a '(' that follows no module name: left out, as L-system Explorer leaves it out
// expect 1: @Cs(0,1)@m(-1,0,0).@m(1,0,0).@Ce(1)F
