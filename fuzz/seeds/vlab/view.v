angle factor: 16
initial color: 3 5
viewpoint: 0,5,10
projection: perspective
light: V:5 6 10 D: 0.5 0.4 0.3
box: x: -1,1 y: 0,2 z: -3,3
surface: l leaf.s 6 6 10
texture: F: bark.png E: m
/* open comment
