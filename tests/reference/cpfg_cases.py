"""The hand-written cases of cpfg_differential.py: small cpfg L-system files, one or more for each
construct of the CPFG manual (VLab's CPFGManual.pdf) and of cpfg's own sources (lsys_input.l and
lsys_input.y, the language; generate.c, the derivation). CASES is a list of (name, text, files):
files maps extra file names (an #include) to their text, or is None."""


def L(axiom, rules, n=3, head="", tail="", label="1"):
    """An L-system: head lines before the axiom, the productions, tail lines after endlsystem."""
    text = "Lsystem: %s\n" % label
    if head:
        text += head.strip("\n") + "\n"
    text += "derivation length: %d\nAxiom: %s\n%s\nendlsystem\n" % (n, axiom, rules.strip("\n"))
    if tail:
        text += tail.lstrip("\n")
    return text


CASES = []


def case(name, text, files=None):
    CASES.append((name, text, files))


# --- Productions, parameters, conditions (manual 3) ---------------------------------------
case("basic", L("A(1)", "A(x) --> B(x*2) A(x+1)\nB(x) : x > 4 --> C(x/3)", 4))
case("no-params-and-params", L("A B(2) C", "A --> B(1)A\nB(x) --> B(x+1)C\nC --> *", 3))
case("empty-successor", L("ABC", "B --> *\nA --> AA", 2))
case("arity-differs", L("A A(1) A(1,2)", "A --> X\nA(x) --> Y(x)\nA(x,y) --> Z(x+y)", 1))
case("first-applicable", L("A(5)", "A(x) : x > 3 --> B\nA(x) : x > 1 --> C\nA(x) --> D", 1))
case("condition-star", L("A(1)", "A(x) : * --> A(x+1)B", 3))
case("condition-false-copies", L("A(1)B(2)", "A(x) : x > 10 --> Z\nB(y) : 0 --> Z", 2))
case("many-params", L("A(1,2,3,4,5,6,7,8)", "A(a,b,c,d,e,f,g,h) --> A(h,a,b,c,d,e,f,g)B(a+b+c+d+e+f+g+h)", 3))
case("axiom-expressions", "#define N 4\n" + L("A(N*2) B(-1) C(2^3) D(1/4)", "A(x) --> A(x-1)", 2))
case("derivation-length-expr", "#define N 2\n" + L("A", "A --> AB", 0).replace("derivation length: 0",
                                                                                "derivation length: N*2+1"))
case("derivation-length-zero", L("A(1)B", "A(x) --> A(x+1)", 0))
case("lowercase-keywords", "lsystem: 1\nderivation length: 2\naxiom: A\nA --> AB\nendlsystem\n")
case("keyword-variants", "Lsystem: 1\nDerivation Length: 2\nAxiom: A\nA --> AB\nEndlsystem\n")
case("derivationlength-no-space", "Lsystem: 1\nderivationlength: 2\nAxiom: A\nA --> AB\nendlsystem\n")
case("lsystem-label-0", L("A", "A --> AB", 2, label="0"))
case("numbers-written", L("A(1.)", "A(x) --> B(.5, 1.e2, 1.0E-2, 1.5e+2, 2.50, 007, 1.e0)", 1))
case("number-exponent-without-point", L("A", "A --> B(1e2)", 1))  # cpfg: a syntax error (Sprout reads 100)
case("symbols", L("A", "A --> F+-&^\\\\/|$@!#;,.{}~'\"A", 1).replace("\\\\", "\\"))
case("symbols-params", L("A(1)", "A(x) --> !(x);(x+1)#(2)@(3)~(4)A(x+1)", 2))
case("comment-lines", "/* a comment */\nLsystem: 1\n/* between */\nderivation length: 2\n"
     "Axiom: A /* after the axiom */\nA --> AB /* after a production */\n/* multi\nline */\nendlsystem\n")
