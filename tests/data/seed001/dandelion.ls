recursion 6

switch_ yz 1
 angle 45
 shape 1
 thickness 5

axiom &(90)+(90)[Q][-(90)Q][-(180)Q][-(270)Q]

rule Q = [".7)c-P][".7)c^P][".7)c+P][".7)c&P]

rule P = F[".7)c-P][".7)c^P][".7)c+P][".7)c&P]
