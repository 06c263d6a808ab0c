recursion 12
switch_zy 1
shape 1
thickness 10

axiom &(-90)>(90)-(90)c(12)A

rule A = FBA
rule B = !>(137.5)[&(45)FA]