case("comment-in-expression", L("A(1)", "A(x) --> A(x /* one */ + 1)", 2))
case("cpp-line-comment", L("A", "A --> AB // a C++ comment", 2))
case("blank-lines", "\n\nLsystem: 1\n\nderivation length: 2\n\nAxiom: A\n\nA --> AB\n\nendlsystem\n\n")
case("spaces-in-modules", L("A ( 1 , 2 )", "A ( x , y ) --> B ( x + y ) A ( y , x )", 2))
case("tab-continuation", L("A(1)", "A(x) --> B(x)\n\tC(x+1)\n\tA(x+1)", 2))
case("tab-continuation-in-expression", L("A(1)", "A(x) --> B(x +\n\t1) A(x+1)", 2))
case("successor-over-lines-in-parens", L("A(1)", "A(x) --> B(x,\n\tx+1) A(x+1)", 2))
case("crlf", L("A(1)", "A(x) --> B(x)A(x+1)", 2).replace("\n", "\r\n"))

# --- Expressions: operators and precedence ----------------------------------------------------
case("arith", L("A(7,2)", "A(x,y) --> B(x+y, x-y, x*y, x/y, x%y, x^y, -x, -x^2, 2^3^2, 2-3-4, 2/3/4, 1+2*3)", 1))
case("compare", L("A(1,2)", "A(x,y) --> B(x<y, x>y, x<=y, x>=y, x==y, x!=y, x<>y, 1<2==1, 3>2>1, 1==1==1)", 1))
case("logic", L("A(0,2)", "A(x,y) --> B(x&&y, x||y, !x, !y, !x+1, !!y, x||y&&x, (x||y)&&x, !x==1, -!x)", 1))
case("ternary", L("A(0,1)", "A(x,y) --> B(x?1:2, y?1:2, x?1:y?3:4, y?x?5:6:7, x||y?8:9, (x?1:2)+10, 1+x?20:30)", 1))
case("unary-minus", L("A(3)", "A(x) --> B(-x, --x, -(-x), 2*-x, 2^-1, -2^2, -x*-x, 1--x, -x^-1)", 1))
case("division-by-zero", L("A(0)", "A(x) --> B(1/x, 5/0, x/0, 0/0, 3/(x-x))", 1))
case("remainder", L("A(7.9,-7.5)", "A(x,y) --> B(x%3, y%3, 7%-3, 10.5%4.9, 1%2.5, -1%2)", 1))
case("pow", L("A(2,-8)", "A(x,y) --> B(x^0.5, y^(1/3), 0^0, x^x^x, (-2)^2, 10^20, 10^-20, y^2, y^-1)", 1))
case("big-small", L("A(1)", "A(x) --> B(1.e20, 1.e-20, 123456789, 0.1+0.2, 1/3, 16777217, 1.e38*10, -0.0, 0*-1, 2.e-45, 1.e-40, 3.4e38*2)", 1))
case("print-g", L("A(1)", "A(x) --> B(100000, 1000000, 1234567, 0.0001, 0.00001, 123.456789, 99999.95, 0.000123456789)", 1))
case("inf-nan", L("A(1)", "A(x) --> B(exp(1000), -exp(1000), log(0), sqrt(-1), exp(1000)-exp(1000), fabs(sqrt(-1)))", 1))
case("compare-nan", L("A(1)", "A(x) --> B(sqrt(-1) < 1, sqrt(-1) == sqrt(-1), sqrt(-1) != 1, !sqrt(-1), sqrt(-1) ? 1 : 2)", 1))
case("or-keeps-value", L("A(0,3)", "A(x,y) --> B(3 || 0, y || x, (y+1) || 0, (y*2) || x, -y || 0, (x+0) || y, (x-1) && 5, sin(90) || 0, -1 || 0)", 1))
case("ternary-stack", L("A(0,3)", "A(x,y) --> B(1 + ((y+0) ? (x+5) : 9), 1 + (y ? (x+5) : 9), 10 * ((x+0) ? 2 : (y+1)), 1 + (y ? (x+0) : 9), ((y+1) ? (x+5) : 9) + 1, x ? (y-3) : 9, 1 ? 2 : 3, 10 + (1 ? (y+1) : 0))", 1))
case("nested-short-circuit", L("A(0,3)", "A(x,y) --> B(x || (y+1 || 0), 5 + (x || (y*2 || 0)), (x+0) || (y+0) || 7, (y+0) && (x+0) || 4, y && (x ? 1 : (y+1)))", 1))
case("short-circuit-ran", L("A(0)A(1)A(0)A(1)", "A(x) --> B((x+0) && ran(1) < 2, (x+0) || ran(1), x ? (ran(1)+0) : 5, ran(1))", 1, head="Start: { srand(3); }"))
case("precedence-mix", L("A(2,3)", "A(x,y) --> B(x+y*2^2, x*y%4, x-y<0==1, x<y&&y<x||1, x+(y>2), -x%3, !x*5, x^2*-1)", 1))
case("float-storage", L("A(0.1)", "A(x) --> A(x*3+0.1)B(x)", 4))
case("float-accumulate", L("A(0)", "A(x) --> A(x+0.1)", 10))
case("integer-precision", L("A(16777216)", "A(x) --> A(x+1)B(x+1)", 2))

