/* '@m(x,y,z)' moves to a point without drawing, as one module (a predecessor here), and
   text macros put in place where they are used. */
dlength: 2
#define UP y+1
axiom: @m(0,0,0)
@m(x,y,z) : y < 5 --> @m(x,y,z)F(1)@m(x,UP,z)
// warning 3: a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is (L-system Explorer's dialect, of the cpfg family)
// expect 2: @m(0,0,0)F(1)@m(0,1,0)F(1)@m(0,1,0)F(1)@m(0,2,0)
