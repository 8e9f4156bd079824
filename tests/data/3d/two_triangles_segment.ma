# a small medial axis: two triangles and a hair
5 6 2
v 0 0 0 0.5
v 1 0 0 0.25
v 0 1 0 0.25
v 1 1 0.5 0.125
v 2 2 0.5 0.1
e 0 1
e 1 2
e 2 0
e 1 3
e 3 2
e 3 4
f 0 1 2
f 1 3 2