# --- Functions (manual 5) -------------------------------------------------------------------
case("trig", L("A(30)", "A(x) --> B(sin(x), cos(x), tan(x), asin(0.5), acos(0.5), atan(1), atan(-2), acos(2))", 1))
case("atan2", L("A(30)", "A(x) --> B(atan2(1,2))", 1))  # cpfg: not a function of its grammar (a syntax error)
case("math", L("A(2.5,-2.5)", "A(x,y) --> B(exp(1), log(10), sqrt(x), fabs(y), floor(y), ceil(y), trunc(x), trunc(y), sign(y), sign(0), sign(x))", 1))
case("trunc-values", L("A(0)", "A(x) --> B(trunc(0.4), trunc(0.5), trunc(0.6), trunc(1.5), trunc(-0.4), trunc(-0.5), trunc(-0.6), trunc(-1.5), trunc(2.4999))", 1))
case("func-args-exprs", L("A(4)", "A(x) --> B(sqrt(x*x+9), floor(x/3)*3, sin(x*10)+cos(x*10), exp(-x)*log(x))", 1))
case("srand-ran", L("A", "A : {srand(5); a = ran(10); b = ran(1); c = ran(100);} * --> B(a,b,c)", 1))
case("srand-nran", L("A", "A : {srand(7); a = nran(10, 2); b = nran(0, 1);} * --> B(a,b)", 1))
case("srand-bran-biran", L("A", "A : {srand(11); a = bran(2, 3); b = biran(10, 0.5); c = bran(0.5, 0.5);} * --> B(a,b,c)", 1))
case("ran-no-srand", L("A", "A --> B(ran(1))A", 3))
case("ran-in-start", L("A", "A --> B(x)A", 2, head="Start: { srand(3); x = ran(5); }"))
case("printf", L("A(1)", "A(x) : { printf(\"x = %f\\n\", x); } * --> A(x+1)", 2))
case("function-names-as-vars", L("A(2)", "A(sine) --> B(sine*2)", 1))

# --- #define and the preprocessor -------------------------------------------------------------
case("define-constant", "#define ANGLE 30\n#define LEN 2.5\n" + L("A(LEN)", "A(x) --> B(x*ANGLE)A(x+LEN)", 2))
case("define-macro", "#define SQ(a) ((a)*(a))\n#define AVG(a,b) (((a)+(b))/2)\n"
     + L("A(3)", "A(x) --> B(SQ(x), AVG(x, 5), SQ(x+1))A(x+1)", 2))
