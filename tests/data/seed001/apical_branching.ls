recursion 3
switch_yz 1
shape 1
thickness 50

# at the top of the stem create two branches on opposite sides
axiom &(-90)>(90)-(90)c(12)S[BW]>(180)[BW]

rule S = F!F!F!F!F!F!F

# incline the branches at 60 degrees
rule B = &(60)F!F!F!F!F!F!F

rule W = L>(45)L>(45)L>(45)L>(45)L>(45)L>(45)L>(45)L

rule L = [&(100)c(4)F[ {.+(30)g(.866).-(30)g(.866).-(120)g(.866).-(30)g(.866)g.}]>(180)c(4){.+(30)g(.866).-(30)g(.866).-(120)g(.866).-(30)g(.866)g.}]
