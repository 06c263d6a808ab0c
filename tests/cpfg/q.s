-0.3 0.3 0 1 0 0.1
CONTACT POINT  X: 0.0 Y: 0.0 Z: 0.0
END POINT  X: 0.0 Y: 1.0 Z: 0.0
HEADING  X: 0.0 Y: 1.0 Z: 0.0
UP  X: 0.0 Y: 0.0 Z: 1.0
SIZE: 1.0
round leaf
TOP COLOR: 2 DIFFUSE: 0.7 BOTTOM COLOR: 2 DIFFUSE: 0.7
AL: ~ A: ~ AR: ~
L: ~ R: ~
BL: ~ B: ~ BR: ~
0 0 0  0 0 0  0 0 0  0 0 0
-0.45 0.25 0.0  -0.15 0.25 0.15  0.15 0.25 0.15  0.45 0.25 0.0
-0.25 0.75 0.0  -0.1 0.75 0.1  0.1 0.75 0.1  0.25 0.75 0.0
0 1 0  0 1 0  0 1 0  0 1 0