case("define-unparenthesised", "#define TWO 1+1\n" + L("A(3)", "A(x) --> B(TWO*x)", 1))
case("define-symbols", "#define GROW A(1)B\n" + L("X", "X --> GROW X", 2))
case("ifdef", "#define FAST\n#ifdef FAST\n#define S 2\n#else\n#define S 1\n#endif\n" + L("A(0)", "A(x) --> A(x+S)", 3))
case("if-expr", "#define V 3\n#if V > 2\n#define W 10\n#else\n#define W 20\n#endif\n" + L("A", "A --> B(W)", 1))
case("include", "#include \"inc.h\"\n" + L("A(0)", "A(x) --> A(x+INC)", 3), {"inc.h": "#define INC 4\n"})
case("define-used-in-rule-names", "#define X A\n" + L("X(1)", "X(x) --> X(x+1)B", 2))

# --- Variables, blocks and statements (manual 2.2, 3.2, 4.1) ------------------------------------
case("start-endeach", L("A", "A --> B(i)A", 3, head="Start: { i = 0; }\nEndEach: { i = i + 1; }"))
case("starteach", L("A", "A --> B(i)A", 3, head="Start: { i = 10; }\nStartEach: { i = i * 2; }"))
case("end-block", L("A", "A --> B(i)A", 2, head="Start: { i = 1; }\nEnd: { i = 100; }"))
case("global-set-in-production", L("AAA", "A : * { n = n + 1; } --> B(n)", 1, head="Start: { n = 0; }"))
case("global-pre-block", L("AAAA", "A : { n = n + 1; } n > 2 --> B(n)", 2, head="Start: { n = 0; }"))
case("global-order-left-to-right", L("A(1)A(2)A(3)", "A(x) : { s = s + x; } * --> B(s)", 1, head="Start: { s = 0; }"))
case("local-pre", L("A(4)", "A(y) : { x = y/2; s = x*x; } s < 10 --> B(x,s)\nA(y) --> C(y)", 1))
case("local-persists", L("AAA", "A : { n = n + 1; } * --> B(n)", 2))
case("local-not-reset", L("A(1)A(0)A(0)", "A(x) : { if (x > 0) { m = 5; } } * --> B(m)", 1))
case("post-block", L("A(3)", "A(y) : * { if (y > 2) { y = 10; } } --> B(y)", 1))
case("pre-cond-post", L("A(3)", "A(y) : { z = y + 1; } z > 3 { z = z * 2; } --> B(z)", 1))
case("pre-post-failing", L("A(1)", "A(y) : { z = y + 1; } z > 3 { z = z * 2; } --> B(z)\nA(y) --> C(z)", 1))
case("if-else", L("A(1)A(5)", "A(y) : { if (y > 2) { z = 1; } else { z = 2; } } * --> B(z)", 1))
case("if-else-newlines", L("A(1)A(5)", "A(y) : {\n\tif (y > 2) {\n\t\tz = 1;\n\t}\n\telse {\n\t\tz = 2;\n\t}\n} * --> B(z)", 1))
case("block-over-lines", L("A(1)", "A(y) : {\nz = y + 1;\nw = z * 2;\n} z > 0 --> B(z, w)", 1))
case("while", L("A(3)", "A(y) : { s = 0; i = 0; while (i < y) { s = s + i; i = i + 1; } } * --> B(s)", 1))
case("do-while", L("A(0)", "A(y) : { i = 0; do { i = i + 1; } while (i < y); } * --> B(i)", 1))
case("nested-if", L("A(1)A(2)A(3)", "A(y) : { if (y > 1) { if (y > 2) { z = 3; } else { z = 2; } } else { z = 1; } } * --> B(z)", 1))
case("assign-param", L("A(1)", "A(x) : { x = x + 10; } * --> B(x)", 1))
case("undefined-variable", L("A", "A --> B(qq)", 1))
case("procedure-statement", L("A", "A : { srand(3); ran(1); v = ran(1); } * --> B(v)", 1))
case("globals-Q-Z", L("A", "A --> B(Q, Z)A", 3))
case("start-in-sub-order", L("A", "A --> B(g)A", 2, head="Start: { g = 2; }\nStartEach: { g = g + 1; }\nEndEach: { g = g * 10; }"))
case("blocks-one-line", L("A", "A --> B(i)A", 2, head="Start: {i=0;}\nEndEach: {i=i+1;}"))
case("statement-empty", L("A(1)", "A(x) : { y = x; ; } * --> B(y)", 1))  # cpfg: a syntax error

