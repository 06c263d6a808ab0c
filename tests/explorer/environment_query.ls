/* '?E' asks L-system Explorer's environment, a JavaScript function of the page: the file
   still opens, and ?E keeps its values. */
n=2
axiom: A ?E(1,2)
A > ?E(x,y) : x > 0 --> F(x)A
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// warning 4: ?E asks L-system Explorer's environment, a JavaScript function of that tool the file does not carry: here ?E keeps the values it is given (declare one with 'environment: sphere 0 10 0 8')
// expect 2: F(1)F(1)A?E(1,2)
