recursion 3 #iterate the rewriting 3 times

switch_yz 1 #switch the y and z axes
shape 1 #use cylinders for F
thickness 50 #diameter is 50% of length

#orient the turtle, set the color and start with S (stem) and W (whorl)
axiom &(-90)>(90)-(90)c(12)SW

# draw the stem with ! causing it to taper by 10% per F
rule S = F!F!F!F!F!F!F

# establish the whorl with 8 arms
rule W = L>(45)L>(45)L>(45)L>(45)L>(45)L>(45)L>(45)L

#draw a leaf with two surfaces using an elongated hexagon
rule L = [&(110)c(4)F[ {.+(30)g(.866).-(30)g(.866).-(120)g(.866).-(30)g(.866)g.}]>(180)c(4){.+(30)g(.866).-(30)g(.866).-(120)g(.866).-(30)g(.866)g.}]