# --- Arrays (manual 2.2.2) -------------------------------------------------------------------
case("array-1d", L("A(0)A(1)A(2)", "A(i) --> B(ang[i])", 1, head="define: { array ang[3] = {75, 60, 45}; }"))
case("array-2d", L("A(0,1)A(1,0)A(2,1)", "A(i,j) --> B(g[i][j])", 1,
                   head="define: { array g[3][2] = {1, 0.9, 0.8, 1, 0.8, 0.6}; }"))
case("array-2d-comma-dims", L("A(0,1)A(1,0)A(2,1)", "A(i,j) --> B(g[i][j])", 1,
                              head="define: { array g[3,2] = {1, 0.9, 0.8, 1, 0.8, 0.6}; }"))
case("array-several", L("A(1)", "A(i) --> B(a[i], b[i], c[i])", 1,
                        head="define: { array a[2] = {1, 2};\n\tarray b[2];\n\tarray c[3] = {7, 8, 9}; }"))
case("array-assign", L("A(0)A(1)A(2)", "A(i) : { v[i] = i * 10; } * --> B(v[i], v[0])", 1,
                       head="define: { array v[3]; }"))
case("array-out-of-range", L("A(5)A(-1)", "A(i) --> B(v[i])", 1, head="define: { array v[3] = {1,2,3}; }"))
case("array-fraction-index", L("A(1.7)", "A(i) --> B(v[i])", 1, head="define: { array v[3] = {1,2,3}; }"))
case("array-in-start", L("A", "A --> B(v[0], v[1])", 1, head="define: { array v[2]; }\nStart: { v[0] = 5; v[1] = v[0] + 1; }"))
case("array-few-init", L("A", "A --> B(v[0], v[1], v[2])", 1, head="define: { array v[3] = {4}; }"))
case("array-persists", L("AA", "A : { v[0] = v[0] + 1; } * --> B(v[0])A", 2, head="define: { array v[1]; }"))

# --- Context (manual 3.1, 4.2) ---------------------------------------------------------------
case("left-context", L("BAAA", "B < A --> B\nB --> A", 3))
case("right-context", L("AAAB", "A > B --> B\nB --> A", 3))
case("both-contexts", L("ABCABC", "A < B > C --> X\nB --> Y", 1))
case("context-params", L("A(1)B(2)C(3)", "A(a) < B(b) > C(c) --> B(a+b+c)", 1))
case("context-multi", L("ABCD", "AB < C --> X\nC > D --> Y", 1))
case("right-multi", L("ABCD", "B > CD --> X", 1))
case("left-skips-branch", L("A[B]C", "A < C --> X", 1))
case("left-out-of-branch", L("A[BC]D", "A < B --> X\nB < C --> Y\nA < D --> Z", 1))
case("left-nested", L("A[B[C]D]E", "A < D --> X\nB < D --> Y\nA < E --> Z", 1))
case("right-skips-branch", L("A[B]C", "A > C --> X", 1))
case("right-stops-at-bracket", L("[AB]C", "B > C --> X", 1))
case("right-into-branch", L("A[B]C", "A > [B]C --> X", 1))
case("right-bracket-explicit", L("A[B][C]D", "A > [B][C]D --> X\nA > [C] --> Y", 1))
case("right-close-bracket", L("[AB]C", "B > ] --> X\nA > B] --> Y", 1))
case("right-close-bracket-next", L("[AB]C[DF]", "A > ] --> X\nD > ] --> Y", 1, head="ignore: F"))
case("right-open-bracket-ignored", L("A[B]C", "A > [B --> X", 1, head="ignore: ["))
case("right-bracket-ignored", L("A[B]C[D]E", "A > C --> X\nC > D --> Y\nB > C --> Z", 1, head="ignore: [ ]"))
case("left-bracket-ignored", L("A[B]C[D]E", "A < C --> X\nC < D --> Y\nC < E --> Z", 1, head="ignore: [ ]"))
case("right-context-deep", L("A[B[C]D]E", "A > E --> X\nB > D --> Y", 1))
case("context-with-arity", L("A(1)BA", "A(x) > B --> X(x)\nB < A --> Y", 1))
case("context-arity-mismatch", L("A(1,2)B", "A(x) < B --> X\nA(x,y) < B --> Y(x+y)", 1))
case("context-null", L("AB", "* < A > * --> X\nA > * --> Y", 1))
case("context-star", L("AB", "* < B --> X", 1))
case("ignore", L("BF+A", "B < A --> X", 1, head="ignore: F +"))
case("ignore-right", L("AF+-B", "A > B --> X", 1, head="ignore: F + -"))
case("ignore-params", L("A(1)F(2)B(3)", "A(x) > B(y) --> X(x+y)", 1, head="ignore: F"))
case("ignore-nothing-bracket", L("A[F]B", "A > B --> X\nB < A --> Y", 1, head="ignore: F"))
case("ignore-bracket", L("A[F]B", "A > B --> X\nB < A --> Y", 1, head="ignore: [ ] F"))
case("consider", L("BF+AFA", "B < A --> B\nB --> A", 2, head="consider: A B"))
case("consider-right-branch", L("A[B]C", "A > C --> X\nA > B --> Y", 1, head="consider: A B C"))
case("consider-left-branch", L("A[B]C", "A < C --> X\nB < C --> Y", 1, head="consider: A B C"))
case("consider-with-brackets", L("A[B]C", "A > C --> X\nA > B --> Y\nA < C --> Z", 1, head="consider: A B C [ ]"))
case("consider-right-end-of-branch", L("[AB]C", "A > B --> X\nB > C --> Y", 1, head="consider: A B C"))
case("context-sensitive-signal", L("B[+A]A[-A]A[+A]A", "B < A --> B\nB --> A", 4, head="ignore: + -"))
case("context-self", L("AAA", "A < A --> B\nA > A --> C", 1))
case("left-context-at-start", L("A", "B < A --> X\nA --> Y", 1))
case("context-both-branches", L("A[B]C[D]E", "C < E --> X\nA < C --> Y\nA > C --> Z", 1))

# --- Multi-module predecessors ---------------------------------------------------------------
case("pred-two", L("ABAB", "AB --> X", 1))
case("pred-two-params", L("A(1)B(2)A(3)", "A(x)B(y) --> X(x+y)", 1))
case("pred-with-context", L("CABD", "C < AB > D --> X", 1))
case("pred-overlap", L("AAA", "AA --> X", 1))
case("pred-three", L("ABCABC", "ABC --> X\nB --> Y", 1))
case("pred-fails-then-single", L("AC", "AB --> X\nA --> Y", 1))
case("pred-with-bracket", L("A[B]", "A[ --> X\n[B --> Y", 1))

# --- Ring L-systems (manual 3.1.1) -----------------------------------------------------------
case("ring", L("ABC", "C < A --> X\nC > A --> Y", 1, head="ring lsystem"))
case("ring-params", L("A(1)B(2)C(3)", "C(z) < A(x) --> A(x+z)\nC(z) > A(x) --> Y\nB(y) > C(z) --> B(y+z)", 2, head="ring lsystem"))
case("ring-capital", L("ABC", "C < A --> X", 1, head="Ring Lsystem"))

# --- Cut (manual 6.4) -------------------------------------------------------------------------
case("cut", L("A", "A --> F[B]A\nB --> %C\nC --> D", 3))
case("cut-nested", L("A[B[C]D]E", "B --> %", 2))
case("cut-top-level", L("AB%CD", "A --> X", 1))
case("cut-in-axiom", L("A[%B]C", "A --> X", 1))
case("cut-with-production", L("A[%B]C", "% --> Y", 1))
case("cut-after-two-steps", L("D(0)", "D(a) : a < 2 --> D(a+1)\nD(a) : a >= 2 --> %", 4))
case("cut-context", L("A[%B]C", "A > C --> X\nB --> Z", 2))
case("cut-age", L("A(0)", "A(t) --> F[D(0)]A(t+1)\nD(a) : a < 2 --> D(a+1)\nD(a) : a >= 2 --> %", 5))

# --- Decomposition and homomorphism (manual 4.3, 4.4) ----------------------------------------
case("decomposition", L("A", "A --> AB", 2, tail="").replace("endlsystem", "decomposition\nB --> CD\nendlsystem"))
case("decomposition-recursive", L("A", "A --> AB", 2).replace("endlsystem", "decomposition\nB --> C\nC --> D\nendlsystem"))
case("decomposition-depth", L("A", "A --> AB", 2).replace("endlsystem", "decomposition\nmaximum depth: 3\nB --> C\nC --> D\nD --> E\nE --> G\nendlsystem"))
case("decomposition-depth-2", L("A", "A --> AB", 2).replace("endlsystem", "decomposition\nmaximum depth: 2\nB --> C\nC --> D\nD --> E\nendlsystem"))
case("decomposition-params", L("A(3)", "A(x) --> A(x-1)B(x)", 3).replace("endlsystem", "decomposition\nmaximum depth: 5\nB(x) : x > 0 --> F B(x-1)\nendlsystem"))
case("decomposition-axiom", L("B", "A --> A", 1).replace("endlsystem", "decomposition\nB --> C\nendlsystem"))
case("decomposition-unrewritten", L("AB", "A --> A", 1).replace("endlsystem", "decomposition\nB --> C\nendlsystem"))
case("decomposition-context", L("XA", "A --> B", 1).replace("endlsystem", "decomposition\nX < B --> C\nendlsystem"))
case("decomposition-context-new", L("A", "A --> XB", 1).replace("endlsystem", "decomposition\nX < B --> C\nB --> D\nendlsystem"))
case("decomposition-right-context", L("AY", "A --> B", 1).replace("endlsystem", "decomposition\nB > Y --> C\nendlsystem"))
case("decomposition-warnings", L("A", "A --> AB", 2).replace("endlsystem", "decomposition: no warnings\nmaximum depth: 2\nB --> B C\nendlsystem"))
case("decomposition-cut", L("A[B]C", "A --> A", 1).replace("endlsystem", "decomposition\nB --> %D\nendlsystem"))
case("decomposition-and-homomorphism", L("A", "A --> AB", 2).replace("endlsystem", "decomposition\nB --> C\nhomomorphism\nC --> FF\nendlsystem"))
case("homomorphism-ignored", L("A", "A --> AB", 2).replace("endlsystem", "homomorphism\nB --> FF\nA --> *\nendlsystem"))
case("homomorphism-depth", L("A", "A --> AB", 2).replace("endlsystem", "homomorphism: warnings\nmaximum depth: 3\nseed: 4\nB --> C\nC --> F\nendlsystem"))
case("decomposition-stochastic", L("A", "A --> AB", 3, head="seed: 3").replace("endlsystem", "decomposition\nB --> C : 1\nB --> D : 1\nendlsystem"))
case("decomposition-globals", L("A", "A --> AB", 2, head="Start: { g = 1; }\nEndEach: { g = g + 1; }").replace("endlsystem", "decomposition\nB --> C(g)\nendlsystem"))

# --- Stochastic (manual 4.5) -------------------------------------------------------------------
case("stochastic", L("F", "F --> F[+F]F : 40\nF --> F[-F]F : 60", 3, head="seed: 5"))
case("stochastic-no-probability", L("AAAAAA", "A --> B\nA --> C", 2, head="seed: 7"))
case("stochastic-conditions", L("A(1)A(2)A(3)A(4)", "A(x) : x > 2 --> B : 1\nA(x) --> C : 2\nA(x) : x < 2 --> D : 3", 3, head="seed: 9"))
case("stochastic-expr-prob", L("A(1)A(5)", "A(x) --> B : x\nA(x) --> C : 5 - x", 3, head="seed: 2"))
case("stochastic-zero-prob", L("AAAA", "A --> B : 0\nA --> C : 0", 2, head="seed: 2"))
case("stochastic-and-ran", L("AAA", "A --> B(ran(1)) : 1\nA --> C(ran(2)) : 1", 2, head="seed: 4"))
case("stochastic-seed-expr", "#define S 10\n" + L("AAAA", "A --> B : 1\nA --> C : 1", 2, head="seed: S*2"))
case("stochastic-after-dlength", "Lsystem: 1\nderivation length: 2\nseed: 3\nAxiom: AAAA\nA --> B : 1\nA --> C : 1\nendlsystem\n")
case("stochastic-prob-no-seed", L("AAAA", "A --> B : 1\nA --> C : 1", 2))
case("stochastic-blocks", L("AAAA", "A : { n = n + 1; } * --> B(n) : 1\nA : { m = m + 1; } * --> C(m) : 1", 2,
                            head="seed: 3\nStart: { n = 0; m = 0; }"))

# --- Sub-L-systems (manual 7.2) ----------------------------------------------------------------
case("sub-lsystem", L("A(2)", "A(t) --> F?(2,1)B(t-1)$A(t+1)", 3)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B(5)\nB(x) --> C(x)B(x+1)\nendlsystem\n")
case("sub-lsystem-ignored-rules", L("A B", "A --> ?(2,1)B$\nB --> X", 2)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nB --> Y\nendlsystem\n")
case("sub-lsystem-context", L("A", "A --> C?(2,1)BD$E", 2)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nC < B --> X\nB > D --> Y\nendlsystem\n")
case("sub-lsystem-globals", L("A", "A --> ?(2,1)B$", 3)
     + "\nLsystem: 2\nderivation length: 1\nStart: { k = 10; }\nEndEach: { k = k + 1; }\nAxiom: B\nB --> B C(k)\nendlsystem\n")
case("sub-lsystem-nested", L("A", "A --> ?(2,1)B$", 4)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nB --> ?(3,1)C$B\nendlsystem\n"
     + "\nLsystem: 3\nderivation length: 1\nAxiom: C\nC --> CD\nendlsystem\n")
case("sub-lsystem-cut", L("A", "A --> ?(2,1)BE$F", 3)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nB --> %\nendlsystem\n")
case("sub-lsystem-ignore", L("A", "A --> ?(2,1)B+C$", 2)
     + "\nLsystem: 2\nderivation length: 1\nignore: +\nAxiom: B\nB > C --> X\nendlsystem\n")
case("sub-lsystem-stochastic", L("A", "A --> ?(2,1)BBBB$", 2)
     + "\nLsystem: 2\nseed: 3\nderivation length: 1\nAxiom: B\nB --> C : 1\nB --> D : 1\nendlsystem\n")
case("sub-lsystem-in-axiom", L("?(2,1)B$A", "A --> AA", 2)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nB --> BC\nendlsystem\n")
case("sub-lsystem-decomposition", L("A", "A --> ?(2,1)B$", 2)
     + "\nLsystem: 2\nderivation length: 1\nAxiom: B\nB --> BC\ndecomposition\nC --> DE\nendlsystem\n")
case("sub-lsystem-locals", L("A", "A --> ?(2,1)B(1)$?(2,1)B(5)$", 3)
     + "\nLsystem: 2\nderivation length: 1\nStart: { s = 0; }\nAxiom: B(1)\nB(x) : * { s = s + x; } --> B(s)\nendlsystem\n")

# --- Queries and environment: derivation side only -------------------------------------------
case("query-position", L("A", "A --> F?P(0,0)A\n?P(x,y) --> B(y)", 3))
